// SPDX-License-Identifier: MIT
// Tests of the constrained variant of triangulation/modification/edge_face_swap_3d
// (SwapConstraints3): locked faces and edges are never removed, the caller's veto refuses a
// swap, on_flip sees each swap, and seeds limit where swapping starts.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"

namespace tri = exactmesh::triangulation;

namespace {

using exactmesh::predicates::Sign;

/// Edge 0-1 pierces triangle 2 3 4 with the three tetrahedra around it: every face wants the
/// 3-2 swap to the two tetrahedra on triangle 2 3 4 (Delaunay and MaxMinDihedral alike).
tri::TetMesh3 three_around_an_edge() {
    std::vector<double> xyz{0, 0, -3, 0, 0, 3, 1, 0, 0, -0.5, 0.875, 0, -0.5, -0.875, 0};
    tri::Tetrahedralization3 mesh;
    const tri::VertIdx ring[3] = {2, 3, 4};
    for (int i = 0; i < 3; ++i) {
        std::array<tri::VertIdx, 4> t{0, 1, ring[i], ring[(i + 1) % 3]};
        if (exactmesh::predicates::orient3d(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]],
                                            &xyz[3 * t[3]]) == Sign::Negative)
            std::swap(t[2], t[3]);
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    mesh.xyz = xyz;
    return tri::make_tet_mesh_3d(mesh);
}

/// Face 0 1 2 with apexes 3 above and 4 below: the 2-3 swap to edge 3-4 (segment 3-4 crosses
/// the face; the flat upper tetrahedron makes both criteria prefer it).
tri::TetMesh3 two_across_a_face() {
    tri::Tetrahedralization3 mesh;
    mesh.xyz = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0.25, 1, 1, -2};
    mesh.tets = {1, 0, 2, 3, 0, 1, 2, 4};
    return tri::make_tet_mesh_3d(mesh);
}

void expect_valid(const tri::TetMesh3& mesh) {
    const tri::TopologyReport3 report =
        tri::check_topology_3d(tri::to_tetrahedralization_3d(mesh), {true});
    EXPECT_TRUE(report.ok) << report.problem;
}

}  // namespace

TEST(Triangulation_EdgeFaceSwap3Constrained, UnconstrainedBothSwapsHappen) {
    for (const auto criterion :
         {tri::SwapCriterion3::Delaunay, tri::SwapCriterion3::MaxMinDihedral}) {
        tri::TetMesh3 a = three_around_an_edge();
        EXPECT_EQ(tri::swap_faces_3d(a, criterion, {}).flips_32, 1u);
        tri::TetMesh3 b = two_across_a_face();
        EXPECT_EQ(tri::swap_faces_3d(b, criterion, {}).flips_23, 1u);
    }
}

TEST(Triangulation_EdgeFaceSwap3Constrained, ALockedEdgeOrFaceIsNeverRemoved) {
    // 3-2: the edge 0-1, or any face around it, locked: no swap. A locked face that the swap
    // creates (2 3 4) or keeps (0 2 3) does not stop it.
    struct Lock {
        std::vector<std::array<tri::VertIdx, 3>> faces;
        std::vector<std::array<tri::VertIdx, 2>> edges;
        bool swaps;
    };
    const Lock locks32[] = {{{}, {{0, 1}}, false},
                            {{{1, 0, 2}}, {}, false},
                            {{{3, 0, 1}}, {}, false},
                            {{{2, 3, 4}}, {{2, 3}}, true},
                            {{{0, 2, 3}}, {{0, 2}}, true}};
    for (const Lock& lock : locks32) {
        tri::SwapLocks3 locks;
        for (const auto& f : lock.faces) locks.add_face(f[0], f[1], f[2]);
        for (const auto& e : lock.edges) locks.add_edge(e[0], e[1]);
        locks.finish();
        tri::SwapConstraints3 constraints;
        constraints.locks = &locks;
        tri::TetMesh3 mesh = three_around_an_edge();
        const auto counters =
            tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
        EXPECT_EQ(counters.flips_32, lock.swaps ? 1u : 0u);
        EXPECT_EQ(counters.locked > 0, !lock.swaps);
        EXPECT_EQ(mesh.live_tet_count(), lock.swaps ? 2u : 3u);
        expect_valid(mesh);
    }
    // 2-3: the face 0 1 2 locked (in either orientation) stays.
    tri::SwapLocks3 locks;
    locks.add_face(2, 1, 0);
    locks.finish();
    EXPECT_TRUE(locks.face_locked(0, 1, 2));
    EXPECT_FALSE(locks.edge_locked(0, 1));
    tri::SwapConstraints3 constraints;
    constraints.locks = &locks;
    tri::TetMesh3 mesh = two_across_a_face();
    const auto counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay, constraints);
    EXPECT_EQ(counters.flips(), 0u);
    EXPECT_EQ(counters.locked, 1u);
    EXPECT_EQ(mesh.live_tet_count(), 2u);
}

TEST(Triangulation_EdgeFaceSwap3Constrained, TheVetoRefusesAndOnFlipSeesEachSwap) {
    tri::SwapConstraints3 constraints;
    unsigned asked = 0;
    constraints.accept = [&](const tri::FlipPlan3& plan) {
        ++asked;
        EXPECT_EQ(plan.kind, tri::FlipKind3::Flip32);
        return false;
    };
    tri::TetMesh3 mesh = three_around_an_edge();
    auto counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
    EXPECT_EQ(counters.flips(), 0u);
    EXPECT_EQ(counters.vetoed, asked);
    EXPECT_GT(asked, 0u);

    std::vector<tri::TetIdx> seen;
    constraints.accept = nullptr;
    constraints.on_flip = [&](const tri::FlipPlan3& plan, const std::vector<tri::TetIdx>& created) {
        EXPECT_EQ(created.size(), plan.made_count);
        for (unsigned i = 0; i < plan.made_count; ++i)
            EXPECT_EQ(mesh.tet(created[i]), plan.made[i]);
        seen = created;
    };
    counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
    EXPECT_EQ(counters.flips_32, 1u);
    EXPECT_EQ(seen.size(), 2u);
    expect_valid(mesh);
}

TEST(Triangulation_EdgeFaceSwap3Constrained, SeedsLimitWhereSwappingStarts) {
    // Seeded with a boundary face only: nothing interior is examined, nothing swaps.
    tri::TetMesh3 mesh = two_across_a_face();
    tri::FaceIdx boundary = tri::kNone, interior = tri::kNone;
    for (tri::FaceIdx f = 0; f < 8; ++f) (mesh.adj[f] == tri::kNone ? boundary : interior) = f;
    tri::SwapConstraints3 constraints;
    const std::vector<tri::FaceIdx> only_boundary{boundary};
    constraints.seeds = only_boundary;
    auto counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
    EXPECT_EQ(counters.faces_examined, 0u);
    EXPECT_EQ(counters.flips(), 0u);
    const std::vector<tri::FaceIdx> the_face{interior};
    constraints.seeds = the_face;
    counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
    EXPECT_EQ(counters.flips_23, 1u);
    expect_valid(mesh);
}

TEST(Triangulation_EdgeFaceSwap3Constrained, OnlyFacesOfWantedTetrahedraAreExamined) {
    // `wanted` false for both tetrahedra of the shared face: it is skipped before any plan (no
    // face examined, nothing swaps); true for one of them: the 2-3 swap is made as without it.
    for (const tri::TetIdx chosen : {tri::TetIdx{0}, tri::TetIdx{1}}) {
        tri::TetMesh3 mesh = two_across_a_face();
        tri::SwapConstraints3 constraints;
        constraints.wanted = [](tri::TetIdx) { return false; };
        auto counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
        EXPECT_EQ(counters.faces_examined, 0u);
        EXPECT_EQ(counters.flips(), 0u);
        constraints.wanted = [chosen](tri::TetIdx t) { return t == chosen; };
        counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
        EXPECT_EQ(counters.flips_23, 1u) << chosen;
        expect_valid(mesh);
    }
}
