// SPDX-License-Identifier: MIT
// TriMesh2: a 2D triangulation in flat index arrays, closed by one infinite vertex so that
// every half-edge has a twin. Algorithms are free functions over it (bowyer_watson_2d, ...).
//
// Local indices of triangle t (counter-clockwise), half-edge e = 3t + k runs from
// tv[3t+k] to tv[3t + (k+1)%3]; twin[e] is the same edge in the neighbouring triangle:
//
//                 v2 = tv[3t+2]
//                   /\    .
//        e = 3t+2  /  \   e = 3t+1
//                 /  t \  .
//               v0 ---- v1
//                 e = 3t+0
//
// An infinite triangle has kInfinite as one vertex; its finite edge has the hull's outside
// on its left, so for an infinite triangle (a, b, inf), orient2d(a, b, q) > 0 means q lies
// beyond the hull edge ab. Dead triangles (recycled by the algorithms) have tv == kNone.
// A mesh converted from a Triangulation2 for editing (flip_2d.hpp's HalfEdgeEdit) has no
// infinite vertex: there twin == kNone on the boundary.
#pragma once

#include <cstdint>
#include <vector>

namespace exactmesh::triangulation {

using VertIdx = std::uint32_t;
using TriIdx = std::uint32_t;
using EdgeIdx = std::uint32_t;

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
inline constexpr VertIdx kInfinite = 0xFFFFFFFEu;
/// Largest number of input points: 3 half-edges per triangle must fit in 32 bits.
inline constexpr std::uint32_t kMaxPoints = 0x3FFFFFFFu;

inline constexpr EdgeIdx next_edge(EdgeIdx e) {
    return e % 3 == 2 ? e - 2 : e + 1;
}
inline constexpr EdgeIdx prev_edge(EdgeIdx e) {
    return e % 3 == 0 ? e + 2 : e - 1;
}
inline constexpr TriIdx triangle_of(EdgeIdx e) {
    return e / 3;
}

struct TriMesh2 {
    std::vector<double> xy;     ///< 2·#V coordinates, x0 y0 x1 y1 ...
    std::vector<VertIdx> tv;    ///< 3·#T vertices, counter-clockwise; kNone for dead triangles
    std::vector<EdgeIdx> twin;  ///< 3·#T opposite half-edges
    std::vector<TriIdx> free_triangles;  ///< dead triangle slots to recycle
    /// 3·#T per half-edge marks (bit 0: constrained edge; both halves of an edge agree), or empty
    /// when no edge carries one; the flip kernel (flip_2d.hpp) keeps them through every edit.
    std::vector<std::uint8_t> flags;

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xy.size() / 2); }
    std::uint32_t triangle_slots() const { return static_cast<std::uint32_t>(tv.size() / 3); }
    const double* point(VertIdx v) const { return xy.data() + 2 * static_cast<std::size_t>(v); }

    VertIdx origin(EdgeIdx e) const { return tv[e]; }
    VertIdx destination(EdgeIdx e) const { return tv[next_edge(e)]; }
    bool is_dead(TriIdx t) const { return tv[3 * t] == kNone; }
    bool is_infinite(TriIdx t) const {
        return tv[3 * t] == kInfinite || tv[3 * t + 1] == kInfinite || tv[3 * t + 2] == kInfinite;
    }

    /// A slot for a new triangle (recycled when possible); the caller fills tv and twin.
    TriIdx new_triangle() {
        if (!free_triangles.empty()) {
            const TriIdx t = free_triangles.back();
            free_triangles.pop_back();
            return t;
        }
        const TriIdx t = triangle_slots();
        tv.resize(tv.size() + 3, kNone);
        twin.resize(twin.size() + 3, kNone);
        if (!flags.empty()) flags.resize(flags.size() + 3, 0);
        return t;
    }

    /// `count` new slots appended to `slots`, the ones `count` calls of new_triangle would give,
    /// in the same order, with one growth of each array.
    void new_triangles(std::size_t count, std::vector<TriIdx>& slots) {
        std::size_t appended = 0;
        for (std::size_t i = 0; i < count; ++i) {
            if (!free_triangles.empty()) {
                slots.push_back(free_triangles.back());
                free_triangles.pop_back();
            } else {
                slots.push_back(triangle_slots() + static_cast<TriIdx>(appended++));
            }
        }
        if (appended == 0) return;
        tv.resize(tv.size() + 3 * appended, kNone);
        twin.resize(twin.size() + 3 * appended, kNone);
        if (!flags.empty()) flags.resize(flags.size() + 3 * appended, 0);
    }

    void kill_triangle(TriIdx t) {
        tv[3 * t] = tv[3 * t + 1] = tv[3 * t + 2] = kNone;
        free_triangles.push_back(t);
    }

    void link(EdgeIdx e, EdgeIdx f) {
        twin[e] = f;
        twin[f] = e;
    }
};

}  // namespace exactmesh::triangulation
