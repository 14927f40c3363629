// SPDX-License-Identifier: MIT
// Advancing front (see advancing_front_2d.hpp).
//
// State: the points (the boundary's first, new ones appended); the front edges in one vector
// (a removed edge is marked dead, its slot never reused), each alive edge listed in its tail's
// out-list (the front edges leaving a vertex: one, or more where the front pinches) and in a
// loose quadtree; a min-heap of (squared length, edge); the edges postponed in this round.
// A round drains the heap; then the postponed edges (by then the whole front) go back into it
// with one attempt more, so each retry sees the front its neighbours left.
#include "generators/mesh_2d/advancing_front_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "base/progress.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/mesh_2d/domain_mesh_2d.hpp"
#include "generators/mesh_2d/front_index_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
using predicates::Sign;
using tri::kNone;
using tri::VertIdx;
using EdgeId = std::uint32_t;

using Box = FrontBox2;

bool boxes_meet(const Box& p, const Box& q) {
    return p.meets(q);
}

bool box_holds(const Box& box, const double* p) {
    return box.holds(p);
}

struct FrontEdge {
    VertIdx a, b;
    EdgeId next_out = kNone;  // the next front edge leaving a
    std::uint32_t attempts = 0;
    bool alive = true;
};

/// The front edges and vertices near a base edge: every alive front edge whose bounding box
/// meets `box`, their end points inside it and the free vertices (no front edge yet) inside it.
struct Neighbourhood {
    Box box{};
    std::vector<EdgeId> edges;
    std::vector<VertIdx> vertices;  ///< the free ones included
    std::vector<VertIdx> free;
};

struct Candidate {
    double key;
    VertIdx v;
};

/// A candidate's order key, never NaN (a rounded-to-zero denominator or an overflow puts the
/// candidate last instead of breaking the sort's ordering).
double sort_key(double key) {
    return std::isnan(key) ? std::numeric_limits<double>::infinity() : key;
}

class AdvancingFront {
  public:
    AdvancingFront(const DomainBoundary2& boundary, const AdvancingFrontOptions2& options,
                   AdvancingFrontCounters2& counters)
        : boundary_(boundary),
          options_(options),
          counters_(counters),
          xy_(boundary.xy),
          quadtree_(make_quadtree(boundary.xy)),
          free_tree_(quadtree_) {  // empty, over the same root square
        out_head_.assign(xy_.size() / 2, kNone);
        stamp_.assign(xy_.size() / 2, 0);
        tested_.assign(xy_.size() / 2, 0);
        for (std::size_t e = 0; 2 * e + 1 < boundary.front.size(); ++e)
            add_edge(boundary.front[2 * e], boundary.front[2 * e + 1]);
        // The free input vertices are front vertices without edges (a front loop of length 0,
        // as a slit is one of width 0): candidates like any front vertex, and points that no
        // triangle may cover, until a triangle takes them in.
        free_.assign(xy_.size() / 2, 0);
        for (const VertIdx v : boundary.free_vertices) {
            const double h = options_.size(point(v)[0], point(v)[1]);
            free_[v] = 1;
            free_tree_.insert(v, Box{point(v)[0], point(v)[1], point(v)[0], point(v)[1]},
                              std::isfinite(h) && h > 0 ? h : 0.0);
        }
        check_initial_front();
        budget_ = options.max_triangles != 0 ? options.max_triangles : automatic_budget();
        // The total only when someone asks: the estimate integrates the size over the domain.
        if (options.cdt.progress) {
            const double expected = expected_triangle_count(boundary_, options_.size);
            progress_ = ProgressCounter(
                options.cdt.progress,
                expected > 0 ? static_cast<std::uint64_t>(std::min(expected, 1e15)) : 0,
                "triangles made");
        }
    }

    void run() {
        std::vector<EdgeId> postponed;
        std::uint64_t round_start = 0;
        for (;;) {
            while (!heap_.empty()) {
                const EdgeId e = heap_.top().second;
                heap_.pop();
                if (!edges_[e].alive) continue;
                if (triangles_.size() / 3 >= budget_ || xy_.size() / 2 >= tri::kMaxPoints ||
                    over_work_budget()) {
                    close_front();
                    return;
                }
                if (!advance(e)) {
                    ++edges_[e].attempts;
                    ++counters_.postponed_edges;
                    postponed.push_back(e);
                }
            }
            std::erase_if(postponed, [&](EdgeId e) { return !edges_[e].alive; });
            if (postponed.empty()) return;
            const bool progress = triangles_.size() / 3 > round_start;
            const bool exhausted = std::all_of(postponed.begin(), postponed.end(), [&](EdgeId e) {
                return edges_[e].attempts > options_.local_attempts;
            });
            // Never expected (the wide search always succeeds), but a front that stopped
            // moving is closed rather than retried forever.
            if (!progress && exhausted) {
                close_front();
                return;
            }
            round_start = triangles_.size() / 3;
            for (const EdgeId e : postponed) push(e);
            postponed.clear();
        }
    }

    std::vector<double> take_points() { return std::move(xy_); }
    std::vector<VertIdx> take_triangles() { return std::move(triangles_); }

  private:
    const DomainBoundary2& boundary_;
    const AdvancingFrontOptions2& options_;
    AdvancingFrontCounters2& counters_;
    ProgressCounter progress_;  ///< triangles made, for options.cdt.progress
    std::vector<double> xy_;
    std::vector<VertIdx> triangles_;
    std::vector<FrontEdge> edges_;
    std::vector<EdgeId> out_head_;
    double root_side_ = 0;  // before quadtree_: make_quadtree sets it
    // Squared lengths and shapes (placement choices) are taken on differences scaled by
    // 2^shift_ = 1 / root_side_ (exact): no overflow or underflow, and the same choices, bit
    // for bit, for a domain scaled by a power of two. Set by make_quadtree.
    int shift_ = 0;
    predicates::PowerOfTwo unit_{0};  // multiplies by 2^shift_ (ldexp, without the call)
    // The shared loose quadtree of the fronts (front_index_2d.hpp).
    FrontIndex2 quadtree_;
    FrontIndex2 free_tree_;           // the free vertices not yet taken in, by vertex number
    std::vector<std::uint8_t> free_;  // 1 for those vertices
    std::priority_queue<std::pair<double, EdgeId>, std::vector<std::pair<double, EdgeId>>,
                        std::greater<>>
        heap_;
    std::uint64_t alive_edges_ = 0;
    std::uint64_t budget_ = 0;
    std::vector<std::uint32_t> stamp_, tested_;
    std::uint32_t stamp_value_ = 0, tested_value_ = 0;
    Neighbourhood near_;
    std::vector<Candidate> candidates_;

    const double* point(VertIdx v) const { return xy_.data() + 2 * std::size_t{v}; }

    /// A difference of coordinates in the scaled units (see shift_).
    double scaled(double d) const { return unit_(d); }

    Sign orient(VertIdx a, VertIdx b, VertIdx c) {
        ++counters_.orient_calls;
        return predicates::orient2d(point(a), point(b), point(c));
    }

    FrontIndex2 make_quadtree(const std::vector<double>& xy) {
        double x0 = xy[0], y0 = xy[1], x1 = xy[0], y1 = xy[1];
        for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
            x0 = std::min(x0, xy[i]), x1 = std::max(x1, xy[i]);
            y0 = std::min(y0, xy[i + 1]), y1 = std::max(y1, xy[i + 1]);
        }
        const double extent = std::max(x1 - x0, y1 - y0);
        if (!std::isfinite(extent) || extent >= std::ldexp(1.0, 1020)) {
            throw InputError(
                "advancing front: the domain's extent overflows a double (coordinates from " +
                std::to_string(x0) + " to " + std::to_string(x1) + ")");
        }
        // The smallest power of two above the extent (a degenerate extent cannot occur: the
        // domain has area).
        root_side_ = std::ldexp(1.0, std::ilogb(std::max(extent, std::ldexp(1.0, -1000))) + 1);
        shift_ = -std::ilogb(root_side_);
        unit_ = predicates::PowerOfTwo(shift_);
        return FrontIndex2(x0 + 0.5 * root_side_, y0 + 0.5 * root_side_, 0.5 * root_side_);
    }

    /// 8 times the triangle count the size function asks for (expected_triangle_count over
    /// the domain's CDT) plus 4 per boundary edge and 4096: a front that makes that many has run
    /// away (ever smaller triangles), and its closure ends the run.
    std::uint64_t automatic_budget() const {
        const double budget = 8 * expected_triangle_count(boundary_, options_.size) +
                              4 * static_cast<double>(boundary_.front.size() / 2) + 4096;
        return static_cast<std::uint64_t>(std::min(budget, 1e15));
    }

    /// The front's work budget. A healthy front makes a few exact crossing tests per triangle
    /// (4 on the sample domains); one whose placements keep failing (a sliver ulps thin beside
    /// a long segment, where every candidate is rejected and every edge needs the wide search)
    /// makes thousands, more with every point: a fuzzed PSLG graded from 1e-310 to 1e-185 made
    /// 12.9 million tests for 1300 points (5 s in release, minutes under the sanitizers).
    /// Past 64 per triangle (plus 2^16) the front is closed by the CDT, as when the triangle
    /// budget runs out (counted as a closure run).
    bool over_work_budget() const {
        return counters_.crossing_tests >
               64 * (triangles_.size() / 3 + boundary_.front.size() / 2) + (std::uint64_t{1} << 16);
    }

    double local_size(double x, double y) const {
        const double h = options_.size(x, y);
        if (!(h > 0)) {
            throw InputError("advancing front: the size function is " + format_number(h) + " at (" +
                             format_number(x) + ", " + format_number(y) + "), not > 0");
        }
        return h;
    }

    // ---- the front ----------------------------------------------------------------------

    void push(EdgeId e) {
        const double* a = point(edges_[e].a);
        const double* b = point(edges_[e].b);
        const double dx = scaled(b[0] - a[0]), dy = scaled(b[1] - a[1]);
        heap_.push({dx * dx + dy * dy, e});
    }

    void add_edge(VertIdx a, VertIdx b) {
        const auto e = static_cast<EdgeId>(edges_.size());
        edges_.push_back({a, b, out_head_[a], 0, true});
        out_head_[a] = e;
        const Box box = edge_box(e);
        quadtree_.insert(e, box, std::max(box.x1 - box.x0, box.y1 - box.y0));
        push(e);
        ++alive_edges_;
        counters_.max_front_edges = std::max(counters_.max_front_edges, alive_edges_);
    }

    void kill_edge(EdgeId e) {
        FrontEdge& edge = edges_[e];
        edge.alive = false;
        EdgeId* link = &out_head_[edge.a];
        while (*link != e) link = &edges_[*link].next_out;
        *link = edge.next_out;
        quadtree_.erase(e);
        --alive_edges_;
    }

    /// The alive front edge u -> v, or kNone.
    EdgeId find_out(VertIdx u, VertIdx v) const {
        for (EdgeId e = out_head_[u]; e != kNone; e = edges_[e].next_out) {
            if (edges_[e].b == v) return e;
        }
        return kNone;
    }

    Box edge_box(EdgeId e) const {
        const double* a = point(edges_[e].a);
        const double* b = point(edges_[e].b);
        return {std::min(a[0], b[0]), std::min(a[1], b[1]), std::max(a[0], b[0]),
                std::max(a[1], b[1])};
    }

    /// near_: the alive front edges whose bounding box meets `box` (exact), their end points
    /// in the box.
    void gather(const Box& box) {
        ++counters_.front_queries;
        near_.box = box;
        near_.edges.clear();
        near_.vertices.clear();
        near_.free.clear();
        if (++stamp_value_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0);
            stamp_value_ = 1;
        }
        // The index reports exactly the edges whose box meets `box` (and the free vertices in it).
        quadtree_.query(box, near_.edges);
        for (const EdgeId e : near_.edges) {
            for (const VertIdx v : {edges_[e].a, edges_[e].b}) {
                if (stamp_[v] != stamp_value_ && box_holds(box, point(v))) {
                    stamp_[v] = stamp_value_;
                    near_.vertices.push_back(v);
                }
            }
        }
        free_tree_.query(box, near_.free);
        near_.vertices.insert(near_.vertices.end(), near_.free.begin(), near_.free.end());
    }

    /// The initial front comes from the CDT's pieces, split at rounded points: check that no
    /// two of its edges meet away from shared ends (an ulp-wide bend could, in principle).
    void check_initial_front() {
        for (EdgeId e = 0; e < edges_.size(); ++e) {
            gather(edge_box(e));
            for (const EdgeId f : near_.edges) {
                if (f > e && edges_meet(edges_[e].a, edges_[e].b, edges_[f].a, edges_[f].b)) {
                    throw GeometryError(
                        "advancing front: boundary pieces " + std::to_string(edges_[e].a) + "-" +
                        std::to_string(edges_[e].b) + " and " + std::to_string(edges_[f].a) + "-" +
                        std::to_string(edges_[f].b) + " meet away from their ends after rounding");
                }
            }
        }
    }

    // ---- exact tests ------------------------------------------------------------------------

    /// Do segments s0-s1 and t0-t1 (distinct vertices at distinct points) meet anywhere but at
    /// a shared end? The same segment does not count (a slit's other side).
    bool edges_meet(VertIdx s0, VertIdx s1, VertIdx t0, VertIdx t1) {
        ++counters_.crossing_tests;
        if ((s0 == t0 && s1 == t1) || (s0 == t1 && s1 == t0)) return false;
        if (s0 == t0 || s0 == t1 || s1 == t0 || s1 == t1) {
            // Sharing end o: they overlap exactly when collinear and leaving o the same way.
            const VertIdx o = (s0 == t0 || s0 == t1) ? s0 : s1;
            const VertIdx s = o == s0 ? s1 : s0, t = o == t0 ? t1 : t0;
            return orient(o, s, t) == Sign::Zero &&
                   predicates::corner_dot_sign(point(o), point(s), point(t)) == Sign::Positive;
        }
        const Sign o1 = orient(s0, s1, t0), o2 = orient(s0, s1, t1);
        if (o1 == o2 && o1 != Sign::Zero) return false;
        const Sign o3 = orient(t0, t1, s0), o4 = orient(t0, t1, s1);
        if (o3 == o4 && o3 != Sign::Zero) return false;
        if (o1 == Sign::Zero && o2 == Sign::Zero) {
            // Collinear: their lexicographic extents overlap?
            auto less = [&](VertIdx u, VertIdx v) {
                return point(u)[0] < point(v)[0] ||
                       (point(u)[0] == point(v)[0] && point(u)[1] < point(v)[1]);
            };
            const VertIdx slo = less(s0, s1) ? s0 : s1, shi = slo == s0 ? s1 : s0;
            const VertIdx tlo = less(t0, t1) ? t0 : t1, thi = tlo == t0 ? t1 : t0;
            return !less(shi, tlo) && !less(thi, slo);
        }
        return true;
    }

    bool in_closed_triangle(VertIdx w, VertIdx a, VertIdx b, VertIdx c) {
        ++counters_.containment_tests;
        return orient(a, b, w) != Sign::Negative && orient(b, c, w) != Sign::Negative &&
               orient(c, a, w) != Sign::Negative;
    }

    struct Matches {
        EdgeId bc = kNone, ca = kNone;
    };

    /// May triangle (a, b, c) be cut off the front at base edge a -> b? Every test exact; near_
    /// must hold every front edge whose bounding box meets the triangle's.
    bool acceptable(EdgeId base, VertIdx c, Matches& m) {
        const VertIdx a = edges_[base].a, b = edges_[base].b;
        if (!box_holds(near_.box, point(c))) return false;  // outside what near_ covers
        if (orient(a, b, c) != Sign::Positive) return false;
        m.bc = find_out(b, c);
        m.ca = find_out(c, a);
        // Front edge c -> b without b -> c: the triangle would lie on its meshed side.
        if (m.bc == kNone && find_out(c, b) != kNone) return false;
        if (m.ca == kNone && find_out(a, c) != kNone) return false;
        const double* pa = point(a);
        const double* pb = point(b);
        const double* pc = point(c);
        const Box box{std::min({pa[0], pb[0], pc[0]}), std::min({pa[1], pb[1], pc[1]}),
                      std::max({pa[0], pb[0], pc[0]}), std::max({pa[1], pb[1], pc[1]})};
        for (const EdgeId f : near_.edges) {
            if (f == base || f == m.bc || f == m.ca || !boxes_meet(edge_box(f), box)) continue;
            const VertIdx u = edges_[f].a, v = edges_[f].b;
            for (const VertIdx w : {u, v}) {
                if (w != a && w != b && w != c && in_closed_triangle(w, a, b, c)) return false;
            }
            if (m.bc == kNone && edges_meet(b, c, u, v)) return false;
            if (m.ca == kNone && edges_meet(c, a, u, v)) return false;
        }
        // A free vertex in the closed triangle would be left out of the mesh (or on an edge).
        for (const VertIdx w : near_.free) {
            if (w != c && box_holds(box, point(w)) && in_closed_triangle(w, a, b, c)) return false;
        }
        return true;
    }

    /// Cuts triangle (a, b, c) off the front.
    void take(EdgeId base, VertIdx c, const Matches& m, bool new_point) {
        const VertIdx a = edges_[base].a, b = edges_[base].b;
        triangles_.insert(triangles_.end(), {a, b, c});
        ++counters_.triangles;
        progress_.tick();
        ++(new_point ? counters_.new_points : counters_.reused_points);
        if (c < free_.size() && free_[c] != 0) {  // new points come after the free vertices
            free_[c] = 0;
            free_tree_.erase(c);
        }
        kill_edge(base);
        if (m.bc != kNone) {
            kill_edge(m.bc);
        } else {
            add_edge(c, b);
        }
        if (m.ca != kNone) {
            kill_edge(m.ca);
        } else {
            add_edge(a, c);
        }
    }

    // ---- candidates ---------------------------------------------------------------------

    /// Squared distance from (x, y) to segment u-v in the scaled units (double precision:
    /// placement only).
    double distance2_to_edge(double x, double y, EdgeId e) const {
        const double* u = point(edges_[e].a);
        const double* v = point(edges_[e].b);
        const double dx = v[0] - u[0], dy = v[1] - u[1];
        const double sx = scaled(dx), sy = scaled(dy), length2 = sx * sx + sy * sy;
        const double t =
            length2 > 0
                ? std::clamp((scaled(x - u[0]) * sx + scaled(y - u[1]) * sy) / length2, 0.0, 1.0)
                : 0.0;
        const double ex = scaled(x - (u[0] + t * dx)), ey = scaled(y - (u[1] + t * dy));
        return ex * ex + ey * ey;
    }

    /// May a new point go at (x, y): `slack` times the option distances (times delta) away
    /// from the front vertices and edges near it (ab's own ends and ab excepted)? Whether it
    /// lies in the domain needs no test of its own: a triangle the exact tests accept lies in
    /// the unmeshed region, which is inside the domain (a point-location per candidate cost a
    /// fifth of the run on naca0012, the domain's CDT having long thin triangles).
    bool placeable(EdgeId base, double x, double y, double delta, double slack) const {
        if (!std::isfinite(x) || !std::isfinite(y)) return false;
        const double vertex_gap = scaled(slack * options_.min_vertex_distance * delta);
        const double edge_gap = scaled(slack * options_.min_edge_distance * delta);
        for (const VertIdx w : near_.vertices) {
            if (w == edges_[base].a || w == edges_[base].b) continue;
            const double dx = scaled(point(w)[0] - x), dy = scaled(point(w)[1] - y);
            if (dx * dx + dy * dy < vertex_gap * vertex_gap) return false;
        }
        for (const EdgeId f : near_.edges) {
            if (f != base && distance2_to_edge(x, y, f) < edge_gap * edge_gap) return false;
        }
        return true;
    }

    /// Tries a new point at (x, y) as the apex.
    bool try_point(EdgeId base, double x, double y, double delta, double slack) {
        if (!placeable(base, x, y, delta, slack)) {
            ++counters_.rejected_candidates;
            return false;
        }
        const auto c = static_cast<VertIdx>(xy_.size() / 2);
        xy_.push_back(x);
        xy_.push_back(y);
        out_head_.push_back(kNone);
        stamp_.push_back(0);
        tested_.push_back(0);
        Matches m;
        if (acceptable(base, c, m)) {
            take(base, c, m, true);
            return true;
        }
        xy_.resize(xy_.size() - 2);
        out_head_.pop_back();
        stamp_.pop_back();
        tested_.pop_back();
        ++counters_.rejected_candidates;
        return false;
    }

    bool try_vertex(EdgeId base, VertIdx c) {
        Matches m;
        if (acceptable(base, c, m)) {
            take(base, c, m, false);
            return true;
        }
        ++counters_.rejected_candidates;
        return false;
    }

    /// 4 sqrt(3) area / (sum of squared sides) of (a, b, c): 1 equilateral, 0 degenerate. On
    /// the sides scaled by a power of two to a largest component in [1, 2) (scale-free).
    static double shape(const double* p, const double* q, const double* r) {
        double side[3][2] = {
            {q[0] - p[0], q[1] - p[1]}, {r[0] - q[0], r[1] - q[1]}, {p[0] - r[0], p[1] - r[1]}};
        double largest = 0;
        for (const auto& d : side) largest = std::max({largest, std::fabs(d[0]), std::fabs(d[1])});
        if (!(largest > 0) || !std::isfinite(largest)) return 0;
        const int shift = -std::ilogb(largest);
        for (auto& d : side) d[0] = std::ldexp(d[0], shift), d[1] = std::ldexp(d[1], shift);
        // (q - p) x (r - p), with r - p = -side[2].
        const double cross = side[0][1] * side[2][0] - side[0][0] * side[2][1];
        const double sides = side[0][0] * side[0][0] + side[0][1] * side[0][1] +
                             side[1][0] * side[1][0] + side[1][1] * side[1][1] +
                             side[2][0] * side[2][0] + side[2][1] * side[2][1];
        return 2 * std::sqrt(3.0) * cross / sides;
    }

    /// One attempt at base edge e: local candidates on the first attempts, then the wide
    /// search. True when a triangle was cut.
    bool advance(EdgeId e) {
        const VertIdx a = edges_[e].a, b = edges_[e].b;
        const double* pa = point(a);
        const double* pb = point(b);
        const double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
        const double length = std::hypot(dx, dy);
        const double mx = 0.5 * pa[0] + 0.5 * pb[0], my = 0.5 * pa[1] + 0.5 * pb[1];
        const double nx = -dy / length, ny = dx / length;  // unit normal into the front's left
        auto side_of = [&](double h) {
            return std::clamp(h, options_.min_side_ratio * length,
                              options_.max_side_ratio * length);
        };
        // Scaled by the power of two at the edge's length (scale-free, exact).
        const int shift = -std::ilogb(length);
        auto height_of = [&](double delta) {
            const double d = std::ldexp(delta, shift), l = std::ldexp(length, shift);
            return std::ldexp(std::sqrt(std::max(0.0, d * d - 0.25 * l * l)), -shift);
        };
        // The size near the triangle: at the midpoint first, then at the centroid of the
        // triangle that size gives (kept only when > 0 there: that centroid may lie outside the
        // domain, where the size need not be defined).
        double delta = side_of(local_size(mx, my));
        double height = height_of(delta);
        const double centroid_size = options_.size(mx + nx * height / 3, my + ny * height / 3);
        if (centroid_size > 0) {
            delta = side_of(centroid_size);
            height = height_of(delta);
        }
        const double px = mx + nx * height, py = my + ny * height;
        const std::uint32_t attempts = edges_[e].attempts;
        if (attempts >= options_.local_attempts) return wide_search(e, std::max(length, delta));

        const bool retry = attempts > 0;
        const double reach = options_.search_radius * delta * (retry ? 2 : 1);
        gather({std::min({pa[0], pb[0], px}) - reach, std::min({pa[1], pb[1], py}) - reach,
                std::max({pa[0], pb[0], px}) + reach, std::max({pa[1], pb[1], py}) + reach});
        // Front vertices near the ideal point, nearest first; the others later by shape.
        candidates_.clear();
        std::vector<Candidate> farther;
        for (const VertIdx v : near_.vertices) {
            if (v == a || v == b || orient(a, b, v) != Sign::Positive) continue;
            const double distance = std::hypot(point(v)[0] - px, point(v)[1] - py);
            const double s = shape(point(a), point(b), point(v));
            if (!retry && s < options_.min_shape) continue;
            if (distance <= options_.reuse_radius * delta) {
                candidates_.push_back({sort_key(distance), v});
            } else {
                farther.push_back({sort_key(-s), v});
            }
        }
        auto by_key = [](const Candidate& p, const Candidate& q) {
            return p.key < q.key || (p.key == q.key && p.v < q.v);
        };
        std::sort(candidates_.begin(), candidates_.end(), by_key);
        if (!retry) {
            for (const Candidate& c : candidates_) {
                if (try_vertex(e, c.v)) return true;
            }
            if (try_point(e, px, py, delta, 1.0)) return true;
            std::sort(farther.begin(), farther.end(), by_key);
            for (const Candidate& c : farther) {
                if (try_vertex(e, c.v)) return true;
            }
            return false;
        }
        // A retry: every front vertex near by and new points ever nearer ab (with ever smaller
        // distances to the front), best shape first.
        candidates_.insert(candidates_.end(), farther.begin(), farther.end());
        for (Candidate& c : candidates_) c.key = sort_key(-shape(point(a), point(b), point(c.v)));
        constexpr std::array<double, 4> kHeights{1.0, 0.6, 0.35, 0.2}, kSlack{1.0, 0.5, 0.5, 0.25};
        for (std::uint32_t k = 0; k < kHeights.size(); ++k) {
            const double q[2] = {mx + nx * height * kHeights[k], my + ny * height * kHeights[k]};
            candidates_.push_back({sort_key(-shape(point(a), point(b), q)), kNone - 1 - k});
        }
        std::sort(candidates_.begin(), candidates_.end(), by_key);
        for (const Candidate& c : candidates_) {
            if (c.v < kNone - kHeights.size()) {
                if (try_vertex(e, c.v)) return true;
            } else {
                const std::uint32_t k = kNone - 1 - c.v;
                if (try_point(e, mx + nx * height * kHeights[k], my + ny * height * kHeights[k],
                              delta, kSlack[k]))
                    return true;
            }
        }
        return false;
    }

    /// Every front vertex left of ab in boxes around it that double until they cover the
    /// domain, best (smallest circumcircle bulge beyond ab: Delaunay-like) first. One of them
    /// is acceptable: the apex of the constrained Delaunay triangle on ab inside the unmeshed
    /// region (proofs/invariants/advancing_front_2d.md).
    bool wide_search(EdgeId e, double reach) {
        const VertIdx a = edges_[e].a, b = edges_[e].b;
        const double* pa = point(a);
        const double* pb = point(b);
        const double mx = 0.5 * pa[0] + 0.5 * pb[0], my = 0.5 * pa[1] + 0.5 * pb[1];
        const double nx = scaled(-(pb[1] - pa[1])), ny = scaled(pb[0] - pa[0]);
        const double quarter = 0.25 * (nx * nx + ny * ny);
        if (++tested_value_ == 0) {
            std::fill(tested_.begin(), tested_.end(), 0);
            tested_value_ = 1;
        }
        for (;;) {
            gather({std::min(pa[0], pb[0]) - reach, std::min(pa[1], pb[1]) - reach,
                    std::max(pa[0], pb[0]) + reach, std::max(pa[1], pb[1]) + reach});
            candidates_.clear();
            for (const VertIdx v : near_.vertices) {
                if (v == a || v == b || tested_[v] == tested_value_) continue;
                tested_[v] = tested_value_;
                if (orient(a, b, v) != Sign::Positive) continue;
                // The circumcenter of abv is m + t n: t = (|v - m|^2 - |ab|^2 / 4) / (2 (v - m).n).
                const double vx = scaled(point(v)[0] - mx), vy = scaled(point(v)[1] - my);
                const double along = vx * nx + vy * ny;
                candidates_.push_back({sort_key((vx * vx + vy * vy - quarter) / (2 * along)), v});
            }
            std::sort(candidates_.begin(), candidates_.end(),
                      [](const Candidate& p, const Candidate& q) {
                          return p.key < q.key || (p.key == q.key && p.v < q.v);
                      });
            for (const Candidate& c : candidates_) {
                if (try_vertex(e, c.v)) {
                    ++counters_.wide_searches;
                    return true;
                }
            }
            if (reach > 2 * root_side_) return false;
            reach *= 2;
        }
    }

    // ---- closure ------------------------------------------------------------------------

    /// Triangulates what the front encloses by the constrained Delaunay triangulation of its
    /// edges: the triangles reached from the left side of a front edge without crossing one.
    void close_front() {
        std::vector<VertIdx> local(xy_.size() / 2, kNone), global;
        std::vector<double> xy;
        std::vector<VertIdx> segments, directed;
        auto local_of = [&](VertIdx v) {
            if (local[v] == kNone) {
                local[v] = static_cast<VertIdx>(global.size());
                global.push_back(v);
                xy.insert(xy.end(), {point(v)[0], point(v)[1]});
            }
            return local[v];
        };
        for (EdgeId e = 0; e < edges_.size(); ++e) {
            if (!edges_[e].alive) continue;
            const VertIdx u = local_of(edges_[e].a), v = local_of(edges_[e].b);
            directed.insert(directed.end(), {u, v});
            // A slit's two sides are one segment.
            if (edges_[e].a < edges_[e].b || find_out(edges_[e].b, edges_[e].a) == kNone)
                segments.insert(segments.end(), {u, v});
        }
        if (directed.empty()) return;
        // The free vertices not taken in yet lie inside the front (no triangle covers one).
        for (const VertIdx v : boundary_.free_vertices) {
            if (free_[v] != 0) local_of(v);
        }
        ++counters_.closure_runs;
        tri::Cdt2Options options = options_.cdt;
        options.remove_exterior = false;
        options.recovery = tri::SegmentRecovery::Swap;
        const tri::Pslg pslg{xy, segments, {}, {}};
        const tri::Cdt2Result cdt = tri::constrained_delaunay_2d(pslg, options);
        const tri::Triangulation2& mesh = cdt.mesh;
        if (mesh.vertex_count() != global.size()) {
            throw InternalError("advancing front: the closure's CDT added vertices (front edges " +
                                std::to_string(directed.size() / 2) + ")");
        }
        std::unordered_map<std::uint64_t, tri::TriIdx> left_of;
        left_of.reserve(mesh.triangles.size());
        for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                left_of[(std::uint64_t{mesh.triangles[3 * t + k]} << 32) |
                        mesh.triangles[3 * t + (k + 1) % 3]] = t;
            }
        }
        std::vector<std::uint8_t> inside(mesh.triangle_count(), 0);
        std::vector<tri::TriIdx> stack;
        for (std::size_t i = 0; i + 1 < directed.size(); i += 2) {
            const auto found = left_of.find((std::uint64_t{directed[i]} << 32) | directed[i + 1]);
            if (found == left_of.end()) {
                throw InternalError("advancing front: front edge " +
                                    std::to_string(global[directed[i]]) + " -> " +
                                    std::to_string(global[directed[i + 1]]) +
                                    " is not an edge of the closure's CDT");
            }
            if (!inside[found->second]) {
                inside[found->second] = 1;
                stack.push_back(found->second);
            }
        }
        while (!stack.empty()) {
            const tri::TriIdx t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const tri::TriIdx n = mesh.neighbors[3 * std::size_t{t} + static_cast<unsigned>(k)];
                if (n != kNone && !mesh.is_constrained(t, k) && !inside[n]) {
                    inside[n] = 1;
                    stack.push_back(n);
                }
            }
        }
        for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            if (!inside[t]) continue;
            for (unsigned k = 0; k < 3; ++k)
                triangles_.push_back(global[mesh.triangles[3 * t + k]]);
            ++counters_.closure_triangles;
            ++counters_.triangles;
            progress_.tick();
        }
        for (EdgeId e = 0; e < edges_.size(); ++e) {
            if (edges_[e].alive) kill_edge(e);
        }
    }
};

void validate(const AdvancingFrontOptions2& o) {
    auto positive = [](double v) { return std::isfinite(v) && v > 0; };
    if (!o.size.bounded()) {
        throw InputError("advancing front: a size function is required (the size is unbounded)");
    }
    if (!positive(o.min_side_ratio) || !positive(o.max_side_ratio) || o.min_side_ratio <= 0.5 ||
        o.max_side_ratio < o.min_side_ratio) {
        throw InputError("advancing front: side ratios must satisfy 0.5 < min (" +
                         std::to_string(o.min_side_ratio) + ") <= max (" +
                         std::to_string(o.max_side_ratio) + ")");
    }
    if (!positive(o.reuse_radius) || !positive(o.search_radius) || !(o.min_vertex_distance >= 0) ||
        !(o.min_edge_distance >= 0) || !std::isfinite(o.min_vertex_distance) ||
        !std::isfinite(o.min_edge_distance) || !(o.min_shape >= 0 && o.min_shape <= 1)) {
        throw InputError(
            "advancing front: reuse and search radii must be finite and > 0, distances finite "
            "and >= 0, min_shape in [0, 1]");
    }
    if (o.local_attempts == 0) {
        throw InputError("advancing front: local_attempts must be at least 1");
    }
}

}  // namespace

AdvancingFrontResult2 advancing_front_2d(const tri::Pslg& pslg,
                                         const AdvancingFrontOptions2& options) {
    return advancing_front_2d(MeshDomain2(pslg, options.cdt), options);
}

AdvancingFrontResult2 advancing_front_2d(const MeshDomain2& domain,
                                         const AdvancingFrontOptions2& options) {
    validate(options);
    return advancing_front_from_boundary_2d(
        discretize_domain_boundary(domain, options.size, options.max_boundary_points), options);
}

AdvancingFrontResult2 advancing_front_from_boundary_2d(const DomainBoundary2& boundary,
                                                       const AdvancingFrontOptions2& options) {
    validate(options);
    AdvancingFrontResult2 result;
    AdvancingFront front(boundary, options, result.counters);
    front.run();
    result.mesh = domain_mesh_result(boundary, front.take_points(), front.take_triangles());
    return result;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const AdvancingFrontCounters2& c) {
    return counters_by_name(kAdvancingFrontCounterNames, c);
}

}  // namespace exactmesh::generators
