// SPDX-License-Identifier: MIT
// Exact topology and orientation check of a Tetrahedralization3 (any producer): every
// tetrahedron strictly positively oriented (exact orient3d), vertex indices in range and
// distinct, each face shared by at most two tetrahedra, neighbor links mutual and across the
// same face in opposite orientations (and present exactly where a face is shared), the boundary
// faces a closed surface (each directed boundary edge used as often as its reverse: once each
// on a manifold boundary, twice each where the domain touches itself along an edge). Optionally
// the boundary manifold and locally convex at every edge (then, being closed, it is the convex
// hull's boundary).
// The Delaunay check lives in check_3d (delaunay_3d's side); this file is topology only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

struct TopologyReport3 {
    bool ok = true;
    std::string problem;            ///< the first problem found, in words; empty when ok
    TetIdx tet = kNone;             ///< the first offending tetrahedron, when one is to blame
    std::vector<VertIdx> vertices;  ///< the vertices the problem names
    std::uint64_t interior_faces = 0;
    std::uint64_t boundary_faces = 0;
};

struct TopologyOptions {
    /// Also require every boundary edge to be convex (exact orient3d): the domain is then the
    /// convex hull of the vertices, as for a Delaunay tetrahedralization.
    bool convex_boundary = false;
};

TopologyReport3 check_topology_3d(const Tetrahedralization3& mesh, TopologyOptions options = {});

}  // namespace exactmesh::triangulation
