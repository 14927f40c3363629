// SPDX-License-Identifier: MIT
#include "triangulation/mesh/constrained_flags_2d.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace exactmesh::triangulation {

void flag_constrained_edges_2d(Triangulation2& mesh, std::span<const VertIdx> edges) {
    // Sorted keys (smaller end in the high half) and a binary search: no hashing of
    // adversarial indices, O((E + T) log E).
    const auto key = [](VertIdx a, VertIdx b) {
        return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
    };
    std::vector<std::uint64_t> keys;
    keys.reserve(edges.size() / 2);
    for (std::size_t s = 0; s + 1 < edges.size(); s += 2)
        keys.push_back(key(edges[s], edges[s + 1]));
    std::sort(keys.begin(), keys.end());
    mesh.constrained.assign(mesh.triangles.size(), 0);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const VertIdx a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
            mesh.constrained[3 * t + k] =
                std::binary_search(keys.begin(), keys.end(), key(a, b)) ? 1 : 0;
        }
    }
}

}  // namespace exactmesh::triangulation
