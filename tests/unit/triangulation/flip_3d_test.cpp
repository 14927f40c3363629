// SPDX-License-Identifier: MIT
// Unit tests of the 3D local rewrites (triangulation/mesh/flip_3d.*): each split and flip of
// TetStar3 (1-4, 2-6, n-2n; 2-3, 3-2, 4-4 from a vertex), each planned flip (2-3, 3-2, 4-4, 2-2)
// and replace_tets, on small hand-made domains. After each: every tetrahedron positive (exact
// orient3d), adjacency symmetric across the same face, check_topology_3d valid, vertex_tet
// pointing at live holders, and the union of the tetrahedra unchanged (the same boundary faces,
// and random probe points covered by as many tetrahedra as before).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "base/errors.hpp"
#include "predicates/orient3d.hpp"
#include "tests/support/placing_tetrahedralization_3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace {

namespace tri = exactmesh::triangulation;
using exactmesh::predicates::Sign;
using tri::kNone;
using tri::Tet;
using tri::TetIdx;
using tri::VertIdx;

using Face = std::array<VertIdx, 3>;

Sign orient(const tri::TetMesh3& mesh, const Tet& t) {
    return exactmesh::predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                           mesh.point(t[3]));
}

/// A domain mesh from points and tetrahedra given in any orientation (swapped to positive).
tri::TetMesh3 domain(const std::vector<double>& xyz, std::vector<Tet> tets) {
    tri::Tetrahedralization3 mesh;
    mesh.xyz = xyz;
    for (Tet& t : tets) {
        const Sign s = exactmesh::predicates::orient3d(&xyz[3 * t[0]], &xyz[3 * t[1]],
                                                       &xyz[3 * t[2]], &xyz[3 * t[3]]);
        EXPECT_NE(s, Sign::Zero);
        if (s == Sign::Negative) std::swap(t[2], t[3]);
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    return tri::make_tet_mesh_3d(mesh);
}

/// A face rotated to start at its smallest vertex, orientation kept.
Face canonical(Face f) {
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    return f;
}

std::multiset<Face> boundary_faces(const tri::TetMesh3& mesh) {
    std::multiset<Face> faces;
    for (TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (mesh.is_dead(t)) continue;
        for (unsigned k = 0; k < 4; ++k) {
            if (mesh.adj[4 * t + k] == kNone) faces.insert(canonical(mesh.face(4 * t + k)));
        }
    }
    return faces;
}

tri::Tetrahedralization3 em_placing(const std::vector<double>& xyz) {
    return exactmesh::testing::placing_tetrahedralization_3d(xyz);
}

/// Whether q lies strictly inside tetrahedron t (all four face orientations positive).
bool covering_tet(const tri::TetMesh3& mesh, TetIdx t, const double* q) {
    for (unsigned k = 0; k < 4; ++k) {
        const Face f = mesh.face(4 * t + k);
        if (exactmesh::predicates::orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]),
                                            q) != Sign::Positive) {
            return false;
        }
    }
    return true;
}

/// Live tetrahedra holding q strictly inside.
int covering(const tri::TetMesh3& mesh, const double* q) {
    int count = 0;
    for (TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (!mesh.is_dead(t) && covering_tet(mesh, t, q)) ++count;
    }
    return count;
}

/// Random probe points in the bounding box of the mesh's points (slightly enlarged).
std::vector<double> probes(const tri::TetMesh3& mesh, unsigned seed) {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::size_t i = 0; i < mesh.xyz.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], mesh.xyz[i]);
        hi[i % 3] = std::max(hi[i % 3], mesh.xyz[i]);
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(-0.1, 1.1);
    std::vector<double> out;
    for (int i = 0; i < 3000; ++i) {
        for (int c = 0; c < 3; ++c) out.push_back(lo[c] + unit(rng) * (hi[c] - lo[c]));
    }
    return out;
}

std::vector<int> coverage(const tri::TetMesh3& mesh, const std::vector<double>& points) {
    std::vector<int> out;
    for (std::size_t i = 0; i < points.size(); i += 3) out.push_back(covering(mesh, &points[i]));
    return out;
}

/// Every invariant a rewrite must keep.
void expect_valid(const tri::TetMesh3& mesh) {
    for (TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (mesh.is_dead(t)) continue;
        EXPECT_EQ(orient(mesh, mesh.tet(t)), Sign::Positive) << "tetrahedron " << t;
        for (unsigned k = 0; k < 4; ++k) {
            const tri::FaceIdx f = 4 * t + k, g = mesh.adj[f];
            if (g == kNone) continue;
            ASSERT_LT(g, mesh.adj.size());
            EXPECT_FALSE(mesh.is_dead(g / 4)) << "face " << f << " points at a dead tetrahedron";
            EXPECT_EQ(mesh.adj[g], f) << "adjacency not symmetric at face " << f;
            Face back = mesh.face(g);
            std::swap(back[1], back[2]);
            EXPECT_EQ(canonical(mesh.face(f)), canonical(back)) << "twins are not the same face";
        }
    }
    for (VertIdx v = 0; v < mesh.vertex_tet.size(); ++v) {
        const TetIdx t = mesh.vertex_tet[v];
        if (t == kNone) continue;
        EXPECT_FALSE(mesh.is_dead(t));
        EXPECT_LT(mesh.slot_of(t, v), 4u) << "vertex_tet of " << v << " does not hold it";
    }
    const tri::TopologyReport3 report = tri::check_topology_3d(tri::to_tetrahedralization_3d(mesh));
    EXPECT_TRUE(report.ok) << report.problem;
}

/// Runs `rewrite` and checks the invariants, the live count and the unchanged union.
template <class Rewrite>
void expect_rewrite(tri::TetMesh3& mesh, std::uint32_t live_after, Rewrite rewrite,
                    bool same_boundary = true) {
    expect_valid(mesh);
    const std::multiset<Face> boundary = boundary_faces(mesh);
    const std::vector<double> points = probes(mesh, 7);
    const std::vector<int> before = coverage(mesh, points);
    rewrite();
    expect_valid(mesh);
    EXPECT_EQ(mesh.live_tet_count(), live_after);
    if (same_boundary) {
        EXPECT_EQ(boundary_faces(mesh), boundary);
    }
    const std::vector<int> after = coverage(mesh, points);
    EXPECT_EQ(after, before);
    EXPECT_LE(*std::max_element(after.begin(), after.end()), 1);
    EXPECT_GE(std::count(after.begin(), after.end(), 1), 100);  // the probes meet the domain
}

bool holds(const tri::TetMesh3& mesh, TetIdx t, VertIdx v) {
    return mesh.slot_of(t, v) < 4;
}

/// The last of the tetrahedra 0 .. count-1 holding both a and b (kNone if none does).
TetIdx last_tet_holding(const tri::TetMesh3& mesh, TetIdx count, VertIdx a, VertIdx b) {
    TetIdx t = kNone;
    for (TetIdx u = 0; u < count; ++u) {
        if (holds(mesh, u, a) && holds(mesh, u, b)) t = u;
    }
    return t;
}

/// Tetrahedron (0,0,0), (4,0,0), (0,4,0), (0,0,4) and, when asked, its mirror (4,4,4) across
/// the face x + y + z = 4.
std::vector<double> corner_points() {
    return {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 4, 4, 4};
}

/// Edge (0,0,-2)-(0,0,2) (vertices 0, 1) with `ring` apexes around it in the plane z = 0.
std::vector<double> edge_ring_points(const std::vector<std::array<double, 2>>& ring) {
    std::vector<double> xyz = {0, 0, -2, 0, 0, 2};
    for (const auto& p : ring) xyz.insert(xyz.end(), {p[0], p[1], 0});
    return xyz;
}

std::vector<Tet> edge_ring_tets(std::size_t n) {
    std::vector<Tet> tets;
    for (std::size_t i = 0; i < n; ++i) {
        tets.push_back({0, 1, static_cast<VertIdx>(2 + i), static_cast<VertIdx>(2 + (i + 1) % n)});
    }
    return tets;
}

TEST(Triangulation_Flip3, Split14JoinsThePointToTheFourFaces) {
    std::vector<double> xyz = corner_points();
    xyz.resize(12);
    xyz.insert(xyz.end(), {1, 0.5, 1.25});  // p = 4, strictly inside
    tri::TetMesh3 mesh = domain(xyz, {{0, 1, 2, 3}});
    tri::TetStar3 star;
    expect_rewrite(mesh, 4, [&] { star.split_1_4(mesh, 0, 4); });
    EXPECT_EQ(star.created.size(), 4u);
    for (const TetIdx t : star.created) EXPECT_TRUE(holds(mesh, t, 4));
    EXPECT_EQ(tri::vertex_star(mesh, 4).size(), 4u);
}

TEST(Triangulation_Flip3, Split26OnTheSharedFace) {
    std::vector<double> xyz = corner_points();
    xyz.insert(xyz.end(), {1, 1, 2});  // p = 5 on x + y + z = 4, inside the triangle
    tri::TetMesh3 mesh = domain(xyz, {{0, 1, 2, 3}, {4, 1, 2, 3}});
    const unsigned k = mesh.slot_of(0, 0);  // the shared face is opposite vertex 0
    ASSERT_NE(mesh.adj[k], kNone);
    tri::TetStar3 star;
    expect_rewrite(mesh, 6, [&] { star.split_2_6(mesh, 0, k, 5); });
    ASSERT_EQ(star.created.size(), 6u);
    for (const TetIdx t : star.created) EXPECT_TRUE(holds(mesh, t, 5));
    EXPECT_EQ(tri::vertex_star(mesh, 5).size(), 6u);
}

TEST(Triangulation_Flip3, SplitEdgeMakesTwiceTheRing) {
    for (const std::size_t n : {3u, 4u, 5u, 7u}) {
        std::vector<std::array<double, 2>> ring;
        const std::vector<std::array<double, 2>> polygon = {{4, 0},   {3, 3},   {0, 4}, {-3, 2},
                                                            {-4, -1}, {-1, -4}, {3, -3}};
        if (n == 3) {
            ring = {{4, 0}, {-2, 3}, {-2, -3}};
        } else if (n == 4) {
            ring = {{4, 0}, {0, 4}, {-4, 0}, {0, -4}};
        } else if (n == 5) {
            ring = {{4, 0}, {1, 4}, {-3, 2}, {-3, -2}, {1, -4}};
        } else {
            ring = polygon;
        }
        std::vector<double> xyz = edge_ring_points(ring);
        const auto p = static_cast<VertIdx>(xyz.size() / 3);
        xyz.insert(xyz.end(), {0, 0, 0.75});  // on the edge
        tri::TetMesh3 mesh = domain(xyz, edge_ring_tets(n));
        const TetIdx t = 0;
        tri::TetStar3 star;
        expect_rewrite(mesh, static_cast<std::uint32_t>(2 * n), [&] {
            star.split_edge(mesh, t, mesh.slot_of(t, 0), mesh.slot_of(t, 1), p);
        });
        EXPECT_EQ(star.ring().size(), n);
        ASSERT_EQ(star.created.size(), 2 * n);
        for (const TetIdx u : star.created) EXPECT_TRUE(holds(mesh, u, p));
    }
}

/// Two tetrahedra abcd, abce (a, b, c = 1, 2, 3; d = 0; e = 4) with de crossing abc.
tri::TetMesh3 two_three_mesh() {
    return domain(corner_points(), {{0, 1, 2, 3}, {4, 1, 2, 3}});
}

TEST(Triangulation_Flip3, Star23FromAVertexMakesTheEdge) {
    tri::TetMesh3 mesh = two_three_mesh();
    const unsigned k = mesh.slot_of(0, 0);
    tri::TetStar3 star;
    expect_rewrite(mesh, 3, [&] { star.flip_2_3(mesh, 0, k); });
    ASSERT_EQ(star.created.size(), 3u);
    for (const TetIdx t : star.created) {
        EXPECT_TRUE(holds(mesh, t, 0));
        EXPECT_TRUE(holds(mesh, t, 4));  // the new edge de
    }
}

TEST(Triangulation_Flip3, Planned23AgreesWithTheStar) {
    tri::TetMesh3 planned = two_three_mesh();
    tri::FlipPlan3 plan;
    const tri::FaceIdx f = 4 * 0 + planned.slot_of(0, 0);
    ASSERT_TRUE(tri::plan_flip_3d(planned, f, plan));
    EXPECT_EQ(plan.kind, tri::FlipKind3::Flip23);
    EXPECT_EQ(plan.old_count, 2u);
    EXPECT_EQ(plan.made_count, 3u);
    std::vector<TetIdx> created;
    expect_rewrite(planned, 3, [&] { tri::apply_flip_3d(planned, plan, created); });
    EXPECT_EQ(created.size(), 3u);
    // The same tetrahedra (as vertex sets) as the star from d.
    tri::TetMesh3 starred = two_three_mesh();
    tri::TetStar3 star;
    star.flip_2_3(starred, 0, starred.slot_of(0, 0));
    auto sets = [](const tri::TetMesh3& m) {
        std::set<Tet> out;
        for (TetIdx t = 0; t < m.tet_slots(); ++t) {
            if (m.is_dead(t)) continue;
            Tet v = m.tet(t);
            std::sort(v.begin(), v.end());
            out.insert(v);
        }
        return out;
    };
    EXPECT_EQ(sets(planned), sets(starred));
}

/// Three tetrahedra around edge xy = (0,0,-2)-(0,0,2) (vertices 0, 1), apexes z, d, e = 2, 3, 4.
tri::TetMesh3 three_two_mesh() {
    return domain(edge_ring_points({{4, 0}, {-2, 3}, {-2, -3}}), edge_ring_tets(3));
}

TEST(Triangulation_Flip3, Star32RemovesTheEdge) {
    tri::TetMesh3 mesh = three_two_mesh();
    // t = (x, y, z, d) seen from d = 3: t2 across the face opposite d, t3 across the face
    // opposite z.
    const TetIdx t = last_tet_holding(mesh, 3, 2, 3);
    ASSERT_NE(t, kNone);
    tri::TetStar3 star;
    expect_rewrite(mesh, 2,
                   [&] { star.flip_3_2(mesh, t, mesh.slot_of(t, 3), mesh.slot_of(t, 2)); });
    ASSERT_EQ(star.created.size(), 2u);
    for (const TetIdx u : star.created) {
        EXPECT_FALSE(holds(mesh, u, 0) && holds(mesh, u, 1)) << "edge xy survived";
    }
}

TEST(Triangulation_Flip3, Planned32RemovesTheEdge) {
    tri::TetMesh3 mesh = three_two_mesh();
    // The face (x, y, z) between the tetrahedra holding z: de passes beyond edge xy.
    const TetIdx t = last_tet_holding(mesh, 3, 2, 3);
    ASSERT_NE(t, kNone);
    tri::FlipPlan3 plan;
    std::uint64_t edges = 0;
    ASSERT_TRUE(tri::plan_flip_3d(mesh, 4 * t + mesh.slot_of(t, 3), plan, &edges));
    EXPECT_EQ(plan.kind, tri::FlipKind3::Flip32);
    EXPECT_EQ(edges, 1u);
    std::vector<TetIdx> created;
    expect_rewrite(mesh, 2, [&] { tri::apply_flip_3d(mesh, plan, created); });
    EXPECT_EQ(created.size(), 2u);
}

/// The octahedron x, y = (-2,0,0), (2,0,0); d, e = (0,-2,0), (0,2,0); z, w = (0,0,2), (0,0,-2)
/// split into four tetrahedra around xy (x, y, d, e coplanar); with `half`, only the two above
/// (xy then on the boundary).
tri::TetMesh3 octahedron(bool half) {
    const std::vector<double> xyz = {-2, 0, 0, 2, 0, 0, 0, -2, 0, 0, 2, 0, 0, 0, 2, 0, 0, -2};
    // x = 0, y = 1, d = 2, e = 3, z = 4, w = 5; around xy: d, z, e, w.
    std::vector<Tet> tets = {{0, 1, 2, 4}, {0, 1, 4, 3}};
    if (!half) tets.insert(tets.end(), {{0, 1, 3, 5}, {0, 1, 5, 2}});
    return domain(xyz, tets);
}

TEST(Triangulation_Flip3, Star44TurnsTheFlatEdge) {
    tri::TetMesh3 mesh = octahedron(false);
    // t = (x, y, d, z) seen from d = 2; j = z's slot (the face xyd leads to xywd).
    const TetIdx t = last_tet_holding(mesh, 4, 2, 4);
    ASSERT_NE(t, kNone);
    tri::TetStar3 star;
    expect_rewrite(mesh, 4,
                   [&] { star.flip_4_4(mesh, t, mesh.slot_of(t, 2), mesh.slot_of(t, 4)); });
    ASSERT_EQ(star.created.size(), 4u);
    for (const TetIdx u : star.created) {
        EXPECT_TRUE(holds(mesh, u, 2) && holds(mesh, u, 3)) << "every new tetrahedron holds de";
    }
}

TEST(Triangulation_Flip3, Planned44And22TurnTheFlatEdge) {
    for (const bool half : {false, true}) {
        tri::TetMesh3 mesh = octahedron(half);
        const TetIdx t = last_tet_holding(mesh, mesh.tet_slots(), 2, 4);
        ASSERT_NE(t, kNone);
        tri::FlipPlan3 plan;
        // The face (x, y, z) between xydz and xyze.
        ASSERT_TRUE(tri::plan_flip_3d(mesh, 4 * t + mesh.slot_of(t, 2), plan));
        EXPECT_EQ(plan.kind, half ? tri::FlipKind3::Flip22 : tri::FlipKind3::Flip44);
        std::vector<TetIdx> created;
        // The 2-2 trades the diagonal of the two flat boundary faces: the boundary changes,
        // the union does not.
        expect_rewrite(
            mesh, half ? 2 : 4, [&] { tri::apply_flip_3d(mesh, plan, created); }, !half);
        ASSERT_EQ(created.size(), half ? 2u : 4u);
        for (const TetIdx u : created) EXPECT_TRUE(holds(mesh, u, 2) && holds(mesh, u, 3));
    }
}

TEST(Triangulation_Flip3, NoFlipAtAFaceWithoutOneAndTheMeshIsKept) {
    // Shared face (0, 1, 2) in z = 0, apexes (1, 1, 1) above and (6, 6, -1) below: their segment
    // meets z = 0 at (3.5, 3.5, 0), beyond the edge (1, 2), which has no third tetrahedron (a
    // boundary edge): no 2-3 (the union is not convex there), no 3-2, no 4-4.
    const std::vector<double> xyz = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 1, 6, 6, -1};
    tri::TetMesh3 mesh = domain(xyz, {{0, 1, 2, 3}, {0, 1, 2, 4}});
    const std::vector<VertIdx> tv_before = mesh.tv;
    const std::vector<tri::FaceIdx> adj_before = mesh.adj;
    tri::FaceIdx shared = kNone;
    for (unsigned k = 0; k < 4; ++k) {
        if (mesh.adj[k] != kNone) shared = k;
    }
    ASSERT_NE(shared, kNone);
    tri::FlipPlan3 plan;
    EXPECT_FALSE(tri::plan_flip_3d(mesh, shared, plan));
    EXPECT_EQ(tri::flip_face_3d(mesh, shared), tri::FlipKind3::None);
    EXPECT_EQ(mesh.tv, tv_before);
    EXPECT_EQ(mesh.adj, adj_before);
    expect_valid(mesh);
}

TEST(Triangulation_Flip3, ReplaceTetsRefusesASetWithAnotherBoundary) {
    tri::TetMesh3 mesh = two_three_mesh();
    const std::vector<VertIdx> tv_before = mesh.tv;
    const std::vector<tri::FaceIdx> adj_before = mesh.adj;
    const std::vector<TetIdx> old = {0, 1};
    // Only two of the three tetrahedra of the 2-3: a face of the old boundary stays unused.
    std::vector<Tet> partial = {{1, 2, 4, 0}, {2, 3, 4, 0}};
    for (Tet& t : partial) {
        if (orient(mesh, t) == Sign::Negative) std::swap(t[2], t[3]);
    }
    EXPECT_FALSE(tri::replace_tets(mesh, old, partial));
    EXPECT_EQ(mesh.tv, tv_before);
    EXPECT_EQ(mesh.adj, adj_before);
    expect_valid(mesh);
}

TEST(Triangulation_Flip3, RewritesChainAndRecycleSlots) {
    // A placing tetrahedralization of 40 random points, then 40 more points inserted by 1-4
    // splits (located by brute force) and random faces flipped, interleaved: every step keeps
    // the invariants and the union, and dead slots are recycled.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xyz(3 * 80);
    for (double& x : xyz) x = unit(rng);
    const std::vector<double> first(xyz.begin(), xyz.begin() + 3 * 40);
    tri::Tetrahedralization3 start = em_placing(first);
    start.xyz = xyz;  // the later points: vertices of no tetrahedron yet
    tri::TetMesh3 mesh = tri::make_tet_mesh_3d(start);
    const std::multiset<Face> boundary = boundary_faces(mesh);
    const std::vector<double> points = probes(mesh, 5);
    const std::vector<int> before = coverage(mesh, points);
    tri::TetStar3 star;
    std::uint32_t most_alive = mesh.live_tet_count();
    int splits = 0, flips = 0;
    for (VertIdx p = 40; p < 80; ++p) {
        TetIdx holder = kNone;
        for (TetIdx t = 0; t < mesh.tet_slots() && holder == kNone; ++t) {
            if (!mesh.is_dead(t) && covering_tet(mesh, t, mesh.point(p))) holder = t;
        }
        if (holder != kNone) {
            star.split_1_4(mesh, holder, p);
            ++splits;
        }
        for (int i = 0; i < 20; ++i) {
            const auto f = static_cast<tri::FaceIdx>(rng() % mesh.adj.size());
            if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) continue;
            if (tri::flip_face_3d(mesh, f) != tri::FlipKind3::None) ++flips;
        }
        most_alive = std::max(most_alive, mesh.live_tet_count());
        expect_valid(mesh);
        if (HasFailure()) return;
    }
    EXPECT_GT(splits, 20);
    EXPECT_GT(flips, 50);
    EXPECT_EQ(boundary_faces(mesh), boundary);
    EXPECT_EQ(coverage(mesh, points), before);
    EXPECT_LE(mesh.tet_slots(), most_alive + 64);
}

}  // namespace

TEST(Triangulation_Flip3, GivenNeighborsAreCheckedForFacesSharedWithoutALink) {
    // make_tet_mesh_3d with a neighbor list: the links it gives are kept when consistent; a
    // face two tetrahedra share with no link (an interior pair unlinked, or a tetrahedron
    // repeated with no neighbors: its faces on the boundary faces and linked faces of its
    // twin) is refused, as without a neighbor list.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xyz(3 * 40);
    for (double& x : xyz) x = unit(rng);
    tri::Tetrahedralization3 mesh = em_placing(xyz);
    mesh.neighbors.clear();
    const tri::TetMesh3 linked = tri::make_tet_mesh_3d(mesh);
    for (std::size_t f = 0; f < linked.adj.size(); ++f)
        mesh.neighbors.push_back(linked.adj[f] == kNone ? kNone : linked.adj[f] / 4);
    EXPECT_EQ(tri::make_tet_mesh_3d(mesh).adj, linked.adj);
    // An interior pair unlinked.
    std::size_t interior = 0;
    while (linked.adj[interior] == kNone) ++interior;
    tri::Tetrahedralization3 unlinked = mesh;
    unlinked.neighbors[interior] = kNone;
    unlinked.neighbors[linked.adj[interior]] = kNone;
    EXPECT_THROW(tri::make_tet_mesh_3d(unlinked), exactmesh::InputError);
    // Every tetrahedron repeated once in turn, with no neighbors.
    for (TetIdx t = 0; t < mesh.tet_count(); ++t) {
        tri::Tetrahedralization3 twice = mesh;
        twice.tets.insert(twice.tets.end(), mesh.tets.begin() + 4 * t,
                          mesh.tets.begin() + 4 * t + 4);
        twice.neighbors.insert(twice.neighbors.end(), 4, kNone);
        EXPECT_THROW(tri::make_tet_mesh_3d(twice), exactmesh::InputError) << t;
    }
}
