// SPDX-License-Identifier: MIT
// Adaptation benchmarks (issue 13): the time of ONE adaptation cycle of each 2D method against
// generating the mesh it produces from scratch, in the same binary and run, so that the ratio
// cycle / regeneration comes from one run.
//
// Workload: the built-in NACA 0012 domain (far-field box [-1.5, 2.5] x [-2, 2]) meshed by
// Delaunay refinement (registry's delaunay-refinement, default angle and polish) at the uniform
// size h0 that gives about EXACTMESH_ADAPT_BENCH_TRIANGLES triangles (default 10^5; h0 calibrated
// by one run at h = 0.1), the boundary discretized at h0; the field is the oblique front
// tanh(50 (x cos 30deg + y sin 30deg - 0.5)) sampled at its vertices; second-difference
// indicator, threshold 1 (the CLI's defaults), no vertex budget.
//
//  - BM_adapt_cycle/<method>: one cycle of insertion, h-refinement, steiner, remesh or
//    local-remesh on that mesh: everything the cycle does (indicator, flags, the new mesh, its
//    field sampled at the new vertices), as `exactmesh adapt` times it. The state is copied
//    before each iteration with the clock stopped (manual time); h-refinement's hierarchy is
//    built from the initial mesh outside the clock too (it persists across cycles).
//  - BM_regenerate/<method>: the same density generated from scratch by the same generator:
//    from the domain's PSLG (the boundary as the initial mesh had it) with a background size
//    function (SizeFunction::background_mesh: linear over the adapted mesh's triangles) whose
//    vertex values are the adapted mesh's local spacing (mean length of the edges at each vertex)
//    times one factor, calibrated outside the clock so that the regenerated mesh has the adapted
//    mesh's vertex count within a few percent. Timed: building the background size function,
//    the whole Delaunay refinement run (CDT of the PSLG, refinement, polish) and sampling the
//    field at the new vertices; not timed: computing the spacing and the calibration (a remesher
//    would have its size field from the indicator instead: that is what `remesh` times).
//  - BM_generate_initial: the initial mesh itself from scratch (uniform size h0), for scale.
// Counters: vertices_before (the initial mesh), vertices and triangles of the mesh produced,
// target_vertices and size_factor for regeneration.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "bench/adaptation_support.hpp"
#include "bench/bench_support.hpp"

namespace {

namespace ad = exactmesh::bench::adaptation;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

double target_triangles() {
    const char* text = std::getenv("EXACTMESH_ADAPT_BENCH_TRIANGLES");
    return text != nullptr ? std::strtod(text, nullptr) : 1e5;
}

struct Workload {
    double h0 = 0;
    gen::DomainPslg domain;
    gen::AnalyticField field = ad::field_by_name("front");
    tri::Cdt2Result initial;
};

const Workload& workload() {
    static const std::unique_ptr<Workload> w = [] {
        auto result = std::make_unique<Workload>();
        const double h = 0.1;
        const double calibration = static_cast<double>(
            ad::generate(ad::naca_domain(h), gen::SizeFunction::uniform(h)).mesh.triangle_count());
        result->h0 = h * std::sqrt(calibration / target_triangles());
        result->domain = ad::naca_domain(result->h0);
        result->initial = ad::generate(result->domain, gen::SizeFunction::uniform(result->h0));
        return result;
    }();
    return *w;
}

const ad::Adapter& prototype(ad::Method method) {
    static std::map<ad::Method, std::unique_ptr<ad::Adapter>> cache;
    auto& slot = cache[method];
    if (!slot) {
        const Workload& w = workload();
        slot = std::make_unique<ad::Adapter>(method, w.domain, w.initial, w.field,
                                             gen::AdaptationOptions{});
    }
    return *slot;
}

/// The mesh one cycle of `method` produces (computed once).
const tri::Triangulation2& adapted(ad::Method method) {
    static std::map<ad::Method, tri::Triangulation2> cache;
    auto it = cache.find(method);
    if (it == cache.end()) {
        ad::Adapter a = prototype(method);
        a.cycle(0);
        it = cache.emplace(method, a.mesh()).first;
    }
    return it->second;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void BM_adapt_cycle(benchmark::State& state, ad::Method method) {
    const ad::Adapter& start = prototype(method);
    std::size_t vertices = 0, triangles = 0;
    for (auto _ : state) {
        auto copy = std::make_unique<ad::Adapter>(start);
        const auto t0 = std::chrono::steady_clock::now();
        copy->cycle(0);
        state.SetIterationTime(seconds_since(t0));
        vertices = copy->mesh().vertex_count();
        triangles = copy->mesh().triangle_count();
        copy.reset();
        exactmesh::bench::after_construction();
    }
    state.counters["vertices_before"] = static_cast<double>(start.mesh().vertex_count());
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["triangles"] = static_cast<double>(triangles);
}

struct Regeneration {
    std::vector<double> spacing;
    double factor = 1;
};

/// The spacing of the adapted mesh and the factor that makes the regenerated mesh's vertex
/// count match it (a few runs, outside the clock).
const Regeneration& regeneration(ad::Method method) {
    static std::map<ad::Method, Regeneration> cache;
    auto it = cache.find(method);
    if (it != cache.end()) return it->second;
    const tri::Triangulation2& target = adapted(method);
    Regeneration r;
    r.spacing = ad::vertex_spacing(target);
    const double wanted = static_cast<double>(target.vertex_count());
    for (int run = 0; run < 5; ++run) {
        std::vector<double> sizes = r.spacing;
        for (double& s : sizes) s *= r.factor;
        const tri::Cdt2Result mesh = ad::generate(
            workload().domain,
            gen::SizeFunction::background_mesh(target.xy, std::move(sizes), target.triangles));
        const double got = static_cast<double>(mesh.mesh.vertex_count());
        if (std::abs(got / wanted - 1) < 0.02) break;
        r.factor *= std::sqrt(got / wanted);
    }
    return cache.emplace(method, std::move(r)).first->second;
}

void BM_regenerate(benchmark::State& state, ad::Method method) {
    const Workload& w = workload();
    const tri::Triangulation2& target = adapted(method);
    const Regeneration& r = regeneration(method);
    std::vector<double> sizes = r.spacing;
    for (double& s : sizes) s *= r.factor;
    std::size_t vertices = 0, triangles = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        auto mesh = std::make_unique<tri::Cdt2Result>(ad::generate(
            w.domain, gen::SizeFunction::background_mesh(target.xy, sizes, target.triangles)));
        const std::vector<double> values = gen::sample_field(w.field, mesh->mesh.xy, 2, 0);
        benchmark::DoNotOptimize(values.data());
        state.SetIterationTime(seconds_since(t0));
        vertices = mesh->mesh.vertex_count();
        triangles = mesh->mesh.triangle_count();
        mesh.reset();
        exactmesh::bench::after_construction();
    }
    state.counters["target_vertices"] = static_cast<double>(target.vertex_count());
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["size_factor"] = r.factor;
}

void BM_generate_initial(benchmark::State& state) {
    const Workload& w = workload();
    std::size_t vertices = 0, triangles = 0;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        auto mesh = std::make_unique<tri::Cdt2Result>(
            ad::generate(w.domain, gen::SizeFunction::uniform(w.h0)));
        state.SetIterationTime(seconds_since(t0));
        vertices = mesh->mesh.vertex_count();
        triangles = mesh->mesh.triangle_count();
        mesh.reset();
        exactmesh::bench::after_construction();
    }
    state.counters["vertices"] = static_cast<double>(vertices);
    state.counters["triangles"] = static_cast<double>(triangles);
    state.counters["h0"] = w.h0;
}

void register_benchmarks() {
    for (const auto& [method, name] : ad::methods()) {
        benchmark::RegisterBenchmark(("BM_adapt_cycle/" + std::string(name)).c_str(),
                                     BM_adapt_cycle, method)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark(("BM_regenerate/" + std::string(name)).c_str(), BM_regenerate,
                                     method)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark("BM_generate_initial", BM_generate_initial)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
}

}  // namespace

int main(int argc, char** argv) {
    exactmesh::bench::set_heap_regime();
    exactmesh::bench::add_compiler_context();
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    register_benchmarks();
    return exactmesh::bench::run_benchmarks_with_default_min_time(argc, argv);
}
