// SPDX-License-Identifier: MIT
// Issue 15: a tetrahedron's circumcentre inserted without removing the tetrahedron. 3D Delaunay
// refinement built the circumcentre's cavity from the tetrahedron that holds the centre and
// shrank it until star-shaped, which could drop the bad tetrahedron itself: the centre went in,
// the tetrahedron stayed over the radius-edge bound, no rejected point was counted, and the
// command's exact check stopped with an internal error. Found on a rotated unit cube
// (tests/data/rotated/cube_11.poly, `exactmesh tetmesh cube_11.poly --radius-edge 2`: a flat
// tetrahedron between the two triangles of a facet split an ulp off its plane). The bad
// tetrahedron is now required in its centre's cavity (as frontal insertion requires its own);
// when it cannot be, the point is rejected and counted (the command warns).
// Facets within rounding of a plane are no longer split (split_nonplanar_facets_3d), so the
// command meets the split cube no more; the test splits each facet itself, along either
// diagonal (all 64 choices; one of them is the split that failed).
#include <gtest/gtest.h>

#include <string>

#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "io/plc_format.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace io = exactmesh::io;
namespace tri = exactmesh::triangulation;

tri::Plc3 cube_11() {
    tri::Plc3 plc = io::plc_from_file(
        io::read_plc(std::string(EXACTMESH_SOURCE_DIR) + "/tests/data/rotated/cube_11.poly"));
    tri::validate_plc_3d_input(plc);
    return plc;
}

/// Each quadrilateral facet of `plc` replaced by two triangles, split along its diagonal from
/// its first corner (bit f of `diagonals` clear) or from its second.
tri::Plc3 split_along(tri::Plc3 plc, unsigned diagonals) {
    const std::size_t count = plc.facets.size();
    for (std::size_t f = 0; f < count; ++f) {
        const std::vector<tri::VertIdx> q = plc.facets[f].polygons.at(0);
        EXPECT_EQ(q.size(), 4u);
        tri::Facet3 first = plc.facets[f], second = plc.facets[f];
        if ((diagonals >> f & 1u) == 0) {
            first.polygons = {{q[0], q[1], q[2]}};
            second.polygons = {{q[0], q[2], q[3]}};
        } else {
            first.polygons = {{q[0], q[1], q[3]}};
            second.polygons = {{q[1], q[2], q[3]}};
        }
        plc.facets[f] = first;
        plc.facets.push_back(second);
    }
    return plc;
}

/// `exactmesh tetmesh --radius-edge 2` without sliver removal.
gen::DelaunayRefinement3Result refined_at_2(const tri::Plc3& plc,
                                            gen::DelaunayRefinement3Options& refinement) {
    refinement.radius_edge_bound = 2;
    return gen::delaunay_refinement_3d(plc, tri::boundary_recovery_3d(plc).mesh, refinement);
}

void expect_every_tetrahedron_over_the_bound_rejected(const tri::Plc3& plc, unsigned diagonals) {
    gen::DelaunayRefinement3Options refinement;
    const gen::DelaunayRefinement3Result refined = refined_at_2(plc, refinement);
    const gen::RefinementQuality3 before =
        gen::check_refinement_quality_3d(refined.mesh, refinement);
    EXPECT_LE(before.over_bound, refined.counters.rejected_points) << diagonals;
    EXPECT_EQ(before.over_volume, 0u) << diagonals;

    // Sliver removal keeps it so (it never adds a tetrahedron over the bounds).
    gen::SliverRemoval3Options options;
    options.radius_edge_bound = refinement.radius_edge_bound;
    const gen::SliverRemoval3Result improved = gen::sliver_removal_3d(refined.mesh, options);
    const gen::RefinementQuality3 after =
        gen::check_refinement_quality_3d(improved.mesh, refinement);
    EXPECT_LE(after.over_bound, before.over_bound) << diagonals;
    EXPECT_LE(after.over_bound, refined.counters.rejected_points) << diagonals;
}

TEST(Issue15, EveryTetrahedronLeftOverTheBoundHasARejectedPoint) {
    for (unsigned diagonals = 0; diagonals < 64; ++diagonals) {
        const tri::Plc3 plc = split_along(cube_11(), diagonals);
        (void)tri::validate_plc_3d(plc);  // the triangles are planar
        expect_every_tetrahedron_over_the_bound_rejected(plc, diagonals);
    }
}

TEST(Issue15, ARotatedCubeKeptWholeMeetsTheBound) {
    // Its facets are within rounding of their planes: nothing split, and refinement leaves no
    // tetrahedron over the bound and rejects no point.
    tri::Plc3 plc = cube_11();
    EXPECT_TRUE(tri::split_nonplanar_facets_3d(plc).empty());
    gen::DelaunayRefinement3Options refinement;
    const gen::DelaunayRefinement3Result refined = refined_at_2(plc, refinement);
    const gen::RefinementQuality3 quality =
        gen::check_refinement_quality_3d(refined.mesh, refinement);
    EXPECT_EQ(quality.over_bound, 0u);
    EXPECT_EQ(refined.counters.rejected_points, 0u);
}

}  // namespace
