// SPDX-License-Identifier: MIT
// Exact check of a conforming tetrahedralization of a PLC (ConformingMesh3, any producer; it
// lives beside boundary_recovery_3d because it triangulates the input facets with
// triangulate_facets_3d, but it does not include the algorithm it checks):
//  - the tetrahedra are a valid mesh (check_topology_3d: positive orientation by exact
//    orient3d, mutual neighbours, a closed boundary surface);
//  - every facet corner (input vertex of the PLC's facets) is a mesh vertex;
//  - every subsegment is an edge of the mesh, and the subsegments of each input segment form one
//    chain from its first end to its second;
//  - every subface is a face of the mesh; every boundary face of the mesh (in one tetrahedron)
//    is a subface, so the domain's boundary is made of facet pieces; each facet's subfaces have
//    the facet's orientation in its projection (exact orient2d, non-zero), no directed edge in
//    two of them, and their boundary chain is exactly the boundary of the facet's input
//    triangles with each input edge replaced by its subsegment chain, directed alike: with the
//    orientations, a winding-number argument makes them tile the facet exactly once (up to the
//    slivers between each segment and its chain of rounded Steiner points);
//  - every Steiner vertex lies within rounding of its recorded feature: a segment vertex
//    within_rounding_of_segment in each coordinate projection where its segment is not a point;
//    a facet vertex's projection (the facet's drop axis) inside the facet's input triangles
//    (triangulate_facets_3d), exactly, and the vertex within rounding of that triangle's plane
//    (beyond_rounding_of_plane: 2^-40 of the coordinates, in doubles; a subface circumcentre
//    2e-9 off its facet passed when the distance was not checked).
// No tetrahedron then has a subface's interior crossing it: the subfaces are faces of a valid
// tetrahedralization, whose tetrahedra have disjoint interiors and meet only in shared faces,
// so a face's interior meets no tetrahedron's interior.
#pragma once

#include <string>

#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

struct BoundaryConformityReport3 {
    bool ok = true;
    std::string problem;  ///< the first problem found, in words; empty when ok
};

/// @pre plc passed validate_plc_3d.
BoundaryConformityReport3 check_boundary_conformity_3d(const Plc3& plc,
                                                       const ConformingMesh3& mesh);

}  // namespace exactmesh::triangulation
