// SPDX-License-Identifier: MIT
// Solution-weighted movement, 2D and 3D: with the indicator exp(-100 (x - 0.5)^2) on Delaunay
// meshes of random points the mean distance of the vertices to the line x = 0.5 decreases,
// the connectivity arrays are identical before and after, no element is flat or inverted (exact
// check), boundary, input, protected and constrained-edge vertices stay bit-identical; one
// sweep on a star matches the header's formula bit for bit, and a move is undone exactly when
// that target would invert a triangle; strength 0 is the Laplacian; coordinates x 2^-600 and
// x 2^600 give the same result scaled, bit for bit; bad indicators and options are InputErrors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/laplacian_smoothing_3d.hpp"
#include "generators/adaptation/mesh_movement_check.hpp"
#include "generators/adaptation/weighted_movement.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/point_sets_3d.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

/// The unit square's (cube's) 4 (8) corners, 20 (60) random points on each side (face), then
/// n random points inside: the boundary is sampled, so that moving the inside vertices does not
/// just shrink the mesh towards its middle.
std::vector<double> box_points(unsigned dimension, std::uint32_t n, std::uint64_t seed) {
    std::vector<double> xs;
    for (unsigned corner = 0; corner < (1u << dimension); ++corner) {
        for (unsigned d = 0; d < dimension; ++d) xs.push_back((corner >> d) & 1u ? 1.0 : 0.0);
    }
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int per_side = dimension == 2 ? 20 : 60;
    for (unsigned d = 0; d < dimension; ++d) {
        for (const double side : {0.0, 1.0}) {
            for (int i = 0; i < per_side; ++i) {
                for (unsigned e = 0; e < dimension; ++e) xs.push_back(e == d ? side : unit(random));
            }
        }
    }
    for (std::size_t i = 0; i < std::size_t{dimension} * n; ++i) xs.push_back(unit(random));
    return xs;
}

tri::Triangulation2 delaunay_2d(const std::vector<double>& xy) {
    const tri::Delaunay2Result r = tri::bowyer_watson_2d(xy);
    return {xy, r.triangles, r.neighbors, {}};
}

tri::Tetrahedralization3 delaunay_3d(const std::vector<double>& xyz) {
    return tri::bowyer_watson_3d(xyz).mesh;
}

double line_indicator(double x) {
    return std::exp(-100 * (x - 0.5) * (x - 0.5));
}

template <unsigned D>
std::vector<double> indicator_of(const std::vector<double>& coordinates) {
    std::vector<double> f(coordinates.size() / D);
    for (std::size_t v = 0; v < f.size(); ++v) f[v] = line_indicator(coordinates[D * v]);
    return f;
}

/// The mean of |x - 0.5| over the vertices with fixed[v] == 0.
template <unsigned D>
double mean_distance_to_line(const std::vector<double>& coordinates,
                             const std::vector<std::uint8_t>& fixed) {
    double sum = 0;
    int count = 0;
    for (std::size_t v = 0; v < fixed.size(); ++v) {
        if (fixed[v]) continue;
        sum += std::fabs(coordinates[D * v] - 0.5);
        ++count;
    }
    return sum / count;
}

/// The smallest 4 sqrt(3) A / (sum of squared edges) over the triangles, in long double.
long double worst_triangle_quality(const tri::Triangulation2& mesh) {
    long double worst = 1;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        long double p[3][2];
        for (unsigned k = 0; k < 3; ++k) {
            for (unsigned d = 0; d < 2; ++d) p[k][d] = mesh.point(mesh.triangles[3 * t + k])[d];
        }
        long double squares = 0;
        for (unsigned k = 0; k < 3; ++k) {
            const long double dx = p[(k + 1) % 3][0] - p[k][0], dy = p[(k + 1) % 3][1] - p[k][1];
            squares += dx * dx + dy * dy;
        }
        const long double twice_area =
            (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        worst = std::min(worst, 2 * std::sqrt(3.0L) * twice_area / squares);
    }
    return worst;
}

/// How many vertices lie within 0.1 of the line (plane) x = 0.5.
template <unsigned D>
int near_line(const std::vector<double>& coordinates) {
    int count = 0;
    for (std::size_t v = 0; v < coordinates.size() / D; ++v) {
        count += std::fabs(coordinates[D * v] - 0.5) < 0.1;
    }
    return count;
}

std::vector<double> scaled(std::vector<double> xs, int k) {
    for (double& x : xs) x = std::ldexp(x, k);
    return xs;
}

}  // namespace

TEST(Generators_WeightedMovement, VerticesCrowdTowardsAHighIndicatorLine2d) {
    for (const std::uint64_t seed : {1u, 2u}) {
        tri::Triangulation2 mesh = delaunay_2d(box_points(2, 600, seed));
        const tri::Triangulation2 before = mesh;
        const std::vector<std::uint8_t> fixed = gen::fixed_vertices_2d(mesh, 0);
        gen::WeightedMovementOptions options;
        options.sweeps = 30;
        options.relaxation = 0.5;
        // Indicator attached to the vertices, all sweeps in one call.
        const gen::WeightedMovementCounters c =
            gen::weighted_movement_2d(mesh, indicator_of<2>(mesh.xy), 0, options);
        EXPECT_GT(c.moves, 0u);
        EXPECT_EQ(c.free_vertices + c.fixed_vertices, mesh.vertex_count());
        const auto check = gen::check_mesh_movement_2d(before, mesh, fixed);
        ASSERT_TRUE(check.ok) << check.problem;
        const tri::CheckReport topology = tri::check_topology_2d(mesh.xy, mesh.triangles);
        EXPECT_TRUE(topology.ok) << topology.problem;
        const double d0 = mean_distance_to_line<2>(before.xy, fixed);
        const double d1 = mean_distance_to_line<2>(mesh.xy, fixed);
        EXPECT_LT(d1, 0.9 * d0) << seed;
        // Density near the line: the vertices within 0.1 of it.
        EXPECT_GT(near_line<2>(mesh.xy), 1.2 * near_line<2>(before.xy)) << seed;
        // Indicator re-evaluated at the moved vertices, one sweep per call: crowds further.
        tri::Triangulation2 again = before;
        options.sweeps = 1;
        for (int sweep = 0; sweep < 30; ++sweep) {
            gen::weighted_movement_2d(again, indicator_of<2>(again.xy), 0, options);
        }
        EXPECT_TRUE(gen::check_mesh_movement_2d(before, again, fixed).ok);
        EXPECT_LT(mean_distance_to_line<2>(again.xy, fixed), d1) << seed;
        // A flat indicator draws nowhere in particular: plain Laplacian, no crowding.
        tri::Triangulation2 flat = before;
        options.sweeps = 30;
        gen::weighted_movement_2d(flat, std::vector<double>(flat.vertex_count(), 3.0), 0, options);
        EXPECT_GT(mean_distance_to_line<2>(flat.xy, fixed), 0.95 * d0) << seed;
        EXPECT_LT(d1, 0.9 * mean_distance_to_line<2>(flat.xy, fixed)) << seed;
        // Smart: the worst triangle (4 sqrt(3) A / sum l^2, measured here in long double) does
        // not get worse, and the vertices still crowd, less.
        tri::Triangulation2 smart = before;
        options.smart = true;
        const auto cs = gen::weighted_movement_2d(smart, indicator_of<2>(smart.xy), 0, options);
        EXPECT_GT(cs.undone_worse, 0u);
        EXPECT_TRUE(gen::check_mesh_movement_2d(before, smart, fixed).ok);
        EXPECT_GE(worst_triangle_quality(smart), worst_triangle_quality(before) * (1 - 1e-12));
        EXPECT_LT(mean_distance_to_line<2>(smart.xy, fixed), d0) << seed;
    }
}

TEST(Generators_WeightedMovement, VerticesCrowdTowardsAHighIndicatorPlane3d) {
    tri::Tetrahedralization3 mesh = delaunay_3d(box_points(3, 1500, 4));
    const tri::Tetrahedralization3 before = mesh;
    const std::vector<std::uint8_t> fixed = gen::fixed_vertices_3d(mesh, 0);
    gen::WeightedMovementOptions options;
    options.sweeps = 20;
    options.relaxation = 0.5;
    const gen::WeightedMovementCounters c =
        gen::weighted_movement_3d(mesh, indicator_of<3>(mesh.xyz), 0, options);
    EXPECT_GT(c.moves, 0u);
    const auto check = gen::check_mesh_movement_3d(before, mesh, fixed);
    ASSERT_TRUE(check.ok) << check.problem;
    tri::TopologyOptions topology_options;
    topology_options.convex_boundary = true;
    const tri::TopologyReport3 topology = tri::check_topology_3d(mesh, topology_options);
    EXPECT_TRUE(topology.ok) << topology.problem;
    EXPECT_LT(mean_distance_to_line<3>(mesh.xyz, fixed),
              0.9 * mean_distance_to_line<3>(before.xyz, fixed));
    EXPECT_GT(near_line<3>(mesh.xyz), 1.2 * near_line<3>(before.xyz));
    // Smart: a move that lowers the worst quality of its star is refused too; the worst
    // tetrahedron of the mesh does not get worse, and the vertices still crowd, less.
    tri::Tetrahedralization3 smart = before;
    options.smart = true;
    const auto cs = gen::weighted_movement_3d(smart, indicator_of<3>(smart.xyz), 0, options);
    EXPECT_GT(cs.undone_worse, 0u);
    EXPECT_TRUE(gen::check_mesh_movement_3d(before, smart, fixed).ok);
    EXPECT_GE(tri::quality_stats_3d(smart).min_volume_edge,
              tri::quality_stats_3d(before).min_volume_edge * (1 - 1e-12));
    EXPECT_LT(mean_distance_to_line<3>(smart.xyz, fixed),
              mean_distance_to_line<3>(before.xyz, fixed));
}

TEST(Generators_WeightedMovement, ProtectedInputAndConstrainedVerticesStayBitIdentical) {
    tri::Triangulation2 mesh = delaunay_2d(box_points(2, 300, 8));
    // Constrain every edge of the first triangle that has no boundary edge.
    mesh.constrained.assign(mesh.triangles.size(), 0);
    tri::TriIdx chosen = tri::kNone;
    for (tri::TriIdx t = 0; t < mesh.triangle_count() && chosen == tri::kNone; ++t) {
        if (mesh.neighbors[3 * t] != tri::kNone && mesh.neighbors[3 * t + 1] != tri::kNone &&
            mesh.neighbors[3 * t + 2] != tri::kNone)
            chosen = t;
    }
    ASSERT_NE(chosen, tri::kNone);
    for (unsigned k = 0; k < 3; ++k) {
        const tri::TriIdx u = mesh.neighbors[3 * chosen + k];
        mesh.constrained[3 * chosen + k] = 1;
        for (unsigned j = 0; j < 3; ++j) {
            if (mesh.neighbors[3 * u + j] == chosen) mesh.constrained[3 * u + j] = 1;
        }
    }
    std::vector<std::uint8_t> protect(mesh.vertex_count(), 0);
    for (tri::VertIdx v = 100; v < mesh.vertex_count(); v += 7) protect[v] = 1;
    const tri::Triangulation2 before = mesh;
    const std::uint32_t fixed_below = 20;
    gen::WeightedMovementOptions options;
    options.sweeps = 5;
    const auto c =
        gen::weighted_movement_2d(mesh, indicator_of<2>(mesh.xy), fixed_below, options, protect);
    EXPECT_GT(c.moves, 0u);
    const std::vector<std::uint8_t> fixed = gen::fixed_vertices_2d(before, fixed_below, protect);
    EXPECT_TRUE(gen::check_mesh_movement_2d(before, mesh, fixed).ok);
    // Independently of fixed_vertices_2d.
    const auto same = [&](tri::VertIdx v) {
        return mesh.xy[2 * v] == before.xy[2 * v] && mesh.xy[2 * v + 1] == before.xy[2 * v + 1];
    };
    for (tri::VertIdx v = 0; v < fixed_below; ++v) EXPECT_TRUE(same(v)) << v;
    for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        if (protect[v]) {
            EXPECT_TRUE(same(v)) << v;
        }
        const double* p = before.point(v);
        if (p[0] == 0 || p[0] == 1 || p[1] == 0 || p[1] == 1) {
            EXPECT_TRUE(same(v)) << v;
        }
    }
    for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE(same(mesh.triangles[3 * chosen + k]));
    EXPECT_EQ(c.fixed_vertices,
              static_cast<std::uint64_t>(std::count(fixed.begin(), fixed.end(), 1)));
}

TEST(Generators_WeightedMovement, OneSweepOnAStarFollowsTheFormulaAndUndoesInvertingMoves) {
    // Random star polygons about a free centre (index k, after the fixed ring 0..k-1), random
    // indicator values: the target is recomputed here from the header's formula, and the move is
    // undone exactly when that target would invert a triangle.
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> radius(0.05, 1.0), jitter(-0.4, 0.4), value(0.0, 5.0);
    int undone = 0, moved = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int k = 3 + static_cast<int>(random() % 6);
        tri::Triangulation2 m;
        for (int i = 0; i < k; ++i) {
            const double a = 2 * std::numbers::pi * (i + 0.5 + jitter(random)) / k,
                         r = radius(random);
            m.xy.insert(m.xy.end(), {r * std::cos(a), r * std::sin(a)});
        }
        m.xy.insert(m.xy.end(), {0.0, 0.0});
        const auto c = static_cast<tri::VertIdx>(k);
        bool valid = true;
        for (int i = 0; i < k; ++i) {
            const auto a = static_cast<tri::VertIdx>(i), b = static_cast<tri::VertIdx>((i + 1) % k);
            m.triangles.insert(m.triangles.end(), {c, a, b});
            valid &= em::predicates::orient2d(m.point(c), m.point(a), m.point(b)) ==
                     em::predicates::Sign::Positive;
        }
        if (!valid) continue;
        m.neighbors.assign(m.triangles.size(), tri::kNone);
        for (int i = 0; i < k; ++i) {
            m.neighbors[3 * std::size_t(i)] = static_cast<tri::TriIdx>((i + k - 1) % k);
            m.neighbors[3 * std::size_t(i) + 2] = static_cast<tri::TriIdx>((i + 1) % k);
        }
        std::vector<double> f(std::size_t(k) + 1);
        for (double& x : f) x = value(random);
        const double omega = trial % 2 ? 1.0 : 0.75, strength = 2.5;
        // The header's formula, in its order.
        double largest = 0, sum = 0;
        for (const double x : f) largest = std::max(largest, x);
        std::vector<double> g(f.size());
        for (std::size_t v = 0; v < f.size(); ++v) sum += g[v] = f[v] / largest;
        const double mean = sum / static_cast<double>(f.size());
        double wx = 0, wy = 0, wsum = 0;
        for (int j = 0; j < k; ++j) {
            const double w = 1.0 + strength * ((g[c] + g[std::size_t(j)]) * 0.5 / mean);
            wsum += w;
            wx += w * (m.xy[2 * std::size_t(j)] - 0.0);
            wy += w * (m.xy[2 * std::size_t(j) + 1] - 0.0);
        }
        const double target[2] = {0.0 + omega * (wx / wsum), 0.0 + omega * (wy / wsum)};
        bool inverts = false;
        for (int i = 0; i < k; ++i) {
            inverts |= em::predicates::orient2d(target, m.point(static_cast<tri::VertIdx>(i)),
                                                m.point(static_cast<tri::VertIdx>((i + 1) % k))) !=
                       em::predicates::Sign::Positive;
        }
        gen::WeightedMovementOptions options;
        options.relaxation = omega;
        options.strength = strength;
        const auto counters = gen::weighted_movement_2d(m, f, 0, options);
        EXPECT_EQ(counters.free_vertices, 1u);
        EXPECT_EQ(counters.undone, inverts ? 1u : 0u) << trial;
        if (inverts) {
            ++undone;
            EXPECT_TRUE(m.xy[2 * c] == 0.0 && m.xy[2 * c + 1] == 0.0) << trial;
        } else {
            ++moved;
            EXPECT_EQ(m.xy[2 * c], target[0]) << trial;
            EXPECT_EQ(m.xy[2 * c + 1], target[1]) << trial;
        }
    }
    EXPECT_GT(undone, 10);
    EXPECT_GT(moved, 100);
}

TEST(Generators_WeightedMovement, StrengthZeroIsTheLaplacianBitForBit) {
    const std::vector<double> xyz = box_points(3, 300, 6);
    tri::Tetrahedralization3 laplacian = delaunay_3d(xyz), weighted = laplacian;
    gen::SmoothingOptions3 smoothing;
    smoothing.smart = false;
    smoothing.iterations = 3;
    smoothing.relaxation = 0.5;
    gen::WeightedMovementOptions options;
    options.sweeps = 3;
    options.relaxation = 0.5;
    options.strength = 0;
    const auto a = gen::laplacian_smoothing_3d(laplacian, 0, smoothing);
    const auto b = gen::weighted_movement_3d(weighted, indicator_of<3>(weighted.xyz), 0, options);
    EXPECT_EQ(weighted.xyz, laplacian.xyz);
    EXPECT_EQ(a.moves, b.moves);
    EXPECT_EQ(a.undone, b.undone);
}

TEST(Generators_WeightedMovement, ScaledByTwoToThePlusMinus600GivesTheSameResultScaled) {
    for (const bool smart : {false, true}) {
        gen::WeightedMovementOptions options;
        options.sweeps = 4;
        options.relaxation = 0.8;
        options.smart = smart;
        {
            const std::vector<double> xy = box_points(2, 400, 12);
            tri::Triangulation2 reference = delaunay_2d(xy);
            const std::vector<double> f = indicator_of<2>(xy);
            const auto c0 = gen::weighted_movement_2d(reference, f, 0, options);
            EXPECT_GT(c0.moves, 0u);
            for (const int k : {-600, 600}) {
                tri::Triangulation2 mesh = delaunay_2d(scaled(xy, k));
                ASSERT_EQ(mesh.triangles, delaunay_2d(xy).triangles);
                // The indicator's unit is free too: f x 2^k gives the same weights.
                const auto c = gen::weighted_movement_2d(mesh, scaled(f, k / 2), 0, options);
                EXPECT_EQ(c.moves, c0.moves);
                EXPECT_EQ(c.undone, c0.undone);
                EXPECT_EQ(c.undone_worse, c0.undone_worse);
                EXPECT_EQ(mesh.xy, scaled(reference.xy, k)) << k;
            }
        }
        {
            const std::vector<double> xyz = box_points(3, 400, 13);
            tri::Tetrahedralization3 reference = delaunay_3d(xyz);
            const std::vector<double> f = indicator_of<3>(xyz);
            const auto c0 = gen::weighted_movement_3d(reference, f, 0, options);
            EXPECT_GT(c0.moves, 0u);
            for (const int k : {-600, 600}) {
                tri::Tetrahedralization3 mesh = delaunay_3d(scaled(xyz, k));
                ASSERT_EQ(mesh.tets, reference.tets);
                const auto c = gen::weighted_movement_3d(mesh, f, 0, options);
                EXPECT_EQ(c.moves, c0.moves);
                EXPECT_EQ(c.undone, c0.undone);
                EXPECT_EQ(c.undone_worse, c0.undone_worse);
                EXPECT_EQ(mesh.xyz, scaled(reference.xyz, k)) << k;
            }
        }
    }
}

TEST(Generators_WeightedMovement, BadIndicatorsAndOptionsAreInputErrors) {
    tri::Triangulation2 mesh2 = delaunay_2d(box_points(2, 30, 1));
    tri::Tetrahedralization3 mesh3 = delaunay_3d(box_points(3, 30, 1));
    const std::vector<double> good2(mesh2.vertex_count(), 1.0), good3(mesh3.vertex_count(), 1.0);
    EXPECT_THROW(gen::weighted_movement_2d(mesh2, std::vector<double>(3, 1.0), 0), em::InputError);
    EXPECT_THROW(gen::weighted_movement_3d(mesh3, std::vector<double>(3, 1.0), 0), em::InputError);
    for (const double bad : {-1.0, std::nan(""), HUGE_VAL}) {
        std::vector<double> f2 = good2, f3 = good3;
        f2[7] = bad;
        f3[7] = bad;
        EXPECT_THROW(gen::weighted_movement_2d(mesh2, f2, 0), em::InputError) << bad;
        EXPECT_THROW(gen::weighted_movement_3d(mesh3, f3, 0), em::InputError) << bad;
        gen::WeightedMovementOptions options;
        options.strength = bad;
        EXPECT_THROW(gen::weighted_movement_2d(mesh2, good2, 0, options), em::InputError) << bad;
        options.strength = 0x1p51;
        EXPECT_THROW(gen::weighted_movement_3d(mesh3, good3, 0, options), em::InputError);
        options.strength = 1;
        options.relaxation = bad;
        EXPECT_THROW(gen::weighted_movement_3d(mesh3, good3, 0, options), em::InputError) << bad;
    }
    const std::vector<std::uint8_t> short_flags(3, 0);
    EXPECT_THROW(gen::weighted_movement_2d(mesh2, good2, 0, {}, short_flags), em::InputError);
    EXPECT_THROW(gen::weighted_movement_3d(mesh3, good3, 0, {}, short_flags), em::InputError);
    // Nothing moved by a refused call.
    EXPECT_EQ(mesh2.xy, box_points(2, 30, 1));
    EXPECT_EQ(mesh3.xyz, box_points(3, 30, 1));
}
