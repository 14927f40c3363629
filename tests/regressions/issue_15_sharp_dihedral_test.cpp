// SPDX-License-Identifier: MIT
// Issue 15: 3D Delaunay refinement did not terminate where two facets meet at a sharp dihedral
// angle. A vertex on facet B lay inside the equatorial spheres of facet A's subfaces next to
// their common segment; each split put a point on A inside B's spheres, and the cascade
// converged on the segment (whose subsegments were encroached too): a triangular prism whose
// side facets meet at 45 degrees (`exactmesh tetmesh wedge.off --max-volume 0.01`) ran 69,038
// subface and 30,961 subsegment splits into a budget of 10^5; a tetrahedron with dihedral
// angles of 45 degrees likewise (--max-volume 0.05). Facets meeting at below 60 degrees are now
// sharp (SharpFacets3, TetGen's sharp segments): their encroachment of each other and of the
// segment between them splits nothing, and a tetrahedron whose shortest edge joins points of two
// sharp facets is spared by the small-input-angle rule, in refinement and in its exact check alike.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/small_angle_rule_3d.hpp"
#include "io/plc_format.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace io = exactmesh::io;
namespace tri = exactmesh::triangulation;

// A triangular prism over the right triangle (0,0), (1,0), (1,1): its side facets meet at 45
// degrees along the vertical edges over (0,0) and (1,1), at 90 over (1,0).
constexpr const char* kWedge =
    "OFF\n6 5 0\n0 0 0\n1 0 0\n1 1 0\n0 0 1\n1 0 1\n1 1 1\n"
    "3 0 2 1\n3 3 4 5\n4 0 1 4 3\n4 1 2 5 4\n4 2 0 3 5\n";
// A tetrahedron over the unit right triangle, apex (0.3, 0.3, 0.3): dihedral angles of 45, 45
// and 46.7 degrees at the base's edges.
constexpr const char* kTetrahedron =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0.3 0.3 0.3\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
// A corner tetrahedron (dihedral angles of 90 and 54.7 degrees) and a cube (90 degrees).
constexpr const char* kCorner =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";
constexpr const char* kCube =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

tri::Plc3 plc_of(const char* off, int scale_exponent = 0) {
    tri::Plc3 plc = io::plc_from_file(io::parse_off(off, "issue_15.off"));
    for (double& x : plc.xyz) x = std::ldexp(x, scale_exponent);
    tri::validate_plc_3d_input(plc);
    return plc;
}

struct Refined {
    gen::DelaunayRefinement3Result result;
    gen::RefinementQuality3 quality;
};

Refined refine(const tri::Plc3& plc, double max_volume) {
    gen::DelaunayRefinement3Options options;
    options.max_volume = max_volume;
    options.max_steiner_points = 100000;
    Refined out;
    out.result = gen::delaunay_refinement_3d(plc, tri::boundary_recovery_3d(plc).mesh, options);
    out.quality = gen::check_refinement_quality_3d(out.result.mesh, options);
    return out;
}

std::size_t sharp_pairs(const tri::Plc3& plc) {
    const tri::ConformingMesh3 mesh = tri::boundary_recovery_3d(plc).mesh;
    const gen::SharpFacets3 sharp(mesh, mesh.mesh.xyz);
    std::size_t count = 0;
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f)
        for (std::uint32_t g = f + 1; g < plc.facets.size(); ++g) count += sharp.sharp(f, g);
    return count;
}

TEST(Issue15, SharpFacetsAreThePairsBelowSixtyDegrees) {
    EXPECT_EQ(sharp_pairs(plc_of(kWedge)), 2u);        // 45, 45; the others 90
    EXPECT_EQ(sharp_pairs(plc_of(kTetrahedron)), 3u);  // 45, 45, 46.7 (the others 97, 120)
    EXPECT_EQ(sharp_pairs(plc_of(kCorner)), 3u);       // the three 54.7-degree edges
    EXPECT_EQ(sharp_pairs(plc_of(kCube)), 0u);
    for (const int e : {-600, 600}) {
        EXPECT_EQ(sharp_pairs(plc_of(kWedge, e)), 2u);
        EXPECT_EQ(sharp_pairs(plc_of(kTetrahedron, e)), 3u);
    }
}

TEST(Issue15, WedgeWithSharpDihedralTerminates) {
    const Refined refined = refine(plc_of(kWedge), 0.01);
    EXPECT_LT(refined.result.counters.insertions, 5000u);
    EXPECT_EQ(refined.quality.over_volume, 0u);
    EXPECT_LE(refined.quality.over_bound, refined.result.counters.rejected_points);
}

TEST(Issue15, TetrahedronWithSharpDihedralsTerminates) {
    // 0.05 is the tetrahedron's own volume: only the apex's encroachment of the base started
    // the cascade. At 0.005 the tetrahedra the rule spares are those refinement counted. (The
    // edges from the base's corners to the apex run over the base at 21.5 degrees, so the
    // base is also sharp at them (SharpFacets3's segments over facets): its points no longer
    // split them, and no tetrahedron is left to spare: 13 vertices, 0 spared, where there were
    // 15 and 2.)
    for (const double bound : {0.05, 0.005}) {
        const Refined refined = refine(plc_of(kTetrahedron), bound);
        EXPECT_LT(refined.result.counters.insertions, 5000u) << bound;
        EXPECT_EQ(refined.quality.over_volume, 0u) << bound;
        EXPECT_LE(refined.quality.over_bound, refined.result.counters.rejected_points) << bound;
        EXPECT_EQ(refined.quality.small_angle, refined.result.counters.small_angle_tets) << bound;
    }
}

TEST(Issue15, ScaledWedgeGivesTheScaledMesh) {
    const Refined unit = refine(plc_of(kWedge), 0.01);
    const auto& m = unit.result.mesh.mesh;
    for (const int e : {-300, 300}) {
        const Refined scaled = refine(plc_of(kWedge, e), std::ldexp(0.01, 3 * e));
        const auto& s = scaled.result.mesh.mesh;
        ASSERT_EQ(s.vertex_count(), m.vertex_count()) << e;
        ASSERT_EQ(s.tets, m.tets) << e;
        for (std::size_t i = 0; i < m.xyz.size(); ++i)
            ASSERT_EQ(s.xyz[i], std::ldexp(m.xyz[i], e)) << e << " " << i;
        EXPECT_EQ(scaled.quality.small_angle, unit.quality.small_angle);
        EXPECT_EQ(scaled.quality.over_bound, unit.quality.over_bound);
    }
}

}  // namespace
