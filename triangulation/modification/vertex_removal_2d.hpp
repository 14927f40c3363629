// SPDX-License-Identifier: MIT
// Removal of vertices from a 2D constrained Delaunay triangulation (derefinement) [Devillers99:
// "On deletion in Delaunay triangulations", SoCG 1999; Chew89 and Lee-Lin86 for the constrained
// Delaunay lemma]. The star of the vertex v is cut out and the hole is retriangulated, then
// Lawson flips (flip_2d.hpp's kernel, never across a constrained edge) make every unconstrained
// edge of the hole locally Delaunay by the SoS incircle (predicates/sos.hpp, ties by vertex
// index, as delaunay_2d, constrained_delaunay_2d and swap_edges_2d decide them). The constrained
// Delaunay triangulation of the remaining vertices differs from the old one only inside v's star,
// so from a constrained Delaunay input (SoS) the result is exactly constrained_delaunay_2d's for
// the remaining points and segments, cocircular ties included. Which vertices go:
//  - interior, no constrained edge at v: its star polygon is retriangulated;
//  - exactly two constrained edges u - v - w of one straight constraint (orient2d(u, v, w) == 0,
//    or v within_rounding_of_segment of u - w), interior or on the mesh boundary (where the two
//    boundary edges count as the constraints, flagged alike): u - w replaces the two pieces
//    (constrained as they were), the star on each side retriangulated;
//  - anything else (a boundary corner, 1 or 3+ constrained edges, u - w leaving the star or
//    meeting a vertex of it, a pinched vertex, a protected one) is refused with a status, the
//    mesh unchanged. Every decision is an exact predicate (orient2d, incircle_sos,
//    within_rounding_of_segment): no tolerance, invariant under scaling by 2^k.
// Check of the output: check_constrained_delaunay_2d (checks/check_constrained_2d.hpp).
// Cost: O(k^2) orient2d for a star of k triangles (ear clipping; O(k^3) for non-convex stars),
// plus the Lawson flips inside the hole; the batch converts the mesh to half-edges once.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// Why a vertex was (not) removed.
enum class RemovalStatus : std::uint8_t {
    Removed,
    OutOfRange,  ///< no such vertex
    Unused,      ///< a vertex of no triangle (e.g. removed before)
    Protected,   ///< below the caller's protected_below (the input's vertices)
    /// On the mesh boundary, its two boundary edges not straight (neither collinear nor within
    /// rounding): removing it would change the domain.
    Corner,
    /// One constrained edge (a segment ends at it), or boundary edges of which one is flagged.
    ConstraintEnd,
    /// Three or more constrained edges (boundary edges included) meet at it.
    ConstraintJunction,
    /// Two constrained edges u - v - w that bend at it (neither collinear nor within rounding).
    ConstraintBend,
    /// The merged edge u - w would cross or pass through another vertex of the star, leave the
    /// star, or (on the boundary) grow the domain beyond the mesh.
    ChordBlocked,
    /// Its triangles form more than one fan (the domain pinched at it).
    NonManifold,
};

/// "removed", "out of range", ..., a phrase for messages.
const char* removal_status_name(RemovalStatus status);

/// Work counters, summed over calls.
struct VertexRemoval2Counters {
    std::uint64_t removed = 0;          ///< vertices removed
    std::uint64_t refused = 0;          ///< vertices refused (any status but Removed)
    std::uint64_t segment_merges = 0;   ///< of the removed: interior, on a straight constraint
    std::uint64_t boundary_merges = 0;  ///< of the removed: on a straight piece of the boundary
    std::uint64_t star_triangles = 0;   ///< triangles of the removed vertices' stars
    std::uint64_t orient_calls = 0;     ///< orient2d in the tests of the star and the ears
    std::uint64_t incircle_tests = 0;   ///< incircle_sos in the Lawson flips
    std::uint64_t delaunay_flips = 0;   ///< Lawson flips after retriangulating a hole
};

/// The name table of VertexRemoval2Counters (base/counter_table.hpp).
inline constexpr std::array kVertexRemoval2CounterNames =
    EM_COUNTER_TABLE(VertexRemoval2Counters, removed, refused, segment_merges, boundary_merges,
                     star_triangles, orient_calls, incircle_tests, delaunay_flips);
static_assert(counter_table_complete(kVertexRemoval2CounterNames));

/// Removes vertex v from the triangulation when the rules above allow it; its coordinates stay
/// in mesh.xy, used by no triangle (the other vertices keep their numbers). Triangles are
/// renumbered (the star's replaced, the mesh compacted); neighbors and constrained stay
/// consistent.
/// @pre mesh.neighbors consistent (link_neighbors_2d), triangles strictly counter-clockwise,
///      mesh.constrained empty or 3·#T; for the constrained Delaunay result, the input is
///      constrained Delaunay by the SoS incircle (constrained_delaunay_2d's output is).
/// @return Removed, or why not (then `mesh` is unchanged).
/// @throws InternalError when the mesh is not a valid triangulation around v.
RemovalStatus remove_vertex_2d(Triangulation2& mesh, VertIdx v,
                               VertexRemoval2Counters* counters = nullptr);

struct VertexRemoval2Result {
    /// One per requested vertex, in the order given.
    std::vector<RemovalStatus> status;
    /// #V before: the new number of each old vertex, kNone for a removed one. Vertices keep
    /// their relative order, so the SoS ranks (the indices) keep theirs.
    std::vector<VertIdx> old_to_new;
    std::uint32_t removed = 0;
};

/// Derefinement: removes each removable vertex of `vertices` in the order given (a refused one
/// is skipped and reported), then compacts the numbering: the removed vertices' coordinates
/// leave mesh.xy and the triangles are renumbered by old_to_new. Vertices below
/// `protected_below` are never removed (pass the input's vertex count to keep the input's
/// vertices and remove only added ones); their numbers stay the same when no vertex below
/// them is removed, so with protected_below = input_vertex_count the input's keep theirs.
/// @pre as remove_vertex_2d.
/// @throws InternalError as remove_vertex_2d; the removals before it stay made (a valid mesh,
///         the removed vertices' coordinates still in mesh.xy, numbering not compacted).
VertexRemoval2Result remove_vertices_2d(Triangulation2& mesh, std::span<const VertIdx> vertices,
                                        VertIdx protected_below = 0,
                                        VertexRemoval2Counters* counters = nullptr);

}  // namespace exactmesh::triangulation
