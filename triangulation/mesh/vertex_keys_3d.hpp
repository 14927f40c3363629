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
/// the same vertices are neighbours in the list. A counting sort by the smallest vertex (stable:
/// face order within a bucket), then each bucket (a vertex's faces, about 20) sorted as 64-bit
/// words (k1 k2, face): the order of one sort of the whole list, which cost 10x more (two of
/// them were 4.6% of tetmesh's instructions on box-with-hole). Vertex numbers far beyond the
/// list's size (no such mesh; kNone in a dead slot) take one sort of (k0 k1, k2 face) pairs.
inline std::vector<KeyedFace3> sorted_faces_3d(const std::vector<VertIdx>& tets) {
    const std::size_t count = tets.size();
    std::vector<Key3> keys(count);
    VertIdx top = 0;
    for (std::size_t f = 0; f < count; ++f) {
        const std::size_t t = f / 4;
        const unsigned* lf = kFaceVertex[f % 4];
        keys[f] = sorted3(tets[4 * t + lf[0]], tets[4 * t + lf[1]], tets[4 * t + lf[2]]);
        top = std::max(top, keys[f][0]);
    }
    std::vector<KeyedFace3> faces;
    faces.reserve(count);
    if (std::size_t{top} > 2 * count + 1024) {
        std::vector<std::pair<std::uint64_t, std::uint64_t>> packed;
        packed.reserve(count);
        for (std::size_t f = 0; f < count; ++f) {
            packed.push_back({(std::uint64_t{keys[f][0]} << 32) | keys[f][1],
                              (std::uint64_t{keys[f][2]} << 32) | f});
        }
        std::sort(packed.begin(), packed.end());
        for (const auto& [high, low] : packed) {
            faces.push_back({{static_cast<VertIdx>(high >> 32), static_cast<VertIdx>(high),
                              static_cast<VertIdx>(low >> 32)},
                             static_cast<std::uint32_t>(low)});
        }
        return faces;
    }
    std::vector<std::uint32_t> begin(std::size_t{top} + 2, 0);
    for (const Key3& key : keys) ++begin[std::size_t{key[0]} + 1];
    for (std::size_t v = 1; v < begin.size(); ++v) begin[v] += begin[v - 1];
    std::vector<std::uint32_t> cursor(begin.begin(), begin.end() - 1);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> rest(count);
    for (std::size_t f = 0; f < count; ++f) {
        rest[cursor[keys[f][0]]++] = {(std::uint64_t{keys[f][1]} << 32) | keys[f][2],
                                      static_cast<std::uint32_t>(f)};
    }
    for (std::size_t v = 0; v + 1 < begin.size(); ++v) {
        const auto first = rest.begin() + static_cast<std::ptrdiff_t>(begin[v]);
        const auto last = rest.begin() + static_cast<std::ptrdiff_t>(begin[v + 1]);
        std::sort(first, last);
        for (auto it = first; it != last; ++it) {
            faces.push_back({{static_cast<VertIdx>(v), static_cast<VertIdx>(it->first >> 32),
                              static_cast<VertIdx>(it->first)},
                             it->second});
        }
    }
    return faces;
}

/// An undirected edge: the smaller vertex in the high word.
inline std::uint64_t edge_key(VertIdx a, VertIdx b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace exactmesh::triangulation
