// SPDX-License-Identifier: MIT
// Advancing-front Delaunay triangulation of a PSLG domain [Mavriplis95: "An advancing front
// Delaunay triangulation algorithm designed for robustness", J. Comput. Phys. 117; Mavriplis97:
// "Unstructured grid techniques", Annu. Rev. Fluid Mech. 29, §3.3; TanemuraMerriamOgawa83 for
// the gift-wrapping construction; seed material, issue 6 generator 4].
//  - The front starts as the discretized boundary (domain_boundary_2d: the domain on its left,
//    slits both ways); the shortest front edge ab is taken first (a heap).
//  - A candidate point p is placed ahead of ab on its bisector so that the circumradius of abp
//    meets the bound from the local size (h / sqrt 3, an equilateral triangle of side h; its
//    height within [l / 2, 1.1 l] for an edge of length l, 1.4 l where h > 2 l), kept
//    only when it is in the domain and not too close to front points or edges (a tolerance of
//    the placement, never of a decision).
//  - The triangle is abc for the c, among the nearby front points and p, left of ab whose circle
//    through a, b, c contains none of the other candidates (exact incircle with the repository's
//    SoS tie-break): the Tanemura-Merriam step. It is accepted only when no front point lies in
//    the closed triangle and no front edge enters the open triangle (exact orient2d tests);
//    otherwise c leaves the candidate set and the next Delaunay candidate is tried. A thin
//    triangle (smallest angle below 15 degrees, a preference in double precision) is passed
//    over until a wider search with the new point at half height finds nothing better.
//  - An edge with no acceptable candidate is postponed to the next round; a round that closes
//    no triangle, or an exhausted point budget, ends with the constrained Delaunay triangulation
//    of the remaining front (triangulation/constrained/constrained_2d), counted.
// Invariants (proofs/invariants/advancing_front_delaunay_2d.md): the front bounds exactly the
// untriangulated part of the domain, each directed edge with that part on its left, and no two
// front edges cross; every triangle is counter-clockwise (orient2d > 0) and inside the domain.
// Cost: O(n log n) for n output triangles (heap; each step queries a loose quadtree of front
// points and edges within O(1) of the local size). Predicates: orient2d, incircle_sos.
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

struct AdvancingFrontDelaunayOptions2 {
    /// The target edge length (must be bounded).
    SizeFunction size;
    /// A new point is not placed within this fraction of the new triangle's side length of a
    /// front point, nor within half of it of a front edge (a placement tolerance, in (0, 1)).
    double placement_tolerance = 0.6;
    /// Stop placing points after this many (0: automatic, 8 times the estimated element count
    /// plus 10^5); the remaining front is then closed by constrained Delaunay triangulation.
    std::uint64_t max_new_points = 0;
    /// A size asking for more new boundary points than this is refused (InputError) as the
    /// boundary is sampled (0: no limit but the discretization's own); the front's own budget
    /// above closes the front instead. The registry passes --max-steiner.
    std::uint64_t max_boundary_points = 0;
    /// The domain's constrained Delaunay triangulation (recovery Swap or Cavity).
    triangulation::Cdt2Options cdt;
};

struct AdvancingFrontDelaunayCounters2 {
    std::uint64_t triangles = 0;            ///< triangles formed by the front (closure apart)
    std::uint64_t new_points = 0;           ///< triangles closed with a newly placed point
    std::uint64_t existing_points = 0;      ///< triangles closed with a front point
    std::uint64_t rejected_candidates = 0;  ///< Delaunay candidates refused as not visible
    std::uint64_t rejected_placements = 0;  ///< new points not placed (outside, too close)
    std::uint64_t thin_skipped = 0;         ///< candidates passed over for a thin triangle
    std::uint64_t postponed_edges = 0;      ///< front edges that could not be closed when taken
    std::uint64_t rounds = 0;               ///< passes over the postponed edges
    std::uint64_t widened_searches = 0;     ///< edges retried with a wider candidate radius
    std::uint64_t closure_triangles = 0;    ///< triangles of the final constrained closure
    std::uint64_t closure_front_edges = 0;  ///< front edges left to the closure
    std::uint64_t incircle_calls = 0;
    std::uint64_t orient_calls = 0;
    std::uint64_t point_queries = 0;  ///< spatial-index queries (points and edges)
    std::uint64_t edge_queries = 0;
};

/// The counters' names as `exactmesh mesh --stats` prints them, in this order (one row
/// per field: counter_table_complete).
inline constexpr std::array kAdvancingFrontDelaunayCounterNames = EM_COUNTER_TABLE(
    AdvancingFrontDelaunayCounters2, triangles, new_points, existing_points, rejected_candidates,
    rejected_placements, thin_skipped, postponed_edges, rounds, widened_searches, closure_triangles,
    closure_front_edges, incircle_calls, orient_calls, point_queries, edge_queries);
static_assert(counter_table_complete(kAdvancingFrontDelaunayCounterNames));

struct AdvancingFrontDelaunayResult2 {
    /// Input vertices first (as constrained_delaunay_2d numbers them), the boundary points the
    /// size function added, then the new points; pieces, warnings as domain_mesh_result gives.
    triangulation::Cdt2Result mesh;
    AdvancingFrontDelaunayCounters2 counters;
};

/// Meshes the domain the PSLG's segments enclose (holes and exterior removed as
/// constrained_delaunay_2d removes them).
/// @throws InputError on bad input (as constrained_delaunay_2d), an unbounded size, a
///         placement tolerance outside (0, 1), or when the segments enclose no region.
/// @throws GeometryError when the discretized boundary touches itself (its rounded split points
///         beside a feature at the resolution of doubles), or the remaining front cannot be
///         closed without new points.
AdvancingFrontDelaunayResult2 advancing_front_delaunay_2d(
    const triangulation::Pslg& pslg, const AdvancingFrontDelaunayOptions2& options);
/// The same over the domain built once (its options replace options.cdt).
AdvancingFrontDelaunayResult2 advancing_front_delaunay_2d(
    const MeshDomain2& domain, const AdvancingFrontDelaunayOptions2& options);

/// The counters by name ("triangles", "new_points", ...), in declaration order.
std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const AdvancingFrontDelaunayCounters2& counters);

}  // namespace exactmesh::generators
