// SPDX-License-Identifier: MIT
// A size field stored in a quadtree (issue 6, "a quadtree with bilinear interpolation"):
// a square root cell over the box, split while a given size field (point and line sources, a
// background mesh, anything) is not followed by the bilinear interpolation of the cell's
// corners (at its centre and edge midpoints, relative tolerance), or while the cell is larger
// than the field's size; then 2:1 balanced (edge neighbours differ by at most one level)
// [Frey-George08 §5.4 (quadtree sizing); deBerg-et-al08 §14.2 (balancing)].
// Invariants: 2:1 balance; each leaf stores its four corner values; a corner in the middle of a
// coarser neighbour's edge (a hanging corner) takes the mean of that edge's end values, so the
// field is bilinear in every leaf and continuous across leaves (piecewise linear on each edge).
// Cost: O(N) field evaluations and O(N · depth) to build for N leaves; a query O(depth) (one
// descent, exact in the cell's fraction bits). Predicates: none (no combinatorial decision
// depends on a rounded value; cells are addressed by integer coordinates).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "generators/sizing/size_function.hpp"

namespace exactmesh::generators {

class SizeQuadtree2 {
  public:
    /// @param field finite and > 0 at every point of `box` (evaluated only there: corners
    ///        outside the box take the value at the nearest point of the box).
    /// @throws InputError on a bad box or options, or a field value that is not finite > 0;
    ///         GeometryError naming the place when a cell would need splitting below
    ///         options.max_depth, or the tree more than options.max_leaves leaves.
    SizeQuadtree2(const std::function<double(double, double)>& field, const SizeBox& box,
                  const QuadtreeSizeOptions& options = {});

    /// The bilinear value in the leaf containing (x, y), clamped to the box first.
    double operator()(double x, double y) const;

    struct Leaf {
        double x0, y0, x1, y1;
        int level;
        /// At (x0, y0), (x1, y0), (x0, y1), (x1, y1).
        std::array<double, 4> corner;
    };
    std::uint32_t leaf_count() const { return static_cast<std::uint32_t>(leaves_.size()); }
    const Leaf& leaf(std::uint32_t i) const { return leaves_[i]; }
    /// The leaf containing (x, y) (clamped to the box; on a shared side, the one above or right).
    std::uint32_t locate_leaf(double x, double y) const;
    /// The bilinear interpolation of leaf i's corners at (x, y).
    double leaf_value(std::uint32_t i, double x, double y) const;
    int depth() const { return depth_; }
    const SizeBox& box() const { return box_; }

  private:
    struct Node {
        std::uint32_t child;  // the first of four (x-major: +1 right, +2 up), or kNone for a leaf
        std::uint32_t leaf;   // the leaf's index, for a leaf
    };
    SizeBox box_;
    double x0_ = 0, y0_ = 0, side_ = 1;  // the root square
    std::vector<Node> nodes_;
    std::vector<Leaf> leaves_;
    int depth_ = 0;
    std::uint32_t descend(double x, double y, double& fx, double& fy) const;
};

}  // namespace exactmesh::generators
