// SPDX-License-Identifier: MIT
// Assembly of a generator's triangles into the common result (see domain_mesh_2d.hpp).
#include "generators/domain_mesh_2d.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "predicates/errors.hpp"

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
    auto key = [](tri::VertIdx a, tri::VertIdx b) { return (std::uint64_t{a} << 32) | b; };
    std::unordered_map<std::uint64_t, tri::EdgeIdx> edge_of;
    edge_of.reserve(triangles.size());
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const tri::VertIdx a = triangles[e], b = triangles[e - e % 3 + (e + 1) % 3];
        if (a >= n || b >= n)
            throw InternalError(
                "domain_mesh_result: a triangle names a vertex that does not exist");
        if (!edge_of.emplace(key(a, b), static_cast<tri::EdgeIdx>(e)).second) {
            throw InternalError("domain_mesh_result: edge " + std::to_string(a) + " -> " +
                                std::to_string(b) + " is in two triangles");
        }
    }
    std::unordered_set<std::uint64_t> piece_set;
    piece_set.reserve(boundary.pieces.size());
    for (std::size_t p = 0; 2 * p + 1 < boundary.pieces.size(); ++p) {
        const tri::VertIdx a = boundary.pieces[2 * p], b = boundary.pieces[2 * p + 1];
        piece_set.insert(key(std::min(a, b), std::max(a, b)));
    }
    tri::Cdt2Result result;
    tri::Triangulation2& mesh = result.mesh;
    mesh.neighbors.assign(triangles.size(), tri::kNone);
    mesh.constrained.assign(triangles.size(), 0);
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const tri::VertIdx a = triangles[e], b = triangles[e - e % 3 + (e + 1) % 3];
        const auto twin = edge_of.find(key(b, a));
        if (twin != edge_of.end()) mesh.neighbors[e] = static_cast<tri::TriIdx>(twin->second / 3);
        mesh.constrained[e] = piece_set.count(key(std::min(a, b), std::max(a, b))) ? 1 : 0;
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
