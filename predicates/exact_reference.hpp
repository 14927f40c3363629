// SPDX-License-Identifier: MIT
// Ground truth for the tests: orient2d, orient3d, incircle, insphere and their symbolic
// perturbations, evaluated in GMP rationals straight from the raw-coordinate determinants
// [Shewchuk97 §4; EdelsbrunnerMücke90]. Slow and obviously correct; shares no code with the
// filtered and adaptive predicates.
#pragma once

#include <gmpxx.h>

#include <cstdint>
#include <vector>

#include "predicates/sign.hpp"

namespace exactmesh::predicates::reference {

/// Sign of an exact rational.
Sign sign_of(const mpq_class& x);

/// The exact value of a finite double; throws GeometryError on NaN or infinity.
mpq_class exact(double x);

/// Sign of the determinant of an n x n matrix, by Gaussian elimination in exact rationals.
/// @param matrix n*n entries, row-major; taken by value because elimination overwrites it.
Sign determinant_sign(std::vector<mpq_class> matrix, int n);

/// det [[ax ay 1], [bx by 1], [cx cy 1]]; equals Shewchuk's orient2d.
/// Every predicate here throws GeometryError on NaN or infinite coordinates.
Sign orient2d(const double* a, const double* b, const double* c);
/// det of the rows [x y z 1] for a, b, c, d; equals Shewchuk's orient3d.
Sign orient3d(const double* a, const double* b, const double* c, const double* d);
/// det of the rows [x y x^2+y^2 1] for a, b, c, d; equals Shewchuk's incircle.
Sign incircle(const double* a, const double* b, const double* c, const double* d);
/// det of the rows [x y z x^2+y^2+z^2 1] for a..e; equals Shewchuk's insphere.
Sign insphere(const double* a, const double* b, const double* c, const double* d, const double* e);

/// Shewchuk's difference forms (det [p-d], det [p-d, |p-d|^2], ...) as explicit cofactor
/// expansions, in GMP integers after scaling every coordinate by the same power of two (exact,
/// and sign-preserving since the forms are homogeneous). A second, independent evaluation with the
/// same signs as the raw forms above (the tests check it), several times faster, so that the
/// million-case random tests can afford it.
Sign orient2d_differences(const double* a, const double* b, const double* c);
Sign orient3d_differences(const double* a, const double* b, const double* c, const double* d);
Sign incircle_differences(const double* a, const double* b, const double* c, const double* d);
Sign insphere_differences(const double* a, const double* b, const double* c, const double* d,
                          const double* e);

/// orient2d of the points perturbed by index, from first principles: with rank r = 0 for the
/// largest index, x_p += eps^(2^(2r+1)) and y_p += eps^(2^(2r)); the determinant is expanded
/// exactly as a polynomial in eps and the sign is that of its lowest-order nonzero coefficient.
/// Any finite doubles; throws std::invalid_argument when two indices are equal.
Sign orient2d_sos(const double* a, const double* b, const double* c, std::uint32_t ia,
                  std::uint32_t ib, std::uint32_t ic);

/// incircle with lifted coordinates perturbed by index: w_p += eps^(r+1), r = 0 for the largest
/// index, evaluated as the raw 4x4 determinant with the explicit rational eps = 2^-200.
/// @pre integer coordinates with |x| <= 2^20 (enough for that eps; std::invalid_argument
/// otherwise) and distinct indices.
Sign incircle_sos(const double* a, const double* b, const double* c, const double* d,
                  std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id);

/// insphere with lifted coordinates perturbed by index, as incircle_sos (5x5, eps = 2^-200).
/// @pre integer coordinates with |x| <= 2^20 and distinct indices.
Sign insphere_sos(const double* a, const double* b, const double* c, const double* d,
                  const double* e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie);

}  // namespace exactmesh::predicates::reference
