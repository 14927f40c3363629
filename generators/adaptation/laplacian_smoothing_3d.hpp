// SPDX-License-Identifier: MIT
// Laplacian smoothing of a tetrahedralization, the 3D counterpart of
// generators/mesh_2d/laplacian_smoothing_2d [Field88: "Laplacian smoothing and Delaunay
// triangulations", Comm. Appl. Numer. Methods 4; Freitag & Ollivier-Gooch 1997 on its 3D
// behaviour]: each free vertex moves towards the centroid of its edge neighbours by the Jacobi
// formula
//     x_i <- x_i + omega ((1 / n_i) sum_{j ~ i} (x_j - x_i)),
// every target computed from the positions before the sweep (as differences: coordinates x 2^k
// give every move x 2^k exactly). Moves are then applied one by one, and a move that would make
// any tetrahedron of the vertex's star not strictly positively oriented (exact orient3d against
// its neighbours' current positions) is undone: the mesh stays valid after every move,
// whatever the input. By default (smart) a move that would lower the smallest quality of its
// star is undone too [Freitag97, "On combining Laplacian and optimization-based mesh smoothing
// techniques"]: plain Laplacian smoothing in 3D raises the mean quality but makes slivers.
// A move below 2^-30 of the star's extent counts as converged, not made.
// Unlike the 2D smoother there is no swapping after the sweeps: connectivity never changes
// (a caller that wants the mesh Delaunay again runs triangulation/modification/edge_face_swap_3d
// afterwards).
// Fixed vertices (generators/adaptation/mesh_movement_check.hpp): the input's (index <
// fixed_below), every vertex of a boundary face (no neighbour across it), vertices in no
// tetrahedron. A vertex of a tetrahedron that is not positive on input never moves.
// Cost: O(iterations * (edges + T)) orient3d calls and flops.
#pragma once

#include <array>
#include <cstdint>

#include "generators/adaptation/movement_counters.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::generators {

struct SmoothingOptions3 {
    std::uint32_t iterations = 1;  ///< at most this many Jacobi sweeps; stops after one that
                                   ///< moves nothing
    double relaxation = 1.0;       ///< omega in (0, 1]: 1 moves to the neighbours' centroid
    /// Smart Laplacian [Freitag97]: also undo a move that lowers the smallest volume-edge
    /// quality of the vertex's star (6 sqrt(2) V / l_rms^3, computed per tetrahedron in a
    /// power-of-two scaled frame: scale-invariant). Off, plain Laplacian smoothing raises the
    /// mean quality but creates slivers: on a jittered 7^3 grid one sweep takes the smallest
    /// dihedral angle from 3.2 to 0.3 degrees (laplacian_smoothing_3d_test).
    bool smart = true;
};

using SmoothingCounters3 = MovementCounters;  ///< movement_counters.hpp
inline constexpr const auto& kSmoothing3CounterNames = kMovementCounterNames;

/// Smooths `mesh` in place (coordinates of free vertices only; tets and neighbors unchanged).
/// @pre tetrahedra positively oriented, neighbors consistent, coordinates finite.
/// @throws InputError when relaxation is not in (0, 1] or the arrays are inconsistent (sizes,
///         a vertex index out of range).
SmoothingCounters3 laplacian_smoothing_3d(triangulation::Tetrahedralization3& mesh,
                                          std::uint32_t fixed_below,
                                          const SmoothingOptions3& options = {});

}  // namespace exactmesh::generators
