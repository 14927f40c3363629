// SPDX-License-Identifier: MIT
// The advancing fronts' loose quadtree (see front_index_2d.hpp).
#include "generators/front_index_2d.hpp"

namespace exactmesh::generators {

FrontIndex2::FrontIndex2(double cx, double cy, double half) {
    nodes_.push_back(Node{cx, cy, half});
}

void FrontIndex2::insert(std::uint32_t id, const FrontBox2& box, double extent) {
    if (id >= boxes_.size()) {
        boxes_.resize(std::size_t{id} + 1);
        node_of_.resize(std::size_t{id} + 1, kNone);
        alive_.resize(std::size_t{id} + 1, 0);
    }
    boxes_[id] = box;
    alive_[id] = 1;
    const double x = 0.5 * box.x0 + 0.5 * box.x1, y = 0.5 * box.y0 + 0.5 * box.y1;
    std::uint32_t node = 0;
    for (int depth = 0;; ++depth) {
        nodes_[node].bounds.add(box);
        ++nodes_[node].live;
        const double half = nodes_[node].half;
        if (depth == kMaxDepth || 0.5 * half < extent) break;
        const unsigned quadrant =
            (x >= nodes_[node].cx ? 1u : 0u) + (y >= nodes_[node].cy ? 2u : 0u);
        if (nodes_[node].child[quadrant] == kNone) {
            const double q = 0.5 * half;
            const Node child{nodes_[node].cx + ((quadrant & 1u) ? q : -q),
                             nodes_[node].cy + ((quadrant & 2u) ? q : -q), q, node};
            nodes_[node].child[quadrant] = static_cast<std::uint32_t>(nodes_.size());
            nodes_.push_back(child);
        }
        node = nodes_[node].child[quadrant];
    }
    nodes_[node].items.push_back(id);
    node_of_[id] = node;
}

void FrontIndex2::erase(std::uint32_t id) {
    if (id >= alive_.size() || !alive_[id]) return;
    alive_[id] = 0;
    for (std::uint32_t node = node_of_[id]; node != kNone; node = nodes_[node].parent)
        --nodes_[node].live;
}

void FrontIndex2::query(const FrontBox2& box, std::vector<std::uint32_t>& out) {
    stack_.assign(1, 0);
    while (!stack_.empty()) {
        Node& node = nodes_[stack_.back()];
        stack_.pop_back();
        if (node.live == 0 || !node.bounds.meets(box)) continue;
        std::size_t kept = 0;
        for (const std::uint32_t id : node.items) {
            if (!alive_[id]) continue;  // erased: dropped from the list here
            node.items[kept++] = id;
            if (boxes_[id].meets(box)) out.push_back(id);
        }
        node.items.resize(kept);
        for (const std::uint32_t c : node.child)
            if (c != kNone) stack_.push_back(c);
    }
}

}  // namespace exactmesh::generators
