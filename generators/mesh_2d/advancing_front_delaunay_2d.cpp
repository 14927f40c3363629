// SPDX-License-Identifier: MIT
// Advancing-front Delaunay triangulation (see advancing_front_delaunay_2d.hpp).
#include "generators/mesh_2d/advancing_front_delaunay_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <unordered_map>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/mesh_2d/domain_mesh_2d.hpp"
#include "generators/mesh_2d/front_index_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using predicates::Sign;
using tri::kNone;
using tri::VertIdx;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using Box = FrontBox2;

/// |(dx, dy)| < radius, in units of the radius (no overflow or underflow of the squares).
bool shorter_than(double dx, double dy, double radius) {
    const double x = dx / radius, y = dy / radius;
    return x * x + y * y < 1.0;
}

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

double checked_size(const SizeFunction& size, double x, double y) {
    const double h = size(x, y);
    if (!(h > 0)) {
        throw InputError("advancing front Delaunay: the size function is " + format_number(h) +
                         " at (" + format_number(x) + ", " + format_number(y) +
                         "); it must be > 0");
    }
    return h;
}

/// The number of equilateral triangles of the local size that cover the domain: each triangle
/// of its constrained Delaunay triangulation split in four until its edges are below 8 times
/// the smallest size sampled at its corners and centroid, at most 8 levels and 2^18 samples in
/// all (then the smallest sampled size stands for the rest: an overestimate; for a steep size,
/// SizeFunction::is_steep, the third smallest). For the point budget, not a decision.
double estimated_elements(const tri::Triangulation2& mesh, const SizeFunction& size) {
    constexpr double kEquilateral = 0.4330127018922193;  // sqrt(3) / 4
    struct Piece {
        std::array<double, 6> p;
        int depth;
    };
    std::vector<Piece> stack;
    double total = 0;
    std::uint64_t samples = 0;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        Piece root_piece{{}, 0};
        for (unsigned k = 0; k < 3; ++k) {
            root_piece.p[2 * k] = mesh.point(mesh.triangles[3 * t + k])[0];
            root_piece.p[2 * k + 1] = mesh.point(mesh.triangles[3 * t + k])[1];
        }
        stack.push_back(root_piece);
        while (!stack.empty()) {
            const Piece piece = stack.back();
            stack.pop_back();
            const auto& p = piece.p;
            const double cx = (p[0] + p[2] + p[4]) / 3, cy = (p[1] + p[3] + p[5]) / 3;
            std::array<double, 4> sampled = {size(cx, cy), size(p[0], p[1]), size(p[2], p[3]),
                                             size(p[4], p[5])};
            std::sort(sampled.begin(), sampled.end());
            double h = sampled[0];
            samples += 4;
            if (!(h > 0)) return kInfinity;
            const double longest = std::max({std::hypot(p[2] - p[0], p[3] - p[1]),
                                             std::hypot(p[4] - p[2], p[5] - p[3]),
                                             std::hypot(p[0] - p[4], p[1] - p[5])});
            if (piece.depth == 8 || longest <= 8 * h || !std::isfinite(h) ||
                samples > (std::uint64_t{1} << 18)) {
                // A piece stopped by a limit, not by its size, counts at its third smallest
                // sample when the size is steep (graded down to a fine feature at one point,
                // which at most two samples come near: a corner, and the centroid of a sliver
                // piece whose middle corner it is). The smallest made a free vertex 1e-12 off a
                // segment ask for 7e18 triangles; the centroid, a vertex 1e-17 off a hole's side
                // (sliver pieces along the side, centred on it) for 1.7e9 and 4.3e9; a graded
                // dip of that depth needs a few hundred. An underestimate near such a feature,
                // which the budget's slack (100,000 points) covers.
                if (size.is_steep() && !(longest <= 8 * h) && std::isfinite(h)) h = sampled[2];
                // The area in units of h squared (no overflow or underflow).
                const double area = 0.5 * std::fabs((p[2] - p[0]) / h * ((p[5] - p[1]) / h) -
                                                    (p[3] - p[1]) / h * ((p[4] - p[0]) / h));
                total += std::isfinite(h) ? area / kEquilateral : 1.0;
                continue;
            }
            const double a[2] = {0.5 * (p[0] + p[2]), 0.5 * (p[1] + p[3])};
            const double b[2] = {0.5 * (p[2] + p[4]), 0.5 * (p[3] + p[5])};
            const double c[2] = {0.5 * (p[4] + p[0]), 0.5 * (p[5] + p[1])};
            const int depth = piece.depth + 1;
            stack.push_back({{p[0], p[1], a[0], a[1], c[0], c[1]}, depth});
            stack.push_back({{a[0], a[1], p[2], p[3], b[0], b[1]}, depth});
            stack.push_back({{c[0], c[1], b[0], b[1], p[4], p[5]}, depth});
            stack.push_back({{a[0], a[1], b[0], b[1], c[0], c[1]}, depth});
        }
    }
    return total;
}

class AdvancingFront {
  public:
    AdvancingFront(const DomainBoundary2& boundary, const AdvancingFrontDelaunayOptions2& options,
                   AdvancingFrontDelaunayCounters2& counters, std::uint64_t max_new_points)
        : boundary_(boundary),
          options_(options),
          counters_(counters),
          max_new_points_(max_new_points),
          xy_(boundary.xy),
          degree_(boundary.xy.size() / 2, 0),
          points_(root(boundary.xy, 0), root(boundary.xy, 1), root(boundary.xy, 2)),
          edges_tree_(root(boundary.xy, 0), root(boundary.xy, 1), root(boundary.xy, 2)) {
        for (std::size_t e = 0; 2 * e + 1 < boundary.front.size(); ++e)
            add_front_edge(boundary.front[2 * e], boundary.front[2 * e + 1]);
        std::vector<double> hint(degree_.size(), kInfinity);
        for (const FrontEdge& e : edges_) {
            const double l = length(e.a, e.b);
            hint[e.a] = std::min(hint[e.a], l);
            hint[e.b] = std::min(hint[e.b], l);
        }
        for (VertIdx v = 0; v < degree_.size(); ++v) {
            if (degree_[v] > 0) points_.insert(v, point_box(point(v)), hint[v]);
        }
        // The free input vertices are front points without edges (a front loop of length 0):
        // candidates like any front point, and points no triangle may cover (visible), until a
        // triangle takes them in; the closure triangulates the ones left.
        free_.assign(degree_.size(), 0);
        for (const VertIdx v : boundary.free_vertices) {
            const double h = options_.size(point(v)[0], point(v)[1]);
            free_[v] = 1;
            points_.insert(v, point_box(point(v)), std::isfinite(h) && h > 0 ? h : 0.0);
        }
        check_initial_front();
    }

    void run() {
        bool progress = false;
        for (;;) {
            while (!heap_.empty()) {
                const std::uint32_t e = heap_.top().second;
                heap_.pop();
                if (!edges_[e].alive) continue;
                if (counters_.new_points >= max_new_points_) {
                    close_by_cdt();
                    return;
                }
                // A thin triangle (smallest angle below 15 degrees) is taken only when neither
                // the usual attempt nor a wider one with the new point at half height finds a
                // better one.
                if (close_edge(e, 2.0, 1.0, kThinSine) ||
                    (++counters_.widened_searches, close_edge(e, 4.0, 0.5, kThinSine)) ||
                    close_edge(e, 2.0, 1.0, 0.0)) {
                    progress = true;
                } else {
                    ++counters_.postponed_edges;
                    postponed_.push_back(e);
                }
            }
            std::erase_if(postponed_, [&](std::uint32_t e) { return !edges_[e].alive; });
            if (postponed_.empty()) return;
            if (!progress || counters_.rounds >= kMaxRounds) {
                close_by_cdt();
                return;
            }
            ++counters_.rounds;
            for (const std::uint32_t e : postponed_)
                heap_.push({length(edges_[e].a, edges_[e].b), e});
            postponed_.clear();
            progress = false;
        }
    }

    std::vector<double>& xy() { return xy_; }
    std::vector<VertIdx>& triangles() { return triangles_; }

  private:
    static constexpr std::uint64_t kMaxRounds = 1000;
    static constexpr double kThinSine = 0.25881904510252074;  // sin(15 degrees)
    static constexpr double kMaxHeight = 1.4;
    static constexpr double kLaggingFront = 2.0;
    struct FrontEdge {
        VertIdx a, b;
        bool alive;
    };
    /// A candidate apex: a front vertex, or the new point (index = the next vertex number).
    struct Candidate {
        VertIdx v;
        double x, y;
    };

    const DomainBoundary2& boundary_;
    const AdvancingFrontDelaunayOptions2& options_;
    AdvancingFrontDelaunayCounters2& counters_;
    std::uint64_t max_new_points_;
    std::vector<double> xy_;
    std::vector<VertIdx> triangles_;
    std::vector<FrontEdge> edges_;
    std::unordered_map<std::uint64_t, std::uint32_t> edge_of_;
    std::vector<std::uint32_t> degree_;  // live front edges at each vertex
    std::vector<std::uint8_t> free_;     // 1: a free vertex no triangle has taken in yet
    FrontIndex2 points_, edges_tree_;    // the shared loose quadtree (front_index_2d.hpp)
    std::priority_queue<std::pair<double, std::uint32_t>,
                        std::vector<std::pair<double, std::uint32_t>>, std::greater<>>
        heap_;
    std::vector<std::uint32_t> postponed_;
    // The front points and edges whose boxes meet near_ (one query of each per attempt).
    Box near_;
    std::vector<std::uint32_t> near_points_, near_edges_, found_, wide_edges_;
    std::vector<Candidate> candidates_;

    /// The centre and half width of a square around the points (the quadtree's root).
    static double root(const std::vector<double>& xy, int what) {
        Box b;
        for (std::size_t i = 0; i + 1 < xy.size(); i += 2) b.add(xy[i], xy[i + 1]);
        if (what == 0) return 0.5 * b.x0 + 0.5 * b.x1;
        if (what == 1) return 0.5 * b.y0 + 0.5 * b.y1;
        return std::max(0.5 * b.x1 - 0.5 * b.x0, 0.5 * b.y1 - 0.5 * b.y0);
    }
    static Box point_box(const double* p) {
        Box b;
        b.add(p[0], p[1]);
        return b;
    }
    const double* point(VertIdx v) const { return xy_.data() + 2 * std::size_t{v}; }
    double length(VertIdx a, VertIdx b) const {
        return std::hypot(point(b)[0] - point(a)[0], point(b)[1] - point(a)[1]);
    }
    Sign orient(const double* a, const double* b, const double* c) {
        ++counters_.orient_calls;
        return predicates::orient2d(a, b, c);
    }

    void add_front_edge(VertIdx a, VertIdx b) {
        const auto id = static_cast<std::uint32_t>(edges_.size());
        if (!edge_of_.emplace(edge_key(a, b), id).second) {
            throw InternalError("advancing front Delaunay: front edge " + std::to_string(a) +
                                " -> " + std::to_string(b) + " twice");
        }
        edges_.push_back({a, b, true});
        ++degree_[a];
        ++degree_[b];
        Box box = point_box(point(a));
        box.add(point(b)[0], point(b)[1]);
        edges_tree_.insert(id, box, std::max(box.x1 - box.x0, box.y1 - box.y0));
        heap_.push({length(a, b), id});
    }

    void remove_front_edge(std::uint32_t e) {
        FrontEdge& edge = edges_[e];
        edge.alive = false;
        edge_of_.erase(edge_key(edge.a, edge.b));
        edges_tree_.erase(e);
        for (const VertIdx v : {edge.a, edge.b}) {
            if (--degree_[v] == 0) points_.erase(v);
        }
    }

    /// Tries to close front edge e: the new point at `height` times the ideal height, candidates
    /// within `radius` times the new triangle's size of the edge's midpoint.
    bool close_edge(std::uint32_t e, double radius, double height, double thin_sine) {
        const VertIdx a = edges_[e].a, b = edges_[e].b;
        const double ax = point(a)[0], ay = point(a)[1], bx = point(b)[0], by = point(b)[1];
        const double l = std::hypot(bx - ax, by - ay);
        const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
        const double nx = -(by - ay) / l, ny = (bx - ax) / l;  // unit normal into the domain
        // The circumradius bound h / sqrt(3) (an equilateral triangle of the local size h),
        // the size taken at the centroid of the equilateral triangle on ab; the apex on the
        // bisector beyond the circumcentre, its height kept within [l / 2, 1.1 l] (right
        // isosceles to 49 degrees at the apex) so that the triangle is never a sliver; up to
        // kMaxHeight l (39 degrees) where the size is over kLaggingFront times the edge, so that
        // a front behind a fast-growing size catches up (else it meets coarse boundary pieces
        // with fine edges, and the triangles between them are thin).
        double h = checked_size(options_.size, mx + 0.29 * l * nx, my + 0.29 * l * ny);
        if (!std::isfinite(h)) h = l;
        // In units of l (no overflow or underflow of the squares).
        const double r = std::max(h / l / std::sqrt(3.0), 0.5);
        const double highest = h > kLaggingFront * l ? kMaxHeight : 1.1;
        const double height_in_l =
            height * std::clamp(r + std::sqrt(std::max(0.0, r * r - 0.25)), 0.5, highest);
        const double d = height_in_l * l;
        const double side = std::sqrt(height_in_l * height_in_l + 0.25) * l;
        const double px = mx + d * nx, py = my + d * ny;
        const auto new_index = static_cast<VertIdx>(xy_.size() / 2);

        // The new point is a candidate; its placement rule is tested only when it wins (the
        // winner among the others does not depend on whether it was there).
        candidates_.clear();
        if (std::isfinite(px) && std::isfinite(py)) candidates_.push_back({new_index, px, py});
        const double reach = radius * std::max(side, l);
        const double tolerance = options_.placement_tolerance * side;
        near_ = Box{};
        near_.add(mx - reach, my - reach);
        near_.add(mx + reach, my + reach);
        near_.add(px - tolerance, py - tolerance);
        near_.add(px + tolerance, py + tolerance);
        near_points_.clear();
        near_edges_.clear();
        ++counters_.point_queries;
        points_.query(near_, near_points_);
        ++counters_.edge_queries;
        edges_tree_.query(near_, near_edges_);
        for (const VertIdx v : near_points_) {
            if (v == a || v == b) continue;
            const double vx = point(v)[0] - mx, vy = point(v)[1] - my;
            if (!shorter_than(vx, vy, reach)) continue;
            if (orient(point(a), point(b), point(v)) != Sign::Positive) continue;
            candidates_.push_back({v, point(v)[0], point(v)[1]});
        }
        // Tanemura-Merriam: the candidate whose circle through a, b holds no other candidate;
        // one not visible leaves the set and the next is found the same way.
        while (!candidates_.empty()) {
            std::size_t best = 0;
            for (std::size_t k = 1; k < candidates_.size(); ++k) {
                const Candidate& c = candidates_[best];
                const Candidate& d2 = candidates_[k];
                const double pc[2] = {c.x, c.y}, pd[2] = {d2.x, d2.y};
                ++counters_.incircle_calls;
                if (predicates::incircle_sos(point(a), point(b), pc, pd, a, b, c.v, d2.v) ==
                    Sign::Positive)
                    best = k;
            }
            const Candidate c = candidates_[best];
            const bool is_new = c.v == new_index;
            if (is_new && !acceptable_placement(e, px, py, tolerance)) {
                ++counters_.rejected_placements;
            } else if (thin_sine > 0 && smallest_sine(a, b, c) < thin_sine) {
                ++counters_.thin_skipped;
            } else if (visible(e, c, is_new)) {
                form_triangle(e, c, is_new, side);
                return true;
            } else {
                ++counters_.rejected_candidates;
            }
            candidates_[best] = candidates_.back();
            candidates_.pop_back();
        }
        return false;
    }

    /// The sine of the smallest angle of triangle (a, b, c) (double precision: a preference,
    /// not a validity decision).
    double smallest_sine(VertIdx a, VertIdx b, const Candidate& c) const {
        const double* pa = point(a);
        const double* pb = point(b);
        // In units of |ab| (no overflow or underflow of the products).
        const double unit = std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
        const double ux = (pb[0] - pa[0]) / unit, uy = (pb[1] - pa[1]) / unit;
        const double vx = (c.x - pa[0]) / unit, vy = (c.y - pa[1]) / unit;
        const double wx = (c.x - pb[0]) / unit, wy = (c.y - pb[1]) / unit;
        const double ab = std::sqrt(ux * ux + uy * uy), ac = std::sqrt(vx * vx + vy * vy),
                     bc = std::sqrt(wx * wx + wy * wy);
        const double twice_area = std::fabs(ux * vy - uy * vx);
        // The smallest angle is opposite the shortest side: sin = 2 area / (product of the
        // other two).
        const double longest_pair = std::max({ab * ac, ab * bc, ac * bc});
        return longest_pair > 0 ? twice_area / longest_pair : 0.0;
    }

    /// The placement rule (a tolerance, not a validity decision): (px, py) in the domain, no
    /// front point within `tolerance` (placement_tolerance times the new sides' length), no
    /// front edge other than e within half of it. The near lists hold every candidate: near_
    /// contains the box of radius `tolerance` about the point.
    bool acceptable_placement(std::uint32_t e, double px, double py, double tolerance) {
        for (const VertIdx v : near_points_) {
            if (shorter_than(point(v)[0] - px, point(v)[1] - py, tolerance)) return false;
        }
        for (const std::uint32_t f : near_edges_) {
            if (f == e) continue;
            const double* u = point(edges_[f].a);
            const double* w = point(edges_[f].b);
            // In units of the tolerance (no overflow or underflow of the squares).
            const double ux = (u[0] - px) / tolerance, uy = (u[1] - py) / tolerance;
            const double dx = (w[0] - u[0]) / tolerance, dy = (w[1] - u[1]) / tolerance;
            const double t = std::clamp(-(ux * dx + uy * dy) / (dx * dx + dy * dy), 0.0, 1.0);
            if (shorter_than(ux + t * dx, uy + t * dy, 0.5)) return false;
        }
        return in_domain(boundary_, px, py);
    }

    /// Exact: triangle (a, b, c) is counter-clockwise, no front point other than its corners
    /// lies in it (closed), no front edge crosses a side or leaves a corner into it, and a new
    /// point c lies on no front edge. Then the open triangle meets no front edge, and as it
    /// lies left of the front edge ab it is inside the untriangulated region
    /// (proofs/invariants/advancing_front_delaunay_2d.md).
    bool visible(std::uint32_t e, const Candidate& c, bool is_new) {
        const VertIdx a = edges_[e].a, b = edges_[e].b;
        const double* pa = point(a);
        const double* pb = point(b);
        const double pc[2] = {c.x, c.y};
        if (orient(pa, pb, pc) != Sign::Positive) return false;
        Box box = point_box(pa);
        box.add(pb[0], pb[1]);
        box.add(pc[0], pc[1]);
        // The near lists hold every front point and edge whose box meets the triangle's when
        // that box lies in near_ (exact comparisons); otherwise ask the trees again.
        const std::vector<std::uint32_t>* points = &near_points_;
        const std::vector<std::uint32_t>* edges = &near_edges_;
        if (!(near_.x0 <= box.x0 && box.x1 <= near_.x1 && near_.y0 <= box.y0 &&
              box.y1 <= near_.y1)) {
            found_.clear();
            ++counters_.point_queries;
            points_.query(box, found_);
            wide_edges_.clear();
            ++counters_.edge_queries;
            edges_tree_.query(box, wide_edges_);
            points = &found_;
            edges = &wide_edges_;
        }
        for (const VertIdx v : *points) {
            if (v == a || v == b || v == c.v) continue;
            const double* pv = point(v);
            if (pv[0] < box.x0 || pv[0] > box.x1 || pv[1] < box.y0 || pv[1] > box.y1) continue;
            if (orient(pa, pb, pv) != Sign::Negative && orient(pb, pc, pv) != Sign::Negative &&
                orient(pc, pa, pv) != Sign::Negative)
                return false;
        }
        const VertIdx corner[3] = {a, b, c.v};
        const double* corner_point[3] = {pa, pb, pc};
        for (const std::uint32_t f : *edges) {
            if (f == e) continue;
            const VertIdx x = edges_[f].a, y = edges_[f].b;
            const double* px = point(x);
            const double* py = point(y);
            if (std::max(px[0], py[0]) < box.x0 || std::min(px[0], py[0]) > box.x1 ||
                std::max(px[1], py[1]) < box.y0 || std::min(px[1], py[1]) > box.y1)
                continue;
            if (is_new && on_segment(px, py, pc)) return false;
            // Sides b -> c and c -> a (front edges never cross the front edge a -> b).
            for (int k = 1; k < 3; ++k) {
                const int k1 = (k + 1) % 3;
                if (corner[k] == x || corner[k] == y || corner[k1] == x || corner[k1] == y)
                    continue;
                if (cross_properly(px, py, corner_point[k], corner_point[k1])) return false;
            }
            // A front edge leaving a corner into the triangle's open angle there.
            for (int k = 0; k < 3; ++k) {
                const double* other = corner[k] == x ? py : corner[k] == y ? px : nullptr;
                if (other == nullptr) continue;
                const double* next = corner_point[(k + 1) % 3];
                const double* previous = corner_point[(k + 2) % 3];
                if (orient(corner_point[k], next, other) == Sign::Positive &&
                    orient(corner_point[k], previous, other) == Sign::Negative)
                    return false;
            }
        }
        return true;
    }

    /// I2 for the initial front (proofs/invariants/advancing_front_delaunay_2d.md): the pieces
    /// of a triangulation cross nothing, but the boundary's split points are rounded, and beside
    /// a feature at the resolution of doubles one may land on another piece or make its pieces
    /// cross one: no front can close there, so that is reported before any work.
    void check_initial_front() {
        for (std::uint32_t e = 0; e < edges_.size(); ++e) {
            const VertIdx a = edges_[e].a, b = edges_[e].b;
            Box box = point_box(point(a));
            box.add(point(b)[0], point(b)[1]);
            found_.clear();
            points_.query(box, found_);
            for (const VertIdx v : found_) {
                if (v != a && v != b && on_segment(point(a), point(b), point(v))) {
                    throw GeometryError(
                        "advancing front Delaunay: the discretized boundary puts vertex " +
                        std::to_string(v) + " on the piece " + std::to_string(a) + " - " +
                        std::to_string(b) +
                        " (a feature at the resolution of doubles; no front can close there)");
                }
            }
            wide_edges_.clear();
            edges_tree_.query(box, wide_edges_);
            for (const std::uint32_t f : wide_edges_) {
                const VertIdx x = edges_[f].a, y = edges_[f].b;
                if (x == a || x == b || y == a || y == b) continue;
                if (cross_properly(point(a), point(b), point(x), point(y))) {
                    throw GeometryError(
                        "advancing front Delaunay: the discretized boundary's pieces " +
                        std::to_string(a) + " - " + std::to_string(b) + " and " +
                        std::to_string(x) + " - " + std::to_string(y) +
                        " cross (rounded split points beside a feature at the resolution of "
                        "doubles)");
                }
            }
        }
    }

    bool on_segment(const double* u, const double* w, const double* p) {
        if (orient(u, w, p) != Sign::Zero) return false;
        return std::min(u[0], w[0]) <= p[0] && p[0] <= std::max(u[0], w[0]) &&
               std::min(u[1], w[1]) <= p[1] && p[1] <= std::max(u[1], w[1]);
    }

    /// The segments' relative interiors meet in one point (exact).
    bool cross_properly(const double* u, const double* w, const double* p, const double* q) {
        const Sign s1 = orient(p, q, u), s2 = orient(p, q, w);
        if (s1 == Sign::Zero || s2 == Sign::Zero || s1 == s2) return false;
        const Sign s3 = orient(u, w, p), s4 = orient(u, w, q);
        return s3 != Sign::Zero && s4 != Sign::Zero && s3 != s4;
    }

    void form_triangle(std::uint32_t e, const Candidate& c, bool is_new, double side) {
        const VertIdx a = edges_[e].a, b = edges_[e].b;
        if (is_new) {
            xy_.push_back(c.x);
            xy_.push_back(c.y);
            degree_.push_back(0);
            free_.push_back(0);
            points_.insert(c.v, point_box(point(c.v)), side);
            ++counters_.new_points;
        } else {
            ++counters_.existing_points;
            free_[c.v] = 0;
        }
        triangles_.insert(triangles_.end(), {a, b, c.v});
        ++counters_.triangles;
        // Sides b -> c and c -> a: a front edge the same way is closed by the triangle; else
        // the side joins the front, the other way round. Added first, so that no vertex's
        // degree passes through zero while it still has front edges.
        std::uint32_t closed[3] = {e, kNone, kNone};
        const VertIdx side_from[2] = {b, c.v}, side_to[2] = {c.v, a};
        for (int k = 0; k < 2; ++k) {
            const auto it = edge_of_.find(edge_key(side_from[k], side_to[k]));
            if (it != edge_of_.end()) {
                closed[k + 1] = it->second;
            } else {
                add_front_edge(side_to[k], side_from[k]);
            }
        }
        for (const std::uint32_t f : closed) {
            if (f != kNone) remove_front_edge(f);
        }
    }

    /// The remaining front, triangulated by its constrained Delaunay triangulation: the
    /// triangles reached from the left of each front edge without crossing one.
    void close_by_cdt() {
        std::vector<VertIdx> local(degree_.size(), kNone), global;
        std::vector<double> xy;
        std::vector<VertIdx> segments;
        std::unordered_map<std::uint64_t, std::uint32_t> front;  // local directed edges
        for (const FrontEdge& edge : edges_) {
            if (!edge.alive) continue;
            for (const VertIdx v : {edge.a, edge.b}) {
                if (local[v] != kNone) continue;
                local[v] = static_cast<VertIdx>(global.size());
                global.push_back(v);
                xy.insert(xy.end(), {point(v)[0], point(v)[1]});
            }
            front.emplace(edge_key(local[edge.a], local[edge.b]), 0);
            if (!front.count(edge_key(local[edge.b], local[edge.a])))
                segments.insert(segments.end(), {local[edge.a], local[edge.b]});
        }
        counters_.closure_front_edges = front.size();
        if (front.empty()) return;
        // The free vertices not taken in yet lie inside the front (no triangle covers one).
        for (const VertIdx v : boundary_.free_vertices) {
            if (free_[v] == 0) continue;
            local[v] = static_cast<VertIdx>(global.size());
            global.push_back(v);
            xy.insert(xy.end(), {point(v)[0], point(v)[1]});
        }
        tri::Cdt2Options options = domain_cdt_options(options_.cdt);
        options.remove_exterior = false;
        const tri::Cdt2Result closure =
            tri::constrained_delaunay_2d(tri::Pslg{xy, segments, {}, {}}, options);
        const tri::Triangulation2& mesh = closure.mesh;
        if (mesh.vertex_count() != global.size() || closure.counters.duplicates != 0) {
            throw GeometryError(
                "advancing front Delaunay: the remaining front (" + std::to_string(front.size()) +
                " edges) cannot be closed without new points: it touches or crosses itself");
        }
        std::unordered_map<std::uint64_t, tri::TriIdx> triangle_of;
        for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            for (unsigned k = 0; k < 3; ++k)
                triangle_of.emplace(
                    edge_key(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]), t);
        }
        std::vector<std::uint8_t> taken(mesh.triangle_count(), 0);
        std::vector<tri::TriIdx> stack;
        for (const auto& [key, unused] : front) {
            const auto it = triangle_of.find(key);
            if (it == triangle_of.end()) {
                throw InternalError(
                    "advancing front Delaunay: a front edge is missing from its closure");
            }
            if (!taken[it->second]) stack.push_back(it->second), taken[it->second] = 1;
        }
        while (!stack.empty()) {
            const tri::TriIdx t = stack.back();
            stack.pop_back();
            triangles_.insert(triangles_.end(),
                              {global[mesh.triangles[3 * t]], global[mesh.triangles[3 * t + 1]],
                               global[mesh.triangles[3 * t + 2]]});
            ++counters_.closure_triangles;
            for (unsigned k = 0; k < 3; ++k) {
                const VertIdx u = mesh.triangles[3 * t + k],
                              w = mesh.triangles[3 * t + (k + 1) % 3];
                if (mesh.is_constrained(t, static_cast<int>(k))) {
                    if (!front.count(edge_key(u, w))) {
                        throw InternalError(
                            "advancing front Delaunay: the closure crosses the front the wrong "
                            "way");
                    }
                    continue;
                }
                const tri::TriIdx n = mesh.neighbors[3 * t + k];
                if (n == kNone) {
                    throw InternalError(
                        "advancing front Delaunay: the region left of the front is not closed");
                }
                if (!taken[n]) taken[n] = 1, stack.push_back(n);
            }
        }
    }
};

}  // namespace

AdvancingFrontDelaunayResult2 advancing_front_delaunay_2d(
    const tri::Pslg& pslg, const AdvancingFrontDelaunayOptions2& options) {
    return advancing_front_delaunay_2d(MeshDomain2(pslg, options.cdt), options);
}

AdvancingFrontDelaunayResult2 advancing_front_delaunay_2d(
    const MeshDomain2& domain, const AdvancingFrontDelaunayOptions2& options) {
    if (!options.size.bounded()) {
        throw InputError(
            "advancing front Delaunay needs a size function (the target edge length); none was "
            "given");
    }
    if (!(options.placement_tolerance > 0 && options.placement_tolerance < 1)) {
        throw InputError("advancing front Delaunay: placement tolerance " +
                         std::to_string(options.placement_tolerance) + " is not in (0, 1)");
    }
    const DomainBoundary2 boundary =
        discretize_domain_boundary(domain, options.size, options.max_boundary_points);
    AdvancingFrontDelaunayResult2 result;
    std::uint64_t budget = options.max_new_points;
    const std::uint64_t room = std::uint64_t{kNone} / 4 - boundary.xy.size() / 2;
    if (budget == 0) {
        const double estimate = estimated_elements(boundary.cdt.mesh, options.size);
        if (!(estimate <= double{1 << 30})) {
            throw InputError(
                "advancing front Delaunay: the size function asks for about " +
                std::to_string(estimate) +
                " triangles, more than 2^30 (or it is not > 0 somewhere in the domain)");
        }
        budget = static_cast<std::uint64_t>(8 * estimate) + 100000;
    }
    budget = std::min(budget, room);
    AdvancingFront front(boundary, options, result.counters, budget);
    front.run();
    result.mesh = domain_mesh_result(boundary, std::move(front.xy()), std::move(front.triangles()));
    return result;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const AdvancingFrontDelaunayCounters2& c) {
    return counters_by_name(kAdvancingFrontDelaunayCounterNames, c);
}

}  // namespace exactmesh::generators
