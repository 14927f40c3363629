// SPDX-License-Identifier: MIT
// Vertex stars and guarded Jacobi sweeps for mesh movement (see vertex_moves.hpp).
#include "generators/adaptation/vertex_moves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators::detail {

namespace tri = exactmesh::triangulation;

namespace {

/// Stars of a mesh with `corners` vertices per element (3 or 4).
VertexStars vertex_stars(std::span<const tri::VertIdx> elements, std::uint32_t n,
                         unsigned corners) {
    VertexStars s;
    s.element_start.assign(std::size_t{n} + 1, 0);
    for (const tri::VertIdx v : elements) ++s.element_start[v + 1];
    for (std::uint32_t v = 0; v < n; ++v) s.element_start[v + 1] += s.element_start[v];
    s.elements.resize(elements.size());
    std::vector<std::uint32_t> fill(s.element_start.begin(), s.element_start.end() - 1);
    for (std::size_t i = 0; i < elements.size(); ++i) {
        s.elements[fill[elements[i]]++] = static_cast<std::uint32_t>(i / corners);
    }
    // Neighbours: the other corners of each element of the star, deduplicated (in a simplicial
    // mesh every two corners of an element share an edge).
    s.neighbor_start.assign(std::size_t{n} + 1, 0);
    std::vector<tri::VertIdx> around;
    for (tri::VertIdx v = 0; v < n; ++v) {
        around.clear();
        for (std::uint32_t i = s.element_start[v]; i < s.element_start[v + 1]; ++i) {
            const std::size_t first = std::size_t{corners} * s.elements[i];
            for (unsigned k = 0; k < corners; ++k) {
                if (elements[first + k] != v) around.push_back(elements[first + k]);
            }
        }
        std::sort(around.begin(), around.end());
        around.erase(std::unique(around.begin(), around.end()), around.end());
        s.neighbors.insert(s.neighbors.end(), around.begin(), around.end());
        s.neighbor_start[v + 1] = static_cast<std::uint32_t>(s.neighbors.size());
    }
    return s;
}

void validate_indices(std::span<const tri::VertIdx> elements, std::size_t neighbors,
                      std::uint32_t n, unsigned corners, const char* what) {
    if (elements.size() % corners != 0 || neighbors != elements.size()) {
        throw InputError(
            std::string("mesh movement: the ") + what + " arrays have " +
            std::to_string(elements.size()) + " corners and " + std::to_string(neighbors) +
            " neighbour slots (expected equal, a multiple of " + std::to_string(corners) + ")");
    }
    for (std::size_t i = 0; i < elements.size(); ++i) {
        if (elements[i] >= n) {
            throw InputError(std::string("mesh movement: ") + what + " " +
                             std::to_string(i / corners) + " names vertex " +
                             std::to_string(elements[i]) + ", but there are " + std::to_string(n) +
                             " vertices");
        }
    }
}

/// Guarded Jacobi sweeps in D dimensions; `positive(e)` is the exact strict-orientation test of
/// element e at the current coordinates, `quality(e)` its element quality (smart mode).
template <unsigned D, class Positive, class Quality>
SweepTally guarded_sweeps(std::vector<double>& coordinates, const VertexStars& stars,
                          std::span<const std::uint8_t> fixed, std::span<const double> weights,
                          const SweepSettings& settings, Positive positive, Quality quality) {
    const double omega = settings.omega;
    const auto n = static_cast<std::uint32_t>(coordinates.size() / D);
    EM_ASSERT(fixed.size() == n);
    EM_ASSERT(weights.empty() || weights.size() == stars.neighbors.size());
    SweepTally tally;
    for (tri::VertIdx v = 0; v < n; ++v) {
        tally.free_vertices += !fixed[v] && stars.neighbor_start[v] != stars.neighbor_start[v + 1];
    }
    std::vector<double> target(coordinates.size());
    // Smart mode: the quality of every element at the current positions, kept up to date as
    // moves are accepted (each is then evaluated once per trial move, not twice).
    std::vector<double> element_quality;
    std::vector<double> trial_quality;
    if (settings.smart) {
        element_quality.resize(stars.elements.size() / (D + 1));
        for (std::uint32_t e = 0; e < element_quality.size(); ++e) element_quality[e] = quality(e);
    }
    for (std::uint32_t sweep = 0; sweep < settings.sweeps; ++sweep) {
        const std::uint64_t moves_before = tally.moves;
        // Jacobi: every target from the positions before the sweep.
        for (tri::VertIdx v = 0; v < n; ++v) {
            const std::uint32_t first = stars.neighbor_start[v], last = stars.neighbor_start[v + 1];
            if (fixed[v] || first == last) continue;
            const double* p = coordinates.data() + std::size_t{D} * v;
            std::array<double, D> sum{};
            double weight_sum = 0, radius = 0;
            for (std::uint32_t i = first; i < last; ++i) {
                const double* q = coordinates.data() + std::size_t{D} * stars.neighbors[i];
                const double w = weights.empty() ? 1.0 : weights[i];
                weight_sum += w;
                for (unsigned d = 0; d < D; ++d) {
                    const double difference = q[d] - p[d];
                    sum[d] += w * difference;
                    radius = std::max(radius, std::fabs(difference));
                }
            }
            double* t = target.data() + std::size_t{D} * v;
            double step = 0;
            for (unsigned d = 0; d < D; ++d) {
                t[d] = p[d] + omega * (sum[d] / weight_sum);
                step = std::max(step, std::fabs(t[d] - p[d]));
            }
            // Converged: a move below 2^-30 of the star's size is rounding noise of the average
            // (the iteration approaches its fixed point geometrically and would go on moving by
            // ulps forever). Relative to the star, so the rule is scale-invariant.
            if (step <= radius * 0x1p-30) {
                ++tally.converged;
                for (unsigned d = 0; d < D; ++d) t[d] = p[d];
            }
        }
        // Moves one by one, each kept only if its whole star stays strictly positive.
        for (tri::VertIdx v = 0; v < n; ++v) {
            const std::uint32_t first = stars.neighbor_start[v], last = stars.neighbor_start[v + 1];
            if (fixed[v] || first == last) continue;
            double* p = coordinates.data() + std::size_t{D} * v;
            const double* t = target.data() + std::size_t{D} * v;
            bool same = true, finite = true;
            for (unsigned d = 0; d < D; ++d) {
                same = same && t[d] == p[d];
                finite = finite && std::isfinite(t[d]);
            }
            // A non-finite target comes only from differences beyond the double range; such a
            // move is not made (the vertex keeps its place, the mesh stays valid).
            if (same || !finite) continue;
            const std::uint32_t star_first = stars.element_start[v],
                                star_last = stars.element_start[v + 1];
            std::array<double, D> old{};
            for (unsigned d = 0; d < D; ++d) old[d] = p[d], p[d] = t[d];
            bool valid = true;
            for (std::uint32_t i = star_first; i < star_last && valid; ++i) {
                valid = positive(stars.elements[i]);
            }
            // Smart mode compares rounded qualities: a heuristic about shape, never about
            // validity, which the exact test above has already settled.
            bool worse = false;
            if (valid && settings.smart) {
                double worst_before = 1, worst_after = 1;
                trial_quality.clear();
                for (std::uint32_t i = star_first; i < star_last; ++i) {
                    trial_quality.push_back(quality(stars.elements[i]));
                    worst_before = std::min(worst_before, element_quality[stars.elements[i]]);
                    worst_after = std::min(worst_after, trial_quality.back());
                }
                worse = worst_after < worst_before;
            }
            if (!valid || worse) {
                for (unsigned d = 0; d < D; ++d) p[d] = old[d];
                ++(valid ? tally.worse : tally.undone);
                continue;
            }
            if (settings.smart) {
                for (std::uint32_t i = star_first; i < star_last; ++i) {
                    element_quality[stars.elements[i]] = trial_quality[i - star_first];
                }
            }
            ++tally.moves;
        }
        ++tally.sweeps;
        // A sweep that moved nothing leaves the mesh as it was: every later sweep would compute
        // the same targets and refuse or skip the same moves.
        if (tally.moves == moves_before) break;
    }
    return tally;
}

}  // namespace

VertexStars vertex_stars_2d(const tri::Triangulation2& mesh) {
    return vertex_stars(mesh.triangles, mesh.vertex_count(), 3);
}

VertexStars vertex_stars_3d(const tri::Tetrahedralization3& mesh) {
    return vertex_stars(mesh.tets, mesh.vertex_count(), 4);
}

void validate_mesh_arrays_2d(const tri::Triangulation2& mesh) {
    if (mesh.xy.size() % 2 != 0) {
        throw InputError("mesh movement: odd number of 2D coordinates " +
                         std::to_string(mesh.xy.size()));
    }
    validate_indices(mesh.triangles, mesh.neighbors.size(), mesh.vertex_count(), 3, "triangle");
    if (!mesh.constrained.empty() && mesh.constrained.size() != mesh.triangles.size()) {
        throw InputError("mesh movement: " + std::to_string(mesh.constrained.size()) +
                         " constraint flags for " + std::to_string(mesh.triangles.size()) +
                         " triangle edges");
    }
}

void validate_mesh_arrays_3d(const tri::Tetrahedralization3& mesh) {
    if (mesh.xyz.size() % 3 != 0) {
        throw InputError("mesh movement: the number of 3D coordinates " +
                         std::to_string(mesh.xyz.size()) + " is not a multiple of 3");
    }
    validate_indices(mesh.tets, mesh.neighbors.size(), mesh.vertex_count(), 4, "tetrahedron");
}

void validate_relaxation(double omega) {
    if (!(omega > 0 && omega <= 1)) {
        throw InputError("mesh movement relaxation " + format_number(omega) + " is not in (0, 1]");
    }
}

double element_quality_2d(const double* a, const double* b, const double* c) {
    double e[2][2] = {{b[0] - a[0], b[1] - a[1]}, {c[0] - a[0], c[1] - a[1]}};
    const double largest =
        std::max({std::fabs(e[0][0]), std::fabs(e[0][1]), std::fabs(e[1][0]), std::fabs(e[1][1])});
    if (!(largest > 0) || !std::isfinite(largest)) return 0;
    const predicates::PowerOfTwo scale(predicates::unit_shift(largest));
    for (auto& row : e) {
        for (double& x : row) x = scale(x);
    }
    const double twice_area = e[0][0] * e[1][1] - e[0][1] * e[1][0];
    const double fx = e[1][0] - e[0][0], fy = e[1][1] - e[0][1];
    const double squares = e[0][0] * e[0][0] + e[0][1] * e[0][1] + e[1][0] * e[1][0] +
                           e[1][1] * e[1][1] + fx * fx + fy * fy;
    return 2 * std::sqrt(3.0) * twice_area / squares;
}

double element_quality_3d(const double* a, const double* b, const double* c, const double* d) {
    double e[3][3];
    double largest = 0;
    for (unsigned k = 0; k < 3; ++k) {
        e[0][k] = b[k] - a[k];
        e[1][k] = c[k] - a[k];
        e[2][k] = d[k] - a[k];
        for (unsigned i = 0; i < 3; ++i) largest = std::max(largest, std::fabs(e[i][k]));
    }
    if (!(largest > 0) || !std::isfinite(largest)) return 0;
    const predicates::PowerOfTwo scale(predicates::unit_shift(largest));
    for (auto& row : e) {
        for (double& x : row) x = scale(x);
    }
    // orient3d's sign convention: positive orientation is det[a-d; b-d; c-d] > 0, which is
    // -det[b-a; c-a; d-a].
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    double squares = 0;
    for (unsigned k = 0; k < 3; ++k) {
        const double f01 = e[1][k] - e[0][k], f02 = e[2][k] - e[0][k], f12 = e[2][k] - e[1][k];
        squares += e[0][k] * e[0][k] + e[1][k] * e[1][k] + e[2][k] * e[2][k] + f01 * f01 +
                   f02 * f02 + f12 * f12;
    }
    const double rms = std::sqrt(squares / 6);
    return std::sqrt(2.0) * -det / (rms * rms * rms);
}

SweepTally guarded_sweeps_2d(tri::Triangulation2& mesh, const VertexStars& stars,
                             std::span<const std::uint8_t> fixed, std::span<const double> weights,
                             const SweepSettings& settings) {
    const auto positive = [&mesh](std::uint32_t t) {
        const tri::VertIdx* c = mesh.triangles.data() + 3 * std::size_t{t};
        return predicates::orient2d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2])) ==
               predicates::Sign::Positive;
    };
    const auto quality = [&mesh](std::uint32_t t) {
        const tri::VertIdx* c = mesh.triangles.data() + 3 * std::size_t{t};
        return element_quality_2d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]));
    };
    return guarded_sweeps<2>(mesh.xy, stars, fixed, weights, settings, positive, quality);
}

SweepTally guarded_sweeps_3d(tri::Tetrahedralization3& mesh, const VertexStars& stars,
                             std::span<const std::uint8_t> fixed, std::span<const double> weights,
                             const SweepSettings& settings) {
    const auto positive = [&mesh](std::uint32_t t) {
        const tri::VertIdx* c = mesh.tets.data() + 4 * std::size_t{t};
        return predicates::orient3d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]),
                                    mesh.point(c[3])) == predicates::Sign::Positive;
    };
    const auto quality = [&mesh](std::uint32_t t) {
        const tri::VertIdx* c = mesh.tets.data() + 4 * std::size_t{t};
        return element_quality_3d(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]),
                                  mesh.point(c[3]));
    };
    return guarded_sweeps<3>(mesh.xyz, stars, fixed, weights, settings, positive, quality);
}

}  // namespace exactmesh::generators::detail
