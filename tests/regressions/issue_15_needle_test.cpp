// SPDX-License-Identifier: MIT
// Issue 15, hostile inputs: a needle. The tetrahedron (0,0,0), (1,2^31,0), (0,1,0), (0,0,1) has
// a volume of 1/6 but facets of area about 2^30. Frontal insertion estimated its Steiner points
// from the volume alone (about 50 at size 0.3) and then placed points on the surface for minutes
// (about 10^10 of them). The estimate now takes the most of the volume's, the surface's and the
// segments' counts, so the size is refused at once with the estimate; a size the budget allows
// meshes it.
#include <gtest/gtest.h>

#include <string>

#include "base/errors.hpp"
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
    const std::string message = exactmesh::testing::error_message<exactmesh::InputError>([&] {
        (void)gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
    });
    EXPECT_NE(message.find("exceeded at once"), std::string::npos) << message;
    EXPECT_NE(message.find("e+10"), std::string::npos) << message;  // about 2^30 / 0.039 points

    // Its edges ask for more at size 4096 (2^31 / 4096 points on each of three long edges,
    // where the area asks for 150); a size the budget allows meshes it.
    options.size = gen::SizeFunction3::uniform(4096);
    const std::string edges = exactmesh::testing::error_message<exactmesh::InputError>([&] {
        (void)gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
    });
    EXPECT_NE(edges.find("about 1.57e+06 points"), std::string::npos) << edges;
    options.size = gen::SizeFunction3::uniform(1 << 24);
    const gen::FrontalDelaunay3Result meshed =
        gen::frontal_delaunay_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
    EXPECT_TRUE(tri::check_boundary_conformity_3d(plc, meshed.mesh).ok);
    EXPECT_LT(meshed.counters.estimated_points, 2'000'000u);
}

}  // namespace
