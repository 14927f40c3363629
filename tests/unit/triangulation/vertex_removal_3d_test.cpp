// SPDX-License-Identifier: MIT
// Vertex removal in 3D: from a Delaunay tetrahedralization, removing interior vertices one by
// one gives the Delaunay tetrahedralization of the remaining points (the empty-sphere oracle,
// SoS ties included: cubic grids), by flips alone in general position; boundary vertices and
// non-Delaunay stars are refused with VertexRemovalError and the mesh left unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <vector>

#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "tests/support/local_delaunay_3d.hpp"
#include "tests/support/placing_tetrahedralization_3d.hpp"
#include "tests/support/point_sets_3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/vertex_removal_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
namespace orc = exactmesh::oracles;

namespace {

double test_scale() {
    const char* text = std::getenv("EXACTMESH_TEST_SCALE");
    return text == nullptr ? 1.0 : std::max(0.0, std::atof(text));
}

/// The Delaunay tetrahedralization by swapping from the placing start, checked against the
/// oracle (the caller skips the rare stalled start).
bool delaunay_by_swapping(const std::vector<double>& xyz, tri::TetMesh3& out) {
    tri::Tetrahedralization3 mesh = em::testing::placing_tetrahedralization_3d(xyz);
    const auto counters = tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
    if (counters.stalled_faces != 0) return false;
    EXPECT_EQ(orc::tet_set(mesh.tets), orc::empty_sphere_delaunay_3d(xyz));
    out = tri::make_tet_mesh_3d(mesh);
    return true;
}

std::vector<tri::VertIdx> interior_vertices(const tri::TetMesh3& mesh) {
    std::vector<tri::VertIdx> out;
    for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_tet[v] == tri::kNone) continue;
        bool interior = true;
        for (const tri::TetIdx t : tri::vertex_star(mesh, v)) {
            const unsigned lv = mesh.slot_of(t, v);
            for (unsigned k = 0; k < 4; ++k)
                interior = interior && (k == lv || mesh.adj[4 * t + k] != tri::kNone);
        }
        if (interior) out.push_back(v);
    }
    return out;
}

std::vector<std::uint32_t> active_vertices(const tri::TetMesh3& mesh) {
    std::vector<std::uint32_t> out;
    for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        if (mesh.vertex_tet[v] != tri::kNone) out.push_back(v);
    }
    return out;
}

void expect_valid(const tri::TetMesh3& mesh) {
    const auto report = tri::check_topology_3d(tri::to_tetrahedralization_3d(mesh), {true});
    EXPECT_TRUE(report.ok) << report.problem;
}

}  // namespace

TEST(Triangulation_VertexRemoval3, RemovingFromDelaunayGivesTheDelaunayOfTheRest) {
    const int cases = std::max(1, static_cast<int>(30 * test_scale()));
    tri::VertexRemovalCounters counters;
    int meshes = 0;
    for (int seed = 0; seed < cases; ++seed) {
        const std::vector<double> xyz =
            em::testing::random_points_3d(14 + static_cast<std::uint32_t>(seed % 16), 900 + seed);
        tri::TetMesh3 mesh;
        if (!delaunay_by_swapping(xyz, mesh)) continue;
        ++meshes;
        std::mt19937_64 rng(seed);
        for (int round = 0; round < 4; ++round) {
            std::vector<tri::VertIdx> candidates = interior_vertices(mesh);
            if (candidates.empty()) break;
            const tri::VertIdx v = candidates[rng() % candidates.size()];
            tri::remove_vertex_3d(mesh, v, &counters);
            EXPECT_EQ(mesh.vertex_tet[v], tri::kNone);
            expect_valid(mesh);
            const tri::Tetrahedralization3 out = tri::to_tetrahedralization_3d(mesh);
            EXPECT_EQ(orc::tet_set(out.tets),
                      orc::empty_sphere_delaunay_3d(xyz, active_vertices(mesh)))
                << "seed " << seed << " round " << round << " vertex " << v;
        }
    }
    EXPECT_GT(meshes, 0);
    EXPECT_GT(counters.removed, 0u);
    EXPECT_EQ(counters.flips_41, counters.removed);  // general position: flips alone
    EXPECT_EQ(counters.cavity_fallbacks, 0u);
    std::printf(
        "removed %llu vertices: 2-3 %llu, 3-2 %llu, 4-4 %llu, 4-1 %llu, cavity %llu, mean star "
        "%.1f\n",
        static_cast<unsigned long long>(counters.removed),
        static_cast<unsigned long long>(counters.flips_23),
        static_cast<unsigned long long>(counters.flips_32),
        static_cast<unsigned long long>(counters.flips_44),
        static_cast<unsigned long long>(counters.flips_41),
        static_cast<unsigned long long>(counters.cavity_fallbacks),
        static_cast<double>(counters.star_tets) / static_cast<double>(counters.removed));
}

TEST(Triangulation_VertexRemoval3, CubicGridDerefinementStaysDelaunayWithTies) {
    // Grid points: cospherical cubes and coplanar stars; SoS decides, the oracle agrees.
    const std::vector<double> xyz = em::testing::cubic_grid_3d(4);
    tri::TetMesh3 mesh;
    ASSERT_TRUE(delaunay_by_swapping(xyz, mesh));
    tri::VertexRemovalCounters counters;
    const std::vector<tri::VertIdx> inner = interior_vertices(mesh);
    ASSERT_EQ(inner.size(), 8u);
    for (const tri::VertIdx v : inner) {
        tri::remove_vertex_3d(mesh, v, &counters);
        expect_valid(mesh);
        // Locally Delaunay by SoS everywhere in a tetrahedralization of the hull: the SoS
        // Delaunay tetrahedralization [Delaunay34 lemma, with the perturbed lifts].
        EXPECT_EQ(em::testing::count_local_delaunay_3d(tri::to_tetrahedralization_3d(mesh))
                      .not_delaunay_sos,
                  0u)
            << "vertex " << v;
    }
    EXPECT_EQ(counters.removed, 8u);
    // The 3 x 3 x 3 grid's center, against the oracle itself.
    const std::vector<double> small = em::testing::cubic_grid_3d(3);
    tri::TetMesh3 center;
    ASSERT_TRUE(delaunay_by_swapping(small, center));
    tri::remove_vertex_3d(center, 13, &counters);
    EXPECT_EQ(orc::tet_set(tri::to_tetrahedralization_3d(center).tets),
              orc::empty_sphere_delaunay_3d(small, active_vertices(center)));
    std::printf("grid: 2-3 %llu, 3-2 %llu, 4-4 %llu, 4-1 %llu, cavity %llu\n",
                static_cast<unsigned long long>(counters.flips_23),
                static_cast<unsigned long long>(counters.flips_32),
                static_cast<unsigned long long>(counters.flips_44),
                static_cast<unsigned long long>(counters.flips_41),
                static_cast<unsigned long long>(counters.cavity_fallbacks));
}

TEST(Triangulation_VertexRemoval3, BoundaryAndUnusedVerticesAreRefusedAndTheMeshKept) {
    const std::vector<double> xyz = em::testing::random_points_3d(20, 5);
    tri::TetMesh3 mesh;
    ASSERT_TRUE(delaunay_by_swapping(xyz, mesh));
    const auto before = orc::tet_set(tri::to_tetrahedralization_3d(mesh).tets);
    const std::vector<tri::VertIdx> inner = interior_vertices(mesh);
    tri::VertIdx boundary = tri::kNone;
    for (tri::VertIdx v = 0; v < mesh.vertex_count() && boundary == tri::kNone; ++v) {
        if (std::find(inner.begin(), inner.end(), v) == inner.end()) boundary = v;
    }
    ASSERT_NE(boundary, tri::kNone);
    try {
        tri::remove_vertex_3d(mesh, boundary);
        FAIL() << "a boundary vertex was removed";
    } catch (const tri::VertexRemovalError& error) {
        EXPECT_EQ(error.vertex(), boundary);
        EXPECT_NE(std::string(error.what()).find("boundary"), std::string::npos) << error.what();
    }
    EXPECT_THROW(tri::remove_vertex_3d(mesh, 20), tri::VertexRemovalError);
    EXPECT_EQ(orc::tet_set(tri::to_tetrahedralization_3d(mesh).tets), before);
    // Removing twice: the second time it is in no tetrahedron.
    tri::remove_vertex_3d(mesh, inner.front());
    EXPECT_THROW(tri::remove_vertex_3d(mesh, inner.front()), tri::VertexRemovalError);
}

TEST(Triangulation_VertexRemoval3, NonDelaunayStarsEitherCloseValidlyOrAreRefusedUnchanged) {
    // Placing tetrahedralizations are far from Delaunay: each removal must leave a valid mesh,
    // or throw and leave exactly the mesh it was given.
    int removed = 0, refused = 0;
    const int cases = std::max(1, static_cast<int>(20 * test_scale()));
    for (int seed = 0; seed < cases; ++seed) {
        const std::vector<double> xyz = em::testing::random_points_3d(30, 300 + seed);
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(em::testing::placing_tetrahedralization_3d(xyz));
        for (const tri::VertIdx v : interior_vertices(mesh)) {
            const auto before = orc::tet_set(tri::to_tetrahedralization_3d(mesh).tets);
            try {
                tri::remove_vertex_3d(mesh, v);
                ++removed;
                EXPECT_EQ(mesh.vertex_tet[v], tri::kNone);
            } catch (const tri::VertexRemovalError& error) {
                ++refused;
                EXPECT_EQ(error.vertex(), v);
                EXPECT_EQ(orc::tet_set(tri::to_tetrahedralization_3d(mesh).tets), before);
            }
            expect_valid(mesh);
        }
    }
    EXPECT_GT(removed + refused, 0);
    std::printf("non-Delaunay stars: %d removed, %d refused\n", removed, refused);
}

TEST(Triangulation_VertexRemoval3, DerefinementOfAListOverATetrahedralization) {
    const std::vector<double> xyz = em::testing::random_points_3d(40, 77);
    tri::TetMesh3 work;
    ASSERT_TRUE(delaunay_by_swapping(xyz, work));
    std::vector<tri::VertIdx> inner = interior_vertices(work);
    inner.resize(std::min<std::size_t>(inner.size(), 5));
    tri::Tetrahedralization3 mesh = tri::to_tetrahedralization_3d(work);
    tri::VertexRemovalCounters counters;
    tri::remove_vertices_3d(mesh, inner, &counters);
    EXPECT_EQ(counters.removed, inner.size());
    EXPECT_TRUE(tri::check_topology_3d(mesh, {true}).ok);
    EXPECT_EQ(em::testing::count_local_delaunay_3d(mesh).not_delaunay_sos, 0u);
    for (const tri::VertIdx v : inner) {
        EXPECT_EQ(std::count(mesh.tets.begin(), mesh.tets.end(), v), 0);
    }
}
