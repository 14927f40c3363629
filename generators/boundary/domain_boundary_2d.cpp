// SPDX-License-Identifier: MIT
// The domain's discretized boundary and point-in-domain queries (see domain_boundary_2d.hpp).
// Split points are placed where the chains of different pieces cannot meet: on the piece, or
// strictly inside the triangle (a, b, g) of a domain triangle (a, b, c) beside piece a - b, g its
// rounded centroid (the CDT's triangles are disjoint, and so are the three parts of one), with
// coordinates strictly monotone along the piece (PieceRegion); a sliver too thin for the rounded
// points bends the chain at its third vertex, as ConstrainedTriangulation2 bends a segment at a
// vertex within rounding. Invariants: the pieces form a PSLG whose pieces meet only at shared
// ends, the front has the domain on its left. O(n) for n output points (a few orient2d each,
// 49 more for a point moved); predicates: orient2d only.
#include "generators/boundary/domain_boundary_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/sizing/triangle_subdivision_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using Point = std::array<double, 2>;

namespace {

/// The parameters of `pieces` pieces of equal integral between samples (u, cumulative integral
/// of ds / size at u, increasing), linear between samples; u0 and u1 included.
std::vector<double> equal_integral_parameters(const std::vector<double>& u,
                                              const std::vector<double>& cumulative, int pieces,
                                              double u0, double u1) {
    const double total = cumulative.back();
    std::vector<double> points{u0};
    std::size_t i = 0;
    for (int k = 1; k < pieces; ++k) {
        const double target = total > 0 ? total * k / pieces : 0.0;
        double parameter;
        if (total > 0) {
            while (i + 1 < cumulative.size() && cumulative[i + 1] < target) ++i;
            const double span = cumulative[i + 1] - cumulative[i];
            const double f = span > 0 ? (target - cumulative[i]) / span : 0.0;
            parameter = u[i] + f * (u[i + 1] - u[i]);
        } else {
            parameter = u0 + (u1 - u0) * k / pieces;
        }
        points.push_back(parameter);
    }
    points.push_back(u1);
    return points;
}

/// The refusal of a size that asks for more new boundary points than `max_points`; `where`
/// names the size and place, or the count so far.
BoundaryBudgetError boundary_budget_error(std::uint64_t max_points, const std::string& where) {
    return BoundaryBudgetError("boundary discretization: the size function asks for more than " +
                               std::to_string(max_points) +
                               " boundary points, over the Steiner point budget (" + where +
                               "): give a larger size or raise --max-steiner");
}

/// Where a discretization's integral grows fastest: the sample interval with the most pieces
/// (its length over the size at its middle), named by the refusals.
struct DensestSample {
    double pieces = -1;
    Point p{0, 0};
    double size = 0;

    void offer(double interval_pieces, const Point& at, double size_there) {
        if (interval_pieces > pieces) *this = {interval_pieces, at, size_there};
    }
    std::string where() const {
        return "size " + format_number(size) + " near (" + format_number(p[0]) + ", " +
               format_number(p[1]) + ")";
    }
};

/// BoundaryBudgetError when the integral asks for more than 2^30 pieces (or is not finite), or more
/// new points than `max_points` (a generator's Steiner budget, 0 for none: the pieces less one
/// are the points the curve adds); either names the densest sample so far.
void check_piece_count(double total, const DensestSample& densest, std::uint64_t max_points) {
    if (!std::isfinite(total) || total > double{1 << 30}) {
        throw BoundaryBudgetError(
            "boundary discretization: the size function asks for more than 2^30 pieces on one "
            "curve or segment (" +
            densest.where() + ")");
    }
    if (max_points != 0 && total > static_cast<double>(max_points) + 1)
        throw boundary_budget_error(max_points, densest.where());
}

/// discretize_curve_parameters with a first sample count (doubled until there are 8 samples per
/// piece).
std::vector<double> spaced_parameters(const Curve2& curve, double u0, double u1,
                                      const SizeFunction& size, int min_pieces, int samples,
                                      std::uint64_t max_points = 0) {
    for (;;) {
        std::vector<double> u(static_cast<std::size_t>(samples) + 1), cumulative(u.size(), 0.0);
        Point previous = curve(u0);
        u[0] = u0;
        DensestSample densest;
        for (int i = 1; i <= samples; ++i) {
            const auto index = static_cast<std::size_t>(i);
            u[index] = u0 + (u1 - u0) * i / samples;
            const Point p = curve(u[index]);
            const Point middle{0.5 * (p[0] + previous[0]), 0.5 * (p[1] + previous[1])};
            const double s = size(middle[0], middle[1]);
            const double ds = std::hypot(p[0] - previous[0], p[1] - previous[1]);
            const double pieces = std::isfinite(s) ? ds / s : 0.0;
            densest.offer(pieces, middle, s);
            cumulative[index] = cumulative[index - 1] + pieces;
            previous = p;
        }
        const double total = cumulative.back();
        check_piece_count(total, densest, max_points);
        const int pieces = std::max(min_pieces, static_cast<int>(std::ceil(total - 1e-9)));
        if (pieces * 8 > samples && samples < (1 << 24)) {
            samples = std::min(1 << 24, pieces * 16);
            continue;
        }
        return equal_integral_parameters(u, cumulative, pieces, u0, u1);
    }
}

/// The same spacing with samples where the size needs them: 64 equal intervals, each bisected
/// while it is longer than a quarter of the smallest size at its ends and middle (at most 40
/// times), the integral by the midpoint rule. A size that is small only near one point (a
/// boundary layer's metric along a side that crosses it) costs samples there only, where the
/// uniform sampling above pays for the smallest size over the whole piece.
std::vector<double> adaptive_spaced_parameters(const Curve2& curve, double u0, double u1,
                                               const SizeFunction& size, int min_pieces,
                                               std::uint64_t max_points) {
    struct Sample {
        double u;
        Point p;
        double s;
    };
    const auto sample = [&](double u) {
        const Point p = curve(u);
        return Sample{u, p, size(p[0], p[1])};
    };
    struct Interval {
        Sample a, b;
        int depth;
    };
    std::vector<double> u{u0}, cumulative{0.0};
    DensestSample densest;
    std::vector<Interval> stack;
    constexpr int kStart = 64;
    Sample left = sample(u0);
    for (int i = 1; i <= kStart; ++i) {
        const Sample right = sample(i == kStart ? u1 : u0 + (u1 - u0) * i / kStart);
        // Each start interval is refined, left to right, before the next one.
        stack.push_back({left, right, 0});
        while (!stack.empty()) {
            const Interval in = stack.back();
            stack.pop_back();
            const Sample mid = sample(0.5 * (in.a.u + in.b.u));
            const double length = std::hypot(in.b.p[0] - in.a.p[0], in.b.p[1] - in.a.p[1]);
            const double smallest = std::min({in.a.s, mid.s, in.b.s});
            if (in.depth < 40 && length > 0.25 * smallest && mid.u > in.a.u && mid.u < in.b.u) {
                stack.push_back({mid, in.b, in.depth + 1});
                stack.push_back({in.a, mid, in.depth + 1});
                continue;
            }
            u.push_back(in.b.u);
            const double pieces = std::isfinite(mid.s) ? length / mid.s : 0.0;
            densest.offer(pieces, mid.p, mid.s);
            cumulative.push_back(cumulative.back() + pieces);
            // Over the budget as the integral grows: each sample costs a size evaluation (a
            // background mesh's point location), so a size asking for millions of points is
            // refused at the budget, not after 2^24 samples (fuzz_adaptation_2d,
            // tests/data/fuzz/adaptation_2d_oom_narrow.bin: 87 s). Without a budget the 2^30
            // pieces' limit holds the same way: a segment 1e300 long at a size of 0.2 was
            // refused only after 2^24 samples (3.4 s, 400 MB).
            check_piece_count(cumulative.back(), densest, max_points);
            // A size far below its values at the start intervals' ends would bisect for minutes
            // before the piece count's check: the samples are capped as the uniform sampling's.
            if (u.size() > std::size_t{1} << 24) {
                throw BoundaryBudgetError(
                    "boundary discretization: the size function needs more than 2^24 samples on "
                    "one curve or segment (size " +
                    format_number(mid.s) + " near (" + format_number(mid.p[0]) + ", " +
                    format_number(mid.p[1]) + "))");
            }
        }
        left = right;
        check_piece_count(cumulative.back(), densest, max_points);
    }
    const int pieces = std::max(min_pieces, static_cast<int>(std::ceil(cumulative.back() - 1e-9)));
    return equal_integral_parameters(u, cumulative, pieces, u0, u1);
}

std::uint64_t edge_key(tri::VertIdx a, tri::VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

std::uint64_t undirected_key(tri::VertIdx a, tri::VertIdx b) {
    return a < b ? edge_key(a, b) : edge_key(b, a);
}

predicates::Sign orient(const double* a, const double* b, const double* c) {
    return predicates::orient2d(a, b, c);
}

/// The spacing of doubles at the larger magnitude of u and v (at least the smallest subnormal).
double unit_in_last_place(double u, double v) {
    const double m = std::max(std::abs(u), std::abs(v));
    return std::max(std::nextafter(m, std::numeric_limits<double>::infinity()) - m,
                    std::numeric_limits<double>::denorm_min());
}

/// Where the split points of one boundary piece a - b may go so that the discretized boundary
/// stays a valid PSLG: on the open segment a - b, or strictly inside the triangle (a, b, g) of a
/// domain triangle (a, b, c) beside the piece, g its rounded centroid (when strictly inside it;
/// else that side holds no split point). Those open triangles are pairwise disjoint over all
/// pieces (the CDT's triangles do not overlap; the three of one triangle share only g's spokes),
/// so the chains of different pieces meet only at their ends; a chain whose coordinate along
/// the piece's longer axis is strictly monotone is simple; a link from one side to the other
/// crosses the line a - b strictly between a and b. Every test is an exact orient2d sign.
/// Every split point is also within rounding of the piece's input segment s0 - s1
/// (predicates::within_rounding_of_segment, the chain rule of the exact checks): a point the
/// interpolation left farther off is first replaced by its chain_point.
class PieceRegion {
  public:
    /// left_c, right_c: the third vertex of the domain triangle on the left of a -> b (on its
    /// right), or nullptr; s0, s1: the ends of the input segment the piece lies on.
    PieceRegion(const Point& a, const Point& b, const double* left_c, const double* right_c,
                const double* s0, const double* s1)
        : a_(a), b_(b), s0_(s0), s1_(s1) {
        axis_ = std::abs(b[0] - a[0]) >= std::abs(b[1] - a[1]) ? 0 : 1;
        increasing_ = b[axis_] > a[axis_];
        step_ = {unit_in_last_place(a[0], b[0]), unit_in_last_place(a[1], b[1])};
        corner(0, a_, b_, left_c);
        corner(1, b_, a_, right_c);
    }

    /// The inner points of `points` (points.front() is a, points.back() b), each moved by at
    /// most 3 units in the last place of the ends' coordinates (step_) into the region when it
    /// rounded outside; a point that no such move places is left out (a longer piece there)
    /// and counted in `missed`.
    std::vector<Point> place(const std::vector<Point>& points, std::size_t& missed) const {
        std::vector<Point> kept;
        Point last = a_;
        int last_side = 0;
        missed = 0;
        for (std::size_t k = 1; k + 1 < points.size(); ++k) {
            const std::optional<Point> chained = chain_point(points[k], s0_, s1_);
            const Point p = chained ? *chained : points[k];  // off the chain: only moves remain
            bool placed = false;
            for (int ring = 0; ring <= 3 && !placed && std::isfinite(p[0]) && std::isfinite(p[1]);
                 ++ring) {
                for (int i = -ring; i <= ring && !placed; ++i) {
                    for (int j = -ring; j <= ring && !placed; ++j) {
                        if (std::max(std::abs(i), std::abs(j)) != ring) continue;
                        const Point q = moved(p.data(), i, j);
                        if (!std::isfinite(q[0]) || !std::isfinite(q[1])) continue;
                        if (!before(last, q) || !before(q, b_) || !on_segment(q)) continue;
                        const int s = side(q);
                        if (s == kNowhere || !links(last, last_side, q, s)) continue;
                        kept.push_back(q);
                        last = q;
                        last_side = s;
                        placed = true;
                    }
                }
            }
            if (!placed) ++missed;
        }
        return kept;  // the link to b is always valid: b is a corner of both regions
    }

    /// p strictly between a and b along the piece's longer axis, and within 3 steps per
    /// coordinate (step_) of a point on the line a - b or beyond it from the given side (exact).
    bool hugs(const double* p, bool from_left) const {
        const Point q{p[0], p[1]};
        if (!before(a_, q) || !before(q, b_)) return false;
        const predicates::Sign side =
            from_left ? predicates::Sign::Positive : predicates::Sign::Negative;
        for (int i = -3; i <= 3; ++i) {
            for (int j = -3; j <= 3; ++j) {
                const Point r = moved(p, i, j);
                if (std::isfinite(r[0]) && std::isfinite(r[1]) &&
                    orient(a_.data(), b_.data(), r.data()) != side)
                    return true;
            }
        }
        return false;
    }

  private:
    static constexpr int kNowhere = 2;
    Point a_, b_;
    const double* s0_;
    const double* s1_;
    std::array<Point, 2> g_{};
    std::array<bool, 2> has_{false, false};
    std::array<double, 2> step_{};  // the spacing of doubles at the piece's ends
    std::size_t axis_ = 0;
    bool increasing_ = true;

    bool on_segment(const Point& p) const {
        return predicates::within_rounding_of_segment(p.data(), s0_, s1_);
    }

    /// p moved by i, j steps (rounded; whatever it gives is tested exactly).
    Point moved(const double* p, int i, int j) const {
        return {p[0] + i * step_[0], p[1] + j * step_[1]};
    }

    void corner(std::size_t which, const Point& u, const Point& v, const double* c) {
        if (c == nullptr) return;
        g_[which] = {u[0] / 3 + v[0] / 3 + c[0] / 3, u[1] / 3 + v[1] / 3 + c[1] / 3};
        const double* g = g_[which].data();
        has_[which] = orient(u.data(), v.data(), g) == predicates::Sign::Positive &&
                      orient(v.data(), c, g) == predicates::Sign::Positive &&
                      orient(c, u.data(), g) == predicates::Sign::Positive;
    }

    /// p strictly before q along the piece's longer axis.
    bool before(const Point& p, const Point& q) const {
        return increasing_ ? p[axis_] < q[axis_] : p[axis_] > q[axis_];
    }

    /// 0 on the line a - b (strictly between a and b when the caller checked `before`), 1 in
    /// the left open triangle, -1 in the right one, else kNowhere.
    int side(const Point& p) const {
        using predicates::Sign;
        const Sign o = orient(a_.data(), b_.data(), p.data());
        if (o == Sign::Zero) return 0;
        if (o == Sign::Positive) {
            return has_[0] && orient(b_.data(), g_[0].data(), p.data()) == Sign::Positive &&
                           orient(g_[0].data(), a_.data(), p.data()) == Sign::Positive
                       ? 1
                       : kNowhere;
        }
        return has_[1] && orient(a_.data(), g_[1].data(), p.data()) == Sign::Positive &&
                       orient(g_[1].data(), b_.data(), p.data()) == Sign::Positive
                   ? -1
                   : kNowhere;
    }

    /// The link p - q stays in the region: within one side, or across the open segment a - b.
    bool links(const Point& p, int p_side, const Point& q, int q_side) const {
        if (p_side * q_side != -1) return true;
        const predicates::Sign sa = orient(p.data(), q.data(), a_.data()),
                               sb = orient(p.data(), q.data(), b_.data());
        return sa != predicates::Sign::Zero && sb != predicates::Sign::Zero && sa != sb;
    }
};

/// The vertex of triangle t other than u and v.
tri::VertIdx third_vertex(const tri::Triangulation2& mesh, tri::TriIdx t, tri::VertIdx u,
                          tri::VertIdx v) {
    for (unsigned k = 0; k < 3; ++k) {
        const tri::VertIdx w = mesh.triangles[3 * t + k];
        if (w != u && w != v) return w;
    }
    throw InternalError("boundary discretization: a degenerate triangle");
}

}  // namespace

std::vector<Point> discretize_curve(const Curve2& curve, double u0, double u1,
                                    const SizeFunction& size, int min_pieces) {
    std::vector<Point> points;
    for (const double u : spaced_parameters(curve, u0, u1, size, min_pieces, 4096))
        points.push_back(curve(u));
    return points;
}

std::vector<double> discretize_curve_parameters(const Curve2& curve, double u0, double u1,
                                                const SizeFunction& size, int min_pieces) {
    return spaced_parameters(curve, u0, u1, size, min_pieces, 4096);
}

namespace {

/// Size evaluations of one expected_triangle_count past which no triangle is split further
/// (each then counts at its own corners' and centroid's smallest size). A size on a background
/// mesh of coordinates from 1e-169 to 1e179 is a point location by GMP orientation tests: a
/// fuzzed local remeshing case spent 37 s here, 4^8 splits of each of its domain triangles.
constexpr std::uint64_t kEstimateEvaluations = std::uint64_t{1} << 18;

/// expected_triangle_count on one triangle (p, q, r), splitting it as documented there (depth
/// first on an explicit stack: subdivision_sum_2d); `evaluations` counts the size evaluations
/// of the whole count.
double triangle_estimate(const SizeFunction& size, const std::array<double, 2>& p,
                         const std::array<double, 2>& q, const std::array<double, 2>& r,
                         std::uint64_t& evaluations) {
    using Point = std::array<double, 2>;
    using Node = std::array<Point, 3>;
    const auto visit = [&](const Node& n, int depth,
                           std::array<Node, 4>& children) -> std::optional<double> {
        const auto& [a, b, c] = n;
        evaluations += 4;
        const double h = std::min({size(a[0], a[1]), size(b[0], b[1]), size(c[0], c[1]),
                                   size((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3)});
        if (!(h > 0) || !std::isfinite(h)) return 0.0;
        // Lengths scaled exactly by the power of two that brings h to [1, 2): no product
        // overflows or underflows at any scale, and the count is the same at every scale.
        const int shift = -std::ilogb(h);
        const auto scaled = [shift](double d) { return std::ldexp(d, shift); };
        const double area = 0.5 * std::fabs(scaled(b[0] - a[0]) * scaled(c[1] - a[1]) -
                                            scaled(b[1] - a[1]) * scaled(c[0] - a[0]));
        if (!(area > 0)) return 0.0;
        const double scaled_h = scaled(h);
        const double width =
            std::max({std::hypot(b[0] - a[0], b[1] - a[1]), std::hypot(c[0] - b[0], c[1] - b[1]),
                      std::hypot(a[0] - c[0], a[1] - c[1])});
        const double count = area / (0.43 * scaled_h * scaled_h);
        if (depth >= 8 || width <= 8 * h || count <= 16 || evaluations >= kEstimateEvaluations)
            return count;
        const auto mid = [](const Point& u, const Point& v) {
            return Point{0.5 * u[0] + 0.5 * v[0], 0.5 * u[1] + 0.5 * v[1]};
        };
        const Point ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
        children = {Node{a, ab, ca}, Node{ab, b, bc}, Node{ca, bc, c}, Node{ab, bc, ca}};
        return std::nullopt;
    };
    return subdivision_sum_2d(Node{p, q, r}, visit);
}

}  // namespace

double expected_triangle_count(const DomainBoundary2& boundary, const SizeFunction& size) {
    if (!size.bounded()) return 0;
    const tri::Triangulation2& mesh = boundary.cdt.mesh;
    double estimate = 0;
    std::uint64_t evaluations = 0;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        std::array<std::array<double, 2>, 3> corner;
        for (unsigned k = 0; k < 3; ++k) {
            const double* p = mesh.point(mesh.triangles[3 * t + k]);
            corner[k] = {p[0], p[1]};
        }
        estimate += triangle_estimate(size, corner[0], corner[1], corner[2], evaluations);
    }
    return estimate;
}

BoundarySpacing boundary_spacing(const tri::Cdt2Result& domain) {
    const tri::Triangulation2& mesh = domain.mesh;
    const std::size_t n = mesh.vertex_count();
    auto length = [&](tri::VertIdx a, tri::VertIdx b) {
        return predicates::scale_free_norm(mesh.xy[2 * b] - mesh.xy[2 * a],
                                           mesh.xy[2 * b + 1] - mesh.xy[2 * a + 1]);
    };
    // The summed length and count of the pieces at each vertex, then of all its edges. No sum
    // overflows for coordinates below 2^900 (fewer than 2^32 terms, each below 2^902).
    std::vector<double> piece_sum(n, 0), edge_sum(n, 0);
    std::vector<std::uint32_t> piece_count(n, 0), edge_count(n, 0);
    BoundarySpacing spacing{std::vector<double>(n, 0),
                            std::vector<double>(n, std::numeric_limits<double>::infinity())};
    for (std::size_t p = 0; p + 1 < domain.pieces.size(); p += 2) {
        const double l = length(domain.pieces[p], domain.pieces[p + 1]);
        for (const tri::VertIdx v : {domain.pieces[p], domain.pieces[p + 1]}) {
            piece_sum[v] += l;
            ++piece_count[v];
        }
    }
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const tri::VertIdx a = mesh.triangles[e];
        const tri::VertIdx b = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
        const double l = length(a, b);
        edge_sum[a] += l;
        ++edge_count[a];
        spacing.shortest[a] = std::min(spacing.shortest[a], l);
        spacing.shortest[b] = std::min(spacing.shortest[b], l);
    }
    for (std::size_t v = 0; v < n; ++v) {
        if (piece_count[v] > 0)
            spacing.mean[v] = piece_sum[v] / piece_count[v];
        else if (edge_count[v] > 0)
            spacing.mean[v] = edge_sum[v] / edge_count[v];
    }
    return spacing;
}

SizeFunction size_from_boundary(const tri::Pslg& pslg, const tri::Cdt2Options& cdt) {
    tri::Cdt2Options options = cdt;
    options.remove_exterior = true;
    const tri::Cdt2Result domain = tri::constrained_delaunay_2d(pslg, options);
    const tri::Triangulation2& mesh = domain.mesh;
    if (mesh.triangle_count() == 0) throw InputError("the segments enclose no region");
    const std::size_t n = mesh.vertex_count();
    const BoundarySpacing spacing = boundary_spacing(domain);
    // The background mesh holds the vertices some triangle uses (merged duplicates and points
    // outside the domain are left out), renumbered densely.
    std::vector<std::uint32_t> dense(n, tri::kNone);
    std::vector<double> xy, sizes;
    std::vector<std::uint32_t> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const tri::VertIdx v : mesh.triangles) {
        if (dense[v] == tri::kNone) {
            dense[v] = static_cast<std::uint32_t>(sizes.size());
            xy.insert(xy.end(), {mesh.xy[2 * v], mesh.xy[2 * v + 1]});
            sizes.push_back(spacing.mean[v]);
        }
        triangles.push_back(dense[v]);
    }
    return SizeFunction::background_mesh(std::move(xy), std::move(sizes), std::move(triangles));
}

std::optional<std::array<double, 2>> chain_point(const std::array<double, 2>& p, const double* s0,
                                                 const double* s1) {
    if (predicates::within_rounding_of_segment(p.data(), s0, s1)) return p;
    if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return std::nullopt;
    const std::size_t axis = std::abs(s1[0] - s0[0]) >= std::abs(s1[1] - s0[1]) ? 0 : 1;
    const std::size_t other = 1 - axis;
    if (!(std::min(s0[axis], s1[axis]) < p[axis] && p[axis] < std::max(s0[axis], s1[axis])))
        return std::nullopt;
    std::array<double, 2> q = p;
    if (s0[other] == s1[other]) {
        q[other] = s0[other];
    } else {
        double c[2], d[2];
        c[axis] = d[axis] = p[axis];
        c[other] = std::min(s0[other], s1[other]);
        d[other] = std::max(s0[other], s1[other]);
        try {
            q = predicates::segment_intersection(s0, s1, c, d);
        } catch (const GeometryError&) {
            return std::nullopt;  // a difference beyond the double range
        }
    }
    if (!predicates::within_rounding_of_segment(q.data(), s0, s1)) return std::nullopt;
    return q;
}

std::vector<triangulation::VertIdx> piece_lines(const DomainBoundary2& boundary) {
    std::vector<triangulation::VertIdx> lines;
    lines.reserve(boundary.pieces.size());
    for (const std::uint32_t s : boundary.piece_segment) {
        lines.push_back(boundary.input_segments[2 * std::size_t{s}]);
        lines.push_back(boundary.input_segments[2 * std::size_t{s} + 1]);
    }
    return lines;
}

bool in_domain(const DomainBoundary2& boundary, double x, double y) {
    return boundary.locator.locate(boundary.cdt.mesh, x, y) != tri::kNone;
}

DomainBoundary2 discretize_domain_boundary(const tri::Pslg& pslg, const SizeFunction& size,
                                           const tri::Cdt2Options& cdt_options) {
    return discretize_domain_boundary(MeshDomain2(pslg, cdt_options), size);
}

namespace {
DomainBoundary2 discretize(const MeshDomain2& domain, const PieceSizeFunction& piece_size,
                           bool adaptive, std::uint64_t max_points);
}  // namespace

void restore_input_terms(const DomainBoundary2& boundary, tri::Cdt2Result& mesh) {
    for (std::uint32_t& s : mesh.piece_segment) s = boundary.piece_segment[s];
    // The constrained triangulation of the boundary's pieces may bend a piece at a vertex within
    // the rounding of the piece but not of its input segment (features finer than doubles
    // resolve, hundreds of binades apart): the exact checks would reject the segment's chain.
    // Refused here instead of returning that mesh.
    const std::span<const tri::VertIdx> segments = boundary.input_segments;
    for (std::size_t p = 0; p < mesh.piece_segment.size(); ++p) {
        const std::uint32_t s = mesh.piece_segment[p];
        const double* s0 = mesh.mesh.point(segments[2 * std::size_t{s}]);
        const double* s1 = mesh.mesh.point(segments[2 * std::size_t{s} + 1]);
        for (const tri::VertIdx w : {mesh.pieces[2 * p], mesh.pieces[2 * p + 1]}) {
            if (w == segments[2 * std::size_t{s}] || w == segments[2 * std::size_t{s} + 1] ||
                predicates::within_rounding_of_segment(mesh.mesh.point(w), s0, s1))
                continue;
            throw GeometryError(
                "segment " + std::to_string(s + boundary.first_index) +
                " would run through vertex " + std::to_string(w + boundary.first_index) + " at (" +
                format_number(mesh.mesh.point(w)[0]) + ", " + format_number(mesh.mesh.point(w)[1]) +
                "), off it by more than its rounding: features finer than "
                "doubles resolve there");
        }
    }
    mesh.input_vertex_count = boundary.input_vertex_count;
    mesh.merged_into = boundary.cdt.merged_into;
    mesh.warnings = boundary.cdt.warnings;
    const std::uint64_t flips = mesh.counters.delaunay_flips;
    mesh.counters = boundary.cdt.counters;
    mesh.counters.delaunay_flips += flips;
}

DomainBoundary2 discretize_domain_boundary(const MeshDomain2& domain, const SizeFunction& size,
                                           std::uint64_t max_points) {
    // A steep size (graded down to fine features) is sampled adaptively: the uniform samples,
    // about 16 per piece at the ends' sizes, step over a dip to 1e-12 beside a free vertex.
    return discretize(
        domain, [&size](const double*, const double*) { return size; }, size.is_steep(),
        max_points);
}

DomainBoundary2 discretize_domain_boundary(const MeshDomain2& domain,
                                           const PieceSizeFunction& piece_size,
                                           std::uint64_t max_points) {
    return discretize(domain, piece_size, true, max_points);
}

namespace {

DomainBoundary2 discretize(const MeshDomain2& domain, const PieceSizeFunction& piece_size,
                           bool adaptive, std::uint64_t max_points) {
    const tri::Pslg& pslg = domain.pslg();
    const tri::Cdt2Options& options = domain.domain_options();
    DomainBoundary2 boundary;
    boundary.cdt = domain.triangulation();
    const tri::Triangulation2& mesh = boundary.cdt.mesh;
    if (mesh.triangle_count() == 0) {
        throw InputError(
            "the segments enclose no region (every triangle is outside the segments or in a hole)");
    }
    boundary.xy = mesh.xy;
    boundary.input_vertex_count = boundary.cdt.input_vertex_count;
    boundary.input_segments.assign(pslg.segments.begin(), pslg.segments.end());
    boundary.first_index = options.first_index;
    // Directed edge -> the (domain) triangle on its left.
    std::unordered_map<std::uint64_t, tri::TriIdx> directed;
    directed.reserve(mesh.triangles.size());
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k)
            directed.emplace(
                edge_key(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]), t);
    }
    const auto left_of = [&](tri::VertIdx u, tri::VertIdx v) {
        const auto found = directed.find(edge_key(u, v));
        return found == directed.end() ? tri::kNone : found->second;
    };
    const auto& pieces = boundary.cdt.pieces;
    // The CDT's pieces and the sides of the triangles bent around (below), undirected; the
    // triangles bent around (left out of the discretized domain).
    std::unordered_set<std::uint64_t> piece_keys;
    piece_keys.reserve(pieces.size());
    for (std::size_t p = 0; 2 * p + 1 < pieces.size(); ++p)
        piece_keys.insert(undirected_key(pieces[2 * p], pieces[2 * p + 1]));
    std::vector<bool> bent_around(mesh.triangle_count(), false);

    std::uint64_t placed = 0;  // new boundary points so far (max_points)
    // Points along u - v spaced by the size (ends included); the first sample count estimated
    // from the sizes at the ends and the middle.
    const auto spaced = [&](tri::VertIdx u, tri::VertIdx v, std::uint32_t segment) {
        const Point pa{mesh.point(u)[0], mesh.point(u)[1]}, pb{mesh.point(v)[0], mesh.point(v)[1]};
        const SizeFunction size = piece_size(mesh.point(u), mesh.point(v));
        // Linear interpolation (the difference of the ends taken as two products when it
        // overflows: ends near the largest double).
        const auto offset = [](double from, double to, double t) {
            const double d = to - from;
            return std::isfinite(d) ? t * d : t * to - t * from;
        };
        const Curve2 line = [&](double t) {
            return t == 1.0
                       ? pb
                       : Point{pa[0] + offset(pa[0], pb[0], t), pa[1] + offset(pa[1], pb[1], t)};
        };
        const double length = std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
        const double smallest = std::min({size(pa[0], pa[1]), size(pb[0], pb[1]),
                                          size(0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]))});
        const double estimate = std::isfinite(smallest) ? length / smallest : 0.0;
        // A steep size's smallest sample (at a fine feature's end) says nothing of its
        // integral: the adaptive sampling counts the pieces itself.
        if (!adaptive && !(estimate <= double{1 << 30})) {
            throw BoundaryBudgetError(
                "boundary discretization: the size function asks for more than 2^30 pieces on "
                "segment " +
                std::to_string(segment + options.first_index) + " (size " +
                format_number(smallest) + " along a length " + format_number(length) + ")");
        }
        const int samples = static_cast<int>(std::clamp(16 * estimate + 16, 16.0, double{1 << 24}));
        std::vector<Point> points;
        const std::vector<double> parameters =
            adaptive ? adaptive_spaced_parameters(line, 0.0, 1.0, size, 1, max_points)
                     : spaced_parameters(line, 0.0, 1.0, size, 1, samples, max_points);
        for (const double t : parameters) points.push_back(line(t));
        // The points of every piece so far against the budget (each piece's sampling stops at
        // the whole budget).
        placed += points.size() - 2;
        if (max_points != 0 && placed > max_points) {
            throw boundary_budget_error(max_points,
                                        std::to_string(placed) + " by segment " +
                                            std::to_string(segment + options.first_index));
        }
        return points;
    };
    const auto append = [&](std::vector<tri::VertIdx>& chain, const std::vector<Point>& kept) {
        for (const Point& q : kept) {
            chain.push_back(static_cast<tri::VertIdx>(boundary.xy.size() / 2));
            boundary.xy.push_back(q[0]);
            boundary.xy.push_back(q[1]);
        }
    };

    // The chain rule of the exact checks (check_constrained_delaunay_2d, the conforming
    // check): a bend at c is a chain u -> c -> v of the input segment only when c is within
    // rounding of the segment and neither step moves against it. `hugs` measures 3 units in
    // the last place of the piece's ends, which can be far coarser than c's own rounding (a
    // subnormal c beside a segment ending at 0.6: fuzz_mesh_generators_2d, CI 2026-12-02).
    const auto segment_end = [&](std::uint32_t segment, std::size_t end) {
        return mesh.point(pslg.segments[2 * std::size_t{segment} + end]);
    };
    const auto on_chain = [&](tri::VertIdx c, tri::VertIdx u, tri::VertIdx v,
                              std::uint32_t segment) {
        const double* s0 = segment_end(segment, 0);
        const double* s1 = segment_end(segment, 1);
        return predicates::within_rounding_of_segment(mesh.point(c), s0, s1) &&
               predicates::direction_dot_sign(mesh.point(u), mesh.point(c), s0, s1) !=
                   predicates::Sign::Negative &&
               predicates::direction_dot_sign(mesh.point(c), mesh.point(v), s0, s1) !=
                   predicates::Sign::Negative;
    };
    std::vector<tri::VertIdx> chain;
    struct Part {
        tri::VertIdx u, v;
        tri::TriIdx left;  // the domain triangle beside u - v
    };
    std::vector<Part> parts;
    for (std::size_t p = 0; 2 * p + 1 < pieces.size(); ++p) {
        const tri::VertIdx a = pieces[2 * p], b = pieces[2 * p + 1];
        const std::uint32_t segment = boundary.cdt.piece_segment[p];
        const tri::TriIdx left_triangle = left_of(a, b), right_triangle = left_of(b, a);
        const bool left = left_triangle != tri::kNone, right = right_triangle != tri::kNone;
        chain.assign(1, a);
        if (left && right) {
            // A slit: split points on either side, across the piece.
            const std::vector<Point> points = spaced(a, b, segment);
            if (points.size() > 2) {
                const PieceRegion region(points.front(), points.back(),
                                         mesh.point(third_vertex(mesh, left_triangle, a, b)),
                                         mesh.point(third_vertex(mesh, right_triangle, b, a)),
                                         segment_end(segment, 0), segment_end(segment, 1));
                std::size_t missed = 0;
                append(chain, region.place(points, missed));
            }
            chain.push_back(b);
        } else if (left || right) {
            // The domain on one side: split points on the piece or on that side. When some
            // point cannot be placed (the triangle there is a sliver: its third vertex c lies
            // within 3 units in the last place of the piece's line, between its ends; hugs)
            // the chain bends at c instead, as
            // ConstrainedTriangulation2 bends a segment at a vertex within rounding of it, and
            // continues along the triangle's other sides (the sliver is left out); that needs
            // c's sides free (no piece, no other bend) and the triangles beyond them unbent.
            // Parts run from a to b; the domain triangle of part u -> v is on the left of u -> v
            // when the piece's is on the left of a -> b, else on its right.
            const auto domain_triangle = [&](tri::VertIdx u, tri::VertIdx v) {
                return left ? left_of(u, v) : left_of(v, u);
            };
            parts.assign(1, Part{a, b, left ? left_triangle : right_triangle});
            while (!parts.empty()) {
                const Part part = parts.back();
                parts.pop_back();
                const std::vector<Point> points = spaced(part.u, part.v, segment);
                if (points.size() > 2) {
                    const tri::VertIdx c = left ? third_vertex(mesh, part.left, part.u, part.v)
                                                : third_vertex(mesh, part.left, part.v, part.u);
                    const PieceRegion region(points.front(), points.back(),
                                             left ? mesh.point(c) : nullptr,
                                             left ? nullptr : mesh.point(c),
                                             segment_end(segment, 0), segment_end(segment, 1));
                    std::size_t missed = 0;
                    std::vector<Point> kept = region.place(points, missed);
                    const tri::TriIdx before_c = domain_triangle(part.u, c),
                                      after_c = domain_triangle(c, part.v);
                    if (missed > 0 && before_c != tri::kNone && after_c != tri::kNone &&
                        !bent_around[part.left] && !bent_around[before_c] &&
                        !bent_around[after_c] && !piece_keys.count(undirected_key(part.u, c)) &&
                        !piece_keys.count(undirected_key(c, part.v)) &&
                        region.hugs(mesh.point(c), left) && on_chain(c, part.u, part.v, segment)) {
                        bent_around[part.left] = true;
                        piece_keys.insert(undirected_key(part.u, c));
                        piece_keys.insert(undirected_key(c, part.v));
                        parts.push_back(Part{c, part.v, after_c});
                        parts.push_back(Part{part.u, c, before_c});
                        continue;
                    }
                    append(chain, kept);
                }
                chain.push_back(part.v);
            }
        } else {
            chain.push_back(b);  // outside the domain (a dangling segment in a hole): kept whole
        }
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
            boundary.pieces.insert(boundary.pieces.end(), {chain[k], chain[k + 1]});
            boundary.piece_segment.push_back(segment);
            if (left) {
                boundary.front.insert(boundary.front.end(), {chain[k], chain[k + 1]});
                boundary.front_segment.push_back(segment);
            }
            if (right) {
                boundary.front.insert(boundary.front.end(), {chain[k + 1], chain[k]});
                boundary.front_segment.push_back(segment);
            }
        }
    }
    if (boundary.xy.size() / 2 > std::uint64_t{tri::kNone} / 4) {
        throw InputError("boundary discretization: " + std::to_string(boundary.xy.size() / 2) +
                         " boundary points, too many for 32-bit vertex numbers");
    }
    // Vertices of domain triangles that no front edge reaches.
    std::vector<std::uint8_t> on_front(boundary.xy.size() / 2, 0);
    for (const tri::VertIdx v : boundary.front) on_front[v] = 1;
    for (const tri::VertIdx v : mesh.triangles) {
        if (on_front[v] == 0) {
            on_front[v] = 1;
            boundary.free_vertices.push_back(v);
        }
    }
    std::sort(boundary.free_vertices.begin(), boundary.free_vertices.end());
    boundary.locator = DomainLocator2(boundary.cdt.mesh);
    return boundary;
}

}  // namespace

}  // namespace exactmesh::generators
