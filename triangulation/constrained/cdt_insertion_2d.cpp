// SPDX-License-Identifier: MIT
// The constrained Delaunay builder's insertion phase (cdt_phases_2d.hpp): the initial
// triangulation of the points, vertex insertion (1-3 split, edge split) with Lawson flips that
// never cross a constraint, the builder's one 2-2 flip, and the enclosing box's corners. The
// splits and flips are the shared kernel's (flip_2d.hpp); the wrappers here add the builder's
// state: constraints per half-edge, vertex_edge, the domain side and the touched slots.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/mesh/flip_2d.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

bool triangulate_vertices(CdtState& cdt) {
    cdt.input_count = cdt.mesh.vertex_count();
    Cdt2Counters& c = cdt.result.counters;
    c.points = cdt.input_count;
    c.segments = cdt.pslg.segments.size() / 2;
    cdt.result.input_vertex_count = cdt.input_count;
    cdt.vertex_edge.assign(cdt.input_count, kNone);
    // The Delaunay triangulation first (no constraint yet: plain Green-Sibson, which keeps
    // no per-edge state), then the constraint and vertex maps in one pass.
    if (!detail::green_sibson_insert_all(cdt.core)) {
        cdt.collinear = true;
        return false;
    }
    cdt.segment_of.reserve(cdt.mesh.tv.capacity());
    cdt.segment_of.assign(cdt.mesh.tv.size(), kNone);
    for (TriIdx t = 0; t < cdt.mesh.triangle_slots(); ++t) {
        if (cdt.mesh.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = cdt.mesh.tv[3 * t + k];
            if (v != kInfinite) cdt.vertex_edge[v] = 3 * t + k;
        }
    }
    return true;
}

namespace {

void split_triangle(CdtState& cdt, TriIdx t, VertIdx p) {
    // The kernel keeps slot t for (p, a, b) and takes two new slots for (p, b, c), (p, c, a);
    // the constraints and domain side are the builder's, read before and written after.
    const std::uint32_t sides[3] = {cdt.segment_of[3 * t], cdt.segment_of[3 * t + 1],
                                    cdt.segment_of[3 * t + 2]};
    const CdtState::Side side = cdt.side_of(t);
    const SplitTriangles made = split_triangle_2d(cdt.mesh, t, p, MeshBoundary::Closed);
    cdt.grow_slots();
    for (unsigned i = 0; i < 3; ++i) {
        const TriIdx ti = made.triangles[i];
        if (i > 0) cdt.put_on_side(ti, side);
        cdt.rewritten(ti);
        cdt.segment_of[made.side(i)] = sides[i];
        cdt.segment_of[3 * ti] = cdt.segment_of[3 * ti + 2] = kNone;  // spokes
    }
    cdt.flip_stack.insert(cdt.flip_stack.end(),
                          {made.triangles[0], made.triangles[1], made.triangles[2]});
    cdt.core.last_triangle = made.triangles[0];
}

/// The kernel's 2-2 flip of e with the builder's state: the four sides keep their constraints,
/// the new diagonal has none (e had none: constraints never flip). The layout is a template
/// argument so that the Lawson loop's flip compiles to constant offsets.
template <unsigned k1, unsigned k2>
inline FlipEdges flip_edges(CdtState& cdt, EdgeIdx e) {
    const EdgeIdx f = cdt.mesh.twin[e];
    // x -> u, u -> y, y -> v, v -> x: the order of FlipEdges::sides.
    const std::uint32_t sides[4] = {cdt.segment_of[prev_edge(e)], cdt.segment_of[next_edge(f)],
                                    cdt.segment_of[prev_edge(f)], cdt.segment_of[next_edge(e)]};
    const TriIdx t1 = triangle_of(e), t2 = triangle_of(f);
    const FlipEdges flipped = flip_2d(cdt.mesh, e, k1, k2, MeshBoundary::Closed);
    cdt.rewritten(t1);
    cdt.rewritten(t2);
    for (unsigned i = 0; i < 4; ++i) cdt.segment_of[flipped.sides[i]] = sides[i];
    cdt.segment_of[flipped.diagonal] = cdt.segment_of[cdt.mesh.twin[flipped.diagonal]] = kNone;
    return flipped;
}

void flip_if_needed(CdtState& cdt, TriIdx t1, std::vector<Piece>* encroached) {
    const EdgeIdx e = 3 * t1 + 1;
    const EdgeIdx f = cdt.mesh.twin[e];
    const VertIdx q = cdt.apex(f);
    if (cdt.segment_of[e] != kNone) {
        // Conforming: a marked piece the new vertex makes not locally Delaunay is split later.
        if (encroached != nullptr && q != kInfinite && !cdt.mesh.is_infinite(t1) &&
            cdt.core.conflict(t1, q)) {
            encroached->push_back(
                {cdt.mesh.tv[3 * t1 + 1], cdt.mesh.tv[3 * t1 + 2], cdt.segment_of[e]});
        }
        return;
    }
    if (q == kInfinite || !cdt.core.conflict(t1, q)) return;
    ++cdt.result.counters.delaunay_flips;
    // t1 = (p, u, v) becomes (p, u, q) and the other (p, q, v): p stays at local index 0 in
    // both, so their sides opposite p (3t + 1) are the edges to test next.
    const FlipEdges flipped = flip_edges<2, 0>(cdt, e);
    cdt.flip_stack.push_back(triangle_of(flipped.sides[1]));
    cdt.flip_stack.push_back(triangle_of(flipped.sides[2]));
}

}  // namespace

void split_edge(CdtState& cdt, EdgeIdx e, VertIdx p) {
    const EdgeIdx f = cdt.mesh.twin[e];
    const TriIdx t = triangle_of(e), u = triangle_of(f);
    const std::uint32_t sides[4] = {cdt.segment_of[next_edge(e)], cdt.segment_of[prev_edge(e)],
                                    cdt.segment_of[next_edge(f)], cdt.segment_of[prev_edge(f)]};
    const std::uint32_t split = cdt.segment_of[e];  // both halves of a split segment keep it
    const std::vector<std::uint32_t> split_shared =
        split == kNone ? std::vector<std::uint32_t>{}
                       : cdt.release_shared(cdt.mesh.origin(e), cdt.mesh.destination(e));
    // Slot u takes a triangle on t's side: the sides are read first.
    const CdtState::Side side_t = cdt.side_of(t), side_u = cdt.side_of(u);
    // (p, b, c) in slot t, (p, c, a) in slot u, (p, a, d) and (p, d, b) in two new slots.
    const SplitTriangles made = split_edge_2d(cdt.mesh, e, p, MeshBoundary::Closed);
    cdt.grow_slots();
    cdt.put_on_side(made.triangles[1], side_t);
    cdt.put_on_side(made.triangles[2], side_u);
    cdt.put_on_side(made.triangles[3], side_u);
    for (unsigned i = 0; i < 4; ++i) {
        const TriIdx ti = made.triangles[i];
        cdt.rewritten(ti);
        cdt.segment_of[made.side(i)] = sides[i];
        // Spokes: p - b and p - a are the halves of the split edge, p - c and p - d new.
        const std::uint32_t spoke = i % 2 == 0 ? split : kNone;
        cdt.segment_of[3 * ti] = spoke;
        cdt.segment_of[3 * made.triangles[(i + 3) % 4] + 2] = spoke;
    }
    const EdgeIdx a_p = 3 * made.triangles[1] + 2, b_p = 3 * made.triangles[3] + 2;
    for (const std::uint32_t other : split_shared) {
        cdt.mark(a_p, other);
        cdt.mark(b_p, other);
    }
    cdt.flip_stack.insert(cdt.flip_stack.end(), {made.triangles[0], made.triangles[1],
                                                 made.triangles[2], made.triangles[3]});
    cdt.core.last_triangle = made.triangles[0];
}

void insert_vertex(CdtState& cdt, VertIdx p, TriIdx t, std::vector<Piece>* encroached) {
    cdt.flip_stack.clear();
    int on_edge = -1;
    if (!cdt.mesh.is_infinite(t)) {
        for (int k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + static_cast<unsigned>(k);
            if (cdt.core.orient(cdt.mesh.origin(e), cdt.mesh.destination(e), p) == Sign::Zero)
                on_edge = k;
        }
    }
    if (on_edge < 0) {
        split_triangle(cdt, t, p);
    } else {
        split_edge(cdt, 3 * t + static_cast<unsigned>(on_edge), p);
    }
    while (!cdt.flip_stack.empty()) {
        const TriIdx t1 = cdt.flip_stack.back();
        cdt.flip_stack.pop_back();
        flip_if_needed(cdt, t1, encroached);
    }
}

EdgeIdx flip(CdtState& cdt, EdgeIdx e) {
    // Quadrilateral u, y, v, x counter-clockwise: (x, u, y) and (y, v, x), diagonal 3t1 + 2.
    return flip_edges<2, 2>(cdt, e).diagonal;
}

bool locally_delaunay(CdtState& cdt, EdgeIdx e) {
    const EdgeIdx f = cdt.mesh.twin[e];
    const TriIdx t = triangle_of(e);
    if (cdt.mesh.is_infinite(t) || cdt.mesh.is_infinite(triangle_of(f)))
        return true;  // hull: fixed
    return !cdt.core.conflict(t, cdt.apex(f));
}

void restore_delaunay(CdtState& cdt, std::vector<std::pair<VertIdx, VertIdx>>& edges) {
    while (!edges.empty()) {
        const auto [u, v] = edges.back();
        edges.pop_back();
        const EdgeIdx e = cdt.find_edge(u, v);
        if (e == kNone || cdt.segment_of[e] != kNone || locally_delaunay(cdt, e)) continue;
        ++cdt.result.counters.delaunay_flips;
        const VertIdx x = cdt.apex(e), y = cdt.apex(cdt.mesh.twin[e]);
        flip(cdt, e);
        edges.insert(edges.end(), {{x, u}, {u, y}, {y, v}, {v, x}});
    }
}

void enclose_in_box(CdtState& cdt) {
    // Corners one bounding-box size beyond the bounding box of every vertex: each of the
    // triangulation's hull edges, segments included, becomes interior (Lawson insertion with
    // the infinite vertex, as Green-Sibson inserts outside the hull; constraints never flip).
    const std::uint32_t n = cdt.mesh.vertex_count();
    double lo_x = cdt.mesh.xy[0], hi_x = lo_x, lo_y = cdt.mesh.xy[1], hi_y = lo_y;
    for (VertIdx v = 1; v < n; ++v) {
        lo_x = std::min(lo_x, cdt.mesh.xy[2 * v]);
        hi_x = std::max(hi_x, cdt.mesh.xy[2 * v]);
        lo_y = std::min(lo_y, cdt.mesh.xy[2 * v + 1]);
        hi_y = std::max(hi_y, cdt.mesh.xy[2 * v + 1]);
    }
    const double margin = std::max(hi_x - lo_x, hi_y - lo_y);
    const double corners[4][2] = {{lo_x - margin, lo_y - margin},
                                  {hi_x + margin, lo_y - margin},
                                  {hi_x + margin, hi_y + margin},
                                  {lo_x - margin, hi_y + margin}};
    for (const auto& corner : corners) {
        if (!std::isfinite(margin) || !std::isfinite(corner[0]) || !std::isfinite(corner[1])) {
            throw GeometryError(
                "coordinates too large to enclose the domain in a box (within a factor 3 of the "
                "largest double)");
        }
    }
    cdt.box_first = n;
    for (const auto& corner : corners) {
        const VertIdx p = cdt.add_vertex(corner[0], corner[1]);
        const TriIdx t = cdt.core.walk_to(p);
        EM_ASSERT(cdt.mesh.is_infinite(t));
        insert_vertex(cdt, p, t);
    }
}

}  // namespace exactmesh::triangulation::detail
