// SPDX-License-Identifier: MIT
// The constrained Delaunay builder's conforming recovery (cdt_phases_2d.hpp): missing or
// encroached pieces split on concentric shells or at midpoints until the plain Delaunay
// triangulation holds every piece; and the bends of a piece through a vertex within rounding of
// its segment (the check's chain rule), which the conforming splits and ConstrainedTriangulation2
// share.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

bool bend_candidate(const CdtState& cdt, std::uint32_t segment, VertIdx a, VertIdx b, VertIdx w) {
    // The chain rule of check_constrained_delaunay_2d (within_rounding_of_segment, exact progress
    // along the input segment), so that every bend the triangulation makes is a chain the check
    // accepts: w within rounding of the input segment and strictly between a and b along it.
    if (w == kInfinite || w == a || w == b) return false;
    const double* s0 = cdt.mesh.point(cdt.segment_line[segment][0]);
    const double* s1 = cdt.mesh.point(cdt.segment_line[segment][1]);
    // The distance test first: it rejects nearly every vertex a piece crosses, by its filter.
    if (!predicates::within_rounding_of_segment(cdt.mesh.point(w), s0, s1)) return false;
    const Sign from_a =
        predicates::direction_dot_sign(cdt.mesh.point(a), cdt.mesh.point(w), s0, s1);
    const Sign to_b = predicates::direction_dot_sign(cdt.mesh.point(w), cdt.mesh.point(b), s0, s1);
    if (from_a == Sign::Zero || from_a != to_b) return false;
    // A piece shared with other segments bends only where each of their chains may bend.
    for (const std::uint32_t other : cdt.shared_segments(a, b)) {
        if (other == segment) continue;
        const double* t0 = cdt.mesh.point(cdt.segment_line[other][0]);
        const double* t1 = cdt.mesh.point(cdt.segment_line[other][1]);
        const Sign o_from_a =
            predicates::direction_dot_sign(cdt.mesh.point(a), cdt.mesh.point(w), t0, t1);
        const Sign o_to_b =
            predicates::direction_dot_sign(cdt.mesh.point(w), cdt.mesh.point(b), t0, t1);
        if (o_from_a == Sign::Zero || o_from_a != o_to_b) return false;
        if (!predicates::within_rounding_of_segment(cdt.mesh.point(w), t0, t1)) return false;
    }
    return true;
}

namespace {

/// A conforming piece to check (present: mark it) or, when encroached, to split.
struct SplitTask {
    Piece piece;
    bool encroached;
};

/// The pieces to check or split: depth first (last in, first out, which keeps the work near
/// the last insertion), within bands of kBandBinades binades of piece size, the band of the
/// largest pieces first. Plain depth-first order split one segment's cascade all the way down
/// before another's: a fuzz PSLG whose segments along the x and y axes both grade from 1e188
/// to 1e-307 around the origin inserted 1,550 points down the y axis, each below every earlier
/// one, and each flipped the whole fan of x-axis points beneath it (622,623 flips for 3,151
/// splits). With bands, every segment's cascade descends one band at a time, and a fan holds
/// at most a band's points. Largest first without bands (a heap) did as well there, but made
/// the conforming benchmark twice as slow (its work scattered over the mesh).
class SplitQueue {
  public:
    explicit SplitQueue(const CdtState& cdt) : cdt_(cdt) {}
    void push(const SplitTask& task) {
        const double* p = cdt_.mesh.point(task.piece.a);
        const double* q = cdt_.mesh.point(task.piece.b);
        // The larger coordinate difference's binade: an overflow to infinity lands in the top
        // band. The order never affects the result's validity, only the work.
        const double size = std::max(std::fabs(q[0] - p[0]), std::fabs(q[1] - p[1]));
        const int exponent = std::isfinite(size) ? std::ilogb(size) : kMaxExponent;
        const auto band = static_cast<std::size_t>(
                              std::clamp(exponent, kMinExponent, kMaxExponent) - kMinExponent) /
                          kBandBinades;
        if (bands_.size() <= band) bands_.resize(band + 1);
        bands_[band].push_back(task);
        top_ = std::max(top_, band);
        ++count_;
    }
    bool empty() const { return count_ == 0; }
    SplitTask pop() {
        while (bands_[top_].empty()) --top_;
        const SplitTask task = bands_[top_].back();
        bands_[top_].pop_back();
        --count_;
        return task;
    }

  private:
    static constexpr int kMinExponent = -1074, kMaxExponent = 1024, kBandBinades = 16;
    const CdtState& cdt_;
    std::vector<std::vector<SplitTask>> bands_;
    std::size_t top_ = 0, count_ = 0;
};

/// The conforming phase's own state, beside the builder's.
struct Conforming {
    std::vector<std::uint32_t> segment_degree;  // pieces at each vertex older than the phase
    std::vector<Piece> encroached;              // marked pieces the last insertion encroached
};

/// What vertex_near_segment found: a vertex where the piece bends (or kNone), and whether a
/// vertex lies exactly on the piece without being one its segment's chain may pass through.
struct NearVertex {
    VertIdx bend = kNone;
    bool blocked = false;
};

/// A vertex that may bend a missing piece (bend_candidate) and that the piece crosses or
/// passes exactly through, the first along the segment; blocked when a vertex lies exactly on
/// the piece but off its input segment by more than rounding (then no edge can carry the
/// piece, and its split point must leave the line a - b: split_piece).
NearVertex vertex_near_segment(CdtState& cdt, const Piece& piece) {
    const VertIdx a = piece.a, b = piece.b;
    const double* s0 = cdt.mesh.point(cdt.segment_ends[piece.segment][0]);
    const double* s1 = cdt.mesh.point(cdt.segment_ends[piece.segment][1]);
    // Among the vertices the piece crosses that may bend it, the first along the segment.
    VertIdx best = kNone;
    auto consider = [&](VertIdx v) {
        if (!bend_candidate(cdt, piece.segment, a, b, v)) return;
        if (best == kNone || predicates::direction_dot_sign(cdt.mesh.point(v), cdt.mesh.point(best),
                                                            s0, s1) == Sign::Positive)
            best = v;
    };
    // The edges the piece crosses, as insert_piece walks them; a vertex exactly on the piece
    // ends the walk (it is the answer).
    // A vertex exactly on the piece bends it when the chain rule allows (a 2-ulp-wide fuzz
    // PSLG: a chain along y = 0 met an input vertex 3e-322 below its segment, and a bend there
    // broke the chain the check follows).
    auto on_piece = [&](VertIdx w) {
        return bend_candidate(cdt, piece.segment, a, b, w) ? NearVertex{w, false}
                                                           : NearVertex{kNone, true};
    };
    const StarExit exit = star_exit(cdt, a, b);
    if (exit.on_ray != kNone) return on_piece(exit.on_ray);
    const EdgeIdx entry = exit.entry;
    if (entry == kNone) return {};  // not expected: the piece would be present
    consider(cdt.mesh.origin(entry));
    consider(cdt.mesh.destination(entry));
    for (EdgeIdx h = entry;;) {
        const EdgeIdx f = cdt.mesh.twin[h];
        const VertIdx w = cdt.apex(f);
        if (w == b || w == kInfinite) break;
        ++cdt.result.counters.walk_steps;
        const Sign sw = cdt.core.orient(a, b, w);
        if (sw == Sign::Zero) return on_piece(w);
        consider(w);
        h = sw == Sign::Positive ? next_edge(f) : prev_edge(f);
    }
    return {best, false};
}

// Conforming split budget: 64 per input vertex, segment and crossing, plus 4,096. Every test
// input needs far fewer (the CGAL campaign's most is 20 per feature... see the proof note §5);
// two segments a few hundred binades long and 1e-312 apart need pieces as short as their gap
// everywhere, which no budget covers: they stop with GeometryError in well under a second.
constexpr std::uint64_t kSplitsPerFeature = 64;
constexpr std::uint64_t kSplitsBase = 4096;

/// Splits a missing piece (concentric shell or midpoint), inserts the point, queues both
/// halves and every marked piece the insertion encroached.
void split_piece(CdtState& cdt, Conforming& conforming, const Piece& piece, SplitQueue& tasks) {
    // A vertex the piece crosses within rounding of its segment (the check's chain rule,
    // bend_candidate) is where the piece bends: (6, 8) on a grid line
    // whose other end is a rounded crossing at (7 - 2^-50, 7) in grid-lines seed 5, where new
    // points would home in on it until no double is left between.
    const NearVertex near = vertex_near_segment(cdt, piece);
    if (near.bend != kNone) {
        ++cdt.result.counters.conforming_bends;
        tasks.push({{near.bend, piece.b, piece.segment}, false});
        tasks.push({{piece.a, near.bend, piece.segment}, false});
        return;
    }
    const double* pa = cdt.mesh.point(piece.a);
    const double* pb = cdt.mesh.point(piece.b);
    double m[2];
    const double* s0 = cdt.mesh.point(cdt.segment_ends[piece.segment][0]);
    const double* s1 = cdt.mesh.point(cdt.segment_ends[piece.segment][1]);
    // The split point on the input segment's line itself, rounded once from the input
    // (predicates::point_on_line_at): the midpoint of the ends' coordinates along the segment's
    // dominant axis, the other coordinate exact then rounded. Used where the cheap midpoint of
    // the (rounded) piece ends cannot serve: a vertex lies exactly on the piece but its chain
    // may not pass through it (then a split point on the line a - b would meet it again: a
    // 2-ulp-wide fuzz PSLG, whose chain along y = 0 met an input vertex 3e-322 below its
    // segment), or the midpoint falls outside rounding of the segment (near the origin, where
    // the rounding allowance shrinks with |w|). A parameter s0 + tau (s1 - s0) in doubles would
    // not do: it underflows for a 1e-20 piece at the end of a 1e303 segment.
    auto midpoint_on_input_line = [&](double* out) {
        const int axis = std::fabs(s1[0] - s0[0]) >= std::fabs(s1[1] - s0[1]) ? 0 : 1;
        const auto point = predicates::point_on_line_at(
            s0, s1, axis, predicates::rounded_midpoint(pa[axis], pb[axis]));
        out[0] = point[0];
        out[1] = point[1];
    };
    // The chain rule (§4): the split point must lie within rounding of the input segment and
    // strictly between the piece's ends along it, exactly (a piece may run either way along
    // its segment).
    auto on_its_way = [&](const double* w) {
        const Sign from_a = predicates::direction_dot_sign(pa, w, s0, s1),
                   to_b = predicates::direction_dot_sign(w, pb, s0, s1);
        return from_a != Sign::Zero && from_a == to_b &&
               predicates::within_rounding_of_segment(w, s0, s1);
    };
    bool on_input_segment = false;
    if (near.blocked) {
        midpoint_on_input_line(m);
        on_input_segment = true;
    }
    // Concentric shells [Ruppert95 §4; Shewchuk97 §3.4]: a piece with an end at a corner (an
    // input vertex where two or more pieces meet) is split at the power of two nearest half its
    // length, measured from that corner, so pieces of segments meeting there at a small angle
    // end on common circles about it and stop encroaching on each other (fuzz input
    // timeout-073fed0d: two segments at 1e-312 radians, 1,686 splits instead of over 100,000).
    // When both ends are corners, the one with more pieces (tiny PSLG 8/20404630: an ulp-narrow
    // angle at (1,1)); on a tie, at an intersection vertex or a split, and where the length is
    // out of the comfortable double range, the correctly rounded midpoint, whose error is
    // smaller (segments a few ulps apart: ReleasedConstraintIsMadeDelaunayAgain).
    auto corner = [&](VertIdx v) {
        return v < cdt.input_count ? conforming.segment_degree[v] : 0u;
    };
    const std::uint32_t ca = corner(piece.a) >= 2 ? corner(piece.a) : 0,
                        cb = corner(piece.b) >= 2 ? corner(piece.b) : 0;
    const int apex_end = ca == cb ? -1 : (ca > cb ? 0 : 1);  // 0: piece.a, 1: piece.b
    bool shell = false;
    if (apex_end >= 0 && !on_input_segment) {
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
    if (!shell && !on_input_segment) {
        for (int k = 0; k < 2; ++k) m[k] = predicates::rounded_midpoint(pa[k], pb[k]);
    }
    // A rounded midpoint of a piece far across the segment's direction may fall off its way (it
    // moved back by an ulp of a coordinate that the segment's direction weighs 1e60 times
    // more): then the point on the input line; if that fails too, the piece is finer than
    // doubles resolve.
    if (!on_its_way(m) && !on_input_segment) midpoint_on_input_line(m);
    if (!on_its_way(m)) {
        throw GeometryError("conforming Delaunay: segment " + cdt.segment_name(piece.segment) +
                            " has a piece whose split point falls off its way (features finer "
                            "than double precision resolves)");
    }
    // Walk from the end nearer the split point (a corner can have a large fan of thin
    // triangles: 60x fewer walk steps on fuzz input timeout-073fed0d than from the first end).
    const double da = std::fabs(m[0] - pa[0]) + std::fabs(m[1] - pa[1]);
    const double db = std::fabs(m[0] - pb[0]) + std::fabs(m[1] - pb[1]);
    cdt.core.last_triangle = triangle_of(cdt.vertex_edge[da < db ? piece.a : piece.b]);
    const VertIdx mid = cdt.add_vertex(m[0], m[1]);
    const TriIdx t = cdt.core.walk_to(mid);
    VertIdx at = mid;
    if (!cdt.mesh.is_infinite(t)) {
        for (unsigned k = 0; k < 3; ++k) {
            if (cdt.core.same_point(cdt.mesh.tv[3 * t + k], mid)) at = cdt.mesh.tv[3 * t + k];
        }
    }
    if (at != mid) {
        cdt.remove_last_vertex();
        // The split point rounds to an existing vertex `at`, at its coordinates, so on its way
        // (on_its_way(m) held: within rounding and strictly between a and b along the segment,
        // which keeps the pieces a - at, at - b from leading back; PSLGs spanning 1e-225..1e212
        // once alternated 57,000 times between two such tasks).
    } else {
        const Cdt2Counters& c = cdt.result.counters;
        if (++cdt.result.counters.conforming_splits >
            kSplitsPerFeature * (c.points + c.segments + c.intersections) + kSplitsBase) {
            throw GeometryError("conforming Delaunay: more than " +
                                std::to_string(c.conforming_splits - 1) +
                                " splits; stopped (small input angles?)");
        }
        conforming.encroached.clear();
        insert_vertex(cdt, mid, t, &conforming.encroached);
        for (const Piece& hit : conforming.encroached) tasks.push({hit, true});
    }
    tasks.push({{at, piece.b, piece.segment}, false});
    tasks.push({{piece.a, at, piece.segment}, false});
}

}  // namespace

void conform(CdtState& cdt) {
    // 1. Pieces as the constrained triangulation found them (crossings and vertices on
    //    segments already split); 2. forget the constraints and make the triangulation
    //    Delaunay; 3. split missing pieces at their midpoints until all are edges.
    std::vector<Piece> pieces;
    std::vector<std::pair<VertIdx, VertIdx>> edges;
    for (TriIdx t = 0; t < cdt.mesh.triangle_slots(); ++t) {
        if (cdt.mesh.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            const VertIdx p = cdt.mesh.origin(e), q = cdt.mesh.destination(e);
            if (p == kInfinite || q == kInfinite || p > q) continue;
            edges.emplace_back(p, q);
            if (cdt.segment_of[e] != kNone) {
                pieces.push_back({p, q, cdt.segment_of[e]});
                for (const std::uint32_t s : cdt.shared_segments(p, q)) pieces.push_back({p, q, s});
            }
        }
    }
    std::fill(cdt.segment_of.begin(), cdt.segment_of.end(), kNone);
    cdt.shared.clear();
    restore_delaunay(cdt, edges);
    // Every present piece is marked; Lawson flips never remove a marked edge but report it when
    // a new vertex makes it not locally Delaunay (flip_if_needed), and such a piece is split
    // instead. When the stack is empty, every unmarked edge is locally Delaunay by the flips and
    // every marked one by its last check: the triangulation is Delaunay and holds every piece.
    Conforming conforming;
    conforming.segment_degree.assign(cdt.mesh.vertex_count(), 0);
    for (const Piece& piece : pieces) {
        ++conforming.segment_degree[piece.a];
        ++conforming.segment_degree[piece.b];
    }
    SplitQueue tasks(cdt);
    for (const Piece& piece : pieces) tasks.push({piece, false});
    for (;;) {
        while (!tasks.empty()) {
            const SplitTask task = tasks.pop();
            guard(cdt);
            const Piece& piece = task.piece;
            const EdgeIdx present = cdt.find_edge(piece.a, piece.b);
            if (present != kNone) {
                if (!task.encroached) {
                    cdt.mark(present, piece.segment);
                    continue;
                }
                if (locally_delaunay(cdt, present)) continue;
                // Released and flipped (it is not locally Delaunay), then split like a missing
                // piece.
                cdt.segment_of[present] = cdt.segment_of[cdt.mesh.twin[present]] = kNone;
                // The other segments whose chains shared the piece recover it again themselves.
                for (const std::uint32_t s : cdt.release_shared(piece.a, piece.b)) {
                    if (s != piece.segment) tasks.push({{piece.a, piece.b, s}, false});
                }
                std::vector<std::pair<VertIdx, VertIdx>> edge{{piece.a, piece.b}};
                restore_delaunay(cdt, edge);
            }
            split_piece(cdt, conforming, piece, tasks);
        }
        // Safety net (normally finds nothing): every edge is checked once more; a marked one not
        // locally Delaunay is split, an unmarked one flipped.
        std::vector<std::pair<VertIdx, VertIdx>> unmarked;
        for (EdgeIdx e = 0; e < cdt.segment_of.size(); ++e) {
            if (cdt.mesh.is_dead(triangle_of(e))) continue;
            const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e);
            if (a == kInfinite || b == kInfinite || a > b || locally_delaunay(cdt, e)) continue;
            if (cdt.segment_of[e] != kNone) {
                tasks.push({{a, b, cdt.segment_of[e]}, true});
            } else {
                unmarked.emplace_back(a, b);
            }
        }
        ++cdt.result.counters.conforming_passes;
        if (tasks.empty() && unmarked.empty()) break;
        restore_delaunay(cdt, unmarked);
    }
}

EdgeIdx near_apex(const CdtState& cdt, EdgeIdx e) {
    // The apex (of e's triangle, else of its twin's) that may bend e's segment between e's ends:
    // bend_candidate, the chain rule that check_constrained_delaunay_2d applies.
    const std::uint32_t segment = cdt.segment_of[e];
    const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e);
    for (const EdgeIdx side : {e, cdt.mesh.twin[e]}) {
        if (bend_candidate(cdt, segment, a, b, cdt.apex(side))) return side;
    }
    return kNone;
}

VertIdx bend_through_apex(CdtState& cdt, EdgeIdx g) {
    // Triangle (u, v, w) of g: the chain u - w - v replaces u - v, and the triangle moves to the
    // other side of the constraint.
    const std::uint32_t segment = cdt.segment_of[g];
    const EdgeIdx h = cdt.mesh.twin[g];
    const VertIdx u = cdt.mesh.origin(g), v = cdt.mesh.destination(g), w = cdt.apex(g);
    const TriIdx t = triangle_of(g);
    cdt.mark(next_edge(g), segment);
    cdt.mark(prev_edge(g), segment);
    for (const std::uint32_t other : cdt.release_shared(u, v)) {
        cdt.mark(next_edge(g), other);
        cdt.mark(prev_edge(g), other);
    }
    cdt.segment_of[g] = cdt.segment_of[h] = kNone;
    cdt.put_on_side(t, cdt.side_of(triangle_of(h)));
    if (cdt.domain_marked()) cdt.touched.push_back(t);
    std::vector<std::pair<VertIdx, VertIdx>> released{{u, v}};
    restore_delaunay(cdt, released);
    return w;
}

void bend_through_near_vertices(CdtState& cdt) {
    // Every piece whose neighbouring triangle has its apex within rounding of the segment (a
    // vertex a few ulps off it) bends through that vertex, as the conforming recovery bends:
    // else refinement would have to resolve the ulp-wide gap between them.
    std::vector<std::pair<VertIdx, VertIdx>> pieces;
    for (EdgeIdx e = 0; e < cdt.segment_of.size(); ++e) {
        if (cdt.segment_of[e] == kNone || cdt.mesh.is_dead(triangle_of(e))) continue;
        if (cdt.mesh.origin(e) < cdt.mesh.destination(e))
            pieces.emplace_back(cdt.mesh.origin(e), cdt.mesh.destination(e));
    }
    while (!pieces.empty()) {
        const auto [a, b] = pieces.back();
        pieces.pop_back();
        const EdgeIdx e = cdt.find_edge(a, b);
        if (e == kNone || cdt.segment_of[e] == kNone) continue;
        const EdgeIdx side = near_apex(cdt, e);
        if (side == kNone) continue;
        const std::uint32_t segment = cdt.segment_of[e];
        const VertIdx w = bend_through_apex(cdt, side);
        ++cdt.result.counters.conforming_bends;
        cdt.result.warnings.push_back(
            "vertex " + std::to_string(cdt.core.input_index[w] + cdt.options.first_index) +
            " lies within rounding of segment " +
            std::to_string(segment + cdt.options.first_index) + "; the segment bends through it");
        pieces.emplace_back(a, w);
        pieces.emplace_back(w, b);
    }
}

}  // namespace exactmesh::triangulation::detail
