// SPDX-License-Identifier: MIT
// `exactmesh adapt`: solution-adaptive meshing (issue 13). 2D: the initial mesh is made by a
// generator of the registry (a .poly, or a built-in sample domain whose curves adaptation
// keeps) or given (a Triangle IN.node IN.ele, validated exactly, its domain the mesh's boundary
// with a point in each hole: generators/adaptation/mesh_input_2d); 3D: a tetrahedral mesh of a
// convex domain (IN.node IN.ele, or --domain cube). The field is an expression (the solver's
// stand-in) or, for a given mesh, a .node attribute; each cycle refines where
// the indicator says (generators/adaptation/), and a transient run (--steps) derefines where it
// no longer does. Per cycle or step it prints the vertex and element counts and, with an
// analytic field, the maximum and L2 error of the field's piecewise-linear interpolant; those
// lines and the final exact check are outside construct_seconds.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "cli/commands.hpp"
#include "cli/expressions.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/adaptive_remeshing_2d.hpp"
#include "generators/adaptation/adaptive_run_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/h_adaptation_2d.hpp"
#include "generators/adaptation/h_adaptation_3d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/insertion_adaptation_3d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/adaptation/mesh_input_2d.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "io/gmsh_format.hpp"
#include "io/tetgen_format.hpp"
#include "io/triangle_format.hpp"
#include "io/vtk_format.hpp"
#include "predicates/stats.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

struct AdaptArguments {
    std::string input;
    std::string ele;
    std::string domain;
    std::string output;
    std::string field;
    std::string field_file;
    std::string method = "insertion";
    std::string indicator = "second-difference";
    std::string generator = "delaunay-refinement";
    std::string size;
    std::uint32_t cycles = 3;
    std::optional<std::uint32_t> initial_cycles;  ///< with --steps; default: cycles
    std::uint64_t max_vertices = 0;
    double threshold = 1.0;
    bool derefine = false;
    double derefine_threshold = 0.1;
    std::uint32_t smooth = 0;
    std::uint32_t move = 0;
    std::uint32_t steps = 0;
    double dt = 0;
    double time = 0;
    bool quality = false;
    bool stats = false;
    PictureArguments picture;  ///< --view, --shade (2D .svg)
};

/// The most cycles, steps and sweeps: far beyond what converges; more is a typo.
constexpr std::uint32_t kMaxCycles = 1000;
constexpr std::uint32_t kMaxSweeps = 1000;
constexpr std::uint32_t kMaxSteps = 100000;

/// "cycle 3: vertices 1234 triangles 2400 max_error 0.01 l2_error 0.001" (errors with a field).
void print_progress(const std::string& label, std::uint64_t vertices, const char* elements,
                    std::uint64_t element_count, const gen::AnalyticField* field,
                    std::span<const double> xyz, unsigned dim,
                    std::span<const tri::VertIdx> element_vertices, std::span<const double> values,
                    double t) {
    std::cout << label << ": vertices " << vertices << ' ' << elements << ' ' << element_count;
    if (field != nullptr) {
        const gen::InterpolationError error =
            gen::interpolation_error(xyz, dim, element_vertices, values, *field, t);
        std::cout << " max_error " << format_approximate(error.maximum) << " l2_error "
                  << format_approximate(error.l2);
    }
    std::cout << '\n' << std::flush;  // a long run shows its progress in a file too
}

/// The cycles and steps of a run, the same for 2D and 3D: `refine` runs one cycle (false: done),
/// `derefine` one pass, `resample` puts the field at time t on the mesh, `progress` prints a
/// line. Returns the seconds spent in the cycles and passes alone.
template <class Refine, class Derefine, class Resample, class Progress>
double run_cycles(const AdaptArguments& arguments, Refine&& refine, Derefine&& derefine,
                  Resample&& resample, Progress&& progress) {
    double seconds = 0;
    const auto timed = [&](auto&& work) {
        const auto start = std::chrono::steady_clock::now();
        const auto result = work();
        seconds += seconds_since(start);
        return result;
    };
    progress("cycle 0", arguments.time);
    if (arguments.steps == 0) {
        for (std::uint32_t cycle = 1; cycle <= arguments.cycles; ++cycle) {
            if (!timed([&] { return refine(arguments.time); })) break;
            progress("cycle " + std::to_string(cycle), arguments.time);
        }
        return seconds;
    }
    // A transient run starts from the mesh adapted at its first time.
    const std::uint32_t initial_cycles = arguments.initial_cycles.value_or(arguments.cycles);
    timed([&] {
        for (std::uint32_t cycle = 0; cycle < initial_cycles; ++cycle)
            if (!refine(arguments.time)) break;
        return true;
    });
    progress("step 0 t " + format_approximate(arguments.time, 12), arguments.time);
    for (std::uint32_t step = 1; step <= arguments.steps; ++step) {
        const double t = arguments.time + step * arguments.dt;
        timed([&] {
            resample(t);
            // Derefinement passes until one removes nothing (each takes an independent set).
            for (int pass = 0; arguments.derefine && pass < gen::kMaxDerefinementPasses; ++pass)
                if (derefine() == 0) break;
            for (std::uint32_t cycle = 0; cycle < arguments.cycles; ++cycle)
                if (!refine(t)) break;
            return true;
        });
        progress("step " + std::to_string(step) + " t " + format_approximate(t, 12), t);
    }
    return seconds;
}

void check_arguments(const AdaptArguments& arguments) {
    if (arguments.field.empty() == arguments.field_file.empty())
        throw InputError("give either --field EXPR or --field-file FILE (one of them)");
    (void)gen::adapt_method_from_name(arguments.method);
    const auto finite_at_least = [](const char* name, double value, double least) {
        if (!(value >= least) || !std::isfinite(value))
            throw InputError(std::string(name) + " must be a finite number >= " +
                             format_number(least) + " (got " + format_number(value) + ")");
    };
    finite_at_least("--threshold", arguments.threshold, 0);
    finite_at_least("--derefine-threshold", arguments.derefine_threshold, 0);
    finite_at_least("--dt", arguments.dt, 0);
    if (!std::isfinite(arguments.time))
        throw InputError("--time must be finite (got " + format_number(arguments.time) + ")");
    if (arguments.initial_cycles && arguments.steps == 0)
        throw InputError(
            "--initial-cycles goes with --steps (without steps, --cycles counts them)");
    if (arguments.steps > 0 && arguments.field.empty())
        throw InputError("--steps needs an analytic --field (a field file has no time)");
}

/// The vertex budget of --max-vertices 0: each cycle can multiply the mesh several times, so a
/// run of many cycles without a budget would end in an out-of-memory after minutes; it stops
/// refining here instead (about half a minute of cycles at most, a few hundred MB).
constexpr std::uint64_t kAutomaticVertexBudget2 = std::uint64_t{1} << 20;
constexpr std::uint64_t kAutomaticVertexBudget3 = std::uint64_t{1} << 18;

gen::AdaptationOptions adaptation_options(const AdaptArguments& arguments, unsigned dim) {
    gen::AdaptationOptions options;
    options.indicator = gen::edge_indicator_from_name(arguments.indicator);
    options.threshold = arguments.threshold;
    options.max_vertices = arguments.max_vertices > 0 ? arguments.max_vertices
                           : dim == 2                 ? kAutomaticVertexBudget2
                                                      : kAutomaticVertexBudget3;
    options.smoothing_sweeps = arguments.smooth;
    options.movement_sweeps = arguments.move;
    return options;
}

/// The field of --field-file for a mesh given as IN.node IN.ele: the first attribute of a .node
/// (dimension `dim`) whose points are the mesh's `coordinates`, in its order.
/// @throws InputError naming the file and the first line that differs (or the counts).
std::vector<double> field_from_node_file(const std::string& path,
                                         std::span<const double> coordinates, unsigned dim) {
    std::vector<double> points, attributes;
    std::vector<std::uint64_t> lines;
    std::uint32_t attribute_count = 0;
    if (dim == 2) {
        io::NodeFile file = io::read_node(path);
        points = std::move(file.xy);
        attributes = std::move(file.attributes);
        lines = std::move(file.lines);
        attribute_count = file.attribute_count;
    } else {
        io::TetgenNodeFile file = io::read_tetgen_node(path);
        points = std::move(file.xyz);
        attributes = std::move(file.attributes);
        lines = std::move(file.lines);
        attribute_count = file.attribute_count;
    }
    const std::string what =
        "a field file must be a .node with the mesh's points, in its order, and the field as its "
        "first attribute";
    if (attribute_count == 0) throw InputError(path + ": no attribute (" + what + ")");
    const std::size_t count = points.size() / dim, mesh_count = coordinates.size() / dim;
    for (std::size_t v = 0; v < count && v < mesh_count; ++v)
        for (unsigned c = 0; c < dim; ++c)
            if (points[dim * v + c] != coordinates[dim * v + c])
                throw InputError(path + ":" + std::to_string(lines[v]) + ": point " +
                                 format_point(&points[dim * v], static_cast<int>(dim)) +
                                 " is not the mesh's vertex " +
                                 format_point(&coordinates[dim * v], static_cast<int>(dim)) + " (" +
                                 what + ")");
    if (count != mesh_count)
        throw InputError(path + ": " + std::to_string(count) + " points, the mesh has " +
                         std::to_string(mesh_count) + " (" + what + ")");
    std::vector<double> values(count);
    for (std::size_t v = 0; v < count; ++v) values[v] = attributes[v * attribute_count];
    return values;
}

void run_adapt_2d(const AdaptArguments& arguments, const gen::AnalyticField* field) {
    const bool given_mesh = !arguments.ele.empty();
    if (!arguments.field_file.empty() && !given_mesh)
        throw InputError(
            "--field-file: a run from a .poly or --domain makes its own mesh, whose vertices "
            "no field file can match; give --field EXPR, or start from a mesh (IN.node IN.ele)");
    if (given_mesh && !arguments.size.empty())
        throw InputError(
            "--size sets the size of a mesh adapt makes; IN.node IN.ele is the "
            "initial mesh already");
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);
    io::SvgOptions svg = picture_options(arguments.picture, format, "");
    const std::vector<fs::path> files = output_files(output, format, {".neigh", ".node", ".poly"});
    if (given_mesh)
        refuse_to_overwrite_inputs({arguments.input, arguments.ele, arguments.field_file}, files);
    else if (!arguments.input.empty())
        refuse_to_overwrite_inputs(
            {arguments.input, io::poly_node_path(arguments.input), arguments.size}, files);
    else if (!arguments.size.empty())
        refuse_to_overwrite_inputs({arguments.size}, files);
    const gen::MeshGenerator2& generator = gen::find_mesh_generator_2d(arguments.generator);
    const gen::AdaptMethod2 method = gen::adapt_method_from_name(arguments.method);
    gen::SizeFunction size =
        arguments.size.empty() ? gen::SizeFunction() : size_from_option(arguments.size);
    io::PolyFile poly;
    std::vector<gen::Curve2> curves;
    std::vector<gen::SegmentCurve> segment_curves;
    std::string title;
    gen::GivenMeshDomain2 given;
    gen::MeshOptions2 mesh_options;
    tri::Cdt2Result initial;
    std::vector<double> file_values;
    if (given_mesh) {
        // A given mesh: its vertices, its boundary edges as segments, a point in each hole.
        const io::NodeFile nodes = io::read_node(arguments.input);
        const io::EleFile ele =
            io::read_ele(arguments.ele, nodes.first_index, nodes.vertex_count());
        try {
            given = gen::given_mesh_domain_2d(nodes.xy, ele.triangles,
                                              {nodes.first_index, ele.first_index});
        } catch (const InputError& error) {
            throw InputError(arguments.ele + ": " + error.what());
        }
        poly.vertices.first_index = nodes.first_index;
        title = fs::path(arguments.ele).filename().string();
        // h-refinement and local remeshing work on any valid mesh: they keep the given one.
        // The others need a constrained Delaunay triangulation (insertion rebuilds the CDT of
        // the domain's vertices each cycle, Steiner restart resumes Delaunay refinement, remesh
        // compares against the generator's): they start from the CDT of the mesh's vertices
        // and boundary, the same vertices in the same numbering.
        if (method == gen::AdaptMethod2::HRefinement || method == gen::AdaptMethod2::LocalRemesh) {
            initial = gen::given_mesh_result_2d(given);
        } else {
            initial = given.cdt;
            if (!given.mesh_is_cdt)
                print_warnings({arguments.ele +
                                ": not the constrained Delaunay triangulation of its vertices "
                                "and boundary; --method " +
                                arguments.method + " starts from that triangulation instead"});
        }
        if (!arguments.field_file.empty())
            file_values = field_from_node_file(arguments.field_file, given.mesh.xy, 2);
    } else if (!arguments.domain.empty()) {
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
        // The domain below carries no regions: say so rather than drop a bound silently.
        warn_unused_region_areas(poly, arguments.input,
                                 "adapt meshes the domain without its regions; the field's "
                                 "indicator decides the sizes");
    }
    const std::uint32_t base = poly.vertices.first_index;
    mesh_options.size = size;
    mesh_options.cdt.first_index = base;
    const tri::Pslg pslg = given_mesh ? tri::Pslg{given.mesh.xy, given.segments, given.holes, {}}
                                      : tri::Pslg{poly.vertices.xy, poly.segments, poly.holes, {}};
    const std::span<const double> fixed_xy = given_mesh ? given.mesh.xy : poly.vertices.xy;
    if (!given_mesh) {
        const gen::MeshDomain2 domain(pslg, mesh_options.cdt);
        const std::string file =
            arguments.input.empty() ? "--domain " + arguments.domain : arguments.input;
        gen::MeshRun2 generated = naming_the_input(file, [&] {
            if (generator.needs_size && !mesh_options.size.bounded())
                mesh_options.size = gen::graded_size_from_boundary(domain);
            return locating_mark_points(
                poly, file, [&] { return generator.run_on_domain(domain, mesh_options); });
        });
        print_warnings(generated.mesh.warnings);
        initial = std::move(generated.mesh);
    }

    gen::AdaptationOptions options = adaptation_options(arguments, 2);
    gen::AdaptiveRunOptions2 run_options;
    run_options.method = method;
    run_options.adaptation = options;
    run_options.derefine_fraction = arguments.derefine_threshold;
    run_options.transient = arguments.steps > 0;
    if (run_options.method == gen::AdaptMethod2::HRefinement &&
        (arguments.smooth > 0 || arguments.move > 0))
        throw InputError("--smooth and --move would break the nesting of h-refinement");
    if (arguments.derefine && run_options.method != gen::AdaptMethod2::Insertion &&
        run_options.method != gen::AdaptMethod2::HRefinement)
        throw InputError(
            "--derefine goes with --method insertion or h-refinement (steiner "
            "and the remeshing methods coarsen by their size field already)");
    const gen::RemeshDomain2 remesh_domain{pslg, mesh_options.cdt, segment_curves};
    if (initial.mesh.vertex_count() >= options.max_vertices)
        print_warnings({"the initial mesh has " + std::to_string(initial.mesh.vertex_count()) +
                        " vertices, at or above --max-vertices " +
                        std::to_string(options.max_vertices) + ": no cycle refines it"});
    gen::AdaptiveRun2 run(remesh_domain, curves, std::move(initial), generator, field,
                          arguments.time, run_options);
    if (!file_values.empty()) run.set_values(std::move(file_values));
    predicates::reset_thread_stats();
    const double seconds = run_cycles(
        arguments, [&](double t) { return run.cycle(t); }, [&] { return run.derefine(); },
        [&](double t) { run.resample(t); },
        [&](const std::string& label, double t) {
            print_progress(label, run.mesh().vertex_count(), "triangles",
                           run.mesh().triangle_count(), field, run.mesh().xy, 2,
                           run.mesh().triangles, run.values(), t);
        });
    const predicates::PredicateStats stats = predicates::thread_stats();
    if (const std::string problem = run.check(fixed_xy); !problem.empty())
        throw Error("internal: the adapted mesh fails its exact check: " + problem);
    const tri::Cdt2Result result = run.result();
    const std::vector<double>& result_values = run.values();
    const auto named = run.counters();
    io::OutputSet set;
    svg.title = title + " (adapted, " + arguments.method + ")";
    stage_constrained_result(set, result, files, format, base, svg, result_values);
    commit_outputs(set);
    std::cout << "vertices: " << result.mesh.vertex_count() << '\n'
              << "triangles: " << result.mesh.triangle_count() << '\n';
    if (arguments.quality) {
        gen::QualityReport2 report =
            gen::quality_report_2d(result.mesh.xy, result.mesh.triangles, gen::SizeFunction());
        report.seconds = seconds;
        std::cout << gen::quality_report_text(report);
    }
    if (arguments.stats) print_construction_stats(named, stats, seconds);
}

/// --domain cube: the Delaunay tetrahedralization of a 6 x 6 x 6 grid of points in the unit
/// cube (coordinates k / 5, the faces at exactly 0 and 1).
tri::Tetrahedralization3 cube_mesh() {
    std::vector<double> xyz;
    for (int k = 0; k <= 5; ++k)
        for (int j = 0; j <= 5; ++j)
            for (int i = 0; i <= 5; ++i) xyz.insert(xyz.end(), {i / 5.0, j / 5.0, k / 5.0});
    return tri::delaunay_3d_algorithm("green-sibson")(xyz, {}).mesh;
}

void run_adapt_3d(const AdaptArguments& arguments, const gen::AnalyticField* field) {
    const gen::AdaptMethod2 method = gen::adapt_method_from_name(arguments.method);
    if (method != gen::AdaptMethod2::Insertion && method != gen::AdaptMethod2::HRefinement)
        throw InputError("--method " + arguments.method +
                         " is 2D only; 3D adapts by insertion or h-refinement");
    gen::AdaptationOptions options = adaptation_options(arguments, 3);
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);
    if (format == OutputFormat::Svg) throw InputError(output.string() + ": no .svg in 3D");
    picture_options(arguments.picture, format, "");  // refuses --view and --shade
    const std::vector<fs::path> files = output_files(output, format, {".face", ".neigh", ".node"});
    tri::Tetrahedralization3 mesh;
    std::uint32_t base = 0, ele_base = 0;
    if (!arguments.domain.empty()) {
        if (arguments.domain != "cube")
            throw InputError("unknown 3D domain '" + arguments.domain + "' (known: cube)");
        mesh = cube_mesh();
    } else {
        refuse_to_overwrite_inputs({arguments.input, arguments.ele, arguments.field_file}, files);
        const io::TetgenNodeFile nodes = io::read_tetgen_node(arguments.input);
        const io::TetgenEleFile ele =
            io::read_tetgen_ele(arguments.ele, nodes.first_index, nodes.vertex_count());
        base = nodes.first_index;
        ele_base = ele.first_index;
        mesh.xyz = nodes.xyz;
        mesh.tets = ele.tets;
        const tri::Check3Numbering numbering{nodes.first_index, ele.first_index,
                                             io::kTetgenFileCorners};
        try {
            tri::link_neighbors_3d(mesh, numbering);
        } catch (const InputError& error) {
            throw InputError(arguments.ele + ": " + error.what());
        }
        // Exact: positive orientation, faces shared by at most two, a closed convex boundary.
        if (const tri::Check3Report report =
                tri::check_tetrahedralization_3d(mesh.xyz, mesh.tets, {}, numbering);
            !report.ok) {
            throw InputError(arguments.ele +
                             ": not a tetrahedralization of a convex domain "
                             "(3D adaptation inserts by Delaunay into its hull): " +
                             report.problem);
        }
    }
    std::vector<double> values;
    if (field != nullptr) {
        values = gen::sample_field(*field, mesh.xyz, 3, arguments.time);
    } else {
        values = field_from_node_file(arguments.field_file, mesh.xyz, 3);
    }
    const std::vector<double> fixed_xyz = mesh.xyz;
    gen::FieldSource source{field, arguments.time};
    if (arguments.steps > 0) {
        // Transient: thresholds relative to the first mesh's mean indicator (see 2D).
        options.reference_mean = gen::mean_indicator(gen::mesh_edge_indicator(
            options.indicator, mesh.xyz, 3, mesh.tets, gen::mesh_edges_3d(mesh.tets), values));
    }
    std::vector<std::pair<std::string, std::uint64_t>> named;
    tri::Tetrahedralization3 result;
    std::vector<double> result_values;
    double seconds = 0;
    predicates::PredicateStats stats;
    const auto progress_of = [&](const tri::Tetrahedralization3& m, const std::vector<double>& u) {
        return [&m, &u, field](const std::string& label, double t) {
            print_progress(label, m.vertex_count(), "tetrahedra", m.tet_count(), field, m.xyz, 3,
                           m.tets, u, t);
        };
    };
    predicates::reset_thread_stats();
    if (method == gen::AdaptMethod2::Insertion) {
        if (arguments.derefine)
            throw InputError(
                "--derefine: 3D derefinement goes with --method h-refinement (by "
                "its history); Delaunay insertion derefines in 2D only");
        gen::AdaptiveMesh3 state = gen::make_adaptive_mesh_3d(std::move(mesh));
        state.values = std::move(values);
        gen::InsertionCounters3 counters;
        seconds = run_cycles(
            arguments,
            [&](double t) {
                source.t = t;
                return gen::insertion_cycle_3d(state, options, source, counters);
            },
            [] { return std::uint64_t{0}; },
            [&](double t) { state.values = gen::sample_field(*field, state.mesh.xyz, 3, t); },
            progress_of(state.mesh, state.values));
        stats = predicates::thread_stats();
        const std::string problem = gen::check_adaptive_mesh_3d(state, fixed_xyz);
        if (!problem.empty())
            throw Error("internal: the adapted mesh fails its exact check: " + problem);
        named = counters_by_name(gen::kInsertionCounterNames3, counters);
        result = std::move(state.mesh);
        result_values = std::move(state.values);
    } else {
        if (arguments.smooth > 0 || arguments.move > 0)
            throw InputError("--smooth and --move would break the nesting of h-refinement");
        gen::HAdaptiveMesh3 state = gen::make_h_adaptive_mesh_3d(std::move(mesh));
        state.values = std::move(values);
        gen::HAdaptationCounters3 counters;
        seconds = run_cycles(
            arguments,
            [&](double t) {
                source.t = t;
                return gen::h_refinement_cycle_3d(state, options, source, counters);
            },
            [&] {
                return gen::h_derefinement_pass_3d(
                    state, options.indicator, arguments.derefine_threshold * arguments.threshold,
                    options.reference_mean, source, counters);
            },
            [&](double t) {
                source.t = t;
                state.values = gen::sample_field(*field, state.leaves.xyz, 3, t);
            },
            progress_of(state.leaves, state.values));
        stats = predicates::thread_stats();
        if (const gen::HRefinement3Report report = state.hierarchy.check_all(); !report.ok)
            throw Error("internal: the refined mesh fails its exact check: " + report.problem);
        named = counters_by_name(gen::kHAdaptationCounterNames3, counters);
        for (const auto& [name, value] :
             counters_by_name(gen::kHRefinement3CounterNames, state.hierarchy.counters()))
            named.emplace_back(name, value);
        result = std::move(state.leaves);
        result_values = std::move(state.values);
    }
    io::OutputSet set;
    switch (format) {
        case OutputFormat::Ele:
            set.stage(files[0], io::format_tetgen_ele(result.tets, ele_base));
            set.stage(files[1],
                      io::format_tetgen_boundary_faces(result.tets, result.neighbors, base));
            set.stage(files[2], io::format_tetgen_neigh(result.neighbors, ele_base));
            set.stage(files[3], io::format_tetgen_node(result.xyz, base, result_values));
            break;
        case OutputFormat::Msh:
            set.stage(output, io::format_msh_3d(result.xyz, result.tets, result_values));
            break;
        case OutputFormat::Vtu:
            set.stage(output, io::format_vtu_3d(result.xyz, result.tets, base, result_values));
            break;
        case OutputFormat::Svg:
            break;
    }
    commit_outputs(set);
    std::cout << "vertices: " << result.vertex_count() << '\n'
              << "tetrahedra: " << result.tet_count() << '\n';
    if (arguments.stats) print_construction_stats(named, stats, seconds, 3);
}

void run_adapt(const AdaptArguments& arguments) {
    check_arguments(arguments);
    if (arguments.input.empty() == arguments.domain.empty())
        throw InputError(
            "give either an input (IN.poly, or a mesh IN.node IN.ele) or --domain "
            "NAME (not both)");
    const bool three_d = arguments.domain == "cube" ||
                         (!arguments.ele.empty() && io::read_node_dimension(arguments.input) == 3);
    std::optional<gen::AnalyticField> field;
    if (!arguments.field.empty()) field = field_from_expression(arguments.field);
    if (three_d)
        run_adapt_3d(arguments, field ? &*field : nullptr);
    else
        run_adapt_2d(arguments, field ? &*field : nullptr);
}

}  // namespace

void add_adapt_command(CLI::App& app) {
    auto arguments = std::make_shared<AdaptArguments>();
    CLI::App* command = app.add_subcommand(
        "adapt",
        "Solution-adaptive meshing: refine (and in time derefine) a mesh where a field's "
        "indicator says");
    command
        ->add_option("input", arguments->input,
                     "2D: a Triangle .poly file (the initial mesh by --generator), or a Triangle "
                     ".node with its .ele as the second argument (the initial mesh: h-refinement "
                     "and local-remesh keep it, the other methods start from the constrained "
                     "Delaunay triangulation of its vertices and boundary); 3D: a TetGen .node "
                     "with its .ele (a convex domain)")
        ->type_name("IN.poly|IN.node");
    command
        ->add_option("ele", arguments->ele,
                     "The mesh's .ele (Triangle's in 2D, TetGen's in 3D); output numbers "
                     "vertices as IN.node does")
        ->type_name("IN.ele");
    command
        ->add_option("--domain", arguments->domain,
                     "A built-in domain instead of the input: square-with-holes, naca0012, key, "
                     "three-element (2D; new boundary points go on their curves), cube (3D: the "
                     "Delaunay tetrahedralization of a 6^3 grid in the unit cube)")
        ->type_name("NAME");
    command
        ->add_option("-o,--output", arguments->output,
                     "Output: .ele (with .neigh, .node carrying the field as its attribute, and "
                     ".poly in 2D or .face in 3D), .msh (the field as node data \"u\"), .vtu "
                     "(the field as point data \"u\"), .svg (2D)")
        ->required()
        ->type_name("OUT");
    command
        ->add_option("--field", arguments->field,
                     "The field u(x, y, z, t) (muParser: + - * / ^ sqrt exp log sin cos tanh "
                     "abs min max _pi), e.g. 'tanh(20 * (x + y - 1 - t))'")
        ->type_name("EXPR");
    command
        ->add_option("--field-file", arguments->field_file,
                     "With a mesh IN.node IN.ele (2D or 3D): a .node with the mesh's points, in "
                     "its order, whose first attribute is the field (carried to new meshes by "
                     "linear interpolation)")
        ->type_name("FILE");
    command
        ->add_option("--method", arguments->method,
                     "insertion: Delaunay point insertion at flagged edges' midpoints")
        ->capture_default_str();
    command
        ->add_option("--indicator", arguments->indicator,
                     "first-difference (|du|), second-difference (|d2u/ds2| h^2 from recovered "
                     "gradients), loehner (second over first differences with the noise filter "
                     "0.05 |u|), length-weighted (|du| |dx|)")
        ->capture_default_str();
    command
        ->add_option("--generator", arguments->generator, "2D: the generator of the initial mesh")
        ->capture_default_str();
    command
        ->add_option("--size", arguments->size,
                     "2D: the initial mesh's size, as `mesh --size`: a number, a size file or an "
                     "expression in x and y "
                     "(default: the domain's own)")
        ->type_name("NUM|FILE|EXPR");
    command
        ->add_option("--cycles", arguments->cycles,
                     "Refinement cycles (per step with --steps); stops early when nothing is "
                     "flagged or --max-vertices is reached")
        ->check(whole_number_at_most(kMaxCycles))
        ->capture_default_str();
    command
        ->add_option("--initial-cycles", arguments->initial_cycles,
                     "With --steps: the refinement cycles that adapt the first mesh to the field "
                     "at --time before step 1 (default: --cycles; h-refinement refines one level "
                     "per cycle)")
        ->check(whole_number_at_most(kMaxCycles));
    command
        ->add_option("--max-vertices", arguments->max_vertices,
                     "Never refine past this many vertices: the largest indicators whose "
                     "closure fits are taken (0: automatic, 2^20 in 2D, 2^18 in 3D)")
        ->check(whole_number_at_most(tri::kMaxPoints))
        ->capture_default_str();
    command
        ->add_option("--threshold", arguments->threshold,
                     "Flag edges whose indicator exceeds this times the mean over all edges")
        ->capture_default_str();
    command->add_flag("--derefine", arguments->derefine,
                      "2D, with --steps: before each step's refinement, remove vertices whose "
                      "every edge's indicator is below --derefine-threshold times the mean");
    command
        ->add_option("--derefine-threshold", arguments->derefine_threshold,
                     "Derefine where every edge's indicator is below this times --threshold "
                     "times the mean: below 1/4, so that a removal (which about doubles the "
                     "edges at its place, and a second difference four times) is not refined "
                     "again at once")
        ->capture_default_str();
    command
        ->add_option("--smooth", arguments->smooth,
                     "Laplacian smoothing sweeps after each cycle (boundary and input vertices "
                     "fixed; 3D: smart, a move that worsens its star is undone)")
        ->check(whole_number_at_most(kMaxSweeps))
        ->capture_default_str();
    command
        ->add_option("--move", arguments->move,
                     "Solution-weighted movement sweeps after each cycle: vertices drawn towards "
                     "high indicator values, connectivity kept, nothing inverted")
        ->check(whole_number_at_most(kMaxSweeps))
        ->capture_default_str();
    command
        ->add_option("--steps", arguments->steps,
                     "Transient: this many time steps of --dt, each resampling the field at its "
                     "time, derefining (--derefine) and refining (--cycles)")
        ->check(whole_number_at_most(kMaxSteps))
        ->capture_default_str();
    command->add_option("--dt", arguments->dt, "The time step of --steps")->capture_default_str();
    command->add_option("--time", arguments->time, "The field's (first) time t")
        ->capture_default_str();
    add_picture_options(*command, arguments->picture);
    command->add_flag("--quality", arguments->quality, "2D: print the quality report");
    command->add_flag("--stats", arguments->stats,
                      "Print the adaptation's counters, predicate stages and construct_seconds "
                      "(the cycles alone: no initial mesh, error lines, checks or file I/O)");
    command->callback([arguments] { run_adapt(*arguments); });
}

}  // namespace exactmesh::cli
