// SPDX-License-Identifier: MIT
// Solution-weighted mesh movement (r-adaptation) in 2D and 3D [Löhner, "Applied CFD Techniques",
// 2nd ed., §12 (mesh movement, the spring analogy) and §14 (adaptive mesh movement); Eiseman,
// "Adaptive grid generation", CMAME 64 (1987), weighted averaging]: the mesh is a network of
// springs whose stiffness grows with the indicator, and each free vertex moves towards the
// equilibrium of its springs, the weighted average of its edge neighbours. At equilibrium a
// stiff spring is short, so vertices crowd where the indicator is high; connectivity never
// changes and no element inverts.
//
// The formula, with f_v >= 0 the caller's indicator value at vertex v and U the vertices used
// by an element:
//     m     = max_{v in U} f_v,      g_v = f_v / m   (g = 0 when m = 0),
//     mean  = (1 / |U|) sum_{v in U} g_v            (summed in increasing v),
//     w_ij  = ((g_i + g_j) * 0.5) / mean            (edge value normalised by the mean: 1 on
//                                                    average, whatever f's unit),
//     W_ij  = 1 + c w_ij                            (c = options.strength; c = 0 is Laplacian),
//     x_i  <- x_i + omega (sum_j W_ij (x_j - x_i)) / (sum_j W_ij)   (j over i's edge neighbours
//                                                    in increasing index, Jacobi: every target
//                                                    from the positions before the sweep).
// Dividing by m first keeps every sum in range whatever f's magnitude; the move is a weighted
// average of coordinate differences with unscaled weights, so coordinates x 2^k give every
// move x 2^k exactly (no squared length). The indicator stays attached to its vertex while it
// moves; a caller with an analytic or re-interpolated indicator calls again per sweep.
// The moves of a sweep are applied one by one; one that would make an element of the vertex's
// star not strictly positive (exact orient2d / orient3d, current positions) is undone, and with
// options.smart one that lowers the star's smallest element quality. A move
// below 2^-30 of the star's extent counts as converged, not made. The sweeps stop after one
// that moves nothing.
// Fixed vertices (mesh_movement_check.hpp): index < fixed_below, the caller's protected ones,
// every vertex of a boundary edge / face or of a constrained edge (2D), vertices in no element.
// Cost: O(sweeps * (edges + elements)) predicates and flops, plus O(edges) for the weights.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "generators/adaptation/movement_counters.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

struct WeightedMovementOptions {
    std::uint32_t sweeps = 1;  ///< at most this many Jacobi sweeps; stops after one that moves
                               ///< nothing
    double relaxation = 1.0;   ///< omega in (0, 1]
    double strength = 4.0;  ///< c in [0, 2^50]: how much stiffer an edge of mean indicator is than
                            ///< an edge where the indicator vanishes (W = 1 + c w)
    /// Also undo a move that lowers the smallest element quality of the vertex's star (the
    /// smart Laplacian's rule [Freitag97]; 2D 4 sqrt(3) A / sum l^2, 3D 6 sqrt(2) V / l_rms^3,
    /// scale-invariant). Off by default: crowding vertices towards a feature flattens elements
    /// on purpose, and the guard refuses many of those moves.
    bool smart = false;
};

using WeightedMovementCounters = MovementCounters;  ///< movement_counters.hpp
inline constexpr const auto& kWeightedMovementCounterNames = kMovementCounterNames;

/// Moves the free vertices of `mesh` in place (coordinates only: triangles, neighbors and
/// constrained unchanged). `indicator`: #V values f_v >= 0; `protected_vertices`: empty or #V
/// flags (nonzero = keep in place).
/// @pre triangles strictly counter-clockwise, neighbors consistent, coordinates finite.
/// @throws InputError when the indicator is not #V finite values >= 0, the strength is not in
///         [0, 2^50], the relaxation is not in (0, 1], protected_vertices has another
///         length, or the mesh arrays are inconsistent.
WeightedMovementCounters weighted_movement_2d(
    triangulation::Triangulation2& mesh, std::span<const double> indicator,
    std::uint32_t fixed_below, const WeightedMovementOptions& options = {},
    std::span<const std::uint8_t> protected_vertices = {});

/// weighted_movement_2d for a tetrahedralization (orient3d guard, boundary faces fixed).
WeightedMovementCounters weighted_movement_3d(
    triangulation::Tetrahedralization3& mesh, std::span<const double> indicator,
    std::uint32_t fixed_below, const WeightedMovementOptions& options = {},
    std::span<const std::uint8_t> protected_vertices = {});

}  // namespace exactmesh::generators
