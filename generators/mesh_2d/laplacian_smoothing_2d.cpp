// SPDX-License-Identifier: MIT
// Laplacian smoothing with an inversion guard and Delaunay re-swapping (see
// laplacian_smoothing_2d.hpp).
#include "generators/mesh_2d/laplacian_smoothing_2d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

/// CSR lists per vertex: its triangles and its distinct neighbours.
struct Stars {
    std::vector<std::uint32_t> triangle_start, neighbor_start;
    std::vector<tri::TriIdx> triangles;
    std::vector<tri::VertIdx> neighbors;
};

Stars build_stars(const tri::Triangulation2& mesh) {
    const std::uint32_t n = mesh.vertex_count();
    Stars s;
    s.triangle_start.assign(std::size_t{n} + 1, 0);
    for (const tri::VertIdx v : mesh.triangles) ++s.triangle_start[v + 1];
    for (std::uint32_t v = 0; v < n; ++v) s.triangle_start[v + 1] += s.triangle_start[v];
    s.triangles.resize(mesh.triangles.size());
    std::vector<std::uint32_t> fill(s.triangle_start.begin(), s.triangle_start.end() - 1);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        s.triangles[fill[mesh.triangles[e]]++] = static_cast<tri::TriIdx>(e / 3);
    }
    // Neighbours: the other two vertices of each triangle of the star, deduplicated.
    s.neighbor_start.assign(std::size_t{n} + 1, 0);
    std::vector<tri::VertIdx> around;
    for (tri::VertIdx v = 0; v < n; ++v) {
        around.clear();
        for (std::uint32_t i = s.triangle_start[v]; i < s.triangle_start[v + 1]; ++i) {
            const tri::TriIdx t = s.triangles[i];
            for (unsigned k = 0; k < 3; ++k) {
                if (mesh.triangles[3 * t + k] != v) around.push_back(mesh.triangles[3 * t + k]);
            }
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        s.neighbors.insert(s.neighbors.end(), around.begin(), around.end());
        s.neighbor_start[v + 1] = static_cast<std::uint32_t>(s.neighbors.size());
    }
    return s;
}

}  // namespace

SmoothingCounters2 laplacian_smoothing_2d(tri::Triangulation2& mesh, std::uint32_t fixed_below,
                                          const SmoothingOptions2& options) {
    if (!(options.relaxation > 0 && options.relaxation <= 1)) {
        throw InputError("smoothing relaxation " + std::to_string(options.relaxation) +
                         " is not in (0, 1]");
    }
    SmoothingCounters2 counters;
    const std::uint32_t n = mesh.vertex_count();
    std::vector<std::uint8_t> fixed(n, 0);
    for (std::uint32_t v = 0; v < std::min(n, fixed_below); ++v) fixed[v] = 1;
    std::vector<double> target(2 * std::size_t{n});
    for (std::uint32_t sweep = 0; sweep < options.iterations; ++sweep) {
        const std::uint64_t moves_before = counters.moves;
        // Connectivity changes with the swaps: the stars are rebuilt per sweep.
        const Stars stars = build_stars(mesh);
        for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                if (mesh.neighbors[3 * t + k] == tri::kNone ||
                    mesh.is_constrained(t, static_cast<int>(k))) {
                    fixed[mesh.triangles[3 * t + k]] = 1;
                    fixed[mesh.triangles[3 * t + (k + 1) % 3]] = 1;
                }
            }
        }
        std::uint64_t free_vertices = 0;
        // Jacobi: every target from the positions before the sweep.
        for (tri::VertIdx v = 0; v < n; ++v) {
            const std::uint32_t first = stars.neighbor_start[v], last = stars.neighbor_start[v + 1];
            if (fixed[v] || first == last) continue;
            ++free_vertices;
            double sx = 0, sy = 0, radius = 0;
            const double* p = mesh.point(v);
            for (std::uint32_t i = first; i < last; ++i) {
                const double* q = mesh.point(stars.neighbors[i]);
                sx += q[0];
                sy += q[1];
                radius = std::max({radius, std::fabs(q[0] - p[0]), std::fabs(q[1] - p[1])});
            }
            const double count = last - first;
            target[2 * v] = p[0] + options.relaxation * (sx / count - p[0]);
            target[2 * v + 1] = p[1] + options.relaxation * (sy / count - p[1]);
            // Converged: a move below 2^-30 of the star's size is rounding noise of the centroid
            // (the Jacobi iteration approaches its fixed point geometrically and would go on
            // moving by ulps forever). Relative to the star, so the rule is scale-invariant.
            if (std::max(std::fabs(target[2 * v] - p[0]), std::fabs(target[2 * v + 1] - p[1])) <=
                radius * 0x1p-30) {
                target[2 * v] = p[0];
                target[2 * v + 1] = p[1];
            }
        }
        counters.free_vertices = free_vertices;
        // Moves one by one, each kept only if its whole star stays counter-clockwise.
        for (tri::VertIdx v = 0; v < n; ++v) {
            const std::uint32_t first = stars.neighbor_start[v], last = stars.neighbor_start[v + 1];
            if (fixed[v] || first == last) continue;
            double* p = mesh.xy.data() + 2 * std::size_t{v};
            const double old_x = p[0], old_y = p[1];
            if (!std::isfinite(target[2 * v]) || !std::isfinite(target[2 * v + 1]) ||
                (target[2 * v] == old_x && target[2 * v + 1] == old_y)) {
                continue;
            }
            p[0] = target[2 * v];
            p[1] = target[2 * v + 1];
            bool valid = true;
            for (std::uint32_t i = stars.triangle_start[v];
                 i < stars.triangle_start[v + 1] && valid; ++i) {
                const tri::TriIdx t = stars.triangles[i];
                valid = predicates::orient2d(mesh.point(mesh.triangles[3 * t]),
                                             mesh.point(mesh.triangles[3 * t + 1]),
                                             mesh.point(mesh.triangles[3 * t + 2])) ==
                        predicates::Sign::Positive;
            }
            if (!valid) {
                p[0] = old_x;
                p[1] = old_y;
                ++counters.undone;
                continue;
            }
            ++counters.moves;
            counters.largest_move =
                std::max(counters.largest_move, std::hypot(p[0] - old_x, p[1] - old_y));
        }
        ++counters.sweeps;
        std::uint64_t swaps = 0;
        if (options.delaunay_swap) swaps = tri::swap_edges_2d(mesh, tri::Delaunay{}).swaps;
        counters.swaps += swaps;
        // A sweep that moved nothing and swapped nothing leaves the mesh as it was: every later
        // sweep would compute the same targets and refuse or skip the same moves.
        if (counters.moves == moves_before && swaps == 0) break;
    }
    return counters;
}

}  // namespace exactmesh::generators
