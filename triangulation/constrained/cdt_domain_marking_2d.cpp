// SPDX-License-Identifier: MIT
// The constrained Delaunay builder's domain marking (cdt_phases_2d.hpp): point location, and
// floods that never cross a constraint marking the exterior, the holes and the regions.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

TriIdx locate_point(CdtState& cdt, double x, double y) {
    const VertIdx probe = cdt.add_vertex(x, y);
    const TriIdx t = cdt.core.walk_to(probe);
    cdt.remove_last_vertex();
    return t;
}

namespace {

/// Marks `value` on every triangle reached from start without crossing a constraint (or
/// into the infinite vertex); calls reached(t) for each one marked.
template <class Mark, class Reached>
void flood(CdtState& cdt, TriIdx start, std::vector<Mark>& mark_value, Mark value,
           Reached reached) {
    std::vector<TriIdx> stack{start};
    mark_value[start] = value;
    reached(start);
    while (!stack.empty()) {
        const TriIdx t = stack.back();
        stack.pop_back();
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            if (cdt.segment_of[e] != kNone) continue;
            const TriIdx u = triangle_of(cdt.mesh.twin[e]);
            if (mark_value[u] == value || cdt.mesh.is_infinite(u)) continue;
            mark_value[u] = value;
            reached(u);
            stack.push_back(u);
        }
    }
}

/// Throws AmbiguousMarkPoint when hole or region `index` at (x, y), located in triangle t,
/// lies on a segment or a vertex (which side it marks would be the walk's choice).
void require_off_boundary(CdtState& cdt, AmbiguousMarkPoint::Kind kind, std::size_t index, double x,
                          double y, TriIdx t) {
    // The walk put the point in t, or across a hull edge of it (an infinite t): a point on a
    // segment or a vertex lies on the closure of one of t's finite edges, so three exact
    // orientations (plus the bounding box, for the hull edge's line beyond it) find it.
    const double point[2] = {x, y};
    const std::string name =
        std::string(kind == AmbiguousMarkPoint::Kind::Hole ? "hole " : "region ") +
        std::to_string(index + cdt.options.first_index) + " at (" + format_number(x) + ", " +
        format_number(y) + ")";
    const char* consequence =
        kind == AmbiguousMarkPoint::Kind::Hole
            ? "which side is the hole is ambiguous; move the point strictly inside the hole"
            : "which side is the region is ambiguous; move the point strictly inside it";
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e);
        for (const VertIdx v : {a, b}) {
            if (v == kInfinite || cdt.mesh.xy[2 * v] != x || cdt.mesh.xy[2 * v + 1] != y) continue;
            // A vertex no segment ends at (a free vertex) has one side only: every triangle
            // around it floods to the others without crossing a constraint.
            bool on_segment_end = false;
            const EdgeIdx first = cdt.vertex_edge[v];
            EdgeIdx around = first;
            do {
                on_segment_end = on_segment_end || cdt.segment_of[around] != kNone;
                around = cdt.mesh.twin[prev_edge(around)];
            } while (around != first);
            if (!on_segment_end) continue;
            const VertIdx caller = cdt.core.input_index[v];
            const std::string vertex =
                caller < cdt.input_count
                    ? "vertex " + std::to_string(caller + cdt.options.first_index)
                    : std::string("a vertex added where segments cross");
            throw AmbiguousMarkPoint(name + " lies on " + vertex + ": " + consequence, kind, index);
        }
        if (a == kInfinite || b == kInfinite || cdt.segment_of[e] == kNone) continue;
        const double* pa = cdt.mesh.point(a);
        const double* pb = cdt.mesh.point(b);
        if (x < std::min(pa[0], pb[0]) || x > std::max(pa[0], pb[0]) ||
            y < std::min(pa[1], pb[1]) || y > std::max(pa[1], pb[1])) {
            continue;
        }
        if (predicates::orient2d(pa, pb, point) == Sign::Zero) {
            throw AmbiguousMarkPoint(
                name + " lies on segment " +
                    std::to_string(cdt.segment_of[e] + cdt.options.first_index) + ": " +
                    consequence,
                kind, index);
        }
    }
    // On an input segment itself, off its pieces: a segment split where another crosses it
    // bends by the crossing's rounding, and a point on the segment between the pieces and the
    // line (a hole point at two crossing segments' midpoints, 1e-17 from the rounded crossing)
    // marked a sliver there, which generators that split the pieces again located elsewhere:
    // some meshed the whole box, others removed a wedge. Such a point lies in a triangle
    // with a corner on one of the segment's pieces: the segments of the constrained edges of
    // the triangles around t's corners are tested as given (exact orient2d and bounding box).
    const auto on_input_segment = [&](std::uint32_t s) {
        const double* pa = &cdt.pslg.xy[2 * std::size_t{cdt.pslg.segments[2 * std::size_t{s}]}];
        const double* pb = &cdt.pslg.xy[2 * std::size_t{cdt.pslg.segments[2 * std::size_t{s} + 1]}];
        return x >= std::min(pa[0], pb[0]) && x <= std::max(pa[0], pb[0]) &&
               y >= std::min(pa[1], pb[1]) && y <= std::max(pa[1], pb[1]) &&
               predicates::orient2d(pa, pb, point) == Sign::Zero;
    };
    for (unsigned c = 0; c < 3; ++c) {
        const VertIdx v = cdt.mesh.tv[3 * t + c];
        if (v == kInfinite) continue;
        const EdgeIdx first = cdt.vertex_edge[v];
        EdgeIdx around = first;
        do {
            for (unsigned k = 0; k < 3; ++k) {
                const std::uint32_t s = cdt.segment_of[3 * triangle_of(around) + k];
                if (s != kNone && s < cdt.pslg.segments.size() / 2 && on_input_segment(s)) {
                    throw AmbiguousMarkPoint(name + " lies on segment " +
                                                 std::to_string(s + cdt.options.first_index) +
                                                 ": " + consequence,
                                             kind, index);
                }
            }
            around = cdt.mesh.twin[prev_edge(around)];
        } while (around != first);
    }
}

void remove_exterior_and_holes(CdtState& cdt) {
    cdt.removed.assign(cdt.mesh.triangle_slots(), 0);
    const bool any_segment = std::any_of(cdt.segment_of.begin(), cdt.segment_of.end(),
                                         [](std::uint32_t s) { return s != kNone; });
    // Without a segment the exterior is nothing (the convex hull is kept, as Triangle keeps it),
    // except around an enclosing box, whose triangles are never the domain.
    if (cdt.options.remove_exterior && (any_segment || cdt.box_first != kNone)) {
        for (TriIdx t = 0; t < cdt.mesh.triangle_slots(); ++t) {
            if (cdt.mesh.is_dead(t) || !cdt.mesh.is_infinite(t)) continue;
            for (unsigned k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * t + k;
                if (cdt.mesh.origin(e) == kInfinite || cdt.mesh.destination(e) == kInfinite)
                    continue;
                const TriIdx inside = triangle_of(cdt.mesh.twin[e]);
                if (cdt.segment_of[e] == kNone && !cdt.removed[inside])
                    flood(cdt, inside, cdt.removed, std::uint8_t{1}, [](TriIdx) {});
            }
        }
    }
    const std::size_t holes = cdt.pslg.holes.size() / 2;
    for (std::size_t h = 0; h < holes; ++h) {
        const TriIdx t = locate_point(cdt, cdt.pslg.holes[2 * h], cdt.pslg.holes[2 * h + 1]);
        require_off_boundary(cdt, AmbiguousMarkPoint::Kind::Hole, h, cdt.pslg.holes[2 * h],
                             cdt.pslg.holes[2 * h + 1], t);
        if (cdt.mesh.is_infinite(t)) {
            cdt.result.warnings.push_back("hole " + std::to_string(h + cdt.options.first_index) +
                                          " lies outside the triangulation; ignored");
            continue;
        }
        if (!cdt.removed[t]) flood(cdt, t, cdt.removed, std::uint8_t{1}, [](TriIdx) {});
    }
}

void assign_regions(CdtState& cdt) {
    const std::size_t regions = cdt.pslg.regions.size() / 4;
    if (regions == 0) return;
    cdt.attribute.assign(cdt.mesh.triangle_slots(), 0.0);
    // One stamp per region (region number + 1): each flood costs its own triangles only.
    std::vector<std::uint32_t> seen(cdt.mesh.triangle_slots(), 0);
    for (std::size_t r = 0; r < regions; ++r) {
        const TriIdx t = locate_point(cdt, cdt.pslg.regions[4 * r], cdt.pslg.regions[4 * r + 1]);
        require_off_boundary(cdt, AmbiguousMarkPoint::Kind::Region, r, cdt.pslg.regions[4 * r],
                             cdt.pslg.regions[4 * r + 1], t);
        if (cdt.mesh.is_infinite(t) || cdt.removed[t]) {
            cdt.result.warnings.push_back("region " + std::to_string(r + cdt.options.first_index) +
                                          " lies outside the domain; ignored");
            continue;
        }
        const double attribute = cdt.pslg.regions[4 * r + 2];
        flood(cdt, t, seen, static_cast<std::uint32_t>(r + 1),
              [&](TriIdx u) { cdt.attribute[u] = attribute; });
    }
}

}  // namespace

void mark_domain(CdtState& cdt) {
    remove_exterior_and_holes(cdt);
    assign_regions(cdt);
}

}  // namespace exactmesh::triangulation::detail
