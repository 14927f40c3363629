// SPDX-License-Identifier: MIT
// The two-term (double-double) stage of incircle and insphere (predicates/two_term.hpp) against
// exact rationals: each operation keeps the invariant (E, H, L) of proofs/invariants/filters.md,
// "Two-term stage", and the whole stage-B evaluations stay within the derived 52 u^2 P and
// 142 u^2 P, on random differences of mixed magnitudes and on cancelling ones.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>

#include "predicates/two_term.hpp"

namespace pr = exactmesh::predicates;
using pr::detail::TwoTerm;

namespace {

constexpr double kU = 0x1p-53;

double scale() {
    const char* text = std::getenv("EXACTMESH_TEST_SCALE");
    const double s = text != nullptr ? std::atof(text) : 1.0;
    return s > 0.0 ? s : 1.0;
}

int cases(int n) {
    const int scaled = static_cast<int>(n * scale());
    return scaled > 100 ? scaled : 100;
}

class Doubles {
  public:
    explicit Doubles(std::uint64_t seed) : engine_(seed) {}
    /// A double with all 53 significand bits random, exponent in [-spread, spread], random sign.
    double next(int spread) {
        const std::uint64_t mantissa = (engine_() >> 11) | (std::uint64_t{1} << 52);
        const int exponent =
            spread == 0
                ? 0
                : static_cast<int>(engine_() % (2u * static_cast<unsigned>(spread) + 1u)) - spread;
        const double x = std::ldexp(static_cast<double>(mantissa), exponent - 52);
        return (engine_() & 1u) != 0u ? -x : x;
    }

  private:
    std::mt19937_64 engine_;
};

mpq_class q(double x) {
    return mpq_class(x);
}
mpq_class value(const TwoTerm& t) {
    return q(t.hi) + q(t.lo);
}
mpq_class magnitude(const mpq_class& x) {
    return abs(x);
}

/// Over points of `dims` exact coordinates from x: the minor x_p y_r - x_r y_p of points p and
/// r, the sum of its products' magnitudes (the P of its error bound), and |point p|^2.
mpq_class minor_xy(const mpq_class* x, int dims, int p, int r) {
    return x[dims * p] * x[dims * r + 1] - x[dims * r] * x[dims * p + 1];
}
mpq_class minor_xy_bound(const mpq_class* x, int dims, int p, int r) {
    return magnitude(x[dims * p] * x[dims * r + 1]) + magnitude(x[dims * r] * x[dims * p + 1]);
}
mpq_class squared_norm(const mpq_class* x, int dims, int p) {
    mpq_class sum = 0;
    for (int k = 0; k < dims; ++k) sum += x[dims * p + k] * x[dims * p + k];
    return sum;
}

/// Checks |hi + lo - x| <= e u^2 p, |hi| <= h p, |lo| <= l u p (with a 2^-40 relative margin for
/// the (1 + u)^k factors the lemmas round into their constants).
void expect_invariant(const TwoTerm& t, const mpq_class& x, const mpq_class& p, double e, double h,
                      double l) {
    const double margin = 1.0 + 0x1p-40;
    const mpq_class u(kU);
    EXPECT_LE(magnitude(value(t) - x), mpq_class(e * margin) * u * u * p);
    EXPECT_LE(magnitude(q(t.hi)), mpq_class(h * margin) * p);
    EXPECT_LE(magnitude(q(t.lo)), mpq_class(l * margin) * u * p);
}

}  // namespace

TEST(Predicates_TwoTerm, LemmaBoundsHoldOnRandomAndCancellingInputs) {
    Doubles rng(11);
    for (int n = 0; n < cases(20000); ++n) {
        const int spread = n % 3 == 0 ? 0 : (n % 3 == 1 ? 4 : 30);
        double a = rng.next(spread), b = rng.next(spread), c = rng.next(spread),
               d = rng.next(spread), z = rng.next(spread);
        if (n % 2 == 1) c = a * b / d;  // a b - c d cancels
        const mpq_class ab = q(a) * q(b), cd = q(c) * q(d);
        // Lemma A.
        const TwoTerm minor = pr::detail::two_term_diff_of_products(a, b, c, d);
        const mpq_class minor_p = magnitude(ab) + magnitude(cd);
        expect_invariant(minor, ab - cd, minor_p, 3, 1, 2);
        expect_invariant(pr::detail::two_term_sum_of_squares(a, b), q(a) * q(a) + q(b) * q(b),
                         q(a) * q(a) + q(b) * q(b), 3, 1, 2);
        // Lemma A'.
        const mpq_class lift3 = q(a) * q(a) + q(b) * q(b) + q(c) * q(c);
        const TwoTerm lift = pr::detail::two_term_sum_of_squares(a, b, c);
        expect_invariant(lift, lift3, lift3, 7, 1, 3);
        // Lemma B on a Lemma A value: (3 + 1 + 2 * 2, 1, 1 + 2).
        expect_invariant(pr::detail::two_term_scale(minor, z), q(z) * (ab - cd),
                         magnitude(q(z)) * minor_p, 8, 1, 3);
        // Lemma C on Lemma A' times Lemma A: 7 + 3 + 3 * (2 + 3) + 1 + 6 = 32, H 1, L 1 + 5.
        expect_invariant(pr::detail::two_term_product(lift, minor), lift3 * (ab - cd),
                         lift3 * minor_p, 32, 1, 6);
    }
}

TEST(Predicates_TwoTerm, StageBErrorIsBelowTheDerivedBound) {
    Doubles rng(12);
    const mpq_class u(kU);
    for (int n = 0; n < cases(20000); ++n) {
        const int spread = n % 3 == 0 ? 0 : (n % 3 == 1 ? 3 : 20);
        double v[12];
        for (double& x : v) x = rng.next(spread);
        if (n % 2 == 1) {
            // Nearly dependent rows: large cancellation in minors and in the determinant.
            for (int k = 0; k < 2; ++k) v[4 + k] = v[k] + v[2 + k];
        }
        {
            mpq_class x[6];
            for (int k = 0; k < 6; ++k) x[k] = v[k];
            auto minor = [&](int p, int r) { return minor_xy(x, 2, p, r); };
            auto minor_p = [&](int p, int r) { return minor_xy_bound(x, 2, p, r); };
            auto lift = [&](int p) { return squared_norm(x, 2, p); };
            const mpq_class det =
                lift(0) * minor(1, 2) + lift(1) * minor(2, 0) + lift(2) * minor(0, 1);
            const mpq_class p =
                lift(0) * minor_p(1, 2) + lift(1) * minor_p(2, 0) + lift(2) * minor_p(0, 1);
            const TwoTerm t = pr::detail::incircle_stage_b(v);
            EXPECT_LE(magnitude(value(t) - det), mpq_class(52) * u * u * p)
                << "incircle case " << n;
        }
        if (n % 2 == 1) {
            for (int k = 0; k < 3; ++k) v[9 + k] = v[k] + v[3 + k] - v[6 + k];
        }
        {
            mpq_class x[12];
            for (int k = 0; k < 12; ++k) x[k] = v[k];
            auto m2 = [&](int p, int r) { return minor_xy(x, 3, p, r); };
            auto p2 = [&](int p, int r) { return minor_xy_bound(x, 3, p, r); };
            auto m3 = [&](int p, int r, int s) -> mpq_class {
                return x[3 * p + 2] * m2(r, s) - x[3 * r + 2] * m2(p, s) + x[3 * s + 2] * m2(p, r);
            };
            auto p3 = [&](int p, int r, int s) -> mpq_class {
                return magnitude(x[3 * p + 2]) * p2(r, s) + magnitude(x[3 * r + 2]) * p2(p, s) +
                       magnitude(x[3 * s + 2]) * p2(p, r);
            };
            auto lift = [&](int p) { return squared_norm(x, 3, p); };
            const mpq_class det = (lift(3) * m3(0, 1, 2) - lift(2) * m3(0, 1, 3)) +
                                  (lift(1) * m3(0, 2, 3) - lift(0) * m3(1, 2, 3));
            const mpq_class p = lift(3) * p3(0, 1, 2) + lift(2) * p3(0, 1, 3) +
                                lift(1) * p3(0, 2, 3) + lift(0) * p3(1, 2, 3);
            const TwoTerm t = pr::detail::insphere_stage_b(v);
            EXPECT_LE(magnitude(value(t) - det), mpq_class(142) * u * u * p)
                << "insphere case " << n;
        }
    }
}
