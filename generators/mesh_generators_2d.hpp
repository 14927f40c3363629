// SPDX-License-Identifier: MIT
// The registry of the 2D mesh generators (issue 6; STYLE.md "a name registry"): one entry per
// generator, each with its name, a one-line summary, whether its meshes are constrained
// Delaunay, and a function that runs it on a PSLG with the options every generator shares. The
// CLI (`exactmesh mesh --generator NAME`), the benchmarks and the tests that compare generators
// all go through it, so they run the same code with the same options.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "generators/delaunay_refinement_2d.hpp"
#include "generators/size_function.hpp"
#include "triangulation/constrained_2d.hpp"

namespace exactmesh::generators {

/// What every generator is given. A generator that needs a size raises InputError when `size`
/// is unbounded; one without an angle criterion ignores `min_angle`.
struct MeshOptions2 {
    SizeFunction size;
    double min_angle = kGuaranteedMinAngle;  ///< degrees (Delaunay refinement)
    double polish_angle = -1;  ///< Delaunay refinement's polish (RefinementOptions2), -1: automatic
    std::uint64_t max_steiner_points = 0;  ///< 0: the generator's automatic budget
    triangulation::Cdt2Options cdt;        ///< numbering, recovery of the initial CDT
};

/// A generator's mesh (caller's numbering, pieces, warnings) and its work counters in the order
/// `--stats` prints them.
struct MeshRun2 {
    triangulation::Cdt2Result mesh;
    std::vector<std::pair<std::string, std::uint64_t>> counters;
};

struct MeshGenerator2 {
    std::string_view name;     ///< "delaunay-refinement", as the CLI spells it
    std::string_view summary;  ///< one line for --help
    bool delaunay;             ///< meshes are constrained Delaunay (else only conforming)
    bool needs_size;           ///< an unbounded size is an InputError
    MeshRun2 (*run)(const triangulation::Pslg& pslg, const MeshOptions2& options);
};

/// Every generator, in the order the CLI lists them.
std::span<const MeshGenerator2> mesh_generators_2d();

/// @throws InputError naming the unknown generator and the known ones.
const MeshGenerator2& find_mesh_generator_2d(std::string_view name);

/// The counters of a Delaunay refinement run, named as `exactmesh mesh --stats` prints them.
std::vector<std::pair<std::string, std::uint64_t>> counter_list(const RefinementCounters2& c);

}  // namespace exactmesh::generators
