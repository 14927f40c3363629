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

    std::uint64_t flips() const { return flips_23 + flips_32 + flips_44 + flips_22; }
};

/// The name table of EdgeFaceSwapCounters (base/counter_table.hpp): --stats prints it in this
/// order.
inline constexpr std::array kEdgeFaceSwapCounterNames =
    EM_COUNTER_TABLE(EdgeFaceSwapCounters, faces_examined, edges_examined, flips_23, flips_32,
                     flips_44, flips_22, not_flippable, stalled_faces);
static_assert(counter_table_complete(kEdgeFaceSwapCounterNames));

/// Swaps until no face wants a swap under `criterion`.
/// The flips themselves are flip_3d's (plan_flip_3d, apply_flip_3d).
/// @pre mesh valid (make_tet_mesh_3d). Vertex indices are the SoS ranks.
EdgeFaceSwapCounters swap_faces_3d(TetMesh3& mesh, SwapCriterion3 criterion);

/// Convenience: make_tet_mesh_3d, swap_faces_3d, to_tetrahedralization_3d into `mesh`.
/// @throws InputError as make_tet_mesh_3d.
EdgeFaceSwapCounters swap_faces_3d(Tetrahedralization3& mesh, SwapCriterion3 criterion);

/// Whether the interior face f is locally Delaunay by insphere_sos (never a tie).
bool locally_delaunay_sos(const TetMesh3& mesh, FaceIdx f);

}  // namespace exactmesh::triangulation
