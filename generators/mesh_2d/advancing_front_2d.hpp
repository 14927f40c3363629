// SPDX-License-Identifier: MIT
// Advancing-front triangulation of a PSLG domain [Lo85: "A new mesh generation scheme for
// arbitrary planar domains", IJNME 21; Peraire-Vahdati-Morgan-Zienkiewicz87: "Adaptive remeshing
// for compressible flow computations", JCP 72; Lohner-Parikh88: "Generation of three-dimensional
// unstructured grids by the advancing-front method", IJNMF 8; Mavriplis97: "Unstructured grid
// techniques", Annu. Rev. Fluid Mech. 29, §2.2; seed material, issue 6 generator 2].
//  - The front starts as the discretized boundary (domain_boundary_2d): directed edges with the
//    unmeshed region on their left, slits in both directions. The shortest front edge ab goes
//    first (a min-heap by length).
//  - Its ideal apex p lies on the perpendicular bisector (the median) of ab at distance delta
//    from a and b: the size near the triangle, clamped to [0.55, 2] |ab| [Peraire87 §3].
//    Candidates: front vertices near p (nearest first), p itself, then front vertices farther
//    off by the shape of their triangle; the first acceptable one c makes triangle abc.
//  - Acceptable: abc strictly counter-clockwise, no front vertex in the closed triangle, neither
//    new edge crossing or touching a front edge away from shared ends (exact orient2d and dot
//    signs), so the triangle lies in the unmeshed region, inside the domain; a new point must
//    also lie a fraction of delta away from front vertices and edges (placement only, in
//    double precision).
//  - An edge with no acceptable candidate is postponed and retried (more candidates, points
//    nearer ab), then with every front vertex in widening boxes, which always succeeds: the
//    constrained Delaunay triangle on ab inside the unmeshed region is acceptable. Past a
//    triangle budget the remaining front is closed by its constrained Delaunay triangulation.
// Invariants (proofs/invariants/advancing_front_2d.md): the front is the directed boundary of the
// unmeshed region, its edges meet only at shared ends, and no vertex lies inside an edge; every
// triangle is strictly counter-clockwise and disjoint from the others' interiors; at the end the
// triangles tile the domain. Cost: O(log n) per triangle (heap, loose quadtree of front edges),
// plus tests against the O(1) front edges near it. Predicates: orient2d, corner_dot_sign
// (predicates/angle_comparisons_2d); the closure: constrained_delaunay_2d (orient2d, incircle).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

struct DomainBoundary2;

struct AdvancingFrontOptions2 {
    /// The target edge length (required: an unbounded size is an InputError).
    SizeFunction size;
    /// delta, the distance of the ideal apex from a and b, is the local size clamped to
    /// [min_side_ratio, max_side_ratio] |ab| [Peraire87]; 0.5 < min <= max.
    double min_side_ratio = 0.55;
    double max_side_ratio = 2.0;
    /// Front vertices within reuse_radius delta of the ideal apex are tried before it.
    double reuse_radius = 0.65;
    /// Front vertices within search_radius delta are tried after it (retries: twice that).
    double search_radius = 1.0;
    /// A new point at least min_vertex_distance delta from every front vertex and
    /// min_edge_distance delta from every front edge (retries: half of each).
    double min_vertex_distance = 0.5;
    double min_edge_distance = 0.3;
    /// On the first attempt, a farther front vertex is taken only when its triangle's shape
    /// 4 sqrt(3) area / (sum of squared sides) (1 for an equilateral one) is at least this.
    double min_shape = 0.4;
    /// Attempts with local candidates before an edge searches every front vertex (>= 1).
    std::uint32_t local_attempts = 2;
    /// Close the front by its constrained Delaunay triangulation after this many triangles
    /// (0: automatic, 8 times the count the size function asks for on the domain, plus 4 per
    /// boundary edge and 4096).
    std::uint64_t max_triangles = 0;
    /// A size asking for more new boundary points than this is refused (InputError) as the
    /// boundary is sampled (0: no limit but the discretization's own); the front's own budget
    /// above closes the front instead. The registry passes --max-steiner.
    std::uint64_t max_boundary_points = 0;
    /// The initial constrained Delaunay triangulation of the PSLG (domain_boundary_2d).
    triangulation::Cdt2Options cdt;
};

struct AdvancingFrontCounters2 {
    std::uint64_t triangles = 0;            ///< all triangles, closure included
    std::uint64_t new_points = 0;           ///< triangles whose apex is a new point
    std::uint64_t reused_points = 0;        ///< triangles whose apex is a front vertex
    std::uint64_t rejected_candidates = 0;  ///< candidates failing a placement or exact test
    std::uint64_t crossing_tests = 0;       ///< new edge against front edge tests
    std::uint64_t containment_tests = 0;    ///< front vertex in closed triangle tests
    std::uint64_t postponed_edges = 0;      ///< attempts that found no candidate (with repeats)
    std::uint64_t wide_searches = 0;        ///< triangles found by searching every front vertex
    std::uint64_t front_queries = 0;        ///< quadtree box queries
    std::uint64_t max_front_edges = 0;      ///< the longest front
    std::uint64_t closure_runs = 0;  ///< 1 when the budget (triangles or work) closed the front
    std::uint64_t closure_triangles = 0;  ///< triangles made by that closure
    std::uint64_t orient_calls = 0;
};

/// The counters' names as `exactmesh mesh --stats` prints them, in this order (one row
/// per field: counter_table_complete).
inline constexpr std::array kAdvancingFrontCounterNames = EM_COUNTER_TABLE(
    AdvancingFrontCounters2, triangles, new_points, reused_points, rejected_candidates,
    crossing_tests, containment_tests, postponed_edges, wide_searches, front_queries,
    max_front_edges, closure_runs, closure_triangles, orient_calls);
static_assert(counter_table_complete(kAdvancingFrontCounterNames));

struct AdvancingFrontResult2 {
    /// The mesh in the caller's numbering (domain_mesh_result): input vertices first, then the
    /// boundary's points, then the new points; pieces and warnings of the boundary.
    triangulation::Cdt2Result mesh;
    AdvancingFrontCounters2 counters;
};

/// Triangulates the domain the PSLG's segments enclose (holes and exterior removed as
/// constrained_delaunay_2d removes them) by an advancing front.
/// @throws InputError on bad input (as discretize_domain_boundary), an unbounded size, a size
///         that is not > 0 somewhere it is evaluated, or options out of range.
AdvancingFrontResult2 advancing_front_2d(const triangulation::Pslg& pslg,
                                         const AdvancingFrontOptions2& options);
/// The same over the domain built once (its options replace options.cdt).
AdvancingFrontResult2 advancing_front_2d(const MeshDomain2& domain,
                                         const AdvancingFrontOptions2& options);

/// The same from a boundary the caller assembled (local remeshing, issue 13: a void of a mesh
/// filled from its boundary): boundary.front is kept as it is, never split, so every front edge
/// is an edge of the result and every new point lies strictly inside the region it encloses;
/// boundary.cdt.mesh must triangulate that region (the automatic budget integrates the size
/// over it), boundary.xy holds every vertex the front and free_vertices name (other vertices in
/// it are left unused). options.cdt is used only by the closure.
/// @throws InputError as above on the size and options; GeometryError when two front edges
///         meet away from a shared end.
AdvancingFrontResult2 advancing_front_from_boundary_2d(const DomainBoundary2& boundary,
                                                       const AdvancingFrontOptions2& options);

/// The counters, named as `exactmesh mesh --stats` prints them.
std::vector<std::pair<std::string, std::uint64_t>> counter_list(const AdvancingFrontCounters2& c);

}  // namespace exactmesh::generators
