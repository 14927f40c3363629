// SPDX-License-Identifier: MIT
// Laplacian smoothing in 3D: on Delaunay tetrahedralizations of a jittered grid, random points
// and the exact cubic grid, every tetrahedron stays strictly positive (exact check), the
// connectivity and every boundary vertex stay bit-identical and the mean (and worst) quality
// improve; on random star polyhedra a move is undone exactly when the centroid would invert a
// tetrahedron (decided independently), and counted; coordinates x 2^-600 and x 2^600 give the
// same result scaled, bit for bit; bad options and arrays are InputErrors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/laplacian_smoothing_3d.hpp"
#include "generators/adaptation/mesh_movement_check.hpp"
#include "predicates/orient3d.hpp"
#include "tests/support/point_sets_3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

tri::Tetrahedralization3 delaunay(const std::vector<double>& xyz) {
    tri::Delaunay3Result r = tri::bowyer_watson_3d(xyz);
    EXPECT_FALSE(r.coplanar);
    return std::move(r.mesh);
}

/// The side^3 grid on [0, side-1]^3 with every interior point moved by up to `jitter` grid
/// units in each coordinate (the boundary points stay on the cube's faces).
std::vector<double> jittered_grid(int side, double jitter, std::uint64_t seed) {
    std::vector<double> xyz = em::testing::cubic_grid_3d(side);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> shift(-jitter, jitter);
    for (std::size_t v = 0; v < xyz.size() / 3; ++v) {
        bool interior = true;
        for (unsigned d = 0; d < 3; ++d) {
            interior = interior && xyz[3 * v + d] > 0 && xyz[3 * v + d] < side - 1;
        }
        if (!interior) continue;
        for (unsigned d = 0; d < 3; ++d) xyz[3 * v + d] += shift(random);
    }
    return xyz;
}

bool on_box_boundary(const double* p, double lo, double hi) {
    for (unsigned d = 0; d < 3; ++d) {
        if (p[d] == lo || p[d] == hi) return true;
    }
    return false;
}

void expect_valid_movement(const tri::Tetrahedralization3& before,
                           const tri::Tetrahedralization3& after, std::uint32_t fixed_below = 0) {
    const auto check =
        gen::check_mesh_movement_3d(before, after, gen::fixed_vertices_3d(before, fixed_below));
    EXPECT_TRUE(check.ok) << check.problem;
    tri::TopologyOptions options;
    options.convex_boundary = true;
    const tri::TopologyReport3 topology = tri::check_topology_3d(after, options);
    EXPECT_TRUE(topology.ok) << topology.problem;
}

std::vector<double> scaled(std::vector<double> xyz, int k) {
    for (double& x : xyz) x = std::ldexp(x, k);
    return xyz;
}

// Smoothing options with these sweeps, relaxation and smart flag.
gen::SmoothingOptions3 smoothing_options(std::uint32_t iterations, double relaxation, bool smart) {
    gen::SmoothingOptions3 options;
    options.iterations = iterations;
    options.relaxation = relaxation;
    options.smart = smart;
    return options;
}

}  // namespace

TEST(Generators_LaplacianSmoothing3, JitteredGridStaysValidBoundaryStaysAndQualityImproves) {
    for (const bool smart : {false, true}) {
        for (const std::uint64_t seed : {1u, 2u, 3u}) {
            const int side = 7;
            tri::Tetrahedralization3 mesh = delaunay(jittered_grid(side, 0.35, seed));
            const tri::Tetrahedralization3 before = mesh;
            const tri::QualityStats3 q0 = tri::quality_stats_3d(mesh);
            const gen::SmoothingOptions3 options = smoothing_options(5, 0.5, smart);
            const gen::SmoothingCounters3 c = gen::laplacian_smoothing_3d(mesh, 0, options);
            EXPECT_EQ(c.sweeps, 5u);
            EXPECT_GT(c.moves, 0u);
            EXPECT_EQ(c.free_vertices, std::uint64_t((side - 2) * (side - 2) * (side - 2)));
            EXPECT_EQ(c.free_vertices + c.fixed_vertices, mesh.vertex_count());
            expect_valid_movement(before, mesh);
            // Independently of fixed_vertices_3d: every point on the cube's surface is unmoved.
            for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
                if (!on_box_boundary(before.point(v), 0.0, side - 1.0)) continue;
                for (unsigned d = 0; d < 3; ++d) {
                    EXPECT_EQ(mesh.xyz[3 * v + d], before.xyz[3 * v + d]);
                }
            }
            const tri::QualityStats3 q1 = tri::quality_stats_3d(mesh);
            EXPECT_GT(q1.mean_volume_edge, q0.mean_volume_edge) << seed << smart;
            if (smart) {
                // No star's worst tetrahedron got worse, so neither did the mesh's (up to the
                // rounding of the two different evaluations of the measure).
                EXPECT_GT(c.undone_worse, 0u);
                EXPECT_GE(q1.min_volume_edge, q0.min_volume_edge * (1 - 1e-12)) << seed;
                EXPECT_GE(q1.min_dihedral_degrees, 0.5 * q0.min_dihedral_degrees) << seed;
            } else {
                // Why smart is the default: plain Laplacian smoothing makes slivers.
                EXPECT_EQ(c.undone_worse, 0u);
                EXPECT_LT(q1.min_volume_edge, 0.5 * q0.min_volume_edge) << seed;
            }
        }
    }
}

TEST(Generators_LaplacianSmoothing3, RandomPointsInABoxStayValidWithHullAndInputVerticesFixed) {
    std::vector<double> xyz = em::testing::random_points_3d(400, 11);
    tri::Tetrahedralization3 mesh = delaunay(xyz);
    const tri::Tetrahedralization3 before = mesh;
    const tri::QualityStats3 q0 = tri::quality_stats_3d(mesh);
    const gen::SmoothingOptions3 options = smoothing_options(4, 0.5, true);  // smart: the default
    const std::uint32_t fixed_below = 50;  // as if the first 50 were a generator's input
    const gen::SmoothingCounters3 c = gen::laplacian_smoothing_3d(mesh, fixed_below, options);
    EXPECT_GT(c.moves, 0u);
    expect_valid_movement(before, mesh, fixed_below);
    for (tri::VertIdx v = 0; v < fixed_below; ++v) {
        for (unsigned d = 0; d < 3; ++d) EXPECT_EQ(mesh.xyz[3 * v + d], before.xyz[3 * v + d]);
    }
    EXPECT_GT(tri::quality_stats_3d(mesh).mean_volume_edge, q0.mean_volume_edge);
}

TEST(Generators_LaplacianSmoothing3, ExactCubicGridWithCosphericalCubesStaysValid) {
    // Every unit cube's eight corners are cospherical: the Delaunay tetrahedralization is a
    // symbolic choice, and the neighbour centroids are not the grid points. Many moves, and
    // every one that would flatten a tetrahedron is refused.
    tri::Tetrahedralization3 mesh = delaunay(em::testing::cubic_grid_3d(6));
    const tri::Tetrahedralization3 before = mesh;
    gen::SmoothingOptions3 options;
    options.iterations = 10;
    const gen::SmoothingCounters3 c = gen::laplacian_smoothing_3d(mesh, 0, options);
    EXPECT_EQ(c.free_vertices, 64u);
    expect_valid_movement(before, mesh);
}

TEST(Generators_LaplacianSmoothing3, AMoveIsUndoneExactlyWhenTheCentroidWouldInvertTheStar) {
    // Random star polyhedra about a free centre at the origin: the cone from the centre over the
    // hull of random directions, each direction scaled by a random radius. The centroid of a
    // non-convex star may lie outside its kernel.
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> radius(0.05, 1.0), normal(-1.0, 1.0);
    int undone = 0, moved = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const int k = 6 + static_cast<int>(random() % 10);
        std::vector<double> directions;
        for (int i = 0; i < k; ++i) {
            double p[3] = {normal(random), normal(random), normal(random)};
            const double norm = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            for (const double x : p) directions.push_back(x / norm);
        }
        const tri::Tetrahedralization3 hull = delaunay(directions);
        // Ring vertices 0..k-1 (scaled directions), the centre k at the origin.
        tri::Tetrahedralization3 star;
        for (int i = 0; i < k; ++i) {
            const double r = radius(random);
            for (unsigned d = 0; d < 3; ++d) star.xyz.push_back(r * directions[3 * i + d]);
        }
        star.xyz.insert(star.xyz.end(), {0.0, 0.0, 0.0});
        const auto centre = static_cast<tri::VertIdx>(k);
        bool valid = true;
        for (std::size_t f = 0; f < hull.tets.size(); ++f) {
            if (hull.neighbors[f] != tri::kNone) continue;
            // The hull face opposite corner f%4, seen from that corner: (a, b, c) with the centre
            // on the inner side; orient it so that (a, b, c, centre) is positive.
            const std::size_t t = f - f % 4;
            std::vector<tri::VertIdx> face;
            for (std::size_t j = t; j < t + 4; ++j) {
                if (j != f) face.push_back(hull.tets[j]);
            }
            tri::VertIdx a = face[0], b = face[1], c = face[2];
            if (em::predicates::orient3d(hull.point(a), hull.point(b), hull.point(c),
                                         hull.point(hull.tets[f])) !=
                em::predicates::Sign::Positive)
                std::swap(a, b);
            star.tets.insert(star.tets.end(), {a, b, c, centre});
            valid &= em::predicates::orient3d(star.point(a), star.point(b), star.point(c),
                                              star.point(centre)) == em::predicates::Sign::Positive;
        }
        if (!valid) continue;  // the centre is not in the kernel: not a mesh
        tri::link_neighbors_3d(star);
        // Independently: would the centroid of the ring invert a tetrahedron?
        double sum[3] = {0, 0, 0};
        for (int i = 0; i < k; ++i) {
            for (unsigned d = 0; d < 3; ++d) sum[d] += star.xyz[3 * i + d] - 0.0;
        }
        double centroid[3];
        for (unsigned d = 0; d < 3; ++d) centroid[d] = 0.0 + 1.0 * (sum[d] / k);
        bool inverts = false;
        for (std::size_t t = 0; t < star.tet_count(); ++t) {
            const tri::VertIdx* c = star.tets.data() + 4 * t;
            inverts |=
                em::predicates::orient3d(star.point(c[0]), star.point(c[1]), star.point(c[2]),
                                         centroid) != em::predicates::Sign::Positive;
        }
        const tri::Tetrahedralization3 before = star;
        gen::SmoothingOptions3 options;
        options.smart = false;  // the inversion guard alone
        const gen::SmoothingCounters3 counters = gen::laplacian_smoothing_3d(star, 0, options);
        EXPECT_EQ(counters.free_vertices, 1u);
        EXPECT_EQ(counters.undone, inverts ? 1u : 0u) << trial;
        const double* p = star.point(centre);
        if (inverts) {
            ++undone;
            EXPECT_EQ(counters.moves, 0u);
            EXPECT_TRUE(p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0);
        } else {
            ++moved;
            EXPECT_EQ(counters.moves, 1u);
            for (unsigned d = 0; d < 3; ++d) EXPECT_EQ(p[d], centroid[d]);
        }
        const auto check =
            gen::check_mesh_movement_3d(before, star, gen::fixed_vertices_3d(before, 0));
        EXPECT_TRUE(check.ok) << check.problem;
    }
    EXPECT_GT(undone, 5);  // both outcomes are exercised
    EXPECT_GT(moved, 20);
}

TEST(Generators_LaplacianSmoothing3, ScaledByTwoToThePlusMinus600GivesTheSameResultScaled) {
    const std::vector<double> xyz = jittered_grid(5, 0.35, 9);
    for (const bool smart : {false, true}) {
        tri::Tetrahedralization3 reference = delaunay(xyz);
        const gen::SmoothingOptions3 options = smoothing_options(3, 0.75, smart);
        const gen::SmoothingCounters3 c0 = gen::laplacian_smoothing_3d(reference, 0, options);
        EXPECT_GT(c0.moves, 0u);
        for (const int k : {-600, 600}) {
            tri::Tetrahedralization3 mesh = delaunay(scaled(xyz, k));
            ASSERT_EQ(mesh.tets, delaunay(xyz).tets);
            const tri::Tetrahedralization3 before = mesh;
            const gen::SmoothingCounters3 c = gen::laplacian_smoothing_3d(mesh, 0, options);
            EXPECT_EQ(c.moves, c0.moves) << k;
            EXPECT_EQ(c.undone, c0.undone) << k;
            EXPECT_EQ(c.undone_worse, c0.undone_worse) << k;
            EXPECT_EQ(c.converged, c0.converged) << k;
            EXPECT_EQ(mesh.xyz, scaled(reference.xyz, k)) << k;
            expect_valid_movement(before, mesh);
        }
    }
}

TEST(Generators_LaplacianSmoothing3, BadRelaxationAndArraysAreInputErrors) {
    tri::Tetrahedralization3 empty;
    for (const double omega : {0.0, -1.0, 1.5, std::nan("")}) {
        gen::SmoothingOptions3 options;
        options.relaxation = omega;
        EXPECT_THROW(gen::laplacian_smoothing_3d(empty, 0, options), em::InputError) << omega;
    }
    tri::Tetrahedralization3 mesh = delaunay(em::testing::random_points_3d(20, 3));
    tri::Tetrahedralization3 bad = mesh;
    bad.tets[5] = 20;  // out of range
    EXPECT_THROW(gen::laplacian_smoothing_3d(bad, 0), em::InputError);
    bad = mesh;
    bad.neighbors.pop_back();
    EXPECT_THROW(gen::laplacian_smoothing_3d(bad, 0), em::InputError);
    // Nothing but the empty mesh: nothing moves, no error.
    EXPECT_EQ(gen::laplacian_smoothing_3d(empty, 0).moves, 0u);
}
