// SPDX-License-Identifier: MIT
// A lower bound on the leaves the quadtree generator's feature criterion forces, computed before
// the tree is built, so that a domain whose features lie far closer together than their length
// (a comb of fingers 1e-9 wide) is refused at once with the estimate instead of after building
// 2^24 leaves (15-30 s and 1.2 GB).
//
// The criterion (quadtree_mesh_2d.cpp, `separates`): a node whose cell, grown by c times its side
// (c = min(1/4, clearance)), meets two pieces that are apart (of different input segments, no
// shared vertex, not a narrow wedge's) is split, down to the depth limit. Let x be a point of a
// piece p and d(x) its distance to the nearest piece apart from p. The grown box of a leaf of
// side s holding x holds the disc of radius c·s about x, so an unsplit leaf has s <= d(x) / c,
// or lies at the depth limit (side s_min). The leaf meets a straight segment over a length of at
// most s·λ, λ = length / (extent along the longer axis), between 1 and sqrt(2). So with g(x) =
// min(c / d(x), 1 / s_min) / λ, the integral of g over the part of one input segment inside one
// leaf is at most 1, and the integral over a segment S is
// at most the number of leaves meeting S. A leaf meets pieces that are pairwise not apart: of
// at most K input segments (all at one vertex, a triangle's three, a narrow wedge's fan; K =
// the largest number of segments at a vertex, plus two). Hence
//   leaves >= max( max_S N_S, (sum_S N_S) / K ),  N_S = integral of g over S.
// Computed from below: d(x) is replaced by the distance to one apart piece found near x (a
// larger distance, a smaller integrand), and the distance to one segment, convex along p, by
// its larger end value on intervals bisected while it varies by more than a quarter. Pieces are
// paired through a uniform grid over the tree's square; pairs the grid does not meet are left
// out (the bound only weakens). Everything is computed in the square's own coordinates (a
// power-of-two scaling): the same bound at every scale 2^k.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

/// One boundary piece as the quadtree's feature criterion sees it.
struct FeaturePiece2 {
    double a[2], b[2];
    triangulation::VertIdx va, vb;
    std::uint32_t segment;  ///< its input segment
};

/// The tree's square [x0, x0 + side]^2, its smallest leaf side and the grown boxes' margin.
struct QuadtreeFrame2 {
    double x0 = 0, y0 = 0, side = 1;
    double smallest_side = 0;  ///< the side of a leaf at the depth limit
    double margin = 0.25;      ///< c: a node's cell is grown by c times its side
};

struct QuadtreeLeafBound2 {
    double leaves = 0;     ///< the lower bound
    double densest_x = 0;  ///< a point of the piece with the largest integral (messages)
    double densest_y = 0;
    double closest_gap = 0;   ///< the smallest distance between apart pieces met
    std::uint64_t pairs = 0;  ///< pairs of apart pieces integrated
};

/// @param narrow whether two input segments make a narrow wedge (their pieces are not apart).
/// @param max_pairs the most pairs of pieces to integrate (the bound from those done).
QuadtreeLeafBound2 quadtree_leaf_bound_2d(
    const std::vector<FeaturePiece2>& pieces, const QuadtreeFrame2& frame,
    const std::function<bool(std::uint32_t, std::uint32_t)>& narrow,
    std::uint64_t max_pairs = std::uint64_t{1} << 20);

}  // namespace exactmesh::generators
