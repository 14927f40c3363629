// SPDX-License-Identifier: MIT
// A given 2D triangle mesh as the start of an adaptive run (see mesh_input_2d.hpp).
#include "generators/adaptation/mesh_input_2d.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using predicates::Sign;
using tri::kNone;
using tri::TriIdx;
using tri::VertIdx;

namespace {

constexpr int kUnknownWinding = std::numeric_limits<int>::min();

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

/// The winding number of the boundary (segments, the mesh on their left) on every triangle of
/// `cdt`, propagated from the CDT's own boundary (where the outside, reached from infinity
/// without crossing a segment, winds 0 times). Every constrained edge of `cdt` is a segment.
std::vector<int> boundary_winding(const tri::Triangulation2& cdt,
                                  const std::vector<std::uint64_t>& sorted_segments) {
    const auto is_segment = [&](VertIdx a, VertIdx b) {
        return std::binary_search(sorted_segments.begin(), sorted_segments.end(), edge_key(a, b));
    };
    // The change of the winding number from triangle t to the other side of its edge k.
    const auto step_across = [&](TriIdx t, int k) {
        if (!cdt.is_constrained(t, k)) return 0;
        const VertIdx u = cdt.triangles[3 * std::size_t{t} + static_cast<std::size_t>(k)];
        const VertIdx w = cdt.triangles[3 * std::size_t{t} + static_cast<std::size_t>((k + 1) % 3)];
        if (is_segment(u, w)) return -1;  // t on the segment's left: leaving the mesh side
        EM_ASSERT(is_segment(w, u));
        return 1;
    };
    const TriIdx count = cdt.triangle_count();
    std::vector<int> winding(count, kUnknownWinding);
    std::vector<TriIdx> stack;
    const auto assign = [&](TriIdx t, int value) {
        if (winding[t] == kUnknownWinding) {
            winding[t] = value;
            stack.push_back(t);
        } else if (winding[t] != value) {
            // A boundary made of closed cycles gives one value per triangle.
            throw InputError("the mesh's boundary edges do not form closed cycles");
        }
    };
    for (TriIdx t = 0; t < count; ++t)
        for (int k = 0; k < 3; ++k)
            if (cdt.neighbors[3 * std::size_t{t} + static_cast<std::size_t>(k)] == kNone) {
                // The exterior was removed up to segments only: this side is one.
                EM_ASSERT(cdt.is_constrained(t, k));
                assign(t, -step_across(t, k));
            }
    while (!stack.empty()) {
        const TriIdx t = stack.back();
        stack.pop_back();
        for (int k = 0; k < 3; ++k) {
            const TriIdx other = cdt.neighbors[3 * std::size_t{t} + static_cast<std::size_t>(k)];
            if (other != kNone) assign(other, winding[t] + step_across(t, k));
        }
    }
    return winding;
}

/// A point strictly inside one of `triangles` of `cdt` (exact orient2d): the rounded centroid
/// of the first triangle that contains its own; false when rounding puts every one out.
bool point_inside_one_of(const tri::Triangulation2& cdt, const std::vector<TriIdx>& triangles,
                         std::array<double, 2>& point) {
    for (const TriIdx t : triangles) {
        const double* a = cdt.point(cdt.triangles[3 * std::size_t{t}]);
        const double* b = cdt.point(cdt.triangles[3 * std::size_t{t} + 1]);
        const double* c = cdt.point(cdt.triangles[3 * std::size_t{t} + 2]);
        // Each coordinate divided first: no overflow near the largest doubles; the point is
        // only a candidate, checked exactly below.
        point = {a[0] / 3 + b[0] / 3 + c[0] / 3, a[1] / 3 + b[1] / 3 + c[1] / 3};
        const double* p = point.data();
        if (predicates::orient2d(a, b, p) == Sign::Positive &&
            predicates::orient2d(b, c, p) == Sign::Positive &&
            predicates::orient2d(c, a, p) == Sign::Positive)
            return true;
    }
    return false;
}

/// The triangles as sorted corner triples (each rotated to start at its least vertex).
std::vector<std::array<VertIdx, 3>> canonical_triangles(const std::vector<VertIdx>& triangles) {
    std::vector<std::array<VertIdx, 3>> out;
    out.reserve(triangles.size() / 3);
    for (std::size_t t = 0; 3 * t < triangles.size(); ++t) {
        std::array<VertIdx, 3> c{triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]};
        std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
        out.push_back(c);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

GivenMeshDomain2 given_mesh_domain_2d(std::vector<double> xy, std::vector<VertIdx> triangles,
                                      tri::CheckNumbering numbering) {
    GivenMeshDomain2 domain;
    tri::Triangulation2& mesh = domain.mesh;
    mesh.xy = std::move(xy);
    mesh.triangles = std::move(triangles);
    const auto vertex_name = [&](std::uint64_t v) {
        return "vertex " + std::to_string(v + numbering.first_vertex);
    };
    if (mesh.triangles.empty()) throw InputError("the mesh has no triangle");
    // Counter-clockwise (exact), each directed edge once, indices in range.
    tri::link_neighbors_2d(mesh, numbering);
    const VertIdx n = mesh.vertex_count();
    std::vector<std::uint8_t> used(n, 0);
    for (const VertIdx v : mesh.triangles) used[v] = 1;
    for (VertIdx v = 0; v < n; ++v)
        if (used[v] == 0)
            throw InputError(vertex_name(v) + " " + format_point(mesh.point(v)) +
                             " is used by no triangle (a mesh to adapt uses every vertex)");

    // The boundary: the sides with no triangle across, flagged as constraints.
    mesh.constrained.assign(mesh.triangles.size(), 0);
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        if (mesh.neighbors[e] != kNone) continue;
        mesh.constrained[e] = 1;
        domain.segments.insert(domain.segments.end(),
                               {mesh.triangles[e], mesh.triangles[e % 3 == 2 ? e - 2 : e + 1]});
    }
    // No fold at any vertex: the mesh is locally injective (the header's argument).
    if (const tri::CheckReport report =
            tri::check_conforming_mesh_2d(mesh, n, domain.segments, {}, numbering);
        !report.ok)
        throw InputError("not a valid triangle mesh: " + report.problem);

    // The CDT of the boundary alone keeps every boundary edge whole, or the boundary touches
    // or crosses itself.
    tri::Cdt2Options options;
    options.first_index = numbering.first_vertex;
    const tri::Pslg boundary{mesh.xy, domain.segments, {}, {}};
    const tri::Cdt2Result outer = tri::constrained_delaunay_2d(boundary, options);
    for (VertIdx v = 0; v < n; ++v)
        if (outer.merged_into[v] != v)
            throw InputError(vertex_name(v) + " and " + vertex_name(outer.merged_into[v]) +
                             " are the same point " + format_point(mesh.point(v)));
    if (outer.mesh.vertex_count() != n || outer.pieces.size() != domain.segments.size()) {
        throw InputError(
            "the mesh's boundary touches or crosses itself away from its vertices" +
            (outer.warnings.empty() ? std::string() : " (" + outer.warnings.front() + ")"));
    }

    std::vector<std::uint64_t> sorted_segments;
    sorted_segments.reserve(domain.segments.size() / 2);
    for (std::size_t s = 0; s < domain.segments.size(); s += 2)
        sorted_segments.push_back(edge_key(domain.segments[s], domain.segments[s + 1]));
    std::sort(sorted_segments.begin(), sorted_segments.end());
    const std::vector<int> winding = boundary_winding(outer.mesh, sorted_segments);
    std::size_t covered = 0;
    for (TriIdx t = 0; t < outer.mesh.triangle_count(); ++t) {
        if (winding[t] == 1) {
            ++covered;
        } else if (winding[t] != 0) {
            throw InputError("the mesh covers the triangle (" +
                             vertex_name(outer.mesh.triangles[3 * std::size_t{t}]) + ", " +
                             vertex_name(outer.mesh.triangles[3 * std::size_t{t} + 1]) + ", " +
                             vertex_name(outer.mesh.triangles[3 * std::size_t{t} + 2]) + ") " +
                             std::to_string(winding[t]) +
                             " times (its boundary winds so around it): it overlaps itself");
        }
    }

    // One point in each hole: each set of winding-0 triangles joined across unconstrained edges.
    std::vector<std::uint8_t> visited(outer.mesh.triangle_count(), 0);
    std::vector<TriIdx> hole, stack;
    for (TriIdx start = 0; start < outer.mesh.triangle_count(); ++start) {
        if (winding[start] != 0 || visited[start] != 0) continue;
        hole.clear();
        stack.assign(1, start);
        visited[start] = 1;
        while (!stack.empty()) {
            const TriIdx t = stack.back();
            stack.pop_back();
            hole.push_back(t);
            for (int k = 0; k < 3; ++k) {
                const TriIdx other =
                    outer.mesh.neighbors[3 * std::size_t{t} + static_cast<std::size_t>(k)];
                if (other == kNone || outer.mesh.is_constrained(t, k) || visited[other] != 0)
                    continue;
                visited[other] = 1;
                stack.push_back(other);
            }
        }
        std::array<double, 2> point{};
        if (!point_inside_one_of(outer.mesh, hole, point))
            throw GeometryError("no point strictly inside the hole at " +
                                vertex_name(outer.mesh.triangles[3 * std::size_t{start}]) +
                                " survives rounding: the hole is too thin to name");
        domain.holes.insert(domain.holes.end(), point.begin(), point.end());
    }

    // The domain with its holes: exactly the winding-1 triangles of the CDT above remain.
    domain.cdt =
        tri::constrained_delaunay_2d({mesh.xy, domain.segments, domain.holes, {}}, options);
    EM_ASSERT(domain.cdt.mesh.triangle_count() == covered && domain.cdt.mesh.vertex_count() == n &&
              domain.cdt.input_vertex_count == n);
    domain.mesh_is_cdt =
        canonical_triangles(domain.cdt.mesh.triangles) == canonical_triangles(mesh.triangles);
    return domain;
}

tri::Cdt2Result given_mesh_result_2d(const GivenMeshDomain2& domain) {
    tri::Cdt2Result result;
    result.mesh = domain.mesh;
    const VertIdx n = domain.mesh.vertex_count();
    result.input_vertex_count = n;
    result.merged_into.resize(n);
    for (VertIdx v = 0; v < n; ++v) result.merged_into[v] = v;
    result.pieces = domain.segments;
    for (std::uint32_t s = 0; 2 * std::size_t{s} < domain.segments.size(); ++s)
        result.piece_segment.push_back(s);
    return result;
}

}  // namespace exactmesh::generators
