// SPDX-License-Identifier: MIT
// Exact check that a constrained triangulation covers the convex hull of its vertices less its
// holes, as `cdt --convex-hull` (Triangle's -c) makes it with hole points: the region is
// compared with the one a reference gives, the constrained Delaunay triangulation of the same
// vertices and constrained edges over the whole hull (itself checked exactly by
// check_constrained_delaunay_2d) less the triangles each hole point reaches without crossing a
// constrained edge. Two triangulations of one vertex set cover the same region exactly when
// they have the same boundary edges, so the comparison is of directed boundary edges; ties
// between cocircular points may be broken differently by the producer and do not matter.
#pragma once

#include <span>

#include "triangulation/checks/check_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// @param mesh a triangulation whose mesh.constrained flags its constrained edges (as
///        flag_constrained_edges_2d sets them); its vertices are every point of the input and
///        every vertex the producer added.
/// @param holes 2·#H hole points. A hole point outside the hull is ignored (as the producer
///        ignores it); one exactly on a constrained edge or a vertex names no side and fails.
/// @pre mesh passed check_constrained_delaunay_2d or check_conforming_mesh_2d (topology).
CheckReport check_hull_cover_2d(const Triangulation2& mesh, std::span<const double> holes,
                                CheckNumbering numbering = {});

}  // namespace exactmesh::triangulation
