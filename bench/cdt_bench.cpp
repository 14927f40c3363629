// SPDX-License-Identifier: MIT
// Constrained Delaunay benchmarks: our swap and cavity recovery (and conforming, at smaller
// sizes) against CGAL's Constrained_Delaunay_triangulation_2<Epick, Default,
// Exact_intersections_tag>, same PSLGs, same run [Sloan93, Anglada97; DESIGN.md "Benchmarks
// and reports"].
//
// Names: BM_cdt_<algo>/<workload>, algo in {swap, cavity, conforming, cgal}; workloads
// (generators/inputs/pslg_inputs, pinned seed): chains/<points>/<segments> (uniform points with
// non-crossing Delaunay-edge chains: 10^6 points with 10^4 and 10^5 segments, and 10^5 points
// with 10^4 segments) and polygon/<points>/<vertices> (a star-shaped polygon of 10^5 vertices
// with 10^6 points in all, and 10^4 in 10^5). Conforming runs only with <= 10^5 points.
// Ours keeps the convex hull (remove_exterior = false), as CGAL does.
// CGAL is built by insert_constraints(points, index pairs): it copies the points, spatially
// sorts them (Hilbert), inserts them with the previous vertex as hint and then inserts every
// constraint between vertex handles; this is the fastest of CGAL's bulk APIs for points plus
// constraints (inserting the point range, then each constraint by its two points, locates
// both points again).
//
// Only the construction is timed; the result is destroyed with the timer paused. Counters
// (first timed run): peak_bytes (bench/heap_accounting.cpp, the rule of delaunay2d_bench), and for
// ours crossed_edges, recovery_flips, delaunay_flips, cavity_triangles, conforming_splits,
// triangles; triangles for CGAL too (a cross-check).
#define CGAL_NO_CDT_2_WARNING  // Epick with Exact_intersections_tag warns on every intersection
#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/heap_accounting.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

// The shared benchmark support: seeds, heap regime, heap accounting, main().
using namespace exactmesh::bench;

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

enum class Workload { Chains, Polygon };

/// The PSLG of one (workload, points, segments), made once.
const gen::PslgInput& input(Workload w, std::uint32_t points, std::uint32_t segments) {
    static std::map<std::tuple<int, std::uint32_t, std::uint32_t>, gen::PslgInput> cache;
    const auto key = std::make_tuple(static_cast<int>(w), points, segments);
    auto it = cache.find(key);
    if (it == cache.end()) {
        const auto d =
            w == Workload::Chains ? gen::PslgDistribution::Chains : gen::PslgDistribution::Polygon;
        it = cache.emplace(key, gen::generate_pslg(d, points, segments, kInputSeed)).first;
    }
    return it->second;
}

void BM_cdt_ours(benchmark::State& state, Workload w, tri::SegmentRecovery recovery) {
    const auto points = static_cast<std::uint32_t>(state.range(0));
    const auto segments = static_cast<std::uint32_t>(state.range(1));
    const gen::PslgInput& in = input(w, points, segments);
    const tri::Pslg pslg{in.xy, in.segments, {}, {}};
    tri::Cdt2Options options;
    options.recovery = recovery;
    options.remove_exterior = false;
    bool first = true;
    double peak = 0;
    tri::Cdt2Counters counters;
    double triangles = 0;
    for (auto _ : state) {
        const std::size_t before = first ? start_heap_measurement() : 0;
        auto result = tri::constrained_delaunay_2d(pslg, options);
        if (first) {
            peak = heap_growth_since(before);
            counters = result.counters;
            triangles = result.mesh.triangle_count();
            first = false;
        }
        state.PauseTiming();
        { auto drop = std::move(result); }
        state.ResumeTiming();
    }
    state.counters["peak_bytes"] = peak;
    state.counters["segments"] = static_cast<double>(in.segments.size() / 2);
    state.counters["triangles"] = triangles;
    state.counters["crossed_edges"] = static_cast<double>(counters.crossed_edges);
    state.counters["recovery_flips"] = static_cast<double>(counters.recovery_flips);
    state.counters["delaunay_flips"] = static_cast<double>(counters.delaunay_flips);
    state.counters["cavity_triangles"] = static_cast<double>(counters.cavity_triangles);
    state.counters["conforming_splits"] = static_cast<double>(counters.conforming_splits);
    state.counters["incircle_calls"] = static_cast<double>(counters.incircle_calls);
    state.counters["orient_calls"] = static_cast<double>(counters.orient_calls);
}

#if defined(EXACTMESH_WITH_CGAL)
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalCdt =
    CGAL::Constrained_Delaunay_triangulation_2<Epick, CGAL::Default, CGAL::Exact_intersections_tag>;

void BM_cdt_cgal(benchmark::State& state, Workload w) {
    const auto points = static_cast<std::uint32_t>(state.range(0));
    const auto segments = static_cast<std::uint32_t>(state.range(1));
    const gen::PslgInput& in = input(w, points, segments);
    std::vector<Epick::Point_2> cgal_points;
    for (std::size_t i = 0; i < in.xy.size(); i += 2)
        cgal_points.emplace_back(in.xy[i], in.xy[i + 1]);
    std::vector<std::pair<std::size_t, std::size_t>> constraints;
    for (std::size_t s = 0; s < in.segments.size(); s += 2)
        constraints.emplace_back(in.segments[s], in.segments[s + 1]);
    bool first = true;
    double peak = 0, triangles = 0;
    for (auto _ : state) {
        const std::size_t before = first ? start_heap_measurement() : 0;
        auto cdt = std::make_unique<CgalCdt>();
        cdt->insert_constraints(cgal_points.begin(), cgal_points.end(), constraints.begin(),
                                constraints.end());
        if (first) {
            peak = heap_growth_since(before);
            triangles = static_cast<double>(cdt->number_of_faces());
            first = false;
        }
        state.PauseTiming();
        cdt.reset();
        state.ResumeTiming();
    }
    state.counters["peak_bytes"] = peak;
    state.counters["segments"] = static_cast<double>(in.segments.size() / 2);
    state.counters["triangles"] = triangles;
}
#endif

void register_all() {
    struct Size {
        Workload workload;
        const char* name;
        std::int64_t points, segments;
    };
    const Size sizes[] = {{Workload::Chains, "chains", 100000, 10000},
                          {Workload::Chains, "chains", 1000000, 10000},
                          {Workload::Chains, "chains", 1000000, 100000},
                          {Workload::Polygon, "polygon", 100000, 10000},
                          {Workload::Polygon, "polygon", 1000000, 100000}};
    for (const Size& s : sizes) {
        const std::string suffix = std::string("/") + s.name;
        benchmark::RegisterBenchmark(("BM_cdt_swap" + suffix).c_str(), BM_cdt_ours, s.workload,
                                     tri::SegmentRecovery::Swap)
            ->Args({s.points, s.segments})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        benchmark::RegisterBenchmark(("BM_cdt_cavity" + suffix).c_str(), BM_cdt_ours, s.workload,
                                     tri::SegmentRecovery::Cavity)
            ->Args({s.points, s.segments})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        if (s.points <= 100000) {
            benchmark::RegisterBenchmark(("BM_cdt_conforming" + suffix).c_str(), BM_cdt_ours,
                                         s.workload, tri::SegmentRecovery::Conforming)
                ->Args({s.points, s.segments})
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
#if defined(EXACTMESH_WITH_CGAL)
        benchmark::RegisterBenchmark(("BM_cdt_cgal" + suffix).c_str(), BM_cdt_cgal, s.workload)
            ->Args({s.points, s.segments})
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
#endif
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    exactmesh::bench::add_peak_memory_context();
    exactmesh::bench::add_cgal_context();
    return exactmesh::bench::run_benchmarks(argc, argv);
}
