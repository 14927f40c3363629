// SPDX-License-Identifier: MIT
// `exactmesh tetrahedralize`: TetGen .node in, Delaunay tetrahedralization out (.ele with .face
// and .neigh beside it, .msh or .vtu by the output's extension), optionally with work counters
// and the construction time.
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
#include "io/tetgen_format.hpp"
#include "io/vtk_format.hpp"
#include "predicates/stats.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // kMaxThreads

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;

struct TetrahedralizeArguments : CommandArguments, OrderArguments {
    std::string algorithm = "bowyer-watson";
    unsigned threads = 1;
};

void run_tetrahedralize(const TetrahedralizeArguments& arguments) {
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);  // before any work: fail fast
    if (format == OutputFormat::Svg) {
        throw InputError(output.string() +
                         ": .svg pictures are 2D only; write tetrahedra as .ele, .msh or .vtu");
    }
    const std::vector<fs::path> files = output_files(output, format, {".face", ".neigh"});
    refuse_to_overwrite_inputs({arguments.input}, files);
    const tri::Delaunay3Function construct = tri::delaunay_3d_algorithm(arguments.algorithm);
    const io::TetgenNodeFile nodes = io::read_tetgen_node(arguments.input);

    const tri::Delaunay3Options options{
        tri::insertion_order_from_name(arguments.order), arguments.seed,
        progress_printer("tetrahedralize", arguments.quiet), arguments.threads};
    const auto [result, stats, seconds] =
        timed_construction([&] { return construct(nodes.xyz, options); });
    if (result.coplanar) {
        throw tri::CoplanarPoints(
            arguments.input + ": all " + std::to_string(nodes.vertex_count()) +
            " points lie in one plane (or fewer than 4 are distinct): no tetrahedralization");
    }

    const tri::Tetrahedralization3& mesh = result.mesh;
    io::OutputSet set;
    switch (format) {
        case OutputFormat::Ele:
            set.stage(files[0], io::format_tetgen_ele(mesh.tets, nodes.first_index));
            set.stage(files[1], io::format_tetgen_boundary_faces(mesh.tets, mesh.neighbors,
                                                                 nodes.first_index));
            set.stage(files[2], io::format_tetgen_neigh(mesh.neighbors, nodes.first_index));
            break;
        case OutputFormat::Msh:
            set.stage(output, io::format_msh_3d(nodes.xyz, mesh.tets));
            break;
        case OutputFormat::Vtu:
            set.stage(output, io::format_vtu_3d(nodes.xyz, mesh.tets, nodes.first_index));
            break;
        case OutputFormat::Svg:
            break;  // refused above
    }
    commit_outputs(set);
    std::cout << "tetrahedra: " << mesh.tet_count() << '\n';
    if (arguments.stats) {
        print_construction_stats(counters_by_name(tri::kDelaunay3CounterNames, result.counters),
                                 stats, seconds, 3);
    }
}

}  // namespace

void add_tetrahedralize_command(CLI::App& app) {
    auto arguments = std::make_shared<TetrahedralizeArguments>();
    CLI::App* command = app.add_subcommand(
        "tetrahedralize", "Delaunay tetrahedralization of the points of a TetGen .node file");
    add_input_option(*command, arguments->input, "input",
                     "Points: a TetGen .node file (dimension 3)", "IN.node");
    add_output_option(*command, arguments->output,
                      "Output; the extension picks the format: .ele (TetGen; .face and .neigh "
                      "beside it), .msh (Gmsh 4.1), .vtu (VTK)");
    add_algorithm_option(*command, arguments->algorithm, tri::delaunay_3d_algorithms());
    add_order_options(*command, *arguments, "Insertion order");
    command
        ->add_option("--threads", arguments->threads,
                     "Threads of bowyer-watson with the brio order (oneTBB; the same tetrahedra "
                     "for every count): 1 runs the sequential code, 0 every hardware thread; "
                     "green-sibson and the other orders run sequentially. --stats prints the "
                     "count used and the parallel rounds' counters")
        ->check(whole_number_at_most(tri::kMaxThreads))
        ->capture_default_str();
    add_stats_flag(*command, arguments->stats, "work counters, predicate stages",
                   "the construction alone, without file I/O");
    add_quiet_flag(*command, arguments->quiet);
    command->callback([arguments] { run_tetrahedralize(*arguments); });
}

}  // namespace exactmesh::cli
