// SPDX-License-Identifier: MIT
// Assembly of a generator's triangles into the common result (see domain_mesh_2d.hpp).
#include "generators/mesh_2d/domain_mesh_2d.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "base/errors.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

tri::Cdt2Result domain_mesh_result(const DomainBoundary2& boundary, std::vector<double> xy,
                                   std::vector<tri::VertIdx> triangles) {
    if (xy.size() < boundary.xy.size() || triangles.size() % 3 != 0) {
        throw InternalError("domain_mesh_result: " + std::to_string(xy.size() / 2) +
                            " vertices (the boundary has " +
                            std::to_string(boundary.xy.size() / 2) + "), " +
                            std::to_string(triangles.size()) + " triangle indices");
    }
    const auto n = static_cast<tri::VertIdx>(xy.size() / 2);
    // Half-edges bucketed by origin vertex (counting sort), each bucket sorted by destination:
    // a twin is a binary search in one vertex's bucket, a repeated directed edge two equal
    // neighbours in it (O(n log degree); a hash map of every half-edge was a third of the
    // quadtree generator's time).
    const std::size_t count = triangles.size();
    auto destination = [&](std::size_t e) { return triangles[e - e % 3 + (e + 1) % 3]; };
    std::vector<std::uint32_t> start(std::size_t{n} + 1, 0);
    for (std::size_t e = 0; e < count; ++e) {
        if (triangles[e] >= n)
            throw InternalError(
                "domain_mesh_result: a triangle names a vertex that does not exist");
        ++start[triangles[e] + 1];
    }
    for (std::size_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<tri::EdgeIdx> bucket(count);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t e = 0; e < count; ++e)
            bucket[fill[triangles[e]]++] = static_cast<tri::EdgeIdx>(e);
    }
    auto by_destination = [&](tri::EdgeIdx e, tri::EdgeIdx f) {
        return destination(e) < destination(f);
    };
    for (std::size_t v = 0; v < n; ++v) {
        const auto first = bucket.begin() + start[v], last = bucket.begin() + start[v + 1];
        std::sort(first, last, by_destination);
        const auto twice = std::adjacent_find(first, last, [&](tri::EdgeIdx e, tri::EdgeIdx f) {
            return destination(e) == destination(f);
        });
        if (twice != last) {
            throw InternalError("domain_mesh_result: edge " + std::to_string(v) + " -> " +
                                std::to_string(destination(*twice)) + " is in two triangles");
        }
    }
    // The half-edge a -> b, or kNone.
    auto find = [&](tri::VertIdx a, tri::VertIdx b) {
        const auto first = bucket.begin() + start[a], last = bucket.begin() + start[a + 1];
        const auto it =
            std::partition_point(first, last, [&](tri::EdgeIdx e) { return destination(e) < b; });
        return it != last && destination(*it) == b ? *it : tri::kNone;
    };
    tri::Cdt2Result result;
    tri::Triangulation2& mesh = result.mesh;
    mesh.neighbors.assign(count, tri::kNone);
    mesh.constrained.assign(count, 0);
    for (std::size_t e = 0; e < count; ++e) {
        const tri::EdgeIdx twin = find(destination(e), triangles[e]);
        if (twin != tri::kNone) mesh.neighbors[e] = static_cast<tri::TriIdx>(twin / 3);
    }
    for (std::size_t p = 0; 2 * p + 1 < boundary.pieces.size(); ++p) {
        const tri::VertIdx a = boundary.pieces[2 * p], b = boundary.pieces[2 * p + 1];
        if (a >= n || b >= n) continue;
        for (const tri::EdgeIdx e : {find(a, b), find(b, a)}) {
            if (e != tri::kNone) mesh.constrained[e] = 1;
        }
    }
    mesh.xy = std::move(xy);
    mesh.triangles = std::move(triangles);
    result.input_vertex_count = boundary.input_vertex_count;
    result.merged_into = boundary.cdt.merged_into;
    result.pieces = boundary.pieces;
    result.piece_segment = boundary.piece_segment;
    result.warnings = boundary.cdt.warnings;
    result.counters = boundary.cdt.counters;
    return result;
}

}  // namespace exactmesh::generators
