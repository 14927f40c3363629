// SPDX-License-Identifier: MIT
// triangle_area_sign(a, b, c, area): the exact sign of signed_area(a, b, c) - area, where
// signed_area = orient2d's determinant / 2 (positive for a counter-clockwise triangle): the
// "area exceeds a bound" test of Delaunay refinement's regional area constraints (Triangle's
// -a). Stage A: the determinant of the differences, each scaled exactly by one power of two to
// a largest magnitude in [1, 2), against 2 area scaled by the square of that power (so nothing
// overflows or underflows at coordinates 2^+-600 and the decision is the same at every scale),
// with a forward error bound; stage B: GMP integers (gmp_fallback.hpp) for any finite input.
#pragma once

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// Sign of (orient2d determinant of a, b, c) / 2 - area, exactly, for finite coordinates and a
/// finite area. Positive: the triangle (counter-clockwise) has an area larger than `area`.
/// @throws GeometryError on a NaN or infinite coordinate or area.
Sign triangle_area_sign(const double* a, const double* b, const double* c, double area);

}  // namespace exactmesh::predicates
