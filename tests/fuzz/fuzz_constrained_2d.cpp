// SPDX-License-Identifier: MIT
// libFuzzer target: constrained Delaunay triangulation (swap, cavity and conforming recovery)
// of fuzzed points and segments, the convex hull kept. Swap and cavity must pass
// check_constrained_delaunay_2d and be identical; conforming must pass it and
// check_delaunay_2d, or stop with GeometryError (its documented split budget). Non-finite
// coordinates must raise NonFiniteCoordinate. Anything else is __builtin_trap().
//
// Input layout (fuzz_pslg.hpp with a 2-byte header): byte 0 the mode, byte 1 the segment count,
// then two index bytes per segment, then the coordinates, 8 bytes each (at most 2·kMaxPoints).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace {

namespace tri = exactmesh::triangulation;
using exactmesh::predicates::Sign;

constexpr std::size_t kMaxPoints = 48;

[[noreturn]] void fail(const std::vector<double>& xy, const std::vector<tri::VertIdx>& segments,
                       const std::string& what) {
    exactmesh::fuzz::fail_pslg(xy, segments, "fuzz_constrained_2d: %s\n", what.c_str());
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
    const std::optional<exactmesh::fuzz::FuzzPslg> input =
        exactmesh::fuzz::decode_pslg(data, size, 2, kMaxPoints);
    if (!input) return 0;
    const std::vector<double>& xy = input->xy;
    const std::vector<tri::VertIdx>& segments = input->segments;
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
    const tri::SegmentRecovery recoveries[] = {tri::SegmentRecovery::Swap,
                                               tri::SegmentRecovery::Cavity};
    for (std::size_t k = 0; k < 2; ++k) {
        try {
            cdt[k] = tri::constrained_delaunay_2d(pslg, options(recoveries[k]));
        } catch (const std::exception& e) {
            fail(xy, segments,
                 std::string(tri::segment_recovery_name(recoveries[k])) + " threw: " + e.what());
        }
    }
    const std::vector<tri::VertIdx>& kept = segments;  // the check follows duplicates' used copies
    for (std::size_t k = 0; k < 2; ++k) {
        // Collinear input has no triangle to carry flags: the check then follows the pieces.
        const auto report = tri::check_constrained_delaunay_2d(
            cdt[k].mesh, cdt[k].input_vertex_count, kept,
            cdt[k].mesh.triangles.empty() ? std::span<const tri::VertIdx>(cdt[k].pieces)
                                          : std::span<const tri::VertIdx>{});
        if (!report.ok) {
            fail(xy, segments,
                 std::string(tri::segment_recovery_name(recoveries[k])) + ": " + report.problem);
        }
        const auto topology = tri::check_topology_2d(cdt[k].mesh.xy, cdt[k].mesh.triangles);
        if (!topology.ok)
            fail(xy, segments,
                 std::string(tri::segment_recovery_name(recoveries[k])) + ": " + topology.problem);
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
        conforming.mesh.triangles.empty() ? std::span<const tri::VertIdx>(conforming.pieces)
                                          : std::span<const tri::VertIdx>{});
    if (!report.ok) fail(xy, segments, "conforming: " + report.problem);
    return 0;
}
