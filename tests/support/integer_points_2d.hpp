// SPDX-License-Identifier: MIT
// Random integer points in [0, range)^2 without repeats: small ranges make collinear and
// cocircular subsets frequent. Test support.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace exactmesh::testing {

inline std::vector<double> integer_points(std::uint32_t n, std::uint32_t range,
                                          std::mt19937_64& rng) {
    std::vector<double> xy;
    std::set<std::pair<double, double>> seen;
    while (xy.size() < 2 * std::size_t{n}) {
        const auto x = static_cast<double>(rng() % range), y = static_cast<double>(rng() % range);
        if (seen.insert({x, y}).second) xy.insert(xy.end(), {x, y});
    }
    return xy;
}

}  // namespace exactmesh::testing
