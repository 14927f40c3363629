// SPDX-License-Identifier: MIT
// Exact local Delaunay counts of a Tetrahedralization3 for the 3D swapping and removal tests:
// interior faces whose far apex lies strictly inside the near tetrahedron's circumsphere (plain
// exact insphere: cospherical is Delaunay), or inside by insphere_sos (ties broken by index).
// A tetrahedralization of the convex hull with no such face is Delaunay [Delaunay34 lemma].
#pragma once

#include <cstdint>

#include "predicates/insphere.hpp"
#include "predicates/sos.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::testing {

struct LocalDelaunayCount {
    std::uint64_t interior_faces = 0;
    std::uint64_t not_delaunay = 0;      ///< exact insphere > 0
    std::uint64_t not_delaunay_sos = 0;  ///< insphere_sos > 0
};

inline LocalDelaunayCount count_local_delaunay_3d(const triangulation::Tetrahedralization3& mesh) {
    using predicates::Sign;
    LocalDelaunayCount count;
    for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
        const std::uint32_t u = mesh.neighbors[f];
        const std::size_t t = f / 4;
        if (u == triangulation::kNone || u < t) continue;
        ++count.interior_faces;
        // The apex of u across: its vertex not in t.
        std::uint32_t e = triangulation::kNone;
        for (unsigned j = 0; j < 4; ++j) {
            const std::uint32_t w = mesh.tets[4 * std::size_t{u} + j];
            bool in_t = false;
            for (unsigned k = 0; k < 4; ++k) in_t = in_t || mesh.tets[4 * t + k] == w;
            if (!in_t) e = w;
        }
        const std::uint32_t* v = &mesh.tets[4 * t];
        if (predicates::insphere(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                 mesh.point(v[3]), mesh.point(e)) == Sign::Positive) {
            ++count.not_delaunay;
        }
        if (predicates::insphere_sos(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                     mesh.point(v[3]), mesh.point(e), v[0], v[1], v[2], v[3],
                                     e) == Sign::Positive) {
            ++count.not_delaunay_sos;
        }
    }
    return count;
}

}  // namespace exactmesh::testing
