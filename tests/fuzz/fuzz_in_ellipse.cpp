// SPDX-License-Identifier: MIT
// libFuzzer target for in_ellipse and compare_metric_lengths (issue 14): the filter, the exact
// stages and the adaptive predicate against the exact rational reference, under permutations of
// the four points and power-of-two scalings of the metric; compare_metric_lengths against its
// rational value and antisymmetric; non-finite input must throw GeometryError.
//
// Input layout: 11 doubles bit for bit (a, b, c, d, then M11, M12, M22; zero-padded), then an
// optional mode byte and parameter byte: 0 raw, 1 lattice (small integers times 2^e, metric too:
// exact ties, symmetric M of any signature), 2 near-elliptic (four points on the ellipse of an
// SPD metric built from the raw bits, rounded), 3 same scale (coordinates reduced to [1, 2)).
#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <numbers>
#include <optional>

#include "base/errors.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/in_ellipse.hpp"
#include "predicates/metric_lengths.hpp"
#include "tests/fuzz/fuzz_reference.hpp"

namespace {

namespace pred = exactmesh::predicates;
using exactmesh::fuzz::fail;
using exactmesh::fuzz::fraction_of;
using pred::Sign;

constexpr std::size_t kDoubles = 11;
constexpr const char* kName = "in_ellipse";

void reshape(std::array<double, kDoubles>& x, std::uint8_t mode, std::uint8_t parameter) {
    switch (mode % 4) {
        case 1: {
            const int exponent = static_cast<int>(parameter) * 8 - 1100;
            for (std::size_t i = 0; i < kDoubles; ++i) {
                const auto small = static_cast<std::int8_t>(exactmesh::fuzz::bits_of(x[i]) & 0xFFu);
                x[i] = std::ldexp(static_cast<double>(small), i < 8 ? exponent : exponent / 4);
            }
            return;
        }
        case 2: {
            const double theta = std::numbers::pi * fraction_of(x[8]);
            const double h2 = std::pow(10.0, -6.0 * fraction_of(x[9]));
            const double c = std::cos(theta), s = std::sin(theta);
            const double ox = fraction_of(x[10]) * 64.0, oy = fraction_of(x[0]) * 64.0;
            const int exponent = static_cast<int>(parameter) - 128;
            for (int p = 0; p < 4; ++p) {
                const double t =
                    2.0 * std::numbers::pi * fraction_of(x[static_cast<std::size_t>(2 * p + 1)]);
                const double u = std::cos(t), v = h2 * std::sin(t);
                x[static_cast<std::size_t>(2 * p)] = std::ldexp(ox + c * u - s * v, exponent);
                x[static_cast<std::size_t>(2 * p + 1)] = std::ldexp(oy + s * u + c * v, exponent);
            }
            const double l2 = 1.0 / (h2 * h2);
            x[8] = c * c + s * s * l2;
            x[9] = c * s * (1.0 - l2);
            x[10] = s * s + c * c * l2;
            return;
        }
        case 3:
            for (double& v : x) {
                if (std::isfinite(v) && v != 0.0) v = std::ldexp(std::fabs(v), -std::ilogb(v));
            }
            return;
        default:
            return;
    }
}

Sign metric_lengths_reference(const double* p1, const double* q1, const double* p2,
                              const double* q2, const double* m) {
    using pred::reference::exact;
    auto square = [&](const double* p, const double* q) {
        const mpq_class dx = exact(q[0]) - exact(p[0]), dy = exact(q[1]) - exact(p[1]);
        return mpq_class(exact(m[0]) * dx * dx + 2 * exact(m[1]) * dx * dy + exact(m[2]) * dy * dy);
    };
    return pred::reference::sign_of(square(p1, q1) - square(p2, q2));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::array<double, kDoubles> x{};
    std::memcpy(x.data(), data, std::min(size, sizeof x));
    if (size >= sizeof x + 2) reshape(x, data[sizeof x], data[sizeof x + 1]);
    const double* p[4] = {x.data(), x.data() + 2, x.data() + 4, x.data() + 6};
    const double* m = x.data() + 8;
    bool finite = true;
    for (const double v : x) finite = finite && std::isfinite(v);
    if (!finite) {
        try {
            (void)pred::in_ellipse(p[0], p[1], p[2], p[3], m);
            fail(kName, "non-finite input returned a sign", x.data(), kDoubles, 0, 0);
        } catch (const exactmesh::GeometryError&) {
        } catch (const std::exception&) {
            fail(kName, "non-finite input threw the wrong exception", x.data(), kDoubles, 0, 0);
        }
        return 0;
    }
    const Sign want = pred::reference::in_ellipse(p[0], p[1], p[2], p[3], m);
    const int w = pred::to_int(want);
    if (pred::in_ellipse(p[0], p[1], p[2], p[3], m) != want) {
        fail(kName, "adaptive sign", x.data(), kDoubles, w,
             pred::to_int(pred::in_ellipse(p[0], p[1], p[2], p[3], m)));
    }
    if (const auto f = pred::in_ellipse_filter(p[0], p[1], p[2], p[3], m); f && *f != want) {
        fail(kName, "filter certified a wrong sign", x.data(), kDoubles, w, pred::to_int(*f));
    }
    // Alternating in all four points (the lifted 4x4 determinant).
    constexpr std::array<std::array<int, 4>, 4> kPermutations = {
        {{1, 2, 0, 3}, {1, 0, 2, 3}, {3, 1, 2, 0}, {1, 2, 3, 0}}};
    for (const auto& perm : kPermutations) {
        const int expected = w * exactmesh::fuzz::parity(perm);
        const Sign s = pred::in_ellipse_exact(p[perm[0]], p[perm[1]], p[perm[2]], p[perm[3]], m);
        if (pred::to_int(s) != expected)
            fail(kName, "permuted", x.data(), kDoubles, expected, pred::to_int(s));
    }
    // A positive power-of-two scaling of the metric keeps the sign (when it stays finite).
    const int k = static_cast<int>(exactmesh::fuzz::bits_of(x[0]) % 1200) - 600;
    const double scaled[3] = {std::ldexp(m[0], k), std::ldexp(m[1], k), std::ldexp(m[2], k)};
    if (std::isfinite(scaled[0]) && std::isfinite(scaled[1]) && std::isfinite(scaled[2])) {
        const Sign s = pred::in_ellipse(p[0], p[1], p[2], p[3], scaled);
        const Sign r = pred::reference::in_ellipse(p[0], p[1], p[2], p[3], scaled);
        if (s != r)
            fail(kName, "scaled metric", x.data(), kDoubles, pred::to_int(r), pred::to_int(s));
    }
    // compare_metric_lengths on (a, b) and (c, d) in M: exact and antisymmetric.
    const Sign l = pred::compare_metric_lengths(p[0], p[1], m, p[2], p[3], m);
    const Sign lr = metric_lengths_reference(p[0], p[1], p[2], p[3], m);
    if (l != lr)
        fail("compare_metric_lengths", "sign", x.data(), kDoubles, pred::to_int(lr),
             pred::to_int(l));
    const Sign swapped = pred::compare_metric_lengths(p[2], p[3], m, p[0], p[1], m);
    if (swapped != -l) {
        fail("compare_metric_lengths", "antisymmetry", x.data(), kDoubles, -pred::to_int(l),
             pred::to_int(swapped));
    }
    return 0;
}
