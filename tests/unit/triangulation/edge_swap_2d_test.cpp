// SPDX-License-Identifier: MIT
// Lawson edge swapping: Delaunay swapping reaches exactly delaunay_2d's triangulation from any
// start (sweep triangulations, every triangulation of small sets, degenerate families); the
// other criteria never worsen their measure and stop in a local optimum, which for min-max angle
// can be strictly worse than the global one (a fixed instance); constraints are never swapped;
// bad input is rejected.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/inputs/sweep_triangulation_2d.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "tests/oracles/triangulation_enumeration_2d.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
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

using Triangles = exactmesh::testing::CanonicalTriangles;
using exactmesh::testing::canonical_triangles;

/// EXACTMESH_TEST_SCALE (default 1) scales the sizes of the larger cases.
using exactmesh::testing::test_scale;

tri::Triangulation2 from_triangles(const std::vector<double>& xy,
                                   const std::vector<std::uint32_t>& triangles) {
    tri::Triangulation2 mesh;
    mesh.xy = xy;
    mesh.triangles = triangles;
    tri::link_neighbors_2d(mesh);
    return mesh;
}

/// Neighbors mutual and sharing the edge, every triangle strictly counter-clockwise.
void expect_consistent(const tri::Triangulation2& mesh) {
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        const tri::VertIdx* v = &mesh.triangles[3 * t];
        ASSERT_EQ(em::predicates::orient2d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])),
                  em::predicates::Sign::Positive);
        for (unsigned k = 0; k < 3; ++k) {
            const tri::TriIdx u = mesh.neighbors[3 * t + k];
            if (u == tri::kNone) continue;
            bool found = false;
            for (unsigned j = 0; j < 3; ++j) {
                found |= mesh.neighbors[3 * u + j] == t &&
                         mesh.triangles[3 * u + j] == v[(k + 1) % 3] &&
                         mesh.triangles[3 * u + (j + 1) % 3] == v[k];
            }
            ASSERT_TRUE(found) << "triangle " << t << " slot " << k;
        }
    }
}

std::vector<double> uniform(std::uint32_t n, std::uint64_t seed) {
    return em::generators::generate_points_2d(em::generators::Distribution::Uniform, n, seed);
}

using exactmesh::testing::integer_points;

/// Delaunay swapping from the sweep triangulation gives delaunay_2d's triangles exactly.
void expect_sweep_swaps_to_delaunay(const std::vector<double>& xy, const std::string& label) {
    tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
    const tri::EdgeSwapCounters counters = tri::swap_edges_2d(mesh, tri::Delaunay{});
    expect_consistent(mesh);
    const tri::Delaunay2Result delaunay = tri::bowyer_watson_2d(xy);
    ASSERT_EQ(canonical_triangles(mesh.triangles), canonical_triangles(delaunay.triangles))
        << label;
    const tri::CheckReport report = tri::check_delaunay_2d(xy, mesh.triangles);
    ASSERT_TRUE(report.ok) << label << ": " << report.problem;
    EXPECT_GE(counters.edges_tested, counters.swaps) << label;
}

/// The exact smallest and largest angles of a triangle list, for the monotonicity checks.
orc::ExactAngle smallest_exact_angle(std::span<const double> xy, std::span<const std::uint32_t> t) {
    orc::ExactAngle best{0, 0};
    for (std::size_t i = 0; i < t.size(); i += 3) {
        for (unsigned k = 0; k < 3; ++k) {
            const std::uint32_t o = t[i + k], p = t[i + (k + 1) % 3], q = t[i + (k + 2) % 3];
            const mpq_class ux = xy[2 * p] - mpq_class(xy[2 * o]);
            const mpq_class uy = xy[2 * p + 1] - mpq_class(xy[2 * o + 1]);
            const mpq_class vx = xy[2 * q] - mpq_class(xy[2 * o]);
            const mpq_class vy = xy[2 * q + 1] - mpq_class(xy[2 * o + 1]);
            const orc::ExactAngle a{ux * vx + uy * vy, ux * vy - uy * vx};
            if ((i == 0 && k == 0) || orc::compare_exact_angles(a, best) < 0) best = a;
        }
    }
    return best;
}

double total_length(const tri::Triangulation2& mesh) {
    long double sum = 0;
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const tri::VertIdx p = mesh.triangles[e], q = mesh.triangles[3 * (e / 3) + (e % 3 + 1) % 3];
        // Each interior edge twice, each hull edge once: a fixed weighting of the same edges.
        sum += std::hypot(mesh.point(p)[0] - mesh.point(q)[0], mesh.point(p)[1] - mesh.point(q)[1]);
    }
    return static_cast<double>(sum);
}

}  // namespace

TEST(Triangulation_EdgeSwap2, DelaunayFromSweepIsDelaunay2dOnRandomPoints) {
    const double scale = test_scale();
    for (const std::uint32_t n : {3u, 10u, 100u, 1000u, 20000u}) {
        const auto count =
            std::max<std::uint32_t>(3, static_cast<std::uint32_t>(n * std::min(1.0, scale)));
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            expect_sweep_swaps_to_delaunay(
                uniform(count, seed),
                "uniform n=" + std::to_string(count) + " seed=" + std::to_string(seed));
        }
    }
}

TEST(Triangulation_EdgeSwap2, DelaunayFromSweepIsDelaunay2dOnDegenerateFamilies) {
    using em::generators::Distribution;
    // Cocircular quadruples (grids, circles) and collinear runs: the SoS incircle makes the
    // answer unique, and swapping finds the same one as delaunay_2d.
    for (const Distribution d :
         {Distribution::Grid, Distribution::Cocircular, Distribution::NearCollinear,
          Distribution::Gaussian, Distribution::Huge, Distribution::Tiny}) {
        for (const std::uint32_t n : {5u, 50u, 500u}) {
            const auto xy = em::generators::generate_points_2d(d, n, 11);
            expect_sweep_swaps_to_delaunay(
                xy, std::string(em::generators::distribution_name(d)) + " n=" + std::to_string(n));
        }
    }
    // A 3x3 grid fan of every orientation, and points on one circle.
    std::vector<double> circle;
    // clang-format off
    for (const auto& [x, y] : std::vector<std::pair<int, int>>{
             {5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4},
             {0, -5}, {3, -4}, {4, -3}}) {
        // clang-format on
        circle.insert(circle.end(), {double(x), double(y)});
    }
    expect_sweep_swaps_to_delaunay(circle, "12 cocircular points");
}

TEST(Triangulation_EdgeSwap2, DelaunayFromEveryTriangulationOfSmallSets) {
    // Every triangulation of each set (the enumeration oracle) swaps to the same Delaunay
    // triangulation: the claim "from any starting triangulation", exhaustively for small sets.
    std::mt19937_64 rng(5);
    std::vector<std::vector<double>> sets;
    const int random_sets = std::max(4, static_cast<int>(60 * std::min(1.0, test_scale())));
    for (int i = 0; i < random_sets; ++i) {
        sets.push_back(integer_points(5 + i % 4, i % 2 ? 6 : 1000, rng));
    }
    sets.push_back({0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1, 0, 2, 1, 2, 2, 2});  // 3x3 grid
    sets.push_back({5, 0, 3, 4, 0, 5, -3, 4, -5, 0, -4, -3, 0, -5, 4, -3});  // cocircular
    std::size_t starts = 0;
    for (const auto& xy : sets) {
        const Triangles expected = canonical_triangles(tri::bowyer_watson_2d(xy).triangles);
        orc::enumerate_triangulations_2d(xy, [&](const std::vector<std::uint32_t>& t) {
            tri::Triangulation2 mesh = from_triangles(xy, t);
            tri::swap_edges_2d(mesh, tri::Delaunay{});
            ASSERT_EQ(canonical_triangles(mesh.triangles), expected);
            ++starts;
        });
    }
    EXPECT_GT(starts, random_sets == 60 ? 1000u : 100u);
}

TEST(Triangulation_EdgeSwap2, MaxMinAngleReachesDelaunayInGeneralPosition) {
    // Without cocircular quadruples the max-min angle swap test is the incircle test
    // [Lawson77; Sibson78], so swapping ends at the (unique) Delaunay triangulation, and the
    // smallest angle never decreases on the way.
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const auto xy = uniform(300, seed);
        tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
        const orc::ExactAngle before = smallest_exact_angle(xy, mesh.triangles);
        const auto counters = tri::swap_edges_2d(mesh, tri::MaxMinAngle{});
        expect_consistent(mesh);
        EXPECT_GT(counters.swaps, 0u);
        EXPECT_EQ(canonical_triangles(mesh.triangles),
                  canonical_triangles(tri::bowyer_watson_2d(xy).triangles));
        EXPECT_GE(orc::compare_exact_angles(smallest_exact_angle(xy, mesh.triangles), before), 0);
    }
}

TEST(Triangulation_EdgeSwap2, EveryCriterionImprovesItsMeasureAndStopsStable) {
    std::mt19937_64 rng(9);
    for (int round = 0; round < 6; ++round) {
        const auto xy = round % 2 ? uniform(400, static_cast<std::uint64_t>(round))
                                  : integer_points(300, 40, rng);
        const tri::Triangulation2 start = em::generators::sweep_triangulation_2d(xy);
        {
            tri::Triangulation2 mesh = start;
            tri::swap_edges_2d(mesh, tri::MinMaxAngle{});
            expect_consistent(mesh);
            EXPECT_LE(orc::compare_exact_angles(orc::largest_exact_angle(xy, mesh.triangles),
                                                orc::largest_exact_angle(xy, start.triangles)),
                      0);
            EXPECT_EQ(tri::swap_edges_2d(mesh, tri::MinMaxAngle{}).swaps, 0u);
            EXPECT_TRUE(tri::check_topology_2d(xy, mesh.triangles).ok);
        }
        {
            tri::Triangulation2 mesh = start;
            tri::swap_edges_2d(mesh, tri::MaxMinAngle{});
            expect_consistent(mesh);
            EXPECT_GE(orc::compare_exact_angles(smallest_exact_angle(xy, mesh.triangles),
                                                smallest_exact_angle(xy, start.triangles)),
                      0);
            EXPECT_EQ(tri::swap_edges_2d(mesh, tri::MaxMinAngle{}).swaps, 0u);
        }
        {
            tri::Triangulation2 mesh = start;
            const auto counters = tri::swap_edges_2d(mesh, tri::MinTotalLength{});
            expect_consistent(mesh);
            EXPECT_GT(counters.swaps, 0u);
            EXPECT_LT(total_length(mesh), total_length(start));
            EXPECT_EQ(tri::swap_edges_2d(mesh, tri::MinTotalLength{}).swaps, 0u);
        }
        for (const tri::DataCost cost :
             {tri::DataCost::AngleBetweenNormals, tri::DataCost::JumpInNormalDerivatives}) {
            std::vector<double> values;
            for (std::size_t v = 0; v < xy.size() / 2; ++v) {
                values.push_back(
                    std::tanh(8.0 * (xy[2 * v] - 0.5 * xy[2 * v + 1]) / (round % 2 ? 1.0 : 40.0)));
            }
            tri::Triangulation2 mesh = start;
            const auto counters = tri::swap_edges_2d(mesh, tri::DataDependent{values, cost});
            expect_consistent(mesh);
            EXPECT_GT(counters.swaps, 0u);
            EXPECT_EQ(tri::swap_edges_2d(mesh, tri::DataDependent{values, cost}).swaps, 0u);
        }
    }
}

TEST(Triangulation_EdgeSwap2, DataDependentHandExamples) {
    // Unit square a(0,0) b(1,0) c(1,1) d(0,1), data 1 at d only. Diagonal bd: planes z = y and
    // z = 1 - x, normals 60 degrees apart; diagonal ac: planes z = 0 and z = y - x, 54.7
    // degrees. ABN swaps bd into ac.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1};
    const std::vector<double> values{0, 0, 0, 1};
    tri::Triangulation2 mesh = from_triangles(xy, {0, 1, 3, 1, 2, 3});
    const auto counters =
        tri::swap_edges_2d(mesh, tri::DataDependent{values, tri::DataCost::AngleBetweenNormals});
    EXPECT_EQ(counters.swaps, 1u);
    EXPECT_EQ(canonical_triangles(mesh.triangles), (Triangles{{0, 1, 2}, {0, 2, 3}}));
    // Linear data on integer points: every gradient is computed exactly (integer numerators
    // and an exact quotient), every cost is exactly zero, nothing improves, nothing swaps.
    std::mt19937_64 rng(3);
    const auto xy2 = integer_points(200, 64, rng);
    std::vector<double> linear;
    for (std::size_t v = 0; v < xy2.size() / 2; ++v)
        linear.push_back(2 * xy2[2 * v] - 3 * xy2[2 * v + 1]);
    const tri::Triangulation2 sweep = em::generators::sweep_triangulation_2d(xy2);
    for (const tri::DataCost cost :
         {tri::DataCost::AngleBetweenNormals, tri::DataCost::JumpInNormalDerivatives}) {
        tri::Triangulation2 copy = sweep;
        EXPECT_EQ(tri::swap_edges_2d(copy, tri::DataDependent{linear, cost}).swaps, 0u);
    }
    // Wrong number of values, and a NaN value.
    EXPECT_THROW(tri::swap_edges_2d(mesh, tri::DataDependent{std::vector<double>{1.0}}),
                 em::InputError);
    const std::vector<double> nan_values{0, std::numeric_limits<double>::quiet_NaN(), 0, 1};
    try {
        tri::swap_edges_2d(mesh, tri::DataDependent{nan_values});
        FAIL() << "NaN value accepted";
    } catch (const em::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("vertex 1"), std::string::npos) << e.what();
    }
}

TEST(Triangulation_EdgeSwap2, JumpInNormalDerivativesIsScaleInvariant) {
    // JND costs are homogeneous in the coordinates: the mesh scaled by 2^+-600 (same data) makes
    // the same swaps. Its triangles' doubled areas there are 2^+-1200 times the unscaled ones,
    // beyond doubles, which left every edge unswapped before the costs took coordinates scaled
    // by the exponent of the largest one.
    const auto xy = uniform(400, 11);
    std::vector<double> values;
    for (std::size_t v = 0; v < xy.size() / 2; ++v)
        values.push_back(std::tanh(8.0 * (xy[2 * v] - 0.5 * xy[2 * v + 1])));
    const tri::Triangulation2 start = em::generators::sweep_triangulation_2d(xy);
    tri::Triangulation2 reference = start;
    const auto counters = tri::swap_edges_2d(
        reference, tri::DataDependent{values, tri::DataCost::JumpInNormalDerivatives});
    EXPECT_GT(counters.swaps, 0u);
    for (const int k : {600, -600, 3, -3}) {
        tri::Triangulation2 mesh = start;
        for (double& x : mesh.xy) x = std::ldexp(x, k);
        const auto scaled = tri::swap_edges_2d(
            mesh, tri::DataDependent{values, tri::DataCost::JumpInNormalDerivatives});
        EXPECT_EQ(scaled.swaps, counters.swaps) << "2^" << k;
        EXPECT_EQ(canonical_triangles(mesh.triangles), canonical_triangles(reference.triangles))
            << "2^" << k;
    }
}

TEST(Triangulation_EdgeSwap2, MinMaxAngleSwappingStopsInALocalOptimum) {
    // Found by random search over small integer sets (start: the Delaunay triangulation; global
    // optimum: edge_cutting_2d, confirmed by enumerating every triangulation). Min-max angle
    // swapping stops at a largest angle of 126.87 degrees (no single swap helps), while the
    // optimum is 113.20 degrees: reaching it needs an edge insertion that crosses several
    // edges at once [EdelsbrunnerTanWaupotitsch92].
    const std::vector<double> xy{17, 12, 17, 5, 7, 16, 14, 16, 10, 2, 0, 8};
    const tri::Delaunay2Result delaunay = tri::bowyer_watson_2d(xy);
    tri::Triangulation2 mesh;
    mesh.xy = xy;
    mesh.triangles = delaunay.triangles;
    mesh.neighbors = delaunay.neighbors;
    tri::swap_edges_2d(mesh, tri::MinMaxAngle{});
    EXPECT_EQ(tri::swap_edges_2d(mesh, tri::MinMaxAngle{}).swaps, 0u);  // a local optimum
    const orc::ExactAngle local = orc::largest_exact_angle(xy, mesh.triangles);
    const orc::ExactAngle optimum = orc::min_max_angle_by_enumeration(xy).angle;
    const tri::Triangulation2 cut = tri::min_max_angle_triangulation_2d(xy);
    EXPECT_EQ(orc::compare_exact_angles(orc::largest_exact_angle(xy, cut.triangles), optimum), 0);
    EXPECT_GT(orc::compare_exact_angles(local, optimum), 0);
    const double local_degrees = std::atan2(local.cross.get_d(), local.dot.get_d()) * 180 / M_PI;
    const double optimum_degrees =
        std::atan2(optimum.cross.get_d(), optimum.dot.get_d()) * 180 / M_PI;
    EXPECT_NEAR(local_degrees, 126.869898, 1e-5);
    EXPECT_NEAR(optimum_degrees, 113.198591, 1e-5);
}

TEST(Triangulation_EdgeSwap2, ConstrainedEdgesAreNeverSwapped) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const auto xy = uniform(500, seed);
        tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
        // Constrain every 7th interior edge of the sweep (long, thin: most would be swapped).
        const auto constrained = em::testing::constrain_every_nth_side(mesh, 7);
        const auto counters = tri::swap_edges_2d(mesh, tri::Delaunay{});
        expect_consistent(mesh);
        EXPECT_GT(counters.swaps, 0u);
        EXPECT_EQ(em::testing::constrained_edges(mesh), constrained);
        // Every unconstrained interior edge is now locally Delaunay (or not flippable).
        for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
            if (mesh.neighbors[e] == tri::kNone || mesh.constrained[e] != 0) continue;
            const std::size_t t = e / 3;
            const tri::VertIdx a = mesh.triangles[e], b = mesh.triangles[3 * t + (e % 3 + 1) % 3],
                               c = mesh.triangles[3 * t + (e % 3 + 2) % 3];
            const tri::TriIdx u = mesh.neighbors[e];
            tri::VertIdx d = tri::kNone;
            for (unsigned j = 0; j < 3; ++j) {
                const tri::VertIdx w = mesh.triangles[3 * u + j];
                if (w != a && w != b) d = w;
            }
            EXPECT_NE(em::predicates::incircle(mesh.point(a), mesh.point(b), mesh.point(c),
                                               mesh.point(d)),
                      em::predicates::Sign::Positive);
        }
    }
}

TEST(Triangulation_EdgeSwap2, CollinearAndTinyInputs) {
    // Collinear points: no triangle, nothing to swap. One triangle: no interior edge.
    for (auto xy :
         {std::vector<double>{0, 0, 1, 1, 2, 2, 3, 3}, std::vector<double>{0, 0, 1, 0, 0, 1}}) {
        tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
        EXPECT_EQ(tri::swap_edges_2d(mesh, tri::Delaunay{}).swaps, 0u);
        EXPECT_EQ(tri::swap_edges_2d(mesh, tri::MinMaxAngle{}).edges_tested, 0u);
    }
    // Collinear runs inside a set: a row of 10 points plus two apexes above and below.
    std::vector<double> xy;
    for (int i = 0; i < 10; ++i) xy.insert(xy.end(), {double(i), 0.0});
    xy.insert(xy.end(), {4.5, 3.0, 4.5, -0.5});
    expect_sweep_swaps_to_delaunay(xy, "collinear row with apexes");
    for (auto* run :
         {+[](tri::Triangulation2& m) { return tri::swap_edges_2d(m, tri::MinMaxAngle{}); },
          +[](tri::Triangulation2& m) { return tri::swap_edges_2d(m, tri::MaxMinAngle{}); },
          +[](tri::Triangulation2& m) { return tri::swap_edges_2d(m, tri::MinTotalLength{}); }}) {
        tri::Triangulation2 mesh = em::generators::sweep_triangulation_2d(xy);
        run(mesh);
        expect_consistent(mesh);
        EXPECT_TRUE(tri::check_topology_2d(xy, mesh.triangles).ok);
    }
}

TEST(Triangulation_EdgeSwap2, RejectsNonFiniteCoordinatesAndBadTriangles) {
    tri::Triangulation2 mesh = from_triangles({0, 0, 1, 0, 1, 1, 0, 1}, {0, 1, 3, 1, 2, 3});
    mesh.xy[5] = std::numeric_limits<double>::quiet_NaN();
    try {
        tri::swap_edges_2d(mesh, tri::Delaunay{});
        FAIL() << "NaN accepted";
    } catch (const em::NonFiniteCoordinate& e) {
        EXPECT_EQ(e.vertex(), 2u);
        EXPECT_NE(std::string(e.what()).find("point 2"), std::string::npos) << e.what();
    }
    EXPECT_THROW(tri::edge_cutting_2d(mesh), em::NonFiniteCoordinate);
    EXPECT_THROW(tri::link_neighbors_2d(mesh), em::NonFiniteCoordinate);
    // Clockwise triangle, repeated directed edge, vertex out of range.
    EXPECT_THROW(from_triangles({0, 0, 1, 0, 0, 1}, {0, 2, 1}), em::InputError);
    EXPECT_THROW(from_triangles({0, 0, 1, 0, 0, 1, 1, 1}, {0, 1, 2, 0, 1, 3}), em::InputError);
    EXPECT_THROW(from_triangles({0, 0, 1, 0, 0, 1}, {0, 1, 7}), em::InputError);
    EXPECT_EQ(tri::swap_criterion_from_name("min-length"), tri::SwapCriterion::MinTotalLength);
    EXPECT_THROW(tri::swap_criterion_from_name("fastest"), em::InputError);
}
