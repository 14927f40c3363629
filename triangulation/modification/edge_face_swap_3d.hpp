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
// The constrained variant (SwapConstraints3) keeps locked faces and edges (a conforming mesh's
// subfaces and subsegments), starts from given faces only, and lets the caller veto a swap and
// follow each one (sliver_removal_3d).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

enum class SwapCriterion3 { Delaunay, MaxMinDihedral, MinMaxDihedral, VolumeEdge };

/// "delaunay", "max-min-dihedral", "min-max-dihedral", "volume-edge"; throws InputError naming
/// the known ones otherwise.
SwapCriterion3 swap_criterion_3d_from_name(std::string_view name);
std::string_view swap_criterion_3d_name(SwapCriterion3 criterion);

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
    /// Constrained swapping: valid swaps refused because they remove a locked face or edge.
    std::uint64_t locked = 0;
    /// Constrained swapping: swaps the criterion preferred but the caller's veto refused.
    std::uint64_t vetoed = 0;

    std::uint64_t flips() const { return flips_23 + flips_32 + flips_44 + flips_22; }
};

/// The name table of EdgeFaceSwapCounters (base/counter_table.hpp): --stats prints it in this
/// order.
inline constexpr std::array kEdgeFaceSwapCounterNames =
    EM_COUNTER_TABLE(EdgeFaceSwapCounters, faces_examined, edges_examined, flips_23, flips_32,
                     flips_44, flips_22, not_flippable, stalled_faces, locked, vetoed);
static_assert(counter_table_complete(kEdgeFaceSwapCounterNames));

/// Swaps until no face wants a swap under `criterion`.
/// The flips themselves are flip_3d's (plan_flip_3d, apply_flip_3d).
/// @pre mesh valid (make_tet_mesh_3d). Vertex indices are the SoS ranks.
EdgeFaceSwapCounters swap_faces_3d(TetMesh3& mesh, SwapCriterion3 criterion);

/// Faces and edges that a constrained swap never removes, as sorted vertex tuples (any
/// orientation locks the face). Call finish() after the last add and before any query.
class SwapLocks3 {
  public:
    void add_face(VertIdx a, VertIdx b, VertIdx c);
    void add_edge(VertIdx a, VertIdx b);
    void finish();
    bool face_locked(VertIdx a, VertIdx b, VertIdx c) const;
    bool edge_locked(VertIdx a, VertIdx b) const;
    bool empty() const { return faces_.empty() && edges_.empty(); }

  private:
    bool marked(VertIdx v) const { return v < marked_.size() && marked_[v] != 0; }
    std::vector<std::array<VertIdx, 3>> faces_;
    std::vector<std::array<VertIdx, 2>> edges_;
    /// Per vertex: whether it is a corner of a locked face or edge. Tested before the sorted
    /// lists are searched: most faces and edges of a mesh have a corner off every lock.
    std::vector<std::uint8_t> marked_;
};

/// Whether the flip removes a locked face or edge: a face (edge) of an old tetrahedron that is
/// no face (edge) of a new one. A 2-2 swap always removes its two domain-boundary faces.
bool flip_removes_locked(const TetMesh3& mesh, const FlipPlan3& plan, const SwapLocks3& locks);

/// The constraints of a constrained swapping run; every member is optional.
struct SwapConstraints3 {
    /// Swaps removing one of these faces or edges are refused (counted as `locked`).
    const SwapLocks3* locks = nullptr;
    /// The faces examined first (then only the new tetrahedra's faces); empty: every interior
    /// face. Dead and boundary faces among them are skipped.
    std::span<const FaceIdx> seeds;
    /// Asked after the criterion prefers a swap and before it is made; false refuses it
    /// (counted as `vetoed`).
    std::function<bool(const FlipPlan3&)> accept;
    /// Told after each swap: the plan and the new tetrahedra's slots (created[i] holds
    /// plan.made[i]; the first plan.old_count of them reuse plan.old's slots in order).
    std::function<void(const FlipPlan3&, const std::vector<TetIdx>&)> on_flip;
    /// When set, swap_faces_3d examines a face only when this holds for one of its two
    /// tetrahedra (sliver removal: a tetrahedron below its angle threshold), and skips the
    /// others before planning anything.
    std::function<bool(TetIdx)> wanted;
};

/// What apply_constrained_flip_3d did with a planned flip.
enum class ConstrainedFlip3 { Made, Locked, Vetoed };

/// Makes the planned flip unless it removes one of `constraints`' locked faces or edges
/// (Locked) or the caller's accept refuses it (Vetoed); when made, its new tetrahedra's slots
/// go to `created` and on_flip is told. The one gate of swap_faces_3d and remove_edges_3d.
ConstrainedFlip3 apply_constrained_flip_3d(TetMesh3& mesh, const FlipPlan3& plan,
                                           const SwapConstraints3& constraints,
                                           std::vector<TetIdx>& created);

/// swap_faces_3d under `constraints`.
/// @pre as swap_faces_3d; criterion is not Delaunay when seeds are given.
EdgeFaceSwapCounters swap_faces_3d(TetMesh3& mesh, SwapCriterion3 criterion,
                                   const SwapConstraints3& constraints);

/// Convenience: make_tet_mesh_3d, swap_faces_3d, to_tetrahedralization_3d into `mesh`.
/// @throws InputError as make_tet_mesh_3d.
EdgeFaceSwapCounters swap_faces_3d(Tetrahedralization3& mesh, SwapCriterion3 criterion);

/// Whether the interior face f is locally Delaunay by insphere_sos (never a tie).
bool locally_delaunay_sos(const TetMesh3& mesh, FaceIdx f);

}  // namespace exactmesh::triangulation
