// SPDX-License-Identifier: MIT
// Bowyer-Watson 3D (see bowyer_watson_3d.hpp).
#include "triangulation/bowyer_watson_3d.hpp"

#include <vector>

#include "triangulation/delaunay_3d_core.hpp"

namespace exactmesh::triangulation {

namespace {

/// Marks of the cavity search, kept in the high bits of vertex slot 1 of a tetrahedron (vertex
/// indices stay below kMaxPoints3 = 2^26, and slot 1 never holds kInfinite or kNone in a live
/// tetrahedron): the mark is then read from the cache line the conflict test loads anyway,
/// where a separate mark array cost a second cache miss per tested neighbour. Inside marks
/// vanish when the cavity's slots are rewritten; outside marks are cleared after each insertion.
constexpr VertIdx kInsideMark = 1u << 31;
constexpr VertIdx kOutsideMark = 1u << 30;
static_assert(kVertexBits == kOutsideMark - 1 && kMaxPoints3 <= kOutsideMark,
              "vertex indices must leave the two mark bits free");

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

/// One insertion: the cavity of tetrahedra in conflict with p, then its star from p.
///
/// Cavity: grown breadth first from a tetrahedron in conflict; the conflict region of a point
/// is connected [Watson81], so every tetrahedron in it is reached. A tetrahedron tested and
/// found outside keeps its mark (and is listed), so it is tested once even when several cavity
/// faces touch it.
///
/// Star: boundary face k of cavity tetrahedron c gives the new tetrahedron c with vertex k
/// replaced by p (positive: the cavity is star-shaped from p). The new tetrahedra's faces
/// through p pair up along the edges of the cavity's boundary (a triangulated sphere around
/// p): each edge (a, b) is met by exactly two of them, matched in a small open-addressing table
/// keyed by the edge and cleared by a generation count. The boundary faces are listed (with
/// their new vertices) before anything is written, so the new tetrahedra take the cavity's
/// slots first, then fresh ones (a cavity has more boundary faces than tetrahedra, about
/// 2C + 2 for C tetrahedra, except in degenerate configurations: leftover slots are freed).
///
/// Whether a neighbour is in conflict, and whether a face is on the boundary, are coin tosses
/// for the branch predictor: both are recorded without a branch (the entry is written
/// unconditionally, the count advances by the outcome).
class CavityInserter {
  public:
    explicit CavityInserter(detail::Delaunay3Core& core) : core_(core), mesh_(core.mesh) {}

    void insert(VertIdx p, TetIdx seed) {
        grow(seed, p);
        core_.counters.cavity_tets += cavity_count_;
        star(p);
    }

  private:
    detail::Delaunay3Core& core_;
    TetMesh3& mesh_;
    std::vector<TetIdx> cavity_, outside_;
    std::size_t cavity_count_ = 0, outside_count_ = 0;

    struct Face {
        VertIdx v[4];  ///< the new tetrahedron
        unsigned k;    ///< the slot of p in it: its face towards the outside
        FaceIdx outside;
    };
    struct Slot {
        std::uint64_t key;
        FaceIdx face;
        std::uint32_t generation;
    };
    std::vector<Face> boundary_;
    std::vector<std::uint8_t> face_mask_;  ///< per cavity tetrahedron: its boundary faces
    std::vector<Slot> table_;
    std::uint32_t generation_ = 0;
    unsigned shift_ = 64;
    FaceIdx scratch_ = kNone;

    /// Room for `count` more entries after `used` (grown, never shrunk: no clearing per call).
    template <class T>
    static void ensure(std::vector<T>& v, std::size_t used, std::size_t count) {
        if (v.size() < used + count) v.resize(2 * (used + count) + 64);
    }

    void grow(TetIdx seed, VertIdx p) {
        ensure(cavity_, 0, 1);
        cavity_[0] = seed;
        cavity_count_ = 1;
        outside_count_ = 0;
        mesh_.tv[4 * std::size_t{seed} + 1] |= kInsideMark;
        // The neighbours are scattered in memory: their lines are requested one cavity
        // tetrahedron ahead (the adjacency of a tetrahedron is requested when it joins the
        // cavity), so the misses overlap the insphere tests of the tetrahedron at hand.
        request_neighbours(seed);
        for (std::size_t i = 0; i < cavity_count_; ++i) {
            const TetIdx c = cavity_[i];
            if (i + 1 < cavity_count_) request_neighbours(cavity_[i + 1]);
            ensure(cavity_, cavity_count_, 4);
            ensure(outside_, outside_count_, 4);
            for (unsigned k = 0; k < 4; ++k) {
                const TetIdx u = tet_of(mesh_.adj[4 * std::size_t{c} + k]);
                VertIdx& marked = mesh_.tv[4 * std::size_t{u} + 1];
                if (marked & (kInsideMark | kOutsideMark)) continue;
                const bool in = core_.conflict(u, p);
                marked |= in ? kInsideMark : kOutsideMark;
                cavity_[cavity_count_] = u;
                cavity_count_ += in ? 1 : 0;
                outside_[outside_count_] = u;
                outside_count_ += in ? 0 : 1;
                __builtin_prefetch(&mesh_.adj[4 * std::size_t{u}]);
            }
        }
    }

    void request_neighbours(TetIdx c) const {
        for (unsigned k = 0; k < 4; ++k) {
            __builtin_prefetch(
                &mesh_.tv[4 * std::size_t{tet_of(mesh_.adj[4 * std::size_t{c} + k])}]);
        }
    }

    void star(VertIdx p) {
        ensure(boundary_, 0, 4 * cavity_count_);
        ensure(face_mask_, 0, cavity_count_);
        std::size_t faces = 0;
        for (std::size_t i = 0; i < cavity_count_; ++i) {
            const TetIdx c = cavity_[i];
            const VertIdx* cv = &mesh_.tv[4 * std::size_t{c}];
            const VertIdx v[4] = {cv[0], cv[1] & kVertexBits, cv[2], cv[3]};
            unsigned mask = 0;
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx outside = mesh_.adj[4 * std::size_t{c} + k];
                Face& f = boundary_[faces];
                f.v[0] = v[0];
                f.v[1] = v[1];
                f.v[2] = v[2];
                f.v[3] = v[3];
                f.v[k] = p;
                f.k = k;
                f.outside = outside;
                const unsigned on_boundary =
                    (mesh_.tv[4 * std::size_t{tet_of(outside)} + 1] & kInsideMark) ? 0u : 1u;
                mask |= on_boundary << k;
                faces += on_boundary;
            }
            face_mask_[i] = static_cast<std::uint8_t>(mask);
        }
        prepare_table(3 * faces);
        // Per cavity tetrahedron c, its boundary faces are consecutive. Two of them, k and j,
        // meet along the edge of c they share: the new tetrahedra c[k := p] and c[j := p] are
        // glued directly (face j of one to face k of the other); only edges leading into the
        // cavity (face j of c interior) go through the edge table.
        std::size_t next = 0;
        for (std::size_t i = 0; i < cavity_count_; ++i) {
            const unsigned mask = face_mask_[i];
            TetIdx made[4];
            for (unsigned k = 0; k < 4; ++k) {
                if (!(mask & (1u << k))) continue;
                const Face& f = boundary_[next];
                const TetIdx t = next < cavity_count_ ? cavity_[next] : mesh_.new_tet();
                ++next;
                made[k] = t;
                VertIdx* w = &mesh_.tv[4 * std::size_t{t}];
                w[0] = f.v[0];
                w[1] = f.v[1];
                w[2] = f.v[2];
                w[3] = f.v[3];
                mesh_.link(4 * t + k, f.outside);
                for (unsigned j = 0; j < 4; ++j) {
                    if (j == k) continue;
                    if (mask & (1u << j)) {
                        if (j < k) mesh_.link(4 * t + j, 4 * made[j] + k);
                    } else {
                        const OtherTwo e = kOtherTwo[j][k];
                        glue(detail::edge_key(f.v[e.a], f.v[e.b]), 4 * t + j);
                    }
                }
            }
        }
        for (std::size_t i = faces; i < cavity_count_; ++i) mesh_.kill_tet(cavity_[i]);
        for (std::size_t i = 0; i < outside_count_; ++i) {
            mesh_.tv[4 * std::size_t{outside_[i]} + 1] &= ~kOutsideMark;
        }
        core_.last_tet = cavity_[0];
    }

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

    /// The first face of an edge is stored, the second is linked with it. Which of the two
    /// happens is a coin toss for the branch predictor, so both are done without a branch:
    /// the stores go to a scratch word when there is nothing to link (the new face's own twin
    /// is then overwritten when its partner arrives).
    void glue(std::uint64_t key, FaceIdx face) {
        const std::size_t mask = table_.size() - 1;
        std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
        while (table_[h].generation == generation_ && table_[h].key != key) h = (h + 1) & mask;
        Slot& slot = table_[h];
        const bool first = slot.generation != generation_;
        const FaceIdx partner = slot.face;
        FaceIdx* partner_twin = first ? &scratch_ : &mesh_.adj[partner];
        *partner_twin = face;
        mesh_.adj[face] = partner;
        slot = {key, face, generation_};
    }
};

}  // namespace

Delaunay3Result bowyer_watson_3d(std::span<const double> xyz, const Delaunay3Options& options) {
    detail::Delaunay3Core core(xyz, options);
    std::vector<bool> skip;
    // Fewer than four non-coplanar points: no tetrahedron, duplicates still merged.
    if (!core.make_first_tet(skip)) return core.coplanar_result(xyz);
    CavityInserter inserter(core);
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const detail::Delaunay3Core::Location where = core.locate(p);
        if (where.tet == kNone) continue;  // duplicate, merged
        inserter.insert(p, where.tet);
    }
    return core.take_result(xyz);
}

}  // namespace exactmesh::triangulation
