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
#include <vector>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "io/format_error.hpp"
#include "io/plc_format.hpp"
#include "io/tetgen_format.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/check_hull_cover_2d.hpp"
#include "triangulation/mesh/constrained_flags_2d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/conforming_mesh_from_faces_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

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
    // The constrained checks are local: only the hull's topology sees a triangle left out. With
    // hole points the mesh covers the hull less the holes (more than one boundary loop): that
    // region is compared with the reference's after the local checks (check_hull_cover_2d).
    const bool hull_less_holes = arguments.convex_hull && !input.holes.empty();
    tri::CheckReport report;
    if (arguments.convex_hull && !hull_less_holes)
        report = tri::check_topology_2d(mesh.xy, mesh.triangles, numbering);
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
    if (report.ok && hull_less_holes)
        report = tri::check_hull_cover_2d(mesh, input.holes, numbering);
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

/// Whether `path` is a 3D PLC: .smesh, .off, .stl, or a .poly of dimension 3.
bool is_plc_3d(const std::string& path) {
    if (io::has_extension(path, ".smesh") || io::has_extension(path, ".off") ||
        io::has_extension(path, ".stl"))
        return true;
    return io::has_extension(path, ".poly") && io::read_node_dimension(path) == 3;
}

/// IN.poly (3D), .smesh, .off or .stl against a TetGen .ele with its .node (and .face, the
/// faces on facets, when it exists) beside it: the exact check that the tetrahedra are a
/// conforming mesh of the PLC (triangulation/recovery_3d/check_boundary_conformity_3d), after
/// the PLC is prepared as `exactmesh tetmesh` prepares it and the mesh's segment and facet
/// vertices are read back (conforming_mesh_from_faces_3d).
int run_plc_check_3d(const CheckArguments& arguments) {
    namespace fs = std::filesystem;
    tri::Plc3 plc = io::plc_from_file(io::read_plc(arguments.node_path));
    const std::vector<double> input_xyz = plc.xyz;  // before vertices at one point are merged
    const auto inputs = static_cast<std::uint32_t>(input_xyz.size() / 3);
    try {
        tri::prepare_plc_for_meshing_3d(plc);
    } catch (const InputError& error) {
        throw InputError(arguments.node_path + ": " + error.what());
    }
    fs::path node_path = arguments.ele_path, face_path = arguments.ele_path;
    node_path.replace_extension(".node");
    face_path.replace_extension(".face");
    if (!fs::exists(node_path))
        throw InputError(node_path.string() +
                         ": no such file (a mesh's vertices are read from the .node beside "
                         "its .ele)");
    const io::TetgenNodeFile nodes = io::read_tetgen_node(node_path);
    const io::TetgenEleFile ele =
        io::read_tetgen_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());
    const auto fail = [&](const std::string& problem) {
        std::cout << "not ok: " << arguments.ele_path << ": " << problem << '\n';
        return kExitCheckFailed;
    };
    if (nodes.vertex_count() < inputs)
        return fail(node_path.string() + " has " + std::to_string(nodes.vertex_count()) +
                    " vertices, fewer than the " + std::to_string(inputs) + " of the input");
    for (std::size_t i = 0; i < input_xyz.size(); ++i) {
        if (nodes.xyz[i] != input_xyz[i])
            return fail("input vertex " + std::to_string(i / 3 + plc.first_index) +
                        " moved or is missing (the mesh's first vertices are the input's)");
    }
    // Checked in the merged PLC's numbering (merge_duplicate_vertices_3d): a merged vertex as
    // the one that stands for it, the Steiner points after the PLC's vertices.
    tri::Tetrahedralization3 mesh;
    mesh.xyz = plc.xyz;
    mesh.xyz.insert(mesh.xyz.end(), nodes.xyz.begin() + 3 * std::ptrdiff_t{inputs},
                    nodes.xyz.end());
    mesh.tets = ele.tets;
    for (std::uint32_t& v : mesh.tets) v = plc.from_input_vertex(v);
    try {
        tri::link_neighbors_3d(
            mesh, tri::Check3Numbering{nodes.first_index, ele.first_index, io::kTetgenFileCorners});
    } catch (const InputError& error) {
        return fail(error.what());  // an inverted, flat or overlapping tetrahedron
    }
    std::vector<tri::VertIdx> faces;
    if (fs::exists(face_path)) {
        faces = io::read_tetgen_face(face_path, nodes.first_index, nodes.vertex_count()).faces;
        for (std::uint32_t& v : faces) v = plc.from_input_vertex(v);
    } else {
        // Without a .face, the mesh's boundary faces (a PLC without internal facets).
        for (std::size_t t = 0; 4 * t < mesh.tets.size(); ++t)
            for (unsigned k = 0; k < 4; ++k)
                if (mesh.neighbors[4 * t + k] == tri::kNone)
                    for (const unsigned c : tri::kFaceVertex[k])
                        faces.push_back(mesh.tets[4 * t + c]);
    }
    const std::uint32_t tets = ele.tet_count();
    tri::ConformingMeshReading3 reading =
        tri::conforming_mesh_from_faces_3d(plc, std::move(mesh), faces);
    if (!reading.problem.empty()) return fail(reading.problem + " (vertices numbered from 0)");
    const tri::BoundaryConformityReport3 report =
        tri::check_boundary_conformity_3d(plc, reading.mesh);
    if (!report.ok) return fail(report.problem + " (vertices numbered from 0)");
    std::cout << "ok: " << tets << " tetrahedra, exact conforming mesh of the PLC ("
              << plc.facets.size()
              << " facets each a union of mesh faces, every segment a chain of edges, no "
                 "inverted or overlapping tetrahedron)\n";
    return kExitSuccess;
}

int run_check(const CheckArguments& arguments) {
    if (is_plc_3d(arguments.node_path)) {
        if (arguments.conforming || arguments.convex_hull)
            throw InputError(
                "--conforming and --convex-hull are for 2D meshes (a 3D PLC's mesh "
                "is checked for conformity always)");
        return run_plc_check_3d(arguments);
    }
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
        "IN.node has dimension 3) of the points of IN.node, or a constrained Delaunay "
        "triangulation of IN.poly (vertices added by `exactmesh cdt` are read from the .node "
        "beside IN.ele, its constrained edges from the .poly beside it), or, with a 3D PLC "
        "(.poly of dimension 3, .smesh, .off, .stl), a conforming tetrahedral mesh of it (the "
        ".node and .face beside IN.ele: valid tetrahedra, every facet a union of faces, every "
        "segment a chain of edges, the input's vertices first and unmoved)");
    command
        ->add_option("node", arguments->node_path,
                     "Input: a Triangle .node or .poly file, or a 3D PLC (.poly, .smesh, .off, "
                     ".stl)")
        ->required()
        ->type_name("IN.node|IN.poly|IN.smesh|IN.off|IN.stl");
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
