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
#include "triangulation/green_sibson_2d.hpp"

#include <vector>

#include "triangulation/delaunay_2d_core.hpp"

namespace exactmesh::triangulation {

namespace {

class LawsonInserter {
public:
    explicit LawsonInserter(detail::Delaunay2Core& core) : core_(core), mesh_(core.mesh) {}

    void insert(VertIdx p, TriIdx t) {
        stack_.clear();
        if (mesh_.is_infinite(t)) {
            split_triangle(t, p);
        } else {
            int on_edge = -1;
            for (int k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * t + static_cast<unsigned>(k);
                if (core_.orient(mesh_.origin(e), mesh_.destination(e), p) == predicates::Sign::Zero) {
                    on_edge = k;
                }
            }
            if (on_edge < 0) {
                split_triangle(t, p);
            } else {
                split_edge(3 * t + static_cast<unsigned>(on_edge), p);
            }
        }
        while (!stack_.empty()) {
            const TriIdx t1 = stack_.back();
            stack_.pop_back();
            flip_if_needed(t1);
        }
    }

private:
    detail::Delaunay2Core& core_;
    TriMesh2& mesh_;
    std::vector<TriIdx> stack_;

    void set(TriIdx t, VertIdx a, VertIdx b, VertIdx c) {
        mesh_.tv[3 * t] = a;
        mesh_.tv[3 * t + 1] = b;
        mesh_.tv[3 * t + 2] = c;
    }

    /// 1 -> 3: t = (a, b, c) becomes (p, a, b), (p, b, c), (p, c, a).
    void split_triangle(TriIdx t, VertIdx p) {
        const VertIdx a = mesh_.tv[3 * t], b = mesh_.tv[3 * t + 1], c = mesh_.tv[3 * t + 2];
        const EdgeIdx x = mesh_.twin[3 * t], y = mesh_.twin[3 * t + 1], z = mesh_.twin[3 * t + 2];
        const TriIdx t1 = t, t2 = mesh_.new_triangle(), t3 = mesh_.new_triangle();
        set(t1, p, a, b);
        set(t2, p, b, c);
        set(t3, p, c, a);
        mesh_.link(3 * t1 + 1, x);
        mesh_.link(3 * t2 + 1, y);
        mesh_.link(3 * t3 + 1, z);
        mesh_.link(3 * t1 + 2, 3 * t2);
        mesh_.link(3 * t2 + 2, 3 * t3);
        mesh_.link(3 * t3 + 2, 3 * t1);
        stack_.insert(stack_.end(), {t1, t2, t3});
        core_.last_triangle = t1;
    }

    /// 2 -> 4: p on edge e = a -> b of (a, b, c), whose twin lies in (b, a, d).
    void split_edge(EdgeIdx e, VertIdx p) {
        const TriIdx t = triangle_of(e), u = triangle_of(mesh_.twin[e]);
        const EdgeIdx f = mesh_.twin[e];
        const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
        const VertIdx c = mesh_.tv[prev_edge(e)], d = mesh_.tv[prev_edge(f)];
        const EdgeIdx bc = mesh_.twin[next_edge(e)], ca = mesh_.twin[prev_edge(e)];
        const EdgeIdx ad = mesh_.twin[next_edge(f)], db = mesh_.twin[prev_edge(f)];
        const TriIdx t1 = t, t2 = u, t3 = mesh_.new_triangle(), t4 = mesh_.new_triangle();
        set(t1, p, b, c);
        set(t2, p, c, a);
        set(t3, p, a, d);
        set(t4, p, d, b);
        mesh_.link(3 * t1 + 1, bc);
        mesh_.link(3 * t2 + 1, ca);
        mesh_.link(3 * t3 + 1, ad);
        mesh_.link(3 * t4 + 1, db);
        mesh_.link(3 * t1 + 2, 3 * t2);
        mesh_.link(3 * t2 + 2, 3 * t3);
        mesh_.link(3 * t3 + 2, 3 * t4);
        mesh_.link(3 * t4 + 2, 3 * t1);
        stack_.insert(stack_.end(), {t1, t2, t3, t4});
        core_.last_triangle = t1;
    }

    /// T1 = (p, u, v); T2 across u -> v has apex q. Flip to (p, u, q), (p, q, v) when q lies in
    /// the perturbed circumcircle of T1 (the infinite vertex never does).
    void flip_if_needed(TriIdx t1) {
        const EdgeIdx e = 3 * t1 + 1;
        const EdgeIdx f = mesh_.twin[e];
        const TriIdx t2 = triangle_of(f);
        const VertIdx q = mesh_.tv[prev_edge(f)];
        if (q == kInfinite || !core_.conflict(t1, q)) return;
        ++core_.counters.flips;
        const VertIdx p = mesh_.tv[3 * t1], u = mesh_.tv[3 * t1 + 1], v = mesh_.tv[3 * t1 + 2];
        const EdgeIdx vp = mesh_.twin[3 * t1 + 2];
        const EdgeIdx uq = mesh_.twin[next_edge(f)], qv = mesh_.twin[prev_edge(f)];
        set(t1, p, u, q);
        set(t2, p, q, v);
        mesh_.link(3 * t1 + 1, uq);
        mesh_.link(3 * t2 + 1, qv);
        mesh_.link(3 * t2 + 2, vp);
        mesh_.link(3 * t1 + 2, 3 * t2);
        stack_.push_back(t1);
        stack_.push_back(t2);
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
    }
    return true;
}

Delaunay2Result green_sibson_2d(std::span<const double> xy, const Delaunay2Options& options) {
    detail::Delaunay2Core core(xy, options);
    if (!detail::green_sibson_insert_all(core)) return core.collinear_result();
    return core.take_result();
}

}  // namespace exactmesh::triangulation
