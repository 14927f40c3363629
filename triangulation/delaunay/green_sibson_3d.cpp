// SPDX-License-Identifier: MIT
// Green-Sibson 3D (see green_sibson_3d.hpp). Every split and flip is one of flip_3d's TetStar3
// primitives (1-4, 2-6, n-2n; 2-3, 3-2, 4-4 seen from p): the region it removes is star-shaped
// from the new point p, and the new tetrahedra join p to the region's boundary faces that do
// not hold p.
//
// A link face F = (a, b, c) of t = (p, a, b, c) with the tetrahedron t2 = (a, b, c, d) behind
// it is not locally Delaunay when p lies in t2's perturbed circumsphere. The segment pd then
// meets the plane of F, and the orientations of t with a, b or c replaced by d say where:
//
//          c                    all > 0: pd crosses F inside          2-3: {t, t2} -> 3 tets
//         / \                   one < 0 (c): pd passes beyond edge ab  3-2 when ab has exactly
//        / F \                               the three tets t, t2, (a, b, p, d)
//       a --- b                 one = 0 (c): pd crosses edge ab       4-4 when ab has exactly
//                                            four tets t, t2, (a,b,p,e), (a,b,d,e)
// Anything else (and a 3-2 or 4-4 whose edge has more tetrahedra) cannot flip now; another link
// face can, and the face is tried again once the stack is empty [Joe91].
#include "triangulation/delaunay/green_sibson_3d.hpp"

#include <bit>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/delaunay/delaunay_3d_core.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

class FlipInserter {
  public:
    explicit FlipInserter(detail::Delaunay3Core& core) : core_(core), mesh_(core.mesh) {}

    void insert(VertIdx p, const detail::Delaunay3Core::Location& where) {
        stack_.clear();
        deferred_.clear();
        region_.clear();  // the hull faces p sees, when it lies outside
        const TetIdx t = where.tet;
        const int zeros = std::popcount(where.zero_faces);
        if (mesh_.is_infinite(t)) {
            collect_visible_hull(t, p);
            ++core_.counters.outside_hull;
            core_.star.star(mesh_, region_, p);
        } else if (zeros == 0) {
            core_.star.split_1_4(mesh_, t, p);
            ++core_.counters.splits_1_4;
        } else if (zeros == 1) {
            const auto k = static_cast<unsigned>(std::countr_zero(where.zero_faces));
            core_.star.split_2_6(mesh_, t, k, p);
            ++core_.counters.splits_2_6;
        } else {
            EM_ASSERT(zeros == 2);
            // The edge: the two slots whose faces do not hold p.
            unsigned ends[2], count = 0;
            for (unsigned k = 0; k < 4; ++k) {
                if ((where.zero_faces & (1u << k)) == 0) ends[count++] = k;
            }
            core_.star.split_edge(mesh_, t, ends[0], ends[1], p);
            ++core_.counters.splits_edge;
        }
        made();
        restore_delaunay(p);
    }

  private:
    detail::Delaunay3Core& core_;
    TetMesh3& mesh_;
    std::vector<TetIdx> stack_;     ///< tetrahedra holding p whose link face is to be checked
    std::vector<TetIdx> deferred_;  ///< link faces found not locally Delaunay but unflippable
    std::vector<TetIdx> region_;    ///< the hull region p sees

    enum class Outcome { LocallyDelaunay, Flipped, Unflippable };

    VertIdx vertex(TetIdx t, unsigned k) const { return mesh_.tv[4 * std::size_t{t} + k]; }
    TetIdx across(TetIdx t, unsigned k) const { return tet_of(mesh_.adj[4 * std::size_t{t} + k]); }
    /// The vertex of the tetrahedron across face k of t that is not on that face.
    VertIdx apex_across(TetIdx t, unsigned k) const {
        return mesh_.tv[mesh_.adj[4 * std::size_t{t} + k]];
    }

    /// p lies outside the hull and sees the hull face of the infinite tetrahedron t: all the
    /// infinite tetrahedra whose hull faces p sees strictly, a connected region of the hull
    /// (its horizon edges are never collinear with p, or the faces on both sides would hold p
    /// in their planes). Starring them joins p to those faces and to the horizon, as repeated
    /// 2-3 flips through the hull would; hull faces whose plane holds p are left to the 4-4
    /// flips, so no flip ever meets a hull face p sees strictly.
    void collect_visible_hull(TetIdx t, VertIdx p) {
        std::vector<std::uint32_t>& stamp = core_.star.stamp;
        const std::uint32_t mark = core_.star.next_stamp();
        stamp[t] = mark;
        region_.push_back(t);
        for (std::size_t r = 0; r < region_.size(); ++r) {
            const TetIdx c = region_[r];
            const unsigned m = mesh_.slot_of(c, kInfinite);
            for (unsigned k = 0; k < 4; ++k) {
                if (k == m) continue;
                const TetIdx u = across(c, k);  // shares kInfinite with c: infinite too
                if (stamp[u] == mark) continue;
                stamp[u] = mark;
                if (core_.orient_replacing(u, mesh_.slot_of(u, kInfinite), p) == Sign::Positive) {
                    region_.push_back(u);
                }
            }
        }
    }

    /// Pushes the tetrahedra the last star made (they hold p) and walks on from the first.
    void made() {
        const std::vector<TetIdx>& created = core_.star.created;
        stack_.insert(stack_.end(), created.begin(), created.end());
        if (!created.empty()) core_.last_tet = created.front();
    }

    void restore_delaunay(VertIdx p) {
        std::uint64_t flips_at_retry = ~std::uint64_t{0};
        for (;;) {
            while (!stack_.empty()) {
                const TetIdx t = stack_.back();
                stack_.pop_back();
                if (mesh_.is_dead(t)) continue;
                const unsigned i = mesh_.slot_of(t, p);
                if (i == 4) continue;  // the slot was recycled for a tetrahedron without p
                if (try_flip(t, i, p) == Outcome::Unflippable) {
                    deferred_.push_back(t);
                    ++core_.counters.unflippable;
                }
            }
            if (deferred_.empty()) return;
            const std::uint64_t flips = flip_count();
            // A whole pass over the deferred faces flipped nothing while some stay non-Delaunay:
            // the theory says this cannot happen, so it is a bug, not bad input.
            EM_ASSERT(flips != flips_at_retry);
            flips_at_retry = flips;
            stack_.swap(deferred_);
        }
    }

    std::uint64_t flip_count() const {
        return core_.counters.flips_2_3 + core_.counters.flips_3_2 + core_.counters.flips_4_4;
    }

    /// The link face of t (opposite p, at slot i): flips it when it is not locally Delaunay and
    /// a 2-3, 3-2 or 4-4 flip applies.
    Outcome try_flip(TetIdx t, unsigned i, VertIdx p) {
        const TetIdx t2 = across(t, i);
        if (!core_.conflict(t2, p)) return Outcome::LocallyDelaunay;
        const VertIdx d = apex_across(t, i);  // finite: no point conflicts across a hull face
        const bool infinite = mesh_.is_infinite(t);
        unsigned negative = 4, zero = 4, negatives = 0, zeros = 0;
        for (unsigned j = 0; j < 4; ++j) {
            if (j == i) continue;
            // With kInfinite on F, replacing a finite vertex of F by d leaves an infinite
            // tetrahedron, valid as soon as the finite one (kInfinite replaced) is.
            if (infinite && vertex(t, j) != kInfinite) continue;
            const Sign s = core_.orient_replacing(t, j, d);
            if (s == Sign::Negative) {
                negative = j;
                ++negatives;
            } else if (s == Sign::Zero) {
                zero = j;
                ++zeros;
            }
        }
        // kInfinite on F: p lies in the plane of the hull face behind F (strictly visible hull
        // faces were all starred when p was inserted), so only the 4-4 case (a 2-2 flip of the
        // hull faces and one of the tetrahedra below them) can apply.
        EM_ASSERT(!infinite || (zeros == 1 && negatives == 0));
        if (negatives == 0 && zeros == 0) {
            core_.star.flip_2_3(mesh_, t, i);
            made();
            ++core_.counters.flips_2_3;
            return Outcome::Flipped;
        }
        if (negatives == 1 && zeros == 0) {
            // Reflex edge ab (F without vertex `negative`): flippable when exactly three
            // tetrahedra share it, the third being (a, b, p, d).
            if (apex_across(t, negative) != d) return Outcome::Unflippable;
            core_.star.flip_3_2(mesh_, t, i, negative);
            made();
            ++core_.counters.flips_3_2;
            return Outcome::Flipped;
        }
        if (negatives == 0 && zeros == 1) {
            // p, d, a, b coplanar and pd crosses edge ab: flippable when exactly four
            // tetrahedra share it, t3 = (a, b, p, e) and t4 = (a, b, d, e).
            const VertIdx c = vertex(t, zero);
            const VertIdx e = apex_across(t, zero);
            const unsigned c_in_t2 = mesh_.slot_of(t2, c);
            if (apex_across(t2, c_in_t2) != e) return Outcome::Unflippable;
            core_.star.flip_4_4(mesh_, t, i, zero);
            made();
            ++core_.counters.flips_4_4;
            return Outcome::Flipped;
        }
        return Outcome::Unflippable;
    }
};

}  // namespace

Delaunay3Result green_sibson_3d(std::span<const double> xyz, const Delaunay3Options& options) {
    return detail::insert_incrementally<FlipInserter>(xyz, options);
}

}  // namespace exactmesh::triangulation
