// SPDX-License-Identifier: MIT
// Exact topology and orientation check of a Tetrahedralization3 (see check_topology_3d.hpp).
#include "triangulation/checks/check_topology_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "predicates/orient3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

std::string name(std::uint64_t v) {
    return std::to_string(v);
}

TopologyReport3 fail(TopologyReport3 report, std::string problem, TetIdx t,
                     std::vector<VertIdx> vertices) {
    report.ok = false;
    report.problem = std::move(problem);
    report.tet = t;
    report.vertices = std::move(vertices);
    return report;
}

std::array<VertIdx, 3> face_of(const Tetrahedralization3& mesh, std::size_t t, unsigned k) {
    const unsigned* lf = kFaceVertex[k];
    return {mesh.tets[4 * t + lf[0]], mesh.tets[4 * t + lf[1]], mesh.tets[4 * t + lf[2]]};
}

bool same_oriented(std::array<VertIdx, 3> x, std::array<VertIdx, 3> y) {
    for (int r = 0; r < 3; ++r) {
        if (x == y) return true;
        std::rotate(y.begin(), y.begin() + 1, y.end());
    }
    return false;
}

}  // namespace

TopologyReport3 check_topology_3d(const Tetrahedralization3& mesh, TopologyOptions options) {
    TopologyReport3 report;
    if (mesh.xyz.size() % 3 != 0)
        return fail(report, "coordinate array length is not a multiple of 3", kNone, {});
    if (mesh.tets.size() % 4 != 0)
        return fail(report, "tetrahedron array length is not a multiple of 4", kNone, {});
    if (mesh.neighbors.size() != mesh.tets.size()) {
        return fail(report,
                    "neighbor array has " + name(mesh.neighbors.size()) + " entries for " +
                        name(mesh.tets.size() / 4) + " tetrahedra",
                    kNone, {});
    }
    const std::size_t n = mesh.xyz.size() / 3, count = mesh.tets.size() / 4;
    for (std::size_t i = 0; i < mesh.xyz.size(); ++i) {
        if (!std::isfinite(mesh.xyz[i])) {
            return fail(report, "vertex " + name(i / 3) + " has a non-finite coordinate", kNone,
                        {static_cast<VertIdx>(i / 3)});
        }
    }
    for (std::size_t t = 0; t < count; ++t) {
        const VertIdx* v = &mesh.tets[4 * t];
        const auto tet = static_cast<TetIdx>(t);
        for (unsigned k = 0; k < 4; ++k) {
            if (v[k] >= n) {
                return fail(report,
                            "tetrahedron " + name(t) + ": vertex " + name(v[k]) + " out of range",
                            tet, {v[k]});
            }
            for (unsigned j = 0; j < k; ++j) {
                if (v[j] == v[k])
                    return fail(report, "tetrahedron " + name(t) + " repeats vertex " + name(v[k]),
                                tet, {v[k]});
            }
        }
        const Sign s = predicates::orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                            mesh.point(v[3]));
        if (s != Sign::Positive) {
            return fail(report,
                        "tetrahedron " + name(t) + " (" + name(v[0]) + ", " + name(v[1]) + ", " +
                            name(v[2]) + ", " + name(v[3]) + ") is " +
                            (s == Sign::Zero ? "flat" : "negatively oriented"),
                        tet, {v[0], v[1], v[2], v[3]});
        }
    }
    // Faces by vertex set: shared by at most two, and linked exactly when shared.
    const std::vector<KeyedFace3> entries = sorted_faces_3d(mesh.tets);
    std::vector<std::uint32_t> shared_with(mesh.tets.size(), kNone);
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i + 1;
        while (j < entries.size() && entries[j].key == entries[i].key) ++j;
        const auto& key = entries[i].key;
        if (j - i > 2) {
            return fail(report,
                        "face (" + name(key[0]) + ", " + name(key[1]) + ", " + name(key[2]) +
                            ") is shared by " + name(j - i) + " tetrahedra",
                        entries[i].face / 4, {key[0], key[1], key[2]});
        }
        if (j - i == 2) {
            const std::uint32_t f = entries[i].face, g = entries[i + 1].face;
            auto back = face_of(mesh, g / 4, g % 4);
            std::swap(back[1], back[2]);
            if (!same_oriented(face_of(mesh, f / 4, f % 4), back)) {
                return fail(report,
                            "tetrahedra " + name(f / 4) + " and " + name(g / 4) +
                                " lie on the same side of their face (" + name(key[0]) + ", " +
                                name(key[1]) + ", " + name(key[2]) + ")",
                            f / 4, {key[0], key[1], key[2]});
            }
            shared_with[f] = g / 4;
            shared_with[g] = f / 4;
            ++report.interior_faces;
        } else {
            ++report.boundary_faces;
        }
        i = j;
    }
    for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
        if (mesh.neighbors[f] != shared_with[f]) {
            const auto face = face_of(mesh, f / 4, f % 4);
            const std::string expected = shared_with[f] == kNone
                                             ? std::string("none (a boundary face)")
                                             : "tetrahedron " + name(shared_with[f]);
            const std::string given = mesh.neighbors[f] == kNone
                                          ? std::string("none")
                                          : "tetrahedron " + name(mesh.neighbors[f]);
            return fail(report,
                        "tetrahedron " + name(f / 4) + ": the neighbor across face (" +
                            name(face[0]) + ", " + name(face[1]) + ", " + name(face[2]) + ") is " +
                            given + ", expected " + expected,
                        static_cast<TetIdx>(f / 4), {face[0], face[1], face[2]});
        }
    }
    // The boundary: every directed boundary edge matched by its reverse as often as it is used.
    // Once each where the boundary is a manifold surface; a domain that touches itself along an
    // edge (two boxes sharing only an edge) has that edge in four boundary faces, twice in each
    // direction, and is still closed.
    struct Half {
        VertIdx from, to;
        std::uint32_t facet;
    };
    std::vector<Half> halves;
    for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
        if (shared_with[f] != kNone) continue;
        const auto face = face_of(mesh, f / 4, f % 4);
        for (int e = 0; e < 3; ++e)
            halves.push_back({face[e], face[(e + 1) % 3], static_cast<std::uint32_t>(f)});
    }
    auto less = [](const Half& x, const Half& y) {
        return x.from != y.from ? x.from < y.from : x.to < y.to;
    };
    std::vector<Half> sorted = halves;
    std::sort(sorted.begin(), sorted.end(), less);
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        while (j < sorted.size() && sorted[j].from == sorted[i].from &&
               sorted[j].to == sorted[i].to)
            ++j;
        const Half reverse{sorted[i].to, sorted[i].from, 0};
        const auto lo = std::lower_bound(sorted.begin(), sorted.end(), reverse, less);
        const auto hi = std::upper_bound(lo, sorted.end(), reverse, less);
        if (hi - lo != static_cast<std::ptrdiff_t>(j - i) && hi != lo) {
            return fail(report,
                        "boundary edge (" + name(sorted[i].from) + ", " + name(sorted[i].to) +
                            ") is used " + std::to_string(j - i) + " times in one direction and " +
                            std::to_string(hi - lo) + " in the other (the boundary is not closed)",
                        sorted[i].facet / 4, {sorted[i].from, sorted[i].to});
        }
        if (options.convex_boundary && j - i > 1) {
            return fail(report,
                        "boundary edge (" + name(sorted[i].from) + ", " + name(sorted[i].to) +
                            ") is used twice in the same direction (the boundary is not a manifold "
                            "surface)",
                        sorted[i].facet / 4, {sorted[i].from, sorted[i].to});
        }
        i = j;
    }
    for (const Half& h : halves) {
        const Half reverse{h.to, h.from, 0};
        const auto it = std::lower_bound(sorted.begin(), sorted.end(), reverse, less);
        if (it == sorted.end() || it->from != h.to || it->to != h.from) {
            return fail(report,
                        "boundary edge (" + name(h.from) + ", " + name(h.to) +
                            ") has a boundary face on one side only",
                        h.facet / 4, {h.from, h.to});
        }
        if (options.convex_boundary) {
            // The face across the edge must not bend outward: its third vertex is not beyond
            // the plane of this face (seen from outside, counter-clockwise).
            const auto face = face_of(mesh, h.facet / 4, h.facet % 4);
            const auto other = face_of(mesh, it->facet / 4, it->facet % 4);
            VertIdx apex = kNone;
            for (const VertIdx v : other) {
                if (v != h.from && v != h.to) apex = v;
            }
            if (predicates::orient3d(mesh.point(face[0]), mesh.point(face[1]), mesh.point(face[2]),
                                     mesh.point(apex)) == Sign::Negative) {
                return fail(
                    report,
                    "the boundary is not convex at edge (" + name(h.from) + ", " + name(h.to) + ")",
                    h.facet / 4, {h.from, h.to, apex});
            }
        }
    }
    return report;
}

}  // namespace exactmesh::triangulation
