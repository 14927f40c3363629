// SPDX-License-Identifier: MIT
// Edge cutting (edge insertion) for the min-max angle triangulation: its largest angle equals,
// exactly, the optimum found by enumerating every triangulation (tests/oracles), over random and
// degenerate sets of up to 10 points; larger sets: valid, never worse than Delaunay or than
// min-max swapping; constrained edges kept.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/inputs/sweep_triangulation_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/oracles/triangulation_enumeration_2d.hpp"
#include "tests/support/constrained_sides_2d.hpp"
#include "tests/support/integer_points_2d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/modification/edge_cutting_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
namespace orc = exactmesh::oracles;

namespace {

std::string describe(const std::vector<double>& xy) {
    std::ostringstream s;
    s.precision(17);
    for (std::size_t i = 0; i < xy.size(); i += 2) s << '(' << xy[i] << ", " << xy[i + 1] << ") ";
    return s.str();
}

/// Edge cutting against the enumeration; returns the number of triangulations enumerated.
std::size_t expect_optimal(const std::vector<double>& xy) {
    const orc::MinMaxAngleOptimum optimum = orc::min_max_angle_by_enumeration(xy);
    tri::EdgeCuttingCounters counters;
    const tri::Triangulation2 mesh = tri::min_max_angle_triangulation_2d(xy, &counters);
    const tri::CheckReport report = tri::check_topology_2d(xy, mesh.triangles);
    EXPECT_TRUE(report.ok) << describe(xy) << report.problem;
    if (optimum.triangulations == 0) {
        EXPECT_TRUE(mesh.triangles.empty()) << describe(xy);
        return 0;
    }
    EXPECT_EQ(
        orc::compare_exact_angles(orc::largest_exact_angle(xy, mesh.triangles), optimum.angle), 0)
        << describe(xy);
    return optimum.triangulations;
}

/// EXACTMESH_TEST_SCALE (default 1) scales the number of random sets (sanitizer runs use 0.02).
using exactmesh::testing::test_scale;

using exactmesh::testing::integer_points;

}  // namespace

TEST(Triangulation_EdgeCutting2, EnumerationOracleCountsKnownFamilies) {
    // Convex n-gons have Catalan(n - 2) triangulations.
    const std::size_t catalan[] = {1, 1, 2, 5, 14, 42, 132, 429, 1430};
    for (std::uint32_t n = 3; n <= 10; ++n) {
        std::vector<double> xy;
        for (std::uint32_t i = 0; i < n; ++i) {
            // Points on the parabola y = x^2: convex position, exact.
            xy.insert(xy.end(), {double(i), double(i * i)});
        }
        EXPECT_EQ(orc::enumerate_triangulations_2d(xy, [](const std::vector<std::uint32_t>&) {}),
                  catalan[n - 2])
            << n;
    }
    // Square with its centre: the diagonals pass through the centre, so the fan around it is the
    // only triangulation.
    EXPECT_EQ(orc::enumerate_triangulations_2d(std::vector<double>{0, 0, 2, 0, 2, 2, 0, 2, 1, 1},
                                               [](const std::vector<std::uint32_t>&) {}),
              1u);
    // Collinear points: none.
    EXPECT_EQ(orc::enumerate_triangulations_2d(std::vector<double>{0, 0, 1, 1, 2, 2},
                                               [](const std::vector<std::uint32_t>&) {}),
              0u);
}

TEST(Triangulation_EdgeCutting2, MatchesExhaustiveEnumerationOnRandomSmallSets) {
    // 2 x 8 x 60 = 960 sets: n = 3..10, coordinates integers in [0, 8) (collinear and cocircular
    // subsets are frequent) or in [0, 1000).
    std::mt19937_64 rng(2024);
    std::size_t sets = 0, triangulations = 0;
    const int rounds = std::max(1, static_cast<int>(60 * std::min(1.0, test_scale())));
    for (int round = 0; round < rounds; ++round) {
        for (std::uint32_t n = 3; n <= 10; ++n) {
            for (const std::uint32_t range : {8u, 1000u}) {
                triangulations += expect_optimal(integer_points(n, range, rng));
                ++sets;
            }
        }
    }
    RecordProperty("sets", static_cast<int>(sets));
    RecordProperty("triangulations", static_cast<int>(triangulations));
    EXPECT_EQ(sets, 16u * static_cast<std::size_t>(rounds));
}

TEST(Triangulation_EdgeCutting2, MatchesExhaustiveEnumerationOnUniformDoubles) {
    const auto seeds =
        std::max<std::uint64_t>(8, static_cast<std::uint64_t>(120 * std::min(1.0, test_scale())));
    for (std::uint64_t seed = 1; seed <= seeds; ++seed) {
        const auto n = static_cast<std::uint32_t>(3 + seed % 8);
        expect_optimal(
            em::generators::generate_points_2d(em::generators::Distribution::Uniform, n, seed));
    }
}

TEST(Triangulation_EdgeCutting2, MatchesExhaustiveEnumerationOnDegenerateSets) {
    std::vector<std::vector<double>> sets;
    // Grids: every cell a cocircular quadruple, rows and columns collinear.
    for (int w = 2; w <= 5; ++w) {
        for (int h = 2; h * w <= 10; ++h) {
            std::vector<double> xy;
            for (int i = 0; i < w; ++i) {
                for (int j = 0; j < h; ++j) xy.insert(xy.end(), {double(i), double(j)});
            }
            sets.push_back(xy);
        }
    }
    // Cocircular: lattice points on x^2 + y^2 = 25, and subsets of them with the centre.
    const std::vector<double> circle{5,  0, 4,  3, 3,  4,  0,  5,  -3, 4,
                                     -4, 3, -5, 0, -4, -3, -3, -4, 0,  -5};
    sets.push_back(circle);
    for (std::size_t drop = 0; drop < 10; ++drop) {
        std::vector<double> xy;
        for (std::size_t i = 0; i < 10; ++i) {
            if (i != drop) xy.insert(xy.end(), {circle[2 * i], circle[2 * i + 1]});
        }
        xy.insert(xy.end(), {0.0, 0.0});
        sets.push_back(xy);
    }
    // Collinear subsets: a row with points above and below; a regular-ish convex hull with
    // collinear hull points; all collinear.
    sets.push_back({0, 0, 1, 0, 2, 0, 3, 0, 4, 0, 5, 0, 2.5, 1, 2.5, -1, 1, 3});
    sets.push_back({0, 0, 2, 0, 4, 0, 4, 2, 4, 4, 2, 4, 0, 4, 0, 2, 2, 2, 1, 1});
    sets.push_back({0, 0, 1, 1, 2, 2, 3, 3, 4, 4});
    sets.push_back({0, 0, 1, 1, 2, 2, 3, 3, 10, 0});
    // Points on a parabola (convex position, exact) and a near-degenerate sliver.
    sets.push_back({0, 0, 1, 1, 2, 4, 3, 9, 4, 16, 5, 25, 6, 36, 7, 49});
    sets.push_back({0, 0, 1, 1e-9, 2, 0, 1, -1e-9, 1, 5, 1, -5});
    for (const auto& xy : sets) expect_optimal(xy);
}

TEST(Triangulation_EdgeCutting2, LargerSetsNeverWorseThanDelaunayOrSwapping) {
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const auto xy = em::generators::generate_points_2d(
            seed % 2 ? em::generators::Distribution::Uniform : em::generators::Distribution::Grid,
            500, seed);
        tri::EdgeCuttingCounters counters;
        const tri::Triangulation2 cut = tri::min_max_angle_triangulation_2d(xy, &counters);
        const auto delaunay = tri::bowyer_watson_2d(xy);
        ASSERT_TRUE(tri::check_topology_2d(xy, cut.triangles).ok);
        EXPECT_EQ(cut.triangles.size(), delaunay.triangles.size());
        const orc::ExactAngle cut_angle = orc::largest_exact_angle(xy, cut.triangles);
        EXPECT_LE(
            orc::compare_exact_angles(cut_angle, orc::largest_exact_angle(xy, delaunay.triangles)),
            0);
        tri::Triangulation2 swapped;
        swapped.xy = xy;
        swapped.triangles = delaunay.triangles;
        swapped.neighbors = delaunay.neighbors;
        tri::swap_edges_2d(swapped, tri::MinMaxAngle{});
        EXPECT_LE(
            orc::compare_exact_angles(cut_angle, orc::largest_exact_angle(xy, swapped.triangles)),
            0);
        // From a bad start (the sweep), edge cutting reaches the same optimal value.
        tri::Triangulation2 sweep = em::generators::sweep_triangulation_2d(xy);
        tri::edge_cutting_2d(sweep);
        EXPECT_EQ(
            orc::compare_exact_angles(orc::largest_exact_angle(xy, sweep.triangles), cut_angle), 0);
        EXPECT_GT(counters.worst_triangles, 0u);
    }
}

TEST(Triangulation_EdgeCutting2, ConstrainedEdgesAreKept) {
    const auto xy =
        em::generators::generate_points_2d(em::generators::Distribution::Uniform, 300, 7);
    tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
    const auto constrained = em::testing::constrain_every_nth_side(mesh, 11);
    const orc::ExactAngle before = orc::largest_exact_angle(xy, mesh.triangles);
    const auto counters = tri::edge_cutting_2d(mesh);
    EXPECT_GT(counters.insertions, 0u);
    EXPECT_EQ(em::testing::constrained_edges(mesh), constrained);
    EXPECT_TRUE(tri::check_topology_2d(xy, mesh.triangles).ok);
    EXPECT_LT(orc::compare_exact_angles(orc::largest_exact_angle(xy, mesh.triangles), before), 0);
}

TEST(Triangulation_EdgeCutting2, RejectsNonFiniteInput) {
    const std::vector<double> xy{0, 0, 1, 0, std::nan(""), 1};
    try {
        tri::min_max_angle_triangulation_2d(xy);
        FAIL() << "NaN accepted";
    } catch (const em::NonFiniteCoordinate& e) {
        EXPECT_EQ(e.vertex(), 2u);
    }
}
