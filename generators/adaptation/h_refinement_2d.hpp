// SPDX-License-Identifier: MIT
// HRefinedMesh2: h-refinement of a 2D triangulation with history. Red-green refinement with
// closure [Bank-Sherman-Weiser 1983, "Refinement algorithms and data structures for regular local
// mesh refinement"; Löhner, "Applied CFD Techniques", ch. on h-refinement]: red (1:4) splits,
// green (1:2) closure splits that are never refined further (a green pair whose child needs
// refinement is undone and its parent refined red), and derefinement by the same history.
// Invariants after every call (check_h_refined_mesh_2d tests them exactly): the leaf mesh is
// conforming (no hanging vertex), every triangle strictly counter-clockwise (exact orient2d),
// every child nested in its parent (see HRefinedMesh2), root vertices keep their index; the
// tests also see neighbouring leaves differ by at most one level.
// Cost: O(T) per call (expected, hashing; a refused split costs local work only), plus O(T)
// per restart (counted; only when a sliver at the resolution of doubles sits beside a green
// pair being undone); memory O(nodes ever alive). Predicates: orient2d (decisions and checks),
// within_rounding_of_segment (checks).
//
// Split points are made from the two ends of the edge being split (rounded once), not from the
// root's coordinates: a child's corners are then its actual parent's corners and split points,
// both sides of an edge get the same point, and nesting is decidable on the parent's own
// vertices. A root edge split l times carries points within l half-ulps of their exact dyadic
// positions (exactly on them when the coordinates are dyadic enough, e.g. grids of k/2^j).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

struct HRefinementCounters2 {
    std::uint64_t red = 0;                 ///< triangles split 1:4
    std::uint64_t green = 0;               ///< triangles split 1:2 (closure)
    std::uint64_t green_undone = 0;        ///< green pairs removed so their parent goes red
    std::uint64_t closure_iterations = 0;  ///< triangles examined by the closure worklist
    std::uint64_t refused_edges = 0;       ///< marked edges left unsplit: a child would not be CCW
    std::uint64_t rounds = 0;        ///< closure-and-split passes (1 unless a marked edge is still
                                     ///< an edge after one: a safeguard, not seen in the tests)
    std::uint64_t restarts = 0;      ///< passes rolled back: a neighbour could not split an edge
                                     ///< of a green undo's red split (slivers only)
    std::uint64_t derefined = 0;     ///< parents whose children were removed
    std::uint64_t red_to_green = 0;  ///< red parents coarsened to a green pair (derefine)
    std::uint64_t removed_vertices = 0;  ///< vertices no leaf uses any more, removed
    std::uint64_t ignored_marks = 0;     ///< marked pairs that are no edge of the leaf mesh
};

inline constexpr std::array kHRefinementCounterNames = EM_COUNTER_TABLE(
    HRefinementCounters2, red, green, green_undone, closure_iterations, refused_edges, rounds,
    restarts, derefined, red_to_green, removed_vertices, ignored_marks);
static_assert(counter_table_complete(kHRefinementCounterNames));

/// One triangle of the refinement history. Children patterns, for corners (a, b, c) =
/// corners[0..2] and m_k the split point of edge k (corners[k], corners[k+1 mod 3]):
///   red:   (a, m0, m2), (m0, b, m1), (m2, m1, c), (m0, m1, m2)
///   green on edge k, with (p, q, r) = (corners[k], corners[k+1], corners[k+2]):
///          (p, m_k, r), (m_k, q, r)
struct HRefinementNode2 {
    std::array<triangulation::VertIdx, 3> corners{};  ///< counter-clockwise
    std::uint32_t parent = triangulation::kNone;      ///< kNone for a root triangle
    std::array<std::uint32_t, 4> children{triangulation::kNone, triangulation::kNone,
                                          triangulation::kNone, triangulation::kNone};
    std::uint8_t child_count = 0;  ///< 0 (leaf), 2 (green) or 4 (red)
    std::uint8_t split_edge = 0;   ///< green: the edge k that is split
    std::uint8_t constrained = 0;  ///< bit k: edge k is constrained
    std::uint8_t alive = 1;        ///< 0: a free slot
    std::uint32_t level = 0;       ///< 0 for a root triangle, parent's + 1
};

/// The midpoint of a and b rounded once to the nearest double (ties to even): (a + b) / 2 when
/// a + b is finite (halving is exact unless the result is subnormal, and then a + b was exact),
/// else a / 2 + b / 2 (exact halves of large numbers). Scale invariant for 2^k, |k| <= 600.
double rounded_midpoint(double a, double b);

/// A triangulation refined by red-green splits, with its history.
///
/// Nesting (what check_h_refined_mesh_2d tests): a child's corners are its parent's corners and
/// split points of its parent's edges, by vertex index, in the patterns of HRefinementNode2; the
/// split point of edge (a, b) is the vertex whose parent_edge() is {a, b}, with coordinates
/// exactly rounded_midpoint of a's and b's, distinct from both, and within_rounding_of_segment
/// (it lies exactly on the closed segment whenever the midpoint is exact, e.g. dyadic inputs);
/// every child is strictly counter-clockwise. So a child lies in its parent up to the rounding
/// of its split points (half an ulp), and exactly in it when the midpoints are exact.
///
/// Vertices: the root's keep their indices forever; refine() appends new ones; derefine()
/// removes the unused ones (never a root vertex) and compacts, keeping the order.
/// Leaf triangles are numbered in depth-first order of the history from the root triangles
/// (root order, children in pattern order), so a mesh with nothing refined is the root itself.
class HRefinedMesh2 {
  public:
    /// @param root the level-0 mesh: xy finite, triangles strictly counter-clockwise (exact),
    ///        each directed edge once, neighbors the triangle across each edge (kNone on the
    ///        boundary) and consistent with the edges, constrained empty or equal on both sides.
    /// @throws InputError naming the first offending vertex, triangle or edge.
    explicit HRefinedMesh2(const triangulation::Triangulation2& root);

    /// Refines the leaf mesh so that no marked edge remains an edge of it (except refused ones).
    /// Closure: a triangle with two marked edges gets the third one marked (to a fixed point);
    /// three marked edges: red; one: green; a green child with a marked edge: its green pair is
    /// undone and the parent split red at once (its red children join the same closure, so a
    /// mark on half of the old split edge is honoured in the same call). A split whose rounded
    /// midpoint would make a child not strictly counter-clockwise (a sliver at the resolution of
    /// doubles, or a midpoint equal to an end) is refused: the edge is left unsplit and counted in
    /// refused_edges, and so is, for a triangle that then cannot go red, the larger (by vertex
    /// pair) of its two other marked edges, and every marked edge of a green child whose parent
    /// cannot go red; the mesh stays valid. Marks on pairs that are not edges of the leaf mesh are
    /// ignored (counted in ignored_marks); duplicates are harmless.
    /// @param marked_edges 2·#E vertex indices (u, v), either order.
    /// @throws InputError for a vertex index out of range or an odd number of indices.
    /// @return this call's counters (also added to counters()).
    HRefinementCounters2 refine(std::span<const triangulation::VertIdx> marked_edges);

    /// Coarsens one generation: a parent whose children are all leaves and all flagged, and
    /// every green pair (flagged or not: greens are closure artefacts), loses its children,
    /// unless one of its split points would be left hanging, i.e. would still be a corner of a
    /// triangle outside it after this step. A red parent with exactly one such split point
    /// becomes the green pair on that edge instead (when both green children are strictly
    /// counter-clockwise; else it is kept whole): the pattern refine()'s closure makes there, so
    /// a coarsening region meets a finer one through a green closure, as after refinement,
    /// rather than through a whole red layer. Decided for all parents at once, to the largest
    /// consistent set, so that neighbouring parents coarsen together and a red parent takes its
    /// green neighbours along. Then vertices no leaf uses are removed (never a root vertex).
    /// Call it repeatedly to coarsen several levels; flagging every leaf each time returns the
    /// root mesh exactly.
    /// @param flagged_leaves leaf triangle indices of the current leaf mesh (any order,
    ///        duplicates harmless).
    /// @throws InputError for an index out of range.
    /// @return for each vertex before the call its new index, or kNone when removed
    ///         (restrict_field applies it to a field).
    std::vector<triangulation::VertIdx> derefine(
        std::span<const triangulation::TriIdx> flagged_leaves);

    /// The leaf mesh: conforming, counter-clockwise, neighbors and constrained flags valid
    /// (constrained empty when the root's was).
    const triangulation::Triangulation2& leaf_mesh() const { return leaf_; }
    /// Level of leaf triangle t (0 for a root triangle).
    std::uint32_t level(triangulation::TriIdx t) const { return nodes_[leaf_nodes_[t]].level; }
    /// The history node of leaf triangle t.
    std::span<const std::uint32_t> leaf_nodes() const { return leaf_nodes_; }
    /// Every node ever made and still referenced; slots with alive == 0 are free. Nodes
    /// [0, root triangle count) are the root triangles, in order.
    std::span<const HRefinementNode2> nodes() const { return nodes_; }
    std::uint32_t root_triangle_count() const { return root_triangles_; }
    std::uint32_t root_vertex_count() const { return root_vertices_; }
    /// The edge (a, b) whose split point vertex v is, or {kNone, kNone} for a root vertex.
    std::array<triangulation::VertIdx, 2> parent_edge(triangulation::VertIdx v) const;
    /// parent_edge of every vertex.
    std::span<const std::array<triangulation::VertIdx, 2>> vertex_parents() const {
        return vertex_parent_;
    }

    /// Prolongs a vertex field after refine(): `field` holds values on the first field.size()
    /// vertices (the vertices before the refinement keep their index); the result has a value on
    /// every vertex: those values exactly (injection), and at each newer vertex the
    /// rounded_midpoint of the values at the two ends of its parent edge (linear interpolation;
    /// exact for a linear field wherever the coordinates' midpoints are exact).
    /// @throws InputError when field.size() is larger than the vertex count or smaller than the
    ///         root's vertex count.
    std::vector<double> transfer_field(std::span<const double> field) const;

    /// Cumulative counters of every call.
    const HRefinementCounters2& counters() const { return counters_; }

  private:
    void collect_leaves();
    void rebuild_leaf_mesh();
    bool split_is_ccw(std::uint32_t id, int green, std::vector<std::uint64_t>& blame) const;
    void split_node(std::uint32_t id, int green);
    void plan_and_apply(std::span<const std::uint64_t> marks,
                        std::unordered_set<std::uint64_t>& blocked, HRefinementCounters2& round);
    std::uint32_t new_node();
    triangulation::VertIdx split_vertex(triangulation::VertIdx a, triangulation::VertIdx b);

    std::vector<double> xy_;
    std::vector<std::array<triangulation::VertIdx, 2>> vertex_parent_;    // kNone for root
    std::unordered_map<std::uint64_t, triangulation::VertIdx> split_of_;  // edge key -> vertex
    std::vector<HRefinementNode2> nodes_;
    std::vector<std::uint32_t> free_nodes_;
    std::vector<std::uint32_t> leaf_nodes_;
    triangulation::Triangulation2 leaf_;
    std::uint32_t root_triangles_ = 0;
    std::uint32_t root_vertices_ = 0;
    bool root_constrained_ = false;
    HRefinementCounters2 counters_;
};

/// Restricts a vertex field by derefine()'s vertex map: the kept vertices' values, exactly.
/// @throws InputError when the sizes differ.
std::vector<double> restrict_field(std::span<const double> field,
                                   std::span<const triangulation::VertIdx> vertex_map);

/// Exact check of an HRefinedMesh2: the leaf mesh (strictly counter-clockwise by orient2d, each
/// directed edge once, neighbors mutual and matching the edges, constrained flags equal on both
/// sides); conformity (every edge with no neighbour lies on a boundary edge of the root, by the
/// history, so no vertex hangs); nesting as HRefinedMesh2 defines it (patterns by index, split
/// points rounded midpoints within rounding of their edge, children strictly counter-clockwise,
/// levels, parent links); constrained flags inherited (a leaf edge is constrained exactly when
/// it lies on a constrained root edge); a green pair never refined further; every vertex past
/// the root's used by a leaf and the split point of its parent edge.
triangulation::CheckReport check_h_refined_mesh_2d(const HRefinedMesh2& mesh);

/// check_h_refined_mesh_2d on the parts it reads (HRefinedMesh2's accessors of the same names),
/// so that a test can hand it a corrupted copy.
triangulation::CheckReport check_h_refinement_history_2d(
    const triangulation::Triangulation2& leaf, std::span<const HRefinementNode2> nodes,
    std::span<const std::uint32_t> leaf_nodes,
    std::span<const std::array<triangulation::VertIdx, 2>> vertex_parents,
    std::uint32_t root_triangle_count, std::uint32_t root_vertex_count);

}  // namespace exactmesh::generators
