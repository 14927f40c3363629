// SPDX-License-Identifier: MIT
// Triangulation2: a finite 2D triangulation in flat arrays (no infinite vertex), with a
// constraint flag per edge side. The common currency of constrained_2d (its output),
// edge_swap_2d and edge_cutting_2d (their input and output), the checks and the writers.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

struct Triangulation2 {
    /// 2·#V coordinates. Input vertices keep their input index; vertices added by an algorithm
    /// (segment intersections, conforming midpoints, Steiner points) are appended after them.
    std::vector<double> xy;
    /// 3·#T vertex indices, counter-clockwise.
    std::vector<VertIdx> triangles;
    /// 3·#T: the triangle across edge (v[k], v[k+1 mod 3]) of triangle t, or kNone on the boundary.
    std::vector<TriIdx> neighbors;
    /// 3·#T: 1 when edge k of triangle t is a constraint (then both of its sides are marked).
    /// Empty means no edge is constrained.
    std::vector<std::uint8_t> constrained;

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xy.size() / 2); }
    std::uint32_t triangle_count() const {
        return static_cast<std::uint32_t>(triangles.size() / 3);
    }
    const double* point(VertIdx v) const { return xy.data() + 2 * static_cast<std::size_t>(v); }
    bool is_constrained(TriIdx t, int k) const {
        return !constrained.empty() &&
               constrained[3 * static_cast<std::size_t>(t) + static_cast<std::size_t>(k)] != 0;
    }
};

}  // namespace exactmesh::triangulation
