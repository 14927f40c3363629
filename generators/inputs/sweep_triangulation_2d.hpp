// SPDX-License-Identifier: MIT
// A deliberately poor starting triangulation for the swapping tests and benches: the sweep
// triangulation (points sorted by x then y, each joined to every hull edge it sees), full of
// long thin triangles. O(n h) with h the hull size; exact orient2d; duplicates are skipped
// (they keep no triangle). An input generator for the swapping tests and benchmarks (the
// starting point that edge swapping and edge cutting improve), not a meshing algorithm.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "predicates/orient2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

inline triangulation::Triangulation2 sweep_triangulation_2d(std::span<const double> xy) {
    using predicates::orient2d;
    using predicates::Sign;
    using triangulation::VertIdx;
    triangulation::Triangulation2 mesh;
    mesh.xy.assign(xy.begin(), xy.end());
    const auto n = static_cast<VertIdx>(xy.size() / 2);
    auto p = [&](VertIdx v) { return xy.data() + 2 * std::size_t{v}; };
    std::vector<VertIdx> order(n);
    std::iota(order.begin(), order.end(), VertIdx{0});
    std::sort(order.begin(), order.end(), [&](VertIdx a, VertIdx b) {
        return p(a)[0] != p(b)[0] ? p(a)[0] < p(b)[0]
                                  : (p(a)[1] != p(b)[1] ? p(a)[1] < p(b)[1] : a < b);
    });
    order.erase(
        std::unique(order.begin(), order.end(),
                    [&](VertIdx a, VertIdx b) { return p(a)[0] == p(b)[0] && p(a)[1] == p(b)[1]; }),
        order.end());
    // The first points, while collinear, form a chain; the first point off their line closes
    // the first fan and a counter-clockwise hull.
    std::size_t k = 2;
    while (k < order.size() && orient2d(p(order[0]), p(order[1]), p(order[k])) == Sign::Zero) ++k;
    if (k >= order.size()) return mesh;  // collinear: no triangle
    const VertIdx apex = order[k];
    const bool ccw = orient2d(p(order[0]), p(order[1]), p(apex)) == Sign::Positive;
    std::vector<VertIdx> hull;
    for (std::size_t i = 0; i + 1 < k; ++i) {
        if (ccw) {
            mesh.triangles.insert(mesh.triangles.end(), {order[i], order[i + 1], apex});
        } else {
            mesh.triangles.insert(mesh.triangles.end(), {order[i + 1], order[i], apex});
        }
    }
    for (std::size_t i = 0; i < k; ++i) hull.push_back(order[ccw ? i : k - 1 - i]);
    hull.push_back(apex);
    for (std::size_t i = k + 1; i < order.size(); ++i) {
        const VertIdx v = order[i];
        const std::size_t h = hull.size();
        std::vector<std::uint8_t> visible(h, 0);
        for (std::size_t e = 0; e < h; ++e) {
            visible[e] = orient2d(p(hull[e]), p(hull[(e + 1) % h]), p(v)) == Sign::Negative;
        }
        // The visible edges are one contiguous run (the hull is convex); find its start.
        std::size_t start = 0;
        while (!(visible[start] && !visible[(start + h - 1) % h])) ++start;
        std::size_t end = start;
        while (visible[end % h]) {
            const std::size_t e = end % h;
            mesh.triangles.insert(mesh.triangles.end(), {hull[(e + 1) % h], hull[e], v});
            ++end;
        }
        // Keep hull[start] .. (not the interior of the run) .. hull[end], insert v between.
        std::vector<VertIdx> next;
        next.push_back(hull[start]);
        next.push_back(v);
        for (std::size_t j = end; j < start + h; ++j) next.push_back(hull[j % h]);
        hull = next;
    }
    triangulation::link_neighbors_2d(mesh);
    return mesh;
}

}  // namespace exactmesh::generators
