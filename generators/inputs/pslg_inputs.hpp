// SPDX-License-Identifier: MIT
// Planar straight-line graphs for the constrained Delaunay tests, benchmarks and fuzz seeds:
// non-crossing segment chains among uniform points, a large star-shaped polygon with interior
// points, a square with polygonal holes, integer grid lines (collinear, overlapping, through
// vertices, cocircular everywhere), randomly crossing segments, near-collinear segments a few
// ulps apart, duplicated vertices, and tiny PSLGs numbered for systematic enumeration.
// Every generator is deterministic for its arguments; "non-crossing" is exact (see each entry).
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace exactmesh::generators {

enum class PslgDistribution {
    /// n uniform points in [0, 1)^2; chains (random walks of 1..64 steps) along unused edges of
    /// the exact Delaunay triangulation of the first min(n, segments + 3) points: the segments
    /// are edges of one triangulation, so no two cross (exactly).
    Chains,
    /// A star-shaped polygon of `segments` vertices (strictly increasing angles about (0.5, 0.5),
    /// checked with exact orient2d, so the polygon is simple), the other points inside its fan
    /// triangles. The polygon's vertices come first.
    Polygon,
    /// The unit square (boundary split into segments/8 pieces per side) with star-shaped holes,
    /// one per cell of a grid (12 vertices each, holes[] holds the cell centres), and uniform
    /// points, some inside holes.
    PolygonWithHoles,
    /// An integer grid of about n points (cocircular quadruples everywhere) with horizontal,
    /// vertical and diagonal segments over random spans: collinear overlaps, segments through
    /// grid vertices, crossings at lattice and half-lattice points.
    GridLines,
    /// n uniform points joined by `segments` random pairs: many crossings, all split.
    Crossing,
    /// Two chains of points along the line y = x, one moved 1..4 ulps below it, one 1..4 ulps
    /// above, consecutive points joined (up to `segments` per chain), plus three points off the
    /// line: segments a few ulps apart and vertices a few ulps off segments, yet (exactly) no
    /// crossing.
    NearCollinear,
    /// Chains, plus exact copies of about n/3 vertices appended (so about 4n/3 points), about
    /// half of the segment ends moved to a copy, and an eighth of the segments repeated
    /// reversed: the same geometry, still without crossings.
    Duplicates,
};

inline constexpr PslgDistribution kAllPslgDistributions[] = {
    PslgDistribution::Chains,    PslgDistribution::Polygon,  PslgDistribution::PolygonWithHoles,
    PslgDistribution::GridLines, PslgDistribution::Crossing, PslgDistribution::NearCollinear,
    PslgDistribution::Duplicates};

std::string_view pslg_distribution_name(PslgDistribution d);

struct PslgInput {
    std::vector<double> xy;               ///< 2·#V coordinates
    std::vector<std::uint32_t> segments;  ///< 2·#S vertex indices (0-based)
    std::vector<double> holes;            ///< 2·#H points inside holes (PolygonWithHoles only)
};

/// About n points and about `segments` segments of the distribution (exact counts where the
/// entry above says so; Chains may return fewer segments when the walks run out of edges).
PslgInput generate_pslg(PslgDistribution d, std::uint32_t n, std::uint32_t segments,
                        std::uint64_t seed);

/// Number of distinct tiny PSLGs with `vertices` (3..8) vertices: 2^(vertices·(vertices-1)/2).
std::uint64_t tiny_pslg_count(std::uint32_t vertices);

/// Tiny PSLG number `index` (taken modulo tiny_pslg_count): the first `vertices` of the points
/// (0,0) (2,0) (2,2) (0,2) (1,1) (1,0) (3,1) (0,1) (a cocircular square, its centre on both
/// diagonals, midpoints on its sides, one point outside), and segment k present when bit k of
/// index is set, pairs (i, j), i < j, numbered in lexicographic order.
PslgInput tiny_pslg(std::uint32_t vertices, std::uint64_t index);

}  // namespace exactmesh::generators
