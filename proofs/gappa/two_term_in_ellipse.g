# proofs/gappa/two_term_in_ellipse.g: Gappa proof of the error bound of in_ellipse's two-term stage
# (predicates/two_term.hpp, in_ellipse_two_term; used by predicates/in_ellipse.cpp) and of the
# constant in_ellipse_errbound_two_term of predicates/adaptive_bounds.hpp.
#
# The stage evaluates Det = det [p - d, q(p - d)], q(v) = m11 vx^2 + m12x2 vx vy + m22 vy^2
# (m12x2 = 2 m12, exact), on the EXACT differences, each given as the pair (hi, lo) of two_diff
# (hi + lo = p - d), and the metric's doubles, in double-double: every intermediate is a pair
# (hi, lo). Proves, lemma by lemma, the invariant (E, H, L) of every operation as the code does
# it: a pair approximating X, whose permanent is P, has |hi + lo - X| <= E u^2 P, |hi| <= H P,
# |lo| <= L u P (u = 2^-53). The chain ends with |hi + lo - Det| <= 138.3125 u^2 P, P the
# permanent of Det in the exact differences, and the last goal checks that
# beta = K u^2 P~ (P~ the permanent as the code computes it from the rounded differences hi:
# 4 factors hi / (p - d) and 9 roundings per monomial) is at least 2 (1 + u) times that error for
# the header's K.
#
# Model (proofs/invariants/filters.md, "Two-term stage" and "Two-term stage of in_ellipse"):
# inside the expansion-safe range every rounding is fl(z) = z (1 + d), |d| <= u (exact below
# 2^-1022, no overflow). An error-free transformation is exact: two_product(a, b) =
# (ab (1 + k), -ab k), two_sum(a, b) = ((a + b)(1 + g), -(a + b) g); each rounded addition or
# product of the tails carries its own factor (1 + f). An input pair is two_diff's: (X (1 + g),
# -X g), so |hi| <= (1 + u) |X|, |lo| <= u |X|, hi + lo = X. Roundings are free variables
# (independent: this covers any sharing). By hand (filters.md): with the roundings fixed, every
# operation is linear in its inputs (bilinear for the product, and linear in the metric entry
# that scales), so each lemma may be checked per input with its permanent normalised to 1, and
# the lemmas compose by taking each lemma's proven (E, H, L) as the next one's hypotheses
# (written out below with the same numbers). The hints below state the exact error of each
# operation without the cancelling leading terms.
#
# Placeholder, filled in from predicates/adaptive_bounds.hpp by proofs/check_two_term_constants.cmake
# (CTest test proofs.two_term_in_ellipse):
#     @K@          in_ellipse_errbound_two_term / u^2
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# Lemma C on two input pairs (two_term_product): the monomials vx vx, vx vy, vy vy of a lift and
# the products of a 2x2 minor; P_Y = P_Z = 1 (normalised |X|).
hi0 = hY0 * hZ0 * (1 + k1_0);  e0 = -(hY0 * hZ0) * k1_0;
r1_0 = hY0 * lZ0 * (1 + f1_0);
r2_0 = lY0 * hZ0 * (1 + f2_0);
r3_0 = (r1_0 + r2_0) * (1 + f3_0);
lo0 = (e0 + r3_0) * (1 + f4_0);
err0 = hi0 + lo0 - XY0 * XZ0;
# proven: E = 8.0009765625, H = 1.0009765625, L = 3.0009765625

# Lemma B: two_term_scale(monomial, metric entry), Y = Lemma C above; z = 1 (linear in z), P_Y = 1.
hi1 = hY1 * (1 + k1_1);  e1 = -hY1 * k1_1;
r1 = lY1 * (1 + f1_1);
lo1 = (e1 + r1) * (1 + f2_1);
err1 = hi1 + lo1 - XY1;
# proven: E = 15.0048828125, H = 1.001953125, L = 4.0029296875

# Lemma D, n = 3: the lift q(v), the sum of the three scaled monomials (Lemma B); one instance per
# position.
s2 = (hI2 + 0) * (1 + g1_2);  e1_2 = -(hI2 + 0) * g1_2;
hi2 = (s2 + 0) * (1 + g2_2);  e2_2 = -(s2 + 0) * g2_2;
a2 = (lI2 + 0) * (1 + f1_2);
b2 = (a2 + 0) * (1 + f2_2);
c2 = (e1_2 + e2_2) * (1 + f3_2);
lo2 = (b2 + c2) * (1 + f4_2);
err2 = hi2 + lo2 - XI2;
s3 = (0 + hI3) * (1 + g1_3);  e1_3 = -(0 + hI3) * g1_3;
hi3 = (s3 + 0) * (1 + g2_3);  e2_3 = -(s3 + 0) * g2_3;
a3 = (0 + lI3) * (1 + f1_3);
b3 = (a3 + 0) * (1 + f2_3);
c3 = (e1_3 + e2_3) * (1 + f3_3);
lo3 = (b3 + c3) * (1 + f4_3);
err3 = hi3 + lo3 - XI3;
s4 = (0 + 0) * (1 + g1_4);  e1_4 = -(0 + 0) * g1_4;
hi4 = (s4 + hI4) * (1 + g2_4);  e2_4 = -(s4 + hI4) * g2_4;
a4 = (0 + 0) * (1 + f1_4);
b4 = (a4 + lI4) * (1 + f2_4);
c4 = (e1_4 + e2_4) * (1 + f3_4);
lo4 = (b4 + c4) * (1 + f4_4);
err4 = hi4 + lo4 - XI4;
# proven: E = 31.0234375, H = 1.0029296875, L = 6.0078125

# Lemma D, n = 2: a 2x2 minor, the sum of two products (Lemma C; a negated pair is exact); one
# instance per position.
hi5 = (hI5 + 0) * (1 + g1_5);  e5 = -(hI5 + 0) * g1_5;
a5 = (lI5 + 0) * (1 + f1_5);
lo5 = (a5 + e5) * (1 + f2_5);
err5 = hi5 + lo5 - XI5;
hi6 = (0 + hI6) * (1 + g1_6);  e6 = -(0 + hI6) * g1_6;
a6 = (0 + lI6) * (1 + f1_6);
lo6 = (a6 + e6) * (1 + f2_6);
err6 = hi6 + lo6 - XI6;
# proven: E = 15.0048828125, H = 1.001953125, L = 4.0029296875

# Lemma C: two_term_product(lift, minor), Y = a lift (Lemma D, n = 3), Z = a minor (Lemma D,
# n = 2), P_Y = P_Z = 1, |X_Z| <= P_Z.
hi7 = hY7 * hZ7 * (1 + k1_7);  e7 = -(hY7 * hZ7) * k1_7;
r1_7 = hY7 * lZ7 * (1 + f1_7);
r2_7 = lY7 * hZ7 * (1 + f2_7);
r3_7 = (r1_7 + r2_7) * (1 + f3_7);
lo7 = (e7 + r3_7) * (1 + f4_7);
err7 = hi7 + lo7 - XY7 * XZ7;
# proven: E = 101.19921875, H = 1.00390625, L = 11.03125

# Lemma D, n = 3: the determinant, the sum of the three lift-times-minor pairs (Lemma C); one
# instance per position.
s8 = (hI8 + 0) * (1 + g1_8);  e1_8 = -(hI8 + 0) * g1_8;
hi8 = (s8 + 0) * (1 + g2_8);  e2_8 = -(s8 + 0) * g2_8;
a8 = (lI8 + 0) * (1 + f1_8);
b8 = (a8 + 0) * (1 + f2_8);
c8 = (e1_8 + e2_8) * (1 + f3_8);
lo8 = (b8 + c8) * (1 + f4_8);
err8 = hi8 + lo8 - XI8;
s9 = (0 + hI9) * (1 + g1_9);  e1_9 = -(0 + hI9) * g1_9;
hi9 = (s9 + 0) * (1 + g2_9);  e2_9 = -(s9 + 0) * g2_9;
a9 = (0 + lI9) * (1 + f1_9);
b9 = (a9 + 0) * (1 + f2_9);
c9 = (e1_9 + e2_9) * (1 + f3_9);
lo9 = (b9 + c9) * (1 + f4_9);
err9 = hi9 + lo9 - XI9;
s10 = (0 + 0) * (1 + g1_10);  e1_10 = -(0 + 0) * g1_10;
hi10 = (s10 + hI10) * (1 + g2_10);  e2_10 = -(s10 + hI10) * g2_10;
a10 = (0 + 0) * (1 + f1_10);
b10 = (a10 + lI10) * (1 + f2_10);
c10 = (e1_10 + e2_10) * (1 + f3_10);
lo10 = (b10 + c10) * (1 + f4_10);
err10 = hi10 + lo10 - XI10;
# proven: E = 138.3125, H = 1.0048828125, L = 13.046875

# Certification: per monomial M of the permanent P (in the exact differences), the computed
# permanent P~ carries the four factors |hi| / |X| = 1 + dg of its differences and 9 rounding
# factors (a lift monomial: product, product, two sums; a minor monomial: product, sum; their
# product; two sums); beta = K u^2 P~ (exact: K u^2 is a power of two, and the code falls
# through unless beta is normal) must be at least 2 (1 + u) times the two-term error E u^2 |M|.
ptilde = (1 + dg1) * (1 + dg2) * (1 + dg3) * (1 + dg4) * (1 + pe1) * (1 + pe2) * (1 + pe3) *
         (1 + pe4) * (1 + pe5) * (1 + pe6) * (1 + pe7) * (1 + pe8) * (1 + pe9);

{ |k1_0| <= 1b-53 /\ |f1_0| <= 1b-53 /\ |f2_0| <= 1b-53 /\ |f3_0| <= 1b-53 /\ |f4_0| <= 1b-53 /\
  |hY0| <= 9007199254740993b-53 /\ |lY0| <= 1b-53 /\ |hY0 + lY0 - XY0| <= 0 /\
  |hZ0| <= 9007199254740993b-53 /\ |lZ0| <= 1b-53 /\ |hZ0 + lZ0 - XZ0| <= 0 /\ |XZ0| <= 1 /\
  |k1_1| <= 1b-53 /\ |f1_1| <= 1b-53 /\ |f2_1| <= 1b-53 /\
  |hY1| <= 0x1.0040000000000p+0 /\ |lY1| <= 0x1.8020000000000p-52 /\ |hY1 + lY1 - XY1| <= 0x1.0008000000000p-103 /\
  |g1_2| <= 1b-53 /\ |g2_2| <= 1b-53 /\ |f1_2| <= 1b-53 /\ |f2_2| <= 1b-53 /\ |f3_2| <= 1b-53 /\ |f4_2| <= 1b-53 /\
  |hI2| <= 0x1.0080000000000p+0 /\ |lI2| <= 0x1.0030000000000p-51 /\ |hI2 + lI2 - XI2| <= 0x1.e028000000000p-103 /\
  |g1_3| <= 1b-53 /\ |g2_3| <= 1b-53 /\ |f1_3| <= 1b-53 /\ |f2_3| <= 1b-53 /\ |f3_3| <= 1b-53 /\ |f4_3| <= 1b-53 /\
  |hI3| <= 0x1.0080000000000p+0 /\ |lI3| <= 0x1.0030000000000p-51 /\ |hI3 + lI3 - XI3| <= 0x1.e028000000000p-103 /\
  |g1_4| <= 1b-53 /\ |g2_4| <= 1b-53 /\ |f1_4| <= 1b-53 /\ |f2_4| <= 1b-53 /\ |f3_4| <= 1b-53 /\ |f4_4| <= 1b-53 /\
  |hI4| <= 0x1.0080000000000p+0 /\ |lI4| <= 0x1.0030000000000p-51 /\ |hI4 + lI4 - XI4| <= 0x1.e028000000000p-103 /\
  |g1_5| <= 1b-53 /\ |f1_5| <= 1b-53 /\ |f2_5| <= 1b-53 /\
  |hI5| <= 0x1.0040000000000p+0 /\ |lI5| <= 0x1.8020000000000p-52 /\ |hI5 + lI5 - XI5| <= 0x1.0008000000000p-103 /\
  |g1_6| <= 1b-53 /\ |f1_6| <= 1b-53 /\ |f2_6| <= 1b-53 /\
  |hI6| <= 0x1.0040000000000p+0 /\ |lI6| <= 0x1.8020000000000p-52 /\ |hI6 + lI6 - XI6| <= 0x1.0008000000000p-103 /\
  |k1_7| <= 1b-53 /\ |f1_7| <= 1b-53 /\ |f2_7| <= 1b-53 /\ |f3_7| <= 1b-53 /\ |f4_7| <= 1b-53 /\
  |hY7| <= 0x1.00c0000000000p+0 /\ |lY7| <= 0x1.8080000000000p-51 /\ |hY7 + lY7 - XY7| <= 0x1.f060000000000p-102 /\
  |hZ7| <= 0x1.0080000000000p+0 /\ |lZ7| <= 0x1.0030000000000p-51 /\ |hZ7 + lZ7 - XZ7| <= 0x1.e028000000000p-103 /\ |XZ7| <= 1 /\
  |g1_8| <= 1b-53 /\ |g2_8| <= 1b-53 /\ |f1_8| <= 1b-53 /\ |f2_8| <= 1b-53 /\ |f3_8| <= 1b-53 /\ |f4_8| <= 1b-53 /\
  |hI8| <= 0x1.0100000000000p+0 /\ |lI8| <= 0x1.6100000000000p-50 /\ |hI8 + lI8 - XI8| <= 0x1.94cc000000000p-100 /\
  |g1_9| <= 1b-53 /\ |g2_9| <= 1b-53 /\ |f1_9| <= 1b-53 /\ |f2_9| <= 1b-53 /\ |f3_9| <= 1b-53 /\ |f4_9| <= 1b-53 /\
  |hI9| <= 0x1.0100000000000p+0 /\ |lI9| <= 0x1.6100000000000p-50 /\ |hI9 + lI9 - XI9| <= 0x1.94cc000000000p-100 /\
  |g1_10| <= 1b-53 /\ |g2_10| <= 1b-53 /\ |f1_10| <= 1b-53 /\ |f2_10| <= 1b-53 /\ |f3_10| <= 1b-53 /\ |f4_10| <= 1b-53 /\
  |hI10| <= 0x1.0100000000000p+0 /\ |lI10| <= 0x1.6100000000000p-50 /\ |hI10 + lI10 - XI10| <= 0x1.94cc000000000p-100 /\
  |dg1| <= 1b-53 /\ |dg2| <= 1b-53 /\ |dg3| <= 1b-53 /\ |dg4| <= 1b-53 /\
  |pe1| <= 1b-53 /\ |pe2| <= 1b-53 /\ |pe3| <= 1b-53 /\ |pe4| <= 1b-53 /\ |pe5| <= 1b-53 /\ |pe6| <= 1b-53 /\ |pe7| <= 1b-53 /\ |pe8| <= 1b-53 /\ |pe9| <= 1b-53
  -> |err0 * 1b106| <= 8.0009765625 /\
     |hi0| <= 1.0009765625 /\
     |lo0 * 1b53| <= 3.0009765625 /\
     |err1 * 1b106| <= 15.0048828125 /\
     |hi1| <= 1.001953125 /\
     |lo1 * 1b53| <= 4.0029296875 /\
     |err2 * 1b106| <= 31.0234375 /\
     |hi2| <= 1.0029296875 /\
     |lo2 * 1b53| <= 6.0078125 /\
     |err3 * 1b106| <= 31.0234375 /\
     |hi3| <= 1.0029296875 /\
     |lo3 * 1b53| <= 6.0078125 /\
     |err4 * 1b106| <= 31.0234375 /\
     |hi4| <= 1.0029296875 /\
     |lo4 * 1b53| <= 6.0078125 /\
     |err5 * 1b106| <= 15.0048828125 /\
     |hi5| <= 1.001953125 /\
     |lo5 * 1b53| <= 4.0029296875 /\
     |err6 * 1b106| <= 15.0048828125 /\
     |hi6| <= 1.001953125 /\
     |lo6 * 1b53| <= 4.0029296875 /\
     |err7 * 1b106| <= 101.19921875 /\
     |hi7| <= 1.00390625 /\
     |lo7 * 1b53| <= 11.03125 /\
     |err8 * 1b106| <= 138.3125 /\
     |hi8| <= 1.0048828125 /\
     |lo8 * 1b53| <= 13.046875 /\
     |err9 * 1b106| <= 138.3125 /\
     |hi9| <= 1.0048828125 /\
     |lo9 * 1b53| <= 13.046875 /\
     |err10 * 1b106| <= 138.3125 /\
     |hi10| <= 1.0048828125 /\
     |lo10 * 1b53| <= 13.046875 /\
     2 * 138.3125 * (1 + 1b-53) - @K@ * ptilde <= 0 }

# Rewritings (Gappa checks each is an identity; check_two_term_constants.cmake fails
# on a warning that one is not).
hi0 + lo0 - XY0 * XZ0 -> hY0 * lZ0 * f1_0 + lY0 * hZ0 * f2_0 + (r1_0 + r2_0) * f3_0 + (e0 + r3_0) * f4_0 - lY0 * lZ0 + (hY0 + lY0) * (hZ0 + lZ0 - XZ0) + (hY0 + lY0 - XY0) * XZ0;
hi1 + lo1 - XY1 -> (hY1 + lY1 - XY1) + lY1 * f1_1 + (e1 + r1) * f2_1;
hi2 + lo2 - XI2 -> (hI2 + lI2 - XI2) + (lI2 + 0) * f1_2 + (a2 + 0) * f2_2 + (e1_2 + e2_2) * f3_2 + (b2 + c2) * f4_2;
hi3 + lo3 - XI3 -> (hI3 + lI3 - XI3) + (0 + lI3) * f1_3 + (a3 + 0) * f2_3 + (e1_3 + e2_3) * f3_3 + (b3 + c3) * f4_3;
hi4 + lo4 - XI4 -> (hI4 + lI4 - XI4) + (0 + 0) * f1_4 + (a4 + lI4) * f2_4 + (e1_4 + e2_4) * f3_4 + (b4 + c4) * f4_4;
hi5 + lo5 - XI5 -> (hI5 + lI5 - XI5) + (lI5 + 0) * f1_5 + (a5 + e5) * f2_5;
hi6 + lo6 - XI6 -> (hI6 + lI6 - XI6) + (0 + lI6) * f1_6 + (a6 + e6) * f2_6;
hi7 + lo7 - XY7 * XZ7 -> hY7 * lZ7 * f1_7 + lY7 * hZ7 * f2_7 + (r1_7 + r2_7) * f3_7 + (e7 + r3_7) * f4_7 - lY7 * lZ7 + (hY7 + lY7) * (hZ7 + lZ7 - XZ7) + (hY7 + lY7 - XY7) * XZ7;
hi8 + lo8 - XI8 -> (hI8 + lI8 - XI8) + (lI8 + 0) * f1_8 + (a8 + 0) * f2_8 + (e1_8 + e2_8) * f3_8 + (b8 + c8) * f4_8;
hi9 + lo9 - XI9 -> (hI9 + lI9 - XI9) + (0 + lI9) * f1_9 + (a9 + 0) * f2_9 + (e1_9 + e2_9) * f3_9 + (b9 + c9) * f4_9;
hi10 + lo10 - XI10 -> (hI10 + lI10 - XI10) + (0 + 0) * f1_10 + (a10 + lI10) * f2_10 + (e1_10 + e2_10) * f3_10 + (b10 + c10) * f4_10;
