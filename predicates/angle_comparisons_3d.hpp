// SPDX-License-Identifier: MIT
// Exact comparisons of tetrahedron dihedral angles and of the volume-edge quality, the
// decisions behind the quality criteria of edge_face_swap_3d. Nothing is compared after
// rounding: the dihedral angle at edge (pi, pj) of a tetrahedron with other vertices pk, pl is
// the angle between n1 = e x u and n2 = e x w (e = pj - pi, u = pk - pi, w = pl - pi), whose
// cosine d / sqrt(N) (d = n1 . n2, N = |n1|^2 |n2|^2) is strictly decreasing on (0, pi); so
// theta1 < theta2 exactly when d1 / sqrt(N1) > d2 / sqrt(N2), decided from the signs of d1, d2
// and of d1^2 N2 - d2^2 N1 (degree 16 in coordinate differences). The volume-edge quality
// q = 12 sqrt(3) D / L^(3/2) (D = 6 x volume, L = sum of the squared edge lengths; 1 for the
// regular tetrahedron, 0 when flat) compares by the sign of D1^2 L2^3 - D2^2 L1^3 (degree 12).
// Stages: long double evaluation with a running forward error bound (angle_comparisons_3d.cpp;
// proofs/gappa/angle_comparisons_3d_filter.g), then GMP. Statistics: stats.hpp.
#pragma once

#include <array>
#include <optional>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// Four corner pointers (3 doubles each, finite) of a tetrahedron, positively oriented.
using TetCorners = std::array<const double*, 4>;

/// The dihedral angle of tetrahedron `p` at its edge (p[i], p[j]), i != j.
struct Dihedral {
    TetCorners p;
    unsigned i, j;
};

/// Sign of angle(a) - angle(b), exact. @pre both tetrahedra non-degenerate.
Sign compare_dihedral(const Dihedral& a, const Dihedral& b);

/// The smallest (largest) of the six dihedral angles of `p`; ties go to the first edge in the
/// order (0,1), (0,2), (0,3), (1,2), (1,3), (2,3).
Dihedral smallest_dihedral(const TetCorners& p);
Dihedral largest_dihedral(const TetCorners& p);

/// Whether compare_dihedral(angle, bound) == wanted for all six dihedral angles of `p` (every
/// angle above `bound`: Positive; below: Negative), exactly; stops at the first that is not.
bool every_dihedral_compares(const TetCorners& p, const Dihedral& bound, Sign wanted);

/// Sign of q(a) - q(b) for the volume-edge quality, exact. @pre both positively oriented.
Sign compare_volume_edge(const TetCorners& a, const TetCorners& b);

/// The long double filters of the two comparisons (stage A): the sign when certified,
/// std::nullopt otherwise (a difference outside 2^-500..2^500, a long double narrower than
/// x86-64's, or too close a call).
std::optional<Sign> compare_dihedral_filter(const Dihedral& a, const Dihedral& b);
std::optional<Sign> compare_volume_edge_filter(const TetCorners& a, const TetCorners& b);

/// The dihedral angle in radians, rounded (reports and statistics, never decisions):
/// atan2(|e| |det(e, u, w)|, n1 . n2) in long double.
long double dihedral_radians(const Dihedral& a);

/// Whether the dihedral angle is below the acute angle T with cos^2 T = `cos_squared`, rounded
/// (a selection, never a decision): n1 . n2 > 0 and (n1 . n2)^2 > cos^2 T |n1|^2 |n2|^2 in
/// long double, where no product over- or underflows for double corners, so the answer is the
/// same for the corners scaled by any power of two. The same angles as dihedral_radians(a) < T
/// but for the roundings near T, at a tenth of its cost (no atan2).
bool dihedral_below_rounded(const Dihedral& a, long double cos_squared);

/// Whether any of the six dihedral angles of the tetrahedron is below the acute angle T with
/// cos^2 T = `cos_squared`, rounded (a selection, never a decision): from the four face normals
/// at once (cos of the angle at edge ij = -n_k . n_l / (|n_k| |n_l|), k and l the other two
/// corners) in doubles on the corner differences scaled by a power of two, the same answer for
/// the corners scaled by 2^k while the largest difference stays in [2^-1000, 2^1000]; outside
/// that, or where a scaled difference or normal comes near the double range's bottom,
/// dihedral_below_rounded per edge (the two may differ within rounding of T). A sixth of the
/// work of six dihedral_below_rounded calls.
bool any_dihedral_below_rounded(const TetCorners& p, long double cos_squared);

/// The dihedral angle of `p` whose rounded cosine (from the face normals as in
/// any_dihedral_below_rounded) is the largest: a selection, never a decision. It is the
/// smallest angle or one within rounding of it, and always an angle of `p`: a caller that needs
/// some angle at least as large as the smallest may use it, and one that needs the smallest
/// itself compares exactly (smallest_dihedral). Edge (0, 1) where the normals are not usable
/// (differences beyond [2^-1000, 2^1000], near-degenerate faces). With `cosine`: the rounded
/// cosine found (-2 for edge (0, 1) then), to pick among several tetrahedra.
Dihedral smallest_dihedral_rounded(const TetCorners& p, double* cosine = nullptr);

/// q = 12 sqrt(3) D / L^(3/2) in long double (1 for the regular tetrahedron), rounded.
long double volume_edge_quality(const TetCorners& p);

}  // namespace exactmesh::predicates
