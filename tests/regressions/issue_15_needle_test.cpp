// SPDX-License-Identifier: MIT
// Issue 15, hostile inputs: a needle. The tetrahedron (0,0,0), (1,2^31,0), (0,1,0), (0,0,1) has
// a volume of 1/6 but facets of area about 2^30. Frontal insertion estimated its Steiner points
// from the volume alone (about 50 at size 0.3) and then placed points on the surface for minutes
// (about 10^10 of them). The estimate now takes the most of the volume's, the surface's and the
// segments' counts, so the size is refused at once with the estimate; a size the budget allows
// meshes it.
// Delaunay refinement (radius-edge 2) split the needle's long edge 10^6 times: vertex (0,1,0) lies
// 4.7e-10 from it, on an edge meeting it at 4.7e-10 radians, so each split point encroached
// the other edge and back (1,004,000 subsegment splits into the Steiner budget, 130 s, 843 MB).
// Encroachment between segments meeting at below 30 degrees now splits nothing
// (SmallInputAngleRule3::narrow_angle_pair); the tetrahedra between them are spared.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "tests/support/error_message.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

tri::Plc3 needle() {
    tri::Plc3 plc;
    plc.xyz = {0, 0, 0, 1, 2147483648.0, 0, 0, 1, 0, 0, 0, 1};
    for (const auto& f : {std::vector<tri::VertIdx>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}) {
        tri::Facet3 facet;
        facet.polygons = {f};
        plc.facets.push_back(facet);
    }
    return plc;
}

TEST(Issue15, FrontalSurfaceOfANeedleIsEstimatedBeforeMeshing) {
    const tri::Plc3 plc = needle();
    gen::FrontalDelaunay3Options options;
    options.size = gen::SizeFunction3::uniform(0.3);
    const std::string message = exactmesh::testing::error_message<exactmesh::InputError>(
        [&] { (void)gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options); });
    EXPECT_NE(message.find("exceeded at once"), std::string::npos) << message;
    EXPECT_NE(message.find("e+10"), std::string::npos) << message;  // about 2^30 / 0.039 points

    // Its edges ask for more at size 4096 (2^31 / 4096 points on each of three long edges,
    // where the area asks for 150); a size the budget allows meshes it.
    options.size = gen::SizeFunction3::uniform(4096);
    const std::string edges = exactmesh::testing::error_message<exactmesh::InputError>(
        [&] { (void)gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options); });
    EXPECT_NE(edges.find("about 1.57e+06 points"), std::string::npos) << edges;
    options.size = gen::SizeFunction3::uniform(1 << 24);
    const gen::FrontalDelaunay3Result meshed =
        gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
    EXPECT_TRUE(tri::check_boundary_conformity_3d(plc, meshed.mesh).ok);
    EXPECT_LT(meshed.counters.estimated_points, 2'000'000u);
}

TEST(Issue15, RefinementOfANeedleEndsWithoutASegmentCascade) {
    for (const int scale : {0, -600, 600}) {
        tri::Plc3 plc = needle();
        for (double& x : plc.xyz) x = std::ldexp(x, scale);
        gen::DelaunayRefinement3Options options;
        options.radius_edge_bound = 2;
        const gen::DelaunayRefinement3Result refined =
            gen::delaunay_refinement_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
        EXPECT_TRUE(tri::check_boundary_conformity_3d(plc, refined.mesh).ok) << scale;
        EXPECT_LT(refined.mesh.mesh.vertex_count(), 1000u) << scale;
        const gen::RefinementQuality3 quality =
            gen::check_refinement_quality_3d(refined.mesh, options);
        EXPECT_LE(quality.over_bound, refined.counters.rejected_points) << scale;
        EXPECT_GT(quality.small_angle, 0u) << scale;
    }
}

}  // namespace
