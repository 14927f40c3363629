// SPDX-License-Identifier: MIT
// check_conforming_mesh_2d: accepts valid meshes that are not Delaunay (where the Delaunay check
// refuses them), and names each kind of invalid mesh: a fold at a vertex (corners overlapping),
// two edges leaving a vertex in one direction, a boundary edge that is no piece, a clockwise
// triangle, a missing segment.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace tri = exactmesh::triangulation;

namespace {

tri::Triangulation2 mesh_of(std::vector<double> xy, std::vector<tri::VertIdx> triangles) {
    tri::Triangulation2 m;
    m.xy = std::move(xy);
    m.triangles = std::move(triangles);
    return m;
}

/// Flags the mesh's edges that are pieces (as producers do); returns the pieces.
std::vector<tri::VertIdx> flagged(tri::Triangulation2& m, std::vector<tri::VertIdx> pieces) {
    m.constrained.assign(m.triangles.size(), 0);
    for (std::size_t e = 0; e < m.triangles.size(); ++e) {
        const tri::VertIdx a = m.triangles[e], b = m.triangles[e - e % 3 + (e + 1) % 3];
        for (std::size_t p = 0; p + 1 < pieces.size(); p += 2) {
            if ((pieces[p] == a && pieces[p + 1] == b) || (pieces[p] == b && pieces[p + 1] == a))
                m.constrained[e] = 1;
        }
    }
    return pieces;
}

/// Every edge of the mesh with one triangle, as pieces (a closed boundary), flagged.
std::vector<tri::VertIdx> boundary_pieces(tri::Triangulation2& m) {
    std::vector<tri::VertIdx> pieces;
    const auto& t = m.triangles;
    for (std::size_t e = 0; e < t.size(); ++e) {
        const tri::VertIdx a = t[e], b = t[e - e % 3 + (e + 1) % 3];
        bool twin = false;
        for (std::size_t f = 0; f < t.size(); ++f)
            twin |= t[f] == b && t[f - f % 3 + (f + 1) % 3] == a;
        if (!twin) pieces.insert(pieces.end(), {a, b});
    }
    return flagged(m, pieces);
}

TEST(CheckConformingMesh2, AcceptsAValidMeshThatIsNotDelaunay) {
    // A kite split along its long diagonal: valid, but the diagonal is not locally Delaunay.
    auto m = mesh_of({0, 0, 4, -1, 8, 0, 4, 1}, {0, 1, 2, 0, 2, 3});
    const auto pieces = boundary_pieces(m);
    ASSERT_EQ(pieces.size(), 8u);
    const auto conforming = tri::check_conforming_mesh_2d(m, 4, {}, pieces);
    EXPECT_TRUE(conforming.ok) << conforming.problem;
    const auto delaunay = tri::check_constrained_delaunay_2d(m, 4, {}, pieces);
    EXPECT_FALSE(delaunay.ok);
}

TEST(CheckConformingMesh2, AcceptsAClosedFanAndSegmentsAsChains) {
    // A hexagon fanned about its centre (vertex 6); segments: the hexagon's sides, one of them
    // given as the whole side 0 - 2 through vertex 1 (collinear).
    const std::vector<double> xy{2, 0, 2, 1, 2, 2, -1, 2, -2, 0, -1, -2, 0, 0};
    std::vector<tri::VertIdx> triangles;
    for (tri::VertIdx k = 0; k < 6; ++k) triangles.insert(triangles.end(), {6, k, (k + 1) % 6});
    auto m = mesh_of(xy, triangles);
    const auto pieces = boundary_pieces(m);
    const std::vector<tri::VertIdx> segments{0, 2, 2, 3, 3, 4, 4, 5, 5, 0};
    const auto report = tri::check_conforming_mesh_2d(m, 7, segments, pieces);
    EXPECT_TRUE(report.ok) << report.problem;
}

TEST(CheckConformingMesh2, RefusesAFoldAtAVertex) {
    // Two triangles at vertex 0 whose corners overlap (45..135 degrees inside 0..90).
    auto m = mesh_of({0, 0, 1, 0, 0, 1, 1, 1, -1, 1}, {0, 1, 2, 0, 3, 4});
    const auto pieces = boundary_pieces(m);
    const auto report = tri::check_conforming_mesh_2d(m, 5, {}, pieces);
    ASSERT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("overlap"), std::string::npos) << report.problem;
    EXPECT_EQ(report.vertices.front(), 0u);
}

TEST(CheckConformingMesh2, RefusesAStarThatWindsTwice) {
    // Six triangles about the origin whose corners are 120 degrees each: they wind twice.
    std::vector<double> xy{0, 0};
    const double c[3][2] = {{1, 0}, {-0.5, 0.8660254037844386}, {-0.5, -0.8660254037844386}};
    for (int k = 0; k < 3; ++k) xy.insert(xy.end(), {c[k][0], c[k][1]});
    for (int k = 0; k < 3; ++k) xy.insert(xy.end(), {2 * c[k][0], 2 * c[k][1]});
    // Corners 1->2, 2->3, 3->1 (inner ring) and 4->5, 5->6, 6->4 (outer ring): no shared edge,
    // so only the corner test sees the double cover.
    auto m = mesh_of(xy, {0, 1, 2, 0, 2, 3, 0, 3, 1, 0, 4, 5, 0, 5, 6, 0, 6, 4});
    const auto report = tri::check_conforming_mesh_2d(m, 7, {}, boundary_pieces(m));
    ASSERT_FALSE(report.ok);
    EXPECT_EQ(report.vertices.front(), 0u);
}

TEST(CheckConformingMesh2, RefusesTwoEdgesInOneDirection) {
    // Edges 0 - 1 and 0 - 3 both along +x.
    auto m = mesh_of({0, 0, 1, 0, 0, 1, 2, 0, 0, -1}, {0, 1, 2, 0, 4, 3});
    const auto report = tri::check_conforming_mesh_2d(m, 5, {}, boundary_pieces(m));
    ASSERT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("same direction"), std::string::npos) << report.problem;
}

TEST(CheckConformingMesh2, RefusesABoundaryEdgeThatIsNoPiece) {
    auto m = mesh_of({0, 0, 1, 0, 0, 1}, {0, 1, 2});
    const auto pieces = flagged(m, {0, 1, 1, 2});  // 2 - 0 missing
    const auto report = tri::check_conforming_mesh_2d(m, 3, {}, pieces);
    ASSERT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("no piece"), std::string::npos) << report.problem;
}

TEST(CheckConformingMesh2, RefusesClockwiseTrianglesAndMissingSegments) {
    auto clockwise = mesh_of({0, 0, 0, 1, 1, 0}, {0, 1, 2});
    EXPECT_FALSE(
        tri::check_conforming_mesh_2d(clockwise, 3, {}, flagged(clockwise, {0, 1, 1, 2, 2, 0})).ok);
    // The square split along 0 - 2; segment 1 - 3 (the other diagonal) is not in it.
    auto square = mesh_of({0, 0, 1, 0, 1, 1, 0, 1}, {0, 1, 2, 0, 2, 3});
    const std::vector<tri::VertIdx> segments{1, 3};
    const auto report = tri::check_conforming_mesh_2d(square, 4, segments, boundary_pieces(square));
    ASSERT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("missing"), std::string::npos) << report.problem;
}

}  // namespace
