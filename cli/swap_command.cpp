// SPDX-License-Identifier: MIT
// `exactmesh swap`: Lawson edge swapping of a given triangulation (.node + .ele) under one
// criterion (triangulation/modification/edge_swap_2d), and `exactmesh min-max`: the min-max angle
// triangulation of a .node's points by edge cutting (triangulation/modification/edge_cutting_2d).
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
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
#include "io/triangle_format.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/modification/edge_cutting_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;

/// input: the .node file.
struct SwapArguments : CommandArguments {
    std::string ele_path;
    std::string criterion = "delaunay";
    std::string data_cost = "abn";
};

/// The largest angle of the triangles, in degrees (for the report only: not a decision).
double largest_angle_degrees(const tri::Triangulation2& mesh) {
    double largest = 0;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const double* o = mesh.point(mesh.triangles[3 * t + k]);
            const double* p = mesh.point(mesh.triangles[3 * t + (k + 1) % 3]);
            const double* q = mesh.point(mesh.triangles[3 * t + (k + 2) % 3]);
            const double ux = p[0] - o[0], uy = p[1] - o[1], vx = q[0] - o[0], vy = q[1] - o[1];
            largest =
                std::max(largest, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy));
        }
    }
    return largest * 180.0 / 3.14159265358979323846;
}

/// Writes `mesh` to the .ele output, numbered from `first_index`, and prints its triangle count;
/// with --stats then the criterion (when one was chosen), the counters, the largest angle and
/// the time of the work alone.
void write_result(const CommandArguments& arguments, const tri::Triangulation2& mesh,
                  std::uint32_t first_index,
                  const std::vector<std::pair<std::string, std::uint64_t>>& counters,
                  double seconds, const std::string& criterion = "") {
    io::OutputSet set;
    set.stage(arguments.output, io::format_ele(mesh.triangles, first_index));
    commit_outputs(set);
    std::cout << "triangles: " << mesh.triangle_count() << '\n';
    if (!arguments.stats) return;
    if (!criterion.empty()) std::cout << "criterion: " << criterion << '\n';
    print_counters(counters);
    std::cout << "max_angle_degrees: " << std::setprecision(10) << largest_angle_degrees(mesh)
              << '\n';
    print_construct_seconds(seconds);
}

void run_swap(const SwapArguments& arguments) {
    const fs::path output = arguments.output;
    require_ele_output(output);
    refuse_to_overwrite_inputs({arguments.input, arguments.ele_path}, {output});
    const tri::SwapCriterion criterion = tri::swap_criterion_from_name(arguments.criterion);
    const io::NodeFile nodes = io::read_node(arguments.input);
    const io::EleFile ele =
        io::read_ele(arguments.ele_path, nodes.first_index, nodes.vertex_count());
    std::vector<double> values;
    if (criterion == tri::SwapCriterion::DataDependent) {
        if (nodes.attribute_count == 0) {
            throw InputError(arguments.input +
                             ": the data-dependent criterion reads the first vertex attribute, "
                             "and this file declares none");
        }
        for (std::uint32_t v = 0; v < nodes.vertex_count(); ++v) {
            values.push_back(nodes.attributes[std::size_t{v} * nodes.attribute_count]);
        }
    }
    tri::Triangulation2 mesh;
    mesh.xy = nodes.xy;
    mesh.triangles = ele.triangles;
    try {
        tri::link_neighbors_2d(mesh, tri::CheckNumbering{nodes.first_index, ele.first_index});
    } catch (const InputError& error) {
        throw InputError(arguments.ele_path + ": " + error.what());
    }
    // The same exact validation as `exactmesh check` (orientation, each edge once, one convex
    // boundary winding once, every point a vertex): overlapping triangles or a fan that winds
    // twice would otherwise be swapped into a "result".
    if (const tri::CheckReport report = tri::check_topology_2d(
            nodes.xy, ele.triangles, tri::CheckNumbering{nodes.first_index, ele.first_index});
        !report.ok) {
        throw InputError(arguments.ele_path + ": not a triangulation of the points of " +
                         arguments.input + ": " + report.problem);
    }
    const auto start = std::chrono::steady_clock::now();
    tri::EdgeSwapCounters counters;
    switch (criterion) {
        case tri::SwapCriterion::Delaunay:
            counters = tri::swap_edges_2d(mesh, tri::Delaunay{});
            break;
        case tri::SwapCriterion::MaxMinAngle:
            counters = tri::swap_edges_2d(mesh, tri::MaxMinAngle{});
            break;
        case tri::SwapCriterion::MinMaxAngle:
            counters = tri::swap_edges_2d(mesh, tri::MinMaxAngle{});
            break;
        case tri::SwapCriterion::MinTotalLength:
            counters = tri::swap_edges_2d(mesh, tri::MinTotalLength{});
            break;
        case tri::SwapCriterion::DataDependent: {
            const tri::DataCost cost = arguments.data_cost == "jnd"
                                           ? tri::DataCost::JumpInNormalDerivatives
                                           : tri::DataCost::AngleBetweenNormals;
            counters = tri::swap_edges_2d(mesh, tri::DataDependent{values, cost});
            break;
        }
    }
    const double seconds = seconds_since(start);
    write_result(arguments, mesh, ele.first_index,
                 counters_by_name(tri::kEdgeSwapCounterNames, counters), seconds,
                 arguments.criterion);
}

void run_min_max(const CommandArguments& arguments) {
    const fs::path output = arguments.output;
    require_ele_output(output);
    refuse_to_overwrite_inputs({arguments.input}, {output});
    const io::NodeFile nodes = io::read_node(arguments.input);
    const auto start = std::chrono::steady_clock::now();
    tri::EdgeCuttingCounters counters;
    const tri::Triangulation2 mesh = tri::min_max_angle_triangulation_2d(nodes.xy, &counters);
    const double seconds = seconds_since(start);
    write_result(arguments, mesh, nodes.first_index,
                 counters_by_name(tri::kEdgeCuttingCounterNames, counters), seconds);
}

}  // namespace

void add_swap_command(CLI::App& app) {
    auto arguments = std::make_shared<SwapArguments>();
    CLI::App* command = app.add_subcommand(
        "swap", "Lawson edge swapping of a triangulation (IN.node + IN.ele) under one criterion");
    add_input_option(*command, arguments->input, "node", "Points: a Triangle .node file",
                     "IN.node");
    add_input_option(*command, arguments->ele_path, "ele",
                     "Triangles: a Triangle .ele file (counter-clockwise)", "IN.ele");
    add_output_option(*command, arguments->output, "Output triangles (.ele)", "OUT.ele");
    command
        ->add_option("--criterion", arguments->criterion,
                     "delaunay (SoS incircle), max-min-angle, min-max-angle, min-length (shorter "
                     "diagonal), data-dependent (Dyn-Levin-Rippa, on the first vertex attribute)")
        ->check(CLI::IsMember(
            {"delaunay", "max-min-angle", "min-max-angle", "min-length", "data-dependent"}))
        ->capture_default_str();
    command
        ->add_option("--data-cost", arguments->data_cost,
                     "data-dependent edge cost: abn (angle between normals) or jnd (jump in "
                     "normal derivatives)")
        ->check(CLI::IsMember({"abn", "jnd"}))
        ->capture_default_str();
    add_stats_flag(*command, arguments->stats, "counters", "the swapping alone, without I/O");
    command->callback([arguments] { run_swap(*arguments); });
}

void add_min_max_command(CLI::App& app) {
    auto arguments = std::make_shared<CommandArguments>();
    CLI::App* command = app.add_subcommand(
        "min-max", "Min-max angle triangulation of the points of IN.node (edge cutting, exact)");
    add_input_option(*command, arguments->input, "node", "Points: a Triangle .node file",
                     "IN.node");
    add_output_option(*command, arguments->output, "Output triangles (.ele)", "OUT.ele");
    add_stats_flag(*command, arguments->stats, "counters",
                   "Delaunay start + edge cutting, without I/O");
    command->callback([arguments] { run_min_max(*arguments); });
}

}  // namespace exactmesh::cli
