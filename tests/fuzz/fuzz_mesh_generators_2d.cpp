// SPDX-License-Identifier: MIT
// libFuzzer target: every 2D mesh generator of the registry (generators/mesh_generators_2d:
// Delaunay refinement, quadtree, advancing front, advancing-front Delaunay, frontal) on fuzzed
// points and segments with a uniform size of 2^-(byte % 6) times the input's extent (so a mesh
// has at most a few thousand triangles) and a budget of 1,000 Steiner points (2,000 triangles for
// the advancing front; its finding on a sliver 1 wide and 3e231 tall, 23 s with its default
// budget while its placement squared 1e230-long differences, ends in milliseconds since the
// placement is scale-free: tests/data/fuzz/mesh_generators_2d_advancing_front_wide_sliver.bin,
// tests/regressions/issue_11_sliver_test.cpp). Every run must end
// with a mesh that passes the exact check the generator promises (check_constrained_delaunay_2d
// for the Delaunay ones, check_conforming_mesh_2d for the others), or with InputError (nothing
// enclosed, collinear, non-finite, a size that asks for too much) or GeometryError (a budget, or
// features finer than doubles resolve). Anything else, an assertion or a sanitizer report, is a
// failure (__builtin_trap()).
//
// Delaunay refinement runs here too since its finding (tests/data/fuzz/
// mesh_generators_2d_refinement_bend_off_short_segment.bin: a unit square's side bent through a
// vertex 5.3e-315 off it along a piece it shared with a segment 2.6e-319 long, whose chain the
// exact check then rejected) is settled: bends and the check share one rule, applied to every
// segment a piece belongs to (issue 11; tests/regressions/issue_11_bend_rule_test.cpp).
//
// Input layout (fuzz_pslg.hpp with a 4-byte header): byte 0 the mode, byte 1 the generator
// (byte % count), byte 2 the size, byte 3 the segment count, two index bytes per segment, then
// coordinates, 8 bytes each (at most 2 * kMaxPoints).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "generators/mesh_generators_2d.hpp"
#include "predicates/errors.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"
#include "triangulation/check_conforming_2d.hpp"
#include "triangulation/check_constrained_2d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

constexpr std::size_t kMaxPoints = 24;

[[noreturn]] void fail(const std::vector<double>& xy, const std::vector<tri::VertIdx>& segments,
                       const gen::MeshGenerator2& generator, double size, const std::string& what) {
    exactmesh::fuzz::fail_pslg(xy, segments, "fuzz_mesh_generators_2d: %s: %s\nsize %a, ",
                               std::string(generator.name).c_str(), what.c_str(), size);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::optional<exactmesh::fuzz::FuzzPslg> input =
        exactmesh::fuzz::decode_pslg(data, size, 4, kMaxPoints);
    if (!input) return 0;
    const auto generators = gen::mesh_generators_2d();
    const gen::MeshGenerator2& generator = generators[data[1] % generators.size()];
    const int size_exponent = data[2] % 6;
    const std::vector<double>& xy = input->xy;
    const std::vector<tri::VertIdx>& segments = input->segments;
    const std::size_t n = xy.size() / 2;
    if (n == 0) return 0;
    // The size: 2^-k of the larger side of the bounding box (finite inputs; others are rejected
    // by the generator's validation, whatever the size).
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
        x0 = std::min(x0, xy[2 * i]), x1 = std::max(x1, xy[2 * i]);
        y0 = std::min(y0, xy[2 * i + 1]), y1 = std::max(y1, xy[2 * i + 1]);
    }
    const double extent = std::max(x1 - x0, y1 - y0);
    const double h = std::ldexp(std::isfinite(extent) && extent > 0 ? extent : 1.0, -size_exponent);
    gen::MeshOptions2 options;
    options.max_steiner_points = 1000;
    if (std::isfinite(h) && h > 0) options.size = gen::SizeFunction::uniform(h);
    gen::MeshRun2 run;
    try {
        run = generator.run(tri::Pslg{xy, segments, {}, {}}, options);
    } catch (const exactmesh::InputError&) {
        return 0;
    } catch (const exactmesh::GeometryError&) {
        return 0;
    } catch (const std::exception& e) {
        fail(xy, segments, generator, h, std::string("threw: ") + e.what());
    }
    const tri::Cdt2Result& mesh = run.mesh;
    const auto report = generator.delaunay
                            ? tri::check_constrained_delaunay_2d(mesh.mesh, mesh.input_vertex_count,
                                                                 segments, mesh.pieces)
                            : tri::check_conforming_mesh_2d(mesh.mesh, mesh.input_vertex_count,
                                                            segments, mesh.pieces);
    if (!report.ok) fail(xy, segments, generator, h, report.problem);
    return 0;
}
