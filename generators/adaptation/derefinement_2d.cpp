// SPDX-License-Identifier: MIT
// Derefinement of an adaptive 2D mesh by constrained Delaunay vertex removal (see
// derefinement_2d.hpp).
#include "generators/adaptation/derefinement_2d.hpp"

#include <algorithm>
#include <numeric>

#include "base/errors.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/modification/vertex_removal_2d.hpp"

namespace exactmesh::generators {

using predicates::Corner;
using predicates::Sign;
using triangulation::kNone;
using triangulation::VertIdx;

namespace {

// The reference corner of kAngleFloorDegrees: (0, 0), (1, 0), (cos 10°, sin 10°) as double
// literals (correctly rounded once by the compiler, the same on every platform, unlike a libm
// cos/sin), a fixed triangle, so the floor is the same for a mesh at any scale: compare_angles
// is exact.
static_assert(kAngleFloorDegrees == 10.0, "the literals below are cos and sin of 10 degrees");
constexpr double kFloorO[2] = {0, 0};
constexpr double kFloorP[2] = {1, 0};
constexpr double kFloorQ[2] = {0.98480775301220805936, 0.17364817766693034885};
constexpr Corner kFloorCorner{kFloorO, kFloorP, kFloorQ};

// The smallest corner of the triangles (3 vertex numbers each, counter-clockwise) of xy.
Corner smallest_of(std::span<const double> xy, std::span<const VertIdx> triangles) {
    Corner smallest{};
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const Corner c = predicates::smallest_corner(&xy[2 * std::size_t{triangles[t]}],
                                                     &xy[2 * std::size_t{triangles[t + 1]}],
                                                     &xy[2 * std::size_t{triangles[t + 2]}]);
        if (t == 0 || predicates::compare_angles(c, smallest) == Sign::Negative) smallest = c;
    }
    return smallest;
}

}  // namespace

bool removal_keeps_angles_2d(const triangulation::Triangulation2& mesh,
                             std::span<const triangulation::TriIdx> star, VertIdx v) {
    // The star as triangles (v, a, b) counter-clockwise: link edges a -> b, constrained spokes.
    std::vector<VertIdx> link;  // pairs a, b
    std::vector<VertIdx> constrained_spokes;
    const bool flags = !mesh.constrained.empty();
    for (const triangulation::TriIdx t : star) {
        const VertIdx* c = &mesh.triangles[3 * std::size_t{t}];
        const int k = c[0] == v ? 0 : c[1] == v ? 1 : 2;
        const VertIdx a = c[(k + 1) % 3], b = c[(k + 2) % 3];
        link.insert(link.end(), {a, b});
        // Spoke v -> a is side k, spoke b -> v side k + 2: each constrained spoke seen once or
        // twice (from both of its triangles); deduplicated below.
        if (flags && mesh.constrained[3 * std::size_t{t} + static_cast<std::size_t>(k)])
            constrained_spokes.push_back(a);
        if (flags && mesh.constrained[3 * std::size_t{t} + static_cast<std::size_t>((k + 2) % 3)])
            constrained_spokes.push_back(b);
    }
    std::sort(constrained_spokes.begin(), constrained_spokes.end());
    constrained_spokes.erase(std::unique(constrained_spokes.begin(), constrained_spokes.end()),
                             constrained_spokes.end());
    // The chain's ends (a boundary vertex): a start with no incoming link edge, an end with no
    // outgoing one. More than one of either: a pinched star, which the removal refuses anyway.
    std::vector<VertIdx> starts, ends;
    for (std::size_t i = 0; i < link.size(); i += 2) {
        bool incoming = false, outgoing = false;
        for (std::size_t j = 0; j < link.size(); j += 2) {
            incoming = incoming || link[j + 1] == link[i];
            outgoing = outgoing || link[j] == link[i + 1];
        }
        if (!incoming) starts.push_back(link[i]);
        if (!outgoing) ends.push_back(link[i + 1]);
    }
    std::vector<VertIdx> segments = link;
    if (starts.size() == 1 && ends.size() == 1) {
        segments.insert(segments.end(), {ends[0], starts[0]});  // the merged boundary edge
    } else if (!starts.empty() || !ends.empty()) {
        return true;  // pinched: refused by the removal
    } else if (constrained_spokes.size() == 2) {
        segments.insert(segments.end(), {constrained_spokes[0], constrained_spokes[1]});
    } else if (!constrained_spokes.empty()) {
        return true;  // a constraint end or junction: refused by the removal
    }
    // The hole's constrained Delaunay triangulation, its vertices in increasing global order so
    // that the SoS ranks (ties by index) are the removal's.
    std::vector<VertIdx> local;
    for (const VertIdx x : link) local.push_back(x);
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    std::vector<double> xy;
    xy.reserve(2 * local.size());
    for (const VertIdx x : local)
        xy.insert(xy.end(), {mesh.xy[2 * std::size_t{x}], mesh.xy[2 * std::size_t{x} + 1]});
    for (VertIdx& x : segments)
        x = static_cast<VertIdx>(std::lower_bound(local.begin(), local.end(), x) - local.begin());
    triangulation::Cdt2Result hole;
    try {
        hole = triangulation::constrained_delaunay_2d({xy, segments, {}, {}}, {});
    } catch (const InputError&) {
        return true;  // not a simple hole (the removal refuses what it cannot do)
    } catch (const GeometryError&) {
        return true;
    }
    const triangulation::Cdt2Counters& c = hole.counters;
    if (c.intersections > 0 || c.vertices_on_segments > 0 || c.duplicates > 0 ||
        hole.mesh.triangle_count() == 0)
        return true;  // the merged edge meets the link: refused by the removal (ChordBlocked)
    std::vector<VertIdx> old_triangles;
    for (const triangulation::TriIdx t : star)
        for (int k = 0; k < 3; ++k)
            old_triangles.push_back(
                mesh.triangles[3 * std::size_t{t} + static_cast<std::size_t>(k)]);
    const Corner before = smallest_of(mesh.xy, old_triangles);
    const Corner after = smallest_of(hole.mesh.xy, hole.mesh.triangles);
    return predicates::compare_angles(after, before) != Sign::Negative ||
           predicates::compare_angles(after, kFloorCorner) != Sign::Negative;
}

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
    // The angle guard: a removal whose retriangulated hole would have a smaller angle than both
    // its old star's smallest and the floor is refused here (the star of each chosen vertex is
    // untouched by the others' removals: they are independent).
    {
        std::vector<std::uint32_t> first(std::size_t{vertex_count} + 1, 0);
        for (const VertIdx x : mesh.triangles) ++first[std::size_t{x} + 1];
        for (std::size_t x = 0; x < vertex_count; ++x) first[x + 1] += first[x];
        std::vector<triangulation::TriIdx> at(mesh.triangles.size());
        {
            std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
            for (std::size_t i = 0; i < mesh.triangles.size(); ++i)
                at[fill[mesh.triangles[i]]++] = static_cast<triangulation::TriIdx>(i / 3);
        }
        std::vector<VertIdx> kept;
        for (const VertIdx v : chosen) {
            const std::span<const triangulation::TriIdx> star(at.data() + first[v],
                                                              first[v + 1] - first[v]);
            if (star.empty() || removal_keeps_angles_2d(mesh, star, v)) {
                kept.push_back(v);
            } else {
                ++counters.refused;
                ++counters.angle_refused;
            }
        }
        chosen.swap(kept);
    }
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
