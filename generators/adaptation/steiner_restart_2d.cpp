// SPDX-License-Identifier: MIT
// Steiner restart in 2D: size field, derefinement, resumed Delaunay refinement (see
// steiner_restart_2d.hpp).
#include "generators/adaptation/steiner_restart_2d.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "base/errors.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/field_transfer.hpp"
#include "generators/adaptation/indicator_size_field.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

namespace {

double edge_length(std::span<const double> xy, VertIdx a, VertIdx b) {
    return predicates::scale_free_norm(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]);
}

// The step 1 sizes at the vertices of `state` (+infinity at a vertex of no edge).
std::vector<double> vertex_sizes(const AdaptiveMesh2& state, const AdaptationOptions& options,
                                 std::span<const VertIdx> edges) {
    const triangulation::Triangulation2& mesh = state.mesh;
    const std::vector<double> indicator =
        mesh_edge_indicator(options.indicator, mesh.xy, 2, mesh.triangles, edges, state.values);
    return indicator_vertex_sizes(mesh.xy, 2, edges, indicator, options.indicator,
                                  options.threshold, kSteinerMaxFactor, options.reference_mean);
}

// About how many vertices a refinement of the triangles to `sizes` (linear over them) makes:
// each triangle's area over the equilateral triangle's of the largest size at its corners,
// one vertex per such triangle (refinement makes about twice the ideal triangles, half as many
// vertices as triangles). In the unit scale (mesh_edges.hpp), so the same for the mesh scaled.
double estimated_vertices(std::span<const double> xy, std::span<const VertIdx> triangles,
                          std::span<const double> sizes) {
    const int exponent = unit_scale_exponent(xy, 2, triangles);
    constexpr double kEquilateral = 0.43301270189221932;  // sqrt(3) / 4
    double total = 0;
    for (std::size_t t = 0; t < triangles.size() / 3; ++t) {
        const VertIdx a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
        const double s = std::max({sizes[a], sizes[b], sizes[c]});
        if (!std::isfinite(s)) continue;
        const double bx = std::ldexp(xy[2 * b] - xy[2 * a], -exponent);
        const double by = std::ldexp(xy[2 * b + 1] - xy[2 * a + 1], -exponent);
        const double cx = std::ldexp(xy[2 * c] - xy[2 * a], -exponent);
        const double cy = std::ldexp(xy[2 * c + 1] - xy[2 * a + 1], -exponent);
        const double unit_s = std::ldexp(s, -exponent);
        total += 0.5 * std::fabs(bx * cy - by * cx) / (kEquilateral * unit_s * unit_s);
    }
    return total;
}

// One derefinement pass (step 2): the vertices every edge of which is shorter than the fraction
// of the mean of the sizes at its ends, as a maximal independent set, removed; `sizes` (per vertex)
// follows the new numbering. Returns the number removed.
std::uint64_t derefine_finer_than_size(AdaptiveMesh2& state, std::span<const VertIdx> edges,
                                       std::vector<double>& sizes,
                                       SteinerRestartCounters2& counters) {
    const std::uint32_t vertex_count = state.mesh.vertex_count();
    std::vector<std::uint8_t> fine(vertex_count, 0), seen(vertex_count, 0);
    for (std::size_t e = 0; e < edges.size() / 2; ++e) {
        const VertIdx a = edges[2 * e], b = edges[2 * e + 1];
        const bool short_edge = edge_length(state.mesh.xy, a, b) <
                                kSteinerDerefineFraction * (0.5 * sizes[a] + 0.5 * sizes[b]);
        for (const VertIdx v : {a, b}) {
            if (!seen[v]) fine[v] = 1;
            seen[v] = 1;
            if (!short_edge) fine[v] = 0;
        }
    }
    // A maximal independent set of them, greedily in increasing vertex order (a vertex is
    // taken unless a neighbour was): remove_vertex_set_2d's own one-pass rule then drops
    // none, and a uniformly too fine region loses about a third of its vertices per pass
    // instead of only the local minima of the numbering.
    std::vector<std::uint32_t> first(vertex_count + 1, 0);
    for (const VertIdx v : edges) ++first[v + 1];
    for (std::uint32_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
    std::vector<VertIdx> adjacent(edges.size());
    {
        std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
        for (std::size_t e = 0; e < edges.size() / 2; ++e) {
            adjacent[next[edges[2 * e]]++] = edges[2 * e + 1];
            adjacent[next[edges[2 * e + 1]]++] = edges[2 * e];
        }
    }
    std::vector<VertIdx> candidates;
    std::vector<std::uint8_t> taken(vertex_count, 0);
    for (std::size_t v = state.fixed_vertices; v < vertex_count; ++v) {
        const bool curve_point = v < state.on_curve.size() && state.on_curve[v] != 0;
        if (!fine[v] || curve_point) continue;
        ++counters.finer_than_size;
        bool free = true;
        for (std::uint32_t k = first[v]; k < first[v + 1] && free; ++k)
            free = taken[adjacent[k]] == 0;
        if (!free) continue;
        taken[v] = 1;
        candidates.push_back(static_cast<VertIdx>(v));
    }
    if (candidates.empty()) return 0;
    DerefinementCounters2 removal;
    std::vector<VertIdx> old_to_new;
    const std::uint64_t removed =
        remove_vertex_set_2d(state, candidates, edges, removal, &old_to_new);
    counters.candidates += removal.candidates;
    counters.removed += removal.removed;
    counters.refused += removal.refused;
    counters.piece_merges += removal.piece_merges;
    std::vector<double> kept_sizes(state.mesh.vertex_count());
    for (std::size_t v = 0; v < old_to_new.size(); ++v)
        if (old_to_new[v] != kNone) kept_sizes[old_to_new[v]] = sizes[v];
    sizes = std::move(kept_sizes);
    return removed;
}

}  // namespace

SizeFunction steiner_restart_size_2d(const AdaptiveMesh2& state, const AdaptationOptions& options) {
    const std::vector<VertIdx> edges = mesh_edges_2d(state.mesh.triangles);
    return indicator_size_function_2d(state.mesh.xy, state.mesh.triangles,
                                      vertex_sizes(state, options, edges));
}

bool steiner_restart_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                              const FieldSource& field, SteinerRestartCounters2& counters) {
    ++counters.cycles;
    // 1. The sizes at the vertices and the background size over the current mesh, kept (with
    // the values) for the field's transfer.
    const std::vector<double> old_xy = state.mesh.xy;
    const std::vector<VertIdx> old_triangles = state.mesh.triangles;
    const std::vector<double> old_values = state.values;
    const std::vector<VertIdx> edges = mesh_edges_2d(old_triangles);
    const std::vector<double> sizes = vertex_sizes(state, options, edges);
    const SizeFunction size = indicator_size_function_2d(old_xy, old_triangles, sizes);

    // 2. Derefinement where every edge at a vertex is shorter than the fraction of the size at
    // its midpoint: passes until none is, at most kSteinerDerefinePasses.
    std::uint64_t removed = 0;
    {
        std::vector<double> kept_sizes = sizes;
        for (std::uint32_t pass = 0; pass < kSteinerDerefinePasses; ++pass) {
            const std::vector<VertIdx> pass_edges =
                pass == 0 ? edges : mesh_edges_2d(state.mesh.triangles);
            const std::uint64_t n =
                derefine_finer_than_size(state, pass_edges, kept_sizes, counters);
            removed += n;
            if (n == 0) break;
        }
    }

    // 3. Delaunay refinement resumed from the derefined mesh, under the budget.
    const std::uint32_t kept = state.mesh.vertex_count();
    std::vector<VertIdx> segments;
    std::vector<SegmentCurve> segment_curves;
    segments.reserve(2 * state.pieces.size());
    segment_curves.reserve(state.pieces.size());
    for (const CurvedPiece2& p : state.pieces) {
        segments.insert(segments.end(), {p.a, p.b});
        segment_curves.push_back({p.curve, p.ua, p.ub});
    }
    const bool budget = options.max_vertices > 0;
    double factor = 1;
    if (budget) {
        const double estimate = estimated_vertices(old_xy, old_triangles, sizes);
        const auto limit = static_cast<double>(options.max_vertices);
        if (estimate > limit) {
            factor = std::sqrt(estimate / limit);
            ++counters.budget_scalings;
        }
    }
    std::optional<RefinementResult2> refined;
    if (!budget || kept < options.max_vertices) {
        const triangulation::Pslg pslg{state.mesh.xy, segments, state.holes, {}};
        // A scaled size is capped at the mesh's extent, as global remeshing's is.
        const double ceiling = size_ceiling_2d(state.mesh.xy);
        for (std::uint32_t run = 0; run < kSteinerBudgetRuns; ++run) {
            // A factor that overflowed (an estimate of infinity: a mesh spanning 1e-309 to
            // 3e231, whose areas overflow even in its unit scale) cannot bring the size under
            // the budget: a budget stop, not a size refused by its scaling.
            if (!std::isfinite(factor)) break;
            RefinementOptions2 refinement;
            refinement.min_angle = kGuaranteedMinAngle;
            refinement.size = factor == 1 ? size : size.scaled(factor, ceiling);
            // Under a vertex budget, refinement's own Steiner budget is a few times the room
            // left, and a run that reaches it (or whose size asks for more at once) is redone
            // coarser: the estimate above takes the size at the old mesh's vertices, and a size
            // interpolated across long spared triangles (a narrow wedge's) can ask for far more
            // (a fuzzed case asked refinement for 1.9e14 triangles and ran to 24 GB).
            if (budget)
                refinement.max_steiner_points =
                    kSteinerRunBudgetFactor * std::uint64_t{options.max_vertices - kept};
            std::optional<RefinementResult2> attempt;
            try {
                attempt = delaunay_refinement_2d(pslg, refinement);
            } catch (const RefinementBudgetError&) {
                if (!budget) throw;
            }
            ++counters.refinement_runs;
            if (!attempt) {
                factor *= 2;
                ++counters.budget_retries;
                continue;
            }
            RefinementResult2 result = std::move(*attempt);
            const std::uint32_t count = result.mesh.mesh.vertex_count();
            if (!budget || count <= options.max_vertices) {
                refined = std::move(result);
                break;
            }
            const double added = static_cast<double>(count - kept);
            const double room = static_cast<double>(options.max_vertices - kept);
            factor *= 1.05 * std::sqrt(added / room);
            ++counters.budget_retries;
        }
    }
    if (budget && !refined) ++counters.budget_stops;

    const auto sample_or_keep = [&](AdaptiveMesh2& next) {
        if (field.analytic != nullptr)
            next.values = sample_field(*field.analytic, next.mesh.xy, 2, field.t);
    };
    if (!refined || refined->mesh.mesh.vertex_count() == kept) {
        // Nothing added: the derefined mesh (its triangles in their order) is the result.
        sample_or_keep(state);
        return removed > 0;
    }

    triangulation::Cdt2Result& result = refined->mesh;
    // The restart's promise: every current vertex at its index, none merged or split off.
    const triangulation::Cdt2Counters& c = result.counters;
    // A vertex of no triangle (an input's repeated point, merged as the first mesh merged it, or
    // one outside the domain) stays unused; every used one must stay itself.
    bool same = result.input_vertex_count == kept && c.intersections == 0 &&
                c.vertices_on_segments == 0 && c.dropped_segments == 0;
    for (std::size_t i = 0; same && i < 2 * std::size_t{kept}; ++i)
        same = result.mesh.xy[i] == state.mesh.xy[i];
    if (same && c.duplicates > 0) {
        for (const VertIdx v : state.mesh.triangles)
            same = same && v < result.merged_into.size() && result.merged_into[v] == v;
    }
    if (!same)
        throw GeometryError(
            "steiner restart: the refinement of the current mesh did not keep its vertices at "
            "their indices (a bug)");
    counters.steiner_points += refined->counters.steiner_points();
    counters.segment_splits += refined->counters.segment_splits;

    const std::vector<double> segment_xy = state.mesh.xy;
    AdaptiveMesh2 next = make_adaptive_mesh_2d(std::move(result), segment_xy, segments, state.holes,
                                               state.curves, segment_curves);
    next.fixed_vertices = state.fixed_vertices;
    next.on_curve = std::move(state.on_curve);
    next.on_curve.resize(next.mesh.vertex_count(), 0);

    // 4. The field.
    if (field.analytic != nullptr) {
        sample_or_keep(next);
    } else {
        std::vector<double> values =
            transfer_field_2d(old_xy, old_triangles, old_values,
                              std::span(next.mesh.xy).subspan(2 * std::size_t{kept}));
        values.insert(values.begin(), state.values.begin(), state.values.end());
        // A point outside the old mesh: the mean of its neighbours' known values, repeated
        // outwards (each pass fills at least the points next to known ones).
        const std::vector<VertIdx> new_edges = mesh_edges_2d(next.mesh.triangles);
        for (bool progress = true; progress;) {
            progress = false;
            std::vector<double> sum(values.size(), 0);
            std::vector<std::uint32_t> count(values.size(), 0);
            for (std::size_t e = 0; e < new_edges.size() / 2; ++e) {
                const VertIdx a = new_edges[2 * e], b = new_edges[2 * e + 1];
                for (const auto& [v, w] : {std::pair{a, b}, std::pair{b, a}}) {
                    if (std::isnan(values[v]) && !std::isnan(values[w])) {
                        sum[v] += values[w];
                        ++count[v];
                    }
                }
            }
            for (std::size_t v = 0; v < values.size(); ++v) {
                if (!std::isnan(values[v])) continue;
                if (count[v] == 0) continue;
                values[v] = sum[v] / static_cast<double>(count[v]);
                ++counters.transfer_fallbacks;
                progress = true;
            }
        }
        next.values = std::move(values);
    }
    state = std::move(next);
    return true;
}

}  // namespace exactmesh::generators
