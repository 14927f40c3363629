// SPDX-License-Identifier: MIT
// Exact validation of a constrained Delaunay triangulation of a domain (any producer: ours,
// CGAL, files). Topology: positive orientation, each directed edge at most once, constraint
// flags equal on both sides. Constrained Delaunay: every unconstrained edge between two
// triangles is locally Delaunay (exact incircle, cocircular accepted), which by the
// constrained Delaunay lemma [Lee-Lin 1986; Chew 1989] is equivalent to Chew's definition
// (no triangle's circumcircle contains a vertex visible from its interior); see
// proofs/invariants/constrained_delaunay.md. Segments: every input segment is present as a
// chain of constrained edges from one endpoint to the other.
#pragma once

#include <cstdint>
#include <span>

#include "triangulation/checks/check_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// @param mesh the triangulation; mesh.constrained flags the constrained edges (empty: none).
/// @param input_vertex_count vertices [0, input_vertex_count) are the input's; the others were
///        added (segment intersections, midpoints) and may lie off a segment by rounding.
/// @param segments 2·#S input segments (0-based). Each must be covered by a chain of pieces from
///        one endpoint to the other, through vertices within_rounding_of_segment (which includes
///        every point of the segment: added vertices are rounded, and a piece between rounded
///        vertices may pass exactly through an input vertex that is not exactly on the segment).
///        No step moves against the segment's direction: (w - v) . (b - a) >= 0, exactly.
///        Zero-length segments are skipped.
/// @param pieces 2·#P constrained edges as the producer reports them (Cdt2Result::pieces), or
///        empty: then the pieces are the flagged edges of the mesh, and every segment must be
///        meshed (convex-hull outputs). With pieces given, parts of segments may lie in removed
///        regions: each piece must be a flagged edge of the mesh, or not an edge of it and not
///        entering any triangle at its endpoints; and every flagged edge must be a piece.
CheckReport check_constrained_delaunay_2d(const Triangulation2& mesh,
                                          std::uint32_t input_vertex_count,
                                          std::span<const VertIdx> segments,
                                          std::span<const VertIdx> pieces = {},
                                          CheckNumbering numbering = {});

namespace detail {
/// check_constrained_delaunay_2d; with delaunay false, without the locally-Delaunay test
/// (check_conforming_mesh_2d adds its own tests).
CheckReport check_constrained_mesh_2d(const Triangulation2& mesh, std::uint32_t input_vertex_count,
                                      std::span<const VertIdx> segments,
                                      std::span<const VertIdx> pieces, CheckNumbering numbering,
                                      bool delaunay);
}  // namespace detail

}  // namespace exactmesh::triangulation
