// SPDX-License-Identifier: MIT
// Green-Sibson 2D (see green_sibson_2d.hpp). Every triangle created around the new point p
// keeps p at local index 0, so the edge to test is always local edge 1:
//
//                 v                         v
//                / \                       /|\              .
//          T1   /   \  e = 3*T1+1         / | \             .
//              p --- u  --------->       p  |  q   (flip: diagonal u-v becomes p-q)
//              \     /                    \ | /             .
//          T2   \   /                      \|/              .
//                 q ... apex of T2           u
#include "triangulation/delaunay/green_sibson_2d.hpp"

#include <vector>

#include "triangulation/delaunay/delaunay_2d_core.hpp"
#include "triangulation/mesh/flip_2d.hpp"

namespace exactmesh::triangulation {

namespace {

// The mesh is closed by the infinite vertex: the kernel links outer twins without a test.
constexpr MeshBoundary kClosed = MeshBoundary::Closed;

class LawsonInserter {
  public:
    explicit LawsonInserter(detail::Delaunay2Core& core) : core_(core), mesh_(core.mesh) {}

    void insert(VertIdx p, TriIdx t) {
        stack_.clear();
        SplitTriangles made;
        if (mesh_.is_infinite(t)) {
            made = split_triangle_2d(mesh_, t, p, kClosed);
        } else {
            int on_edge = -1;
            for (int k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * t + static_cast<unsigned>(k);
                if (core_.orient(mesh_.origin(e), mesh_.destination(e), p) ==
                    predicates::Sign::Zero) {
                    on_edge = k;
                }
            }
            if (on_edge < 0) {
                made = split_triangle_2d(mesh_, t, p, kClosed);
            } else {
                made = split_edge_2d(mesh_, 3 * t + static_cast<unsigned>(on_edge), p, kClosed);
            }
        }
        core_.last_triangle = made.triangles[0];
        for (unsigned i = 0; i < made.count; ++i) stack_.push_back(made.side(i));
        while (!stack_.empty()) {
            const EdgeIdx e = stack_.back();
            stack_.pop_back();
            flip_if_needed(e);
        }
    }

  private:
    detail::Delaunay2Core& core_;
    TriMesh2& mesh_;
    std::vector<EdgeIdx> stack_;  // sides opposite p: local edge 1 of a triangle (p, u, v)

    /// e = u -> v of T1 = (p, u, v); T2 across it has apex q. Flip to (p, u, q), (p, q, v) when q
    /// lies in the perturbed circumcircle of T1 (the infinite vertex never does).
    void flip_if_needed(EdgeIdx e) {
        const TriIdx t1 = triangle_of(e);
        const VertIdx q = mesh_.tv[prev_edge(mesh_.twin[e])];
        if (q == kInfinite || !core_.conflict(t1, q)) return;
        ++core_.counters.flips;
        // The new diagonal q -> p at local 2 of T1 and p -> q at local 0 of T2: p stays at 0.
        const FlipEdges flipped = flip_2d(mesh_, e, 2, 0, kClosed);
        stack_.push_back(flipped.sides[1]);  // u -> q in (p, u, q)
        stack_.push_back(flipped.sides[2]);  // q -> v in (p, q, v)
    }
};

}  // namespace

bool detail::green_sibson_insert_all(Delaunay2Core& core) {
    std::vector<bool> skip;
    if (!core.make_first_triangle(skip)) return false;
    LawsonInserter inserter(core);
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const TriIdx t = core.locate(p);
        if (t == kNone) continue;  // duplicate, merged
        inserter.insert(p, t);
        core.note_inserted(p);
        core.progress.tick();
    }
    return true;
}

Delaunay2Result green_sibson_2d(std::span<const double> xy, const Delaunay2Options& options) {
    detail::Delaunay2Core core(xy, options);
    if (!detail::green_sibson_insert_all(core)) return core.collinear_result();
    return core.take_result();
}

}  // namespace exactmesh::triangulation
