// SPDX-License-Identifier: MIT
// Laplacian smoothing of a tetrahedralization with an inversion guard (see
// laplacian_smoothing_3d.hpp): unit edge weights in the shared guarded sweep.
#include "generators/adaptation/laplacian_smoothing_3d.hpp"

#include <algorithm>
#include <vector>

#include "generators/adaptation/mesh_movement_check.hpp"
#include "generators/adaptation/vertex_moves.hpp"

namespace exactmesh::generators {

SmoothingCounters3 laplacian_smoothing_3d(triangulation::Tetrahedralization3& mesh,
                                          std::uint32_t fixed_below,
                                          const SmoothingOptions3& options) {
    detail::validate_relaxation(options.relaxation);
    detail::validate_mesh_arrays_3d(mesh);
    const std::vector<std::uint8_t> fixed = fixed_vertices_3d(mesh, fixed_below);
    const detail::VertexStars stars = detail::vertex_stars_3d(mesh);
    const detail::SweepTally tally = detail::guarded_sweeps_3d(
        mesh, stars, fixed, {}, {options.relaxation, options.iterations, options.smart});
    return detail::sweep_counters(tally, fixed);
}

}  // namespace exactmesh::generators
