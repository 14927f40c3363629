// SPDX-License-Identifier: MIT
// libFuzzer target: Delaunay refinement (generators/mesh_2d/delaunay_refinement_2d) of fuzzed
// points and segments, at a fuzzed angle bound (0..33 degrees) with an optional uniform size, under
// a budget of 5,000 Steiner points (ASan makes 20,000 take 10 s). Every run must end with a mesh
// that passes check_constrained_delaunay_2d, or with InputError (nothing enclosed, collinear,
// non-finite) or GeometryError (the budget, or features finer than doubles resolve). Anything else,
// an assertion or a sanitizer report, is a failure (__builtin_trap()). With bit 7 of byte 2 set,
// the refinement runs in rounds (RefinementOrder::Rounds) on two threads and again on one: the
// two meshes (or errors) must be the same.
//
// Input layout (fuzz_pslg.hpp with a 4-byte header): byte 0 the mode, byte 1 the angle
// (byte % 34 degrees), byte 2 the size (0: none, else 2^-(byte % 8)) and the order (bit 7:
// rounds), byte 3 the segment count,
// two index bytes per segment, then coordinates, 8 bytes each (at most 2 * kMaxPoints).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 24;

[[noreturn]] void fail(const std::vector<double>& xy, const std::vector<tri::VertIdx>& segments,
                       double angle, const std::string& what) {
    exactmesh::fuzz::fail_pslg(xy, segments, "fuzz_delaunay_refinement_2d: %s\nangle %g, ",
                               what.c_str(), angle);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::optional<exactmesh::fuzz::FuzzPslg> input =
        exactmesh::fuzz::decode_pslg(data, size, 4, kMaxPoints);
    if (!input) return 0;
    const double angle = data[1] % 34;
    const std::uint8_t size_byte = data[2];
    const std::vector<double>& xy = input->xy;
    const std::vector<tri::VertIdx>& segments = input->segments;
    gen::RefinementOptions2 options;
    options.min_angle = angle;
    options.max_steiner_points = 5000;
    if (size_byte != 0)
        options.size = gen::SizeFunction::uniform(std::ldexp(1.0, -(size_byte % 8)));
    const bool rounds = (size_byte & 0x80) != 0;
    if (rounds) {
        options.order = gen::RefinementOrder::Rounds;
        options.threads = 2;
    }
    // The mesh, or the error's text ("" for a mesh).
    const auto refine = [&](gen::RefinementResult2& result) -> std::string {
        try {
            result = gen::delaunay_refinement_2d(tri::Pslg{xy, segments, {}, {}}, options);
        } catch (const exactmesh::InputError& e) {
            return std::string("InputError: ") + e.what();
        } catch (const exactmesh::GeometryError& e) {
            return std::string("GeometryError: ") + e.what();
        } catch (const std::exception& e) {
            fail(xy, segments, angle, std::string("threw: ") + e.what());
        }
        return "";
    };
    gen::RefinementResult2 result;
    const std::string error = refine(result);
    if (rounds) {
        options.threads = 1;
        gen::RefinementResult2 one;
        if (refine(one) != error) fail(xy, segments, angle, "rounds: another error on one thread");
        if (error.empty() && (one.mesh.mesh.xy != result.mesh.mesh.xy ||
                              one.mesh.mesh.triangles != result.mesh.mesh.triangles)) {
            fail(xy, segments, angle, "rounds: another mesh on one thread than on two");
        }
    }
    if (!error.empty()) return 0;
    const auto report = tri::check_constrained_delaunay_2d(
        result.mesh.mesh, result.mesh.input_vertex_count, segments, result.mesh.pieces);
    if (!report.ok) fail(xy, segments, angle, report.problem);
    return 0;
}
