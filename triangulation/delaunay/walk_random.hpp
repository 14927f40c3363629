// SPDX-License-Identifier: MIT
// The random choices of the visibility walks (internal to triangulation/delaunay): one xorshift
// step [Marsaglia 2003] per walk step, reduced to an edge (2D) or a face (3D). Each walk keeps
// its own state (the sequential core's, or a parallel worker's), so the choices repeat run to run.
#pragma once

#include <cstdint>

namespace exactmesh::triangulation::detail {

/// One xorshift64 step of `state`; returns the new state.
inline std::uint64_t xorshift64_step(std::uint64_t& state) {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
}

/// The 2D walk's random edge: 0, 1 or 2.
inline std::uint32_t walk_random_offset_2d(std::uint64_t& state) {
    return static_cast<std::uint32_t>(xorshift64_step(state) % 3);
}

/// The 3D walk's random face order: 2 bits of the step.
inline std::uint32_t walk_random_offset(std::uint64_t& state) {
    return static_cast<std::uint32_t>(xorshift64_step(state) >> 40) & 3u;
}

}  // namespace exactmesh::triangulation::detail
