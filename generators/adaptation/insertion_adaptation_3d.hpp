// SPDX-License-Identifier: MIT
// Delaunay point-insertion adaptation in 3D (issue 13): the 2D method
// (insertion_adaptation_2d.hpp) on the Delaunay tetrahedralization of a convex domain (a box):
// the indicator on every edge, flags above threshold × mean (or the largest under a vertex
// budget), the one-pass isotropic closure (every tetrahedron with a flagged edge gets all six),
// a point at each flagged edge's rounded midpoint, and the Delaunay tetrahedralization of all
// points (delaunay_3d, the same shared symbolic perturbation: the unique tetrahedralization
// Bowyer-Watson insertion of the new points would give, built again because 3D Laplacian
// smoothing may have moved the vertices since the last one), then smoothing and the field.
// Boundary faces stay conforming: a midpoint of a hull edge is kept only when it lies exactly
// (orient3d zero) in the plane of every hull face at that edge — always on an axis-aligned box
// (the mean of two equal coordinates is that coordinate); one rounded off a slanted face is
// left out (counted), so the hull never changes: every hull face of the result lies in a plane
// of the input's hull (check_adaptive_mesh_3d).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::generators {

struct AdaptiveMesh3 {
    triangulation::Tetrahedralization3 mesh;
    std::uint32_t fixed_vertices = 0;  ///< the input's vertices, never moved
    std::vector<double> values;        ///< the field at each vertex
    /// 9·#F: the input's hull faces (three points each), the planes the boundary must keep.
    std::vector<double> hull_faces;
};

/// The state of a convex tetrahedral mesh (its hull faces recorded); fixed = its vertex count.
AdaptiveMesh3 make_adaptive_mesh_3d(triangulation::Tetrahedralization3 mesh);

struct InsertionCounters3 {
    std::uint64_t cycles = 0;
    std::uint64_t flagged_edges = 0;
    std::uint64_t closure_edges = 0;
    std::uint64_t inserted = 0;
    std::uint64_t boundary_points = 0;    ///< of the inserted, on hull faces
    std::uint64_t off_plane_skipped = 0;  ///< hull-edge midpoints rounded off a slanted face
    std::uint64_t smoothing_moves = 0;
    std::uint64_t smoothing_undone = 0;
    std::uint64_t movement_moves = 0;
    std::uint64_t movement_undone = 0;
};

inline constexpr std::array kInsertionCounterNames3 = EM_COUNTER_TABLE(
    InsertionCounters3, cycles, flagged_edges, closure_edges, inserted, boundary_points,
    off_plane_skipped, smoothing_moves, smoothing_undone, movement_moves, movement_undone);
static_assert(counter_table_complete(kInsertionCounterNames3));

/// One cycle; false when nothing was flagged (or the budget is reached), the mesh unchanged.
bool insertion_cycle_3d(AdaptiveMesh3& state, const AdaptationOptions& options,
                        const FieldSource& field, InsertionCounters3& counters);

/// The exact checks after a cycle: a valid tetrahedralization of its convex hull
/// (check_tetrahedralization_3d), the fixed vertices at `fixed_xyz`, and every hull face of
/// the mesh in the plane of one of the input's hull faces (orient3d zero for its three
/// vertices). Returns the first problem, or "".
std::string check_adaptive_mesh_3d(const AdaptiveMesh3& state, std::span<const double> fixed_xyz);

}  // namespace exactmesh::generators
