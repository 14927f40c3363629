// SPDX-License-Identifier: MIT
// Advancing-front min-max triangulation (issue 14) after Marcum and Weatherill's AFLR
// [MarcumWeatherill95: "Unstructured grid generation using iterative point insertion and local
// reconnection", AIAA J. 33(9)]: points are generated from the current triangulation, never
// from a separate front data structure, and each is inserted into it by forced triangulation
// followed by local reconnection.
//  1. The coarse triangulation: the domain's boundary split to the size (discretize_domain_
//     boundary: it only splits, so a wall sampled finer than the size keeps its own points),
//     then its constrained Delaunay triangulation (ConstrainedTriangulation2, as frontal and
//     metric-delaunay build it; holes and exterior removed; segments that enclose nothing an
//     InputError): every boundary piece is a constrained edge from the start, so the boundary is
//     recovered before any interior point exists.
//  2. Stretched region (layers.first_height > 0): one stack per wall vertex (walls: the hole
//     loops of that triangulation, wall_loops_2d) along its smoothed wall normal (wall_normals_2d),
//     layer k at height first_height (1 + g + ... + g^(k-1)) from the wall vertex p, the point p +
//     t n rounded once (fma); all stacks advance together, layer by layer. A stack stops when its
//     next layer's thickness reaches its cell's tangential spacing (the mean distance from its last
//     point to its neighbours' points of the same layer: aspect ratio about 1), after
//     max_layers, when a neighbour stopped more than two layers below, or when the new point
//     would not be strictly inside a triangle or on an unconstrained edge of the current
//     triangulation reached from the stack's last point without crossing a constrained or
//     boundary edge (a collision with a wall or the outer boundary), would lie closer than
//     min_distance times its layer's thickness to an existing point, or closer to a
//     constrained edge away from its wall vertex than its height above that vertex (past the
//     middle of a gap: the opposing wall is near; without it stacks from the flap reached the
//     main element of the three-element domain and left triangles of 169 degrees).
//  3. Isotropic region, in passes. A triangle is accepted when its longest side is at most
//     `acceptance` times the size at its centroid (scale-free lengths). Front edges: the sides
//     of unaccepted triangles that are boundary or constrained edges or face an accepted
//     triangle (initially the boundary pieces: Marcum's front is exactly this interface). For
//     each, shortest first, the ideal point lies on its perpendicular bisector, on the
//     unaccepted side, at the equilateral height sqrt(3)/2 s of the size s at its midpoint. It
//     is rejected when the walk from the edge's triangle to it is blocked by a constrained or
//     boundary edge (outside the domain, or across a segment), when it lies on a constrained
//     edge or a vertex, when it lies in the closed diametral circle of a constrained or
//     boundary edge nearby (exact corner_dot_sign: a rule for points beside walls), or when an
//     existing point
//     (the points of this pass included: they are inserted at once) lies closer than min_distance
//     times s at the new point (found by a breadth-first search over the triangles whose bounding
//     boxes meet the square of that radius). Passes repeat until one inserts no point.
//  4. Insertion: the point splits the triangle that holds it into three, or the two triangles
//     beside the unconstrained edge it lies on into four (flip_2d.hpp's kernel); then Lawson
//     flips restore the Delaunay criterion around it (exact incircle with the shared symbolic
//     perturbation by vertex index; a flip only when the quadrilateral is strictly convex,
//     never across a constrained edge; each flip adds an edge at the new point and none is
//     removed, so the flips end even where the mesh is no longer Delaunay). After each layer
//     and each pass, min-max swapping (MinMaxAngle: the largest of the six angles strictly
//     decreases, exact compare_angles) seeded by the sides of the triangles its insertions
//     wrote (swap_edges_2d's local form on the half-edge mesh; a whole-mesh pass per layer and
//     per pass took 2.4 s of 3 on the three-element domain with layers, the local one 0.36 s
//     in all): the stretched cells' Delaunay diagonals make obtuse triangles; min-max removes
//     them.
//  5. A last min-max swapping over the whole mesh (swap_edges_2d), then the exact check.
// Choices: the points of a pass are inserted as they are made (Marcum makes a pass's points
// first, then inserts them), so the too-close test sees them through the mesh and no point grid
// of its own is needed (sizes range over five orders of magnitude with layers); the front is
// recomputed from the acceptance of every triangle at each pass, and an edge whose triangle an
// earlier insertion of the pass rewrote waits for the next pass.
// Invariants: after every insertion the triangles are strictly counter-clockwise (the point
// strictly inside its triangle, or exactly on an unconstrained edge; flips only of strictly
// convex quadrilaterals), every boundary piece is a constrained edge, and every input vertex
// and segment is present; checked exactly at the end (check_conforming_mesh_2d), a
// GeometryError if not. Scale: the decisions are exact predicates on the points, every length,
// size and height compared is scale-free (scale_free_norm), and every point is made by
// operations exact under power-of-two scaling, so a domain scaled by 2^k with its sizes and
// first height scaled alike gives the same mesh scaled.
// Cost: O(S L) layer points for S stacks and L layers; per insertion a walk, a search and flips
// (local: O(1) expected away from the layers' fans); O(T) per pass for the acceptance and the
// front; a final O(T) swapping.
// Predicates: orient2d, incircle_sos, corner_dot_sign, compare_angles (through swap_edges_2d).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/advancing_layers_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

struct MinMaxFrontOptions2 {
    /// The layers (first_height 0: none, the isotropic advancing front alone); quads refused.
    LayerParameters2 layers;
    /// The isotropic size; unbounded: graded_size_from_boundary of the domain.
    SizeFunction size;
    /// The most points the layers and the front may add (0: automatic, kMinMaxFrontPointBudget);
    /// the layers' count is checked before they are made, the front's as it grows (InputError).
    std::uint64_t max_steiner_points = 0;
    /// A triangle is accepted when its longest side is at most this times the size at its
    /// centroid; in [1, 2].
    double acceptance = 1.4142135623730951;
    /// A new point is rejected closer than this times the size (a layer point: its layer's
    /// thickness) to an existing point; in (0, 1).
    double min_distance = 0.6;
    /// Passes of averaging the wall normals with their neighbours' (>= 0, at most 100).
    int normal_smoothing_passes = 2;
};

struct MinMaxFrontCounters2 {
    std::uint64_t boundary_points = 0;  ///< points added on the boundary by the size
    std::uint64_t wall_loops = 0;
    std::uint64_t stacks = 0;        ///< one per wall vertex
    std::uint64_t layers = 0;        ///< the most layers any stack reached
    std::uint64_t layer_points = 0;  ///< points inserted by the layers
    std::uint64_t stopped_aspect_ratio = 0;
    std::uint64_t stopped_collision = 0;  ///< blocked walk, on a vertex or constrained edge
    std::uint64_t stopped_too_close = 0;
    std::uint64_t stopped_neighbour = 0;  ///< a neighbour stopped more than two layers below
    std::uint64_t stopped_max_layers = 0;
    std::uint64_t passes = 0;              ///< isotropic passes (the last inserts nothing)
    std::uint64_t front_edges = 0;         ///< front edges tried, summed over the passes
    std::uint64_t front_points = 0;        ///< points inserted by the front
    std::uint64_t closure_points = 0;      ///< circumcentres of triangles over the size, inserted
                                           ///< once a pass of the front inserted nothing
    std::uint64_t rejected_outside = 0;    ///< blocked walk, on a vertex or constrained edge
    std::uint64_t rejected_too_close = 0;  ///< too close to an existing point
    std::uint64_t edge_insertions = 0;     ///< points inserted on an edge (2 -> 4)
    std::uint64_t delaunay_flips = 0;      ///< Lawson flips after the insertions
    std::uint64_t min_max_swaps = 0;       ///< min-max swaps, summed over every swapping
    std::uint64_t triangles = 0;           ///< in the output
    std::uint64_t max_wall_aspect_ratio = 0;  ///< largest wall spacing / first height of a
                                              ///< stack with a layer (floor)
};

inline constexpr std::array kMinMaxFrontCounterNames =
    EM_COUNTER_TABLE(MinMaxFrontCounters2, boundary_points, wall_loops, stacks, layers,
                     layer_points, stopped_aspect_ratio, stopped_collision, stopped_too_close,
                     stopped_neighbour, stopped_max_layers, passes, front_edges, front_points,
                     closure_points, rejected_outside, rejected_too_close, edge_insertions,
                     delaunay_flips, min_max_swaps, triangles, max_wall_aspect_ratio);
static_assert(counter_table_complete(kMinMaxFrontCounterNames));

struct MinMaxFrontResult2 {
    /// Input vertices first (as constrained_delaunay_2d numbers them), then the boundary
    /// points, then the layer and front points in their order of insertion; pieces carry their
    /// input segment; no regional attributes.
    triangulation::Cdt2Result mesh;
    /// Per stack: its wall vertex and the layers it reached (tests, pictures).
    std::vector<std::pair<triangulation::VertIdx, std::uint32_t>> stack_layers;
    MinMaxFrontCounters2 counters;
};

/// The automatic point budget: 2^24.
inline constexpr std::uint64_t kMinMaxFrontPointBudget = std::uint64_t{1} << 24;

/// @throws InputError on bad input (as constrained_delaunay_2d), bad layer parameters, quads,
///         knobs out of range, segments enclosing no region, or the point budget exceeded.
/// @throws GeometryError when the final exact check fails (a bug).
MinMaxFrontResult2 min_max_front_2d(const MeshDomain2& domain, const MinMaxFrontOptions2& options);

/// The counters as (name, value) pairs, in declaration order (the CLI's --stats).
std::vector<std::pair<std::string, std::uint64_t>> counter_list(const MinMaxFrontCounters2& c);

}  // namespace exactmesh::generators
