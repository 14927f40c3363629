// SPDX-License-Identifier: MIT
// Exact validation of a triangulation of a domain that need not be Delaunay (the output of the
// quadtree and advancing-front generators, of smoothing, of any producer). Tests:
//  - topology: every triangle counter-clockwise (exact orient2d > 0), each directed edge in at
//    most one triangle, constraint flags equal on both sides of an edge;
//  - no fold at any vertex: the corners of the triangles around a vertex are pairwise disjoint
//    (sorted exactly by angle, each corner spans from one edge direction to the next one, and no
//    two edges leave the vertex in the same direction);
//  - every edge with a triangle on one side only is a piece of a segment (the mesh is closed by
//    the boundary);
//  - every input segment is a chain of pieces, as check_constrained_delaunay_2d tests it;
//  - every input vertex in the meshed region is a mesh vertex (check_input_vertices_kept_2d).
// Why this is enough (proofs/invariants/conforming_mesh_2d.md): the first two make the map from
// the mesh to the plane locally injective, so each point off the mesh's boundary is covered as
// many times as the boundary winds around it; the third puts that boundary on the segments.
// What it cannot see alone is a second layer over a region enclosed twice by pieces with the
// same orientation; the tests' check_quality_mesh adds the point-in-domain test of centroids.
#pragma once

#include <cstdint>
#include <span>

#include "triangulation/checks/check_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// Every input vertex (the first input_xy.size() / 2 vertices of the mesh, in the input's
/// numbering) is kept: its coordinates in the mesh are the input's, exactly, and when no
/// triangle uses it, it lies in no closed triangle of the mesh (it is outside the meshed region:
/// in a hole or outside the domain) unless a corner of that triangle has its coordinates (a
/// merged duplicate). Exact orient2d tests; the unused vertices are bucketed by x, so the cost
/// is O((V + T) log V) plus the tests of the unused vertices in each triangle's x-range.
CheckReport check_input_vertices_kept_2d(const Triangulation2& mesh,
                                         std::span<const double> input_xy,
                                         CheckNumbering numbering = {});

/// The arguments as check_constrained_delaunay_2d takes them (pieces empty: the flagged edges).
CheckReport check_conforming_mesh_2d(const Triangulation2& mesh, std::uint32_t input_vertex_count,
                                     std::span<const VertIdx> segments,
                                     std::span<const VertIdx> pieces = {},
                                     CheckNumbering numbering = {});

}  // namespace exactmesh::triangulation
