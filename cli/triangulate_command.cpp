// SPDX-License-Identifier: MIT
// `exactmesh triangulate`: .node in, Delaunay triangulation out (.ele + .neigh, .msh, .vtu or
// .svg by the output's extension), optionally with work counters and the construction time.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "cli/progress_output.hpp"
#include "io/gmsh_format.hpp"
#include "io/svg_picture.hpp"
#include "io/triangle_format.hpp"
#include "io/vtk_format.hpp"
#include "predicates/stats.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // kMaxThreads

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;

struct TriangulateArguments : CommandArguments, OrderArguments {
    PictureArguments picture;
    std::string algorithm = "bowyer-watson";
    std::string location = "auto";
    unsigned threads = 1;
};

tri::PointLocation point_location(const std::string& name) {
    if (name == "auto") return tri::PointLocation::Auto;
    if (name == "walk") return tri::PointLocation::Walk;
    if (name == "grid") return tri::PointLocation::Grid;
    throw InputError("unknown point location '" + name + "' (known: auto, walk, grid)");
}

void run_triangulate(const TriangulateArguments& arguments) {
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);  // before any work: fail fast
    const std::vector<fs::path> files = output_files(output, format, {".neigh"});
    const io::SvgOptions svg = picture_options(
        arguments.picture, format,
        fs::path(arguments.input).filename().string() + " (" + arguments.algorithm + ")");
    refuse_to_overwrite_inputs({arguments.input}, files);
    const tri::Delaunay2Function construct = tri::delaunay_2d_algorithm(arguments.algorithm);
    const io::NodeFile nodes = io::read_node(arguments.input);

    const tri::Delaunay2Options options{tri::insertion_order_from_name(arguments.order),
                                        arguments.seed, point_location(arguments.location),
                                        progress_printer("triangulate", arguments.quiet),
                                        arguments.threads};
    const auto [result, stats, seconds] =
        timed_construction([&] { return construct(nodes.xy, options); });

    io::OutputSet set;
    switch (format) {
        case OutputFormat::Ele:
            set.stage(files[0], io::format_ele(result.triangles, nodes.first_index));
            set.stage(files[1], io::format_neigh(result.neighbors, nodes.first_index));
            break;
        case OutputFormat::Msh:
            set.stage(output, io::format_msh(nodes.xy, result.triangles));
            break;
        case OutputFormat::Vtu:
            set.stage(output, io::format_vtu(nodes.xy, result.triangles, nodes.first_index));
            break;
        case OutputFormat::Svg:
            set.stage(output, io::format_svg(nodes.xy, result.triangles, svg));
            break;
    }
    commit_outputs(set);
    std::cout << "triangles: " << result.triangles.size() / 3 << '\n';
    if (arguments.stats) {
        print_construction_stats(counters_by_name(tri::kDelaunay2CounterNames, result.counters),
                                 stats, seconds);
    }
}

}  // namespace

void add_triangulate_command(CLI::App& app) {
    auto arguments = std::make_shared<TriangulateArguments>();
    CLI::App* command = app.add_subcommand(
        "triangulate", "Delaunay triangulation of the points of a Triangle .node file");
    add_input_option(*command, arguments->input, "input", "Points: a Triangle .node file",
                     "IN.node");
    add_output_option(*command, arguments->output,
                      "Output; the extension picks the format: .ele (and .neigh beside it), "
                      ".msh (Gmsh 4.1), .vtu (VTK), .svg (picture)");
    add_algorithm_option(*command, arguments->algorithm, tri::delaunay_2d_algorithms());
    add_order_options(*command, *arguments, "Insertion order");
    command
        ->add_option("--location", arguments->location,
                     "Point location of the incremental algorithms: walk from the last "
                     "insertion, grid (jump to a recent insertion nearby, then walk), or auto "
                     "(grid for the random order, else walk); tanemura-merriam locates nothing")
        ->check(CLI::IsMember({"auto", "walk", "grid"}))
        ->capture_default_str();
    command
        ->add_option("--threads", arguments->threads,
                     "Threads of bowyer-watson with the brio order (oneTBB; the same triangles "
                     "for every count): 1 runs the sequential code, 0 every hardware thread; "
                     "the other algorithms and orders run sequentially. --stats prints the "
                     "count used and the parallel rounds' counters")
        ->check(whole_number_at_most(tri::kMaxThreads))
        ->capture_default_str();
    add_picture_options(*command, arguments->picture);
    add_stats_flag(*command, arguments->stats, "work counters, predicate stages",
                   "the construction alone, without file I/O");
    add_quiet_flag(*command, arguments->quiet);
    command->callback([arguments] { run_triangulate(*arguments); });
}

}  // namespace exactmesh::cli
