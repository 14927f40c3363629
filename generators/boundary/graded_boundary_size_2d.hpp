// SPDX-License-Identifier: MIT
// The default size of the generators that need one (quadtree, both advancing fronts, frontal)
// when the caller gives none: the input's own spacing at its vertices, extended into the domain
// with a bounded gradation, as Gmsh users get from a size extended from the boundary with a
// gradation field and Triangle users from -q alone (Delaunay refinement grades by itself):
//     h(x) = min over the vertices v of the domain's CDT of (h_v + g |x - v|),
// h_v the mean length of the boundary pieces at v (of its CDT edges when no piece ends there),
// capped by its shortest CDT edge (a vertex near another feature takes that gap as its size).
// h is g-Lipschitz and equals h_v at v. Why not the linear interpolation of the h_v over the
// CDT (size_from_boundary): inside a polygon of many close vertices (10^4 on a circle) that is
// the boundary spacing everywhere, 18 million triangles where Delaunay refinement makes 34,000.
// g = kDefaultGradation = 0.5, measured on that circle (exactmesh mesh circ.poly --quality):
// at 0.5 every front generator keeps a minimum angle of 18-19 degrees and makes 1.7-2.7 times
// Delaunay refinement's count (advancing front 57k, frontal 60k, advancing-front Delaunay 94k;
// the quadtree, whose leaves are at most the size, 290k); at 0.3 the counts are 1.6 times
// larger for 2-4 degrees more mean minimum angle; at 1.0 the advancing front breaks down
// (0.14 degrees). On a disk of boundary spacing h0 the count is about 2.31 * 2 pi / (g h0).
// Delaunay refinement needs no size (it grades by the local feature size) and keeps none.
// Evaluation: a kd-tree over the vertices, each node holding its bounding box and smallest h_v;
// a node is skipped when h_min + g * (distance to its box) exceeds the best value found divided
// by 1 + 2^-6, so the value is within 1.6% above the exact minimum, and a query visits a bounded
// number of nodes even at the centre of a circle, where every vertex is nearly as close.
// Scale invariance: lengths are taken in a frame rescaled by a power of two (no squared length
// overflows or underflows at 2^+-600), so every comparison and value scales exactly by 2^k.
#pragma once

#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// The gradation g of graded_size_from_boundary's default.
inline constexpr double kDefaultGradation = 0.5;

/// The size above for the domain of `pslg` (exterior and holes removed, as the generators do).
/// @param gradation g, finite and > 0.
/// @throws InputError as constrained_delaunay_2d; InputError when the segments enclose no region
///         or g is not finite and > 0.
SizeFunction graded_size_from_boundary(const triangulation::Pslg& pslg,
                                       const triangulation::Cdt2Options& cdt = {},
                                       double gradation = kDefaultGradation);

/// The same over the domain's triangulation, built once (MeshDomain2::triangulation).
/// @throws InputError as above.
SizeFunction graded_size_from_boundary(const MeshDomain2& domain,
                                       double gradation = kDefaultGradation);

/// `size` graded down to the domain's fine features, as the 3D generators do
/// (generators/mesh_3d/feature_size_3d): h'(x) = min(h(x), min over the sources v of
/// f_v + g |x - v|), f_v the vertex's shortest edge in the domain's CDT and its distance to each
/// segment piece opposite it in a triangle, at least 2^-44 of its coordinates; the sources are
/// the free vertices (on no segment) with f_v < h(v) / sqrt 2 and any vertex with f_v below
/// h(v) / 1024. Free vertices 1e-9 apart, or 1e-12 off a segment, otherwise sit in triangles of
/// 1e-6 degrees and less in the front and quadtree generators' meshes. A vertex on a segment
/// near another segment is not a source unless 1024 times finer than the size (the input's
/// own spacing, which the boundary's discretization follows). Scale-free as the size above.
/// The size itself when unbounded or when no vertex is a source.
/// @throws InputError as graded_size_from_boundary.
SizeFunction graded_to_fine_features(const MeshDomain2& domain, const SizeFunction& size,
                                     double gradation = kDefaultGradation);

}  // namespace exactmesh::generators
