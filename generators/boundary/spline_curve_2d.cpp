// SPDX-License-Identifier: MIT
// Cubic splines and spline domains (see spline_curve_2d.hpp). On segment i (h = u_{i+1} - u_i,
// t = (u - u_i) / h) with second derivatives M_i, M_{i+1} at its ends:
//   S(t) = (1 - t) P_i + t P_{i+1} + h^2 / 6 [((1 - t)^3 - (1 - t)) M_i + (t^3 - t) M_{i+1}],
// which is P_i at t = 0 and P_{i+1} at t = 1 exactly (the bracket's terms vanish exactly), and
// C2 when h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1}) at every
// inner knot (d_i = (P_{i+1} - P_i) / h_i), cyclically for a closed spline.
#include "generators/boundary/spline_curve_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;
using Point = std::array<double, 2>;

namespace {

/// Solves the tridiagonal system (sub a, diagonal b, super c; a[0], c[n-1] unused) for `count`
/// right-hand sides stored interleaved in rhs (rhs[count * i + k]); diagonally dominant, so no
/// pivoting (Thomas).
void solve_tridiagonal(const std::vector<double>& a, const std::vector<double>& b,
                       const std::vector<double>& c, std::vector<double>& rhs, std::size_t count) {
    const std::size_t n = b.size();
    std::vector<double> cp(n);
    double pivot = b[0];
    cp[0] = c[0] / pivot;
    for (std::size_t k = 0; k < count; ++k) rhs[k] /= pivot;
    for (std::size_t i = 1; i < n; ++i) {
        pivot = b[i] - a[i] * cp[i - 1];
        cp[i] = i + 1 < n ? c[i] / pivot : 0.0;
        for (std::size_t k = 0; k < count; ++k)
            rhs[count * i + k] = (rhs[count * i + k] - a[i] * rhs[count * (i - 1) + k]) / pivot;
    }
    for (std::size_t i = n - 1; i-- > 0;) {
        for (std::size_t k = 0; k < count; ++k)
            rhs[count * i + k] -= cp[i] * rhs[count * (i + 1) + k];
    }
}

/// The cyclic tridiagonal system (row 0 has a[0] in column n-1, row n-1 has c[n-1] in column
/// 0), n >= 3, by Sherman-Morrison on the tridiagonal part.
void solve_cyclic(const std::vector<double>& a, std::vector<double> b, const std::vector<double>& c,
                  std::vector<double>& rhs, std::size_t count) {
    const std::size_t n = b.size();
    const double gamma = -b[0], alpha = c[n - 1], beta = a[0];
    b[0] -= gamma;
    b[n - 1] -= alpha * beta / gamma;
    std::vector<double> z(n, 0.0);
    z[0] = gamma;
    z[n - 1] = alpha;
    solve_tridiagonal(a, b, c, rhs, count);
    solve_tridiagonal(a, b, c, z, 1);
    const double denominator = 1 + z[0] + beta * z[n - 1] / gamma;
    for (std::size_t k = 0; k < count; ++k) {
        const double factor = (rhs[k] + beta * rhs[count * (n - 1) + k] / gamma) / denominator;
        for (std::size_t i = 0; i < n; ++i) rhs[count * i + k] -= factor * z[i];
    }
}

}  // namespace

CubicSpline2::CubicSpline2(std::vector<double> xy, bool closed)
    : closed_(closed), xy_(std::move(xy)) {
    if (xy_.size() % 2 != 0) throw InputError("spline: odd number of coordinates");
    for (std::size_t i = 0; i < xy_.size(); ++i) {
        if (!std::isfinite(xy_[i]))
            throw InputError("spline: control point " + std::to_string(i / 2) + " is not finite");
    }
    std::size_t n = xy_.size() / 2;
    if (closed_ && n >= 2 && xy_[0] == xy_[2 * n - 2] && xy_[1] == xy_[2 * n - 1]) {
        xy_.resize(2 * --n);
    }
    if (n < (closed_ ? 3u : 2u)) {
        throw InputError(std::string("spline: a ") + (closed_ ? "closed" : "open") +
                         " spline needs at least " + (closed_ ? "3" : "2") +
                         " control points (got " + std::to_string(n) + ")");
    }
    const std::size_t segments = closed_ ? n : n - 1;
    knots_.assign(segments + 1, 0.0);
    std::vector<double> h(segments);
    for (std::size_t i = 0; i < segments; ++i) {
        const std::size_t j = (i + 1) % n;
        h[i] = std::hypot(xy_[2 * j] - xy_[2 * i], xy_[2 * j + 1] - xy_[2 * i + 1]);
        if (!(h[i] > 0) || !std::isfinite(h[i])) {
            throw InputError("spline: control points " + std::to_string(i) + " and " +
                             std::to_string(j) + (h[i] > 0 ? " are too far apart" : " coincide") +
                             " (" + format_number(xy_[2 * i]) + ", " +
                             format_number(xy_[2 * i + 1]) + ")");
        }
        knots_[i + 1] = knots_[i] + h[i];
    }
    moments_.assign(2 * n, 0.0);
    auto slope = [&](std::size_t i, std::size_t k) {  // d_i, coordinate k
        return (xy_[2 * ((i + 1) % n) + k] - xy_[2 * i + k]) / h[i];
    };
    if (closed_) {
        std::vector<double> a(n), b(n), c(n), rhs(2 * n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t before = (i + n - 1) % n;
            a[i] = h[before], b[i] = 2 * (h[before] + h[i]), c[i] = h[i];
            for (std::size_t k = 0; k < 2; ++k)
                rhs[2 * i + k] = 6 * (slope(i, k) - slope(before, k));
        }
        solve_cyclic(a, b, c, rhs, 2);
        moments_ = rhs;
    } else if (n > 2) {
        const std::size_t m = n - 2;  // the inner knots 1 .. n-2
        std::vector<double> a(m), b(m), c(m), rhs(2 * m);
        for (std::size_t r = 0; r < m; ++r) {
            const std::size_t i = r + 1;
            a[r] = h[i - 1], b[r] = 2 * (h[i - 1] + h[i]), c[r] = h[i];
            for (std::size_t k = 0; k < 2; ++k)
                rhs[2 * r + k] = 6 * (slope(i, k) - slope(i - 1, k));
        }
        solve_tridiagonal(a, b, c, rhs, 2);
        std::copy(rhs.begin(), rhs.end(), moments_.begin() + 2);
    }
}

Point CubicSpline2::on_segment(std::size_t segment, double t, int order) const {
    const std::size_t n = point_count();
    const std::size_t i = segment, j = (segment + 1) % n;
    const double h = knots_[segment + 1] - knots_[segment];
    const double s = 1 - t;
    Point result{};
    for (std::size_t k = 0; k < 2; ++k) {
        const double p0 = xy_[2 * i + k], p1 = xy_[2 * j + k], m0 = moments_[2 * i + k],
                     m1 = moments_[2 * j + k];
        switch (order) {
            case 0:
                result[k] =
                    s * p0 + t * p1 + h * h / 6 * ((s * s * s - s) * m0 + (t * t * t - t) * m1);
                break;
            case 1:
                result[k] = (p1 - p0) / h + h / 6 * ((1 - 3 * s * s) * m0 + (3 * t * t - 1) * m1);
                break;
            default:
                result[k] = s * m0 + t * m1;
                break;
        }
    }
    return result;
}

Point CubicSpline2::at(double u, int order) const {
    const double end = knots_.back();
    if (closed_) {
        u = std::fmod(u, end);
        if (u < 0) u += end;
    }
    u = std::clamp(u, 0.0, end);
    const std::size_t last = segment_count() - 1;
    const auto above = std::upper_bound(knots_.begin(), knots_.end(), u);
    const std::size_t segment = std::min(
        last, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, above - knots_.begin() - 1)));
    const double t =
        std::clamp((u - knots_[segment]) / (knots_[segment + 1] - knots_[segment]), 0.0, 1.0);
    return on_segment(segment, t, order);
}

Curve2 CubicSpline2::curve() const {
    auto shared = std::make_shared<const CubicSpline2>(*this);
    return [shared](double u) { return shared->point(u); };
}

std::vector<Point> CubicSpline2::discretize(const SizeFunction& size, int min_pieces) const {
    std::vector<Point> points = discretize_curve(curve(), 0.0, parameter_end(), size,
                                                 std::max(min_pieces, closed_ ? 3 : 1));
    if (closed_) points.pop_back();
    return points;
}

namespace {

bool same(const double* p, const double* q) {
    return p[0] == q[0] && p[1] == q[1];
}

/// On one line: do the closed segments ab and cd share a point? Exact coordinate comparisons.
bool collinear_overlap(const double* a, const double* b, const double* c, const double* d) {
    const int axis = a[0] != b[0] || c[0] != d[0] ? 0 : 1;
    const double lo1 = std::min(a[axis], b[axis]), hi1 = std::max(a[axis], b[axis]);
    const double lo2 = std::min(c[axis], d[axis]), hi2 = std::max(c[axis], d[axis]);
    return lo1 <= hi2 && lo2 <= hi1;
}

/// Do segments s and t of the PSLG cross or touch (beyond sharing one end vertex)?
bool segments_meet(const DomainPslg& d, std::size_t s, std::size_t t) {
    const std::uint32_t ia = d.segments[2 * s], ib = d.segments[2 * s + 1];
    const std::uint32_t ic = d.segments[2 * t], id = d.segments[2 * t + 1];
    const double* a = &d.xy[2 * std::size_t{ia}];
    const double* b = &d.xy[2 * std::size_t{ib}];
    const double* c = &d.xy[2 * std::size_t{ic}];
    const double* e = &d.xy[2 * std::size_t{id}];
    using predicates::orient2d;
    using predicates::Sign;
    const int shared = (ia == ic) + (ia == id) + (ib == ic) + (ib == id);
    if (shared > 0) {
        // Consecutive sides: they meet only at the shared vertex unless they fold back on one
        // line (the other two ends on the same side of the shared one).
        const double* o = ia == ic || ia == id ? a : b;
        const double* p = o == a ? b : a;
        const double* q = ic == (o == a ? ia : ib) ? e : c;
        if (orient2d(o, p, q) != Sign::Zero) return false;
        const int axis = o[0] != p[0] ? 0 : 1;
        return (p[axis] > o[axis]) == (q[axis] > o[axis]);
    }
    const Sign o1 = orient2d(a, b, c), o2 = orient2d(a, b, e);
    const Sign o3 = orient2d(c, e, a), o4 = orient2d(c, e, b);
    if (o1 == Sign::Zero && o2 == Sign::Zero) return collinear_overlap(a, b, c, e);
    const bool straddle1 = o1 == Sign::Zero || o2 == Sign::Zero || o1 != o2;
    const bool straddle2 = o3 == Sign::Zero || o4 == Sign::Zero || o3 != o4;
    return straddle1 && straddle2;
}

/// Throws when two segments of different places of the loops cross or touch.
void check_no_crossing(const DomainPslg& d) {
    const std::size_t count = d.segments.size() / 2;
    std::vector<std::size_t> order(count);
    std::vector<double> lo(count), hi(count);
    for (std::size_t s = 0; s < count; ++s) {
        order[s] = s;
        const double ax = d.xy[2 * std::size_t{d.segments[2 * s]}],
                     bx = d.xy[2 * std::size_t{d.segments[2 * s + 1]}];
        lo[s] = std::min(ax, bx), hi[s] = std::max(ax, bx);
    }
    std::sort(order.begin(), order.end(),
              [&](std::size_t p, std::size_t q) { return lo[p] < lo[q]; });
    auto y_range = [&](std::size_t s) {
        const double ay = d.xy[2 * std::size_t{d.segments[2 * s]} + 1],
                     by = d.xy[2 * std::size_t{d.segments[2 * s + 1]} + 1];
        return std::pair{std::min(ay, by), std::max(ay, by)};
    };
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t s = order[i];
        const auto [s0, s1] = y_range(s);
        for (std::size_t j = i + 1; j < count && lo[order[j]] <= hi[s]; ++j) {
            const std::size_t t = order[j];
            const auto [t0, t1] = y_range(t);
            if (t0 > s1 || s0 > t1) continue;
            if (segments_meet(d, s, t)) {
                const double* p = &d.xy[2 * std::size_t{d.segments[2 * s]}];
                throw InputError("boundary loops: segments " + std::to_string(std::min(s, t)) +
                                 " and " + std::to_string(std::max(s, t)) +
                                 " cross or touch (near (" + format_number(p[0]) + ", " +
                                 format_number(p[1]) + "))");
            }
        }
    }
}

/// A point strictly inside the polygon (vertices `xy` in order): the centroid of the largest
/// triangle of its constrained Delaunay triangulation whose centroid is strictly inside it.
Point point_inside(const std::vector<double>& xy, std::size_t loop) {
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    std::vector<tri::VertIdx> segments;
    for (std::uint32_t k = 0; k < n; ++k) segments.insert(segments.end(), {k, (k + 1) % n});
    const tri::Cdt2Result cdt = tri::constrained_delaunay_2d(tri::Pslg{xy, segments, {}, {}});
    const tri::Triangulation2& m = cdt.mesh;
    std::vector<std::pair<double, tri::TriIdx>> by_area;
    for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
        const double* a = m.point(m.triangles[3 * t]);
        const double* b = m.point(m.triangles[3 * t + 1]);
        const double* c = m.point(m.triangles[3 * t + 2]);
        by_area.push_back({(b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]), t});
    }
    std::sort(by_area.begin(), by_area.end(),
              [](const auto& p, const auto& q) { return p.first > q.first; });
    for (const auto& [area, t] : by_area) {
        const double* p[3] = {m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]),
                              m.point(m.triangles[3 * t + 2])};
        const double centroid[2] = {(p[0][0] + p[1][0] + p[2][0]) / 3,
                                    (p[0][1] + p[1][1] + p[2][1]) / 3};
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
            inside =
                predicates::orient2d(p[k], p[(k + 1) % 3], centroid) == predicates::Sign::Positive;
        }
        if (inside) return {centroid[0], centroid[1]};
    }
    throw GeometryError("boundary loops: no point found strictly inside hole loop " +
                        std::to_string(loop));
}

}  // namespace

DomainPslg boundary_loops_domain(std::span<const BoundaryLoop2> loops, const SizeFunction& size,
                                 int min_pieces) {
    if (loops.empty()) throw InputError("boundary loops: no loop");
    DomainPslg d;
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const BoundaryLoop2& loop = loops[l];
        const std::string name = "boundary loop " + std::to_string(l) + ": ";
        std::vector<double> points;
        try {
            if (loop.spline && loop.corners.empty()) {
                const CubicSpline2 spline(loop.xy, true);
                const int pieces = min_pieces > 0
                                       ? min_pieces
                                       : std::max(8, 2 * static_cast<int>(spline.point_count()));
                for (const Point& p : spline.discretize(size, pieces))
                    points.insert(points.end(), {p[0], p[1]});
            } else if (loop.spline) {
                // One open spline from each corner to the next, round the loop; each piece's
                // last point is the next piece's first.
                if (loop.xy.size() % 2 != 0) throw InputError("odd number of coordinates");
                const std::size_t n = loop.xy.size() / 2;
                for (std::size_t k = 0; k < loop.corners.size(); ++k) {
                    if (loop.corners[k] >= n || (k > 0 && loop.corners[k] <= loop.corners[k - 1])) {
                        throw InputError("corner " + std::to_string(k) + " (" +
                                         std::to_string(loop.corners[k]) +
                                         ") is not an increasing control point number below " +
                                         std::to_string(n));
                    }
                }
                for (std::size_t k = 0; k < loop.corners.size(); ++k) {
                    const std::size_t from = loop.corners[k],
                                      to = loop.corners[(k + 1) % loop.corners.size()];
                    std::vector<double> piece;
                    for (std::size_t i = from;; i = (i + 1) % n) {
                        piece.insert(piece.end(), {loop.xy[2 * i], loop.xy[2 * i + 1]});
                        if (piece.size() > 2 && i == to) break;
                    }
                    const CubicSpline2 spline(std::move(piece), false);
                    const int pieces =
                        min_pieces > 0 ? min_pieces : 2 * static_cast<int>(spline.point_count());
                    std::vector<Point> along = spline.discretize(size, pieces);
                    along.pop_back();
                    for (const Point& p : along) points.insert(points.end(), {p[0], p[1]});
                }
            } else {
                points = loop.xy;
                if (points.size() % 2 != 0) throw InputError("odd number of coordinates");
                const std::size_t n = points.size() / 2;
                if (n < 3)
                    throw InputError("a polygon needs at least 3 vertices (got " +
                                     std::to_string(n) + ")");
                for (std::size_t i = 0; i < n; ++i) {
                    if (!std::isfinite(points[2 * i]) || !std::isfinite(points[2 * i + 1])) {
                        throw InputError("vertex " + std::to_string(i) + " is not finite");
                    }
                    if (same(&points[2 * i], &points[2 * ((i + 1) % n)])) {
                        throw InputError("vertices " + std::to_string(i) + " and " +
                                         std::to_string((i + 1) % n) + " coincide");
                    }
                }
            }
        } catch (const InputError& error) {
            throw InputError(name + error.what());
        }
        const auto first = static_cast<std::uint32_t>(d.xy.size() / 2);
        const auto n = static_cast<std::uint32_t>(points.size() / 2);
        d.xy.insert(d.xy.end(), points.begin(), points.end());
        for (std::uint32_t k = 0; k < n; ++k)
            d.segments.insert(d.segments.end(), {first + k, first + (k + 1) % n});
        if (loop.hole) {
            const Point inside = point_inside(points, l);
            d.holes.insert(d.holes.end(), {inside[0], inside[1]});
        }
    }
    check_no_crossing(d);
    return d;
}

}  // namespace exactmesh::generators
