// SPDX-License-Identifier: MIT
// Laplacian smoothing of a 2D mesh [seed material, issue 6; Field88: "Laplacian smoothing and
// Delaunay triangulations", Comm. Appl. Numer. Methods 4]: each free vertex moves towards the
// centroid of its neighbours by the Jacobi formula
//     x_i <- x_i + omega ((1 / n_i) sum_{j ~ i} x_j - x_i),
// every target computed from the positions before the sweep. Moves are then applied one by one,
// and a move that would make any triangle of the vertex's star not strictly counter-clockwise
// (exact orient2d against its neighbours' current positions) is undone: the mesh stays valid
// after every move, whatever the input. After each sweep, Lawson's Delaunay swapping
// (triangulation/modification/edge_swap_2d) restores the (constrained) Delaunay property the moves
// break; Field shows that smoothing alone can lower the minimum angle and that swapping after it
// repairs most of that.
// Fixed vertices: the input's (index < fixed_below), every vertex of a constrained edge or of an
// edge with one triangle (the boundary and the segments), and vertices in no triangle.
// Cost: O(iterations * (T + swaps)).
#pragma once

#include <cstdint>

#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

struct SmoothingOptions2 {
    std::uint32_t iterations = 1;  ///< at most this many Jacobi sweeps (each followed by
                                   ///< Delaunay swapping); stops after one that changes nothing
    double relaxation = 1.0;       ///< omega in (0, 1]: 1 moves to the neighbours' centroid
    bool delaunay_swap = true;     ///< swap edges to (constrained) Delaunay after each sweep
};

struct SmoothingCounters2 {
    std::uint64_t sweeps = 0;
    std::uint64_t moves = 0;          ///< vertex moves applied (summed over sweeps)
    std::uint64_t undone = 0;         ///< moves refused because a triangle would invert
    std::uint64_t swaps = 0;          ///< Delaunay swaps after the sweeps
    std::uint64_t free_vertices = 0;  ///< vertices allowed to move
    double largest_move = 0;          ///< the longest single move, in coordinate units
};

/// Smooths `mesh` in place (coordinates of free vertices; connectivity by the swaps).
/// @pre mesh.neighbors consistent, triangles strictly counter-clockwise, coordinates finite.
/// @throws InputError when relaxation is not in (0, 1].
SmoothingCounters2 laplacian_smoothing_2d(triangulation::Triangulation2& mesh,
                                          std::uint32_t fixed_below,
                                          const SmoothingOptions2& options = {});

}  // namespace exactmesh::generators
