// SPDX-License-Identifier: MIT
// Correctly rounded constructions: circumcenters (2D, 3D) and segment intersections, each
// coordinate the double nearest (ties to even) to the exact rational value on the input doubles.
// Reference: expansion arithmetic [Shewchuk97 §2]; test-and-fall-back correct rounding [Ziv91:
// Ziv, "Fast evaluation of elementary mathematical functions with correctly rounded last bit",
// ACM TOMS 17(3), 1991]; exact rounding with IEEE subnormals emulated by mpfr_subnormalize.
// Invariant: a returned coordinate is the correctly rounded one, never a nearby double: the fast
// path returns a candidate only after comparing the exact value with both of its midpoints.
// Cost (callgrind, per call): fast path ~11k instructions in 2D (~7k when the differences are
// exact), ~50k in 3D (~22k); the exact path ~48k (2D) and ~190k (3D). Segments as 2D.
//
// Paths, per call (all coordinates of one point take the same path):
//  - Stage 0 (2D circumcenters whose differences to c are exact doubles; 3D circumcenters
//    whatever their differences, kept as exact double-doubles when they round): double-double
//    arithmetic with a proven error bound (constructions.cpp), accepted when the exact value
//    cannot lie beyond a midpoint of the candidate: ~20x cheaper than the fast path below,
//    which decides whatever it leaves. In 2D it runs before the input checks (its certificate
//    implies finite, non-collinear points) and takes its exact products by FMA where the CPU
//    has it (runtime dispatch; Dekker's elsewhere, the same bits): ~560 instructions a call
//    with FMA, ~1,010 without.
//  - Fast path, when detail::expansion_safe(degree, inputs) holds: |coordinates| <= 2^331 (2D,
//    degree 3) or 2^248 (3D, degree 4) and no product of `degree` factors underflows. Each
//    coordinate is num / den with num, den determinants in the raw doubles (degree 3 over 2 in
//    2D, 4 over 3 in 3D), or in the differences p - p0 when all of those are exact doubles
//    (Sterbenz: nearby points), which is shorter. num and den are evaluated exactly as
//    expansions; q0 = fl(approx(num) / approx(den)); one exact residual num - q0 den refines it
//    to q (a double-double estimate, so q is nearly always already the answer). q is certified
//    by the exact signs of num - m den at its two midpoints m (half an ulp below and above, with
//    each side's own ulp at binade boundaries); an exact tie returns the even neighbour; if the
//    test says the value lies beyond a midpoint, that neighbour is tried once. Measured: 100% of
//    uniform random inputs certify (tests: FastPathCertifiesNearlyAllRandomInputs).
//  - Exact path (GMP mpq, rounded once by MPFR at 53 bits in binary64's exponent range,
//    subnormals included): inputs outside the expansion-safe range (e.g. 1e200 or 1e-200
//    coordinates, subnormals), a result outside it (beyond 2^331 / 2^248, or below 2^-500, whose
//    half-ulps would underflow), or a value within ~2^-100 (relative) of a midpoint that neither
//    q nor its neighbour certifies. Exact zero is returned as +0 on both paths.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace exactmesh::predicates {

/// 2D circumcenter of the triangle a, b, c (any orientation), correctly rounded per coordinate.
/// @param a, b, c: 2 doubles each (x, y).
/// @return the circumcenter (x, y); exact zero is returned as +0.
/// @throws GeometryError when a coordinate is NaN or infinite, when a, b, c are collinear
///         (exact orient2d; includes coincident points), or when a coordinate of the result
///         rounds beyond the double range (|x| >= DBL_MAX + ulp(DBL_MAX) / 2).
std::array<double, 2> circumcenter(const double* a, const double* b, const double* c);

/// 3D circumcenter of the tetrahedron a, b, c, d (any orientation), correctly rounded.
/// @param a, b, c, d: 3 doubles each (x, y, z).
/// @throws GeometryError on non-finite input, coplanar points (exact orient3d) or overflow.
std::array<double, 3> circumcenter(const double* a, const double* b, const double* c,
                                   const double* d);

/// 3D circumcenter of the triangle a, b, c (the centre of its circumcircle, in its plane),
/// correctly rounded per coordinate: c + ((|u|^2 v - |v|^2 u) x (u x v)) / (2 |u x v|^2) with
/// u = a - c, v = b - c, evaluated exactly in GMP rationals and rounded once by MPFR; a triangle
/// in a coordinate plane (its three points share a coordinate) goes to the 2D circumcenter of
/// the other two coordinates (the same exact point, with its fast paths: 3D refinement splits
/// subfaces of boxes by the thousand).
/// @throws GeometryError on non-finite input, collinear points (exact: u x v = 0) or overflow.
std::array<double, 3> triangle_circumcenter_3d(const double* a, const double* b, const double* c);

/// The point of the plane through p, q, r equidistant from a, b and c: the circumcentre of the
/// triangle a, b, c moved onto that plane, correctly rounded per coordinate (the exact solution
/// of 2 x . (a - c) = |a|^2 - |c|^2, 2 x . (b - c) = |b|^2 - |c|^2, n . x = n . p with
/// n = (q - p) x (r - p), in GMP rationals, rounded once by MPFR). When a, b, c lie on the plane
/// it is their circumcentre, the same point triangle_circumcenter_3d rounds. For a subface whose
/// corners were rounded off its facet's plane (p, q, r: input vertices of the facet): its split
/// point on the facet, from the corners and the facet's own vertices, rounded once. Always the
/// exact path (about 200k instructions): 3D refinement needs it for a few subfaces per mesh.
/// @throws GeometryError on non-finite input, p, q, r collinear, or when the system is
///         singular (the triangle's projection onto the plane is flat), or on overflow.
std::array<double, 3> triangle_circumcenter_on_plane_3d(const double* a, const double* b,
                                                        const double* c, const double* p,
                                                        const double* q, const double* r);

/// The point p + t (q - p) of the segment from p to q (3 doubles each) at parameter t,
/// correctly rounded per coordinate (exact rational value, rounded once by MPFR): a split point
/// on an input segment computed from the segment's original ends. Scaling p and q by 2^k scales
/// the result by 2^k exactly (while nothing is subnormal).
/// @throws GeometryError on non-finite input.
std::array<double, 3> point_on_segment_3d(const double* p, const double* q, double t);

/// The point where the segments [a, b] and [c, d] meet, correctly rounded per coordinate.
/// Accepted: the segments have exactly one common point and are not collinear, i.e. a proper
/// crossing, or one or two endpoints lying on the other segment (T-junctions, shared endpoints);
/// the point returned is the intersection of the lines ab and cd (an endpoint, exactly, when
/// the segments touch there).
/// @param a, b, c, d: 2 doubles each.
/// @throws GeometryError when a coordinate is non-finite, when a segment has zero length, when
///         the lines are parallel (including collinear segments, even overlapping or sharing
///         only an endpoint) or when the segments do not intersect.
std::array<double, 2> segment_intersection(const double* a, const double* b, const double* c,
                                           const double* d);

/// (a + b) / 2 rounded once: the exact halves summed (one rounding), or, where a half would be
/// subnormal (and so inexact), the sum (exact there, far from overflow) halved (one rounding).
/// The split-point coordinate of the constrained triangulation's and the quadtree's pieces.
inline double rounded_midpoint(double a, double b) noexcept {
    const bool tiny = std::fabs(a) < 0x1p-1000 || std::fabs(b) < 0x1p-1000;
    return tiny ? (a + b) * 0.5 : a * 0.5 + b * 0.5;
}

/// The point of the line through s0 and s1 whose coordinate `axis` (0: x, 1: y) is `value`,
/// that coordinate kept and the other correctly rounded (exact rational arithmetic, one
/// rounding): within half an ulp of the exact point of the line, whatever the span of
/// magnitudes (s0 near 1e300 and s1 subnormal included), where a parameter s0 + tau (s1 - s0)
/// in doubles could not resolve it. Always the exact path: meant for the rare split points that
/// the cheap midpoint of rounded piece ends cannot give (cdt_conforming_2d.cpp).
/// @throws GeometryError when an input is non-finite, when s0[axis] == s1[axis] or when the
///         other coordinate overflows.
std::array<double, 2> point_on_line_at(const double* s0, const double* s1, int axis, double value);

/// The same constructions, always through the exact path (GMP + MPFR); same errors.
/// For tests and for measuring the fast path; results are identical by construction.
std::array<double, 2> circumcenter_exact(const double* a, const double* b, const double* c);
std::array<double, 3> circumcenter_exact(const double* a, const double* b, const double* c,
                                         const double* d);
std::array<double, 2> segment_intersection_exact(const double* a, const double* b, const double* c,
                                                 const double* d);

namespace detail {
/// circumcenter (2D) with the double-double stage's exact products by Dekker's algorithm even
/// where the CPU has FMA (circumcenter takes one fused multiply-add per product there, chosen
/// at run time): the same bits, for the tests that compare the two.
std::array<double, 2> circumcenter_without_fma(const double* a, const double* b, const double* c);
/// Whether circumcenter (2D) takes FMA products on this CPU.
bool circumcenter_uses_fma() noexcept;
}  // namespace detail

/// Per-thread counts of which path the constructions took. Always compiled in: one increment
/// is negligible beside the expansion arithmetic, and the tests check the documented claim
/// that the fast path handles nearly all inputs in every build.
/// Every call that returns counts once: calls == fast + exact_range + exact_uncertified.
struct ConstructionStats {
    std::uint64_t calls = 0;
    std::uint64_t fast = 0;  ///< every coordinate certified on the fast path
    std::uint64_t double_double =
        0;  ///< of those, by the double-double stage (2D and 3D, exact differences)
    std::uint64_t neighbour_steps = 0;    ///< coordinates certified at q's neighbour, not q
    std::uint64_t exact_range = 0;        ///< inputs or result outside the expansion-safe range
    std::uint64_t exact_uncertified = 0;  ///< in range, but neither q nor its neighbour certified
};

/// This thread's counters (the *_exact functions do not count).
ConstructionStats& construction_stats() noexcept;
void reset_construction_stats() noexcept;

}  // namespace exactmesh::predicates
