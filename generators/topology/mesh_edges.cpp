// SPDX-License-Identifier: MIT
// Edge lists and the unit scale of the adaptation layer (see mesh_edges.hpp).
#include "generators/topology/mesh_edges.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

namespace {

// The distinct pairs among `pairs` (2 per pair, any order within a pair), as (u, v) with
// u < v in increasing order: bucketed by u (a counting sort, O(P + V)), then each vertex's few
// partners sorted and deduplicated in place. A comparison sort of 64-bit keys was a seventh of
// an adaptation cycle.
std::vector<VertIdx> sorted_unique_pairs(std::span<const VertIdx> pairs) {
    VertIdx largest = 0;
    for (const VertIdx v : pairs) largest = std::max(largest, v);
    const std::size_t count = pairs.size() / 2;
    std::vector<std::uint32_t> first(std::size_t{largest} + 2, 0);
    for (std::size_t i = 0; i < count; ++i)
        ++first[std::size_t{std::min(pairs[2 * i], pairs[2 * i + 1])} + 1];
    for (std::size_t u = 0; u + 1 < first.size(); ++u) first[u + 1] += first[u];
    std::vector<VertIdx> partner(count);
    {
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::size_t i = 0; i < count; ++i) {
            const VertIdx a = pairs[2 * i], b = pairs[2 * i + 1];
            partner[fill[std::min(a, b)]++] = std::max(a, b);
        }
    }
    std::vector<VertIdx> edges;
    edges.reserve(count + 2);  // about half the element sides are shared
    for (std::size_t u = 0; u + 1 < first.size(); ++u) {
        const auto begin = partner.begin() + first[u], end = partner.begin() + first[u + 1];
        std::sort(begin, end);
        for (auto it = begin; it != end; ++it) {
            if (it != begin && *it == *(it - 1)) continue;
            edges.push_back(static_cast<VertIdx>(u));
            edges.push_back(*it);
        }
    }
    return edges;
}

}  // namespace

std::vector<VertIdx> mesh_edges_2d(std::span<const VertIdx> triangles) {
    std::vector<VertIdx> pairs;
    pairs.reserve(2 * triangles.size());
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        if (triangles[t] == kNone) continue;
        for (unsigned k = 0; k < 3; ++k)
            pairs.insert(pairs.end(), {triangles[t + k], triangles[t + (k + 1) % 3]});
    }
    return sorted_unique_pairs(pairs);
}

std::vector<VertIdx> mesh_edges_3d(std::span<const VertIdx> tets) {
    std::vector<VertIdx> pairs;
    pairs.reserve(tets.size() / 4 * 12);
    for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
        if (tets[t] == kNone) continue;
        for (unsigned i = 0; i < 4; ++i)
            for (unsigned j = i + 1; j < 4; ++j)
                pairs.insert(pairs.end(), {tets[t + i], tets[t + j]});
    }
    return sorted_unique_pairs(pairs);
}

std::uint32_t find_mesh_edge(std::span<const VertIdx> edges, VertIdx u, VertIdx v) {
    if (u > v) std::swap(u, v);
    std::size_t lo = 0, hi = edges.size() / 2;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        const VertIdx a = edges[2 * mid], b = edges[2 * mid + 1];
        if (a < u || (a == u && b < v))
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo < edges.size() / 2 && edges[2 * lo] == u && edges[2 * lo + 1] == v)
        return static_cast<std::uint32_t>(lo);
    return kNone;
}

MeshEdgeIndex::MeshEdgeIndex(std::span<const VertIdx> edges) : edges_(edges) {
    const std::size_t count = edges.size() / 2;
    const VertIdx last = count == 0 ? 0 : edges[2 * (count - 1)];
    first_.assign(std::size_t{last} + 2, 0);
    // Edges are sorted by their first vertex: first_[u] is the number of edges whose first
    // vertex is below u.
    for (std::size_t e = 0; e < count; ++e) ++first_[std::size_t{edges[2 * e]} + 1];
    for (std::size_t u = 0; u + 1 < first_.size(); ++u) first_[u + 1] += first_[u];
}

std::uint32_t MeshEdgeIndex::find(VertIdx u, VertIdx v) const {
    if (u > v) std::swap(u, v);
    if (std::size_t{u} + 1 >= first_.size()) return kNone;
    for (std::uint32_t e = first_[u]; e < first_[std::size_t{u} + 1]; ++e)
        if (edges_[2 * std::size_t{e} + 1] == v) return e;
    return kNone;
}

int unit_scale_exponent(std::span<const double> coordinates, unsigned dim,
                        std::span<const VertIdx> elements) {
    double lo[3], hi[3];
    for (unsigned d = 0; d < dim; ++d) {
        lo[d] = std::numeric_limits<double>::infinity();
        hi[d] = -lo[d];
    }
    for (const VertIdx v : elements) {
        if (v == kNone || v == triangulation::kInfinite) continue;
        for (unsigned d = 0; d < dim; ++d) {
            const double c = coordinates[std::size_t{dim} * v + d];
            lo[d] = std::min(lo[d], c);
            hi[d] = std::max(hi[d], c);
        }
    }
    // The extent of each axis as max(|hi|, |lo|, hi - lo) scaled down by 2 first, so that
    // hi - lo cannot overflow near the largest double.
    double extent = 0;
    for (unsigned d = 0; d < dim; ++d) {
        if (!(lo[d] <= hi[d])) return 0;
        extent = std::max(extent, 0.5 * hi[d] - 0.5 * lo[d]);
    }
    if (extent == 0) return 0;
    int exponent = 0;
    (void)std::frexp(extent, &exponent);
    return exponent + 1;
}

std::vector<double> scaled_coordinates(std::span<const double> coordinates, int exponent) {
    std::vector<double> scaled(coordinates.size());
    for (std::size_t i = 0; i < coordinates.size(); ++i)
        scaled[i] = std::ldexp(coordinates[i], -exponent);
    return scaled;
}

}  // namespace exactmesh::generators
