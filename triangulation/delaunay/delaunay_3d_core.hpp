// SPDX-License-Identifier: MIT
// Shared machinery of the 3D Delaunay constructions (internal to triangulation/): the points in
// insertion order, the exact conflict test with the infinite vertex, the remembering visibility
// walk, the first tetrahedron, the star of a point over a region (flip_3d's TetStar3: the
// retetrahedralization Green-Sibson's splits and flips are made of; Bowyer-Watson stars its
// cavities with its own, specialised copy), and the conversion to the caller's numbering.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "base/stopwatch.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
#include "triangulation/delaunay/walk_random.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

/// The exact conflict test of the constructions on `mesh`, counted in `counters`: what
/// Delaunay3Core calls with its own counters, and each thread of parallel_bowyer_watson_3d with
/// its own (the tests only read the mesh).
struct ConflictTest3 {
    const TetMesh3& mesh;
    const VertIdx* input_index;  ///< mesh vertex -> caller's index (the perturbation's order)
    Delaunay3Counters& counters;

    /// Perturbed insphere of four finite mesh vertices (positively oriented) and p: never Zero.
    /// Inline: the filter decides almost every call; the exact tie goes out of line.
    Sign insphere(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p) {
        ++counters.insphere_calls;
        const Sign s = predicates::insphere(mesh.point(a), mesh.point(b), mesh.point(c),
                                            mesh.point(d), mesh.point(p));
        return s != Sign::Zero ? s : insphere_tie(a, b, c, d, p);
    }
    /// True when p lies in the perturbed circumsphere of t. For an infinite tetrahedron: p lies
    /// strictly beyond its hull face, or in the face's plane and inside its perturbed
    /// circumcircle (the limit of the circumspheres as the fourth vertex goes to infinity).
    bool conflict(TetIdx t, VertIdx p) {
        const VertIdx* v = &mesh.tv[4 * std::size_t{t}];
        if (v[3] != kInfinite) return insphere(v[0], v[1], v[2], v[3], p) == Sign::Positive;
        return conflict_infinite(t, p);
    }
    /// in0 = conflict(u0, p), in1 = conflict(u1, p), as 0 or 1 (u0 may equal u1: counted once).
    /// Two finite tetrahedra are tested by one paired filter (predicates::insphere_filter_pair,
    /// the same decisions as insphere's filter), the lanes it leaves undecided exactly.
    void conflict_pair(TetIdx u0, TetIdx u1, VertIdx p, unsigned& in0, unsigned& in1) {
        const VertIdx* v = &mesh.tv[4 * std::size_t{u0}];
        const VertIdx* w = &mesh.tv[4 * std::size_t{u1}];
        if (v[3] == kInfinite || w[3] == kInfinite) {
            in0 = conflict(u0, p) ? 1u : 0u;
            in1 = u1 == u0 ? in0 : conflict(u1, p) ? 1u : 0u;
            return;
        }
        counters.insphere_calls += u1 == u0 ? 1 : 2;
        const auto s = predicates::insphere_filter_pair(
            mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]),
            mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3]), mesh.point(p));
        for (std::size_t lane = 0; lane < (u1 == u0 ? 1u : 2u); ++lane) {
            EM_STAT(insphere, calls);
            if (s[lane]) EM_STAT(insphere, filter);
        }
        const Sign s0 = s[0] ? *s[0] : insphere_unfiltered(v[0], v[1], v[2], v[3], p);
        const Sign s1 = s[1]       ? *s[1]
                        : u1 == u0 ? s0
                                   : insphere_unfiltered(w[0], w[1], w[2], w[3], p);
        in0 = s0 == Sign::Positive ? 1u : 0u;
        in1 = s1 == Sign::Positive ? 1u : 0u;
    }
    /// insphere_sos by the caller's indices, for an exact tie.
    Sign insphere_tie(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p);
    /// The perturbed insphere where the filter gave no answer: the exact stages, then the tie.
    Sign insphere_unfiltered(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p);
    bool conflict_infinite(TetIdx t, VertIdx p);
};

/// Where a walk ended: a finite tetrahedron containing p (closed), with bit k of zero_faces set
/// when p lies on the plane of face k; or an infinite tetrahedron whose hull face sees p strictly
/// (zero_faces unused); or kNone when the walk was not allowed to go on (walk_3d).
struct Location3 {
    TetIdx tet = kNone;
    unsigned zero_faces = 0;
};

/// Remembering stochastic visibility walk [Devillers, Pion, Teillaud 2002] from the finite
/// tetrahedron `t` towards p, entering a neighbour only when may_enter(neighbour): otherwise
/// it stops, returning kNone, with `t` the last tetrahedron it stood in. On arrival `t` is the
/// tetrahedron returned. Orientations are counted in counters.orient_calls, steps in walk_steps.
template <class MayEnter>
Location3 walk_3d(const TetMesh3& mesh, TetIdx& t, VertIdx p, std::uint64_t& rng,
                  Delaunay3Counters& counters, MayEnter&& may_enter) {
    const VertIdx* const tv = mesh.tv.data();
    const FaceIdx* const adj = mesh.adj.data();
    const double* const q = mesh.point(p);
    // The face we came through has p strictly on this side: the walk does not test it again.
    FaceIdx entered = kNone;
    for (;;) {
        ++counters.walk_steps;
        const VertIdx* v = &tv[4 * std::size_t{t}];
        if (v[kInfiniteSlot] == kInfinite) return {t, 0};  // crossed a hull face that sees p
        // orient3d inline (the filter decides almost every call): the tetrahedron's corners
        // are looked up once for its faces.
        const double* corner[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                   mesh.point(v[3])};
        const std::uint32_t r = walk_random_offset(rng);
        unsigned zeros = 0;
        bool moved = false;
        for (std::uint32_t i = 0; i < 4; ++i) {
            const unsigned k = (r + i) & 3u;
            const FaceIdx f = 4 * t + k;
            if (f == entered) continue;
            ++counters.orient_calls;
            const unsigned* face = kFaceVertex[k];
            const Sign s =
                predicates::orient3d(corner[face[0]], corner[face[1]], corner[face[2]], q);
            if (s == Sign::Negative) {
                const TetIdx u = tet_of(adj[f]);
                if (!may_enter(u)) return {kNone, 0};
                entered = adj[f];
                t = u;
                moved = true;
                break;
            }
            if (s == Sign::Zero) zeros |= 1u << k;
        }
        if (!moved) return {t, zeros};
    }
}

/// The vertex p equals when a walk to p ended on three face planes of a finite tetrahedron
/// (their shared vertex), else kNone.
VertIdx duplicate_vertex(const TetMesh3& mesh, const Location3& where);

class Delaunay3Core {
  public:
    /// Validates the input, orders it (options.order) and copies it into mesh.xyz.
    Delaunay3Core(std::span<const double> xyz, const Delaunay3Options& options);
    /// Copies the validated input into mesh.xyz in `order` (mesh vertex -> caller's index),
    /// reserving room for `reserved_tets` tetrahedra.
    Delaunay3Core(std::span<const double> xyz, std::vector<VertIdx> order,
                  std::size_t reserved_tets);

    TetMesh3 mesh;
    std::vector<VertIdx> input_index;  ///< mesh vertex -> caller's index
    std::vector<VertIdx> merged_into;  ///< caller's index -> caller index of the kept copy
    Delaunay3Counters counters;

    /// Exact orientation of four finite mesh vertices.
    Sign orient(VertIdx a, VertIdx b, VertIdx c, VertIdx d);
    /// orient3d of finite tetrahedron t with its vertex at slot k replaced by p: positive when p
    /// lies on the same side of face k as that vertex.
    Sign orient_replacing(TetIdx t, unsigned k, VertIdx p);
    /// ConflictTest3::insphere with the core's counters.
    Sign insphere(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p) {
        return tests().insphere(a, b, c, d, p);
    }
    /// ConflictTest3::conflict with the core's counters.
    bool conflict(TetIdx t, VertIdx p) { return tests().conflict(t, p); }
    ConflictTest3 tests() { return {mesh, input_index.data(), counters}; }
    bool same_point(VertIdx a, VertIdx b) const;

    /// Builds the first tetrahedron and its four infinite neighbours from the first four
    /// non-coplanar points in insertion order. Returns false when all points are coplanar
    /// (then there is no tetrahedron). `skip` receives the four mesh vertices used.
    bool make_first_tet(std::vector<bool>& skip);

    using Location = Location3;
    /// Remembering stochastic visibility walk [Devillers, Pion, Teillaud 2002] from the last
    /// tetrahedron made. Sets last_tet.
    Location walk_to(VertIdx p);
    /// walk_to, recording a duplicate (and returning tet == kNone) when p equals a vertex.
    Location locate(VertIdx p);

    /// The splits and flips as stars of a point, with their region marks (flip_3d.hpp).
    TetStar3 star;

    /// The finite tetrahedra in the caller's numbering, with a copy of the caller's points
    /// `xyz`; consumes the mesh. The compaction runs in `chunks` slot ranges by `run`
    /// (compact_cells): the same result for any chunks.
    Delaunay3Result take_result(std::span<const double> xyz, std::size_t chunks = 1,
                                const ChunkRunner& run = {});
    /// The result for coplanar input (no tetrahedron): only duplicates are detected, by sorting.
    Delaunay3Result coplanar_result(std::span<const double> xyz);

    TetIdx last_tet = kNone;

  private:
    std::uint64_t rng_state_ = 0x9E3779B97F4A7C15ull;
};

/// The incremental construction both 3D algorithms share: the first tetrahedron, then every other
/// point in insertion order located and handed to `Inserter(core).insert(p, where)` (a duplicate
/// is merged instead). Fewer than four non-coplanar points: no tetrahedron, duplicates still
/// merged (coplanar_result).
template <class Inserter>
Delaunay3Result insert_incrementally(std::span<const double> xyz, const Delaunay3Options& options) {
    using Clock = std::chrono::steady_clock;
    Clock::time_point phase = Clock::now();
    Delaunay3Core core(xyz, options);
    core.counters.order_microseconds = microseconds_since(phase);
    std::vector<bool> skip;
    if (!core.make_first_tet(skip)) return core.coplanar_result(xyz);
    phase = Clock::now();
    Inserter inserter(core);
    ProgressCounter progress(options.progress, core.mesh.vertex_count(), "points inserted");
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const Delaunay3Core::Location where = core.locate(p);
        if (where.tet == kNone) continue;  // duplicate, merged
        inserter.insert(p, where);
        progress.tick();
    }
    core.counters.sequential_microseconds = microseconds_since(phase);
    phase = Clock::now();
    Delaunay3Result result = core.take_result(xyz);
    result.counters.result_microseconds = microseconds_since(phase);
    return result;
}

}  // namespace exactmesh::triangulation::detail
