// SPDX-License-Identifier: MIT
// h-refinement of tetrahedral meshes with history [LohnerBaum92; Lohner, Applied CFD
// Techniques §14.4]: a forest of tetrahedra over a root Tetrahedralization3, refined by edge
// marks and derefined by restoring parents.
//
// Refinement cases. A leaf whose marked edges are one edge is split 1:2, three edges of one face
// 1:4, all six 1:8; any other pattern is upgraded (all marks in one face: that face's three
// edges; otherwise all six), iterated over the mesh to a fixed point (the compatibility
// iteration: marks belong to edges, so every tetrahedron around an edge sees the same mark and
// every face, boundary faces included, is split the same way on both sides). Children of a 1:2
// or 1:4 (transitional) tetrahedron are never refined: a mark on one reopens the parent, which
// becomes 1:4 when a 1:2 parent's marks (its split edge plus marked whole edges of the parent)
// lie in one face (2:4), else 1:8 (2:8, 4:8); marks on the old children's half edges are then
// applied to the new 1:8 children in the next round. The 8:1 jump limit (face-neighbouring
// leaves at most one level apart) follows from these rules: a leaf face F lies in a support
// face S created at some level k (a root face, or an inner face of a split at level k - 1, the
// same on both sides) and is S refined 1:4 d times (then possibly bisected), where d is fixed by
// F itself; a leaf at level l has d = l - k, or d = l - 1 - k when it is a 1:2 or 1:4 child
// (whose parent is never a transitional child), so the two sides differ by at most one. Rounds
// still check it on the conforming mesh and would mark the coarser leaf (one edge off the shared
// face; counted as jump_marks, 0 in every test), and derefinement checks it per parent.
// Every child is one level deeper than its parent.
// 1:8 interior diagonal: of the three diagonals, those whose four inner children are strictly
// positive are compared by the worst inner child's volume-edge quality (exact
// predicates::compare_volume_edge); the best wins, ties to the first diagonal in the order
// (mid(g0,g1), mid(g2,g3)), (mid(g0,g2), mid(g1,g3)), (mid(g0,g3), mid(g1,g2)) over the
// parent's global vertex ids g0 < g1 < g2 < g3.
// New vertices: one per split edge, the correctly rounded midpoint of the edge's two ends.
// A split whose rounded midpoint leaves some child not strictly positive (exact orient3d) or a
// midpoint outside its parent (see check_nesting) is refused: the call is rolled back and run
// again with every edge of that tetrahedron's pattern refused (never split in this call, the
// marks and upgrades that need one dropped), until a run completes (counted per refused edge).
// Derefinement: a parent whose children are all flagged leaves is restored when the midpoints
// it removes are used by no leaf that stays, and no face neighbour of it is then more than one
// level finer (a fixed point too). Vertices are renumbered compactly after each derefinement,
// keeping their order, so derefining everything gives back the root arrays exactly.
// Complexity: O(T) per sweep, hash maps on edges and faces. Predicates: orient3d,
// compare_volume_edge.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::generators {

using triangulation::TetIdx;
using triangulation::Tetrahedralization3;
using triangulation::VertIdx;

/// Work counters of an HRefinedMesh3, summed over its calls.
struct HRefinement3Counters {
    std::uint64_t refine_1_2 = 0;  ///< leaves split along one edge
    std::uint64_t refine_1_4 = 0;  ///< leaves split along one face
    std::uint64_t refine_1_8 = 0;  ///< leaves split regularly
    std::uint64_t refine_2_4 = 0;  ///< 1:2 parents reopened as 1:4
    std::uint64_t refine_2_8 = 0;  ///< 1:2 parents reopened as 1:8
    std::uint64_t refine_4_8 = 0;  ///< 1:4 (or 2:4) parents reopened as 1:8
    std::uint64_t upgraded = 0;    ///< leaf patterns upgraded by the compatibility iteration
    std::uint64_t compatibility_iterations = 0;  ///< sweeps over the leaves, summed
    std::uint64_t rounds = 0;                    ///< refine rounds (half-edge marks, jump marks)
    std::uint64_t jump_marks = 0;                ///< leaves marked to keep the 8:1 jump limit
    std::uint64_t refused_splits = 0;    ///< edges not split: a rounded midpoint would invert
    std::uint64_t derefined = 0;         ///< parents restored
    std::uint64_t derefine_blocked = 0;  ///< candidate parents kept by compatibility or jump
};

inline constexpr std::array kHRefinement3CounterNames =
    EM_COUNTER_TABLE(HRefinement3Counters, refine_1_2, refine_1_4, refine_1_8, refine_2_4,
                     refine_2_8, refine_4_8, upgraded, compatibility_iterations, rounds, jump_marks,
                     refused_splits, derefined, derefine_blocked);
static_assert(counter_table_complete(kHRefinement3CounterNames));

/// A report of the exact checks below: the first problem in words, empty when ok.
struct HRefinement3Report {
    bool ok = true;
    std::string problem;
};

/// A nested tetrahedral mesh: the root tetrahedralization and the refinement history above it.
/// Vertex ids are those of leaf_mesh(): the root's vertices first, in their order, then the
/// midpoints in order of creation.
class HRefinedMesh3 {
  public:
    /// @pre root is a conforming Tetrahedralization3 (its neighbors are not read: the leaf
    /// mesh's are recomputed from shared faces). @throws InputError when root's arrays have
    /// inconsistent sizes, a vertex index is out of range, a coordinate is not finite, or a
    /// tetrahedron is not strictly positively oriented (exact orient3d).
    explicit HRefinedMesh3(Tetrahedralization3 root);

    /// Splits the marked edges (pairs of vertex ids, either order) and whatever the rules above
    /// add. @throws InputError when a pair is not an edge of the leaf mesh.
    void refine(std::span<const std::array<VertIdx, 2>> marked_edges);

    /// Restores parents of flagged leaves (flags: one per leaf_mesh() tetrahedron, nonzero =
    /// may be removed). One level per call. @throws InputError on a wrong flag count.
    void derefine(std::span<const std::uint8_t> flags);

    /// The current leaves as a conforming tetrahedralization (xyz, tets, neighbors), leaves in
    /// depth-first order of the roots: with nothing refined, the root arrays exactly.
    Tetrahedralization3 leaf_mesh() const;
    /// Refinement level of each leaf_mesh() tetrahedron (roots 0).
    std::vector<std::uint32_t> leaf_levels() const;
    std::uint32_t leaf_count() const { return static_cast<std::uint32_t>(leaves_.size()); }
    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz_.size() / 3); }
    /// Number of root vertices (the vertices that no derefinement removes).
    std::uint32_t root_vertex_count() const { return root_vertices_; }
    /// For a vertex made by refinement, the edge it is the midpoint of; {kNone, kNone} for a
    /// root vertex. @pre v < vertex_count().
    std::array<VertIdx, 2> midpoint_ends(VertIdx v) const { return ends_[v]; }

    /// A per-vertex field on the leaf mesh before the last refine or derefine, carried to the
    /// current one: injection at the vertices that were there, the average of the edge's ends'
    /// values at new midpoints. @throws InputError on a wrong size.
    std::vector<double> transfer(std::span<const double> previous_field) const;

    const HRefinement3Counters& counters() const { return counters_; }

    /// Nesting, exactly: every child's corners are corners of its parent or vertices whose
    /// coordinates are bit for bit the correctly rounded midpoint of an edge of the parent; and
    /// for every face F of the parent and every child corner x not on F combinatorially (x is
    /// neither a corner of F nor the midpoint of an edge of F), orient3d(F, x) >= 0 (x in the
    /// closed half-space of the parent; corners on F combinatorially lie on F up to that one
    /// rounding and are not tested). Also: each child strictly positive.
    HRefinement3Report check_nesting() const;
    /// No two face-neighbouring leaves differ by more than one level.
    HRefinement3Report check_jump_limit() const;
    /// check_topology_3d of leaf_mesh(), every leaf edge unsplit (no hanging midpoint), plus
    /// check_nesting and check_jump_limit.
    HRefinement3Report check_all() const;

  private:
    struct Node {
        std::array<VertIdx, 4> v{};
        std::uint32_t parent = 0xFFFFFFFFu;
        std::array<std::uint32_t, 8> children{};
        std::uint8_t child_count = 0;
        std::uint8_t kind = 0;        // 0 leaf, 2 (1:2), 4 (1:4), 8 (1:8)
        std::uint8_t split_mask = 0;  // local edges split (bit k: kEdges[k])
        std::uint8_t diagonal = 0;    // 1:8: which diagonal
        std::uint32_t level = 0;
        bool alive = true;
    };

    bool refine_once(const std::vector<std::uint64_t>& user_marks,
                     std::vector<std::uint64_t>& forbidden);
    VertIdx midpoint_vertex(VertIdx a, VertIdx b);
    bool is_split(VertIdx a, VertIdx b) const;
    std::uint32_t new_node();
    void set_leaf_uses(std::uint32_t node, int delta);
    void remove_children(std::uint32_t node);
    bool make_children(std::uint32_t node, std::uint8_t mask);
    void rebuild_leaves();

    std::vector<double> xyz_;
    std::vector<std::array<VertIdx, 2>> ends_;
    std::vector<std::uint32_t> uses_;  // leaves using each vertex
    std::unordered_map<std::uint64_t, VertIdx> midpoints_;
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> free_nodes_;
    std::uint32_t root_vertices_ = 0;
    std::uint32_t root_tets_ = 0;
    std::vector<std::uint32_t> leaves_;  // depth-first order
    // transfer(): for each current vertex its id before the last call, or kNone when new
    std::vector<VertIdx> previous_id_;
    std::uint32_t previous_count_ = 0;
    HRefinement3Counters counters_;
};

}  // namespace exactmesh::generators
