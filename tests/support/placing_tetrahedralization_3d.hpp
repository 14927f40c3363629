// SPDX-License-Identifier: MIT
// A deliberately arbitrary starting tetrahedralization for the 3D swapping tests: the placing
// (beneath-beyond) construction. Points in lexicographic order; the first four affinely
// independent ones make the first tetrahedron; each later point is joined to every hull face it
// sees strictly (outside the hull) or splits the tetrahedra whose closure holds it (1-4, 2-6 or
// n-2n, skipping the faces it lies on). Long thin tetrahedra everywhere, no Delaunay property.
// Brute force (O(n T) exact orient3d): tests only, a few thousand points at most. Duplicates are
// skipped (they keep no tetrahedron); with fewer than four independent points: no tetrahedron.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <vector>

#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::testing {

inline triangulation::Tetrahedralization3 placing_tetrahedralization_3d(
    std::span<const double> xyz) {
    using predicates::Sign;
    using triangulation::kFaceVertex;
    using triangulation::Tet;
    using triangulation::VertIdx;
    triangulation::Tetrahedralization3 out;
    out.xyz.assign(xyz.begin(), xyz.end());
    const auto n = static_cast<VertIdx>(xyz.size() / 3);
    auto p = [&](VertIdx v) { return xyz.data() + 3 * std::size_t{v}; };
    std::vector<VertIdx> order(n);
    std::iota(order.begin(), order.end(), VertIdx{0});
    auto lex = [&](VertIdx a, VertIdx b) {
        for (int i = 0; i < 3; ++i) {
            if (p(a)[i] != p(b)[i]) return p(a)[i] < p(b)[i];
        }
        return a < b;
    };
    std::sort(order.begin(), order.end(), lex);
    order.erase(std::unique(order.begin(), order.end(),
                            [&](VertIdx a, VertIdx b) {
                                return p(a)[0] == p(b)[0] && p(a)[1] == p(b)[1] &&
                                       p(a)[2] == p(b)[2];
                            }),
                order.end());
    if (order.size() < 4) return out;
    auto collinear = [&](VertIdx a, VertIdx b, VertIdx c) {
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            const double pa[2] = {p(a)[i], p(a)[j]}, pb[2] = {p(b)[i], p(b)[j]},
                         pc[2] = {p(c)[i], p(c)[j]};
            if (predicates::orient2d(pa, pb, pc) != Sign::Zero) return false;
        }
        return true;
    };
    std::size_t i2 = 2;
    while (i2 < order.size() && collinear(order[0], order[1], order[i2])) ++i2;
    if (i2 == order.size()) return out;
    std::size_t i3 = i2 + 1;
    while (i3 < order.size() &&
           predicates::orient3d(p(order[0]), p(order[1]), p(order[i2]), p(order[i3])) == Sign::Zero)
        ++i3;
    if (i3 == order.size()) return out;
    std::vector<Tet> tets;
    std::map<std::array<VertIdx, 3>, int> face_count;
    auto key = [](VertIdx a, VertIdx b, VertIdx c) {
        std::array<VertIdx, 3> k{a, b, c};
        std::sort(k.begin(), k.end());
        return k;
    };
    auto add = [&](const Tet& t) {
        tets.push_back(t);
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned* lf = kFaceVertex[k];
            ++face_count[key(t[lf[0]], t[lf[1]], t[lf[2]])];
        }
    };
    auto remove_faces = [&](const Tet& t) {
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned* lf = kFaceVertex[k];
            if (--face_count[key(t[lf[0]], t[lf[1]], t[lf[2]])] == 0)
                face_count.erase(key(t[lf[0]], t[lf[1]], t[lf[2]]));
        }
    };
    Tet first{order[0], order[1], order[i2], order[i3]};
    if (predicates::orient3d(p(first[0]), p(first[1]), p(first[2]), p(first[3])) == Sign::Negative)
        std::swap(first[0], first[1]);
    add(first);
    for (std::size_t i = 2; i < order.size(); ++i) {
        if (i == i2 || i == i3) continue;
        const VertIdx v = order[i];
        std::vector<std::array<Sign, 4>> signs(tets.size());
        std::vector<std::size_t> holding;
        for (std::size_t t = 0; t < tets.size(); ++t) {
            bool inside = true;
            for (unsigned k = 0; k < 4; ++k) {
                const unsigned* lf = kFaceVertex[k];
                signs[t][k] = predicates::orient3d(p(tets[t][lf[0]]), p(tets[t][lf[1]]),
                                                   p(tets[t][lf[2]]), p(v));
                inside = inside && signs[t][k] != Sign::Negative;
            }
            if (inside) holding.push_back(t);
        }
        std::vector<Tet> made;
        if (!holding.empty()) {
            // Faces of the holding set not shared inside it, that v does not lie on.
            std::map<std::array<VertIdx, 3>, int> local;
            for (const std::size_t t : holding) {
                for (unsigned k = 0; k < 4; ++k) {
                    const unsigned* lf = kFaceVertex[k];
                    ++local[key(tets[t][lf[0]], tets[t][lf[1]], tets[t][lf[2]])];
                }
            }
            for (const std::size_t t : holding) {
                for (unsigned k = 0; k < 4; ++k) {
                    const unsigned* lf = kFaceVertex[k];
                    if (local[key(tets[t][lf[0]], tets[t][lf[1]], tets[t][lf[2]])] != 1) continue;
                    if (signs[t][k] != Sign::Positive) continue;
                    made.push_back({tets[t][lf[0]], tets[t][lf[1]], tets[t][lf[2]], v});
                }
            }
            std::vector<Tet> kept;
            for (std::size_t t = 0; t < tets.size(); ++t) {
                if (std::find(holding.begin(), holding.end(), t) != holding.end()) {
                    remove_faces(tets[t]);
                } else {
                    kept.push_back(tets[t]);
                }
            }
            tets.swap(kept);
        } else {
            for (std::size_t t = 0; t < tets.size(); ++t) {
                for (unsigned k = 0; k < 4; ++k) {
                    const unsigned* lf = kFaceVertex[k];
                    if (signs[t][k] != Sign::Negative) continue;
                    if (face_count[key(tets[t][lf[0]], tets[t][lf[1]], tets[t][lf[2]])] != 1)
                        continue;
                    made.push_back({tets[t][lf[1]], tets[t][lf[0]], tets[t][lf[2]], v});
                }
            }
        }
        for (const Tet& t : made) add(t);
    }
    for (const Tet& t : tets) out.tets.insert(out.tets.end(), t.begin(), t.end());
    triangulation::link_neighbors_3d(out);
    return out;
}

}  // namespace exactmesh::testing
