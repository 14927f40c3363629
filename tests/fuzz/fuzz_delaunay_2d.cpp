// SPDX-License-Identifier: MIT
// libFuzzer target: the three 2D Delaunay constructions on up to kMaxPoints fuzzed points. Each
// output must pass the exact check (triangulation/checks/check_2d) and have mutual neighbours; the
// three must agree (same count and merged_into; same triangles when no point repeats, by the
// shared symbolic perturbation); Bowyer-Watson on 2 threads (parallel_bowyer_watson_2d, parallel
// rounds from 4 points per thread) must give exactly the sequential brio order's triangles and
// merged_into; small inputs must match the naive empty-circle oracle
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
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "tests/fuzz/fuzz_points.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/compare_triangulations_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_naive.hpp"

namespace {

namespace fz = exactmesh::fuzz;
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
    if (mode != Mode::cocircular) {
        // The shared modes: lattices of 3- to 8-bit integers, 16 x 16 ulp lattices.
        fz::reshape_shared(xy, 2, mode, parameter, {3, 4, 6, 8}, 16);
        return;
    }
    // Lattice points of one circle (exactly cocircular), possibly with its centre, on
    // up to four circles with integer centres; scaled by a power of two.
    const auto& circle = circle_points();
    const int scale = static_cast<int>(parameter >> 2) * 16 - 500;  // stays finite
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
        const std::uint64_t b = fz::bits_of(xy[i]);
        const auto& p = circle[b % circle.size()];
        const std::uint64_t circles = 1u + (parameter & 3u);
        const int centre = static_cast<int>(fz::bits_of(xy[i + 1]) % circles) * 1500;
        const bool at_centre = (b >> 20) % 16 == 0;
        xy[i] = std::ldexp(static_cast<double>((at_centre ? 0 : p[0]) + centre), scale);
        xy[i + 1] = std::ldexp(static_cast<double>(at_centre ? 0 : p[1]), scale);
    }
}

[[noreturn]] void fail(const std::vector<double>& xy, const std::string& what) {
    fz::fail_points("fuzz_delaunay_2d", xy, 2, what);
}

using Triangles = std::vector<std::array<tri::VertIdx, 3>>;

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
    fz::PointsInput<Mode> in = fz::decode_points<Mode>(data, size, 2, kMaxPoints, kMaxRawPoints);
    std::vector<double>& xy = in.xs;
    reshape(xy, in.mode, in.parameter);
    // Orders and the order seed from the data too, so the corpus explores them.
    const std::uint64_t hash = in.hash;
    auto options = [hash](std::size_t a) {
        return tri::Delaunay2Options{kOrders[(hash >> (2 * a)) % 3], hash >> 8};
    };
    auto label = [&options](std::size_t a) {
        return std::string(kAlgorithms[a].name) + " (order " +
               kOrderNames[static_cast<std::size_t>(options(a).order)] + ", seed " +
               std::to_string(options(a).seed) + ")";
    };
    if (fz::check_non_finite_rejected(
            xy, 2, kAlgorithms.size(), [&](std::size_t a) { kAlgorithms[a].build(xy, options(a)); },
            label, [&](const std::string& what) { fail(xy, what); })) {
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
    const bool duplicates = tri::has_duplicate_points_2d(xy);
    const Triangles reference =
        duplicates ? Triangles{} : tri::canonical_triangles_2d(results[0].triangles);
    for (std::size_t a = 1; a < kAlgorithms.size(); ++a) {
        if (results[a].triangles.size() != results[0].triangles.size()) {
            fail(xy, label(a) + ": " + std::to_string(results[a].triangles.size() / 3) +
                         " triangles, " + label(0) + ": " +
                         std::to_string(results[0].triangles.size() / 3));
        }
        if (results[a].merged_into != results[0].merged_into) {
            fail(xy, label(a) + ": merged_into differs from " + label(0));
        }
        if (!duplicates && tri::canonical_triangles_2d(results[a].triangles) != reference) {
            fail(xy, label(a) + ": triangles differ from " + label(0));
        }
    }
    // 2 threads against one, both in the brio order of the same seed (the same kept copies).
    tri::Delaunay2Options brio{tri::InsertionOrder::Brio, hash >> 8};
    const tri::Delaunay2Result one_thread = kAlgorithms[0].build(xy, brio);
    brio.threads = 2;
    brio.parallel_round_minimum = 4;
    tri::Delaunay2Result two_threads;
    try {
        two_threads = kAlgorithms[0].build(xy, brio);
    } catch (const std::exception& e) {
        fail(xy, std::string("bowyer-watson --threads 2 threw on finite input: ") + e.what());
    }
    if (tri::canonical_triangles_2d(two_threads.triangles) !=
            tri::canonical_triangles_2d(one_thread.triangles) ||
        two_threads.merged_into != one_thread.merged_into) {
        fail(xy, "bowyer-watson on 2 threads differs from 1 thread");
    }
    if (xy.size() / 2 <= kOracleMaxPoints) {
        const exactmesh::triangulation::NaiveDelaunay2 oracle =
            exactmesh::triangulation::delaunay_2d_naive(xy);
        for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
            const std::string problem = exactmesh::triangulation::compare_with_delaunay_2d_naive(
                xy, results[a].triangles, oracle, results[a].merged_into);
            if (!problem.empty()) fail(xy, label(a) + ": oracle: " + problem);
        }
    }
    return 0;
}
