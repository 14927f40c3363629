// SPDX-License-Identifier: MIT
// Red-green h-refinement with history and derefinement (see h_refinement_2d.hpp)
// [Bank-Sherman-Weiser 1983; Löhner, Applied CFD Techniques, h-refinement].
#include "generators/adaptation/h_refinement_2d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "base/errors.hpp"
#include "generators/adaptation/refinement_forest.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"

namespace exactmesh::generators {

namespace {

using predicates::Sign;
using triangulation::kNone;
using triangulation::TriIdx;
using triangulation::VertIdx;

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}
std::uint64_t directed_key(VertIdx a, VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}
VertIdx key_low(std::uint64_t k) {
    return static_cast<VertIdx>(k >> 32);
}
VertIdx key_high(std::uint64_t k) {
    return static_cast<VertIdx>(k & 0xFFFFFFFFu);
}

std::uint64_t node_edge(const HRefinementNode2& n, int k) {
    return edge_key(n.corners[static_cast<std::size_t>(k)],
                    n.corners[static_cast<std::size_t>((k + 1) % 3)]);
}

/// The split point of edge k of a split node, read from its children (kNone when that edge is
/// not split: a green node's other edges).
VertIdx split_point(std::span<const HRefinementNode2> nodes, const HRefinementNode2& n, int k) {
    if (n.child_count == 4) {
        // red children: (a, m0, m2), (m0, b, m1), ...
        if (k == 0) return nodes[n.children[0]].corners[1];
        if (k == 2) return nodes[n.children[0]].corners[2];
        return nodes[n.children[1]].corners[2];
    }
    if (n.child_count == 2 && n.split_edge == k) return nodes[n.children[0]].corners[1];
    return kNone;
}

/// The corners of the children of (a, b, c) with split points m (kNone where unsplit), and the
/// constrained bits of each child from the parent's bits: a child edge on parent edge k keeps
/// bit k, an interior one is unconstrained.
struct ChildPattern {
    int count = 0;
    std::array<std::array<VertIdx, 3>, 4> corners{};
    std::array<std::uint8_t, 4> constrained{};
};

ChildPattern child_pattern(const std::array<VertIdx, 3>& c, const std::array<VertIdx, 3>& m,
                           std::uint8_t bits, int green_edge) {
    auto bit = [bits](int k, int child_edge) {
        return static_cast<std::uint8_t>(((bits >> k) & 1u) << child_edge);
    };
    ChildPattern p;
    if (green_edge < 0) {
        p.count = 4;
        p.corners[0] = {c[0], m[0], m[2]};
        p.constrained[0] = static_cast<std::uint8_t>(bit(0, 0) | bit(2, 2));
        p.corners[1] = {m[0], c[1], m[1]};
        p.constrained[1] = static_cast<std::uint8_t>(bit(0, 0) | bit(1, 1));
        p.corners[2] = {m[2], m[1], c[2]};
        p.constrained[2] = static_cast<std::uint8_t>(bit(1, 1) | bit(2, 2));
        p.corners[3] = {m[0], m[1], m[2]};
        p.constrained[3] = 0;
        return p;
    }
    const int k = green_edge, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    const auto uk = static_cast<std::size_t>(k), uk1 = static_cast<std::size_t>(k1),
               uk2 = static_cast<std::size_t>(k2);
    p.count = 2;
    // (p, m, r): edge 0 on parent edge k, edge 2 (r, p) on parent edge k2.
    p.corners[0] = {c[uk], m[uk], c[uk2]};
    p.constrained[0] = static_cast<std::uint8_t>(bit(k, 0) | bit(k2, 2));
    // (m, q, r): edge 0 on parent edge k, edge 1 (q, r) on parent edge k1.
    p.corners[1] = {m[uk], c[uk1], c[uk2]};
    p.constrained[1] = static_cast<std::uint8_t>(bit(k, 0) | bit(k1, 1));
    return p;
}

[[noreturn]] void input_error(const std::string& what) {
    throw InputError("h-refinement: " + what);
}

/// The leaves on each side of an edge (at most two), by edge key: open addressing with linear
/// probing in a power-of-two table at most half full, keys never erased (a detached leaf leaves
/// kNone). A closure pass attaches every leaf's three edges; std::unordered_map made that a
/// sixth of an h-refinement cycle in node allocations.
class EdgeSides {
  public:
    explicit EdgeSides(std::size_t edges) {
        std::size_t capacity = 16;
        while (capacity < 2 * edges) capacity *= 2;
        keys_.assign(capacity, kEmpty);
        sides_.resize(capacity);
    }
    /// The two sides of edge key e, made empty (kNone, kNone) when new.
    std::array<std::uint32_t, 2>& at(std::uint64_t e) {
        std::size_t i = slot(e);
        if (keys_[i] == kEmpty) {
            if (2 * (size_ + 1) > keys_.size()) {
                grow();
                i = slot(e);
            }
            keys_[i] = e;
            sides_[i] = {kNone, kNone};
            ++size_;
        }
        return sides_[i];
    }
    /// The sides of e, or nullptr when no leaf was ever attached to it.
    const std::array<std::uint32_t, 2>* find(std::uint64_t e) const {
        const std::size_t i = slot(e);
        return keys_[i] == kEmpty ? nullptr : &sides_[i];
    }

  private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // no edge (u < v < 2^32 - 1)
    std::size_t slot(std::uint64_t e) const {
        const std::size_t mask = keys_.size() - 1;
        std::size_t i = static_cast<std::size_t>((e * 0x9E3779B97F4A7C15ull) >> 17) & mask;
        while (keys_[i] != kEmpty && keys_[i] != e) i = (i + 1) & mask;
        return i;
    }
    void grow() {
        std::vector<std::uint64_t> keys = std::move(keys_);
        std::vector<std::array<std::uint32_t, 2>> sides = std::move(sides_);
        keys_.assign(2 * keys.size(), kEmpty);
        sides_.assign(2 * keys.size(), {kNone, kNone});
        for (std::size_t i = 0; i < keys.size(); ++i) {
            if (keys[i] == kEmpty) continue;
            const std::size_t j = slot(keys[i]);
            keys_[j] = keys[i];
            sides_[j] = sides[i];
        }
    }
    std::vector<std::uint64_t> keys_;
    std::vector<std::array<std::uint32_t, 2>> sides_;
    std::size_t size_ = 0;
};

}  // namespace

double rounded_midpoint(double a, double b) {
    const double s = a + b;
    // a + b rounded once; halving it is exact unless the half is subnormal, and a sum whose
    // half is subnormal is itself exact (no bits below the subnormal spacing), so either way
    // the result is the exact midpoint rounded once.
    if (std::isfinite(s)) return s * 0.5;
    // Overflow: both are large, so the halves are exact; the sum rounds once.
    return a * 0.5 + b * 0.5;
}

HRefinedMesh2::HRefinedMesh2(const triangulation::Triangulation2& root) {
    const auto& tv = root.triangles;
    if (root.xy.size() % 2 != 0)
        input_error("odd number of coordinates " + std::to_string(root.xy.size()));
    if (root.xy.size() / 2 > triangulation::kMaxPoints)
        input_error("too many vertices: " + std::to_string(root.xy.size() / 2));
    if (tv.size() % 3 != 0) input_error("triangle array of size " + std::to_string(tv.size()));
    if (root.neighbors.size() != tv.size())
        input_error("neighbors: " + std::to_string(root.neighbors.size()) + " for " +
                    std::to_string(tv.size() / 3) + " triangles");
    if (!root.constrained.empty() && root.constrained.size() != tv.size())
        input_error("constrained flags: " + std::to_string(root.constrained.size()) + " for " +
                    std::to_string(tv.size() / 3) + " triangles");
    const std::uint32_t n = root.vertex_count();
    const TriIdx count = root.triangle_count();
    for (VertIdx v = 0; v < n; ++v) {
        if (!std::isfinite(root.xy[2 * v]) || !std::isfinite(root.xy[2 * v + 1]))
            throw NonFiniteCoordinate(
                "h-refinement: vertex " + std::to_string(v) + " has a non-finite coordinate", v);
    }
    auto name = [&](TriIdx t) {
        return "triangle " + std::to_string(t) + " (" + std::to_string(tv[3 * t]) + ", " +
               std::to_string(tv[3 * t + 1]) + ", " + std::to_string(tv[3 * t + 2]) + ")";
    };
    std::unordered_map<std::uint64_t, std::uint32_t> edge_of;
    edge_of.reserve(tv.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (tv[3 * t + k] >= n) input_error(name(t) + " names a vertex that does not exist");
        }
        if (predicates::orient2d(root.point(tv[3 * t]), root.point(tv[3 * t + 1]),
                                 root.point(tv[3 * t + 2])) != Sign::Positive)
            input_error(name(t) + " is not strictly counter-clockwise");
        for (unsigned k = 0; k < 3; ++k) {
            if (!edge_of.emplace(directed_key(tv[3 * t + k], tv[3 * t + (k + 1) % 3]), 3 * t + k)
                     .second)
                input_error(name(t) + ": its edge " + std::to_string(k) +
                            " is an edge of another triangle in the same direction");
        }
    }
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3];
            const auto other = edge_of.find(directed_key(b, a));
            const TriIdx across = other == edge_of.end() ? kNone : other->second / 3;
            if (root.neighbors[3 * t + k] != across)
                input_error(name(t) + ": neighbor " + std::to_string(k) + " is " +
                            std::to_string(root.neighbors[3 * t + k]) +
                            ", the triangle across its edge is " + std::to_string(across));
            if (across != kNone &&
                root.is_constrained(t, static_cast<int>(k)) !=
                    root.is_constrained(across, static_cast<int>(other->second % 3)))
                input_error(name(t) + ": edge " + std::to_string(a) + " - " + std::to_string(b) +
                            " is constrained on one side only");
        }
    }
    xy_ = root.xy;
    root_vertices_ = n;
    root_triangles_ = count;
    root_constrained_ = !root.constrained.empty();
    vertex_parent_.assign(n, {kNone, kNone});
    nodes_.resize(count);
    for (TriIdx t = 0; t < count; ++t) {
        HRefinementNode2& node = nodes_[t];
        node.corners = {tv[3 * t], tv[3 * t + 1], tv[3 * t + 2]};
        for (unsigned k = 0; k < 3; ++k) {
            if (root.is_constrained(t, static_cast<int>(k)))
                node.constrained = static_cast<std::uint8_t>(node.constrained | (1u << k));
        }
    }
    rebuild_leaf_mesh();
}

std::array<VertIdx, 2> HRefinedMesh2::parent_edge(VertIdx v) const {
    return vertex_parent_.at(v);
}

std::uint32_t HRefinedMesh2::new_node() {
    if (!free_nodes_.empty()) {
        const std::uint32_t id = free_nodes_.back();
        free_nodes_.pop_back();
        nodes_[id] = HRefinementNode2{};
        return id;
    }
    EM_ASSERT(nodes_.size() < kNone - 1);
    nodes_.emplace_back();
    return static_cast<std::uint32_t>(nodes_.size() - 1);
}

VertIdx HRefinedMesh2::split_vertex(VertIdx a, VertIdx b) {
    const auto found = split_of_.find(edge_key(a, b));
    if (found != split_of_.end()) return found->second;
    EM_ASSERT(xy_.size() / 2 < triangulation::kMaxPoints);
    const auto v = static_cast<VertIdx>(xy_.size() / 2);
    const double x = rounded_midpoint(xy_[2 * std::size_t{a}], xy_[2 * std::size_t{b}]);
    const double y = rounded_midpoint(xy_[2 * std::size_t{a} + 1], xy_[2 * std::size_t{b} + 1]);
    xy_.push_back(x);
    xy_.push_back(y);
    vertex_parent_.push_back({a, b});
    split_of_.emplace(edge_key(a, b), v);
    return v;
}

void HRefinedMesh2::collect_leaves() {
    detail::collect_forest_leaves<HRefinementNode2>(nodes_, root_triangles_, leaf_nodes_);
}

void HRefinedMesh2::rebuild_leaf_mesh() {
    collect_leaves();
    const auto count = static_cast<TriIdx>(leaf_nodes_.size());
    leaf_.xy = xy_;
    leaf_.triangles.resize(3 * std::size_t{count});
    leaf_.neighbors.assign(3 * std::size_t{count}, kNone);
    leaf_.constrained.assign(root_constrained_ ? 3 * std::size_t{count} : 0, 0);
    // Neighbours by matching each half-edge with its reverse among the half-edges filed under
    // their smaller end (a vertex's few edges), no hashing: this runs after every call.
    const std::uint32_t n = static_cast<std::uint32_t>(xy_.size() / 2);
    std::vector<std::uint32_t> start(std::size_t{n} + 1, 0);
    for (TriIdx t = 0; t < count; ++t) {
        const HRefinementNode2& node = nodes_[leaf_nodes_[t]];
        for (unsigned k = 0; k < 3; ++k) {
            leaf_.triangles[3 * t + k] = node.corners[k];
            if (root_constrained_) leaf_.constrained[3 * t + k] = (node.constrained >> k) & 1u;
            ++start[std::min(node.corners[k], node.corners[(k + 1) % 3]) + 1];
        }
    }
    for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> filed(3 * std::size_t{count});
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t e = 0; e < 3 * count; ++e) {
            const VertIdx a = leaf_.triangles[e], b = leaf_.triangles[e % 3 == 2 ? e - 2 : e + 1];
            filed[fill[std::min(a, b)]++] = e;
        }
    }
    for (std::uint32_t v = 0; v < n; ++v) {
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t e = filed[i];
            const VertIdx a = leaf_.triangles[e], b = leaf_.triangles[e % 3 == 2 ? e - 2 : e + 1];
            for (std::uint32_t j = i + 1; j < start[v + 1]; ++j) {
                const std::uint32_t f = filed[j];
                if (leaf_.triangles[f] == b && leaf_.triangles[f % 3 == 2 ? f - 2 : f + 1] == a) {
                    leaf_.neighbors[e] = f / 3;
                    leaf_.neighbors[f] = e / 3;
                }
            }
        }
    }
}

// The split points of the marked edges of node `id` (green: one edge, red: three), as vertex
// indices when they exist and as rounded coordinates when not, and whether every child of that
// split is strictly counter-clockwise; when not, the edges whose split points a failing child
// uses are added to `blame`.
bool HRefinedMesh2::split_is_ccw(std::uint32_t id, int green,
                                 std::vector<std::uint64_t>& blame) const {
    const HRefinementNode2& node = nodes_[id];
    // Points: 0..2 corners, 3..5 split points (placeholders where unsplit).
    std::array<std::array<double, 2>, 6> point{};
    for (int k = 0; k < 3; ++k) {
        const VertIdx v = node.corners[static_cast<std::size_t>(k)];
        point[static_cast<std::size_t>(k)] = {xy_[2 * std::size_t{v}], xy_[2 * std::size_t{v} + 1]};
        if (green >= 0 && k != green) continue;
        const std::uint64_t e = node_edge(node, k);
        const auto found = split_of_.find(e);
        auto& out = point[static_cast<std::size_t>(3 + k)];
        if (found != split_of_.end()) {
            out = {xy_[2 * std::size_t{found->second}], xy_[2 * std::size_t{found->second} + 1]};
        } else {
            const VertIdx a = key_low(e), b = key_high(e);
            out = {rounded_midpoint(xy_[2 * std::size_t{a}], xy_[2 * std::size_t{b}]),
                   rounded_midpoint(xy_[2 * std::size_t{a} + 1], xy_[2 * std::size_t{b} + 1])};
        }
    }
    const ChildPattern pattern = child_pattern({0, 1, 2}, {3, 4, 5}, 0, green);
    bool ccw = true;
    for (int c = 0; c < pattern.count; ++c) {
        const auto& ch = pattern.corners[static_cast<std::size_t>(c)];
        if (predicates::orient2d(point[ch[0]].data(), point[ch[1]].data(), point[ch[2]].data()) ==
            Sign::Positive)
            continue;
        for (const VertIdx local : ch) {
            if (local >= 3) blame.push_back(node_edge(node, static_cast<int>(local - 3)));
        }
        ccw = false;
    }
    return ccw;
}

// Splits leaf `id` red (green < 0) or green on edge `green`, making the split points it needs.
void HRefinedMesh2::split_node(std::uint32_t id, int green) {
    std::array<VertIdx, 3> m{kNone, kNone, kNone};
    for (int k = 0; k < 3; ++k) {
        if (green >= 0 && k != green) continue;
        const auto& c = nodes_[id].corners;
        m[static_cast<std::size_t>(k)] =
            split_vertex(c[static_cast<std::size_t>(k)], c[static_cast<std::size_t>((k + 1) % 3)]);
    }
    const ChildPattern pattern =
        child_pattern(nodes_[id].corners, m, nodes_[id].constrained, green);
    std::array<std::uint32_t, 4> children{kNone, kNone, kNone, kNone};
    for (int c = 0; c < pattern.count; ++c) {
        const std::uint32_t child = new_node();  // may reallocate nodes_
        HRefinementNode2& made = nodes_[child];
        made.corners = pattern.corners[static_cast<std::size_t>(c)];
        made.constrained = pattern.constrained[static_cast<std::size_t>(c)];
        made.parent = id;
        made.level = nodes_[id].level + 1;
        children[static_cast<std::size_t>(c)] = child;
    }
    HRefinementNode2& node = nodes_[id];
    node.children = children;
    node.child_count = static_cast<std::uint8_t>(pattern.count);
    node.split_edge = static_cast<std::uint8_t>(green < 0 ? 0 : green);
}

// One closure-and-split pass [Bank-Sherman-Weiser §3]. Closure to a fixed point over a worklist:
// a leaf with two marked edges gets the third; a green child with a marked edge has its pair
// undone and its parent split red at once (so the parent's red children, which may carry marks
// on the halves of its split edge, take part in the same closure). Every leaf whose marks
// changed is then checked: its split (red for three marked edges, green for one) must give
// strictly counter-clockwise children (exact orient2d). A refusal (a split that is not, a
// third edge that is refused, a green child whose parent cannot go red) blocks the edge to
// blame, unmarks it and sends its leaves back to the closure, so refusals cost only local work.
// Splits are made after the fixed point, except a green undo's red split, which is made at
// once: its edges are committed, and a refusal of a committed edge (a neighbour that cannot
// split it) rolls the pass back and starts again with that edge blocked (blocked only grows,
// so this ends).
void HRefinedMesh2::plan_and_apply(std::span<const std::uint64_t> marks,
                                   std::unordered_set<std::uint64_t>& blocked,
                                   HRefinementCounters2& round) {
    for (;;) {
        // What a rollback restores.
        const std::vector<double> saved_xy = xy_;
        const auto saved_vertex_parent = vertex_parent_;
        const auto saved_nodes = nodes_;
        const auto saved_free_nodes = free_nodes_;
        const HRefinementCounters2 saved_round = round;
        auto rollback = [&] {
            xy_ = saved_xy;
            vertex_parent_ = saved_vertex_parent;
            nodes_ = saved_nodes;
            free_nodes_ = saved_free_nodes;
            // (rebuilt rather than copied on every pass: rollbacks are rare)
            split_of_.clear();
            for (VertIdx v = root_vertices_; v < vertex_parent_.size(); ++v)
                split_of_.emplace(edge_key(vertex_parent_[v][0], vertex_parent_[v][1]), v);
            const std::uint64_t iterations = round.closure_iterations;
            round = saved_round;
            round.closure_iterations = iterations;
        };

        // The leaves around each edge (at most two).
        EdgeSides around(2 * leaf_nodes_.size());
        auto attach = [&](std::uint32_t id) {
            for (int k = 0; k < 3; ++k) {
                std::array<std::uint32_t, 2>& sides = around.at(node_edge(nodes_[id], k));
                (sides[0] == kNone ? sides[0] : sides[1]) = id;
            }
        };
        auto detach = [&](std::uint32_t id) {
            for (int k = 0; k < 3; ++k) {
                auto& slots = around.at(node_edge(nodes_[id], k));
                (slots[0] == id ? slots[0] : slots[1]) = kNone;
            }
        };
        for (const std::uint32_t id : leaf_nodes_) attach(id);
        std::unordered_set<std::uint64_t> marked, committed;
        std::vector<std::uint64_t> hard;  // committed edges a neighbour cannot split
        std::vector<std::uint32_t> work, touched;
        auto push_around = [&](std::uint64_t e) {
            const std::array<std::uint32_t, 2>* sides = around.find(e);
            if (sides == nullptr) return;
            for (const std::uint32_t id : *sides) {
                if (id != kNone) work.push_back(id);
            }
        };
        auto mark = [&](std::uint64_t e) {
            if (blocked.count(e) || !marked.insert(e).second) return;
            push_around(e);
        };
        auto refuse = [&](std::uint64_t e) {
            if (committed.count(e)) {
                hard.push_back(e);
                return;
            }
            if (!blocked.insert(e).second) return;
            if (marked.erase(e)) push_around(e);
        };
        for (const std::uint64_t e : marks) mark(e);
        std::vector<std::uint64_t> blame;
        for (;;) {
            while (!work.empty()) {
                const std::uint32_t id = work.back();
                work.pop_back();
                if (!nodes_[id].alive || nodes_[id].child_count != 0) continue;
                ++round.closure_iterations;
                touched.push_back(id);
                std::array<bool, 3> on{};
                int count = 0;
                for (int k = 0; k < 3; ++k) {
                    on[static_cast<std::size_t>(k)] = marked.count(node_edge(nodes_[id], k)) != 0;
                    count += on[static_cast<std::size_t>(k)];
                }
                if (count == 0) continue;
                const std::uint32_t parent = nodes_[id].parent;
                if (parent != kNone && nodes_[parent].child_count == 2) {
                    // A green child is never split: undo the pair and split the parent red,
                    // unless an edge of the parent is refused or its red split is not
                    // counter-clockwise, when this child's marks are refused.
                    bool free = true;
                    for (int k = 0; k < 3; ++k)
                        free = free && !blocked.count(node_edge(nodes_[parent], k));
                    blame.clear();
                    if (!free || !split_is_ccw(parent, -1, blame)) {
                        for (int k = 0; k < 3; ++k) {
                            if (on[static_cast<std::size_t>(k)]) refuse(node_edge(nodes_[id], k));
                        }
                        continue;
                    }
                    for (int c = 0; c < 2; ++c) {
                        const std::uint32_t child =
                            nodes_[parent].children[static_cast<std::size_t>(c)];
                        detach(child);
                        nodes_[child].alive = 0;
                        free_nodes_.push_back(child);
                    }
                    nodes_[parent].child_count = 0;
                    nodes_[parent].children = {kNone, kNone, kNone, kNone};
                    ++round.green_undone;
                    split_node(parent, -1);
                    ++round.red;
                    for (int c = 0; c < 4; ++c) {
                        const std::uint32_t child =
                            nodes_[parent].children[static_cast<std::size_t>(c)];
                        attach(child);
                        work.push_back(child);
                    }
                    for (int k = 0; k < 3; ++k) {
                        committed.insert(node_edge(nodes_[parent], k));
                        mark(node_edge(nodes_[parent], k));
                    }
                    continue;
                }
                if (count == 2) {
                    int k = 0;
                    while (on[static_cast<std::size_t>(k)]) ++k;
                    const std::uint64_t third = node_edge(nodes_[id], k);
                    if (blocked.count(third)) {
                        // Red is refused here: keep the leaf green on one of its marked edges
                        // and refuse the other (the larger key, so the choice is reproducible).
                        refuse(std::max(node_edge(nodes_[id], (k + 1) % 3),
                                        node_edge(nodes_[id], (k + 2) % 3)));
                    } else {
                        mark(third);
                    }
                }
            }
            // The splits of the leaves whose marks changed, checked before any is made.
            std::sort(touched.begin(), touched.end());
            touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
            for (const std::uint32_t id : touched) {
                if (!nodes_[id].alive || nodes_[id].child_count != 0) continue;
                int count = 0, green = -1;
                for (int k = 0; k < 3; ++k) {
                    if (marked.count(node_edge(nodes_[id], k))) {
                        ++count;
                        green = k;
                    }
                }
                if (count == 0 || count == 2) continue;  // 2: only beside a hard conflict
                blame.clear();
                if (!split_is_ccw(id, count == 3 ? -1 : green, blame)) {
                    for (const std::uint64_t e : blame) refuse(e);
                }
            }
            touched.clear();
            if (work.empty()) break;
        }
        if (!hard.empty()) {
            rollback();
            ++round.restarts;
            blocked.insert(hard.begin(), hard.end());
            continue;
        }

        // Split every leaf with marked edges, in depth-first order (reproducible numbering).
        collect_leaves();
        std::vector<std::pair<std::uint32_t, int>> splits;  // (leaf, green edge or -1)
        for (const std::uint32_t id : leaf_nodes_) {
            int count = 0, green = -1;
            for (int k = 0; k < 3; ++k) {
                if (marked.count(node_edge(nodes_[id], k))) {
                    ++count;
                    green = k;
                }
            }
            if (count == 0) continue;
            EM_ASSERT(count != 2);
            splits.emplace_back(id, count == 3 ? -1 : green);
        }
        for (const auto& [id, green] : splits) {
            split_node(id, green);
            ++(green < 0 ? round.red : round.green);
        }
        rebuild_leaf_mesh();
        return;
    }
}

HRefinementCounters2 HRefinedMesh2::refine(std::span<const VertIdx> marked_edges) {
    const std::uint32_t n = static_cast<std::uint32_t>(xy_.size() / 2);
    if (marked_edges.size() % 2 != 0)
        input_error("marked edges: an odd number of vertex indices (" +
                    std::to_string(marked_edges.size()) + ")");
    std::vector<std::uint64_t> wanted;
    wanted.reserve(marked_edges.size() / 2);
    for (std::size_t i = 0; i + 1 < marked_edges.size(); i += 2) {
        const VertIdx a = marked_edges[i], b = marked_edges[i + 1];
        if (a >= n || b >= n)
            input_error("marked edge " + std::to_string(i / 2) + " (" + std::to_string(a) + ", " +
                        std::to_string(b) + ") names a vertex that does not exist (" +
                        std::to_string(n) + " vertices)");
        wanted.push_back(edge_key(a, b));
    }
    std::sort(wanted.begin(), wanted.end());
    wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());

    HRefinementCounters2 round;
    std::unordered_set<std::uint64_t> blocked;
    // The wanted edges that are edges of the leaf mesh (lookups in the small set of marks).
    const std::unordered_set<std::uint64_t> wanted_set(wanted.begin(), wanted.end());
    std::unordered_set<std::uint64_t> leaf_edges;
    auto collect_leaf_edges = [&] {
        leaf_edges.clear();
        for (const std::uint32_t id : leaf_nodes_) {
            for (int k = 0; k < 3; ++k) {
                const std::uint64_t e = node_edge(nodes_[id], k);
                if (wanted_set.count(e)) leaf_edges.insert(e);
            }
        }
    };
    collect_leaf_edges();
    for (const std::uint64_t e : wanted) round.ignored_marks += leaf_edges.count(e) == 0;
    // One pass splits or refuses every mark it sees (a green pair undone in it is split red at
    // once, and its red children take part in the same closure). Another pass runs only if a
    // marked edge is somehow still an edge; a split edge never comes back, so the bound only
    // guards against a bug.
    for (int pass = 0;; ++pass) {
        EM_ASSERT(pass < 1000);
        std::vector<std::uint64_t> present;
        for (const std::uint64_t e : wanted) {
            if (leaf_edges.count(e) && !blocked.count(e)) present.push_back(e);
        }
        if (present.empty()) break;
        ++round.rounds;
        plan_and_apply(present, blocked, round);
        collect_leaf_edges();
    }
    round.refused_edges = blocked.size();
    counters_.red += round.red;
    counters_.green += round.green;
    counters_.green_undone += round.green_undone;
    counters_.closure_iterations += round.closure_iterations;
    counters_.refused_edges += round.refused_edges;
    counters_.rounds += round.rounds;
    counters_.restarts += round.restarts;
    counters_.ignored_marks += round.ignored_marks;
    return round;
}

std::vector<VertIdx> HRefinedMesh2::derefine(std::span<const TriIdx> flagged_leaves) {
    const auto leaf_count = static_cast<TriIdx>(leaf_nodes_.size());
    std::vector<std::uint8_t> flagged(nodes_.size(), 0);
    for (const TriIdx t : flagged_leaves) {
        if (t >= leaf_count)
            input_error("flagged triangle " + std::to_string(t) + " does not exist (" +
                        std::to_string(leaf_count) + " leaf triangles)");
        flagged[leaf_nodes_[t]] = 1;
    }
    // Candidates: parents whose children are all flagged leaves, and every green pair (a
    // closure artefact: it goes when its split point is no longer needed across its edge, so
    // coarsening a red parent takes its green neighbours along). The decision per candidate:
    // kCoarsen (no children), kGreen (a red parent whose one still needed split point stays:
    // it coarsens to the green pair on that edge, green_edge[id]), kKeep.
    constexpr std::uint8_t kKeep = 0, kGreen = 1, kCoarsen = 2;
    std::vector<std::uint8_t> decision(nodes_.size(), kKeep);
    std::vector<std::uint8_t> green_edge(nodes_.size(), 0);
    std::vector<std::uint32_t> candidates;
    for (const std::uint32_t id : leaf_nodes_) {
        const std::uint32_t parent = nodes_[id].parent;
        if (parent == kNone || decision[parent] != kKeep) continue;
        const HRefinementNode2& p = nodes_[parent];
        bool all = true;
        for (int c = 0; c < p.child_count; ++c) {
            const std::uint32_t child = p.children[static_cast<std::size_t>(c)];
            all = all && nodes_[child].child_count == 0 && (flagged[child] || p.child_count == 2);
        }
        if (!all) continue;
        decision[parent] = kCoarsen;
        candidates.push_back(parent);
    }
    // The leaves at each vertex.
    const std::uint32_t n = static_cast<std::uint32_t>(xy_.size() / 2);
    std::vector<std::uint32_t> start(std::size_t{n} + 1, 0);
    for (const std::uint32_t id : leaf_nodes_) {
        for (const VertIdx v : nodes_[id].corners) ++start[v + 1];
    }
    for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> at(start[n]);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (const std::uint32_t id : leaf_nodes_) {
            for (const VertIdx v : nodes_[id].corners) at[fill[v]++] = id;
        }
    }
    // Whether vertex m is still a corner after this step of what stands in parent x's place:
    // its children (kept), its green pair on green_edge[x] (its corners and that split
    // point), or itself (its corners).
    const auto stays_corner = [&](std::uint32_t x, VertIdx m) {
        const HRefinementNode2& node = nodes_[x];
        if (std::find(node.corners.begin(), node.corners.end(), m) != node.corners.end())
            return true;
        if (decision[x] == kKeep) return true;
        return decision[x] == kGreen && split_point(nodes_, node, green_edge[x]) == m;
    };
    // A split point hangs when a leaf outside the parent keeps it as a corner after this step:
    // that leaf stays unless its own parent coarsens (fully, or to a green pair not on m).
    // Decided for all candidates together, to the largest fixed point (decisions only go down,
    // kCoarsen -> kGreen -> kKeep, each when something that stays needs more of its split
    // points), so that neighbouring parents coarsen together. A red parent with exactly one
    // hanging split point coarsens to the green pair on that edge when both green children are
    // strictly counter-clockwise (exact orient2d on the rounded split point), so that a wake
    // coarsens into the closure of what stays fine instead of keeping a whole red layer. A
    // worklist: lowering a decision re-examines only the candidates whose split points its
    // children's corners are.
    std::vector<std::uint64_t> blame;
    std::vector<std::uint32_t> work(candidates.rbegin(), candidates.rend());
    while (!work.empty()) {
        const std::uint32_t id = work.back();
        work.pop_back();
        if (decision[id] == kKeep) continue;
        const HRefinementNode2& p = nodes_[id];
        int hanging = 0, hanging_edge = -1;
        for (int k = 0; k < 3 && hanging < 2; ++k) {
            const VertIdx m = split_point(nodes_, p, k);
            if (m == kNone) continue;
            bool hangs = false;
            for (std::uint32_t i = start[m]; i < start[m + 1] && !hangs; ++i) {
                const std::uint32_t x = nodes_[at[i]].parent;
                if (x == id) continue;
                hangs = x == kNone || stays_corner(x, m);
            }
            if (hangs) {
                ++hanging;
                hanging_edge = k;
            }
        }
        std::uint8_t now = kCoarsen;
        if (hanging == 1 && p.child_count == 4) {
            blame.clear();
            now = split_is_ccw(id, hanging_edge, blame) ? kGreen : kKeep;
        } else if (hanging > 0) {
            now = kKeep;
        }
        if (now == decision[id]) continue;
        EM_ASSERT(now < decision[id]);
        decision[id] = now;
        green_edge[id] = static_cast<std::uint8_t>(hanging_edge < 0 ? 0 : hanging_edge);
        for (int c = 0; c < p.child_count; ++c) {
            for (const VertIdx v : nodes_[p.children[static_cast<std::size_t>(c)]].corners) {
                for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
                    const std::uint32_t x = nodes_[at[i]].parent;
                    if (x != kNone && x != id && decision[x] != kKeep) work.push_back(x);
                }
            }
        }
    }
    for (const std::uint32_t id : candidates) {
        if (decision[id] == kKeep) continue;
        for (int c = 0; c < nodes_[id].child_count; ++c) {
            const std::uint32_t child = nodes_[id].children[static_cast<std::size_t>(c)];
            nodes_[child].alive = 0;
            free_nodes_.push_back(child);
        }
        HRefinementNode2& node = nodes_[id];
        node.child_count = 0;
        node.split_edge = 0;
        node.children = {kNone, kNone, kNone, kNone};
        if (decision[id] == kGreen) {
            split_node(id, green_edge[id]);  // its split point exists: no new vertex
            ++counters_.red_to_green;
        } else {
            ++counters_.derefined;
        }
    }
    collect_leaves();

    // Remove the vertices no leaf uses (never a root vertex), keeping the order.
    std::vector<std::uint8_t> used(n, 0);
    std::fill(used.begin(), used.begin() + root_vertices_, 1);
    for (const std::uint32_t id : leaf_nodes_) {
        for (const VertIdx v : nodes_[id].corners) used[v] = 1;
    }
    std::vector<VertIdx> map(n, kNone);
    VertIdx next = 0;
    for (VertIdx v = 0; v < n; ++v) {
        if (!used[v]) continue;
        map[v] = next;
        xy_[2 * std::size_t{next}] = xy_[2 * std::size_t{v}];
        xy_[2 * std::size_t{next} + 1] = xy_[2 * std::size_t{v} + 1];
        vertex_parent_[next] = vertex_parent_[v];
        ++next;
    }
    counters_.removed_vertices += n - next;
    xy_.resize(2 * std::size_t{next});
    vertex_parent_.resize(next);
    split_of_.clear();
    for (VertIdx v = root_vertices_; v < next; ++v) {
        auto& ends = vertex_parent_[v];
        ends = {map[ends[0]], map[ends[1]]};
        EM_ASSERT(ends[0] != kNone && ends[1] != kNone);
        split_of_.emplace(edge_key(ends[0], ends[1]), v);
    }
    for (HRefinementNode2& node : nodes_) {
        if (!node.alive) continue;
        for (VertIdx& v : node.corners) {
            v = map[v];
            EM_ASSERT(v != kNone);
        }
    }
    rebuild_leaf_mesh();
    return map;
}

std::vector<double> HRefinedMesh2::transfer_field(std::span<const double> field) const {
    const std::size_t n = xy_.size() / 2;
    if (field.size() > n || field.size() < root_vertices_)
        input_error("field of " + std::to_string(field.size()) + " values for a mesh of " +
                    std::to_string(n) + " vertices (" + std::to_string(root_vertices_) +
                    " at the root)");
    std::vector<double> out(field.begin(), field.end());
    out.resize(n);
    // Parent edges name earlier vertices only (a split point is made after its edge's ends).
    for (std::size_t v = field.size(); v < n; ++v) {
        const auto& ends = vertex_parent_[v];
        out[v] = rounded_midpoint(out[ends[0]], out[ends[1]]);
    }
    return out;
}

std::vector<double> restrict_field(std::span<const double> field,
                                   std::span<const VertIdx> vertex_map) {
    if (field.size() != vertex_map.size())
        throw InputError("h-refinement: field of " + std::to_string(field.size()) +
                         " values for a vertex map of " + std::to_string(vertex_map.size()));
    std::size_t kept = 0;
    for (const VertIdx v : vertex_map) kept += v != kNone;
    std::vector<double> out(kept);
    for (std::size_t v = 0; v < field.size(); ++v) {
        if (vertex_map[v] == kNone) continue;
        if (vertex_map[v] >= kept)
            throw InputError("h-refinement: vertex map sends " + std::to_string(v) + " to " +
                             std::to_string(vertex_map[v]) + ", past the " + std::to_string(kept) +
                             " kept vertices");
        out[vertex_map[v]] = field[v];
    }
    return out;
}

triangulation::CheckReport check_h_refined_mesh_2d(const HRefinedMesh2& mesh) {
    return check_h_refinement_history_2d(mesh.leaf_mesh(), mesh.nodes(), mesh.leaf_nodes(),
                                         mesh.vertex_parents(), mesh.root_triangle_count(),
                                         mesh.root_vertex_count());
}

triangulation::CheckReport check_h_refinement_history_2d(
    const triangulation::Triangulation2& leaf, std::span<const HRefinementNode2> nodes,
    std::span<const std::uint32_t> leaf_nodes,
    std::span<const std::array<VertIdx, 2>> vertex_parents, std::uint32_t root_triangle_count,
    std::uint32_t root_vertex_count) {
    using triangulation::CheckReport;
    if (vertex_parents.size() != leaf.vertex_count() || root_vertex_count > leaf.vertex_count() ||
        root_triangle_count > nodes.size())
        return CheckReport{false,
                           "the history's vertex records or root counts do not match its "
                           "leaf mesh",
                           kNone,
                           {}};
    auto parent_edge = [&](VertIdx v) { return vertex_parents[v]; };
    const std::uint32_t n = leaf.vertex_count();
    const TriIdx count = leaf.triangle_count();
    const auto& tv = leaf.triangles;
    auto fail = [](std::string problem, TriIdx t = kNone, std::vector<VertIdx> vertices = {}) {
        return CheckReport{false, std::move(problem), t, std::move(vertices)};
    };
    auto named = [&](TriIdx t) {
        return "leaf triangle " + std::to_string(t) + " (" + std::to_string(tv[3 * t]) + ", " +
               std::to_string(tv[3 * t + 1]) + ", " + std::to_string(tv[3 * t + 2]) + ")";
    };
    if (tv.size() % 3 != 0 || leaf.neighbors.size() != tv.size() ||
        (!leaf.constrained.empty() && leaf.constrained.size() != tv.size()) ||
        leaf_nodes.size() != count)
        return fail("the leaf mesh's arrays have inconsistent sizes");

    // The leaf mesh: orientation, edges once, neighbours matching the edges, flags symmetric.
    std::unordered_map<std::uint64_t, std::uint32_t> edge_of;
    edge_of.reserve(tv.size());
    for (TriIdx t = 0; t < count; ++t) {
        const std::uint32_t id = leaf_nodes[t];
        if (id >= nodes.size() || !nodes[id].alive || nodes[id].child_count != 0)
            return fail(named(t) + " is not a leaf of the history", t);
        for (unsigned k = 0; k < 3; ++k) {
            if (tv[3 * t + k] >= n)
                return fail(named(t) + " names a vertex that does not exist", t);
            if (nodes[id].corners[k] != tv[3 * t + k])
                return fail(named(t) + " differs from its history node " + std::to_string(id), t);
        }
        if (predicates::orient2d(leaf.point(tv[3 * t]), leaf.point(tv[3 * t + 1]),
                                 leaf.point(tv[3 * t + 2])) != Sign::Positive)
            return fail(named(t) + " is not strictly counter-clockwise", t,
                        {tv[3 * t], tv[3 * t + 1], tv[3 * t + 2]});
        for (unsigned k = 0; k < 3; ++k) {
            if (!edge_of.emplace(directed_key(tv[3 * t + k], tv[3 * t + (k + 1) % 3]), 3 * t + k)
                     .second)
                return fail("edge " + std::to_string(tv[3 * t + k]) + " -> " +
                                std::to_string(tv[3 * t + (k + 1) % 3]) +
                                " appears in two leaf triangles (overlap)",
                            t);
        }
    }
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const auto other = edge_of.find(directed_key(tv[3 * t + (k + 1) % 3], tv[3 * t + k]));
            const TriIdx across = other == edge_of.end() ? kNone : other->second / 3;
            if (leaf.neighbors[3 * t + k] != across)
                return fail(named(t) + ": neighbor " + std::to_string(k) + " is " +
                                std::to_string(leaf.neighbors[3 * t + k]) + ", not " +
                                std::to_string(across),
                            t);
            if (across != kNone &&
                leaf.is_constrained(t, static_cast<int>(k)) !=
                    leaf.is_constrained(across, static_cast<int>(other->second % 3)))
                return fail(
                    named(t) + ": edge " + std::to_string(k) + " is constrained on one side only",
                    t);
        }
    }

    // Nesting: every split node's children are its pattern, its split points rounded midpoints
    // of its edges within rounding of them, its children strictly counter-clockwise.
    std::size_t alive_leaves = 0;
    for (std::uint32_t id = 0; id < nodes.size(); ++id) {
        const HRefinementNode2& node = nodes[id];
        if (!node.alive) continue;
        const std::string name = "history node " + std::to_string(id);
        for (const VertIdx v : node.corners) {
            if (v >= n) return fail(name + " names a vertex that does not exist");
        }
        if (id < root_triangle_count) {
            if (node.parent != kNone || node.level != 0)
                return fail(name + " is a root triangle with a parent or a level");
        } else {
            if (node.parent >= nodes.size() || !nodes[node.parent].alive)
                return fail(name + " has no live parent");
            const HRefinementNode2& p = nodes[node.parent];
            if (std::find(p.children.begin(), p.children.begin() + p.child_count, id) ==
                p.children.begin() + p.child_count)
                return fail(name + " is not a child of its parent");
            if (node.level != p.level + 1) return fail(name + " has the wrong level");
        }
        if (node.child_count == 0) {
            ++alive_leaves;
            continue;
        }
        if (node.child_count != 2 && node.child_count != 4)
            return fail(name + " has " + std::to_string(node.child_count) + " children");
        std::array<VertIdx, 3> m{kNone, kNone, kNone};
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < node.child_count; ++c) {
                const std::uint32_t child = node.children[static_cast<std::size_t>(c)];
                if (child >= nodes.size() || !nodes[child].alive || nodes[child].parent != id)
                    return fail(name + ": child " + std::to_string(c) + " is not linked to it");
            }
            const VertIdx v = split_point(nodes, node, k);
            m[static_cast<std::size_t>(k)] = v;
            if (v == kNone) continue;
            const VertIdx a = node.corners[static_cast<std::size_t>(k)],
                          b = node.corners[static_cast<std::size_t>((k + 1) % 3)];
            if (v >= n) return fail(name + ": a split point does not exist");
            const auto ends = parent_edge(v);
            if (edge_key(ends[0], ends[1]) != edge_key(a, b))
                return fail(name + ": split point " + std::to_string(v) +
                                " is not recorded as the split point of edge " + std::to_string(a) +
                                " - " + std::to_string(b),
                            kNone, {v, a, b});
            const double* pa = leaf.point(a);
            const double* pb = leaf.point(b);
            const double* pm = leaf.point(v);
            if (pm[0] != rounded_midpoint(pa[0], pb[0]) || pm[1] != rounded_midpoint(pa[1], pb[1]))
                return fail(name + ": split point " + std::to_string(v) +
                                " is not the rounded midpoint of its edge",
                            kNone, {v, a, b});
            if (!predicates::within_rounding_of_segment(pm, pa, pb))
                return fail(name + ": split point " + std::to_string(v) +
                                " is not within rounding of its edge",
                            kNone, {v, a, b});
        }
        const ChildPattern pattern = child_pattern(node.corners, m, node.constrained,
                                                   node.child_count == 4 ? -1 : node.split_edge);
        for (int c = 0; c < node.child_count; ++c) {
            const HRefinementNode2& child = nodes[node.children[static_cast<std::size_t>(c)]];
            const auto& want = pattern.corners[static_cast<std::size_t>(c)];
            if (child.corners != want)
                return fail(name + ": child " + std::to_string(c) + " is not its " +
                            (node.child_count == 4 ? "red" : "green") + " pattern");
            if (child.constrained != pattern.constrained[static_cast<std::size_t>(c)])
                return fail(name + ": child " + std::to_string(c) +
                            " does not inherit its constrained edges");
            if (predicates::orient2d(leaf.point(want[0]), leaf.point(want[1]),
                                     leaf.point(want[2])) != Sign::Positive)
                return fail(
                    name + ": child " + std::to_string(c) + " is not strictly counter-clockwise",
                    kNone, {want[0], want[1], want[2]});
            if (node.child_count == 2 && child.child_count != 0)
                return fail(name + " is a green pair with a child refined further");
        }
    }
    if (alive_leaves != count)
        return fail(std::to_string(alive_leaves) + " leaves in the history, " +
                    std::to_string(count) + " in the leaf mesh");

    // Conformity: climb each leaf edge through the history to the root edge it lies on (or to
    // the node it crosses). An edge with no neighbour must lie on a boundary edge of the root,
    // else a vertex hangs on it; a constrained edge must lie on a constrained root edge.
    std::unordered_set<std::uint64_t> root_edges;
    for (std::uint32_t r = 0; r < root_triangle_count; ++r) {
        for (int k = 0; k < 3; ++k)
            root_edges.insert(
                directed_key(nodes[r].corners[static_cast<std::size_t>(k)],
                             nodes[r].corners[static_cast<std::size_t>((k + 1) % 3)]));
    }
    for (TriIdx t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k) {
            std::uint32_t id = leaf_nodes[t];
            int edge = k;
            bool on_root = true;
            while (nodes[id].parent != kNone) {
                const HRefinementNode2& child = nodes[id];
                const VertIdx p = child.corners[static_cast<std::size_t>(edge)],
                              q = child.corners[static_cast<std::size_t>((edge + 1) % 3)];
                const HRefinementNode2& x = nodes[child.parent];
                int found = -1;
                for (int j = 0; j < 3 && found < 0; ++j) {
                    const VertIdx a = x.corners[static_cast<std::size_t>(j)],
                                  b = x.corners[static_cast<std::size_t>((j + 1) % 3)];
                    const VertIdx mid = split_point(nodes, x, j);
                    auto on = [&](VertIdx v) { return v == a || v == b || v == mid; };
                    if (on(p) && on(q)) found = j;
                }
                if (found < 0) {
                    on_root = false;
                    break;
                }
                id = child.parent;
                edge = found;
            }
            const HRefinementNode2& top = nodes[id];
            const VertIdx a = top.corners[static_cast<std::size_t>(edge)],
                          b = top.corners[static_cast<std::size_t>((edge + 1) % 3)];
            const bool root_boundary = on_root && root_edges.count(directed_key(b, a)) == 0;
            if (leaf.neighbors[3 * t + static_cast<std::size_t>(k)] == kNone && !root_boundary)
                return fail(named(t) + ": edge " + std::to_string(k) +
                                " has no neighbour but is no piece of the root's boundary "
                                "(a hanging vertex)",
                            t);
            const bool constrained = on_root && ((top.constrained >> edge) & 1u) != 0;
            if (leaf.is_constrained(t, k) != constrained)
                return fail(named(t) + ": edge " + std::to_string(k) +
                                (constrained ? " lies on a constrained root edge but is not "
                                               "constrained"
                                             : " is constrained but lies on no constrained root "
                                               "edge"),
                            t);
        }
    }

    // Vertices: the root's have no parent edge; every later one is used by a leaf and made
    // after the ends of its parent edge.
    std::vector<std::uint8_t> used(n, 0);
    for (const VertIdx v : tv) used[v] = 1;
    for (VertIdx v = 0; v < n; ++v) {
        const auto ends = parent_edge(v);
        if (v < root_vertex_count) {
            if (ends[0] != kNone) return fail("root vertex " + std::to_string(v) + " has a parent");
            continue;
        }
        if (!used[v])
            return fail("vertex " + std::to_string(v) + " is used by no leaf", kNone, {v});
        if (ends[0] >= v || ends[1] >= v)
            return fail("vertex " + std::to_string(v) + " has a parent edge of later vertices",
                        kNone, {v});
    }
    return CheckReport{};
}

}  // namespace exactmesh::generators
