// SPDX-License-Identifier: MIT
// Fixed vertices of a mesh movement and the exact check of a moved mesh (see
// mesh_movement_check.hpp).
#include "generators/adaptation/mesh_movement_check.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>
#include <string_view>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

std::vector<std::uint8_t> base_marks(std::uint32_t n, std::uint32_t fixed_below,
                                     std::span<const std::uint8_t> protected_vertices,
                                     std::span<const tri::VertIdx> elements) {
    if (!protected_vertices.empty() && protected_vertices.size() != n) {
        throw InputError("mesh movement: " + std::to_string(protected_vertices.size()) +
                         " protected-vertex flags for " + std::to_string(n) + " vertices");
    }
    // Start with every vertex fixed, free the ones an element uses, then fix the rest again.
    std::vector<std::uint8_t> fixed(n, 1);
    for (const tri::VertIdx v : elements) {
        if (v < n) fixed[v] = 0;
    }
    for (std::uint32_t v = 0; v < std::min(n, fixed_below); ++v) fixed[v] = 1;
    for (std::uint32_t v = 0; v < protected_vertices.size(); ++v) {
        if (protected_vertices[v] != 0) fixed[v] = 1;
    }
    return fixed;
}

/// `problem` when the coordinates of the vertices differ in any bit or are not finite.
template <unsigned D>
MovementCheckReport compare_coordinates(std::span<const double> before,
                                        std::span<const double> after,
                                        std::span<const std::uint8_t> fixed) {
    MovementCheckReport r;
    const std::size_t n = before.size() / D;
    if (after.size() != before.size() || fixed.size() != n) {
        r.ok = false;
        r.problem = "the vertex count or the fixed flags changed: " + std::to_string(n) + " vs " +
                    std::to_string(after.size() / D) + " vertices, " +
                    std::to_string(fixed.size()) + " flags";
        return r;
    }
    for (std::size_t v = 0; v < n; ++v) {
        for (unsigned d = 0; d < D; ++d) {
            const double a = before[D * v + d], b = after[D * v + d];
            if (!std::isfinite(b) ||
                (fixed[v] && std::bit_cast<std::uint64_t>(a) != std::bit_cast<std::uint64_t>(b))) {
                r.ok = false;
                r.vertex = static_cast<std::uint32_t>(v);
                r.problem = std::string(std::isfinite(b) ? "fixed vertex " : "vertex ") +
                            std::to_string(v) +
                            (std::isfinite(b) ? " moved" : " has a non-finite coordinate");
                return r;
            }
        }
    }
    return r;
}

// The check both dimensions share: the connectivity as before, the coordinates as
// compare_coordinates allows, every element (D + 1 corners in range) strictly positive by the
// exact orient2d / orient3d.
template <unsigned D>
MovementCheckReport check_moved(bool same_connectivity, std::span<const double> before,
                                std::span<const double> after,
                                std::span<const tri::VertIdx> elements,
                                std::span<const std::uint8_t> fixed, std::string_view element,
                                std::string_view positive) {
    MovementCheckReport r;
    if (!same_connectivity) {
        r.ok = false;
        r.problem = "the connectivity changed";
        return r;
    }
    r = compare_coordinates<D>(before, after, fixed);
    if (!r.ok) return r;
    const std::size_t vertices = after.size() / D;
    for (std::uint32_t t = 0; t < elements.size() / (D + 1); ++t) {
        const tri::VertIdx* c = elements.data() + (D + 1) * std::size_t{t};
        const auto p = [&](unsigned i) { return after.data() + D * std::size_t{c[i]}; };
        bool ok = *std::max_element(c, c + D + 1) < vertices;
        if constexpr (D == 2) {
            ok = ok && predicates::orient2d(p(0), p(1), p(2)) == predicates::Sign::Positive;
        } else {
            ok = ok && predicates::orient3d(p(0), p(1), p(2), p(3)) == predicates::Sign::Positive;
        }
        if (!ok) {
            r.ok = false;
            r.element = t;
            r.problem = std::string(element) + " " + std::to_string(t) + " is not strictly " +
                        std::string(positive);
            return r;
        }
    }
    return r;
}

}  // namespace

std::vector<std::uint8_t> fixed_vertices_2d(const tri::Triangulation2& mesh,
                                            std::uint32_t fixed_below,
                                            std::span<const std::uint8_t> protected_vertices) {
    const std::uint32_t n = mesh.vertex_count();
    std::vector<std::uint8_t> fixed =
        base_marks(n, fixed_below, protected_vertices, mesh.triangles);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const bool boundary = e >= mesh.neighbors.size() || mesh.neighbors[e] == tri::kNone;
        if (!boundary && !(mesh.constrained.size() > e && mesh.constrained[e] != 0)) continue;
        const std::size_t next = e % 3 == 2 ? e - 2 : e + 1;
        for (const std::size_t corner : {e, next}) {
            if (mesh.triangles[corner] < n) fixed[mesh.triangles[corner]] = 1;
        }
    }
    return fixed;
}

std::vector<std::uint8_t> fixed_vertices_3d(const tri::Tetrahedralization3& mesh,
                                            std::uint32_t fixed_below,
                                            std::span<const std::uint8_t> protected_vertices) {
    const std::uint32_t n = mesh.vertex_count();
    std::vector<std::uint8_t> fixed = base_marks(n, fixed_below, protected_vertices, mesh.tets);
    for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
        if (f < mesh.neighbors.size() && mesh.neighbors[f] != tri::kNone) continue;
        // Face k of t is the triangle opposite corner k: its other three corners.
        const std::size_t first = f - f % 4;
        for (std::size_t corner = first; corner < first + 4; ++corner) {
            if (corner != f && mesh.tets[corner] < n) fixed[mesh.tets[corner]] = 1;
        }
    }
    return fixed;
}

MovementCheckReport check_mesh_movement_2d(const tri::Triangulation2& before,
                                           const tri::Triangulation2& after,
                                           std::span<const std::uint8_t> fixed) {
    return check_moved<2>(
        after.triangles == before.triangles && after.neighbors == before.neighbors &&
            after.constrained == before.constrained,
        before.xy, after.xy, after.triangles, fixed, "triangle", "counter-clockwise");
}

MovementCheckReport check_mesh_movement_3d(const tri::Tetrahedralization3& before,
                                           const tri::Tetrahedralization3& after,
                                           std::span<const std::uint8_t> fixed) {
    return check_moved<3>(after.tets == before.tets && after.neighbors == before.neighbors,
                          before.xyz, after.xyz, after.tets, fixed, "tetrahedron", "positive");
}

}  // namespace exactmesh::generators
