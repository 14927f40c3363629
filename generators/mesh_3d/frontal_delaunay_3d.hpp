// SPDX-License-Identifier: MIT
// Frontal Delaunay tetrahedral mesh generation [Rebay93 "Efficient unstructured mesh generation
// by means of Delaunay triangulation and Bowyer-Watson algorithm" §3, carried to 3D as in
// Frey-George "Mesh generation" §7.3 (Delaunay-based point placement from a front); the 2D
// version is frontal_delaunay_2d]. Starts from a conforming Delaunay tetrahedralization of a
// PLC's domain (boundary_recovery_3d) and:
//  1. fits the boundary to the size h: subsegments longer than sqrt 2 h are split at their
//     midpoints, subfaces of circumradius above h / sqrt 2 at their circumcentres (with the
//     encroachment rules of delaunay_refinement_3d, whose insertion machinery it shares:
//     restricted_delaunay_3d.hpp), so every boundary triangle has edges of at most sqrt 2 h;
//  2. Rebay's scheme: a tetrahedron is accepted when its circumradius R <= acceptance * f,
//     f = sqrt(3/8) h (the circumradius of the regular tetrahedron of edge h, h at its
//     centroid); active when not accepted but beside an accepted one or a subface; waiting
//     else. The active tetrahedron with the largest R / f gets a point on the normal through the
//     circumcentre M of its front face (the one against an accepted tetrahedron or a subface
//     with the smallest circumradius r), on the tetrahedron's side, at Rebay's distance
//        d = rho + sqrt(rho^2 - r^2),  rho = min(max(f, r), (r^2 + q^2) / (2 q)),
//     q the distance from M to the tetrahedron's circumcentre (which lies on that normal): the
//     new tetrahedron on the face has circumradius f when possible, and the point stays inside
//     the circumsphere (d <= q). The point is inserted by Bowyer-Watson restricted to the
//     domain (never across a subface); it is rejected (the tetrahedron accepted, counted) when
//     the walk to it crosses a subface or leaves the domain, when it encroaches a subface or
//     subsegment of its cavity, when it is closer than min_distance * h to a cavity vertex, or
//     when its cavity cannot be kept star-shaped and conforming.
// Decisions that affect validity are exact (orient3d, insphere, dot_sign_3d,
// in_equatorial_sphere_3d). The size comparisons (R against f, subface circumradius and
// subsegment length against h) and the point placement are heuristic choices: they are computed
// in doubles on coordinate differences divided by a power of two near h (exact), so the same
// input and size times 2^k (k in [-300, 300]) give bit-identical decisions and the same mesh
// times 2^k; no exact predicate is needed since no invariant depends on them.
// Invariants: every subface stays a face, every subsegment an edge, every tetrahedron positively
// oriented; every input vertex kept. Every step inserts a point or accepts a tetrahedron, so the
// loop ends within the Steiner budget. Cost: a heap of active tetrahedra with lazy deletion,
// and cavities of about 17 tetrahedra on the box-with-hole and ellipsoid (measured). Where the
// recovered mesh has flat tetrahedra with huge circumspheres (the wing's finely sampled,
// extruded airfoil against coarse walls: R / f up to ~800), cavities grow to hundreds or
// thousands of tetrahedra and most such points are rejected: a point that encroaches a
// subface or subsegment of its seed or front tetrahedron, or comes too close to one of their
// vertices, is rejected before its cavity grows, and a cavity sheds all its tetrahedra facing
// away from the point in one round (restricted_delaunay_3d), with the same mesh; the wing at
// h 0.1 went from 126-200 s to 24 s (README "Known gaps"). Boundary split points within 2^-20 h
// of a vertex of their cavity are refused (they made edges of 1e-15 h). Known limit: the
// flat tetrahedra whose point is rejected are accepted (Rebay's rule) and stay in the output.
#pragma once

#include <array>
#include <cstdint>

#include "base/counter_table.hpp"
#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::generators {

struct FrontalDelaunay3Options {
    /// The target edge length h (required: InputError when undefined).
    SizeFunction3 size;
    /// Accept a tetrahedron when R <= acceptance * sqrt(3/8) h. In [1, 4]. 1.3: a little above
    /// the 2D default sqrt(3/2), since regular tetrahedra do not fill space and a good Delaunay
    /// tetrahedron has R / f near 1.1-1.2; not tuned further (with it, 87-93% of the edges of
    /// the sample domains are within [0.7, 1.4] h, frontal_delaunay_3d_test.cpp).
    double acceptance = 1.3;
    /// Reject a point closer than this times h to a vertex of its cavity. In [0, 1).
    double min_distance = 0.55;
    /// Most Steiner points (boundary and interior); 0: 10^6 plus 1,000 per input vertex
    /// (restricted_3d::steiner_budget_3d, as Delaunay refinement). A size whose estimate
    /// (domain volume / regular tetrahedron volume / 5 per vertex) exceeds the budget fails at
    /// once with InputError naming both; the budget does not grow with the estimate.
    std::uint64_t max_steiner_points = 0;
    /// Refuse a PLC whose narrow gaps ask for far more than the budget (gap_estimate_3d)
    /// before meshing; octree_mesh_3d, which asked it of the input already, turns it off for
    /// its band.
    bool estimate_gaps = true;
    /// Grade the size down to the PLC's local feature sizes (feature_graded_size_3d) with this
    /// gradation; 0: follow `size` as given. octree_mesh_3d turns it off for its band.
    double feature_gradation = 0.5;
};

struct FrontalDelaunay3Counters {
    std::uint64_t segment_splits = 0;       ///< boundary fitting: subsegment midpoints
    std::uint64_t subface_splits = 0;       ///< boundary fitting: subface circumcentres
    std::uint64_t interior_points = 0;      ///< points placed from the front and inserted
    std::uint64_t active_pops = 0;          ///< active tetrahedra taken from the heap
    std::uint64_t stale_pops = 0;           ///< heap entries rewritten or no longer active
    std::uint64_t forced_accepts = 0;       ///< tetrahedra accepted after a rejected point
    std::uint64_t rejected_outside = 0;     ///< the walk to the point met a subface/boundary
    std::uint64_t rejected_encroach = 0;    ///< the point encroaches a subface or subsegment
    std::uint64_t rejected_too_close = 0;   ///< closer than min_distance h to a cavity vertex
    std::uint64_t rejected_cavity = 0;      ///< its cavity could not stay star-shaped/conforming
    std::uint64_t boundary_rejections = 0;  ///< boundary-fitting splits that were rejected
    /// boundary fitting: subfaces whose circumcentre was a vertex already, split at their
    /// longest edge instead
    std::uint64_t longest_edge_subfaces = 0;
    std::uint64_t early_rejections = 0;  ///< of the encroaching and too close points, those
                                         ///< found by their seed or front tetrahedron alone,
                                         ///< before their cavity was grown
    std::uint64_t batched_removals = 0;  ///< cavity tetrahedra shrunk away beside the first
                                         ///< of their round (one regrowth for all)
    std::uint64_t cavity_tets = 0;       ///< tetrahedra replaced, summed over insertions
    std::uint64_t accepted_tets = 0;     ///< output tetrahedra within the acceptance
    std::uint64_t estimated_points = 0;  ///< the size's estimate (the budget's basis)
};

inline constexpr std::array kFrontalDelaunay3CounterNames = EM_COUNTER_TABLE(
    FrontalDelaunay3Counters, segment_splits, subface_splits, interior_points, active_pops,
    stale_pops, forced_accepts, rejected_outside, rejected_encroach, rejected_too_close,
    rejected_cavity, boundary_rejections, longest_edge_subfaces, early_rejections, batched_removals,
    cavity_tets, accepted_tets, estimated_points);
static_assert(counter_table_complete(kFrontalDelaunay3CounterNames));

struct FrontalDelaunay3Result {
    triangulation::ConformingMesh3 mesh;
    FrontalDelaunay3Counters counters;
    /// The size followed: options.size, graded to the feature sizes unless turned off.
    SizeFunction3 size;
};

/// Meshes the domain of `recovered` (boundary_recovery_3d's result for `plc`, or any mesh that
/// passes check_boundary_conformity_3d for it) as above. The recovered mesh's vertices keep
/// their indices; boundary points (VertexFeature3::Segment/Facet) and interior ones (Volume)
/// follow them.
/// @throws InputError when the size is undefined or not > 0 where evaluated, the options are
///         out of range, or the Steiner budget is exceeded (at once when the estimate does).
FrontalDelaunay3Result frontal_delaunay_3d(const triangulation::Plc3& plc,
                                           triangulation::ConformingMesh3 recovered,
                                           const FrontalDelaunay3Options& options);

}  // namespace exactmesh::generators
