// SPDX-License-Identifier: MIT
// Tests of generators/mesh_3d/sliver_removal_3d on the sample domains after Delaunay
// refinement: the result passes the exact conformity check (valid positive tetrahedra, every
// subface and subsegment present), keeps every vertex that is not a Volume Steiner point where
// it was, keeps the region attributes' count, never raises the count of tetrahedra over the
// refinement's bounds, and its smallest dihedral angle is strictly larger than before (exact
// comparison); the domain scaled by 2^300 and 2^-300 gives the same mesh scaled.
#include "generators/mesh_3d/sliver_removal_3d.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "tests/support/plcs_3d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"

namespace exactmesh::generators {
namespace {

using predicates::Dihedral;
using predicates::Sign;
using triangulation::ConformingMesh3;
using triangulation::Plc3;
using triangulation::VertexFeature3;

/// The smallest dihedral angle of the mesh, exactly (pointers into `mesh`).
Dihedral smallest_dihedral_of(const triangulation::Tetrahedralization3& mesh) {
    Dihedral best{};
    for (std::uint32_t t = 0; t < mesh.tet_count(); ++t) {
        const auto* v = &mesh.tets[4 * std::size_t{t}];
        const Dihedral d = predicates::smallest_dihedral(
            {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])});
        if (t == 0 || predicates::compare_dihedral(d, best) == Sign::Negative) best = d;
    }
    return best;
}

struct Improved {
    ConformingMesh3 refined;
    SliverRemoval3Result result;
};

/// Recovers, refines and removes slivers; checks everything the file header lists.
Improved improve_and_check(const Plc3& plc, const std::string& what,
                           const DelaunayRefinement3Options& refinement) {
    Improved out;
    out.refined =
        delaunay_refinement_3d(plc, triangulation::boundary_recovery_3d(plc).mesh, refinement).mesh;
    SliverRemoval3Options options;
    options.radius_edge_bound = refinement.radius_edge_bound;
    options.max_volume = refinement.max_volume;
    out.result = sliver_removal_3d(out.refined, options);
    const ConformingMesh3& before = out.refined;
    const ConformingMesh3& after = out.result.mesh;

    const auto report = triangulation::check_boundary_conformity_3d(plc, after);
    EXPECT_TRUE(report.ok) << what << ": " << report.problem;
    EXPECT_NEAR(triangulation::mesh_volume(after.mesh), triangulation::mesh_volume(before.mesh),
                1e-12 * std::fabs(triangulation::mesh_volume(before.mesh)))
        << what;
    // Same vertices; only Volume Steiner points moved; every vertex still used.
    EXPECT_EQ(after.mesh.vertex_count(), before.mesh.vertex_count()) << what;
    EXPECT_EQ(after.vertex_feature, before.vertex_feature) << what;
    std::vector<bool> used(after.mesh.vertex_count(), false);
    for (const auto v : after.mesh.tets) used[v] = true;
    std::uint32_t moved = 0;
    for (std::uint32_t v = 0; v < after.mesh.vertex_count(); ++v) {
        EXPECT_TRUE(used[v]) << what << ": vertex " << v << " lost";
        const bool same = after.mesh.point(v)[0] == before.mesh.point(v)[0] &&
                          after.mesh.point(v)[1] == before.mesh.point(v)[1] &&
                          after.mesh.point(v)[2] == before.mesh.point(v)[2];
        if (after.vertex_feature[v] != VertexFeature3::Volume) {
            EXPECT_TRUE(same) << what << ": vertex " << v << " is not interior but moved";
        }
        moved += same ? 0 : 1;
    }
    EXPECT_EQ(after.subfaces, before.subfaces) << what;
    EXPECT_EQ(after.subsegments, before.subsegments) << what;
    EXPECT_EQ(after.tet_attributes.size(),
              before.tet_attributes.empty() ? 0u : after.mesh.tet_count())
        << what;
    // The bounds: the count over them never grows (keep_bounds).
    const RefinementQuality3 q0 = check_refinement_quality_3d(before, refinement);
    const RefinementQuality3 q1 = check_refinement_quality_3d(after, refinement);
    EXPECT_LE(q1.over_bound + q1.small_angle, q0.over_bound + q0.small_angle) << what;
    // Nor is a tetrahedron refinement spares (small input angles) traded for one it would split.
    EXPECT_LE(q1.over_bound, q0.over_bound) << what;
    EXPECT_LE(q1.over_volume, q0.over_volume) << what;
    // Strictly better smallest dihedral angle, exactly.
    EXPECT_EQ(predicates::compare_dihedral(smallest_dihedral_of(after.mesh),
                                           smallest_dihedral_of(before.mesh)),
              Sign::Positive)
        << what;
    const auto s0 = triangulation::quality_stats_3d(before.mesh);
    const auto s1 = triangulation::quality_stats_3d(after.mesh);
    const auto& c = out.result.counters;
    std::printf(
        "%s: %llu -> %llu tets, min dihedral %.4f -> %.4f degrees, angles below 10 degrees %llu "
        "-> %llu; swaps 2-3 %llu 3-2 %llu 4-4 %llu, locked %llu, vetoed %llu; moves %llu "
        "(rejected %llu, vetoed %llu; %u vertices moved); below threshold %llu -> %llu\n",
        what.c_str(), static_cast<unsigned long long>(s0.tets),
        static_cast<unsigned long long>(s1.tets), s0.min_dihedral_degrees, s1.min_dihedral_degrees,
        static_cast<unsigned long long>(s0.dihedral_histogram[0]),
        static_cast<unsigned long long>(s1.dihedral_histogram[0]),
        static_cast<unsigned long long>(c.flips_23), static_cast<unsigned long long>(c.flips_32),
        static_cast<unsigned long long>(c.flips_44),
        static_cast<unsigned long long>(c.swaps_locked),
        static_cast<unsigned long long>(c.swaps_vetoed),
        static_cast<unsigned long long>(c.moves_accepted),
        static_cast<unsigned long long>(c.moves_rejected),
        static_cast<unsigned long long>(c.moves_vetoed), moved,
        static_cast<unsigned long long>(c.slivers_before),
        static_cast<unsigned long long>(c.slivers_after));
    EXPECT_LE(c.slivers_after, c.slivers_before) << what;
    EXPECT_GT(c.slivers_before, 0u) << what;
    return out;
}

TEST(Generators_SliverRemoval3d, BoxWithHoleGainsItsSmallestDihedralAngle) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    DelaunayRefinement3Options refinement;
    // Not scaled by EXACTMESH_TEST_SCALE: 762 tetrahedra, and at 0.003 and above the refined box
    // has no sliver left to remove (smallest dihedral 35.3 degrees, measured 2026-12-03).
    refinement.max_volume = 0.0025;
    const Improved improved = improve_and_check(plc, "box-with-hole", refinement);
    EXPECT_EQ(improved.result.counters.slivers_after, 0u);
}

TEST(Generators_SliverRemoval3d, EllipsoidGainsItsSmallestDihedralAngle) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::Ellipsoid, 0.25);
    DelaunayRefinement3Options refinement;
    improve_and_check(plc, "ellipsoid B=2", refinement);
    refinement.max_volume = 0.004 / std::max(testing::test_scale(), 0.5);
    improve_and_check(plc, "ellipsoid V", refinement);
}

TEST(Generators_SliverRemoval3d, WingGainsItsSmallestDihedralAngle) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::Wing, 0.1);
    DelaunayRefinement3Options refinement;
    improve_and_check(plc, "wing", refinement);
}

TEST(Generators_SliverRemoval3d, WithoutBoundsKeptTheMeshIsStillConforming) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::Ellipsoid, 0.25);
    DelaunayRefinement3Options refinement;
    const ConformingMesh3 refined =
        delaunay_refinement_3d(plc, triangulation::boundary_recovery_3d(plc).mesh, refinement).mesh;
    SliverRemoval3Options options;
    options.keep_bounds = false;
    const SliverRemoval3Result result = sliver_removal_3d(refined, options);
    const auto report = triangulation::check_boundary_conformity_3d(plc, result.mesh);
    EXPECT_TRUE(report.ok) << report.problem;
    EXPECT_EQ(result.counters.swaps_vetoed, 0u);
    EXPECT_EQ(result.counters.moves_vetoed, 0u);
    EXPECT_EQ(predicates::compare_dihedral(smallest_dihedral_of(result.mesh.mesh),
                                           smallest_dihedral_of(refined.mesh)),
              Sign::Positive);
}

TEST(Generators_SliverRemoval3d, ScalingByPowersOfTwoGivesTheSameMesh) {
    // Swaps and smoothing moves both happen here (the ellipsoid and the wing move vertices):
    // the frame of each move is scaled by a power of two, so the moved points scale exactly.
    struct Case {
        SampleDomain3 domain;
        double size, max_volume;
    };
    std::uint64_t moves = 0;
    for (const Case& k :
         {Case{SampleDomain3::BoxWithHole, 0, 0.0025}, Case{SampleDomain3::Ellipsoid, 0.25, 0},
          Case{SampleDomain3::Wing, 0.1, 0}}) {
        const Plc3 plc = sample_domain_3d(k.domain, k.size);
        const std::string name(sample_domain_3d_name(k.domain));
        DelaunayRefinement3Options refinement;
        refinement.max_volume = k.max_volume;
        const Improved reference = improve_and_check(plc, name + " unscaled", refinement);
        moves += reference.result.counters.moves_accepted;
        for (const int e : {300, -300}) {
            DelaunayRefinement3Options scaled_refinement = refinement;
            scaled_refinement.max_volume = std::ldexp(refinement.max_volume, 3 * e);
            const Improved result =
                improve_and_check(triangulation::scaled(plc, e),
                                  name + " scaled by 2^" + std::to_string(e), scaled_refinement);
            const auto& a = result.result.mesh.mesh;
            const auto& b = reference.result.mesh.mesh;
            EXPECT_EQ(a.tets, b.tets) << name << " " << e;
            EXPECT_EQ(result.result.counters.moves_accepted,
                      reference.result.counters.moves_accepted)
                << name << " " << e;
            ASSERT_EQ(a.xyz.size(), b.xyz.size());
            for (std::size_t i = 0; i < a.xyz.size(); ++i)
                ASSERT_EQ(a.xyz[i], std::ldexp(b.xyz[i], e))
                    << name << " " << e << ": coordinate " << i;
        }
    }
    EXPECT_GT(moves, 0u);
}

TEST(Generators_SliverRemoval3d, SparedTetrahedraAreNotTradedForOnesOverTheBound) {
    // A free vertex an ulp below the top facet of the unit cube (z = 1 - 2^-53): refinement
    // spares the tetrahedra with an edge finer than doubles resolve there. Sliver removal kept
    // the count over the bounds but swapped a spared tetrahedron for one with no such edge,
    // which the command's exact check then took for a bug (an internal error, exit 3). Now a
    // spared tetrahedron counts less than one refinement would have split.
    Plc3 plc = triangulation::box(1, 1, 1);
    plc.xyz.insert(plc.xyz.end(), {0.3, 0.6, 1 - 0x1p-53});
    DelaunayRefinement3Options refinement;
    const ConformingMesh3 refined =
        delaunay_refinement_3d(plc, triangulation::boundary_recovery_3d(plc).mesh, refinement).mesh;
    const RefinementQuality3 q0 = check_refinement_quality_3d(refined, refinement);
    ASSERT_GT(q0.unresolvable, 0u);
    EXPECT_EQ(q0.over_bound, 0u);
    SliverRemoval3Options options;
    options.radius_edge_bound = refinement.radius_edge_bound;
    const SliverRemoval3Result improved = sliver_removal_3d(refined, options);
    EXPECT_TRUE(triangulation::check_boundary_conformity_3d(plc, improved.mesh).ok);
    const RefinementQuality3 q1 = check_refinement_quality_3d(improved.mesh, refinement);
    EXPECT_EQ(q1.over_bound, 0u);
    EXPECT_LE(q1.unresolvable, q0.unresolvable);
}

TEST(Generators_SliverRemoval3d, BadOptionsAreInputErrors) {
    const Plc3 plc = triangulation::box(1, 1, 1);
    const ConformingMesh3 mesh = triangulation::boundary_recovery_3d(plc).mesh;
    for (const double threshold : {0.0, -1.0, 90.0, std::nan("")}) {
        SliverRemoval3Options options;
        options.threshold_degrees = threshold;
        EXPECT_THROW(sliver_removal_3d(mesh, options), InputError) << threshold;
    }
    SliverRemoval3Options options;
    options.radius_edge_bound = 0;
    EXPECT_THROW(sliver_removal_3d(mesh, options), InputError);
}

TEST(Generators_SliverRemoval3d, RegionVolumeBoundsAreKept) {
    // Two regions with their own volume bounds (0.001 and 0.01): sliver removal counts each
    // tetrahedron against its own region's bound, so a refined mesh within them stays within
    // them; every tetrahedron keeps its region's attribute and bound.
    const Plc3 plc = triangulation::two_regions_box(0.001, 0.01);
    const DelaunayRefinement3Options refine;
    DelaunayRefinement3Result refined =
        delaunay_refinement_3d(plc, triangulation::boundary_recovery_3d(plc).mesh, refine);
    ASSERT_EQ(check_refinement_quality_3d(refined.mesh, refine).over_volume, 0u);
    // This mesh has no dihedral angle below 15 degrees; a 35-degree threshold gives sliver
    // removal swaps and moves to make (and to veto).
    SliverRemoval3Options options;
    options.threshold_degrees = 35;
    const auto result = sliver_removal_3d(std::move(refined.mesh), options);
    EXPECT_GT(result.counters.flips_23 + result.counters.flips_32 + result.counters.flips_44 +
                  result.counters.moves_accepted,
              0u);
    const auto report = triangulation::check_boundary_conformity_3d(plc, result.mesh);
    EXPECT_TRUE(report.ok) << report.problem;
    const auto& m = result.mesh.mesh;
    ASSERT_EQ(result.mesh.tet_attributes.size(), m.tet_count());
    ASSERT_EQ(result.mesh.tet_max_volume.size(), m.tet_count());
    for (std::uint32_t t = 0; t < m.tet_count(); ++t) {
        const double attribute = result.mesh.tet_attributes[t];
        EXPECT_EQ(result.mesh.tet_max_volume[t], attribute == 1 ? 0.001 : 0.01) << t;
    }
    const RefinementQuality3 quality = check_refinement_quality_3d(result.mesh, refine);
    EXPECT_EQ(quality.over_volume, 0u);
    EXPECT_EQ(quality.over_bound, 0u);
    const auto& c = result.counters;
    std::printf(
        "two regions: %llu tets below 35 degrees before, %llu after; %llu swaps, %llu vetoed; "
        "%llu moves, %llu vetoed\n",
        static_cast<unsigned long long>(c.slivers_before),
        static_cast<unsigned long long>(c.slivers_after),
        static_cast<unsigned long long>(c.flips_23 + c.flips_32 + c.flips_44),
        static_cast<unsigned long long>(c.swaps_vetoed),
        static_cast<unsigned long long>(c.moves_accepted),
        static_cast<unsigned long long>(c.moves_vetoed));
}

TEST(Generators_SliverRemoval3d, InsideRefinementGivesTheSameMeshAsAfterIt) {
    // DelaunayRefinement3Options::sliver_removal hands refinement's working mesh (dead slots,
    // its own links) to sliver removal's linked entry; sliver_removal_3d on the returned mesh
    // links it again from a Tetrahedralization3. The two must agree on every tetrahedron, every
    // moved point, region values and counters: on the sample domains, and on two regions with
    // their own volume bounds at a threshold that makes swaps and moves (and vetoes).
    struct Case {
        std::string name;
        Plc3 plc;
        double max_volume, threshold;
    };
    const std::vector<Case> cases{
        {"box-with-hole", sample_domain_3d(SampleDomain3::BoxWithHole), 0.0025, 15},
        {"ellipsoid", sample_domain_3d(SampleDomain3::Ellipsoid, 0.25), 0.004, 15},
        {"wing", sample_domain_3d(SampleDomain3::Wing, 0.1), 0, 15},
        {"two regions", triangulation::two_regions_box(0.001, 0.01), 0, 35}};
    for (const Case& k : cases) {
        DelaunayRefinement3Options refinement;
        refinement.max_volume = k.max_volume;
        SliverRemoval3Options options;
        options.max_volume = k.max_volume;
        options.threshold_degrees = k.threshold;
        const ConformingMesh3 recovered = triangulation::boundary_recovery_3d(k.plc).mesh;
        const SliverRemoval3Result after =
            sliver_removal_3d(delaunay_refinement_3d(k.plc, recovered, refinement).mesh, options);
        refinement.sliver_removal = options;
        const DelaunayRefinement3Result inside =
            delaunay_refinement_3d(k.plc, recovered, refinement);
        EXPECT_EQ(inside.mesh.mesh.tets, after.mesh.mesh.tets) << k.name;
        EXPECT_EQ(inside.mesh.mesh.neighbors, after.mesh.mesh.neighbors) << k.name;
        EXPECT_EQ(inside.mesh.mesh.xyz, after.mesh.mesh.xyz) << k.name;
        EXPECT_EQ(inside.mesh.subfaces, after.mesh.subfaces) << k.name;
        EXPECT_EQ(inside.mesh.tet_attributes, after.mesh.tet_attributes) << k.name;
        EXPECT_EQ(inside.mesh.tet_max_volume, after.mesh.tet_max_volume) << k.name;
        const auto& a = inside.slivers;
        const auto& b = after.counters;
        EXPECT_EQ(a.flips_23 + a.flips_32 + a.flips_44, b.flips_23 + b.flips_32 + b.flips_44)
            << k.name;
        EXPECT_EQ(a.moves_accepted, b.moves_accepted) << k.name;
        EXPECT_EQ(a.slivers_before, b.slivers_before) << k.name;
        EXPECT_EQ(a.slivers_after, b.slivers_after) << k.name;
        EXPECT_GT(a.flips_23 + a.flips_32 + a.flips_44 + a.moves_accepted, 0u) << k.name;
        const auto report = triangulation::check_boundary_conformity_3d(k.plc, inside.mesh);
        EXPECT_TRUE(report.ok) << k.name << ": " << report.problem;
    }
}

TEST(Generators_SliverRemoval3d, TheLinkedEntryRefusesMismatchedArrays) {
    const Plc3 plc = triangulation::box(1, 1, 1);
    ConformingMesh3 mesh = triangulation::boundary_recovery_3d(plc).mesh;
    const triangulation::TetMesh3 linked = triangulation::make_tet_mesh_3d(mesh.mesh);
    ConformingMesh3 short_features = mesh;
    short_features.vertex_feature.pop_back();
    EXPECT_THROW(sliver_removal_3d(short_features, linked), InputError);
    ConformingMesh3 short_attributes = mesh;
    short_attributes.tet_attributes.assign(linked.tet_slots() + 1, 1.0);
    EXPECT_THROW(sliver_removal_3d(short_attributes, linked), InputError);
    triangulation::TetMesh3 unlinked = linked;
    unlinked.vertex_tet.clear();
    EXPECT_THROW(sliver_removal_3d(mesh, unlinked), InputError);
    EXPECT_NO_THROW(sliver_removal_3d(mesh, linked));
}

}  // namespace
}  // namespace exactmesh::generators
