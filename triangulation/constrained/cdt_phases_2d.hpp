// SPDX-License-Identifier: MIT
// Internal to triangulation/: the phases of the constrained Delaunay builder, free functions
// over CdtState (cdt_state_2d.hpp), one file each. constrained_delaunay_2d (constrained_2d.cpp)
// and ConstrainedTriangulation2 (constrained_triangulation_2d.cpp) call them in order:
//   triangulate_vertices -> recover_segments (swap or cavity) -> [conform] ->
//   [bend_through_near_vertices, enclose_in_box: ConstrainedTriangulation2] -> mark_domain ->
//   finish.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "triangulation/constrained/cdt_state_2d.hpp"

namespace exactmesh::triangulation::detail {

// ---- cdt_insertion_2d.cpp: vertex insertion with Lawson flips that never cross a constraint --

/// The Delaunay triangulation of the input points (Green-Sibson), then the per-half-edge
/// constraint and per-vertex edge maps. Returns false (and sets cdt.collinear) when every point
/// lies on one line.
bool triangulate_vertices(CdtState& cdt);
/// Inserts mesh vertex p, located in triangle t, and restores the constrained Delaunay property
/// by Lawson flips. With `encroached` (the conforming phase): every constrained edge the new
/// vertex makes not locally Delaunay is appended there.
void insert_vertex(CdtState& cdt, VertIdx p, TriIdx t, std::vector<Piece>* encroached = nullptr);
/// Splits the edge of e at p (on it) into four triangles; queues them on cdt.flip_stack.
void split_edge(CdtState& cdt, EdgeIdx e, VertIdx p);
/// Flips the edge of e (u -> v, apexes x and y) to x - y; returns the half-edge y -> x.
EdgeIdx flip(CdtState& cdt, EdgeIdx e);
bool locally_delaunay(CdtState& cdt, EdgeIdx e);
/// Lawson flips from the given edges until every unconstrained one is locally Delaunay.
void restore_delaunay(CdtState& cdt, std::vector<std::pair<VertIdx, VertIdx>>& edges);
/// After recovering the segments, four corners of a box around every vertex, so that no
/// segment lies on the convex hull (ConstrainedTriangulation2: splitting a hull segment at a
/// rounded point could leave the hull non-convex); the corners never reach the output.
void enclose_in_box(CdtState& cdt);

// ---- cdt_segment_recovery_2d.cpp: segments as pieces, the walk, swap and cavity recovery ------

/// How one piece whose walk crossed the given edges (none constrained, no vertex on the piece)
/// becomes an edge: recover_by_swaps or recover_by_cavity.
using RecoverCrossed = void (*)(CdtState& cdt, const Piece& piece,
                                const std::vector<EdgeIdx>& crossed);
void recover_by_swaps(CdtState& cdt, const Piece& piece, const std::vector<EdgeIdx>& crossed);
void recover_by_cavity(CdtState& cdt, const Piece& piece, const std::vector<EdgeIdx>& crossed);
/// Every input segment as a chain of constrained edges: crossings and vertices on segments
/// split them (warnings), the rest is recovered by `recover`.
void recover_segments(CdtState& cdt, RecoverCrossed recover);
/// How the segment a -> b leaves vertex a: the half-edge a -> b itself, else a neighbour
/// exactly on the ray a -> b, else the edge (of the triangle whose angle at a the segment
/// enters) that it crosses first; each kNone when absent.
struct StarExit {
    EdgeIdx edge = kNone;
    VertIdx on_ray = kNone;
    EdgeIdx entry = kNone;
};
StarExit star_exit(CdtState& cdt, VertIdx a, VertIdx b);
/// Counts one step of recovery; GeometryError past a budget paid for by the input.
void guard(CdtState& cdt);

// ---- cdt_conforming_2d.cpp: conforming recovery and bends through near vertices -------------

/// Forgets the constraints, makes the triangulation Delaunay and splits (or bends) pieces until
/// every piece is an edge of it.
void conform(CdtState& cdt);
/// w may bend the chain of `segment` between its vertices a and b (the check's chain rule).
bool bend_candidate(const CdtState& cdt, std::uint32_t segment, VertIdx a, VertIdx b, VertIdx w);
/// The half-edge (e or its twin) whose apex lies within rounding of e's segment, strictly
/// between e's ends; kNone if neither.
EdgeIdx near_apex(const CdtState& cdt, EdgeIdx e);
/// The chain u - w - v replaces u - v = g, w the apex of g's triangle; returns w.
VertIdx bend_through_apex(CdtState& cdt, EdgeIdx g);
/// Before refinement (ConstrainedTriangulation2): every vertex within rounding of a segment
/// becomes a vertex of it.
void bend_through_near_vertices(CdtState& cdt);

// ---- cdt_domain_marking_2d.cpp: exterior, holes and regions ---------------------------------

/// A triangle containing (x, y) (closed), or an infinite one outside the convex hull.
TriIdx locate_point(CdtState& cdt, double x, double y);
/// Removes the exterior and the holes, assigns the regions' attributes; from here on the marks
/// follow every edit (CdtState::domain_marked).
void mark_domain(CdtState& cdt);

// ---- constrained_2d.cpp: the result ---------------------------------------------------------

/// The result in the caller's numbering; consumes the state.
Cdt2Result finish(CdtState& cdt);

}  // namespace exactmesh::triangulation::detail
