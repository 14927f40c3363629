// SPDX-License-Identifier: MIT
// Edge swapping and edge cutting benchmarks [Lawson77; DynLevinRippa90;
// EdelsbrunnerTanWaupotitsch92]: time against N with Complexity() fits, and the work counters.
//
// Names: BM_swap_<criterion>/<distribution>/<n>: Lawson swapping under one criterion from the
// sweep triangulation (generators/inputs/sweep_triangulation_2d.hpp: points sorted by x, each
// joined to the hull edges it sees; long thin triangles everywhere), n = 2^10 ... 2^14, fitted with
// Complexity() (oAuto: the best of O(1), N, N log N, N^2, N^3). BM_edge_cutting/<distribution>/<n>:
// min-max angle by edge cutting from the Delaunay triangulation (min_max_angle_triangulation_2d,
// Delaunay construction included, a negligible share), n = 2^7 ... 2^12, fitted against
// N^2 log N (the paper's bound) with a user complexity. Distributions: uniform in the unit
// square, and `disk`: uniform in the unit disk with 1/8 of the points on its circle (a hull with
// no nearly straight corner, so that the largest angle sits inside and many cuts happen);
// edge cutting also on `circle`: n points cos/sin(2 pi k / n), where every ear has the same
// angle up to rounding and cuts succeed or fail on near-ties (issue 11: 400 points took 28 s).
// Counters (first timed run): swaps/pt, tested/pt; insertions/pt, candidates/pt, visited/pt.
// The fitted exponent: the slope of log(real_time) on log(n) over the JSON, e.g.
//   edge_swap_bench --benchmark_format=json > swap.json
// and a least-squares fit per family (the final message of the swap branch gives the numbers).
// Only the algorithm is timed: inputs and starting triangulations are built once per (family,
// n) with a pinned seed; each iteration copies the start with the timer paused.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_support.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/inputs/sweep_triangulation_2d.hpp"
#include "triangulation/modification/edge_cutting_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace {

namespace tri = exactmesh::triangulation;
constexpr std::uint64_t kSeed = 20240611;

enum class Points { Uniform, Disk, Circle };

std::vector<double> make_points(Points kind, std::uint32_t n) {
    if (kind == Points::Uniform) {
        return exactmesh::generators::generate_points_2d(
            exactmesh::generators::Distribution::Uniform, n, kSeed);
    }
    std::vector<double> xy;
    if (kind == Points::Circle) {
        for (std::uint32_t k = 0; k < n; ++k) {
            const double angle = 2 * 3.14159265358979323846 * k / n;
            xy.insert(xy.end(), {std::cos(angle), std::sin(angle)});
        }
        return xy;
    }
    std::mt19937_64 rng(kSeed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::uint32_t on_circle = std::max<std::uint32_t>(8, n / 8);
    for (std::uint32_t i = 0; i < on_circle; ++i) {
        const double angle = 2 * 3.14159265358979323846 * (i + 0.5 * unit(rng)) / on_circle;
        xy.insert(xy.end(), {std::cos(angle), std::sin(angle)});
    }
    while (xy.size() < 2 * std::size_t{n}) {
        const double x = 2 * unit(rng) - 1, y = 2 * unit(rng) - 1;
        if (x * x + y * y < 0.95) xy.insert(xy.end(), {x, y});
    }
    return xy;
}

/// The data of the data-dependent criterion: a smoothed step across a line.
std::vector<double> make_values(const std::vector<double>& xy) {
    std::vector<double> values;
    for (std::size_t v = 0; v < xy.size() / 2; ++v) {
        values.push_back(std::tanh(10.0 * (xy[2 * v] + 0.5 * xy[2 * v + 1] - 0.5)));
    }
    return values;
}

const tri::Triangulation2& sweep_start(Points kind, std::uint32_t n) {
    static std::map<std::pair<int, std::uint32_t>, tri::Triangulation2> cache;
    const auto key = std::make_pair(static_cast<int>(kind), n);
    auto it = cache.find(key);
    if (it == cache.end()) {
        it = cache.emplace(key, exactmesh::generators::sweep_triangulation_2d(make_points(kind, n)))
                 .first;
    }
    return it->second;
}

template <class Criterion>
void swap_benchmark(benchmark::State& state, Points kind, Criterion criterion) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const tri::Triangulation2& start = sweep_start(kind, n);
    std::vector<double> values;
    if constexpr (std::is_same_v<Criterion, tri::DataDependent>) {
        values = make_values(start.xy);
        criterion.values = values;
    }
    bool counted = false;
    for (auto _ : state) {
        state.PauseTiming();
        tri::Triangulation2 mesh = start;
        state.ResumeTiming();
        const tri::EdgeSwapCounters counters = tri::swap_edges_2d(mesh, criterion);
        benchmark::DoNotOptimize(mesh.triangles.data());
        if (!counted) {
            state.counters["swaps/pt"] = static_cast<double>(counters.swaps) / n;
            state.counters["tested/pt"] = static_cast<double>(counters.edges_tested) / n;
            counted = true;
        }
    }
    state.SetComplexityN(n);
}

void edge_cutting_benchmark(benchmark::State& state, Points kind, bool from_sweep) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const std::vector<double> xy = make_points(kind, n);
    bool counted = false;
    for (auto _ : state) {
        tri::EdgeCuttingCounters counters;
        if (from_sweep) {
            state.PauseTiming();
            tri::Triangulation2 mesh = sweep_start(kind, n);
            state.ResumeTiming();
            counters = tri::edge_cutting_2d(mesh);
            benchmark::DoNotOptimize(mesh.triangles.data());
        } else {
            const tri::Triangulation2 mesh = tri::min_max_angle_triangulation_2d(xy, &counters);
            benchmark::DoNotOptimize(mesh.triangles.data());
        }
        if (!counted) {
            state.counters["insertions/pt"] = static_cast<double>(counters.insertions) / n;
            state.counters["candidates/pt"] = static_cast<double>(counters.candidates) / n;
            state.counters["visited/pt"] = static_cast<double>(counters.visited) / n;
            counted = true;
        }
    }
    state.SetComplexityN(n);
}

double n2_log_n(benchmark::IterationCount n) {
    const auto x = static_cast<double>(n);
    return x * x * std::log2(x);
}

void register_all() {
    const std::pair<Points, const char*> kinds[] = {{Points::Uniform, "uniform"},
                                                    {Points::Disk, "disk"}};
    for (const auto& [kind, name] : kinds) {
        const std::string suffix = std::string("/") + name;
        auto swap_family = [&](const std::string& family, auto criterion) {
            const Points k = kind;
            benchmark::RegisterBenchmark(
                ("BM_swap_" + family + suffix).c_str(),
                [k, criterion](benchmark::State& state) { swap_benchmark(state, k, criterion); })
                ->RangeMultiplier(2)
                ->Range(1 << 10, 1 << 14)
                ->Unit(benchmark::kMillisecond)
                ->Complexity();
        };
        swap_family("delaunay", tri::Delaunay{});
        swap_family("max_min_angle", tri::MaxMinAngle{});
        swap_family("min_max_angle", tri::MinMaxAngle{});
        swap_family("min_length", tri::MinTotalLength{});
        swap_family("data_abn", tri::DataDependent{{}, tri::DataCost::AngleBetweenNormals});
        swap_family("data_jnd", tri::DataDependent{{}, tri::DataCost::JumpInNormalDerivatives});
        const Points k = kind;
        for (const bool from_sweep : {true, false}) {
            const std::string family =
                from_sweep ? "BM_edge_cutting_from_sweep" : "BM_edge_cutting_from_delaunay";
            benchmark::RegisterBenchmark((family + suffix).c_str(),
                                         [k, from_sweep](benchmark::State& state) {
                                             edge_cutting_benchmark(state, k, from_sweep);
                                         })
                ->RangeMultiplier(2)
                ->Range(1 << 7, 1 << (from_sweep ? 12 : 13))
                ->Unit(benchmark::kMillisecond)
                ->Complexity(n2_log_n);
        }
    }
    benchmark::RegisterBenchmark(
        "BM_edge_cutting_from_delaunay/circle",
        [](benchmark::State& state) { edge_cutting_benchmark(state, Points::Circle, false); })
        ->RangeMultiplier(2)
        ->Range(1 << 7, 1 << 12)
        ->Unit(benchmark::kMillisecond)
        ->Complexity(n2_log_n);
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::AddCustomContext("build_type", EXACTMESH_BENCH_BUILD_TYPE);
    return exactmesh::bench::run_benchmarks(argc, argv);
}
