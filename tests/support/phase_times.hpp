// SPDX-License-Identifier: MIT
// The six phase times (--stats' *_microseconds) of a parallel Delaunay construction: summed, and
// checked to fit inside the call's wall time together (the 2D and 3D tests).
#pragma once

#include <chrono>
#include <cstdint>

namespace exactmesh::testing {

/// order + keys + sequential + partition + parallel + result microseconds of Delaunay2Counters
/// or Delaunay3Counters.
template <class Counters>
std::uint64_t phase_microseconds(const Counters& c) {
    return c.order_microseconds + c.keys_microseconds + c.sequential_microseconds +
           c.partition_microseconds + c.parallel_microseconds + c.result_microseconds;
}

/// Whether the six phases of `build()`'s counters fit inside the call's own wall time, the
/// passes and the keys phase having time.
template <class Build>
bool phases_fit_in_call(Build&& build) {
    const auto start = std::chrono::steady_clock::now();
    const auto result = build();
    const auto wall = std::chrono::duration_cast<std::chrono::microseconds>(
        std::chrono::steady_clock::now() - start);
    return phase_microseconds(result.counters) <= static_cast<std::uint64_t>(wall.count()) &&
           result.counters.parallel_microseconds > 0 && result.counters.keys_microseconds > 0;
}

}  // namespace exactmesh::testing
