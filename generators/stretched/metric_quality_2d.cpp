// SPDX-License-Identifier: MIT
// The stretched-mesh quality report (see metric_quality_2d.hpp).
#include "generators/stretched/metric_quality_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <vector>

#include "base/number_text.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace {

using predicates::PowerOfTwo;
using triangulation::VertIdx;

/// Three edge vectors (ex[k], ey[k]) scaled exactly by the power of two that brings their
/// largest component to [1, 2) (unchanged when all are zero or one is not finite).
void scale_to_unit(double ex[3], double ey[3]) {
    double largest = 0;
    for (int k = 0; k < 3; ++k) largest = std::max({largest, std::fabs(ex[k]), std::fabs(ey[k])});
    const PowerOfTwo scale(predicates::unit_shift(largest));
    for (int k = 0; k < 3; ++k) ex[k] = scale(ex[k]), ey[k] = scale(ey[k]);
}

/// The mean ratio 4 sqrt(3) area / sum of squared edge lengths of the triangle with edge
/// vectors (ex, ey) (e[k] from corner k to corner k + 1), signed area: 0 or less when inverted.
double mean_ratio(double ex[3], double ey[3]) {
    scale_to_unit(ex, ey);
    const double area = 0.5 * (ex[0] * -ey[2] - ey[0] * -ex[2]);
    double squares = 0;
    for (int k = 0; k < 3; ++k) squares += ex[k] * ex[k] + ey[k] * ey[k];
    return squares > 0 ? 4.0 * std::numbers::sqrt3 * area / squares : 0.0;
}

/// The largest corner angle (degrees) and longest edge over smallest altitude of the triangle
/// with Euclidean edge vectors (ex, ey), from atan2(|cross|, dot) at each corner.
void euclidean_shape(double ex[3], double ey[3], double& largest_angle, double& aspect) {
    scale_to_unit(ex, ey);
    largest_angle = 0;
    double longest2 = 0;
    for (int k = 0; k < 3; ++k) {
        // At corner k + 1: the vectors to corner k (-e[k]) and to corner k + 2 (e[k + 1]).
        const int j = (k + 1) % 3;
        const double ux = -ex[k], uy = -ey[k], wx = ex[j], wy = ey[j];
        const double angle = std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
        largest_angle = std::max(largest_angle, angle * (180.0 / std::numbers::pi));
        longest2 = std::max(longest2, ex[k] * ex[k] + ey[k] * ey[k]);
    }
    const double twice_area = std::fabs(ex[0] * ey[1] - ey[0] * ex[1]);
    aspect = twice_area > 0 ? longest2 / twice_area : std::numeric_limits<double>::infinity();
}

}  // namespace

MetricQualityReport2 metric_quality_report_2d(std::span<const double> xy,
                                              std::span<const VertIdx> triangles,
                                              const MetricField2& metric) {
    MetricQualityReport2 r;
    const std::size_t count = triangles.size() / 3;
    r.triangles = count;
    if (count == 0) return r;
    // The field at each vertex a triangle uses, once.
    std::vector<Metric2> at_vertex(xy.size() / 2);
    std::vector<std::uint8_t> evaluated(xy.size() / 2, 0);
    for (const VertIdx v : triangles) {
        if (evaluated[v] != 0) continue;
        at_vertex[v] = metric(xy[2 * std::size_t{v}], xy[2 * std::size_t{v} + 1]);
        evaluated[v] = 1;
    }
    const std::vector<VertIdx> edges = mesh_edges_2d(triangles);
    r.edges = edges.size() / 2;
    std::vector<double> lengths;
    lengths.reserve(r.edges);
    const double half[2] = {0.5, 0.5};
    std::uint64_t unit = 0;
    for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
        const VertIdx a = edges[e], b = edges[e + 1];
        const Metric2 ends[2] = {at_vertex[a], at_vertex[b]};
        const Metric2 middle = log_euclidean_mean(ends, half);
        const double length =
            metric_length(middle, xy[2 * std::size_t{b}] - xy[2 * std::size_t{a}],
                          xy[2 * std::size_t{b} + 1] - xy[2 * std::size_t{a} + 1]);
        lengths.push_back(length);
        // A relative 1e-12 of slack at both ends: the diagonal of a unit square of the metric
        // is sqrt 2 exactly, and its computed length lands an ulp on either side of it.
        if (length >= std::numbers::sqrt2 / 2 * (1 - 1e-12) &&
            length <= std::numbers::sqrt2 * (1 + 1e-12)) {
            ++unit;
        }
    }
    r.length_min = *std::min_element(lengths.begin(), lengths.end());
    r.length_max = *std::max_element(lengths.begin(), lengths.end());
    r.length_median = median_of(lengths);
    r.unit_length_share = static_cast<double>(unit) / static_cast<double>(r.edges);

    std::vector<double> shapes, aspects;
    shapes.reserve(count);
    aspects.reserve(count);
    const double third[3] = {1.0 / 3, 1.0 / 3, 1.0 / 3};
    double shape_sum = 0;
    for (std::size_t t = 0; t < count; ++t) {
        const VertIdx v[3] = {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
        double ex[3], ey[3];
        for (int k = 0; k < 3; ++k) {
            const double* p = &xy[2 * std::size_t{v[k]}];
            const double* q = &xy[2 * std::size_t{v[(k + 1) % 3]}];
            ex[k] = q[0] - p[0];
            ey[k] = q[1] - p[1];
        }
        const Metric2 corners[3] = {at_vertex[v[0]], at_vertex[v[1]], at_vertex[v[2]]};
        const Metric2 mean = log_euclidean_mean(corners, third);
        double mx[3], my[3];
        for (int k = 0; k < 3; ++k) metric_map(mean, ex[k], ey[k], mx[k], my[k]);
        const double shape = mean_ratio(mx, my);
        shapes.push_back(shape);
        shape_sum += shape;
        double largest_angle = 0, aspect = 0;
        euclidean_shape(ex, ey, largest_angle, aspect);
        aspects.push_back(aspect);
        r.max_angle = std::max(r.max_angle, largest_angle);
        ++r.max_angle_histogram[std::min<std::size_t>(
            17, static_cast<std::size_t>(largest_angle / 10))];
        if (largest_angle > 150) ++r.above_150_degrees;
    }
    r.shape_min = *std::min_element(shapes.begin(), shapes.end());
    r.shape_mean = shape_sum / static_cast<double>(count);
    r.shape_median = median_of(shapes);
    r.aspect_min = *std::min_element(aspects.begin(), aspects.end());
    r.aspect_max = *std::max_element(aspects.begin(), aspects.end());
    r.aspect_median = median_of(aspects);
    return r;
}

std::string metric_quality_report_text(const MetricQualityReport2& r) {
    std::string text;
    text += "quality.metric_edge_length: min " + format_fixed(r.length_min) + " median " +
            format_fixed(r.length_median) + " max " + format_fixed(r.length_max) + " (" +
            std::to_string(r.edges) + " edges, " + format_fixed(100 * r.unit_length_share, 2) +
            "% in [1/sqrt2, sqrt2])\n";
    text += "quality.metric_shape: min " + format_fixed(r.shape_min) + " median " +
            format_fixed(r.shape_median) + " mean " + format_fixed(r.shape_mean) +
            " (mean ratio in the metric, 1 = equilateral)\n";
    text += "quality.max_angle_histogram:";
    for (std::size_t k = 0; k < r.max_angle_histogram.size(); ++k) {
        char bin[64];
        std::snprintf(bin, sizeof bin, " %zu-%zu:%llu", 10 * k, 10 * k + 10,
                      static_cast<unsigned long long>(r.max_angle_histogram[k]));
        text += bin;
    }
    text += "\n";
    text += "quality.above_150_degrees: " + std::to_string(r.above_150_degrees) + " of " +
            std::to_string(r.triangles) + " triangles\n";
    text += "quality.aspect_ratio: min " + format_fixed(r.aspect_min) + " median " +
            format_fixed(r.aspect_median) + " max " + format_fixed(r.aspect_max) +
            " (longest edge / smallest altitude, 1.154701 = equilateral)\n";
    return text;
}

}  // namespace exactmesh::generators
