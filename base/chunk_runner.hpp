// SPDX-License-Identifier: MIT
// ChunkRunner: how a caller lends its threads to work cut into chunks (the multicore Delaunay
// constructions' result, the parallel refinement's fans) without the callee knowing its pool.
#pragma once

#include <cstddef>
#include <functional>

namespace exactmesh {

/// Runs body(c) for every chunk c in [0, count), in any order and possibly at once (the
/// multicore constructions run the chunks on their threads); empty: one after another.
using ChunkRunner = std::function<void(std::size_t count, const std::function<void(std::size_t)>&)>;

}  // namespace exactmesh
