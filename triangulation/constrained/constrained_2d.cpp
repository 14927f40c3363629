// SPDX-License-Identifier: MIT
// Constrained and conforming Delaunay triangulation (see constrained_2d.hpp): the entry point,
// which runs the builder's phases (cdt_phases_2d.hpp) over one CdtState (cdt_state_2d.hpp),
// and the result in the caller's numbering.
#include "triangulation/constrained/constrained_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_core.hpp"

namespace exactmesh::triangulation {

using predicates::Sign;

namespace {

constexpr std::array<EnumName<SegmentRecovery>, 3> kSegmentRecoveryNames{{
    {"swap", SegmentRecovery::Swap},
    {"cavity", SegmentRecovery::Cavity},
    {"conforming", SegmentRecovery::Conforming},
}};

}  // namespace

SegmentRecovery segment_recovery_from_name(std::string_view name) {
    if (const auto recovery = find_name(kSegmentRecoveryNames, name)) return *recovery;
    // Worded as it always was ("expected a, b or c"), unlike parse_name's "known: a, b, c".
    throw InputError("unknown segment recovery '" + std::string(name) + "' (expected " +
                     known_names(kSegmentRecoveryNames, " or ") + ")");
}

const char* segment_recovery_name(SegmentRecovery recovery) {
    return name_of(kSegmentRecoveryNames, recovery).data();  // the names are literals
}

namespace {

void require_finite_items(std::span<const double> values, std::size_t stride, const char* what) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            throw InputError(std::string(what) + " " + std::to_string(i / stride) +
                             ": non-finite value " + format_number(values[i]));
        }
    }
}

}  // namespace

namespace detail {

namespace {

void collect_output(CdtState& cdt) {
    // In place, as Delaunay2Core::take_result does: fresh output arrays would cost a page fault
    // per 4 KiB, a third of the whole construction time at 10^6 points (perf, this machine).
    const std::uint32_t slots = cdt.mesh.triangle_slots();
    const std::uint32_t vertices = cdt.mesh.vertex_count();
    // Caller numbering: inputs as given (duplicates reported as the smallest equal index),
    // added vertices after the inputs in creation order (their input_index already).
    cdt.result.merged_into.resize(cdt.input_count);
    for (VertIdx i = 0; i < cdt.input_count; ++i) cdt.result.merged_into[i] = i;
    for (VertIdx i = 0; i < cdt.input_count; ++i) {
        const VertIdx kept = cdt.core.merged_into[i];
        cdt.result.merged_into[kept] = std::min(cdt.result.merged_into[kept], i);
    }
    for (VertIdx i = 0; i < cdt.input_count; ++i)
        cdt.result.merged_into[i] = cdt.result.merged_into[cdt.core.merged_into[i]];
    std::vector<VertIdx>& caller = cdt.core.input_index;  // reused: mesh vertex -> output vertex
    for (VertIdx v = 0; v < vertices; ++v) {
        if (caller[v] < cdt.input_count) caller[v] = cdt.result.merged_into[caller[v]];
    }
    // The enclosing box's corners (all in removed triangles) are not output; the vertices added
    // after them close the gap.
    std::uint32_t output_vertices = vertices;
    if (cdt.box_first != kNone) {
        for (VertIdx v = cdt.box_first; v < vertices; ++v)
            caller[v] = v < cdt.box_first + 4 ? kNone : v - 4;
        output_vertices -= 4;
    }
    Triangulation2& out = cdt.result.mesh;
    out.xy.reserve(2 * std::size_t{output_vertices});
    out.xy.assign(cdt.pslg.xy.begin(), cdt.pslg.xy.end());
    out.xy.resize(2 * std::size_t{output_vertices});
    for (VertIdx v = cdt.input_count; v < vertices; ++v) {
        if (caller[v] == kNone) continue;
        out.xy[2 * std::size_t{caller[v]}] = cdt.mesh.xy[2 * std::size_t{v}];
        out.xy[2 * std::size_t{caller[v]} + 1] = cdt.mesh.xy[2 * std::size_t{v} + 1];
    }
    cdt.mesh.xy = {};
    // Pieces: every constrained edge once, including those inside removed regions.
    for (TriIdx t = 0; t < slots; ++t) {
        if (cdt.mesh.is_dead(t)) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            if (cdt.segment_of[e] == kNone) continue;
            const VertIdx p = caller[cdt.mesh.origin(e)], q = caller[cdt.mesh.destination(e)];
            if (p < q) {
                cdt.result.pieces.insert(cdt.result.pieces.end(), {p, q});
                cdt.result.piece_segment.push_back(cdt.segment_of[e]);
            }
        }
    }
    std::vector<TriIdx> index(slots, kNone);
    TriIdx count = 0;
    for (TriIdx t = 0; t < slots; ++t) {
        if (cdt.mesh.is_dead(t) || cdt.mesh.is_infinite(t)) continue;
        if (cdt.removed[t]) {
            ++cdt.result.counters.removed_triangles;
            continue;
        }
        index[t] = count++;
    }
    if (!cdt.attribute.empty()) cdt.result.triangle_attributes.resize(count);
    out.constrained.resize(3 * std::size_t{count});
    // Compaction: triangle t moves to index[t] <= t, so nothing unread is overwritten.
    for (TriIdx t = 0; t < slots; ++t) {
        const TriIdx o = index[t];
        if (o == kNone) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = cdt.mesh.tv[3 * t + k];
            const EdgeIdx across = cdt.mesh.twin[3 * t + k];
            out.constrained[3 * o + k] = cdt.segment_of[3 * t + k] != kNone ? 1 : 0;
            cdt.mesh.tv[3 * o + k] = caller[v];
            cdt.mesh.twin[3 * o + k] = index[triangle_of(across)];
        }
        if (!cdt.attribute.empty()) cdt.result.triangle_attributes[o] = cdt.attribute[t];
    }
    cdt.mesh.tv.resize(3 * std::size_t{count});
    cdt.mesh.twin.resize(3 * std::size_t{count});
    out.triangles = std::move(cdt.mesh.tv);
    out.neighbors = std::move(cdt.mesh.twin);
}

void collinear_output(CdtState& cdt) {
    // No triangle: every distinct point lies on one line. Pieces: each segment split at the
    // vertices strictly inside it, found by sorting the distinct points along the line.
    Delaunay2Result points = cdt.core.collinear_result();
    cdt.result.merged_into = std::move(points.merged_into);
    cdt.result.mesh.xy.assign(cdt.pslg.xy.begin(), cdt.pslg.xy.end());
    std::vector<VertIdx> order;
    for (VertIdx i = 0; i < cdt.input_count; ++i) {
        if (cdt.result.merged_into[i] == i) order.push_back(i);
    }
    const double* xy = cdt.pslg.xy.data();
    std::sort(order.begin(), order.end(), [xy](VertIdx p, VertIdx q) {
        return xy[2 * p] < xy[2 * q] || (xy[2 * p] == xy[2 * q] && xy[2 * p + 1] < xy[2 * q + 1]);
    });
    std::vector<std::uint32_t> rank(cdt.input_count);
    for (std::uint32_t r = 0; r < order.size(); ++r) rank[order[r]] = r;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (std::size_t s = 0; s < cdt.pslg.segments.size() / 2; ++s) {
        std::uint32_t i = rank[cdt.result.merged_into[cdt.pslg.segments[2 * s]]];
        std::uint32_t j = rank[cdt.result.merged_into[cdt.pslg.segments[2 * s + 1]]];
        if (i == j) {
            ++cdt.result.counters.dropped_segments;
            cdt.result.warnings.push_back("segment " +
                                          cdt.segment_name(static_cast<std::uint32_t>(s)) +
                                          " has zero length; ignored");
            continue;
        }
        if (i > j) std::swap(i, j);
        for (std::uint32_t r = i; r < j; ++r)
            keyed.emplace_back((std::uint64_t{r} << 32) | (r + 1), s);
        if (j > i + 1) ++cdt.result.counters.vertices_on_segments;
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
        if (k > 0 && keyed[k - 1].first == keyed[k].first) continue;
        cdt.result.pieces.push_back(order[keyed[k].first >> 32]);
        cdt.result.pieces.push_back(order[keyed[k].first & 0xFFFFFFFFu]);
        cdt.result.piece_segment.push_back(keyed[k].second);
    }
    cdt.result.counters.points = cdt.input_count;
    cdt.result.counters.duplicates = points.counters.duplicates;
}

}  // namespace

Cdt2Result finish(CdtState& cdt) {
    if (cdt.collinear) {
        collinear_output(cdt);
        return std::move(cdt.result);
    }
    Cdt2Counters& c = cdt.result.counters;
    c.duplicates = cdt.core.counters.duplicates;
    c.orient_calls = cdt.core.counters.orient_calls;
    c.incircle_calls = cdt.core.counters.incircle_calls;
    c.delaunay_flips += cdt.core.counters.flips;
    c.walk_steps += cdt.core.counters.walk_steps;
    collect_output(cdt);
    return std::move(cdt.result);
}

}  // namespace detail

void validate_pslg(const Pslg& pslg) {
    validate_points_2d(pslg.xy);
    const std::size_t n = pslg.xy.size() / 2;
    if (pslg.segments.size() % 2 != 0) throw InputError("segments: odd number of endpoint indices");
    for (std::size_t i = 0; i < pslg.segments.size(); ++i) {
        if (pslg.segments[i] >= n) {
            throw InputError("segment " + std::to_string(i / 2) + ": vertex " +
                             std::to_string(pslg.segments[i]) + " does not exist (" +
                             std::to_string(n) + " vertices)");
        }
    }
    if (pslg.holes.size() % 2 != 0) throw InputError("holes: odd number of coordinates");
    if (pslg.regions.size() % 4 != 0) throw InputError("regions: expected 4 numbers per region");
    require_finite_items(pslg.holes, 2, "hole");
    require_finite_items(pslg.regions, 4, "region");
}

Cdt2Result constrained_delaunay_2d(const Pslg& pslg, const Cdt2Options& options) {
    validate_pslg(pslg);
    detail::CdtState cdt(pslg, options);
    if (detail::triangulate_vertices(cdt)) {
        detail::recover_segments(cdt, options.recovery == SegmentRecovery::Cavity
                                          ? detail::recover_by_cavity
                                          : detail::recover_by_swaps);
        if (options.recovery == SegmentRecovery::Conforming) detail::conform(cdt);
        detail::mark_domain(cdt);
    }
    return detail::finish(cdt);
}

}  // namespace exactmesh::triangulation
