// SPDX-License-Identifier: MIT
// libFuzzer target: the two 3D Delaunay constructions (Bowyer-Watson, Green-Sibson) on up to
// kMaxPoints fuzzed points. Each output must pass the exact check (triangulation/checks/check_3d,
// with its neighbor array) and keep the points; the two must agree exactly for the same insertion
// order (shared perturbation, same kept copies of duplicates), and for different orders when no
// point repeats; Bowyer-Watson on 2 threads (parallel_bowyer_watson_3d, parallel rounds from 4
// points per thread) must give exactly the sequential brio order's tetrahedra; small inputs match
// the naive empty-sphere oracle (every 4-subset whose perturbed circumsphere is empty). Non-finite
// input must make both throw NonFiniteCoordinate naming the first bad point. Anything else is
// __builtin_trap().
//
// Input layout: the first 8·floor(size/8) bytes are doubles copied bit for bit, x0 y0 z0 x1 ...
// (a partial last point is dropped). The size % 8 bytes left over are the optional trailer: a
// mode byte and a parameter byte that reshape the raw values towards what random bits almost
// never produce (see reshape()): lattices, ulp-perturbed lattices, duplicates, exactly
// cospherical points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <set>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "tests/fuzz/fuzz_points.hpp"
#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/compare_tetrahedralizations_3d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"

namespace {

namespace fz = exactmesh::fuzz;
namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 160;
/// Raw bit patterns put coordinates at every magnitude, where every predicate ends in GMP.
constexpr std::size_t kMaxRawPoints = 40;
/// The oracle is O(n^5); above this it is skipped.
constexpr std::size_t kOracleMaxPoints = 12;

const std::array<tri::Delaunay3Function, 2> kAlgorithms = {
    tri::delaunay_3d_algorithm("bowyer-watson"), tri::delaunay_3d_algorithm("green-sibson")};
constexpr std::array<const char*, 2> kNames = {"bowyer-watson", "green-sibson"};
constexpr std::array<tri::InsertionOrder, 3> kOrders = {
    tri::InsertionOrder::Given, tri::InsertionOrder::Random, tri::InsertionOrder::Brio};

enum class Mode : std::uint8_t { raw, lattice, ulps, duplicates, cospherical, count };

/// All integer points of x^2 + y^2 + z^2 = 15^2 (exactly cospherical).
const std::vector<std::array<int, 3>>& sphere_points() {
    static const std::vector<std::array<int, 3>> points = [] {
        constexpr int r = 15;
        std::vector<std::array<int, 3>> out;
        for (int x = -r; x <= r; ++x)
            for (int y = -r; y <= r; ++y)
                for (int z = -r; z <= r; ++z)
                    if (x * x + y * y + z * z == r * r) out.push_back({x, y, z});
        return out;
    }();
    return points;
}

void reshape(std::vector<double>& xyz, Mode mode, std::uint8_t parameter) {
    if (mode != Mode::cospherical) {
        // The shared modes: lattices of 2- to 6-bit integers, 8 x 8 x 8 ulp lattices.
        fz::reshape_shared(xyz, 3, mode, parameter, {2, 3, 4, 6}, 8);
        return;
    }
    // Lattice points of one sphere, possibly its centre, on up to four spheres with
    // integer centres; scaled by a power of two.
    const auto& sphere = sphere_points();
    const int scale = static_cast<int>(parameter >> 2) * 16 - 500;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        const std::uint64_t b = fz::bits_of(xyz[i]);
        const auto& p = sphere[b % sphere.size()];
        const int centre = static_cast<int>(fz::bits_of(xyz[i + 1]) % (1u + (parameter & 3u))) * 20;
        const bool at_centre = (b >> 20) % 16 == 0;
        for (std::size_t c = 0; c < 3; ++c) {
            xyz[i + c] = std::ldexp(
                static_cast<double>((at_centre ? 0 : p[c]) + (c == 0 ? centre : 0)), scale);
        }
    }
}

[[noreturn]] void fail(const std::vector<double>& xyz, const std::string& what) {
    fz::fail_points("fuzz_delaunay_3d", xyz, 3, what);
}

bool has_duplicates(const std::vector<double>& xyz) {
    std::set<std::array<double, 3>> seen;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        if (!seen.insert({xyz[i] + 0.0, xyz[i + 1] + 0.0, xyz[i + 2] + 0.0}).second) return true;
    }
    return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fz::PointsInput<Mode> in = fz::decode_points<Mode>(data, size, 3, kMaxPoints, kMaxRawPoints);
    std::vector<double>& xyz = in.xs;
    reshape(xyz, in.mode, in.parameter);
    const std::uint64_t hash = in.hash;  // orders and seed from the data too
    const tri::Delaunay3Options same{kOrders[hash % 3], hash >> 8};
    const tri::Delaunay3Options other{kOrders[(hash >> 2) % 3], (hash >> 8) + 1};
    if (fz::check_non_finite_rejected(
            xyz, 3, kAlgorithms.size(), [&](std::size_t a) { kAlgorithms[a](xyz, same); },
            [](std::size_t a) { return std::string(kNames[a]); },
            [&](const std::string& what) { fail(xyz, what); })) {
        return 0;
    }

    std::array<tri::Delaunay3Result, 2> results;
    for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
        try {
            results[a] = kAlgorithms[a](xyz, same);
        } catch (const std::exception& e) {
            fail(xyz, std::string(kNames[a]) + " threw on finite input: " + e.what());
        }
        const tri::Check3Report report = tri::check_delaunay_3d(results[a].mesh);
        if (!report.ok) fail(xyz, std::string(kNames[a]) + ": check: " + report.problem);
        if (results[a].mesh.xyz != xyz) fail(xyz, std::string(kNames[a]) + ": points changed");
    }
    if (exactmesh::oracles::tet_set(results[1].mesh.tets) !=
            exactmesh::oracles::tet_set(results[0].mesh.tets) ||
        results[1].merged_into != results[0].merged_into ||
        results[1].coplanar != results[0].coplanar) {
        fail(xyz, "green-sibson and bowyer-watson differ for the same insertion order");
    }
    // 2 threads against one, both in the brio order of the same seed (the same kept copies).
    tri::Delaunay3Options brio{tri::InsertionOrder::Brio, hash >> 8};
    const tri::Delaunay3Result one_thread = kAlgorithms[0](xyz, brio);
    brio.threads = 2;
    brio.parallel_round_minimum = 4;
    tri::Delaunay3Result two_threads;
    try {
        two_threads = kAlgorithms[0](xyz, brio);
    } catch (const std::exception& e) {
        fail(xyz, std::string("bowyer-watson --threads 2 threw on finite input: ") + e.what());
    }
    if (tri::canonical_tetrahedra_3d(two_threads.mesh.tets) !=
            tri::canonical_tetrahedra_3d(one_thread.mesh.tets) ||
        two_threads.merged_into != one_thread.merged_into ||
        two_threads.coplanar != one_thread.coplanar) {
        fail(xyz, "bowyer-watson on 2 threads differs from 1 thread");
    }
    const tri::Check3Report parallel_report = tri::check_delaunay_3d(two_threads.mesh);
    if (!parallel_report.ok)
        fail(xyz, "bowyer-watson --threads 2: check: " + parallel_report.problem);
    if (!has_duplicates(xyz)) {
        const tri::Delaunay3Result again = kAlgorithms[hash % 2](xyz, other);
        if (exactmesh::oracles::tet_set(again.mesh.tets) !=
            exactmesh::oracles::tet_set(results[0].mesh.tets)) {
            fail(xyz, std::string(kNames[hash % 2]) +
                          ": another insertion order gives other tetrahedra");
        }
        if (xyz.size() / 3 <= kOracleMaxPoints &&
            exactmesh::oracles::tet_set(results[0].mesh.tets) !=
                exactmesh::oracles::empty_sphere_delaunay_3d(xyz)) {
            fail(xyz, "the tetrahedra differ from the naive empty-sphere oracle");
        }
    }
    return 0;
}
