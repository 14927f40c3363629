// SPDX-License-Identifier: MIT
// 2D Delaunay construction benchmarks: Bowyer-Watson, Green-Sibson (insert + Lawson flips) and
// Tanemura-Merriam (gift-wrapping) against CGAL's Delaunay_triangulation_2<Epick>, same points,
// same run [Watson81, GreenSibson78, Merriam92; DESIGN.md "Benchmarks and reports"].
//
// Names: BM_<algo>/<distribution>/<order>/<n>, algo in {bowyer_watson, green_sibson,
// tanemura_merriam, cgal}, distribution in {uniform, gaussian}, order in {brio, random} (none for
// tanemura_merriam, which orders nothing; brio for cgal, whose range constructor spatially sorts
// the points itself), n = 2^10 ... 2^EXACTMESH_BENCH_MAX_LOG2 (default 20, at most 22; the
// random order up to 2^EXACTMESH_BENCH_RANDOM_MAX_LOG2, by default the same: see
// random_max_log2_points). Each (algo, distribution, order) family is fitted with
// Complexity(oNLogN). The adversary, n = 2^8 ... 2^14: BM_bowyer_watson/parabola/given/<n>
// inserts points (t, t^2) sorted by decreasing t as given (Theta(n^2), oNSquared), against
// BM_bowyer_watson/parabola/random/<n>, the same points shuffled (oN), and
// BM_bowyer_watson/parabola/ascending/<n>, by increasing t as generate_points_2d lists them
// (oN; see PointOrder for why that order is not the adversary).
//
// Only the construction is timed: inputs are generated once per (distribution, n) with a pinned
// seed and cached, CGAL's points are converted once, and the triangulation is destroyed with the
// timer paused (the same for ours and CGAL's; a pause costs about a microsecond, under 1% even at
// n = 2^10). The heap is kept warm unless EXACTMESH_BENCH_COLD_HEAP=1 (see cold_heap). Counters,
// recorded by the first timed construction of each benchmark: walk_steps/pt, incircle_calls/pt,
// orient_calls/pt, flips/pt, cavity/pt, candidates/pt (ours only), triangles/pt (both: a
// cross-check), peak_bytes and peak_bytes/pt (both; see bench/heap_accounting.cpp).
// scripts/delaunay_report.py turns the JSON into report/delaunay2d.md and plots.
//
// Strong scaling (issue 17): BM_bowyer_watson_<T>_threads/<distribution>/brio/<n>/real_time
// (options.threads = T; T = 1 runs the sequential code, T > 1 parallel_bowyer_watson_2d) for T = 1
// .. EXACTMESH_BENCH_MAX_THREADS (default std::thread::hardware_concurrency()), beside
// BM_cgal_1_threads/<distribution>/brio/<n>/real_time, CGAL's sequential construction at the same
// sizes (CGAL has no parallel 2D triangulation), n in {10^5, 10^6, 10^7} up to
// EXACTMESH_BENCH_SCALING_MAX_POINTS (default 2^EXACTMESH_BENCH_MAX_LOG2: 10^5 and 10^6 at the
// default 2^20; 10000000 adds the 10^7 row). Timed in real (wall-clock) time, since the CPU
// column adds up every thread's time. For example
//   EXACTMESH_BENCH_SCALING_MAX_POINTS=10000000 delaunay2d_bench
//       --benchmark_filter='_threads/uniform/brio/10000000/' --benchmark_repetitions=3
//
// The memory floor (issue 17), at the strong-scaling sizes:
// BM_memory_floor_<memory>/<distribution>/brio/<n>/real_time, memory in {warm, fresh,
// fresh_huge_pages}: one pass that reads the points in BRIO order and writes what the result
// holds (bench/memory_floor.hpp), the floor under any construction of that result on this
// machine; delaunay_report.py leaves them out of its tables.
//
// The insertion order alone: BM_insertion_order/uniform/hilbert_keys/1000000/real_time (the
// keys) and BM_insertion_order/uniform/brio_<T>_threads/1000000/real_time (the BRIO order on
// T = 1, 2 threads); delaunay_report.py leaves them out of its tables.
//
// Helper mode (no benchmark runs): `delaunay2d_bench --write_node=<distribution>,<n>,<path>`
// writes generate_points_2d(distribution, n, kInputSeed) as a Triangle .node file, which the
// report pictures with `exactmesh triangulate <path> -o picture.svg`.
#include <benchmark/benchmark.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/heap_accounting.hpp"
#include "bench/memory_floor.hpp"
#include "generators/inputs/inputs.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

// The shared benchmark support: seeds, heap regime, heap accounting, main().
using namespace exactmesh::bench;

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using gen::Distribution;

int log2_from_environment(const char* variable, int fallback, int lo, int hi) {
    int log2_points = fallback;
    if (const char* text = std::getenv(variable)) log2_points = std::atoi(text);
    return std::clamp(log2_points, lo, hi);
}

/// 2^10 ... 2^max points: EXACTMESH_BENCH_MAX_LOG2 (default 20), clamped to [10, 22].
int max_log2_points() {
    static const int value = log2_from_environment("EXACTMESH_BENCH_MAX_LOG2", 20, 10, 22);
    return value;
}

/// The strong-scaling rows' sizes stop at EXACTMESH_BENCH_SCALING_MAX_POINTS (default
/// 2^max_log2_points(), clamped to [0, 10^7]).
std::int64_t scaling_max_points() {
    static const std::int64_t value = [] {
        std::int64_t points = std::int64_t{1} << max_log2_points();
        if (const char* text = std::getenv("EXACTMESH_BENCH_SCALING_MAX_POINTS")) {
            points = std::atoll(text);
        }
        return std::clamp<std::int64_t>(points, 0, 10000000);
    }();
    return value;
}

/// The random insertion order may stop earlier: EXACTMESH_BENCH_RANDOM_MAX_LOG2 (default and
/// at most max_log2_points()). With the grid jump-and-walk location (PointLocation::Auto picks
/// it for the random order) a random order walks O(1) triangles per point, so it runs to the
/// largest size too; with the plain walk from the last insertion it cost ~sqrt(n) steps per
/// point, Theta(n^1.5), about 35 s per construction at 2^20, and stopped at 2^16.
int random_max_log2_points() {
    static const int value = std::min(
        log2_from_environment("EXACTMESH_BENCH_RANDOM_MAX_LOG2", max_log2_points(), 10, 22),
        max_log2_points());
    return value;
}

std::string points_name(Distribution distribution) {
    return std::string(gen::distribution_name(distribution));
}

/// How the generated points are listed. Reversed exists for the parabola: generate_points_2d
/// lists it by increasing t >= 0, and in that order each new point lies outside every
/// circumcircle (the fourth intersection of a circle through (a, a^2), (b, b^2), (c, c^2) with
/// the parabola is at t = -(a + b + c) < 0, so the circle holds only t in (b, c) beyond a), so
/// Bowyer-Watson's cavity is one hull triangle per point: linear. Listed by decreasing t, each
/// new point lies in every circumcircle, (-(a + b + c), a) containing it: the cavity is the
/// whole triangulation, Theta(n^2) in all, the classic adversary.
enum class PointOrder { AsGenerated, Reversed };

#if defined(EXACTMESH_WITH_CGAL)
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Epick>;
using CgalPoint = Epick::Point_2;
#endif

/// The points of one (distribution, n), and the same points as CGAL's (made on first use).
struct Input {
    std::vector<double> xy;
    std::vector<std::uint32_t> order;  ///< the BRIO insertion order (memory floor rows)
    std::size_t triangles = 0;         ///< triangles of their Delaunay triangulation
#if defined(EXACTMESH_WITH_CGAL)
    std::vector<CgalPoint> points;
#endif
};

/// Cached per (distribution, point order, n). Benchmarks are registered distribution by
/// distribution, so the cache keeps one distribution only: at 2^22 points the sizes of one
/// distribution take ~260 MB with their CGAL copies.
Input& input_for(Distribution distribution, PointOrder point_order, std::uint32_t n) {
    using Key = std::tuple<Distribution, PointOrder, std::uint32_t>;
    static std::map<Key, std::unique_ptr<Input>> cache;
    const Key key{distribution, point_order, n};
    if (auto found = cache.find(key); found != cache.end()) return *found->second;
    if (!cache.empty() && std::get<0>(cache.begin()->first) != distribution) cache.clear();
    auto input = std::make_unique<Input>();
    input->xy = gen::generate_points_2d(distribution, n, kInputSeed);
    if (point_order == PointOrder::Reversed) {
        for (std::size_t i = 0, j = n == 0 ? 0 : n - 1; i < j; ++i, --j) {
            std::swap(input->xy[2 * i], input->xy[2 * j]);
            std::swap(input->xy[2 * i + 1], input->xy[2 * j + 1]);
        }
    }
    return *cache.emplace(key, std::move(input)).first->second;
}

#if defined(EXACTMESH_WITH_CGAL)
const std::vector<CgalPoint>& cgal_points_for(Distribution distribution, std::uint32_t n) {
    Input& input = input_for(distribution, PointOrder::AsGenerated, n);
    if (input.points.empty()) {
        input.points.reserve(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            input.points.emplace_back(input.xy[2 * std::size_t{i}],
                                      input.xy[2 * std::size_t{i} + 1]);
        }
    }
    return input.points;
}
#endif

/// What one construction measured: the first timed iteration of each benchmark instance records
/// it (the heap bookkeeping runs anyway; reading it costs two atomic accesses), and the later
/// iterations and repetitions reuse it, since the constructions are deterministic.
struct Measurement {
    bool done = false;
    double peak_bytes = 0;
    double triangles = 0;
    bool has_counters = false;
    tri::Delaunay2Counters counters;
};

using MeasurementKey = std::tuple<std::string, std::string, std::string, std::uint32_t>;

Measurement& measurement_for(const std::string& algorithm, const std::string& points,
                             const std::string& order, std::uint32_t n) {
    static std::map<MeasurementKey, Measurement> table;
    return table[MeasurementKey{algorithm, points, order, n}];
}

void set_counters(benchmark::State& state, const Measurement& m, std::uint32_t n) {
    const double points = static_cast<double>(n);
    auto per_point = [points](std::uint64_t count) { return static_cast<double>(count) / points; };
    if (m.has_counters) {
        const tri::Delaunay2Counters& c = m.counters;
        state.counters["walk_steps/pt"] = per_point(c.walk_steps);
        state.counters["incircle_calls/pt"] = per_point(c.incircle_calls);
        state.counters["orient_calls/pt"] = per_point(c.orient_calls);
        state.counters["flips/pt"] = per_point(c.flips);
        state.counters["cavity/pt"] = per_point(c.cavity_triangles);
        state.counters["candidates/pt"] = per_point(c.candidates);
        state.counters["duplicates"] = static_cast<double>(c.duplicates);
    }
    state.counters["triangles/pt"] = m.triangles / points;
    state.counters["peak_bytes"] = m.peak_bytes;
    state.counters["peak_bytes/pt"] = m.peak_bytes / points;
    state.SetComplexityN(static_cast<std::int64_t>(n));
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}

/// One family of our benchmarks: an algorithm by its registry name ("bowyer-watson", ...), its
/// points, and the insertion order passed to it (`order_label` names it in the benchmark).
struct Family {
    std::string algorithm;
    Distribution distribution;
    tri::InsertionOrder order;
    std::string order_label;
    PointOrder point_order = PointOrder::AsGenerated;
    unsigned threads = 1;  ///< options.threads (bowyer-watson with brio runs in parallel above 1)
};

void bm_exactmesh(benchmark::State& state, const Family& family) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const tri::Delaunay2Function construct = tri::delaunay_2d_algorithm(family.algorithm);
    const Input& input = input_for(family.distribution, family.point_order, n);
    tri::Delaunay2Options options{family.order, kOrderSeed};
    options.threads = family.threads;
    Measurement& m = measurement_for(family.algorithm + std::to_string(family.threads),
                                     points_name(family.distribution), family.order_label, n);

    for (auto _ : state) {
        const bool measure = !m.done;
        const std::size_t heap_before = measure ? start_heap_measurement() : 0;
        {
            tri::Delaunay2Result result = construct(input.xy, options);
            benchmark::DoNotOptimize(result.triangles.data());
            benchmark::ClobberMemory();
            state.PauseTiming();  // the destructor runs paused
            if (measure) {
                m.peak_bytes = heap_growth_since(heap_before);
                m.counters = result.counters;
                m.has_counters = true;
                m.triangles = static_cast<double>(result.triangles.size() / 3);
                m.done = true;
            }
        }
        after_construction();
        state.ResumeTiming();
    }
    set_counters(state, m, n);
}

#if defined(EXACTMESH_WITH_CGAL)
/// CGAL's range constructor: copies the points, spatially sorts them (Hilbert, BRIO-like
/// rounds) and inserts each from the previous one's face.
void bm_cgal(benchmark::State& state, Distribution distribution) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const std::vector<CgalPoint>& points = cgal_points_for(distribution, n);
    Measurement& m = measurement_for("cgal", points_name(distribution), "brio", n);

    for (auto _ : state) {
        const bool measure = !m.done;
        const std::size_t heap_before = measure ? start_heap_measurement() : 0;
        {
            CgalDelaunay dt(points.begin(), points.end());
            benchmark::DoNotOptimize(dt.number_of_faces());
            benchmark::ClobberMemory();
            state.PauseTiming();  // the destructor runs paused
            if (measure) {
                m.peak_bytes = heap_growth_since(heap_before);
                m.triangles = static_cast<double>(dt.number_of_faces());
                m.done = true;
            }
        }
        after_construction();
        state.ResumeTiming();
    }
    set_counters(state, m, n);
}
#endif

/// The memory floor of the construction of these points (bench/memory_floor.hpp): their BRIO
/// order and their triangles (one untimed construction, made on first use) set its pass.
void bm_memory_floor(benchmark::State& state, Distribution distribution, FloorMemory memory) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    Input& input = input_for(distribution, PointOrder::AsGenerated, n);
    if (input.order.empty()) {
        input.order = tri::insertion_order_2d(input.xy, tri::InsertionOrder::Brio, kOrderSeed);
        const tri::Delaunay2Options options{tri::InsertionOrder::Brio, kOrderSeed};
        input.triangles =
            tri::delaunay_2d_algorithm("bowyer-watson")(input.xy, options).triangles.size() / 3;
    }
    run_memory_floor<2, 3>(state, input.xy, input.order, input.triangles, false, memory);
    state.counters["triangles/pt"] = static_cast<double>(input.triangles) / n;
}

/// The insertion order alone (issue 17: the order phase of `--stats`): the Hilbert keys of the
/// points, and the whole BRIO order (keys, shuffle, rounds) on `threads` threads of an arena.
void bm_hilbert_keys(benchmark::State& state, Distribution distribution) {
    const std::vector<double>& xy =
        input_for(distribution, PointOrder::AsGenerated, static_cast<std::uint32_t>(state.range(0)))
            .xy;
    for (auto _ : state) benchmark::DoNotOptimize(tri::hilbert_keys_2d(xy));
}

void bm_brio_order(benchmark::State& state, Distribution distribution, unsigned threads) {
    const std::vector<double>& xy =
        input_for(distribution, PointOrder::AsGenerated, static_cast<std::uint32_t>(state.range(0)))
            .xy;
    tbb::task_arena arena(static_cast<int>(threads));
    for (auto _ : state) {
        arena.execute([&] {
            benchmark::DoNotOptimize(
                tri::insertion_order_2d(xy, tri::InsertionOrder::Brio, 1, threads > 1));
        });
    }
}

std::string algorithm_label(const std::string& registry_name) {
    std::string label = registry_name;
    std::replace(label.begin(), label.end(), '-', '_');
    return label;
}

void register_family(const Family& family, int min_log2, int max_log2, benchmark::BigO complexity) {
    const std::string name = "BM_" + algorithm_label(family.algorithm) + "/" +
                             points_name(family.distribution) + "/" + family.order_label;
    benchmark::RegisterBenchmark(name.c_str(), &bm_exactmesh, family)
        ->RangeMultiplier(2)
        ->Range(std::int64_t{1} << min_log2, std::int64_t{1} << max_log2)
        ->Complexity(complexity)
        ->Unit(benchmark::kMillisecond);
}

/// The strong-scaling rows of one distribution (see the header): ours on 1 .. max threads and
/// CGAL's sequential construction, at the scaling sizes, in wall-clock time.
void register_scaling(Distribution distribution) {
    const std::vector<std::int64_t> ns = scaling_sizes(scaling_max_points());
    if (ns.empty()) return;
    auto apply = [&ns](benchmark::internal::Benchmark* b) {
        for (const std::int64_t n : ns) b->Arg(n);
        b->UseRealTime()->Unit(benchmark::kMillisecond);
    };
    const std::string points = points_name(distribution) + "/brio";
    for (unsigned threads = 1; threads <= max_bench_threads(); ++threads) {
        Family family{"bowyer-watson", distribution, tri::InsertionOrder::Brio, "brio"};
        family.threads = threads;
        const std::string name =
            "BM_bowyer_watson_" + std::to_string(threads) + "_threads/" + points;
        apply(benchmark::RegisterBenchmark(name.c_str(), &bm_exactmesh, family));
    }
#if defined(EXACTMESH_WITH_CGAL)
    apply(benchmark::RegisterBenchmark(("BM_cgal_1_threads/" + points).c_str(), &bm_cgal,
                                       distribution));
#endif
    for_each_memory_floor_row(points, [&](const std::string& name, FloorMemory memory) {
        apply(benchmark::RegisterBenchmark(name.c_str(), &bm_memory_floor, distribution, memory));
    });
}

void register_all() {
    using tri::InsertionOrder;
    const int max_log2 = max_log2_points();
    for (const Distribution distribution : {Distribution::Uniform, Distribution::Gaussian}) {
        register_scaling(distribution);
        for (const char* algorithm : {"bowyer-watson", "green-sibson"}) {
            register_family({algorithm, distribution, InsertionOrder::Brio, "brio"}, 10, max_log2,
                            benchmark::oNLogN);
            register_family({algorithm, distribution, InsertionOrder::Random, "random"}, 10,
                            random_max_log2_points(), benchmark::oNLogN);
        }
        register_family({"tanemura-merriam", distribution, InsertionOrder::Given, "none"}, 10,
                        max_log2, benchmark::oNLogN);
#if defined(EXACTMESH_WITH_CGAL)
        const std::string name = "BM_cgal/" + points_name(distribution) + "/brio";
        benchmark::RegisterBenchmark(name.c_str(), &bm_cgal, distribution)
            ->RangeMultiplier(2)
            ->Range(std::int64_t{1} << 10, std::int64_t{1} << max_log2)
            ->Complexity(benchmark::oNLogN)
            ->Unit(benchmark::kMillisecond);
#endif
    }
    // The insertion order alone, at 10^6 uniform points (BM_insertion_order/...).
    benchmark::RegisterBenchmark("BM_insertion_order/uniform/hilbert_keys", &bm_hilbert_keys,
                                 Distribution::Uniform)
        ->Arg(1000000)
        ->UseRealTime()  // the /real_time suffix keeps these rows out of the report's families
        ->Unit(benchmark::kMillisecond);
    for (const unsigned threads : {1u, 2u}) {
        const std::string name =
            "BM_insertion_order/uniform/brio_" + std::to_string(threads) + "_threads";
        benchmark::RegisterBenchmark(name.c_str(), &bm_brio_order, Distribution::Uniform, threads)
            ->Arg(1000000)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
    // A degenerate input for gift wrapping: on the integer grid every circle through three
    // neighbours passes through a fourth, a candidate the exact incircle decides.
    register_family({"tanemura-merriam", Distribution::Grid, InsertionOrder::Given, "none"}, 10, 16,
                    benchmark::oNLogN);
    // The adversary (see PointOrder): the parabola by decreasing t, inserted as given, against
    // the same points shuffled; and, for the record, as generated (increasing t), in that order.
    const Distribution parabola = Distribution::Parabola;
    register_family(
        {"bowyer-watson", parabola, InsertionOrder::Given, "given", PointOrder::Reversed}, 8, 14,
        benchmark::oNSquared);
    register_family(
        {"bowyer-watson", parabola, InsertionOrder::Random, "random", PointOrder::Reversed}, 8, 14,
        benchmark::oN);
    register_family(
        {"bowyer-watson", parabola, InsertionOrder::Given, "ascending", PointOrder::AsGenerated}, 8,
        14, benchmark::oN);
}

/// --write_node=<distribution>,<n>,<path>: returns the exit status.
int write_node(std::string_view spec) {
    const std::size_t first = spec.find(',');
    const std::size_t second = first == std::string_view::npos ? first : spec.find(',', first + 1);
    if (second == std::string_view::npos) {
        std::cerr << "delaunay2d_bench: --write_node wants <distribution>,<n>,<path>\n";
        return 2;
    }
    try {
        const Distribution distribution = gen::distribution_from_name(spec.substr(0, first));
        const std::string count(spec.substr(first + 1, second - first - 1));
        const auto n = static_cast<std::uint32_t>(std::stoul(count));
        exactmesh::io::NodeFile nodes;
        nodes.xy = gen::generate_points_2d(distribution, n, kInputSeed);
        exactmesh::io::write_node(std::string(spec.substr(second + 1)), nodes);
    } catch (const std::exception& error) {
        std::cerr << "delaunay2d_bench: --write_node: " << error.what() << '\n';
        return 2;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    constexpr std::string_view kWriteNode = "--write_node=";
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument = argv[i];
        if (argument.starts_with(kWriteNode)) return write_node(argument.substr(kWriteNode.size()));
    }

    exactmesh::bench::set_heap_regime();
    register_all();

    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    benchmark::AddCustomContext("exactmesh_max_log2_points", std::to_string(max_log2_points()));
    benchmark::AddCustomContext("exactmesh_random_max_log2_points",
                                std::to_string(random_max_log2_points()));
    benchmark::AddCustomContext("exactmesh_scaling_max_points",
                                std::to_string(scaling_max_points()));
    exactmesh::bench::add_threads_context();
    benchmark::AddCustomContext("exactmesh_heap", cold_heap() ? "cold" : "warm");
    bool interleaved = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view argument = argv[i];
        if (argument.starts_with("--benchmark_enable_random_interleaving")) {
            interleaved = argument.ends_with("=true") || argument.ends_with("=1") ||
                          argument == "--benchmark_enable_random_interleaving";
        }
    }
    benchmark::AddCustomContext("exactmesh_interleaved", interleaved ? "yes" : "no");
    benchmark::AddCustomContext("exactmesh_input_seed", std::to_string(kInputSeed));
    benchmark::AddCustomContext("exactmesh_order_seed", std::to_string(kOrderSeed));
    exactmesh::bench::add_peak_memory_context();
    exactmesh::bench::add_compiler_context();
    exactmesh::bench::add_cgal_context();
    // A short default min_time keeps the suite within a few minutes (a construction of 2^20
    // points runs once per repetition anyway).
    return exactmesh::bench::run_benchmarks_with_default_min_time(argc, argv);
}
