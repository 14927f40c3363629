// SPDX-License-Identifier: MIT
// 3D flips against CGAL's Delaunay_triangulation_3 (Epick), the reference:
//  (a) Delaunay insertion by flips [Joe91]: from CGAL's tetrahedralization of some points,
//      each further point splits the tetrahedra holding it (1-4, or 2-6 / n-2n on a face or an
//      edge) and Delaunay edge-face swapping runs: never a stall, and the result is CGAL's
//      tetrahedralization of all the points (identical tetrahedra: random points, unique);
//  (b) Delaunay swapping from CGAL's tetrahedralization scrambled by random valid swaps returns
//      to CGAL's whenever it does not stall (3D can stall: edge_face_swap_3d_test keeps one);
//  (d) vertex removal from CGAL's tetrahedralization gives CGAL's tetrahedralization of the
//      remaining points (identical when unique; on cubic grids, where it is not, both are
//      exactly Delaunay and ours is the SoS one).
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

#include "predicates/orient3d.hpp"
#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "tests/support/local_delaunay_3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/vertex_removal_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
namespace orc = exactmesh::oracles;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
using em::predicates::Sign;

double test_scale() {
    const char* s = std::getenv("EXACTMESH_TEST_SCALE");
    return s ? std::max(0.0, std::atof(s)) : 1.0;
}

/// CGAL's finite tetrahedra of the points `active` (global indices kept), in our orientation.
tri::Tetrahedralization3 cgal_delaunay(const std::vector<double>& xyz,
                                       const std::vector<std::uint32_t>& active) {
    std::vector<std::pair<K::Point_3, std::uint32_t>> points;
    for (const std::uint32_t v : active)
        points.emplace_back(K::Point_3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]), v);
    CgalDelaunay dt(points.begin(), points.end());
    tri::Tetrahedralization3 mesh;
    mesh.xyz = xyz;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        std::array<std::uint32_t, 4> t{c->vertex(0)->info(), c->vertex(1)->info(),
                                       c->vertex(2)->info(), c->vertex(3)->info()};
        if (em::predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                     mesh.point(t[3])) == Sign::Negative) {
            std::swap(t[0], t[1]);
        }
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    tri::link_neighbors_3d(mesh);
    return mesh;
}

std::vector<std::uint32_t> first(std::uint32_t n) {
    std::vector<std::uint32_t> v(n);
    for (std::uint32_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

/// Four far corners (a big tetrahedron holding the unit cube), then n random points inside.
std::vector<double> points_in_tetrahedron(std::uint32_t n, std::uint64_t seed) {
    std::vector<double> xyz{-3, -3, -3, 9, -3.1, -2.9, -3.2, 9.1, -3, -2.9, -3, 9.2};
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::uint32_t i = 0; i < 3 * n; ++i) xyz.push_back(unit(rng));
    return xyz;
}

/// Splits the tetrahedra whose closure holds v (brute-force location) by joining v to their
/// boundary faces: 1-4, 2-6 or n-2n.
void insert_point(tri::TetMesh3& mesh, tri::VertIdx v) {
    std::vector<tri::TetIdx> holding;
    for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (mesh.is_dead(t)) continue;
        bool inside = true;
        for (unsigned k = 0; k < 4 && inside; ++k) {
            const auto f = mesh.face(4 * t + k);
            inside = em::predicates::orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]),
                                              mesh.point(v)) != Sign::Negative;
        }
        if (inside) holding.push_back(t);
    }
    ASSERT_FALSE(holding.empty());
    std::vector<tri::Tet> made;
    for (const tri::TetIdx t : holding) {
        for (unsigned k = 0; k < 4; ++k) {
            const tri::FaceIdx twin = mesh.adj[4 * t + k];
            if (twin != tri::kNone &&
                std::find(holding.begin(), holding.end(), twin / 4) != holding.end())
                continue;
            const auto f = mesh.face(4 * t + k);
            if (em::predicates::orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]),
                                         mesh.point(v)) == Sign::Positive) {
                made.push_back({f[0], f[1], f[2], v});
            }
        }
    }
    mesh.vertex_tet.resize(mesh.vertex_count(), tri::kNone);
    ASSERT_TRUE(tri::replace_tets(mesh, holding, made));
}

}  // namespace

TEST(Differential_Swap3VsCgal, DelaunayInsertionByFlipsReachesCgalsTetrahedralization) {
    const int cases = std::max(1, static_cast<int>(12 * test_scale()));
    for (int seed = 0; seed < cases; ++seed) {
        const std::uint32_t n = 50 + 40 * static_cast<std::uint32_t>(seed % 5);
        const std::vector<double> xyz = points_in_tetrahedron(n, 10 + seed);
        const std::uint32_t start = 4 + n / 4;
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(cgal_delaunay(xyz, first(start)));
        for (tri::VertIdx v = start; v < n + 4; ++v) {
            insert_point(mesh, v);
            const tri::EdgeFaceSwapCounters counters =
                tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
            ASSERT_EQ(counters.stalled_faces, 0u) << "seed " << seed << " point " << v;
        }
        const tri::Tetrahedralization3 ours = tri::to_tetrahedralization_3d(mesh);
        EXPECT_TRUE(tri::check_topology_3d(ours, {true}).ok);
        EXPECT_EQ(orc::tet_set(ours.tets), orc::tet_set(cgal_delaunay(xyz, first(n + 4)).tets))
            << "seed " << seed;
    }
}

TEST(Differential_Swap3VsCgal, DelaunaySwappingUndoesRandomSwapsUnlessItStalls) {
    const int cases = std::max(1, static_cast<int>(12 * test_scale()));
    int reached = 0, stalled = 0;
    for (int seed = 0; seed < cases; ++seed) {
        const std::uint32_t n = 100 + 100 * static_cast<std::uint32_t>(seed % 4);
        const std::vector<double> xyz = points_in_tetrahedron(n, 50 + seed);
        const tri::Tetrahedralization3 reference = cgal_delaunay(xyz, first(n + 4));
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(reference);
        std::mt19937_64 rng(seed);
        std::uint64_t scrambled = 0;
        for (int i = 0; i < 4 * static_cast<int>(n); ++i) {
            const auto f = static_cast<tri::FaceIdx>(rng() % mesh.adj.size());
            if (tri::flip_face_3d(mesh, f) != tri::FlipKind3::None) ++scrambled;
        }
        ASSERT_GT(scrambled, 0u);
        const tri::EdgeFaceSwapCounters counters =
            tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
        const tri::Tetrahedralization3 ours = tri::to_tetrahedralization_3d(mesh);
        EXPECT_TRUE(tri::check_topology_3d(ours, {true}).ok);
        if (counters.stalled_faces == 0) {
            ++reached;
            EXPECT_EQ(orc::tet_set(ours.tets), orc::tet_set(reference.tets)) << "seed " << seed;
        } else {
            ++stalled;
        }
    }
    EXPECT_GT(reached, 0);
    std::printf("scrambled CGAL tetrahedralizations: %d back to CGAL's, %d stalled\n", reached,
                stalled);
}

TEST(Differential_Swap3VsCgal, VertexRemovalGivesCgalsTetrahedralizationOfTheRest) {
    const int cases = std::max(1, static_cast<int>(8 * test_scale()));
    tri::VertexRemovalCounters counters;
    for (int seed = 0; seed < cases; ++seed) {
        const std::uint32_t n = 200 + 100 * static_cast<std::uint32_t>(seed % 3);
        const std::vector<double> xyz = points_in_tetrahedron(n, 80 + seed);
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(cgal_delaunay(xyz, first(n + 4)));
        std::vector<std::uint32_t> remaining = first(n + 4);
        std::mt19937_64 rng(seed);
        // Remove a third of the inner points (the four corners hold the hull).
        for (std::uint32_t i = 0; i < n / 3; ++i) {
            const auto pick = 4 + static_cast<std::size_t>(rng() % (remaining.size() - 4));
            const tri::VertIdx v = remaining[pick];
            tri::remove_vertex_3d(mesh, v, &counters);
            remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(pick));
        }
        const tri::Tetrahedralization3 ours = tri::to_tetrahedralization_3d(mesh);
        EXPECT_TRUE(tri::check_topology_3d(ours, {true}).ok);
        EXPECT_EQ(orc::tet_set(ours.tets), orc::tet_set(cgal_delaunay(xyz, remaining).tets))
            << "seed " << seed;
    }
    EXPECT_EQ(counters.cavity_fallbacks, 0u);
}

TEST(Differential_Swap3VsCgal, VertexRemovalOnCubicGridsStaysDelaunay) {
    // Not unique: CGAL's and ours may differ among cospherical points; both must be exactly
    // Delaunay (plain insphere), ours also for the SoS ties, with the same vertices.
    std::vector<double> xyz;
    const int side = 5;
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            for (int k = 0; k < side; ++k) xyz.insert(xyz.end(), {double(i), double(j), double(k)});
        }
    }
    const auto n = static_cast<std::uint32_t>(xyz.size() / 3);
    tri::TetMesh3 mesh = tri::make_tet_mesh_3d(cgal_delaunay(xyz, first(n)));
    std::vector<std::uint32_t> remaining = first(n);
    tri::VertexRemovalCounters counters;
    for (int i = 1; i < side - 1; ++i) {
        for (int j = 1; j < side - 1; j += 2) {
            for (int k = 1; k < side - 1; ++k) {
                const auto v = static_cast<tri::VertIdx>((i * side + j) * side + k);
                tri::remove_vertex_3d(mesh, v, &counters);
                remaining.erase(std::find(remaining.begin(), remaining.end(), v));
            }
        }
    }
    const tri::Tetrahedralization3 ours = tri::to_tetrahedralization_3d(mesh);
    EXPECT_TRUE(tri::check_topology_3d(ours, {true}).ok);
    const auto local = em::testing::count_local_delaunay_3d(ours);
    EXPECT_EQ(local.not_delaunay, 0u);
    EXPECT_EQ(local.not_delaunay_sos, 0u);
    const tri::Tetrahedralization3 theirs = cgal_delaunay(xyz, remaining);
    EXPECT_EQ(em::testing::count_local_delaunay_3d(theirs).not_delaunay, 0u);
    std::vector<std::uint32_t> used(ours.tets.begin(), ours.tets.end()),
        cgal_used(theirs.tets.begin(), theirs.tets.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::sort(cgal_used.begin(), cgal_used.end());
    cgal_used.erase(std::unique(cgal_used.begin(), cgal_used.end()), cgal_used.end());
    EXPECT_EQ(used, cgal_used);
    EXPECT_EQ(used, remaining);
}
