// SPDX-License-Identifier: MIT
// Which vertices a mesh movement may move, and the exact check of a moved mesh (issue 13; used
// by laplacian_smoothing_3d, weighted_movement and their tests). A movement changes coordinates
// only: the check demands the same vertex count and bit-identical connectivity arrays, the fixed
// vertices' coordinates bit-identical, every coordinate finite, and every element strictly
// positively oriented by the exact orient2d / orient3d (so no element is flat or inverted).
// Fixed: the vertices below fixed_below (a generator's input vertices), the caller's protected
// ones, every vertex of a boundary edge / face (no neighbour across it) or, in 2D, of a
// constrained edge, and the vertices in no element.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "triangulation/mesh/tetrahedralization_3d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// #V flags, 1 for a vertex no movement may move (see above). `protected_vertices` is empty or
/// #V flags (nonzero = protected).
/// @throws InputError when protected_vertices is neither empty nor #V long.
std::vector<std::uint8_t> fixed_vertices_2d(const triangulation::Triangulation2& mesh,
                                            std::uint32_t fixed_below,
                                            std::span<const std::uint8_t> protected_vertices = {});
std::vector<std::uint8_t> fixed_vertices_3d(const triangulation::Tetrahedralization3& mesh,
                                            std::uint32_t fixed_below,
                                            std::span<const std::uint8_t> protected_vertices = {});

struct MovementCheckReport {
    bool ok = true;
    std::string problem;  ///< the first problem found, in words; empty when ok
    std::uint32_t vertex = triangulation::kNone;   ///< the offending vertex, when one is
    std::uint32_t element = triangulation::kNone;  ///< the offending triangle / tetrahedron
};

/// Checks `after` as a movement of `before` keeping the vertices with fixed[v] != 0 (#V flags,
/// e.g. fixed_vertices_2d(before, ...)) in place; exact.
MovementCheckReport check_mesh_movement_2d(const triangulation::Triangulation2& before,
                                           const triangulation::Triangulation2& after,
                                           std::span<const std::uint8_t> fixed);
MovementCheckReport check_mesh_movement_3d(const triangulation::Tetrahedralization3& before,
                                           const triangulation::Tetrahedralization3& after,
                                           std::span<const std::uint8_t> fixed);

}  // namespace exactmesh::generators
