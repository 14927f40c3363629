// SPDX-License-Identifier: MIT
// Narrow wedges of a PSLG: two segments from one end vertex less than a degree apart. Conforming
// to both needs pieces as short as the wedge is wide all along it wherever the two are split at
// different places (ends at different distances, midpoints): about (1 / angle) ln(length /
// shortest piece) points. A fan of segments 1e-4 radians apart ran 2D Delaunay refinement past
// 10^6 points and the quadtree past 1.6 10^7 leaves; 1e-9 would need 10^10. Delaunay refinement
// lets a vertex on one not encroach the other's pieces and leaves the skinny triangles spanning
// the wedge; the quadtree does not split a leaf to separate them (the band's CDT keeps both).
// Above a degree a wedge costs a few hundred points and is resolved as before.
// The angles are doubles on differences scaled by a power of two (a classification, as the 60
// degree small-angle rule is: the same pairs for the input scaled by 2^k).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

inline constexpr double kNarrowWedgeRadians = 3.14159265358979323846 / 180;

/// The pairs of segments (indices into `ends`, a segment's two vertex numbers, kNone for none)
/// that share an end vertex and leave it less than kNarrowWedgeRadians apart: keys
/// a << 32 | b with a < b, sorted. `xy` holds the vertices' coordinates.
std::vector<std::uint64_t> narrow_wedges_2d(
    std::span<const double> xy, std::span<const std::array<triangulation::VertIdx, 2>> ends);

/// Whether segments a and b make one of `pairs` (narrow_wedges_2d).
bool narrow_wedge_pair(const std::vector<std::uint64_t>& pairs, std::uint32_t a, std::uint32_t b);

}  // namespace exactmesh::generators
