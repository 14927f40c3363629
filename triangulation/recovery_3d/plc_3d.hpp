// SPDX-License-Identifier: MIT
// The input of 3D mesh generation: a piecewise linear complex (PLC) [Si15 §1.2.1; the TetGen
// 1.5 manual §5.1.1], its facets triangulated in their own planes, and exact validity checks.
//
// Conventions:
//  - Indices are 0-based in memory. Plc3::first_index (0 or 1) is the numbering of the file the
//    PLC came from; every message names vertices and facets in that numbering (facets are
//    numbered in order from first_index, as TetGen's .face markers count them).
//  - A facet is TetGen's: one or more polygons in one plane. A polygon of n >= 3 corners is a
//    closed loop (corner n-1 joins corner 0); of 2 corners a segment inside the facet; of 1 an
//    isolated point. Facet hole points (3 each) mark the polygons' holes; each is projected into
//    the facet's plane along the coordinate axis the facet's triangulation drops (for a hole
//    point in the plane that is the point itself; TetGen uses the orthogonal projection).
//  - Region3::max_volume <= 0 means "no volume bound"; volume hole points are 3 per hole.
//  - Surface triangles of one facet all share the orientation of the facet's reference corners:
//    its first three non-collinear polygon corners in the order listed.
// Every decision is an exact predicate (orient3d; orient2d on a coordinate projection, which
// is exact because dropping a coordinate is): scaling every coordinate by 2^k changes nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

/// One facet: polygons (corner lists), hole points in the facet, a boundary marker.
struct Facet3 {
    std::vector<std::vector<VertIdx>> polygons;  ///< each: n >= 1 corner indices into Plc3::xyz
    std::vector<double> holes;                   ///< 3·#H points inside the facet's holes
    int marker = 0;                              ///< boundary marker (TetGen's facet marker)
};

/// A region point with its attribute and volume bound (TetGen's region list).
struct Region3 {
    double x = 0, y = 0, z = 0;
    double attribute = 0;
    double max_volume = -1;  ///< <= 0: no bound
};

/// A piecewise linear complex.
struct Plc3 {
    std::vector<double> xyz;        ///< 3·#V coordinates
    std::vector<Facet3> facets;     ///< #F facets
    std::vector<double> holes;      ///< 3·#H points inside volume holes
    std::vector<Region3> regions;   ///< #R region points
    std::uint32_t first_index = 0;  ///< numbering of vertices and facets in messages: 0 or 1

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
    const double* point(VertIdx v) const { return xyz.data() + 3 * static_cast<std::size_t>(v); }
};

/// The facets triangulated: the PLC's own vertices only (no Steiner points).
struct SurfaceTriangles3 {
    std::vector<VertIdx> triangles;     ///< 3·#T vertex indices into Plc3::xyz
    std::vector<std::uint32_t> facets;  ///< #T: the facet each triangle comes from (0-based)

    std::uint32_t triangle_count() const {
        return static_cast<std::uint32_t>(triangles.size() / 3);
    }
};

/// Checks the PLC's numbers: finite coordinates (vertices, holes, regions), facet corner
/// indices in range, at least one facet, no two vertices at the same point (exact).
/// @throws InputError naming the vertex, facet, polygon or point.
void validate_plc_3d_input(const Plc3& plc);

/// Triangulates every facet in its plane by the 2D constrained Delaunay triangulation
/// (triangulation/constrained) after dropping the coordinate of the largest normal component.
/// @pre validate_plc_3d_input(plc) passed.
/// @throws InputError naming the facet: not coplanar (with the vertex off the plane), degenerate
///         (no polygon of 3 corners, collinear corners, a polygon repeating a vertex, no area
///         left after the holes), polygons that cross (naming the two edges), a hole point on
///         a polygon edge, a corner outside the facet's area (a dangling point or segment).
SurfaceTriangles3 triangulate_facets_3d(const Plc3& plc);

/// Throws InputError naming the two facets (and their triangles) when two surface triangles of
/// different facets meet other than in a shared vertex or a shared edge. Exact (orient3d, and
/// orient2d on a projection for coplanar pairs); a uniform grid limits the pairs tested.
void check_surface_self_intersection_3d(const Plc3& plc, const SurfaceTriangles3& surface);

/// Throws InputError "surface not closed: edge (a, b) of facet f lies in only one surface
/// triangle" for the first such edge (in vertex order). Edges in more than two triangles are
/// allowed (internal facets of a general PLC). The mesh generators call it for domains that must
/// enclose a volume.
void check_surface_closed_3d(const Plc3& plc, const SurfaceTriangles3& surface);

/// validate_plc_3d_input, triangulate_facets_3d and check_surface_self_intersection_3d; returns
/// the surface triangles. Closedness is checked separately (check_surface_closed_3d).
SurfaceTriangles3 validate_plc_3d(const Plc3& plc);

}  // namespace exactmesh::triangulation
