// SPDX-License-Identifier: MIT
// Seeded 3D point sets for the tetrahedralization tests: uniform random points in a cube,
// random integer points, and the cubic grid (every unit cube's corners cospherical, many
// coplanar points). Coordinates xyz interleaved. Test support.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace exactmesh::testing {

/// n points uniform in [lo, hi)^3 (mt19937_64 seeded with `seed`).
inline std::vector<double> random_points_3d(std::uint32_t n, std::uint64_t seed, double lo = 0.0,
                                            double hi = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(lo, hi);
    std::vector<double> xyz(3 * std::size_t{n});
    for (double& x : xyz) x = unit(rng);
    return xyz;
}

/// n points with integer coordinates in [0, range] (mt19937_64 seeded with `seed`).
inline std::vector<double> integer_points_3d(std::uint32_t n, std::uint64_t seed, int range) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> coordinate(0, range);
    std::vector<double> xyz(3 * std::size_t{n});
    for (double& x : xyz) x = coordinate(rng);
    return xyz;
}

/// The side^3 grid points (i, j, k), 0 <= i, j, k < side, k fastest.
inline std::vector<double> cubic_grid_3d(int side) {
    std::vector<double> xyz;
    for (int i = 0; i < side; ++i) {
        for (int j = 0; j < side; ++j) {
            for (int k = 0; k < side; ++k) xyz.insert(xyz.end(), {double(i), double(j), double(k)});
        }
    }
    return xyz;
}

}  // namespace exactmesh::testing
