// SPDX-License-Identifier: MIT
// The state every 2D adaptation method works on (issue 13): a constrained triangulation of the
// domain (the current mesh), its boundary and segment pieces, each with the piece of the
// original curve it approximates (so that new boundary points go on the curve, not on the
// polyline), the hole points that rebuild its domain, and the field at its vertices.
// Invariants kept by every method: the mesh is a valid triangulation of the domain whose
// constrained edges are exactly `pieces`; vertices [0, fixed_vertices) are the domain's input
// vertices, never moved or removed, in their input numbering; a curved piece (a, b) has
// curve(ua) == a and curve(ub) == b bit for bit when both ends were placed on the curve by
// adaptation (the input's own points and the generator's chord points keep the parameter of
// their position along the chord, see make_adaptive_mesh_2d).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "generators/boundary/sample_domains.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// A constrained edge (a, b) and the piece of curve it approximates (curve == kStraightSide:
/// a straight piece; then ua, ub are unused).
struct CurvedPiece2 {
    triangulation::VertIdx a = 0, b = 0;
    std::uint32_t curve = kStraightSide;
    double ua = 0, ub = 0;
};

struct AdaptiveMesh2 {
    triangulation::Triangulation2 mesh;
    std::uint32_t fixed_vertices = 0;
    std::vector<CurvedPiece2> pieces;
    std::vector<double> holes;   ///< 2·#H points inside holes
    std::vector<Curve2> curves;  ///< the domain's curves (DomainPslg::curves)
    std::vector<double> values;  ///< the field at each vertex (#V), or empty
    /// Curve points placed by adaptation (#V flags): checked to lie on their curve.
    std::vector<std::uint8_t> on_curve;
};

/// The adaptive state of a generator's mesh of a domain: `segment_curves` (#S of the domain's
/// PSLG, or empty: every side straight) gives each piece its curve; a piece's end that is
/// not an end of its input segment (a generator's point on the chord) takes the parameter of its
/// position along the chord, by the chord's longer axis.
AdaptiveMesh2 make_adaptive_mesh_2d(triangulation::Cdt2Result mesh,
                                    std::span<const double> segment_xy,
                                    std::span<const triangulation::VertIdx> segments,
                                    std::span<const double> holes, std::vector<Curve2> curves,
                                    std::span<const SegmentCurve> segment_curves);

/// The exact checks after every cycle: the triangulation valid (counter-clockwise by exact
/// orient2d, neighbours mutual), its constrained edges exactly the pieces, every piece an edge,
/// constrained Delaunay when `delaunay` (not after a movement, which keeps the connectivity),
/// the fixed vertices at their input position, every vertex flagged on_curve equal to its
/// curve at the piece parameters recorded for it. Returns the first problem, or "".
std::string check_adaptive_mesh_2d(const AdaptiveMesh2& state, std::span<const double> fixed_xy,
                                   bool delaunay = true);

}  // namespace exactmesh::generators
