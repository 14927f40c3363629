// SPDX-License-Identifier: MIT
// The min-max angle triangulation by edge insertion ("edge cutting") [EdelsbrunnerTanWaupotitsch92:
// H. Edelsbrunner, T. S. Tan, R. Waupotitsch, "An O(n^2 log n) time algorithm for the minmax
// angle triangulation", SIAM J. Sci. Stat. Comput. 13(4), 1992; the paradigm in
// BernEdelsbrunnerEppsteinMitchellTan93, "Edge insertion for optimal triangulations", DCG 10].
// Repeatedly take a triangle abc with the largest angle of the triangulation, at b; try to cut
// that angle by an edge bq (q any vertex seen from b through the open wedge abc): remove the
// edges crossing bq, retriangulate the two polygons on either side; keep the result when all
// new angles are strictly below angle abc. When no q succeeds, the triangulation minimizes the
// largest angle. Each polygon is retriangulated the paper's way, by ears cut with a stack as
// the walk from b to q meets the chain vertices, in O(m) (see edge_cutting_2d.cpp); only when an
// exact tie (or an angle the paper leaves untested) makes that outcome differ from the paper's,
// and the ears fail, the candidate is decided by an optimal (min-max angle) retriangulation
// by dynamic programming [Klincsek80], O(m^3), which succeeds whenever the paper's does.
// Cost: O(n) per candidate, so O(n^2) per largest-angle triangle in the worst case (the paper
// narrows the candidates to reach O(n log n) per step; every candidate is tried here).
// Constrained edges are never crossed, which gives the optimum among triangulations keeping
// them (the cut lemma holds there too). All angle decisions are exact (angle_comparisons_2d).
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "base/counter_table.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

struct EdgeCuttingCounters {
    std::uint64_t worst_triangles = 0;   ///< largest-angle triangles taken from the heap
    std::uint64_t insertions = 0;        ///< edges bq inserted (successful cuts)
    std::uint64_t candidates = 0;        ///< edges bq whose polygons were retriangulated
    std::uint64_t visited = 0;           ///< triangles entered by the visibility searches
    std::uint64_t removed_edges = 0;     ///< edges crossing an inserted bq, summed
    std::uint64_t dynamic_programs = 0;  ///< candidates retriangulated optimally (ties only)
};

/// The name table of EdgeCuttingCounters (base/counter_table.hpp): --stats prints it in this order.
inline constexpr std::array kEdgeCuttingCounterNames =
    EM_COUNTER_TABLE(EdgeCuttingCounters, worst_triangles, insertions, candidates, visited,
                     removed_edges, dynamic_programs);
static_assert(counter_table_complete(kEdgeCuttingCounterNames));

/// Improves `mesh` in place to a triangulation of the same vertices and domain minimizing the
/// largest angle (among those keeping the constrained edges).
/// @pre mesh.neighbors consistent (see link_neighbors_2d), triangles strictly counter-clockwise.
EdgeCuttingCounters edge_cutting_2d(Triangulation2& mesh);

/// The min-max angle triangulation of the points `xy` (2·#V doubles) over their convex hull:
/// the Delaunay triangulation (delaunay_2d, duplicates merged into their first occurrence),
/// then edge_cutting_2d. Vertex indices are the caller's. No triangle for collinear points.
/// @throws InputError (NonFiniteCoordinate) on NaN or infinite coordinates.
Triangulation2 min_max_angle_triangulation_2d(std::span<const double> xy,
                                              EdgeCuttingCounters* counters = nullptr);

}  // namespace exactmesh::triangulation
