// SPDX-License-Identifier: MIT
// The within-rounding rule of constrained segments (see within_rounding_of_segment.hpp).
// Half-width t = 2^-40 max(|w_x|, |w_y|) (at least the smallest subnormal): t is a double, part of
// the rule's definition, so every test below is on exact quantities. The box meets the closed
// segment iff it overlaps the segment's bounding box in x and in y and the segment's line passes
// within the box's support in the normal direction n = (dy, -dx): |(w - s0) x d| <= t_x |dy| +
// t_y |dx| (separating axes of a box and a segment). Long double (64-bit significand, exponents
// to 2^16383) represents every difference and product of two doubles' differences without
// overflow or underflow; with at most 5 roundings of 2^-64 per monomial in each tested value
// and in its margin, a margin of within_rounding_filter_eps times the sum of the magnitudes
// decides (proofs/gappa/within_rounding_filter.g), else GMP integers on one power-of-two scale. On
// a platform whose long double is narrower, GMP decides every call.
#include "predicates/within_rounding_of_segment.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/scaled_integers.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {

constexpr bool kWideLongDouble = std::numeric_limits<long double>::digits >= 64 &&
                                 std::numeric_limits<long double>::max_exponent >= 16384;

/// The half-width of the square around w.
double half_width(const double* w) {
    const double m = std::max(std::fabs(w[0]), std::fabs(w[1]));
    return std::max(std::ldexp(m, -40), std::numeric_limits<double>::denorm_min());
}

}  // namespace

bool within_rounding_of_segment_exact(const double* w, const double* s0, const double* s1) {
    // Every test is homogeneous (degree 1 for the overlaps, 2 for the slab), so the inputs and
    // t may all be scaled by one power of two: as integers (scaled_integers), with no gcd after
    // each operation, unlike rationals (mpq, the previous stage: 84 s of one fuzz input under
    // ASan was spent there).
    const double t = half_width(w);
    const std::array<mpz_class, 7> v =
        detail::scaled_integers<7>({w[0], w[1], s0[0], s0[1], s1[0], s1[1], t});
    const mpz_class& et = v[6];
    for (int k = 0; k < 2; ++k) {
        const mpz_class& wk = v[static_cast<std::size_t>(k)];
        const mpz_class& ak = v[2 + static_cast<std::size_t>(k)];
        const mpz_class& bk = v[4 + static_cast<std::size_t>(k)];
        const mpz_class& lo = ak < bk ? ak : bk;
        const mpz_class& hi = ak < bk ? bk : ak;
        if (wk - et > hi || wk + et < lo) return false;
    }
    const mpz_class ex = v[4] - v[2], ey = v[5] - v[3];
    const mpz_class c = (v[0] - v[2]) * ey - (v[1] - v[3]) * ex;
    const mpz_class support = et * (abs(ey) + abs(ex));
    return abs(c) <= support;
}

std::optional<bool> within_rounding_of_segment_filter(const double* w, const double* s0,
                                                      const double* s1) {
    if constexpr (!kWideLongDouble) return std::nullopt;
    using LD = long double;
    const double t = half_width(w);
    bool certain = true;
    for (int k = 0; k < 2; ++k) {
        // Overlap in coordinate k: w_k - t <= max_k and w_k + t >= min_k.
        const LD lo = std::min(s0[k], s1[k]), hi = std::max(s0[k], s1[k]);
        const LD below = static_cast<LD>(w[k]) - t - hi, above = lo - (static_cast<LD>(w[k]) + t);
        const LD scale = std::fabs(static_cast<LD>(w[k])) + t + std::fabs(lo) + std::fabs(hi);
        const LD margin = within_rounding_filter_eps * scale;
        if (below > margin || above > margin) return false;
        if (!(below < -margin && above < -margin)) certain = false;
    }
    const LD dx = static_cast<LD>(s1[0]) - s0[0], dy = static_cast<LD>(s1[1]) - s0[1];
    const LD ux = static_cast<LD>(w[0]) - s0[0], uy = static_cast<LD>(w[1]) - s0[1];
    const LD cross = std::fabs(ux * dy - uy * dx);
    const LD support = t * std::fabs(dy) + t * std::fabs(dx);
    const LD margin =
        within_rounding_filter_eps * (std::fabs(ux * dy) + std::fabs(uy * dx) + support);
    if (cross - support > margin) return false;
    if (certain && cross - support < -margin) return true;
    return std::nullopt;
}

bool within_rounding_of_segment_3d(const double* w, const double* s0, const double* s1) {
    for (int drop = 0; drop < 3; ++drop) {
        const int i = (drop + 1) % 3, j = (drop + 2) % 3;  // triangulation's facet projection
        const double pw[2] = {w[i], w[j]}, p0[2] = {s0[i], s0[j]}, p1[2] = {s1[i], s1[j]};
        if (p0[0] == p1[0] && p0[1] == p1[1]) continue;
        if (!within_rounding_of_segment(pw, p0, p1)) return false;
    }
    return true;
}

bool within_rounding_of_segment(const double* w, const double* s0, const double* s1) {
    EM_STAT(within_rounding_of_segment, calls);
    if (const auto r = within_rounding_of_segment_filter(w, s0, s1)) {
        EM_STAT(within_rounding_of_segment, filter);
        return *r;
    }
    EM_STAT(within_rounding_of_segment, gmp);
    return within_rounding_of_segment_exact(w, s0, s1);
}

}  // namespace exactmesh::predicates
