// SPDX-License-Identifier: MIT
// Derefinement of an adaptive 2D mesh (issue 13): vertices where the field no longer needs them
// are removed, each by 2D constrained Delaunay vertex removal
// (triangulation/modification/vertex_removal_2d), so the mesh stays the constrained Delaunay
// triangulation of what is left. A vertex is a candidate when every edge at it has an indicator
// below derefine_threshold × the mean over all edges; candidates are taken in increasing vertex
// order, skipping any vertex next to one already taken (an independent set: the holes stay
// one star wide, and a feature is not erased by removing a whole neighbourhood at once). Never
// removed: the domain's input vertices (index < fixed_vertices), corners and ends of pieces,
// curve points where their two pieces are not straight (vertex_removal_2d refuses bends); a
// vertex on a straight run of pieces is removed and its two pieces merge into one (the curve
// parameters of the outer ends kept).
// The angle guard: a vertex goes only when the constrained Delaunay triangulation of its hole
// (what the removal will make there) has no angle smaller than both the smallest angle of its
// old star and kAngleFloorDegrees, decided by the exact compare_angles; so derefinement never
// makes the mesh's worst angle worse than the floor where it was not already. Without it a
// transient's repeated removals and midpoint insertions degraded the mesh into fans of slivers
// where the front met the far-field boundary (insertion, 78 steps: 118,098 vertices, then
// 345,435 in slivers the step after).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"

namespace exactmesh::generators {

/// The angle a removal may go down to when its star's smallest angle was larger.
inline constexpr double kAngleFloorDegrees = 10.0;

struct DerefinementOptions {
    EdgeIndicator indicator = EdgeIndicator::SecondDifference;
    double threshold = 0.2;     ///< remove where every edge's indicator < threshold × mean
    double reference_mean = 0;  ///< > 0: the mean to use instead of the current mesh's
};

struct DerefinementCounters2 {
    std::uint64_t passes = 0;
    std::uint64_t candidates = 0;  ///< vertices with every edge below the threshold
    std::uint64_t removed = 0;
    std::uint64_t refused = 0;        ///< candidates refused (the angle guard, corners, bends, ...)
    std::uint64_t angle_refused = 0;  ///< of those, by the angle guard
    std::uint64_t piece_merges = 0;
};

inline constexpr std::array kDerefinementCounterNames2 = EM_COUNTER_TABLE(
    DerefinementCounters2, passes, candidates, removed, refused, angle_refused, piece_merges);
static_assert(counter_table_complete(kDerefinementCounterNames2));

/// The angle guard for vertex v of `mesh` (constrained flags, if any, on its pieces) whose
/// triangles are `star`: true when removing it keeps the angles (see the header comment), and
/// for stars the removal refuses anyway (pinched, a constraint end or junction, a merged edge
/// that meets the link), which it leaves to the removal to report.
bool removal_keeps_angles_2d(const triangulation::Triangulation2& mesh,
                             std::span<const triangulation::TriIdx> star, triangulation::VertIdx v);

/// One pass over `state` (state.values the field at its vertices); the surviving vertices keep
/// their values and their relative order (the input's keep their numbers).
/// @return the number of vertices removed.
std::uint64_t derefinement_pass_2d(AdaptiveMesh2& state, const DerefinementOptions& options,
                                   DerefinementCounters2& counters);

/// The removal step of a pass, for any rule that names the candidates (Steiner restart removes
/// where the mesh is finer than a size): of `candidates` (any order, repeats ignored), those at
/// or above state.fixed_vertices, taken in increasing vertex order as an independent set of the
/// mesh's `edges` (mesh_edges_2d of state.mesh.triangles), are removed where vertex_removal_2d
/// allows it; pieces merge, values and curve flags follow, as derefinement_pass_2d. Counts
/// candidates (the independent set), removed, refused and piece_merges; not passes.
/// `old_to_new` (when not null) receives the new number of each old vertex (kNone: removed).
/// @return the number of vertices removed.
std::uint64_t remove_vertex_set_2d(AdaptiveMesh2& state,
                                   std::span<const triangulation::VertIdx> candidates,
                                   std::span<const triangulation::VertIdx> edges,
                                   DerefinementCounters2& counters,
                                   std::vector<triangulation::VertIdx>* old_to_new = nullptr);

}  // namespace exactmesh::generators
