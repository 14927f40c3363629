// SPDX-License-Identifier: MIT
// Shared machinery of the 3D Delaunay constructions (see delaunay_3d_core.hpp).
#include "triangulation/delaunay/delaunay_3d_core.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/huge_pages.hpp"
#include "base/number_text.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

void validate_points_3d(std::span<const double> xyz) {
    if (xyz.size() % 3 != 0) {
        throw InputError("points: the number of coordinates (" + std::to_string(xyz.size()) +
                         ") is not a multiple of 3");
    }
    if (xyz.size() / 3 > kMaxPoints3) {
        throw InputError("points: " + std::to_string(xyz.size() / 3) +
                         " points exceed the limit of " + std::to_string(kMaxPoints3));
    }
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        if (!std::isfinite(xyz[i])) {
            const std::string value = format_number(xyz[i]);
            const auto v = static_cast<std::uint32_t>(i / 3);
            const char* axis = i % 3 == 0 ? "x" : i % 3 == 1 ? "y" : "z";
            throw NonFiniteCoordinate(
                "point " + std::to_string(v) + ": non-finite " + axis + " coordinate " + value, v);
        }
    }
}

namespace detail {

namespace {

/// The insertion order of options, once the points are known to be valid.
std::vector<VertIdx> validated_order(std::span<const double> xyz, const Delaunay3Options& options) {
    validate_points_3d(xyz);
    return insertion_order_3d(xyz, options.order, options.seed);
}

}  // namespace

Delaunay3Core::Delaunay3Core(std::span<const double> xyz, const Delaunay3Options& options)
    : Delaunay3Core(xyz, validated_order(xyz, options),
                    // About 6.7 tetrahedra per point for uniform points, plus the hull's
                    // infinite ones.
                    7 * (xyz.size() / 3) + 64) {}

Delaunay3Core::Delaunay3Core(std::span<const double> xyz, std::vector<VertIdx> order,
                             std::size_t reserved_tets)
    : input_index(std::move(order)) {
    const auto n = static_cast<std::uint32_t>(xyz.size() / 3);
    mesh.xyz.resize(xyz.size());
    for (std::uint32_t v = 0; v < n; ++v) {
        const std::size_t from = 3 * std::size_t{input_index[v]};
        mesh.xyz[3 * std::size_t{v}] = xyz[from];
        mesh.xyz[3 * std::size_t{v} + 1] = xyz[from + 1];
        mesh.xyz[3 * std::size_t{v} + 2] = xyz[from + 2];
    }
    merged_into.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) merged_into[i] = i;
    counters.points = n;
    star.closed = true;  // kInfinite closes the mesh: every face has a twin
    mesh.tv.reserve(4 * reserved_tets);
    mesh.adj.reserve(4 * reserved_tets);
    // With 4 KiB pages the first-touch faults and TLB misses of the mesh arrays cost about a
    // fifth of a construction.
    advise_huge_pages(mesh.tv);
    advise_huge_pages(mesh.adj);
}

Sign Delaunay3Core::orient(VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
    ++counters.orient_calls;
    return predicates::orient3d(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
}

Sign Delaunay3Core::orient_replacing(TetIdx t, unsigned k, VertIdx p) {
    const VertIdx* v = &mesh.tv[4 * std::size_t{t}];
    const unsigned* f = kFaceVertex[k];
    return orient(v[f[0]], v[f[1]], v[f[2]], p);
}

Sign ConflictTest3::insphere_tie(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p) {
    return predicates::insphere_sos(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d),
                                    mesh.point(p), input_index[a], input_index[b], input_index[c],
                                    input_index[d], input_index[p]);
}

Sign ConflictTest3::insphere_unfiltered(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p) {
    const Sign s = predicates::insphere_exact(mesh.point(a), mesh.point(b), mesh.point(c),
                                              mesh.point(d), mesh.point(p));
    return s != Sign::Zero ? s : insphere_tie(a, b, c, d, p);
}

bool ConflictTest3::conflict_infinite(TetIdx t, VertIdx p) {
    const VertIdx* v = &mesh.tv[4 * std::size_t{t}];
    constexpr unsigned m = kInfiniteSlot;
    const unsigned* f = kFaceVertex[m];
    ++counters.orient_calls;
    const Sign side = predicates::orient3d(mesh.point(v[f[0]]), mesh.point(v[f[1]]),
                                           mesh.point(v[f[2]]), mesh.point(p));
    if (side != Sign::Zero) return side == Sign::Positive;
    // p lies in the plane of the hull face: the sphere through the face and the apex x of the
    // finite tetrahedron behind it meets that plane in the face's circumcircle, so the
    // perturbed insphere with x decides "inside the perturbed circumcircle" (x's own
    // perturbation term is orient3d(face, p) = 0 and drops out). t with kInfinite replaced by
    // x is negative; swapping two of its finite vertices makes it positive.
    // (The tetrahedron behind may carry a cavity mark in its slot 1: masked.)
    const FaceIdx behind = mesh.adj[4 * std::size_t{t} + m];
    const VertIdx x = mesh.tv[behind] & kVertexBits;
    return insphere(v[1], v[0], v[2], x, p) == Sign::Positive;
}

bool Delaunay3Core::same_point(VertIdx a, VertIdx b) const {
    const double* p = mesh.point(a);
    const double* q = mesh.point(b);
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

namespace {

/// True when the finite points a, b, c are collinear: every coordinate projection is.
bool collinear(const double* a, const double* b, const double* c) {
    for (int drop = 0; drop < 3; ++drop) {
        const int i = (drop + 1) % 3, j = (drop + 2) % 3;
        const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
        if (predicates::orient2d(pa, pb, pc) != Sign::Zero) return false;
    }
    return true;
}

}  // namespace

bool Delaunay3Core::make_first_tet(std::vector<bool>& skip) {
    const std::uint32_t n = mesh.vertex_count();
    skip.assign(n, false);
    if (n == 0) return false;
    const VertIdx v0 = 0;
    VertIdx v1 = kNone, v2 = kNone, v3 = kNone;
    for (VertIdx v = 1; v < n && v1 == kNone; ++v) {
        if (!same_point(v0, v)) v1 = v;
    }
    if (v1 == kNone) return false;
    for (VertIdx v = v1 + 1; v < n && v2 == kNone; ++v) {
        if (!collinear(mesh.point(v0), mesh.point(v1), mesh.point(v))) v2 = v;
    }
    if (v2 == kNone) return false;
    for (VertIdx v = v2 + 1; v < n && v3 == kNone; ++v) {
        if (orient(v0, v1, v2, v) != Sign::Zero) v3 = v;
    }
    if (v3 == kNone) return false;
    skip[v0] = skip[v1] = skip[v2] = skip[v3] = true;
    VertIdx a = v0, b = v1, c = v2, d = v3;
    if (orient(a, b, c, d) == Sign::Negative) std::swap(c, d);
    const TetIdx t = mesh.new_tet();
    const VertIdx finite[4] = {a, b, c, d};
    std::copy(finite, finite + 4, &mesh.tv[4 * std::size_t{t}]);
    // Behind face k: t with vertex k replaced by kInfinite, two other vertices swapped so that
    // the hull face is seen from outside (kInfinite on its positive side), then kInfinite moved
    // to slot 3 by an even permutation (two transpositions).
    TetIdx outer[4];
    for (unsigned k = 0; k < 4; ++k) {
        outer[k] = mesh.new_tet();
        VertIdx w[4] = {a, b, c, d};
        w[k] = kInfinite;
        std::swap(w[(k + 1) % 4], w[(k + 2) % 4]);
        if (k != 3) {
            std::swap(w[k], w[3]);
            const unsigned i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;  // the two slots besides k, 3
            std::swap(w[i], w[j]);
        }
        std::copy(w, w + 4, &mesh.tv[4 * std::size_t{outer[k]}]);
        mesh.link(4 * t + k, 4 * outer[k] + kInfiniteSlot);
    }
    // Infinite tetrahedra k and j meet at the face holding kInfinite and the two finite
    // vertices other than finite[k] and finite[j]: in outer[k] it is the face opposite
    // finite[j], in outer[j] the face opposite finite[k].
    for (unsigned k = 0; k < 4; ++k) {
        for (unsigned j = k + 1; j < 4; ++j) {
            const unsigned in_k = mesh.slot_of(outer[k], finite[j]);
            const unsigned in_j = mesh.slot_of(outer[j], finite[k]);
            mesh.link(4 * outer[k] + in_k, 4 * outer[j] + in_j);
        }
    }
    star.grow_stamps(mesh);
    last_tet = t;
    return true;
}

Delaunay3Core::Location Delaunay3Core::walk_to(VertIdx p) {
    TetIdx t = last_tet;
    if (t == kNone || mesh.is_dead(t)) {
        for (t = 0; mesh.is_dead(t); ++t) {
        }
    }
    if (mesh.is_infinite(t)) t = tet_of(mesh.adj[4 * std::size_t{t} + kInfiniteSlot]);
    const Location where = walk_3d(mesh, t, p, rng_state_, counters, [](TetIdx) { return true; });
    last_tet = t;
    return where;
}

VertIdx duplicate_vertex(const TetMesh3& mesh, const Location3& where) {
    if (where.zero_faces == 0 || std::popcount(where.zero_faces) != 3) return kNone;
    // On three face planes of a closed tetrahedron: p is the vertex they share.
    const unsigned k = static_cast<unsigned>(std::countr_zero(~where.zero_faces & 15u));
    return mesh.tv[4 * std::size_t{where.tet} + k] & kVertexBits;
}

Delaunay3Core::Location Delaunay3Core::locate(VertIdx p) {
    const Location where = walk_to(p);
    const VertIdx v = duplicate_vertex(mesh, where);
    if (v != kNone) {
        EM_ASSERT(same_point(v, p));
        merged_into[input_index[p]] = input_index[v];
        ++counters.duplicates;
        return {kNone, 0};
    }
    return where;
}

Delaunay3Result Delaunay3Core::take_result(std::span<const double> xyz, std::size_t chunks,
                                           const ChunkRunner& run) {
    Delaunay3Result out;
    out.counters = counters;
    std::vector<VertIdx>& first = input_index;  // mesh vertex -> reported caller index
    if (counters.duplicates > 0) report_first_occurrence(merged_into, first);
    out.merged_into = std::move(merged_into);
    // Number the finite tetrahedra, then compact tv and adj in place (output index <= slot).
    std::vector<TetIdx>& output_index = star.stamp;  // reused
    const TetIdx count = compact_cells<4>(
        mesh, mesh.tv, mesh.adj, first, output_index, mesh.tet_slots(), chunks, run,
        [&output_index](FaceIdx across) { return output_index[tet_of(across)]; });
    mesh.tv.resize(4 * std::size_t{count});
    mesh.adj.resize(4 * std::size_t{count});
    out.mesh.tets = std::move(mesh.tv);
    out.mesh.neighbors = std::move(mesh.adj);
    std::vector<std::uint32_t>().swap(star.stamp);
    // The caller's points, copied in order: a sequential copy is cheaper than carrying the
    // insertion-ordered copy back through the permutation (a random scatter).
    mesh = TetMesh3{};
    out.mesh.xyz.assign(xyz.begin(), xyz.end());
    return out;
}

Delaunay3Result Delaunay3Core::coplanar_result(std::span<const double> xyz) {
    std::vector<VertIdx> by_point(mesh.vertex_count());
    for (VertIdx v = 0; v < by_point.size(); ++v) by_point[v] = v;
    std::sort(by_point.begin(), by_point.end(), [this](VertIdx a, VertIdx b) {
        const double* p = mesh.point(a);
        const double* q = mesh.point(b);
        if (p[0] != q[0]) return p[0] < q[0];
        if (p[1] != q[1]) return p[1] < q[1];
        if (p[2] != q[2]) return p[2] < q[2];
        return input_index[a] < input_index[b];
    });
    for (std::size_t i = 1; i < by_point.size(); ++i) {
        if (same_point(by_point[i - 1], by_point[i])) {
            merged_into[input_index[by_point[i]]] = merged_into[input_index[by_point[i - 1]]];
            ++counters.duplicates;
        }
    }
    Delaunay3Result out = take_result(xyz);
    out.coplanar = true;
    return out;
}

}  // namespace detail
}  // namespace exactmesh::triangulation
