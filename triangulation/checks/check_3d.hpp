// SPDX-License-Identifier: MIT
// Exact validation of a 3D tetrahedralization given as flat arrays (any producer: ours, CGAL, a
// TetGen file). All decisions use exact predicates.
//
// Topology and hull (check_tetrahedralization_3d): every tetrahedron positively oriented
// (orient3d > 0); each face in one or two tetrahedra, with opposite orientations when in two;
// the neighbor array, when given, names exactly the tetrahedron across each face (kNone on the
// boundary); the boundary faces form one connected closed surface (each boundary edge in two
// boundary faces, oppositely directed), locally convex at every boundary edge, and embedded at
// every boundary vertex (a symbolic ray into one tetrahedron at the vertex lies in exactly one
// tetrahedron's cone there); every distinct point is a vertex and no two vertices coincide.
// Together these make the tetrahedra tile the convex hull of the points exactly once (the
// argument is in proofs/invariants/delaunay_3d.md). With no tetrahedron the check passes only
// when all points are coplanar.
// Delaunay (check_delaunay_3d): in addition, every interior face is locally Delaunay by the
// exact insphere (cospherical accepted: the apex is not strictly inside), which implies global
// Delaunay [Delaunay34 lemma].
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

struct Check3Report {
    bool ok = true;
    std::string problem;            ///< the first problem found, in words, empty when ok
    TetIdx tet = kNone;             ///< the first offending tetrahedron (0-based), when one is
    std::vector<VertIdx> vertices;  ///< the vertices the problem names (0-based), in its order
};

/// Topology and convex-hull checks of `tets` (4·#T vertex indices into xyz, 3·#V coordinates);
/// `neighbors` (4·#T, or empty to skip) as in Tetrahedralization3.
Check3Report check_tetrahedralization_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                                         std::span<const TetIdx> neighbors = {},
                                         Check3Numbering numbering = {});

/// check_tetrahedralization_3d, then every interior face locally Delaunay.
Check3Report check_delaunay_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                               std::span<const TetIdx> neighbors = {},
                               Check3Numbering numbering = {});

inline Check3Report check_delaunay_3d(const Tetrahedralization3& mesh,
                                      Check3Numbering numbering = {}) {
    return check_delaunay_3d(mesh.xyz, mesh.tets, mesh.neighbors, numbering);
}

}  // namespace exactmesh::triangulation
