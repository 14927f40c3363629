// SPDX-License-Identifier: MIT
// libFuzzer target: Delaunay refinement (generators/delaunay_refinement_2d) of fuzzed points and
// segments, at a fuzzed angle bound (0..33 degrees) with an optional uniform size, under a
// budget of 5,000 Steiner points (ASan makes 20,000 take 10 s). Every run must end with a mesh that passes
// check_constrained_delaunay_2d, or with InputError (nothing enclosed, collinear, non-finite)
// or GeometryError (the budget, or features finer than doubles resolve). Anything else, an
// assertion or a sanitizer report, is a failure (__builtin_trap()).
//
// Input layout: byte 0 the mode (raw doubles; lattice integers -4..4; a lattice moved by -2..2
// ulps), byte 1 the angle (byte % 34 degrees), byte 2 the size (0: none, else 2^-(byte % 8)),
// byte 3 the segment count (0..31), two index bytes per segment, then coordinates, 8 bytes each
// (at most 2 * kMaxPoints).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "generators/delaunay_refinement_2d.hpp"
#include "predicates/errors.hpp"
#include "triangulation/check_constrained_2d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 24;

[[noreturn]] void fail(const std::vector<double>& xy, const std::vector<tri::VertIdx>& segments, double angle,
                       const std::string& what) {
    std::fprintf(stderr, "fuzz_delaunay_refinement_2d: %s\nangle %g, points (%zu):", what.c_str(), angle, xy.size() / 2);
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) std::fprintf(stderr, " (%a, %a)", xy[i], xy[i + 1]);
    std::fprintf(stderr, "\nsegments:");
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) std::fprintf(stderr, " %u-%u", segments[s], segments[s + 1]);
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 4) return 0;
    const std::uint8_t mode = data[0] % 3;
    const double angle = data[1] % 34;
    const std::uint8_t size_byte = data[2];
    const std::size_t segment_count = data[3] % 32;
    std::size_t at = 4;
    if (size < at + 2 * segment_count) return 0;
    std::vector<std::uint8_t> ends(data + at, data + at + 2 * segment_count);
    at += 2 * segment_count;
    const std::size_t doubles = std::min((size - at) / 8, 2 * kMaxPoints) & ~std::size_t{1};
    std::vector<double> xy(doubles);
    if (doubles > 0) std::memcpy(xy.data(), data + at, doubles * sizeof(double));
    for (double& v : xy) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        if (mode == 1) v = static_cast<double>(static_cast<int>(bits % 9) - 4);
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
    gen::RefinementOptions2 options;
    options.min_angle = angle;
    options.max_steiner_points = 5000;
    if (size_byte != 0) options.size = gen::SizeFunction::uniform(std::ldexp(1.0, -(size_byte % 8)));
    gen::RefinementResult2 result;
    try {
        result = gen::delaunay_refinement_2d(tri::Pslg{xy, segments, {}, {}}, options);
    } catch (const exactmesh::InputError&) {
        return 0;
    } catch (const exactmesh::GeometryError&) {
        return 0;
    } catch (const std::exception& e) {
        fail(xy, segments, angle, std::string("threw: ") + e.what());
    }
    const auto report = tri::check_constrained_delaunay_2d(result.mesh.mesh, result.mesh.input_vertex_count, segments,
                                                           result.mesh.pieces);
    if (!report.ok) fail(xy, segments, angle, report.problem);
    return 0;
}
