// SPDX-License-Identifier: MIT
// Tests of generators/mesh_3d/feature_size_3d: the local feature sizes of free vertices near
// each other, a facet and an edge; the graded size is the given one where no feature is finer
// (the sample domains: the same frontal mesh with and without grading); and frontal insertion
// and the octree around free vertices far finer than the size, then sliver removal, reach the
// angles they reach elsewhere (1e-6 degrees without the grading), the same mesh at 2^+-600.
#include "generators/mesh_3d/feature_size_3d.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_mesh_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "tests/support/plcs_3d.hpp"
#include "tests/support/scaled_mesh_3d.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"

namespace exactmesh::generators {
namespace {

using triangulation::Plc3;

/// The unit cube with free vertices: five on a line 1e-9 apart, one 1e-10 above the bottom
/// facet, one 1e-12 off the edge y = 0 of the back facet x = 1 (inside the cube).
Plc3 cube_with_fine_free_vertices() {
    Plc3 plc = triangulation::box(1, 1, 1);
    for (int i = 0; i < 5; ++i) plc.xyz.insert(plc.xyz.end(), {0.3 + i * 1e-9, 0.4, 0.5});
    plc.xyz.insert(plc.xyz.end(), {0.37, 0.61, 1e-10});
    plc.xyz.insert(plc.xyz.end(), {1 - 1e-12, 1e-12, 0.75});
    return plc;
}

TEST(Generators_FeatureSize3d, FreeVerticesNearEachOtherAFacetAndAnEdge) {
    const Plc3 plc = cube_with_fine_free_vertices();
    const std::vector<double> f = local_feature_sizes_3d(plc);
    ASSERT_EQ(f.size(), plc.vertex_count());
    const std::uint32_t first_free = 8;
    for (std::uint32_t v = first_free; v < first_free + 5; ++v)
        EXPECT_NEAR(f[v], 1e-9, 1e-15) << "cluster vertex " << v;
    EXPECT_NEAR(f[first_free + 5], 1e-10, 1e-16);  // above the bottom facet
    // 1e-12 from two facets (x = 1 and y = 0): the nearest point of either.
    EXPECT_NEAR(f[first_free + 6], 1e-12, 1e-16);  // 1 - 1e-12 rounded
    // The cube's corners: the nearest other corner, facet or free vertex is at least 0.25 away
    // (corner (1, 0, 1) to the free vertex at z = 0.75).
    for (std::uint32_t v = 0; v < first_free; ++v) EXPECT_GE(f[v], 0.25) << v;
    // Scaled by 2^+-600: the same sizes scaled (coordinates scaled by one power of two).
    for (const int k : {600, -600}) {
        const std::vector<double> g = local_feature_sizes_3d(triangulation::scaled(plc, k));
        for (std::size_t v = 0; v < f.size(); ++v) EXPECT_EQ(g[v], std::ldexp(f[v], k)) << v;
    }
}

TEST(Generators_FeatureSize3d, NoFeatureFinerThanTheSizeLeavesItAlone) {
    for (const SampleDomain3 d : {SampleDomain3::BoxWithHole, SampleDomain3::Ellipsoid}) {
        const Plc3 plc = sample_domain_3d(d);
        const SizeFunction3 h = SizeFunction3::uniform(0.2);
        EXPECT_TRUE(feature_graded_size_3d(plc, h).is_uniform()) << sample_domain_3d_name(d);
        // So frontal insertion makes the same mesh with the grading as without.
        FrontalDelaunay3Options graded, plain;
        graded.size = plain.size = h;
        plain.feature_gradation = 0;
        const auto recovered = triangulation::boundary_recovery_3d(plc).mesh;
        const auto a = frontal_delaunay_3d(plc, recovered, graded);
        const auto b = frontal_delaunay_3d(plc, recovered, plain);
        EXPECT_EQ(a.mesh.mesh.tets, b.mesh.mesh.tets) << sample_domain_3d_name(d);
        EXPECT_EQ(a.mesh.mesh.xyz, b.mesh.mesh.xyz) << sample_domain_3d_name(d);
    }
    const Plc3 plc = triangulation::box(1, 1, 1);
    EXPECT_THROW(feature_graded_size_3d(plc, SizeFunction3::uniform(0.1), 0), InputError);
    EXPECT_THROW(feature_graded_size_3d(plc, SizeFunction3{}), InputError);
    FrontalDelaunay3Options bad;
    bad.size = SizeFunction3::uniform(0.1);
    bad.feature_gradation = -1;
    EXPECT_THROW(frontal_delaunay_3d(plc, triangulation::boundary_recovery_3d(plc).mesh, bad),
                 InputError);
}

/// Frontal insertion (or the octree) at size h, then sliver removal as `exactmesh tetmesh`
/// runs it; checked exactly; the smallest dihedral angle in degrees.
double mesh_and_remove_slivers(const Plc3& plc, double h, bool octree, double gradation,
                               triangulation::ConformingMesh3* out = nullptr) {
    const auto recovered = triangulation::boundary_recovery_3d(plc).mesh;
    triangulation::ConformingMesh3 meshed;
    if (octree) {
        OctreeMesh3Options options;
        options.size = SizeFunction3::uniform(h);
        options.feature_gradation = gradation;
        meshed = octree_mesh_3d(plc, recovered, options).mesh;
    } else {
        FrontalDelaunay3Options options;
        options.size = SizeFunction3::uniform(h);
        options.feature_gradation = gradation;
        meshed = frontal_delaunay_3d(plc, recovered, options).mesh;
    }
    auto improved = sliver_removal_3d(std::move(meshed), SliverRemoval3Options{}).mesh;
    const auto report = triangulation::check_boundary_conformity_3d(plc, improved);
    EXPECT_TRUE(report.ok) << report.problem;
    for (std::size_t i = 0; i < plc.xyz.size(); ++i) EXPECT_EQ(improved.mesh.xyz[i], plc.xyz[i]);
    const double angle = triangulation::quality_stats_3d(improved.mesh).min_dihedral_degrees;
    std::printf("%s, gradation %g: %u tets, smallest dihedral %.3g degrees\n",
                octree ? "octree" : "frontal", gradation, improved.mesh.tet_count(), angle);
    if (out != nullptr) *out = std::move(improved);
    return angle;
}

TEST(Generators_FeatureSize3d, FrontalAndOctreeAroundFeaturesFarFinerThanTheSize) {
    const Plc3 plc = cube_with_fine_free_vertices();
    for (const bool octree : {false, true}) {
        // Without the grading the flat tetrahedra beside the features stay (1e-6 degrees).
        EXPECT_LT(mesh_and_remove_slivers(plc, 0.1, octree, 0), 1.0);
        triangulation::ConformingMesh3 reference;
        EXPECT_GE(mesh_and_remove_slivers(plc, 0.1, octree, 0.5, &reference), 14.0);
        for (const int k : {600, -600}) {
            triangulation::ConformingMesh3 scaled;
            mesh_and_remove_slivers(triangulation::scaled(plc, k), std::ldexp(0.1, k), octree, 0.5,
                                    &scaled);
            exactmesh::testing::expect_scaled_mesh(scaled, reference, k);
        }
    }
}

}  // namespace
}  // namespace exactmesh::generators
