// SPDX-License-Identifier: MIT
// The walls of a domain as the stretched generators see them (issue 14): the closed loops of
// its boundary with the domain outside them (hole loops: an airfoil component, an obstacle),
// each vertex's smoothed wall normal and tangential spacing, and the domain's boundary split to
// a size everywhere but along the walls (whose own vertices are the feet of the layers).
// Shared by stretched_delaunay_2d (the O-meshes' normals) and min_max_front_2d (its layer
// stacks). Predicates: orient2d (a loop's turn at its lowest vertex). Lengths scale-free
// (predicates::scale_free_norm): a domain scaled by 2^k gives the same normals and the spacing
// scaled by 2^k. Cost: O(V + T) for the loops, O(passes V) for the normals.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// A closed loop of the domain's boundary with the domain outside it.
struct WallLoop2 {
    std::vector<triangulation::VertIdx> vertices;  ///< in order, the domain on the left
    std::vector<std::array<double, 2>> normals;    ///< unit, into the domain (wall_normals_2d)
    std::vector<double> spacing;  ///< the mean length of the two sides at each vertex
};

/// The loops of boundary edges (triangle sides with no neighbour) of a domain's triangulation
/// whose traversal with the domain on the left turns clockwise (exact orient2d at the
/// lexicographically lowest vertex): holes, i.e. walls. A loop through a vertex with two
/// outgoing boundary edges (the boundary pinches there) is skipped.
std::vector<WallLoop2> wall_loops_2d(const triangulation::Triangulation2& mesh);

/// Each wall vertex's normal (the mean of its two sides' unit left normals, a cusp's own side's
/// normal, then averaged with its neighbours' (weights 1, 2, 1) `passes` times) and tangential
/// spacing (the mean of its two sides' lengths).
void wall_normals_2d(const triangulation::Triangulation2& mesh, WallLoop2& wall, int passes);

/// The domain's boundary split to `size` (discretize_domain_boundary) except the walls' sides,
/// kept as they are.
DomainBoundary2 discretize_except_walls(const MeshDomain2& domain, std::span<const WallLoop2> walls,
                                        const SizeFunction& size);

}  // namespace exactmesh::generators
