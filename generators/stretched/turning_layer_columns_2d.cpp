// SPDX-License-Identifier: MIT
// Structured columns across thin layers that turn (see turning_layer_columns_2d.hpp).
#include "generators/stretched/turning_layer_columns_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "base/errors.hpp"

namespace exactmesh::generators {

namespace {

struct Point {
    double x = 0, y = 0;
};

/// The metric's direction across (its smallest size), that size and the size along; ok is false
/// where the field could not be evaluated.
struct Across {
    double x = 1, y = 0, h = 0, along = 0;
    bool ok = false;
};

/// The golden section's smaller fraction, 2 - phi.
constexpr double kGolden = 0.3819660112501051;

class Columns {
  public:
    Columns(const MetricField2& field, const std::array<double, 4>& box,
            const std::function<bool(double, double)>& inside,
            const TurningLayerColumnsOptions2& options, std::uint64_t max_points)
        : field_(field), box_(box), inside_(inside), options_(options), max_points_(max_points) {
        // How far a line search may walk: the box's diagonal (no square: hypot).
        reach_ = std::hypot(box[2] - box[0], box[3] - box[1]);
    }

    std::vector<double> run();

  private:
    Across at(double x, double y) const {
        Across a;
        try {
            const Metric2 m = field_(x, y);
            if (m.h1 <= m.h2) {
                a = {m.c, m.s, m.h1, m.h2, true};
            } else {
                a = {-m.s, m.c, m.h2, m.h1, true};
            }
        } catch (const InputError&) {
            a.ok = false;
        }
        return a;
    }
    Across at(Point p) const { return at(p.x, p.y); }
    /// The metric length of (dx, dy) in the field at (x, y) (infinite where it fails).
    double length_at(Point p, double dx, double dy) const {
        try {
            return metric_length(field_(p.x, p.y), dx, dy);
        } catch (const InputError&) {
            return std::numeric_limits<double>::infinity();
        }
    }
    /// The metric length of the chord pq in the field at its middle: where the layer turns, the
    /// metric at either end sees the other end off its line along by the chord's sag (many sizes
    /// across), the metric at the middle sees the chord along the layer.
    double chord_length(Point p, Point q) const {
        return length_at({0.5 * (p.x + q.x), 0.5 * (p.y + q.y)}, q.x - p.x, q.y - p.y);
    }
    /// The point of smallest size across on the line across the layer through p (golden-section
    /// search after a bracketing walk), when that is a strict minimum: the size grows by half
    /// within 4 sizes on both sides.
    bool ridge_minimum(Point p, Point& ridge, double& h_ridge) const;
    /// The sag of the chord of one size along at p over the size across there (the direction
    /// across sampled half a size along on either side).
    double sag_ratio(Point p) const { return sag_ratio(p, at(p)); }
    /// The same with the field's value at p already sampled.
    double sag_ratio(Point p, const Across& a) const;
    /// The ridge through r0 traced both ways at quarter sizes along, each step projected back on
    /// the ridge; closed when it comes back to r0.
    std::vector<Point> trace_ridge(Point r0, bool& closed) const;
    /// The ridge resampled at equal metric spacing along (about unit).
    std::vector<Point> resample(const std::vector<Point>& ridge, bool closed) const;
    /// The column from q across the layer on `side` (+1 or -1 times the direction across at q),
    /// without q itself.
    std::vector<Point> column(Point q, double side) const;

    const MetricField2& field_;
    std::array<double, 4> box_;
    const std::function<bool(double, double)>& inside_;
    const TurningLayerColumnsOptions2& options_;
    std::uint64_t max_points_;
    double reach_ = 0;
};

bool Columns::ridge_minimum(Point p, Point& ridge, double& h_ridge) const {
    const Across a = at(p);
    if (!a.ok) return false;
    const double ux = a.x, uy = a.y;
    const auto h = [&](double t) {
        const Across b = at(p.x + t * ux, p.y + t * uy);
        return b.ok ? b.h : std::numeric_limits<double>::infinity();
    };
    const double d = 0.5 * a.h;
    const double h0 = a.h, hp = h(d), hm = h(-d);
    // A size across that does not change along the line (a layer of constant thickness): no ridge.
    if (hp == h0 && hm == h0) return false;
    double lo = -d, mid = 0, hi = d, hmid = h0;
    if (hp < h0 || hm < h0) {
        // Walk downhill with doubling steps until the size grows again.
        const double side = hp < hm ? 1.0 : -1.0;
        double t0 = 0, t1 = side * d, h1 = side > 0 ? hp : hm, step = d;
        bool bracketed = false;
        for (int i = 0; i < 200; ++i) {
            step *= 2;
            const double t2 = t1 + side * step;
            if (!(std::fabs(t2) <= reach_)) break;
            const double h2 = h(t2);
            if (!(h2 < h1)) {
                lo = std::min(t0, t2);
                hi = std::max(t0, t2);
                mid = t1;
                hmid = h1;
                bracketed = true;
                break;
            }
            t0 = t1;
            t1 = t2;
            h1 = h2;
        }
        if (!bracketed) return false;
    }
    // Golden section: probe the larger part of the bracket; stop at a fiftieth of the size.
    for (int i = 0; i < 200 && hi - lo > 0.02 * hmid; ++i) {
        if (hi - mid > mid - lo) {
            const double x = mid + kGolden * (hi - mid), hx = h(x);
            if (hx < hmid) {
                lo = mid;
                mid = x;
                hmid = hx;
            } else {
                hi = x;
            }
        } else {
            const double x = mid - kGolden * (mid - lo), hx = h(x);
            if (hx < hmid) {
                hi = mid;
                mid = x;
                hmid = hx;
            } else {
                lo = x;
            }
        }
    }
    if (!(h(mid + 4 * hmid) >= 1.5 * hmid) || !(h(mid - 4 * hmid) >= 1.5 * hmid)) return false;
    ridge = {p.x + mid * ux, p.y + mid * uy};
    h_ridge = hmid;
    return true;
}

double Columns::sag_ratio(Point p, const Across& a) const {
    if (!a.ok) return 0;
    const double sx = 0.5 * a.along * a.y, sy = 0.5 * a.along * a.x;
    const Across left = at(p.x - sx, p.y + sy);
    const Across right = at(p.x + sx, p.y - sy);
    if (!left.ok || !right.ok) return 0;
    const double turn = std::fabs(left.x * right.y - left.y * right.x);
    return a.along * turn / (8 * a.h);
}

std::vector<Point> Columns::trace_ridge(Point r0, bool& closed) const {
    closed = false;
    const Across a0 = at(r0);
    const std::size_t most_steps = 4 * std::min<std::uint64_t>(max_points_, 1u << 20) + 16;
    std::vector<Point> forward, backward;
    for (const double side : {1.0, -1.0}) {
        std::vector<Point>& out = side > 0 ? forward : backward;
        Point cur = r0;
        double vx = -side * a0.y, vy = side * a0.x;
        for (std::size_t i = 0; i < most_steps; ++i) {
            const Across a = at(cur);
            if (!a.ok) break;
            // The direction along, kept pointing the way of the last step.
            const auto oriented = [&](const Across& b, double& ox, double& oy) {
                ox = -b.y;
                oy = b.x;
                if (ox * vx + oy * vy < 0) {
                    ox = -ox;
                    oy = -oy;
                }
            };
            double wx, wy;
            oriented(a, wx, wy);
            const double step = 0.25 * a.along;
            const Across am = at(cur.x + 0.5 * step * wx, cur.y + 0.5 * step * wy);
            if (!am.ok) break;
            double mx, my;
            oriented(am, mx, my);
            const double step_mid = 0.25 * am.along;
            Point next;
            double h_next;
            if (!ridge_minimum({cur.x + step_mid * mx, cur.y + step_mid * my}, next, h_next)) break;
            if (!inside_(next.x, next.y)) break;
            // The ridge is followed as long as the layer stays thin, turning or not: columns
            // along its straight stretches too keep the layers lined up from one turn to the
            // next (a ridge cut where it stops turning leaves unstructured gaps between pieces).
            const Across an = at(next);
            if (!an.ok || !(an.along >= options_.ridge_aspect * an.h)) break;
            if (side > 0 && i >= 8 && chord_length(r0, next) < 0.3) {
                closed = true;
                break;
            }
            // The next step's orientation: this step's chord (its sign is what matters).
            vx = next.x - cur.x;
            vy = next.y - cur.y;
            out.push_back(next);
            cur = next;
        }
        if (closed) break;
    }
    std::vector<Point> ridge(backward.rbegin(), backward.rend());
    ridge.push_back(r0);
    ridge.insert(ridge.end(), forward.begin(), forward.end());
    return ridge;
}

std::vector<Point> Columns::resample(const std::vector<Point>& ridge, bool closed) const {
    const std::size_t n = ridge.size();
    const std::size_t chords = closed ? n : n - 1;
    if (n < 2) return {};
    // Metric lengths of the chords, in the metric at each chord's middle.
    std::vector<double> cumulative(chords + 1, 0.0);
    for (std::size_t j = 0; j < chords; ++j) {
        const Point& p = ridge[j];
        const Point& q = ridge[(j + 1) % n];
        const double l = chord_length(p, q);
        if (!std::isfinite(l)) return {};
        cumulative[j + 1] = cumulative[j] + l;
    }
    const double total = cumulative.back();
    std::vector<double> stations;
    if (closed) {
        const auto count = static_cast<std::size_t>(std::max(3.0, std::round(total)));
        for (std::size_t i = 0; i < count; ++i)
            stations.push_back(total * static_cast<double>(i) / static_cast<double>(count));
    } else {
        const double count = std::floor(total);
        if (count < 1) return {};
        for (double i = 0; i <= count; ++i) stations.push_back(0.5 * (total - count) + i);
    }
    std::vector<Point> out;
    std::size_t j = 0;
    for (const double s : stations) {
        while (j + 1 < chords && cumulative[j + 1] < s) ++j;
        const Point& p = ridge[j];
        const Point& q = ridge[(j + 1) % n];
        const double span = cumulative[j + 1] - cumulative[j];
        const double f = span > 0 ? std::clamp((s - cumulative[j]) / span, 0.0, 1.0) : 0.0;
        const Point guess = {p.x + f * (q.x - p.x), p.y + f * (q.y - p.y)};
        Point on;
        double h;
        out.push_back(ridge_minimum(guess, on, h) ? on : guess);
    }
    return out;
}

std::vector<Point> Columns::column(Point q, double side) const {
    std::vector<Point> out;
    const Across a0 = at(q);
    if (!a0.ok) return out;
    double dx = side * a0.x, dy = side * a0.y;
    Point p = q;
    const std::size_t most = std::min<std::uint64_t>(max_points_, 1u << 20);
    const double spacing = options_.layer_spacing;
    for (std::size_t k = 0; k < most; ++k) {
        const Across a = at(p);
        if (!a.ok) break;
        // The direction across at b, pointing the column's way.
        const auto oriented = [&](const Across& b, double& ox, double& oy) {
            ox = b.x;
            oy = b.y;
            if (ox * dx + oy * dy < 0) {
                ox = -ox;
                oy = -oy;
            }
        };
        double ux, uy;
        oriented(a, ux, uy);
        // A step of `spacing` in the geometric mean of the sizes across at its ends (the
        // log-Euclidean mean the edges are measured in), by fixed-point iteration on the far end.
        double delta = spacing * a.h;
        bool ok = true;
        for (int it = 0; it < 3 && ok; ++it) {
            const Across am = at(p.x + 0.5 * delta * ux, p.y + 0.5 * delta * uy);
            if (!am.ok) {
                ok = false;
                break;
            }
            double mx, my;
            oriented(am, mx, my);
            const Across ae = at(p.x + delta * mx, p.y + delta * my);
            if (!ae.ok) {
                ok = false;
                break;
            }
            delta = spacing * a.h * std::sqrt(ae.h / a.h);
        }
        if (!ok) break;
        const Across am = at(p.x + 0.5 * delta * ux, p.y + 0.5 * delta * uy);
        if (!am.ok) break;
        double mx, my;
        oriented(am, mx, my);
        const Point next = {p.x + delta * mx, p.y + delta * my};
        const Across an = at(next);
        if (!an.ok || !(an.along >= options_.stop_aspect * an.h) || !inside_(next.x, next.y)) break;
        out.push_back(next);
        dx = mx;
        dy = my;
        p = next;
    }
    return out;
}

std::vector<double> Columns::run() {
    std::vector<double> out;
    if (field_.is_uniform() || !(reach_ > 0) || max_points_ == 0) return out;
    const int g = std::max(1, options_.grid);
    // Every accepted ridge's resampled points: a later sample finding the same ridge is dropped.
    std::vector<Point> known;
    for (int j = 0; j < g; ++j) {
        for (int i = 0; i < g; ++i) {
            const Point sample = {box_[0] + (i + 0.5) / g * (box_[2] - box_[0]),
                                  box_[1] + (j + 0.5) / g * (box_[3] - box_[1])};
            const Across a = at(sample);
            // Anisotropic and turning at the sample (a straight layer has no turn at all); the
            // sag over the size across grows towards the ridge as the size across falls (on the
            // curved layer of aspect ratio 1000, 0.1 at 0.03 from the ridge, 21 on it).
            if (!a.ok || !(a.along >= 2 * a.h) ||
                !(sag_ratio(sample, a) > 0.01 * options_.sag_ratio)) {
                continue;
            }
            Point r;
            double h;
            if (!ridge_minimum(sample, r, h) || !inside_(r.x, r.y)) continue;
            const bool seen = std::any_of(known.begin(), known.end(),
                                          [&](const Point& k) { return chord_length(r, k) < 1.0; });
            if (seen || !(sag_ratio(r) > options_.sag_ratio)) continue;
            bool closed = false;
            const std::vector<Point> traced = trace_ridge(r, closed);
            const std::vector<Point> ridge = resample(traced, closed);
            if (ridge.size() < 2) continue;
            known.insert(known.end(), ridge.begin(), ridge.end());
            // The columns of each side, then each cut at the first layer where it and a
            // neighbour stand too close or too far along. A column cut where the layer still
            // turns (a chord sags by half a size across or more) leaves the structure unfinished
            // there: when that is so of most columns (columns converging on a tight bend), the
            // ridge gets none, the passes doing better without a ragged edge of columns inside
            // the turning part.
            const std::size_t n = ridge.size();
            std::vector<double> points;
            std::size_t unfinished = 0;
            for (const double side : {1.0, -1.0}) {
                std::vector<std::vector<Point>> cols(n);
                for (std::size_t c = 0; c < n; ++c) cols[c] = column(ridge[c], side);
                std::vector<std::size_t> keep(n);
                for (std::size_t c = 0; c < n; ++c) keep[c] = cols[c].size();
                const std::size_t pairs = closed ? n : n - 1;
                for (std::size_t c = 0; c < pairs; ++c) {
                    const std::size_t d = (c + 1) % n;
                    const std::size_t common = std::min(cols[c].size(), cols[d].size());
                    for (std::size_t k = 0; k < common; ++k) {
                        const Point& p = cols[c][k];
                        const Point& q = cols[d][k];
                        const double l = chord_length(p, q);
                        if (!(l >= options_.spacing_low && l <= options_.spacing_high)) {
                            keep[c] = std::min(keep[c], k);
                            keep[d] = std::min(keep[d], k);
                            break;
                        }
                    }
                }
                for (std::size_t c = 0; c < n; ++c) {
                    if (keep[c] < cols[c].size() && sag_ratio(cols[c][keep[c]]) >= 0.5) {
                        ++unfinished;
                    }
                    for (std::size_t k = 0; k < keep[c]; ++k) {
                        points.push_back(cols[c][k].x);
                        points.push_back(cols[c][k].y);
                    }
                }
            }
            if (unfinished > n) continue;
            out.insert(out.end(), points.begin(), points.end());
            for (const Point& p : ridge) {
                out.push_back(p.x);
                out.push_back(p.y);
            }
            if (out.size() / 2 >= max_points_) {
                out.resize(2 * max_points_);
                return out;
            }
        }
    }
    return out;
}

}  // namespace

std::vector<double> turning_layer_columns_2d(const MetricField2& field,
                                             const std::array<double, 4>& box,
                                             const std::function<bool(double, double)>& inside,
                                             const TurningLayerColumnsOptions2& options,
                                             std::uint64_t max_points) {
    return Columns(field, box, inside, options, max_points).run();
}

}  // namespace exactmesh::generators
