// SPDX-License-Identifier: MIT
// Sliver removal: constrained MaxMinDihedral swapping and smoothing of interior Steiner
// vertices (see sliver_removal_3d.hpp).
#include "generators/mesh_3d/sliver_removal_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/scaled_differences_3d.hpp"
#include "generators/mesh_3d/small_angle_rule_3d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/edge_removal_3d.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
using predicates::compare_dihedral;
using predicates::Dihedral;
using predicates::Sign;
using predicates::TetCorners;
using tri::FaceIdx;
using tri::kNone;
using tri::Tet;
using tri::TetIdx;
using tri::TetMesh3;
using tri::VertIdx;

constexpr double kPi = 3.141592653589793238462643383279502884;

TetCorners corners_of(const TetMesh3& mesh, const Tet& t) {
    return {mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3])};
}

/// The working state: the mesh, the region attribute and volume bound per slot, the bounds.
struct Work {
    TetMesh3 mesh;
    std::vector<double> slot_attributes;   ///< per slot; empty without regions
    std::vector<double> slot_max_volumes;  ///< per slot; empty when no region has a bound
    const SliverRemoval3Options* options = nullptr;
    /// refinement's small-input-angle rule on the mesh's segments (over_bounds)
    const SmallInputAngleRule3* small_angles = nullptr;
    /// cos^2 of the threshold angle (acute), for dihedral_below_rounded
    long double threshold_cos_squared = 1;

    /// The volume bound of the tetrahedron in slot t, or of one made from it by a swap (the
    /// global bound and its region's, the smaller; 0: none), as delaunay_refinement_3d rules.
    double volume_bound(TetIdx t) const {
        return tet_volume_bound_3d(options->max_volume,
                                   t < slot_max_volumes.size() ? slot_max_volumes[t] : 0.0);
    }

    /// Whether the tetrahedron with vertices `v` at corners p exceeds B or the volume bound
    /// `max_volume` (> 0; else none), exactly. 0 within the bounds; 1 over the radius-edge
    /// bound where refinement spares it (the small-input-angle rule, or an edge finer than
    /// doubles resolve: tet_finer_than_doubles_resolve_3d); kOverBound otherwise. Sums compared
    /// before and after a change keep the count over the bounds and never trade a spared
    /// tetrahedron for one refinement would have split (the command's exact check,
    /// check_refinement_quality_3d, then called that a bug; regression_issue_15_hostile_inputs_test
    /// on cube_free_2.poly fails without the small-angle rule here).
    unsigned over_bounds(const Tet& v, const TetCorners& p, double max_volume) const {
        if (max_volume > 0 &&
            predicates::compare_tet_volume_3d(p[0], p[1], p[2], p[3], max_volume) == Sign::Positive)
            return kOverBound;
        if (predicates::compare_radius_edge_3d(p[0], p[1], p[2], p[3],
                                               options->radius_edge_bound) != Sign::Positive)
            return 0;
        if (small_angles != nullptr && small_angles->spares(v, p)) return 1;
        const double* const corners[4] = {p[0], p[1], p[2], p[3]};
        return tet_finer_than_doubles_resolve_3d(corners) ? 1 : kOverBound;
    }
    static constexpr unsigned kOverBound = 1u << 16;

    /// Whether tetrahedron t has a dihedral angle below the threshold (rounded: a selection,
    /// not a decision; the same for the mesh scaled by 2^k).
    bool below_threshold(TetIdx t) const {
        // The six rounded angles, no exact comparison: finding the exact smallest first (five
        // filtered comparisons, ties in GMP) was a third of sliver removal's time; then
        // atan2 of each angle in long double was 9% of tetmesh's time on the wing, and six
        // separate long double angles 17% of sliver removal's on box-with-hole.
        return predicates::any_dihedral_below_rounded(corners_of(mesh, mesh.tet(t)),
                                                      threshold_cos_squared);
    }

    /// below_threshold per slot: 0 not known, 1 below, 2 not below. A slot's entry is forgotten
    /// when a swap makes a tetrahedron in it or a corner of its tetrahedron moves (touch): only
    /// those change (bad_tets runs six times per round, and swaps and moves change few
    /// tetrahedra: the angles were a quarter of sliver removal's instructions). One byte per
    /// slot (the entries had held the slot's corners and a move count, checked against every
    /// corner's last move: a tenth of the face swaps' time went to those reads).
    mutable std::vector<std::uint8_t> below_state;

    void move_vertex(VertIdx v, const std::array<double, 3>& to) {
        for (std::size_t k = 0; k < 3; ++k) mesh.xyz[3 * std::size_t{v} + k] = to[k];
    }

    bool below_threshold_remembered(TetIdx t) const {
        if (below_state.size() < mesh.tet_slots()) below_state.resize(mesh.tet_slots(), 0);
        std::uint8_t& state = below_state[t];
        if (state == 0) state = below_threshold(t) ? 1 : 2;
        return state == 1;
    }

    /// The tetrahedra below the threshold when bad_tets last ran, and those made or changed
    /// since (the tetrahedra a swap creates, the star of a moved vertex): no other tetrahedron
    /// can have crossed the threshold in between.
    std::vector<TetIdx> last_bad;
    std::vector<TetIdx> touched;
    bool scanned = false;

    /// Tetrahedra made by a swap, or the star of a vertex after it moved: their entries are
    /// forgotten, and bad_tets looks at them again.
    void touch(const std::vector<TetIdx>& tets) {
        touched.insert(touched.end(), tets.begin(), tets.end());
        for (const TetIdx t : tets)
            if (t < below_state.size()) below_state[t] = 0;
    }

    /// The live tetrahedra below the threshold, in slot order: the whole mesh the first time,
    /// then last_bad and touched (the same list a scan of the whole mesh gives, without
    /// reading its 10^6 slots six times per round: a tenth of sliver removal's time).
    std::vector<TetIdx> bad_tets() {
        std::vector<TetIdx> bad;
        if (!scanned) {
            // The corners of a tetrahedron a few slots ahead are fetched while this one is
            // measured (they lie anywhere in the coordinates: a third of this scan's time).
            constexpr TetIdx kAhead = 8;
            const TetIdx slots = mesh.tet_slots();
            for (TetIdx t = 0; t < slots; ++t) {
                if (t + kAhead < slots && !mesh.is_dead(t + kAhead)) {
                    for (unsigned k = 0; k < 4; ++k)
                        __builtin_prefetch(mesh.point(mesh.vertex(t + kAhead, k)));
                }
                if (!mesh.is_dead(t) && below_threshold_remembered(t)) bad.push_back(t);
            }
            scanned = true;
        } else {
            std::vector<TetIdx> candidates = std::move(last_bad);
            candidates.insert(candidates.end(), touched.begin(), touched.end());
            std::sort(candidates.begin(), candidates.end());
            candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
            for (const TetIdx t : candidates) {
                if (t < mesh.tet_slots() && !mesh.is_dead(t) && below_threshold_remembered(t))
                    bad.push_back(t);
            }
        }
        touched.clear();
        last_bad = bad;
        return bad;
    }
};

// ---- Swapping ----

/// The subfaces and subsegments, and every edge of a subface.
tri::SwapLocks3 conforming_locks(const tri::ConformingMesh3& conforming) {
    tri::SwapLocks3 locks;
    const auto& sub = conforming.subfaces;
    for (std::size_t s = 0; s + 2 < sub.size(); s += 3) {
        locks.add_face(sub[s], sub[s + 1], sub[s + 2]);
        locks.add_edge(sub[s], sub[s + 1]);
        locks.add_edge(sub[s + 1], sub[s + 2]);
        locks.add_edge(sub[s + 2], sub[s]);
    }
    const auto& seg = conforming.subsegments;
    for (std::size_t s = 0; s + 1 < seg.size(); s += 2) locks.add_edge(seg[s], seg[s + 1]);
    locks.finish();
    return locks;
}

/// One swapping pass from the faces of the tetrahedra below the threshold; the number of swaps.
std::uint64_t swap_pass(Work& work, const tri::SwapLocks3& locks, SliverRemoval3Counters& c) {
    std::vector<FaceIdx> seeds;
    for (const TetIdx t : work.bad_tets()) {
        for (unsigned k = 0; k < 4; ++k) seeds.push_back(4 * t + k);
    }
    if (seeds.empty()) return 0;
    tri::SwapConstraints3 constraints;
    constraints.locks = &locks;
    constraints.seeds = seeds;
    // Only faces of tetrahedra below the threshold: swaps between good tetrahedra (a cascade
    // from each new one's faces) raised no final angle. On the wing at 7 10^5 tetrahedra the
    // same smallest angle (11.66 degrees) and slivers left, 1.05 s -> 0.77 s, 3% more angles
    // below 20 degrees (still 2.6 times fewer than TetGen's).
    constraints.wanted = [&work](TetIdx t) { return work.below_threshold_remembered(t); };
    if (work.options->keep_bounds) {
        // The old tetrahedra lie in one region (see on_flip below): the new ones are held to
        // its volume bound.
        constraints.accept = [&work](const tri::FlipPlan3& plan) {
            unsigned before = 0, after = 0;
            for (unsigned i = 0; i < plan.old_count; ++i)
                before += work.over_bounds(work.mesh.tet(plan.old[i]),
                                           corners_of(work.mesh, work.mesh.tet(plan.old[i])),
                                           work.volume_bound(plan.old[i]));
            const double made_bound = work.volume_bound(plan.old[0]);
            for (unsigned i = 0; i < plan.made_count; ++i)
                after +=
                    work.over_bounds(plan.made[i], corners_of(work.mesh, plan.made[i]), made_bound);
            return after <= before;
        };
    }
    // The old tetrahedra of a swap share faces that are no subfaces, so they lie in one
    // region: the new ones take its attribute and volume bound (slot created[0] is old[0]'s,
    // unchanged).
    constraints.on_flip = [&work](const tri::FlipPlan3&, const std::vector<TetIdx>& created) {
        work.touch(created);
        for (std::vector<double>* values : {&work.slot_attributes, &work.slot_max_volumes}) {
            if (values->empty()) continue;
            values->resize(work.mesh.tet_slots(), 0.0);
            const double value = (*values)[created.front()];
            for (const TetIdx t : created) (*values)[t] = value;
        }
    };
    const tri::EdgeFaceSwapCounters s =
        tri::swap_faces_3d(work.mesh, tri::SwapCriterion3::MaxMinDihedral, constraints);
    c.flips_23 += s.flips_23;
    c.flips_32 += s.flips_32;
    c.flips_44 += s.flips_44;
    c.swaps_locked += s.locked;
    c.swaps_vetoed += s.vetoed;
    EM_ASSERT(s.flips_22 == 0);
    // Then the edges of the tetrahedra still below the threshold, by edge removal (rings of up
    // to 7, which the face swaps above do not reach): the same locks, bounds and regions.
    const std::vector<TetIdx> still = work.bad_tets();
    const tri::EdgeRemovalCounters e =
        tri::remove_edges_3d(work.mesh, tri::SwapCriterion3::MaxMinDihedral, still, constraints);
    c.edge_removals += e.removals;
    c.swaps_locked += e.locked;
    c.swaps_vetoed += e.vetoed;
    return s.flips() + e.removals;
}

// ---- Smoothing ----

using vec3::cross;
using vec3::dot;
using vec3::sub;
using vec3::Vec;

/// A tetrahedron of a star in the frame below: its corners (the moving one at slot `moving`,
/// the origin), and what does not depend on where the moving corner goes: the area vector of
/// the face opposite it (area_vector below) and that vector's squared length.
struct StarTet {
    std::array<Vec, 4> corners;
    unsigned moving = 0;
    Vec fixed_area{0, 0, 0};
    double fixed_area_squared = 0;
};

/// The star of a vertex in a frame centred at the vertex and scaled by a power of two (the
/// largest neighbour offset in [1/2, 1)). Offsets are rounded differences times 2^-exponent,
/// so the frame's numbers are the same for the mesh scaled by any power of two.
struct StarFrame {
    std::vector<StarTet> tets;
    std::vector<Vec> neighbours;
    int exponent = 0;
    /// The order in which star_smallest_angle evaluates the tetrahedra: each one found at or
    /// below a floor moves to the front (the tetrahedra that ruled out recent candidates rule
    /// out most of the next ones). Only the order of evaluation, never a value, depends on it.
    mutable std::vector<std::uint32_t> order;
};

/// The corners of the face opposite corner k, in the order whose cross product
/// (b - a) x (c - a) points into the tetrahedron for every k when it is positively oriented
/// (then the four area vectors sum to zero, and each one's dot product with its opposite
/// corner minus the face's first corner is six times the volume).
constexpr unsigned kFaceCorners[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// Twice the area of the face opposite corner k, as an inward vector (kFaceCorners).
Vec area_vector(const std::array<Vec, 4>& p, unsigned k) {
    const unsigned* f = kFaceCorners[k];
    return cross(sub(p[f[1]], p[f[0]]), sub(p[f[2]], p[f[0]]));
}

/// The six dihedral angles' minimum, as an increasing function of the angle, of the
/// tetrahedron with its moving corner at x (an inverted or flat one gives -1). Returns as soon
/// as an angle is at or below `floor`: the result is exact when above `floor`, else some
/// value at or below it. The function: with N_k, N_l the area vectors of the two faces at edge
/// e and V the volume, cos = -N_k . N_l / (|N_k| |N_l|) and |N_k x N_l| = 6 V |e|, so
/// s = |e|^2 (6V)^2 / (|N_k|^2 |N_l|^2) is sin^2 of the angle; the value is s for an acute
/// angle and 2 - s for an obtuse one, in [0, 2] and increasing over [0, pi]. No square root and
/// full relative precision near 0 (the slivers' angles). The search below only takes minima
/// and compares them, so an increasing function of the angle steers it as the angle would
/// (atan2 of each angle was 40% of tetmesh's time on the wing; the pseudo-angle that replaced
/// it took two cross products and a triple product per edge, and the star evaluations were
/// still 42% of sliver removal's instructions at 10^5 tetrahedra on the wing).
double smallest_angle(const StarTet& tet, const Vec& x, double floor, unsigned* which = nullptr) {
    std::array<Vec, 4> p = tet.corners;
    p[tet.moving] = x;
    const unsigned m = tet.moving;
    const double six_volume = dot(tet.fixed_area, sub(x, p[kFaceCorners[m][0]]));
    if (!(six_volume > 0)) return -1;
    std::array<Vec, 4> area;
    std::array<double, 4> area_squared;
    for (unsigned k = 0; k < 4; ++k) {
        if (k == m) {
            area[k] = tet.fixed_area;
            area_squared[k] = tet.fixed_area_squared;
        } else {
            area[k] = area_vector(p, k);
            area_squared[k] = dot(area[k], area[k]);
        }
    }
    // Edge (i, j) and the two corners k, l off it: its faces are those opposite k and l.
    static constexpr unsigned kEdges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                              {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};
    const double volume_squared = six_volume * six_volume;
    double smallest = 2;
    for (unsigned k = 0; k < 6; ++k) {
        const auto& edge = kEdges[k];
        const Vec e = sub(p[edge[1]], p[edge[0]]);
        const double s =
            dot(e, e) * volume_squared / (area_squared[edge[2]] * area_squared[edge[3]]);
        const double value = dot(area[edge[2]], area[edge[3]]) < 0 ? s : 2 - s;
        if (which != nullptr && value < smallest) *which = k;
        smallest = std::min(smallest, value);
        if (smallest <= floor) return smallest;
    }
    return smallest;
}

/// The tetrahedron of the star (its index in frame.tets) and its edge ({i, j} of the corners)
/// whose dihedral angle is the smallest in the frame's doubles with the vertex where it is: a
/// selection, within rounding of the exact smallest angle, and an angle of the star's at least
/// as large as that one.
std::pair<std::size_t, std::array<unsigned, 2>> star_smallest_edge(const StarFrame& frame) {
    static constexpr unsigned kEdgeCorners[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    std::size_t best_tet = 0;
    unsigned best_edge = 0;
    double best = 3;
    for (std::size_t i = 0; i < frame.tets.size(); ++i) {
        unsigned edge = 0;
        const double value = smallest_angle(frame.tets[i], Vec{0, 0, 0}, -2, &edge);
        if (value < best) {
            best = value;
            best_tet = i;
            best_edge = edge;
        }
    }
    return {best_tet, {kEdgeCorners[best_edge][0], kEdgeCorners[best_edge][1]}};
}

/// The star's smallest angle (smallest_angle over its tetrahedra) with the moving vertex at x;
/// with `floor`, as soon as one tetrahedron is at or below it, that tetrahedron's value: exact
/// above `floor`, else at or below it. The search only asks whether a value beats the best so
/// far, so stopping at the first tetrahedron that rules it out gives the same decisions at a
/// fraction of the work (the tetrahedra that ruled out recent candidates are tried first: the
/// active ones, usually; on box-with-hole this cut the tetrahedra evaluated from 7.7 to 3.1 per
/// call, and those of rejected candidates from 6.5 to 1.7). The minimum does not depend on the
/// order (no NaN arises in the frame).
double star_smallest_angle(const StarFrame& frame, const Vec& x, double floor = -2) {
    double smallest = 2;
    const std::size_t n = frame.tets.size();
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t i = frame.order[j];
        smallest = std::min(smallest, smallest_angle(frame.tets[i], x, floor));
        if (smallest <= floor) {
            const auto at = frame.order.begin() + static_cast<std::ptrdiff_t>(j);
            std::rotate(frame.order.begin(), at, at + 1);
            return smallest;
        }
    }
    return smallest;
}

StarFrame star_frame(const TetMesh3& mesh, VertIdx v, const std::vector<TetIdx>& star) {
    StarFrame frame;
    const double* p = mesh.point(v);
    std::vector<VertIdx> others;
    for (const TetIdx t : star) {
        for (unsigned k = 0; k < 4; ++k) {
            const VertIdx w = mesh.vertex(t, k);
            if (w != v) others.push_back(w);
        }
    }
    std::sort(others.begin(), others.end());
    others.erase(std::unique(others.begin(), others.end()), others.end());
    double largest = 0;
    for (const VertIdx w : others) {
        for (int i = 0; i < 3; ++i) largest = std::max(largest, std::fabs(mesh.point(w)[i] - p[i]));
    }
    std::frexp(largest, &frame.exponent);
    auto local = [&](VertIdx w) -> Vec {
        if (w == v) return {0, 0, 0};
        Vec q;
        for (int i = 0; i < 3; ++i)
            q[static_cast<std::size_t>(i)] = std::ldexp(mesh.point(w)[i] - p[i], -frame.exponent);
        return q;
    };
    for (const VertIdx w : others) frame.neighbours.push_back(local(w));
    for (const TetIdx t : star) {
        StarTet tet;
        for (unsigned k = 0; k < 4; ++k) tet.corners[k] = local(mesh.vertex(t, k));
        tet.moving = mesh.slot_of(t, v);
        tet.fixed_area = area_vector(tet.corners, tet.moving);
        tet.fixed_area_squared = dot(tet.fixed_area, tet.fixed_area);
        frame.tets.push_back(tet);
    }
    frame.order.resize(frame.tets.size());
    std::iota(frame.order.begin(), frame.order.end(), std::uint32_t{0});
    return frame;
}

/// Candidate offsets (in the frame) of the moving vertex.
std::vector<Vec> candidate_offsets(const StarFrame& frame, double enough) {
    std::vector<Vec> out;
    Vec centroid{0, 0, 0};
    double shortest = 4;
    for (const Vec& q : frame.neighbours) {
        for (int i = 0; i < 3; ++i)
            centroid[static_cast<std::size_t>(i)] += q[static_cast<std::size_t>(i)];
        shortest = std::min(shortest, std::sqrt(dot(q, q)));
    }
    const auto n = static_cast<double>(frame.neighbours.size());
    for (auto& x : centroid) x /= n;
    out.push_back(centroid);
    out.push_back({centroid[0] / 2, centroid[1] / 2, centroid[2] / 2});
    // The ascent direction of the star's smallest angle, by central differences (the smallest
    // angle is piecewise smooth; its gradient is the active angle's).
    const double h = shortest * 0x1p-20;
    Vec gradient{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i) {
        Vec plus{0, 0, 0}, minus{0, 0, 0};
        plus[i] = h;
        minus[i] = -h;
        gradient[i] =
            (star_smallest_angle(frame, plus) - star_smallest_angle(frame, minus)) / (2 * h);
    }
    const double length = std::sqrt(dot(gradient, gradient));
    if (length > 0 && std::isfinite(length)) {
        for (int k = 1; k <= 6; ++k) {
            const double step = std::ldexp(shortest, -k) / length;
            out.push_back({gradient[0] * step, gradient[1] * step, gradient[2] * step});
        }
    }
    // A compass search on the rounded smallest angle: where two or more angles are active
    // (a max-min optimum along every single gradient), a step along one of the 26 lattice
    // directions that raises them all can still exist. Halves the step when none improves.
    Vec x{0, 0, 0};
    double best = star_smallest_angle(frame, x);
    double step = shortest / 4;
    for (int iteration = 0; iteration < 24 && step > shortest * 0x1p-12 && best <= enough;
         ++iteration) {
        Vec next = x;
        double next_value = best;
        for (int dx = -1; dx <= 1; ++dx) {
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dz = -1; dz <= 1; ++dz) {
                    if (dx == 0 && dy == 0 && dz == 0) continue;
                    const double scale =
                        step / std::sqrt(static_cast<double>(dx * dx + dy * dy + dz * dz));
                    const Vec y{x[0] + dx * scale, x[1] + dy * scale, x[2] + dz * scale};
                    const double value = star_smallest_angle(frame, y, next_value);
                    if (value > next_value) {
                        next_value = value;
                        next = y;
                    }
                }
            }
        }
        if (next_value > best) {
            x = next;
            best = next_value;
        } else {
            step /= 2;
        }
    }
    if (x[0] != 0 || x[1] != 0 || x[2] != 0) out.push_back(x);
    return out;
}

/// Whether the star with v at `at` is positively oriented and its smallest exact dihedral angle
/// exceeds `current`: every angle of every tetrahedron does (stopping at the first angle that
/// does not).
bool star_improves(const TetMesh3& mesh, const std::vector<TetIdx>& star, VertIdx v,
                   const double* at, const Dihedral& current) {
    for (const TetIdx t : star) {
        TetCorners p = corners_of(mesh, mesh.tet(t));
        p[mesh.slot_of(t, v)] = at;
        if (predicates::orient3d(p[0], p[1], p[2], p[3]) != Sign::Positive) return false;
        if (!predicates::every_dihedral_compares(p, current, Sign::Positive)) return false;
    }
    return true;
}

unsigned star_over_bounds(const Work& work, const std::vector<TetIdx>& star, VertIdx v,
                          const double* at) {
    unsigned over = 0;
    for (const TetIdx t : star) {
        const Tet vertices = work.mesh.tet(t);
        TetCorners p = corners_of(work.mesh, vertices);
        p[work.mesh.slot_of(t, v)] = at;
        over += work.over_bounds(vertices, p, work.volume_bound(t));
    }
    return over;
}

/// Tries to move the Volume vertex v; true when it moved.
bool smooth_vertex(Work& work, VertIdx v, SliverRemoval3Counters& c) {
    TetMesh3& mesh = work.mesh;
    const std::vector<TetIdx> star = tri::vertex_star(mesh, v);
    if (star.empty()) return false;
    const StarFrame frame = star_frame(mesh, v, star);
    const std::vector<Vec> offsets =
        candidate_offsets(frame, static_cast<double>(1 - work.threshold_cos_squared));
    const double* p = mesh.point(v);
    std::vector<std::array<double, 3>> points;
    for (const Vec& d : offsets) {
        std::array<double, 3> q;
        for (std::size_t i = 0; i < 3; ++i)
            q[i] = p[i] + std::ldexp(static_cast<double>(d[i]), frame.exponent);
        if (q[0] == p[0] && q[1] == p[1] && q[2] == p[2]) continue;
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2])) continue;
        points.push_back(q);
    }
    // A move must raise the star's smallest angle: every angle after it must exceed `current`,
    // the angle the frame's doubles find smallest now. That angle is the exact smallest one or
    // within rounding above it, so a move accepted by the exact comparisons below raises the
    // exact smallest angle; the exact smallest itself (five exact comparisons per tetrahedron
    // of the star) was a tenth of sliver removal's time on the wing.
    const auto [smallest_tet, smallest_edge] = star_smallest_edge(frame);
    const Dihedral current{corners_of(mesh, mesh.tet(star[smallest_tet])), smallest_edge[0],
                           smallest_edge[1]};
    // Candidates in the order of their approximate smallest angle (the frame's double
    // values: scale-free, a heuristic only), best first, those not approximately better than
    // the current star skipped; the first that strictly raises the exact smallest angle (and
    // keeps the bounds) is taken. Exact evaluation of every candidate, then an exact sort, cost
    // most of tetmesh's time (2.2 of 2.4 s on box-with-hole at 35,000 tetrahedra).
    const double now = star_smallest_angle(frame, Vec{0, 0, 0});
    const auto approximate = [&](const std::array<double, 3>& q) {
        Vec x;
        for (std::size_t i = 0; i < 3; ++i)
            x[i] =
                std::ldexp(static_cast<double>(q[i]) - static_cast<double>(p[i]), -frame.exponent);
        return star_smallest_angle(frame, x, now);
    };
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double value = approximate(points[i]);
        if (value > now) order.push_back({value, i});
    }
    std::stable_sort(order.begin(), order.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    if (order.empty()) {
        ++c.moves_rejected;
        return false;
    }
    const unsigned over_before = work.options->keep_bounds ? star_over_bounds(work, star, v, p) : 0;
    bool improving = false;
    for (const auto& [value, i] : order) {
        if (!star_improves(mesh, star, v, points[i].data(), current)) continue;
        improving = true;
        if (work.options->keep_bounds &&
            star_over_bounds(work, star, v, points[i].data()) > over_before)
            continue;
        work.move_vertex(v, points[i]);
        work.touch(star);
        ++c.moves_accepted;
        return true;
    }
    if (!improving) {
        ++c.moves_rejected;
        return false;
    }
    ++c.moves_vetoed;
    return false;
}

/// One smoothing pass over the Volume vertices of the tetrahedra below the threshold; the
/// number of moves.
std::uint64_t smooth_pass(Work& work, const std::vector<tri::VertexFeature3>& features,
                          SliverRemoval3Counters& c) {
    std::vector<VertIdx> vertices;
    for (const TetIdx t : work.bad_tets()) {
        for (unsigned k = 0; k < 4; ++k) {
            const VertIdx v = work.mesh.vertex(t, k);
            if (features[v] == tri::VertexFeature3::Volume) vertices.push_back(v);
        }
    }
    std::sort(vertices.begin(), vertices.end());
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    std::uint64_t moves = 0;
    for (const VertIdx v : vertices) moves += smooth_vertex(work, v, c) ? 1 : 0;
    return moves;
}

// ---- Folds of a facet ----

/// Removes the tetrahedra whose two boundary faces are subfaces of one facet sharing an edge
/// that is no subsegment ("folds": flat across a facet whose corners are within rounding of a
/// plane, not in it, so no flip can reach them: both faces are constrained). Each becomes two
/// subfaces, its other two faces, when (exact) its edge ab is in no other tetrahedron, the
/// opposite edge cd in no subface, and both new subfaces have, in every coordinate projection
/// where the two old ones agree strictly, that same strict orientation: then they tile the
/// same quadrilateral of the facet's projection, which is what its exact check asks. The
/// boundary moves by the tetrahedron's volume, within rounding of the facet (the facet is
/// one only within rounding: any triangulation of its corners is as good). Works on the mesh
/// in working form `m` (conforming's tetrahedra): a removed tetrahedron's slot dies and its
/// neighbours' faces become boundary faces. Returns the count.
std::uint64_t remove_boundary_folds(tri::ConformingMesh3& conforming, TetMesh3& m) {
    const TetIdx count = m.tet_slots();
    const auto face_key = [&m](TetIdx t, unsigned k) {
        const VertIdx* v = &m.tv[4 * std::size_t{t}];
        return tri::sorted3(v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4]);
    };
    const auto neighbour = [&m](TetIdx t, unsigned k) {
        const FaceIdx twin = m.adj[4 * std::size_t{t} + k];
        return twin == kNone ? kNone : tri::tet_of(twin);
    };
    // Only a tetrahedron with two faces on the boundary can be a fold, and only their faces
    // are looked up among the subfaces (a map of every subface was a twentieth of sliver
    // removal's time on the wing, where no fold is found).
    std::vector<TetIdx> two_boundary_faces;
    std::unordered_map<tri::Key3, std::size_t, tri::Key3Hash> subface_of;
    for (TetIdx t = 0; t < count; ++t) {
        if (m.is_dead(t)) continue;
        const FaceIdx* u = &m.adj[4 * std::size_t{t}];
        if ((u[0] == kNone) + (u[1] == kNone) + (u[2] == kNone) + (u[3] == kNone) < 2) continue;
        two_boundary_faces.push_back(t);
        for (unsigned k = 0; k < 4; ++k)
            if (u[k] == kNone) subface_of.emplace(face_key(t, k), kNone);
    }
    if (two_boundary_faces.empty()) return 0;
    for (std::size_t i = 0; 3 * i + 2 < conforming.subfaces.size(); ++i) {
        const VertIdx* f = &conforming.subfaces[3 * i];
        const auto it = subface_of.find(tri::sorted3(f[0], f[1], f[2]));
        if (it != subface_of.end() && it->second == kNone) it->second = i;
    }
    // The candidates: two boundary faces that are subfaces of one facet. They are rare, so the
    // edge counts below are taken for their edges alone (counting every edge of a 10^6
    // tetrahedron mesh would be a pass of hash insertions on every sliver removal).
    struct Fold {
        TetIdx t;
        std::array<std::size_t, 2> subs;
        VertIdx a, b, c, d;  ///< the subfaces share a b; c and d are the corners opposite them
    };
    std::vector<Fold> folds;
    for (const TetIdx t : two_boundary_faces) {
        const VertIdx* v = &m.tv[4 * std::size_t{t}];
        Fold fold{t, {}, kNone, kNone, kNone, kNone};
        std::array<unsigned, 2> opposite{};
        unsigned found = 0;
        for (unsigned k = 0; k < 4 && found <= 2; ++k) {
            if (m.adj[4 * std::size_t{t} + k] != kNone) continue;
            const auto it = subface_of.find(face_key(t, k));
            if (it == subface_of.end() || it->second == kNone) continue;
            if (found < 2) {
                fold.subs[found] = it->second;
                opposite[found] = k;
            }
            ++found;
        }
        if (found != 2 ||
            conforming.subface_facet[fold.subs[0]] != conforming.subface_facet[fold.subs[1]])
            continue;
        fold.c = v[opposite[0]];
        fold.d = v[opposite[1]];
        for (unsigned k = 0; k < 4; ++k)
            if (k != opposite[0] && k != opposite[1]) (fold.a == kNone ? fold.a : fold.b) = v[k];
        folds.push_back(fold);
    }
    if (folds.empty()) return 0;
    std::unordered_map<std::uint64_t, unsigned> ab_tets, cd_subfaces;
    for (const Fold& fold : folds) {
        ab_tets.emplace(tri::edge_key(fold.a, fold.b), 0);
        cd_subfaces.emplace(tri::edge_key(fold.c, fold.d), 0);
    }
    const auto count_in = [](std::unordered_map<std::uint64_t, unsigned>& counts,
                             std::uint64_t key) {
        const auto it = counts.find(key);
        if (it != counts.end()) ++it->second;
    };
    for (TetIdx t = 0; t < count; ++t) {
        if (m.is_dead(t)) continue;
        const VertIdx* v = &m.tv[4 * std::size_t{t}];
        for (unsigned i = 0; i < 4; ++i)
            for (unsigned j = i + 1; j < 4; ++j) count_in(ab_tets, tri::edge_key(v[i], v[j]));
    }
    for (std::size_t i = 0; 3 * i + 2 < conforming.subfaces.size(); ++i) {
        const VertIdx* f = &conforming.subfaces[3 * i];
        for (unsigned k = 0; k < 3; ++k) count_in(cd_subfaces, tri::edge_key(f[k], f[(k + 1) % 3]));
    }
    std::unordered_set<std::uint64_t> subsegments;
    for (std::size_t i = 0; i + 1 < conforming.subsegments.size(); i += 2)
        subsegments.insert(tri::edge_key(conforming.subsegments[i], conforming.subsegments[i + 1]));

    std::vector<std::uint8_t> removed(count, 0);
    std::vector<std::size_t> dropped_subfaces;
    std::vector<VertIdx> added_subfaces;
    std::vector<std::uint32_t> added_facets;
    std::uint64_t removed_count = 0;
    for (const Fold& fold : folds) {
        const TetIdx t = fold.t;
        const VertIdx a = fold.a, b = fold.b, c = fold.c, d = fold.d;
        const std::uint64_t ab = tri::edge_key(a, b);
        if (subsegments.count(ab) != 0 || ab_tets.at(ab) != 1 ||
            cd_subfaces.at(tri::edge_key(c, d)) != 0)
            continue;
        // Neighbours across the two new subfaces must stay: no two folds side by side.
        bool next_to_removed = false;
        for (unsigned k = 0; k < 4; ++k) {
            const TetIdx u = neighbour(t, k);
            next_to_removed = next_to_removed || (u != kNone && removed[u]);
        }
        if (next_to_removed) continue;
        const VertIdx* s0 = &conforming.subfaces[3 * fold.subs[0]];
        const VertIdx* s1 = &conforming.subfaces[3 * fold.subs[1]];
        // The new subfaces keep the quadrilateral's edges as the old ones direct them: the one
        // at corner p (a or b) runs p -> d when the old subface holding p and d does, so its
        // corner order is fixed by the old ones, not by the geometry. Every coordinate
        // projection where the old two agree strictly must then give both new ones that same
        // strict orientation: a quadrilateral not convex there (reflex at a or b) turns one of
        // them over. (Choosing each new subface's order to match the first such projection
        // matched it by construction: a fold removed across a reflex corner overlapped the
        // facet's next subface, a directed edge in two subfaces, and `tetmesh` stopped with an
        // internal error on a turned cube with free vertices beside an edge, frontal at 0.1.)
        const VertIdx* with_d = std::find(s0, s0 + 3, d) != s0 + 3 ? s0 : s1;
        const auto runs = [](const VertIdx* f, VertIdx x, VertIdx y) {
            for (unsigned k = 0; k < 3; ++k)
                if (f[k] == x && f[(k + 1) % 3] == y) return true;
            return false;
        };
        std::array<std::array<VertIdx, 3>, 2> fresh;
        for (unsigned i = 0; i < 2; ++i) {
            const VertIdx p = i == 0 ? a : b;
            fresh[i] = runs(with_d, p, d) ? std::array<VertIdx, 3>{p, d, c}
                                          : std::array<VertIdx, 3>{p, c, d};
        }
        bool oriented = false, ok = true;
        for (int drop = 0; drop < 3 && ok; ++drop) {
            const Sign o0 =
                tri::projected_orient(m.point(s0[0]), m.point(s0[1]), m.point(s0[2]), drop);
            const Sign o1 =
                tri::projected_orient(m.point(s1[0]), m.point(s1[1]), m.point(s1[2]), drop);
            if (o0 == Sign::Zero || o0 != o1) continue;
            for (const auto& f : fresh) {
                ok = ok &&
                     tri::projected_orient(m.point(f[0]), m.point(f[1]), m.point(f[2]), drop) == o0;
            }
            oriented = true;
        }
        if (!oriented || !ok) continue;
        removed[t] = 1;
        ++removed_count;
        dropped_subfaces.push_back(fold.subs[0]);
        dropped_subfaces.push_back(fold.subs[1]);
        const std::uint32_t facet = conforming.subface_facet[fold.subs[0]];
        for (const auto& f : fresh) {
            added_subfaces.insert(added_subfaces.end(), f.begin(), f.end());
            added_facets.push_back(facet);
            for (unsigned k = 0; k < 3; ++k)
                count_in(cd_subfaces, tri::edge_key(f[k], f[(k + 1) % 3]));
        }
    }
    if (removed_count == 0) return 0;
    // The subfaces: the dropped ones out, the new ones appended.
    std::sort(dropped_subfaces.begin(), dropped_subfaces.end());
    std::vector<VertIdx> subfaces;
    std::vector<std::uint32_t> facets;
    for (std::size_t i = 0; i < conforming.subface_facet.size(); ++i) {
        if (std::binary_search(dropped_subfaces.begin(), dropped_subfaces.end(), i)) continue;
        subfaces.insert(subfaces.end(), conforming.subfaces.begin() + 3 * i,
                        conforming.subfaces.begin() + 3 * i + 3);
        facets.push_back(conforming.subface_facet[i]);
    }
    subfaces.insert(subfaces.end(), added_subfaces.begin(), added_subfaces.end());
    facets.insert(facets.end(), added_facets.begin(), added_facets.end());
    conforming.subfaces = std::move(subfaces);
    conforming.subface_facet = std::move(facets);
    // The tetrahedra: each removed one's slot dies, its neighbours' faces become boundary
    // faces, and a corner whose tetrahedron it was takes a neighbour holding it (every corner
    // is on a face with a neighbour: two of its faces are not on the boundary).
    for (TetIdx t = 0; t < count; ++t) {
        if (!removed[t]) continue;
        const Tet v = m.tet(t);
        for (unsigned k = 0; k < 4; ++k) {
            const FaceIdx twin = m.adj[4 * std::size_t{t} + k];
            if (twin == kNone) continue;
            for (unsigned j = 0; j < 4; ++j)
                if (j != k && m.vertex_tet[v[j]] == t) m.vertex_tet[v[j]] = tri::tet_of(twin);
        }
        for (unsigned k = 0; k < 4; ++k) {
            const FaceIdx twin = m.adj[4 * std::size_t{t} + k];
            if (twin != kNone) m.adj[twin] = kNone;
            m.adj[4 * std::size_t{t} + k] = kNone;
        }
        m.kill_tet(t);
    }
    return removed_count;
}

void check_options(const SliverRemoval3Options& options) {
    if (!(options.threshold_degrees > 0 && options.threshold_degrees < 90))
        throw InputError("sliver removal: the threshold must be in (0, 90) degrees, not " +
                         std::to_string(options.threshold_degrees));
    if (!(options.radius_edge_bound > 0) || !std::isfinite(options.radius_edge_bound) ||
        !std::isfinite(options.max_volume))
        throw InputError("sliver removal: the bounds must be finite and B > 0");
}

/// Both entry points after their checks: `conforming` without its tetrahedra, `linked` holding
/// them, the region attributes and volume bounds of conforming per slot of `linked`.
SliverRemoval3Result remove_slivers(tri::ConformingMesh3 conforming, TetMesh3 linked,
                                    const SliverRemoval3Options& options,
                                    const SharpFacets3* sharp) {
    SliverRemoval3Result result;
    SliverRemoval3Counters& c = result.counters;
    c.folds_removed = remove_boundary_folds(conforming, linked);

    Work work;
    work.options = &options;
    const long double threshold_cos =
        std::cos(static_cast<long double>(options.threshold_degrees) * kPi / 180);
    work.threshold_cos_squared = threshold_cos * threshold_cos;
    work.mesh = std::move(linked);
    const SmallInputAngleRule3 small_angles =
        sharp != nullptr ? SmallInputAngleRule3(conforming, work.mesh.xyz, *sharp)
                         : SmallInputAngleRule3(conforming, work.mesh.xyz);
    work.small_angles = &small_angles;
    work.slot_attributes = std::move(conforming.tet_attributes);
    work.slot_max_volumes = std::move(conforming.tet_max_volume);
    c.slivers_before = work.bad_tets().size();
    const tri::SwapLocks3 locks = conforming_locks(conforming);
    for (unsigned round = 0; round < options.rounds; ++round) {
        ++c.rounds;
        const std::uint64_t swaps = swap_pass(work, locks, c);
        const std::uint64_t moves = smooth_pass(work, conforming.vertex_feature, c);
        if (swaps == 0 && moves == 0) break;
    }
    c.slivers_after = work.bad_tets().size();

    // Back to the exchange type: live slots in order, attributes and volume bounds alike.
    const auto live_values = [&work](std::vector<double>& slots) {
        std::vector<double> values;
        if (slots.empty()) return values;
        slots.resize(work.mesh.tet_slots(), 0.0);
        for (TetIdx t = 0; t < work.mesh.tet_slots(); ++t) {
            if (!work.mesh.is_dead(t)) values.push_back(slots[t]);
        }
        return values;
    };
    std::vector<double> attributes = live_values(work.slot_attributes);
    std::vector<double> max_volumes = live_values(work.slot_max_volumes);
    conforming.mesh = tri::to_tetrahedralization_3d(std::move(work.mesh));
    conforming.tet_attributes = std::move(attributes);
    conforming.tet_max_volume = std::move(max_volumes);
    result.mesh = std::move(conforming);
    return result;
}

}  // namespace

SliverRemoval3Result sliver_removal_3d(tri::ConformingMesh3 conforming,
                                       const SliverRemoval3Options& options) {
    check_options(options);
    if (conforming.vertex_feature.size() != conforming.mesh.vertex_count())
        throw InputError("sliver removal: one vertex feature per vertex is needed");
    if (!conforming.tet_max_volume.empty() &&
        conforming.tet_max_volume.size() != conforming.mesh.tet_count())
        throw InputError("sliver removal: one region volume bound per tetrahedron is needed");
    TetMesh3 linked = tri::make_tet_mesh_3d(std::move(conforming.mesh));
    conforming.mesh = {};
    return remove_slivers(std::move(conforming), std::move(linked), options, nullptr);
}

SliverRemoval3Result sliver_removal_3d(tri::ConformingMesh3 conforming, TetMesh3 linked,
                                       const SliverRemoval3Options& options,
                                       const SharpFacets3* sharp) {
    check_options(options);
    if (conforming.vertex_feature.size() != linked.vertex_count())
        throw InputError("sliver removal: one vertex feature per vertex is needed");
    if (linked.vertex_tet.size() != linked.vertex_count() || linked.adj.size() != linked.tv.size())
        throw InputError("sliver removal: the linked mesh needs its links and vertex_tet");
    for (const std::vector<double>* values :
         {&conforming.tet_attributes, &conforming.tet_max_volume})
        if (!values->empty() && values->size() != linked.tet_slots())
            throw InputError("sliver removal: one region value per tetrahedron slot is needed");
    conforming.mesh = {};
    return remove_slivers(std::move(conforming), std::move(linked), options, sharp);
}

}  // namespace exactmesh::generators
