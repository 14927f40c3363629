// SPDX-License-Identifier: MIT
// `exactmesh adapt`: solution-adaptive meshing of a domain (issue 13). The initial mesh is made
// by a generator of the registry (a .poly, or a built-in sample domain whose curves adaptation
// keeps), the field is an expression (the solver's stand-in), and each cycle refines where the
// indicator says (generators/adaptation/); per cycle it prints the vertex and triangle counts
// and the maximum and L2 error of the field's piecewise-linear interpolant.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "cli/commands.hpp"
#include "cli/field_expression.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "cli/size_expression.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "io/triangle_format.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

/// The adaptation methods `--method` names.
enum class AdaptMethod { Insertion };
constexpr std::array<EnumName<AdaptMethod>, 1> kAdaptMethodNames{{
    {"insertion", AdaptMethod::Insertion},
}};

struct AdaptArguments {
    std::string input;
    std::string domain;
    std::string output;
    std::string field;
    std::string method = "insertion";
    std::string indicator = "second-difference";
    std::string generator = "delaunay-refinement";
    std::string size;
    std::uint32_t cycles = 3;
    std::uint64_t max_vertices = 0;
    double threshold = 1.0;
    std::uint32_t smooth = 0;
    double time = 0;
    bool quality = false;
    bool stats = false;
};

/// The most cycles: each at least doubles nothing, but a run that asks for more is a typo.
constexpr std::uint32_t kMaxCycles = 1000;
constexpr std::uint32_t kMaxSmoothSweeps = 1000;

void print_cycle(std::uint64_t cycle, const gen::AdaptiveMesh2& state,
                 const gen::AnalyticField& field, double t) {
    const gen::InterpolationError error =
        gen::interpolation_error(state.mesh.xy, 2, state.mesh.triangles, state.values, field, t);
    std::cout << "cycle " << cycle << ": vertices " << state.mesh.vertex_count() << " triangles "
              << state.mesh.triangle_count() << " max_error " << format_approximate(error.maximum)
              << " l2_error " << format_approximate(error.l2) << '\n';
}

void run_adapt(const AdaptArguments& arguments) {
    if (arguments.input.empty() == arguments.domain.empty())
        throw InputError("give either an input .poly file or --domain NAME (not both)");
    if (arguments.field.empty()) throw InputError("--field EXPR is required");
    (void)parse_name(kAdaptMethodNames, arguments.method, "adaptation method");
    if (!(arguments.threshold >= 0) || !std::isfinite(arguments.threshold))
        throw InputError("--threshold must be a finite number >= 0 (got " +
                         format_number(arguments.threshold) + ")");
    if (!std::isfinite(arguments.time))
        throw InputError("--time must be finite (got " + format_number(arguments.time) + ")");
    const gen::AnalyticField field = field_from_expression(arguments.field);
    const gen::MeshGenerator2& generator = gen::find_mesh_generator_2d(arguments.generator);
    gen::AdaptationOptions options;
    options.indicator = gen::edge_indicator_from_name(arguments.indicator);
    options.threshold = arguments.threshold;
    options.max_vertices = arguments.max_vertices;
    options.smoothing_sweeps = arguments.smooth;

    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);
    const std::vector<fs::path> files = output_files(output, format, {".neigh", ".node", ".poly"});
    if (!arguments.input.empty())
        refuse_to_overwrite_inputs({arguments.input, io::poly_node_path(arguments.input)}, files);

    gen::SizeFunction size = arguments.size.empty() ? gen::SizeFunction() : [&] {
        double uniform = 0;
        if (gen::parse_uniform_size(arguments.size, uniform))
            return gen::SizeFunction::uniform(uniform);
        return size_from_expression(arguments.size);
    }();
    io::PolyFile poly;
    std::vector<gen::Curve2> curves;
    std::vector<gen::SegmentCurve> segment_curves;
    std::string title;
    if (!arguments.domain.empty()) {
        const gen::SampleDomain sample = gen::sample_domain_from_name(arguments.domain);
        if (!size.bounded()) size = gen::sample_domain_size(sample);
        gen::DomainPslg pslg = gen::sample_domain(sample, size);
        poly.vertices.xy = std::move(pslg.xy);
        poly.segments = std::move(pslg.segments);
        poly.holes = std::move(pslg.holes);
        curves = std::move(pslg.curves);
        segment_curves = std::move(pslg.segment_curves);
        title = arguments.domain;
    } else {
        poly = io::read_poly(arguments.input);
        title = fs::path(arguments.input).filename().string();
    }
    const std::uint32_t base = poly.vertices.first_index;
    gen::MeshOptions2 mesh_options;
    mesh_options.size = size;
    mesh_options.cdt.first_index = base;
    const tri::Pslg pslg{poly.vertices.xy, poly.segments, poly.holes, {}};
    const gen::MeshDomain2 domain(pslg, mesh_options.cdt);
    const std::string file =
        arguments.input.empty() ? "--domain " + arguments.domain : arguments.input;
    if (generator.needs_size && !mesh_options.size.bounded())
        mesh_options.size = gen::graded_size_from_boundary(domain);
    gen::MeshRun2 initial = locating_mark_points(
        poly, file, [&] { return generator.run_on_domain(domain, mesh_options); });
    print_warnings(initial.mesh.warnings);

    gen::InsertionCounters2 counters;
    const auto [state, stats, seconds] = timed_construction([&] {
        gen::AdaptiveMesh2 s =
            gen::make_adaptive_mesh_2d(std::move(initial.mesh), poly.vertices.xy, poly.segments,
                                       poly.holes, curves, segment_curves);
        s.values = gen::sample_field(field, s.mesh.xy, 2, arguments.time);
        const gen::FieldSource source{&field, arguments.time};
        for (std::uint32_t cycle = 0; cycle < arguments.cycles; ++cycle) {
            if (!gen::insertion_cycle_2d(s, options, source, counters)) break;
        }
        return s;
    });
    // The per-cycle report needs the meshes of every cycle; the run above is timed alone, so
    // the checks and errors are measured on its result here.
    const std::string problem = gen::check_adaptive_mesh_2d(state, poly.vertices.xy);
    if (!problem.empty())
        throw Error("internal: the adapted mesh fails its exact check: " + problem);
    print_cycle(counters.cycles, state, field, arguments.time);

    tri::Cdt2Result result;
    result.mesh = state.mesh;
    result.input_vertex_count = state.fixed_vertices;
    for (std::size_t p = 0; p < state.pieces.size(); ++p) {
        result.pieces.insert(result.pieces.end(), {state.pieces[p].a, state.pieces[p].b});
        result.piece_segment.push_back(static_cast<std::uint32_t>(p));
    }
    io::OutputSet set;
    stage_constrained_result(set, result, files, format, base,
                             title + " (adapted, " + arguments.method + ")", state.values);
    commit_outputs(set);
    std::cout << "vertices: " << state.mesh.vertex_count() << '\n'
              << "triangles: " << state.mesh.triangle_count() << '\n';
    if (arguments.quality) {
        gen::QualityReport2 report =
            gen::quality_report_2d(state.mesh.xy, state.mesh.triangles, gen::SizeFunction());
        report.seconds = seconds;
        std::cout << gen::quality_report_text(report);
    }
    if (arguments.stats)
        print_construction_stats(counters_by_name(gen::kInsertionCounterNames2, counters), stats,
                                 seconds);
}

}  // namespace

void add_adapt_command(CLI::App& app) {
    auto arguments = std::make_shared<AdaptArguments>();
    CLI::App* command = app.add_subcommand(
        "adapt",
        "Solution-adaptive meshing: refine a mesh of a domain where a field's indicator says");
    command->add_option("input", arguments->input, "A Triangle .poly file")->type_name("IN.poly");
    command
        ->add_option("--domain", arguments->domain,
                     "A built-in domain instead of IN.poly: square-with-holes, naca0012, key, "
                     "three-element (new boundary points go on its curves)")
        ->type_name("NAME");
    command
        ->add_option("-o,--output", arguments->output,
                     "Output (.ele with .neigh, .node (the field as its attribute) and .poly; "
                     ".msh; .vtu; .svg)")
        ->required()
        ->type_name("OUT");
    command
        ->add_option("--field", arguments->field,
                     "The field u(x, y, z, t) (muParser), e.g. 'tanh(20 * (x + y - 1))'")
        ->type_name("EXPR");
    command->add_option("--method", arguments->method, "insertion")->capture_default_str();
    command
        ->add_option("--indicator", arguments->indicator,
                     "first-difference, second-difference, loehner, length-weighted")
        ->capture_default_str();
    command->add_option("--generator", arguments->generator, "The generator of the initial mesh")
        ->capture_default_str();
    command
        ->add_option("--size", arguments->size,
                     "The initial mesh's size: a number or an expression in x and y")
        ->type_name("NUM|EXPR");
    command->add_option("--cycles", arguments->cycles, "Adaptation cycles")
        ->check(whole_number_at_most(kMaxCycles))
        ->capture_default_str();
    command
        ->add_option("--max-vertices", arguments->max_vertices,
                     "Stop refining at this many vertices (0: no limit)")
        ->check(whole_number_at_most(tri::kMaxPoints))
        ->capture_default_str();
    command
        ->add_option("--threshold", arguments->threshold,
                     "Flag edges whose indicator exceeds this times the mean over all edges")
        ->capture_default_str();
    command
        ->add_option("--smooth", arguments->smooth,
                     "Laplacian smoothing sweeps after each cycle (boundary fixed)")
        ->check(whole_number_at_most(kMaxSmoothSweeps))
        ->capture_default_str();
    command->add_option("--time", arguments->time, "The field's time t")->capture_default_str();
    command->add_flag("--quality", arguments->quality, "Print the quality report");
    command->add_flag("--stats", arguments->stats,
                      "Print the adaptation's counters, predicate stages and construct_seconds "
                      "(the cycles alone: no initial mesh, no file I/O)");
    command->callback([arguments] { run_adapt(*arguments); });
}

}  // namespace exactmesh::cli
