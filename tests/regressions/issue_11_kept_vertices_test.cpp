// SPDX-License-Identifier: MIT
// Issue 11, finding 2: every generator keeps every input vertex that lies in the domain. The
// advancing front and the advancing-front Delaunay generator left out free vertices (no segment
// at them): the one in the middle of a star polygon, free vertices inside a box with holes,
// the free vertices of a .node beside its .poly. Each case runs all five generators of the
// registry and checks the mesh with check_quality_mesh (which now verifies, through
// check_input_vertices_kept_2d, that every input vertex in the meshed region is a mesh vertex
// at its input coordinates) and, explicitly, that each free vertex inside the domain is a corner
// of some triangle and each one in a hole of none. Each case runs in well under a second.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "io/triangle_format.hpp"
#include "tests/support/generated_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"

namespace {

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using em::testing::Input;

/// Runs every generator on `in` with `size`; checks the mesh and that the vertices `inside` are
/// corners of triangles (at their input coordinates) and the vertices `outside` of none.
void expect_kept(const Input& in, const gen::SizeFunction& size,
                 const std::vector<std::uint32_t>& inside,
                 const std::vector<std::uint32_t>& outside, const std::string& what) {
    for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
        SCOPED_TRACE(what + ", " + std::string(generator.name));
        gen::MeshOptions2 options;
        options.size = size;
        const gen::MeshRun2 run = generator.run(in.pslg(), options);
        const tri::Cdt2Result& r = run.mesh;
        const auto check = em::testing::check_mesh_of_input(r, in, generator.delaunay);
        EXPECT_TRUE(check.ok) << check.problem;
        std::set<std::uint32_t> corners(r.mesh.triangles.begin(), r.mesh.triangles.end());
        for (const std::uint32_t v : inside) {
            EXPECT_TRUE(corners.count(v)) << "free vertex " << v << " left out";
            ASSERT_LT(v, r.mesh.vertex_count());
            EXPECT_EQ(r.mesh.point(v)[0], in.xy[2 * v]);
            EXPECT_EQ(r.mesh.point(v)[1], in.xy[2 * v + 1]);
        }
        for (const std::uint32_t v : outside) {
            EXPECT_FALSE(corners.count(v)) << "vertex " << v << " in a hole is a mesh vertex";
        }
    }
}

/// A star of `points` spikes (radii 1 and `inner`) about the origin.
std::vector<double> star(int points, double inner) {
    std::vector<double> xy;
    for (int k = 0; k < 2 * points; ++k) {
        const double angle = std::numbers::pi * k / points;
        const double r = k % 2 == 0 ? 1.0 : inner;
        xy.insert(xy.end(), {r * std::cos(angle), r * std::sin(angle)});
    }
    return xy;
}

TEST(Issue11KeptVertices, issue_11_kept_vertices_star_centre) {
    Input in = em::testing::polygon(star(5, 0.4));
    const auto centre = static_cast<std::uint32_t>(in.xy.size() / 2);
    in.xy.insert(in.xy.end(), {0.0, 0.0});
    // A second free vertex off the centre, at a point no regular placement would choose.
    in.xy.insert(in.xy.end(), {0.123456789, -0.0456});
    expect_kept(in, gen::SizeFunction::uniform(0.15), {centre, centre + 1}, {}, "star");
    expect_kept(in, gen::SizeFunction::uniform(0.05), {centre, centre + 1}, {}, "star, fine");
}

TEST(Issue11KeptVertices, issue_11_kept_vertices_box_with_holes) {
    Input in;
    em::testing::add_loop(in, {0, 0, 4, 0, 4, 2, 0, 2});
    em::testing::add_loop(in, {0.5, 0.5, 1.5, 0.5, 1.5, 1.5, 0.5, 1.5});
    em::testing::add_loop(in, {2.5, 0.5, 3.5, 0.5, 3.5, 1.5, 2.5, 1.5});
    in.holes = {1, 1, 3, 1};
    const auto first = static_cast<std::uint32_t>(in.xy.size() / 2);
    // Between the holes, near a hole's side (1e-3 off), in a corner, above a hole; then one in
    // each hole (not meshed).
    in.xy.insert(in.xy.end(), {2.0, 1.0, 1.501, 0.9, 0.1, 0.1, 1.0, 1.75, 3.9, 1.9});
    in.xy.insert(in.xy.end(), {1.0, 1.0, 3.2, 0.7});
    const std::vector<std::uint32_t> inside{first, first + 1, first + 2, first + 3, first + 4};
    const std::vector<std::uint32_t> outside{first + 5, first + 6};
    expect_kept(in, gen::SizeFunction::uniform(0.2), inside, outside, "box with holes");
    expect_kept(in, gen::SizeFunction::uniform(0.07), inside, outside, "box with holes, fine");
}

TEST(Issue11KeptVertices, issue_11_kept_vertices_node_beside_poly) {
    // A .poly announcing 0 vertices reads them from the .node beside it; vertices 4-6 of the
    // .node are on no segment.
    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("exactmesh_issue_11_kept_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path node = dir / "free.node";
    {
        std::ofstream out(node);
        out << "7 2 0 0\n1 0 0\n2 3 0\n3 3 2\n4 0 2\n5 1 1\n6 2 0.5\n7 2.9 1.9\n";
    }
    const std::string poly_text = "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
    const em::io::PolyFile poly = em::io::parse_poly(poly_text, "free.poly", node);
    std::filesystem::remove_all(dir);
    ASSERT_EQ(poly.vertices.xy.size(), 14u);
    Input in{poly.vertices.xy, poly.segments, poly.holes, {}};
    expect_kept(in, gen::SizeFunction::uniform(0.3), {4, 5, 6}, {}, ".node beside .poly");
}

TEST(Issue11KeptVertices, issue_11_kept_vertices_random) {
    // Random star-shaped polygons, some with a square hole about the centre, each with random
    // free vertices inside (some in the hole), for every generator. Seeds fixed.
    std::mt19937_64 rng(20261201);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int round = 0; round < 6; ++round) {
        // At least 8 vertices 0.8 to 1.4 from the centre, at most 1.5 (2 pi / 8) apart in
        // angle: every edge stays 0.8 cos(0.59) > 0.66 from the centre.
        const int n = 8 + static_cast<int>(unit(rng) * 10);
        std::vector<double> outline;
        for (int k = 0; k < n; ++k) {
            const double angle = 2 * std::numbers::pi * (k + 0.5 * unit(rng)) / n;
            const double r = 0.8 + 0.6 * unit(rng);
            outline.insert(outline.end(), {r * std::cos(angle), r * std::sin(angle)});
        }
        Input in = em::testing::polygon(outline);
        const bool hole = round % 2 == 1;
        if (hole) {
            em::testing::add_loop(in, {-0.2, -0.2, 0.2, -0.2, 0.2, 0.2, -0.2, 0.2});
            in.holes = {0, 0};
        }
        std::vector<std::uint32_t> inside, outside;
        for (int k = 0; k < 8; ++k) {
            // Within radius 0.6: inside every outline.
            const double angle = 2 * std::numbers::pi * unit(rng);
            const double r = 0.6 * std::sqrt(unit(rng));
            const double x = r * std::cos(angle), y = r * std::sin(angle);
            const bool in_hole = hole && std::fabs(x) < 0.2 && std::fabs(y) < 0.2;
            if (hole && !in_hole &&
                (std::fabs(std::fabs(x) - 0.2) < 1e-9 || std::fabs(std::fabs(y) - 0.2) < 1e-9))
                continue;  // never on the hole's boundary
            (in_hole ? outside : inside).push_back(static_cast<std::uint32_t>(in.xy.size() / 2));
            in.xy.insert(in.xy.end(), {x, y});
        }
        expect_kept(in, gen::SizeFunction::uniform(0.08 + 0.1 * unit(rng)), inside, outside,
                    "random round " + std::to_string(round));
    }
}

TEST(Issue11KeptVertices, issue_11_kept_vertices_check_catches_a_dropped_vertex) {
    // The shared check itself: a mesh of the unit square by two triangles, with a free input
    // vertex at (0.25, 0.5) that no triangle uses, fails; the same vertex outside the square,
    // or as a duplicate of a corner, passes; a moved input vertex fails.
    tri::Triangulation2 mesh;
    mesh.xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.25, 0.5};
    mesh.triangles = {0, 1, 2, 0, 2, 3};
    const auto dropped = tri::check_input_vertices_kept_2d(mesh, mesh.xy);
    EXPECT_FALSE(dropped.ok);
    EXPECT_NE(dropped.problem.find("input vertex 4"), std::string::npos) << dropped.problem;
    mesh.xy[8] = 2.0;  // outside the meshed square
    EXPECT_TRUE(tri::check_input_vertices_kept_2d(mesh, mesh.xy).ok);
    mesh.xy[8] = 1.0, mesh.xy[9] = 1.0;  // a duplicate of corner 2
    EXPECT_TRUE(tri::check_input_vertices_kept_2d(mesh, mesh.xy).ok);
    mesh.xy[8] = 1.0, mesh.xy[9] = 0.5;  // on the square's side: in a closed triangle
    EXPECT_FALSE(tri::check_input_vertices_kept_2d(mesh, mesh.xy).ok);
    std::vector<double> input = mesh.xy;
    input[8] = 2.0;
    const auto moved = tri::check_input_vertices_kept_2d(mesh, input);
    EXPECT_FALSE(moved.ok);
    EXPECT_NE(moved.problem.find("moved"), std::string::npos) << moved.problem;
}

}  // namespace
