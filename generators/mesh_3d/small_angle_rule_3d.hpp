// SPDX-License-Identifier: MIT
// The small-input-angle rule of 3D Delaunay refinement (Shewchuk's: a tetrahedron whose shortest
// edge joins two points on input segments that meet at less than 60 degrees is not split, since
// splitting it could make shorter edges without end). One class, so that refinement, the exact
// check of its result and sliver removal (which must not trade a spared tetrahedron for one
// refinement would split) see the same rule. Its 3D companion for facets (TetGen's sharp
// segments [Si15 §3.3]): two facets meeting at an input segment at a dihedral angle below 60
// degrees are "sharp"; encroachment between them splits nothing (each split on one would
// encroach the other, a cascade into the segment without end: issue 15), and a tetrahedron whose
// shortest edge joins points of two sharp facets is spared like the segment rule's. A segment
// that runs over a facet at less than 30 degrees from a common end makes the facet sharp with
// the segment's facets (the same cascade, into the vertex).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/mesh/conforming_mesh_3d.hpp"

namespace exactmesh::generators {

/// The pairs of facets of a ConformingMesh3 that meet at an input segment at a dihedral angle
/// below 60 degrees (the angle between the two half-planes bounded by the segment's line, each
/// holding its facet next to the segment; in [0, 180]), decided exactly (compare_dihedral
/// against a lattice tetrahedron whose angle is exactly 60 degrees, scale-free) on input
/// vertices only: the side of the segment a facet lies on is read from any subface at the
/// segment (a subface is not flat, so each gives the same side), the half-plane from an input
/// vertex of the facet on that side. So the mesh before refinement, after it and after
/// smoothing classify alike. Keeps no reference.
class SharpFacets3 {
  public:
    SharpFacets3() = default;
    /// From `mesh`'s subfaces, segments and vertex features; `xyz` holds its coordinates (the
    /// input vertices' are read).
    SharpFacets3(const triangulation::ConformingMesh3& mesh, const std::vector<double>& xyz);

    bool empty() const { return pairs_.empty(); }
    /// Whether facets f and g (f != g) meet at some segment at below 60 degrees.
    bool sharp(std::uint32_t f, std::uint32_t g) const;
    /// The facets v lies on (an input vertex: those it is a corner of; a segment point: the
    /// segment's; a facet point: its own; a volume point: none).
    std::span<const std::uint32_t> facets_of(const triangulation::ConformingMesh3& mesh,
                                             triangulation::VertIdx v) const;
    /// Whether v lies on a facet sharp with `facet` and not on `facet` itself: its encroachment
    /// of `facet`'s subfaces does not split them.
    bool shields_subface(const triangulation::ConformingMesh3& mesh, triangulation::VertIdx v,
                         std::uint32_t facet) const;
    /// Whether `facet` is one of two sharp facets at segment s: a point on it does not split s's
    /// subsegments by encroachment (TetGen's sharp segments).
    bool shields_segment(std::uint32_t s, std::uint32_t facet) const;
    /// Whether some facet of v lies on a sharp pair at segment s.
    bool shields_segment(const triangulation::ConformingMesh3& mesh, triangulation::VertIdx v,
                         std::uint32_t s) const;
    /// Whether u and w lie on two different facets that are sharp.
    bool sharp_pair(const triangulation::ConformingMesh3& mesh, triangulation::VertIdx u,
                    triangulation::VertIdx w) const;

    /// The angle below which a segment and a facet meeting at one of its ends (the segment
    /// running over the facet's sector there, not on the facet) count as sharp.
    static constexpr double kSegmentFacetDegrees = 30;

  private:
    /// Segments that run over a facet at a small angle from a common vertex (the segment not on
    /// the facet; kSegmentFacetDegrees, in doubles on scaled differences: a choice of what to
    /// split, like SmallInputAngleRule3::narrow_angle_pair): each split of the facet's subfaces
    /// by the segment's points, and of the segment by the facet's, would encroach the other
    /// again, down to the vertex (random star-shaped PLCs put a third of their points within
    /// 1e-9 of such vertices, some an ulp apart). The facet and each facet of the segment
    /// become a sharp pair, and the facet is sharp at the segment.
    void add_segments_near_facets(const triangulation::ConformingMesh3& mesh,
                                  const std::vector<double>& xyz);
    std::vector<std::vector<std::uint32_t>> segment_facets_;  ///< per segment: facets at it
    std::vector<std::vector<std::uint32_t>> input_facets_;    ///< per input vertex
    std::vector<std::vector<std::uint32_t>> sharp_at_;        ///< per segment: facets sharp there
    std::vector<std::uint64_t> pairs_;                        ///< sorted (f << 32 | g), f < g
};

/// The segments of a ConformingMesh3 seen from its vertices, and the rule on them. Keeps
/// references: `mesh` (its segments, input vertex count and vertex features, which may grow)
/// and `xyz` (the coordinates the rule measures: mesh.mesh.xyz, or a working copy) must outlive
/// it.
class SmallInputAngleRule3 {
  public:
    /// The sharp facets are classified from `mesh`'s subfaces.
    SmallInputAngleRule3(const triangulation::ConformingMesh3& mesh,
                         const std::vector<double>& xyz);
    /// With the sharp facets classified already (refinement, whose working mesh keeps its
    /// subfaces elsewhere).
    SmallInputAngleRule3(const triangulation::ConformingMesh3& mesh, const std::vector<double>& xyz,
                         SharpFacets3 sharp);

    /// Whether u and w lie on two input segments that meet at an input vertex (neither u nor w)
    /// at less than 60 degrees (exact), or on two sharp facets (SharpFacets3), one of them at
    /// least a Steiner point (an edge between two input vertices is the input's own, which
    /// refinement does not shorten).
    bool small_angle_pair(triangulation::VertIdx u, triangulation::VertIdx w) const;

    /// Whether u and w lie on two input segments that meet at an input vertex (neither u nor w)
    /// at less than 30 degrees, one of them at least a Steiner point: a point on one does not
    /// split the other's subsegments by encroachment (each split would encroach the first
    /// again, down to the apex: a needle's two long edges 5e-10 radians apart ran 10^6
    /// subsegment splits into the Steiner budget). A choice of what to split, not a validity
    /// decision (refinement spares the tetrahedra between such segments by small_angle_pair):
    /// the angle is taken in doubles on the input vertices' differences scaled by a power of
    /// two (the same at 2^+-600), so an angle within rounding of 30 degrees may go either way.
    /// Below 30, not 60: the split diagonals of a rotated box's facets meet its edges at 45
    /// degrees, where shell splitting ends by itself and the splits keep the corners' tetrahedra
    /// well shaped.
    bool narrow_angle_pair(triangulation::VertIdx u, triangulation::VertIdx w) const;

    /// Whether the tetrahedron with corners `corners` is spared: one of its shortest edges
    /// (exact length comparisons) joins a small_angle_pair.
    bool spares(const std::array<triangulation::VertIdx, 4>& corners) const;

    /// spares(corners) with the edge lengths measured at `at` (the corners' coordinates, one of
    /// them possibly a trial position of a Steiner point that smoothing may move; the segments'
    /// input vertices are the mesh's own).
    bool spares(const std::array<triangulation::VertIdx, 4>& corners,
                const std::array<const double*, 4>& at) const;

  private:
    const triangulation::ConformingMesh3& mesh_;
    const std::vector<double>& xyz_;
    std::vector<std::vector<std::uint32_t>> at_input_;  ///< segments ending at each input vertex
    SharpFacets3 sharp_;

    /// Whether u and w lie on two input segments meeting at an input vertex (neither u nor w)
    /// whose angle there `below(apex, far1, far2)` accepts.
    template <class AngleTest>
    bool meet_at_apex(triangulation::VertIdx u, triangulation::VertIdx w, AngleTest&& below) const;
    /// The input segments v lies on (an input vertex: those ending at it).
    std::span<const std::uint32_t> segments_of(triangulation::VertIdx v) const;
    const double* point(triangulation::VertIdx v) const { return xyz_.data() + 3 * std::size_t{v}; }
};

}  // namespace exactmesh::generators
