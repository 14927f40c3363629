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

/// Wall-clock microseconds since `phase`, which restarts now: consecutive laps of one stopwatch
/// time disjoint stretches (a phase timed from a stopwatch not restarted counts the one before
/// it again: the parallel 2D construction's sequential phase once included its keys phase).
inline std::uint64_t lap_microseconds(std::chrono::steady_clock::time_point& phase) {
    const std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
    const auto elapsed = std::chrono::duration_cast<std::chrono::microseconds>(now - phase);
    phase = now;
    return static_cast<std::uint64_t>(elapsed.count());
}

}  // namespace exactmesh
