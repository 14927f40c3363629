// SPDX-License-Identifier: MIT
// `exactmesh check`: reads a .node and a .ele and runs the exact Delaunay check
// (triangulation/check_2d), reporting in the files' own numbering.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/check_2d.hpp"

namespace exactmesh::cli {

namespace {

namespace tri = exactmesh::triangulation;

struct CheckArguments {
    std::string node_path;
    std::string ele_path;
};

/// "triangle <t> (" opens check_2d's messages about triangle t; renumber it as the file does.
std::string in_file_numbering(const tri::CheckReport& report, std::uint32_t vertex_first_index,
                              std::uint32_t triangle_first_index) {
    std::string problem = report.problem;
    if (report.triangle != tri::kNone) {
        const std::string prefix = "triangle " + std::to_string(report.triangle) + " (";
        if (problem.compare(0, prefix.size(), prefix) == 0) {
            problem.replace(
                0, prefix.size(),
                "triangle " +
                    std::to_string(std::uint64_t{report.triangle} + triangle_first_index) + " (");
        }
    }
    // The one message that can name the padding point (see run_check): it stands for vertex 1.
    const std::string padding = "point 0 ";
    if (vertex_first_index == 1 && problem.compare(0, padding.size(), padding) == 0) {
        problem.replace(0, padding.size(), "point 1 ");
    }
    return problem;
}

int run_check(const CheckArguments& arguments) {
    const io::NodeFile nodes = io::read_node(arguments.node_path);
    const io::EleFile ele =
        io::read_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());

    // check_2d names vertices by their index into xy. For a 1-based file, put a copy of vertex 1
    // in front, so indices are the file's own numbers: a duplicate point that no triangle uses
    // is accepted by the check, as any unused duplicate is.
    std::vector<double> xy;
    std::vector<tri::VertIdx> triangles = ele.triangles;
    if (nodes.first_index == 1 && nodes.vertex_count() > 0) {
        xy.reserve(nodes.xy.size() + 2);
        xy.push_back(nodes.xy[0]);
        xy.push_back(nodes.xy[1]);
        xy.insert(xy.end(), nodes.xy.begin(), nodes.xy.end());
        for (tri::VertIdx& v : triangles) ++v;
    } else {
        xy = nodes.xy;
    }

    const tri::CheckReport report = tri::check_delaunay_2d(xy, triangles);
    if (report.ok) {
        std::cout << "ok: " << ele.triangle_count() << " triangles, exact Delaunay\n";
        return kExitSuccess;
    }
    std::cout << "not ok: " << arguments.ele_path << ": "
              << in_file_numbering(report, nodes.first_index, ele.first_index) << '\n';
    return kExitCheckFailed;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_status) {
    auto arguments = std::make_shared<CheckArguments>();
    CLI::App* command = app.add_subcommand(
        "check", "Exact check that IN.ele is a Delaunay triangulation of the points of IN.node");
    command->add_option("node", arguments->node_path, "Points: a Triangle .node file")
        ->required()
        ->type_name("IN.node");
    command->add_option("ele", arguments->ele_path, "Triangles: a Triangle .ele file")
        ->required()
        ->type_name("IN.ele");
    command->callback([arguments, &exit_status] { exit_status = run_check(*arguments); });
}

}  // namespace exactmesh::cli
