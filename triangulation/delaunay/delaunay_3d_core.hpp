// SPDX-License-Identifier: MIT
// Shared machinery of the 3D Delaunay constructions (internal to triangulation/): the points in
// insertion order, the exact conflict test with the infinite vertex, the remembering visibility
// walk, the first tetrahedron, the star of a point over a region (flip_3d's TetStar3: the
// retetrahedralization Green-Sibson's splits and flips are made of; Bowyer-Watson stars its
// cavities with its own, specialised copy), and the conversion to the caller's numbering.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "predicates/insphere.hpp"
#include "predicates/sign.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

class Delaunay3Core {
  public:
    /// Validates the input, orders it (options.order) and copies it into mesh.xyz.
    Delaunay3Core(std::span<const double> xyz, const Delaunay3Options& options);

    TetMesh3 mesh;
    std::vector<VertIdx> input_index;  ///< mesh vertex -> caller's index
    std::vector<VertIdx> merged_into;  ///< caller's index -> caller index of the kept copy
    Delaunay3Counters counters;

    /// Exact orientation of four finite mesh vertices.
    Sign orient(VertIdx a, VertIdx b, VertIdx c, VertIdx d);
    /// orient3d of finite tetrahedron t with its vertex at slot k replaced by p: positive when p
    /// lies on the same side of face k as that vertex.
    Sign orient_replacing(TetIdx t, unsigned k, VertIdx p);
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
    bool same_point(VertIdx a, VertIdx b) const;

    /// Builds the first tetrahedron and its four infinite neighbours from the first four
    /// non-coplanar points in insertion order. Returns false when all points are coplanar
    /// (then there is no tetrahedron). `skip` receives the four mesh vertices used.
    bool make_first_tet(std::vector<bool>& skip);

    /// Where a walk ended: a finite tetrahedron containing p (closed), with bit k of zero_faces
    /// set when p lies on the plane of face k; or an infinite tetrahedron whose hull face sees p
    /// strictly (zero_faces unused).
    struct Location {
        TetIdx tet = kNone;
        unsigned zero_faces = 0;
    };
    /// Remembering stochastic visibility walk [Devillers, Pion, Teillaud 2002] from the last
    /// tetrahedron made. Sets last_tet.
    Location walk_to(VertIdx p);
    /// walk_to, recording a duplicate (and returning tet == kNone) when p equals a vertex.
    Location locate(VertIdx p);

    /// The splits and flips as stars of a point, with their region marks (flip_3d.hpp).
    TetStar3 star;

    /// The finite tetrahedra in the caller's numbering, with a copy of the caller's points
    /// `xyz`; consumes the mesh.
    Delaunay3Result take_result(std::span<const double> xyz);
    /// The result for coplanar input (no tetrahedron): only duplicates are detected, by sorting.
    Delaunay3Result coplanar_result(std::span<const double> xyz);

    TetIdx last_tet = kNone;

  private:
    /// insphere_sos by the caller's indices, for an exact tie.
    Sign insphere_tie(VertIdx a, VertIdx b, VertIdx c, VertIdx d, VertIdx p);
    bool conflict_infinite(TetIdx t, VertIdx p);

    std::uint64_t rng_state_ = 0x9E3779B97F4A7C15ull;
    std::uint32_t random_offset();
};

/// The incremental construction both 3D algorithms share: the first tetrahedron, then every other
/// point in insertion order located and handed to `Inserter(core).insert(p, where)` (a duplicate
/// is merged instead). Fewer than four non-coplanar points: no tetrahedron, duplicates still
/// merged (coplanar_result).
template <class Inserter>
Delaunay3Result insert_incrementally(std::span<const double> xyz, const Delaunay3Options& options) {
    Delaunay3Core core(xyz, options);
    std::vector<bool> skip;
    if (!core.make_first_tet(skip)) return core.coplanar_result(xyz);
    Inserter inserter(core);
    ProgressCounter progress(options.progress, core.mesh.vertex_count(), "points inserted");
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const Delaunay3Core::Location where = core.locate(p);
        if (where.tet == kNone) continue;  // duplicate, merged
        inserter.insert(p, where);
        progress.tick();
    }
    return core.take_result(xyz);
}

}  // namespace exactmesh::triangulation::detail
