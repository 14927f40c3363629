// SPDX-License-Identifier: MIT
// The edges of a simplicial mesh (2D triangles or 3D tetrahedra), each once, and the one
// power-of-two scale the adaptation layer measures in (issue 13).
//  - mesh_edges_2d / mesh_edges_3d: every edge once as (u, v) with u < v, sorted, so that an
//    edge's number does not depend on the element order (indicators and flags are per edge).
//  - unit_scale_exponent: the exponent E of the bounding box's largest extent (frexp), so that
//    coordinates times 2^-E lie within about [-2^k, 2^k] of each other for the mesh's own k.
//    Multiplying by a power of two is exact, so every floating-point quantity the indicators,
//    gradients and error measures compute from scaled coordinates is bit for bit the same for a
//    mesh scaled by 2^k (|k| <= 600): no squared length or area overflows or underflows.
// Cost: O(E + V) (a counting sort by the smaller end).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

/// 2·#E vertex pairs (u < v), in increasing (u, v) order.
std::vector<triangulation::VertIdx> mesh_edges_2d(
    std::span<const triangulation::VertIdx> triangles);
std::vector<triangulation::VertIdx> mesh_edges_3d(std::span<const triangulation::VertIdx> tets);

/// The index of edge (u, v) (either order) in a sorted edge list, or kNone.
std::uint32_t find_mesh_edge(std::span<const triangulation::VertIdx> edges,
                             triangulation::VertIdx u, triangulation::VertIdx v);

/// Edge numbers by their ends in O(1) on average: the sorted edge list's rows grouped by their
/// first vertex (a CSR offset per vertex), so a lookup scans the few edges of the smaller end
/// instead of a binary search over all of them (the per-element lookups of the flags' closure
/// and the error measures were a third of an insertion cycle). Holds a view of `edges`.
class MeshEdgeIndex {
  public:
    explicit MeshEdgeIndex(std::span<const triangulation::VertIdx> edges);
    /// The index of edge (u, v) (either order), or kNone.
    std::uint32_t find(triangulation::VertIdx u, triangulation::VertIdx v) const;

  private:
    std::span<const triangulation::VertIdx> edges_;
    std::vector<std::uint32_t> first_;  ///< first_[u]: the first edge (u, *); size max u + 2
};

/// frexp exponent of the largest extent of the coordinates (dim per point) of the vertices the
/// elements use; 0 for an empty or single-point mesh.
int unit_scale_exponent(std::span<const double> coordinates, unsigned dim,
                        std::span<const triangulation::VertIdx> elements);

/// The coordinates times 2^-exponent (exact).
std::vector<double> scaled_coordinates(std::span<const double> coordinates, int exponent);

}  // namespace exactmesh::generators
