// SPDX-License-Identifier: MIT
// Shared machinery of the 2D Delaunay constructions (see delaunay_2d_core.hpp).
#include "triangulation/delaunay/delaunay_2d_core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "base/errors.hpp"
#include "base/huge_pages.hpp"
#include "base/number_text.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

void validate_points_2d(std::span<const double> xy) {
    if (xy.size() % 2 != 0) {
        throw InputError("points: odd number of coordinates (" + std::to_string(xy.size()) + ")");
    }
    if (xy.size() / 2 > kMaxPoints) {
        throw InputError("points: " + std::to_string(xy.size() / 2) +
                         " points exceed the limit of " + std::to_string(kMaxPoints));
    }
    for (std::size_t i = 0; i < xy.size(); ++i) {
        if (!std::isfinite(xy[i])) {
            const std::string value = format_number(xy[i]);
            const auto v = static_cast<std::uint32_t>(i / 2);
            throw NonFiniteCoordinate("point " + std::to_string(v) + ": non-finite " +
                                          (i % 2 == 0 ? "x" : "y") + " coordinate " + value,
                                      v);
        }
    }
}

namespace detail {

Delaunay2Core::Delaunay2Core(std::span<const double> xy, const Delaunay2Options& options)
    : Delaunay2Core(xy,
                    (validate_points_2d(xy), insertion_order_2d(xy, options.order, options.seed))) {
    build_jump_grid(options);
    progress = ProgressCounter(options.progress, xy.size() / 2, "points inserted");
}

void Delaunay2Core::build_jump_grid(const Delaunay2Options& options) {
    const bool wanted =
        options.location == PointLocation::Grid ||
        (options.location == PointLocation::Auto && options.order == InsertionOrder::Random);
    const std::uint32_t n = mesh.vertex_count();
    if (!wanted || n < 64) return;
    double lo_x = mesh.xy[0], hi_x = lo_x, lo_y = mesh.xy[1], hi_y = lo_y;
    for (std::uint32_t v = 1; v < n; ++v) {
        lo_x = std::min(lo_x, mesh.xy[2 * v]);
        hi_x = std::max(hi_x, mesh.xy[2 * v]);
        lo_y = std::min(lo_y, mesh.xy[2 * v + 1]);
        hi_y = std::max(hi_y, mesh.xy[2 * v + 1]);
    }
    // About one finest cell per two points; halves keep huge extents from overflowing.
    int depth = 1;
    while (depth < 15 && (std::uint64_t{1} << (2 * depth)) < n / 2) ++depth;
    jump_.enabled = true;
    jump_.depth = depth;
    jump_.min_x = lo_x / 2;
    jump_.min_y = lo_y / 2;
    const double cells = static_cast<double>(std::uint32_t{1} << depth);
    const double half_x = hi_x / 2 - lo_x / 2, half_y = hi_y / 2 - lo_y / 2;
    jump_.scale_x = half_x > 0 ? cells / half_x : 0.0;
    jump_.scale_y = half_y > 0 ? cells / half_y : 0.0;
    std::uint32_t offset = 0;
    for (int l = 0; l <= depth; ++l) {
        jump_.level_offset.push_back(offset);
        offset += std::uint32_t{1} << (2 * l);
    }
    jump_.triangle.assign(offset, kNone);
}

void Delaunay2Core::jump_cell(VertIdx p, std::uint32_t& ix, std::uint32_t& iy) const {
    const std::uint32_t top = (std::uint32_t{1} << jump_.depth) - 1;
    auto index = [top](double t) -> std::uint32_t {
        if (!(t > 0)) return 0;
        if (!(t < top)) return top;
        return static_cast<std::uint32_t>(t);
    };
    ix = index((mesh.point(p)[0] / 2 - jump_.min_x) * jump_.scale_x);
    iy = index((mesh.point(p)[1] / 2 - jump_.min_y) * jump_.scale_y);
}

void Delaunay2Core::note_inserted(VertIdx p) {
    if (!jump_.enabled) return;
    std::uint32_t ix, iy;
    jump_cell(p, ix, iy);
    for (int l = 0; l <= jump_.depth; ++l) {
        const int shift = jump_.depth - l;
        jump_.triangle[jump_.level_offset[static_cast<unsigned>(l)] + ((iy >> shift) << l) +
                       (ix >> shift)] = last_triangle;
    }
}

Delaunay2Core::Delaunay2Core(std::span<const double> xy, std::vector<VertIdx> order,
                             const ChunkRunner& run) {
    const std::uint32_t n = static_cast<std::uint32_t>(xy.size() / 2);
    input_index = std::move(order);
    mesh.xy.reserve(xy.size());
    advise_huge_pages(mesh.xy);
    mesh.xy.resize(xy.size());
    merged_into.resize(n);
    // In chunks of points, on run's threads when given (the same arrays).
    constexpr std::uint32_t kChunk = 1u << 16;
    const std::size_t chunks = (std::size_t{n} + kChunk - 1) / kChunk;
    const auto gather = [&](std::size_t chunk) {
        const auto begin = static_cast<std::uint32_t>(chunk * kChunk);
        const std::uint32_t end = std::min(n, begin + kChunk);
        for (std::uint32_t v = begin; v < end; ++v) {
            mesh.xy[2 * v] = xy[2 * input_index[v]];
            mesh.xy[2 * v + 1] = xy[2 * input_index[v] + 1];
            merged_into[v] = v;
        }
    };
    if (run && chunks > 1) {
        run(chunks, gather);
    } else {
        for (std::size_t chunk = 0; chunk < chunks; ++chunk) gather(chunk);
    }
    counters.points = n;
    mesh.tv.reserve(6 * static_cast<std::size_t>(n) + 12);
    mesh.twin.reserve(6 * static_cast<std::size_t>(n) + 12);
}

Sign Delaunay2Core::orient(VertIdx a, VertIdx b, VertIdx c) {
    ++counters.orient_calls;
    return predicates::orient2d(mesh.point(a), mesh.point(b), mesh.point(c));
}

Sign incircle_tie_2d(const TriMesh2& mesh, const std::vector<VertIdx>& input_index, VertIdx a,
                     VertIdx b, VertIdx c, VertIdx d) {
    // The caller's indices are loaded only for the rare exact tie.
    return predicates::incircle_sos(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d),
                                    input_index[a], input_index[b], input_index[c], input_index[d]);
}

namespace {

/// True when the finite points a, b, p are collinear and p lies strictly between a and b.
bool strictly_between_2d(const TriMesh2& mesh, VertIdx a, VertIdx b, VertIdx p) {
    const double* pa = mesh.point(a);
    const double* pb = mesh.point(b);
    const double* pp = mesh.point(p);
    // Collinear: compare along x unless the segment is vertical. Exact comparisons.
    const int k = pa[0] != pb[0] ? 0 : 1;
    return (pa[k] < pp[k] && pp[k] < pb[k]) || (pb[k] < pp[k] && pp[k] < pa[k]);
}

}  // namespace

bool Delaunay2Core::strictly_between(VertIdx a, VertIdx b, VertIdx p) const {
    return strictly_between_2d(mesh, a, b, p);
}

bool conflict_infinite_2d(const TriMesh2& mesh, Delaunay2Counters& counters, TriIdx t, VertIdx p) {
    const VertIdx* v = &mesh.tv[3 * static_cast<std::size_t>(t)];
    int k = 0;
    while (v[k] != kInfinite) ++k;
    const VertIdx a = v[(k + 1) % 3], b = v[(k + 2) % 3];
    ++counters.orient_calls;
    const Sign s = predicates::orient2d(mesh.point(a), mesh.point(b), mesh.point(p));
    if (s != Sign::Zero) return s == Sign::Positive;
    return strictly_between_2d(mesh, a, b, p);
}

bool Delaunay2Core::make_first_triangle(std::vector<bool>& skip) {
    const std::uint32_t n = mesh.vertex_count();
    skip.assign(n, false);
    if (n == 0) return false;
    const VertIdx v0 = 0;
    VertIdx v1 = kNone, v2 = kNone;
    for (VertIdx v = 1; v < n && v1 == kNone; ++v) {
        if (!same_point(v0, v)) v1 = v;
    }
    if (v1 == kNone) return false;
    for (VertIdx v = v1 + 1; v < n && v2 == kNone; ++v) {
        if (orient(v0, v1, v) != Sign::Zero) v2 = v;
    }
    if (v2 == kNone) return false;
    skip[v0] = skip[v1] = skip[v2] = true;
    VertIdx a = v0, b = v1, c = v2;
    if (orient(a, b, c) == Sign::Negative) std::swap(b, c);
    const TriIdx f = mesh.new_triangle();
    mesh.tv[3 * f] = a;
    mesh.tv[3 * f + 1] = b;
    mesh.tv[3 * f + 2] = c;
    // One infinite triangle (q, p, inf) behind each finite edge p -> q; infinite triangle i
    // lies behind edge i of f, and its edge (p -> inf) meets edge (inf -> p) of the one before.
    TriIdx inf[3];
    for (int k = 0; k < 3; ++k) {
        inf[k] = mesh.new_triangle();
        const VertIdx p = mesh.tv[3 * f + static_cast<unsigned>(k)];
        const VertIdx q = mesh.tv[3 * f + static_cast<unsigned>((k + 1) % 3)];
        mesh.tv[3 * inf[k]] = q;
        mesh.tv[3 * inf[k] + 1] = p;
        mesh.tv[3 * inf[k] + 2] = kInfinite;
        mesh.link(3 * f + static_cast<unsigned>(k), 3 * inf[k]);
    }
    for (int k = 0; k < 3; ++k) {
        // inf[k] = (q, p, inf) with p = f[k]; its edge p -> inf (local 1) meets edge inf -> p
        // (local 2) of the infinite triangle whose first vertex is p, i.e. inf[k-1].
        mesh.link(3 * inf[k] + 1, 3 * inf[(k + 2) % 3] + 2);
    }
    last_triangle = f;
    return true;
}

TriIdx Delaunay2Core::locate(VertIdx p) {
    const TriIdx t = walk_to(p);
    if (!mesh.is_infinite(t)) {
        for (int k = 0; k < 3; ++k) {
            const VertIdx v = mesh.tv[3 * t + static_cast<unsigned>(k)];
            if (same_point(v, p)) {
                merged_into[input_index[p]] = input_index[v];
                ++counters.duplicates;
                return kNone;
            }
        }
    }
    return t;
}

TriIdx Delaunay2Core::walk_to(VertIdx p) {
    TriIdx t = last_triangle;
    if (jump_.enabled) {
        // The finest level whose cell around p has seen an insertion whose triangle lives.
        std::uint32_t ix, iy;
        jump_cell(p, ix, iy);
        for (int l = jump_.depth; l >= 0; --l) {
            const int shift = jump_.depth - l;
            const TriIdx candidate = jump_.triangle[jump_.level_offset[static_cast<unsigned>(l)] +
                                                    ((iy >> shift) << l) + (ix >> shift)];
            if (candidate != kNone && !mesh.is_dead(candidate)) {
                t = candidate;
                break;
            }
        }
    }
    if (mesh.is_dead(t)) {
        for (t = 0; mesh.is_dead(t); ++t) {
        }
    }
    if (mesh.is_infinite(t)) {
        // Step to the finite neighbour across the hull edge.
        for (int k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + static_cast<unsigned>(k);
            if (mesh.tv[e] != kInfinite && mesh.tv[next_edge(e)] != kInfinite) {
                t = triangle_of(mesh.twin[e]);
                break;
            }
        }
    }
    TriIdx stopped = kNone;
    // In a fixed order for as many steps as there are slots: the whole walk in a Delaunay
    // triangulation.
    visibility_walk_2d(
        mesh, t, p, counters, mesh.triangle_slots(), [](TriIdx) { return true; },
        [this] { return walk_random_offset_2d(rng_state_); }, stopped);
    last_triangle = stopped;
    return stopped;
}

Delaunay2Result Delaunay2Core::take_result(std::size_t chunks, const ChunkRunner& run) {
    Delaunay2Result out;
    out.counters = counters;
    std::vector<VertIdx>& first = input_index;  // mesh vertex -> reported caller index
    if (counters.duplicates > 0) report_first_occurrence(merged_into, first);
    out.merged_into = std::move(merged_into);
    // Number the finite triangles, then compact tv and twin in place (output index <= slot).
    std::vector<TriIdx> output_index;
    const TriIdx count =
        compact_cells<3>(mesh, mesh.tv, mesh.twin, first, output_index, mesh.triangle_slots(),
                         chunks, run, [&output_index](EdgeIdx across) {
                             return across == kNone ? kNone : output_index[triangle_of(across)];
                         });
    mesh.tv.resize(3 * static_cast<std::size_t>(count));
    mesh.twin.resize(3 * static_cast<std::size_t>(count));
    out.triangles = std::move(mesh.tv);
    out.neighbors = std::move(mesh.twin);
    mesh = TriMesh2{};
    return out;
}

Delaunay2Result Delaunay2Core::collinear_result() {
    std::vector<VertIdx> by_point(mesh.vertex_count());
    for (VertIdx v = 0; v < by_point.size(); ++v) by_point[v] = v;
    std::sort(by_point.begin(), by_point.end(), [this](VertIdx a, VertIdx b) {
        const double* p = mesh.point(a);
        const double* q = mesh.point(b);
        return p[0] < q[0] ||
               (p[0] == q[0] && (p[1] < q[1] || (p[1] == q[1] && input_index[a] < input_index[b])));
    });
    for (std::size_t i = 1; i < by_point.size(); ++i) {
        if (same_point(by_point[i - 1], by_point[i])) {
            merged_into[input_index[by_point[i]]] = merged_into[input_index[by_point[i - 1]]];
            ++counters.duplicates;
        }
    }
    return take_result();
}

}  // namespace detail
}  // namespace exactmesh::triangulation
