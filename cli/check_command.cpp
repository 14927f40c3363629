// SPDX-License-Identifier: MIT
// `exactmesh check`: reads a .node and a .ele and runs the exact Delaunay check
// (triangulation/checks/check_2d, or check_3d for a TetGen .node of dimension 3 and its .ele), or a
// .poly and a .ele and runs the exact constrained Delaunay check
// (triangulation/checks/check_constrained_2d), or with --conforming the exact validity of a mesh of
// the domain that need not be Delaunay (triangulation/checks/check_conforming_2d: the quadtree and
// advancing-front generators' meshes), reporting in the files' own numbering.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "io/tetgen_format.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/mesh/constrained_flags_2d.hpp"

namespace exactmesh::cli {

namespace {

namespace tri = exactmesh::triangulation;

struct CheckArguments {
    std::string node_path;
    std::string ele_path;
    bool conforming = false;   ///< a .poly mesh checked for validity only, not Delaunay
    bool convex_hull = false;  ///< a .poly mesh must also cover the convex hull exactly once
};

/// IN.poly against OUT.ele. The vertices are OUT.node's when it exists beside OUT.ele (it holds
/// the added vertices after the input's), the constrained edges OUT.poly's when it exists (the
/// pieces `exactmesh cdt` writes), else the input segments themselves.
int run_constrained_check(const CheckArguments& arguments) {
    namespace fs = std::filesystem;
    const io::PolyFile input = io::read_poly(arguments.node_path);
    fs::path node_path = arguments.ele_path, pieces_path = arguments.ele_path;
    node_path.replace_extension(".node");
    pieces_path.replace_extension(".poly");
    tri::Triangulation2 mesh;
    mesh.xy = input.vertices.xy;
    if (fs::exists(node_path)) {
        const io::NodeFile all = io::read_node(node_path);
        for (std::size_t i = 0; i < input.vertices.xy.size(); ++i) {
            if (i >= all.xy.size() || all.xy[i] != input.vertices.xy[i]) {
                throw InputError(node_path.string() + ": vertex " +
                                 std::to_string(i / 2 + all.first_index) + " differs from " +
                                 arguments.node_path + " (expected its vertices first)");
            }
        }
        mesh.xy = all.xy;
    }
    const std::uint32_t base = input.vertices.first_index;
    const io::EleFile ele = io::read_ele(arguments.ele_path, base, mesh.vertex_count());
    mesh.triangles = ele.triangles;
    std::vector<tri::VertIdx> constrained_edges = input.segments, pieces;
    if (fs::exists(pieces_path) && !fs::equivalent(pieces_path, arguments.node_path)) {
        pieces = io::read_poly(pieces_path).segments;
        constrained_edges = pieces;
    }
    tri::flag_constrained_edges_2d(mesh, constrained_edges);
    const tri::CheckNumbering numbering{base, ele.first_index};
    // The constrained checks are local: only the hull's topology sees a triangle left out.
    tri::CheckReport report;
    if (arguments.convex_hull) report = tri::check_topology_2d(mesh.xy, mesh.triangles, numbering);
    if (report.ok)
        report = arguments.conforming
                     ? tri::check_conforming_mesh_2d(mesh, input.vertices.vertex_count(),
                                                     input.segments, pieces, numbering)
                     : tri::check_constrained_delaunay_2d(mesh, input.vertices.vertex_count(),
                                                          input.segments, pieces, numbering);
    // Every input vertex in the meshed region is a mesh vertex (check_conforming_mesh_2d
    // includes it).
    if (report.ok && !arguments.conforming)
        report = tri::check_input_vertices_kept_2d(mesh, input.vertices.xy, numbering);
    if (report.ok) {
        std::cout << "ok: " << ele.triangle_count() << " triangles, "
                  << (arguments.conforming
                          ? "exact valid mesh (no fold, boundary on the segments), "
                          : "exact constrained Delaunay, ")
                  << input.segment_count()
                  << " segments covered (parts in removed regions need not be edges)\n";
        return kExitSuccess;
    }
    std::cout << "not ok: " << arguments.ele_path << ": " << report.problem << '\n';
    return kExitCheckFailed;
}

/// IN.node of dimension 3 against a TetGen .ele.
int run_check_3d(const CheckArguments& arguments) {
    const io::TetgenNodeFile nodes = io::read_tetgen_node(arguments.node_path);
    const io::TetgenEleFile ele =
        io::read_tetgen_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());
    const tri::Check3Report report = tri::check_delaunay_3d(
        nodes.xyz, ele.tets, {},
        tri::Check3Numbering{nodes.first_index, ele.first_index, io::kTetgenFileCorners});
    if (report.ok) {
        std::cout << "ok: " << ele.tet_count() << " tetrahedra, exact Delaunay\n";
        return kExitSuccess;
    }
    std::cout << "not ok: " << arguments.ele_path << ": " << report.problem << '\n';
    return kExitCheckFailed;
}

int run_check(const CheckArguments& arguments) {
    if (io::has_extension(arguments.node_path, ".poly")) return run_constrained_check(arguments);
    if (arguments.conforming)
        throw InputError("--conforming needs an IN.poly (the domain's segments)");
    if (arguments.convex_hull)
        throw InputError("--convex-hull needs an IN.poly (a constrained triangulation's segments)");
    if (io::read_node_dimension(arguments.node_path) == 3) return run_check_3d(arguments);
    const io::NodeFile nodes = io::read_node(arguments.node_path);
    const io::EleFile ele =
        io::read_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());
    const tri::CheckReport report = tri::check_delaunay_2d(
        nodes.xy, ele.triangles, tri::CheckNumbering{nodes.first_index, ele.first_index});
    if (report.ok) {
        std::cout << "ok: " << ele.triangle_count() << " triangles, exact Delaunay\n";
        return kExitSuccess;
    }
    std::cout << "not ok: " << arguments.ele_path << ": " << report.problem << '\n';
    return kExitCheckFailed;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_status) {
    auto arguments = std::make_shared<CheckArguments>();
    CLI::App* command = app.add_subcommand(
        "check",
        "Exact check that IN.ele is a Delaunay triangulation (a Delaunay tetrahedralization when "
        "IN.node has "
        "dimension 3) of the points of IN.node, or a "
        "constrained Delaunay triangulation of IN.poly (vertices added by `exactmesh cdt` are read "
        "from the .node beside IN.ele, its constrained edges from the .poly beside it)");
    command->add_option("node", arguments->node_path, "Input: a Triangle .node or .poly file")
        ->required()
        ->type_name("IN.node|IN.poly");
    command
        ->add_option("ele", arguments->ele_path,
                     "Triangles: a Triangle .ele file (tetrahedra: a TetGen .ele file)")
        ->required()
        ->type_name("IN.ele");
    command->add_flag(
        "--conforming", arguments->conforming,
        "With IN.poly: check a mesh that need not be Delaunay (quadtree, advancing front): "
        "strictly counter-clockwise triangles, no fold at any vertex, every boundary edge a piece "
        "of a segment, every segment a chain of edges");
    command->add_flag("--convex-hull", arguments->convex_hull,
                      "With IN.poly: the mesh must also cover the convex hull of its vertices "
                      "exactly once, every vertex used (the output of `cdt --convex-hull`)");
    command->callback([arguments, &exit_status] { exit_status = run_check(*arguments); });
}

}  // namespace exactmesh::cli
