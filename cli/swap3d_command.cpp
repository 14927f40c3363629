// SPDX-License-Identifier: MIT
// `exactmesh swap3d`: edge-face swapping of a given tetrahedralization (TetGen .node + .ele)
// under one criterion (triangulation/modification/edge_face_swap_3d), with counters and a quality
// report (triangulation/checks/quality_3d).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "io/tetgen_format.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/edge_removal_3d.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;

/// input: the .node file.
struct Swap3dArguments : CommandArguments {
    std::string ele_path;
    std::string criterion = "delaunay";
    bool quality = false;
    bool edge_removal = false;
};

void run_swap3d(const Swap3dArguments& arguments) {
    const fs::path output = arguments.output;
    require_ele_output(output);
    refuse_to_overwrite_inputs({arguments.input, arguments.ele_path}, {output});
    const tri::SwapCriterion3 criterion = tri::swap_criterion_3d_from_name(arguments.criterion);
    if (arguments.edge_removal && criterion == tri::SwapCriterion3::Delaunay)
        throw InputError(
            "--edge-removal needs a quality criterion (max-min-dihedral, "
            "min-max-dihedral or volume-edge), not delaunay");
    const io::TetgenNodeFile nodes = io::read_tetgen_node(arguments.input);
    const io::TetgenEleFile ele =
        io::read_tetgen_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());
    tri::Tetrahedralization3 mesh;
    mesh.xyz = nodes.xyz;
    mesh.tets = ele.tets;
    try {
        tri::link_neighbors_3d(
            mesh, tri::Check3Numbering{nodes.first_index, ele.first_index, io::kTetgenFileCorners});
    } catch (const InputError& error) {
        throw InputError(arguments.ele_path + ": " + error.what());
    }
    // The same exact validation as `exactmesh check` (positive orientation, faces shared by at
    // most two tetrahedra, a closed convex boundary): overlapping tetrahedra would otherwise be
    // swapped into a "result".
    if (const tri::Check3Report report = tri::check_tetrahedralization_3d(
            nodes.xyz, ele.tets, {},
            tri::Check3Numbering{nodes.first_index, ele.first_index, io::kTetgenFileCorners});
        !report.ok) {
        throw InputError(arguments.ele_path + ": not a tetrahedralization of the points of " +
                         arguments.input + ": " + report.problem);
    }
    const auto start = std::chrono::steady_clock::now();
    tri::TetMesh3 work = tri::make_tet_mesh_3d(mesh);
    tri::EdgeFaceSwapCounters counters = tri::swap_faces_3d(work, criterion);
    tri::EdgeRemovalCounters removal;
    // Edge removal on every edge, then the face swaps from the tetrahedra it made, then edge
    // removal on the edges of everything made since, until no edge goes (an edge whose ring
    // changed is an edge of a new tetrahedron). Each step strictly improves the sorted
    // qualities (edge_removal_3d.hpp), so the loop ends.
    if (arguments.edge_removal) {
        std::vector<tri::TetIdx> made, next;
        tri::SwapConstraints3 follow;
        follow.on_flip = [&made](const tri::FlipPlan3&, const std::vector<tri::TetIdx>& created) {
            made.insert(made.end(), created.begin(), created.end());
        };
        for (tri::TetIdx t = 0; t < work.tet_slots(); ++t)
            if (!work.is_dead(t)) next.push_back(t);
        while (true) {
            made.clear();
            const tri::EdgeRemovalCounters round =
                tri::remove_edges_3d(work, criterion, next, follow);
            add_counters(tri::kEdgeRemovalCounterNames, removal, round);
            if (round.removals == 0) break;
            std::vector<tri::FaceIdx> seeds;
            for (const tri::TetIdx t : made)
                for (unsigned k = 0; k < 4; ++k) seeds.push_back(4 * t + k);
            tri::SwapConstraints3 swaps = follow;
            swaps.seeds = seeds;
            add_counters(tri::kEdgeFaceSwapCounterNames, counters,
                         tri::swap_faces_3d(work, criterion, swaps));
            next = made;  // the removals' tetrahedra, then the swaps' (slots may repeat)
            std::sort(next.begin(), next.end());
            next.erase(std::unique(next.begin(), next.end()), next.end());
        }
    }
    mesh = tri::to_tetrahedralization_3d(work);
    const double seconds = seconds_since(start);
    io::OutputSet set;
    set.stage(output, io::format_tetgen_ele(mesh.tets, ele.first_index));
    commit_outputs(set);
    std::cout << "tetrahedra: " << mesh.tet_count() << '\n';
    if (arguments.stats) {
        std::cout << "criterion: " << tri::swap_criterion_3d_name(criterion) << '\n';
        auto named = counters_by_name(tri::kEdgeFaceSwapCounterNames, counters);
        // stalled_faces is counted for the Delaunay criterion only.
        if (criterion != tri::SwapCriterion3::Delaunay)
            std::erase_if(named, [](const auto& c) { return c.first == "stalled_faces"; });
        print_counters(named);
        if (arguments.edge_removal) {
            auto removal_named = counters_by_name(tri::kEdgeRemovalCounterNames, removal);
            for (auto& [name, value] : removal_named) name = "edge_removal_" + name;
            print_counters(removal_named);
        }
        print_construct_seconds(seconds);
    }
    if (arguments.quality) print_quality_3d(mesh);
}

}  // namespace

void add_swap3d_command(CLI::App& app) {
    auto arguments = std::make_shared<Swap3dArguments>();
    CLI::App* command = app.add_subcommand("swap3d",
                                           "Edge-face swapping of a tetrahedralization (IN.node + "
                                           "IN.ele, TetGen formats) under one criterion");
    add_input_option(*command, arguments->input, "node", "Points: a TetGen .node file", "IN.node");
    add_input_option(*command, arguments->ele_path, "ele",
                     "Tetrahedra: a TetGen .ele file (TetGen's orientation)", "IN.ele");
    add_output_option(*command, arguments->output, "Output tetrahedra (.ele)", "OUT.ele");
    command
        ->add_option(
            "--criterion", arguments->criterion,
            "delaunay (SoS insphere), max-min-dihedral, min-max-dihedral, volume-edge (max-min of "
            "6 sqrt(2) V / l_rms^3)")
        ->check(CLI::IsMember({"delaunay", "max-min-dihedral", "min-max-dihedral", "volume-edge"}))
        ->capture_default_str();
    command->add_flag("--edge-removal", arguments->edge_removal,
                      "With a quality criterion: also remove edges (triangulation/modification/"
                      "edge_removal_3d: the 3 to 7 tetrahedra around an edge replaced by the best "
                      "triangulation of its ring when every new one beats the worst old one), "
                      "alternating with the face swaps until no edge goes");
    command->add_flag(
        "--quality", arguments->quality,
        "Print the output's quality: dihedral extremes and 10-degree histogram, volume-edge, "
        "radius-edge, slivers (min dihedral < 5 degrees with radius-edge <= 2)");
    add_stats_flag(*command, arguments->stats, "counters", "the swapping alone, without I/O");
    command->callback([arguments] { run_swap3d(*arguments); });
}

}  // namespace exactmesh::cli
