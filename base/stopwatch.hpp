// SPDX-License-Identifier: MIT
// Wall-clock phase timing for the *_microseconds counters of the constructions (measured time,
// not work: it differs from run to run and never decides anything).
#pragma once

#include <chrono>
#include <cstdint>

namespace exactmesh {

/// Wall-clock microseconds since `start` (std::chrono::steady_clock).
inline std::uint64_t microseconds_since(std::chrono::steady_clock::time_point start) {
    return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::microseconds>(
                                          std::chrono::steady_clock::now() - start)
                                          .count());
}

}  // namespace exactmesh
