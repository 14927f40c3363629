// SPDX-License-Identifier: MIT
// Delaunay point-insertion adaptation in 2D (see insertion_adaptation_2d.hpp).
#include "generators/adaptation/insertion_adaptation_2d.hpp"

#include <algorithm>
#include <cmath>

#include "generators/adaptation/field_transfer.hpp"
#include "generators/adaptation/weighted_movement.hpp"
#include "generators/mesh_2d/laplacian_smoothing_2d.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

namespace {

struct NewPoint {
    double x, y;
    VertIdx a, b;  // the flagged edge it halves
};

}  // namespace

namespace detail {

CycleFlags cycle_flags(const AdaptationOptions& options, std::span<const double> coordinates,
                       unsigned dim, std::span<const VertIdx> elements,
                       std::span<const double> values) {
    CycleFlags r;
    const std::uint64_t vertices = coordinates.size() / dim;
    const bool budget = options.max_vertices > 0;
    if (budget && vertices >= options.max_vertices) return r;
    const std::uint64_t room = budget ? options.max_vertices - vertices : 0;
    r.edges = dim == 2 ? mesh_edges_2d(elements) : mesh_edges_3d(elements);
    const std::vector<double> indicator =
        mesh_edge_indicator(options.indicator, coordinates, dim, elements, r.edges, values);
    r.flags = refinement_flags(elements, dim, r.edges, indicator, options.threshold, room, budget,
                               &r.flagged, &r.closure, options.reference_mean);
    return r;
}

}  // namespace detail

bool insertion_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                        const FieldSource& field, InsertionCounters2& counters) {
    const triangulation::Triangulation2& mesh = state.mesh;

    // 1-2. Indicator, flags, closure.
    const detail::CycleFlags marked =
        detail::cycle_flags(options, mesh.xy, 2, mesh.triangles, state.values);
    if (marked.flagged == 0) return false;
    const std::vector<VertIdx>& edges = marked.edges;
    const std::vector<std::uint8_t>& flags = marked.flags;

    // 3. The points: pieces split at their curve's (or chord's) midpoint, interior edges at
    // their rounded midpoint. An edge so short that its midpoint rounds to an end is left.
    std::vector<std::uint32_t> piece_of_edge(edges.size() / 2, kNone);
    for (std::size_t p = 0; p < state.pieces.size(); ++p) {
        const std::uint32_t e = find_mesh_edge(edges, state.pieces[p].a, state.pieces[p].b);
        if (e != kNone) piece_of_edge[e] = static_cast<std::uint32_t>(p);
    }
    const auto same = [&](double x, double y, VertIdx v) {
        return x == mesh.xy[2 * v] && y == mesh.xy[2 * v + 1];
    };
    std::vector<NewPoint> interior;
    for (std::size_t e = 0; e < flags.size(); ++e) {
        if (!flags[e] || piece_of_edge[e] != kNone) continue;
        const VertIdx a = edges[2 * e], b = edges[2 * e + 1];
        const double x = 0.5 * mesh.xy[2 * a] + 0.5 * mesh.xy[2 * b];
        const double y = 0.5 * mesh.xy[2 * a + 1] + 0.5 * mesh.xy[2 * b + 1];
        if (same(x, y, a) || same(x, y, b)) continue;
        interior.push_back({x, y, a, b});
    }
    // Inserted along a Hilbert curve, so that each location walks from the last one's
    // neighbourhood (in edge order the walks crossed the mesh: a sixth of the cycle).
    {
        std::vector<double> points;
        points.reserve(2 * interior.size());
        for (const NewPoint& p : interior) points.insert(points.end(), {p.x, p.y});
        std::vector<std::uint32_t> order(interior.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
        triangulation::hilbert_sort_2d(points, order);
        std::vector<NewPoint> sorted;
        sorted.reserve(interior.size());
        for (const std::uint32_t i : order) sorted.push_back(interior[i]);
        interior = std::move(sorted);
    }

    const std::vector<double> old_xy = mesh.xy;
    const std::vector<VertIdx> old_triangles = mesh.triangles;
    const std::vector<double> old_values = state.values;
    AdaptiveMesh2 next;
    std::vector<double> first_values;  // the field before smoothing, per vertex of `next`
    for (bool use_curves = !state.curves.empty();; use_curves = false) {
        std::vector<double> xy = old_xy;
        std::vector<double> values = old_values;
        std::vector<VertIdx> segments;
        std::vector<SegmentCurve> segment_curves;
        std::vector<std::uint8_t> on_curve = state.on_curve;
        std::uint64_t boundary_points = 0, curve_points = 0;
        for (const CurvedPiece2& piece : state.pieces) {
            const std::uint32_t e = find_mesh_edge(edges, piece.a, piece.b);
            const bool split = e != kNone && flags[e] != 0;
            double x = 0, y = 0, um = 0;
            bool curved = false;
            if (split) {
                x = 0.5 * old_xy[2 * piece.a] + 0.5 * old_xy[2 * piece.b];
                y = 0.5 * old_xy[2 * piece.a + 1] + 0.5 * old_xy[2 * piece.b + 1];
                if (use_curves && piece.curve != kStraightSide) {
                    um = 0.5 * piece.ua + 0.5 * piece.ub;
                    const std::array<double, 2> c = state.curves[piece.curve](um);
                    if (std::isfinite(c[0]) && std::isfinite(c[1])) {
                        x = c[0];
                        y = c[1];
                        curved = true;
                    }
                }
            }
            if (!split || same(x, y, piece.a) || same(x, y, piece.b)) {
                segments.insert(segments.end(), {piece.a, piece.b});
                segment_curves.push_back({piece.curve, piece.ua, piece.ub});
                continue;
            }
            const auto m = static_cast<VertIdx>(xy.size() / 2);
            xy.insert(xy.end(), {x, y});
            values.push_back(0.5 * old_values[piece.a] + 0.5 * old_values[piece.b]);
            on_curve.push_back(curved ? 1 : 0);
            segments.insert(segments.end(), {piece.a, m, m, piece.b});
            segment_curves.push_back({piece.curve, piece.ua, curved ? um : piece.ua});
            segment_curves.push_back({piece.curve, curved ? um : piece.ub, piece.ub});
            if (!curved && piece.curve != kStraightSide) {
                // A chord point on a curved piece: its parameter by its place on the chord.
                const double mid = 0.5 * piece.ua + 0.5 * piece.ub;
                segment_curves[segment_curves.size() - 2].u1 = mid;
                segment_curves.back().u0 = mid;
            }
            ++boundary_points;
            curve_points += curved ? 1 : 0;
        }
        const triangulation::Pslg pslg{xy, segments, state.holes, {}};
        triangulation::ConstrainedTriangulation2 ct(pslg);
        triangulation::Cdt2Counters cdt_counters;
        {
            // Interior points by Bowyer-Watson in the constrained triangulation.
            std::vector<double> added_values;
            std::uint64_t inserted = 0, encroaching = 0, outside = 0;
            for (const NewPoint& p : interior) {
                const triangulation::TriIdx t = ct.locate(p.x, p.y);
                if (t == kNone || !ct.in_domain(t)) {
                    ++outside;
                    continue;
                }
                switch (ct.insert_in_cavity(t, p.x, p.y)) {
                    case triangulation::CavityInsertion::Inserted:
                        ++inserted;
                        added_values.push_back(0.5 * old_values[p.a] + 0.5 * old_values[p.b]);
                        break;
                    case triangulation::CavityInsertion::Encroaches:
                        ++encroaching;
                        break;
                    default:
                        ++outside;
                        break;
                }
            }
            triangulation::Cdt2Result result = std::move(ct).take_result();
            cdt_counters = result.counters;
            // A vertex of no triangle (an input's repeated point, merged as the first mesh
            // merged it) is merged again; every vertex the old triangles use and every new
            // boundary point must stay itself.
            bool clean = result.counters.intersections == 0 &&
                         result.counters.vertices_on_segments == 0 &&
                         result.counters.dropped_segments == 0;
            if (clean && result.counters.duplicates > 0) {
                const std::vector<VertIdx>& merged = result.merged_into;
                for (const VertIdx v : old_triangles)
                    clean = clean && (v >= merged.size() || merged[v] == v);
                for (std::size_t v = old_xy.size() / 2; clean && v < merged.size(); ++v)
                    clean = merged[v] == v;
            }
            if (!clean && use_curves && curve_points > 0) {
                ++counters.curve_retries;
                continue;
            }
            if (!clean)
                throw GeometryError(
                    "insertion adaptation: the boundary's pieces met after chord "
                    "midpoints were added (a bug)");
            next = make_adaptive_mesh_2d(std::move(result), xy, segments, state.holes, state.curves,
                                         segment_curves);
            next.fixed_vertices = state.fixed_vertices;
            next.on_curve = std::move(on_curve);
            next.on_curve.resize(next.mesh.vertex_count(), 0);
            first_values = std::move(values);
            first_values.insert(first_values.end(), added_values.begin(), added_values.end());
            counters.inserted += inserted;
            counters.encroaching_skipped += encroaching;
            counters.outside_skipped += outside;
        }
        counters.boundary_points += boundary_points;
        counters.curve_points += curve_points;
        break;
    }
    ++counters.cycles;
    counters.flagged_edges += marked.flagged;
    counters.closure_edges += marked.closure;

    // 5. Smoothing, boundary and input vertices fixed.
    const std::vector<double> before_smoothing = next.mesh.xy;
    if (options.smoothing_sweeps > 0) {
        SmoothingOptions2 smoothing;
        smoothing.iterations = options.smoothing_sweeps;
        const SmoothingCounters2 c =
            laplacian_smoothing_2d(next.mesh, next.fixed_vertices, smoothing);
        counters.smoothing_moves += c.moves;
        counters.smoothing_undone += c.undone;
    }

    // 6. The field on the new mesh (7: and again after the movement).
    const auto set_field = [&] {
        if (field.analytic != nullptr) {
            next.values = sample_field(*field.analytic, next.mesh.xy, 2, field.t);
            return;
        }
        next.values = transfer_field_2d(old_xy, old_triangles, old_values, next.mesh.xy);
        // A point outside the old mesh (beside a convex curve point) keeps the value it was
        // made with; so does every point that did not move.
        keep_values_of_unmoved(next.values, next.mesh.xy, before_smoothing, 2, first_values);
    };
    set_field();
    if (options.movement_sweeps > 0) {
        WeightedMovementOptions movement;
        movement.sweeps = options.movement_sweeps;
        movement.strength = options.movement_strength;
        const WeightedMovementCounters c =
            weighted_movement_2d(next.mesh,
                                 mesh_vertex_indicator(options.indicator, next.mesh.xy, 2,
                                                       next.mesh.triangles, next.values),
                                 next.fixed_vertices, movement);
        counters.movement_moves += c.moves;
        counters.movement_undone += c.undone + c.undone_worse;
        set_field();
    }
    state = std::move(next);
    return true;
}

}  // namespace exactmesh::generators
