// SPDX-License-Identifier: MIT
// Exact decisions of 3D Delaunay refinement [Shewchuk98 "Tetrahedral mesh generation by
// Delaunay refinement" §3; Si15 §3]: a tetrahedron's radius-edge ratio against a bound, its
// volume against a bound, a point inside a triangle's equatorial sphere (subface encroachment),
// an angle below 60 degrees (the small-input-angle rule). Every test is a polynomial sign
// evaluated exactly in GMP integers on the coordinates scaled by one power of two (each finite
// double is an integer times 2^k for the smallest exponent k among them), so nothing overflows
// or underflows and the answer is the same for the input scaled by any power of two (while the
// bounds scale with it). Slow (tens of microseconds) and obviously correct, so each test first
// runs a relative double filter (*_filter, predicates/relative_filter.hpp): the polynomial on
// the differences scaled by a power of two with its permanent, the constant proven by Gappa
// (proofs/gappa/tet_quality_3d_*_filter.g); it abstains near ties, when a nonzero difference is
// below 2^-50 of the largest, and (radius-edge) for bounds outside [2^-64, 2^65).
#pragma once

#include <optional>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// Sign of R - bound * l_min for the tetrahedron a, b, c, d (3 doubles each, any orientation,
/// not flat), R its circumradius and l_min its shortest edge: Positive when the radius-edge
/// ratio exceeds `bound` (> 0, finite).
Sign compare_radius_edge_3d(const double* a, const double* b, const double* c, const double* d,
                            double bound);

/// Sign of |volume(a, b, c, d)| - max_volume (max_volume > 0, finite).
Sign compare_tet_volume_3d(const double* a, const double* b, const double* c, const double* d,
                           double max_volume);

/// Whether p lies inside the equatorial (diametral) sphere of triangle a, b, c, the smallest
/// sphere through a, b, c (its centre the triangle's circumcentre): Positive strictly inside,
/// Zero on it, Negative outside. @pre a, b, c not collinear. Four points with one coordinate
/// equal (a facet in a coordinate plane) are decided, after the filter, by the 2D incircle and
/// orient2d on the other two coordinates (exact expansions), not in GMP.
Sign in_equatorial_sphere_3d(const double* p, const double* a, const double* b, const double* c);

/// Sign of cos(angle p-apex-q) - 1/2: Positive when the angle at `apex` between p and q is
/// below 60 degrees. @pre p != apex, q != apex.
Sign compare_angle_60_3d(const double* apex, const double* p, const double* q);

/// Sign of |a - b| - |c - d|.
Sign compare_lengths_3d(const double* a, const double* b, const double* c, const double* d);

/// The filter stages of the five tests above: the exact answer when the double filter certifies
/// it, std::nullopt otherwise (the public functions then decide in GMP integers).
std::optional<Sign> compare_radius_edge_3d_filter(const double* a, const double* b, const double* c,
                                                  const double* d, double bound);
std::optional<Sign> compare_tet_volume_3d_filter(const double* a, const double* b, const double* c,
                                                 const double* d, double max_volume);
std::optional<Sign> in_equatorial_sphere_3d_filter(const double* p, const double* a,
                                                   const double* b, const double* c);
std::optional<Sign> compare_angle_60_3d_filter(const double* apex, const double* p,
                                               const double* q);
std::optional<Sign> compare_lengths_3d_filter(const double* a, const double* b, const double* c,
                                              const double* d);

}  // namespace exactmesh::predicates
