// SPDX-License-Identifier: MIT
// Edge removal: the n tetrahedra around an interior edge ab (3 <= n <= kMaxEdgeRemovalRing)
// replaced by the 2 (n - 2) tetrahedra of a triangulation of the ring of ab's link, each
// triangle joined to a and to b, the triangulation chosen by dynamic programming to be the best
// under a quality criterion [Klincsek80: G. T. Klincsek, "Minimal triangulations of polygonal
// domains", Annals of Discrete Mathematics 9, 1980; Shewchuk02: J. R. Shewchuk, "Two discrete
// optimization algorithms for the topological improvement of tetrahedral meshes", 2002;
// FreitagOllivierGooch97's "edge swapping"]. n = 3 is the 3-2 flip; larger rings reach
// tetrahedra no 2-3, 3-2 or 4-4 flip reaches: a flat tetrahedron of four boundary points
// coplanar before rounding, across the sharp edge of a turned wedge, stayed at 1e-14 degrees
// after frontal insertion's sliver removal, its diagonals in rings of 4 and 6.
// Every decision is exact: each new tetrahedron positive by orient3d, qualities compared by
// predicates/angle_comparisons_3d. The removal is made only when every new tetrahedron is
// strictly better than the worst old one, so the termination argument of edge_face_swap_3d.cpp
// (the sorted vector of qualities grows lexicographically) covers a run mixing both.
#pragma once

#include <cstdint>
#include <span>

#include "base/counter_table.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"

namespace exactmesh::triangulation {

struct EdgeRemovalCounters {
    std::uint64_t edges_examined = 0;  ///< unlocked edges tried
    std::uint64_t removals = 0;        ///< edges removed
    std::uint64_t locked = 0;          ///< removals refused: a locked face or edge would go
    std::uint64_t vetoed = 0;          ///< removals the caller's accept refused
};

inline constexpr std::array kEdgeRemovalCounterNames =
    EM_COUNTER_TABLE(EdgeRemovalCounters, edges_examined, removals, locked, vetoed);
static_assert(counter_table_complete(kEdgeRemovalCounterNames));

/// The removal of edge (a, b) of live tetrahedron t into `plan` (kind EdgeRemoval): the best
/// triangulation of the edge's ring under `criterion` (MaxMinDihedral, MinMaxDihedral or
/// VolumeEdge) among those whose every tetrahedron is positive and strictly better than the
/// ring's worst. False, with `plan` unspecified, when the edge is on the domain boundary, its
/// ring has more than kMaxEdgeRemovalRing tetrahedra, or no such triangulation exists.
bool plan_edge_removal_3d(const TetMesh3& mesh, TetIdx t, VertIdx a, VertIdx b,
                          SwapCriterion3 criterion, FlipPlan3& plan);

/// Removes, where plan_edge_removal_3d finds a removal, the edges of the given tetrahedra (each
/// still live when reached; the edges of a tetrahedron a removal made are not revisited),
/// under `constraints`' locks, accept and on_flip (its seeds are not used).
/// @pre mesh valid; criterion is not Delaunay.
EdgeRemovalCounters remove_edges_3d(TetMesh3& mesh, SwapCriterion3 criterion,
                                    std::span<const TetIdx> tets,
                                    const SwapConstraints3& constraints);

}  // namespace exactmesh::triangulation
