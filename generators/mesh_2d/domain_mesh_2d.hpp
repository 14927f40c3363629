// SPDX-License-Identifier: MIT
// The common result of the 2D mesh generators: their triangles over the discretized boundary's
// vertices (and their own), assembled as a triangulation::Cdt2Result (neighbours, constraint
// flags on the boundary pieces, pieces with their input segment, the input's numbering), so that
// the CLI writes every generator's mesh the same way and every check applies to it.
#pragma once

#include <vector>

#include "generators/boundary/domain_boundary_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// @param xy 2·#V coordinates starting with boundary.xy (the generator's vertices after them).
/// @param triangles 3·#T vertex indices into xy, counter-clockwise.
/// @return mesh {xy, triangles, neighbours, constrained flags on the edges that are pieces},
///         input_vertex_count, merged_into, pieces and piece_segment from the boundary, the CDT's
///         warnings and counters.
/// @throws InternalError when two triangles share a directed edge or an index is out of range.
triangulation::Cdt2Result domain_mesh_result(const DomainBoundary2& boundary,
                                             std::vector<double> xy,
                                             std::vector<triangulation::VertIdx> triangles);

}  // namespace exactmesh::generators
