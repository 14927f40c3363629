// SPDX-License-Identifier: MIT
// The quality report (see quality_2d.hpp). Corner angles from atan2(|cross|, dot), which is
// accurate to an ulp or so over the whole range (acos of a cosine is not, near 0 and 180), on
// the corner's edge vectors first scaled exactly by a power of two to a largest component in
// [1, 2): no product overflows or underflows at any scale, and a mesh scaled by 2^k reports the
// same angles, bit for bit.
#include "generators/mesh_2d/quality_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "base/number_text.hpp"

namespace exactmesh::generators {

namespace {

/// The corner angle at o of (o, p, q) in degrees, scale-free (see the top of the file).
double corner_degrees(const double* o, const double* p, const double* q) {
    double ux = p[0] - o[0], uy = p[1] - o[1], wx = q[0] - o[0], wy = q[1] - o[1];
    const double largest = std::max({std::fabs(ux), std::fabs(uy), std::fabs(wx), std::fabs(wy)});
    if (largest > 0 && std::isfinite(largest)) {
        const int shift = -std::ilogb(largest);
        ux = std::ldexp(ux, shift), uy = std::ldexp(uy, shift);
        wx = std::ldexp(wx, shift), wy = std::ldexp(wy, shift);
    }
    return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) * (180.0 / std::numbers::pi);
}

}  // namespace

QualityReport2 quality_report_2d(std::span<const double> xy,
                                 std::span<const triangulation::VertIdx> triangles,
                                 const SizeFunction& size) {
    QualityReport2 r;
    const std::size_t count = triangles.size() / 3;
    r.triangles = count;
    if (count == 0) return r;
    constexpr double kDegrees = 180.0 / std::numbers::pi;  // for the sine of the smallest angle
    std::vector<std::uint8_t> used(xy.size() / 2, 0);
    std::vector<double> radius_edge;
    radius_edge.reserve(count);
    r.min_angle = 180;
    double min_angle_sum = 0;
    std::vector<std::uint64_t> edges;
    edges.reserve(3 * count);
    for (std::size_t t = 0; t < count; ++t) {
        const triangulation::VertIdx v[3] = {triangles[3 * t], triangles[3 * t + 1],
                                             triangles[3 * t + 2]};
        double smallest = 180;
        for (int k = 0; k < 3; ++k) {
            used[v[k]] = 1;
            const double* o = &xy[2 * std::size_t{v[k]}];
            const double* p = &xy[2 * std::size_t{v[(k + 1) % 3]}];
            const double* q = &xy[2 * std::size_t{v[(k + 2) % 3]}];
            const double angle = corner_degrees(o, p, q);
            smallest = std::min(smallest, angle);
            r.min_angle = std::min(r.min_angle, angle);
            r.max_angle = std::max(r.max_angle, angle);
            ++r.angle_histogram[std::min<std::size_t>(17, static_cast<std::size_t>(angle / 10))];
            const triangulation::VertIdx a = std::min(v[k], v[(k + 1) % 3]),
                                         b = std::max(v[k], v[(k + 1) % 3]);
            edges.push_back((std::uint64_t{a} << 32) | b);
        }
        min_angle_sum += smallest;
        // Law of sines: the shortest edge l_min = 2 R sin(theta_min).
        const double sine = std::sin(smallest / kDegrees);
        radius_edge.push_back(sine > 0 ? 1.0 / (2.0 * sine)
                                       : std::numeric_limits<double>::infinity());
    }
    r.mean_min_angle = min_angle_sum / static_cast<double>(count);
    r.vertices = static_cast<std::uint64_t>(std::count(used.begin(), used.end(), std::uint8_t{1}));
    r.radius_edge_min = *std::min_element(radius_edge.begin(), radius_edge.end());
    r.radius_edge_max = *std::max_element(radius_edge.begin(), radius_edge.end());
    r.radius_edge_median = median_of(radius_edge);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    r.edges = edges.size();
    if (size.bounded()) {
        r.has_size = true;
        std::vector<double> ratios;
        ratios.reserve(edges.size());
        for (const std::uint64_t key : edges) {
            const double* a = &xy[2 * (key >> 32)];
            const double* b = &xy[2 * (key & 0xFFFFFFFFu)];
            const double target = size(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
            ratios.push_back(std::hypot(b[0] - a[0], b[1] - a[1]) / target);
        }
        r.size_ratio_min = *std::min_element(ratios.begin(), ratios.end());
        r.size_ratio_max = *std::max_element(ratios.begin(), ratios.end());
        r.size_ratio_median = median_of(ratios);
    }
    return r;
}

std::string quality_report_text(const QualityReport2& r) {
    std::string text;
    text += "quality.triangles: " + std::to_string(r.triangles) + "\n";
    text += "quality.vertices: " + std::to_string(r.vertices) + "\n";
    text += "quality.min_angle: " + format_fixed(r.min_angle) + "\n";
    text += "quality.max_angle: " + format_fixed(r.max_angle) + "\n";
    text += "quality.mean_min_angle: " + format_fixed(r.mean_min_angle) + "\n";
    text += "quality.angle_histogram:";
    for (std::size_t k = 0; k < r.angle_histogram.size(); ++k) {
        char bin[64];
        std::snprintf(bin, sizeof bin, " %zu-%zu:%llu", 10 * k, 10 * k + 10,
                      static_cast<unsigned long long>(r.angle_histogram[k]));
        text += bin;
    }
    text += "\n";
    text += "quality.radius_edge: min " + format_fixed(r.radius_edge_min) + " median " +
            format_fixed(r.radius_edge_median) + " max " + format_fixed(r.radius_edge_max) + "\n";
    if (r.has_size) {
        text += "quality.size_conformity: min " + format_fixed(r.size_ratio_min) + " median " +
                format_fixed(r.size_ratio_median) + " max " + format_fixed(r.size_ratio_max) +
                " (edge length / size at its midpoint, " + std::to_string(r.edges) + " edges)\n";
    } else {
        text += "quality.size_conformity: none (no size function)\n";
    }
    text += "quality.seconds: " + format_fixed(r.seconds) + "\n";
    return text;
}

}  // namespace exactmesh::generators
