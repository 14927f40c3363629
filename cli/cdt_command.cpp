// SPDX-License-Identifier: MIT
// `exactmesh cdt`: a .poly (or .node) in, its constrained (or conforming) Delaunay triangulation
// out: .ele with .neigh, .node (input vertices, then added ones) and .poly (the constrained
// edges, each marked with its input segment's number) beside it; or .msh, .vtu, .svg.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <string>

#include "cli/commands.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "cli/progress_output.hpp"
#include "io/triangle_format.hpp"
#include "predicates/stats.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;

struct CdtArguments : CommandArguments, OrderArguments {
    std::string recovery = "swap";
    bool convex_hull = false;
    PictureArguments picture;
};

/// The input as a PSLG: a .poly, or a .node (points only).
io::PolyFile read_input(const fs::path& input) {
    if (io::has_extension(input, ".node")) {
        io::PolyFile poly;
        poly.vertices = io::read_node(input);
        return poly;
    }
    return io::read_poly(input);
}

void run_cdt(const CdtArguments& arguments) {
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);
    const std::vector<fs::path> files = output_files(output, format, {".neigh", ".node", ".poly"});
    refuse_to_overwrite_inputs({arguments.input, io::poly_node_path(arguments.input)}, files);
    const io::SvgOptions svg = picture_options(
        arguments.picture, format,
        fs::path(arguments.input).filename().string() + " (cdt, " + arguments.recovery + ")");
    const io::PolyFile poly = read_input(arguments.input);
    const std::uint32_t base = poly.vertices.first_index;
    warn_unused_region_areas(poly, arguments.input,
                             "cdt adds no vertices; `exactmesh mesh` applies them with "
                             "--generator delaunay-refinement or frontal");

    tri::Cdt2Options options;
    options.recovery = tri::segment_recovery_from_name(arguments.recovery);
    options.remove_exterior = !arguments.convex_hull;
    options.order = tri::insertion_order_from_name(arguments.order);
    options.seed = arguments.seed;
    options.first_index = base;
    options.progress = progress_printer("cdt", arguments.quiet);
    const tri::Pslg pslg{poly.vertices.xy, poly.segments, poly.holes, poly.regions};

    const auto [result, stats, seconds] = timed_construction([&] {
        return naming_the_input(arguments.input, [&] {
            return locating_mark_points(
                poly, arguments.input, [&] { return tri::constrained_delaunay_2d(pslg, options); });
        });
    });

    print_warnings(result.warnings);
    io::OutputSet set;
    stage_constrained_result(set, result, files, format, base, svg);
    commit_outputs(set);
    const tri::Triangulation2& mesh = result.mesh;
    std::cout << "vertices: " << mesh.vertex_count() << '\n'
              << "triangles: " << mesh.triangle_count() << '\n';
    if (arguments.stats) {
        print_construction_stats(counters_by_name(tri::kCdt2CounterNames, result.counters), stats,
                                 seconds);
    }
}

}  // namespace

void add_cdt_command(CLI::App& app) {
    auto arguments = std::make_shared<CdtArguments>();
    CLI::App* command = app.add_subcommand(
        "cdt", "Constrained (or conforming) Delaunay triangulation of a Triangle .poly file");
    add_input_option(*command, arguments->input, "input",
                     "A Triangle .poly file (or a .node: points only)", "IN.poly");
    add_output_option(*command, arguments->output,
                      "Output; the extension picks the format: .ele (with .neigh, .node and .poly "
                      "beside it), .msh (Gmsh 4.1), .vtu (VTK), .svg (picture)");
    command
        ->add_option("--recovery", arguments->recovery,
                     "Segment recovery: swap (Sloan's edge swapping), cavity (retriangulate the "
                     "crossed polygons), conforming (split at midpoints; the result is Delaunay)")
        ->check(CLI::IsMember({"swap", "cavity", "conforming"}))
        ->capture_default_str();
    command->add_flag(
        "--convex-hull", arguments->convex_hull,
        "Keep the triangles outside the segments (Triangle's -c); holes are still removed");
    add_order_options(*command, *arguments, "Vertex insertion order");
    add_picture_options(*command, arguments->picture);
    add_stats_flag(*command, arguments->stats, "work counters, predicate stages",
                   "the construction alone, without file I/O");
    add_quiet_flag(*command, arguments->quiet);
    command->callback([arguments] { run_cdt(*arguments); });
}

}  // namespace exactmesh::cli
