// SPDX-License-Identifier: MIT
// The leaf walk h_refinement_2d and h_refinement_3d share (internal to generators/adaptation):
// the leaves of a forest of refinement trees stored as one node array, roots first.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace exactmesh::generators::detail {

/// The leaves (nodes with child_count 0) under roots 0 .. roots - 1, depth first: each root's
/// tree in turn, each node's children in their order (node.children[0 .. child_count)).
template <class Node>
void collect_forest_leaves(std::span<const Node> nodes, std::uint32_t roots,
                           std::vector<std::uint32_t>& leaves) {
    leaves.clear();
    std::vector<std::uint32_t> stack;
    for (std::uint32_t r = roots; r-- > 0;) stack.push_back(r);
    while (!stack.empty()) {
        const std::uint32_t id = stack.back();
        stack.pop_back();
        const Node& node = nodes[id];
        if (node.child_count == 0) {
            leaves.push_back(id);
            continue;
        }
        for (int c = node.child_count; c-- > 0;)
            stack.push_back(node.children[static_cast<std::size_t>(c)]);
    }
}

}  // namespace exactmesh::generators::detail
