// SPDX-License-Identifier: MIT
// libFuzzer target: every 2D mesh generator of the registry (generators/mesh_2d/mesh_generators_2d:
// Delaunay refinement, quadtree, advancing front, advancing-front Delaunay, frontal, advancing
// layers with layers (both methods: advancing layers and the truncated O-mesh) and a hole seed,
// see mesh_generators_2d_case.hpp) on fuzzed
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

#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "tests/fuzz/mesh_generators_2d_case.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

[[noreturn]] void fail(const exactmesh::fuzz::MeshGeneratorCase& c, const std::string& what) {
    exactmesh::fuzz::fail_pslg(c.input.xy, c.input.segments,
                               "fuzz_mesh_generators_2d: %s: %s\nsize %a, ",
                               std::string(c.generator->name).c_str(), what.c_str(), c.size);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::optional<exactmesh::fuzz::MeshGeneratorCase> c =
        exactmesh::fuzz::decode_mesh_generator_case(data, size, 1000);
    if (!c) return 0;
    gen::MeshRun2 run;
    try {
        run = c->generator->run(c->pslg(), c->options);
    } catch (const exactmesh::InputError&) {
        return 0;
    } catch (const exactmesh::GeometryError&) {
        return 0;
    } catch (const std::exception& e) {
        fail(*c, std::string("threw: ") + e.what());
    }
    const auto report = exactmesh::fuzz::check_mesh_generator_case(*c, run.mesh, run.quads);
    if (!report.ok) fail(*c, report.problem);
    return 0;
}
