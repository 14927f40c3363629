// SPDX-License-Identifier: MIT
// 3D point-set generators shared by tests, benchmarks and fuzzing, in the style of inputs.hpp:
// uniform, Gaussian clusters, integer cubic grids (massively cospherical and coplanar), exact
// lattice points on spheres, near-coplanar by a few ulps, duplicates, huge and tiny magnitudes.
// Every generator is deterministic for a given (n, seed).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace exactmesh::generators {

enum class Distribution3 {
    Uniform,       ///< uniform in [0, 1)^3
    Gaussian,      ///< Gaussian clusters (about 1000 points each, sigma 0.01) in [0, 1)^3
    Grid,          ///< integer cubic grid, row by row: every unit cube's 8 corners cospherical
    Cospherical,   ///< exact integer points on spheres x^2 + y^2 + z^2 = 231^2 (3510 per
                   ///< sphere), shifted, each sphere's points in random order
    NearCoplanar,  ///< points on the plane z = x + y moved by -4..4 ulps, plus two far apexes
    Duplicates,    ///< uniform, a third of the points repeating earlier ones exactly
    Huge,          ///< uniform scaled by 1e290 (products overflow)
    Tiny,          ///< uniform scaled by 1e-290, with some subnormal coordinates
};

inline constexpr Distribution3 kAllDistributions3[] = {
    Distribution3::Uniform,     Distribution3::Gaussian,     Distribution3::Grid,
    Distribution3::Cospherical, Distribution3::NearCoplanar, Distribution3::Duplicates,
    Distribution3::Huge,        Distribution3::Tiny};

std::string_view distribution_name(Distribution3 d);
/// Throws exactmesh::InputError naming the unknown distribution and the known ones.
Distribution3 distribution3_from_name(std::string_view name);

/// n points (3n doubles, x0 y0 z0 x1 ...) of the distribution.
std::vector<double> generate_points_3d(Distribution3 d, std::uint32_t n, std::uint64_t seed);

}  // namespace exactmesh::generators
