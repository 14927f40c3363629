// SPDX-License-Identifier: MIT
// Python bindings of the generators: mesh() of a PSLG or a built-in domain by any generator of
// the registry (the same steps as `exactmesh mesh`: the size budget, the graded default size
// for the generators that need one), and the quality report. Wiring only.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/inputs/inputs_3d.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "python/bindings.hpp"
#include "python/numpy_arrays.hpp"

namespace exactmesh::python {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using namespace pybind11::literals;

namespace {

/// The size= of mesh() and quality(): None, a number (uniform), a text of size sources (the
/// command's size-file lines), or a field sampled on a triangulated grid (the Python side
/// samples a callable; linear in between).
struct SizeArgument {
    std::optional<double> uniform;
    std::string sources;
    std::optional<CoordinateArray> grid_points;
    std::optional<CoordinateArray> grid_values;
    std::optional<IndexArray> grid_triangles;
};

gen::SizeFunction size_function(const SizeArgument& size) {
    if (size.uniform) {
        if (!(std::isfinite(*size.uniform) && *size.uniform > 0))
            throw InputError("size: " + std::to_string(*size.uniform) +
                             " is not a finite number > 0");
        return gen::SizeFunction::uniform(*size.uniform);
    }
    if (!size.sources.empty()) return gen::parse_size_sources(size.sources, "size");
    if (size.grid_points) {
        const std::span<const double> xy = coordinates(*size.grid_points, 2, "size grid points");
        const std::span<const double> values =
            coordinates(*size.grid_values, 1, "size grid values");
        if (values.size() != xy.size() / 2)
            throw InputError("size grid: one value per grid point expected");
        std::vector<std::uint32_t> triangles =
            indices(*size.grid_triangles, 3, xy.size() / 2, "size grid triangles");
        return gen::SizeFunction::background_mesh(
            {xy.begin(), xy.end()}, {values.begin(), values.end()}, std::move(triangles));
    }
    return {};
}

py::dict mesh(const CoordinateArray& points, const IndexArray& segments,
              const CoordinateArray& holes, const std::string& domain_name,
              const std::string& generator_name, const SizeArgument& size_argument,
              std::optional<double> min_angle, std::optional<double> polish_angle,
              std::uint64_t max_steiner, const std::string& layers, bool quads, bool o_mesh,
              unsigned threads, const std::string& refine_order) {
    const gen::MeshGenerator2& generator = gen::find_mesh_generator_2d(generator_name);
    if ((threads != 1 || !refine_order.empty()) &&
        !generator.honours.contains(gen::MeshOption::Threads)) {
        throw InputError(
            "threads and refine_order apply to generator='delaunay-refinement' only; " +
            generator_name + " runs on one thread");
    }
    if ((min_angle || polish_angle) &&
        !(generator.honours.contains(gen::MeshOption::MinAngle) &&
          generator.honours.contains(gen::MeshOption::PolishAngle))) {
        throw InputError(
            "min_angle and polish_angle apply to generator='delaunay-refinement' "
            "only; " +
            generator_name + " has no angle criterion");
    }
    const bool layered = generator.honours.contains(gen::MeshOption::Layers);
    if (!layered && (!layers.empty() || quads || o_mesh)) {
        throw InputError(
            "layers, quads and o_mesh apply to the layered generators "
            "(advancing-layers, stretched-delaunay, min-max-front), not " +
            generator_name);
    }
    if ((quads || o_mesh) && generator.name != "advancing-layers")
        throw InputError("quads and o_mesh apply to generator='advancing-layers' only");
    if (layered && generator.name != "min-max-front" && layers.empty()) {
        throw InputError("generator='" + generator_name +
                         "' needs layers=(first_height, growth[, max_layers])");
    }
    gen::MeshOptions2 options;
    if (min_angle) options.min_angle = *min_angle;
    if (polish_angle) options.polish_angle = *polish_angle;
    if (!std::isfinite(options.min_angle) || !std::isfinite(options.polish_angle))
        throw InputError("min_angle and polish_angle must be finite numbers");
    options.max_steiner_points = max_steiner;
    options.threads = checked_threads(threads);
    options.refinement_order = gen::refinement_order_from_name(refine_order, threads);
    if (!layers.empty()) options.layers = gen::parse_layer_parameters(layers);
    options.layers.quads = quads;
    if (o_mesh) options.layers.method = gen::LayerMethod2::TruncatedOMesh;
    gen::SizeFunction size = size_function(size_argument);

    // The PSLG: the caller's arrays, or the built-in domain discretized by the size.
    std::vector<double> xy, hole_points;
    std::vector<std::uint32_t> segment_indices;
    if (domain_name.empty() == (points.size() == 0)) {
        throw InputError("give either points and segments, or domain= (not both)");
    }
    if (!domain_name.empty()) {
        const gen::SampleDomain sample = gen::sample_domain_from_name(domain_name);
        if (!size.bounded())
            size = gen::sample_domain_size(sample);
        else if (max_steiner == 0)
            gen::refuse_sample_domain_size_far_over_budget(sample, size);
        gen::DomainPslg pslg = gen::sample_domain(sample, size);
        xy = std::move(pslg.xy);
        segment_indices = std::move(pslg.segments);
        hole_points = std::move(pslg.holes);
    } else {
        const std::span<const double> p = coordinates(points, 2, "points");
        xy.assign(p.begin(), p.end());
        segment_indices = indices(segments, 2, xy.size() / 2, "segments");
        if (holes.size() != 0) {
            const std::span<const double> h = coordinates(holes, 2, "holes");
            hole_points.assign(h.begin(), h.end());
        }
    }
    options.size = size;
    gen::MeshRun2 run;
    double seconds = 0;
    {
        py::gil_scoped_release release;
        const tri::Pslg pslg{xy, segment_indices, hole_points, {}};
        const gen::MeshDomain2 domain(pslg, options.cdt);
        const auto start = std::chrono::steady_clock::now();
        if (generator.needs_size && !options.size.bounded())
            options.size = gen::graded_size_from_boundary(domain);
        run = generator.run_on_domain(domain, options);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    py::dict counters;
    for (const auto& [name, value] : run.counters) counters[py::str(name)] = value;
    py::dict result = constrained_result_dict(std::move(run.mesh), std::move(run.quads));
    for (const auto& [name, value] : py::dict(result["counters"])) counters[name] = value;
    result["counters"] = counters;
    result["segments"] = indices_to_numpy(std::move(segment_indices), 2);
    result["holes"] = to_numpy(std::move(hole_points), 2);
    result["construct_seconds"] = seconds;
    result["delaunay"] = generator.delaunay;
    return result;
}

py::dict quality(const CoordinateArray& points, const IndexArray& triangles,
                 const SizeArgument& size_argument) {
    const std::span<const double> xy = coordinates(points, 2, "points");
    const std::vector<std::uint32_t> cells = indices(triangles, 3, xy.size() / 2, "triangles");
    const gen::SizeFunction size = size_function(size_argument);
    gen::QualityReport2 r;
    {
        py::gil_scoped_release release;
        r = gen::quality_report_2d(xy, cells, size);
    }
    py::dict d("triangles"_a = r.triangles, "vertices"_a = r.vertices, "min_angle"_a = r.min_angle,
               "max_angle"_a = r.max_angle, "mean_min_angle"_a = r.mean_min_angle,
               "angle_histogram"_a =
                   std::vector<std::uint64_t>(r.angle_histogram.begin(), r.angle_histogram.end()),
               "radius_edge_min"_a = r.radius_edge_min,
               "radius_edge_median"_a = r.radius_edge_median,
               "radius_edge_max"_a = r.radius_edge_max);
    if (r.has_size) {
        d["edges"] = r.edges;
        d["size_ratio_min"] = r.size_ratio_min;
        d["size_ratio_median"] = r.size_ratio_median;
        d["size_ratio_max"] = r.size_ratio_max;
    }
    return d;
}

SizeArgument size_argument(std::optional<double> uniform, const std::string& sources,
                           std::optional<CoordinateArray> grid_points,
                           std::optional<CoordinateArray> grid_values,
                           std::optional<IndexArray> grid_triangles) {
    if (grid_points.has_value() != grid_values.has_value() ||
        grid_points.has_value() != grid_triangles.has_value())
        throw InputError("size grid: points, values and triangles go together");
    return {uniform, sources, std::move(grid_points), std::move(grid_values),
            std::move(grid_triangles)};
}

}  // namespace

void bind_generators(py::module_& m) {
    m.def(
        "_mesh",
        [](const CoordinateArray& points, const IndexArray& segments, const CoordinateArray& holes,
           const std::string& domain, const std::string& generator,
           std::optional<double> size_uniform, const std::string& size_sources,
           std::optional<CoordinateArray> size_grid_points,
           std::optional<CoordinateArray> size_grid_values,
           std::optional<IndexArray> size_grid_triangles, std::optional<double> min_angle,
           std::optional<double> polish_angle, std::uint64_t max_steiner, const std::string& layers,
           bool quads, bool o_mesh, unsigned threads, const std::string& refine_order) {
            return mesh(points, segments, holes, domain, generator,
                        size_argument(size_uniform, size_sources, std::move(size_grid_points),
                                      std::move(size_grid_values), std::move(size_grid_triangles)),
                        min_angle, polish_angle, max_steiner, layers, quads, o_mesh, threads,
                        refine_order);
        },
        "points"_a, "segments"_a, "holes"_a, "domain"_a, "generator"_a, "size_uniform"_a,
        "size_sources"_a, "size_grid_points"_a, "size_grid_values"_a, "size_grid_triangles"_a,
        "min_angle"_a, "polish_angle"_a, "max_steiner"_a, "layers"_a, "quads"_a, "o_mesh"_a,
        "threads"_a, "refine_order"_a);
    m.def(
        "_quality",
        [](const CoordinateArray& points, const IndexArray& triangles,
           std::optional<double> size_uniform, const std::string& size_sources,
           std::optional<CoordinateArray> size_grid_points,
           std::optional<CoordinateArray> size_grid_values,
           std::optional<IndexArray> size_grid_triangles) {
            return quality(
                points, triangles,
                size_argument(size_uniform, size_sources, std::move(size_grid_points),
                              std::move(size_grid_values), std::move(size_grid_triangles)));
        },
        "points"_a, "triangles"_a, "size_uniform"_a, "size_sources"_a, "size_grid_points"_a,
        "size_grid_values"_a, "size_grid_triangles"_a);
    m.def(
        "_domain",
        [](const std::string& name) {
            gen::DomainPslg pslg = gen::sample_domain(gen::sample_domain_from_name(name));
            return py::dict("points"_a = to_numpy(std::move(pslg.xy), 2),
                            "segments"_a = indices_to_numpy(std::move(pslg.segments), 2),
                            "holes"_a = to_numpy(std::move(pslg.holes), 2));
        },
        "name"_a);
    m.def(
        "points_2d",
        [](const std::string& distribution, std::uint32_t n, std::uint64_t seed) {
            const gen::Distribution d = gen::distribution_from_name(distribution);
            std::vector<double> xy;
            {
                py::gil_scoped_release release;
                xy = gen::generate_points_2d(d, n, seed);
            }
            return to_numpy(std::move(xy), 2);
        },
        "distribution"_a, "n"_a, "seed"_a = 1,
        "n points of a test distribution (the benchmarks' and fuzzers' generators), shape (n, 2): "
        "uniform, gaussian, grid, cocircular (exactly cocircular lattice points), near-collinear "
        "(a few ulps off a line), duplicates, huge (1e290), tiny (1e-290, subnormals), parabola.");
    m.def(
        "points_3d",
        [](const std::string& distribution, std::uint32_t n, std::uint64_t seed) {
            const gen::Distribution3 d = gen::distribution3_from_name(distribution);
            std::vector<double> xyz;
            {
                py::gil_scoped_release release;
                xyz = gen::generate_points_3d(d, n, seed);
            }
            return to_numpy(std::move(xyz), 3);
        },
        "distribution"_a, "n"_a, "seed"_a = 1,
        "n points of a 3D test distribution, shape (n, 3) (names as `exactmesh tetrahedralize` "
        "benchmarks use them).");
    std::vector<std::string> generators, domains;
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) generators.emplace_back(g.name);
    for (const gen::SampleDomain d : gen::kAllSampleDomains)
        domains.emplace_back(gen::sample_domain_name(d));
    std::vector<std::string> distributions_2d, distributions_3d;
    for (const gen::Distribution d : gen::kAllDistributions)
        distributions_2d.emplace_back(gen::distribution_name(d));
    for (const gen::Distribution3 d : gen::kAllDistributions3)
        distributions_3d.emplace_back(gen::distribution_name(d));
    m.attr("distributions_2d") = distributions_2d;
    m.attr("distributions_3d") = distributions_3d;
    m.attr("generators") = generators;
    m.attr("domains") = domains;
}

}  // namespace exactmesh::python
