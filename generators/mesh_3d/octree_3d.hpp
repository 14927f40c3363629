// SPDX-License-Identifier: MIT
// Octree3: a 2:1 balanced octree of axis-aligned cubes [Yerry-Shephard84 "Automatic
// three-dimensional mesh generation by the modified-octree technique"; Mitchell-Vavasis92
// "Quality mesh generation in three dimensions" §2 for the balance rule], the spatial
// structure of octree_mesh_3d. The root is the smallest cube with a power-of-two edge and
// corner coordinates that are multiples of half that edge containing a given box (multiples of
// the whole edge cannot hold a box that straddles zero), so every cell's
// corners are exact doubles (c + i * edge / 2^level, no rounding while the grid's integers fit
// a double's mantissa, checked) and the whole octree scales with its input by any power of two.
// Cells are named by (level, i, j, k) and stored as 64-bit keys in hash sets; leaves partition
// the root. Balance: after refinement, every leaf whose neighbour across a face, an edge or a
// corner (the 26 directions) is more than one level coarser splits that neighbour, until none
// is (a worklist; every split only adds finer cells, so it ends). Decisions compare exact grid
// coordinates only; the split rule is the caller's.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace exactmesh::generators {

/// A cell of the octree: level 0 is the root; i, j, k in [0, 2^level).
struct OctreeCell3 {
    std::uint32_t level = 0;
    std::uint32_t i = 0, j = 0, k = 0;

    std::uint32_t index(int axis) const { return axis == 0 ? i : axis == 1 ? j : k; }
    bool operator==(const OctreeCell3&) const = default;
};

class Octree3 {
  public:
    /// Deepest level: the keys hold 19 bits per axis.
    static constexpr std::uint32_t kMaxLevel = 19;
    /// find_leaf's answers that are not a leaf index.
    static constexpr std::uint32_t kOutside = 0xFFFFFFFFu;  ///< the cell is outside the root
    static constexpr std::uint32_t kFiner = 0xFFFFFFFEu;    ///< the cell is subdivided

    Octree3() = default;
    /// The root cube for the box [lo, hi] (see above).
    /// @throws InputError when the box is empty, not finite, or so far from the origin for its
    ///         size that the grid's coordinates would not be exact doubles.
    Octree3(const std::array<double, 3>& lo, const std::array<double, 3>& hi);

    /// Refines from the root: splits every leaf for which `split(cell)` holds (children are
    /// tested too), then balances 2:1 across faces, edges and corners.
    /// @throws InputError when the leaves would exceed `max_leaves` or a split would go below
    ///         kMaxLevel.
    void refine_and_balance(const std::function<bool(const OctreeCell3&)>& split,
                            std::uint64_t max_leaves);

    const std::array<double, 3>& corner() const { return corner_; }
    double root_edge() const { return edge_; }
    /// The leaves, sorted by key (level first): a deterministic order.
    const std::vector<OctreeCell3>& leaves() const { return leaves_; }
    std::uint64_t balance_splits() const { return balance_splits_; }
    std::uint32_t max_level() const { return max_level_; }

    double cell_edge(std::uint32_t level) const;
    /// The cell's lower corner coordinate on `axis` (exact).
    double cell_min(const OctreeCell3& cell, int axis) const;
    double cell_max(const OctreeCell3& cell, int axis) const;

    /// The leaf containing `cell` (the cell itself or an ancestor), kFiner when the cell is
    /// subdivided, kOutside when (level, i, j, k) lies outside the root (indices as signed
    /// 64-bit so that a neighbour one step outside is expressible).
    std::uint32_t find_leaf(std::uint32_t level, std::int64_t i, std::int64_t j,
                            std::int64_t k) const;

  private:
    static std::uint64_t key(std::uint32_t level, std::uint32_t i, std::uint32_t j,
                             std::uint32_t k);
    void split_leaf(const OctreeCell3& cell, std::vector<OctreeCell3>& created);
    std::uint32_t containing_level(std::uint32_t level, std::int64_t i, std::int64_t j,
                                   std::int64_t k) const;
    void finish();

    std::array<double, 3> corner_{};
    double edge_ = 0;
    std::unordered_set<std::uint64_t> leaf_keys_;
    std::unordered_set<std::uint64_t> split_keys_;  ///< subdivided cells
    std::vector<OctreeCell3> leaves_;
    std::uint64_t max_leaves_ = 0;
    std::uint64_t balance_splits_ = 0;
    std::uint32_t max_level_ = 0;
    std::unordered_map<std::uint64_t, std::uint32_t> leaf_index_;  ///< by key, from finish()
};

}  // namespace exactmesh::generators
