// SPDX-License-Identifier: MIT
// Cubic spline boundaries (issue 6, curved boundaries): an interpolating C2 cubic spline through
// control points, parameterized by chord length; closed splines are periodic (C2 at every
// control point, the first included), open ones natural (zero second derivative at both ends)
// [deBoor78 ch. IV; Farin02 §9.4]. A spline is a Curve2 (domain_boundary_2d.hpp), so
// discretize_curve places points on it spaced by the size function; boundary_loops_domain turns
// closed splines and polygons into a DomainPslg (sample_domains.hpp) with holes.
// Invariants: the spline passes exactly through each control point (the evaluation at a knot
// returns it bit for bit); consecutive control points are distinct.
// Cost: O(n) to build (a tridiagonal, or cyclic tridiagonal by Sherman-Morrison, solve per
// coordinate); an evaluation O(log n). boundary_loops_domain: the discretization, an exact
// crossing check of the loops' segments (a sweep in x, orient2d), a constrained Delaunay
// triangulation per hole loop to place its hole point. Predicates: orient2d.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/sizing/size_function.hpp"

namespace exactmesh::generators {

class CubicSpline2 {
  public:
    /// `xy`: 2·#P finite control points (at least 2 open, 3 closed); consecutive points (and,
    /// closed, the last and the first) distinct. A closed spline's last point equal to its first
    /// is dropped (the loop closes by itself).
    /// @throws InputError naming the offending point.
    CubicSpline2(std::vector<double> xy, bool closed);

    bool closed() const { return closed_; }
    std::size_t point_count() const { return xy_.size() / 2; }
    std::size_t segment_count() const { return knots_.size() - 1; }
    /// The parameter runs over [0, parameter_end()], the total chord length; knot(i) is the
    /// parameter of control point i (knot(segment_count()) = parameter_end(); closed: point 0).
    double parameter_end() const { return knots_.back(); }
    double knot(std::size_t i) const { return knots_[i]; }

    /// The curve at u, and its first and second derivatives with respect to u. u outside the
    /// range wraps round (closed) or is clamped to it (open).
    std::array<double, 2> point(double u) const { return at(u, 0); }
    std::array<double, 2> derivative(double u) const { return at(u, 1); }
    std::array<double, 2> second_derivative(double u) const { return at(u, 2); }
    /// The `order`-th derivative (0, 1, 2) on one segment at t in [0, 1] (u = knot(s) + t h_s):
    /// one-sided values at the knots.
    std::array<double, 2> on_segment(std::size_t segment, double t, int order) const;

    /// The spline as a Curve2 over [0, parameter_end()] (shares this spline's data).
    Curve2 curve() const;
    /// discretize_curve over the whole spline (at least min_pieces pieces); closed: the last
    /// point (the first again) left out.
    std::vector<std::array<double, 2>> discretize(const SizeFunction& size, int min_pieces) const;

  private:
    bool closed_ = false;
    std::vector<double> xy_;       // 2·#P
    std::vector<double> knots_;    // #segments + 1
    std::vector<double> moments_;  // 2·#P second derivatives (x, y) at the control points
    std::array<double, 2> at(double u, int order) const;
};

struct BoundaryLoop2 {
    std::vector<double> xy;  ///< 2·#P: spline control points or polygon vertices, in order
    bool spline = true;      ///< a closed cubic spline through them; false: the polygon
    bool hole = false;       ///< the loop bounds a hole (containing no other loop)
    /// Spline loops: the control points (0-based, increasing) where the loop has a corner (a
    /// sharp trailing edge): the loop is then an open natural spline from each corner to the
    /// next, round the loop. Empty: one periodic spline.
    std::vector<std::uint32_t> corners;
};

/// The PSLG of closed loops: each spline loop discretized by `size` (at least min_pieces pieces;
/// 0: two per control point, at least 8; with corners, per piece between corners, 0: two per
/// control point of the piece), each polygon side one segment; a hole point inside
/// each hole loop (the centroid of the largest triangle of the loop's constrained Delaunay
/// triangulation, checked inside by exact orient2d).
/// @throws InputError on a bad loop (as CubicSpline2; a polygon with fewer than 3 vertices,
///         repeated consecutive vertices), no loop, or loops whose segments cross or touch.
DomainPslg boundary_loops_domain(std::span<const BoundaryLoop2> loops, const SizeFunction& size,
                                 int min_pieces = 0);

}  // namespace exactmesh::generators
