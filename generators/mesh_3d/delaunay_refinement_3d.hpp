// SPDX-License-Identifier: MIT
// 3D Delaunay refinement [Shewchuk98 "Tetrahedral mesh generation by Delaunay refinement"
// §3-4; Si15 §3 (TetGen -q); Ruppert95 §4 / Shewchuk97 §3.4 concentric shells]. Starts from a
// conforming Delaunay tetrahedralization of a PLC's domain (boundary_recovery_3d) and inserts,
// one at a time and incrementally:
//  1. midpoints (or concentric-shell points next to an acute input vertex) of encroached
//     subsegments: a vertex or a rejected point strictly inside the diametral sphere;
//  2. circumcentres of encroached subfaces (strictly inside the equatorial sphere), unless
//     the circumcentre encroaches a subsegment or lies beyond one in the facet: then those
//     subsegments are split instead;
//  3. circumcentres of tetrahedra whose radius-edge ratio exceeds B or whose volume exceeds
//     the bound, unless the circumcentre encroaches a subsegment or subface of its cavity, or
//     lies beyond a subface (the walk towards it is blocked): then those are split instead.
//     A tetrahedron whose shortest edge joins vertices of two segments that meet at an input
//     vertex at less than 60 degrees, or of two facets that meet at an input segment at a
//     dihedral angle below 60 degrees (sharp facets, SharpFacets3: a point on one does not
//     split the other's subfaces, nor the segment between them, by encroachment), is not split
//     (the small-input-angle rule, SmallInputAngleRule3), nor one with an
//     edge below 2^-44 of its coordinates' magnitude (finer than doubles resolve there: its
//     circumcentre would round onto a grid too coarse to improve it).
// Insertion is Bowyer-Watson restricted to the domain: the cavity grows through faces whose
// far tetrahedron has the point strictly inside its circumsphere, never across a subface (other
// than the ones being split); it is then shrunk until it is star-shaped from the point (every
// kept boundary face sees it positively, exact orient3d) and keeps every subface, subsegment and
// vertex outside the split ones (a tetrahedron that must go holds the point: the insertion is
// rejected and counted). So every subface stays a face and the tetrahedra stay positively
// oriented; the mesh is Delaunay except where a cavity was shrunk (then constrained Delaunay).
// Decisions: orient3d, insphere, orient2d on facet projections, dot_sign_3d and
// predicates/tet_quality_3d (exact radius-edge, volume, equatorial sphere, 60-degree angle,
// scale-free). Constructions: circumcenter, triangle_circumcenter_3d, point_on_segment_3d.
// Termination: guaranteed by Shewchuk's analysis only for B > 2 and input angles of at least
// 90 degrees between segments and facets; otherwise the Steiner budget stops it with an error.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "base/counter_table.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::generators {

struct DelaunayRefinement3Options {
    /// B: tetrahedra with circumradius / shortest edge > B are split (> 0; TetGen -q's 2).
    double radius_edge_bound = 2.0;
    /// Tetrahedra of larger volume are split; <= 0: no bound. The recovered mesh's per-region
    /// bounds (ConformingMesh3::tet_max_volume, from Region3::max_volume) apply as well: each
    /// tetrahedron is held to the smaller of the two that are set (tet_volume_bound_3d).
    double max_volume = 0;
    /// Most Steiner points added by refinement; 0 takes 1,000 per input vertex plus 10^6.
    /// Exceeding it raises InputError naming the budget.
    std::uint64_t max_steiner_points = 0;
    /// When set, sliver_removal_3d with these options runs on the refined mesh before it is
    /// returned, taking the working mesh over as it is (its linked entry): the same result as
    /// calling it on the returned mesh (but for the numbering of the tetrahedra it makes),
    /// without the Tetrahedralization3 in between and its linking.
    std::optional<SliverRemoval3Options> sliver_removal;
};

struct DelaunayRefinement3Counters {
    std::uint64_t circumcenters = 0;            ///< tetrahedron circumcentres inserted
    std::uint64_t subface_splits = 0;           ///< subface circumcentres inserted
    std::uint64_t segment_splits = 0;           ///< subsegment midpoints inserted
    std::uint64_t shell_splits = 0;             ///< subsegment concentric-shell points inserted
    std::uint64_t encroached_segments = 0;      ///< subsegment splits queued by encroachment
    std::uint64_t encroached_subfaces = 0;      ///< subface splits queued by encroachment
    std::uint64_t blocked_circumcenters = 0;    ///< circumcentres beyond a subface (it is split)
    std::uint64_t rejected_points = 0;          ///< insertions whose cavity could not be kept valid
    std::uint64_t longest_edge_subfaces = 0;    ///< subfaces whose circumcentre was a vertex
                                                ///< already, split at their longest edge instead
    std::uint64_t projected_circumcentres = 0;  ///< subface circumcentres off the facet's plane
                                                ///< beyond rounding, moved onto it
    std::uint64_t shrunk_cavities = 0;          ///< cavities shrunk to stay star-shaped/conforming
    std::uint64_t batched_removals = 0;         ///< tetrahedra shrunk away beside the first of
                                                ///< their round (all facing away from the point)
    std::uint64_t forced_cavity_tets = 0;       ///< tetrahedra taken into a cavity past their
                                                ///< spheres: a seed's face did not see the point
    std::uint64_t walk_seeded_cavities = 0;     ///< circumcentre cavities retried from the walk's
                                                ///< tetrahedra (t and its centre not connected by
                                                ///< tetrahedra in conflict)
    std::uint64_t small_angle_tets = 0;         ///< bad tetrahedra spared by the small-angle rule
    std::uint64_t unresolvable_tets = 0;  ///< bad tetrahedra spared: an edge finer than doubles
                                          ///< resolve there (below 2^-44 of the coordinates)
    std::uint64_t cavity_tets = 0;        ///< tetrahedra replaced, summed over insertions
    std::uint64_t insertions = 0;         ///< Steiner points added by refinement
};

inline constexpr std::array kDelaunayRefinement3CounterNames =
    EM_COUNTER_TABLE(DelaunayRefinement3Counters, circumcenters, subface_splits, segment_splits,
                     shell_splits, encroached_segments, encroached_subfaces, blocked_circumcenters,
                     rejected_points, longest_edge_subfaces, projected_circumcentres,
                     shrunk_cavities, batched_removals, forced_cavity_tets, walk_seeded_cavities,
                     small_angle_tets, unresolvable_tets, cavity_tets, insertions);
static_assert(counter_table_complete(kDelaunayRefinement3CounterNames));

struct DelaunayRefinement3Result {
    triangulation::ConformingMesh3 mesh;
    DelaunayRefinement3Counters counters;
    /// Sliver removal's counters and time (steady clock) when options.sliver_removal is set.
    SliverRemoval3Counters slivers;
    double sliver_seconds = 0;
};

/// Refinement cannot mend a tetrahedron whose shortest edge is finer than doubles resolve at
/// its place: below 2^-44 of its largest coordinate magnitude (about 2^8 units in the last
/// place), circumcentres round to a grid too coarse to make well-shaped tetrahedra (a free
/// vertex 1e-30 above a facet vertex at 0.5 drove refinement into its budget for minutes). Such
/// a tetrahedron is spared, like the small-input-angle rule. The test is exact and scale-free:
/// each rounded coordinate difference is compared with a power of two (rounding is monotone, so
/// |fl(d)| < 2^e implies |d| < 2^e), taken from the exponent of the largest magnitude.
bool tet_finer_than_doubles_resolve_3d(const double* const (&p)[4]);

/// The volume bound of one tetrahedron: the smaller of the global bound and its region's bound,
/// each only when > 0 (TetGen's -a with region volume constraints); 0 when neither is set. The
/// smaller of two doubles is one of them, so the exact volume test sees the bound as given.
inline double tet_volume_bound_3d(double global_bound, double region_bound) {
    if (!(region_bound > 0)) return global_bound > 0 ? global_bound : 0;
    if (!(global_bound > 0)) return region_bound;
    return global_bound < region_bound ? global_bound : region_bound;
}

/// The volume bound of tetrahedron t of `mesh` under `global_bound` (tet_volume_bound_3d with
/// its region's bound, when the mesh carries per-region bounds).
inline double tet_volume_bound_3d(const triangulation::ConformingMesh3& mesh,
                                  triangulation::TetIdx t, double global_bound) {
    return tet_volume_bound_3d(global_bound,
                               t < mesh.tet_max_volume.size() ? mesh.tet_max_volume[t] : 0.0);
}

/// Refines `recovered` (boundary_recovery_3d's result for `plc`, or any mesh that passes
/// check_boundary_conformity_3d for it) as above; per-region volume bounds carried by
/// `recovered` (tet_max_volume) are applied with options.max_volume. Vertex numbering: the
/// recovered mesh's vertices keep their indices, refinement's follow them (VertexFeature3::Volume
/// inside).
/// @throws InputError when the options or a region bound are out of range, or the Steiner budget
/// is exceeded (at once when the volume bounds' estimate exceeds it).
DelaunayRefinement3Result delaunay_refinement_3d(const triangulation::Plc3& plc,
                                                 triangulation::ConformingMesh3 recovered,
                                                 const DelaunayRefinement3Options& options = {});

/// What the exact quality check of a refined mesh found.
struct RefinementQuality3 {
    std::uint64_t over_bound = 0;   ///< tetrahedra with radius-edge > B not spared
    std::uint64_t small_angle = 0;  ///< tetrahedra with radius-edge > B spared by the rule
    /// tetrahedra with radius-edge > B spared for an edge finer than doubles resolve there
    std::uint64_t unresolvable = 0;
    std::uint64_t over_volume = 0;  ///< tetrahedra over their volume bound (0 when none)
};

/// Exact check of every tetrahedron of `mesh` against B and its volume bound (the global one
/// and its region's, tet_volume_bound_3d), with the small-input-angle rule of
/// delaunay_refinement_3d (`mesh` as it returns it).
RefinementQuality3 check_refinement_quality_3d(const triangulation::ConformingMesh3& mesh,
                                               const DelaunayRefinement3Options& options);

}  // namespace exactmesh::generators
