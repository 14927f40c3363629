// SPDX-License-Identifier: MIT
// libFuzzer target: the 3D mesh generators as `exactmesh tetmesh` runs them, on small fuzzed
// PLCs (tests/fuzz/tetmesh_3d_case.hpp: a box, a prism, a box with a box hole at a tiny gap or
// a star-shaped polyhedron, free vertices on and 1e-12..1e-300 near the surface, scaled by
// 2^[-600, 600]): embedding of free vertices, validation, boundary recovery, then Delaunay
// refinement, frontal insertion or the octree generator, then sliver removal, with small
// budgets. Every mesh must pass check_boundary_conformity_3d and keep the input vertices at
// their coordinates; InputError and GeometryError are accepted, anything else (InternalError,
// another exception, a sanitizer report, an EM_ASSERT) is a crash that prints the decoded PLC.
// With EXACTMESH_FUZZ_VERBOSE=1 in the environment every input prints its PLC and outcome (for
// replaying a saved input by hand).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "tests/fuzz/tetmesh_3d_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const exactmesh::fuzz::TetmeshCase c = exactmesh::fuzz::decode_tetmesh_case(data, size);
    const exactmesh::fuzz::TetmeshOutcome outcome = exactmesh::fuzz::run_tetmesh_case(c);
    static const bool verbose = std::getenv("EXACTMESH_FUZZ_VERBOSE") != nullptr;
    if (verbose) {
        std::fprintf(stderr, "%s%s: %s\n", exactmesh::fuzz::describe_tetmesh_case(c).c_str(),
                     outcome.stage.c_str(),
                     outcome.meshed          ? "meshed"
                     : outcome.error.empty() ? "failed"
                                             : outcome.error.c_str());
    }
    if (!outcome.failure.empty()) {
        std::fprintf(stderr, "fuzz_tetmesh_3d: %s\n%s", outcome.failure.c_str(),
                     exactmesh::fuzz::describe_tetmesh_case(c).c_str());
        std::abort();
    }
    return 0;
}
