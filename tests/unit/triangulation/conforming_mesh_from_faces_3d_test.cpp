// SPDX-License-Identifier: MIT
// Tests of triangulation/recovery_3d/conforming_mesh_from_faces_3d: meshes of the 3D
// generators (refinement, frontal insertion, the octree) stripped to what their files hold
// (vertices, tetrahedra, the faces on facets) are read back and pass
// check_boundary_conformity_3d, on the sample domains, a turned cube with free vertices
// attached to its edges, and random star-shaped PLCs; meshes spoilt in the ways a file can be
// (a tetrahedron left out, a face on no facet, a facet vertex moved off its facet, a face of
// another facet's marker dropped) are not.
#include "triangulation/recovery_3d/conforming_mesh_from_faces_3d.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_mesh_3d.hpp"
#include "tests/support/plcs_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::triangulation {
namespace {

namespace gen = exactmesh::generators;

/// The check of `cm` read back from its vertices, tetrahedra and subfaces alone: "" when it
/// passes, else the problem.
std::string read_back(const Plc3& plc, const ConformingMesh3& cm) {
    const ConformingMeshReading3 reading = conforming_mesh_from_faces_3d(plc, cm.mesh, cm.subfaces);
    if (!reading.problem.empty()) return reading.problem;
    const BoundaryConformityReport3 report = check_boundary_conformity_3d(plc, reading.mesh);
    return report.ok ? "" : report.problem;
}

ConformingMesh3 refined(const Plc3& plc, double max_volume) {
    gen::DelaunayRefinement3Options options;
    options.max_volume = max_volume;
    return gen::delaunay_refinement_3d(plc, boundary_recovery_3d(plc).mesh, options).mesh;
}

TEST(Triangulation_ConformingMeshFromFaces3d, GeneratorsMeshesReadBackAndPass) {
    for (const gen::SampleDomain3 d : gen::kAllSampleDomains3) {
        Plc3 plc = gen::sample_domain_3d(d);
        prepare_plc_for_meshing_3d(plc);
        const std::string name(gen::sample_domain_3d_name(d));
        EXPECT_EQ(read_back(plc, refined(plc, 0.01)), "") << name << " refinement";
        gen::FrontalDelaunay3Options frontal;
        frontal.size = gen::SizeFunction3::uniform(0.3);
        EXPECT_EQ(
            read_back(plc,
                      gen::frontal_delaunay_3d(plc, boundary_recovery_3d(plc).mesh, frontal).mesh),
            "")
            << name << " frontal";
        gen::OctreeMesh3Options octree;
        octree.size = gen::SizeFunction3::uniform(0.3);
        EXPECT_EQ(
            read_back(plc, gen::octree_mesh_3d(plc, boundary_recovery_3d(plc).mesh, octree).mesh),
            "")
            << name << " octree";
    }
    // Random star-shaped PLCs (small input angles). Seeds 5 and 6 were misread: refinement
    // encroached, from segments running over a facet at 9 to 28 degrees from a common vertex,
    // the facet's subfaces and back into that vertex, and put a third of the points within 1e-9
    // of it, some an ulp apart (faces of three such points the reading cannot place). Such a
    // segment and facet are now a sharp pair (SharpFacets3): 182 and 146 vertices, not 534 and
    // 580, and they read back. Seed 9 still cascades at 38 to 42 degrees (README, known gaps).
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        Plc3 plc = random_star(seed, 14);
        prepare_plc_for_meshing_3d(plc);
        const ConformingMesh3 cm = refined(plc, 0.002);
        EXPECT_EQ(read_back(plc, cm), "") << "star " << seed;
        EXPECT_LT(cm.mesh.vertex_count(), 400u) << "star " << seed;
    }
}

TEST(Triangulation_ConformingMeshFromFaces3d, AttachedFreeVerticesAndTurnedFacets) {
    // A cube turned by a rotation (its facets planar within rounding only) with a free vertex
    // at the rounded midpoint of each of two edges: attached to those segments, whose first
    // three polygon corners are then within rounding of collinear (their cross product is
    // noise: the facet's plane comes from its largest input triangle).
    Plc3 plc = box(1, 1, 1);
    const double c = 0.8, s = 0.6;  // a rotation about z by atan(3/4)
    for (std::size_t i = 0; i < plc.xyz.size(); i += 3) {
        const double x = plc.xyz[i], y = plc.xyz[i + 1];
        plc.xyz[i] = c * x - s * y;
        plc.xyz[i + 1] = s * x + c * y;
    }
    for (const auto& [a, b] : {std::pair{0u, 1u}, std::pair{2u, 6u}}) {
        for (int k = 0; k < 3; ++k)
            plc.xyz.push_back(0.5 * plc.xyz[3 * a + static_cast<unsigned>(k)] +
                              0.5 * plc.xyz[3 * b + static_cast<unsigned>(k)]);
    }
    prepare_plc_for_meshing_3d(plc);
    EXPECT_EQ(read_back(plc, refined(plc, 0.003)), "");
}

/// Whether `problem` names vertex v inside a face's parentheses ("(a, b, v)").
bool names_vertex(const std::string& problem, VertIdx v) {
    const std::string n = std::to_string(v);
    for (const std::string& form : {"(" + n + ",", " " + n + ",", " " + n + ")"})
        if (problem.find(form) != std::string::npos) return true;
    return false;
}

TEST(Triangulation_ConformingMeshFromFaces3d, SpoiltMeshesFail) {
    Plc3 plc = gen::sample_domain_3d(gen::SampleDomain3::BoxWithHole);
    prepare_plc_for_meshing_3d(plc);
    const ConformingMesh3 good = refined(plc, 0.001);
    ASSERT_EQ(read_back(plc, good), "");
    // A facet vertex moved off its facet (inward, by a hundredth): its faces lie on no facet.
    {
        ConformingMesh3 moved = good;
        VertIdx spoilt = kNone;
        for (VertIdx v = good.input_vertex_count; v < good.mesh.vertex_count(); ++v) {
            if (good.vertex_feature[v] != VertexFeature3::Facet) continue;
            for (int k = 0; k < 3; ++k) {
                double& x = moved.mesh.xyz[3 * std::size_t{v} + static_cast<unsigned>(k)];
                x = 0.99 * x + 0.005;
            }
            spoilt = v;
            break;
        }
        ASSERT_NE(spoilt, kNone);
        // The problem named is a face of the moved vertex that lies on no facet.
        const std::string problem = read_back(plc, moved);
        EXPECT_NE(problem.find("lies on no facet"), std::string::npos) << problem;
        EXPECT_TRUE(names_vertex(problem, spoilt)) << spoilt << ": " << problem;
    }
    // A subface left out of the faces: a boundary face that is no subface.
    {
        ConformingMesh3 fewer = good;
        fewer.subfaces.resize(fewer.subfaces.size() - 3);
        const std::string problem = read_back(plc, fewer);
        EXPECT_NE(problem.find("facet"), std::string::npos) << problem;
    }
    // A face that lies on no facet: one through a vertex inside the domain.
    {
        ConformingMesh3 extra = good;
        bool added = false;
        VertIdx inner = kNone;
        for (std::size_t t = 0; 4 * t < good.mesh.tets.size() && !added; ++t) {
            const VertIdx* v = &good.mesh.tets[4 * t];
            for (unsigned k = 0; k < 4 && !added; ++k) {
                if (good.vertex_feature[v[k]] != VertexFeature3::Volume) continue;
                extra.subfaces.insert(extra.subfaces.end(), {v[k], v[(k + 1) % 4], v[(k + 2) % 4]});
                inner = v[k];
                added = true;
            }
        }
        ASSERT_TRUE(added);
        const std::string problem = read_back(plc, extra);
        EXPECT_NE(problem.find("lies on no facet"), std::string::npos) << problem;
        EXPECT_TRUE(names_vertex(problem, inner)) << inner << ": " << problem;
    }
    // A tetrahedron left out: a hole in the mesh, whose faces are no subfaces.
    {
        ConformingMesh3 holed = good;
        holed.mesh.tets.erase(holed.mesh.tets.begin(), holed.mesh.tets.begin() + 4);
        holed.mesh.neighbors.clear();
        link_neighbors_3d(holed.mesh);
        const std::string problem = read_back(plc, holed);
        EXPECT_NE(problem.find("is not a mesh face"), std::string::npos) << problem;
    }
}

}  // namespace
}  // namespace exactmesh::triangulation
