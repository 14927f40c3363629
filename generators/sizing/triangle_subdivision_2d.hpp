// SPDX-License-Identifier: MIT
// A sum over a triangle subdivided in four, depth first, on an explicit stack: the size
// estimates of the generators (check_size_budget's sampler, expected_triangle_count) split a
// triangle where the size varies and add its pieces' counts.
// Why not recursion: under AddressSanitizer each allocation records its call stack (30 frames)
// in a depot that is never freed. With a recursive call per child every path down the
// subdivision was a new stack for each allocation below it (GMP's, in a size's point location
// on a background mesh of coordinates from 1e-319 to 1e252), and fuzzed adaptation cases grew
// that depot to 2.8 GB and 3 GB (tests/data/fuzz/adaptation_2d_oom_narrow.bin,
// adaptation_2d_local_remesh_estimate_slow.bin). Here every evaluation has the same stack.
// Invariant: the same visits in the same order, and the same sums, as the recursion
//   value(node) = leaf value, or ((value(c0) + value(c1)) + value(c2)) + value(c3).
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace exactmesh::generators {

/// The value of `root` as above. visit(node, depth, children) returns the node's leaf value, or
/// nullopt after writing its four children (depth: 0 at the root, one more per level; the
/// visitor bounds it).
template <class Node, class Visit>
double subdivision_sum_2d(const Node& root, Visit&& visit) {
    struct Frame {
        std::array<Node, 4> children;
        unsigned next = 0;
        double sum = 0;
    };
    std::array<Node, 4> children{};  // written by visit before any read
    if (const std::optional<double> leaf = visit(root, 0, children)) return *leaf;
    std::vector<Frame> stack;
    stack.push_back({children, 0, 0.0});
    for (;;) {
        Frame& top = stack.back();
        if (top.next < 4) {
            const Node child = top.children[top.next++];
            const int depth = static_cast<int>(stack.size());
            if (const std::optional<double> leaf = visit(child, depth, children)) {
                top.sum += *leaf;
            } else {
                stack.push_back({children, 0, 0.0});
            }
            continue;
        }
        const double sum = top.sum;
        stack.pop_back();
        if (stack.empty()) return sum;
        stack.back().sum += sum;
    }
}

}  // namespace exactmesh::generators
