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
#include <vector>

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

/// A face of a tetrahedron list by its key, with its face slot (4 t + k, opposite corner k).
struct KeyedFace3 {
    Key3 key;
    std::uint32_t face;
};

/// Every face of `tets` (4 vertex indices per tetrahedron), sorted by (key, face): faces with
/// the same vertices are neighbours in the list. Sorted as pairs of 64-bit words (k0 k1, k2
/// face), the same order, two integer comparisons each (std::array's went through memcmp, most
/// of the sort's time in the topology check and link_facets).
inline std::vector<KeyedFace3> sorted_faces_3d(const std::vector<VertIdx>& tets) {
    std::vector<std::pair<std::uint64_t, std::uint64_t>> packed;
    packed.reserve(tets.size());
    for (std::size_t f = 0; f < tets.size(); ++f) {
        const std::size_t t = f / 4;
        const unsigned* lf = kFaceVertex[f % 4];
        const Key3 key = sorted3(tets[4 * t + lf[0]], tets[4 * t + lf[1]], tets[4 * t + lf[2]]);
        packed.push_back(
            {(std::uint64_t{key[0]} << 32) | key[1], (std::uint64_t{key[2]} << 32) | f});
    }
    std::sort(packed.begin(), packed.end());
    std::vector<KeyedFace3> faces;
    faces.reserve(packed.size());
    for (const auto& [high, low] : packed) {
        faces.push_back({{static_cast<VertIdx>(high >> 32), static_cast<VertIdx>(high),
                          static_cast<VertIdx>(low >> 32)},
                         static_cast<std::uint32_t>(low)});
    }
    return faces;
}

/// An undirected edge: the smaller vertex in the high word.
inline std::uint64_t edge_key(VertIdx a, VertIdx b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace exactmesh::triangulation
