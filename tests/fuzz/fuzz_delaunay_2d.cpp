// SPDX-License-Identifier: MIT
// libFuzzer target: the three 2D Delaunay constructions on up to kMaxPoints fuzzed points. Each
// output must pass the exact check (triangulation/checks/check_2d) and have mutual neighbours; the
// three must agree (same count and merged_into; same triangles when no point repeats, by the
// shared symbolic perturbation); small inputs must match the naive empty-circle oracle
// (tests/oracles). Non-finite input must make every algorithm throw NonFiniteCoordinate naming
// the first bad point. Anything else is __builtin_trap().
//
// Input layout: the first 8·floor(size/8) bytes are doubles copied bit for bit, x0 y0 x1 y1 ...
// (an odd last one is dropped; at most 2·kMaxPoints are read, 2·kMaxRawPoints in the modes that
// keep raw values). The size % 8 bytes left over are the optional trailer: a mode byte and a
// parameter byte that reshape the raw values towards what random bits almost never produce
// (see reshape()): lattices, ulp-perturbed lattices, duplicates, exactly cocircular points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_naive.hpp"

namespace {

namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 256;
/// Raw bit patterns (the raw and duplicates modes) spread coordinates over every magnitude from
/// 2^-1074 to 2^1023, where every predicate ends in GMP: about 0.1 s per 256 points without
/// ASan, ten times the reshaped modes. Fewer of them keep the executions per second up; the
/// magnitudes themselves are the predicate targets' business.
constexpr std::size_t kMaxRawPoints = 64;
/// The oracle is O(n^4); above this it is skipped to keep executions fast.
constexpr std::size_t kOracleMaxPoints = 24;

struct Algorithm {
    const char* name;
    tri::Delaunay2Function build;
};
const std::array<Algorithm, 3> kAlgorithms = {
    Algorithm{"bowyer-watson", tri::delaunay_2d_algorithm("bowyer-watson")},
    Algorithm{"green-sibson", tri::delaunay_2d_algorithm("green-sibson")},
    Algorithm{"tanemura-merriam", tri::delaunay_2d_algorithm("tanemura-merriam")}};
constexpr std::array<tri::InsertionOrder, 3> kOrders = {
    tri::InsertionOrder::Given, tri::InsertionOrder::Random, tri::InsertionOrder::Brio};
constexpr std::array<const char*, 3> kOrderNames = {"given", "random", "brio"};

enum class Mode : std::uint8_t { raw, lattice, ulps, duplicates, cocircular, count };

std::uint64_t bits_of(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

double nudge(double x, int ulps) {
    for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
    return x;
}

/// All integer points of x^2 + y^2 = 1105^2: 108 of them (1105 = 5·13·17, each prime 1 mod 4,
/// gives 4·3·3·3 representations).
const std::vector<std::array<int, 2>>& circle_points() {
    static const std::vector<std::array<int, 2>> points = [] {
        constexpr int r = 1105;
        std::vector<std::array<int, 2>> out;
        for (int x = -r; x <= r; ++x) {
            const int rest = r * r - x * x;
            const int y = static_cast<int>(std::lround(std::sqrt(static_cast<double>(rest))));
            if (y * y != rest) continue;
            out.push_back({x, y});
            if (y != 0) out.push_back({x, -y});
        }
        return out;
    }();
    return points;
}

/// Rewrites the raw coordinates according to `mode` (each mode keeps the point count).
void reshape(std::vector<double>& xy, Mode mode, std::uint8_t parameter) {
    const int exponent = static_cast<int>(parameter >> 2) * 31 - 1100;  // 2^-1100 .. 2^853
    switch (mode) {
        case Mode::raw:
        case Mode::count:
            return;
        case Mode::lattice: {
            // Small integers (3 to 8 bits, by the parameter) times one power of two: collinear
            // and cocircular subsets everywhere, exact zeros, underflow at the low exponents.
            const int width = std::array<int, 4>{3, 4, 6, 8}[parameter & 3u];
            for (double& v : xy) {
                const auto small = static_cast<std::int64_t>(bits_of(v) & ((1u << width) - 1)) -
                                   (std::int64_t{1} << (width - 1));
                v = std::ldexp(static_cast<double>(small), exponent);
            }
            return;
        }
        case Mode::ulps: {
            // A 16 x 16 lattice scaled to about 2^e, each coordinate moved by -2..2 ulps: nearly
            // degenerate everywhere, decided only by the exact stages.
            for (double& v : xy) {
                const std::uint64_t b = bits_of(v);
                const double base = std::ldexp(static_cast<double>((b & 15u) + 16), exponent);
                v = nudge(base, static_cast<int>((b >> 8) % 5) - 2);
            }
            return;
        }
        case Mode::duplicates: {
            // Each point, with probability about 1/(1 + parameter % 4), repeats an earlier one.
            const std::size_t n = xy.size() / 2;
            for (std::size_t i = 1; i < n; ++i) {
                const std::uint64_t b = bits_of(xy[2 * i]);
                if (b % (1u + parameter % 4u) != 0) continue;
                const std::size_t j = (b >> 8) % i;
                xy[2 * i] = xy[2 * j];
                xy[2 * i + 1] = xy[2 * j + 1];
            }
            return;
        }
        case Mode::cocircular: {
            // Lattice points of one circle (exactly cocircular), possibly with its centre, on
            // up to four circles with integer centres; scaled by a power of two.
            const auto& circle = circle_points();
            const int scale = static_cast<int>(parameter >> 2) * 16 - 500;  // stays finite
            for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
                const std::uint64_t b = bits_of(xy[i]);
                const auto& p = circle[b % circle.size()];
                const std::uint64_t circles = 1u + (parameter & 3u);
                const int centre = static_cast<int>(bits_of(xy[i + 1]) % circles) * 1500;
                const bool at_centre = (b >> 20) % 16 == 0;
                xy[i] = std::ldexp(static_cast<double>((at_centre ? 0 : p[0]) + centre), scale);
                xy[i + 1] = std::ldexp(static_cast<double>(at_centre ? 0 : p[1]), scale);
            }
            return;
        }
    }
}

[[noreturn]] void fail(const std::vector<double>& xy, const std::string& what) {
    std::fprintf(stderr, "fuzz_delaunay_2d: %s\npoints (%zu):", what.c_str(), xy.size() / 2);
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
        std::fprintf(stderr, " (%a, %a)", xy[i], xy[i + 1]);
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

using Triangles = std::vector<std::array<tri::VertIdx, 3>>;

Triangles canonical(const std::vector<tri::VertIdx>& triangles) {
    Triangles out;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        std::array<tri::VertIdx, 3> a{triangles[t], triangles[t + 1], triangles[t + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        out.push_back(a);
    }
    std::sort(out.begin(), out.end());
    return out;
}

bool has_duplicates(const std::vector<double>& xy) {
    std::vector<std::pair<double, double>> points;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) points.emplace_back(xy[i], xy[i + 1]);
    std::sort(points.begin(), points.end());
    return std::adjacent_find(points.begin(), points.end()) != points.end();
}

/// Neighbour slot 3t+k: the triangle across edge (v[k], v[k+1]), which names t back.
bool neighbors_mutual(const tri::Delaunay2Result& r) {
    const std::size_t count = r.triangles.size() / 3;
    if (r.neighbors.size() != r.triangles.size()) return false;
    for (std::size_t t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::TriIdx u = r.neighbors[3 * t + k];
            if (u == tri::kNone) continue;
            if (u >= count) return false;
            const tri::VertIdx a = r.triangles[3 * t + k], b = r.triangles[3 * t + (k + 1) % 3];
            bool found = false;
            for (unsigned j = 0; j < 3; ++j) {
                found =
                    found || (r.triangles[3 * u + j] == b &&
                              r.triangles[3 * u + (j + 1) % 3] == a && r.neighbors[3 * u + j] == t);
            }
            if (!found) return false;
        }
    }
    return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::size_t trailer = size % 8;
    const Mode mode = trailer > 0
                          ? static_cast<Mode>(data[size - trailer] % static_cast<int>(Mode::count))
                          : Mode::raw;
    const std::uint8_t parameter = trailer > 1 ? data[size - trailer + 1] : 0;
    const bool raw_values = mode == Mode::raw || mode == Mode::duplicates;
    const std::size_t doubles =
        std::min(size / 8, 2 * (raw_values ? kMaxRawPoints : kMaxPoints)) & ~std::size_t{1};
    std::vector<double> xy(doubles);
    if (doubles > 0) std::memcpy(xy.data(), data, doubles * sizeof(double));
    reshape(xy, mode, parameter);
    // Orders and the order seed from the data too, so the corpus explores them.
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 1099511628211ull;
    auto options = [hash](std::size_t a) {
        return tri::Delaunay2Options{kOrders[(hash >> (2 * a)) % 3], hash >> 8};
    };
    auto label = [&options](std::size_t a) {
        return std::string(kAlgorithms[a].name) + " (order " +
               kOrderNames[static_cast<std::size_t>(options(a).order)] + ", seed " +
               std::to_string(options(a).seed) + ")";
    };

    const auto bad = std::find_if(xy.begin(), xy.end(), [](double v) { return !std::isfinite(v); });
    if (bad != xy.end()) {
        const auto vertex = static_cast<std::uint32_t>((bad - xy.begin()) / 2);
        for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
            try {
                kAlgorithms[a].build(xy, options(a));
            } catch (const exactmesh::NonFiniteCoordinate& e) {
                if (e.vertex() != vertex) {
                    fail(xy, label(a) + ": NonFiniteCoordinate names point " +
                                 std::to_string(e.vertex()) + ", the first is " +
                                 std::to_string(vertex));
                }
                continue;
            } catch (const std::exception& e) {
                fail(xy, label(a) + " threw something else on non-finite input: " + e.what());
            }
            fail(xy, label(a) + " accepted a non-finite coordinate");
        }
        return 0;
    }

    std::array<tri::Delaunay2Result, 3> results;
    for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
        try {
            results[a] = kAlgorithms[a].build(xy, options(a));
        } catch (const std::exception& e) {
            fail(xy, label(a) + " threw on finite input: " + e.what());
        }
        const tri::CheckReport report = tri::check_delaunay_2d(xy, results[a].triangles);
        if (!report.ok) fail(xy, label(a) + ": check: " + report.problem);
        if (!neighbors_mutual(results[a])) fail(xy, label(a) + ": neighbours not mutual");
    }
    const bool duplicates = has_duplicates(xy);
    const Triangles reference = duplicates ? Triangles{} : canonical(results[0].triangles);
    for (std::size_t a = 1; a < kAlgorithms.size(); ++a) {
        if (results[a].triangles.size() != results[0].triangles.size()) {
            fail(xy, label(a) + ": " + std::to_string(results[a].triangles.size() / 3) +
                         " triangles, " + label(0) + ": " +
                         std::to_string(results[0].triangles.size() / 3));
        }
        if (results[a].merged_into != results[0].merged_into) {
            fail(xy, label(a) + ": merged_into differs from " + label(0));
        }
        if (!duplicates && canonical(results[a].triangles) != reference) {
            fail(xy, label(a) + ": triangles differ from " + label(0));
        }
    }
    if (xy.size() / 2 <= kOracleMaxPoints) {
        const exactmesh::triangulation::NaiveDelaunay2 oracle = exactmesh::triangulation::delaunay_2d_naive(xy);
        for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
            const std::string problem = exactmesh::triangulation::compare_with_delaunay_2d_naive(
                xy, results[a].triangles, oracle, results[a].merged_into);
            if (!problem.empty()) fail(xy, label(a) + ": oracle: " + problem);
        }
    }
    return 0;
}
