// SPDX-License-Identifier: MIT
// Shared by the Delaunay fuzz targets (fuzz_delaunay_2d, fuzz_delaunay_3d): the input layout
// (coordinates copied bit for bit, then a mode byte and a parameter byte in the size % 8 bytes
// left over), the reshaping modes both have (lattice, ulps, duplicates), the check that
// non-finite input is rejected, and the failure report. Bit access to doubles is shared with
// the predicate targets (fuzz_reference.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "base/errors.hpp"

namespace exactmesh::fuzz {

/// x moved by `ulps` representable doubles.
inline double nudge(double x, int ulps) {
    const double direction = ulps > 0 ? INFINITY : -INFINITY;
    for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, direction);
    return x;
}

inline std::uint64_t bits_of(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

/// The decoded input: the mode and parameter of the trailer, the coordinates (`dims` per point)
/// and an FNV-1a hash of all the bytes, from which the targets pick insertion orders and seeds.
template <class Mode>
struct PointsInput {
    Mode mode = Mode::raw;
    std::uint8_t parameter = 0;
    std::vector<double> xs;
    std::uint64_t hash = 1469598103934665603ull;
};

/// Up to `max_points` points (`max_raw_points` in the modes that keep raw bit patterns, raw and
/// duplicates); a partial last point is dropped.
template <class Mode>
PointsInput<Mode> decode_points(const std::uint8_t* data, std::size_t size, std::size_t dims,
                                std::size_t max_points, std::size_t max_raw_points) {
    PointsInput<Mode> in;
    const std::size_t trailer = size % 8;
    if (trailer > 0)
        in.mode = static_cast<Mode>(data[size - trailer] % static_cast<int>(Mode::count));
    if (trailer > 1) in.parameter = data[size - trailer + 1];
    const bool raw_values = in.mode == Mode::raw || in.mode == Mode::duplicates;
    const std::size_t doubles =
        std::min(size / 8, dims * (raw_values ? max_raw_points : max_points)) / dims * dims;
    in.xs.resize(doubles);
    if (doubles > 0) std::memcpy(in.xs.data(), data, doubles * sizeof(double));
    for (std::size_t i = 0; i < size; ++i) in.hash = (in.hash ^ data[i]) * 1099511628211ull;
    return in;
}

/// The power of two the lattice and ulps modes scale to: 2^-1100 .. 2^853 by the parameter.
inline int reshape_exponent(std::uint8_t parameter) {
    return static_cast<int>(parameter >> 2) * 31 - 1100;
}

/// Lattice mode: small integers of `width` bits (centred on 0) times 2^exponent: collinear,
/// coplanar, cocircular and cospherical subsets everywhere, exact zeros, underflow at the low
/// exponents.
inline void reshape_lattice(std::vector<double>& xs, int width, int exponent) {
    for (double& v : xs) {
        const auto small = static_cast<std::int64_t>(bits_of(v) & ((1u << width) - 1)) -
                           (std::int64_t{1} << (width - 1));
        v = std::ldexp(static_cast<double>(small), exponent);
    }
}

/// Ulps mode: a lattice of `side` (a power of two) values per axis scaled to about 2^exponent,
/// each coordinate moved by -2..2 ulps: nearly degenerate everywhere, decided only by the exact
/// stages.
inline void reshape_ulps(std::vector<double>& xs, std::uint64_t side, int exponent) {
    for (double& v : xs) {
        const std::uint64_t b = bits_of(v);
        v = nudge(std::ldexp(static_cast<double>((b & (side - 1)) + side), exponent),
                  static_cast<int>((b >> 8) % 5) - 2);
    }
}

/// Duplicates mode: each point, with probability about 1/(1 + parameter % 4), repeats an
/// earlier one.
inline void reshape_duplicates(std::vector<double>& xs, std::size_t dims, std::uint8_t parameter) {
    const std::size_t n = xs.size() / dims;
    for (std::size_t i = 1; i < n; ++i) {
        const std::uint64_t b = bits_of(xs[dims * i]);
        if (b % (1u + parameter % 4u) != 0) continue;
        const std::size_t j = (b >> 8) % i;
        for (std::size_t c = 0; c < dims; ++c) xs[dims * i + c] = xs[dims * j + c];
    }
}

/// The modes both targets have, on points of `dims` coordinates: raw and count leave the values,
/// lattice makes them integers of widths[parameter & 3] bits, ulps an ulp-perturbed lattice of
/// `side` values per axis, duplicates repeats points. Other modes are the target's own.
template <class Mode>
void reshape_shared(std::vector<double>& xs, std::size_t dims, Mode mode, std::uint8_t parameter,
                    const std::array<int, 4>& widths, std::uint64_t side) {
    const int exponent = reshape_exponent(parameter);
    if (mode == Mode::lattice) reshape_lattice(xs, widths[parameter & 3u], exponent);
    if (mode == Mode::ulps) reshape_ulps(xs, side, exponent);
    if (mode == Mode::duplicates) reshape_duplicates(xs, dims, parameter);
}

/// Prints what failed and the points, then __builtin_trap() (which libFuzzer reports).
[[noreturn]] inline void fail_points(const char* target, const std::vector<double>& xs,
                                     std::size_t dims, const std::string& what) {
    std::fprintf(stderr, "%s: %s\npoints (%zu):", target, what.c_str(), xs.size() / dims);
    for (std::size_t i = 0; i + dims <= xs.size(); i += dims) {
        for (std::size_t c = 0; c < dims; ++c) {
            std::fprintf(stderr, "%s%a", c == 0 ? " (" : ", ", xs[i + c]);
        }
        std::fprintf(stderr, ")");
    }
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

/// If xs holds a non-finite coordinate, each of the `count` algorithms (build(a), named
/// label(a)) must throw NonFiniteCoordinate naming the first bad point; fail(what) otherwise.
/// Returns whether xs held one.
template <class Build, class Label, class Fail>
bool check_non_finite_rejected(const std::vector<double>& xs, std::size_t dims, std::size_t count,
                               Build build, Label label, Fail fail) {
    const auto bad = std::find_if(xs.begin(), xs.end(), [](double v) { return !std::isfinite(v); });
    if (bad == xs.end()) return false;
    const auto vertex =
        static_cast<std::uint32_t>(static_cast<std::size_t>(bad - xs.begin()) / dims);
    for (std::size_t a = 0; a < count; ++a) {
        try {
            build(a);
        } catch (const NonFiniteCoordinate& e) {
            if (e.vertex() != vertex) {
                fail(label(a) + ": NonFiniteCoordinate names point " + std::to_string(e.vertex()) +
                     ", the first is " + std::to_string(vertex));
            }
            continue;
        } catch (const std::exception& e) {
            fail(label(a) + " threw something else on non-finite input: " + e.what());
        }
        fail(label(a) + " accepted a non-finite coordinate");
    }
    return true;
}

}  // namespace exactmesh::fuzz
