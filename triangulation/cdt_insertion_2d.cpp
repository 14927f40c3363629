// SPDX-License-Identifier: MIT
// The constrained Delaunay builder's insertion phase (cdt_phases_2d.hpp): the initial
// triangulation of the points, vertex insertion (1-3 split, edge split) with Lawson flips that
// never cross a constraint, the builder's one 2-2 flip, and the enclosing box's corners.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/cdt_phases_2d.hpp"
#include "triangulation/cdt_state_2d.hpp"
#include "triangulation/green_sibson_2d.hpp"

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
    const VertIdx a = cdt.mesh.tv[3 * t], b = cdt.mesh.tv[3 * t + 1], c = cdt.mesh.tv[3 * t + 2];
    const EdgeIdx x = cdt.mesh.twin[3 * t], y = cdt.mesh.twin[3 * t + 1],
                  z = cdt.mesh.twin[3 * t + 2];
    const std::uint32_t sx = cdt.segment_of[3 * t], sy = cdt.segment_of[3 * t + 1],
                        sz = cdt.segment_of[3 * t + 2];
    const TriIdx t1 = t, t2 = cdt.new_triangle(), t3 = cdt.new_triangle();
    cdt.put_on_side(t2, cdt.side_of(t));
    cdt.put_on_side(t3, cdt.side_of(t));
    cdt.set(t1, p, a, b);
    cdt.set(t2, p, b, c);
    cdt.set(t3, p, c, a);
    cdt.link_outer(3 * t1 + 1, x, sx);
    cdt.link_outer(3 * t2 + 1, y, sy);
    cdt.link_outer(3 * t3 + 1, z, sz);
    cdt.link_inner(3 * t1 + 2, 3 * t2);
    cdt.link_inner(3 * t2 + 2, 3 * t3);
    cdt.link_inner(3 * t3 + 2, 3 * t1);
    cdt.flip_stack.insert(cdt.flip_stack.end(), {t1, t2, t3});
    cdt.core.last_triangle = t1;
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
    const TriIdx t2 = triangle_of(f);
    const VertIdx p = cdt.mesh.tv[3 * t1], u = cdt.mesh.tv[3 * t1 + 1], v = cdt.mesh.tv[3 * t1 + 2];
    const EdgeIdx vp = cdt.mesh.twin[3 * t1 + 2];
    const std::uint32_t svp = cdt.segment_of[3 * t1 + 2];
    const EdgeIdx uq = cdt.mesh.twin[next_edge(f)], qv = cdt.mesh.twin[prev_edge(f)];
    const std::uint32_t suq = cdt.segment_of[next_edge(f)], sqv = cdt.segment_of[prev_edge(f)];
    cdt.set(t1, p, u, q);
    cdt.set(t2, p, q, v);
    cdt.link_outer(3 * t1 + 1, uq, suq);
    cdt.link_outer(3 * t2 + 1, qv, sqv);
    cdt.link_outer(3 * t2 + 2, vp, svp);
    cdt.link_inner(3 * t1 + 2, 3 * t2);
    cdt.flip_stack.push_back(t1);
    cdt.flip_stack.push_back(t2);
}

}  // namespace

void split_edge(CdtState& cdt, EdgeIdx e, VertIdx p) {
    const EdgeIdx f = cdt.mesh.twin[e];
    const TriIdx t = triangle_of(e), u = triangle_of(f);
    const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e);
    const VertIdx c = cdt.apex(e), d = cdt.apex(f);
    const EdgeIdx bc = cdt.mesh.twin[next_edge(e)], ca = cdt.mesh.twin[prev_edge(e)];
    const EdgeIdx ad = cdt.mesh.twin[next_edge(f)], db = cdt.mesh.twin[prev_edge(f)];
    const std::uint32_t sbc = cdt.segment_of[next_edge(e)], sca = cdt.segment_of[prev_edge(e)];
    const std::uint32_t sad = cdt.segment_of[next_edge(f)], sdb = cdt.segment_of[prev_edge(f)];
    const std::uint32_t split = cdt.segment_of[e];  // both halves of a split segment keep it
    const std::vector<std::uint32_t> split_shared =
        split == kNone ? std::vector<std::uint32_t>{} : cdt.release_shared(a, b);
    // Slot u takes a triangle on t's side: the sides are read first.
    const CdtState::Side side_t = cdt.side_of(t), side_u = cdt.side_of(u);
    const TriIdx t1 = t, t2 = u, t3 = cdt.new_triangle(), t4 = cdt.new_triangle();
    cdt.put_on_side(t2, side_t);
    cdt.put_on_side(t3, side_u);
    cdt.put_on_side(t4, side_u);
    cdt.set(t1, p, b, c);
    cdt.set(t2, p, c, a);
    cdt.set(t3, p, a, d);
    cdt.set(t4, p, d, b);
    cdt.link_outer(3 * t1 + 1, bc, sbc);
    cdt.link_outer(3 * t2 + 1, ca, sca);
    cdt.link_outer(3 * t3 + 1, ad, sad);
    cdt.link_outer(3 * t4 + 1, db, sdb);
    cdt.link_inner(3 * t1 + 2, 3 * t2);
    cdt.link_inner(3 * t2 + 2, 3 * t3, split);  // a - p
    cdt.link_inner(3 * t3 + 2, 3 * t4);
    cdt.link_inner(3 * t4 + 2, 3 * t1, split);  // b - p
    for (const std::uint32_t other : split_shared) {
        cdt.mark(3 * t2 + 2, other);
        cdt.mark(3 * t4 + 2, other);
    }
    cdt.flip_stack.insert(cdt.flip_stack.end(), {t1, t2, t3, t4});
    cdt.core.last_triangle = t1;
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
    const EdgeIdx f = cdt.mesh.twin[e];
    const TriIdx t1 = triangle_of(e), t2 = triangle_of(f);
    const VertIdx u = cdt.mesh.origin(e), v = cdt.mesh.destination(e), x = cdt.apex(e),
                  y = cdt.apex(f);
    const EdgeIdx vx = cdt.mesh.twin[next_edge(e)], xu = cdt.mesh.twin[prev_edge(e)];
    const EdgeIdx uy = cdt.mesh.twin[next_edge(f)], yv = cdt.mesh.twin[prev_edge(f)];
    const std::uint32_t svx = cdt.segment_of[next_edge(e)], sxu = cdt.segment_of[prev_edge(e)];
    const std::uint32_t suy = cdt.segment_of[next_edge(f)], syv = cdt.segment_of[prev_edge(f)];
    // Quadrilateral u, y, v, x counter-clockwise: (x, u, y) and (y, v, x).
    cdt.set(t1, x, u, y);
    cdt.set(t2, y, v, x);
    cdt.link_outer(3 * t1, xu, sxu);
    cdt.link_outer(3 * t1 + 1, uy, suy);
    cdt.link_outer(3 * t2, yv, syv);
    cdt.link_outer(3 * t2 + 1, vx, svx);
    cdt.link_inner(3 * t1 + 2, 3 * t2 + 2);
    return 3 * t1 + 2;
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
