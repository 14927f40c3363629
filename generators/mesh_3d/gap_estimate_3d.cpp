// SPDX-License-Identifier: MIT
// The points a narrow gap asks for (see gap_estimate_3d.hpp).
#include "generators/mesh_3d/gap_estimate_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::generators {

namespace {

using triangulation::Plc3;
using triangulation::VertIdx;
using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec add_scaled(const Vec& a, const Vec& d, double t) {
    return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
double squared_distance(const Vec& a, const Vec& b) {
    const Vec d = sub(a, b);
    return dot(d, d);
}

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec closest_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
    const Vec ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return add_scaled(a, ab, d1 / (d1 - d3));
    const Vec cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return add_scaled(a, ac, d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return add_scaled(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = va + vb + vc;
    if (!(denominator > 0)) return a;  // degenerate in rounding: a corner is close enough
    const double v = vb / denominator, w = vc / denominator;
    return {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
            a[2] + ab[2] * v + ac[2] * w};
}

/// The squared distance of segments pq and rs (Ericson 5.1.9).
double segment_squared_distance(const Vec& p, const Vec& q, const Vec& r, const Vec& s) {
    const Vec d1 = sub(q, p), d2 = sub(s, r), w = sub(p, r);
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, w);
    double t1 = 0, t2 = 0;
    if (a <= 0 && e <= 0) return dot(w, w);
    if (a <= 0) {
        t2 = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, w);
        if (e <= 0) {
            t1 = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2), denominator = a * e - b * b;
            t1 = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t2 = (b * t1 + f) / e;
            if (t2 < 0) {
                t2 = 0;
                t1 = std::clamp(-c / a, 0.0, 1.0);
            } else if (t2 > 1) {
                t2 = 1;
                t1 = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return squared_distance(add_scaled(p, d1, t1), add_scaled(r, d2, t2));
}

/// The squared distance of two triangles that do not cross (a valid PLC's triangles sharing no
/// vertex): the least of corner-to-triangle and edge-to-edge distances.
double triangle_squared_distance(const std::array<Vec, 3>& t, const std::array<Vec, 3>& u) {
    double best = INFINITY;
    for (int k = 0; k < 3; ++k) {
        best = std::min(best, squared_distance(t[k], closest_on_triangle(t[k], u[0], u[1], u[2])));
        best = std::min(best, squared_distance(u[k], closest_on_triangle(u[k], t[0], t[1], t[2])));
        for (int m = 0; m < 3; ++m) {
            best = std::min(best,
                            segment_squared_distance(t[k], t[(k + 1) % 3], u[m], u[(m + 1) % 3]));
        }
    }
    return best;
}

/// Cells a triangle may cover in the grid before it counts as large (kept out of the grid).
constexpr double kMaxCellsPerTriangle = 512;
/// A triangle with a close feature is sampled at up to this many points per side (squared).
constexpr int kMaxSamplesPerSide = 16;

}  // namespace

GapEstimate3 gap_estimate_3d(const Plc3& plc) {
    GapEstimate3 estimate;
    const triangulation::SurfaceTriangles3 surface = triangulation::triangulate_facets_3d(plc);
    const std::uint32_t count = surface.triangle_count();
    if (count == 0) return estimate;
    double largest = 0;
    for (const double x : plc.xyz) largest = std::max(largest, std::fabs(x));
    const int shift = predicates::unit_shift(largest);
    const predicates::PowerOfTwo unit(shift);
    std::vector<std::array<Vec, 3>> triangles(count);
    std::vector<double> longest(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const double* p = plc.point(surface.triangles[3 * std::size_t{t} + k]);
            triangles[t][k] = {unit(p[0]), unit(p[1]), unit(p[2])};
        }
        double l2 = 0;
        for (int k = 0; k < 3; ++k)
            l2 = std::max(l2, squared_distance(triangles[t][k], triangles[t][(k + 1) % 3]));
        longest[t] = std::sqrt(l2);
    }
    // The grid: cells of the median longest edge; a feature farther than one cell from a
    // triangle is not looked for (the estimate then takes the triangle's own size: a lower
    // bound, so a refusal is never wrong).
    std::vector<double> sorted = longest;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    // The floor: 2^-44 of the scaled coordinates' magnitude (in [1, 2)). Cells are no finer
    // (no feature below it counts), so cell indices stay below 2^46.
    const double floor = 0x1p-44;
    const double cell = std::max(sorted[sorted.size() / 2], floor);
    auto box_of = [&](std::uint32_t t, double margin) {
        std::array<std::int64_t, 6> box{};
        for (int axis = 0; axis < 3; ++axis) {
            double lo = triangles[t][0][axis], hi = lo;
            for (int k = 1; k < 3; ++k) {
                lo = std::min(lo, triangles[t][k][axis]);
                hi = std::max(hi, triangles[t][k][axis]);
            }
            box[axis] = static_cast<std::int64_t>(std::floor((lo - margin) / cell));
            box[axis + 3] = static_cast<std::int64_t>(std::floor((hi + margin) / cell));
        }
        return box;
    };
    // In doubles: a large triangle over tiny cells spans more than 2^63 of them.
    auto cells_in = [](const std::array<std::int64_t, 6>& box) {
        return (static_cast<double>(box[3] - box[0]) + 1) *
               (static_cast<double>(box[4] - box[1]) + 1) *
               (static_cast<double>(box[5] - box[2]) + 1);
    };
    auto key = [](std::int64_t x, std::int64_t y, std::int64_t z) {
        // Scaled coordinates are below 2 and cells at least 2^-44: indices below 2^46, kept
        // to 21 bits per axis (a wrap only adds candidates, never loses one).
        return (static_cast<std::uint64_t>(x & 0x1fffff) << 42) |
               (static_cast<std::uint64_t>(y & 0x1fffff) << 21) |
               static_cast<std::uint64_t>(z & 0x1fffff);
    };
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
    std::vector<bool> in_grid(count, false);
    for (std::uint32_t t = 0; t < count; ++t) {
        const auto box = box_of(t, 0);
        if (cells_in(box) > kMaxCellsPerTriangle) continue;
        in_grid[t] = true;
        for (std::int64_t x = box[0]; x <= box[3]; ++x)
            for (std::int64_t y = box[1]; y <= box[4]; ++y)
                for (std::int64_t z = box[2]; z <= box[5]; ++z) grid[key(x, y, z)].push_back(t);
    }
    std::vector<std::uint32_t> seen(count, 0);
    std::vector<std::uint32_t> near;
    std::uint32_t epoch = 0;
    double smallest = INFINITY;
    for (std::uint32_t t = 0; t < count; ++t) {
        const Vec e1 = sub(triangles[t][1], triangles[t][0]);
        const Vec e2 = sub(triangles[t][2], triangles[t][0]);
        const Vec normal = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                            e1[0] * e2[1] - e1[1] * e2[0]};
        const double area = 0.5 * std::sqrt(dot(normal, normal));
        const double own = std::max(longest[t], floor);
        // The triangles sharing no vertex with t and nearer than its longest edge.
        near.clear();
        double nearest = longest[t] * longest[t];
        if (in_grid[t]) {
            ++epoch;
            const auto box = box_of(t, std::min(cell, longest[t]));
            const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
            for (std::int64_t x = box[0]; x <= box[3]; ++x) {
                for (std::int64_t y = box[1]; y <= box[4]; ++y) {
                    for (std::int64_t z = box[2]; z <= box[5]; ++z) {
                        const auto found = grid.find(key(x, y, z));
                        if (found == grid.end()) continue;
                        for (const std::uint32_t u : found->second) {
                            if (u == t || seen[u] == epoch) continue;
                            seen[u] = epoch;
                            const VertIdx* uv = &surface.triangles[3 * std::size_t{u}];
                            bool shares = false;
                            for (int i = 0; i < 3; ++i)
                                for (int j = 0; j < 3; ++j) shares = shares || tv[i] == uv[j];
                            if (shares) continue;
                            const double d2 = triangle_squared_distance(triangles[t], triangles[u]);
                            if (d2 < longest[t] * longest[t]) {
                                near.push_back(u);
                                nearest = std::min(nearest, d2);
                            }
                        }
                    }
                }
            }
        }
        smallest = std::min(smallest, std::max(std::sqrt(nearest), floor));
        if (near.empty()) {
            estimate.points += area / (4 * own * own);
            continue;
        }
        // A close feature faces only part of t (the outer wall's triangle beside a small
        // hole): t is sampled at the centres of its k^2 congruent sub-triangles, each with
        // the distance from its centre to the near triangles (capped and floored as f).
        // Clamped as a double: the ratio can exceed any int (1.9e11 from a fuzzed PLC, an
        // undefined conversion), or be infinite when the nearest distance is 0.
        const double ratio = std::ceil(longest[t] / std::sqrt(nearest));
        const int k = !(ratio < kMaxSamplesPerSide) ? kMaxSamplesPerSide
                                                    : std::max(1, static_cast<int>(ratio));
        const double piece = area / (static_cast<double>(k) * k);
        auto sample = [&](double a, double b) {
            const Vec p = {triangles[t][0][0] + a * e1[0] + b * e2[0],
                           triangles[t][0][1] + a * e1[1] + b * e2[1],
                           triangles[t][0][2] + a * e1[2] + b * e2[2]};
            double best = own * own;
            for (const std::uint32_t u : near) {
                best = std::min(best, squared_distance(p, closest_on_triangle(p, triangles[u][0],
                                                                              triangles[u][1],
                                                                              triangles[u][2])));
            }
            const double f = std::max(std::sqrt(best), floor);
            estimate.points += piece / (4 * f * f);
        };
        for (int i = 0; i < k; ++i) {
            for (int j = 0; i + j < k; ++j) {
                sample((i + 1.0 / 3) / k, (j + 1.0 / 3) / k);  // the upward sub-triangle
                if (i + j + 1 < k) sample((i + 2.0 / 3) / k, (j + 2.0 / 3) / k);  // downward
            }
        }
    }
    estimate.smallest_feature = std::ldexp(smallest, -shift);
    return estimate;
}

void refuse_gaps_far_over_budget_3d(const Plc3& plc, std::uint64_t budget, const char* who) {
    const GapEstimate3 estimate = gap_estimate_3d(plc);
    if (!(estimate.points > 6.0 * static_cast<double>(budget))) return;
    throw InputError(std::string(who) + ": Steiner point budget of " + std::to_string(budget) +
                     " exceeded at once: facets " +
                     format_approximate(estimate.smallest_feature, 3) +
                     " apart (a narrow gap between parts of the surface that share no vertex) ask "
                     "for about " +
                     format_approximate(estimate.points, 3) +
                     " points (the surface's area over 4 f^2, f the distance to the nearest such "
                     "part); widen the gap or raise the budget");
}

}  // namespace exactmesh::generators
