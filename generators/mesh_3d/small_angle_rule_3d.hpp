// SPDX-License-Identifier: MIT
// The small-input-angle rule of 3D Delaunay refinement (Shewchuk's: a tetrahedron whose shortest
// edge joins two points on input segments that meet at less than 60 degrees is not split, since
// splitting it could make shorter edges without end). One class, so that refinement, the exact
// check of its result and sliver removal (which must not trade a spared tetrahedron for one
// refinement would split) see the same rule.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "triangulation/mesh/conforming_mesh_3d.hpp"

namespace exactmesh::generators {

/// The segments of a ConformingMesh3 seen from its vertices, and the rule on them. Keeps
/// references: `mesh` (its segments, input vertex count and vertex features, which may grow)
/// and `xyz` (the coordinates the rule measures: mesh.mesh.xyz, or a working copy) must outlive
/// it.
class SmallInputAngleRule3 {
  public:
    SmallInputAngleRule3(const triangulation::ConformingMesh3& mesh, const std::vector<double>& xyz);

    /// Whether u and w lie on two input segments that meet at an input vertex (neither u nor w)
    /// at less than 60 degrees (exact), one of them at least a Steiner point (an edge between
    /// two input vertices is the input's own, which refinement does not shorten).
    bool small_angle_pair(triangulation::VertIdx u, triangulation::VertIdx w) const;

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

    /// The input segments v lies on (an input vertex: those ending at it).
    std::vector<std::uint32_t> segments_of(triangulation::VertIdx v) const;
    const double* point(triangulation::VertIdx v) const {
        return xyz_.data() + 3 * std::size_t{v};
    }
};

}  // namespace exactmesh::generators
