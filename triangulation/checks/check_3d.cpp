// SPDX-License-Identifier: MIT
// Exact validation of 3D tetrahedralizations (see check_3d.hpp).
#include "triangulation/checks/check_3d.hpp"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// Vertices and tetrahedra named in the caller's numbering.
class Namer {
  public:
    Namer(std::span<const VertIdx> tets, Check3Numbering numbering)
        : tets_(tets), numbering_(numbering) {}

    std::string vertex(VertIdx v) const {
        return std::to_string(std::uint64_t{v} + numbering_.first_vertex);
    }
    std::string tet(TetIdx t) const {
        const std::size_t base = 4 * std::size_t{t};
        const auto& order = numbering_.corner_order;  // the caller's corner order
        return "tetrahedron " + std::to_string(std::uint64_t{t} + numbering_.first_tet) + " (" +
               vertex(tets_[base + order[0]]) + ", " + vertex(tets_[base + order[1]]) + ", " +
               vertex(tets_[base + order[2]]) + ", " + vertex(tets_[base + order[3]]) + ")";
    }

  private:
    std::span<const VertIdx> tets_;
    Check3Numbering numbering_;
};

Check3Report fail(std::string problem, TetIdx t = kNone, std::vector<VertIdx> vertices = {}) {
    return Check3Report{false, std::move(problem), t, std::move(vertices)};
}

/// One face of one tetrahedron: its vertices sorted, and the face slot 4t + k.
struct FaceEntry {
    VertIdx a, b, c;
    FaceIdx slot;
};

bool face_less(const FaceEntry& x, const FaceEntry& y) {
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    if (x.c != y.c) return x.c < y.c;
    return x.slot < y.slot;
}

/// A directed boundary edge u -> v of boundary face `face` (index into the boundary list).
struct DirectedEdge {
    VertIdx u, v;
    std::uint32_t face;
};

class Checker {
  public:
    Checker(std::span<const double> xyz, std::span<const VertIdx> tets,
            std::span<const TetIdx> neighbors, Check3Numbering numbering)
        : xyz_(xyz),
          tets_(tets),
          neighbors_(neighbors),
          name_(tets, numbering),
          n_(static_cast<VertIdx>(xyz.size() / 3)),
          count_(static_cast<TetIdx>(tets.size() / 4)) {}

    Check3Report topology() {
        if (tets_.size() % 4 != 0)
            return fail("the tetrahedron array length is not a multiple of 4");
        if (!neighbors_.empty() && neighbors_.size() != tets_.size()) {
            return fail("the neighbor array does not hold 4 entries per tetrahedron");
        }
        if (Check3Report r = tetrahedra(); !r.ok) return r;
        if (Check3Report r = faces(); !r.ok) return r;
        if (Check3Report r = points(); !r.ok) return r;
        if (count_ == 0) return coplanar();
        if (Check3Report r = hull_surface(); !r.ok) return r;
        return hull_vertices();
    }

    Check3Report delaunay() {
        for (TetIdx t = 0; t < count_; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx other = twin_[4 * std::size_t{t} + k];
                if (other == kNone) continue;
                const VertIdx d = vertex(tet_of(other), local_of(other));
                if (predicates::insphere(point(vertex(t, 0)), point(vertex(t, 1)),
                                         point(vertex(t, 2)), point(vertex(t, 3)),
                                         point(d)) == Sign::Positive) {
                    return fail(name_.tet(t) + ": not Delaunay, vertex " + name_.vertex(d) +
                                    " lies inside its circumsphere",
                                t, {d});
                }
            }
        }
        return {};
    }

  private:
    std::span<const double> xyz_;
    std::span<const VertIdx> tets_;
    std::span<const TetIdx> neighbors_;
    Namer name_;
    VertIdx n_;
    TetIdx count_;
    std::vector<FaceIdx> twin_;      ///< 4·#T: the same face in the other tetrahedron
    std::vector<FaceIdx> boundary_;  ///< boundary face slots
    std::vector<bool> used_;         ///< per point: a vertex of some tetrahedron

    const double* point(VertIdx v) const { return xyz_.data() + 3 * std::size_t{v}; }
    VertIdx vertex(TetIdx t, unsigned k) const { return tets_[4 * std::size_t{t} + k]; }
    /// Face k of t in the order that sees vertex k (the inside) on its positive side.
    std::array<VertIdx, 3> face(TetIdx t, unsigned k) const {
        return {vertex(t, kFaceVertex[k][0]), vertex(t, kFaceVertex[k][1]),
                vertex(t, kFaceVertex[k][2])};
    }
    bool same_point(VertIdx a, VertIdx b) const {
        const double* p = point(a);
        const double* q = point(b);
        return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
    }

    Check3Report tetrahedra() {
        for (TetIdx t = 0; t < count_; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                if (vertex(t, k) >= n_) {
                    return fail(name_.tet(t) + ": vertex out of range", t, {vertex(t, k)});
                }
            }
            for (unsigned i = 0; i < 4; ++i) {
                for (unsigned j = i + 1; j < 4; ++j) {
                    if (vertex(t, i) == vertex(t, j)) {
                        return fail(name_.tet(t) + ": vertex " + name_.vertex(vertex(t, i)) +
                                        " appears twice",
                                    t, {vertex(t, i)});
                    }
                }
            }
            if (predicates::orient3d(point(vertex(t, 0)), point(vertex(t, 1)), point(vertex(t, 2)),
                                     point(vertex(t, 3))) != Sign::Positive) {
                return fail(name_.tet(t) + ": not positively oriented (orient3d <= 0)", t);
            }
        }
        return {};
    }

    /// Every face in at most two tetrahedra, oppositely oriented; neighbors consistent.
    Check3Report faces() {
        std::vector<FaceEntry> entries;
        entries.reserve(tets_.size());
        for (TetIdx t = 0; t < count_; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                std::array<VertIdx, 3> f = face(t, k);
                std::sort(f.begin(), f.end());
                entries.push_back({f[0], f[1], f[2], 4 * t + k});
            }
        }
        std::sort(entries.begin(), entries.end(), face_less);
        twin_.assign(tets_.size(), kNone);
        auto same_face = [](const FaceEntry& x, const FaceEntry& y) {
            return x.a == y.a && x.b == y.b && x.c == y.c;
        };
        for (std::size_t i = 0; i < entries.size();) {
            std::size_t j = i + 1;
            while (j < entries.size() && same_face(entries[i], entries[j])) ++j;
            const FaceEntry& e = entries[i];
            if (j - i > 2) {
                const TetIdx t = tet_of(entries[i + 2].slot);
                return fail("face (" + name_.vertex(e.a) + ", " + name_.vertex(e.b) + ", " +
                                name_.vertex(e.c) + ") is shared by " + std::to_string(j - i) +
                                " tetrahedra, among them " + name_.tet(t),
                            t, {e.a, e.b, e.c});
            }
            if (j - i == 2) {
                const FaceIdx f = e.slot, g = entries[i + 1].slot;
                if (parity(f) == parity(g)) {
                    return fail(name_.tet(tet_of(g)) + " and " + name_.tet(tet_of(f)) +
                                    " share face (" + name_.vertex(e.a) + ", " + name_.vertex(e.b) +
                                    ", " + name_.vertex(e.c) +
                                    ") with the same orientation: they overlap",
                                tet_of(g), {e.a, e.b, e.c});
                }
                twin_[f] = g;
                twin_[g] = f;
            } else {
                boundary_.push_back(e.slot);
            }
            i = j;
        }
        if (neighbors_.empty()) return {};
        for (TetIdx t = 0; t < count_; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx other = twin_[4 * std::size_t{t} + k];
                const TetIdx expected = other == kNone ? kNone : tet_of(other);
                const TetIdx given = neighbors_[4 * std::size_t{t} + k];
                if (given != expected) {
                    return fail(name_.tet(t) + ": neighbor across the face opposite vertex " +
                                    name_.vertex(vertex(t, k)) + " is " +
                                    (given == kNone ? std::string("none")
                                                    : "tetrahedron " + std::to_string(given)) +
                                    ", expected " +
                                    (expected == kNone ? std::string("none (boundary)")
                                                       : "tetrahedron " + std::to_string(expected)),
                                t);
                }
            }
        }
        return {};
    }

    /// Parity of the permutation that sorts face f's oriented vertices.
    int parity(FaceIdx f) const {
        const std::array<VertIdx, 3> v = face(tet_of(f), local_of(f));
        return ((v[0] > v[1]) + (v[0] > v[2]) + (v[1] > v[2])) & 1;
    }

    /// Distinct points are all vertices (when there are tetrahedra); no two vertices coincide.
    Check3Report points() {
        used_.assign(n_, false);
        for (const VertIdx v : tets_) used_[v] = true;
        std::vector<VertIdx> order(n_);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [this](VertIdx a, VertIdx b) {
            const double* p = point(a);
            const double* q = point(b);
            if (p[0] != q[0]) return p[0] < q[0];
            if (p[1] != q[1]) return p[1] < q[1];
            if (p[2] != q[2]) return p[2] < q[2];
            return a < b;
        });
        for (std::size_t i = 0; i < order.size();) {
            std::size_t j = i;
            VertIdx first_used = kNone;
            while (j < order.size() && same_point(order[j], order[i])) {
                if (used_[order[j]]) {
                    if (first_used != kNone) {
                        return fail("vertices " + name_.vertex(first_used) + " and " +
                                        name_.vertex(order[j]) + " have the same coordinates",
                                    kNone, {first_used, order[j]});
                    }
                    first_used = order[j];
                }
                ++j;
            }
            if (first_used == kNone && count_ > 0) {
                return fail(
                    "point " + name_.vertex(order[i]) + " is not a vertex of any tetrahedron",
                    kNone, {order[i]});
            }
            i = j;
        }
        return {};
    }

    /// No tetrahedron: every point must lie in one plane.
    Check3Report coplanar() const {
        VertIdx b = kNone, c = kNone;
        for (VertIdx v = 1; v < n_ && b == kNone; ++v) {
            if (!same_point(0, v)) b = v;
        }
        if (b == kNone) return {};
        for (VertIdx v = b + 1; v < n_ && c == kNone; ++v) {
            const double* p = point(0);
            const double* q = point(b);
            const double* r = point(v);
            // Not collinear: some coordinate projection of the three points is not.
            for (int drop = 0; drop < 3 && c == kNone; ++drop) {
                const int i = (drop + 1) % 3, j = (drop + 2) % 3;
                const double p2[2] = {p[i], p[j]}, q2[2] = {q[i], q[j]}, r2[2] = {r[i], r[j]};
                if (predicates::orient2d(p2, q2, r2) != Sign::Zero) c = v;
            }
        }
        if (c == kNone) return {};
        for (VertIdx v = c + 1; v < n_; ++v) {
            if (predicates::orient3d(point(0), point(b), point(c), point(v)) != Sign::Zero) {
                return fail("no tetrahedra, but points " + name_.vertex(0) + ", " +
                                name_.vertex(b) + ", " + name_.vertex(c) + ", " + name_.vertex(v) +
                                " are not coplanar",
                            kNone, {0, b, c, v});
            }
        }
        return {};
    }

    /// The boundary faces form one connected closed surface, locally convex at every edge.
    Check3Report hull_surface() {
        if (boundary_.empty()) return fail("no boundary face: the tetrahedra do not close");
        std::vector<DirectedEdge> edges;
        edges.reserve(3 * boundary_.size());
        for (std::uint32_t i = 0; i < boundary_.size(); ++i) {
            const std::array<VertIdx, 3> f = face(tet_of(boundary_[i]), local_of(boundary_[i]));
            for (unsigned e = 0; e < 3; ++e) edges.push_back({f[e], f[(e + 1) % 3], i});
        }
        std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
            return x.u != y.u ? x.u < y.u : x.v != y.v ? x.v < y.v : x.face < y.face;
        });
        auto find = [&edges](VertIdx u, VertIdx v) {
            const auto it =
                std::lower_bound(edges.begin(), edges.end(), std::pair<VertIdx, VertIdx>{u, v},
                                 [](const DirectedEdge& x, const std::pair<VertIdx, VertIdx>& key) {
                                     return x.u != key.first ? x.u < key.first : x.v < key.second;
                                 });
            return it != edges.end() && it->u == u && it->v == v ? it : edges.end();
        };
        std::vector<std::uint32_t> component(boundary_.size());
        std::iota(component.begin(), component.end(), 0u);
        auto root = [&component](std::uint32_t x) {
            while (component[x] != x) x = component[x] = component[component[x]];
            return x;
        };
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const DirectedEdge& e = edges[i];
            const TetIdx t = tet_of(boundary_[e.face]);
            if (i + 1 < edges.size() && edges[i + 1].u == e.u && edges[i + 1].v == e.v) {
                return fail("boundary edge " + name_.vertex(e.u) + "-" + name_.vertex(e.v) +
                                " is in more than two boundary faces",
                            t, {e.u, e.v});
            }
            const auto reverse = find(e.v, e.u);
            if (reverse == edges.end()) {
                return fail("boundary edge " + name_.vertex(e.u) + "-" + name_.vertex(e.v) +
                                " of " + name_.tet(t) +
                                " is in one boundary face only: the boundary is not closed",
                            t, {e.u, e.v});
            }
            component[root(e.face)] = root(reverse->face);
            // The other face's third vertex must not lie strictly outside this face.
            const std::array<VertIdx, 3> f = face(t, local_of(boundary_[e.face]));
            const std::array<VertIdx, 3> g =
                face(tet_of(boundary_[reverse->face]), local_of(boundary_[reverse->face]));
            VertIdx apex = kNone;
            for (const VertIdx w : g) {
                if (w != e.u && w != e.v) apex = w;
            }
            if (predicates::orient3d(point(f[0]), point(f[1]), point(f[2]), point(apex)) ==
                Sign::Negative) {
                return fail("boundary is not convex at edge " + name_.vertex(e.u) + "-" +
                                name_.vertex(e.v) + ": vertex " + name_.vertex(apex) +
                                " lies outside the boundary face of " + name_.tet(t),
                            t, {e.u, e.v, apex});
            }
        }
        for (std::uint32_t i = 0; i < boundary_.size(); ++i) {
            if (root(i) != root(0)) {
                return fail("the boundary has more than one connected component (" +
                                name_.tet(tet_of(boundary_[i])) + " is on another)",
                            tet_of(boundary_[i]));
            }
        }
        return {};
    }

    /// At every boundary vertex v, a ray from v into one of its boundary tetrahedra, t0 =
    /// (v, x, y, z), lies in exactly one tetrahedron's cone at v: the tetrahedra cover the
    /// neighbourhood of v once, so the boundary does not wind around v twice. The ray goes
    /// through P = x + e1 (y - x) + e2 (z - x), 1 >> e1 >> e2 > 0; orient3d(a, b, c, P) is affine
    /// in P, so its sign is that of the first nonzero among orient3d(a, b, c, x), (.., y),
    /// (.., z), and it is never zero (x, y, z do not lie in one plane with v).
    Check3Report hull_vertices() const {
        std::vector<std::array<VertIdx, 3>> ray(n_, {kNone, kNone, kNone});
        for (const FaceIdx f : boundary_) {
            const TetIdx t = tet_of(f);
            for (unsigned s = 0; s < 4; ++s) {
                const VertIdx v = vertex(t, s);
                if (s == local_of(f) || ray[v][0] != kNone) continue;
                std::array<VertIdx, 3>& r = ray[v];
                unsigned count = 0;
                for (unsigned i = 0; i < 4; ++i) {
                    if (i != s) r[count++] = vertex(t, i);
                }
            }
        }
        std::vector<std::uint32_t> cones(n_, 0);
        for (TetIdx t = 0; t < count_; ++t) {
            for (unsigned s = 0; s < 4; ++s) {
                const VertIdx v = vertex(t, s);
                if (ray[v][0] == kNone) continue;
                bool inside = true;
                for (unsigned k = 0; k < 4 && inside; ++k) {
                    if (k == s) continue;
                    const std::array<VertIdx, 3> f = face(t, k);  // holds v
                    Sign side = Sign::Zero;
                    for (unsigned i = 0; i < 3 && side == Sign::Zero; ++i) {
                        side = predicates::orient3d(point(f[0]), point(f[1]), point(f[2]),
                                                    point(ray[v][i]));
                    }
                    inside = side == Sign::Positive;
                }
                if (inside) ++cones[v];
            }
        }
        for (VertIdx v = 0; v < n_; ++v) {
            if (ray[v][0] != kNone && cones[v] != 1) {
                return fail("the tetrahedra cover the neighbourhood of boundary vertex " +
                                name_.vertex(v) + " " + std::to_string(cones[v]) +
                                " times: the boundary winds around it",
                            kNone, {v});
            }
        }
        return {};
    }
};

}  // namespace

Check3Report check_tetrahedralization_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                                         std::span<const TetIdx> neighbors,
                                         Check3Numbering numbering) {
    Checker checker(xyz, tets, neighbors, numbering);
    return checker.topology();
}

Check3Report check_delaunay_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                               std::span<const TetIdx> neighbors, Check3Numbering numbering) {
    Checker checker(xyz, tets, neighbors, numbering);
    Check3Report report = checker.topology();
    if (!report.ok) return report;
    return checker.delaunay();
}

}  // namespace exactmesh::triangulation
