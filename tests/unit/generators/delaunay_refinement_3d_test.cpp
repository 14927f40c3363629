// SPDX-License-Identifier: MIT
// Tests of generators/mesh_3d/delaunay_refinement_3d: the sample domains, the same mesh for the
// domain scaled by 2^600 and 2^-600, a cube (cocircular facets, cospherical corners), and small
// random convex and star-shaped PLCs, a box cut into two regions with their own volume bounds;
// every output checked exactly (check_boundary_conformity_3d:
// valid positively oriented tetrahedra, every facet and segment present; and
// check_refinement_quality_3d: every tetrahedron within the bounds unless spared or explained by
// a rejected point), and the wing's circumcentres cut off by tetrahedra out of conflict.
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "tests/support/plcs_3d.hpp"
#include "tests/support/scaled_mesh_3d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::generators {
namespace {

using triangulation::ConformingMesh3;
using triangulation::Plc3;

/// Recovers and refines `plc`, checks the result exactly, and returns it.
DelaunayRefinement3Result refine_and_check(const Plc3& plc, const std::string& what,
                                           const DelaunayRefinement3Options& options,
                                           bool require_all_good = true) {
    ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    const std::uint32_t recovered_vertices = recovered.mesh.vertex_count();
    DelaunayRefinement3Result result = delaunay_refinement_3d(plc, std::move(recovered), options);
    const auto report = triangulation::check_boundary_conformity_3d(plc, result.mesh);
    EXPECT_TRUE(report.ok) << what << ": " << report.problem;
    const RefinementQuality3 quality = check_refinement_quality_3d(result.mesh, options);
    const auto& c = result.counters;
    std::printf(
        "%s: %u vertices, %u tets; %llu circumcentres, %llu subface, %llu segment, %llu "
        "shell splits, %llu rejected, %llu spared tets (check: %llu over, %llu spared)\n",
        what.c_str(), result.mesh.mesh.vertex_count(), result.mesh.mesh.tet_count(),
        static_cast<unsigned long long>(c.circumcenters),
        static_cast<unsigned long long>(c.subface_splits),
        static_cast<unsigned long long>(c.segment_splits),
        static_cast<unsigned long long>(c.shell_splits),
        static_cast<unsigned long long>(c.rejected_points),
        static_cast<unsigned long long>(c.small_angle_tets),
        static_cast<unsigned long long>(quality.over_bound),
        static_cast<unsigned long long>(quality.small_angle));
    EXPECT_EQ(c.insertions, c.circumcenters + c.subface_splits + c.segment_splits + c.shell_splits);
    EXPECT_EQ(result.mesh.mesh.vertex_count(), recovered_vertices + c.insertions);
    if (require_all_good || c.rejected_points == 0) {
        EXPECT_EQ(quality.over_bound, 0u) << what;
        EXPECT_EQ(quality.over_volume, 0u) << what;
    }
    return result;
}

TEST(Generators_DelaunayRefinement3d, BoxWithHoleMeetsTheRadiusEdgeBound) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    for (const double bound : {2.0, 1.5, 1.2}) {
        DelaunayRefinement3Options options;
        options.radius_edge_bound = bound;
        const auto result =
            refine_and_check(plc, "box-with-hole B=" + std::to_string(bound), options);
        EXPECT_NEAR(triangulation::mesh_volume(result.mesh.mesh), 0.875, 1e-12);
        EXPECT_GT(result.counters.insertions, 0u);
    }
}

TEST(Generators_DelaunayRefinement3d, BoxWithHoleMeetsTheVolumeBound) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    DelaunayRefinement3Options options;
    options.max_volume = 0.002 / testing::test_scale();
    const auto result = refine_and_check(plc, "box-with-hole volume", options);
    EXPECT_NEAR(triangulation::mesh_volume(result.mesh.mesh), 0.875, 1e-12);
    EXPECT_GE(result.mesh.mesh.tet_count(), static_cast<std::uint32_t>(0.875 / options.max_volume));
}

TEST(Generators_DelaunayRefinement3d, EllipsoidMeetsTheRadiusEdgeBound) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::Ellipsoid, 0.25);
    DelaunayRefinement3Options options;
    const auto result = refine_and_check(plc, "ellipsoid", options);
    EXPECT_GT(result.counters.circumcenters, 0u);
}

TEST(Generators_DelaunayRefinement3d, CircumcentresCutOffByTetrahedraOutOfConflictAreInserted) {
    // On the wing at V = 0.01 the cavity grown from the tetrahedron holding one circumcentre
    // missed the tetrahedron it belongs to: tetrahedra whose spheres leave the centre out lie
    // between them (left by shrunk cavities), no subface among them. The centre was rejected;
    // at 7 10^5 tetrahedra such rejections left 2 tetrahedra over the radius-edge bound. The
    // cavity seeded with the walk's tetrahedra inserts it, the same at 2^+-300 (V scaled by
    // 2^+-900).
    const Plc3 plc = sample_domain_3d(SampleDomain3::Wing);
    DelaunayRefinement3Options options;
    options.max_volume = 0.01;
    const auto reference = refine_and_check(plc, "wing V=0.01", options);
    EXPECT_GT(reference.counters.walk_seeded_cavities, 0u);
    EXPECT_EQ(reference.counters.rejected_points, 0u);
    for (const int e : {300, -300}) {
        DelaunayRefinement3Options scaled_options = options;
        scaled_options.max_volume = std::ldexp(options.max_volume, 3 * e);
        const auto result = refine_and_check(
            triangulation::scaled(plc, e), "wing scaled by 2^" + std::to_string(e), scaled_options);
        exactmesh::testing::expect_scaled_mesh(result.mesh, reference.mesh, e);
    }
}

TEST(Generators_DelaunayRefinement3d, CubeWithCocircularFacets) {
    // Every facet's corners are cocircular and all eight cospherical: the Delaunay choices are
    // made by the perturbation, and the facets' circumcentres fall on their diagonals.
    for (const double bound : {2.0, 1.2, 1.0}) {
        DelaunayRefinement3Options options;
        options.radius_edge_bound = bound;
        const auto result = refine_and_check(triangulation::box(1, 1, 1),
                                             "cube B=" + std::to_string(bound), options);
        EXPECT_NEAR(triangulation::mesh_volume(result.mesh.mesh), 1.0, 1e-12);
    }
    DelaunayRefinement3Options options;
    options.max_volume = 1.0 / 64;
    const auto result = refine_and_check(triangulation::box(1, 1, 1), "cube V=1/64", options);
    EXPECT_GE(result.mesh.mesh.tet_count(), 64u);
}

TEST(Generators_DelaunayRefinement3d, FreeVerticesOnAndNearTheSurfaceSurvive) {
    // The unit cube with free vertices: on an edge, in a facet (embedded by
    // embed_free_vertices_3d, as `exactmesh tetmesh` does), 1e-12 off the edge and the facet,
    // and inside. Every one is a mesh vertex at its own coordinates, at 2^0 and 2^+-600.
    const std::vector<std::array<double, 3>> free = {
        {0.5, 0, 0}, {0.3, 0.6, 1}, {0.5, 1e-12, 1e-12}, {0.25, 0.75, 1 - 1e-12}, {0.4, 0.3, 0.6}};
    for (const int e : {0, 600, -600}) {
        Plc3 plc = triangulation::box(1, 1, 1);
        for (const auto& p : free) plc.xyz.insert(plc.xyz.end(), p.begin(), p.end());
        plc = triangulation::scaled(plc, e);
        const triangulation::FreeVertexEmbedding3 embedded =
            triangulation::embed_free_vertices_3d(plc);
        EXPECT_EQ(embedded.on_segments, 1u);
        EXPECT_EQ(embedded.on_facets, 1u);
        const auto result = refine_and_check(
            plc, "cube with free vertices at 2^" + std::to_string(e), DelaunayRefinement3Options{});
        std::vector<bool> used(result.mesh.mesh.vertex_count(), false);
        for (const auto v : result.mesh.mesh.tets) used[v] = true;
        for (triangulation::VertIdx v = 0; v < plc.vertex_count(); ++v) {
            EXPECT_TRUE(used[v]) << "input vertex " << v << " at 2^" << e;
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(result.mesh.mesh.xyz[3 * v + k], plc.xyz[3 * v + k]);
        }
    }
}

TEST(Generators_DelaunayRefinement3d, FeaturesFinerThanDoublesResolveAreSparedNotChased) {
    // A free vertex 1e-30 above a facet vertex at (0.5, 0.5, 0): a tetrahedron of edge 1e-30
    // beside edges of at least an ulp of 0.5 (1.1e-16) cannot be mended by rounded points. It
    // used to run circumcentres into the budget (10^5 in 12 s, 10^6 in minutes); now the
    // tetrahedra with an edge below 2^-44 of their coordinates are spared, counted and reported
    // by the exact check as unresolvable, not as over the bound.
    for (const double gap : {1e-30, 1e-300}) {
        Plc3 plc = triangulation::box(1, 1, 1);
        plc.xyz.insert(plc.xyz.end(), {0.5, 0.5, 0.0, 0.5, 0.5, gap});
        triangulation::embed_free_vertices_3d(plc);
        const auto result = refine_and_check(plc, "vertex pair " + format_number(gap) + " apart",
                                             DelaunayRefinement3Options{});
        EXPECT_GT(result.counters.unresolvable_tets, 0u);
        const RefinementQuality3 q = check_refinement_quality_3d(result.mesh, {});
        EXPECT_GT(q.unresolvable, 0u);
        EXPECT_EQ(q.over_bound, 0u);
        EXPECT_LT(result.counters.insertions, 1000u);
    }
    // 1e-10 apart is resolved: refinement meets the bound everywhere.
    Plc3 plc = triangulation::box(1, 1, 1);
    plc.xyz.insert(plc.xyz.end(), {0.5, 0.5, 0.0, 0.5, 0.5, 1e-10});
    triangulation::embed_free_vertices_3d(plc);
    const auto result =
        refine_and_check(plc, "vertex pair 1e-10 apart", DelaunayRefinement3Options{});
    EXPECT_EQ(result.counters.unresolvable_tets, 0u);
    const RefinementQuality3 q = check_refinement_quality_3d(result.mesh, {});
    EXPECT_EQ(q.unresolvable + q.over_bound + q.small_angle, 0u);
}

TEST(Generators_DelaunayRefinement3d, DomainsTouchingThemselvesAlongAnEdgeOrAtACorner) {
    // Two cubes sharing only an edge, or only a corner: stars of the shared vertices (and of
    // the points refinement puts on the shared edge) fall in two pieces, which a walk by
    // adjacency does not cross. Refinement used to find no tetrahedron on a subface there
    // (InternalError), and the topology check refused the edge in four boundary faces.
    for (const bool edge : {true, false}) {
        const Plc3 plc = triangulation::cubes_touching(edge);
        DelaunayRefinement3Options options;
        options.max_volume = 0.002;
        const auto result = refine_and_check(
            plc, edge ? "cubes sharing an edge" : "cubes sharing a corner", options);
        EXPECT_NEAR(triangulation::mesh_volume(result.mesh.mesh), 2.0, 1e-12);
        EXPECT_GT(result.counters.segment_splits, 0u);
    }
}

TEST(Generators_DelaunayRefinement3d, ScalingByPowersOfTwoGivesTheSameMesh) {
    for (const SampleDomain3 d : {SampleDomain3::BoxWithHole, SampleDomain3::Ellipsoid}) {
        const Plc3 plc = sample_domain_3d(d, 0.4);
        DelaunayRefinement3Options options;
        options.radius_edge_bound = 1.5;
        const auto reference = refine_and_check(plc, "unscaled", options);
        for (const int e : {600, -600}) {
            const Plc3 s = triangulation::scaled(plc, e);
            const auto result = refine_and_check(s, "scaled by 2^" + std::to_string(e), options);
            exactmesh::testing::expect_scaled_mesh(result.mesh, reference.mesh, e);
        }
    }
}

TEST(Generators_DelaunayRefinement3d, RandomConvexPolyhedra) {
    const int count = std::max(2, static_cast<int>(6 * testing::test_scale()));
    for (int seed = 1; seed <= count; ++seed) {
        const Plc3 plc =
            triangulation::random_convex(static_cast<std::uint64_t>(seed), 10 + 4 * seed);
        DelaunayRefinement3Options options;
        options.max_steiner_points = 200000;
        // Random hulls have small angles between facets: points may be rejected (counted), and
        // then only tetrahedra they explain may stay over the bound.
        refine_and_check(plc, "random convex seed " + std::to_string(seed), options, false);
    }
}

TEST(Generators_DelaunayRefinement3d, RandomStarShapedPolyhedraRefineOrStopAtTheBudget) {
    // At least four seeds at every test scale: seeds 1 and 2 stop at the budget, 3 and 4 refine
    // (the sanitizer run's reduced scale once kept only 1 and 2, and nothing refined).
    const int count = std::max(4, static_cast<int>(6 * testing::test_scale()));
    int refined = 0;
    for (int seed = 1; seed <= count; ++seed) {
        const Plc3 plc =
            triangulation::random_star(static_cast<std::uint64_t>(seed), 10 + 4 * seed);
        DelaunayRefinement3Options options;
        options.max_steiner_points = 5000;
        try {
            refine_and_check(plc, "random star seed " + std::to_string(seed), options, false);
            ++refined;
        } catch (const InputError& error) {
            // Small input angles: the budget stops refinement with a message naming it.
            const std::string message = error.what();
            EXPECT_NE(message.find("budget"), std::string::npos) << message;
            std::printf("random star seed %d: %s\n", seed, message.c_str());
        }
    }
    EXPECT_GT(refined, 0);
}

TEST(Generators_DelaunayRefinement3d, VolumeBoundFarOverTheBudgetFailsAtOnceAtEveryScale) {
    // A unit cube at 10^-12: about 1.5e11 Steiner points against a budget of about 10^6; refused
    // before any insertion, with the estimate, the same at 2^300 (the bound scaled by 2^900).
    for (const int e : {0, 300, -300}) {
        const Plc3 plc = triangulation::scaled(triangulation::box(1, 1, 1), e);
        ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
        DelaunayRefinement3Options options;
        options.max_volume = std::ldexp(1e-12, 3 * e);
        try {
            delaunay_refinement_3d(plc, std::move(recovered), options);
            ADD_FAILURE() << "2^" << e << ": refined";
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("exceeded at once"), std::string::npos) << message;
            EXPECT_NE(message.find("1.54e+11"), std::string::npos) << message;
        }
    }
}

TEST(Generators_DelaunayRefinement3d, VolumeBoundAFewTimesOverTheBudgetFailsAtOnce) {
    // box-with-hole at V = 2.65e-8: the estimate (5.08e6 points) is about 5 times the default
    // budget; with a margin of 6 it ran a million insertions (22 s) into it. Refinement makes
    // 1.35-8 times the estimate's points on the sample domains, so the budget itself refuses.
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    DelaunayRefinement3Options options;
    options.max_volume = 2.65e-8;
    try {
        delaunay_refinement_3d(plc, std::move(recovered), options);
        ADD_FAILURE() << "refined";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("exceeded at once"), std::string::npos) << message;
        EXPECT_NE(message.find("5.08e+06"), std::string::npos) << message;
    }
}

TEST(Generators_DelaunayRefinement3d, BadOptionsAndTheBudgetAreInputErrors) {
    const Plc3 plc = triangulation::box(1, 1, 1);
    ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    DelaunayRefinement3Options options;
    options.radius_edge_bound = -1;
    EXPECT_THROW(delaunay_refinement_3d(plc, recovered, options), InputError);
    options.radius_edge_bound = std::nan("");
    EXPECT_THROW(delaunay_refinement_3d(plc, recovered, options), InputError);
    // Below 1 circumcentre insertion may shorten edges without end: refused at once.
    for (const double bound : {0.999, 0.9, 0.5}) {
        options.radius_edge_bound = bound;
        try {
            delaunay_refinement_3d(plc, recovered, options);
            ADD_FAILURE() << "bound " << bound << " accepted";
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("is below 1"), std::string::npos)
                << error.what();
        }
    }
    options.radius_edge_bound = 2;
    options.max_volume = 1e-6;
    options.max_steiner_points = 10;
    try {
        delaunay_refinement_3d(plc, recovered, options);
        ADD_FAILURE() << "no budget error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("budget of 10"), std::string::npos)
            << error.what();
    }
}

/// Checks a refined two_regions_box (scaled by 2^e) region by region: every tetrahedron carries
/// attribute 1 or 2, lies on its region's side of x = 2^e (exact coordinate comparisons), carries
/// its region's bound `region_bounds[attribute - 1]` and is within `in_force[attribute - 1]`
/// (exact compare_tet_volume_3d). Returns the count of tetrahedra per region.
std::array<std::uint32_t, 2> check_regions(const ConformingMesh3& mesh, int e,
                                           const std::array<double, 2>& region_bounds,
                                           const std::array<double, 2>& in_force) {
    const auto& m = mesh.mesh;
    EXPECT_EQ(mesh.tet_attributes.size(), m.tet_count());
    EXPECT_EQ(mesh.tet_max_volume.size(), m.tet_count());
    std::array<std::uint32_t, 2> counts{0, 0};
    if (mesh.tet_attributes.size() != m.tet_count() || mesh.tet_max_volume.size() != m.tet_count())
        return counts;
    const double middle = std::ldexp(1.0, e);
    for (std::uint32_t t = 0; t < m.tet_count(); ++t) {
        const double attribute = mesh.tet_attributes[t];
        EXPECT_TRUE(attribute == 1 || attribute == 2) << attribute;
        const unsigned r = attribute == 1 ? 0 : 1;
        ++counts[r];
        EXPECT_EQ(mesh.tet_max_volume[t], region_bounds[r]) << t;
        const double* p[4];
        for (unsigned k = 0; k < 4; ++k) {
            p[k] = m.point(m.tets[4 * std::size_t{t} + k]);
            EXPECT_TRUE(r == 0 ? p[k][0] <= middle : p[k][0] >= middle)
                << "tetrahedron " << t << " of region " << attribute << " crosses x = 2^" << e;
        }
        EXPECT_NE(predicates::compare_tet_volume_3d(p[0], p[1], p[2], p[3], in_force[r]),
                  predicates::Sign::Positive)
            << "tetrahedron " << t << " of region " << attribute << " over " << in_force[r];
    }
    return counts;
}

TEST(Generators_DelaunayRefinement3d, RegionVolumeBoundsHoldInEachRegion) {
    // Two unit cubes, bounds 0.001 and 0.01 (TetGen's region list), no global bound.
    const Plc3 plc = triangulation::two_regions_box(0.001, 0.01);
    const DelaunayRefinement3Options options;
    const auto result = refine_and_check(plc, "two regions 0.001 | 0.01", options);
    const auto counts = check_regions(result.mesh, 0, {0.001, 0.01}, {0.001, 0.01});
    std::printf("two regions: %u tets at 0.001, %u at 0.01\n", counts[0], counts[1]);
    // The fine cube needs at least 1,000 tetrahedra, the coarse one at least 100.
    EXPECT_GE(counts[0], 1000u);
    EXPECT_GT(counts[0], 4 * counts[1]);
    // The quality check applies each tetrahedron's own bound: under a global 0.001 the coarse
    // cube's tetrahedra are over it.
    DelaunayRefinement3Options global = options;
    global.max_volume = 0.001;
    EXPECT_GT(check_refinement_quality_3d(result.mesh, global).over_volume, 0u);
    EXPECT_EQ(check_refinement_quality_3d(result.mesh, options).over_volume, 0u);
}

TEST(Generators_DelaunayRefinement3d, GlobalVolumeBoundAppliesOnTopOfRegionBounds) {
    // Global 0.004: the smaller bound holds in each region (0.001 left, 0.004 right, where the
    // region asks only 0.01); a region without a bound takes the global one.
    DelaunayRefinement3Options options;
    options.max_volume = 0.004;
    const auto both = refine_and_check(triangulation::two_regions_box(0.001, 0.01),
                                       "two regions 0.001 | 0.01, global 0.004", options);
    check_regions(both.mesh, 0, {0.001, 0.01}, {0.001, 0.004});
    const auto one = refine_and_check(triangulation::two_regions_box(0.001, -1),
                                      "two regions 0.001 | none, global 0.004", options);
    check_regions(one.mesh, 0, {0.001, -1}, {0.001, 0.004});
}

TEST(Generators_DelaunayRefinement3d, RegionVolumeBoundsScaleByPowersOfTwo) {
    // The domain scaled by 2^k and the bounds by 2^3k: the same mesh scaled. (Volumes of a
    // domain at 2^+-600 are 2^+-1800, beyond doubles, so no volume bound exists there; 2^+-300
    // puts the bounds at 2^+-900.)
    const Plc3 plc = triangulation::two_regions_box(0.001, 0.01);
    const DelaunayRefinement3Options options;
    const auto reference = refine_and_check(plc, "two regions unscaled", options);
    for (const int e : {300, -300}) {
        const Plc3 s = triangulation::scaled(plc, e);
        const auto result =
            refine_and_check(s, "two regions scaled by 2^" + std::to_string(e), options);
        exactmesh::testing::expect_scaled_mesh(result.mesh, reference.mesh, e);
        EXPECT_EQ(result.mesh.tet_attributes, reference.mesh.tet_attributes) << e;
        check_regions(result.mesh, e, {std::ldexp(0.001, 3 * e), std::ldexp(0.01, 3 * e)},
                      {std::ldexp(0.001, 3 * e), std::ldexp(0.01, 3 * e)});
    }
}

TEST(Generators_DelaunayRefinement3d, RegionVolumeBoundFarOverTheBudgetFailsAtOnce) {
    // A unit cube bounded at 10^-12 beside one at 0.01: about 1.54e11 Steiner points, refused
    // before any insertion with the estimate, at every scale.
    for (const int e : {0, 300, -300}) {
        const Plc3 plc = triangulation::scaled(triangulation::two_regions_box(1e-12, 0.01), e);
        ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
        try {
            delaunay_refinement_3d(plc, std::move(recovered), {});
            ADD_FAILURE() << "2^" << e << ": refined";
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_NE(message.find("exceeded at once"), std::string::npos) << message;
            EXPECT_NE(message.find("region volume bounds"), std::string::npos) << message;
            EXPECT_NE(message.find("1.54e+11"), std::string::npos) << message;
        }
    }
}

TEST(Generators_DelaunayRefinement3d, BadRegionVolumeBoundsAreInputErrors) {
    const Plc3 plc = triangulation::two_regions_box(0.01, 0.01);
    const ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    ASSERT_EQ(recovered.tet_max_volume.size(), recovered.mesh.tet_count());
    ConformingMesh3 infinite = recovered;
    infinite.tet_max_volume[0] = INFINITY;
    EXPECT_THROW(delaunay_refinement_3d(plc, infinite, {}), InputError);
    ConformingMesh3 short_list = recovered;
    short_list.tet_max_volume.pop_back();
    EXPECT_THROW(delaunay_refinement_3d(plc, short_list, {}), InputError);
}

}  // namespace
}  // namespace exactmesh::generators
