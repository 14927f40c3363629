// SPDX-License-Identifier: MIT
// 2D mesh generation benchmarks: our Delaunay refinement (generators/delaunay_refinement_2d)
// against CGAL's Delaunay_mesher_2 (with EXACTMESH_WITH_CGAL), same run, same inputs, same
// criteria [Ruppert95, Shewchuk02; DESIGN.md "Benchmarks and reports"; issue 6].
//
// Names: BM_mesh_<ours|cgal>/<domain>/<angle>/<target triangles>. Domains: the built-in
// sample domains (generators/sample_domains), each with its own size function scaled by a
// constant so that the mesh has about the target number of triangles (10^4, 10^5, 10^6); the
// boundary is discretized by the same scaled size function, once, outside the timed loop, and
// both meshers get that PSLG. Angle bound 20.7 degrees (the proven one; CGAL's default shape
// bound 0.125 = sin^2(20.7)), and 30 degrees at 10^5. Size: every edge at most the size at its
// midpoint for both (CGAL: Delaunay_mesh_size_criteria_2 with the size function evaluated as
// ours does, tests/support/cgal_mesh_2d.hpp). Timed: everything from the PSLG to the finished
// mesh (ours: constrained Delaunay, refinement and the flat output; CGAL: point and constraint
// insertion, refinement). One iteration per repetition; run with --benchmark_repetitions=3 for
// medians of 3 (the default here).
//
// Counters: triangles (in the domain), items_per_second (triangles per second), min_angle
// (degrees, over the mesh), steiner_points (ours), max_size_ratio (longest edge over the size at
// its midpoint).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>

#include "generators/delaunay_refinement_2d.hpp"
#include "generators/sample_domains.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include "tests/support/cgal_mesh_2d.hpp"
#endif

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

struct Workload {
    gen::SizeFunction size;
    gen::DomainPslg pslg;
};

/// The triangle count of our mesh of domain d with its own size function at 20.7 degrees.
double calibration(gen::SampleDomain d) {
    static std::map<int, double> cache;
    auto it = cache.find(static_cast<int>(d));
    if (it == cache.end()) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const gen::DomainPslg pslg = gen::sample_domain(d, size);
        gen::RefinementOptions2 options;
        options.size = size;
        const auto r = gen::delaunay_refinement_2d(tri::Pslg{pslg.xy, pslg.segments, pslg.holes, {}}, options);
        it = cache.emplace(static_cast<int>(d), static_cast<double>(r.mesh.mesh.triangle_count())).first;
    }
    return it->second;
}

const Workload& workload(gen::SampleDomain d, std::int64_t target) {
    static std::map<std::pair<int, std::int64_t>, Workload> cache;
    const auto key = std::make_pair(static_cast<int>(d), target);
    auto it = cache.find(key);
    if (it == cache.end()) {
        // Triangle count ~ 1 / size^2.
        const double factor = std::sqrt(calibration(d) / static_cast<double>(target));
        Workload w;
        w.size = gen::sample_domain_size(d).scaled(factor);
        w.pslg = gen::sample_domain(d, w.size);
        it = cache.emplace(key, std::move(w)).first;
    }
    return it->second;
}

struct MeshStats {
    double min_angle = 180, max_size_ratio = 0;
};

MeshStats measure(const tri::Triangulation2& m, const gen::SizeFunction& size) {
    MeshStats s;
    for (std::uint32_t t = 0; t < m.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const double* o = m.point(m.triangles[3 * t + static_cast<unsigned>(k)]);
            const double* a = m.point(m.triangles[3 * t + static_cast<unsigned>((k + 1) % 3)]);
            const double* b = m.point(m.triangles[3 * t + static_cast<unsigned>((k + 2) % 3)]);
            const double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
            s.min_angle = std::min(s.min_angle, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 /
                                                    std::numbers::pi);
            s.max_size_ratio = std::max(s.max_size_ratio, std::hypot(ux, uy) / size(0.5 * (o[0] + a[0]), 0.5 * (o[1] + a[1])));
        }
    }
    return s;
}

void BM_mesh_ours(benchmark::State& state, gen::SampleDomain d, double angle) {
    const Workload& w = workload(d, state.range(0));
    const tri::Pslg pslg{w.pslg.xy, w.pslg.segments, w.pslg.holes, {}};
    gen::RefinementOptions2 options;
    options.min_angle = angle;
    options.size = w.size;
    double triangles = 0, steiner = 0;
    MeshStats stats;
    for (auto _ : state) {
        auto result = gen::delaunay_refinement_2d(pslg, options);
        state.PauseTiming();
        triangles = result.mesh.mesh.triangle_count();
        steiner = static_cast<double>(result.counters.steiner_points());
        stats = measure(result.mesh.mesh, w.size);
        { auto drop = std::move(result); }
        state.ResumeTiming();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(triangles) * state.iterations());
    state.counters["triangles"] = triangles;
    state.counters["steiner_points"] = steiner;
    state.counters["min_angle"] = stats.min_angle;
    state.counters["max_size_ratio"] = stats.max_size_ratio;
}

#if defined(EXACTMESH_WITH_CGAL)
void BM_mesh_cgal(benchmark::State& state, gen::SampleDomain d, double angle) {
    const Workload& w = workload(d, state.range(0));
    double triangles = 0;
    MeshStats stats;
    for (auto _ : state) {
        auto mesh = exactmesh::testing::cgal_delaunay_mesh_2d(w.pslg.xy, w.pslg.segments, w.pslg.holes, angle, w.size);
        state.PauseTiming();
        std::vector<std::uint32_t> pieces;
        const tri::Triangulation2 flat = exactmesh::testing::cgal_mesh_triangulation(mesh, pieces);
        triangles = flat.triangle_count();
        stats = measure(flat, w.size);
        { auto drop = std::move(mesh); }
        state.ResumeTiming();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(triangles) * state.iterations());
    state.counters["triangles"] = triangles;
    state.counters["min_angle"] = stats.min_angle;
    state.counters["max_size_ratio"] = stats.max_size_ratio;
}
#endif

void register_all() {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        for (const double angle : {20.7, 30.0}) {
            for (const std::int64_t target : {10000, 100000, 1000000}) {
                if (angle == 30.0 && target != 100000) continue;
                char suffix[96];
                std::snprintf(suffix, sizeof suffix, "%s/%g", std::string(gen::sample_domain_name(d)).c_str(), angle);
                auto configure = [&](benchmark::internal::Benchmark* b) {
                    b->Arg(target)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(false)->Unit(benchmark::kMillisecond);
                };
                configure(benchmark::RegisterBenchmark((std::string("BM_mesh_ours/") + suffix).c_str(), BM_mesh_ours, d, angle));
#if defined(EXACTMESH_WITH_CGAL)
                configure(benchmark::RegisterBenchmark((std::string("BM_mesh_cgal/") + suffix).c_str(), BM_mesh_cgal, d, angle));
#endif
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
