// SPDX-License-Identifier: MIT
// h-refinement of tetrahedra with history (see h_refinement_3d.hpp for the rules). Children are
// written as tuples of local nodes (0..3 the parent's corners, 4 + k the midpoint of local edge
// k) and oriented combinatorially, by the sign of their barycentric determinant (the sign with
// exact midpoints); orient3d on the rounded midpoints then only confirms it.
#include "generators/adaptation/h_refinement_3d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <set>
#include <unordered_set>
#include <utility>

#include "base/errors.hpp"
#include "generators/adaptation/refinement_forest.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"

namespace exactmesh::generators {

namespace {

using predicates::Sign;
using triangulation::kNone;

// Local edge k joins corners kEdges[k]; the opposite edge is 5 - k.
constexpr std::array<std::array<int, 2>, 6> kEdges{
    {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
// The edges of face f (opposite corner f).
constexpr std::array<std::uint8_t, 4> kFaceMask{0x38, 0x26, 0x15, 0x0B};
constexpr std::uint8_t kAllEdges = 0x3F;

constexpr int edge_index(int i, int j) {
    if (i > j) std::swap(i, j);
    for (int k = 0; k < 6; ++k) {
        if (kEdges[k][0] == i && kEdges[k][1] == j) return k;
    }
    return -1;
}

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

/// The pattern a set of marked local edges is upgraded to: itself when empty, one edge or a face;
/// the face's three edges when all marks lie in one face; else all six.
std::uint8_t upgraded_pattern(std::uint8_t mask) {
    if (mask == 0 || std::popcount(mask) == 1) return mask;
    for (std::uint8_t face : kFaceMask) {
        if ((mask & face) == mask) return face;
    }
    return kAllEdges;
}

/// The correctly rounded midpoint of a and b: (a + b) / 2 rounds once when a + b is finite
/// (halving is exact in the normal range, and a sum below 2^-1021 is exact), else both halves
/// are exact and the sum rounds once.
double midpoint(double a, double b) {
    const double sum = a + b;
    return std::isfinite(sum) ? sum * 0.5 : 0.5 * a + 0.5 * b;
}

struct FaceKey {
    std::uint64_t ab;
    std::uint32_t c;
    bool operator==(const FaceKey&) const = default;
};
struct FaceKeyHash {
    std::size_t operator()(const FaceKey& key) const noexcept {
        return std::hash<std::uint64_t>()(key.ab * 0x9E3779B97F4A7C15ull ^ key.c);
    }
};

FaceKey face_key(VertIdx a, VertIdx b, VertIdx c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {(std::uint64_t{a} << 32) | b, c};
}

/// The face of tet v opposite corner f.
FaceKey tet_face(const std::array<VertIdx, 4>& v, int f) {
    return face_key(v[f == 0 ? 1 : 0], v[f <= 1 ? 2 : 1], v[f <= 2 ? 3 : 2]);
}

using LocalTet = std::array<std::uint8_t, 4>;

/// Barycentric coordinates (times 2) of local node n.
std::array<int, 4> barycentric(std::uint8_t n) {
    std::array<int, 4> b{};
    if (n < 4) {
        b[n] = 2;
    } else {
        b[kEdges[n - 4][0]] = 1;
        b[kEdges[n - 4][1]] = 1;
    }
    return b;
}

long long det4(const std::array<std::array<int, 4>, 4>& m) {
    auto det3 = [&](int skip_col) {
        std::array<int, 3> c{};
        for (int j = 0, k = 0; j < 4; ++j) {
            if (j != skip_col) c[k++] = j;
        }
        const long long a = m[1][c[0]], b = m[1][c[1]], cc = m[1][c[2]];
        const long long d = m[2][c[0]], e = m[2][c[1]], f = m[2][c[2]];
        const long long g = m[3][c[0]], h = m[3][c[1]], i = m[3][c[2]];
        return a * (e * i - f * h) - b * (d * i - f * g) + cc * (d * h - e * g);
    };
    long long det = 0;
    for (int j = 0; j < 4; ++j) det += (j % 2 == 0 ? 1 : -1) * m[0][j] * det3(j);
    return det;
}

/// The child with its corners ordered so that it has the parent's orientation (with exact
/// midpoints): two corners swapped when the barycentric determinant is negative.
LocalTet oriented(LocalTet t) {
    std::array<std::array<int, 4>, 4> m{};
    for (int k = 0; k < 4; ++k) m[k] = barycentric(t[k]);
    const long long det = det4(m);
    if (det < 0) std::swap(t[2], t[3]);
    return t;
}

LocalTet with_replaced(LocalTet t, int corner, std::uint8_t node) {
    t[corner] = node;
    return t;
}

/// The 1:2, 1:4 and 1:8 children of a pattern (1:8 with the diagonal joining the midpoints of
/// local edges d and 5 - d), each oriented.
std::vector<LocalTet> children_of(std::uint8_t mask, int diagonal) {
    const LocalTet parent{0, 1, 2, 3};
    std::vector<LocalTet> children;
    const int count = std::popcount(mask);
    if (count == 1) {
        const int k = std::countr_zero(mask);
        const auto mid = static_cast<std::uint8_t>(4 + k);
        children.push_back(with_replaced(parent, kEdges[k][1], mid));
        children.push_back(with_replaced(parent, kEdges[k][0], mid));
    } else if (count == 3) {
        int apex = 0;
        while (kFaceMask[apex] != mask) ++apex;
        std::array<int, 3> face{};
        for (int j = 0, k = 0; j < 4; ++j) {
            if (j != apex) face[k++] = j;
        }
        for (int p : face) {
            LocalTet child = parent;
            for (int q : face) {
                if (q != p) child[q] = static_cast<std::uint8_t>(4 + edge_index(p, q));
            }
            children.push_back(child);
        }
        children.push_back(oriented({static_cast<std::uint8_t>(4 + edge_index(face[0], face[1])),
                                     static_cast<std::uint8_t>(4 + edge_index(face[1], face[2])),
                                     static_cast<std::uint8_t>(4 + edge_index(face[2], face[0])),
                                     static_cast<std::uint8_t>(apex)}));
    } else {
        for (int i = 0; i < 4; ++i) {
            LocalTet child = parent;
            for (int j = 0; j < 4; ++j) {
                if (j != i) child[j] = static_cast<std::uint8_t>(4 + edge_index(i, j));
            }
            children.push_back(child);
        }
        // The diagonal (a, b)-(c, d); the equator (a, c), (c, b), (b, d), (d, a) in cyclic order.
        const int a = kEdges[diagonal][0], b = kEdges[diagonal][1];
        const int c = kEdges[5 - diagonal][0], d = kEdges[5 - diagonal][1];
        const std::array<int, 4> equator{edge_index(a, c), edge_index(c, b), edge_index(b, d),
                                         edge_index(d, a)};
        for (int s = 0; s < 4; ++s) {
            children.push_back(oriented({static_cast<std::uint8_t>(4 + diagonal),
                                         static_cast<std::uint8_t>(4 + 5 - diagonal),
                                         static_cast<std::uint8_t>(4 + equator[s]),
                                         static_cast<std::uint8_t>(4 + equator[(s + 1) % 4])}));
        }
    }
    return children;
}

/// The positions of a parent's 10 local nodes (midpoints rounded, only those of `mask`).
struct LocalPoints {
    std::array<std::array<double, 3>, 10> p{};
    const double* operator[](std::uint8_t n) const { return p[n].data(); }
};

bool strictly_positive(const LocalPoints& pts, const LocalTet& t) {
    return predicates::orient3d(pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]) == Sign::Positive;
}

predicates::TetCorners corners(const LocalPoints& pts, const LocalTet& t) {
    return {pts[t[0]], pts[t[1]], pts[t[2]], pts[t[3]]};
}

}  // namespace

HRefinedMesh3::HRefinedMesh3(Tetrahedralization3 root) {
    if (root.xyz.size() % 3 != 0 || root.tets.size() % 4 != 0 ||
        root.neighbors.size() != root.tets.size()) {
        throw InputError("h-refinement: root tetrahedralization has inconsistent array sizes");
    }
    const std::uint32_t n = root.vertex_count();
    for (std::size_t i = 0; i < root.xyz.size(); ++i) {
        if (!std::isfinite(root.xyz[i])) {
            throw InputError("h-refinement: vertex " + std::to_string(i / 3) +
                             " has a non-finite coordinate");
        }
    }
    for (std::size_t i = 0; i < root.tets.size(); ++i) {
        if (root.tets[i] >= n) {
            throw InputError("h-refinement: tetrahedron " + std::to_string(i / 4) +
                             " names vertex " + std::to_string(root.tets[i]) + " of " +
                             std::to_string(n));
        }
    }
    for (std::uint32_t t = 0; t < root.tet_count(); ++t) {
        const VertIdx* v = root.tets.data() + 4 * std::size_t{t};
        if (predicates::orient3d(root.point(v[0]), root.point(v[1]), root.point(v[2]),
                                 root.point(v[3])) != Sign::Positive) {
            throw InputError("h-refinement: tetrahedron " + std::to_string(t) +
                             " is not positively oriented (exact orient3d)");
        }
    }
    xyz_ = std::move(root.xyz);
    root_vertices_ = n;
    root_tets_ = root.tet_count();
    ends_.assign(n, {kNone, kNone});
    uses_.assign(n, 0);
    nodes_.resize(root_tets_);
    for (std::uint32_t t = 0; t < root_tets_; ++t) {
        for (int k = 0; k < 4; ++k) nodes_[t].v[k] = root.tets[4 * t + k];
        set_leaf_uses(t, +1);
    }
    rebuild_leaves();
    previous_id_.resize(n);
    for (VertIdx v = 0; v < n; ++v) previous_id_[v] = v;
    previous_count_ = n;
}

bool HRefinedMesh3::is_split(VertIdx a, VertIdx b) const {
    const auto it = midpoints_.find(edge_key(a, b));
    return it != midpoints_.end() && uses_[it->second] > 0;
}

VertIdx HRefinedMesh3::midpoint_vertex(VertIdx a, VertIdx b) {
    const std::uint64_t key = edge_key(a, b);
    const auto it = midpoints_.find(key);
    if (it != midpoints_.end()) return it->second;
    const auto v = static_cast<VertIdx>(xyz_.size() / 3);
    EM_ASSERT(v < triangulation::kMaxPoints);
    for (int c = 0; c < 3; ++c) {
        xyz_.push_back(midpoint(xyz_[3 * std::size_t{a} + c], xyz_[3 * std::size_t{b} + c]));
    }
    ends_.push_back({std::min(a, b), std::max(a, b)});
    uses_.push_back(0);
    midpoints_.emplace(key, v);
    return v;
}

std::uint32_t HRefinedMesh3::new_node() {
    if (!free_nodes_.empty()) {
        const std::uint32_t id = free_nodes_.back();
        free_nodes_.pop_back();
        nodes_[id] = Node{};
        return id;
    }
    nodes_.emplace_back();
    return static_cast<std::uint32_t>(nodes_.size() - 1);
}

void HRefinedMesh3::set_leaf_uses(std::uint32_t node, int delta) {
    for (VertIdx v : nodes_[node].v) {
        uses_[v] = static_cast<std::uint32_t>(static_cast<int>(uses_[v]) + delta);
    }
}

void HRefinedMesh3::remove_children(std::uint32_t node) {
    Node& parent = nodes_[node];
    for (int k = 0; k < parent.child_count; ++k) {
        const std::uint32_t child = parent.children[k];
        EM_ASSERT(nodes_[child].kind == 0);
        set_leaf_uses(child, -1);
        nodes_[child].alive = false;
        free_nodes_.push_back(child);
    }
    parent.child_count = 0;
    parent.kind = 0;
    parent.split_mask = 0;
    set_leaf_uses(node, +1);
}

bool HRefinedMesh3::make_children(std::uint32_t node, std::uint8_t mask) {
    const std::array<VertIdx, 4> v = nodes_[node].v;
    LocalPoints pts;
    for (int i = 0; i < 4; ++i) {
        for (int c = 0; c < 3; ++c) pts.p[i][c] = xyz_[3 * std::size_t{v[i]} + c];
    }
    for (int k = 0; k < 6; ++k) {
        if ((mask >> k & 1) == 0) continue;
        const int i = kEdges[k][0], j = kEdges[k][1];
        for (int c = 0; c < 3; ++c) pts.p[4 + k][c] = midpoint(pts.p[i][c], pts.p[j][c]);
        // The rounded midpoint must stay in the closed parent: on the inner side of the two
        // faces that do not contain its edge (those opposite i and opposite j).
        for (int opposite : {i, j}) {
            const LocalTet probe =
                with_replaced({0, 1, 2, 3}, opposite, static_cast<std::uint8_t>(4 + k));
            if (predicates::orient3d(pts[probe[0]], pts[probe[1]], pts[probe[2]], pts[probe[3]]) ==
                Sign::Negative) {
                return false;
            }
        }
    }
    std::vector<LocalTet> children;
    int diagonal = 0;
    if (std::popcount(mask) != 6) {
        children = children_of(mask, 0);
        for (const LocalTet& child : children) {
            if (!strictly_positive(pts, child)) {
                return false;
            }
        }
    } else {
        // The diagonals in the order of the parent's global vertex ids (see the header).
        std::array<int, 4> by_id{0, 1, 2, 3};
        std::sort(by_id.begin(), by_id.end(), [&](int a, int b) { return v[a] < v[b]; });
        const std::array<int, 3> candidates{
            std::min(edge_index(by_id[0], by_id[1]), 5 - edge_index(by_id[0], by_id[1])),
            std::min(edge_index(by_id[0], by_id[2]), 5 - edge_index(by_id[0], by_id[2])),
            std::min(edge_index(by_id[0], by_id[3]), 5 - edge_index(by_id[0], by_id[3]))};
        int best = -1;
        predicates::TetCorners best_worst{};
        for (int d : candidates) {
            std::vector<LocalTet> trial = children_of(mask, d);
            if (!std::all_of(trial.begin(), trial.end(),
                             [&](const LocalTet& t) { return strictly_positive(pts, t); })) {
                continue;
            }
            predicates::TetCorners worst = corners(pts, trial[4]);
            for (int s = 5; s < 8; ++s) {
                const predicates::TetCorners inner = corners(pts, trial[s]);
                if (predicates::compare_volume_edge(inner, worst) == Sign::Negative) worst = inner;
            }
            if (best < 0 || predicates::compare_volume_edge(worst, best_worst) == Sign::Positive) {
                best = d;
                best_worst = worst;
                children = std::move(trial);
            }
        }
        if (best < 0) {
            return false;
        }
        diagonal = best;
    }
    // Commit: vertices (once per edge), nodes, uses.
    std::array<VertIdx, 10> global{};
    for (int i = 0; i < 4; ++i) global[i] = v[i];
    for (int k = 0; k < 6; ++k) {
        if (mask >> k & 1) global[4 + k] = midpoint_vertex(v[kEdges[k][0]], v[kEdges[k][1]]);
    }
    set_leaf_uses(node, -1);
    const std::uint32_t level = nodes_[node].level + 1;
    std::array<std::uint32_t, 8> ids{};
    for (std::size_t c = 0; c < children.size(); ++c) {
        const std::uint32_t id = new_node();
        Node& child = nodes_[id];
        for (int k = 0; k < 4; ++k) child.v[k] = global[children[c][k]];
        child.parent = node;
        child.level = level;
        ids[c] = id;
        set_leaf_uses(id, +1);
    }
    Node& parent = nodes_[node];
    parent.children = ids;
    parent.child_count = static_cast<std::uint8_t>(children.size());
    parent.kind = static_cast<std::uint8_t>(children.size() == 2 ? 2 : children.size());
    parent.split_mask = mask;
    parent.diagonal = static_cast<std::uint8_t>(diagonal);
    return true;
}

void HRefinedMesh3::rebuild_leaves() {
    detail::collect_forest_leaves<Node>(nodes_, root_tets_, leaves_);
}

void HRefinedMesh3::refine(std::span<const std::array<VertIdx, 2>> marked_edges) {
    std::unordered_set<std::uint64_t> leaf_edges;
    for (std::uint32_t leaf : leaves_) {
        for (const auto& e : kEdges)
            leaf_edges.insert(edge_key(nodes_[leaf].v[e[0]], nodes_[leaf].v[e[1]]));
    }
    std::vector<std::uint64_t> marks;
    for (const auto& e : marked_edges) {
        if (e[0] == e[1] || !leaf_edges.count(edge_key(e[0], e[1]))) {
            throw InputError("h-refinement: marked pair (" + std::to_string(e[0]) + ", " +
                             std::to_string(e[1]) + ") is not an edge of the leaf mesh");
        }
        marks.push_back(edge_key(e[0], e[1]));
    }
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());

    const std::uint32_t old_count = vertex_count();
    // A refused split rolls the whole call back and runs it again without that edge.
    const auto xyz = xyz_;
    const auto ends = ends_;
    const auto uses = uses_;
    const auto midpoints = midpoints_;
    const auto nodes = nodes_;
    const auto free_nodes = free_nodes_;
    const auto leaves = leaves_;
    const HRefinement3Counters counters = counters_;
    std::vector<std::uint64_t> forbidden;
    while (!refine_once(marks, forbidden)) {
        // Only the refusals of the abandoned attempt count.
        const std::uint64_t refused = counters_.refused_splits;
        counters_ = counters;
        counters_.refused_splits = refused;
        xyz_ = xyz;
        ends_ = ends;
        uses_ = uses;
        midpoints_ = midpoints;
        nodes_ = nodes;
        free_nodes_ = free_nodes;
        leaves_ = leaves;
    }
    previous_count_ = old_count;
    previous_id_.resize(vertex_count());
    for (VertIdx v = 0; v < vertex_count(); ++v) previous_id_[v] = v < old_count ? v : kNone;
}

bool HRefinedMesh3::refine_once(const std::vector<std::uint64_t>& user_marks,
                                std::vector<std::uint64_t>& forbidden) {
    const std::unordered_set<std::uint64_t> banned(forbidden.begin(), forbidden.end());
    std::unordered_set<std::uint64_t> marked;
    for (std::uint64_t e : user_marks) {
        if (!banned.count(e)) marked.insert(e);
    }
    // Gives up this attempt: the edges of `mask` on `node` are refused from now on.
    auto refuse = [&](std::uint32_t node, std::uint8_t mask) {
        for (int k = 0; k < 6; ++k) {
            if (mask >> k & 1) {
                const std::uint64_t e =
                    edge_key(nodes_[node].v[kEdges[k][0]], nodes_[node].v[kEdges[k][1]]);
                if (!banned.count(e)) {
                    forbidden.push_back(e);
                    ++counters_.refused_splits;
                }
            }
        }
        return false;
    };
    auto marked_mask = [&](std::uint32_t node) {
        std::uint8_t mask = 0;
        const auto& v = nodes_[node].v;
        for (int k = 0; k < 6; ++k) {
            const VertIdx a = v[kEdges[k][0]], b = v[kEdges[k][1]];
            if (marked.count(edge_key(a, b)) || is_split(a, b))
                mask |= static_cast<std::uint8_t>(1u << k);
        }
        return mask;
    };
    auto mark_edges = [&](std::uint32_t node, std::uint8_t mask) {
        bool added = false;
        for (int k = 0; k < 6; ++k) {
            if (mask >> k & 1) {
                added |= marked
                             .insert(edge_key(nodes_[node].v[kEdges[k][0]],
                                              nodes_[node].v[kEdges[k][1]]))
                             .second;
            }
        }
        return added;
    };
    auto has_banned = [&](std::uint32_t node, std::uint8_t mask) {
        for (int k = 0; k < 6; ++k) {
            if ((mask >> k & 1) &&
                banned.count(edge_key(nodes_[node].v[kEdges[k][0]], nodes_[node].v[kEdges[k][1]])))
                return true;
        }
        return false;
    };

    for (;;) {
        ++counters_.rounds;
        // The compatibility iteration over the leaves, to a fixed point.
        std::map<std::uint32_t, std::uint8_t> reopen;  // transitional parent -> its new pattern
        bool changed = true;
        while (changed) {
            changed = false;
            ++counters_.compatibility_iterations;
            for (std::uint32_t leaf : leaves_) {
                const std::uint8_t mask = marked_mask(leaf);
                if (mask == 0) continue;
                const std::uint32_t parent = nodes_[leaf].parent;
                if (parent != kNone && nodes_[parent].kind != 8) {
                    // A child of a 1:2 or 1:4 tetrahedron: its parent is refined again instead.
                    const Node& p = nodes_[parent];
                    std::uint8_t pattern = static_cast<std::uint8_t>(p.split_mask | reopen[parent]);
                    for (int k = 0; k < 6; ++k) {
                        if ((mask >> k & 1) == 0) continue;
                        const VertIdx a = nodes_[leaf].v[kEdges[k][0]],
                                      b = nodes_[leaf].v[kEdges[k][1]];
                        const auto ia = std::find(p.v.begin(), p.v.end(), a) - p.v.begin();
                        const auto ib = std::find(p.v.begin(), p.v.end(), b) - p.v.begin();
                        if (ia < 4 && ib < 4) {
                            pattern |=
                                static_cast<std::uint8_t>(1u << edge_index(int(ia), int(ib)));
                        } else {
                            pattern = kAllEdges;  // a half or inner edge: 1:8, then deeper
                        }
                    }
                    pattern = upgraded_pattern(pattern);
                    if (has_banned(parent, pattern)) return refuse(leaf, mask);
                    if (pattern != reopen[parent]) {
                        reopen[parent] = pattern;
                        mark_edges(parent, pattern);
                        changed = true;
                    }
                    continue;
                }
                const std::uint8_t pattern = upgraded_pattern(mask);
                if (has_banned(leaf, pattern)) return refuse(leaf, mask);
                if (pattern != mask) {
                    ++counters_.upgraded;
                    mark_edges(leaf, pattern);
                    changed = true;
                }
            }
        }
        // Apply: reopened parents first, then every other marked leaf.
        std::vector<std::pair<std::uint32_t, std::uint8_t>> work;
        for (std::uint32_t leaf : leaves_) {
            const std::uint32_t parent = nodes_[leaf].parent;
            if (parent != kNone && reopen.count(parent)) continue;
            const std::uint8_t mask = marked_mask(leaf);
            if (mask != 0) work.emplace_back(leaf, mask);
        }
        for (const auto& [parent, pattern] : reopen) {
            const std::uint8_t old_kind = nodes_[parent].kind;
            remove_children(parent);
            if (!make_children(parent, pattern)) return refuse(parent, pattern);
            if (old_kind == 2 && pattern != kAllEdges)
                ++counters_.refine_2_4;
            else if (old_kind == 2)
                ++counters_.refine_2_8;
            else
                ++counters_.refine_4_8;
        }
        for (const auto& [leaf, mask] : work) {
            if (!make_children(leaf, mask)) return refuse(leaf, mask);
            const int count = std::popcount(mask);
            ++(count == 1   ? counters_.refine_1_2
               : count == 3 ? counters_.refine_1_4
                            : counters_.refine_1_8);
        }
        rebuild_leaves();
        // Marks left on leaf edges (halves of old children's edges) or hanging midpoints: another
        // round. Otherwise the mesh is conforming: enforce the jump limit.
        bool pending = false;
        for (std::uint32_t leaf : leaves_) {
            if (marked_mask(leaf) != 0) {
                pending = true;
                break;
            }
        }
        if (pending) continue;
        std::unordered_map<FaceKey, std::pair<std::uint32_t, int>, FaceKeyHash> faces;
        bool jump = false;
        for (std::uint32_t leaf : leaves_) {
            for (int f = 0; f < 4; ++f) {
                const auto [it, inserted] =
                    faces.emplace(tet_face(nodes_[leaf].v, f), std::make_pair(leaf, f));
                if (inserted) continue;
                const auto [other, g] = it->second;
                const std::uint32_t la = nodes_[leaf].level, lb = nodes_[other].level;
                if (la + 1 >= lb && lb + 1 >= la) continue;
                // Mark the coarser leaf along an edge off the shared face: from its opposite
                // corner to the face corner of smallest id that is not refused.
                const auto [coarse, face] =
                    la < lb ? std::make_pair(leaf, f) : std::make_pair(other, g);
                const auto& v = nodes_[coarse].v;
                std::array<VertIdx, 3> ends{};
                for (int j = 0, k = 0; j < 4; ++j) {
                    if (j != face) ends[k++] = v[j];
                }
                std::sort(ends.begin(), ends.end());
                for (VertIdx end : ends) {
                    const std::uint64_t e = edge_key(v[face], end);
                    if (!banned.count(e)) {
                        if (marked.insert(e).second) {
                            ++counters_.jump_marks;
                            jump = true;
                        }
                        break;
                    }
                }
            }
        }
        if (!jump) return true;
    }
}

void HRefinedMesh3::derefine(std::span<const std::uint8_t> flags) {
    if (flags.size() != leaves_.size()) {
        throw InputError("h-refinement: " + std::to_string(flags.size()) +
                         " derefinement flags for " + std::to_string(leaves_.size()) + " leaves");
    }
    std::vector<std::uint8_t> flagged(nodes_.size(), 0);
    std::vector<std::uint32_t> leaf_index(nodes_.size(), kNone);
    for (std::size_t i = 0; i < leaves_.size(); ++i) {
        flagged[leaves_[i]] = flags[i] != 0;
        leaf_index[leaves_[i]] = static_cast<std::uint32_t>(i);
    }
    // Candidates: parents whose children are all flagged leaves.
    std::set<std::uint32_t> candidates;
    for (std::uint32_t leaf : leaves_) {
        const std::uint32_t parent = nodes_[leaf].parent;
        if (parent == kNone || candidates.count(parent)) continue;
        const Node& p = nodes_[parent];
        bool all = true;
        for (int k = 0; k < p.child_count; ++k) {
            all &= nodes_[p.children[k]].child_count == 0 && flagged[p.children[k]];
        }
        if (all) candidates.insert(parent);
    }
    // Leaf face neighbours (the mesh is conforming).
    std::unordered_map<FaceKey, std::pair<std::uint32_t, std::uint32_t>, FaceKeyHash> faces;
    for (std::uint32_t leaf : leaves_) {
        for (int f = 0; f < 4; ++f) {
            auto [it, inserted] =
                faces.emplace(tet_face(nodes_[leaf].v, f), std::make_pair(leaf, kNone));
            if (!inserted) it->second.second = leaf;
        }
    }
    // The compatibility and jump iteration: drop candidates until every one left can go.
    std::uint64_t blocked = 0;
    bool changed = true;
    while (changed) {
        changed = false;
        std::vector<std::int64_t> after(uses_.begin(), uses_.end());
        for (std::uint32_t parent : candidates) {
            const Node& p = nodes_[parent];
            for (int k = 0; k < p.child_count; ++k) {
                for (VertIdx v : nodes_[p.children[k]].v) --after[v];
            }
            for (VertIdx v : p.v) ++after[v];
        }
        std::vector<std::uint32_t> drop;
        for (std::uint32_t parent : candidates) {
            const Node& p = nodes_[parent];
            bool keep = true;
            for (int k = 0; k < 6 && keep; ++k) {
                if ((p.split_mask >> k & 1) == 0) continue;
                const VertIdx m = midpoints_.at(edge_key(p.v[kEdges[k][0]], p.v[kEdges[k][1]]));
                keep = after[m] == 0;
            }
            for (int c = 0; c < p.child_count && keep; ++c) {
                const std::uint32_t child = p.children[c];
                for (int f = 0; f < 4 && keep; ++f) {
                    const auto& sides = faces.at(tet_face(nodes_[child].v, f));
                    const std::uint32_t other = sides.first == child ? sides.second : sides.first;
                    if (other == kNone || nodes_[other].parent == parent) continue;
                    std::uint32_t level = nodes_[other].level;
                    if (candidates.count(nodes_[other].parent)) --level;
                    keep = level <= p.level + 1;
                }
            }
            if (!keep) drop.push_back(parent);
        }
        for (std::uint32_t parent : drop) candidates.erase(parent);
        blocked += drop.size();
        changed = !drop.empty();
    }
    counters_.derefine_blocked += blocked;
    for (std::uint32_t parent : candidates) {
        remove_children(parent);
        ++counters_.derefined;
    }
    // Renumber the vertices that are still used (root vertices always), keeping their order.
    const std::uint32_t old_count = vertex_count();
    std::vector<VertIdx> renumber(old_count, kNone);
    previous_id_.clear();
    VertIdx next = 0;
    for (VertIdx v = 0; v < old_count; ++v) {
        if (v < root_vertices_ || uses_[v] > 0) {
            renumber[v] = next++;
            previous_id_.push_back(v);
        }
    }
    previous_count_ = old_count;
    if (next != old_count) {
        std::vector<double> xyz(3 * std::size_t{next});
        std::vector<std::array<VertIdx, 2>> ends(next);
        std::vector<std::uint32_t> uses(next);
        for (VertIdx v = 0; v < old_count; ++v) {
            if (renumber[v] == kNone) continue;
            const VertIdx w = renumber[v];
            for (int c = 0; c < 3; ++c) xyz[3 * std::size_t{w} + c] = xyz_[3 * std::size_t{v} + c];
            ends[w] = ends_[v][0] == kNone
                          ? ends_[v]
                          : std::array<VertIdx, 2>{renumber[ends_[v][0]], renumber[ends_[v][1]]};
            uses[w] = uses_[v];
        }
        std::unordered_map<std::uint64_t, VertIdx> midpoints;
        for (const auto& [key, m] : midpoints_) {
            if (renumber[m] == kNone) continue;
            EM_ASSERT(renumber[key >> 32] != kNone && renumber[key & 0xFFFFFFFFu] != kNone);
            midpoints.emplace(edge_key(renumber[key >> 32], renumber[key & 0xFFFFFFFFu]),
                              renumber[m]);
        }
        for (Node& node : nodes_) {
            if (!node.alive) continue;
            for (VertIdx& v : node.v) {
                EM_ASSERT(renumber[v] != kNone);
                v = renumber[v];
            }
        }
        xyz_ = std::move(xyz);
        ends_ = std::move(ends);
        uses_ = std::move(uses);
        midpoints_ = std::move(midpoints);
    }
    // Dead node slots past the live ones are dropped, so a fully derefined mesh is the roots.
    while (nodes_.size() > root_tets_ && !nodes_.back().alive) nodes_.pop_back();
    free_nodes_.clear();
    for (std::uint32_t n = root_tets_; n < nodes_.size(); ++n) {
        if (!nodes_[n].alive) free_nodes_.push_back(n);
    }
    rebuild_leaves();
}

Tetrahedralization3 HRefinedMesh3::leaf_mesh() const {
    Tetrahedralization3 mesh;
    mesh.xyz = xyz_;
    mesh.tets.reserve(4 * leaves_.size());
    for (std::uint32_t leaf : leaves_) {
        for (VertIdx v : nodes_[leaf].v) mesh.tets.push_back(v);
    }
    mesh.neighbors.assign(mesh.tets.size(), kNone);
    std::unordered_map<FaceKey, std::uint32_t, FaceKeyHash> faces;
    for (std::uint32_t t = 0; t < leaves_.size(); ++t) {
        for (int f = 0; f < 4; ++f) {
            const FaceKey key = tet_face(nodes_[leaves_[t]].v, f);
            const auto [it, inserted] = faces.emplace(key, 4 * t + f);
            if (inserted) continue;
            const std::uint32_t slot = it->second;
            mesh.neighbors[4 * t + f] = slot / 4;
            mesh.neighbors[slot] = t;
        }
    }
    return mesh;
}

std::vector<std::uint32_t> HRefinedMesh3::leaf_levels() const {
    std::vector<std::uint32_t> levels;
    levels.reserve(leaves_.size());
    for (std::uint32_t leaf : leaves_) levels.push_back(nodes_[leaf].level);
    return levels;
}

std::vector<double> HRefinedMesh3::transfer(std::span<const double> previous_field) const {
    if (previous_field.size() != previous_count_) {
        throw InputError("h-refinement: field has " + std::to_string(previous_field.size()) +
                         " values for " + std::to_string(previous_count_) + " vertices");
    }
    std::vector<double> field(vertex_count());
    for (VertIdx v = 0; v < vertex_count(); ++v) {
        if (previous_id_[v] != kNone) {
            field[v] = previous_field[previous_id_[v]];
        } else {
            // A new midpoint: its ends have smaller ids (they existed when it was made).
            field[v] = 0.5 * field[ends_[v][0]] + 0.5 * field[ends_[v][1]];
        }
    }
    return field;
}

HRefinement3Report HRefinedMesh3::check_nesting() const {
    HRefinement3Report report;
    auto fail = [&](std::string problem) {
        report.ok = false;
        report.problem = std::move(problem);
        return report;
    };
    for (std::uint32_t n = 0; n < nodes_.size(); ++n) {
        const Node& p = nodes_[n];
        if (!p.alive || p.child_count == 0) continue;
        for (int c = 0; c < p.child_count; ++c) {
            const Node& child = nodes_[p.children[c]];
            if (child.level != p.level + 1) return fail("child level is not its parent's plus one");
            if (predicates::orient3d(xyz_.data() + 3 * std::size_t{child.v[0]},
                                     xyz_.data() + 3 * std::size_t{child.v[1]},
                                     xyz_.data() + 3 * std::size_t{child.v[2]},
                                     xyz_.data() + 3 * std::size_t{child.v[3]}) != Sign::Positive)
                return fail("child of node " + std::to_string(n) + " not strictly positive");
            for (VertIdx x : child.v) {
                // Its place among the parent's nodes: corner i, or midpoint of edge (i, j).
                int i = -1, j = -1;
                for (int k = 0; k < 4; ++k) {
                    if (p.v[k] == x) i = k;
                }
                if (i < 0) {
                    const auto ends = ends_[x];
                    if (ends[0] == kNone)
                        return fail("child corner is neither a parent corner nor a midpoint");
                    for (int k = 0; k < 4; ++k) {
                        if (p.v[k] == ends[0]) i = k;
                        if (p.v[k] == ends[1]) j = k;
                    }
                    if (i < 0 || j < 0)
                        return fail("child corner is the midpoint of no parent edge");
                    for (int a = 0; a < 3; ++a) {
                        const double expected = midpoint(xyz_[3 * std::size_t{ends[0]} + a],
                                                         xyz_[3 * std::size_t{ends[1]} + a]);
                        if (std::bit_cast<std::uint64_t>(expected) !=
                            std::bit_cast<std::uint64_t>(xyz_[3 * std::size_t{x} + a]))
                            return fail("vertex " + std::to_string(x) +
                                        " is not the rounded midpoint of its edge");
                    }
                }
                // Faces opposite i (and j): x is off them combinatorially; it must be inside.
                for (int opposite : {i, j}) {
                    if (opposite < 0) continue;
                    std::array<const double*, 4> probe{};
                    for (int k = 0; k < 4; ++k) probe[k] = xyz_.data() + 3 * std::size_t{p.v[k]};
                    probe[opposite] = xyz_.data() + 3 * std::size_t{x};
                    if (predicates::orient3d(probe[0], probe[1], probe[2], probe[3]) ==
                        Sign::Negative)
                        return fail("child corner " + std::to_string(x) + " outside its parent");
                }
            }
        }
    }
    return report;
}

HRefinement3Report HRefinedMesh3::check_jump_limit() const {
    HRefinement3Report report;
    std::unordered_map<FaceKey, std::uint32_t, FaceKeyHash> faces;
    for (std::uint32_t leaf : leaves_) {
        for (int f = 0; f < 4; ++f) {
            const auto [it, inserted] = faces.emplace(tet_face(nodes_[leaf].v, f), leaf);
            if (inserted) continue;
            const std::uint32_t a = nodes_[leaf].level, b = nodes_[it->second].level;
            if (a > b + 1 || b > a + 1) {
                report.ok = false;
                report.problem =
                    "face neighbours at levels " + std::to_string(a) + " and " + std::to_string(b);
                return report;
            }
        }
    }
    return report;
}

HRefinement3Report HRefinedMesh3::check_all() const {
    HRefinement3Report report;
    const triangulation::TopologyReport3 topology = triangulation::check_topology_3d(leaf_mesh());
    if (!topology.ok) {
        report.ok = false;
        report.problem = "leaf mesh: " + topology.problem;
        return report;
    }
    for (std::uint32_t leaf : leaves_) {
        for (const auto& e : kEdges) {
            if (is_split(nodes_[leaf].v[e[0]], nodes_[leaf].v[e[1]])) {
                report.ok = false;
                report.problem = "leaf edge (" + std::to_string(nodes_[leaf].v[e[0]]) + ", " +
                                 std::to_string(nodes_[leaf].v[e[1]]) + ") has a hanging midpoint";
                return report;
            }
        }
    }
    report = check_nesting();
    if (!report.ok) return report;
    return check_jump_limit();
}

}  // namespace exactmesh::generators
