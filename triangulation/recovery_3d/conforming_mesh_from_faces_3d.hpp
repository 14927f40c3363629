// SPDX-License-Identifier: MIT
// The conforming structure of a tetrahedral mesh of a PLC read back from files (issue 15:
// `exactmesh check IN.poly OUT.ele` for a mesh `exactmesh tetmesh` or another mesher wrote),
// so that check_boundary_conformity_3d can check it: the files hold the vertices (the PLC's
// first, in its numbering), the tetrahedra and the faces that lie on facets (.face), not which
// segment or facet each Steiner point is on nor which facet each face belongs to. Recovered:
//  - the segments, the facets' polygon edges each once (as boundary recovery numbers them);
//  - a Steiner vertex of a face is a segment vertex when it lies within rounding of a segment
//    (within_rounding_of_segment in every coordinate projection, the check's own rule; the first
//    such segment when several, near a corner), else a facet vertex;
//  - each face's facet: among the facets that hold every one of its input and segment vertices
//    (a polygon corner of the facet, a vertex of one of its segments) the one whose input
//    triangles (triangulate_facets_3d) hold the projections of its facet vertices, exactly
//    (orient2d in the facet's projection); a face of facet vertices only takes the facet of a
//    face it shares a facet vertex with (propagated), or, with none, the first facet whose
//    triangles hold all three projections; its corners ordered as the facet is oriented;
//  - each segment's chain: its ends and its vertices in order along its largest coordinate.
// What cannot be recovered is reported, not guessed: a face on no facet, a vertex on none.
// Those choices are a reading of the files; check_boundary_conformity_3d then decides exactly
// whether the mesh conforms (a wrong reading can only make it fail).
// Cost: O(F + V_s S) with V_s the Steiner vertices on faces and S the segments (a bounding-box
// test first), plus the facet triangle tests per face.
#pragma once

#include <span>
#include <string>

#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

struct ConformingMeshReading3 {
    ConformingMesh3 mesh;
    /// Empty when every face and vertex was placed; else the first that was not, in words
    /// (0-based vertex numbers).
    std::string problem;
};

/// `mesh` (tetrahedra and neighbours linked) with `faces` (3·#F 0-based corners; the faces on
/// facets) read as a mesh of `plc` (prepared as for meshing: prepare_plc_for_meshing_3d).
ConformingMeshReading3 conforming_mesh_from_faces_3d(const Plc3& plc, Tetrahedralization3 mesh,
                                                     std::span<const VertIdx> faces);

}  // namespace exactmesh::triangulation
