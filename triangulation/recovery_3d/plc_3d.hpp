// SPDX-License-Identifier: MIT
// The input of 3D mesh generation: a piecewise linear complex (PLC) [Si15 §1.2.1; the TetGen
// 1.5 manual §5.1.1], its facets triangulated in their own planes, and exact validity checks.
//
// Conventions:
//  - The types and numbering are triangulation/mesh/plc_3d.hpp's. Facet hole points are
//    projected into the facet's plane along the coordinate axis the facet's triangulation drops
//    (for a hole point in the plane that is the point itself; TetGen projects orthogonally).
//  - Surface triangles of one facet all share the orientation of the facet's reference corners:
//    its first three non-collinear polygon corners in the order listed.
// Every decision is an exact predicate (orient3d; orient2d on a coordinate projection, which
// is exact because dropping a coordinate is): scaling every coordinate by 2^k changes nothing.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

/// The facets triangulated: the PLC's own vertices only (no Steiner points).
struct SurfaceTriangles3 {
    std::vector<VertIdx> triangles;     ///< 3·#T vertex indices into Plc3::xyz
    std::vector<std::uint32_t> facets;  ///< #T: the facet each triangle comes from (0-based)

    std::uint32_t triangle_count() const {
        return static_cast<std::uint32_t>(triangles.size() / 3);
    }
};

/// Merges vertices at the same point (exactly; -0 equals 0) into the first of them, as TetGen
/// does ("Point #j is coincident with #i. Ignored!"): the others leave the PLC, the facets'
/// corners name the first instead (a corner then repeated next to itself in a polygon is
/// dropped), and Plc3::input_vertex and merged_vertex map between the two numberings (a
/// mesh's vertices back with Plc3::to_input_vertex; messages keep the input's numbers). Returns
/// one warning naming the merged vertices; nothing (and no change) when no two vertices share
/// a point, a coordinate is not finite or a corner index is out of range (validate_plc_3d_input
/// then names it in the input's numbering). At most once per PLC.
std::vector<std::string> merge_duplicate_vertices_3d(Plc3& plc);

/// Leaves out the facets with no area: those whose polygons list three or more corners but
/// name fewer than three vertices each (a triangle of an exported STL with two corners at one
/// point, or one that merge_duplicate_vertices_3d made so), and no polygon with three distinct
/// vertices. Their edges are their neighbours' in a closed surface; a facet written with only
/// 1- or 2-corner polygons, or naming a vertex out of range, is left for validate_plc_3d_input
/// to refuse. Returns one warning naming them (with their lines); nothing when there is none.
std::vector<std::string> drop_zero_area_facets_3d(Plc3& plc);

/// Leaves out each facet that repeats an earlier one: the same single polygon, its corners in
/// the same cyclic order either way round, and no holes (an exported STL's triangle written
/// twice). Corner indices out of range leave a facet alone. Returns one warning naming them
/// (with their lines and the facet each repeats); nothing when there is none.
std::vector<std::string> drop_repeated_facets_3d(Plc3& plc);

/// Checks the PLC's numbers: finite coordinates (vertices, holes, regions), facet corner
/// indices in range, at least one facet, no two vertices at the same point (exact).
/// @throws InputError naming the vertex, facet, polygon or point.
void validate_plc_3d_input(const Plc3& plc);

/// Triangulates every facet in its plane by the 2D constrained Delaunay triangulation
/// (triangulation/constrained) after dropping the coordinate of the largest normal component.
/// A facet whose corners lie within rounding of one plane (2^-46 of their largest coordinate
/// magnitude from the plane of three corners spanning a wide triangle: a rotated box's facet,
/// its corners rounded an ulp off it) counts as planar and is triangulated the same way.
/// @pre validate_plc_3d_input(plc) passed.
/// @throws InputError naming the facet: not coplanar beyond rounding (with the vertex off the
///         plane), degenerate
///         (no polygon of 3 corners, collinear corners, a polygon repeating a vertex, no area
///         left after the holes), polygons that cross (naming the two edges), a hole point on
///         a polygon edge, a corner outside the facet's area (a dangling point or segment).
SurfaceTriangles3 triangulate_facets_3d(const Plc3& plc);

/// Per facet, its input triangle (of `surface`) of largest area, or {kNone, kNone, kNone} for a
/// facet with none: the plane a facet's Steiner points must lie on within rounding, where its
/// first corners may be within rounding of collinear (a free vertex attached to an edge). Areas
/// are compared as (exponent, mantissa) of the cross product's 1-norm on differences scaled by
/// a power of two: exactly alike for the PLC scaled by 2^k, no square overflows; ties keep the
/// first triangle. Used by Delaunay refinement (its facet planes) and by the reading of a mesh
/// back onto the PLC (conforming_mesh_from_faces_3d), so both measure against the same plane.
std::vector<std::array<VertIdx, 3>> facet_largest_triangles_3d(const Plc3& plc,
                                                               const SurfaceTriangles3& surface);

/// Throws InputError naming the two facets (and their triangles) when two surface triangles of
/// different facets meet other than in a shared vertex or a shared edge. Exact (orient3d, and
/// orient2d on a projection for coplanar pairs); a uniform grid limits the pairs tested.
void check_surface_self_intersection_3d(const Plc3& plc, const SurfaceTriangles3& surface);

/// Throws InputError "surface not closed: edge (a, b) of facet f lies in only one surface
/// triangle" for the first such edge (in vertex order). Edges in more than two triangles are
/// allowed (internal facets of a general PLC). The mesh generators call it for domains that must
/// enclose a volume.
void check_surface_closed_3d(const Plc3& plc, const SurfaceTriangles3& surface);

/// What embed_free_vertices_3d did.
struct FreeVertexEmbedding3 {
    std::uint32_t on_segments = 0;  ///< free vertices inserted into the polygon edges they lie on
    std::uint32_t on_facets = 0;    ///< free vertices added to a facet as 1-corner polygons
    std::vector<VertIdx> vertices;  ///< those vertices, in index order
    /// attach_free_vertices_near_surface_3d: split_nonplanar_facets_3d's warnings for the
    /// facets the attached vertices bent off their planes
    std::vector<std::string> split_warnings;
};

/// Makes every free vertex (one in no facet polygon) that lies on the PLC's surface part of it,
/// as Triangle does with a vertex on a segment and TetGen with a point on a facet: a vertex
/// strictly inside a polygon edge (a segment) is inserted into that edge in every facet
/// polygon that has the edge (a 2-corner polygon is cut in two); a vertex inside a facet's area
/// (closed, off every segment) is added to the facet as a 1-corner polygon (an isolated point
/// of the facet). Free vertices off the surface are left as they are. Exact: orient2d on the
/// coordinate projections, orient3d, coordinate comparisons; boxes only select candidates.
/// Without it such a vertex is refused by validate_plc_3d (a facet's triangulation cannot
/// contain it, so no tetrahedralization could keep both).
/// @pre validate_plc_3d_input(plc) passed.
FreeVertexEmbedding3 embed_free_vertices_3d(Plc3& plc);

/// Makes every free vertex that lies off the surface but within rounding of it part of the
/// surface, as embed_free_vertices_3d does for one exactly on it: within 2^-48 of the largest
/// coordinate magnitude (of it and the feature; 16 units in the last place there) of a point of
/// a segment, not of its ends, it is inserted into that segment; else within that of the plane
/// of a facet triangle (triangulate_facets_3d), inside the triangle's projection, it is added
/// to the facet as a 1-corner polygon. Such a vertex (a point of a rotated box's facet or edge,
/// rounded off it) was a free vertex inside (or outside) the domain closer to the facet than
/// the rounding noise of every split point there: whether a point split on the facet beside it
/// lay above or below it was decided by rounding, so splits beside it were rejected and the
/// tetrahedra over the unsplit subfaces drove Delaunay refinement into its Steiner budget.
/// A facet it joins stays within rounding of its plane as a rule (the vertex is within 2^-48
/// of it, the facet's tolerance is 2^-46); one that does not is split here by
/// split_nonplanar_facets_3d (its warnings in split_warnings), so the facets are planar (within
/// rounding) after it as before. Exact: orient3d and orient2d at the corners of a box rounded
/// outward, which scales with the input (the same decision at 2^+-600). Vertices beside a corner
/// (the box holds a segment's end) are left free.
/// @pre split_nonplanar_facets_3d(plc) passed (the facets are planar).
FreeVertexEmbedding3 attach_free_vertices_near_surface_3d(Plc3& plc);

/// Replaces every facet whose corners do not lie within rounding of one plane (the rule of
/// triangulate_facets_3d, exact; a facet of a rotated box whose corners were rounded to
/// doubles is within it and stays whole: splitting it made its diagonals segments, small input
/// angles the input does not have) by the triangles of its polygons'
/// constrained Delaunay triangulation in the coordinate plane that its first three
/// non-collinear corners project to best (its holes removed, no vertex added), each triangle a
/// facet with the facet's marker and origin; the first keeps the facet's index, the others are
/// appended. As TetGen triangulates every facet in a projection. Returns one warning per facet
/// split. The triangles are planar and conforming; the surface is the polygon's triangulation,
/// which no choice of a plane could make flat.
/// @throws InputError when a non-planar facet's projection crosses itself (or as
///         triangulate_facets_3d does for a bad polygon).
/// With `within_rounding_too`, a facet whose corners are within rounding of a plane but not
/// exactly in one is split as well (boundary_recovery_3d_whole_facets' fallback).
/// @pre validate_plc_3d_input(plc) passed.
std::vector<std::string> split_nonplanar_facets_3d(Plc3& plc, bool within_rounding_too = false);

/// Whether every facet's corners lie exactly in one plane (exact orient3d): false when some
/// facet is planar only within rounding (see triangulate_facets_3d).
/// @throws InputError as triangulate_facets_3d does for a degenerate polygon.
bool facets_exactly_planar_3d(const Plc3& plc);

/// The preparation every 3D generator's input gets (`exactmesh tetmesh`), and `exactmesh check`
/// gives a PLC before checking a mesh of it: merge_duplicate_vertices_3d (a mesh of the result
/// numbers its vertices as the merged PLC does: Plc3::to_input_vertex gives the input's
/// numbers), drop_zero_area_facets_3d, drop_repeated_facets_3d, validate_plc_3d_input,
/// split_nonplanar_facets_3d, attach_free_vertices_near_surface_3d, embed_free_vertices_3d, then
/// validate_plc_3d and check_surface_closed_3d. Returns the warnings (facets split, vertices
/// attached), unprefixed.
/// @throws InputError as those do.
std::vector<std::string> prepare_plc_for_meshing_3d(Plc3& plc);

/// validate_plc_3d_input, triangulate_facets_3d and check_surface_self_intersection_3d; returns
/// the surface triangles. Closedness is checked separately (check_surface_closed_3d).
/// @throws InputError also when a free vertex lies on the surface (see embed_free_vertices_3d).
SurfaceTriangles3 validate_plc_3d(const Plc3& plc);

/// The PLC's segments as boundary recovery, and everything built on its result (the
/// ConformingMesh3's `segments` and `feature_index`), numbers them: each polygon edge of each
/// facet (a polygon of two vertices is one segment) in facet and polygon order, first
/// occurrence first, its ends sorted.
struct PlcSegments3 {
    std::vector<std::array<VertIdx, 2>> ends;
    std::vector<std::vector<std::uint32_t>> facets_of_segment;  ///< facets holding it, in order
    std::vector<std::vector<std::uint32_t>> segments_of_facet;  ///< in order of first meeting
};
PlcSegments3 plc_segments_3d(const Plc3& plc);

}  // namespace exactmesh::triangulation
