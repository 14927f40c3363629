// SPDX-License-Identifier: MIT
// Quality statistics of a tetrahedralization: dihedral angles (all six of every tetrahedron,
// long double, atan2 form: accurate near 0 and 180 degrees), their histogram, the extremes,
// the volume-edge quality q = 6 sqrt(2) V / l_rms^3 (1 for the regular tetrahedron, 0 when
// flat), the radius-edge ratio, and slivers. A sliver is a tetrahedron whose four vertices are
// nearly coplanar although no edge is short: its smallest dihedral angle is below
// `sliver_max_dihedral_degrees` (default 5) while its radius-edge ratio (circumradius over
// shortest edge) is at most `sliver_max_radius_edge` (default 2, the bound Delaunay refinement
// achieves [Shewchuk98, "Tetrahedral mesh generation by Delaunay refinement"]): small angles
// with a bounded ratio are exactly the slivers that refinement cannot remove [Cheng et al.,
// "Sliver exudation", J. ACM 47(5), 2000]. Needles and caps (a large ratio) are not slivers.
// The radius-edge ratios have a histogram too (bins of `radius_edge_bin_width` up to
// `radius_edge_histogram_max`, one open bin above). Every measure is computed on the corners
// scaled by a power of two to a largest coordinate in [1, 2), the ratio on edge vectors rescaled
// the same way: no square overflows or underflows, and the mesh scaled by 2^k (k in -600..600)
// gives the same bits.
// Statistics only: no decision anywhere depends on these rounded numbers.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

struct QualityOptions {
    double histogram_bin_degrees = 10.0;  ///< dihedral histogram bin width, divides 180
    double sliver_max_dihedral_degrees = 5.0;
    double sliver_max_radius_edge = 2.0;
    /// radius-edge histogram bin width; it divides radius_edge_histogram_max
    double radius_edge_bin_width = 0.2;
    /// the last bin is [radius_edge_histogram_max, infinity) (flat tetrahedra included)
    double radius_edge_histogram_max = 4.0;
    /// counted in QualityStats3::over_radius_edge_bound (2: Delaunay refinement's default)
    double radius_edge_bound = 2.0;
};

struct QualityStats3 {
    std::uint64_t tets = 0;
    double min_dihedral_degrees = 0;
    double max_dihedral_degrees = 0;
    /// Counts of the 6 #T dihedral angles per bin [k w, (k+1) w), the last bin closed at 180.
    std::vector<std::uint64_t> dihedral_histogram;
    double histogram_bin_degrees = 10.0;
    double min_volume_edge = 0;  ///< smallest q over the tetrahedra
    double mean_volume_edge = 0;
    double max_radius_edge = 0;  ///< largest circumradius / shortest edge
    /// Counts of the #T radius-edge ratios per bin [k w, (k+1) w) for k < max / w, then one bin
    /// [max, infinity) (w = radius_edge_bin_width, max = radius_edge_histogram_max).
    std::vector<std::uint64_t> radius_edge_histogram;
    double radius_edge_bin_width = 0.2;
    double radius_edge_histogram_max = 4.0;
    std::uint64_t over_radius_edge_bound = 0;  ///< ratio > QualityOptions::radius_edge_bound
    std::uint64_t slivers = 0;
};

/// @throws InputError when the dihedral bin width is not positive or does not divide 180 into at
///         most 18000 bins, or the radius-edge bin width does not divide a positive
///         radius_edge_histogram_max into at most 18000 bins.
QualityStats3 quality_stats_3d(const Tetrahedralization3& mesh, const QualityOptions& options = {});

}  // namespace exactmesh::triangulation
