// SPDX-License-Identifier: MIT
// Point-set generators shared by tests, benchmarks and `exactmesh fuzz`: uniform, Gaussian
// clusters, integer grids, exactly cocircular points, near-collinear by a few ulps, duplicates,
// huge and tiny magnitudes, and an adversarial insertion order (a parabola, sorted).
// Every generator is deterministic for a given (n, seed).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace exactmesh::generators {

enum class Distribution {
    Uniform,        ///< uniform in [0, 1)^2
    Gaussian,       ///< Gaussian clusters (about 1000 points each, sigma 0.01) in [0, 1)^2
    Grid,           ///< integer grid, row by row: many cocircular quadruples and collinear rows
    Cocircular,     ///< exact lattice points on circles x^2 + y^2 = R^2 (R = 2082925), shifted
    NearCollinear,  ///< points on y = x moved by -4..4 ulps, plus two far points
    Duplicates,     ///< uniform, a third of the points repeating earlier ones exactly
    Huge,           ///< uniform scaled by 1e290 (products overflow)
    Tiny,           ///< uniform scaled by 1e-290, with some subnormal coordinates
    Parabola,       ///< (t, t^2) by increasing t; inserted backwards (decreasing t), each
                    ///< Bowyer-Watson cavity holds all earlier triangles: Theta(n^2)
};

inline constexpr Distribution kAllDistributions[] = {
    Distribution::Uniform,    Distribution::Gaussian,      Distribution::Grid,
    Distribution::Cocircular, Distribution::NearCollinear, Distribution::Duplicates,
    Distribution::Huge,       Distribution::Tiny,          Distribution::Parabola};

std::string_view distribution_name(Distribution d);
/// Throws exactmesh::InputError naming the unknown distribution and the known ones.
Distribution distribution_from_name(std::string_view name);

/// n points (2n doubles, x0 y0 x1 y1 ...) of the distribution.
std::vector<double> generate_points_2d(Distribution d, std::uint32_t n, std::uint64_t seed);

}  // namespace exactmesh::generators
