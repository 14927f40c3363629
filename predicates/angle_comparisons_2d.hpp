// SPDX-License-Identifier: MIT
// Exact comparisons of triangle angles and of edge lengths, the decisions behind the angle and
// length criteria of edge_swap_2d and edge_cutting_2d. An angle is never computed: the corner
// angle at o of a counter-clockwise triangle (o, p, q) lies in (0, pi), where the cotangent
// dot(p-o, q-o) / cross(p-o, q-o) is strictly decreasing, so theta1 < theta2 exactly when
// dot1 * cross2 - dot2 * cross1 > 0 (cross > 0 by orientation): a degree-4 polynomial sign.
// The same stages decide the sign of a dot product (right-angle and diametral-circle tests).
// Stages as in predicates/: a floating-point filter with a forward error bound (constants in
// filter_constants.hpp, proven in proofs/gappa/compare_angles_filter.g, compare_lengths_filter.g,
// dot_sign_filter.g), then expansion arithmetic on exact differences [Shewchuk97 §2], then GMP
// (direction_dot_sign: a long double stage before GMP). Statistics: stats.hpp.
#pragma once

#include <optional>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// The corner of triangle (o, p, q) at o, the triangle given counter-clockwise: the angle
/// from ray o->p to ray o->q. Pointers to 2 doubles each (finite).
struct Corner {
    const double* o;
    const double* p;
    const double* q;
};

/// Sign of angle(a) - angle(b), exact.
/// @pre orient2d(a.o, a.p, a.q) > 0 and orient2d(b.o, b.p, b.q) > 0 (each triangle strictly
///      counter-clockwise), coordinates finite. With a degenerate corner the result is
///      meaningless but the call is still safe.
Sign compare_angles(const Corner& a, const Corner& b);

/// Sign of |p1 - q1|^2 - |p2 - q2|^2, exact (finite coordinates).
Sign compare_lengths(const double* p1, const double* q1, const double* p2, const double* q2);

/// Sign of the dot product (p - o) . (q - o), exact (finite coordinates): Positive when the
/// angle at o is acute, Zero when it is right (or o equals p or q), Negative when obtuse. So o
/// lies in the closed disk with diameter pq (Thales) exactly when the result is not Positive:
/// the encroachment test of Delaunay refinement [Ruppert95 §3].
Sign corner_dot_sign(const double* o, const double* p, const double* q);

/// Sign of the dot product (q - p) . (b - a), exact (finite coordinates): whether the step from
/// p to q moves along the direction a -> b (Positive), across it (Zero) or against it.
Sign direction_dot_sign(const double* p, const double* q, const double* a, const double* b);

/// The double filters of the four comparisons above (stage A): the sign when the filter
/// certifies it, std::nullopt otherwise (a difference outside the window 2^-200..2^200, or too
/// close a call). Constants in filter_constants.hpp, proofs in proofs/gappa/.
std::optional<Sign> compare_angles_filter(const Corner& a, const Corner& b);
std::optional<Sign> compare_lengths_filter(const double* p1, const double* q1, const double* p2,
                                           const double* q2);
std::optional<Sign> corner_dot_sign_filter(const double* o, const double* p, const double* q);
std::optional<Sign> direction_dot_sign_filter(const double* p, const double* q, const double* a,
                                              const double* b);

/// The largest corner of the strictly counter-clockwise triangle (a, b, c): the corner opposite
/// its longest side (law of sines), found with compare_lengths; ties go to the earliest of
/// the corners at a, b, c.
Corner largest_corner(const double* a, const double* b, const double* c);

/// The smallest corner (opposite the shortest side); ties go to the earliest of a, b, c.
Corner smallest_corner(const double* a, const double* b, const double* c);

}  // namespace exactmesh::predicates
