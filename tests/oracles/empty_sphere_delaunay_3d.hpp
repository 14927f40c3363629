// SPDX-License-Identifier: MIT
// The Delaunay tetrahedralization by its definition, for tiny point sets: every 4 affinely
// independent points whose circumsphere holds no other point, by insphere_sos (ties broken by
// index, as everywhere in exactmesh, so the answer is unique even for cospherical points).
// O(n^5): a test oracle for a few dozen points, sharing no code with the flip algorithms.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <set>
#include <span>
#include <vector>

#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"

namespace exactmesh::oracles {

/// Each tetrahedron's vertex indices sorted increasingly.
using TetSet = std::set<std::array<std::uint32_t, 4>>;

/// Over the vertices in `active` only (increasing indices into xyz, which stay the SoS ranks).
inline TetSet empty_sphere_delaunay_3d(std::span<const double> xyz,
                                       const std::vector<std::uint32_t>& active) {
    using predicates::Sign;
    auto p = [&](std::uint32_t v) { return xyz.data() + 3 * std::size_t{v}; };
    TetSet out;
    const std::size_t n = active.size();
    for (std::size_t ia = 0; ia < n; ++ia) {
        for (std::size_t ib = ia + 1; ib < n; ++ib) {
            for (std::size_t ic = ib + 1; ic < n; ++ic) {
                for (std::size_t id = ic + 1; id < n; ++id) {
                    const std::uint32_t a = active[ia], b = active[ib], c = active[ic],
                                        d = active[id];
                    const Sign s = predicates::orient3d(p(a), p(b), p(c), p(d));
                    if (s == Sign::Zero) continue;
                    std::array<std::uint32_t, 4> t{a, b, c, d};
                    if (s == Sign::Negative) std::swap(t[0], t[1]);
                    bool empty = true;
                    for (std::size_t ie = 0; ie < n && empty; ++ie) {
                        const std::uint32_t e = active[ie];
                        if (e == a || e == b || e == c || e == d) continue;
                        empty =
                            predicates::insphere_sos(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e), t[0],
                                                     t[1], t[2], t[3], e) != Sign::Positive;
                    }
                    if (empty) out.insert({a, b, c, d});
                }
            }
        }
    }
    return out;
}

inline TetSet empty_sphere_delaunay_3d(std::span<const double> xyz) {
    std::vector<std::uint32_t> all(xyz.size() / 3);
    for (std::uint32_t v = 0; v < all.size(); ++v) all[v] = v;
    return empty_sphere_delaunay_3d(xyz, all);
}

/// The tetrahedra of a flat list (4 per tetrahedron), each sorted.
inline TetSet tet_set(std::span<const std::uint32_t> tets) {
    TetSet out;
    for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
        std::array<std::uint32_t, 4> k{tets[t], tets[t + 1], tets[t + 2], tets[t + 3]};
        std::sort(k.begin(), k.end());
        out.insert(k);
    }
    return out;
}

}  // namespace exactmesh::oracles
