// SPDX-License-Identifier: MIT
// Steiner restart in 2D (issue 13; the seed material's adaptation chapter: "the indicator turned
// into a size field on the current mesh; Delaunay refinement resumed until the mesh meets it;
// derefinement where the mesh is finer than the new size"). One cycle:
//  1. the indicator on the current mesh's edges, turned into a size at each vertex
//     (indicator_vertex_sizes: error equidistribution, at most a factor kSteinerMaxFactor finer
//     or coarser than the mesh there per cycle) and into the background size function, linear
//     over the current (not yet derefined) mesh (indicator_size_function_2d);
//  2. derefinement where the mesh is finer than that size: a vertex is a candidate when every
//     edge (v, w) at it is shorter than kSteinerDerefineFraction (1/2) of the mean of the sizes
//     at v and w (the linear size at the edge's midpoint), so that the edges its removal makes,
//     about twice as long, still meet the size; never an input vertex (index < fixed_vertices)
//     nor a curve point (on_curve). Candidates go as a maximal independent set (greedy in vertex
//     order) by constrained Delaunay vertex removal (remove_vertex_set_2d, derefinement_2d.hpp),
//     which also refuses corners, constraint ends and bends: a vertex on the boundary or a segment
//     goes only where its two pieces are straight (a chord point exactly collinear), so the
//     polyline of each curve is unchanged. Up to kSteinerDerefinePasses passes, the sizes of
//     step 1 kept, while one removes a vertex (the size caps the coarsening: at most about a
//     factor 2 in length per cycle). Where a removal leaves a bad angle, step 3 puts a point
//     back: the angle bound comes first;
//  3. Delaunay refinement resumed: the mesh's vertices (all of them, at their indices) and its
//     pieces as segments, with its holes, are the PSLG of a new delaunay_refinement_2d run with
//     the size function of step 1 and the guaranteed angle bound (kGuaranteedMinAngle, with the
//     automatic polish). The constrained Delaunay triangulation of that PSLG is the derefined
//     mesh itself (both are the unique SoS constrained Delaunay triangulation), so refinement
//     resumes where the mesh is, and the output keeps every current vertex at its index (checked:
//     a GeometryError otherwise, a bug), the Steiner points after them. The new state's pieces
//     take their curve parameters by make_adaptive_mesh_2d's rule (a new boundary point is on
//     its piece's chord, with the parameter of its place along it); on_curve and fixed_vertices
//     are carried;
//  4. the field on the new mesh: the analytic field sampled, or the old mesh's values
//     transferred (field_transfer.hpp; the vertices kept keep their values exactly; a point the
//     old mesh does not hold, a rounded chord midpoint just outside it, takes the mean of its
//     neighbours' values, counted).
// The vertex budget (options.max_vertices > 0) is never exceeded: the size is scaled up by one
// factor until the refinement fits it. The first factor makes an estimate of the refinement's
// vertex count (the domain's area over the equilateral triangles of the size, one per vertex)
// fit the budget; a run that still ends above it is redone with the factor grown by the square
// root of the ratio of the points it added to the room left (times 1.05), and a run that
// reaches its own Steiner budget (kSteinerRunBudgetFactor times the room left; or whose size
// asks refinement for more than that at once) with the factor doubled, at most
// kSteinerBudgetRuns runs; if none fits (or the derefined mesh has no room left), the cycle
// keeps the derefined mesh unrefined and counts a budget stop. Invariants after a cycle
// (check_adaptive_mesh_2d): a valid constrained Delaunay triangulation whose constrained edges
// are the pieces, input vertices at their place and number, curve points on their curve.
// Scale invariance: lengths are scale-free norms, the estimate is taken in the mesh's unit
// scale, the size's factor is a function of vertex counts: a domain scaled by 2^k (|k| <= 600)
// gives the same mesh scaled, bit for bit.
#pragma once

#include <array>
#include <cstdint>

#include "base/counter_table.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"

namespace exactmesh::generators {

/// A vertex is removed when every edge at it is shorter than this fraction of the size.
inline constexpr double kSteinerDerefineFraction = 0.5;
/// The size at a vertex is within this factor of its shortest edge (indicator_vertex_sizes).
inline constexpr double kSteinerMaxFactor = 4.0;
/// Derefinement passes per cycle (each an independent set; the sizes stay those of step 1).
inline constexpr std::uint32_t kSteinerDerefinePasses = 3;
/// Refinement runs per cycle under a vertex budget (the first and the coarser retries).
inline constexpr std::uint32_t kSteinerBudgetRuns = 4;
/// Under a vertex budget, each refinement run's Steiner budget is this many times the room
/// left (budget minus the vertices kept); a run that reaches it is redone with the size's
/// factor doubled.
inline constexpr std::uint32_t kSteinerRunBudgetFactor = 4;

struct SteinerRestartCounters2 {
    std::uint64_t cycles = 0;
    std::uint64_t finer_than_size = 0;  ///< vertices whose every edge is below the fraction
    std::uint64_t candidates = 0;       ///< of those, the independent set tried
    std::uint64_t removed = 0;
    std::uint64_t refused = 0;  ///< candidates vertex removal refused (corners, bends, ...)
    std::uint64_t piece_merges = 0;
    std::uint64_t refinement_runs = 0;
    std::uint64_t steiner_points = 0;      ///< points the kept refinements added
    std::uint64_t segment_splits = 0;      ///< of those, on pieces
    std::uint64_t budget_scalings = 0;     ///< cycles whose size was scaled up for the budget
    std::uint64_t budget_retries = 0;      ///< refinement runs redone coarser (over the budget)
    std::uint64_t budget_stops = 0;        ///< cycles left unrefined: no size fitted the budget
    std::uint64_t transfer_fallbacks = 0;  ///< new points outside the old mesh (neighbour mean)
};

inline constexpr std::array kSteinerRestartCounterNames2 =
    EM_COUNTER_TABLE(SteinerRestartCounters2, cycles, finer_than_size, candidates, removed, refused,
                     piece_merges, refinement_runs, steiner_points, segment_splits, budget_scalings,
                     budget_retries, budget_stops, transfer_fallbacks);
static_assert(counter_table_complete(kSteinerRestartCounterNames2));

/// The background size of step 1 on `state` (its values the field at its vertices): the sizes
/// at its vertices, kSteinerMaxFactor, linear over its triangles (what the cycle refines to,
/// before a budget's scaling; tests measure the mesh against it).
SizeFunction steiner_restart_size_2d(const AdaptiveMesh2& state, const AdaptationOptions& options);

/// One cycle on `state` (state.values must hold the field at its vertices, at the time the
/// adaptation follows). options.indicator and options.threshold define the size (the target
/// indicator is threshold × its mean); options.max_vertices the budget; the smoothing and
/// movement options are not used (the mesh stays constrained Delaunay). Returns false when the
/// cycle neither removed nor added a vertex (then only the values changed: sampled at field.t).
/// @throws InputError as sample_field; GeometryError as delaunay_refinement_2d when a piece
///         becomes too short to split in double precision (the graded size reaching features
///         finer than doubles resolve, which a coarser first mesh did not need to split), and on
///         a bug (the message says so).
bool steiner_restart_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                              const FieldSource& field, SteinerRestartCounters2& counters);

}  // namespace exactmesh::generators
