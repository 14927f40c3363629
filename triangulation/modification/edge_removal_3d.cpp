// SPDX-License-Identifier: MIT
// Edge removal by dynamic programming over the ring's triangles (see edge_removal_3d.hpp).
//
// The ring. Orient the link of ab as r_0 .. r_{n-1} so that every ring tetrahedron is
// (a, b, r_i, r_{i+1}) positive (indices mod n). A triangulation of the polygon r_0 .. r_{n-1}
// gives, for each triangle r_i r_j r_k (i < j < k), the tetrahedra (r_i, r_j, r_k, b) and
// (r_i, r_k, r_j, a): the 3-2 flip of flip_3d.hpp is the case n = 3. The new tetrahedra have
// the ring's boundary faces (a, r_i, r_{i+1}) and (b, r_i, r_{i+1}) with their orientations,
// and replace_tets checks that combinatorially; with every new tetrahedron exactly positive,
// they cover the ring's region once (the argument of flip_3d.cpp).
// The choice. A triangle is usable when both of its tetrahedra are positive and strictly better
// than the worst ring tetrahedron (early-exit exact comparisons: most triangles fail at once);
// Klincsek's recurrence then finds, over usable triangles only, the triangulation whose worst
// tetrahedron is best: Q(i, k) = best over i < j < k of worst(Q(i, j), Q(j, k), q(i, j, k)),
// Q(i, i + 1) = no tetrahedron. O(n^3) triangles and steps for n <= 7.
#include "triangulation/modification/edge_removal_3d.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Dihedral;
using predicates::Sign;
using predicates::TetCorners;

constexpr unsigned kMaxRing = kMaxEdgeRemovalRing;

TetCorners corners(const TetMesh3& mesh, const Tet& t) {
    return {mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])};
}

bool positive(const TetMesh3& mesh, const Tet& t) {
    return predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                mesh.point(t[3])) == Sign::Positive;
}

/// A tetrahedron's quality under the criterion (the smallest or largest dihedral angle, or its
/// corners for volume-edge), or none (better than every tetrahedron).
struct Quality {
    bool none = true;
    Dihedral angle{};
    TetCorners tet{};
};

class Criterion {
  public:
    explicit Criterion(SwapCriterion3 criterion) : criterion_(criterion) {
        if (criterion == SwapCriterion3::Delaunay)
            throw InternalError("edge_removal_3d: the Delaunay criterion has no quality");
    }

    Quality of(const TetCorners& p) const {
        Quality q;
        q.none = false;
        q.tet = p;
        if (criterion_ == SwapCriterion3::MaxMinDihedral)
            q.angle = predicates::smallest_dihedral(p);
        if (criterion_ == SwapCriterion3::MinMaxDihedral) q.angle = predicates::largest_dihedral(p);
        return q;
    }

    /// x strictly better than y.
    bool better(const Quality& x, const Quality& y) const {
        if (y.none) return false;
        if (x.none) return true;
        switch (criterion_) {
            case SwapCriterion3::MaxMinDihedral:
                return predicates::compare_dihedral(x.angle, y.angle) == Sign::Positive;
            case SwapCriterion3::MinMaxDihedral:
                return predicates::compare_dihedral(x.angle, y.angle) == Sign::Negative;
            case SwapCriterion3::VolumeEdge:
                return predicates::compare_volume_edge(x.tet, y.tet) == Sign::Positive;
            case SwapCriterion3::Delaunay:
                break;
        }
        return false;
    }

    const Quality& worse(const Quality& x, const Quality& y) const { return better(x, y) ? y : x; }

    /// Whether tetrahedron p is strictly better than `bound` (not none), stopping early.
    bool beats(const TetCorners& p, const Quality& bound) const {
        switch (criterion_) {
            case SwapCriterion3::MaxMinDihedral:
                return predicates::every_dihedral_compares(p, bound.angle, Sign::Positive);
            case SwapCriterion3::MinMaxDihedral:
                return predicates::every_dihedral_compares(p, bound.angle, Sign::Negative);
            case SwapCriterion3::VolumeEdge:
                return predicates::compare_volume_edge(p, bound.tet) == Sign::Positive;
            case SwapCriterion3::Delaunay:
                break;
        }
        return false;
    }

  private:
    SwapCriterion3 criterion_;
};

/// Whether the stored order of t, rearranged as (a, b, u, w), is an even permutation.
bool even_order(const Tet& t, VertIdx a, VertIdx b, VertIdx u, VertIdx w) {
    const VertIdx order[4] = {a, b, u, w};
    unsigned position[4];
    for (unsigned i = 0; i < 4; ++i)
        position[i] = static_cast<unsigned>(std::find(t.begin(), t.end(), order[i]) - t.begin());
    unsigned inversions = 0;
    for (unsigned i = 0; i < 4; ++i)
        for (unsigned j = i + 1; j < 4; ++j) inversions += position[i] > position[j] ? 1 : 0;
    return inversions % 2 == 0;
}

}  // namespace

bool plan_edge_removal_3d(const TetMesh3& mesh, TetIdx t, VertIdx a, VertIdx b,
                          SwapCriterion3 criterion, FlipPlan3& plan) {
    const Criterion rule(criterion);
    const EdgeRing ring = edge_ring(mesh, t, a, b);
    const auto n = static_cast<unsigned>(ring.tets.size());
    if (!ring.closed || n < 3 || n > kMaxRing) return false;
    // The link, oriented: each ring tetrahedron's two other corners; r_0, r_1 from t's order.
    std::array<std::array<VertIdx, 2>, kMaxRing> pairs{};
    for (unsigned i = 0; i < n; ++i) {
        const Tet tet = mesh.tet(ring.tets[i]);
        unsigned m = 0;
        for (const VertIdx v : tet)
            if (v != a && v != b) pairs[i][m++] = v;
        EM_ASSERT(m == 2);
    }
    std::array<VertIdx, kMaxRing> r{};
    const Tet first = mesh.tet(ring.tets[0]);
    const bool forward = even_order(first, a, b, pairs[0][0], pairs[0][1]);
    r[0] = forward ? pairs[0][0] : pairs[0][1];
    r[1] = forward ? pairs[0][1] : pairs[0][0];
    std::array<bool, kMaxRing> used{};
    used[0] = true;
    for (unsigned i = 1; i + 1 < n; ++i) {
        bool found = false;
        for (unsigned s = 1; s < n && !found; ++s) {
            if (used[s]) continue;
            if (pairs[s][0] == r[i] || pairs[s][1] == r[i]) {
                r[i + 1] = pairs[s][0] == r[i] ? pairs[s][1] : pairs[s][0];
                used[s] = true;
                found = true;
            }
        }
        if (!found) return false;  // not a simple ring (cannot happen in a valid mesh)
    }
    // The worst ring tetrahedron.
    Quality old;
    for (unsigned i = 0; i < n; ++i)
        old = rule.worse(old, rule.of(corners(mesh, mesh.tet(ring.tets[i]))));

    // Usable triangles (i < j < k) and their two tetrahedra.
    auto index = [](unsigned i, unsigned j, unsigned k) {
        return (i * kMaxRing + j) * kMaxRing + k;
    };
    std::array<std::int8_t, kMaxRing * kMaxRing * kMaxRing> usable{};  // 0 unknown, 1 yes, -1 no
    auto b_tet = [&](unsigned i, unsigned j, unsigned k) { return Tet{r[i], r[j], r[k], b}; };
    auto a_tet = [&](unsigned i, unsigned j, unsigned k) { return Tet{r[i], r[k], r[j], a}; };
    auto is_usable = [&](unsigned i, unsigned j, unsigned k) {
        std::int8_t& u = usable[index(i, j, k)];
        if (u == 0) {
            const Tet lower = b_tet(i, j, k), upper = a_tet(i, j, k);
            const bool ok = positive(mesh, lower) && positive(mesh, upper) &&
                            rule.beats(corners(mesh, lower), old) &&
                            rule.beats(corners(mesh, upper), old);
            u = ok ? 1 : -1;
        }
        return u > 0;
    };
    // Feasibility first (cheap): which spans (i, k) have a triangulation of usable triangles.
    std::array<std::array<std::int8_t, kMaxRing>, kMaxRing> choice{};  // j + 1; 0: none
    std::array<std::array<bool, kMaxRing>, kMaxRing> feasible{};
    for (unsigned i = 0; i + 1 < n; ++i) feasible[i][i + 1] = true;
    for (unsigned length = 2; length < n; ++length) {
        for (unsigned i = 0; i + length < n; ++i) {
            const unsigned k = i + length;
            for (unsigned j = i + 1; j < k && !feasible[i][k]; ++j)
                feasible[i][k] = feasible[i][j] && feasible[j][k] && is_usable(i, j, k);
        }
    }
    if (!feasible[0][n - 1]) return false;
    // The best among them, with the exact qualities of the usable triangles only.
    std::array<std::array<Quality, kMaxRing>, kMaxRing> best{};
    for (unsigned length = 2; length < n; ++length) {
        for (unsigned i = 0; i + length < n; ++i) {
            const unsigned k = i + length;
            if (!feasible[i][k]) continue;
            bool have = false;
            for (unsigned j = i + 1; j < k; ++j) {
                if (!(feasible[i][j] && feasible[j][k] && is_usable(i, j, k))) continue;
                Quality q = rule.worse(best[i][j], best[j][k]);
                q = rule.worse(q, rule.of(corners(mesh, b_tet(i, j, k))));
                q = rule.worse(q, rule.of(corners(mesh, a_tet(i, j, k))));
                if (!have || rule.better(q, best[i][k])) {
                    best[i][k] = q;
                    choice[i][k] = static_cast<std::int8_t>(j + 1);
                    have = true;
                }
            }
        }
    }
    plan = FlipPlan3{};
    plan.kind = FlipKind3::EdgeRemoval;
    for (unsigned i = 0; i < n; ++i) plan.old[i] = ring.tets[i];
    plan.old_count = n;
    // The chosen triangles, by an explicit stack of spans.
    std::array<std::array<unsigned, 2>, kMaxRing> stack{};
    unsigned depth = 0;
    stack[depth++] = {0, n - 1};
    while (depth > 0) {
        const auto [i, k] = stack[--depth];
        if (k < i + 2) continue;
        const unsigned j = static_cast<unsigned>(choice[i][k] - 1);
        plan.made[plan.made_count++] = b_tet(i, j, k);
        plan.made[plan.made_count++] = a_tet(i, j, k);
        stack[depth++] = {i, j};
        stack[depth++] = {j, k};
    }
    EM_ASSERT(plan.made_count == 2 * (n - 2));
    return true;
}

EdgeRemovalCounters remove_edges_3d(TetMesh3& mesh, SwapCriterion3 criterion,
                                    std::span<const TetIdx> tets,
                                    const SwapConstraints3& constraints) {
    EdgeRemovalCounters counters;
    FlipPlan3 plan;
    std::vector<TetIdx> created;
    for (const TetIdx t : tets) {
        if (t >= mesh.tet_slots() || mesh.is_dead(t)) continue;
        // Slots are reused by the new tetrahedra of a removal: stop at the first change.
        const Tet original = mesh.tet(t);
        for (unsigned e = 0; e < 6 && !mesh.is_dead(t) && mesh.tet(t) == original; ++e) {
            static constexpr unsigned kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3},
                                                      {1, 2}, {1, 3}, {2, 3}};
            const VertIdx a = mesh.vertex(t, kPairs[e][0]), b = mesh.vertex(t, kPairs[e][1]);
            if (constraints.locks != nullptr && constraints.locks->edge_locked(a, b)) continue;
            ++counters.edges_examined;
            if (!plan_edge_removal_3d(mesh, t, a, b, criterion, plan)) continue;
            const ConstrainedFlip3 outcome =
                apply_constrained_flip_3d(mesh, plan, constraints, created);
            if (outcome == ConstrainedFlip3::Locked) ++counters.locked;
            if (outcome == ConstrainedFlip3::Vetoed) ++counters.vetoed;
            if (outcome == ConstrainedFlip3::Made) ++counters.removals;
        }
    }
    return counters;
}

}  // namespace exactmesh::triangulation
