// SPDX-License-Identifier: MIT
// The numbering of a Delaunay result, shared by Delaunay2Core::take_result and
// Delaunay3Core::take_result: merged duplicate points reported by their first occurrence, the
// finite cells (triangles, tetrahedra) numbered consecutively and compacted in place (by chunks,
// on every thread of the multicore constructions). Internal to triangulation/delaunay.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "base/chunk_runner.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation::detail {

/// merged_into (caller index -> caller index of the copy kept in the mesh) rewritten so that each
/// group of equal points maps to its smallest caller index ("the first occurrence"), and
/// input_index (mesh vertex -> caller index) to the same representative, so that the triangles
/// or tetrahedra name it too. Needed only when some points were merged.
inline void report_first_occurrence(std::vector<VertIdx>& merged_into,
                                    std::vector<VertIdx>& input_index) {
    std::vector<VertIdx> smallest(merged_into.size());
    for (VertIdx i = 0; i < smallest.size(); ++i) smallest[i] = i;
    for (VertIdx i = 0; i < smallest.size(); ++i) {
        const VertIdx kept = merged_into[i];
        if (i < smallest[kept]) smallest[kept] = i;
    }
    for (VertIdx i = 0; i < smallest.size(); ++i) merged_into[i] = smallest[merged_into[i]];
    for (VertIdx& v : input_index) v = merged_into[v];
}

using exactmesh::ChunkRunner;

/// The result of a mesh of cells of K vertices (triangles K = 3, tetrahedra K = 4) in place:
/// the live finite cells among the first `slots` numbered consecutively in slot order
/// (output_index[t], kNone for a dead or infinite cell), and cell t's vertices (mapped by
/// `first`) and neighbours (neighbour_of(entry of `across`) -> output number or kNone) moved to
/// position output_index[t]. Returns the number of cells. `chunks` cut the slots into ranges run
/// by `run` (possibly at once): a cell's output position is at most its slot, so a chunk writes in
/// place what lands in its own range, after reading it, and holds what lands in earlier chunks'
/// ranges until every chunk has read its own (those are the dead slots before it: a few percent).
/// One chunk is the sequential compaction.
template <unsigned K, class Mesh, class NeighbourOf>
std::uint32_t compact_cells(const Mesh& mesh, std::vector<std::uint32_t>& vertices,
                            std::vector<std::uint32_t>& across, const std::vector<VertIdx>& first,
                            std::vector<std::uint32_t>& output_index, std::uint32_t slots,
                            std::size_t chunks, const ChunkRunner& run, NeighbourOf neighbour_of) {
    chunks = std::max<std::size_t>(1, std::min<std::size_t>(chunks, slots / 4096 + 1));
    auto run_chunks = [&](const std::function<void(std::size_t)>& body) {
        if (run && chunks > 1) {
            run(chunks, body);
        } else {
            for (std::size_t c = 0; c < chunks; ++c) body(c);
        }
    };
    auto chunk_begin = [&](std::size_t c) {
        return static_cast<std::uint32_t>(std::uint64_t{slots} * c / chunks);
    };
    output_index.resize(slots);
    // The chunks' first numbers (the cells before them: counted first when there are several).
    std::vector<std::uint32_t> first_output(chunks + 1, 0);
    auto is_cell = [&mesh](std::uint32_t t) { return !mesh.is_dead(t) && !mesh.is_infinite(t); };
    if (chunks > 1) {
        run_chunks([&](std::size_t c) {
            std::uint32_t count = 0;
            for (std::uint32_t t = chunk_begin(c); t < chunk_begin(c + 1); ++t) count += is_cell(t);
            first_output[c + 1] = count;
        });
        for (std::size_t c = 0; c < chunks; ++c) first_output[c + 1] += first_output[c];
    }
    run_chunks([&](std::size_t c) {
        std::uint32_t next = first_output[c];
        for (std::uint32_t t = chunk_begin(c); t < chunk_begin(c + 1); ++t) {
            output_index[t] = is_cell(t) ? next++ : kNone;
        }
        if (c + 1 == chunks) first_output[chunks] = next;
    });
    std::vector<std::vector<std::uint32_t>> held(chunks);
    // Every number is known before any cell moves (neighbours read the numbers of others).
    run_chunks([&](std::size_t c) {
        const std::uint32_t own = chunk_begin(c), end = chunk_begin(c + 1);
        std::uint32_t* const cell_vertices = vertices.data();
        std::uint32_t* const cell_across = across.data();
        const VertIdx* const reported = first.data();
        const std::uint32_t* const number = output_index.data();
        std::uint32_t t = own;
        // What lands before the chunk is held (the first cells of a chunk only).
        for (; t < end; ++t) {
            const std::uint32_t o = number[t];
            if (o == kNone) continue;
            if (o >= own) break;
            for (unsigned k = 0; k < K; ++k)
                held[c].push_back(reported[cell_vertices[std::size_t{K} * t + k]]);
            for (unsigned k = 0; k < K; ++k)
                held[c].push_back(neighbour_of(cell_across[std::size_t{K} * t + k]));
        }
        for (; t < end; ++t) {
            const std::uint32_t o = number[t];
            if (o == kNone) continue;
            for (unsigned k = 0; k < K; ++k) {
                cell_vertices[std::size_t{K} * o + k] =
                    reported[cell_vertices[std::size_t{K} * t + k]];
                cell_across[std::size_t{K} * o + k] =
                    neighbour_of(cell_across[std::size_t{K} * t + k]);
            }
        }
    });
    run_chunks([&](std::size_t c) {
        const std::vector<std::uint32_t>& cells = held[c];
        for (std::size_t i = 0; i < cells.size() / (2 * K); ++i) {
            const std::size_t o = first_output[c] + i;
            for (unsigned k = 0; k < K; ++k) {
                vertices[K * o + k] = cells[2 * K * i + k];
                across[K * o + k] = cells[2 * K * i + K + k];
            }
        }
    });
    return first_output[chunks];
}

}  // namespace exactmesh::triangulation::detail
