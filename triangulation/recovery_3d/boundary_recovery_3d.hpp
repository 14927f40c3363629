// SPDX-License-Identifier: MIT
// Boundary recovery in 3D by conforming Delaunay refinement [Si15 §2 (TetGen's conforming
// mode); Shewchuk97 §3.4 and Ruppert95 §4 for the splitting rules, applied per segment and per
// facet plane; Murphy-Mount-Gable 2001 and Cohen-Steiner et al. 2002 for the conforming 3D
// problem]. The surface is never cut: Steiner points are added on segments and inside facets
// until every subsegment is an edge and every subface a face of the Delaunay tetrahedralization.
//  1. The Delaunay tetrahedralization of the PLC's vertices (delaunay_3d, SoS: canonical).
//  2. Every subsegment that is not an edge is split: at the concentric-shell point (a power of
//     two from an input vertex where another segment meets it at an acute angle) or the
//     midpoint, each computed from the ORIGINAL segment's ends and a parameter, rounded once.
//  3. Each facet's vertices are triangulated in its plane (the 2D constrained Delaunay
//     triangulation of its projection, as triangulate_facets_3d); a subface that is not a face
//     gets its circumcenter (3D, in its plane, correctly rounded) unless that point encroaches
//     a subsegment of the facet (inside its diametral sphere, exact dot_sign_3d): then those
//     subsegments are split instead. Steps 2-3 repeat until nothing is missing.
//  4. Tetrahedra reached from the hull or a hole point's tetrahedron without crossing a subface
//     are removed; region attributes spread by the same flood fill.
// Invariant after every round: the tetrahedralization is the (SoS-perturbed) Delaunay one of
// the current points; each round rebuilds it from the point set (as insertion_adaptation_3d
// does), which by SoS uniqueness equals incremental Bowyer-Watson insertion of the new points.
// Cost: O(rounds * n log n). Predicates: orient3d, insphere_sos (Delaunay), orient2d and
// incircle (facet CDTs), dot_sign_3d (encroachment). Constructions: point_on_segment_3d,
// triangle_circumcenter_3d (predicates/constructions).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

struct BoundaryRecovery3Options {
    /// Most Steiner points allowed; 0 takes 100 per input vertex plus 100,000. Exceeding it
    /// raises InputError naming the budget and the feature being recovered (PLCs with tiny
    /// input angles may need unbounded refinement).
    std::uint64_t max_steiner_points = 0;
    /// The insertion order's seed of the Delaunay tetrahedralizations it builds: other seeds
    /// give the same tetrahedra numbered otherwise (and so the generators after it, which visit
    /// them in that numbering, other meshes of the same domain).
    std::uint64_t seed = 1;
};

struct BoundaryRecovery3Counters {
    std::uint64_t segments = 0;             ///< input segments (facet polygon edges, each once)
    std::uint64_t segment_splits = 0;       ///< missing subsegments split at the midpoint
    std::uint64_t shell_splits = 0;         ///< missing subsegments split on a concentric shell
    std::uint64_t encroachment_splits = 0;  ///< subsegments split instead of a circumcenter
    std::uint64_t facet_splits = 0;         ///< subface circumcenters inserted
    std::uint64_t fallback_points = 0;      ///< subface centroids (circumcenter outside, nothing
                                            ///< encroached: the projection's metric differs)
    std::uint64_t insertions = 0;           ///< Steiner points inserted (sum of the above)
    std::uint64_t rounds = 0;               ///< Delaunay tetrahedralizations built
    std::uint64_t removed_tets = 0;         ///< exterior and hole tetrahedra flood-filled away
};

inline constexpr std::array kBoundaryRecovery3CounterNames = EM_COUNTER_TABLE(
    BoundaryRecovery3Counters, segments, segment_splits, shell_splits, encroachment_splits,
    facet_splits, fallback_points, insertions, rounds, removed_tets);
static_assert(counter_table_complete(kBoundaryRecovery3CounterNames));

struct BoundaryRecovery3Result {
    ConformingMesh3 mesh;
    BoundaryRecovery3Counters counters;
    /// Input points the domain leaves unused, one line each: hole and region points outside
    /// the domain (or a region point in a hole), input vertices outside it or in a hole (TetGen
    /// ignores them silently).
    std::vector<std::string> warnings;
};

/// The concentric-shell split parameter of segment p -> q [Ruppert95 §4, Shewchuk97 §3.4]: the
/// point at the power of two nearest half the subsegment [t_apex, t_far]'s length from the apex
/// (t_apex 0 or 1), towards t_far; NaN when the lengths leave the comfortable double range or
/// the point does not fall strictly inside. The length is measured on the segment's direction
/// scaled by a power of two, so the parameter is the same for the input scaled by 2^k. Shared
/// by boundary recovery and 3D Delaunay refinement.
double concentric_shell_parameter(const double* p, const double* q, double t_apex, double t_far);

/// The conforming Delaunay tetrahedralization of the PLC's domain (see above).
/// @throws InputError from validate_plc_3d (bad or self-intersecting PLC), when the vertices
///         are coplanar, when a facet corner lies inside one of the facet's segments, when the
///         Steiner budget is exceeded (naming the segment or facet), or when refinement
///         cascades (at small input angles) down to split points doubles cannot separate;
///         GeometryError when a facet's rounded points cannot be triangulated in its plane or
///         a missing subface admits no new point (neither seen on any test input).
BoundaryRecovery3Result boundary_recovery_3d(const Plc3& plc,
                                             const BoundaryRecovery3Options& options = {});

/// boundary_recovery_3d for a PLC whose facets within rounding of a plane are whole (see
/// triangulate_facets_3d). On such a crumpled facet (corners an ulp off one plane), the
/// projection's triangles can stay missing from the tetrahedralization however many points are
/// added (a rotated L-shaped prism with an attached free vertex: past 10^5 points, minutes).
/// So, when some facet is not exactly planar, recovery first runs with at most 4,096 plus 64
/// per input vertex Steiner points (fewer when `options` asks so), and its result is checked
/// exactly (check_boundary_conformity_3d: a vertex attached 2e-88 beside a whole facet's corner
/// left its subfaces not tiling it); past them, or when it does not conform, those facets are
/// split into their triangles (split_nonplanar_facets_3d(plc, true): `plc` changes, its split
/// warnings and one naming the budget are appended to `warnings`) and recovery runs again with
/// `options`. A PLC whose facets are all exactly planar goes straight to boundary_recovery_3d.
BoundaryRecovery3Result boundary_recovery_3d_whole_facets(Plc3& plc,
                                                          const BoundaryRecovery3Options& options,
                                                          std::vector<std::string>& warnings);

}  // namespace exactmesh::triangulation
