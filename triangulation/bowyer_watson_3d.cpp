// SPDX-License-Identifier: MIT
// Bowyer-Watson 3D (see bowyer_watson_3d.hpp).
#include "triangulation/bowyer_watson_3d.hpp"

#include <vector>

#include "triangulation/delaunay_3d_core.hpp"

namespace exactmesh::triangulation {

namespace {

/// Grows the cavity of p from `seed` (in conflict) breadth first: the conflict region of a
/// point is connected [Watson81], so every tetrahedron in it is reached. A tetrahedron tested
/// and found outside keeps its own mark, so it is tested once even when several cavity faces
/// touch it.
void grow_cavity(detail::Delaunay3Core& core, std::vector<TetIdx>& cavity, TetIdx seed, VertIdx p,
                 std::uint32_t inside, std::uint32_t outside) {
    TetMesh3& mesh = core.mesh;
    cavity.clear();
    cavity.push_back(seed);
    core.stamp[seed] = inside;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const TetIdx c = cavity[i];
        for (unsigned k = 0; k < 4; ++k) {
            const TetIdx u = tet_of(mesh.adj[4 * std::size_t{c} + k]);
            const std::uint32_t mark = core.stamp[u];
            if (mark == inside || mark == outside) continue;
            if (core.conflict(u, p)) {
                core.stamp[u] = inside;
                cavity.push_back(u);
            } else {
                core.stamp[u] = outside;
            }
        }
    }
}

/// For slots j != k of a tetrahedron: the other two slots.
struct OtherTwo {
    unsigned a, b;
};
constexpr OtherTwo other_two(unsigned j, unsigned k) {
    unsigned a = 0;
    while (a == j || a == k) ++a;
    unsigned b = a + 1;
    while (b == j || b == k) ++b;
    return {a, b};
}
constexpr OtherTwo kOtherTwo[4][4] = {{{}, other_two(0, 1), other_two(0, 2), other_two(0, 3)},
                                      {other_two(1, 0), {}, other_two(1, 2), other_two(1, 3)},
                                      {other_two(2, 0), other_two(2, 1), {}, other_two(2, 3)},
                                      {other_two(3, 0), other_two(3, 1), other_two(3, 2), {}}};

/// Joins p to every boundary face of the cavity: boundary face k of cavity tetrahedron c gives
/// the new tetrahedron c with vertex k replaced by p (positive: the cavity is star-shaped from
/// p). The new tetrahedra's faces through p pair up along the edges of the cavity's boundary
/// (a triangulated sphere around p): each edge (a, b) is met by exactly two of them, matched in
/// a small open-addressing table keyed by the edge and cleared by a generation count. New
/// tetrahedra take other slots than the cavity's (from the free list: the previous cavity's),
/// so the cavity stays readable until it is freed at the end.
class CavityStar {
  public:
    void build(detail::Delaunay3Core& core, const std::vector<TetIdx>& cavity, std::uint32_t inside,
               VertIdx p) {
        TetMesh3& mesh = core.mesh;
        boundary_.clear();
        for (const TetIdx c : cavity) {
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx outside = mesh.adj[4 * std::size_t{c} + k];
                if (core.stamp[tet_of(outside)] != inside) boundary_.push_back({c, k, outside});
            }
        }
        prepare_table(3 * boundary_.size());
        TetIdx first = kNone;
        for (const Face& f : boundary_) {
            const TetIdx t = mesh.new_tet();
            if (first == kNone) first = t;
            const VertIdx* cv = &mesh.tv[4 * std::size_t{f.c}];
            VertIdx* w = &mesh.tv[4 * std::size_t{t}];
            w[0] = cv[0];
            w[1] = cv[1];
            w[2] = cv[2];
            w[3] = cv[3];
            w[f.k] = p;
            mesh.link(4 * t + f.k, f.outside);
            for (unsigned j = 0; j < 4; ++j) {
                if (j == f.k) continue;
                const OtherTwo e = kOtherTwo[j][f.k];
                glue(mesh, detail::edge_key(cv[e.a], cv[e.b]), 4 * t + j);
            }
        }
        for (const TetIdx c : cavity) mesh.kill_tet(c);
        core.grow_stamps();
        core.last_tet = first;
    }

  private:
    struct Face {
        TetIdx c;
        unsigned k;
        FaceIdx outside;
    };
    struct Slot {
        std::uint64_t key;
        FaceIdx face;
        std::uint32_t generation;
    };
    std::vector<Face> boundary_;
    std::vector<Slot> table_;
    std::uint32_t generation_ = 0;
    unsigned shift_ = 64;

    void prepare_table(std::size_t entries) {
        if (table_.size() < 2 * entries) {
            std::size_t size = 256;
            unsigned bits = 8;
            while (size < 2 * entries) {
                size *= 2;
                ++bits;
            }
            table_.assign(size, Slot{0, kNone, 0});
            shift_ = 64 - bits;
            generation_ = 0;
        }
        if (++generation_ == 0) {
            for (Slot& slot : table_) slot.generation = 0;
            generation_ = 1;
        }
    }

    void glue(TetMesh3& mesh, std::uint64_t key, FaceIdx face) {
        const std::size_t mask = table_.size() - 1;
        for (std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);;
             h = (h + 1) & mask) {
            Slot& slot = table_[h];
            if (slot.generation != generation_) {
                slot = {key, face, generation_};
                return;
            }
            if (slot.key == key) {
                mesh.link(slot.face, face);
                return;
            }
        }
    }
};

}  // namespace

Delaunay3Result bowyer_watson_3d(std::span<const double> xyz, const Delaunay3Options& options) {
    detail::Delaunay3Core core(xyz, options);
    std::vector<bool> skip;
    // Fewer than four non-coplanar points: no tetrahedron, duplicates still merged.
    if (!core.make_first_tet(skip)) return core.coplanar_result();
    std::vector<TetIdx> cavity;
    CavityStar star;
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const detail::Delaunay3Core::Location where = core.locate(p);
        if (where.tet == kNone) continue;  // duplicate, merged
        const std::uint32_t inside = core.next_stamp();
        const std::uint32_t outside = core.next_stamp();
        grow_cavity(core, cavity, where.tet, p, inside, outside);
        core.counters.cavity_tets += cavity.size();
        star.build(core, cavity, inside, p);
    }
    return core.take_result();
}

}  // namespace exactmesh::triangulation
