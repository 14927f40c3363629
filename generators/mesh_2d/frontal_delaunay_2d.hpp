// SPDX-License-Identifier: MIT
// Frontal Delaunay mesh generation: advancing-front point placement, Bowyer-Watson insertion
// [Rebay93: "Efficient unstructured mesh generation by means of Delaunay triangulation and
// Bowyer-Watson algorithm", J. Comput. Phys. 106; Mavriplis97 survey §3; seed material, issue 6
// generator 5].
//  - The boundary is split to the size first (discretize_domain_boundary); its constrained
//    Delaunay triangulation is then refined from the boundary inwards. A triangle is accepted
//    when its circumradius R <= c f(centroid) (Rebay's criterion: R against a constant times the
//    ideal f), f = s / sqrt 3 the circumradius of the equilateral triangle of edge s (the size),
//    c = acceptance, sqrt(3/2) by default (R <= s / sqrt 2: every edge of an accepted triangle
//    at most sqrt 2 times the size); active when not accepted but beside an accepted triangle
//    or a boundary piece; waiting else.
//  - The active triangle with the largest R / f gets a point on the perpendicular bisector of
//    its shortest front edge (length 2p, midpoint M), towards its apex, at Rebay's distance
//        d = rho + sqrt(rho^2 - p^2),  rho = min(max(f(M), p), (p^2 + q^2) / (2 q)),
//    q the distance from M to the triangle's circumcenter: the new triangle on the edge has
//    circumradius f(M) when possible, between the limits d = p (the edge's diametral circle)
//    and d = q (the circumcenter). The point is inserted by Bowyer-Watson (the CDT's cavity).
//  - A point outside the domain, encroaching a boundary piece (closed diametral circle), or
//    closer than min_distance * s(X) to a vertex of its cavity is not inserted: the triangle is
//    accepted as it is (counted).
// Invariants (proofs/invariants/frontal_delaunay_2d.md): after every step the triangulation is
// constrained Delaunay (exact incircle, SoS) with every boundary piece a constrained edge; every
// step inserts a point or accepts a triangle; a budget of Steiner points ends in GeometryError.
// Cost: O(m log m) for m output vertices (a binary heap of active triangles, lazy deletion;
// O(1) expected cavities). Predicates: orient2d, incircle (SoS in the CDT, exact for the
// too-close scan), corner_dot_sign (encroachment).
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

struct FrontalDelaunayOptions2 {
    /// The target edge length; must be bounded (InputError otherwise). Inside a region of the
    /// PSLG with a maximum area A > 0, the smaller of it and sqrt(4 A / sqrt 3), the edge of the
    /// equilateral triangle of area A (region_areas_2d.hpp): accepted triangles then have an
    /// area of at most 1.5 A (the acceptance's circumradius bound, squared).
    SizeFunction size;
    /// Accept a triangle when its circumradius is at most this times s / sqrt 3 at its
    /// centroid (s / sqrt 3: the equilateral triangle of edge s). In [1, 4]. The default
    /// sqrt(3/2) (R <= s / sqrt 2) measured +1 degree of mean smallest angle over 1.5 on the
    /// sample domains, for 18% more triangles; edges stay within sqrt 2 of the size.
    double acceptance = 1.2247448713915890;
    /// Reject a point closer than this times s (at the point) to a vertex of its cavity. In
    /// [0, 1).
    double min_distance = 0.5;
    /// The constrained Delaunay triangulation (recovery Swap or Cavity; Conforming means Swap).
    triangulation::Cdt2Options cdt;
    /// Stop with GeometryError after this many Steiner points (0: automatic, at least 10^6 and
    /// 16 times the element count the size function asks for).
    std::uint64_t max_steiner_points = 0;
    /// A size asking for more new boundary points than this is refused (InputError) as the
    /// boundary is sampled (0: the budget above).
    std::uint64_t max_boundary_points = 0;
};

struct FrontalDelaunayCounters2 {
    std::uint64_t boundary_points = 0;     ///< points added on the boundary by the size
    std::uint64_t points_inserted = 0;     ///< Steiner points inserted inside the domain
    std::uint64_t accepted_triangles = 0;  ///< output triangles accepted by the radius criterion
    std::uint64_t forced_triangles = 0;    ///< output triangles above it (their point was rejected)
    std::uint64_t forced_accepts = 0;      ///< acceptances after a rejected point (with rewrites)
    std::uint64_t rejected_encroach = 0;   ///< points encroaching a boundary piece
    std::uint64_t rejected_outside = 0;    ///< points outside the domain
    std::uint64_t rejected_too_close = 0;  ///< points too close to a vertex (or equal to one)
    std::uint64_t rejected_no_conflict = 0;  ///< points outside their triangle's circumcircle
    std::uint64_t active_pops = 0;           ///< active triangles taken from the heap
    std::uint64_t stale_pops = 0;            ///< heap entries found rewritten or no longer active
    std::uint64_t cavity_triangles = 0;      ///< triangles replaced by the insertions, summed
    std::uint64_t closeness_incircle = 0;    ///< incircle calls of the too-close scan
    std::uint64_t orient_calls = 0;          ///< the CDT's (initial triangulation and edits)
    std::uint64_t incircle_calls = 0;
};

/// The counters' names as `exactmesh mesh --stats` prints them, in this order (one row
/// per field: counter_table_complete).
inline constexpr std::array kFrontalDelaunayCounterNames =
    EM_COUNTER_TABLE(FrontalDelaunayCounters2, boundary_points, points_inserted, accepted_triangles,
                     forced_triangles, forced_accepts, rejected_encroach, rejected_outside,
                     rejected_too_close, rejected_no_conflict, active_pops, stale_pops,
                     cavity_triangles, closeness_incircle, orient_calls, incircle_calls);
static_assert(counter_table_complete(kFrontalDelaunayCounterNames));

struct FrontalDelaunayResult2 {
    /// The mesh in the caller's numbering: input vertices first (as constrained_delaunay_2d
    /// numbers them), then the boundary points, then the interior ones; exterior and holes
    /// removed; pieces (with their input segment), attributes and the input's warnings.
    triangulation::Cdt2Result mesh;
    FrontalDelaunayCounters2 counters;
};

/// Meshes the domain the PSLG's segments enclose (holes and exterior removed as
/// constrained_delaunay_2d removes them).
/// @throws InputError on bad input (as constrained_delaunay_2d), an unbounded size, a size not
///         > 0 where it is evaluated, knobs out of range, or segments enclosing no region.
/// @throws GeometryError when the Steiner point budget is exhausted.
FrontalDelaunayResult2 frontal_delaunay_2d(const triangulation::Pslg& pslg,
                                           const FrontalDelaunayOptions2& options);
/// The same over the domain built once (its options replace options.cdt).
FrontalDelaunayResult2 frontal_delaunay_2d(const MeshDomain2& domain,
                                           const FrontalDelaunayOptions2& options);

/// The counters as (name, value) pairs, in declaration order (the CLI's --stats).
std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const FrontalDelaunayCounters2& counters);

}  // namespace exactmesh::generators
