// SPDX-License-Identifier: MIT
// Stage D of the predicates: exact signs in GMP integers for inputs outside the range where
// expansion arithmetic is exact (huge, tiny or subnormal coordinates). Finite inputs only.
#pragma once

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

Sign orient2d_gmp(const double* a, const double* b, const double* c);
Sign orient3d_gmp(const double* a, const double* b, const double* c, const double* d);
Sign incircle_gmp(const double* a, const double* b, const double* c, const double* d);
/// in_ellipse.hpp's determinant, m = {M11, M12, M22}.
Sign in_ellipse_gmp(const double* a, const double* b, const double* c, const double* d,
                    const double* m);
Sign insphere_gmp(const double* a, const double* b, const double* c, const double* d,
                  const double* e);
/// Sign of orient2d's determinant of a, b, c minus 2 area (triangle_area.hpp's stage B).
Sign triangle_area_gmp(const double* a, const double* b, const double* c, double area);

}  // namespace exactmesh::predicates
