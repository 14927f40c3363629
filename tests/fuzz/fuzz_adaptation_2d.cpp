// SPDX-License-Identifier: MIT
// libFuzzer target: 2D solution-adaptive meshing (issue 13, generators/adaptation/) on fuzzed
// PSLGs, methods, indicators, thresholds and fields. Each input is one case of
// adaptation_2d_case.hpp: the PSLG meshed by Delaunay refinement (1,000 Steiner points at most),
// then 1 to 3 cycles of insertion, h-refinement, Steiner restart, global or local remeshing under
// a budget of 4,000 vertices, optionally a transient run with derefinement, and for h-refinement
// the refine-then-derefine identity. Every cycle and pass must pass its exact check
// (check_adaptive_mesh_2d, check_h_refined_mesh_2d) and stay within the budget; the first mesh
// may end in InputError or GeometryError (as in fuzz_mesh_generators_2d), a cycle only in
// InputError (documented: a remeshing generator refusing the size) or, for Steiner restart and
// remeshing, the generator's documented GeometryError. Anything else, an assertion or a sanitizer
// report, is a failure (__builtin_trap()).
//
// Input layout (fuzz_pslg.hpp with an 11-byte header): byte 0 the mode, bytes 1..9 the case's
// parameters (adaptation_2d_case.hpp), byte 10 the segment count, two index bytes per segment,
// then coordinates, 8 bytes each (at most 2 * kAdaptationMaxPoints).

#include <cstddef>
#include <cstdint>
#include <optional>

#include "tests/fuzz/adaptation_2d_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::optional<exactmesh::fuzz::AdaptationCase> c =
        exactmesh::fuzz::decode_adaptation_case(data, size);
    if (!c) return 0;
    const exactmesh::fuzz::AdaptationOutcome out = exactmesh::fuzz::run_adaptation_case(*c);
    if (!out.problem.empty()) {
        exactmesh::fuzz::fail_pslg(c->input.xy, c->input.segments, "fuzz_adaptation_2d: %s\n%s\n",
                                   out.problem.c_str(),
                                   exactmesh::fuzz::describe_adaptation_case(*c).c_str());
    }
    return 0;
}
