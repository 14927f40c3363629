// SPDX-License-Identifier: MIT
// Global and local adaptive remeshing in 2D (see adaptive_remeshing_2d.hpp).
#include "generators/adaptation/adaptive_remeshing_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/adaptation/field_transfer.hpp"
#include "generators/adaptation/indicator_size_field.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/mesh_2d/advancing_front_2d.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using tri::kNone;
using tri::TriIdx;
using tri::VertIdx;

namespace {

/// The field on a new mesh: sampled, or transferred from the old mesh; a point in no old
/// triangle (a generator's chord point beside a concave curve point of the old boundary) takes
/// the value of the nearest old vertex (a plain scan: such points are few).
std::vector<double> field_on(const tri::Triangulation2& old_mesh,
                             std::span<const double> old_values, std::span<const double> xy,
                             const FieldSource& field, std::uint64_t& outside) {
    if (field.analytic != nullptr) return sample_field(*field.analytic, xy, 2, field.t);
    std::vector<double> values = transfer_field_2d(old_mesh.xy, old_mesh.triangles, old_values, xy);
    for (std::size_t v = 0; v < values.size(); ++v) {
        if (!std::isnan(values[v])) continue;
        ++outside;
        double best = std::numeric_limits<double>::infinity();
        for (VertIdx w = 0; w < old_mesh.vertex_count(); ++w) {
            const double d = predicates::scale_free_norm(old_mesh.xy[2 * w] - xy[2 * v],
                                                         old_mesh.xy[2 * w + 1] - xy[2 * v + 1]);
            if (d < best) {
                best = d;
                values[v] = old_values[w];
            }
        }
    }
    return values;
}

std::vector<double> vertex_sizes(const AdaptiveMesh2& state, const AdaptationOptions& options) {
    const tri::Triangulation2& mesh = state.mesh;
    if (state.values.size() != mesh.vertex_count()) {
        throw InputError("adaptive remeshing: the field has " +
                         std::to_string(state.values.size()) + " values for " +
                         std::to_string(mesh.vertex_count()) + " vertices");
    }
    const std::vector<VertIdx> edges = mesh_edges_2d(mesh.triangles);
    const std::vector<double> indicator =
        mesh_edge_indicator(options.indicator, mesh.xy, 2, mesh.triangles, edges, state.values);
    return indicator_vertex_sizes(mesh.xy, 2, edges, indicator, options.indicator,
                                  options.threshold, 4.0, options.reference_mean);
}

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
}

}  // namespace

RemeshDomain2 remesh_domain_2d(const DomainPslg& domain) {
    return {{domain.xy, domain.segments, domain.holes, {}}, {}, domain.segment_curves};
}

SizeFunction remesh_size_function_2d(const AdaptiveMesh2& state, const AdaptationOptions& options) {
    return indicator_size_function_2d(state.mesh.xy, state.mesh.triangles,
                                      vertex_sizes(state, options));
}

// ---- global remeshing ------------------------------------------------------------------------

bool remesh_cycle_2d(AdaptiveMesh2& state, const RemeshDomain2& domain,
                     const MeshGenerator2& generator, const AdaptationOptions& options,
                     const FieldSource& field, RemeshCounters2& counters) {
    for (std::size_t s = 0; s < domain.segment_curves.size(); ++s) {
        const std::uint32_t curve = domain.segment_curves[s].curve;
        if (curve != kStraightSide && curve >= state.curves.size()) {
            throw InputError("adaptive remeshing: segment " + std::to_string(s) + " names curve " +
                             std::to_string(curve) + " of " + std::to_string(state.curves.size()));
        }
    }
    // At or over the budget already (a domain whose own features need more vertices): no cycle,
    // as for the other methods; a generator rerun could only overshoot again, up to 8 times.
    if (options.max_vertices > 0 && state.mesh.vertex_count() >= options.max_vertices) {
        ++counters.budget_refusals;
        return false;
    }
    const SizeFunction size = remesh_size_function_2d(state, options);
    const MeshDomain2 mesh_domain(domain.pslg, domain.cdt);
    MeshOptions2 mesh_options;
    mesh_options.cdt = domain.cdt;
    const bool budget = options.max_vertices > 0;
    const double most = static_cast<double>(options.max_vertices);
    // The generator's boundary at twice the vertex budget (a boundary asking for more could
    // not be brought under it by the reruns): a size that asks for more, as a steep grading to
    // fine features can along the boundary, ends in the generator's error at once, not after
    // millions of size evaluations (fuzz_adaptation_2d, tests/data/fuzz/
    // adaptation_2d_oom_narrow.bin: 87 s). Its Steiner budget stays automatic: a given one
    // makes its size check (check_size_budget) sample the size field finely, 2^18 evaluations,
    // which on that case's background mesh (GMP orientation tests at coordinates 1e-319 to
    // 1e252) ran out of memory under the fuzzer's sanitizers.
    if (budget)
        mesh_options.max_boundary_points =
            2 * std::min<std::uint64_t>(options.max_vertices, std::uint64_t{1} << 58);
    double scale = 1;
    // A scaled size is capped at the domain's extent (size_ceiling_2d): a budget that must coarsen
    // a fine corner by 1e98 would otherwise scale the size of a far corner 1e231 away to infinity
    // (fuzz_adaptation_2d, tests/data/fuzz/adaptation_2d_size_overflow.bin).
    const double ceiling = size_ceiling_2d(domain.pslg.xy);
    const auto scaled_size = [&](double factor) {
        return factor == 1 ? size : size.scaled(factor, ceiling);
    };
    if (budget) {
        // The estimate counts triangles of an ideal (equilateral) mesh, a lower bound; a mesh has
        // about half as many vertices as triangles, so asking for at most max_vertices triangles
        // leaves a factor 2 for the generators' worse shapes and their boundary points.
        const tri::Triangulation2& whole = mesh_domain.triangulation().mesh;
        for (int attempt = 0; attempt < 64; ++attempt) {
            const double estimate = minimum_triangle_count(whole, scaled_size(scale), 4 * most);
            if (estimate <= most) break;
            scale *= std::max(1.05, std::sqrt(estimate / most));
            ++counters.budget_scalings;
        }
    }
    MeshRun2 run;
    const auto refused = [&counters] {
        ++counters.budget_refusals;
        return false;
    };
    for (int attempt = 0;; ++attempt) {
        mesh_options.size = scaled_size(scale);
        // Under a budget, a generator's refusal of the size for its count (the boundary's
        // pieces over twice the budget, refinement's Steiner budget) ends the cycle as a budget
        // refusal: the size is this cycle's own, not the caller's bad input (the estimate above
        // samples the size and can miss a steep part of it: tests/data/fuzz/
        // adaptation_2d_size_overflow.bin's long side asked for 1e88 pieces). Not rerun
        // coarser: each refusal costs a sampling of the boundary up to the budget, and eight of
        // them made tests/data/fuzz/adaptation_2d_oom_narrow.bin six times slower.
        ++counters.generator_runs;
        try {
            run = generator.run_on_domain(mesh_domain, mesh_options);
        } catch (const BoundaryBudgetError&) {
            if (!budget) throw;
            return refused();
        } catch (const RefinementBudgetError&) {
            if (!budget) throw;
            return refused();
        }
        const double count = run.mesh.mesh.vertex_count();
        if (!budget || count <= most) break;
        if (attempt == 7) return refused();
        // An area-dominated mesh's count falls as 1 / s^2, a boundary-dominated one's (the
        // quadtree's band) as 1 / s: the first reruns take the square root of the excess, later
        // ones all of it, so that both converge in a few runs.
        const double excess = count / most;
        scale *= std::max(1.1, 1.05 * (attempt < 2 ? std::sqrt(excess) : excess));
        ++counters.budget_reruns;
    }
    AdaptiveMesh2 next =
        make_adaptive_mesh_2d(std::move(run.mesh), domain.pslg.xy, domain.pslg.segments,
                              domain.pslg.holes, state.curves, domain.segment_curves);
    next.values = field_on(state.mesh, state.values, next.mesh.xy, field, counters.outside_values);
    state = std::move(next);
    ++counters.cycles;
    return true;
}

bool remesh_cycle_2d(AdaptiveMesh2& state, const RemeshDomain2& domain, std::string_view generator,
                     const AdaptationOptions& options, const FieldSource& field,
                     RemeshCounters2& counters) {
    return remesh_cycle_2d(state, domain, find_mesh_generator_2d(generator), options, field,
                           counters);
}

// ---- local remeshing -------------------------------------------------------------------------

namespace {

/// One void refilled by the advancing front: its triangles in the old mesh, the front's mesh
/// in the void's own numbering (`global`: the old vertex of each of its first vertices, kNone
/// for the void's inner vertices that go), and the vertex count it adds (negative: removes).
struct FilledVoid {
    std::vector<TriIdx> triangles;
    std::vector<VertIdx> global;
    std::vector<double> xy;
    std::vector<VertIdx> mesh;
    std::int64_t net = 0;
    std::uint64_t removed = 0;
    std::uint64_t inner_inputs = 0;
    std::uint64_t slits = 0;
    bool closed = false;
};

/// The void's boundary (its triangles' edges that face no triangle of the void across a
/// non-piece edge) as the front, directed with the void on its left (the triangles are
/// counter-clockwise); its triangles as the domain's triangulation; the input vertices strictly
/// inside it as free vertices; then the advancing front with `size`.
FilledVoid fill_void(const AdaptiveMesh2& state, std::vector<TriIdx> triangles,
                     const std::vector<std::uint32_t>& void_of, std::uint32_t id,
                     const SizeFunction& size, std::vector<VertIdx>& local) {
    const tri::Triangulation2& mesh = state.mesh;
    FilledVoid filled;
    filled.triangles = std::move(triangles);
    DomainBoundary2 boundary;
    std::vector<VertIdx>& global = filled.global;
    auto local_of = [&](VertIdx v) {
        if (local[v] == kNone) {
            local[v] = static_cast<VertIdx>(global.size());
            global.push_back(v);
            boundary.xy.insert(boundary.xy.end(), {mesh.xy[2 * v], mesh.xy[2 * v + 1]});
        }
        return local[v];
    };
    std::vector<std::uint8_t> on_front;
    std::unordered_set<std::uint64_t> directed;
    for (const TriIdx t : filled.triangles) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = local_of(mesh.triangles[3 * t + k]);
            boundary.cdt.mesh.triangles.push_back(a);
        }
    }
    on_front.assign(global.size(), 0);
    for (const TriIdx t : filled.triangles) {
        for (unsigned k = 0; k < 3; ++k) {
            const TriIdx n = mesh.neighbors[3 * t + k];
            const bool inner =
                n != kNone && !mesh.is_constrained(t, static_cast<int>(k)) && void_of[n] == id;
            if (inner) continue;
            const VertIdx a = local[mesh.triangles[3 * t + k]];
            const VertIdx b = local[mesh.triangles[3 * t + (k + 1) % 3]];
            boundary.front.insert(boundary.front.end(), {a, b});
            boundary.front_segment.push_back(0);
            directed.insert((std::uint64_t{a} << 32) | b);
            on_front[a] = on_front[b] = 1;
        }
    }
    // Each undirected boundary edge once as a piece (a piece with the void on both sides, a
    // slit of the void, is two front edges).
    for (std::size_t e = 0; 2 * e + 1 < boundary.front.size(); ++e) {
        const VertIdx a = boundary.front[2 * e], b = boundary.front[2 * e + 1];
        const bool slit = directed.contains((std::uint64_t{b} << 32) | a);
        if (a < b || !slit) {
            boundary.pieces.insert(boundary.pieces.end(), {a, b});
            boundary.piece_segment.push_back(0);
            filled.slits += slit ? 1 : 0;
        }
    }
    const auto count = static_cast<VertIdx>(global.size());
    for (VertIdx l = 0; l < count; ++l) {
        if (on_front[l]) continue;
        if (global[l] < state.fixed_vertices) {
            boundary.free_vertices.push_back(l);  // an input vertex: kept
            ++filled.inner_inputs;
        } else {
            ++filled.removed;
        }
    }
    boundary.cdt.mesh.xy = boundary.xy;
    boundary.cdt.input_vertex_count = count;
    boundary.input_vertex_count = count;

    AdvancingFrontOptions2 front;
    front.size = size;
    AdvancingFrontResult2 result = advancing_front_from_boundary_2d(boundary, front);
    filled.closed = result.counters.closure_runs > 0;
    filled.xy = std::move(result.mesh.mesh.xy);
    filled.mesh = std::move(result.mesh.mesh.triangles);
    // The void's inner vertices (neither on the front nor free) must be in no new triangle.
    for (VertIdx l = 0; l < count; ++l)
        if (!on_front[l] && global[l] >= state.fixed_vertices) global[l] = kNone;
    for (const VertIdx l : filled.mesh) {
        if (l < count && global[l] == kNone)
            throw InternalError("local remeshing: the front used a vertex of its void's inside");
    }
    const auto added = static_cast<std::int64_t>(filled.xy.size() / 2 - count);
    filled.net = added - static_cast<std::int64_t>(filled.removed);
    return filled;
}

/// Triangles whose mean edge and mean wanted size differ by more than the factor (1: larger,
/// 2: smaller). Both are scale-free lengths (scale_free_norm, sizes from it): ×2^k scales both
/// exactly, and neither overflows at 2^±600.
std::vector<std::uint8_t> size_flags(const tri::Triangulation2& mesh,
                                     const std::vector<double>& sizes, double factor) {
    if (!(std::isfinite(factor) && factor > 1)) {
        throw InputError("local remeshing: the size factor must be finite and > 1, not " +
                         format_number(factor));
    }
    std::vector<std::uint8_t> flags(mesh.triangle_count(), 0);
    for (TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        double current = 0, wanted = 0;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
            current += predicates::scale_free_norm(mesh.xy[2 * b] - mesh.xy[2 * a],
                                                   mesh.xy[2 * b + 1] - mesh.xy[2 * a + 1]);
            wanted += sizes[a];
        }
        if (current > factor * wanted)
            flags[t] = 1;
        else if (wanted > factor * current)
            flags[t] = 2;
    }
    return flags;
}

}  // namespace

std::vector<std::uint8_t> local_remesh_flags_2d(const AdaptiveMesh2& state,
                                                const AdaptationOptions& options, double factor) {
    return size_flags(state.mesh, vertex_sizes(state, options), factor);
}

bool local_remesh_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                           const FieldSource& field, LocalRemeshCounters2& counters,
                           double factor) {
    const tri::Triangulation2& mesh = state.mesh;
    std::vector<double> sizes = vertex_sizes(state, options);

    // 1. The triangles to remove.
    const TriIdx triangle_count = mesh.triangle_count();
    const std::vector<std::uint8_t> removed = size_flags(mesh, sizes, factor);
    const auto too_large =
        static_cast<std::uint64_t>(std::count(removed.begin(), removed.end(), 1));
    const auto too_small =
        static_cast<std::uint64_t>(std::count(removed.begin(), removed.end(), 2));
    if (too_large + too_small == 0) return false;

    // 2. The voids: removed triangles connected across edges that are not pieces.
    constexpr std::uint32_t kKept = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> void_of(triangle_count, kKept);
    std::vector<std::vector<TriIdx>> voids;
    for (TriIdx seed = 0; seed < triangle_count; ++seed) {
        if (!removed[seed] || void_of[seed] != kKept) continue;
        const auto id = static_cast<std::uint32_t>(voids.size());
        std::vector<TriIdx> members{seed};
        void_of[seed] = id;
        for (std::size_t i = 0; i < members.size(); ++i) {
            const TriIdx t = members[i];
            for (unsigned k = 0; k < 3; ++k) {
                const TriIdx n = mesh.neighbors[3 * t + k];
                if (n == kNone || mesh.is_constrained(t, static_cast<int>(k)) || !removed[n] ||
                    void_of[n] != kKept)
                    continue;
                void_of[n] = id;
                members.push_back(n);
            }
        }
        voids.push_back(std::move(members));
    }

    // 3. Each void filled by the advancing front from its boundary.
    const SizeFunction size = indicator_size_function_2d(mesh.xy, mesh.triangles, sizes);
    std::vector<FilledVoid> filled;
    filled.reserve(voids.size());
    std::vector<VertIdx> local(mesh.vertex_count(), kNone);
    for (std::uint32_t id = 0; id < voids.size(); ++id) {
        filled.push_back(fill_void(state, std::move(voids[id]), void_of, id, size, local));
        for (const TriIdx t : filled.back().triangles)
            for (unsigned k = 0; k < 3; ++k) local[mesh.triangles[3 * t + k]] = kNone;
    }

    // 4. Under a budget, the voids that remove vertices first, then the others while they fit.
    std::vector<std::uint8_t> accepted(filled.size(), 1);
    if (options.max_vertices > 0) {
        auto vertices = static_cast<std::int64_t>(mesh.vertex_count());
        const auto most = static_cast<std::int64_t>(
            std::min<std::uint64_t>(options.max_vertices, std::uint64_t{1} << 62));
        for (const FilledVoid& f : filled)
            if (f.net <= 0) vertices += f.net;
        for (std::size_t i = 0; i < filled.size(); ++i) {
            if (filled[i].net <= 0) continue;
            if (vertices + filled[i].net <= most) {
                vertices += filled[i].net;
            } else {
                accepted[i] = 0;
                ++counters.budget_kept_voids;
            }
        }
    }
    if (std::find(accepted.begin(), accepted.end(), 1) == accepted.end()) return false;

    // 5. The merge: the kept vertices in their order (the input vertices never go, so they keep
    // their numbers), then each void's new points; the kept triangles as they were, then the
    // voids' triangles.
    std::vector<std::uint8_t> in_void(triangle_count, 0);
    std::vector<std::uint8_t> goes(mesh.vertex_count(), 0);
    for (std::size_t i = 0; i < filled.size(); ++i) {
        if (!accepted[i]) continue;
        for (const TriIdx t : filled[i].triangles) in_void[t] = 1;
    }
    // A vertex goes when it is inside an accepted void: every triangle at it there, not on the
    // void's boundary (fill_void marked those kNone in `global`).
    for (std::size_t i = 0; i < filled.size(); ++i) {
        if (!accepted[i]) continue;
        std::vector<VertIdx> seen;
        for (const TriIdx t : filled[i].triangles)
            for (unsigned k = 0; k < 3; ++k) seen.push_back(mesh.triangles[3 * t + k]);
        std::sort(seen.begin(), seen.end());
        seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
        std::vector<VertIdx> kept(filled[i].global);
        std::sort(kept.begin(), kept.end());
        for (const VertIdx v : seen)
            if (!std::binary_search(kept.begin(), kept.end(), v)) goes[v] = 1;
    }
    std::vector<VertIdx> renumber(mesh.vertex_count(), kNone);
    tri::Triangulation2 merged;
    std::vector<std::uint8_t> on_curve;
    std::vector<double> values;
    for (VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        if (goes[v]) continue;
        renumber[v] = merged.vertex_count();
        merged.xy.insert(merged.xy.end(), {mesh.xy[2 * v], mesh.xy[2 * v + 1]});
        on_curve.push_back(v < state.on_curve.size() ? state.on_curve[v] : 0);
        values.push_back(state.values[v]);
    }
    const VertIdx old_kept = merged.vertex_count();
    for (TriIdx t = 0; t < triangle_count; ++t) {
        if (in_void[t]) continue;
        for (unsigned k = 0; k < 3; ++k)
            merged.triangles.push_back(renumber[mesh.triangles[3 * t + k]]);
    }
    LocalRemeshCounters2 added;
    for (std::size_t i = 0; i < filled.size(); ++i) {
        if (!accepted[i]) continue;
        const FilledVoid& f = filled[i];
        const auto count = static_cast<VertIdx>(f.global.size());
        std::vector<VertIdx> to_merged(f.xy.size() / 2, kNone);
        for (VertIdx l = 0; l < count; ++l)
            if (f.global[l] != kNone) to_merged[l] = renumber[f.global[l]];
        for (VertIdx l = count; l < to_merged.size(); ++l) {
            to_merged[l] = merged.vertex_count();
            merged.xy.insert(merged.xy.end(), {f.xy[2 * l], f.xy[2 * l + 1]});
            on_curve.push_back(0);
        }
        for (const VertIdx l : f.mesh) merged.triangles.push_back(to_merged[l]);
        ++added.voids;
        added.removed_vertices += f.removed;
        added.new_points += f.xy.size() / 2 - count;
        added.new_triangles += f.mesh.size() / 3;
        added.front_closures += f.closed ? 1 : 0;
        added.inner_inputs += f.inner_inputs;
        added.slit_pieces += f.slits;
    }
    try {
        tri::link_neighbors_2d(merged);
    } catch (const InputError& e) {
        throw InternalError(std::string("local remeshing: the filled voids do not conform: ") +
                            e.what());
    }
    std::unordered_set<std::uint64_t> piece_edges;
    std::vector<CurvedPiece2> pieces = state.pieces;
    for (CurvedPiece2& p : pieces) {
        p.a = renumber[p.a];
        p.b = renumber[p.b];
        piece_edges.insert(edge_key(p.a, p.b));
    }
    merged.constrained.assign(merged.triangles.size(), 0);
    for (std::size_t e = 0; e < merged.triangles.size(); ++e) {
        const VertIdx a = merged.triangles[e], b = merged.triangles[e - e % 3 + (e + 1) % 3];
        if (piece_edges.contains(edge_key(a, b))) merged.constrained[e] = 1;
    }

    // 6. The field: sampled, or the old values at the kept vertices and transferred at the new.
    std::uint64_t outside = 0;
    if (field.analytic != nullptr) {
        values = sample_field(*field.analytic, merged.xy, 2, field.t);
    } else {
        const std::span<const double> fresh(merged.xy.data() + 2 * std::size_t{old_kept},
                                            merged.xy.size() - 2 * std::size_t{old_kept});
        const std::vector<double> moved = field_on(mesh, state.values, fresh, field, outside);
        values.insert(values.end(), moved.begin(), moved.end());
    }

    state.mesh = std::move(merged);
    state.pieces = std::move(pieces);
    state.on_curve = std::move(on_curve);
    state.values = std::move(values);
    ++counters.cycles;
    counters.too_large += too_large;
    counters.too_small += too_small;
    counters.voids += added.voids;
    counters.removed_vertices += added.removed_vertices;
    counters.new_points += added.new_points;
    counters.new_triangles += added.new_triangles;
    counters.front_closures += added.front_closures;
    counters.inner_inputs += added.inner_inputs;
    counters.slit_pieces += added.slit_pieces;
    counters.outside_values += outside;
    return true;
}

}  // namespace exactmesh::generators
