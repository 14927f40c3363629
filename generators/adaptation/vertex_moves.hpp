// SPDX-License-Identifier: MIT
// The guarded Jacobi sweep shared by laplacian_smoothing_3d and weighted_movement (internal to
// generators/adaptation): vertex stars in compressed rows, the fixed-vertex marks, and sweeps
// that move each free vertex towards the weighted average of its edge neighbours,
//     x_i <- x_i + omega (sum_j W_ij (x_j - x_i)) / (sum_j W_ij),
// every target from the positions before the sweep, then the moves applied one by one and each
// undone when an element of the vertex's star is not strictly positive by the exact orient2d /
// orient3d against the current positions [Field88; Löhner, "Applied CFD Techniques", 2nd ed.,
// §12 (mesh movement)]; in smart mode [Freitag97, "On combining Laplacian and
// optimization-based mesh smoothing techniques", the smart Laplacian] also when it lowers the
// smallest element quality of the star (element_quality_2d / _3d). Weighted differences rather than
// weighted coordinates: the target is a sum of products of unscaled weights and coordinate
// differences, so coordinates x 2^k give every target x 2^k exactly (no squared length is formed).
// Connectivity never changes. Cost: O(sweeps * (edges + elements)) predicates and flops.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "generators/adaptation/movement_counters.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators::detail {

/// Per vertex v: its elements elements[element_start[v] .. element_start[v+1]) and its distinct
/// edge neighbours neighbors[neighbor_start[v] .. neighbor_start[v+1]) (increasing).
struct VertexStars {
    std::vector<std::uint32_t> element_start, neighbor_start;
    std::vector<std::uint32_t> elements;
    std::vector<triangulation::VertIdx> neighbors;
};

VertexStars vertex_stars_2d(const triangulation::Triangulation2& mesh);
VertexStars vertex_stars_3d(const triangulation::Tetrahedralization3& mesh);

/// Throws InputError unless the arrays are consistent in size and every vertex index is in
/// range (the cheap part of a precondition; orientation is the caller's).
void validate_mesh_arrays_2d(const triangulation::Triangulation2& mesh);
void validate_mesh_arrays_3d(const triangulation::Tetrahedralization3& mesh);

/// Throws InputError unless omega is in (0, 1].
void validate_relaxation(double omega);

/// What the sweeps did.
struct SweepTally {
    std::uint64_t sweeps = 0;
    std::uint64_t moves = 0;
    std::uint64_t undone = 0;
    std::uint64_t worse = 0;      ///< smart mode: moves undone because the star's quality fell
    std::uint64_t converged = 0;  ///< targets within 2^-30 of the star's size: not moved
    std::uint64_t free_vertices = 0;
};

/// What a sweep run did, from its tally and the fixed-vertex marks.
inline MovementCounters sweep_counters(const SweepTally& tally,
                                       std::span<const std::uint8_t> fixed) {
    MovementCounters counters;
    counters.sweeps = tally.sweeps;
    counters.moves = tally.moves;
    counters.undone = tally.undone;
    counters.undone_worse = tally.worse;
    counters.converged = tally.converged;
    counters.free_vertices = tally.free_vertices;
    counters.fixed_vertices = static_cast<std::uint64_t>(std::count(fixed.begin(), fixed.end(), 1));
    return counters;
}

/// The element quality used by smart mode, 1 for the equilateral triangle / regular
/// tetrahedron, 0 when flat: 4 sqrt(3) A / (sum of squared edges), and 6 sqrt(2) V / l_rms^3
/// (triangulation/checks/quality_3d's volume-edge measure). Computed from the differences to
/// the first corner scaled by a power of two that brings the largest to [1, 2): the value is
/// the same bits when every coordinate is multiplied by 2^k, and no square over- or underflows.
/// Depends on the corner order only through rounding (the order stored in the element is used).
double element_quality_2d(const double* a, const double* b, const double* c);
double element_quality_3d(const double* a, const double* b, const double* c, const double* d);

/// Up to `sweeps` guarded Jacobi sweeps over the vertices with fixed[v] == 0; stops after a sweep
/// that moves nothing. `weights` holds W per neighbour slot of `stars` (same length as
/// stars.neighbors, every value finite and >= 1), or is empty for W = 1. `smart`: also undo a
/// move that lowers the smallest element_quality over the vertex's star.
struct SweepSettings {
    double omega = 1.0;
    std::uint32_t sweeps = 1;
    bool smart = false;
};
SweepTally guarded_sweeps_2d(triangulation::Triangulation2& mesh, const VertexStars& stars,
                             std::span<const std::uint8_t> fixed, std::span<const double> weights,
                             const SweepSettings& settings);
SweepTally guarded_sweeps_3d(triangulation::Tetrahedralization3& mesh, const VertexStars& stars,
                             std::span<const std::uint8_t> fixed, std::span<const double> weights,
                             const SweepSettings& settings);

}  // namespace exactmesh::generators::detail
