// SPDX-License-Identifier: MIT
// Shared libFuzzer harness for the predicates: decodes fuzz bytes into coordinates and checks
// every stage against an exact GMP-rational evaluation of the difference-form determinant
// [Shewchuk97 §4], under point permutations, and that non-finite input raises GeometryError.
//
// Input layout: Points * Dim doubles copied bit for bit (any pattern: NaN, inf, subnormal; short
// inputs are zero-padded), then an optional mode byte and parameter byte that reshape the raw
// values towards the cases random bits almost never produce (see reshape()).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <numbers>
#include <optional>
#include <vector>

#include "base/errors.hpp"
#include "predicates/sign.hpp"
#include "tests/fuzz/fuzz_points.hpp"

namespace exactmesh::fuzz {

using predicates::Sign;

/// The exact sign of a rational.
inline Sign sign_of_rational(const mpq_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

/// Laplace expansion along the first row: slow and obviously right, which is the point.
inline mpq_class determinant(const std::vector<std::vector<mpq_class>>& m) {
    const std::size_t n = m.size();
    if (n == 1) return m[0][0];
    mpq_class sum = 0;
    for (std::size_t col = 0; col < n; ++col) {
        if (sgn(m[0][col]) == 0) continue;
        std::vector<std::vector<mpq_class>> minor;
        for (std::size_t row = 1; row < n; ++row) {
            std::vector<mpq_class> entries;
            for (std::size_t k = 0; k < n; ++k) {
                if (k != col) entries.push_back(m[row][k]);
            }
            minor.push_back(std::move(entries));
        }
        const mpq_class term = m[0][col] * determinant(minor);
        if (col % 2 == 0) {
            sum += term;
        } else {
            sum -= term;
        }
    }
    return sum;
}

/// Sign of the difference-form determinant over `points` (each `dim` finite doubles, converted
/// exactly): rows p_i - p_last, plus the lifted column |p_i - p_last|^2 when `lifted`.
/// orient2d/orient3d: lifted = false, dim + 1 points; incircle/insphere: lifted, dim + 2 points.
inline Sign reference_sign(const double* const* points, std::size_t count, std::size_t dim,
                           bool lifted) {
    const double* last = points[count - 1];
    std::vector<std::vector<mpq_class>> m;
    for (std::size_t i = 0; i + 1 < count; ++i) {
        std::vector<mpq_class> row;
        mpq_class lift = 0;
        for (std::size_t k = 0; k < dim; ++k) {
            mpq_class d = mpq_class(points[i][k]) - mpq_class(last[k]);
            lift += d * d;
            row.push_back(std::move(d));
        }
        if (lifted) row.push_back(lift);
        m.push_back(std::move(row));
    }
    return sign_of_rational(determinant(m));
}

/// +1 for an even permutation, -1 for an odd one.
template <std::size_t N>
constexpr int parity(const std::array<int, N>& perm) {
    int inversions = 0;
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = i + 1; j < N; ++j) {
            if (perm[i] > perm[j]) ++inversions;
        }
    }
    return inversions % 2 == 0 ? 1 : -1;
}

inline double from_bits(std::uint64_t b) {
    double x;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

/// A fraction in [0, 1) taken from 20 bits of x's pattern (finite whatever x is).
inline double fraction_of(double x) {
    return std::ldexp(static_cast<double>(bits_of(x) & 0xFFFFFu), -20);
}

/// The modes of the trailer byte. Raw random bit patterns almost never cancel, so most modes
/// build the configurations where predicates fail: degenerate, nearly degenerate, duplicated,
/// on a lattice (exact zeros), and of comparable magnitudes (heavy cancellation).
enum class Mode : std::uint8_t { raw, lattice, near_degenerate, duplicate, same_scale, count };

/// Rewrites the raw coordinates of `Points` points in `Dim` dimensions according to `mode`;
/// `lifted` says whether the predicate is in-circle/in-sphere (else orientation).
template <std::size_t Points, std::size_t Dim>
void reshape(std::array<double, Points * Dim>& x, Mode mode, std::uint8_t parameter, bool lifted) {
    switch (mode) {
        case Mode::raw:
        case Mode::count:
            return;
        case Mode::lattice: {
            // Small integers times one power of two between 2^-1100 (underflow) and 2^940.
            const int exponent = static_cast<int>(parameter) * 8 - 1100;
            for (double& v : x) {
                const auto small = static_cast<std::int8_t>(bits_of(v) & 0xFFu);
                v = std::ldexp(static_cast<double>(small), exponent);
            }
            return;
        }
        case Mode::near_degenerate: {
            const int ulps = static_cast<int>(parameter) - 128;
            double* last = x.data() + (Points - 1) * Dim;
            if (!lifted) {
                // Last point on the line / plane of the others, rounded, then moved by `ulps`.
                std::array<double, Points - 2> weights;
                for (std::size_t j = 0; j + 2 < Points; ++j) {
                    weights[j] = 4.0 * fraction_of(last[j]) - 1.5;
                }
                for (std::size_t k = 0; k < Dim; ++k) {
                    double v = x[k];
                    for (std::size_t j = 0; j + 2 < Points; ++j) {
                        v += weights[j] * (x[(j + 1) * Dim + k] - x[k]);
                    }
                    last[k] = v;
                }
            } else {
                // Every point on the circle / sphere centred at the first raw point with radius
                // |second raw coordinate|, rounded.
                const std::array<double, Dim> centre = [&] {
                    std::array<double, Dim> c;
                    std::copy(x.begin(), x.begin() + Dim, c.begin());
                    return c;
                }();
                const double radius = std::fabs(x[1]);
                for (std::size_t p = 0; p < Points; ++p) {
                    double* q = x.data() + p * Dim;
                    const double angle = 2.0 * std::numbers::pi * fraction_of(q[0]);
                    if constexpr (Dim == 2) {
                        q[0] = centre[0] + radius * std::cos(angle);
                        q[1] = centre[1] + radius * std::sin(angle);
                    } else {
                        const double z = 2.0 * fraction_of(q[1]) - 1.0;
                        const double rho = std::sqrt(1.0 - z * z);
                        q[0] = centre[0] + radius * rho * std::cos(angle);
                        q[1] = centre[1] + radius * rho * std::sin(angle);
                        q[2] = centre[2] + radius * z;
                    }
                }
            }
            for (std::size_t k = 0; k < Dim; ++k) last[k] = nudge(last[k], ulps);
            return;
        }
        case Mode::duplicate: {
            const std::size_t to = parameter % Points, from = (parameter / Points) % Points;
            for (std::size_t k = 0; k < Dim; ++k) x[to * Dim + k] = x[from * Dim + k];
            return;
        }
        case Mode::same_scale: {
            // Keep sign and mantissa; exponents within a factor of 8 of 2^(8 p - 1100).
            const int base = static_cast<int>(parameter) * 8 - 1100 + 1023;
            for (double& v : x) {
                const std::uint64_t b = bits_of(v);
                const int field = std::clamp(base + static_cast<int>((b >> 52) & 3u), 0, 2046);
                v = from_bits((b & 0x800FFFFFFFFFFFFFull) |
                              (static_cast<std::uint64_t>(field) << 52));
            }
            return;
        }
    }
}

[[noreturn]] inline void fail(const char* predicate, const char* what, const double* x,
                              std::size_t n, int expected, int got) {
    std::fprintf(stderr, "%s: %s (expected %d, got %d) for coordinates:", predicate, what, expected,
                 got);
    for (std::size_t i = 0; i < n; ++i) std::fprintf(stderr, " %a", x[i]);
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

/// Runs one fuzz input through predicate `P`, which provides:
///   kName, kPoints, kDim, kLifted,
///   Sign adaptive(const double* const* p), Sign exact(...), std::optional<Sign> filter(...).
template <class P>
int check_input(const std::uint8_t* data, std::size_t size) {
    constexpr std::size_t kPoints = P::kPoints, kDim = P::kDim, kCount = kPoints * kDim;
    std::array<double, kCount> x{};
    std::memcpy(x.data(), data, std::min(size, sizeof x));
    if (size > sizeof x) {
        const auto mode = static_cast<Mode>(data[sizeof x] % static_cast<int>(Mode::count));
        const std::uint8_t parameter = size > sizeof x + 1 ? data[sizeof x + 1] : 0;
        reshape<kPoints, kDim>(x, mode, parameter, P::kLifted);
    }
    std::array<const double*, kPoints> points;
    for (std::size_t p = 0; p < kPoints; ++p) points[p] = x.data() + p * kDim;

    const bool finite = std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
    if (!finite) {
        // No exact answer exists: every entry point that reaches the exact stages must throw
        // GeometryError; returning a sign, or crashing, is the bug.
        auto must_throw = [&](const char* entry, auto call) {
            try {
                const Sign s = call();
                fail(P::kName, entry, x.data(), kCount, 99, predicates::to_int(s));
            } catch (const GeometryError&) {
                return;
            } catch (const std::exception& e) {
                std::fprintf(stderr, "%s: %s threw something else: %s\n", P::kName, entry,
                             e.what());
                __builtin_trap();
            }
        };
        must_throw("adaptive on non-finite input", [&] { return P::adaptive(points.data()); });
        must_throw("exact on non-finite input", [&] { return P::exact(points.data()); });
        return 0;
    }

    try {
        const Sign expected = reference_sign(points.data(), kPoints, kDim, P::kLifted);
        const int e = predicates::to_int(expected);
        if (const std::optional<Sign> f = P::filter(points.data()); f && *f != expected) {
            fail(P::kName, "filter certified a wrong sign", x.data(), kCount, e,
                 predicates::to_int(*f));
        }
        if (const Sign s = P::exact(points.data()); s != expected) {
            fail(P::kName, "exact stage", x.data(), kCount, e, predicates::to_int(s));
        }
        for (const auto& perm : P::kPermutations) {
            std::array<const double*, kPoints> permuted;
            for (std::size_t p = 0; p < kPoints; ++p) {
                permuted[p] = points[static_cast<std::size_t>(perm[p])];
            }
            const int want = e * parity(perm);
            if (const Sign s = P::adaptive(permuted.data()); predicates::to_int(s) != want) {
                fail(P::kName, "adaptive predicate (permuted, see kPermutations)", x.data(), kCount,
                     want, predicates::to_int(s));
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: exception on finite input: %s\n", P::kName, e.what());
        __builtin_trap();
    }
    return 0;
}

}  // namespace exactmesh::fuzz
