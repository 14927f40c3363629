// SPDX-License-Identifier: MIT
// 3D Delaunay construction benchmarks: Bowyer-Watson and Green-Sibson (BRIO order) against
// CGAL's Delaunay_triangulation_3<Epick> built from a range (sequential; CGAL spatially sorts
// the points itself), same points, same run [Watson81, Joe91; DESIGN.md "Benchmarks"].
//
// Names: BM_<algo>/<distribution>/<n>, algo in {bowyer_watson, green_sibson, cgal} (one
// thread), distribution in {uniform, gaussian}, n = 10^3, 3·10^3, ..., up to
// EXACTMESH_BENCH3_MAX_POINTS (default 10^6, at most 10^7). Each family is fitted with
// Complexity(oNLogN).
// Strong scaling (issue 17): BM_bowyer_watson_<T>_threads/<distribution>/<n>/real_time
// (options.threads = T; T = 1 runs the sequential code, T > 1 parallel_bowyer_watson_3d) and
// BM_cgal_parallel_<T>_threads/<distribution>/<n>/real_time (CGAL's Parallel_tag triangulation
// with its lock grid, run in a oneTBB arena of T threads; built when CGAL sees TBB), for T = 1 ..
// EXACTMESH_BENCH_MAX_THREADS (default std::thread::hardware_concurrency()), n in {10^5, 10^6,
// 10^7} up to EXACTMESH_BENCH3_MAX_POINTS (so 10^7 only when it is set to 10000000). They are
// timed in real (wall-clock) time: the CPU column adds up every thread's time.
// The memory floor (issue 17): BM_memory_floor_<memory>/<distribution>/<n>/real_time at the same
// sizes, memory in {warm, fresh, fresh_huge_pages}: one pass that reads the points in BRIO order
// and writes what the result holds (bench/memory_floor.hpp), the floor under any construction of
// that result on this machine, with its memory warm, first touched, or first touched on 2 MiB
// pages.
// scripts/delaunay3d_report.py turns them into the strong-scaling table and plots.
//
// Only the construction is timed: inputs are generated once per (distribution, n) with a pinned
// seed, CGAL's points are converted once, and the result is destroyed with the timer paused (the
// same for both). Inputs are made on first use, so a filtered run makes only its own. Counters,
// from the first timed construction of each benchmark: walk_steps/pt, insphere_calls/pt,
// orient_calls/pt, cavity/pt, flips/pt (ours), tets/pt (both: a cross-check), peak_bytes and
// peak_bytes/pt (both: peak live heap during the construction, with the result alive at the end;
// bench/heap_accounting.cpp).
//
// The heap is kept warm (malloc never returns memory to the kernel), as in delaunay2d_bench,
// unless EXACTMESH_BENCH_COLD_HEAP=1. On a shared machine compare the CPU column of the one-thread
// rows: it counts only this process's time. The ratios reported in the README (uniform and
// Gaussian, 10^6 points) come from
//   delaunay3d_bench --benchmark_filter='(bowyer_watson|cgal)/(uniform|gaussian)/1000000$'
//                    --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true
//                    --benchmark_report_aggregates_only=true
// and the multicore ones (issue 17) from
//   delaunay3d_bench --benchmark_filter='(bowyer_watson|cgal).*/uniform/1000000($|/)'
//                    --benchmark_repetitions=5 --benchmark_enable_random_interleaving=true
// with the real-time column (the README's command; scripts/run runs every algorithm and size
// with the same repetitions and interleaving, keeping the individual repetitions for its report).
// The 10^7-point run with peak memory (ours on 1 and 2 threads, one construction each; about
// 3 GB of heap and 30-60 s each on the reference machine):
//   EXACTMESH_BENCH3_MAX_POINTS=10000000 delaunay3d_bench
//       --benchmark_filter='BM_bowyer_watson_[12]_threads/uniform/10000000/'
//       --benchmark_out=bench3_1e7.json --benchmark_out_format=json
// (add cgal_parallel to the filter, '(bowyer_watson|cgal_parallel)_[12]_threads/...', for CGAL's).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/heap_accounting.hpp"
#include "bench/memory_floor.hpp"
#include "generators/inputs/inputs_3d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#if defined(CGAL_LINKED_WITH_TBB)
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <tbb/task_arena.h>
#endif
#endif

namespace {

// The shared benchmark support: seeds, heap regime, heap accounting, main().
using namespace exactmesh::bench;

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using gen::Distribution3;

/// EXACTMESH_BENCH3_MAX_POINTS (default 10^6), clamped to [10^3, 10^7].
std::int64_t max_points() {
    static const std::int64_t value = [] {
        std::int64_t points = 1000000;
        if (const char* text = std::getenv("EXACTMESH_BENCH3_MAX_POINTS")) {
            points = std::clamp<std::int64_t>(std::atoll(text), 1000, 10000000);
        }
        return points;
    }();
    return value;
}

/// 10^3, 3·10^3, 10^4, ... up to max_points().
std::vector<std::int64_t> sizes() {
    std::vector<std::int64_t> out;
    for (std::int64_t n = 1000; n <= max_points(); n *= 10) {
        out.push_back(n);
        if (3 * n <= max_points()) out.push_back(3 * n);
    }
    return out;
}

struct Input {
    std::vector<double> xyz;
    std::vector<std::uint32_t> order;  ///< the BRIO insertion order (memory floor rows)
    std::size_t tets = 0;              ///< tetrahedra of their Delaunay tetrahedralization
#if defined(EXACTMESH_WITH_CGAL)
    std::vector<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> points;
#endif
};

/// Cached per (distribution, n); one distribution at a time.
Input& input_for(Distribution3 distribution, std::uint32_t n) {
    static std::map<std::pair<Distribution3, std::uint32_t>, std::unique_ptr<Input>> cache;
    const auto key = std::pair{distribution, n};
    if (auto found = cache.find(key); found != cache.end()) return *found->second;
    if (!cache.empty() && cache.begin()->first.first != distribution) cache.clear();
    auto input = std::make_unique<Input>();
    input->xyz = gen::generate_points_3d(distribution, n, kInputSeed);
    return *cache.emplace(key, std::move(input)).first->second;
}

struct Measurement {
    bool done = false;
    double peak_bytes = 0;
    double tets = 0;
    bool has_counters = false;
    tri::Delaunay3Counters counters;
};

Measurement& measurement_for(const std::string& algorithm, Distribution3 distribution,
                             std::uint32_t n) {
    static std::map<std::tuple<std::string, Distribution3, std::uint32_t>, Measurement> table;
    return table[{algorithm, distribution, n}];
}

void set_counters(benchmark::State& state, const Measurement& m, std::uint32_t n) {
    const double points = static_cast<double>(n);
    auto per_point = [points](std::uint64_t count) { return static_cast<double>(count) / points; };
    if (m.has_counters) {
        const tri::Delaunay3Counters& c = m.counters;
        state.counters["walk_steps/pt"] = per_point(c.walk_steps);
        state.counters["insphere_calls/pt"] = per_point(c.insphere_calls);
        state.counters["orient_calls/pt"] = per_point(c.orient_calls);
        state.counters["cavity/pt"] = per_point(c.cavity_tets);
        state.counters["flips/pt"] = per_point(c.flips_2_3 + c.flips_3_2 + c.flips_4_4);
    }
    state.counters["tets/pt"] = m.tets / points;
    state.counters["peak_bytes"] = m.peak_bytes;
    state.counters["peak_bytes/pt"] = m.peak_bytes / points;
    state.SetComplexityN(static_cast<std::int64_t>(n));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

void bm_exactmesh(benchmark::State& state, const std::string& algorithm, Distribution3 distribution,
                  unsigned threads) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const tri::Delaunay3Function construct = tri::delaunay_3d_algorithm(algorithm);
    const Input& input = input_for(distribution, n);
    tri::Delaunay3Options options{tri::InsertionOrder::Brio, kOrderSeed};
    options.threads = threads;
    Measurement& m = measurement_for(algorithm + std::to_string(threads), distribution, n);
    for (auto _ : state) {
        const bool measure = !m.done;
        const std::size_t heap_before = measure ? start_heap_measurement() : 0;
        {
            tri::Delaunay3Result result = construct(input.xyz, options);
            benchmark::DoNotOptimize(result.mesh.tets.data());
            benchmark::ClobberMemory();
            state.PauseTiming();  // the destructor runs paused
            if (measure) {
                m.peak_bytes = heap_growth_since(heap_before);
                m.counters = result.counters;
                m.has_counters = true;
                m.tets = static_cast<double>(result.mesh.tet_count());
                m.done = true;
            }
        }
        after_construction();
        state.ResumeTiming();
    }
    set_counters(state, m, n);
}

/// The memory floor of the construction of these points (bench/memory_floor.hpp): their BRIO
/// order and their tetrahedra (one untimed construction, made on first use) set its pass.
void bm_memory_floor(benchmark::State& state, Distribution3 distribution, FloorMemory memory) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    Input& input = input_for(distribution, n);
    if (input.order.empty()) {
        input.order = tri::insertion_order_3d(input.xyz, tri::InsertionOrder::Brio, kOrderSeed);
        const tri::Delaunay3Options options{tri::InsertionOrder::Brio, kOrderSeed};
        input.tets =
            tri::delaunay_3d_algorithm("bowyer-watson")(input.xyz, options).mesh.tet_count();
    }
    run_memory_floor<3, 4>(state, input.xyz, input.order, input.tets, true, memory);
    state.counters["tets/pt"] = static_cast<double>(input.tets) / n;
}

#if defined(EXACTMESH_WITH_CGAL)
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<Epick>;

/// input_for with CGAL's copy of the points, converted once.
const Input& input_with_cgal_points(Distribution3 distribution, std::uint32_t n) {
    Input& input = input_for(distribution, n);
    if (input.points.empty()) {
        for (std::uint32_t i = 0; i < n; ++i) {
            input.points.emplace_back(input.xyz[3 * std::size_t{i}],
                                      input.xyz[3 * std::size_t{i} + 1],
                                      input.xyz[3 * std::size_t{i} + 2]);
        }
    }
    return input;
}

/// After a timed CGAL construction `dt`, still alive: pauses the timer (the destructor runs
/// paused) and, on the first construction of `m`, records its peak heap and tetrahedra.
template <class Triangulation>
void record_cgal(benchmark::State& state, Measurement& m, const Triangulation& dt, bool measure,
                 std::size_t heap_before) {
    benchmark::DoNotOptimize(dt.number_of_cells());
    benchmark::ClobberMemory();
    state.PauseTiming();
    if (measure) {
        m.peak_bytes = heap_growth_since(heap_before);
        m.tets = static_cast<double>(dt.number_of_finite_cells());
        m.done = true;
    }
}

void bm_cgal(benchmark::State& state, Distribution3 distribution) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const Input& input = input_with_cgal_points(distribution, n);
    Measurement& m = measurement_for("cgal", distribution, n);
    for (auto _ : state) {
        const bool measure = !m.done;
        const std::size_t heap_before = measure ? start_heap_measurement() : 0;
        {
            const CgalDelaunay dt(input.points.begin(), input.points.end());
            record_cgal(state, m, dt, measure, heap_before);
        }
        after_construction();
        state.ResumeTiming();
    }
    set_counters(state, m, n);
}

#if defined(CGAL_LINKED_WITH_TBB)
using CgalParallelDelaunay = CGAL::Delaunay_triangulation_3<
    Epick, CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<Epick>,
                                                CGAL::Delaunay_triangulation_cell_base_3<Epick>,
                                                CGAL::Parallel_tag>>;

/// CGAL's parallel insertion (a grid of locks over the bounding box, 50 cells per axis as in
/// CGAL's examples) on `threads` threads of a oneTBB arena.
void bm_cgal_parallel(benchmark::State& state, Distribution3 distribution, int threads) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const Input& input = input_with_cgal_points(distribution, n);
    const CGAL::Bbox_3 box = CGAL::bbox_3(input.points.begin(), input.points.end());
    Measurement& m = measurement_for("cgal_parallel" + std::to_string(threads), distribution, n);
    tbb::task_arena arena(threads);
    for (auto _ : state) {
        const bool measure = !m.done;
        const std::size_t heap_before = measure ? start_heap_measurement() : 0;
        arena.execute([&] {
            CgalParallelDelaunay::Lock_data_structure locks(box, 50);
            const CgalParallelDelaunay dt(input.points.begin(), input.points.end(), &locks);
            record_cgal(state, m, dt, measure, heap_before);
        });
        after_construction();
        state.ResumeTiming();
    }
    set_counters(state, m, n);
}
#endif
#endif

void register_all() {
    const std::vector<std::int64_t> ns = sizes();
    auto apply = [&ns](benchmark::internal::Benchmark* b) {
        for (const std::int64_t n : ns) b->Arg(n);
        b->Complexity(benchmark::oNLogN)->Unit(benchmark::kMillisecond);
    };
    // The strong-scaling rows: the scaling sizes only, wall-clock time, no complexity fit (two or
    // three sizes).
    const std::vector<std::int64_t> scaling_ns = scaling_sizes(max_points());
    auto apply_scaling = [&scaling_ns](benchmark::internal::Benchmark* b) {
        for (const std::int64_t n : scaling_ns) b->Arg(n);
        b->UseRealTime()->Unit(benchmark::kMillisecond);
    };
    const unsigned max_threads = max_bench_threads();
    for (const Distribution3 distribution : {Distribution3::Uniform, Distribution3::Gaussian}) {
        const std::string points(gen::distribution_name(distribution));
        for (const char* algorithm : {"bowyer-watson", "green-sibson"}) {
            std::string label = algorithm;
            std::replace(label.begin(), label.end(), '-', '_');
            apply(benchmark::RegisterBenchmark(("BM_" + label + "/" + points).c_str(),
                                               &bm_exactmesh, std::string(algorithm), distribution,
                                               1u));
        }
#if defined(EXACTMESH_WITH_CGAL)
        apply(benchmark::RegisterBenchmark(("BM_cgal/" + points).c_str(), &bm_cgal, distribution));
#endif
        if (scaling_ns.empty()) continue;
        for_each_memory_floor_row(points, [&](const std::string& name, FloorMemory memory) {
            apply_scaling(
                benchmark::RegisterBenchmark(name.c_str(), &bm_memory_floor, distribution, memory));
        });
        for (unsigned threads = 1; threads <= max_threads; ++threads) {
            // Appended rather than "_" + to_string(...): GCC 12 -O3 warns (-Wrestrict, a false
            // positive) on operator+ of a literal and a temporary string.
            std::string suffix = "_";
            suffix += std::to_string(threads) + "_threads/" + points;
            apply_scaling(benchmark::RegisterBenchmark(("BM_bowyer_watson" + suffix).c_str(),
                                                       &bm_exactmesh, std::string("bowyer-watson"),
                                                       distribution, threads));
#if defined(EXACTMESH_WITH_CGAL) && defined(CGAL_LINKED_WITH_TBB)
            apply_scaling(benchmark::RegisterBenchmark(("BM_cgal_parallel" + suffix).c_str(),
                                                       &bm_cgal_parallel, distribution,
                                                       static_cast<int>(threads)));
#endif
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    exactmesh::bench::set_heap_regime();
    register_all();
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    benchmark::AddCustomContext("exactmesh_heap", cold_heap() ? "cold" : "warm");
    benchmark::AddCustomContext("exactmesh_input_seed", std::to_string(kInputSeed));
    exactmesh::bench::add_peak_memory_context();
    exactmesh::bench::add_cgal_context();
    exactmesh::bench::add_threads_context();
    benchmark::AddCustomContext("exactmesh_max_points", std::to_string(max_points()));
    return exactmesh::bench::run_benchmarks_with_default_min_time(argc, argv);
}
