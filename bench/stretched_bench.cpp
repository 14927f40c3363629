// SPDX-License-Identifier: MIT
// Stretched-mesh benchmarks (issue 14): the metric Delaunay generator
// (generators/stretched/metric_delaunay_2d) against Gmsh's anisotropic algorithm (BAMG,
// Mesh.Algorithm = 7) given the same metric as a MathEvalAniso background field, same run, same
// PSLG, same metric formulas.
//
// Names: BM_metric/<mesher>/<domain>/<metric>, mesher `exactmesh` or `gmsh-bamg`; domains the unit
// square and the built-in NACA 0012 domain (generators/boundary/sample_domains); metrics:
//   aniso10     sizes 0.02 along x and 0.002 along y (aspect ratio 10, aligned with the axes);
//   rotated100  sizes 0.05 and 0.0005 along directions at 30 degrees (aspect ratio 100);
//   layer1000   a boundary layer along y = 0.5 (square) or y = 0 (NACA 0012): 0.05 along x,
//               0.00005 + 0.3 |y - y0| across (aspect ratio 1000 on the line);
//   circle100   (square only) a boundary layer curved around the circle of radius 0.3 about
//               (0.5, 0.5): 0.05 along the circle's tangent, 0.0005 + 0.3 |r - 0.3| across (aspect
//               ratio 100 on the circle), M = R diag(1/h_n^2, 1/h_t^2) R^T with R's first column
//               the radial direction (x - 0.5, y - 0.5) / r;
//   circle1000  (square only) the same with 0.00005 + 0.3 |r - 0.3| across (aspect ratio 1000 on
//               the circle: a chord of one cell sags by 21 layer thicknesses there);
//   turning100  (square only, ours only: Gmsh 4.8.4's BAMG aborts on it, an assertion in
//               FindTriangleContening, 2026-12-06) sizes 0.02 along and 0.0002 across the
//               circles about (0.5, 0.5) everywhere (aspect ratio 100 turning about the centre;
//               about 570,000 triangles).
// Timed: ours everything from the PSLG to the finished mesh, in process (CPU time, the boundary's
// discretization included); Gmsh its own "Done meshing 2D" CPU time (its 1D meshing of the
// segments excluded, which favours it), as manual time. Each repetition runs at least 0.5 s of
// iterations; run with --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true.
// Counters (of the last mesh, both measured by the same code, metric_quality_report_2d against
// the same MetricField2): triangles, items_per_second (triangles per second), unit_share (edges
// with metric length in [1/sqrt 2, sqrt 2], lengths in the log-Euclidean mean of the ends'
// metrics), length_min/length_max, shape_median (metric mean ratio), above_150 (triangles with
// an angle above 150 degrees), aspect_max.
//
// Boundary layers: BM_layers/<mesher>/<domain>/<first height>, domains naca0012 and three-element
// (the three-element airfoil also with the layer1000 metric above): advancing layers (the
// registry's `advancing-layers`, layers split into triangles, the rest by frontal) against Gmsh's
// BoundaryLayer field (Quads = 0, a fan at each element's trailing edge, its default
// Frontal-Delaunay for the rest) with the same first height and growth 1.2, Gmsh's Thickness the
// height our tallest stack reached, and the same size elsewhere on both sides (min(1, 0.02 + 0.1
// r), r the distance from mid-chord: our SizeFunction and a MathEval background field). Counters:
// triangles, items_per_second, max_angle and above_150 over the whole mesh, aspect_max (longest
// edge over the smallest altitude), wall_aspect (the wall's longest piece over the first height:
// what the layers must reach at the wall), layers (ours: the most a stack reached; Gmsh's from its
// thickness); ours also layer_max_angle and layer_above_150 over the layers' triangles alone.
// The truncated O-mesh variant (`--o-mesh`, generators/stretched/truncated_omesh_2d) runs on the
// same cases as BM_layers/exactmesh-o-mesh/<domain>/<first height> (no peer of its own).
// BM_layers/min-max-front/<domain>/<first height>: the registry's `min-max-front` (Marcum's
// advancing-front min-max, generators/stretched/min_max_front_2d) with the same size and layers,
// the same counters but the layer-only ones (its layer triangles are not numbered apart).
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench/gmsh_peer.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/stretched/metric_2d.hpp"
#include "generators/stretched/metric_delaunay_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "generators/stretched/metric_quality_2d.hpp"

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using exactmesh::bench::GmshMesh;

struct Domain {
    std::string name;
    std::vector<double> xy;
    std::vector<tri::VertIdx> segments;
    std::vector<double> holes;
    double layer_y = 0;  ///< the line the boundary-layer metric hugs
};

Domain square() {
    return {"square", {0, 0, 1, 0, 1, 1, 0, 1}, {0, 1, 1, 2, 2, 3, 3, 0}, {}, 0.5};
}

Domain naca0012() {
    const gen::DomainPslg d = gen::sample_domain(gen::SampleDomain::Naca0012);
    return {"naca0012", d.xy, d.segments, d.holes, 0.0};
}

Domain three_element() {
    const gen::DomainPslg d = gen::sample_domain(gen::SampleDomain::ThreeElement);
    return {"three-element", d.xy, d.segments, d.holes, 0.0};
}

/// One metric as a C++ function and as the three MathEvalAniso formulas Gmsh evaluates.
struct MetricCase {
    std::string name;
    double m11 = 0, m12 = 0, m22 = 0;  ///< constant metrics
    bool layer = false;
    bool circle = false;           ///< the curved layer (square only)
    double circle_first = 0.0005;  ///< the curved layer's size across on the circle
    bool turning = false;          ///< the turning field (square only, no peer)
};

const std::vector<MetricCase>& metric_cases() {
    static const std::vector<MetricCase> cases = [] {
        const double c = std::cos(0.5235987755982988), s = std::sin(0.5235987755982988);
        const double l1 = 1 / (0.05 * 0.05), l2 = 1 / (0.0005 * 0.0005);
        return std::vector<MetricCase>{
            {"aniso10", 1 / (0.02 * 0.02), 0, 1 / (0.002 * 0.002), false},
            {"rotated100", c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2,
             false},
            {"layer1000", 0, 0, 0, true},
            {"circle100", 0, 0, 0, false, true},
            {"circle1000", 0, 0, 0, false, true, 0.00005},
            {"turning100", 0, 0, 0, false, false, 0, true},
        };
    }();
    return cases;
}

/// The circle100 (first = 0.0005) and circle1000 (0.00005) metrics' entries at (x, y), as
/// gmsh_field writes them for Gmsh: the radial direction (dx, dy) / r with r^2 + 1e-30 (the
/// centre gets the tangential size both ways).
std::array<double, 3> circle_matrix(double x, double y, double first) {
    const double dx = x - 0.5, dy = y - 0.5, r2 = dx * dx + dy * dy + 1e-30;
    const double hn = first + 0.3 * std::fabs(std::sqrt(r2) - 0.3), ht = 0.05;
    const double across = 1 / (hn * hn) - 1 / (ht * ht);
    return {1 / (ht * ht) + dx * dx / r2 * across, dx * dy / r2 * across,
            1 / (ht * ht) + dy * dy / r2 * across};
}

gen::MetricField2 field_of(const MetricCase& m, double layer_y) {
    if (m.circle) {
        return gen::MetricField2::analytic(
            [first = m.circle_first](double x, double y) {
                const std::array<double, 3> e = circle_matrix(x, y, first);
                return gen::metric_from_matrix(e[0], e[1], e[2]);
            },
            "circle boundary layer");
    }
    if (m.turning) {
        return gen::MetricField2::analytic(
            [](double x, double y) {
                // 0.0002 across the circles about the centre (radially), 0.02 along them.
                const double dx = x - 0.5, dy = y - 0.5, r = std::hypot(dx, dy);
                gen::Metric2 metric;
                metric.h1 = 0.0002;
                metric.h2 = 0.02;
                if (r > 0) {
                    metric.c = dx / r;
                    metric.s = dy / r;
                }
                return metric;
            },
            "turning field");
    }
    if (!m.layer) return gen::MetricField2::uniform(gen::metric_from_matrix(m.m11, m.m12, m.m22));
    return gen::MetricField2::analytic(
        [layer_y](double, double y) {
            const double across = 0.00005 + 0.3 * std::fabs(y - layer_y);
            return gen::metric_from_matrix(1 / (0.05 * 0.05), 0, 1 / (across * across));
        },
        "boundary layer");
}

std::string gmsh_field(const MetricCase& m, double layer_y) {
    char text[1024];
    if (m.circle) {
        // circle_matrix written with x and y.
        const char* r2 = "((x-0.5)^2+(y-0.5)^2+1e-30)";
        char first[32];
        std::snprintf(first, sizeof first, "%.17g", m.circle_first);
        const std::string across =
            "(1/(" + std::string(first) + "+0.3*Fabs(Sqrt(" + std::string(r2) + ")-0.3))^2-400)";
        std::snprintf(text, sizeof text,
                      "Field[1] = MathEvalAniso;\nField[1].M11 = \"400+(x-0.5)^2/%s*%s\";\n"
                      "Field[1].M12 = \"(x-0.5)*(y-0.5)/%s*%s\";\n"
                      "Field[1].M22 = \"400+(y-0.5)^2/%s*%s\";\n",
                      r2, across.c_str(), r2, across.c_str(), r2, across.c_str());
    } else if (!m.layer) {
        std::snprintf(text, sizeof text,
                      "Field[1] = MathEvalAniso;\nField[1].M11 = \"%.17g\";\nField[1].M12 = "
                      "\"%.17g\";\nField[1].M22 = \"%.17g\";\n",
                      m.m11, m.m12, m.m22);
    } else {
        std::snprintf(text, sizeof text,
                      "Field[1] = MathEvalAniso;\nField[1].M11 = \"%.17g\";\nField[1].M12 = "
                      "\"0\";\nField[1].M22 = \"1/(0.00005+0.3*Fabs(y-(%.17g)))^2\";\n",
                      1 / (0.05 * 0.05), layer_y);
    }
    return std::string(text) +
           "Field[1].M13 = \"0\";\nField[1].M23 = \"0\";\nField[1].M33 = \"1\";\n"
           "Background Field = 1;\nMesh.MeshSizeExtendFromBoundary = 0;\n"
           "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\nMesh.Algorithm = 7;\n";
}

void report(benchmark::State& state, const std::vector<double>& xy,
            const std::vector<tri::VertIdx>& triangles, const gen::MetricField2& field) {
    const gen::MetricQualityReport2 q = gen::metric_quality_report_2d(xy, triangles, field);
    state.counters["triangles"] = static_cast<double>(q.triangles);
    state.counters["unit_share"] = q.unit_length_share;
    state.counters["length_min"] = q.length_min;
    state.counters["length_max"] = q.length_max;
    state.counters["shape_median"] = q.shape_median;
    state.counters["above_150"] = static_cast<double>(q.above_150_degrees);
    state.counters["aspect_max"] = q.aspect_max;
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(q.triangles));
}

void BM_metric_exactmesh(benchmark::State& state, const Domain* domain, const MetricCase* m) {
    const gen::MetricField2 field = field_of(*m, domain->layer_y);
    const gen::MeshDomain2 mesh_domain(tri::Pslg{domain->xy, domain->segments, domain->holes, {}});
    mesh_domain.triangulation();  // the input's CDT, shared by every iteration (as Gmsh's .geo)
    gen::MetricDelaunayOptions2 options;
    options.metric = field;
    gen::MetricDelaunayResult2 result;
    for (auto _ : state) {
        result = gen::metric_delaunay_2d(mesh_domain, options);
        state.PauseTiming();
        benchmark::DoNotOptimize(result);
        state.ResumeTiming();
    }
    report(state, result.mesh.mesh.xy, result.mesh.mesh.triangles, field);
}

const fs::path& gmsh_dir() {
    static const fs::path dir = [] {
        fs::path d =
            fs::temp_directory_path() / ("exactmesh_stretched_bench_" + std::to_string(getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

void BM_metric_gmsh(benchmark::State& state, const Domain* domain, const MetricCase* m) {
    const gen::MetricField2 field = field_of(*m, domain->layer_y);
    const std::string geo = exactmesh::bench::gmsh_pslg_geo(domain->xy, domain->segments) +
                            gmsh_field(*m, domain->layer_y);
    GmshMesh mesh;
    for (auto _ : state) {
        try {
            mesh = exactmesh::bench::run_gmsh_geo(geo, gmsh_dir());
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        state.SetIterationTime(mesh.cpu_seconds);
    }
    report(state, mesh.xy, mesh.triangles, field);
}

// ---- boundary layers ----------------------------------------------------------------------

constexpr double kLayerGrowth = 1.2;

double layer_size(double x, double y) {
    return std::min(1.0, 0.02 + 0.1 * std::hypot(x - 0.5, y));
}

void report_layers(benchmark::State& state, const std::vector<double>& xy,
                   const std::vector<tri::VertIdx>& triangles, double first_height, double layers) {
    const gen::MetricQualityReport2 q = gen::metric_quality_report_2d(
        xy, triangles, gen::MetricField2::uniform(gen::metric_from_matrix(1, 0, 1)));
    state.counters["triangles"] = static_cast<double>(q.triangles);
    state.counters["max_angle"] = q.max_angle;
    state.counters["above_150"] = static_cast<double>(q.above_150_degrees);
    state.counters["aspect_max"] = q.aspect_max;
    state.counters["layers"] = layers;
    state.counters["first_height"] = first_height;
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(q.triangles));
}

/// A segment of the airfoil (both ends near the chord), not of the far field.
bool on_airfoil(const Domain& d, std::size_t s) {
    for (const tri::VertIdx v : {d.segments[2 * s], d.segments[2 * s + 1]}) {
        if (d.xy[2 * v] < -0.5 || d.xy[2 * v] > 1.5 || std::fabs(d.xy[2 * v + 1]) > 0.5)
            return false;
    }
    return true;
}

/// The wall's longest piece over the first height (the aspect ratio the first layer has there).
double wall_aspect(const Domain& d, double first_height) {
    double longest = 0;
    for (std::size_t s = 0; s < d.segments.size() / 2; ++s) {
        if (!on_airfoil(d, s)) continue;
        const tri::VertIdx a = d.segments[2 * s], b = d.segments[2 * s + 1];
        longest = std::max(
            longest, std::hypot(d.xy[2 * b] - d.xy[2 * a], d.xy[2 * b + 1] - d.xy[2 * a + 1]));
    }
    return longest / first_height;
}

/// First height, most layers: the last reaches aspect ratio 10^4 at the wall (issue 14's goal).
struct LayerCase {
    double first_height;
    std::uint32_t max_layers;
};
constexpr LayerCase kLayerCases[] = {{1e-4, 60}, {1e-5, 60}, {1e-6, 100}};

gen::MeshOptions2 layer_options(const LayerCase& c) {
    gen::MeshOptions2 options;
    options.size = gen::SizeFunction::analytic(layer_size, "min(1, 0.02 + 0.1 r)");
    options.layers.first_height = c.first_height;
    options.layers.growth = kLayerGrowth;
    options.layers.max_layers = c.max_layers;
    return options;
}

/// Runs advancing layers once: the most layers a stack reached (Gmsh's thickness follows it).
double our_layer_count(const Domain& d, const LayerCase& c) {
    const gen::MeshDomain2 domain(tri::Pslg{d.xy, d.segments, d.holes, {}});
    const gen::MeshRun2 run =
        gen::find_mesh_generator_2d("advancing-layers").run_on_domain(domain, layer_options(c));
    for (const auto& [name, value] : run.counters) {
        if (name == "layers") return static_cast<double>(value);
    }
    throw std::runtime_error("advancing-layers reports no 'layers' counter");
}

/// Runs the registry's `generator` with the layer options (and layer method), timed; the last
/// run.
gen::MeshRun2 time_layers(benchmark::State& state, const Domain& d, const LayerCase& c,
                          const char* generator_name,
                          gen::LayerMethod2 method = gen::LayerMethod2::AdvancingLayers) {
    const gen::MeshDomain2 domain(tri::Pslg{d.xy, d.segments, d.holes, {}});
    domain.triangulation();
    gen::MeshOptions2 options = layer_options(c);
    options.layers.method = method;
    const gen::MeshGenerator2& generator = gen::find_mesh_generator_2d(generator_name);
    gen::MeshRun2 run;
    for (auto _ : state) {
        run = generator.run_on_domain(domain, options);
        state.PauseTiming();
        benchmark::DoNotOptimize(run);
        state.ResumeTiming();
    }
    return run;
}

/// advancing-layers by `method`: the layers' own angles beside the whole mesh's.
void run_layers(benchmark::State& state, const Domain* d, const LayerCase* c,
                gen::LayerMethod2 method) {
    const gen::MeshRun2 run = time_layers(state, *d, *c, "advancing-layers", method);
    double layers = 0;
    std::size_t layer_triangles = 0;
    for (const auto& [name, value] : run.counters) {
        if (name == "layers") layers = static_cast<double>(value);
        if (name == "layer_triangles") layer_triangles = static_cast<std::size_t>(value);
    }
    const std::vector<tri::VertIdx>& triangles = run.mesh.mesh.triangles;
    report_layers(state, run.mesh.mesh.xy, triangles, c->first_height, layers);
    // The layers' triangles come first (AdvancingLayersResult2): their angles apart, the goal's.
    const gen::MetricQualityReport2 in_layers = gen::metric_quality_report_2d(
        run.mesh.mesh.xy,
        std::span<const tri::VertIdx>(triangles.data(),
                                      std::min(3 * layer_triangles, triangles.size())),
        gen::MetricField2::uniform(gen::metric_from_matrix(1, 0, 1)));
    state.counters["layer_max_angle"] = in_layers.max_angle;
    state.counters["layer_above_150"] = static_cast<double>(in_layers.above_150_degrees);
    state.counters["wall_aspect"] = wall_aspect(*d, c->first_height);
}

void BM_layers_exactmesh(benchmark::State& state, const Domain* d, const LayerCase* c) {
    run_layers(state, d, c, gen::LayerMethod2::AdvancingLayers);
}

void BM_layers_omesh(benchmark::State& state, const Domain* d, const LayerCase* c) {
    run_layers(state, d, c, gen::LayerMethod2::TruncatedOMesh);
}

/// The advancing-front min-max generator with the same layers (its layers are triangles from the
/// start; layers: the most a stack reached).
void BM_layers_min_max_front(benchmark::State& state, const Domain* d, const LayerCase* c) {
    const gen::MeshRun2 run = time_layers(state, *d, *c, "min-max-front");
    double layers = 0;
    for (const auto& [name, value] : run.counters) {
        if (name == "layers") layers = static_cast<double>(value);
    }
    report_layers(state, run.mesh.mesh.xy, run.mesh.mesh.triangles, c->first_height, layers);
    state.counters["wall_aspect"] = wall_aspect(*d, c->first_height);
}

/// Gmsh's BoundaryLayer field on every airfoil segment, a fan at each element's trailing edge.
std::string gmsh_layer_fields(const Domain& d, double first_height, double thickness) {
    // The airfoil segments, and each element's rightmost vertex (its trailing edge): elements are
    // the connected components of the airfoil segments (union-find over their vertices).
    std::vector<tri::VertIdx> parent(d.xy.size() / 2);
    for (std::size_t v = 0; v < parent.size(); ++v) parent[v] = static_cast<tri::VertIdx>(v);
    const auto root = [&parent](tri::VertIdx v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    std::string curves;
    for (std::size_t s = 0; s < d.segments.size() / 2; ++s) {
        if (!on_airfoil(d, s)) continue;
        curves += (curves.empty() ? "" : ", ") + std::to_string(s + 1);
        parent[root(d.segments[2 * s])] = root(d.segments[2 * s + 1]);
    }
    std::vector<tri::VertIdx> trailing(parent.size(), tri::kNone);
    for (std::size_t s = 0; s < d.segments.size() / 2; ++s) {
        if (!on_airfoil(d, s)) continue;
        for (const tri::VertIdx v : {d.segments[2 * s], d.segments[2 * s + 1]}) {
            tri::VertIdx& t = trailing[root(v)];
            if (t == tri::kNone || d.xy[2 * v] > d.xy[2 * t]) t = v;
        }
    }
    std::string fans;
    for (const tri::VertIdx t : trailing) {
        if (t != tri::kNone) fans += (fans.empty() ? "" : ", ") + std::to_string(t + 1);
    }
    std::ostringstream geo;
    geo.precision(17);
    geo << "Field[1] = BoundaryLayer;\nField[1].CurvesList = {" << curves << "};\n"
        << "Field[1].Size = " << first_height << ";\nField[1].Ratio = " << kLayerGrowth
        << ";\nField[1].Thickness = " << thickness << ";\nField[1].Quads = 0;\n"
        << "Field[1].FanPointsList = {" << fans << "};\nBoundaryLayer Field = 1;\n"
        << "Field[2] = MathEval;\nField[2].F = \"Min(1, 0.02 + 0.1 * Sqrt((x - 0.5)^2 + y^2))\";\n"
        << "Background Field = 2;\nMesh.MeshSizeExtendFromBoundary = 0;\n"
        << "Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\n";
    return geo.str();
}

void BM_layers_gmsh(benchmark::State& state, const Domain* d, const LayerCase* c) {
    const double first_height = c->first_height;
    const double layers = our_layer_count(*d, *c);  // untimed
    const double thickness =
        first_height * (std::pow(kLayerGrowth, layers) - 1) / (kLayerGrowth - 1);
    const std::string geo = exactmesh::bench::gmsh_pslg_geo(d->xy, d->segments) +
                            gmsh_layer_fields(*d, first_height, thickness);
    GmshMesh mesh;
    for (auto _ : state) {
        try {
            mesh = exactmesh::bench::run_gmsh_geo(geo, gmsh_dir());
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        state.SetIterationTime(mesh.cpu_seconds);
    }
    report_layers(state, mesh.xy, mesh.triangles, first_height, layers);
    state.counters["wall_aspect"] = wall_aspect(*d, first_height);
}

/// Registers FAMILY/exactmesh/SUFFIX (in-process time) and, when Gmsh is there,
/// FAMILY/PEER/SUFFIX (Gmsh's own CPU time, manual), on the same arguments.
template <class Ours, class Theirs, class... Args>
void register_side_by_side(const std::string& family, const std::string& peer,
                           const std::string& suffix, bool with_peer, Ours ours, Theirs theirs,
                           Args... args) {
    benchmark::RegisterBenchmark((family + "/exactmesh" + suffix).c_str(), ours, args...)
        ->Unit(benchmark::kMillisecond)
        ->MinTime(0.5);
    if (!with_peer) return;
    benchmark::RegisterBenchmark((family + "/" + peer + suffix).c_str(), theirs, args...)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->MinTime(0.5);
}

}  // namespace

int main(int argc, char** argv) {
    // The three-element airfoil with the boundary-layer metric only (the constant metrics say
    // the same as on the NACA 0012, at a minute of Gmsh per repetition).
    static const std::vector<Domain> domains = {square(), naca0012(), three_element()};
    const bool gmsh = exactmesh::bench::have_gmsh();
    for (const Domain& d : domains) {
        for (const MetricCase& m : metric_cases()) {
            if (d.name == "three-element" && !m.layer) continue;
            if (d.name != "square" && (m.circle || m.turning)) continue;
            register_side_by_side("BM_metric", "gmsh-bamg", "/" + d.name + "/" + m.name,
                                  gmsh && !m.turning, BM_metric_exactmesh, BM_metric_gmsh, &d, &m);
        }
    }
    static const std::vector<Domain> airfoils = {naca0012(), three_element()};
    for (const Domain& airfoil : airfoils) {
        for (const LayerCase& c : kLayerCases) {
            char height[32];
            std::snprintf(height, sizeof height, "%g", c.first_height);
            const std::string suffix = "/" + airfoil.name + "/" + height;
            register_side_by_side("BM_layers", "gmsh-boundary-layer", suffix, gmsh,
                                  BM_layers_exactmesh, BM_layers_gmsh, &airfoil, &c);
            for (const auto& [name, function] :
                 {std::pair{"BM_layers/exactmesh-o-mesh", &BM_layers_omesh},
                  std::pair{"BM_layers/min-max-front", &BM_layers_min_max_front}}) {
                benchmark::RegisterBenchmark((name + suffix).c_str(), function, &airfoil, &c)
                    ->Unit(benchmark::kMillisecond)
                    ->MinTime(0.5);
            }
        }
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    std::error_code ignored;
    fs::remove_all(gmsh_dir(), ignored);
    return 0;
}
