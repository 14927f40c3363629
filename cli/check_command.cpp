// SPDX-License-Identifier: MIT
// `exactmesh check`: reads a .node and a .ele and runs the exact Delaunay check
// (triangulation/check_2d), reporting in the files' own numbering.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <string>

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

int run_check(const CheckArguments& arguments) {
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
