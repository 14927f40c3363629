// SPDX-License-Identifier: MIT
// One Bowyer-Watson insertion in 3D [Bowyer81, Watson81]: the cavity of tetrahedra whose
// perturbed circumsphere holds the point, grown breadth first, then starred from the point.
// Shared by bowyer_watson_3d (the whole mesh) and parallel_bowyer_watson_3d (a thread's
// partition: the cavity must stay in it, else the point is deferred before anything changes).
// Internal to triangulation/. Predicates: insphere_sos, orient3d (hull faces), through
// ConflictTest3.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "triangulation/delaunay/delaunay_3d_core.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation::detail {

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
/// faces touch it. Each face of a cavity tetrahedron is known to be on the cavity's boundary
/// or not as soon as its neighbour is tested (or found marked): the boundary faces are
/// recorded per cavity tetrahedron as a 4-bit mask during the search.
///
/// Star: boundary face k of cavity tetrahedron c gives the new tetrahedron c with vertex k
/// replaced by p (positive: the cavity is star-shaped from p). The cavity tetrahedra are
/// starred in one pass, each read whole before any slot is written, so a new tetrahedron
/// takes the slot of a cavity tetrahedron already read, or a free one (a cavity usually has
/// more boundary faces than tetrahedra: about C + 6.7 for C tetrahedra of uniform points;
/// leftover cavity slots are freed). Two new tetrahedra made from faces k and j of the same
/// cavity tetrahedron are glued directly; the other faces through p pair up along the edges of
/// the cavity's boundary (a triangulated sphere around p): each edge (a, b) is met by exactly
/// two of them, matched in a small open-addressing table keyed by the edge and cleared by a
/// generation count.
///
/// Whether a neighbour is in conflict is a coin toss for the branch predictor: the outcome is
/// recorded without a branch (the entry is written unconditionally, the count advances by the
/// outcome).
///
/// Region: where the insertion may work (the one template seam: the whole mesh for the
/// sequential construction, a thread's partition for the parallel one), with
///   static constexpr bool kPartitioned;   false: every tetrahedron is the region's
///   bool owns(TetIdx t) const;            (partitioned) t may join a cavity: only such
///                                         tetrahedra are marked or rewritten; the others are
///                                         only read, and one in conflict defers the point
///   ConflictTest3 tests();                the conflict test with the region's counters
///   Delaunay3Counters& counters();
///   std::vector<TetIdx>& free_tets();     dead slots this insertion may fill and free
///   bool make_room(std::size_t faces);    at least `faces` free slots, or false (defer)
///   TetIdx last_tet;                      set to a new tetrahedron of p
template <class Region>
class CavityInserter3 {
  public:
    CavityInserter3(Region& region, TetMesh3& mesh) : region_(region), mesh_(mesh) {}

    /// Inserts p, located in seed (a tetrahedron of the region in conflict with p). Partitioned:
    /// returns false and changes nothing when the cavity leaves the region or the region has
    /// too few free slots.
    bool insert(VertIdx p, TetIdx seed) {
        const std::size_t faces = grow(seed, p);
        if constexpr (Region::kPartitioned) {
            if (faces == kLeftRegion || !region_.make_room(faces)) {
                clear_marks();
                return false;
            }
        } else {
            region_.make_room(faces);
        }
        region_.counters().cavity_tets += cavity_count_;
        star(p, faces);
        return true;
    }

  private:
    static constexpr std::size_t kLeftRegion = ~std::size_t{0};

    Region& region_;
    TetMesh3& mesh_;
    std::vector<TetIdx> cavity_, outside_;
    std::vector<std::uint8_t> face_mask_;  ///< per cavity tetrahedron: its boundary faces
    std::size_t cavity_count_ = 0, outside_count_ = 0;

    /// Edge table entry: the edge's key (its vertices, 27 bits each: indices below kMaxPoints3 =
    /// 2^26 and kInfinite's low bits, which are not) tagged with the insertion's generation in
    /// the top 10 bits, so that one comparison tells a live entry of this edge, and a stale
    /// generation an empty slot.
    struct Slot {
        std::uint64_t tag;
        FaceIdx face;
    };
    static constexpr unsigned kGenerationShift = 54;
    static constexpr std::uint64_t kKeyBits = (1u << 27) - 1;
    static constexpr std::uint64_t kGenerationMask = ~std::uint64_t{0} << kGenerationShift;
    static_assert(kMaxPoints3 <= (1u << 26) && (kInfinite & kKeyBits) >= (1u << 26),
                  "edge keys hold two vertex indices or kInfinite in 27 bits each");
    std::vector<Slot> table_;
    std::uint64_t generation_ = 0;  ///< 1 .. 1023
    std::uint64_t shift_ = 64;
    FaceIdx scratch_ = kNone;

    /// Grows the cavity from seed; returns the number of its boundary faces, or kLeftRegion
    /// (partitioned: a tetrahedron in conflict is not the region's; the marks are left).
    std::size_t grow(TetIdx seed, VertIdx p) {
        ConflictTest3 tests = region_.tests();
        VertIdx* const tv = mesh_.tv.data();
        const FaceIdx* const adj = mesh_.adj.data();
        if (cavity_.empty()) {
            cavity_.resize(64);
            face_mask_.resize(64);
        }
        cavity_[0] = seed;
        std::size_t count = 1, outside = 0, faces = 0;
        tv[4 * std::size_t{seed} + 1] |= kInsideMark;
        // The neighbours are scattered in memory: their lines are requested one cavity
        // tetrahedron ahead (the adjacency of a tetrahedron is requested when it joins the
        // cavity), so the misses overlap the insphere tests of the tetrahedron at hand.
        request_neighbours(seed);
        for (std::size_t i = 0; i < count; ++i) {
            if (cavity_.size() < count + 4) {
                cavity_.resize(2 * cavity_.size());
                face_mask_.resize(cavity_.size());
            }
            if (outside_.size() < outside + 4) outside_.resize(2 * outside_.size() + 64);
            TetIdx* const cavity = cavity_.data();
            TetIdx* const outside_list = outside_.data();
            const TetIdx c = cavity[i];
            if (i + 1 < count) request_neighbours(cavity[i + 1]);
            unsigned mask = 0;
            // The neighbours to test, in face order (c's four neighbours are distinct
            // tetrahedra, so none of them is marked by another's test).
            TetIdx untested[4];
            unsigned untested_face[4], untested_count = 0;
            for (unsigned k = 0; k < 4; ++k) {
                const TetIdx u = tet_of(adj[4 * std::size_t{c} + k]);
                const VertIdx marked = tv[4 * std::size_t{u} + 1];
                if (marked & (kInsideMark | kOutsideMark)) {
                    const unsigned in = marked >> 31;
                    mask |= (in ^ 1u) << k;
                    faces += in ^ 1u;
                } else if (Region::kPartitioned && !region_.owns(u)) {
                    // Not ours: read, never marked (another thread may test it too).
                    if (tests.conflict(u, p)) {
                        cavity_count_ = count;
                        outside_count_ = outside;
                        return kLeftRegion;
                    }
                    mask |= 1u << k;
                    ++faces;
                } else {
                    untested[untested_count] = u;
                    untested_face[untested_count++] = k;
                }
            }
            // Tested two at a time (an odd one with itself): one paired filter, whose two chains
            // of dependent operations overlap (7% faster at 10^6 uniform points).
            unsigned in[4];
            for (unsigned j = 0; j < untested_count; j += 2) {
                const unsigned second = j + 1 < untested_count ? j + 1 : j;
                tests.conflict_pair(untested[j], untested[second], p, in[j], in[second]);
            }
            for (unsigned j = 0; j < untested_count; ++j) {
                const TetIdx u = untested[j];
                tv[4 * std::size_t{u} + 1] |= in[j] ? kInsideMark : kOutsideMark;
                cavity[count] = u;
                count += in[j];
                outside_list[outside] = u;
                outside += in[j] ^ 1u;
                __builtin_prefetch(&adj[4 * std::size_t{u}]);
                mask |= (in[j] ^ 1u) << untested_face[j];
                faces += in[j] ^ 1u;
            }
            face_mask_[i] = static_cast<std::uint8_t>(mask);
        }
        cavity_count_ = count;
        outside_count_ = outside;
        return faces;
    }

    void request_neighbours(TetIdx c) const {
        for (unsigned k = 0; k < 4; ++k) {
            __builtin_prefetch(
                &mesh_.tv[4 * std::size_t{tet_of(mesh_.adj[4 * std::size_t{c} + k])}]);
        }
    }

    /// Takes the marks off the cavity and the tetrahedra tested outside it.
    void clear_marks() {
        VertIdx* const tv = mesh_.tv.data();
        for (std::size_t i = 0; i < cavity_count_; ++i)
            tv[4 * std::size_t{cavity_[i]} + 1] &= kVertexBits;
        for (std::size_t i = 0; i < outside_count_; ++i)
            tv[4 * std::size_t{outside_[i]} + 1] &= kVertexBits;
    }

    /// Stars the cavity from p. Free slots for every face are there (region_.make_room: a
    /// cavity slot is reused only once it has been read, so in degenerate cavities the free
    /// list may serve more than faces - count), made before the arrays are addressed (adding
    /// slots may move them).
    void star(VertIdx p, std::size_t faces) {
        const std::size_t count = cavity_count_;
        std::vector<TetIdx>& free_list = region_.free_tets();
        prepare_table(3 * faces);
        VertIdx* const tv = mesh_.tv.data();
        FaceIdx* const adj = mesh_.adj.data();
        const TetIdx* const cavity = cavity_.data();
        const std::uint8_t* const face_mask = face_mask_.data();
        const TetIdx* const free_tets = free_list.data();
        std::size_t free_count = free_list.size();
        std::size_t reuse = 0;  // cavity slots [0, reuse) rewritten; all up to i are read
        for (std::size_t i = 0; i < count; ++i) {
            const unsigned mask = face_mask[i];
            if (mask == 0) continue;
            const TetIdx c = cavity[i];
            const VertIdx* cv = &tv[4 * std::size_t{c}];
            const VertIdx v[4] = {cv[0], cv[1] & kVertexBits, cv[2], cv[3]};
            const FaceIdx* ca = &adj[4 * std::size_t{c}];
            const FaceIdx out[4] = {ca[0], ca[1], ca[2], ca[3]};
            // The new tetrahedra of c's boundary faces, unrolled for each mask of boundary
            // faces (the loops over faces and neighbours, with their mask tests, were about a
            // quarter of the star's instructions).
            auto make = [&](auto mask_constant) __attribute__((always_inline)) {
                constexpr unsigned m = decltype(mask_constant)::value;
                TetIdx made[4] = {};
                for_each_slot([&](auto k_constant) __attribute__((always_inline)) {
                    constexpr unsigned k = decltype(k_constant)::value;
                    if constexpr ((m >> k) & 1u) {
                        const TetIdx t = reuse <= i ? cavity[reuse++] : free_tets[--free_count];
                        made[k] = t;
                        VertIdx* w = &tv[4 * std::size_t{t}];
                        w[0] = k == 0 ? p : v[0];
                        w[1] = k == 1 ? p : v[1];
                        w[2] = k == 2 ? p : v[2];
                        w[3] = k == 3 ? p : v[3];
                        adj[4 * std::size_t{t} + k] = out[k];
                        adj[out[k]] = 4 * t + k;
                        for_each_slot([&](auto j_constant) __attribute__((always_inline)) {
                            constexpr unsigned j = decltype(j_constant)::value;
                            if constexpr (j == k) {
                            } else if constexpr ((m >> j) & 1u) {
                                if constexpr (j < k) {
                                    adj[4 * std::size_t{t} + j] = 4 * made[j] + k;
                                    adj[4 * std::size_t{made[j]} + k] = 4 * t + j;
                                }
                            } else {
                                constexpr OtherTwo e = kOtherTwo[j][k];
                                glue(adj, v[e.a], v[e.b], 4 * t + j);
                            }
                        });
                    }
                });
            };
            switch (mask) {
                case 1:
                    make(std::integral_constant<unsigned, 1>{});
                    break;
                case 2:
                    make(std::integral_constant<unsigned, 2>{});
                    break;
                case 3:
                    make(std::integral_constant<unsigned, 3>{});
                    break;
                case 4:
                    make(std::integral_constant<unsigned, 4>{});
                    break;
                case 5:
                    make(std::integral_constant<unsigned, 5>{});
                    break;
                case 6:
                    make(std::integral_constant<unsigned, 6>{});
                    break;
                case 7:
                    make(std::integral_constant<unsigned, 7>{});
                    break;
                case 8:
                    make(std::integral_constant<unsigned, 8>{});
                    break;
                case 9:
                    make(std::integral_constant<unsigned, 9>{});
                    break;
                case 10:
                    make(std::integral_constant<unsigned, 10>{});
                    break;
                case 11:
                    make(std::integral_constant<unsigned, 11>{});
                    break;
                case 12:
                    make(std::integral_constant<unsigned, 12>{});
                    break;
                case 13:
                    make(std::integral_constant<unsigned, 13>{});
                    break;
                case 14:
                    make(std::integral_constant<unsigned, 14>{});
                    break;
                default:
                    make(std::integral_constant<unsigned, 15>{});
                    break;
            }
        }
        free_list.resize(free_count);
        for (std::size_t i = reuse; i < count; ++i) {
            tv[4 * std::size_t{cavity[i]}] = kNone;
            free_list.push_back(cavity[i]);
        }
        const TetIdx* const outside = outside_.data();
        for (std::size_t i = 0; i < outside_count_; ++i) {
            tv[4 * std::size_t{outside[i]} + 1] &= ~kOutsideMark;
        }
        region_.last_tet = cavity[0];
    }

    /// f(integral_constant<unsigned, k>) for k = 0..3.
    template <class F>
    [[gnu::always_inline]] static void for_each_slot(F&& f) {
        f(std::integral_constant<unsigned, 0>{});
        f(std::integral_constant<unsigned, 1>{});
        f(std::integral_constant<unsigned, 2>{});
        f(std::integral_constant<unsigned, 3>{});
    }

    void prepare_table(std::size_t entries) {
        if (table_.size() < 2 * entries) {
            std::size_t size = 256;
            unsigned bits = 8;
            while (size < 2 * entries) {
                size *= 2;
                ++bits;
            }
            table_.assign(size, Slot{0, kNone});
            shift_ = 64 - bits;
            generation_ = 0;
        }
        if (++generation_ == (std::uint64_t{1} << (64 - kGenerationShift))) {
            for (Slot& slot : table_) slot.tag = 0;
            generation_ = 1;
        }
    }

    /// Edge (a, b) of the face slot `face` (holding p, a and b). The first face of an edge is
    /// stored, the second is linked with it. Which of the two happens is a coin toss for the
    /// branch predictor, so both are done without a branch: the stores go to a scratch word
    /// when there is nothing to link (the new face's own twin is then overwritten when its
    /// partner arrives).
    [[gnu::always_inline]] void glue(FaceIdx* adj, VertIdx a, VertIdx b, FaceIdx face) {
        const std::uint64_t lo = (a < b ? a : b) & kKeyBits, hi = (a < b ? b : a) & kKeyBits;
        const std::uint64_t key = lo << 27 | hi;
        const std::uint64_t generation = generation_ << kGenerationShift;
        const std::uint64_t tag = generation | key;
        Slot* const table = table_.data();
        const std::size_t mask = table_.size() - 1;
        std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
        while (table[h].tag != tag && (table[h].tag & kGenerationMask) == generation) {
            h = (h + 1) & mask;
        }
        Slot& slot = table[h];
        const bool first = slot.tag != tag;
        const FaceIdx partner = slot.face;
        FaceIdx* partner_twin = first ? &scratch_ : &adj[partner];
        *partner_twin = face;
        adj[face] = partner;
        slot = {tag, face};
    }
};

}  // namespace exactmesh::triangulation::detail
