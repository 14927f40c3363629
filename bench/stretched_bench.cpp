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
//               0.00005 + 0.3 |y - y0| across (aspect ratio 1000 on the line).
// Timed: ours everything from the PSLG to the finished mesh, in process (CPU time, the boundary's
// discretization included); Gmsh its own "Done meshing 2D" CPU time (its 1D meshing of the
// segments excluded, which favours it), as manual time. Each repetition runs at least 0.5 s of
// iterations; run with --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true.
// Counters (of the last mesh, both measured by the same code, metric_quality_report_2d against
// the same MetricField2): triangles, items_per_second (triangles per second), unit_share (edges
// with metric length in [1/sqrt 2, sqrt 2], lengths in the log-Euclidean mean of the ends'
// metrics), length_min/length_max, shape_median (metric mean ratio), above_150 (triangles with
// an angle above 150 degrees), aspect_max.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/gmsh_peer.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
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

/// One metric as a C++ function and as the three MathEvalAniso formulas Gmsh evaluates.
struct MetricCase {
    std::string name;
    double m11 = 0, m12 = 0, m22 = 0;  ///< constant metrics
    bool layer = false;
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
        };
    }();
    return cases;
}

gen::MetricField2 field_of(const MetricCase& m, double layer_y) {
    if (!m.layer) return gen::MetricField2::uniform(gen::metric_from_matrix(m.m11, m.m12, m.m22));
    return gen::MetricField2::analytic(
        [layer_y](double, double y) {
            const double across = 0.00005 + 0.3 * std::fabs(y - layer_y);
            return gen::metric_from_matrix(1 / (0.05 * 0.05), 0, 1 / (across * across));
        },
        "boundary layer");
}

std::string gmsh_field(const MetricCase& m, double layer_y) {
    char text[512];
    if (!m.layer) {
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

}  // namespace

int main(int argc, char** argv) {
    static const std::vector<Domain> domains = {square(), naca0012()};
    const bool gmsh = exactmesh::bench::have_gmsh();
    for (const Domain& d : domains) {
        for (const MetricCase& m : metric_cases()) {
            const std::string suffix = "/" + d.name + "/" + m.name;
            benchmark::RegisterBenchmark(("BM_metric/exactmesh" + suffix).c_str(),
                                         BM_metric_exactmesh, &d, &m)
                ->Unit(benchmark::kMillisecond)
                ->MinTime(0.5);
            if (gmsh) {
                benchmark::RegisterBenchmark(("BM_metric/gmsh-bamg" + suffix).c_str(),
                                             BM_metric_gmsh, &d, &m)
                    ->Unit(benchmark::kMillisecond)
                    ->UseManualTime()
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
