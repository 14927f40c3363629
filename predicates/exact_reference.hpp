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
/// det of the rows [x y q(p) 1] for a, b, c, d, q(p) = p^T M p with m = {M11, M12, M22}; equals
/// in_ellipse (in_ellipse.hpp).
Sign in_ellipse(const double* a, const double* b, const double* c, const double* d,
                const double* m);
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

/// in_ellipse with lifted coordinates perturbed by index, as incircle_sos (the lift q(p)).
/// @pre integer coordinates with |x| <= 2^20, integer metric entries with |m| <= 2^20, and
/// distinct indices.
Sign in_ellipse_sos(const double* a, const double* b, const double* c, const double* d,
                    const double* m, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                    std::uint32_t id);

/// insphere with lifted coordinates perturbed by index, as incircle_sos (5x5, eps = 2^-200).
/// @pre integer coordinates with |x| <= 2^20 and distinct indices.
Sign insphere_sos(const double* a, const double* b, const double* c, const double* d,
                  const double* e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie);

/// References for the comparisons of angle_comparisons_2d/3d, within_rounding_of_segment and
/// triangle_area, in rationals from the raw coordinates, written without the predicates' forms.

/// Sign of angle(o1; p1, q1) - angle(o2; p2, q2), the corners of counter-clockwise triangles,
/// from the cotangents dot / cross as rationals. @pre both crosses positive
/// (std::invalid_argument otherwise).
Sign compare_angles(const double* o1, const double* p1, const double* q1, const double* o2,
                    const double* p2, const double* q2);
/// Sign of |p1 - q1|^2 - |p2 - q2|^2.
Sign compare_lengths(const double* p1, const double* q1, const double* p2, const double* q2);
/// Sign of (q - p) . (b - a).
Sign dot_sign(const double* p, const double* q, const double* a, const double* b);
/// Whether the closed square of half-width 2^-40 max(|w_x|, |w_y|) (at least 2^-1074) around w
/// meets the closed segment [s0, s1]: the segment clipped to the square by its parameter range
/// (Liang-Barsky) is not empty.
bool within_rounding_of_segment(const double* w, const double* s0, const double* s1);
/// Sign of the dihedral angle of tetrahedron a (4 points of 3 doubles) at edge (a[i], a[j])
/// minus that of b at (b[k], b[l]), from the cosines n1 . n2 / (|n1| |n2|) compared by sign and
/// by their squares as rationals. @pre both tetrahedra non-degenerate.
Sign compare_dihedral(const double* const* a, unsigned i, unsigned j, const double* const* b,
                      unsigned k, unsigned l);
/// Sign of q(a) - q(b) for the volume-edge quality q = 12 sqrt(3) V6 / L^(3/2) of positively
/// oriented tetrahedra: compares V6^2 / L^3 as rationals (V6 > 0).
Sign compare_volume_edge(const double* const* a, const double* const* b);
/// Sign of det [a - c; b - c] / 2 - area.
Sign triangle_area_sign(const double* a, const double* b, const double* c, double area);

}  // namespace exactmesh::predicates::reference
