// SPDX-License-Identifier: MIT
// Constrained and conforming Delaunay triangulation (see constrained_2d.hpp); the builder's
// state is described in constrained_2d_builder.hpp.
//
// A segment is processed as a stack of pieces (a, b, segment). A piece whose walk meets a
// vertex on it, or a constrained edge across it, is split there and its parts pushed back;
// otherwise the crossed edges are removed by the chosen recovery. Local indices in the walk:
// crossed half-edge h runs from x (right of a->b) to y (left of a->b).
#include "triangulation/constrained_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <string>
#include <unordered_map>
#include <utility>

#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/errors.hpp"
#include "predicates/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/check_constrained_2d.hpp"
#include "triangulation/constrained_2d_builder.hpp"
#include "triangulation/delaunay_2d_core.hpp"
#include "triangulation/green_sibson_2d.hpp"

namespace exactmesh::triangulation {

using predicates::Sign;

SegmentRecovery segment_recovery_from_name(std::string_view name) {
    if (name == "swap") return SegmentRecovery::Swap;
    if (name == "cavity") return SegmentRecovery::Cavity;
    if (name == "conforming") return SegmentRecovery::Conforming;
    throw InputError("unknown segment recovery '" + std::string(name) +
                     "' (expected swap, cavity or conforming)");
}

const char* segment_recovery_name(SegmentRecovery recovery) {
    switch (recovery) {
        case SegmentRecovery::Swap:
            return "swap";
        case SegmentRecovery::Cavity:
            return "cavity";
        case SegmentRecovery::Conforming:
            return "conforming";
    }
    return "?";
}

namespace {

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void require_finite_items(std::span<const double> values, std::size_t stride, const char* what) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            throw InputError(std::string(what) + " " + std::to_string(i / stride) +
                             ": non-finite value " + number_text(values[i]));
        }
    }
}

}  // namespace

namespace detail {

// ---------------------------------------------------------------------------------------------

void CdtBuilder::split_triangle(TriIdx t, VertIdx p) {
    const VertIdx a = mesh_.tv[3 * t], b = mesh_.tv[3 * t + 1], c = mesh_.tv[3 * t + 2];
    const EdgeIdx x = mesh_.twin[3 * t], y = mesh_.twin[3 * t + 1], z = mesh_.twin[3 * t + 2];
    const std::uint32_t sx = segment_of_[3 * t], sy = segment_of_[3 * t + 1],
                        sz = segment_of_[3 * t + 2];
    const TriIdx t1 = t, t2 = new_triangle(), t3 = new_triangle();
    put_on_side(t2, side_of(t));
    put_on_side(t3, side_of(t));
    set(t1, p, a, b);
    set(t2, p, b, c);
    set(t3, p, c, a);
    link_outer(3 * t1 + 1, x, sx);
    link_outer(3 * t2 + 1, y, sy);
    link_outer(3 * t3 + 1, z, sz);
    link_inner(3 * t1 + 2, 3 * t2);
    link_inner(3 * t2 + 2, 3 * t3);
    link_inner(3 * t3 + 2, 3 * t1);
    flip_stack_.insert(flip_stack_.end(), {t1, t2, t3});
    core_.last_triangle = t1;
}

void CdtBuilder::split_edge(EdgeIdx e, VertIdx p) {
    const EdgeIdx f = mesh_.twin[e];
    const TriIdx t = triangle_of(e), u = triangle_of(f);
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
    const VertIdx c = apex(e), d = apex(f);
    const EdgeIdx bc = mesh_.twin[next_edge(e)], ca = mesh_.twin[prev_edge(e)];
    const EdgeIdx ad = mesh_.twin[next_edge(f)], db = mesh_.twin[prev_edge(f)];
    const std::uint32_t sbc = segment_of_[next_edge(e)], sca = segment_of_[prev_edge(e)];
    const std::uint32_t sad = segment_of_[next_edge(f)], sdb = segment_of_[prev_edge(f)];
    const std::uint32_t split = segment_of_[e];  // both halves of a split segment keep it
    const std::vector<std::uint32_t> split_shared =
        split == kNone ? std::vector<std::uint32_t>{} : release_shared(a, b);
    // Slot u takes a triangle on t's side: the sides are read first.
    const Side side_t = side_of(t), side_u = side_of(u);
    const TriIdx t1 = t, t2 = u, t3 = new_triangle(), t4 = new_triangle();
    put_on_side(t2, side_t);
    put_on_side(t3, side_u);
    put_on_side(t4, side_u);
    set(t1, p, b, c);
    set(t2, p, c, a);
    set(t3, p, a, d);
    set(t4, p, d, b);
    link_outer(3 * t1 + 1, bc, sbc);
    link_outer(3 * t2 + 1, ca, sca);
    link_outer(3 * t3 + 1, ad, sad);
    link_outer(3 * t4 + 1, db, sdb);
    link_inner(3 * t1 + 2, 3 * t2);
    link_inner(3 * t2 + 2, 3 * t3, split);  // a - p
    link_inner(3 * t3 + 2, 3 * t4);
    link_inner(3 * t4 + 2, 3 * t1, split);  // b - p
    for (const std::uint32_t other : split_shared) {
        mark(3 * t2 + 2, other);
        mark(3 * t4 + 2, other);
    }
    flip_stack_.insert(flip_stack_.end(), {t1, t2, t3, t4});
    core_.last_triangle = t1;
}

void CdtBuilder::insert_vertex(VertIdx p, TriIdx t) {
    flip_stack_.clear();
    int on_edge = -1;
    if (!mesh_.is_infinite(t)) {
        for (int k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + static_cast<unsigned>(k);
            if (core_.orient(mesh_.origin(e), mesh_.destination(e), p) == Sign::Zero) on_edge = k;
        }
    }
    if (on_edge < 0) {
        split_triangle(t, p);
    } else {
        split_edge(3 * t + static_cast<unsigned>(on_edge), p);
    }
    while (!flip_stack_.empty()) {
        const TriIdx t1 = flip_stack_.back();
        flip_stack_.pop_back();
        flip_if_needed(t1);
    }
}

void CdtBuilder::flip_if_needed(TriIdx t1) {
    const EdgeIdx e = 3 * t1 + 1;
    const EdgeIdx f = mesh_.twin[e];
    const VertIdx q = apex(f);
    if (segment_of_[e] != kNone) {
        // Conforming: a marked piece the new vertex makes not locally Delaunay is split later.
        if (conforming_ && q != kInfinite && !mesh_.is_infinite(t1) && core_.conflict(t1, q)) {
            encroached_.push_back({mesh_.tv[3 * t1 + 1], mesh_.tv[3 * t1 + 2], segment_of_[e]});
        }
        return;
    }
    if (q == kInfinite || !core_.conflict(t1, q)) return;
    ++result_.counters.delaunay_flips;
    const TriIdx t2 = triangle_of(f);
    const VertIdx p = mesh_.tv[3 * t1], u = mesh_.tv[3 * t1 + 1], v = mesh_.tv[3 * t1 + 2];
    const EdgeIdx vp = mesh_.twin[3 * t1 + 2];
    const std::uint32_t svp = segment_of_[3 * t1 + 2];
    const EdgeIdx uq = mesh_.twin[next_edge(f)], qv = mesh_.twin[prev_edge(f)];
    const std::uint32_t suq = segment_of_[next_edge(f)], sqv = segment_of_[prev_edge(f)];
    set(t1, p, u, q);
    set(t2, p, q, v);
    link_outer(3 * t1 + 1, uq, suq);
    link_outer(3 * t2 + 1, qv, sqv);
    link_outer(3 * t2 + 2, vp, svp);
    link_inner(3 * t1 + 2, 3 * t2);
    flip_stack_.push_back(t1);
    flip_stack_.push_back(t2);
}

EdgeIdx CdtBuilder::flip(EdgeIdx e) {
    const EdgeIdx f = mesh_.twin[e];
    const TriIdx t1 = triangle_of(e), t2 = triangle_of(f);
    const VertIdx u = mesh_.origin(e), v = mesh_.destination(e), x = apex(e), y = apex(f);
    const EdgeIdx vx = mesh_.twin[next_edge(e)], xu = mesh_.twin[prev_edge(e)];
    const EdgeIdx uy = mesh_.twin[next_edge(f)], yv = mesh_.twin[prev_edge(f)];
    const std::uint32_t svx = segment_of_[next_edge(e)], sxu = segment_of_[prev_edge(e)];
    const std::uint32_t suy = segment_of_[next_edge(f)], syv = segment_of_[prev_edge(f)];
    // Quadrilateral u, y, v, x counter-clockwise: (x, u, y) and (y, v, x).
    set(t1, x, u, y);
    set(t2, y, v, x);
    link_outer(3 * t1, xu, sxu);
    link_outer(3 * t1 + 1, uy, suy);
    link_outer(3 * t2, yv, syv);
    link_outer(3 * t2 + 1, vx, svx);
    link_inner(3 * t1 + 2, 3 * t2 + 2);
    return 3 * t1 + 2;
}

bool CdtBuilder::locally_delaunay(EdgeIdx e) {
    const EdgeIdx f = mesh_.twin[e];
    const TriIdx t = triangle_of(e);
    if (mesh_.is_infinite(t) || mesh_.is_infinite(triangle_of(f))) return true;  // hull: fixed
    return !core_.conflict(t, apex(f));
}

void CdtBuilder::restore_delaunay(std::vector<std::pair<VertIdx, VertIdx>>& edges) {
    while (!edges.empty()) {
        const auto [u, v] = edges.back();
        edges.pop_back();
        const EdgeIdx e = find_edge(u, v);
        if (e == kNone || segment_of_[e] != kNone || locally_delaunay(e)) continue;
        ++result_.counters.delaunay_flips;
        const VertIdx x = apex(e), y = apex(mesh_.twin[e]);
        flip(e);
        edges.insert(edges.end(), {{x, u}, {u, y}, {y, v}, {v, x}});
    }
}

// ---------------------------------------------------------------------------------------------

bool CdtBuilder::on_ray(VertIdx a, VertIdx b, VertIdx x) const {
    // a, b, x collinear: is x on the side of a where b is? Exact coordinate comparisons along
    // a coordinate in which a and b differ.
    const double* pa = mesh_.point(a);
    const double* pb = mesh_.point(b);
    const double* px = mesh_.point(x);
    const int k = pa[0] != pb[0] ? 0 : 1;
    return pb[k] > pa[k] ? px[k] > pa[k] : px[k] < pa[k];
}

void CdtBuilder::guard() {
    // Every legitimate step is paid for by an input segment, a vertex or a split; a run that
    // exceeds this budget is looping on rounded intersections: report instead of hanging.
    const Cdt2Counters& c = result_.counters;
    const std::uint64_t budget = 64 * (c.segments + c.points + c.intersections +
                                       c.vertices_on_segments + c.conforming_splits) +
                                 100000;
    if (++work_done_ > budget) {
        throw GeometryError("constrained_delaunay_2d: segment recovery did not converge after " +
                            std::to_string(work_done_) + " steps (please report the input)");
    }
}

CdtBuilder::StarExit CdtBuilder::star_exit(VertIdx a, VertIdx b) {
    StarExit exit;
    const EdgeIdx first = vertex_edge_[a];
    EdgeIdx e = first;
    do {
        const VertIdx x = mesh_.destination(e), y = apex(e);
        if (x == b) {
            exit.edge = e;
            return exit;
        }
        if (x != kInfinite) {
            // Every neighbour x is tested, also when a -> x borders the infinite vertex (a
            // segment along the hull through a hull vertex).
            const Sign sx = core_.orient(a, b, x);
            if (sx == Sign::Zero && on_ray(a, b, x)) {
                exit.on_ray = x;
                return exit;
            }
            if (y != kInfinite && sx == Sign::Negative && exit.entry == kNone &&
                core_.orient(a, b, y) == Sign::Positive) {
                exit.entry = next_edge(e);
            }
        }
        e = mesh_.twin[prev_edge(e)];
    } while (e != first);
    return exit;
}

void CdtBuilder::insert_piece(const Piece& piece) {
    const VertIdx a = piece.a, b = piece.b;
    if (a == b) return;
    guard();
    const StarExit exit = star_exit(a, b);
    if (exit.edge != kNone) {
        mark(exit.edge, piece.segment);
        return;
    }
    if (exit.on_ray != kNone) {
        split_piece_at_vertex(piece, exit.on_ray);
        return;
    }
    const EdgeIdx entry = exit.entry;
    EM_ASSERT(entry != kNone);
    // Walk to b through the crossed edges.
    std::vector<EdgeIdx> crossed;
    EdgeIdx h = entry;
    for (;;) {
        if (segment_of_[h] != kNone) {
            split_at_intersection(piece, h);
            return;
        }
        crossed.push_back(h);
        const EdgeIdx f = mesh_.twin[h];
        const VertIdx w = apex(f);
        if (w == b) break;
        EM_ASSERT(w != kInfinite);
        const Sign sw = core_.orient(a, b, w);
        ++result_.counters.walk_steps;
        if (sw == Sign::Zero) {
            split_piece_at_vertex(piece, w);
            return;
        }
        h = sw == Sign::Positive ? next_edge(f) : prev_edge(f);
    }
    result_.counters.crossed_edges += crossed.size();
    if (options_.recovery == SegmentRecovery::Cavity) {
        recover_by_cavity(piece, crossed);
    } else {
        recover_by_swaps(piece, crossed);
    }
}

namespace {

/// p lies in the closed axis-parallel box of a and b (exact comparisons).
bool in_box(const double* p, const double* a, const double* b) {
    for (int k = 0; k < 2; ++k) {
        if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
    }
    return true;
}

}  // namespace

std::array<double, 2> CdtBuilder::crossing_point(const Piece& piece, VertIdx u, VertIdx v,
                                                 std::uint32_t other) {
    // The rule (proofs/invariants/constrained_delaunay.md §4): the pieces a - b of segment S and
    // u - v of segment T cross. When the INPUT segments S and T have exactly one common point X,
    // the vertex is X rounded once to the nearest doubles (predicates::segment_intersection is
    // exact and correctly rounded at every magnitude), provided it lies in the closed coordinate
    // boxes of both pieces. Rounding is monotone per coordinate, so the rounded crossings of a
    // segment keep their order along it, weakly: every vertex of S's chain then lies in the box of
    // its neighbours, the chain is monotone in both coordinates, and no piece is ever split
    // outside its own box. Otherwise the two pieces cross only because earlier roundings bent them
    // (S and T are parallel, or meet elsewhere, or not at all: an endpoint of one lies within
    // rounding of the other): then the pieces' own intersection, rounded once, which lies in both
    // boxes. Each split adds a vertex in both boxes (or merges with an equal one), so every chain
    // stays monotone; the first kind adds at most one vertex per pair of segments, and the guard
    // (GeometryError) bounds the second.
    const double* a = mesh_.point(piece.a);
    const double* b = mesh_.point(piece.b);
    const double* pu = mesh_.point(u);
    const double* pv = mesh_.point(v);
    const double* s0 = mesh_.point(segment_ends_[piece.segment][0]);
    const double* s1 = mesh_.point(segment_ends_[piece.segment][1]);
    const double* t0 = mesh_.point(segment_ends_[other][0]);
    const double* t1 = mesh_.point(segment_ends_[other][1]);
    const Sign o0 = predicates::orient2d(t0, t1, s0), o1 = predicates::orient2d(t0, t1, s1);
    const Sign o2 = predicates::orient2d(s0, s1, t0), o3 = predicates::orient2d(s0, s1, t1);
    const bool meet = !(o0 == Sign::Zero && o1 == Sign::Zero) && (o0 != o1 || o0 == Sign::Zero) &&
                      (o2 != o3 || o2 == Sign::Zero);
    if (meet) {
        const auto x = predicates::segment_intersection(s0, s1, t0, t1);
        if (in_box(x.data(), a, b) && in_box(x.data(), pu, pv)) return x;
    }
    ++result_.counters.bent_crossings;
    return predicates::segment_intersection(a, b, pu, pv);
}

void CdtBuilder::split_at_intersection(const Piece& piece, EdgeIdx h) {
    const VertIdx a = piece.a, b = piece.b;
    const VertIdx u = mesh_.origin(h), v = mesh_.destination(h);
    const std::uint32_t other = segment_of_[h];
    const std::array<double, 2> p = crossing_point(piece, u, v, other);
    // The rounded point may equal a vertex (then both segments bend through it).
    const VertIdx candidate = add_vertex(p[0], p[1]);
    core_.last_triangle = triangle_of(h);
    const TriIdx t = core_.walk_to(candidate);
    VertIdx at = candidate;
    if (!mesh_.is_infinite(t)) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx w = mesh_.tv[3 * t + k];
            if (core_.same_point(w, candidate)) at = w;
        }
    }
    segment_of_[h] = segment_of_[mesh_.twin[h]] = kNone;
    const std::vector<std::uint32_t> also = release_shared(u, v);
    if (at != candidate) {
        remove_last_vertex();
        ++result_.counters.vertices_on_segments;
        result_.warnings.push_back("segments " + segment_name(piece.segment) + " and " +
                                   segment_name(other) + " cross at " + vertex_name(at) +
                                   "; both split there");
    } else {
        const std::uint64_t segments = result_.counters.segments;
        if (++result_.counters.intersections > segments * (segments + 1) / 2 + 1000) {
            throw GeometryError(
                "constrained_delaunay_2d: more segment intersections than pairs of "
                "segments; recovery is looping (please report the input)");
        }
        insert_vertex(candidate, t);
        result_.warnings.push_back(
            "segments " + segment_name(piece.segment) + " and " + segment_name(other) +
            " cross; split at new vertex " +
            std::to_string(core_.input_index[candidate] + options_.first_index) + " (" +
            number_text(p[0]) + ", " + number_text(p[1]) + ")");
    }
    // u - v, no longer constrained, may not be locally Delaunay (the new vertex need not be
    // next to it): restore before recovering the four pieces.
    std::vector<std::pair<VertIdx, VertIdx>> released{{u, v}};
    restore_delaunay(released);
    for (const std::uint32_t s : also) {
        work_.push_back({u, at, s});
        work_.push_back({at, v, s});
    }
    work_.push_back({u, at, other});
    work_.push_back({at, v, other});
    work_.push_back({at, b, piece.segment});
    work_.push_back({a, at, piece.segment});
}

void CdtBuilder::recover_by_swaps(const Piece& piece, const std::vector<EdgeIdx>& crossed) {
    const VertIdx a = piece.a, b = piece.b;
    std::deque<std::pair<VertIdx, VertIdx>> pending;
    for (const EdgeIdx h : crossed) pending.emplace_back(mesh_.origin(h), mesh_.destination(h));
    std::vector<std::pair<VertIdx, VertIdx>> created;
    std::uint64_t stalled = 0;
    while (!pending.empty()) {
        const auto [u, v] = pending.front();
        pending.pop_front();
        const EdgeIdx e = find_edge(u, v);
        EM_ASSERT(e != kNone);
        const VertIdx x = apex(e), y = apex(mesh_.twin[e]);
        // Strictly convex quadrilateral: the other diagonal x - y crosses u - v.
        const Sign su = core_.orient(x, y, u), sv = core_.orient(x, y, v);
        if (su == Sign::Zero || sv == Sign::Zero || su == sv) {
            pending.emplace_back(u, v);
            // Sloan's lemma: among the crossed edges one is always flippable.
            EM_ASSERT(++stalled <= pending.size() + 1);
            continue;
        }
        stalled = 0;
        flip(e);
        ++result_.counters.recovery_flips;
        const Sign sx = x == a || x == b ? Sign::Zero : core_.orient(a, b, x);
        const Sign sy = y == a || y == b ? Sign::Zero : core_.orient(a, b, y);
        if (sx != Sign::Zero && sy != Sign::Zero && sx != sy) {
            pending.emplace_back(x, y);
        } else {
            created.emplace_back(x, y);
        }
    }
    const EdgeIdx ab = find_edge(a, b);
    EM_ASSERT(ab != kNone);
    mark(ab, piece.segment);
    restore_delaunay(created);
}

void CdtBuilder::triangulate_pseudo_polygon(VertIdx u, VertIdx v, std::span<const VertIdx> chain,
                                            std::vector<std::array<VertIdx, 3>>& out) {
    // Polygon u, v, chain[0], ..., chain[k-1], left of u -> v. The apex whose circle through
    // u and v holds no other chain vertex: one pass suffices, since every circle through u, v
    // met later has a smaller cap on this side of the line.
    if (chain.empty()) return;
    std::size_t best = 0;
    for (std::size_t i = 1; i < chain.size(); ++i) {
        if (core_.incircle(u, v, chain[best], chain[i]) == Sign::Positive) best = i;
    }
    const VertIdx c = chain[best];
    out.push_back({u, v, c});
    triangulate_pseudo_polygon(c, v, chain.subspan(0, best), out);
    triangulate_pseudo_polygon(u, c, chain.subspan(best + 1), out);
}

void CdtBuilder::recover_by_cavity(const Piece& piece, const std::vector<EdgeIdx>& crossed) {
    const VertIdx a = piece.a, b = piece.b;
    // The crossed triangles, the chains left (upper) and right (lower) of a -> b, and the
    // cavity's boundary half-edges seen from outside, keyed by their (origin, destination).
    std::vector<TriIdx> cavity;
    cavity.push_back(triangle_of(crossed.front()));
    for (const EdgeIdx h : crossed) cavity.push_back(triangle_of(mesh_.twin[h]));
    std::vector<VertIdx> upper, lower;  // from a's side to b's side
    for (const EdgeIdx h : crossed) {
        const VertIdx x = mesh_.origin(h), y = mesh_.destination(h);
        if (lower.empty() || lower.back() != x) lower.push_back(x);
        if (upper.empty() || upper.back() != y) upper.push_back(y);
    }
    std::unordered_map<std::uint64_t, std::pair<EdgeIdx, std::uint32_t>> boundary;
    auto key = [](VertIdx p, VertIdx q) { return (std::uint64_t{p} << 32) | q; };
    if (in_cavity_.size() < mesh_.triangle_slots()) in_cavity_.resize(mesh_.triangle_slots(), 0);
    for (const TriIdx t : cavity) in_cavity_[t] = 1;
    // Constrained edges with a cavity triangle on both sides: the segment crosses the whole star
    // of a vertex but one edge, that edge being a piece (e.g. vertex w inside triangle x, y, z,
    // the segment separating {w, z} from {x, y}: it crosses x - z, x - w, y - w, y - z, and w - z
    // dangles into the cavity; PSLGs spanning 1e-225..1e212, where the triangles are extreme).
    // The pseudo-polygon's chain then visits z, w, z, its retriangulation has w - z again, and
    // the edge must keep its constraint (it was lost: a piece missing from the output).
    std::unordered_map<std::uint64_t, std::uint32_t> dangling;
    for (const TriIdx t : cavity) {
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx g = 3 * t + k;
            if (in_cavity_[triangle_of(mesh_.twin[g])]) {
                const VertIdx p = mesh_.origin(g), q = mesh_.destination(g);
                if (segment_of_[g] != kNone)
                    dangling[key(std::min(p, q), std::max(p, q))] = segment_of_[g];
                continue;
            }
            boundary[key(mesh_.origin(g), mesh_.destination(g))] = {mesh_.twin[g], segment_of_[g]};
        }
    }
    for (const TriIdx t : cavity) in_cavity_[t] = 0;
    result_.counters.cavity_triangles += cavity.size();
    std::vector<std::array<VertIdx, 3>> triangles;
    std::vector<VertIdx> chain(upper.rbegin(), upper.rend());  // left of a -> b, from b back to a
    triangulate_pseudo_polygon(a, b, chain, triangles);
    chain.assign(lower.begin(), lower.end());  // left of b -> a, from a back to b
    triangulate_pseudo_polygon(b, a, chain, triangles);
    EM_ASSERT(triangles.size() == cavity.size());
    for (const TriIdx t : cavity) mesh_.kill_triangle(t);
    std::unordered_map<std::uint64_t, EdgeIdx> open;  // new half-edges awaiting their twin
    for (const auto& tri : triangles) {
        const TriIdx t = new_triangle();
        set(t, tri[0], tri[1], tri[2]);
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx p = tri[k], q = tri[(k + 1) % 3];
            const EdgeIdx e = 3 * t + k;
            const auto outer = boundary.find(key(p, q));
            if (outer != boundary.end()) {
                link_outer(e, outer->second.first, outer->second.second);
                continue;
            }
            const auto twin = open.find(key(q, p));
            if (twin != open.end()) {
                const auto kept = dangling.find(key(std::min(p, q), std::max(p, q)));
                if (kept != dangling.end()) {
                    link_inner(e, twin->second, kept->second);
                    dangling.erase(kept);
                } else {
                    link_inner(e, twin->second);
                }
                open.erase(twin);
            } else {
                open.emplace(key(p, q), e);
            }
        }
    }
    EM_ASSERT(open.empty());
    EM_ASSERT(dangling.empty());  // every constrained edge inside the cavity is an edge again
    mark(find_edge(a, b), piece.segment);
}

void CdtBuilder::prepare_segments() {
    const std::size_t count = pslg_.segments.size() / 2;
    const std::uint32_t n = input_count_;
    segment_ends_.assign(count, {kNone, kNone});
    // Caller index -> mesh vertex, through duplicate merging.
    std::vector<VertIdx> mesh_of(n);
    for (VertIdx v = 0; v < n; ++v) mesh_of[core_.input_index[v]] = v;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    keyed.reserve(count);
    for (std::size_t s = 0; s < count; ++s) {
        const VertIdx i = pslg_.segments[2 * s], j = pslg_.segments[2 * s + 1];
        const VertIdx a = mesh_of[core_.merged_into[i]], b = mesh_of[core_.merged_into[j]];
        if (a == b) {
            ++result_.counters.dropped_segments;
            result_.warnings.push_back("segment " + segment_name(static_cast<std::uint32_t>(s)) +
                                       " has zero length (vertices " +
                                       std::to_string(i + options_.first_index) + " and " +
                                       std::to_string(j + options_.first_index) + "); ignored");
            continue;
        }
        keyed.emplace_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b),
                           static_cast<std::uint32_t>(s));
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        const std::uint32_t s = keyed[k].second;
        if (k > 0 && keyed[k - 1].first == keyed[k].first) {
            ++result_.counters.dropped_segments;
            result_.warnings.push_back("segment " + segment_name(s) + " repeats segment " +
                                       segment_name(keyed[k - 1].second) + "; ignored");
            continue;
        }
        const VertIdx i = pslg_.segments[2 * s], j = pslg_.segments[2 * s + 1];
        work_.push_back({mesh_of[core_.merged_into[i]], mesh_of[core_.merged_into[j]], s});
        segment_ends_[s] = {work_.back().a, work_.back().b};
    }
    // Process in input order (the work list is a stack).
    std::sort(work_.begin(), work_.end(),
              [](const Piece& p, const Piece& q) { return p.segment > q.segment; });
}

void CdtBuilder::conform() {
    // 1. Pieces as the constrained triangulation found them (crossings and vertices on
    //    segments already split); 2. forget the constraints and make the triangulation
    //    Delaunay; 3. split missing pieces at their midpoints until all are edges.
    std::vector<Piece> pieces;
    std::vector<std::pair<VertIdx, VertIdx>> edges;
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (mesh_.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            const VertIdx p = mesh_.origin(e), q = mesh_.destination(e);
            if (p == kInfinite || q == kInfinite || p > q) continue;
            edges.emplace_back(p, q);
            if (segment_of_[e] != kNone) {
                pieces.push_back({p, q, segment_of_[e]});
                for (const std::uint32_t s : shared_segments(p, q)) pieces.push_back({p, q, s});
            }
        }
    }
    std::fill(segment_of_.begin(), segment_of_.end(), kNone);
    shared_.clear();
    restore_delaunay(edges);
    // Every present piece is marked; Lawson flips never remove a marked edge but report it when
    // a new vertex makes it not locally Delaunay (flip_if_needed), and such a piece is split
    // instead. When the stack is empty, every unmarked edge is locally Delaunay by the flips and
    // every marked one by its last check: the triangulation is Delaunay and holds every piece.
    conforming_ = true;
    first_split_vertex_ = mesh_.vertex_count();
    segment_degree_.assign(first_split_vertex_, 0);
    for (const Piece& piece : pieces) {
        ++segment_degree_[piece.a];
        ++segment_degree_[piece.b];
    }
    std::vector<SplitTask> tasks;
    tasks.reserve(pieces.size());
    for (const Piece& piece : pieces) tasks.push_back({piece, false});
    for (;;) {
        while (!tasks.empty()) {
            const SplitTask task = tasks.back();
            tasks.pop_back();
            guard();
            const Piece& piece = task.piece;
            const EdgeIdx present = find_edge(piece.a, piece.b);
            if (present != kNone) {
                if (!task.encroached) {
                    mark(present, piece.segment);
                    continue;
                }
                if (locally_delaunay(present)) continue;
                // Released and flipped (it is not locally Delaunay), then split like a missing
                // piece.
                segment_of_[present] = segment_of_[mesh_.twin[present]] = kNone;
                // The other segments whose chains shared the piece recover it again themselves.
                for (const std::uint32_t s : release_shared(piece.a, piece.b)) {
                    if (s != piece.segment) tasks.push_back({{piece.a, piece.b, s}, false});
                }
                std::vector<std::pair<VertIdx, VertIdx>> edge{{piece.a, piece.b}};
                restore_delaunay(edge);
            }
            split_piece(piece, tasks);
        }
        // Safety net (normally finds nothing): every edge is checked once more; a marked one not
        // locally Delaunay is split, an unmarked one flipped.
        std::vector<std::pair<VertIdx, VertIdx>> unmarked;
        for (EdgeIdx e = 0; e < segment_of_.size(); ++e) {
            if (mesh_.is_dead(triangle_of(e))) continue;
            const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
            if (a == kInfinite || b == kInfinite || a > b || locally_delaunay(e)) continue;
            if (segment_of_[e] != kNone) {
                tasks.push_back({{a, b, segment_of_[e]}, true});
            } else {
                unmarked.emplace_back(a, b);
            }
        }
        ++result_.counters.conforming_passes;
        if (tasks.empty() && unmarked.empty()) break;
        restore_delaunay(unmarked);
    }
    conforming_ = false;
}

bool CdtBuilder::bend_candidate(std::uint32_t segment, VertIdx a, VertIdx b, VertIdx w) const {
    // The chain rule of check_constrained_delaunay_2d (within_rounding_of_segment, exact progress
    // along the input segment), so that every bend the triangulation makes is a chain the check
    // accepts: w within rounding of the input segment and strictly between a and b along it.
    if (w == kInfinite || w == a || w == b) return false;
    const double* s0 = mesh_.point(segment_ends_[segment][0]);
    const double* s1 = mesh_.point(segment_ends_[segment][1]);
    // The distance test first: it rejects nearly every vertex a piece crosses, by its filter.
    if (!predicates::within_rounding_of_segment(mesh_.point(w), s0, s1)) return false;
    const Sign from_a = predicates::direction_dot_sign(mesh_.point(a), mesh_.point(w), s0, s1);
    const Sign to_b = predicates::direction_dot_sign(mesh_.point(w), mesh_.point(b), s0, s1);
    if (from_a == Sign::Zero || from_a != to_b) return false;
    // A piece shared with other segments bends only where each of their chains may bend.
    for (const std::uint32_t other : shared_segments(a, b)) {
        if (other == segment) continue;
        const double* t0 = mesh_.point(segment_ends_[other][0]);
        const double* t1 = mesh_.point(segment_ends_[other][1]);
        const Sign o_from_a =
            predicates::direction_dot_sign(mesh_.point(a), mesh_.point(w), t0, t1);
        const Sign o_to_b = predicates::direction_dot_sign(mesh_.point(w), mesh_.point(b), t0, t1);
        if (o_from_a == Sign::Zero || o_from_a != o_to_b) return false;
        if (!predicates::within_rounding_of_segment(mesh_.point(w), t0, t1)) return false;
    }
    return true;
}

VertIdx CdtBuilder::vertex_near_segment(const Piece& piece) {
    const VertIdx a = piece.a, b = piece.b;
    const double* s0 = mesh_.point(segment_ends_[piece.segment][0]);
    const double* s1 = mesh_.point(segment_ends_[piece.segment][1]);
    // Among the vertices the piece crosses that may bend it, the first along the segment.
    VertIdx best = kNone;
    auto consider = [&](VertIdx v) {
        if (!bend_candidate(piece.segment, a, b, v)) return;
        if (best == kNone || predicates::direction_dot_sign(mesh_.point(v), mesh_.point(best), s0,
                                                            s1) == Sign::Positive)
            best = v;
    };
    // The edges the piece crosses, as insert_piece walks them; a vertex exactly on the piece
    // ends the walk (it is the answer).
    const StarExit exit = star_exit(a, b);
    if (exit.on_ray != kNone) return exit.on_ray;
    const EdgeIdx entry = exit.entry;
    if (entry == kNone) return kNone;  // not expected: the piece would be present
    consider(mesh_.origin(entry));
    consider(mesh_.destination(entry));
    for (EdgeIdx h = entry;;) {
        const EdgeIdx f = mesh_.twin[h];
        const VertIdx w = apex(f);
        if (w == b || w == kInfinite) break;
        ++result_.counters.walk_steps;
        const Sign sw = core_.orient(a, b, w);
        if (sw == Sign::Zero) return w;
        consider(w);
        h = sw == Sign::Positive ? next_edge(f) : prev_edge(f);
    }
    return best;
}

// Conforming split budget: 64 per input vertex, segment and crossing, plus 4,096. Every test
// input needs far fewer (the CGAL campaign's most is 20 per feature... see the proof note §5);
// two segments a few hundred binades long and 1e-312 apart need pieces as short as their gap
// everywhere, which no budget covers: they stop with GeometryError in well under a second.
constexpr std::uint64_t kSplitsPerFeature = 64;
constexpr std::uint64_t kSplitsBase = 4096;

void CdtBuilder::split_piece(const Piece& piece, std::vector<SplitTask>& tasks) {
    // A vertex the piece crosses within rounding of its segment (the check's chain rule,
    // bend_candidate) is where the piece bends: (6, 8) on a grid line
    // whose other end is a rounded crossing at (7 - 2^-50, 7) in grid-lines seed 5, where new
    // points would home in on it until no double is left between.
    const VertIdx near = vertex_near_segment(piece);
    if (near != kNone) {
        ++result_.counters.conforming_bends;
        tasks.push_back({{near, piece.b, piece.segment}, false});
        tasks.push_back({{piece.a, near, piece.segment}, false});
        return;
    }
    const double* pa = mesh_.point(piece.a);
    const double* pb = mesh_.point(piece.b);
    double m[2];
    // Concentric shells [Ruppert95 §4; Shewchuk97 §3.4]: a piece with an end at a corner (an
    // input vertex where two or more pieces meet) is split at the power of two nearest half its
    // length, measured from that corner, so pieces of segments meeting there at a small angle
    // end on common circles about it and stop encroaching on each other (fuzz input
    // timeout-073fed0d: two segments at 1e-312 radians, 1,686 splits instead of over 100,000).
    // When both ends are corners, the one with more pieces (tiny PSLG 8/20404630: an ulp-narrow
    // angle at (1,1)); on a tie, at an intersection vertex or a split, and where the length is
    // out of the comfortable double range, the correctly rounded midpoint, whose error is
    // smaller (segments a few ulps apart: ReleasedConstraintIsMadeDelaunayAgain).
    auto corner = [&](VertIdx v) { return v < input_count_ ? segment_degree_[v] : 0u; };
    const std::uint32_t ca = corner(piece.a) >= 2 ? corner(piece.a) : 0,
                        cb = corner(piece.b) >= 2 ? corner(piece.b) : 0;
    const int apex_end = ca == cb ? -1 : (ca > cb ? 0 : 1);  // 0: piece.a, 1: piece.b
    bool shell = false;
    if (apex_end >= 0) {
        const double* apex = apex_end == 0 ? pa : pb;
        const double* far = apex_end == 0 ? pb : pa;
        const double dx = far[0] - apex[0], dy = far[1] - apex[1];
        const double length = std::hypot(dx, dy);
        if (std::isfinite(dx) && std::isfinite(dy) && length > 0x1p-900 && length < 0x1p900) {
            const double ratio =
                std::ldexp(1.0, static_cast<int>(std::lround(std::log2(length / 2)))) / length;
            m[0] = apex[0] + dx * ratio;
            m[1] = apex[1] + dy * ratio;
            shell = true;
        }
    }
    if (!shell) {
        for (int k = 0; k < 2; ++k) {
            // Halving first is exact unless the halves are subnormal; then sum first (which
            // cannot overflow at such magnitudes).
            const bool tiny = std::fabs(pa[k]) < 0x1p-1000 || std::fabs(pb[k]) < 0x1p-1000;
            m[k] = tiny ? (pa[k] + pb[k]) * 0.5 : pa[k] * 0.5 + pb[k] * 0.5;
        }
    }
    // The chain rule (§4): the split point must lie within rounding of the input segment and
    // strictly between the piece's ends along it, exactly; a rounded midpoint of a piece far
    // across the segment's direction may not (it moved back by an ulp of a coordinate that the
    // segment's direction weighs 1e60 times more): then the piece is finer than doubles resolve.
    {
        const double* s0 = mesh_.point(segment_ends_[piece.segment][0]);
        const double* s1 = mesh_.point(segment_ends_[piece.segment][1]);
        // (A piece may run either way along its segment.)
        const Sign from_a = predicates::direction_dot_sign(pa, m, s0, s1),
                   to_b = predicates::direction_dot_sign(m, pb, s0, s1);
        if (from_a == Sign::Zero || from_a != to_b ||
            !predicates::within_rounding_of_segment(m, s0, s1)) {
            throw GeometryError(
                "conforming Delaunay: segment " + segment_name(piece.segment) +
                " has a piece whose split point falls off its way (features finer than "
                "double precision resolves)");
        }
    }
    // Walk from the end nearer the split point (a corner can have a large fan of thin
    // triangles: 60x fewer walk steps on fuzz input timeout-073fed0d than from the first end).
    const double da = std::fabs(m[0] - pa[0]) + std::fabs(m[1] - pa[1]);
    const double db = std::fabs(m[0] - pb[0]) + std::fabs(m[1] - pb[1]);
    core_.last_triangle = triangle_of(vertex_edge_[da < db ? piece.a : piece.b]);
    const VertIdx mid = add_vertex(m[0], m[1]);
    const TriIdx t = core_.walk_to(mid);
    VertIdx at = mid;
    if (!mesh_.is_infinite(t)) {
        for (unsigned k = 0; k < 3; ++k) {
            if (core_.same_point(mesh_.tv[3 * t + k], mid)) at = mesh_.tv[3 * t + k];
        }
    }
    if (at != mid) {
        remove_last_vertex();
        if (at == piece.a || at == piece.b) {
            throw GeometryError("conforming Delaunay: segment " + segment_name(piece.segment) +
                                " has a piece too short to split (adjacent doubles)");
        }
        // The split point rounds to an existing vertex: the chain may pass through it only if it
        // progresses along the segment from a to b (exactly). Else the pieces a - at, at - b
        // would lead back (PSLGs spanning 1e-225..1e212: a piece bent through one vertex had its
        // midpoint round to the vertex beyond it, and the two tasks alternated 57,000 times).
        const double* s0 = mesh_.point(segment_ends_[piece.segment][0]);
        const double* s1 = mesh_.point(segment_ends_[piece.segment][1]);
        const Sign from_a = predicates::direction_dot_sign(pa, mesh_.point(at), s0, s1);
        if (from_a == Sign::Zero ||
            from_a != predicates::direction_dot_sign(mesh_.point(at), pb, s0, s1)) {
            throw GeometryError("conforming Delaunay: segment " + segment_name(piece.segment) +
                                " has a piece whose split point rounds to a vertex off its way "
                                "(features finer than double precision resolves)");
        }
    } else {
        const Cdt2Counters& c = result_.counters;
        if (++result_.counters.conforming_splits >
            kSplitsPerFeature * (c.points + c.segments + c.intersections) + kSplitsBase) {
            throw GeometryError("conforming Delaunay: more than " +
                                std::to_string(c.conforming_splits - 1) +
                                " splits; stopped (small input angles?)");
        }
        encroached_.clear();
        insert_vertex(mid, t);
        for (const Piece& hit : encroached_) tasks.push_back({hit, true});
    }
    tasks.push_back({{at, piece.b, piece.segment}, false});
    tasks.push_back({{piece.a, at, piece.segment}, false});
}

// ---------------------------------------------------------------------------------------------

void CdtBuilder::enclose_in_box() {
    // Corners one bounding-box size beyond the bounding box of every vertex: each of the
    // triangulation's hull edges, segments included, becomes interior (Lawson insertion with
    // the infinite vertex, as Green-Sibson inserts outside the hull; constraints never flip).
    const std::uint32_t n = mesh_.vertex_count();
    double lo_x = mesh_.xy[0], hi_x = lo_x, lo_y = mesh_.xy[1], hi_y = lo_y;
    for (VertIdx v = 1; v < n; ++v) {
        lo_x = std::min(lo_x, mesh_.xy[2 * v]);
        hi_x = std::max(hi_x, mesh_.xy[2 * v]);
        lo_y = std::min(lo_y, mesh_.xy[2 * v + 1]);
        hi_y = std::max(hi_y, mesh_.xy[2 * v + 1]);
    }
    const double margin = std::max(hi_x - lo_x, hi_y - lo_y);
    const double corners[4][2] = {{lo_x - margin, lo_y - margin},
                                  {hi_x + margin, lo_y - margin},
                                  {hi_x + margin, hi_y + margin},
                                  {lo_x - margin, hi_y + margin}};
    for (const auto& corner : corners) {
        if (!std::isfinite(margin) || !std::isfinite(corner[0]) || !std::isfinite(corner[1])) {
            throw GeometryError(
                "coordinates too large to enclose the domain in a box (within a factor 3 of the "
                "largest double)");
        }
    }
    box_first_ = n;
    for (const auto& corner : corners) {
        const VertIdx p = add_vertex(corner[0], corner[1]);
        const TriIdx t = core_.walk_to(p);
        EM_ASSERT(mesh_.is_infinite(t));
        insert_vertex(p, t);
    }
}

TriIdx CdtBuilder::locate_point(double x, double y) {
    const VertIdx probe = add_vertex(x, y);
    const TriIdx t = core_.walk_to(probe);
    remove_last_vertex();
    return t;
}

template <class Mark, class Reached>
void CdtBuilder::flood(TriIdx start, std::vector<Mark>& mark_value, Mark value, Reached reached) {
    std::vector<TriIdx> stack{start};
    mark_value[start] = value;
    reached(start);
    while (!stack.empty()) {
        const TriIdx t = stack.back();
        stack.pop_back();
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            if (segment_of_[e] != kNone) continue;
            const TriIdx u = triangle_of(mesh_.twin[e]);
            if (mark_value[u] == value || mesh_.is_infinite(u)) continue;
            mark_value[u] = value;
            reached(u);
            stack.push_back(u);
        }
    }
}

void CdtBuilder::require_off_boundary(AmbiguousMarkPoint::Kind kind, std::size_t index, double x,
                                      double y, TriIdx t) {
    // The walk put the point in t, or across a hull edge of it (an infinite t): a point on a
    // segment or a vertex lies on the closure of one of t's finite edges, so three exact
    // orientations (plus the bounding box, for the hull edge's line beyond it) find it.
    const double point[2] = {x, y};
    const std::string name =
        std::string(kind == AmbiguousMarkPoint::Kind::Hole ? "hole " : "region ") +
        std::to_string(index + options_.first_index) + " at (" + format_number(x) + ", " +
        format_number(y) + ")";
    const char* consequence =
        kind == AmbiguousMarkPoint::Kind::Hole
            ? "which side is the hole is ambiguous; move the point strictly inside the hole"
            : "which side is the region is ambiguous; move the point strictly inside it";
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
        for (const VertIdx v : {a, b}) {
            if (v == kInfinite || mesh_.xy[2 * v] != x || mesh_.xy[2 * v + 1] != y) continue;
            // A vertex no segment ends at (a free vertex) has one side only: every triangle
            // around it floods to the others without crossing a constraint.
            bool on_segment_end = false;
            const EdgeIdx first = vertex_edge_[v];
            EdgeIdx around = first;
            do {
                on_segment_end = on_segment_end || segment_of_[around] != kNone;
                around = mesh_.twin[prev_edge(around)];
            } while (around != first);
            if (!on_segment_end) continue;
            const VertIdx caller = core_.input_index[v];
            const std::string vertex =
                caller < input_count_ ? "vertex " + std::to_string(caller + options_.first_index)
                                      : std::string("a vertex added where segments cross");
            throw AmbiguousMarkPoint(name + " lies on " + vertex + ": " + consequence, kind, index);
        }
        if (a == kInfinite || b == kInfinite || segment_of_[e] == kNone) continue;
        const double* pa = mesh_.point(a);
        const double* pb = mesh_.point(b);
        if (x < std::min(pa[0], pb[0]) || x > std::max(pa[0], pb[0]) ||
            y < std::min(pa[1], pb[1]) || y > std::max(pa[1], pb[1])) {
            continue;
        }
        if (predicates::orient2d(pa, pb, point) == Sign::Zero) {
            throw AmbiguousMarkPoint(name + " lies on segment " +
                                         std::to_string(segment_of_[e] + options_.first_index) +
                                         ": " + consequence,
                                     kind, index);
        }
    }
}

void CdtBuilder::remove_exterior_and_holes() {
    removed_.assign(mesh_.triangle_slots(), 0);
    const bool any_segment = std::any_of(segment_of_.begin(), segment_of_.end(),
                                         [](std::uint32_t s) { return s != kNone; });
    // Without a segment the exterior is nothing (the convex hull is kept, as Triangle keeps it),
    // except around an enclosing box, whose triangles are never the domain.
    if (options_.remove_exterior && (any_segment || enclose_in_box_)) {
        for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
            if (mesh_.is_dead(t) || !mesh_.is_infinite(t)) continue;
            for (unsigned k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * t + k;
                if (mesh_.origin(e) == kInfinite || mesh_.destination(e) == kInfinite) continue;
                const TriIdx inside = triangle_of(mesh_.twin[e]);
                if (segment_of_[e] == kNone && !removed_[inside])
                    flood(inside, removed_, std::uint8_t{1}, [](TriIdx) {});
            }
        }
    }
    const std::size_t holes = pslg_.holes.size() / 2;
    for (std::size_t h = 0; h < holes; ++h) {
        const TriIdx t = locate_point(pslg_.holes[2 * h], pslg_.holes[2 * h + 1]);
        require_off_boundary(AmbiguousMarkPoint::Kind::Hole, h, pslg_.holes[2 * h],
                             pslg_.holes[2 * h + 1], t);
        if (mesh_.is_infinite(t)) {
            result_.warnings.push_back("hole " + std::to_string(h + options_.first_index) +
                                       " lies outside the triangulation; ignored");
            continue;
        }
        if (!removed_[t]) flood(t, removed_, std::uint8_t{1}, [](TriIdx) {});
    }
}

void CdtBuilder::assign_regions() {
    const std::size_t regions = pslg_.regions.size() / 4;
    if (regions == 0) return;
    attribute_.assign(mesh_.triangle_slots(), 0.0);
    // One stamp per region (region number + 1): each flood costs its own triangles only.
    std::vector<std::uint32_t> seen(mesh_.triangle_slots(), 0);
    for (std::size_t r = 0; r < regions; ++r) {
        const TriIdx t = locate_point(pslg_.regions[4 * r], pslg_.regions[4 * r + 1]);
        require_off_boundary(AmbiguousMarkPoint::Kind::Region, r, pslg_.regions[4 * r],
                             pslg_.regions[4 * r + 1], t);
        if (mesh_.is_infinite(t) || removed_[t]) {
            result_.warnings.push_back("region " + std::to_string(r + options_.first_index) +
                                       " lies outside the domain; ignored");
            continue;
        }
        const double attribute = pslg_.regions[4 * r + 2];
        flood(t, seen, static_cast<std::uint32_t>(r + 1),
              [&](TriIdx u) { attribute_[u] = attribute; });
    }
}

void CdtBuilder::collect_output() {
    // In place, as Delaunay2Core::take_result does: fresh output arrays would cost a page fault
    // per 4 KiB, a third of the whole construction time at 10^6 points (perf, this machine).
    const std::uint32_t slots = mesh_.triangle_slots();
    const std::uint32_t vertices = mesh_.vertex_count();
    // Caller numbering: inputs as given (duplicates reported as the smallest equal index),
    // added vertices after the inputs in creation order (their input_index already).
    result_.merged_into.resize(input_count_);
    for (VertIdx i = 0; i < input_count_; ++i) result_.merged_into[i] = i;
    for (VertIdx i = 0; i < input_count_; ++i) {
        const VertIdx kept = core_.merged_into[i];
        result_.merged_into[kept] = std::min(result_.merged_into[kept], i);
    }
    for (VertIdx i = 0; i < input_count_; ++i)
        result_.merged_into[i] = result_.merged_into[core_.merged_into[i]];
    std::vector<VertIdx>& caller = core_.input_index;  // reused: mesh vertex -> output vertex
    for (VertIdx v = 0; v < vertices; ++v) {
        if (caller[v] < input_count_) caller[v] = result_.merged_into[caller[v]];
    }
    // The enclosing box's corners (all in removed triangles) are not output; the vertices added
    // after them close the gap.
    std::uint32_t output_vertices = vertices;
    if (box_first_ != kNone) {
        for (VertIdx v = box_first_; v < vertices; ++v)
            caller[v] = v < box_first_ + 4 ? kNone : v - 4;
        output_vertices -= 4;
    }
    Triangulation2& out = result_.mesh;
    out.xy.reserve(2 * std::size_t{output_vertices});
    out.xy.assign(pslg_.xy.begin(), pslg_.xy.end());
    out.xy.resize(2 * std::size_t{output_vertices});
    for (VertIdx v = input_count_; v < vertices; ++v) {
        if (caller[v] == kNone) continue;
        out.xy[2 * std::size_t{caller[v]}] = mesh_.xy[2 * std::size_t{v}];
        out.xy[2 * std::size_t{caller[v]} + 1] = mesh_.xy[2 * std::size_t{v} + 1];
    }
    mesh_.xy = {};
    // Pieces: every constrained edge once, including those inside removed regions.
    for (TriIdx t = 0; t < slots; ++t) {
        if (mesh_.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            if (segment_of_[e] == kNone) continue;
            const VertIdx p = caller[mesh_.origin(e)], q = caller[mesh_.destination(e)];
            if (p < q) {
                result_.pieces.insert(result_.pieces.end(), {p, q});
                result_.piece_segment.push_back(segment_of_[e]);
            }
        }
    }
    std::vector<TriIdx> index(slots, kNone);
    TriIdx count = 0;
    for (TriIdx t = 0; t < slots; ++t) {
        if (mesh_.is_dead(t) || mesh_.is_infinite(t)) continue;
        if (removed_[t]) {
            ++result_.counters.removed_triangles;
            continue;
        }
        index[t] = count++;
    }
    if (!attribute_.empty()) result_.triangle_attributes.resize(count);
    out.constrained.resize(3 * std::size_t{count});
    // Compaction: triangle t moves to index[t] <= t, so nothing unread is overwritten.
    for (TriIdx t = 0; t < slots; ++t) {
        const TriIdx o = index[t];
        if (o == kNone) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = mesh_.tv[3 * t + k];
            const EdgeIdx across = mesh_.twin[3 * t + k];
            out.constrained[3 * o + k] = segment_of_[3 * t + k] != kNone ? 1 : 0;
            mesh_.tv[3 * o + k] = caller[v];
            mesh_.twin[3 * o + k] = index[triangle_of(across)];
        }
        if (!attribute_.empty()) result_.triangle_attributes[o] = attribute_[t];
    }
    mesh_.tv.resize(3 * std::size_t{count});
    mesh_.twin.resize(3 * std::size_t{count});
    out.triangles = std::move(mesh_.tv);
    out.neighbors = std::move(mesh_.twin);
}

void CdtBuilder::collinear_output() {
    // No triangle: every distinct point lies on one line. Pieces: each segment split at the
    // vertices strictly inside it, found by sorting the distinct points along the line.
    Delaunay2Result points = core_.collinear_result();
    result_.merged_into = std::move(points.merged_into);
    result_.mesh.xy.assign(pslg_.xy.begin(), pslg_.xy.end());
    std::vector<VertIdx> order;
    for (VertIdx i = 0; i < input_count_; ++i) {
        if (result_.merged_into[i] == i) order.push_back(i);
    }
    const double* xy = pslg_.xy.data();
    std::sort(order.begin(), order.end(), [xy](VertIdx p, VertIdx q) {
        return xy[2 * p] < xy[2 * q] || (xy[2 * p] == xy[2 * q] && xy[2 * p + 1] < xy[2 * q + 1]);
    });
    std::vector<std::uint32_t> rank(input_count_);
    for (std::uint32_t r = 0; r < order.size(); ++r) rank[order[r]] = r;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (std::size_t s = 0; s < pslg_.segments.size() / 2; ++s) {
        std::uint32_t i = rank[result_.merged_into[pslg_.segments[2 * s]]];
        std::uint32_t j = rank[result_.merged_into[pslg_.segments[2 * s + 1]]];
        if (i == j) {
            ++result_.counters.dropped_segments;
            result_.warnings.push_back("segment " + segment_name(static_cast<std::uint32_t>(s)) +
                                       " has zero length; ignored");
            continue;
        }
        if (i > j) std::swap(i, j);
        for (std::uint32_t r = i; r < j; ++r)
            keyed.emplace_back((std::uint64_t{r} << 32) | (r + 1), s);
        if (j > i + 1) ++result_.counters.vertices_on_segments;
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        if (k > 0 && keyed[k - 1].first == keyed[k].first) continue;
        result_.pieces.push_back(order[keyed[k].first >> 32]);
        result_.pieces.push_back(order[keyed[k].first & 0xFFFFFFFFu]);
        result_.piece_segment.push_back(keyed[k].second);
    }
    result_.counters.points = input_count_;
    result_.counters.duplicates = points.counters.duplicates;
}

bool CdtBuilder::build() {
    input_count_ = mesh_.vertex_count();
    Cdt2Counters& c = result_.counters;
    c.points = input_count_;
    c.segments = pslg_.segments.size() / 2;
    result_.input_vertex_count = input_count_;
    vertex_edge_.assign(input_count_, kNone);
    // The Delaunay triangulation first (no constraint yet: plain Green-Sibson, which keeps
    // no per-edge state), then the constraint and vertex maps in one pass.
    if (!detail::green_sibson_insert_all(core_)) {
        collinear_ = true;
        return false;
    }
    segment_of_.reserve(mesh_.tv.capacity());
    segment_of_.assign(mesh_.tv.size(), kNone);
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (mesh_.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = mesh_.tv[3 * t + k];
            if (v != kInfinite) vertex_edge_[v] = 3 * t + k;
        }
    }
    prepare_segments();
    while (!work_.empty()) {
        const Piece piece = work_.back();
        work_.pop_back();
        insert_piece(piece);
    }
    if (options_.recovery == SegmentRecovery::Conforming) conform();
    if (enclose_in_box_) {
        bend_through_near_vertices();
        enclose_in_box();
    }
    remove_exterior_and_holes();
    assign_regions();
    domain_marked_ = true;
    return true;
}

Cdt2Result CdtBuilder::finish() {
    if (collinear_) {
        collinear_output();
        return std::move(result_);
    }
    Cdt2Counters& c = result_.counters;
    c.duplicates = core_.counters.duplicates;
    c.orient_calls = core_.counters.orient_calls;
    c.incircle_calls = core_.counters.incircle_calls;
    c.delaunay_flips += core_.counters.flips;
    c.walk_steps += core_.counters.walk_steps;
    collect_output();
    return std::move(result_);
}

}  // namespace detail

void validate_pslg(const Pslg& pslg) {
    validate_points_2d(pslg.xy);
    const std::size_t n = pslg.xy.size() / 2;
    if (pslg.segments.size() % 2 != 0) throw InputError("segments: odd number of endpoint indices");
    for (std::size_t i = 0; i < pslg.segments.size(); ++i) {
        if (pslg.segments[i] >= n) {
            throw InputError("segment " + std::to_string(i / 2) + ": vertex " +
                             std::to_string(pslg.segments[i]) + " does not exist (" +
                             std::to_string(n) + " vertices)");
        }
    }
    if (pslg.holes.size() % 2 != 0) throw InputError("holes: odd number of coordinates");
    if (pslg.regions.size() % 4 != 0) throw InputError("regions: expected 4 numbers per region");
    require_finite_items(pslg.holes, 2, "hole");
    require_finite_items(pslg.regions, 4, "region");
}

Cdt2Result constrained_delaunay_2d(const Pslg& pslg, const Cdt2Options& options) {
    validate_pslg(pslg);
    detail::CdtBuilder builder(pslg, options);
    builder.build();
    return builder.finish();
}

}  // namespace exactmesh::triangulation
