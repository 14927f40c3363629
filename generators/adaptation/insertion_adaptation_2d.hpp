// SPDX-License-Identifier: MIT
// Delaunay point-insertion adaptation in 2D (issue 13; the seed material's adaptation chapter;
// Weatherill's and Rebay's "insert where the indicator says" with Bowyer-Watson):
//  1. the indicator on every edge (edge_indicators.hpp), edges flagged above threshold × mean,
//     or, under a vertex budget, the largest ones that fit it;
//  2. the isotropic closure: every triangle with a flagged edge gets all three flagged (one pass);
//  3. a point at each flagged edge's midpoint, rounded once; a boundary (segment) edge's point
//     on the original curve (the piece's curve at the mean of its end parameters) when the domain
//     has curves, else the chord's rounded midpoint;
//  4. the boundary points split their pieces and the constrained Delaunay triangulation of the
//     domain is built again with them (ConstrainedTriangulation2), then every interior point is
//     inserted by Bowyer-Watson in it (insert_in_cavity: cavities never cross a constraint); a
//     point that would encroach a constrained edge is left out (the boundary's own flagged edges
//     refine it), as is one that has left the domain (beside a concave curve point);
//  5. Laplacian smoothing (laplacian_smoothing_2d with its Delaunay swaps), boundary fixed;
//  6. the field on the new mesh: the analytic field sampled, or a given field transferred
//     (field_transfer.hpp) from the old mesh;
//  7. optionally solution-weighted movement towards the new mesh's indicator, and the field
//     again at the moved vertices.
// When a curve point would make the domain's pieces cross or touch another (a thin gap at the
// resolution of the mesh), the cycle is redone with chord midpoints on the boundary (counted):
// the domain never self-intersects. Invariants after a cycle (check_adaptive_mesh_2d): a valid
// constrained Delaunay triangulation whose constrained edges are the pieces, input vertices at
// their place, curve points on their curve.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/vertex_field.hpp"

namespace exactmesh::generators {

struct AdaptationOptions {
    EdgeIndicator indicator = EdgeIndicator::SecondDifference;
    double threshold = 1.0;              ///< flag edges above threshold × the mean indicator
    std::uint64_t max_vertices = 0;      ///< 0: no budget; else never refine past it
    std::uint32_t smoothing_sweeps = 0;  ///< Laplacian sweeps after each cycle
    /// Solution-weighted movement sweeps after each cycle (weighted_movement.hpp: vertices drawn
    /// towards the largest indicator at them; connectivity kept, so the 2D mesh is then no
    /// longer Delaunay until the next cycle's triangulation).
    std::uint32_t movement_sweeps = 0;
    double movement_strength = 4.0;  ///< WeightedMovementOptions::strength
    /// > 0: thresholds relative to this mean instead of the current mesh's (flag_above_mean).
    double reference_mean = 0;
};

/// Where the field on a new mesh comes from: the analytic field at time t (the solver's
/// stand-in), or (analytic == nullptr) the old mesh's values transferred.
struct FieldSource {
    const AnalyticField* analytic = nullptr;
    double t = 0;
};

namespace detail {

/// Steps 1-2 of an insertion cycle in either dimension: the mesh's edges (mesh_edges_2d for
/// dim 2, mesh_edges_3d for dim 3) and refinement_flags of their indicator within the room the
/// budget leaves. flagged is 0 when the budget is reached (nothing computed) or nothing is
/// flagged.
struct CycleFlags {
    std::vector<triangulation::VertIdx> edges;
    std::vector<std::uint8_t> flags;
    std::uint64_t flagged = 0, closure = 0;
};
CycleFlags cycle_flags(const AdaptationOptions& options, std::span<const double> coordinates,
                       unsigned dim, std::span<const triangulation::VertIdx> elements,
                       std::span<const double> values);

}  // namespace detail

struct InsertionCounters2 {
    std::uint64_t cycles = 0;
    std::uint64_t flagged_edges = 0;        ///< by the indicator (summed over cycles)
    std::uint64_t closure_edges = 0;        ///< added by the isotropic closure
    std::uint64_t inserted = 0;             ///< interior points inserted by Bowyer-Watson
    std::uint64_t boundary_points = 0;      ///< pieces split
    std::uint64_t curve_points = 0;         ///< of those, placed on the original curve
    std::uint64_t curve_retries = 0;        ///< cycles redone with chord points on the boundary
    std::uint64_t encroaching_skipped = 0;  ///< interior points left out: they encroach a piece
    std::uint64_t outside_skipped = 0;      ///< interior points left out: outside the domain
    std::uint64_t smoothing_moves = 0;
    std::uint64_t smoothing_undone = 0;
    std::uint64_t movement_moves = 0;
    std::uint64_t movement_undone = 0;
};

inline constexpr std::array kInsertionCounterNames2 = EM_COUNTER_TABLE(
    InsertionCounters2, cycles, flagged_edges, closure_edges, inserted, boundary_points,
    curve_points, curve_retries, encroaching_skipped, outside_skipped, smoothing_moves,
    smoothing_undone, movement_moves, movement_undone);
static_assert(counter_table_complete(kInsertionCounterNames2));

/// One cycle on `state` (state.values must hold the field at its vertices); returns false when
/// no edge was flagged (or the budget is reached), the mesh unchanged.
/// @throws InputError as sample_field; GeometryError from the triangulation only on a bug.
bool insertion_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                        const FieldSource& field, InsertionCounters2& counters);

}  // namespace exactmesh::generators
