// SPDX-License-Identifier: MIT
// Edge-face swapping under a criterion (see edge_face_swap_3d.hpp).
//
// The flips (2-3, 3-2, 4-4, 2-2: their pictures are in flip_3d.hpp) are planned and made by
// flip_3d (plan_flip_3d, apply_flip_3d): each new tetrahedron exactly positive, the new set
// checked to have the old one's boundary.
//
// Termination. Faces are queued only after a swap, so the loop ends when the swaps do; the
// tetrahedralizations of a finite point set with a fixed boundary are finitely many, so it is
// enough that every swap strictly improves a quantity of the whole tetrahedralization:
//  - Delaunay: with lifts |p|^2 - eps^(n - index) [EdelsbrunnerMücke90], insphere_sos(abcd, e)
//    > 0 says e's lift lies below the hyperplane of abcd's lifts; the five (or, coplanar, six)
//    points' two triangulations then differ by replacing the upper lifted tetrahedra by the
//    lower ones over the same region, so the piecewise-linear lifted surface goes down
//    pointwise (as polynomials in eps) there and stays elsewhere. A surface never returns
//    above itself. In the coplanar case d, e, x, y, insphere_sos(abcd, e) equals the in-plane
//    perturbed incircle of x, y, d, e (the plane's lift is vertical through it), the same
//    decision seen from either side, so a 4-4 swap lowers both halves.
//  - MaxMinDihedral (VolumeEdge the same with that quality): the vector of all tetrahedra's
//    smallest dihedral angles sorted increasingly grows strictly in lexicographic order. Let m
//    be the old minimum among the changed tetrahedra; every new one exceeds m; below m both
//    vectors agree, and the old one has more entries equal to m, where the new one has a larger
//    entry (it has at least one more entry past them: a swap creates two or more tetrahedra).
//  - MinMaxDihedral: symmetrically, the decreasingly sorted vector of largest angles decreases.
// Comparisons are exact (angle_comparisons_3d), so "strictly" holds for the real angles.
#include "triangulation/modification/edge_face_swap_3d.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <initializer_list>
#include <span>
#include <string>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/sos.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::compare_dihedral;
using predicates::compare_volume_edge;
using predicates::Dihedral;
using predicates::largest_dihedral;
using predicates::Sign;
using predicates::smallest_dihedral;
using predicates::TetCorners;

using FlipPlan = FlipPlan3;

bool delaunay_wants(const TetMesh3& mesh, FaceIdx f) {
    const TetIdx t1 = f / 4;
    const VertIdx e = mesh.vertex(mesh.adj[f] / 4, mesh.adj[f] % 4);
    const Tet t = mesh.tet(t1);
    return predicates::insphere_sos(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                    mesh.point(t[3]), mesh.point(e), t[0], t[1], t[2], t[3],
                                    e) == Sign::Positive;
}

TetCorners corners(const TetMesh3& mesh, const Tet& t) {
    return {mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])};
}

/// Whether the quality criterion strictly prefers the plan's new tetrahedra.
bool quality_prefers(const TetMesh3& mesh, SwapCriterion3 criterion, const FlipPlan& plan) {
    std::array<Tet, kMaxEdgeRemovalRing> old{};
    for (unsigned i = 0; i < plan.old_count; ++i) old[i] = mesh.tet(plan.old[i]);
    switch (criterion) {
        case SwapCriterion3::MaxMinDihedral:
        case SwapCriterion3::MinMaxDihedral: {
            const bool min = criterion == SwapCriterion3::MaxMinDihedral;
            auto extreme = [&](const std::span<const Tet> set, unsigned count) {
                Dihedral best = min ? smallest_dihedral(corners(mesh, set[0]))
                                    : largest_dihedral(corners(mesh, set[0]));
                for (unsigned i = 1; i < count; ++i) {
                    const Dihedral c = min ? smallest_dihedral(corners(mesh, set[i]))
                                           : largest_dihedral(corners(mesh, set[i]));
                    if (compare_dihedral(c, best) == (min ? Sign::Negative : Sign::Positive))
                        best = c;
                }
                return best;
            };
            // The new extreme beats the old one exactly when every angle of every new
            // tetrahedron does: checked angle by angle, stopping at the first that does not
            // (the new extreme itself cost a fifth of sliver removal).
            if (min) {
                // First against the old angle the rounded cosines find smallest: if every new
                // angle exceeds it, every one exceeds the old smallest angle (at most it), the
                // same answer without the old extreme's exact comparisons (99% of sliver
                // removal's plans on the wing pass so; their smallest_dihedral calls were a
                // fifth of its face swaps' time). Otherwise the exact extreme decides.
                double guess_cosine = 0;
                Dihedral guess =
                    predicates::smallest_dihedral_rounded(corners(mesh, old[0]), &guess_cosine);
                for (unsigned i = 1; i < plan.old_count; ++i) {
                    double cosine = 0;
                    const Dihedral c =
                        predicates::smallest_dihedral_rounded(corners(mesh, old[i]), &cosine);
                    if (cosine > guess_cosine) {
                        guess = c;
                        guess_cosine = cosine;
                    }
                }
                bool beaten = true;
                for (unsigned i = 0; i < plan.made_count && beaten; ++i)
                    beaten = predicates::every_dihedral_compares(corners(mesh, plan.made[i]), guess,
                                                                 Sign::Positive);
                if (beaten) return true;
            }
            const Dihedral before = extreme(old, plan.old_count);
            const Sign wanted = min ? Sign::Positive : Sign::Negative;
            for (unsigned i = 0; i < plan.made_count; ++i) {
                if (!predicates::every_dihedral_compares(corners(mesh, plan.made[i]), before,
                                                         wanted))
                    return false;
            }
            return true;
        }
        case SwapCriterion3::VolumeEdge: {
            auto worst = [&](const std::span<const Tet> set, unsigned count) {
                TetCorners best = corners(mesh, set[0]);
                for (unsigned i = 1; i < count; ++i) {
                    const TetCorners c = corners(mesh, set[i]);
                    if (compare_volume_edge(c, best) == Sign::Negative) best = c;
                }
                return best;
            };
            return compare_volume_edge(worst(plan.made, plan.made_count),
                                       worst(old, plan.old_count)) == Sign::Positive;
        }
        case SwapCriterion3::Delaunay:
            break;
    }
    throw InternalError("edge_face_swap_3d: quality_prefers called for the Delaunay criterion");
}

constexpr std::array<EnumName<SwapCriterion3>, 4> kSwapCriterion3Names{{
    {"delaunay", SwapCriterion3::Delaunay},
    {"max-min-dihedral", SwapCriterion3::MaxMinDihedral},
    {"min-max-dihedral", SwapCriterion3::MinMaxDihedral},
    {"volume-edge", SwapCriterion3::VolumeEdge},
}};

}  // namespace

SwapCriterion3 swap_criterion_3d_from_name(std::string_view name) {
    return parse_name(kSwapCriterion3Names, name, "3D swap criterion");
}

std::string_view swap_criterion_3d_name(SwapCriterion3 criterion) {
    return name_of(kSwapCriterion3Names, criterion, "unknown");
}

bool locally_delaunay_sos(const TetMesh3& mesh, FaceIdx f) {
    EM_ASSERT(mesh.adj[f] != kNone);
    return !delaunay_wants(mesh, f);
}

void SwapLocks3::add_face(VertIdx a, VertIdx b, VertIdx c) {
    std::array<VertIdx, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    faces_.push_back(key);
}

void SwapLocks3::add_edge(VertIdx a, VertIdx b) {
    edges_.push_back({std::min(a, b), std::max(a, b)});
}

void SwapLocks3::finish() {
    std::sort(faces_.begin(), faces_.end());
    faces_.erase(std::unique(faces_.begin(), faces_.end()), faces_.end());
    std::sort(edges_.begin(), edges_.end());
    edges_.erase(std::unique(edges_.begin(), edges_.end()), edges_.end());
    marked_.clear();
    const auto mark = [this](VertIdx v) {
        if (v >= marked_.size()) marked_.resize(std::size_t{v} + 1, 0);
        marked_[v] = 1;
    };
    for (const auto& face : faces_)
        for (const VertIdx v : face) mark(v);
    for (const auto& edge : edges_)
        for (const VertIdx v : edge) mark(v);
}

bool SwapLocks3::face_locked(VertIdx a, VertIdx b, VertIdx c) const {
    if (!marked(a) || !marked(b) || !marked(c)) return false;
    std::array<VertIdx, 3> key{a, b, c};
    std::sort(key.begin(), key.end());
    return std::binary_search(faces_.begin(), faces_.end(), key);
}

bool SwapLocks3::edge_locked(VertIdx a, VertIdx b) const {
    if (!marked(a) || !marked(b)) return false;
    return std::binary_search(edges_.begin(), edges_.end(),
                              std::array<VertIdx, 2>{std::min(a, b), std::max(a, b)});
}

bool flip_removes_locked(const TetMesh3& mesh, const FlipPlan3& plan, const SwapLocks3& locks) {
    auto has_all = [](const Tet& t, std::initializer_list<VertIdx> vs) {
        for (const VertIdx v : vs) {
            if (std::find(t.begin(), t.end(), v) == t.end()) return false;
        }
        return true;
    };
    auto in_made = [&](std::initializer_list<VertIdx> vs) {
        for (unsigned i = 0; i < plan.made_count; ++i) {
            if (has_all(plan.made[i], vs)) return true;
        }
        return false;
    };
    for (unsigned i = 0; i < plan.old_count; ++i) {
        const Tet t = mesh.tet(plan.old[i]);
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned* lf = kFaceVertex[k];
            const VertIdx a = t[lf[0]], b = t[lf[1]], c = t[lf[2]];
            if (locks.face_locked(a, b, c) && !in_made({a, b, c})) return true;
        }
        for (unsigned j = 0; j < 4; ++j) {
            for (unsigned k = j + 1; k < 4; ++k) {
                if (locks.edge_locked(t[j], t[k]) && !in_made({t[j], t[k]})) return true;
            }
        }
    }
    return false;
}

ConstrainedFlip3 apply_constrained_flip_3d(TetMesh3& mesh, const FlipPlan3& plan,
                                           const SwapConstraints3& constraints,
                                           std::vector<TetIdx>& created) {
    if (constraints.locks != nullptr && flip_removes_locked(mesh, plan, *constraints.locks))
        return ConstrainedFlip3::Locked;
    if (constraints.accept && !constraints.accept(plan)) return ConstrainedFlip3::Vetoed;
    apply_flip_3d(mesh, plan, created);
    if (constraints.on_flip) constraints.on_flip(plan, created);
    return ConstrainedFlip3::Made;
}

EdgeFaceSwapCounters swap_faces_3d(TetMesh3& mesh, SwapCriterion3 criterion) {
    return swap_faces_3d(mesh, criterion, SwapConstraints3{});
}

EdgeFaceSwapCounters swap_faces_3d(TetMesh3& mesh, SwapCriterion3 criterion,
                                   const SwapConstraints3& constraints) {
    EdgeFaceSwapCounters counters;
    std::vector<std::uint8_t> queued(mesh.adj.size(), 0);
    std::deque<FaceIdx> queue;
    auto push = [&](FaceIdx f) {
        if (f >= queued.size()) queued.resize(mesh.adj.size(), 0);
        if (queued[f] != 0 || mesh.adj[f] == kNone) return;
        queued[f] = 1;
        queue.push_back(f);
    };
    if (constraints.seeds.empty()) {
        for (FaceIdx f = 0; f < mesh.adj.size(); ++f) {
            if (!mesh.is_dead(f / 4) && mesh.adj[f] != kNone && mesh.adj[f] > f) push(f);
        }
    } else {
        for (const FaceIdx f : constraints.seeds) {
            if (f < mesh.adj.size() && !mesh.is_dead(f / 4)) push(f);
        }
    }
    std::vector<TetIdx> created;
    FlipPlan plan;
    while (!queue.empty()) {
        const FaceIdx f = queue.front();
        queue.pop_front();
        queued[f] = 0;
        if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) continue;
        if (constraints.wanted && !constraints.wanted(f / 4) &&
            !constraints.wanted(mesh.adj[f] / 4))
            continue;
        ++counters.faces_examined;
        if (criterion == SwapCriterion3::Delaunay) {
            if (!delaunay_wants(mesh, f)) continue;
            if (!plan_flip_3d(mesh, f, plan, &counters.edges_examined)) {
                ++counters.not_flippable;
                continue;
            }
        } else {
            if (!plan_flip_3d(mesh, f, plan, &counters.edges_examined)) {
                ++counters.not_flippable;
                continue;
            }
            if (!quality_prefers(mesh, criterion, plan)) continue;
        }
        const ConstrainedFlip3 outcome =
            apply_constrained_flip_3d(mesh, plan, constraints, created);
        if (outcome == ConstrainedFlip3::Locked) ++counters.locked;
        if (outcome == ConstrainedFlip3::Vetoed) ++counters.vetoed;
        if (outcome != ConstrainedFlip3::Made) continue;
        count_flip(counters, plan.kind);
        // Every face of the new tetrahedra, the ones between them too: a face between two new
        // tetrahedra is where a later 4-4 swap through them is seen from (its other faces see
        // other point sets), and the swap that would undo this one is simply never preferred.
        for (const TetIdx t : created) {
            for (unsigned k = 0; k < 4; ++k) push(4 * t + k);
        }
    }
    if (criterion == SwapCriterion3::Delaunay) {
        for (FaceIdx f = 0; f < mesh.adj.size(); ++f) {
            if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone || mesh.adj[f] < f) continue;
            if (delaunay_wants(mesh, f)) ++counters.stalled_faces;
        }
    }
    return counters;
}

EdgeFaceSwapCounters swap_faces_3d(Tetrahedralization3& mesh, SwapCriterion3 criterion) {
    TetMesh3 work = make_tet_mesh_3d(mesh);
    const EdgeFaceSwapCounters counters = swap_faces_3d(work, criterion);
    mesh = to_tetrahedralization_3d(work);
    return counters;
}

}  // namespace exactmesh::triangulation
