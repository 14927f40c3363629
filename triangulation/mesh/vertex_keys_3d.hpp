// SPDX-License-Identifier: MIT
// Hash keys of mesh faces and edges by their vertex numbers, shared by the 3D boundary recovery
// and Delaunay refinement (which keep sets of subfaces and subsegments): a face as its three
// vertices sorted, an edge as its two vertices sorted in one 64-bit word.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation {

/// A face by its vertices (sorted by sorted3: the same key for every orientation).
using Key3 = std::array<VertIdx, 3>;

struct Key3Hash {
    std::size_t operator()(const Key3& k) const noexcept {
        std::uint64_t h = k[0];
        h = h * 0x9E3779B97F4A7C15ull + k[1];
        h = h * 0x9E3779B97F4A7C15ull + k[2];
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

inline Key3 sorted3(VertIdx a, VertIdx b, VertIdx c) {
    // Three compare-exchanges (std::sort's call was a tenth of 3D refinement's instructions).
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {a, b, c};
}

/// An undirected edge: the smaller vertex in the high word.
inline std::uint64_t edge_key(VertIdx a, VertIdx b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace exactmesh::triangulation
