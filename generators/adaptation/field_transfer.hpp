// SPDX-License-Identifier: MIT
// Piecewise-linear transfer of a vertex field from one mesh to points of the next (issue 13):
// each point is located exactly in the old mesh (orient2d / orient3d), then the old mesh's
// linear interpolant is evaluated there. The value is the same whichever element holding the
// point the location finds: a point exactly at a vertex (every other barycentric sign zero)
// takes the vertex's value, a point exactly on an edge or a face (the signs say which, exactly)
// is interpolated from that edge's or face's vertices alone, taken in increasing vertex order,
// so both sides compute the same floating-point value. Barycentric weights are computed in the
// old mesh's unit scale (mesh_edges.hpp). A point in no element (outside the old domain, e.g. a
// boundary point moved onto a convex curve) gets NaN: the caller knows where it came from.
// Cost: 2D O(#T) to build the bucket grid, then about O(1) per point; 3D a visibility walk from
// the previous point's tetrahedron (queries in a coherent order are cheap), falling back to a
// scan of every tetrahedron when the walk does not arrive within a step limit.
#pragma once

#include <span>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

/// The old mesh's P1 interpolant at each point (2·#P coordinates).
std::vector<double> transfer_field_2d(std::span<const double> old_xy,
                                      std::span<const triangulation::VertIdx> old_triangles,
                                      std::span<const double> old_values,
                                      std::span<const double> points);

/// The same in 3D: old_neighbors as Tetrahedralization3::neighbors (across the face opposite
/// corner k), points 3·#P.
std::vector<double> transfer_field_3d(std::span<const double> old_xyz,
                                      std::span<const triangulation::VertIdx> old_tets,
                                      std::span<const std::uint32_t> old_neighbors,
                                      std::span<const double> old_values,
                                      std::span<const double> points);

/// After a transfer to moved points: every point that did not move (all `dim` coordinates of
/// `points` equal to `before`'s) or that lies in no old element (NaN) takes first_values[v],
/// the value it was made with.
void keep_values_of_unmoved(std::vector<double>& values, std::span<const double> points,
                            std::span<const double> before, unsigned dim,
                            std::span<const double> first_values);

}  // namespace exactmesh::generators
