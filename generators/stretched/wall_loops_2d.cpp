// SPDX-License-Identifier: MIT
// Wall loops, normals and the boundary split beside them (see wall_loops_2d.hpp).
#include "generators/stretched/wall_loops_2d.hpp"

#include <array>
#include <set>
#include <utility>
#include <vector>

#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;
using predicates::scale_free_norm;
using predicates::Sign;

namespace {

/// (x, y) over its scale-free length; (0, 0) for the zero vector.
std::array<double, 2> unit_vector(double x, double y) {
    const double n = scale_free_norm(x, y);
    if (!(n > 0)) return {0, 0};
    return {x / n, y / n};
}

}  // namespace

/// The loops of boundary edges (triangle sides with no neighbour) of the domain's CDT whose
/// traversal with the domain on the left turns clockwise: holes, i.e. components. A loop
/// through a vertex with two outgoing boundary edges is skipped (no O-mesh there).
std::vector<WallLoop2> wall_loops_2d(const tri::Triangulation2& mesh) {
    constexpr tri::VertIdx kNoVertex = 0xFFFFFFFFu;
    std::vector<tri::VertIdx> next(mesh.vertex_count(), kNoVertex);
    std::vector<bool> ambiguous(mesh.vertex_count(), false);
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (mesh.neighbors[3 * t + k] != tri::kNone) continue;
            const tri::VertIdx a = mesh.triangles[3 * t + k];
            const tri::VertIdx b = mesh.triangles[3 * t + (k + 1) % 3];
            if (next[a] != kNoVertex) ambiguous[a] = true;
            next[a] = b;
        }
    }
    std::vector<WallLoop2> walls;
    std::vector<bool> visited(mesh.vertex_count(), false);
    for (tri::VertIdx start = 0; start < mesh.vertex_count(); ++start) {
        if (next[start] == kNoVertex || visited[start]) continue;
        WallLoop2 wall;
        bool closed = false, usable = true;
        for (tri::VertIdx v = start; v != kNoVertex && !visited[v]; v = next[v]) {
            visited[v] = true;
            usable = usable && !ambiguous[v];
            wall.vertices.push_back(v);
            if (next[v] == start) closed = true;
        }
        if (!closed || !usable || wall.vertices.size() < 3) continue;
        // The orientation at the lexicographically lowest vertex, where the loop is convex.
        const std::size_t n = wall.vertices.size();
        std::size_t low = 0;
        for (std::size_t i = 1; i < n; ++i) {
            const double* p = mesh.point(wall.vertices[i]);
            const double* q = mesh.point(wall.vertices[low]);
            if (p[0] < q[0] || (p[0] == q[0] && p[1] < q[1])) low = i;
        }
        const Sign turn = predicates::orient2d(mesh.point(wall.vertices[(low + n - 1) % n]),
                                               mesh.point(wall.vertices[low]),
                                               mesh.point(wall.vertices[(low + 1) % n]));
        if (turn == Sign::Negative) walls.push_back(std::move(wall));
    }
    return walls;
}

/// Each wall vertex's normal (the mean of its two sides' left normals, then averaged with its
/// neighbours' `passes` times) and tangential spacing (the mean of its two sides' lengths).
void wall_normals_2d(const tri::Triangulation2& mesh, WallLoop2& wall, int passes) {
    const std::size_t n = wall.vertices.size();
    std::vector<std::array<double, 2>> side_normals(n);
    std::vector<double> side_lengths(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double* a = mesh.point(wall.vertices[i]);
        const double* b = mesh.point(wall.vertices[(i + 1) % n]);
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        side_lengths[i] = scale_free_norm(dx, dy);
        side_normals[i] = unit_vector(-dy, dx);
    }
    wall.normals.resize(n);
    wall.spacing.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t before = (i + n - 1) % n;
        wall.spacing[i] = 0.5 * (side_lengths[before] + side_lengths[i]);
        const std::array<double, 2> m = unit_vector(side_normals[before][0] + side_normals[i][0],
                                                    side_normals[before][1] + side_normals[i][1]);
        // A cusp (sides folded back on each other): the side's own normal.
        wall.normals[i] = (m[0] == 0 && m[1] == 0) ? side_normals[i] : m;
    }
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<std::array<double, 2>> smoothed(n);
        for (std::size_t i = 0; i < n; ++i) {
            const std::array<double, 2>& p = wall.normals[(i + n - 1) % n];
            const std::array<double, 2>& q = wall.normals[(i + 1) % n];
            const std::array<double, 2> m = unit_vector(p[0] + 2 * wall.normals[i][0] + q[0],
                                                        p[1] + 2 * wall.normals[i][1] + q[1]);
            smoothed[i] = (m[0] == 0 && m[1] == 0) ? wall.normals[i] : m;
        }
        wall.normals = std::move(smoothed);
    }
}

DomainBoundary2 discretize_except_walls(const MeshDomain2& domain, std::span<const WallLoop2> walls,
                                        const SizeFunction& size) {
    const tri::Triangulation2& mesh = domain.triangulation().mesh;
    std::set<std::array<double, 4>> wall_sides;
    for (const WallLoop2& wall : walls) {
        for (std::size_t i = 0; i < wall.vertices.size(); ++i) {
            const double* a = mesh.point(wall.vertices[i]);
            const double* b = mesh.point(wall.vertices[(i + 1) % wall.vertices.size()]);
            wall_sides.insert({a[0], a[1], b[0], b[1]});
            wall_sides.insert({b[0], b[1], a[0], a[1]});
        }
    }
    return discretize_domain_boundary(domain, [&](const double* a, const double* b) {
        return wall_sides.count({a[0], a[1], b[0], b[1]}) != 0 ? SizeFunction{} : size;
    });
}

}  // namespace exactmesh::generators
