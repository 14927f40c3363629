// SPDX-License-Identifier: MIT
// What a run of guarded vertex sweeps did (vertex_moves.hpp): the counters laplacian_smoothing_3d
// (SmoothingCounters3) and weighted_movement (WeightedMovementCounters) both return.
#pragma once

#include <array>
#include <cstdint>

#include "base/counter_table.hpp"

namespace exactmesh::generators {

struct MovementCounters {
    std::uint64_t sweeps = 0;
    std::uint64_t moves = 0;           ///< vertex moves applied (summed over sweeps)
    std::uint64_t undone = 0;          ///< moves refused because an element (triangle or
                                       ///< tetrahedron) would not be strictly positive (summed
                                       ///< over sweeps)
    std::uint64_t undone_worse = 0;    ///< smart: moves refused because the smallest quality of
                                       ///< the star would fall (summed over sweeps)
    std::uint64_t converged = 0;       ///< targets within 2^-30 of the star's extent, not moved
                                       ///< (summed over sweeps)
    std::uint64_t free_vertices = 0;   ///< vertices allowed to move
    std::uint64_t fixed_vertices = 0;  ///< vertices kept in place
};

/// The name table of MovementCounters (base/counter_table.hpp).
inline constexpr std::array kMovementCounterNames =
    EM_COUNTER_TABLE(MovementCounters, sweeps, moves, undone, undone_worse, converged,
                     free_vertices, fixed_vertices);
static_assert(counter_table_complete(kMovementCounterNames));

}  // namespace exactmesh::generators
