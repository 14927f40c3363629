// SPDX-License-Identifier: MIT
// Derefinement of an adaptive 2D mesh by constrained Delaunay vertex removal (see
// derefinement_2d.hpp).
#include "generators/adaptation/derefinement_2d.hpp"

#include <numeric>

#include "generators/adaptation/mesh_edges.hpp"
#include "triangulation/modification/vertex_removal_2d.hpp"

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

std::uint64_t derefinement_pass_2d(AdaptiveMesh2& state, const DerefinementOptions& options,
                                   DerefinementCounters2& counters) {
    triangulation::Triangulation2& mesh = state.mesh;
    const std::uint32_t vertex_count = mesh.vertex_count();
    ++counters.passes;
    const std::vector<VertIdx> edges = mesh_edges_2d(mesh.triangles);
    if (edges.empty()) return 0;
    const std::vector<double> indicator =
        mesh_edge_indicator(options.indicator, mesh.xy, 2, mesh.triangles, edges, state.values);
    const double mean =
        options.reference_mean > 0 ? options.reference_mean : mean_indicator(indicator);
    // A vertex is a candidate when every edge at it is below the threshold (and it has one).
    std::vector<std::uint8_t> low(vertex_count, 0), seen(vertex_count, 0);
    for (std::size_t e = 0; e < indicator.size(); ++e) {
        for (const VertIdx v : {edges[2 * e], edges[2 * e + 1]}) {
            if (!seen[v]) low[v] = 1;
            seen[v] = 1;
            if (!(indicator[e] < options.threshold * mean)) low[v] = 0;
        }
    }
    std::vector<VertIdx> chosen;
    for (std::size_t v = state.fixed_vertices; v < vertex_count; ++v) {
        if (low[v]) chosen.push_back(static_cast<VertIdx>(v));
    }
    return remove_vertex_set_2d(state, chosen, edges, counters);
}

std::uint64_t remove_vertex_set_2d(AdaptiveMesh2& state, std::span<const VertIdx> candidates,
                                   std::span<const VertIdx> edges, DerefinementCounters2& counters,
                                   std::vector<VertIdx>* old_to_new) {
    triangulation::Triangulation2& mesh = state.mesh;
    const std::uint32_t vertex_count = mesh.vertex_count();
    std::vector<VertIdx> chosen;
    {
        std::vector<std::uint8_t> wanted(vertex_count, 0);
        for (const VertIdx v : candidates)
            if (v >= state.fixed_vertices && v < vertex_count) wanted[v] = 1;
        for (std::size_t v = state.fixed_vertices; v < vertex_count; ++v)
            if (wanted[v]) chosen.push_back(static_cast<VertIdx>(v));
    }
    // A maximal independent set of them, greedily in increasing vertex order: a candidate is
    // taken unless a neighbour was taken before it (the holes stay one star wide).
    {
        std::vector<std::uint32_t> start(vertex_count + 1, 0);
        for (const VertIdx v : edges) ++start[v + 1];
        for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
        std::vector<VertIdx> neighbours(edges.size());
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::size_t e = 0; e < edges.size() / 2; ++e) {
            neighbours[fill[edges[2 * e]]++] = edges[2 * e + 1];
            neighbours[fill[edges[2 * e + 1]]++] = edges[2 * e];
        }
        std::vector<std::uint8_t> taken(vertex_count, 0);
        std::vector<VertIdx> independent;
        for (const VertIdx v : chosen) {
            bool free = true;
            for (std::uint32_t k = start[v]; k < start[v + 1] && free; ++k)
                free = taken[neighbours[k]] == 0;
            if (!free) continue;
            taken[v] = 1;
            independent.push_back(v);
        }
        chosen.swap(independent);
    }
    counters.candidates += chosen.size();
    if (chosen.empty()) {
        if (old_to_new != nullptr) {
            old_to_new->resize(vertex_count);
            std::iota(old_to_new->begin(), old_to_new->end(), VertIdx{0});
        }
        return 0;
    }

    // The pieces at each vertex, to merge the two at a removed one.
    std::vector<std::uint32_t> piece_at(2 * std::size_t{vertex_count}, kNone);
    for (std::size_t p = 0; p < state.pieces.size(); ++p) {
        for (const VertIdx v : {state.pieces[p].a, state.pieces[p].b}) {
            std::uint32_t* slot = &piece_at[2 * std::size_t{v}];
            if (slot[0] == kNone)
                slot[0] = static_cast<std::uint32_t>(p);
            else
                slot[1] = static_cast<std::uint32_t>(p);
        }
    }
    triangulation::VertexRemoval2Counters removal;
    const triangulation::VertexRemoval2Result result =
        triangulation::remove_vertices_2d(mesh, chosen, state.fixed_vertices, &removal);
    std::vector<std::uint8_t> dead_piece(state.pieces.size(), 0);
    for (std::size_t i = 0; i < chosen.size(); ++i) {
        if (result.status[i] != triangulation::RemovalStatus::Removed) {
            ++counters.refused;
            continue;
        }
        ++counters.removed;
        const VertIdx v = chosen[i];
        const std::uint32_t p = piece_at[2 * std::size_t{v}], q = piece_at[2 * std::size_t{v} + 1];
        if (p == kNone || q == kNone) continue;
        // Merge: p = (u, v) or (v, u), q = (v, w) or (w, v); the merged piece runs u -> w with
        // the outer ends' parameters.
        CurvedPiece2& first = state.pieces[p];
        const CurvedPiece2& second = state.pieces[q];
        const VertIdx u = first.a == v ? first.b : first.a;
        const double uu = first.a == v ? first.ub : first.ua;
        const VertIdx w = second.a == v ? second.b : second.a;
        const double uw = second.a == v ? second.ub : second.ua;
        first = {u, w, first.curve, uu, uw};
        dead_piece[q] = 1;
        ++counters.piece_merges;
        // w's slot that named q now names p.
        std::uint32_t* slot = &piece_at[2 * std::size_t{w}];
        if (slot[0] == q) slot[0] = p;
        if (slot[1] == q) slot[1] = p;
    }
    // Compact: pieces, values and curve flags by the removal's numbering.
    std::vector<CurvedPiece2> pieces;
    for (std::size_t p = 0; p < state.pieces.size(); ++p) {
        if (dead_piece[p]) continue;
        CurvedPiece2 piece = state.pieces[p];
        piece.a = result.old_to_new[piece.a];
        piece.b = result.old_to_new[piece.b];
        pieces.push_back(piece);
    }
    state.pieces = std::move(pieces);
    std::vector<double> values(mesh.vertex_count());
    std::vector<std::uint8_t> on_curve(mesh.vertex_count(), 0);
    for (std::size_t v = 0; v < result.old_to_new.size(); ++v) {
        const VertIdx n = result.old_to_new[v];
        if (n == kNone) continue;
        values[n] = state.values[v];
        if (v < state.on_curve.size()) on_curve[n] = state.on_curve[v];
    }
    state.values = std::move(values);
    state.on_curve = std::move(on_curve);
    if (old_to_new != nullptr) *old_to_new = result.old_to_new;
    return result.removed;
}

}  // namespace exactmesh::generators
