// SPDX-License-Identifier: MIT
// The spatial index of the advancing fronts (issue 12: one loose quadtree, where the advancing
// front and the advancing-front Delaunay generator each had their own) [Ulrich00, "Loose
// octrees", Game Programming Gems §4.11]: items with boxes (front points, front edges). An item
// sits in the node on the path of its box's centre whose width is about its extent; each node
// keeps the union of the boxes ever stored below it, exactly (it never shrinks), and the number
// of live items below it. A query reports every live item whose box meets the query box: the
// pruning uses only exact box comparisons, so nothing is missed whatever the rounding of the
// descent.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace exactmesh::generators {

/// A closed axis-parallel box; empty (inverted) until a point is added.
struct FrontBox2 {
    double x0 = std::numeric_limits<double>::infinity(),
           y0 = std::numeric_limits<double>::infinity(),
           x1 = -std::numeric_limits<double>::infinity(),
           y1 = -std::numeric_limits<double>::infinity();
    void add(double x, double y) {
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
    void add(const FrontBox2& b) {
        x0 = std::min(x0, b.x0), y0 = std::min(y0, b.y0);
        x1 = std::max(x1, b.x1), y1 = std::max(y1, b.y1);
    }
    /// Closed boxes meet (exact comparisons of doubles).
    bool meets(const FrontBox2& b) const {
        return x0 <= b.x1 && b.x0 <= x1 && y0 <= b.y1 && b.y0 <= y1;
    }
    /// The box holds the point (closed, exact).
    bool holds(const double* p) const {
        return x0 <= p[0] && p[0] <= x1 && y0 <= p[1] && p[1] <= y1;
    }
};

class FrontIndex2 {
  public:
    /// The root square: centre (cx, cy), half width `half`.
    FrontIndex2(double cx, double cy, double half);

    /// Adds item `id` (ids are small integers: the index grows to the largest) with its box;
    /// `extent`: the item is listed no deeper than an item that wide would go (a point, whose
    /// box is empty of width, at the level of its local size).
    void insert(std::uint32_t id, const FrontBox2& box, double extent);
    /// Removes item `id` (nothing when it is not in the index).
    void erase(std::uint32_t id);
    /// Appends to `out` every live item whose box meets `box` (each once).
    void query(const FrontBox2& box, std::vector<std::uint32_t>& out);

  private:
    static constexpr int kMaxDepth = 48;
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
    struct Node {
        double cx, cy, half;
        std::uint32_t parent = kNone;
        FrontBox2 bounds{};
        std::uint32_t live = 0;
        std::uint32_t child[4] = {kNone, kNone, kNone, kNone};
        std::vector<std::uint32_t> items{};
    };
    std::vector<Node> nodes_;
    std::vector<FrontBox2> boxes_;
    std::vector<std::uint32_t> node_of_;
    std::vector<std::uint8_t> alive_;
    std::vector<std::uint32_t> stack_;
};

// Inline: the fronts call these in their innermost loops.
inline FrontIndex2::FrontIndex2(double cx, double cy, double half) {
    nodes_.push_back(Node{cx, cy, half});
}

inline void FrontIndex2::insert(std::uint32_t id, const FrontBox2& box, double extent) {
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

inline void FrontIndex2::erase(std::uint32_t id) {
    if (id >= alive_.size() || !alive_[id]) return;
    alive_[id] = 0;
    for (std::uint32_t node = node_of_[id]; node != kNone; node = nodes_[node].parent)
        --nodes_[node].live;
}

inline void FrontIndex2::query(const FrontBox2& box, std::vector<std::uint32_t>& out) {
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
