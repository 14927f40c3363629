// SPDX-License-Identifier: MIT
// The memory floor of a Delaunay construction (issue 17: "a lower bound you measure"): one pass
// that reads the points in insertion order and writes what the construction's result holds, and
// nothing else. Its time is what any construction of that result pays on this machine for the
// memory alone, so it tells how much of a construction's time is computing and how much of a
// ratio between machines is their memory (DESIGN.md "Benchmarks").
//
// The pass: the points gathered into insertion order (the constructions' working copy, read
// through the permutation as they read it), then K vertex and K neighbour entries for each of the
// result's cells written in order, each a function of a gathered point so that nothing is
// elided, and, where the result holds a copy of the points (3D), the caller's points copied
// beside them. Its memory is
//   warm:              allocated once before the timed passes (the writes and reads alone);
//   fresh:             mapped anonymously in each timed pass and unmapped paused, so every page
//                      is first touched in the pass: the kernel's page faults and zeroing (and,
//                      under a hypervisor, the host's), which a construction's new arrays pay;
//   fresh_huge_pages:  fresh, advised onto 2 MiB pages as the constructions' mesh arrays are
//                      (base/huge_pages.hpp).
#pragma once

#include <benchmark/benchmark.h>
#include <sys/mman.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <span>
#include <string>

#include "base/enum_names.hpp"
#include "base/huge_pages.hpp"

namespace exactmesh::bench {

enum class FloorMemory { Warm, Fresh, FreshHugePages };

/// The memories' names, in the rows' order (base/enum_names.hpp).
inline constexpr std::array<EnumName<FloorMemory>, 3> kFloorMemoryNames{
    {{"warm", FloorMemory::Warm},
     {"fresh", FloorMemory::Fresh},
     {"fresh_huge_pages", FloorMemory::FreshHugePages}}};

/// Calls add(name, memory) for each floor row of the points named `points` (a benchmark name's
/// tail, "uniform/1000000" style): name = BM_memory_floor_<memory>/<points>.
template <class Add>
void for_each_memory_floor_row(const std::string& points, Add&& add) {
    for (const EnumName<FloorMemory>& row : kFloorMemoryNames) {
        std::string name = "BM_memory_floor_";
        name += std::string(row.name) + "/" + points;
        add(name, row.value);
    }
}

/// One anonymous mapping of `bytes` (its pages untouched), unmapped on destruction.
class FloorMapping {
  public:
    FloorMapping(std::size_t bytes, bool huge_pages) : bytes_(std::max<std::size_t>(bytes, 1)) {
        data_ = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (data_ == MAP_FAILED) throw std::bad_alloc();
        if (huge_pages) advise_huge_pages(data_, bytes_);
    }
    FloorMapping(const FloorMapping&) = delete;
    FloorMapping& operator=(const FloorMapping&) = delete;
    ~FloorMapping() { munmap(data_, bytes_); }
    template <class T>
    T* as() const {
        return static_cast<T*>(data_);
    }

  private:
    std::size_t bytes_;
    void* data_;
};

/// What one pass writes: n points of D coordinates (`coordinates` = D n) in insertion order, a
/// copy of `copied` coordinates (D n or none), and the cells' `entries` (K per cell) twice.
struct FloorArrays {
    FloorArrays(std::size_t coordinates, std::size_t copied, std::size_t entries, bool huge_pages)
        : ordered(coordinates * sizeof(double), huge_pages),
          copy(copied * sizeof(double), huge_pages),
          vertices(entries * sizeof(std::uint32_t), huge_pages),
          neighbours(entries * sizeof(std::uint32_t), huge_pages) {}
    FloorMapping ordered, copy, vertices, neighbours;
};

/// One pass (see the header) over `points` (D coordinates each) in `order`, writing `cells`
/// cells of K entries into `out`, and the points when `copy_points`.
template <unsigned D, unsigned K>
void memory_floor_pass(std::span<const double> points, std::span<const std::uint32_t> order,
                       std::size_t cells, bool copy_points, FloorArrays& out) {
    const std::size_t n = order.size();
    double* const ordered = out.ordered.as<double>();
    for (std::size_t v = 0; v < n; ++v) {
        for (unsigned d = 0; d < D; ++d) ordered[D * v + d] = points[D * std::size_t{order[v]} + d];
    }
    std::uint32_t* const vertices = out.vertices.as<std::uint32_t>();
    std::uint32_t* const neighbours = out.neighbours.as<std::uint32_t>();
    std::size_t v = 0;
    for (std::size_t c = 0; c < cells; ++c) {
        const auto side = static_cast<std::uint32_t>(ordered[D * v] < 0.0);
        for (unsigned k = 0; k < K; ++k) {
            vertices[K * c + k] = static_cast<std::uint32_t>(v + k) ^ side;
            neighbours[K * c + k] = static_cast<std::uint32_t>(K * c + k) ^ side;
        }
        if (++v == n) v = 0;
    }
    if (copy_points) std::copy(points.begin(), points.end(), out.copy.as<double>());
    benchmark::DoNotOptimize(vertices);
    benchmark::DoNotOptimize(neighbours);
    benchmark::ClobberMemory();
}

/// The timed loop of a floor row (see the header for `memory`; `copy_points`: the result holds
/// a copy of the points).
template <unsigned D, unsigned K>
void run_memory_floor(benchmark::State& state, std::span<const double> points,
                      std::span<const std::uint32_t> order, std::size_t cells, bool copy_points,
                      FloorMemory memory) {
    const std::size_t coordinates = points.size(), entries = K * cells;
    const std::size_t copied = copy_points ? coordinates : 0;
    if (memory == FloorMemory::Warm) {
        FloorArrays arrays(coordinates, copied, entries, false);
        memory_floor_pass<D, K>(points, order, cells, copy_points, arrays);  // untimed first touch
        for (auto _ : state) memory_floor_pass<D, K>(points, order, cells, copy_points, arrays);
    } else {
        for (auto _ : state) {
            auto arrays = std::make_unique<FloorArrays>(coordinates, copied, entries,
                                                        memory == FloorMemory::FreshHugePages);
            memory_floor_pass<D, K>(points, order, cells, copy_points, *arrays);
            state.PauseTiming();  // unmapped paused, as the constructions' results are freed
            arrays.reset();
            state.ResumeTiming();
        }
    }
    const std::size_t bytes =
        (coordinates + copied) * sizeof(double) + 2 * entries * sizeof(std::uint32_t);
    state.counters["MB_written"] = static_cast<double>(bytes) / 1e6;
}

}  // namespace exactmesh::bench
