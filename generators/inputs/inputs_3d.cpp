// SPDX-License-Identifier: MIT
// 3D point-set generators (see inputs_3d.hpp).
#include "generators/inputs/inputs_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <string>

#include "base/errors.hpp"

namespace exactmesh::generators {

namespace {

struct NameOf {
    Distribution3 distribution;
    std::string_view name;
};
constexpr NameOf kNames[] = {{Distribution3::Uniform, "uniform"},
                             {Distribution3::Gaussian, "gaussian"},
                             {Distribution3::Grid, "grid"},
                             {Distribution3::Cospherical, "cospherical"},
                             {Distribution3::NearCoplanar, "near-coplanar"},
                             {Distribution3::Duplicates, "duplicates"},
                             {Distribution3::Huge, "huge"},
                             {Distribution3::Tiny, "tiny"}};

/// All integer points on x^2 + y^2 + z^2 = R^2 for R = 231 = 3 * 7 * 11 (3510 of them).
const std::vector<std::array<std::int64_t, 3>>& sphere_lattice() {
    static const std::vector<std::array<std::int64_t, 3>> points = [] {
        constexpr std::int64_t R = 231;
        std::vector<std::array<std::int64_t, 3>> out;
        for (std::int64_t x = -R; x <= R; ++x) {
            for (std::int64_t y = -R; y <= R; ++y) {
                const std::int64_t rest = R * R - x * x - y * y;
                if (rest < 0) continue;
                auto z = static_cast<std::int64_t>(std::sqrt(static_cast<double>(rest)));
                while (z * z > rest) --z;
                while ((z + 1) * (z + 1) <= rest) ++z;
                if (z * z != rest) continue;
                out.push_back({x, y, z});
                if (z != 0) out.push_back({x, y, -z});
            }
        }
        return out;
    }();
    return points;
}

}  // namespace

std::string_view distribution_name(Distribution3 d) {
    for (const NameOf& entry : kNames) {
        if (entry.distribution == d) return entry.name;
    }
    return "unknown";
}

Distribution3 distribution3_from_name(std::string_view name) {
    std::string known;
    for (const NameOf& entry : kNames) {
        if (entry.name == name) return entry.distribution;
        known += (known.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw InputError("unknown 3D distribution '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<double> generate_points_3d(Distribution3 d, std::uint32_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + 0x3D00u + static_cast<std::uint64_t>(d));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xyz;
    xyz.reserve(3 * static_cast<std::size_t>(n));
    switch (d) {
        case Distribution3::Uniform:
            for (std::uint32_t i = 0; i < 3 * n; ++i) xyz.push_back(unit(rng));
            break;
        case Distribution3::Gaussian: {
            const std::uint32_t clusters = std::max<std::uint32_t>(1, n / 1000);
            std::vector<double> centres(3 * clusters);
            for (double& c : centres) c = 0.1 + 0.8 * unit(rng);
            std::normal_distribution<double> spread(0.0, 0.01);
            std::uniform_int_distribution<std::uint32_t> pick(0, clusters - 1);
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t c = pick(rng);
                for (std::uint32_t k = 0; k < 3; ++k)
                    xyz.push_back(centres[3 * c + k] + spread(rng));
            }
            break;
        }
        case Distribution3::Grid: {
            auto side = static_cast<std::uint32_t>(std::ceil(std::cbrt(static_cast<double>(n))));
            side = std::max(side, 1u);
            for (std::uint32_t i = 0; i < n; ++i) {
                xyz.push_back(static_cast<double>(i % side));
                xyz.push_back(static_cast<double>((i / side) % side));
                xyz.push_back(static_cast<double>(i / (side * side)));
            }
            break;
        }
        case Distribution3::Cospherical: {
            // Spheres of the lattice, each shifted by an integer offset: every sphere stays
            // exactly cospherical (integers below 2^53 are exact).
            const auto& lattice = sphere_lattice();
            std::vector<std::size_t> order(lattice.size());
            for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
            std::shuffle(order.begin(), order.end(), rng);
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::size_t sphere = i / lattice.size();
                const auto& p = lattice[order[i % lattice.size()]];
                const double shift = static_cast<double>(sphere) * 500.0;
                xyz.push_back(static_cast<double>(p[0]) + shift);
                xyz.push_back(static_cast<double>(p[1]));
                xyz.push_back(static_cast<double>(p[2]) + static_cast<double>(sphere % 3) * 100.0);
            }
            break;
        }
        case Distribution3::NearCoplanar: {
            std::uniform_int_distribution<int> ulps(-4, 4);
            for (std::uint32_t i = 0; i < n; ++i) {
                const double x = 0.5 + unit(rng), y = 0.5 + unit(rng);
                double z = x + y;
                for (int k = ulps(rng); k != 0; k += (k > 0 ? -1 : 1)) {
                    z = std::nextafter(z, k > 0 ? 8.0 : 0.0);
                }
                xyz.insert(xyz.end(), {x, y, z});
            }
            if (n >= 2) {  // two far apexes, one on each side of the plane
                xyz[0] = 1.0, xyz[1] = 1.0, xyz[2] = 12.0;
                xyz[3] = 1.0, xyz[4] = 1.0, xyz[5] = -10.0;
            }
            break;
        }
        case Distribution3::Duplicates:
            for (std::uint32_t i = 0; i < n; ++i) {
                if (i > 0 && unit(rng) < 1.0 / 3.0) {
                    const auto j = static_cast<std::uint32_t>(unit(rng) * i);
                    for (std::uint32_t k = 0; k < 3; ++k) xyz.push_back(xyz[3 * j + k]);
                } else {
                    for (std::uint32_t k = 0; k < 3; ++k) xyz.push_back(unit(rng));
                }
            }
            break;
        case Distribution3::Huge:
            for (std::uint32_t i = 0; i < 3 * n; ++i) xyz.push_back((unit(rng) - 0.5) * 1e290);
            break;
        case Distribution3::Tiny:
            for (std::uint32_t i = 0; i < 3 * n; ++i) {
                const double scale = unit(rng) < 0.1 ? 1e-310 : 1e-290;  // some subnormals
                xyz.push_back((unit(rng) - 0.5) * scale);
            }
            break;
    }
    return xyz;
}

}  // namespace exactmesh::generators
