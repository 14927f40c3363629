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

inline TetSet empty_sphere_delaunay_3d(std::span<const double> xyz) {
    using predicates::Sign;
    const auto n = static_cast<std::uint32_t>(xyz.size() / 3);
    auto p = [&](std::uint32_t v) { return xyz.data() + 3 * std::size_t{v}; };
    TetSet out;
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            for (std::uint32_t c = b + 1; c < n; ++c) {
                for (std::uint32_t d = c + 1; d < n; ++d) {
                    const Sign s = predicates::orient3d(p(a), p(b), p(c), p(d));
                    if (s == Sign::Zero) continue;
                    std::array<std::uint32_t, 4> t{a, b, c, d};
                    if (s == Sign::Negative) std::swap(t[0], t[1]);
                    bool empty = true;
                    for (std::uint32_t e = 0; e < n && empty; ++e) {
                        if (e == a || e == b || e == c || e == d) continue;
                        empty = predicates::insphere_sos(p(t[0]), p(t[1]), p(t[2]), p(t[3]), p(e), t[0], t[1], t[2],
                                                         t[3], e) != Sign::Positive;
                    }
                    if (empty) out.insert({a, b, c, d});
                }
            }
        }
    }
    return out;
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
