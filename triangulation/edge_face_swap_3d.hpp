// SPDX-License-Identifier: MIT
// Edge-face swapping of a tetrahedralization under a pluggable criterion, the 3D analogue of
// Lawson's edge swapping [Joe89: B. Joe, "Three-dimensional triangulations from local
// transformations", SIAM J. Sci. Stat. Comput. 10(4), 1989; Joe91: "Construction of
// three-dimensional Delaunay triangulations using local transformations", CAGD 8, 1991;
// FreitagOllivierGooch97: "Tetrahedral mesh improvement using swapping and smoothing", IJNME
// 40, 1997]. The seed's eight steps: pop an interior face abc shared by tetrahedra abcd and
// abce; if segment de crosses the triangle's interior (exact orient3d), the 2-3 swap replaces
// the face by edge de; if de passes beyond an edge xy of the face and xy is shared by exactly
// the three tetrahedra xyzd, xyze, xyde, the 3-2 swap removes xy; if d, e, x, y are coplanar
// (de meets xy) the 4-4 swap (xy interior, four tetrahedra) or the 2-2 swap (xy on the boundary,
// two) turns xy into de. The swap is made when the criterion strictly prefers the new
// tetrahedra, and the faces of the new tetrahedra are queued; the loop ends when no face
// wants a swap. Criteria:
//  - Delaunay: insphere_sos(abcd, e) > 0 (the same decision for all four kinds): lifted
//    lower, so the loop reaches the Delaunay tetrahedralization when it does not stall; in 3D
//    it can stall (a face not locally Delaunay with no valid swap: proofs/invariants/
//    edge_face_swapping_3d.md and the fixed instance in the tests). Ties broken by index (SoS).
//  - MaxMinDihedral / MinMaxDihedral: the smallest (largest) dihedral angle among the new
//    tetrahedra is strictly larger (smaller) than among the old ones (exact, angle_comparisons_3d).
//  - VolumeEdge: the smallest volume-edge quality among the new tetrahedra is strictly larger.
// Termination of each criterion: proofs/invariants/edge_face_swapping_3d.md (and the .cpp).
// Works on any tetrahedralization (convex hull or not): the domain and its boundary never change.
#pragma once

#include <array>
#include <cstdint>
#include <vector>
#include <string_view>

#include "triangulation/flip_mesh_3d.hpp"
#include "triangulation/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

enum class SwapCriterion3 { Delaunay, MaxMinDihedral, MinMaxDihedral, VolumeEdge };

/// "delaunay", "max-min-dihedral", "min-max-dihedral", "volume-edge"; throws InputError naming
/// the known ones otherwise.
SwapCriterion3 swap_criterion_3d_from_name(std::string_view name);
std::string_view swap_criterion_3d_name(SwapCriterion3 criterion);

enum class FlipKind3 { None, Flip23, Flip32, Flip44, Flip22 };

/// Work counters of one swapping run.
struct EdgeFaceSwapCounters {
    std::uint64_t faces_examined = 0;  ///< interior faces popped from the queue and examined
    std::uint64_t edges_examined = 0;  ///< edge rings walked for a 3-2, 4-4 or 2-2 swap
    std::uint64_t flips_23 = 0;
    std::uint64_t flips_32 = 0;
    std::uint64_t flips_44 = 0;
    std::uint64_t flips_22 = 0;
    /// Examinations where no swap was valid (the union of the tetrahedra not convex).
    std::uint64_t not_flippable = 0;
    /// Delaunay only, counted after the loop: interior faces still not locally Delaunay (SoS),
    /// each with no valid swap. Zero exactly when the result is the Delaunay tetrahedralization.
    std::uint64_t stalled_faces = 0;

    std::uint64_t flips() const { return flips_23 + flips_32 + flips_44 + flips_22; }
};

/// Swaps until no face wants a swap under `criterion`.
/// @pre mesh valid (make_flip_mesh_3d). Vertex indices are the SoS ranks.
EdgeFaceSwapCounters swap_faces_3d(FlipMesh3& mesh, SwapCriterion3 criterion);

/// Convenience: make_flip_mesh_3d, swap_faces_3d, to_tetrahedralization_3d into `mesh`.
/// @throws InputError as make_flip_mesh_3d.
EdgeFaceSwapCounters swap_faces_3d(Tetrahedralization3& mesh, SwapCriterion3 criterion);

/// Makes the one valid swap (2-3, 3-2, 4-4 or 2-2) at the interior face of facet f, whatever
/// any criterion says (test and bench scaffolding: scrambling a Delaunay mesh). Returns the
/// kind made, None when the face has no valid swap.
FlipKind3 flip_face_3d(FlipMesh3& mesh, FacetIdx f);

/// A swap found at a face: the tetrahedra it removes and the positive ones it makes.
struct FlipPlan3 {
    FlipKind3 kind = FlipKind3::None;
    std::array<TetIdx, 4> old{};
    unsigned old_count = 0;
    std::array<Tet, 4> made{};
    unsigned made_count = 0;
};

/// The valid swap at the interior face of facet f (at most one exists), into `plan`; false
/// when there is none. `edges_examined`, when given, counts the edge rings walked.
bool plan_flip_3d(const FlipMesh3& mesh, FacetIdx f, FlipPlan3& plan, std::uint64_t* edges_examined = nullptr);

/// Makes a planned swap; the new tetrahedra's slots go to `created`.
void apply_flip_3d(FlipMesh3& mesh, const FlipPlan3& plan, std::vector<TetIdx>& created);

/// Whether the interior face of facet f is locally Delaunay by insphere_sos (never a tie).
bool locally_delaunay_sos(const FlipMesh3& mesh, FacetIdx f);

}  // namespace exactmesh::triangulation
