// SPDX-License-Identifier: MIT
// The six phase times (--stats' *_microseconds) of a parallel Delaunay construction, summed:
// the 2D and 3D tests check that together they fit inside the call's wall time.
#pragma once

#include <cstdint>

namespace exactmesh::testing {

/// order + keys + sequential + partition + parallel + result microseconds of Delaunay2Counters
/// or Delaunay3Counters.
template <class Counters>
std::uint64_t phase_microseconds(const Counters& c) {
    return c.order_microseconds + c.keys_microseconds + c.sequential_microseconds +
           c.partition_microseconds + c.parallel_microseconds + c.result_microseconds;
}

}  // namespace exactmesh::testing
