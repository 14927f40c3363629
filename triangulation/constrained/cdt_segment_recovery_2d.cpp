// SPDX-License-Identifier: MIT
// The constrained Delaunay builder's segment recovery (cdt_phases_2d.hpp): segments as stacks
// of pieces, the walk along a piece, splits at crossings and at vertices on a segment, and the
// two ways of removing the crossed edges, swaps [Sloan93] and cavity retriangulation [Anglada97].
//
// A segment is processed as a stack of pieces (a, b, segment). A piece whose walk meets a
// vertex on it, or a constrained edge across it, is split there and its parts pushed back;
// otherwise the crossed edges are removed by the chosen recovery. Local indices in the walk:
// crossed half-edge h runs from x (right of a->b) to y (left of a->b).
#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/constructions.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

namespace {

bool on_ray(const CdtState& cdt, VertIdx a, VertIdx b, VertIdx x) {
    // a, b, x collinear: is x on the side of a where b is? Exact coordinate comparisons along
    // a coordinate in which a and b differ.
    const double* pa = cdt.mesh.point(a);
    const double* pb = cdt.mesh.point(b);
    const double* px = cdt.mesh.point(x);
    const int k = pa[0] != pb[0] ? 0 : 1;
    return pb[k] > pa[k] ? px[k] > pa[k] : px[k] < pa[k];
}

}  // namespace

void guard(CdtState& cdt) {
    // Every legitimate step is paid for by an input segment, a vertex or a split; a run that
    // exceeds this budget is looping on rounded intersections: report instead of hanging.
    const Cdt2Counters& c = cdt.result.counters;
    const std::uint64_t budget = 64 * (c.segments + c.points + c.intersections +
                                       c.vertices_on_segments + c.conforming_splits) +
                                 100000;
    if (++cdt.work_done > budget) {
        throw GeometryError("constrained_delaunay_2d: segment recovery did not converge after " +
                            std::to_string(cdt.work_done) + " steps (please report the input)");
    }
}

StarExit star_exit(CdtState& cdt, VertIdx a, VertIdx b) {
    StarExit exit;
    const EdgeIdx first = cdt.vertex_edge[a];
    EdgeIdx e = first;
    do {
        const VertIdx x = cdt.mesh.destination(e), y = cdt.apex(e);
        if (x == b) {
            exit.edge = e;
            return exit;
        }
        if (x != kInfinite) {
            // Every neighbour x is tested, also when a -> x borders the infinite vertex (a
            // segment along the hull through a hull vertex).
            const Sign sx = cdt.core.orient(a, b, x);
            if (sx == Sign::Zero && on_ray(cdt, a, b, x)) {
                exit.on_ray = x;
                return exit;
            }
            if (y != kInfinite && sx == Sign::Negative && exit.entry == kNone &&
                cdt.core.orient(a, b, y) == Sign::Positive) {
                exit.entry = next_edge(e);
            }
        }
        e = cdt.mesh.twin[prev_edge(e)];
    } while (e != first);
    return exit;
}

namespace {

/// The piece passes exactly through vertex v: recover its two parts instead (a warning).
void split_piece_at_vertex(CdtState& cdt, const Piece& piece, VertIdx v) {
    ++cdt.result.counters.vertices_on_segments;
    cdt.result.warnings.push_back("segment " + cdt.segment_name(piece.segment) +
                                  " passes through " + cdt.vertex_name(v) + "; split there");
    cdt.work.push_back({v, piece.b, piece.segment});
    cdt.work.push_back({piece.a, v, piece.segment});
}

/// The constrained edge u - v (of segment `other` and the segments `also` sharing it), released,
/// made locally Delaunay again, and its two parts through w queued for every one of them.
void release_and_split(CdtState& cdt, VertIdx u, VertIdx v, VertIdx w, std::uint32_t other,
                       const std::vector<std::uint32_t>& also) {
    std::vector<std::pair<VertIdx, VertIdx>> released{{u, v}};
    restore_delaunay(cdt, released);
    for (const std::uint32_t s : also) {
        cdt.work.push_back({u, w, s});
        cdt.work.push_back({w, v, s});
    }
    cdt.work.push_back({u, w, other});
    cdt.work.push_back({w, v, other});
}

void split_at_intersection(CdtState& cdt, const Piece& piece, EdgeIdx h);

void insert_piece(CdtState& cdt, const Piece& piece, RecoverCrossed recover) {
    const VertIdx a = piece.a, b = piece.b;
    if (a == b) return;
    guard(cdt);
    const StarExit exit = star_exit(cdt, a, b);
    if (exit.edge != kNone) {
        cdt.mark(exit.edge, piece.segment);
        return;
    }
    if (exit.on_ray != kNone) {
        split_piece_at_vertex(cdt, piece, exit.on_ray);
        return;
    }
    const EdgeIdx entry = exit.entry;
    EM_ASSERT(entry != kNone);
    // Walk to b through the crossed edges.
    std::vector<EdgeIdx> crossed;
    EdgeIdx h = entry;
    for (;;) {
        if (cdt.segment_of[h] != kNone) {
            split_at_intersection(cdt, piece, h);
            return;
        }
        crossed.push_back(h);
        const EdgeIdx f = cdt.mesh.twin[h];
        const VertIdx w = cdt.apex(f);
        if (w == b) break;
        EM_ASSERT(w != kInfinite);
        const Sign sw = cdt.core.orient(a, b, w);
        ++cdt.result.counters.walk_steps;
        if (sw == Sign::Zero) {
            split_piece_at_vertex(cdt, piece, w);
            return;
        }
        h = sw == Sign::Positive ? next_edge(f) : prev_edge(f);
    }
    cdt.result.counters.crossed_edges += crossed.size();
    recover(cdt, piece, crossed);
}

/// p lies in the closed axis-parallel box of a and b (exact comparisons).
bool in_box(const double* p, const double* a, const double* b) {
    for (int k = 0; k < 2; ++k) {
        if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k])) return false;
    }
    return true;
}

std::array<double, 2> crossing_point(CdtState& cdt, const Piece& piece, VertIdx u, VertIdx v,
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
    const double* a = cdt.mesh.point(piece.a);
    const double* b = cdt.mesh.point(piece.b);
    const double* pu = cdt.mesh.point(u);
    const double* pv = cdt.mesh.point(v);
    const double* s0 = cdt.mesh.point(cdt.segment_ends[piece.segment][0]);
    const double* s1 = cdt.mesh.point(cdt.segment_ends[piece.segment][1]);
    const double* t0 = cdt.mesh.point(cdt.segment_ends[other][0]);
    const double* t1 = cdt.mesh.point(cdt.segment_ends[other][1]);
    const Sign o0 = predicates::orient2d(t0, t1, s0), o1 = predicates::orient2d(t0, t1, s1);
    const Sign o2 = predicates::orient2d(s0, s1, t0), o3 = predicates::orient2d(s0, s1, t1);
    const bool meet = !(o0 == Sign::Zero && o1 == Sign::Zero) && (o0 != o1 || o0 == Sign::Zero) &&
                      (o2 != o3 || o2 == Sign::Zero);
    if (meet) {
        const auto x = predicates::segment_intersection(s0, s1, t0, t1);
        if (in_box(x.data(), a, b) && in_box(x.data(), pu, pv)) return x;
    }
    ++cdt.result.counters.bent_crossings;
    return predicates::segment_intersection(a, b, pu, pv);
}

void split_at_intersection(CdtState& cdt, const Piece& piece, EdgeIdx h) {
    const VertIdx a = piece.a, b = piece.b;
    const VertIdx u = cdt.mesh.origin(h), v = cdt.mesh.destination(h);
    const std::uint32_t other = cdt.segment_of[h];
    const std::array<double, 2> p = crossing_point(cdt, piece, u, v, other);
    // The crossing rounded a few ulps from an end w of one piece that lies within rounding of the
    // other's segment (a T-junction whose end was rounded off the segment it ends on): the other
    // bends through w instead, as bend_through_near_vertices bends a piece through a near apex.
    // Inserted, the crossing would leave a piece a few ulps long between it and w, a feature no
    // refinement can split (every generator refused such inputs). Ulps of each coordinate, not
    // the chain rule's 2^-40 of |w|: a feature 1e-61 wide beside y = 4e-5 is resolvable near
    // x = 0 and keeps its crossing.
    const auto near = [&](VertIdx w) {
        const double* q = cdt.mesh.point(w);
        if (q[0] == p[0] && q[1] == p[1]) return false;  // the same point: both split there
        for (int k = 0; k < 2; ++k) {
            const double m = std::max(std::fabs(q[k]), std::fabs(p[k]));
            if (!(std::fabs(q[k] - p[k]) <= 4 * (std::nextafter(m, INFINITY) - m))) return false;
        }
        return true;
    };
    const auto note_bend = [&](VertIdx w, std::uint32_t segment) {
        ++cdt.result.counters.vertices_on_segments;
        cdt.result.warnings.push_back(cdt.vertex_name(w) + " lies within rounding of segment " +
                                      cdt.segment_name(segment) + "; the segment bends through it");
    };
    for (const VertIdx w : {a, b}) {
        if (!near(w) || !bend_candidate(cdt, other, u, v, w)) continue;
        cdt.segment_of[h] = cdt.segment_of[cdt.mesh.twin[h]] = kNone;
        note_bend(w, other);
        release_and_split(cdt, u, v, w, other, cdt.release_shared(u, v));
        cdt.work.push_back({a, b, piece.segment});
        return;
    }
    for (const VertIdx w : {u, v}) {
        if (!near(w) || !bend_candidate(cdt, piece.segment, a, b, w)) continue;
        note_bend(w, piece.segment);
        cdt.work.push_back({w, b, piece.segment});
        cdt.work.push_back({a, w, piece.segment});
        return;
    }
    // The rounded point may equal a vertex (then both segments bend through it).
    const VertIdx candidate = cdt.add_vertex(p[0], p[1]);
    cdt.core.last_triangle = triangle_of(h);
    const TriIdx t = cdt.core.walk_to(candidate);
    VertIdx at = candidate;
    if (!cdt.mesh.is_infinite(t)) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx w = cdt.mesh.tv[3 * t + k];
            if (cdt.core.same_point(w, candidate)) at = w;
        }
    }
    cdt.segment_of[h] = cdt.segment_of[cdt.mesh.twin[h]] = kNone;
    const std::vector<std::uint32_t> also = cdt.release_shared(u, v);
    if (at != candidate) {
        cdt.remove_last_vertex();
        ++cdt.result.counters.vertices_on_segments;
        cdt.result.warnings.push_back("segments " + cdt.segment_name(piece.segment) + " and " +
                                      cdt.segment_name(other) + " cross at " + cdt.vertex_name(at) +
                                      "; both split there");
    } else {
        const std::uint64_t segments = cdt.result.counters.segments;
        if (++cdt.result.counters.intersections > segments * (segments + 1) / 2 + 1000) {
            throw GeometryError(
                "constrained_delaunay_2d: more segment intersections than pairs of "
                "segments; recovery is looping (please report the input)");
        }
        insert_vertex(cdt, candidate, t);
        cdt.result.warnings.push_back(
            "segments " + cdt.segment_name(piece.segment) + " and " + cdt.segment_name(other) +
            " cross; split at new vertex " +
            std::to_string(cdt.core.input_index[candidate] + cdt.options.first_index) + " (" +
            format_number(p[0]) + ", " + format_number(p[1]) + ")");
    }
    // u - v, no longer constrained, may not be locally Delaunay (the new vertex need not be
    // next to it): restore before recovering the four pieces.
    release_and_split(cdt, u, v, at, other, also);
    cdt.work.push_back({at, b, piece.segment});
    cdt.work.push_back({a, at, piece.segment});
}

}  // namespace

void recover_by_swaps(CdtState& cdt, const Piece& piece, const std::vector<EdgeIdx>& crossed) {
    const VertIdx a = piece.a, b = piece.b;
    std::deque<std::pair<VertIdx, VertIdx>> pending;
    for (const EdgeIdx h : crossed)
        pending.emplace_back(cdt.mesh.origin(h), cdt.mesh.destination(h));
    std::vector<std::pair<VertIdx, VertIdx>> created;
    std::uint64_t stalled = 0;
    while (!pending.empty()) {
        const auto [u, v] = pending.front();
        pending.pop_front();
        const EdgeIdx e = cdt.find_edge(u, v);
        EM_ASSERT(e != kNone);
        const VertIdx x = cdt.apex(e), y = cdt.apex(cdt.mesh.twin[e]);
        // Strictly convex quadrilateral: the other diagonal x - y crosses u - v.
        const Sign su = cdt.core.orient(x, y, u), sv = cdt.core.orient(x, y, v);
        if (su == Sign::Zero || sv == Sign::Zero || su == sv) {
            pending.emplace_back(u, v);
            // Sloan's lemma: among the crossed edges one is always flippable.
            EM_ASSERT(++stalled <= pending.size() + 1);
            continue;
        }
        stalled = 0;
        flip(cdt, e);
        ++cdt.result.counters.recovery_flips;
        const Sign sx = x == a || x == b ? Sign::Zero : cdt.core.orient(a, b, x);
        const Sign sy = y == a || y == b ? Sign::Zero : cdt.core.orient(a, b, y);
        if (sx != Sign::Zero && sy != Sign::Zero && sx != sy) {
            pending.emplace_back(x, y);
        } else {
            created.emplace_back(x, y);
        }
    }
    const EdgeIdx ab = cdt.find_edge(a, b);
    EM_ASSERT(ab != kNone);
    cdt.mark(ab, piece.segment);
    restore_delaunay(cdt, created);
}

namespace {

void triangulate_pseudo_polygon(CdtState& cdt, VertIdx u, VertIdx v, std::span<const VertIdx> chain,
                                std::vector<std::array<VertIdx, 3>>& out) {
    // Polygon u, v, chain[0], ..., chain[k-1], left of u -> v. The apex whose circle through
    // u and v holds no other chain vertex: one pass suffices, since every circle through u, v
    // met later has a smaller cap on this side of the line.
    if (chain.empty()) return;
    std::size_t best = 0;
    for (std::size_t i = 1; i < chain.size(); ++i) {
        if (cdt.core.incircle(u, v, chain[best], chain[i]) == Sign::Positive) best = i;
    }
    const VertIdx c = chain[best];
    out.push_back({u, v, c});
    triangulate_pseudo_polygon(cdt, c, v, chain.subspan(0, best), out);
    triangulate_pseudo_polygon(cdt, u, c, chain.subspan(best + 1), out);
}

}  // namespace

void recover_by_cavity(CdtState& cdt, const Piece& piece, const std::vector<EdgeIdx>& crossed) {
    const VertIdx a = piece.a, b = piece.b;
    // The crossed triangles, the chains left (upper) and right (lower) of a -> b, and the
    // cavity's boundary half-edges seen from outside, keyed by their (origin, destination).
    std::vector<TriIdx> cavity;
    cavity.push_back(triangle_of(crossed.front()));
    for (const EdgeIdx h : crossed) cavity.push_back(triangle_of(cdt.mesh.twin[h]));
    std::vector<VertIdx> upper, lower;  // from a's side to b's side
    for (const EdgeIdx h : crossed) {
        const VertIdx x = cdt.mesh.origin(h), y = cdt.mesh.destination(h);
        if (lower.empty() || lower.back() != x) lower.push_back(x);
        if (upper.empty() || upper.back() != y) upper.push_back(y);
    }
    std::unordered_map<std::uint64_t, std::pair<EdgeIdx, std::uint32_t>> boundary;
    auto key = [](VertIdx p, VertIdx q) { return (std::uint64_t{p} << 32) | q; };
    if (cdt.in_cavity.size() < cdt.mesh.triangle_slots())
        cdt.in_cavity.resize(cdt.mesh.triangle_slots(), 0);
    for (const TriIdx t : cavity) cdt.in_cavity[t] = 1;
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
            if (cdt.in_cavity[triangle_of(cdt.mesh.twin[g])]) {
                const VertIdx p = cdt.mesh.origin(g), q = cdt.mesh.destination(g);
                if (cdt.segment_of[g] != kNone)
                    dangling[key(std::min(p, q), std::max(p, q))] = cdt.segment_of[g];
                continue;
            }
            boundary[key(cdt.mesh.origin(g), cdt.mesh.destination(g))] = {cdt.mesh.twin[g],
                                                                          cdt.segment_of[g]};
        }
    }
    for (const TriIdx t : cavity) cdt.in_cavity[t] = 0;
    cdt.result.counters.cavity_triangles += cavity.size();
    std::vector<std::array<VertIdx, 3>> triangles;
    std::vector<VertIdx> chain(upper.rbegin(), upper.rend());  // left of a -> b, from b back to a
    triangulate_pseudo_polygon(cdt, a, b, chain, triangles);
    chain.assign(lower.begin(), lower.end());  // left of b -> a, from a back to b
    triangulate_pseudo_polygon(cdt, b, a, chain, triangles);
    EM_ASSERT(triangles.size() == cavity.size());
    for (const TriIdx t : cavity) cdt.mesh.kill_triangle(t);
    std::unordered_map<std::uint64_t, EdgeIdx> open;  // new half-edges awaiting their twin
    for (const auto& tri : triangles) {
        const TriIdx t = cdt.new_triangle();
        cdt.set(t, tri[0], tri[1], tri[2]);
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx p = tri[k], q = tri[(k + 1) % 3];
            const EdgeIdx e = 3 * t + k;
            const auto outer = boundary.find(key(p, q));
            if (outer != boundary.end()) {
                cdt.link_outer(e, outer->second.first, outer->second.second);
                continue;
            }
            const auto twin = open.find(key(q, p));
            if (twin != open.end()) {
                const auto kept = dangling.find(key(std::min(p, q), std::max(p, q)));
                if (kept != dangling.end()) {
                    cdt.link_inner(e, twin->second, kept->second);
                    dangling.erase(kept);
                } else {
                    cdt.link_inner(e, twin->second);
                }
                open.erase(twin);
            } else {
                open.emplace(key(p, q), e);
            }
        }
    }
    EM_ASSERT(open.empty());
    EM_ASSERT(dangling.empty());  // every constrained edge inside the cavity is an edge again
    cdt.mark(cdt.find_edge(a, b), piece.segment);
}

namespace {

void prepare_segments(CdtState& cdt) {
    const std::size_t count = cdt.pslg.segments.size() / 2;
    const std::uint32_t n = cdt.input_count;
    cdt.segment_ends.assign(count, {kNone, kNone});
    cdt.segment_line.assign(count, {kNone, kNone});
    if (!cdt.pslg.segment_lines.empty() && cdt.pslg.segment_lines.size() != 2 * count)
        throw InputError("constrained_delaunay_2d: segment_lines holds " +
                         std::to_string(cdt.pslg.segment_lines.size()) + " indices for " +
                         std::to_string(count) + " segments");
    // Caller index -> mesh vertex, through duplicate merging.
    std::vector<VertIdx> mesh_of(n);
    for (VertIdx v = 0; v < n; ++v) mesh_of[cdt.core.input_index[v]] = v;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    keyed.reserve(count);
    for (std::size_t s = 0; s < count; ++s) {
        const VertIdx i = cdt.pslg.segments[2 * s], j = cdt.pslg.segments[2 * s + 1];
        const VertIdx a = mesh_of[cdt.core.merged_into[i]], b = mesh_of[cdt.core.merged_into[j]];
        if (a == b) {
            ++cdt.result.counters.dropped_segments;
            cdt.result.warnings.push_back(
                "segment " + cdt.segment_name(static_cast<std::uint32_t>(s)) +
                " has zero length (vertices " + std::to_string(i + cdt.options.first_index) +
                " and " + std::to_string(j + cdt.options.first_index) + "); ignored");
            continue;
        }
        keyed.emplace_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b),
                           static_cast<std::uint32_t>(s));
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        const std::uint32_t s = keyed[k].second;
        if (k > 0 && keyed[k - 1].first == keyed[k].first) {
            ++cdt.result.counters.dropped_segments;
            cdt.result.warnings.push_back("segment " + cdt.segment_name(s) + " repeats segment " +
                                          cdt.segment_name(keyed[k - 1].second) + "; ignored");
            continue;
        }
        const VertIdx i = cdt.pslg.segments[2 * s], j = cdt.pslg.segments[2 * s + 1];
        cdt.work.push_back({mesh_of[cdt.core.merged_into[i]], mesh_of[cdt.core.merged_into[j]], s});
        cdt.segment_ends[s] = {cdt.work.back().a, cdt.work.back().b};
        cdt.segment_line[s] = cdt.segment_ends[s];
        if (!cdt.pslg.segment_lines.empty()) {
            const VertIdx p = cdt.pslg.segment_lines[2 * s], q = cdt.pslg.segment_lines[2 * s + 1];
            if (p >= n || q >= n)
                throw InputError(
                    "constrained_delaunay_2d: segment_lines names a vertex that "
                    "does not exist");
            cdt.segment_line[s] = {mesh_of[cdt.core.merged_into[p]],
                                   mesh_of[cdt.core.merged_into[q]]};
        }
    }
    // Process in input order (the work list is a stack).
    std::sort(cdt.work.begin(), cdt.work.end(),
              [](const Piece& p, const Piece& q) { return p.segment > q.segment; });
}

}  // namespace

void recover_segments(CdtState& cdt, RecoverCrossed recover) {
    prepare_segments(cdt);
    while (!cdt.work.empty()) {
        const Piece piece = cdt.work.back();
        cdt.work.pop_back();
        insert_piece(cdt, piece, recover);
    }
}

}  // namespace exactmesh::triangulation::detail
