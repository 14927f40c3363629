// SPDX-License-Identifier: MIT
// Region volume bounds as a size (TetGen's -a with region constraints, for the generators driven
// by an edge length; the 3D counterpart of generators/boundary/region_areas_2d's
// size_with_region_areas): in a region whose bound is V the size is at most the edge of the
// regular tetrahedron of volume V, a_V = cbrt(6 sqrt(2) V). The region holding a point is found
// by exact point location (orient3d, closed tetrahedra) among the bounded tetrahedra of the
// recovered mesh (ConformingMesh3::tet_max_volume, flooded by boundary recovery), through a
// uniform grid of their bounding boxes. A point on a face between regions takes the smallest
// bound of the tetrahedra holding it. Cost per evaluation: one grid cell's candidates.
#pragma once

#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"

namespace exactmesh::generators {

/// a_V = cbrt(6 sqrt(2) V), the edge of the regular tetrahedron of volume V, computed on V
/// scaled by a power of eight (the same bits times 2^k for V times 2^(3k)); +infinity for
/// V <= 0 (no bound).
double regular_tet_edge_of_volume(double volume);

/// `size` when no tetrahedron of `recovered` has a volume bound, else min(size, a_V of the
/// bounded region holding the point) (points in no bounded tetrahedron: `size`). The result
/// keeps its own copy of the bounded tetrahedra, so `recovered` may go.
SizeFunction3 size_with_region_volumes_3d(const SizeFunction3& size,
                                          const triangulation::ConformingMesh3& recovered);

}  // namespace exactmesh::generators
