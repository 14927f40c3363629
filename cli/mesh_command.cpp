// SPDX-License-Identifier: MIT
// `exactmesh mesh`: a quality mesh of a domain (a .poly, or a built-in sample domain) by one of
// the 2D mesh generators of issue 6, written as .ele (with .neigh, .node, .poly), .msh, .vtu or
// .svg; --quality prints the shared quality report (and, with --metric, the stretched-mesh
// report against that metric field), --stats the generator's counters.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "cli/commands.hpp"
#include "cli/expressions.hpp"
#include "cli/metric_file.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "cli/progress_output.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/laplacian_smoothing_2d.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_conditioning_2d.hpp"
#include "generators/stretched/metric_quality_2d.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"
#include "predicates/stats.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // kMaxThreads

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

struct MeshArguments {
    std::string input;
    std::string domain;
    std::string output;
    std::string generator = "delaunay-refinement";
    double min_angle = gen::kGuaranteedMinAngle;
    double polish_angle = -1;
    std::string size;
    std::string metric;  ///< --metric EXPR|FILE (for now: the stretched-mesh quality report)
    std::string metric_smoothing;  ///< --metric-smoothing PASSES[,WEIGHT]
    double metric_gradation = 0;   ///< --metric-gradation BETA
    std::uint64_t max_steiner = 0;
    unsigned threads = 1;      ///< --threads (delaunay-refinement)
    std::string refine_order;  ///< --refine-order (empty: by --threads)
    std::uint32_t smooth = 0;
    bool quality = false;
    bool stats = false;
    bool quiet = false;         ///< --quiet: no progress lines
    bool angles_given = false;  ///< --min-angle or --polish-angle on the command line
    std::string layers;         ///< --layers FIRST_HEIGHT,GROWTH[,MAX_LAYERS]
    bool quads = false;         ///< --quads
    bool omesh = false;         ///< --o-mesh
    double wake = 0;            ///< --wake LENGTH (chords; 0: none)
    bool staggered = false;     ///< --staggered-layers
    PictureArguments picture;   ///< --view, --shade
};

/// The most --smooth sweeps: Laplacian smoothing converges within tens of sweeps, and each
/// costs a pass over the mesh and a Delaunay re-swap.
constexpr std::uint32_t kMaxSmoothSweeps = 1000;

void print_stats(const gen::MeshRun2& run, const predicates::PredicateStats& stats,
                 double seconds) {
    const tri::Cdt2Counters& cdt = run.mesh.counters;
    std::cout << "points: " << cdt.points << '\n'
              << "duplicates: " << cdt.duplicates << '\n'
              << "segments: " << cdt.segments << '\n'
              << "intersections: " << cdt.intersections << '\n';
    for (const auto& [name, value] : run.counters) std::cout << name << ": " << value << '\n';
    print_predicate_stats(stats);
    for (const auto& [name, value] : run.phase_seconds)
        std::cout << name << ": " << std::fixed << std::setprecision(6) << value << '\n';
    std::cout << "construct_seconds: " << std::fixed << std::setprecision(6) << seconds << '\n';
}

void print_smoothing_stats(const gen::SmoothingCounters2& c, double seconds) {
    std::cout << "smoothing_sweeps: " << c.sweeps << '\n'
              << "smoothing_free_vertices: " << c.free_vertices << '\n'
              << "smoothing_moves: " << c.moves << '\n'
              << "smoothing_undone: " << c.undone << '\n'
              << "smoothing_swaps: " << c.swaps << '\n'
              << "smoothing_largest_move: " << c.largest_move << '\n'
              << "smooth_seconds: " << std::fixed << std::setprecision(6) << seconds << '\n';
}

/// One warning per option or input feature given to a generator that ignores it (issue 12: a
/// warning, not silence). The angles and region maximum areas are refused before this.
std::vector<std::string> ignored_options(const gen::MeshGenerator2& generator,
                                         const MeshArguments& arguments, const io::PolyFile& poly) {
    std::vector<std::string> warnings;
    const auto ignores = [&](gen::MeshOption option, bool given, const std::string& what,
                             const std::string& why = "") {
        if (given && !generator.honours.contains(option)) {
            warnings.push_back(what + " ignored: --generator " + std::string(generator.name) +
                               " does not honour " + std::string(gen::mesh_option_name(option)) +
                               why);
        }
    };
    ignores(gen::MeshOption::Size, !arguments.size.empty(), "--size " + arguments.size);
    ignores(gen::MeshOption::MaxSteinerPoints, arguments.max_steiner != 0,
            "--max-steiner " + std::to_string(arguments.max_steiner));
    ignores(gen::MeshOption::Threads, arguments.threads != 1,
            "--threads " + std::to_string(arguments.threads), " (it runs on one thread)");
    if (!poly.regions.empty()) {
        ignores(gen::MeshOption::RegionAttributes, true,
                arguments.input + ":" + std::to_string(poly.region_lines[0]) + ": " +
                    std::to_string(poly.regions.size() / 4) + " regions' attributes",
                " (its mesh carries none; delaunay-refinement and frontal carry them)");
    }
    return warnings;
}

/// --metric-smoothing PASSES[,WEIGHT] and --metric-gradation BETA, checked; they need --metric
/// and a generator that meshes to it.
gen::MetricConditioning2 metric_conditioning(const MeshArguments& arguments,
                                             const gen::MeshGenerator2& generator) {
    gen::MetricConditioning2 conditioning;
    conditioning.gradation = arguments.metric_gradation;
    if (!arguments.metric_smoothing.empty()) {
        const std::string& text = arguments.metric_smoothing;
        const std::size_t comma = text.find(',');
        const std::string passes = text.substr(0, comma);
        std::size_t used = 0;
        long value = -1;
        try {
            value = std::stol(passes, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != passes.size() || value < 1 || value > gen::kMaxMetricConditioningPasses) {
            throw InputError("--metric-smoothing '" + text +
                             "': PASSES must be a whole number in [1, " +
                             std::to_string(gen::kMaxMetricConditioningPasses) + "]");
        }
        conditioning.smoothing_passes = static_cast<int>(value);
        if (comma != std::string::npos) {
            const std::string weight = text.substr(comma + 1);
            double w = -1;
            try {
                w = std::stod(weight, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used != weight.size() || !(w >= 0 && w <= 1)) {
                throw InputError("--metric-smoothing '" + text +
                                 "': WEIGHT must be a number in [0, 1]");
            }
            conditioning.smoothing_weight = w;
        }
    }
    gen::check_metric_conditioning(conditioning);
    if (conditioning.active()) {
        if (arguments.metric.empty())
            throw InputError("--metric-smoothing and --metric-gradation need --metric");
        if (!generator.honours.contains(gen::MeshOption::Metric)) {
            throw InputError(
                "--metric-smoothing and --metric-gradation condition the metric a "
                "generator meshes to: --generator " +
                std::string(generator.name) + " does not use --metric");
        }
    }
    return conditioning;
}

void run_mesh(const MeshArguments& arguments) {
    const gen::MeshGenerator2& generator = gen::find_mesh_generator_2d(arguments.generator);
    if (arguments.angles_given && !(generator.honours.contains(gen::MeshOption::MinAngle) &&
                                    generator.honours.contains(gen::MeshOption::PolishAngle))) {
        // Refused (documented in --help), so that --min-angle 30 never looks as if it had been
        // honoured; the other options a generator ignores are warnings (ignored_options).
        throw InputError(
            "--min-angle and --polish-angle apply to --generator delaunay-refinement only; " +
            std::string(generator.name) + " has no angle criterion");
    }
    if (!std::isfinite(arguments.min_angle) || !std::isfinite(arguments.polish_angle)) {
        throw InputError("--min-angle and --polish-angle must be finite numbers (got " +
                         format_number(arguments.min_angle) + " and " +
                         format_number(arguments.polish_angle) + ")");
    }
    if (arguments.input.empty() == arguments.domain.empty()) {
        throw InputError("give either an input .poly file or --domain NAME (not both)");
    }
    const bool layered = generator.honours.contains(gen::MeshOption::Layers);
    if (!layered && (!arguments.layers.empty() || arguments.quads)) {
        throw InputError(
            "--layers and --quads apply to --generator advancing-layers (and --layers to "
            "stretched-delaunay and min-max-front) only, not " +
            std::string(generator.name));
    }
    if (arguments.quads && generator.name != "advancing-layers") {
        throw InputError("--quads applies to --generator advancing-layers only, not " +
                         std::string(generator.name));
    }
    if (arguments.staggered && generator.name != "stretched-delaunay") {
        throw InputError("--staggered-layers applies to --generator stretched-delaunay only, not " +
                         std::string(generator.name));
    }
    if (arguments.wake != 0 && generator.name != "stretched-delaunay") {
        throw InputError("--wake applies to --generator stretched-delaunay only, not " +
                         std::string(generator.name));
    }
    if (!(arguments.wake >= 0) || !std::isfinite(arguments.wake))
        throw InputError("--wake " + format_number(arguments.wake) +
                         ": a length in chords, finite and >= 0");
    if (arguments.omesh && generator.name != "advancing-layers") {
        throw InputError("--o-mesh applies to --generator advancing-layers only, not " +
                         std::string(generator.name));
    }
    // min-max-front meshes without layers too (its isotropic advancing front alone).
    const bool layers_optional = generator.name == "min-max-front";
    if (layered && !layers_optional && arguments.layers.empty()) {
        throw InputError("--generator " + std::string(generator.name) +
                         " needs --layers FIRST_HEIGHT,GROWTH[,MAX_LAYERS] (e.g. 1e-4,1.2)");
    }
    if (layered && (!layers_optional || !arguments.layers.empty()) && arguments.smooth > 0) {
        // Laplacian smoothing moves every free vertex, the layers' too: it would undo them.
        throw InputError("--smooth would move the layers' points: not with --generator " +
                         std::string(generator.name));
    }
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);
    io::SvgOptions svg = picture_options(arguments.picture, format, "");
    if (arguments.quads && format == OutputFormat::Ele) {
        throw InputError(output.string() +
                         ": a .ele file holds triangles only; --quads needs a .msh or .vtu "
                         "output (or .svg)");
    }
    const gen::LayerParameters2 layer_parameters =
        layered && !arguments.layers.empty() ? gen::parse_layer_parameters(arguments.layers)
                                             : gen::LayerParameters2{};
    const std::vector<fs::path> files = output_files(output, format, {".neigh", ".node", ".poly"});
    if (!arguments.input.empty()) {
        std::vector<fs::path> inputs{arguments.input, io::poly_node_path(arguments.input)};
        if (!arguments.size.empty()) inputs.emplace_back(arguments.size);
        if (!arguments.metric.empty())
            inputs.insert(inputs.end(), {arguments.metric, metric_ele_path(arguments.metric)});
        refuse_to_overwrite_inputs(inputs, files);
    } else {
        std::vector<fs::path> inputs;
        if (!arguments.size.empty()) inputs.emplace_back(arguments.size);
        if (!arguments.metric.empty())
            inputs.insert(inputs.end(), {arguments.metric, metric_ele_path(arguments.metric)});
        if (!inputs.empty()) refuse_to_overwrite_inputs(inputs, files);
    }
    const gen::MetricConditioning2 conditioning = metric_conditioning(arguments, generator);
    // Read (and check) the metric before any meshing: a bad --metric fails at once.
    std::optional<gen::MetricField2> metric;
    if (!arguments.metric.empty()) {
        metric = metric_from_option(arguments.metric);
        if (!arguments.quality && !gen::find_mesh_generator_2d(arguments.generator)
                                       .honours.contains(gen::MeshOption::Metric)) {
            print_warnings({"--metric " + arguments.metric +
                            " ignored without --quality (--generator " + arguments.generator +
                            " does not use it; it feeds only the stretched-mesh quality "
                            "report)"});
        }
    }

    gen::SizeFunction size =
        arguments.size.empty() ? gen::SizeFunction() : size_from_option(arguments.size);
    io::PolyFile poly;
    std::string title;
    if (!arguments.domain.empty()) {
        const gen::SampleDomain domain = gen::sample_domain_from_name(arguments.domain);
        if (!size.bounded())
            size = gen::sample_domain_size(domain);
        else if (arguments.max_steiner == 0)  // the automatic budget, whatever the generator
            gen::refuse_sample_domain_size_far_over_budget(domain, size);
        gen::DomainPslg pslg = gen::sample_domain(domain, size);
        poly.vertices.xy = std::move(pslg.xy);
        poly.segments = std::move(pslg.segments);
        poly.holes = std::move(pslg.holes);
        title = arguments.domain;
    } else {
        poly = io::read_poly(arguments.input);
        title = fs::path(arguments.input).filename().string();
        if (!generator.honours.contains(gen::MeshOption::RegionAreas)) {
            // A generator that carries no regions would silently ignore the areas: refused, so
            // that a mesh never looks as if it had honoured them.
            for (std::size_t r = 0; r < poly.regions.size() / 4; ++r) {
                if (poly.regions[4 * r + 3] > 0) {
                    throw InputError(arguments.input + ":" + std::to_string(poly.region_lines[r]) +
                                     ": region maximum area " +
                                     format_number(poly.regions[4 * r + 3]) +
                                     ": region maximum areas are honoured by delaunay-refinement "
                                     "and frontal only (--generator " +
                                     std::string(generator.name) + ")");
                }
            }
        }
    }
    const std::uint32_t base = poly.vertices.first_index;

    gen::MeshOptions2 options;
    options.min_angle = arguments.min_angle;
    options.polish_angle = arguments.polish_angle;
    options.size = size;
    options.max_steiner_points = arguments.max_steiner;
    options.threads = arguments.threads;
    options.refinement_order =
        gen::refinement_order_from_name(arguments.refine_order, arguments.threads);
    options.cdt.first_index = base;
    options.cdt.progress = progress_printer("mesh", arguments.quiet);
    options.layers = layer_parameters;
    options.layers.quads = arguments.quads;
    if (arguments.omesh) options.layers.method = gen::LayerMethod2::TruncatedOMesh;
    options.metric = metric;
    options.wake_length = arguments.wake;
    options.staggered_layers = arguments.staggered;
    const tri::Pslg pslg{poly.vertices.xy, poly.segments, poly.holes, poly.regions};
    print_warnings(ignored_options(generator, arguments, poly));
    // The domain's constrained triangulation, built once (by the first step that needs it) for
    // the default size, the size budget and the generator.
    const gen::MeshDomain2 domain(pslg, options.cdt);
    if (domain.hull_segments())
        print_warnings(
            {arguments.input + ": no segments: the domain is the convex hull of the vertices"});

    const std::string file =
        arguments.input.empty() ? "--domain " + arguments.domain : arguments.input;
    gen::MetricConditioningCounters2 conditioning_counters;
    const auto [result, stats, seconds] = timed_construction([&] {
        return naming_the_input(file, [&] {
            // A generator that needs a size and was given none takes the input's own spacing at its
            // vertices, graded away from them (timed: it is part of the construction).
            if (generator.needs_size && !size.bounded()) {
                size = locating_mark_points(poly, file,
                                            [&] { return gen::graded_size_from_boundary(domain); });
                options.size = size;
            }
            if (conditioning.active()) {
                // Smoothing and gradation act on a background mesh: a metric file's own, else a
                // first mesh of the domain made with the raw field (BAMG's way; timed with the
                // construction, as it is part of it).
                gen::ConditionedMetricField2 conditioned;
                if (metric->background() != nullptr) {
                    conditioned = gen::condition_metric_field_2d(*metric, conditioning);
                } else {
                    const gen::MeshRun2 first = locating_mark_points(
                        poly, file, [&] { return generator.run_on_domain(domain, options); });
                    conditioned = gen::condition_metric_field_2d(
                        *metric, first.mesh.mesh.xy, first.mesh.mesh.triangles, conditioning);
                }
                conditioning_counters = conditioned.counters;
                options.metric = std::move(conditioned.field);
            }
            return locating_mark_points(poly, file,
                                        [&] { return generator.run_on_domain(domain, options); });
        });
    });

    // Optional Laplacian smoothing, timed and reported apart from the generator, on a copy (the
    // report compares it with the generator's mesh); without it the mesh is not copied.
    std::optional<gen::MeshRun2> smoothed;
    gen::SmoothingCounters2 smoothing;
    double smooth_seconds = 0;
    if (arguments.smooth > 0) {
        smoothed = result;
        gen::SmoothingOptions2 smoothing_options;
        smoothing_options.iterations = arguments.smooth;
        const auto smooth_start = std::chrono::steady_clock::now();
        smoothing = gen::laplacian_smoothing_2d(
            smoothed->mesh.mesh, smoothed->mesh.input_vertex_count, smoothing_options);
        smooth_seconds = seconds_since(smooth_start);
    }
    const gen::MeshRun2& final_result = smoothed ? *smoothed : result;
    print_warnings(result.mesh.warnings);
    char label[64];
    if (generator.name == "delaunay-refinement") {
        std::snprintf(label, sizeof label, " (%s, %g degrees)", arguments.generator.c_str(),
                      arguments.min_angle);
    } else {
        std::snprintf(label, sizeof label, " (%s)", arguments.generator.c_str());
    }
    // The stretched-mesh report before any output is written: a metric that is not positive
    // definite somewhere on the mesh is an input error that leaves no files behind.
    std::optional<gen::MetricQualityReport2> metric_report;
    if (metric && arguments.quality) {
        // Against the field the generator meshed to (the conditioned one when conditioned).
        metric_report = gen::metric_quality_report_2d(
            final_result.mesh.mesh.xy, final_result.mesh.mesh.triangles, *options.metric);
    }
    // Without --metric, a generator that makes its own metrics (stretched-delaunay) is measured
    // against them, log-Euclidean linear in its triangles (the unit-edge share of issue 14).
    std::optional<gen::MetricQualityReport2> own_metric_report;
    if (!metric && arguments.quality && !final_result.vertex_metrics.empty()) {
        const tri::Triangulation2& own = final_result.mesh.mesh;
        own_metric_report = gen::metric_quality_report_2d(
            own.xy, own.triangles,
            gen::MetricField2::background_mesh(own.xy, final_result.vertex_metrics, own.triangles));
    }
    io::OutputSet set;
    svg.title = title + label;
    stage_constrained_result(set, final_result.mesh, files, format, base, svg, {},
                             final_result.quads);
    commit_outputs(set);
    const tri::Triangulation2& mesh = final_result.mesh.mesh;
    std::cout << "vertices: " << mesh.vertex_count() << '\n'
              << "triangles: " << mesh.triangle_count() << '\n';
    if (!final_result.quads.empty())
        std::cout << "quads: " << final_result.quads.size() / 4 << '\n';
    if (arguments.quality) {
        gen::QualityReport2 report = gen::quality_report_2d(mesh.xy, mesh.triangles, size);
        report.seconds = seconds;
        std::cout << gen::quality_report_text(report);
        if (!final_result.quads.empty()) {
            // The shared report measures triangles; the quadrilaterals are left out of it.
            std::cout << "quality.note: the report above covers the " << mesh.triangle_count()
                      << " triangles only; the " << final_result.quads.size() / 4
                      << " layer quadrilaterals (strictly convex, checked exactly) are measured "
                         "below: corner angles, aspect ratio (longest over shortest side)\n";
            const gen::QuadQuality2 quads = gen::quad_quality_2d(mesh.xy, final_result.quads);
            std::cout << "quality.quads: " << quads.quads << '\n'
                      << "quality.quad_min_angle: " << quads.min_angle << '\n'
                      << "quality.quad_max_angle: " << quads.max_angle << '\n'
                      << "quality.quad_max_aspect_ratio: " << quads.max_aspect_ratio << '\n'
                      << "quality.quad_mean_aspect_ratio: " << quads.mean_aspect_ratio << '\n';
        }
        if (metric_report) {
            std::cout << "quality.metric: " << options.metric->describe() << '\n'
                      << gen::metric_quality_report_text(*metric_report);
        }
        if (own_metric_report) {
            std::cout << "quality.metric: the generator's own per-vertex metrics\n"
                      << gen::metric_quality_report_text(*own_metric_report);
        }
        if (arguments.smooth > 0) {
            const tri::Triangulation2& unsmoothed = result.mesh.mesh;
            const gen::QualityReport2 before =
                gen::quality_report_2d(unsmoothed.xy, unsmoothed.triangles, size);
            std::cout << "smoothing.min_angle_before: " << before.min_angle << '\n'
                      << "smoothing.mean_min_angle_before: " << before.mean_min_angle << '\n';
        }
    }
    if (arguments.stats) {
        print_stats(result, stats, seconds);
        if (conditioning.active()) {
            for (const auto& [name, value] :
                 counters_by_name(gen::kMetricConditioningCounterNames, conditioning_counters))
                std::cout << "metric_" << name << ": " << value << '\n';
        }
        if (arguments.smooth > 0) print_smoothing_stats(smoothing, smooth_seconds);
    }
}

}  // namespace

void add_mesh_command(CLI::App& app) {
    auto arguments = std::make_shared<MeshArguments>();
    CLI::App* command = app.add_subcommand(
        "mesh",
        "Quality mesh of a domain: a Triangle .poly file, or a built-in sample domain (--domain)");
    command
        ->add_option("input", arguments->input,
                     "A Triangle .poly file (segments enclose the domain; holes)")
        ->type_name("IN.poly");
    command
        ->add_option("--domain", arguments->domain,
                     "A built-in domain instead of IN.poly: square-with-holes, naca0012, key, "
                     "three-element (its curves "
                     "discretized by --size, else by the domain's own size function)")
        ->type_name("NAME");
    command
        ->add_option("-o,--output", arguments->output,
                     "Output; the extension picks the format: .ele (with .neigh, .node and .poly "
                     "beside it), .msh (Gmsh 4.1), .vtu (VTK), .svg (picture)")
        ->required()
        ->type_name("OUT");
    std::string generator_help = "The mesh generator:";
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        generator_help += "\n  " + std::string(g.name) + ": " + std::string(g.summary);
    }
    command->add_option("--generator", arguments->generator, generator_help)->capture_default_str();
    command
        ->add_option(
            "--min-angle", arguments->min_angle,
            "delaunay-refinement only (the other generators refuse it): every angle at least this "
            "many degrees, away from small input angles; proven to terminate up to 20.7 (input "
            "angles >= 60), accepted in [0, 34]; 0: no angle criterion")
        ->capture_default_str();
    command
        ->add_option(
            "--polish-angle", arguments->polish_angle,
            "delaunay-refinement only: after the refinement to --min-angle, refine triangles "
            "below this angle too, worst first, within 10% more points (no guarantee: "
            "when that budget runs out the --min-angle mesh is finished as usual); "
            "negative: min(--min-angle + 10, 32); 0: off")
        ->capture_default_str();
    command
        ->add_option("--size", arguments->size,
                     "Target edge length: a number (uniform); a size file of lines 'uniform H', "
                     "'point X Y S RBAR GAMMA', 'line X0 Y0 X1 Y1 S RBAR GAMMA' (source formula "
                     "s = min(H, sum s_k [1 + (d_k / rbar_k)^gamma_k])); or an expression in x and "
                     "y (muParser: + - * / ^ sqrt exp log sin cos abs min max _pi), e.g. "
                     "'0.01 + 0.1 * sqrt(x^2 + y^2)'. Default: none for delaunay-refinement "
                     "(it grades by itself); for the other generators, the input's spacing at "
                     "each vertex h_v (mean length of its boundary pieces, at most its shortest "
                     "edge in the domain's CDT) graded away from it: min over v of "
                     "h_v + 0.5 |x - v| (the gradation: sizes grow by half the distance)")
        ->type_name("NUM|FILE|EXPR");
    command
        ->add_option("--max-steiner", arguments->max_steiner,
                     "Stop with an error after this many Steiner points (0: automatic; at most " +
                         std::to_string(tri::kMaxPoints) + ")")
        ->check(whole_number_at_most(tri::kMaxPoints))
        ->capture_default_str();
    command
        ->add_option("--threads", arguments->threads,
                     "Threads of delaunay-refinement (oneTBB): 1 runs the sequential "
                     "worst-first refinement, 0 every hardware thread; more than one refines in "
                     "rounds (--refine-order), whose mesh is the same for every thread count. "
                     "--stats prints the count used and the rounds' counters")
        ->check(whole_number_at_most(tri::kMaxThreads))
        ->capture_default_str();
    command
        ->add_option("--refine-order", arguments->refine_order,
                     "delaunay-refinement's order: worst-first (one point at a time, the worst "
                     "triangle first; one thread) or rounds (up to 1024 of the worst triangles, "
                     "keys within 9%, at once: their cavities found in parallel, inserted "
                     "unless one meets an earlier one's; the same mesh on any --threads, not "
                     "worst-first's). Default: worst-first on one thread, rounds on more")
        ->check(CLI::IsMember({"worst-first", "rounds"}));
    command
        ->add_option(
            "--smooth", arguments->smooth,
            "Laplacian smoothing sweeps after the generator (Jacobi formula, a move that would "
            "invert a triangle undone, Delaunay re-swapping after each sweep; boundary and input "
            "vertices fixed); stops early after a sweep that moves no vertex; at most " +
                std::to_string(kMaxSmoothSweeps) + "; timed apart as smooth_seconds")
        ->check(whole_number_at_most(kMaxSmoothSweeps))
        ->capture_default_str();
    command
        ->add_option("--metric", arguments->metric,
                     "A metric field for the stretched-mesh quality report (with --quality: "
                     "metric edge lengths, metric shape, largest angles, aspect ratios), for any "
                     "generator: 'M11;M12;M22', three expressions in x and y (muParser, as "
                     "--size) giving a symmetric positive definite matrix, e.g. "
                     "'1e4;0;1' (edges 0.01 long in x, 1 in y); or four, a stretching vector "
                     "'DIR_X;DIR_Y;SIZE_ALONG;ASPECT_RATIO', e.g. '1;0;1;100' (edges 1 long in x, "
                     "0.01 in y; sizes scale with the domain); or a metric file: a Triangle "
                     ".node whose vertices carry 3 attributes M11 M12 M22 or 4 (a stretching "
                     "vector) DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO, with its .ele beside it "
                     "(log-Euclidean interpolation inside, nearest boundary value outside)")
        ->type_name("EXPR|FILE");
    command
        ->add_option("--metric-smoothing", arguments->metric_smoothing,
                     "metric-delaunay only: before meshing, PASSES log-Euclidean smoothing passes "
                     "of the metric over a background mesh's edges, each moving a vertex's metric "
                     "WEIGHT (default 0.5) of the way to its neighbours' mean; the background "
                     "mesh is the metric file's own, else a first mesh made with the raw metric")
        ->type_name("PASSES[,WEIGHT]");
    command
        ->add_option("--metric-gradation", arguments->metric_gradation,
                     "metric-delaunay only: before meshing (after --metric-smoothing), "
                     "H-correction of the metric on the same background mesh: sizes grow by at "
                     "most a factor 1 + BETA per unit of metric length, in every direction; "
                     "0: off")
        ->type_name("BETA")
        ->capture_default_str();
    command
        ->add_option(
            "--layers", arguments->layers,
            "advancing-layers and stretched-delaunay (required there) and min-max-front "
            "(optional) only: boundary layers on the walls "
            "(every hole loop: the airfoils of the built-in domains): the first layer's "
            "thickness, the growth ratio in [1, 10], and at most MAX_LAYERS layers (1 to " +
                std::to_string(gen::kMaxLayers) +
                ", default 60); a stack also stops at aspect ratio 1 or where it would "
                "cross anything")
        ->type_name("FIRST_HEIGHT,GROWTH[,MAX_LAYERS]");
    command->add_flag("--quads", arguments->quads,
                      "advancing-layers only: keep the layer cells as quadrilaterals (a mixed "
                      "mesh; .msh or .vtu output, not .ele); else each is split in two triangles "
                      "by the diagonal with the smaller largest angle");
    command->add_flag("--o-mesh", arguments->omesh,
                      "advancing-layers only: build the layers as a truncated structured O-mesh "
                      "about each wall (a ring of normal lines, stopped at the layer where its "
                      "cells turn isotropic; where two rings overlap the coarser cells removed) "
                      "instead of stacks advanced one by one; the rest filled the same way");
    command->add_option(
        "--wake", arguments->wake,
        "stretched-delaunay only: a wake behind each trailing edge (a wall's rearmost vertex, "
        "largest x, when it is a convex corner sharper than 90 degrees), LENGTH chords of its "
        "element long at most: stretched points along the corner's bisector, stations growing "
        "by the --layers growth, staggered layers on both sides thickening by growth^2 per "
        "station, ending where they turn isotropic or leave the domain; 0 (the default): none");
    command->add_flag(
        "--staggered-layers", arguments->staggered,
        "stretched-delaunay only: stagger the O-mesh layers (odd layers half a cell along the "
        "wall) so that each cell's triangles are equilateral in the metric: about 96% of edges "
        "of unit metric length instead of 80-85%, but stretched triangles with a largest angle "
        "near 180 degrees (the default keeps right-angled cells: none above 150 degrees in the "
        "layers)");
    add_picture_options(*command, arguments->picture);
    command->add_flag(
        "--quality", arguments->quality,
        "Print the quality report: angles, angle histogram, radius-edge ratio, size conformity "
        "(and the stretched-mesh measures against --metric)");
    command->add_flag(
        "--stats", arguments->stats,
        "Print work counters, predicate stages and construct_seconds (the generator alone, "
        "without file I/O)");
    add_quiet_flag(*command, arguments->quiet);
    command->callback([arguments, command] {
        arguments->angles_given =
            command->count("--min-angle") + command->count("--polish-angle") > 0;
        run_mesh(*arguments);
    });
}

}  // namespace exactmesh::cli
