// SPDX-License-Identifier: MIT
// libFuzzer target: constrained Delaunay triangulation (swap, cavity and conforming recovery)
// of fuzzed points and segments, the convex hull kept. Swap and cavity must pass
// check_constrained_delaunay_2d and be identical; conforming must pass it and
// check_delaunay_2d, or stop with GeometryError (its documented split budget). Non-finite
// coordinates must raise NonFiniteCoordinate. Anything else is __builtin_trap().
//
// Input layout: byte 0 is the mode (raw doubles; small lattice integers, exactly collinear and
// cocircular everywhere; a lattice moved by -2..2 ulps), byte 1 the segment count (0..31),
// then two index bytes per segment (taken modulo the point count), then the coordinates,
// 8 bytes each (at most 2·kMaxPoints, an odd last one dropped).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <span>
#include <string>
#include <vector>

#include "predicates/errors.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/check_2d.hpp"
#include "triangulation/check_constrained_2d.hpp"
#include "triangulation/constrained_2d.hpp"

namespace {

namespace tri = exactmesh::triangulation;
using exactmesh::predicates::Sign;

constexpr std::size_t kMaxPoints = 48;

[[noreturn]] void fail(const std::vector<double>& xy, const std::vector<tri::VertIdx>& segments,
                       const std::string& what) {
    std::fprintf(stderr, "fuzz_constrained_2d: %s\npoints (%zu):", what.c_str(), xy.size() / 2);
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) std::fprintf(stderr, " (%a, %a)", xy[i], xy[i + 1]);
    std::fprintf(stderr, "\nsegments:");
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) std::fprintf(stderr, " %u-%u", segments[s], segments[s + 1]);
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

std::vector<std::array<tri::VertIdx, 3>> canonical(const tri::Triangulation2& m) {
    std::vector<std::array<tri::VertIdx, 3>> out;
    for (std::size_t t = 0; t + 2 < m.triangles.size(); t += 3) {
        std::array<tri::VertIdx, 3> a{m.triangles[t], m.triangles[t + 1], m.triangles[t + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        out.push_back(a);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const std::uint8_t mode = data[0] % 3;
    const std::size_t segment_count = data[1] % 32;
    std::size_t at = 2;
    if (size < at + 2 * segment_count) return 0;
    std::vector<std::uint8_t> ends(data + at, data + at + 2 * segment_count);
    at += 2 * segment_count;
    const std::size_t doubles = std::min((size - at) / 8, 2 * kMaxPoints) & ~std::size_t{1};
    std::vector<double> xy(doubles);
    if (doubles > 0) std::memcpy(xy.data(), data + at, doubles * sizeof(double));
    for (double& v : xy) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        if (mode == 1) v = static_cast<double>(static_cast<int>(bits % 9) - 4);  // lattice -4..4
        if (mode == 2) {
            v = static_cast<double>(bits % 9) + 16;
            for (int k = static_cast<int>((bits >> 8) % 5) - 2; k != 0; k += k > 0 ? -1 : 1) {
                v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
            }
        }
    }
    const std::size_t n = xy.size() / 2;
    std::vector<tri::VertIdx> segments;
    if (n > 0) {
        for (const std::uint8_t e : ends) segments.push_back(static_cast<tri::VertIdx>(e % n));
    }
    const tri::Pslg pslg{xy, segments, {}, {}};
    auto options = [](tri::SegmentRecovery recovery) {
        tri::Cdt2Options o;
        o.recovery = recovery;
        o.remove_exterior = false;
        return o;
    };

    if (std::any_of(xy.begin(), xy.end(), [](double v) { return !std::isfinite(v); })) {
        try {
            tri::constrained_delaunay_2d(pslg, options(tri::SegmentRecovery::Swap));
        } catch (const exactmesh::NonFiniteCoordinate&) {
            return 0;
        } catch (const std::exception& e) {
            fail(xy, segments, std::string("non-finite input: wrong exception: ") + e.what());
        }
        fail(xy, segments, "non-finite coordinate accepted");
    }

    std::array<tri::Cdt2Result, 2> cdt;
    const tri::SegmentRecovery recoveries[] = {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity};
    for (std::size_t k = 0; k < 2; ++k) {
        try {
            cdt[k] = tri::constrained_delaunay_2d(pslg, options(recoveries[k]));
        } catch (const std::exception& e) {
            fail(xy, segments, std::string(tri::segment_recovery_name(recoveries[k])) + " threw: " + e.what());
        }
    }
    const std::vector<tri::VertIdx>& kept = segments;  // the check follows duplicates' used copies
    for (std::size_t k = 0; k < 2; ++k) {
        // Collinear input has no triangle to carry flags: the check then follows the pieces.
        const auto report = tri::check_constrained_delaunay_2d(
            cdt[k].mesh, cdt[k].input_vertex_count, kept,
            cdt[k].mesh.triangles.empty() ? std::span<const tri::VertIdx>(cdt[k].pieces) : std::span<const tri::VertIdx>{});
        if (!report.ok) {
            fail(xy, segments, std::string(tri::segment_recovery_name(recoveries[k])) + ": " + report.problem);
        }
        const auto topology = tri::check_topology_2d(cdt[k].mesh.xy, cdt[k].mesh.triangles);
        if (!topology.ok) fail(xy, segments, std::string(tri::segment_recovery_name(recoveries[k])) + ": " + topology.problem);
    }
    if ((cdt[0].mesh.xy != cdt[1].mesh.xy || canonical(cdt[0].mesh) != canonical(cdt[1].mesh))) {
        fail(xy, segments, "swap and cavity differ");
    }

    tri::Cdt2Result conforming;
    try {
        conforming = tri::constrained_delaunay_2d(pslg, options(tri::SegmentRecovery::Conforming));
    } catch (const exactmesh::GeometryError&) {
        return 0;  // the midpoint budget (small angles): documented
    } catch (const std::exception& e) {
        fail(xy, segments, std::string("conforming threw: ") + e.what());
    }
    const auto delaunay = tri::check_delaunay_2d(conforming.mesh.xy, conforming.mesh.triangles);
    if (!delaunay.ok) fail(xy, segments, "conforming is not Delaunay: " + delaunay.problem);
    const auto report = tri::check_constrained_delaunay_2d(
        conforming.mesh, conforming.input_vertex_count, kept,
        conforming.mesh.triangles.empty() ? std::span<const tri::VertIdx>(conforming.pieces) : std::span<const tri::VertIdx>{});
    if (!report.ok) fail(xy, segments, "conforming: " + report.problem);
    return 0;
}
