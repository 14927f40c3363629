// SPDX-License-Identifier: MIT
// Edge insertion for the min-max angle triangulation (see edge_cutting_2d.hpp).
//
// One cut, around the worst triangle t = (b, c, a) with its largest angle at b:
//
//            l_m ....... q            the candidate edge bq leaves b through the open
//            /  .      .  \           wedge c-b-a and crosses the edges (l_i, r_i),
//          l_1 ---------- r_1 ...     l_1 = a, r_1 = c, l_i on its left, r_i on its right;
//            \     t     /            the triangles it crosses (t first) are removed, and
//             \         /             the polygons b, l_1.., q (left) and b, r_1.., q (right)
//              \       /              are triangulated again by ears (retriangulate_by_ears).
//                  b
//
// Why the result is optimal: let theta be the angle at b. If a triangulation T* had all its
// angles below theta, some edge bq of T* would enter the open wedge (else one triangle of T*
// at b would contain the wedge and have an angle >= theta at b), and since t holds no vertex,
// bq crosses ac. [EdelsbrunnerTanWaupotitsch92] show that then inserting some such bq and
// retriangulating the two polygons (their way: retriangulate_by_ears) leaves every new angle
// below theta; an optimal retriangulation of each polygon does at least as well (the fallback
// where exact ties may part the two), so a cut exists whenever T is not optimal, and a failed
// search over every q proves optimality.
// The cutter works on the half-edges of a HalfEdgeEdit (flip_2d.hpp) of the Triangulation2: the
// walk crosses to the twin's local edge directly, and a cut links the new triangles' sides to the
// outer half-edges it saved, with no search for the shared edge.
// Termination: a cut removes t (largest angle theta) and adds triangles whose angles are all
// below theta, so the decreasingly sorted vector of the triangles' largest angles strictly
// decreases lexicographically; there are finitely many triangulations.
#include "triangulation/modification/edge_cutting_2d.hpp"

#include <algorithm>
#include <array>
#include <queue>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/mesh/flip_2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::compare_angles;
using predicates::compare_lengths;
using predicates::Corner;
using predicates::largest_corner;
using predicates::orient2d;
using predicates::Sign;

std::size_t slot(TriIdx t, unsigned k) {
    return 3 * static_cast<std::size_t>(t) + k;
}

/// A triangle in the heap of largest angles, with the vertices it had when pushed (a slot that
/// no longer holds them is a stale entry).
struct HeapEntry {
    TriIdx t;
    std::array<VertIdx, 3> vertices;
    unsigned corner;  ///< local index of the largest corner
    Corner largest;
};

/// For v on the line pq (p != q): whether v lies strictly between p and q (exact comparisons).
bool strictly_between(const double* p, const double* q, const double* v) {
    const int k = p[0] != q[0] ? 0 : 1;
    const double lo = std::min(p[k], q[k]), hi = std::max(p[k], q[k]);
    return lo < v[k] && v[k] < hi;
}

/// A triangle of a polygon's retriangulation, counter-clockwise.
using NewTriangle = std::array<VertIdx, 3>;

class EdgeCutter {
  public:
    explicit EdgeCutter(TriMesh2& mesh) : mesh_(mesh) {}

    EdgeCuttingCounters run() {
        region_mark_.assign(mesh_.triangle_slots(), 0);
        for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) push_triangle(t);
        while (!heap_.empty()) {
            const HeapEntry top = heap_.top();
            heap_.pop();
            if (!current(top)) continue;
            ++counters_.worst_triangles;
            if (!cut(top)) break;
        }
        return counters_;
    }

  private:
    struct Compare {
        bool operator()(const HeapEntry& x, const HeapEntry& y) const {
            const Sign s = compare_angles(x.largest, y.largest);
            if (s != Sign::Zero) return s == Sign::Negative;
            return x.t > y.t;  // deterministic among equal angles: lower slot first
        }
    };

    VertIdx vertex(TriIdx t, unsigned k) const { return mesh_.tv[slot(t, k % 3)]; }
    const double* point(VertIdx v) const { return mesh_.point(v); }
    bool blocked(TriIdx t, unsigned k) const {
        const std::size_t e = slot(t, k);
        return mesh_.twin[e] == kNone || (!mesh_.flags.empty() && mesh_.flags[e] != 0);
    }
    /// The triangle across edge k of t (not blocked).
    TriIdx across(TriIdx t, unsigned k) const { return triangle_of(mesh_.twin[slot(t, k)]); }

    bool current(const HeapEntry& e) const {
        return vertex(e.t, 0) == e.vertices[0] && vertex(e.t, 1) == e.vertices[1] &&
               vertex(e.t, 2) == e.vertices[2];
    }

    void push_triangle(TriIdx t) {
        HeapEntry e;
        e.t = t;
        e.vertices = {vertex(t, 0), vertex(t, 1), vertex(t, 2)};
        // The largest corner is opposite the longest side (side k+1 is opposite corner k).
        unsigned best = 0;
        for (unsigned k = 1; k < 3; ++k) {
            if (compare_lengths(point(vertex(t, k + 1)), point(vertex(t, k + 2)),
                                point(vertex(t, best + 1)),
                                point(vertex(t, best + 2))) == Sign::Positive) {
                best = k;
            }
        }
        e.corner = best;
        e.largest = {point(vertex(t, best)), point(vertex(t, best + 1)),
                     point(vertex(t, best + 2))};
        heap_.push(e);
    }

    /// Tries every candidate q for the worst triangle; applies the first cut that succeeds.
    bool cut(const HeapEntry& worst) {
        const TriIdx t = worst.t;
        b_ = vertex(t, worst.corner);
        c_ = vertex(t, worst.corner + 1);
        a_ = vertex(t, worst.corner + 2);
        theta_ = worst.largest;
        const unsigned entry = (worst.corner + 1) % 3;  // edge c -> a
        if (blocked(t, entry)) return false;
        collect_candidates(t, entry);
        for (const auto& [depth, q] : candidates_) {
            q_ = q;
            if (!walk(t, entry, q)) continue;
            ++counters_.candidates;
            // The paper's retriangulation first, in O(m); the optimal one (O(m^3)) only where an
            // exact tie or an angle it does not test may have made the two differ.
            if (!retriangulate_by_ears()) {
                if (!ear_anomaly_) continue;
                ++counters_.dynamic_programs;
                if (!retriangulate()) continue;
            }
            apply();
            return true;
        }
        return false;
    }

    /// Whether vertex z lies strictly inside the wedge at b and strictly beyond line ca.
    bool in_region(VertIdx z) const {
        return orient2d(point(b_), point(c_), point(z)) == Sign::Positive &&
               orient2d(point(b_), point(a_), point(z)) == Sign::Negative &&
               orient2d(point(c_), point(a_), point(z)) == Sign::Negative;
    }

    /// Whether the edge (p, q) may meet the open region (wedge beyond ca): a superset test
    /// (the far side of ca minus the wedge falls in two pieces, so an edge that has a point
    /// strictly beyond ca and reaches both half-planes of the wedge crosses the wedge).
    bool may_meet_region(VertIdx p, VertIdx q) const {
        const double *pb = point(b_), *pc = point(c_), *pa = point(a_);
        const double *pp = point(p), *pq = point(q);
        if (orient2d(pb, pc, pp) != Sign::Positive && orient2d(pb, pc, pq) != Sign::Positive) {
            return false;
        }
        if (orient2d(pb, pa, pp) != Sign::Negative && orient2d(pb, pa, pq) != Sign::Negative) {
            return false;
        }
        return orient2d(pc, pa, pp) == Sign::Negative || orient2d(pc, pa, pq) == Sign::Negative;
    }

    /// Breadth-first search of the triangles meeting the region beyond edge ca, never across a
    /// constrained or boundary edge; every vertex in the region is a candidate, in order of
    /// search depth (near ones first: fewer crossings, cheaper polygons).
    void collect_candidates(TriIdx t, unsigned entry) {
        candidates_.clear();
        vertex_mark_.resize(mesh_.vertex_count(), 0);
        ++stamp_;
        if (stamp_ == 0) {
            std::fill(region_mark_.begin(), region_mark_.end(), 0);
            std::fill(vertex_mark_.begin(), vertex_mark_.end(), 0);
            stamp_ = 1;
        }
        region_mark_[t] = stamp_;
        std::vector<std::pair<TriIdx, std::uint32_t>>& queue = bfs_;
        queue.clear();
        const TriIdx first = across(t, entry);
        region_mark_[first] = stamp_;
        queue.emplace_back(first, 1);
        for (std::size_t head = 0; head < queue.size(); ++head) {
            const auto [w, depth] = queue[head];
            ++counters_.visited;
            for (unsigned s = 0; s < 3; ++s) {
                const VertIdx z = vertex(w, s);
                if (vertex_mark_[z] != stamp_) {
                    vertex_mark_[z] = stamp_;
                    if (in_region(z)) candidates_.emplace_back(depth, z);
                }
                if (blocked(w, s)) continue;
                const TriIdx next = across(w, s);
                if (region_mark_[next] == stamp_) continue;
                if (!may_meet_region(vertex(w, s), vertex(w, s + 1))) continue;
                region_mark_[next] = stamp_;
                queue.emplace_back(next, depth + 1);
            }
        }
        std::stable_sort(candidates_.begin(), candidates_.end());
    }

    /// The straight walk from b to q starting across edge ca of t: fills the crossed triangles
    /// and the left and right chains; false when bq hits a vertex, the boundary or a constraint.
    bool walk(TriIdx t, unsigned entry, VertIdx q) {
        crossed_.assign(1, t);
        left_.assign(1, a_);
        right_.assign(1, c_);
        TriIdx w = t;
        unsigned exit = entry;
        const double *pb = point(b_), *pq = point(q);
        for (;;) {
            if (blocked(w, exit)) return false;
            // Edge r -> l of w is l -> r of next, its local edge s; z is next's third vertex.
            const EdgeIdx twin = mesh_.twin[slot(w, exit)];
            const TriIdx next = triangle_of(twin);
            const unsigned s = twin % 3;
            crossed_.push_back(next);
            const VertIdx z = vertex(next, s + 2);
            if (z == q) return true;
            const Sign side = orient2d(pb, pq, point(z));
            if (side == Sign::Zero) return false;  // z on the segment bq (it cannot lie beyond q)
            w = next;
            if (side == Sign::Positive) {
                left_.push_back(z);
                exit = (s + 1) % 3;  // edge r -> z
            } else {
                right_.push_back(z);
                exit = (s + 2) % 3;  // edge z -> l
            }
        }
    }

    /// How one ear (apex, x, y) fares: `apex` is the newest vertex, x and y the top two of its
    /// chain's stack, x the corner the paper tests.
    enum class Ear { Cut, Refused, Anomaly };

    /// The ear of the new vertex `apex` over the chain vertices x (stack top) and y (below it),
    /// given counter-clockwise as (o, p, r) with the paper's corner at x. Cut when the triangle is
    /// strictly counter-clockwise and all three of its angles are below theta; Refused where
    /// the paper refuses too (a reflex or flat turn, or the angle at x above theta); Anomaly
    /// where the paper would cut but this exact test does not (the angle at x equals theta, or
    /// another angle reaches it): then the two procedures may part ways.
    Ear test_ear(VertIdx o, VertIdx p, VertIdx r, VertIdx x) {
        const double *po = point(o), *pp = point(p), *pr = point(r);
        if (orient2d(po, pp, pr) != Sign::Positive) return Ear::Refused;
        // Rotate (o, p, r) so that x comes first: its corner is (x, next, next-next).
        const double* px = point(x);
        const Corner at_x = x == o   ? Corner{po, pp, pr}
                            : x == p ? Corner{pp, pr, po}
                                     : Corner{pr, po, pp};
        const Sign center = compare_angles(at_x, theta_);
        if (center == Sign::Positive) return Ear::Refused;
        if (center == Sign::Zero) return Ear::Anomaly;
        const Corner others[2] = {{at_x.p, at_x.q, px}, {at_x.q, px, at_x.p}};
        for (const Corner& c : others) {
            if (compare_angles(c, theta_) != Sign::Negative) return Ear::Anomaly;
        }
        return Ear::Cut;
    }

    /// The retriangulation of [EdelsbrunnerTanWaupotitsch92] (as in the authors' edge-insertion
    /// code): walking from b to q, each new chain vertex S cuts ears (S, x, y) off the top of its
    /// side's stack while the angle at x stays below theta, never down to b; q then has to cut
    /// every remaining ear of both sides, down to b. Each side is a stack (O(m) ears in all).
    /// Every ear is strictly counter-clockwise and the ears triangulate each polygon
    /// combinatorially, so they tile it (signed areas add up to the polygon's, all positive).
    /// Records in ear_anomaly_ whether the outcome may differ from the paper's.
    bool retriangulate_by_ears() {
        new_triangles_.clear();
        ear_anomaly_ = false;
        // left: the polygon q, l_m, ..., l_1, b is counter-clockwise, so an ear of the newest
        // vertex S over (x, y) is (S, x, y); right: b, r_1, ..., r_k, q, so the ear is (y, x, S).
        auto side = [&](const std::vector<VertIdx>& chain, bool left) {
            std::vector<VertIdx>& stack = ear_stack_;
            stack.assign({b_, chain.front()});
            auto ears = [&](VertIdx apex, std::size_t floor) {
                while (stack.size() > floor) {
                    const VertIdx x = stack.back(), y = stack[stack.size() - 2];
                    const Ear ear = left ? test_ear(apex, x, y, x) : test_ear(y, x, apex, x);
                    if (ear != Ear::Cut) {
                        if (ear == Ear::Anomaly) ear_anomaly_ = true;
                        return false;
                    }
                    new_triangles_.push_back(left ? NewTriangle{apex, x, y}
                                                  : NewTriangle{y, x, apex});
                    stack.pop_back();
                }
                return true;
            };
            for (std::size_t i = 1; i < chain.size(); ++i) {
                ears(chain[i], 2);  // never down to b: (S, b) is no edge of the result
                stack.push_back(chain[i]);
            }
            return ears(q_, 1);
        };
        return side(left_, true) && side(right_, false);
    }

    /// Triangulates both polygons with every largest angle below theta (optimal min-max each);
    /// false when one of them cannot be.
    bool retriangulate() {
        new_triangles_.clear();
        // Left polygon, counter-clockwise with base b -> q closing it: q, l_m, ..., l_1, b.
        polygon_.clear();
        polygon_.push_back(q_);
        for (auto it = left_.rbegin(); it != left_.rend(); ++it) polygon_.push_back(*it);
        polygon_.push_back(b_);
        if (!triangulate_polygon()) return false;
        // Right polygon: b, r_1, ..., r_k, q, closed by q -> b.
        polygon_.clear();
        polygon_.push_back(b_);
        for (const VertIdx r : right_) polygon_.push_back(r);
        polygon_.push_back(q_);
        return triangulate_polygon();
    }

    bool diagonal_in_cone(std::size_t i, std::size_t j) const {
        const std::size_t n = polygon_.size();
        const double* a = point(polygon_[i]);
        const double* a0 = point(polygon_[(i + n - 1) % n]);
        const double* a1 = point(polygon_[(i + 1) % n]);
        const double* b = point(polygon_[j]);
        if (orient2d(a, a1, a0) != Sign::Negative) {  // convex (or flat) corner
            return orient2d(a, b, a0) == Sign::Positive && orient2d(b, a, a1) == Sign::Positive;
        }
        return !(orient2d(a, b, a1) != Sign::Negative && orient2d(b, a, a0) != Sign::Negative);
    }

    /// Whether polygon_[i] polygon_[j] is a diagonal: inside at both ends, crossing no side
    /// and passing through no vertex.
    bool is_diagonal(std::size_t i, std::size_t j) const {
        if (!diagonal_in_cone(i, j) || !diagonal_in_cone(j, i)) return false;
        const std::size_t n = polygon_.size();
        const double* p = point(polygon_[i]);
        const double* q = point(polygon_[j]);
        for (std::size_t x = 0; x < n; ++x) {
            if (x == i || x == j) continue;
            const double* v = point(polygon_[x]);
            const Sign o = orient2d(p, q, v);
            if (o == Sign::Zero && strictly_between(p, q, v)) return false;
            const std::size_t y = (x + 1) % n;
            if (y == i || y == j) continue;
            const double* w = point(polygon_[y]);
            const Sign o2 = orient2d(p, q, w);
            if (to_int(o) * to_int(o2) < 0 &&
                to_int(orient2d(v, w, p)) * to_int(orient2d(v, w, q)) < 0) {
                return false;
            }
        }
        return true;
    }

    /// Klincsek's dynamic program over polygon_ (counter-clockwise, closed by its last -> first
    /// edge): the triangulation minimizing the largest angle among those whose angles are all
    /// below theta. Appends its triangles to new_triangles_; false when there is none.
    bool triangulate_polygon() {
        const std::size_t n = polygon_.size();
        EM_ASSERT(n >= 3);
        diagonal_.assign(n * n, 0);
        feasible_.assign(n * n, 0);
        value_.assign(n * n, Corner{nullptr, nullptr, nullptr});
        choice_.assign(n * n, 0);
        auto at = [n](std::size_t i, std::size_t j) { return i * n + j; };
        for (std::size_t i = 0; i + 1 < n; ++i) {
            diagonal_[at(i, i + 1)] = 1;
            feasible_[at(i, i + 1)] = 1;  // a side: no triangle, value -infinity
        }
        for (std::size_t i = 0; i + 2 < n; ++i) {
            for (std::size_t j = i + 2; j < n; ++j) {
                diagonal_[at(i, j)] = (i == 0 && j == n - 1) ? 1 : (is_diagonal(i, j) ? 1 : 0);
            }
        }
        auto larger = [](const Corner& x, const Corner& y) {
            if (x.o == nullptr) return y;
            if (y.o == nullptr) return x;
            return compare_angles(y, x) == Sign::Positive ? y : x;
        };
        for (std::size_t length = 2; length < n; ++length) {
            for (std::size_t i = 0; i + length < n; ++i) {
                const std::size_t j = i + length;
                if (diagonal_[at(i, j)] == 0) continue;
                const double* pi = point(polygon_[i]);
                const double* pj = point(polygon_[j]);
                for (std::size_t m = i + 1; m < j; ++m) {
                    if (feasible_[at(i, m)] == 0 || feasible_[at(m, j)] == 0) continue;
                    const double* pm = point(polygon_[m]);
                    if (orient2d(pi, pm, pj) != Sign::Positive) continue;
                    const Corner corner = largest_corner(pi, pm, pj);
                    if (compare_angles(corner, theta_) != Sign::Negative) continue;
                    const Corner value = larger(larger(corner, value_[at(i, m)]), value_[at(m, j)]);
                    if (feasible_[at(i, j)] == 0 ||
                        compare_angles(value, value_[at(i, j)]) == Sign::Negative) {
                        feasible_[at(i, j)] = 1;
                        value_[at(i, j)] = value;
                        choice_[at(i, j)] = static_cast<std::uint32_t>(m);
                    }
                }
            }
        }
        if (feasible_[at(0, n - 1)] == 0) return false;
        std::vector<std::pair<std::size_t, std::size_t>>& stack = dp_stack_;
        stack.assign(1, {0, n - 1});
        while (!stack.empty()) {
            const auto [i, j] = stack.back();
            stack.pop_back();
            if (j < i + 2) continue;
            const std::size_t m = choice_[at(i, j)];
            new_triangles_.push_back({polygon_[i], polygon_[m], polygon_[j]});
            stack.emplace_back(i, m);
            stack.emplace_back(m, j);
        }
        return true;
    }

    /// Replaces the crossed triangles by the new ones (same count: m crossed edges remove m + 1
    /// triangles, and the two polygons of m + 5 vertices in all take m + 1), relinking twins.
    void apply() {
        EM_ASSERT(new_triangles_.size() == crossed_.size());
        ++counters_.insertions;
        counters_.removed_edges += crossed_.size() - 1;
        std::vector<TriIdx> removed = crossed_;
        std::sort(removed.begin(), removed.end());
        // The region's boundary: directed edge p -> q of a removed triangle, the outer half-edge
        // facing it (kNone on the domain boundary) and its flags.
        struct Side {
            std::uint64_t key;
            EdgeIdx outer;
            std::uint8_t flag;
        };
        std::vector<Side> boundary;
        const bool flagged = !mesh_.flags.empty();
        for (const TriIdx r : crossed_) {
            for (unsigned s = 0; s < 3; ++s) {
                const EdgeIdx outer = mesh_.twin[slot(r, s)];
                if (outer != kNone &&
                    std::binary_search(removed.begin(), removed.end(), triangle_of(outer)))
                    continue;
                const std::uint64_t key = (std::uint64_t{vertex(r, s)} << 32) | vertex(r, s + 1);
                const std::uint8_t flag = flagged ? mesh_.flags[slot(r, s)] : 0;
                boundary.push_back({key, outer, flag});
            }
        }
        std::sort(boundary.begin(), boundary.end(),
                  [](const Side& x, const Side& y) { return x.key < y.key; });
        std::vector<std::pair<std::uint64_t, EdgeIdx>> inner;
        for (std::size_t i = 0; i < crossed_.size(); ++i) {
            const TriIdx t = crossed_[i];
            for (unsigned s = 0; s < 3; ++s) mesh_.tv[slot(t, s)] = new_triangles_[i][s];
            for (unsigned s = 0; s < 3; ++s) {
                const std::uint64_t key = (std::uint64_t{vertex(t, s)} << 32) | vertex(t, s + 1);
                inner.emplace_back(key, static_cast<EdgeIdx>(slot(t, s)));
            }
        }
        std::sort(inner.begin(), inner.end());
        for (const auto& [key, e] : inner) {
            const std::uint64_t reverse = (key << 32) | (key >> 32);
            const auto twin =
                std::lower_bound(inner.begin(), inner.end(), std::make_pair(reverse, EdgeIdx{0}));
            if (twin != inner.end() && twin->first == reverse) {
                mesh_.twin[e] = twin->second;
                if (flagged) mesh_.flags[e] = 0;
                continue;
            }
            const auto side =
                std::lower_bound(boundary.begin(), boundary.end(), key,
                                 [](const Side& x, std::uint64_t k) { return x.key < k; });
            if (side == boundary.end() || side->key != key) {
                throw InternalError(
                    "edge_cutting_2d: new triangle side not on the region boundary");
            }
            mesh_.twin[e] = side->outer;
            if (flagged) mesh_.flags[e] = side->flag;
            if (side->outer != kNone) mesh_.twin[side->outer] = e;
        }
        for (const TriIdx t : crossed_) push_triangle(t);
    }

    TriMesh2& mesh_;
    EdgeCuttingCounters counters_;
    std::priority_queue<HeapEntry, std::vector<HeapEntry>, Compare> heap_;
    VertIdx a_ = kNone, b_ = kNone, c_ = kNone, q_ = kNone;
    Corner theta_{nullptr, nullptr, nullptr};
    // Scratch, reused across cuts.
    std::vector<std::pair<std::uint32_t, VertIdx>> candidates_;
    std::vector<std::pair<TriIdx, std::uint32_t>> bfs_;
    std::vector<std::uint32_t> region_mark_, vertex_mark_;
    std::uint32_t stamp_ = 0;
    std::vector<TriIdx> crossed_;
    std::vector<VertIdx> left_, right_, polygon_, ear_stack_;
    bool ear_anomaly_ = false;
    std::vector<std::uint8_t> diagonal_, feasible_;
    std::vector<Corner> value_;
    std::vector<std::uint32_t> choice_;
    std::vector<std::pair<std::size_t, std::size_t>> dp_stack_;
    std::vector<NewTriangle> new_triangles_;
};

}  // namespace

EdgeCuttingCounters edge_cutting_2d(Triangulation2& mesh) {
    validate_points_2d(mesh.xy);
    HalfEdgeEdit edit(mesh);
    return EdgeCutter(edit.mesh()).run();
}

Triangulation2 min_max_angle_triangulation_2d(std::span<const double> xy,
                                              EdgeCuttingCounters* counters) {
    const Delaunay2Result delaunay = bowyer_watson_2d(xy);
    Triangulation2 mesh;
    mesh.xy.assign(xy.begin(), xy.end());
    mesh.triangles = delaunay.triangles;
    mesh.neighbors = delaunay.neighbors;
    const EdgeCuttingCounters work = edge_cutting_2d(mesh);
    if (counters != nullptr) *counters = work;
    return mesh;
}

}  // namespace exactmesh::triangulation
