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

}  // namespace exactmesh::generators
