// SPDX-License-Identifier: MIT
// Small PLCs shared by the 3D tests (boundary recovery, Delaunay refinement): an axis-aligned
// box, a box cut into two regions with volume bounds, scaling by a power of two, random convex
// and random star-shaped polyhedra.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

/// The mesh's volume (a rounded sum of |det| / 6: for tests' expectations only, at moderate
/// scales).
inline double mesh_volume(const Tetrahedralization3& mesh) {
    double sum = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); t += 4) {
        const double* p[4];
        for (unsigned k = 0; k < 4; ++k) p[k] = mesh.point(mesh.tets[t + k]);
        double u[3], v[3], w[3];
        for (int k = 0; k < 3; ++k) {
            u[k] = p[1][k] - p[0][k];
            v[k] = p[2][k] - p[0][k];
            w[k] = p[3][k] - p[0][k];
        }
        sum += std::fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                         u[2] * (v[0] * w[1] - v[1] * w[0])) /
               6;
    }
    return sum;
}

/// The box [0, x] x [0, y] x [0, z], one quadrilateral facet per side (marker 1).
inline Plc3 box(double x, double y, double z) {
    Plc3 plc;
    for (int k = 0; k < 8; ++k)
        plc.xyz.insert(plc.xyz.end(), {(k & 1) * x, ((k >> 1) & 1) * y, ((k >> 2) & 1) * z});
    const std::vector<std::vector<VertIdx>> faces = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& face : faces) plc.facets.push_back({{face}, {}, 1});
    return plc;
}

/// Two unit cubes that touch only along an edge (the second at (1, 1, 0)) or only at a corner
/// (at (1, 1, 1)): a valid domain whose boundary is not a manifold there (the touching edge is
/// in four boundary faces; the corner's star is in two pieces). Shared points are one vertex.
inline Plc3 cubes_touching(bool along_an_edge) {
    Plc3 plc;
    std::vector<std::array<double, 3>> points;
    const auto index = [&](const std::array<double, 3>& p) {
        for (std::size_t i = 0; i < points.size(); ++i)
            if (points[i] == p) return static_cast<VertIdx>(i);
        points.push_back(p);
        plc.xyz.insert(plc.xyz.end(), p.begin(), p.end());
        return static_cast<VertIdx>(points.size() - 1);
    };
    const std::vector<std::vector<VertIdx>> faces = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                                                     {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    const std::array<double, 3> second = {1, 1, along_an_edge ? 0.0 : 1.0};
    for (const std::array<double, 3>& origin : {std::array<double, 3>{0, 0, 0}, second}) {
        VertIdx corner[8];
        for (int k = 0; k < 8; ++k)
            corner[k] = index(
                {(k & 1) + origin[0], ((k >> 1) & 1) + origin[1], ((k >> 2) & 1) + origin[2]});
        for (const auto& face : faces) {
            std::vector<VertIdx> polygon;
            for (const VertIdx k : face) polygon.push_back(corner[k]);
            plc.facets.push_back({{polygon}, {}, 1});
        }
    }
    return plc;
}

/// The box [0, 2] x [0, 1] x [0, 1] cut by an internal facet at x = 1 (marker 3) into two unit
/// cubes: region attribute 1 with volume bound `left_bound` on the left, attribute 2 with
/// `right_bound` on the right (<= 0: no bound).
inline Plc3 two_regions_box(double left_bound, double right_bound) {
    Plc3 plc;
    // Vertex 6 * z + 3 * y + i is (i, y, z).
    for (int z = 0; z < 2; ++z)
        for (int y = 0; y < 2; ++y)
            for (int i = 0; i < 3; ++i)
                plc.xyz.insert(plc.xyz.end(), {static_cast<double>(i), static_cast<double>(y),
                                               static_cast<double>(z)});
    const auto v = [](int i, int y, int z) { return static_cast<VertIdx>(6 * z + 3 * y + i); };
    plc.facets.push_back({{{v(0, 0, 0), v(0, 1, 0), v(0, 1, 1), v(0, 0, 1)}}, {}, 1});
    plc.facets.push_back({{{v(2, 0, 0), v(2, 0, 1), v(2, 1, 1), v(2, 1, 0)}}, {}, 1});
    plc.facets.push_back({{{v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)}}, {}, 3});
    for (int i = 0; i < 2; ++i) {
        plc.facets.push_back({{{v(i, 0, 0), v(i + 1, 0, 0), v(i + 1, 0, 1), v(i, 0, 1)}}, {}, 1});
        plc.facets.push_back({{{v(i, 1, 0), v(i, 1, 1), v(i + 1, 1, 1), v(i + 1, 1, 0)}}, {}, 1});
        plc.facets.push_back({{{v(i, 0, 0), v(i, 1, 0), v(i + 1, 1, 0), v(i + 1, 0, 0)}}, {}, 1});
        plc.facets.push_back({{{v(i, 0, 1), v(i + 1, 0, 1), v(i + 1, 1, 1), v(i, 1, 1)}}, {}, 1});
    }
    plc.regions.push_back({0.5, 0.5, 0.5, 1, left_bound});
    plc.regions.push_back({1.5, 0.5, 0.5, 2, right_bound});
    return plc;
}

/// The PLC scaled by 2^exponent (vertices, hole and region points; region volume bounds by
/// 2^(3 exponent)).
inline Plc3 scaled(Plc3 plc, int exponent) {
    for (double& x : plc.xyz) x = std::ldexp(x, exponent);
    for (double& x : plc.holes) x = std::ldexp(x, exponent);
    for (Facet3& facet : plc.facets)
        for (double& x : facet.holes) x = std::ldexp(x, exponent);
    for (Region3& r : plc.regions) {
        r.x = std::ldexp(r.x, exponent);
        r.y = std::ldexp(r.y, exponent);
        r.z = std::ldexp(r.z, exponent);
        if (r.max_volume > 0) r.max_volume = std::ldexp(r.max_volume, 3 * exponent);
    }
    return plc;
}

/// A random convex polyhedron: the hull triangles of random points.
inline Plc3 random_convex(std::uint64_t seed, int points) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> xyz;
    for (int i = 0; i < 3 * points; ++i) xyz.push_back(u(rng));
    const Delaunay3Result d = delaunay_3d_algorithm("green-sibson")(xyz, {});
    Plc3 plc;
    plc.xyz = xyz;
    for (std::size_t t = 0; t < d.mesh.tets.size(); t += 4)
        for (unsigned k = 0; k < 4; ++k)
            if (d.mesh.neighbors[t + k] == kNone)
                plc.facets.push_back(
                    {{{d.mesh.tets[t + kFaceVertex[k][0]], d.mesh.tets[t + kFaceVertex[k][1]],
                       d.mesh.tets[t + kFaceVertex[k][2]]}},
                     {},
                     1});
    return plc;
}

/// A random star-shaped (non-convex) polyhedron: the hull triangles of random directions,
/// each direction's point moved to a random radius in [0.4, 1]. The triangles stay in the
/// disjoint cones over the hull triangles, so the surface does not intersect itself.
inline Plc3 random_star(std::uint64_t seed, int points) {
    Plc3 plc = random_convex(seed, points);
    std::mt19937_64 rng(seed + 1000);
    std::uniform_real_distribution<double> radius(0.4, 1);
    for (std::size_t v = 0; v < plc.xyz.size(); v += 3) {
        const double n = std::sqrt(plc.xyz[v] * plc.xyz[v] + plc.xyz[v + 1] * plc.xyz[v + 1] +
                                   plc.xyz[v + 2] * plc.xyz[v + 2]);
        const double r = radius(rng) / n;
        for (int k = 0; k < 3; ++k) plc.xyz[v + std::size_t(k)] *= r;
    }
    // Points inside the hull (not facet corners) would be dangling: drop them from the PLC by
    // keeping only the corners (renumbered).
    std::vector<VertIdx> index(plc.vertex_count(), kNone);
    std::vector<double> xyz;
    for (Facet3& f : plc.facets)
        for (VertIdx& v : f.polygons[0]) {
            if (index[v] == kNone) {
                index[v] = static_cast<VertIdx>(xyz.size() / 3);
                xyz.insert(xyz.end(), plc.point(v), plc.point(v) + 3);
            }
            v = index[v];
        }
    plc.xyz = xyz;
    return plc;
}

}  // namespace exactmesh::triangulation
