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

TEST(Issue15, EveryTetrahedronLeftOverTheBoundHasARejectedPoint) {
    tri::Plc3 plc = io::plc_from_file(
        io::read_plc(std::string(EXACTMESH_SOURCE_DIR) + "/tests/data/rotated/cube_11.poly"));
    tri::validate_plc_3d_input(plc);
    EXPECT_EQ(tri::split_nonplanar_facets_3d(plc).size(), 6u);  // every facet an ulp off
    tri::embed_free_vertices_3d(plc);
    gen::DelaunayRefinement3Options refinement;
    refinement.radius_edge_bound = 2;
    const gen::DelaunayRefinement3Result refined =
        gen::delaunay_refinement_3d(plc, tri::boundary_recovery_3d(plc).mesh, refinement);
    const gen::RefinementQuality3 before =
        gen::check_refinement_quality_3d(refined.mesh, refinement);
    EXPECT_LE(before.over_bound, refined.counters.rejected_points);
    EXPECT_EQ(before.over_volume, 0u);

    // Sliver removal keeps it so (it never adds a tetrahedron over the bounds).
    gen::SliverRemoval3Options options;
    options.radius_edge_bound = refinement.radius_edge_bound;
    const gen::SliverRemoval3Result improved = gen::sliver_removal_3d(refined.mesh, options);
    const gen::RefinementQuality3 after =
        gen::check_refinement_quality_3d(improved.mesh, refinement);
    EXPECT_LE(after.over_bound, before.over_bound);
    EXPECT_LE(after.over_bound, refined.counters.rejected_points);
}

}  // namespace
