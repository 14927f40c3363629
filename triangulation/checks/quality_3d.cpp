// SPDX-License-Identifier: MIT
// Quality statistics of a tetrahedralization (see quality_3d.hpp).
#include "triangulation/checks/quality_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::triangulation {

using predicates::Dihedral;
using predicates::dihedral_radians;
using predicates::TetCorners;
using predicates::volume_edge_quality;

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

/// Circumradius over the shortest edge, in long double, on the edge vectors from p0 rescaled by
/// the power of two that brings their largest component to [1, 2): the squares below (and the
/// products of squares and cross products) then neither overflow nor underflow whatever the
/// mesh's scale, and a mesh scaled by 2^k gives the same bits (scaling by 2^k is exact). The
/// circumcenter c - p0 solves 2 [a; b; c] x = (|a|^2, |b|^2, |c|^2) with a, b, c the edges from
/// p0 (Cramer's rule). A flat tetrahedron gives infinity.
long double radius_edge(const TetCorners& p) {
    long double d[4][3];  // d[r] = p[r] - p[0]; d[0] unused
    long double largest = 0;
    for (int r = 1; r < 4; ++r) {
        for (int i = 0; i < 3; ++i) {
            d[r][i] = static_cast<long double>(p[r][i]) - p[0][i];
            largest = std::max(largest, std::fabs(d[r][i]));
        }
    }
    if (!(largest > 0) || !std::isfinite(largest))
        return std::numeric_limits<long double>::infinity();
    // Every edge p[b] - p[a] = d[b] - d[a] has components below 2 largest.
    const long double unit = std::ldexp(1.0L, -std::ilogb(largest));
    long double e[3][3];
    for (int r = 0; r < 3; ++r) {
        for (int i = 0; i < 3; ++i) e[r][i] = d[r + 1][i] * unit;
    }
    auto cross = [](const long double* x, const long double* y, long double* out) {
        out[0] = x[1] * y[2] - x[2] * y[1];
        out[1] = x[2] * y[0] - x[0] * y[2];
        out[2] = x[0] * y[1] - x[1] * y[0];
    };
    long double bc[3], ca[3], ab[3];
    cross(e[1], e[2], bc);
    cross(e[2], e[0], ca);
    cross(e[0], e[1], ab);
    const long double det = e[0][0] * bc[0] + e[0][1] * bc[1] + e[0][2] * bc[2];
    if (det == 0) return std::numeric_limits<long double>::infinity();
    long double sq[3];
    for (int r = 0; r < 3; ++r) sq[r] = e[r][0] * e[r][0] + e[r][1] * e[r][1] + e[r][2] * e[r][2];
    long double center[3];
    for (int i = 0; i < 3; ++i)
        center[i] = (sq[0] * bc[i] + sq[1] * ca[i] + sq[2] * ab[i]) / (2 * det);
    const long double radius =
        std::sqrt(center[0] * center[0] + center[1] * center[1] + center[2] * center[2]);
    long double shortest = std::min({sq[0], sq[1], sq[2]});
    for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            long double s = 0;
            for (int i = 0; i < 3; ++i) {
                const long double x = e[b][i] - e[a][i];
                s += x * x;
            }
            shortest = std::min(shortest, s);
        }
    }
    return radius / std::sqrt(shortest);
}

/// The number of bins of width `width` in [0, total), or 0 when width does not divide total into
/// at most 18000 of them.
std::size_t bin_count(double width, double total) {
    const double bins = total / width;
    if (!(width > 0) || !(total > 0) || !(bins <= 18000) ||
        std::fabs(bins - std::round(bins)) > 1e-9)
        return 0;
    return static_cast<std::size_t>(std::round(bins));
}

}  // namespace

QualityStats3 quality_stats_3d(const Tetrahedralization3& mesh, const QualityOptions& options) {
    const double width = options.histogram_bin_degrees;
    const std::size_t bins = bin_count(width, 180.0);
    if (bins == 0) {
        throw InputError(
            "dihedral histogram bin width must be positive and divide 180 degrees (got " +
            std::to_string(width) + ")");
    }
    const double ratio_width = options.radius_edge_bin_width;
    const std::size_t ratio_bins = bin_count(ratio_width, options.radius_edge_histogram_max);
    if (ratio_bins == 0) {
        throw InputError(
            "radius-edge histogram bin width must be positive and divide the "
            "histogram's positive maximum (got " +
            std::to_string(ratio_width) + " and " +
            std::to_string(options.radius_edge_histogram_max) + ")");
    }
    QualityStats3 stats;
    stats.histogram_bin_degrees = width;
    stats.dihedral_histogram.assign(bins, 0);
    stats.radius_edge_bin_width = ratio_width;
    stats.radius_edge_histogram_max = options.radius_edge_histogram_max;
    stats.radius_edge_histogram.assign(ratio_bins + 1, 0);
    stats.tets = mesh.tet_count();
    if (stats.tets == 0) return stats;
    constexpr unsigned kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    long double min_angle = 180, max_angle = 0, min_q = 2, sum_q = 0, max_ratio = 0;
    for (std::size_t t = 0; t < stats.tets; ++t) {
        // The corners scaled by the power of two that brings their largest coordinate to
        // [1, 2) (exact): the angles' long double products then stay in range whatever the
        // mesh's scale, even where long double is double, and a mesh scaled by 2^k gives the
        // same bits.
        double corners[4][3];
        double largest = 0;
        for (int r = 0; r < 4; ++r) {
            const double* point = mesh.point(mesh.tets[4 * t + static_cast<std::size_t>(r)]);
            for (int i = 0; i < 3; ++i) largest = std::max(largest, std::fabs(point[i]));
        }
        const predicates::PowerOfTwo unit(predicates::unit_shift(largest));
        for (int r = 0; r < 4; ++r) {
            const double* point = mesh.point(mesh.tets[4 * t + static_cast<std::size_t>(r)]);
            for (int i = 0; i < 3; ++i) corners[r][i] = unit(point[i]);
        }
        const TetCorners p{corners[0], corners[1], corners[2], corners[3]};
        long double smallest = 180;
        for (const auto& e : kEdges) {
            const long double degrees = dihedral_radians(Dihedral{p, e[0], e[1]}) * 180 / kPi;
            smallest = std::min(smallest, degrees);
            max_angle = std::max(max_angle, degrees);
            auto bin = static_cast<std::size_t>(std::max(0.0L, degrees / width));
            bin = std::min(bin, stats.dihedral_histogram.size() - 1);
            ++stats.dihedral_histogram[bin];
        }
        min_angle = std::min(min_angle, smallest);
        const long double q = volume_edge_quality(p);
        min_q = std::min(min_q, q);
        sum_q += q;
        const long double ratio = radius_edge(p);
        max_ratio = std::max(max_ratio, ratio);
        // The bin from the ratio (long double, exactly as scale-free as the ratio): the open bin
        // takes everything from the maximum on, infinity included.
        const long double scaled = ratio / ratio_width;
        const std::size_t bin = scaled < static_cast<long double>(ratio_bins)
                                    ? static_cast<std::size_t>(scaled)
                                    : ratio_bins;
        ++stats.radius_edge_histogram[bin];
        if (ratio > options.radius_edge_bound) ++stats.over_radius_edge_bound;
        if (smallest < options.sliver_max_dihedral_degrees &&
            ratio <= options.sliver_max_radius_edge)
            ++stats.slivers;
    }
    stats.min_dihedral_degrees = static_cast<double>(min_angle);
    stats.max_dihedral_degrees = static_cast<double>(max_angle);
    stats.min_volume_edge = static_cast<double>(min_q);
    stats.mean_volume_edge = static_cast<double>(sum_q / static_cast<long double>(stats.tets));
    stats.max_radius_edge = static_cast<double>(max_ratio);
    return stats;
}

}  // namespace exactmesh::triangulation
