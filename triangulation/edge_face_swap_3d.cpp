// SPDX-License-Identifier: MIT
// Edge-face swapping under a criterion (see edge_face_swap_3d.hpp).
//
// The face abc (outward from t1 = abcd, so orient3d(a, b, c, d) > 0) and its neighbor t2 = bace:
//
//   2-3: de crosses abc        ->  (a, b, e, d), (b, c, e, d), (c, a, e, d)   [edge de]
//   3-2: ring of xy = {xyzd, xyze, xyde}, z the third vertex of the face, (x, y, z, d) positive
//                              ->  (z, d, e, y), (z, e, d, x)                 [face zde]
//   4-4: d, e, x, y coplanar, ring of xy = {xyzd, xyze, xywe, xywd}
//                              ->  (y, z, e, d), (z, x, e, d) and the same two from the far
//                                  side's face (x, y, w) seen from xywd        [edge de]
//   2-2: as 4-4 with xy on the boundary and only xyzd, xyze around it.
//
// Each new tetrahedron is accepted only when exact orient3d says it is positively oriented;
// replace_tets then checks combinatorially that the new set has the old one's boundary. Both
// together make each swap a retetrahedralization of the same region (positive tetrahedra
// with matching faces and boundary cover the region once).
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
#include "triangulation/edge_face_swap_3d.hpp"

#include <array>
#include <deque>
#include <string>

#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/errors.hpp"
#include "predicates/orient3d.hpp"
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

Sign orient(const FlipMesh3& mesh, const Tet& t) {
    return predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]));
}

bool all_positive(const FlipMesh3& mesh, const FlipPlan& plan) {
    for (unsigned i = 0; i < plan.made_count; ++i) {
        if (orient(mesh, plan.made[i]) != Sign::Positive) return false;
    }
    return true;
}

/// The vertices around the face of facet f (face outward from t1, apexes d in t1 and e in t2).
struct FaceConfig {
    TetIdx t1, t2;
    VertIdx a, b, c, d, e;
};

FaceConfig face_config(const FlipMesh3& mesh, FacetIdx f) {
    FaceConfig q{};
    q.t1 = f / 4;
    const FacetIdx g = mesh.adj[f];
    q.t2 = g / 4;
    const auto face = mesh.face(f);
    q.a = face[0];
    q.b = face[1];
    q.c = face[2];
    q.d = mesh.vertex(q.t1, f % 4);
    q.e = mesh.vertex(q.t2, g % 4);
    return q;
}

/// The 3-2 swap of edge (x, y) of the face, z its third vertex, when the ring is the three
/// tetrahedra xyzd, xyze, xyde and both new tetrahedra are positive.
bool plan_32(const FlipMesh3& mesh, const FaceConfig& q, VertIdx x, VertIdx y, VertIdx z, FlipPlan& plan) {
    const EdgeRing ring = edge_ring(mesh, q.t1, x, y);
    if (!ring.closed || ring.tets.size() != 3) return false;
    TetIdx third = kNone;
    for (const TetIdx t : ring.tets) {
        if (t != q.t1 && t != q.t2) third = t;
    }
    if (third == kNone || mesh.local_index(third, q.d) == 4 || mesh.local_index(third, q.e) == 4) return false;
    plan.kind = FlipKind3::Flip32;
    plan.old = {q.t1, q.t2, third, kNone};
    plan.old_count = 3;
    plan.made[0] = {z, q.d, q.e, y};
    plan.made[1] = {z, q.e, q.d, x};
    plan.made_count = 2;
    return all_positive(mesh, plan);
}

/// The 4-4 or 2-2 swap turning edge (x, y) of the face into de (d, e, x, y coplanar).
bool plan_44(const FlipMesh3& mesh, const FaceConfig& q, VertIdx x, VertIdx y, VertIdx z, FlipPlan& plan) {
    const EdgeRing ring = edge_ring(mesh, q.t1, x, y);
    plan.made[0] = {y, z, q.e, q.d};
    plan.made[1] = {z, x, q.e, q.d};
    if (!ring.closed) {
        if (ring.tets.size() != 2) return false;
        plan.kind = FlipKind3::Flip22;
        plan.old = {q.t1, q.t2, kNone, kNone};
        plan.old_count = 2;
        plan.made_count = 2;
        return all_positive(mesh, plan);
    }
    if (ring.tets.size() != 4) return false;
    // The far side: the tetrahedron of the ring holding d other than t1, and its face opposite d.
    TetIdx near_d = kNone, near_e = kNone;
    for (const TetIdx t : ring.tets) {
        if (t == q.t1 || t == q.t2) continue;
        if (mesh.local_index(t, q.d) < 4) near_d = t;
        if (mesh.local_index(t, q.e) < 4) near_e = t;
    }
    if (near_d == kNone || near_e == kNone || near_d == near_e) return false;
    const unsigned ld = mesh.local_index(near_d, q.d);
    const auto far = mesh.face(4 * near_d + ld);  // (x, y, w) in some rotation, outward from near_d
    unsigned made = 2;
    for (unsigned s = 0; s < 3; ++s) {
        const VertIdx p = far[s], r = far[(s + 1) % 3];
        if ((p == x && r == y) || (p == y && r == x)) continue;  // the flat one
        plan.made[made++] = {p, r, q.e, q.d};
    }
    if (made != 4) return false;
    plan.kind = FlipKind3::Flip44;
    plan.old = {q.t1, q.t2, near_d, near_e};
    plan.old_count = 4;
    plan.made_count = 4;
    return all_positive(mesh, plan);
}

/// The valid swap at the interior face of facet f, if any (at most one exists for the five
/// points; the order of the tries does not matter).
bool plan_flip(const FlipMesh3& mesh, FacetIdx f, FlipPlan& plan, std::uint64_t* edges_examined) {
    const FaceConfig q = face_config(mesh, f);
    const Tet t23[3] = {{q.a, q.b, q.e, q.d}, {q.b, q.c, q.e, q.d}, {q.c, q.a, q.e, q.d}};
    Sign s[3];
    for (int i = 0; i < 3; ++i) s[i] = orient(mesh, t23[i]);
    if (s[0] == Sign::Positive && s[1] == Sign::Positive && s[2] == Sign::Positive) {
        plan.kind = FlipKind3::Flip23;
        plan.old = {q.t1, q.t2, kNone, kNone};
        plan.old_count = 2;
        plan.made = {t23[0], t23[1], t23[2], Tet{}};
        plan.made_count = 3;
        return true;
    }
    const VertIdx face[3] = {q.a, q.b, q.c};
    int zeros = 0;
    for (int i = 0; i < 3; ++i) zeros += s[i] == Sign::Zero ? 1 : 0;
    for (int i = 0; i < 3; ++i) {
        const VertIdx x = face[i], y = face[(i + 1) % 3], z = face[(i + 2) % 3];
        if (s[i] == Sign::Negative) {
            if (edges_examined != nullptr) ++*edges_examined;
            if (plan_32(mesh, q, x, y, z, plan)) return true;
        } else if (s[i] == Sign::Zero && zeros == 1) {
            if (edges_examined != nullptr) ++*edges_examined;
            if (plan_44(mesh, q, x, y, z, plan)) return true;
        }
    }
    plan.kind = FlipKind3::None;
    return false;
}

bool delaunay_wants(const FlipMesh3& mesh, FacetIdx f) {
    const TetIdx t1 = f / 4;
    const VertIdx e = mesh.vertex(mesh.adj[f] / 4, mesh.adj[f] % 4);
    const Tet t = mesh.tet(t1);
    return predicates::insphere_sos(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]),
                                    mesh.point(e), t[0], t[1], t[2], t[3], e) == Sign::Positive;
}

TetCorners corners(const FlipMesh3& mesh, const Tet& t) {
    return {mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])};
}

/// Whether the quality criterion strictly prefers the plan's new tetrahedra.
bool quality_prefers(const FlipMesh3& mesh, SwapCriterion3 criterion, const FlipPlan& plan) {
    std::array<Tet, 4> old{};
    for (unsigned i = 0; i < plan.old_count; ++i) old[i] = mesh.tet(plan.old[i]);
    switch (criterion) {
        case SwapCriterion3::MaxMinDihedral:
        case SwapCriterion3::MinMaxDihedral: {
            const bool min = criterion == SwapCriterion3::MaxMinDihedral;
            auto extreme = [&](const std::array<Tet, 4>& set, unsigned count) {
                Dihedral best = min ? smallest_dihedral(corners(mesh, set[0])) : largest_dihedral(corners(mesh, set[0]));
                for (unsigned i = 1; i < count; ++i) {
                    const Dihedral c = min ? smallest_dihedral(corners(mesh, set[i])) : largest_dihedral(corners(mesh, set[i]));
                    if (compare_dihedral(c, best) == (min ? Sign::Negative : Sign::Positive)) best = c;
                }
                return best;
            };
            const Dihedral before = extreme(old, plan.old_count);
            const Dihedral after = extreme(plan.made, plan.made_count);
            return compare_dihedral(after, before) == (min ? Sign::Positive : Sign::Negative);
        }
        case SwapCriterion3::VolumeEdge: {
            auto worst = [&](const std::array<Tet, 4>& set, unsigned count) {
                TetCorners best = corners(mesh, set[0]);
                for (unsigned i = 1; i < count; ++i) {
                    const TetCorners c = corners(mesh, set[i]);
                    if (compare_volume_edge(c, best) == Sign::Negative) best = c;
                }
                return best;
            };
            return compare_volume_edge(worst(plan.made, plan.made_count), worst(old, plan.old_count)) == Sign::Positive;
        }
        case SwapCriterion3::Delaunay: break;
    }
    throw InternalError("edge_face_swap_3d: quality_prefers called for the Delaunay criterion");
}

void apply(FlipMesh3& mesh, const FlipPlan& plan, std::vector<TetIdx>& created) {
    const bool ok = replace_tets(mesh, std::span<const TetIdx>(plan.old.data(), plan.old_count),
                                 std::span<const Tet>(plan.made.data(), plan.made_count), &created,
                                 plan.kind == FlipKind3::Flip22);
    if (!ok) throw InternalError("edge_face_swap_3d: a swap's new tetrahedra do not fit the old boundary");
}

void count_flip(EdgeFaceSwapCounters& counters, FlipKind3 kind) {
    switch (kind) {
        case FlipKind3::Flip23: ++counters.flips_23; break;
        case FlipKind3::Flip32: ++counters.flips_32; break;
        case FlipKind3::Flip44: ++counters.flips_44; break;
        case FlipKind3::Flip22: ++counters.flips_22; break;
        case FlipKind3::None: break;
    }
}

}  // namespace

SwapCriterion3 swap_criterion_3d_from_name(std::string_view name) {
    if (name == "delaunay") return SwapCriterion3::Delaunay;
    if (name == "max-min-dihedral") return SwapCriterion3::MaxMinDihedral;
    if (name == "min-max-dihedral") return SwapCriterion3::MinMaxDihedral;
    if (name == "volume-edge") return SwapCriterion3::VolumeEdge;
    throw InputError("unknown 3D swap criterion '" + std::string(name) +
                     "' (known: delaunay, max-min-dihedral, min-max-dihedral, volume-edge)");
}

std::string_view swap_criterion_3d_name(SwapCriterion3 criterion) {
    switch (criterion) {
        case SwapCriterion3::Delaunay: return "delaunay";
        case SwapCriterion3::MaxMinDihedral: return "max-min-dihedral";
        case SwapCriterion3::MinMaxDihedral: return "min-max-dihedral";
        case SwapCriterion3::VolumeEdge: return "volume-edge";
    }
    return "unknown";
}

bool plan_flip_3d(const FlipMesh3& mesh, FacetIdx f, FlipPlan3& plan, std::uint64_t* edges_examined) {
    if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) return false;
    return plan_flip(mesh, f, plan, edges_examined);
}

void apply_flip_3d(FlipMesh3& mesh, const FlipPlan3& plan, std::vector<TetIdx>& created) { apply(mesh, plan, created); }

bool locally_delaunay_sos(const FlipMesh3& mesh, FacetIdx f) {
    EM_ASSERT(mesh.adj[f] != kNone);
    return !delaunay_wants(mesh, f);
}

FlipKind3 flip_face_3d(FlipMesh3& mesh, FacetIdx f) {
    if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) return FlipKind3::None;
    FlipPlan plan;
    if (!plan_flip(mesh, f, plan, nullptr)) return FlipKind3::None;
    std::vector<TetIdx> created;
    apply(mesh, plan, created);
    return plan.kind;
}

EdgeFaceSwapCounters swap_faces_3d(FlipMesh3& mesh, SwapCriterion3 criterion) {
    EdgeFaceSwapCounters counters;
    std::vector<std::uint8_t> queued(mesh.adj.size(), 0);
    std::deque<FacetIdx> queue;
    auto push = [&](FacetIdx f) {
        if (f >= queued.size()) queued.resize(mesh.adj.size(), 0);
        if (queued[f] != 0 || mesh.adj[f] == kNone) return;
        queued[f] = 1;
        queue.push_back(f);
    };
    for (FacetIdx f = 0; f < mesh.adj.size(); ++f) {
        if (!mesh.is_dead(f / 4) && mesh.adj[f] != kNone && mesh.adj[f] > f) push(f);
    }
    std::vector<TetIdx> created;
    FlipPlan plan;
    while (!queue.empty()) {
        const FacetIdx f = queue.front();
        queue.pop_front();
        queued[f] = 0;
        if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) continue;
        ++counters.faces_examined;
        if (criterion == SwapCriterion3::Delaunay) {
            if (!delaunay_wants(mesh, f)) continue;
            if (!plan_flip(mesh, f, plan, &counters.edges_examined)) {
                ++counters.not_flippable;
                continue;
            }
        } else {
            if (!plan_flip(mesh, f, plan, &counters.edges_examined)) {
                ++counters.not_flippable;
                continue;
            }
            if (!quality_prefers(mesh, criterion, plan)) continue;
        }
        apply(mesh, plan, created);
        count_flip(counters, plan.kind);
        // Every face of the new tetrahedra, the ones between them too: a face between two new
        // tetrahedra is where a later 4-4 swap through them is seen from (its other faces see
        // other point sets), and the swap that would undo this one is simply never preferred.
        for (const TetIdx t : created) {
            for (unsigned k = 0; k < 4; ++k) push(4 * t + k);
        }
    }
    if (criterion == SwapCriterion3::Delaunay) {
        for (FacetIdx f = 0; f < mesh.adj.size(); ++f) {
            if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone || mesh.adj[f] < f) continue;
            if (delaunay_wants(mesh, f)) ++counters.stalled_faces;
        }
    }
    return counters;
}

EdgeFaceSwapCounters swap_faces_3d(Tetrahedralization3& mesh, SwapCriterion3 criterion) {
    FlipMesh3 work = make_flip_mesh_3d(mesh);
    const EdgeFaceSwapCounters counters = swap_faces_3d(work, criterion);
    mesh = to_tetrahedralization_3d(work);
    return counters;
}

}  // namespace exactmesh::triangulation
