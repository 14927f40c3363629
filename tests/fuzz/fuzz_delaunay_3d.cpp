// SPDX-License-Identifier: MIT
// libFuzzer target: the two 3D Delaunay constructions (Bowyer-Watson, Green-Sibson) on up to
// kMaxPoints fuzzed points. Each output must pass the exact check (triangulation/checks/check_3d, with
// its neighbor array) and keep the points; the two must agree exactly for the same insertion
// order (shared perturbation, same kept copies of duplicates), and for different orders when no
// point repeats; small inputs must match the naive empty-sphere oracle (every 4-subset whose
// perturbed circumsphere is empty). Non-finite input must make both throw NonFiniteCoordinate
// naming the first bad point. Anything else is __builtin_trap().
//
// Input layout: the first 8·floor(size/8) bytes are doubles copied bit for bit, x0 y0 z0 x1 ...
// (a partial last point is dropped). The size % 8 bytes left over are the optional trailer: a
// mode byte and a parameter byte that reshape the raw values towards what random bits almost
// never produce (see reshape()): lattices, ulp-perturbed lattices, duplicates, exactly
// cospherical points.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <set>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"

namespace {

namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 160;
/// Raw bit patterns put coordinates at every magnitude, where every predicate ends in GMP.
constexpr std::size_t kMaxRawPoints = 40;
/// The oracle is O(n^5); above this it is skipped.
constexpr std::size_t kOracleMaxPoints = 12;

const std::array<tri::Delaunay3Function, 2> kAlgorithms = {
    tri::delaunay_3d_algorithm("bowyer-watson"), tri::delaunay_3d_algorithm("green-sibson")};
constexpr std::array<const char*, 2> kNames = {"bowyer-watson", "green-sibson"};
constexpr std::array<tri::InsertionOrder, 3> kOrders = {
    tri::InsertionOrder::Given, tri::InsertionOrder::Random, tri::InsertionOrder::Brio};

enum class Mode : std::uint8_t { raw, lattice, ulps, duplicates, cospherical, count };

std::uint64_t bits_of(double x) {
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

double nudge(double x, int ulps) {
    for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
    return x;
}

/// All integer points of x^2 + y^2 + z^2 = 15^2 (exactly cospherical).
const std::vector<std::array<int, 3>>& sphere_points() {
    static const std::vector<std::array<int, 3>> points = [] {
        constexpr int r = 15;
        std::vector<std::array<int, 3>> out;
        for (int x = -r; x <= r; ++x)
            for (int y = -r; y <= r; ++y)
                for (int z = -r; z <= r; ++z)
                    if (x * x + y * y + z * z == r * r) out.push_back({x, y, z});
        return out;
    }();
    return points;
}

void reshape(std::vector<double>& xyz, Mode mode, std::uint8_t parameter) {
    const int exponent = static_cast<int>(parameter >> 2) * 31 - 1100;  // 2^-1100 .. 2^853
    switch (mode) {
        case Mode::raw:
        case Mode::count:
            return;
        case Mode::lattice: {
            // Small integers (2 to 6 bits) times one power of two: coplanar and cospherical
            // subsets everywhere, exact zeros, underflow at the low exponents.
            const int width = std::array<int, 4>{2, 3, 4, 6}[parameter & 3u];
            for (double& v : xyz) {
                const auto small = static_cast<std::int64_t>(bits_of(v) & ((1u << width) - 1)) -
                                   (std::int64_t{1} << (width - 1));
                v = std::ldexp(static_cast<double>(small), exponent);
            }
            return;
        }
        case Mode::ulps:
            // An 8 x 8 x 8 lattice scaled to about 2^e, each coordinate moved by -2..2 ulps.
            for (double& v : xyz) {
                const std::uint64_t b = bits_of(v);
                v = nudge(std::ldexp(static_cast<double>((b & 7u) + 8), exponent),
                          static_cast<int>((b >> 8) % 5) - 2);
            }
            return;
        case Mode::duplicates: {
            const std::size_t n = xyz.size() / 3;
            for (std::size_t i = 1; i < n; ++i) {
                const std::uint64_t b = bits_of(xyz[3 * i]);
                if (b % (1u + parameter % 4u) != 0) continue;
                const std::size_t j = (b >> 8) % i;
                for (std::size_t c = 0; c < 3; ++c) xyz[3 * i + c] = xyz[3 * j + c];
            }
            return;
        }
        case Mode::cospherical: {
            // Lattice points of one sphere, possibly its centre, on up to four spheres with
            // integer centres; scaled by a power of two.
            const auto& sphere = sphere_points();
            const int scale = static_cast<int>(parameter >> 2) * 16 - 500;
            for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
                const std::uint64_t b = bits_of(xyz[i]);
                const auto& p = sphere[b % sphere.size()];
                const int centre =
                    static_cast<int>(bits_of(xyz[i + 1]) % (1u + (parameter & 3u))) * 20;
                const bool at_centre = (b >> 20) % 16 == 0;
                for (std::size_t c = 0; c < 3; ++c) {
                    xyz[i + c] = std::ldexp(
                        static_cast<double>((at_centre ? 0 : p[c]) + (c == 0 ? centre : 0)), scale);
                }
            }
            return;
        }
    }
}

[[noreturn]] void fail(const std::vector<double>& xyz, const std::string& what) {
    std::fprintf(stderr, "fuzz_delaunay_3d: %s\npoints (%zu):", what.c_str(), xyz.size() / 3);
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        std::fprintf(stderr, " (%a, %a, %a)", xyz[i], xyz[i + 1], xyz[i + 2]);
    }
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

using Tets = std::set<std::array<tri::VertIdx, 4>>;

Tets canonical(const std::vector<tri::VertIdx>& tets) {
    Tets out;
    for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
        std::array<tri::VertIdx, 4> a{tets[t], tets[t + 1], tets[t + 2], tets[t + 3]};
        std::sort(a.begin(), a.end());
        out.insert(a);
    }
    return out;
}

bool has_duplicates(const std::vector<double>& xyz) {
    std::set<std::array<double, 3>> seen;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        if (!seen.insert({xyz[i] + 0.0, xyz[i + 1] + 0.0, xyz[i + 2] + 0.0}).second) return true;
    }
    return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::size_t trailer = size % 8;
    const Mode mode = trailer > 0
                          ? static_cast<Mode>(data[size - trailer] % static_cast<int>(Mode::count))
                          : Mode::raw;
    const std::uint8_t parameter = trailer > 1 ? data[size - trailer + 1] : 0;
    const bool raw_values = mode == Mode::raw || mode == Mode::duplicates;
    const std::size_t doubles =
        std::min(size / 8, 3 * (raw_values ? kMaxRawPoints : kMaxPoints)) / 3 * 3;
    std::vector<double> xyz(doubles);
    if (doubles > 0) std::memcpy(xyz.data(), data, doubles * sizeof(double));
    reshape(xyz, mode, parameter);
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a: orders and seed from the data too
    for (std::size_t i = 0; i < size; ++i) hash = (hash ^ data[i]) * 1099511628211ull;
    const tri::Delaunay3Options same{kOrders[hash % 3], hash >> 8};
    const tri::Delaunay3Options other{kOrders[(hash >> 2) % 3], (hash >> 8) + 1};

    const auto bad =
        std::find_if(xyz.begin(), xyz.end(), [](double v) { return !std::isfinite(v); });
    if (bad != xyz.end()) {
        const auto vertex = static_cast<std::uint32_t>((bad - xyz.begin()) / 3);
        for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
            try {
                kAlgorithms[a](xyz, same);
            } catch (const exactmesh::NonFiniteCoordinate& e) {
                if (e.vertex() != vertex) {
                    fail(xyz, std::string(kNames[a]) + ": NonFiniteCoordinate names point " +
                                  std::to_string(e.vertex()) + ", the first is " +
                                  std::to_string(vertex));
                }
                continue;
            } catch (const std::exception& e) {
                fail(xyz, std::string(kNames[a]) +
                              " threw something else on non-finite input: " + e.what());
            }
            fail(xyz, std::string(kNames[a]) + " accepted a non-finite coordinate");
        }
        return 0;
    }

    std::array<tri::Delaunay3Result, 2> results;
    for (std::size_t a = 0; a < kAlgorithms.size(); ++a) {
        try {
            results[a] = kAlgorithms[a](xyz, same);
        } catch (const std::exception& e) {
            fail(xyz, std::string(kNames[a]) + " threw on finite input: " + e.what());
        }
        const tri::Check3Report report = tri::check_delaunay_3d(results[a].mesh);
        if (!report.ok) fail(xyz, std::string(kNames[a]) + ": check: " + report.problem);
        if (results[a].mesh.xyz != xyz) fail(xyz, std::string(kNames[a]) + ": points changed");
    }
    if (canonical(results[1].mesh.tets) != canonical(results[0].mesh.tets) ||
        results[1].merged_into != results[0].merged_into ||
        results[1].coplanar != results[0].coplanar) {
        fail(xyz, "green-sibson and bowyer-watson differ for the same insertion order");
    }
    if (!has_duplicates(xyz)) {
        const tri::Delaunay3Result again = kAlgorithms[hash % 2](xyz, other);
        if (canonical(again.mesh.tets) != canonical(results[0].mesh.tets)) {
            fail(xyz, std::string(kNames[hash % 2]) +
                          ": another insertion order gives other tetrahedra");
        }
        if (xyz.size() / 3 <= kOracleMaxPoints &&
            canonical(results[0].mesh.tets) != exactmesh::oracles::empty_sphere_delaunay_3d(xyz)) {
            fail(xyz, "the tetrahedra differ from the naive empty-sphere oracle");
        }
    }
    return 0;
}
