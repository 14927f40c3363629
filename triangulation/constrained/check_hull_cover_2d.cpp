// SPDX-License-Identifier: MIT
// The convex hull less the holes (see check_hull_cover_2d.hpp).
#include "triangulation/constrained/check_hull_cover_2d.hpp"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <string>
#include <unordered_set>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/locate_2d.hpp"

namespace exactmesh::triangulation {

namespace {

CheckReport fail(std::string problem, std::vector<VertIdx> vertices = {}) {
    CheckReport report;
    report.ok = false;
    report.problem = std::move(problem);
    report.vertices = std::move(vertices);
    return report;
}

std::uint64_t directed(VertIdx a, VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

/// The directed edges (a, b) of the triangles `keep` accepts whose reverse (b, a) is in no
/// kept triangle: the boundary of their union, counter-clockwise around it. Sorted.
template <class Keep>
std::vector<std::uint64_t> boundary_edges(const Triangulation2& mesh, Keep&& keep) {
    std::unordered_set<std::uint64_t> edges;
    for (TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        if (!keep(t)) continue;
        for (int k = 0; k < 3; ++k)
            edges.insert(directed(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]));
    }
    std::vector<std::uint64_t> out;
    for (const std::uint64_t e : edges) {
        if (!edges.contains(
                directed(static_cast<VertIdx>(e & 0xFFFFFFFFu), static_cast<VertIdx>(e >> 32))))
            out.push_back(e);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

CheckReport check_hull_cover_2d(const Triangulation2& mesh, std::span<const double> holes,
                                CheckNumbering numbering) {
    const auto name = [&](VertIdx v) {
        return std::to_string(std::uint64_t{v} + numbering.first_vertex);
    };
    // The constrained edges, once each: the reference's segments.
    std::vector<VertIdx> edges;
    {
        std::unordered_set<std::uint64_t> seen;
        for (TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            for (int k = 0; k < 3; ++k) {
                if (!mesh.is_constrained(t, k)) continue;
                VertIdx a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
                if (a > b) std::swap(a, b);
                if (seen.insert(directed(a, b)).second) edges.insert(edges.end(), {a, b});
            }
        }
    }
    // The reference: the same vertices and constrained edges over the whole hull, checked.
    Cdt2Options options;
    options.remove_exterior = false;
    Cdt2Result full;
    try {
        full = constrained_delaunay_2d(Pslg{mesh.xy, edges, {}, {}}, options);
    } catch (const InputError& error) {
        return fail(std::string("the constrained edges make no triangulation of the hull: ") +
                    error.what());
    }
    const Triangulation2& reference = full.mesh;
    if (reference.vertex_count() != mesh.vertex_count())
        return fail(
            "the constrained edges cross or pass through vertices (their triangulation "
            "over the hull needed " +
            std::to_string(reference.vertex_count() - mesh.vertex_count()) + " more vertices)");
    const CheckReport exact =
        check_constrained_delaunay_2d(reference, mesh.vertex_count(), edges, {}, numbering);
    if (!exact.ok) {
        throw InternalError(
            "check_hull_cover_2d: the reference triangulation fails its exact "
            "check: " +
            exact.problem);
    }
    std::vector<std::uint8_t> constrained_end(mesh.vertex_count(), 0);
    for (const VertIdx v : edges) constrained_end[v] = 1;
    // Less what each hole point reaches without crossing a constrained edge.
    std::vector<std::uint8_t> removed(reference.triangle_count(), 0);
    const TriangleLocator2 locator(reference);
    std::vector<TriIdx> stack;
    for (std::size_t h = 0; 2 * h + 1 < holes.size(); ++h) {
        const double q[2] = {holes[2 * h], holes[2 * h + 1]};
        const TriIdx t = locator.locate(reference, q[0], q[1]);
        if (t == kNone) continue;  // outside the hull: the producer ignores it too
        const auto hole = [&] {
            return "hole point " + std::to_string(h + numbering.first_vertex) + " " +
                   format_point(q);
        };
        for (int k = 0; k < 3; ++k) {
            const VertIdx a = reference.triangles[3 * t + k];
            const VertIdx b = reference.triangles[3 * t + (k + 1) % 3];
            // On a vertex a constrained edge ends at, or on a constrained edge: which side is
            // the hole is ambiguous (the producer refuses it). A free vertex has one side.
            if (reference.point(a)[0] == q[0] && reference.point(a)[1] == q[1] &&
                constrained_end[a] != 0)
                return fail(hole() + " is vertex " + name(a) +
                                ", where a constrained edge ends: it "
                                "names no side",
                            {a});
            if (reference.is_constrained(t, k) &&
                predicates::orient2d(reference.point(a), reference.point(b), q) ==
                    predicates::Sign::Zero)
                return fail(hole() + " lies on the constrained edge (" + name(std::min(a, b)) +
                                ", " + name(std::max(a, b)) + "): it names no side",
                            {a, b});
        }
        if (removed[t] != 0) continue;
        removed[t] = 1;
        stack.push_back(t);
        while (!stack.empty()) {
            const TriIdx u = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                const TriIdx n = reference.neighbors[3 * u + k];
                if (n == kNone || reference.is_constrained(u, k) || removed[n] != 0) continue;
                removed[n] = 1;
                stack.push_back(n);
            }
        }
    }
    // One vertex set: the same region exactly when the same boundary edges.
    const std::vector<std::uint64_t> have = boundary_edges(mesh, [](TriIdx) { return true; });
    const std::vector<std::uint64_t> want =
        boundary_edges(reference, [&](TriIdx t) { return removed[t] == 0; });
    if (have == want) return {};
    std::vector<std::uint64_t> only_have, only_want;
    std::set_difference(have.begin(), have.end(), want.begin(), want.end(),
                        std::back_inserter(only_have));
    std::set_difference(want.begin(), want.end(), have.begin(), have.end(),
                        std::back_inserter(only_want));
    const bool extra = !only_have.empty();
    const std::uint64_t e = extra ? only_have.front() : only_want.front();
    const auto a = static_cast<VertIdx>(e >> 32), b = static_cast<VertIdx>(e & 0xFFFFFFFFu);
    return fail("edge (" + name(a) + ", " + name(b) + ") " +
                    (extra ? "bounds the mesh but not the convex hull less the holes"
                           : "bounds the convex hull less the holes but not the mesh") +
                    " (" + std::to_string(only_have.size()) + " edges bound only the mesh, " +
                    std::to_string(only_want.size()) +
                    " only the hull less the holes: a hole region kept, or a region removed "
                    "with no hole point in it)",
                {a, b});
}

}  // namespace exactmesh::triangulation
