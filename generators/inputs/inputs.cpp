// SPDX-License-Identifier: MIT
// Point-set generators (see inputs.hpp).
#include "generators/inputs/inputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include "base/errors.hpp"

namespace exactmesh::generators {

namespace {

struct NameOf {
    Distribution distribution;
    std::string_view name;
};
constexpr NameOf kNames[] = {{Distribution::Uniform, "uniform"},
                             {Distribution::Gaussian, "gaussian"},
                             {Distribution::Grid, "grid"},
                             {Distribution::Cocircular, "cocircular"},
                             {Distribution::NearCollinear, "near-collinear"},
                             {Distribution::Duplicates, "duplicates"},
                             {Distribution::Huge, "huge"},
                             {Distribution::Tiny, "tiny"},
                             {Distribution::Parabola, "parabola"}};

/// All integer points on x^2 + y^2 = R^2 for R = 5^2 * 13^2 * 17 * 29 (900 points: R^2 has
/// many representations as a sum of two squares), in angular order of discovery.
const std::vector<std::int64_t>& circle_lattice() {
    static const std::vector<std::int64_t> points = [] {
        constexpr std::int64_t R = 25 * 169 * 17 * 29;
        std::vector<std::int64_t> out;
        for (std::int64_t x = -R; x <= R; ++x) {
            const std::int64_t rest = R * R - x * x;
            auto y = static_cast<std::int64_t>(std::sqrt(static_cast<double>(rest)));
            while (y * y > rest) --y;
            while ((y + 1) * (y + 1) <= rest) ++y;
            if (y * y != rest) continue;
            out.push_back(x);
            out.push_back(y);
            if (y != 0) {
                out.push_back(x);
                out.push_back(-y);
            }
        }
        return out;
    }();
    return points;
}

}  // namespace

std::string_view distribution_name(Distribution d) {
    for (const NameOf& entry : kNames) {
        if (entry.distribution == d) return entry.name;
    }
    return "unknown";
}

Distribution distribution_from_name(std::string_view name) {
    std::string known;
    for (const NameOf& entry : kNames) {
        if (entry.name == name) return entry.distribution;
        known += (known.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw InputError("unknown distribution '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<double> generate_points_2d(Distribution d, std::uint32_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(d));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xy;
    xy.reserve(2 * static_cast<std::size_t>(n));
    switch (d) {
        case Distribution::Uniform:
            for (std::uint32_t i = 0; i < 2 * n; ++i) xy.push_back(unit(rng));
            break;
        case Distribution::Gaussian: {
            const std::uint32_t clusters = std::max<std::uint32_t>(1, n / 1000);
            std::vector<double> centres(2 * clusters);
            for (double& c : centres) c = 0.1 + 0.8 * unit(rng);
            std::normal_distribution<double> spread(0.0, 0.01);
            std::uniform_int_distribution<std::uint32_t> pick(0, clusters - 1);
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t c = pick(rng);
                xy.push_back(centres[2 * c] + spread(rng));
                xy.push_back(centres[2 * c + 1] + spread(rng));
            }
            break;
        }
        case Distribution::Grid: {
            const auto side =
                static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(n))));
            for (std::uint32_t i = 0; i < n; ++i) {
                xy.push_back(static_cast<double>(i % std::max(side, 1u)));
                xy.push_back(static_cast<double>(i / std::max(side, 1u)));
            }
            break;
        }
        case Distribution::Cocircular: {
            // Circles of the lattice, each shifted by an integer offset: every circle stays
            // exactly cocircular (integers below 2^53 are exact).
            const std::vector<std::int64_t>& lattice = circle_lattice();
            const std::size_t per_circle = lattice.size() / 2;
            std::vector<std::size_t> order(per_circle);
            for (std::size_t k = 0; k < per_circle; ++k) order[k] = k;
            std::shuffle(order.begin(), order.end(), rng);  // distinct points on each circle
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::size_t circle = i / per_circle;
                const std::size_t k = order[i % per_circle];
                const double shift_x = static_cast<double>(circle % 7) * 5000000.0;
                const double shift_y = static_cast<double>(circle / 7) * 5000000.0;
                xy.push_back(static_cast<double>(lattice[2 * k]) + shift_x);
                xy.push_back(static_cast<double>(lattice[2 * k + 1]) + shift_y);
            }
            break;
        }
        case Distribution::NearCollinear: {
            std::uniform_int_distribution<int> ulps(-4, 4);
            for (std::uint32_t i = 0; i < n; ++i) {
                const double t = 0.5 + unit(rng);
                double y = t;
                for (int k = ulps(rng); k != 0; k += (k > 0 ? -1 : 1)) {
                    y = std::nextafter(y, k > 0 ? 2.0 : 0.0);
                }
                xy.push_back(t);
                xy.push_back(y);
            }
            if (n >= 2) {  // two far points on the same line, as in the classic 12 / 24 test
                xy[0] = xy[1] = 12.0;
                xy[2] = xy[3] = 24.0;
            }
            break;
        }
        case Distribution::Duplicates:
            for (std::uint32_t i = 0; i < n; ++i) {
                if (i > 0 && unit(rng) < 1.0 / 3.0) {
                    const auto j = static_cast<std::uint32_t>(unit(rng) * i);
                    xy.push_back(xy[2 * j]);
                    xy.push_back(xy[2 * j + 1]);
                } else {
                    xy.push_back(unit(rng));
                    xy.push_back(unit(rng));
                }
            }
            break;
        case Distribution::Huge:
            for (std::uint32_t i = 0; i < 2 * n; ++i) xy.push_back((unit(rng) - 0.5) * 1e290);
            break;
        case Distribution::Tiny:
            for (std::uint32_t i = 0; i < 2 * n; ++i) {
                const double scale = unit(rng) < 0.1 ? 1e-310 : 1e-290;  // some subnormals
                xy.push_back((unit(rng) - 0.5) * scale);
            }
            break;
        case Distribution::Parabola:
            for (std::uint32_t i = 0; i < n; ++i) {
                const double t = static_cast<double>(i) / std::max<std::uint32_t>(n, 1);
                xy.push_back(t);
                xy.push_back(t * t);
            }
            break;
    }
    return xy;
}

}  // namespace exactmesh::generators
