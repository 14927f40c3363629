# proofs/gappa/two_term_incircle.g: Gappa proof of the error bound of incircle's two-term stage B
# (predicates/two_term.hpp, incircle_stage_b; used by predicates/incircle.cpp) and of the
# constant icc_errbound_two_term of predicates/adaptive_bounds.hpp.
#
# Proves, lemma by lemma, the invariant (E, H, L) of every double-double operation of the
# evaluation as the code does it: a pair (hi, lo) approximating X, whose permanent is P, has
# |hi + lo - X| <= E u^2 P, |hi| <= H P, |lo| <= L u P (u = 2^-53). The chain ends with
# |hi + lo - B| <= 42.05 u^2 P for the determinant B of the rounded differences, and the last goal
# checks that beta = K u^2 P~ (P~ the permanent as the code computes it, 6 roundings per monomial)
# is at least 12/5 (1 + u) times that error for the header's K.
#
# Model (proofs/invariants/filters.md, "Two-term stage"): inside the expansion-safe range every
# rounding is fl(z) = z (1 + d), |d| <= u (exact below 2^-1022, no overflow). An error-free
# transformation is exact: two_product(a, b) = (ab (1 + k), -ab k), two_sum/two_diff(a, b) =
# ((a +- b)(1 + g), -(a +- b) g); each rounded addition or product of the tails carries its own
# factor (1 + f). Roundings are free variables (independent: this covers any sharing). By hand
# (filters.md): with the roundings fixed, every operation is linear in its inputs (bilinear for
# the product), so each lemma may be checked per monomial / per input with its permanent
# normalised to 1, and the lemmas compose by taking each lemma's proven (E, H, L) as the next
# one's hypotheses (written out below with the same numbers). The hints below state the exact
# error of each operation without the cancelling leading terms.
#
# Placeholder, filled in from predicates/adaptive_bounds.hpp by proofs/check_two_term_constants.cmake
# (CTest test proofs.two_term_incircle):
#     @K@          icc_errbound_two_term / u^2
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# Lemma A: two_term_diff_of_products / two_term_sum_of_squares (two), X = x - y, x = ab, y = cd,
# P = |x| + |y|; one instance per monomial (x = 1, y = 0; x = 0, y = 1; and x = 0, y = -1, the
# sum of squares: two_sum(p, q) is two_diff(p, -q) and fl(-z) = -fl(z)).
p0 = 1 * (1 + k1_0);  pt0 = -(1) * k1_0;
q0 = 0 * (1 + k2_0);  qt0 = -(0) * k2_0;
hi0 = (p0 - q0) * (1 + g1_0);  s0 = -(p0 - q0) * g1_0;
t0 = (pt0 - qt0) * (1 + f1_0);
lo0 = (s0 + t0) * (1 + f2_0);
err0 = hi0 + lo0 - (1 - 0);
p1 = 0 * (1 + k1_1);  pt1 = -(0) * k1_1;
q1 = 1 * (1 + k2_1);  qt1 = -(1) * k2_1;
hi1 = (p1 - q1) * (1 + g1_1);  s1 = -(p1 - q1) * g1_1;
t1 = (pt1 - qt1) * (1 + f1_1);
lo1 = (s1 + t1) * (1 + f2_1);
err1 = hi1 + lo1 - (0 - 1);
p2 = 0 * (1 + k1_2);  pt2 = -(0) * k1_2;
q2 = -1 * (1 + k2_2);  qt2 = -(-1) * k2_2;
hi2 = (p2 - q2) * (1 + g1_2);  s2 = -(p2 - q2) * g1_2;
t2 = (pt2 - qt2) * (1 + f1_2);
lo2 = (s2 + t2) * (1 + f2_2);
err2 = hi2 + lo2 - (0 - -1);
# proven: E = 3.0009765625, H = 1.0009765625, L = 2.0009765625

# Lemma C: two_term_product(lift, minor), Y = lift (Lemma A), Z = minor (Lemma A), P_Y = P_Z = 1.
hi3 = hY3 * hZ3 * (1 + k1_3);  e3 = -(hY3 * hZ3) * k1_3;
r1_3 = hY3 * lZ3 * (1 + f1_3);
r2_3 = lY3 * hZ3 * (1 + f2_3);
r3_3 = (r1_3 + r2_3) * (1 + f3_3);
lo3 = (e3 + r3_3) * (1 + f4_3);
err3 = hi3 + lo3 - XY3 * XZ3;
# proven: E = 23.0224609375, H = 1.001953125, L = 5.005859375

# Lemma D, n = 3: two_term_sum of the three lift-times-minor pairs (Lemma C); one instance per
# position (the sum is linear in its inputs), each input normalised to permanent 1.
s4 = (hI4 + 0) * (1 + g1_4);  e1_4 = -(hI4 + 0) * g1_4;
hi4 = (s4 + 0) * (1 + g2_4);  e2_4 = -(s4 + 0) * g2_4;
a4 = (lI4 + 0) * (1 + f1_4);
b4 = (a4 + 0) * (1 + f2_4);
c4 = (e1_4 + e2_4) * (1 + f3_4);
lo4 = (b4 + c4) * (1 + f4_4);
err4 = hi4 + lo4 - XI4;
s5 = (0 + hI5) * (1 + g1_5);  e1_5 = -(0 + hI5) * g1_5;
hi5 = (s5 + 0) * (1 + g2_5);  e2_5 = -(s5 + 0) * g2_5;
a5 = (0 + lI5) * (1 + f1_5);
b5 = (a5 + 0) * (1 + f2_5);
c5 = (e1_5 + e2_5) * (1 + f3_5);
lo5 = (b5 + c5) * (1 + f4_5);
err5 = hi5 + lo5 - XI5;
s6 = (0 + 0) * (1 + g1_6);  e1_6 = -(0 + 0) * g1_6;
hi6 = (s6 + hI6) * (1 + g2_6);  e2_6 = -(s6 + hI6) * g2_6;
a6 = (0 + 0) * (1 + f1_6);
b6 = (a6 + lI6) * (1 + f2_6);
c6 = (e1_6 + e2_6) * (1 + f3_6);
lo6 = (b6 + c6) * (1 + f4_6);
err6 = hi6 + lo6 - XI6;
# proven: E = 42.048828125, H = 1.0029296875, L = 7.0107421875

# Certification: per monomial M of the permanent, the computed permanent carries
# 6 rounding factors; beta = K u^2 P~ (exact: K u^2 is a power of two) must exceed 12/5
# times the two-term error E u^2 |M|, itself divided by (1 + u) for fl(hi + lo).
ptilde = (1 + pe1) * (1 + pe2) * (1 + pe3) * (1 + pe4) * (1 + pe5) * (1 + pe6);

{ |k1_0| <= 1b-53 /\ |k2_0| <= 1b-53 /\ |g1_0| <= 1b-53 /\ |f1_0| <= 1b-53 /\ |f2_0| <= 1b-53 /\ |k1_1| <= 1b-53 /\ |k2_1| <= 1b-53 /\ |g1_1| <= 1b-53 /\ |f1_1| <= 1b-53 /\ |f2_1| <= 1b-53 /\ |k1_2| <= 1b-53 /\ |k2_2| <= 1b-53 /\ |g1_2| <= 1b-53 /\ |f1_2| <= 1b-53 /\ |f2_2| <= 1b-53 /\ |k1_3| <= 1b-53 /\ |f1_3| <= 1b-53 /\ |f2_3| <= 1b-53 /\ |f3_3| <= 1b-53 /\ |f4_3| <= 1b-53 /\ |g1_4| <= 1b-53 /\ |g2_4| <= 1b-53 /\ |f1_4| <= 1b-53 /\ |f2_4| <= 1b-53 /\ |f3_4| <= 1b-53 /\ |f4_4| <= 1b-53 /\ |g1_5| <= 1b-53 /\ |g2_5| <= 1b-53 /\ |f1_5| <= 1b-53 /\ |f2_5| <= 1b-53 /\ |f3_5| <= 1b-53 /\ |f4_5| <= 1b-53 /\ |g1_6| <= 1b-53 /\ |g2_6| <= 1b-53 /\ |f1_6| <= 1b-53 /\ |f2_6| <= 1b-53 /\ |f3_6| <= 1b-53 /\ |f4_6| <= 1b-53 /\ |pe1| <= 1b-53 /\ |pe2| <= 1b-53 /\ |pe3| <= 1b-53 /\ |pe4| <= 1b-53 /\ |pe5| <= 1b-53 /\ |pe6| <= 1b-53 /\
  |hY3| <= 0x1.0040000000000p+0 /\ |lY3| <= 0x1.0020000000000p-52 /\ |hY3 + lY3 - XY3| <= 0x1.8020000000000p-105 /\
  |hZ3| <= 0x1.0040000000000p+0 /\ |lZ3| <= 0x1.0020000000000p-52 /\ |hZ3 + lZ3 - XZ3| <= 0x1.8020000000000p-105 /\
  |XZ3| <= 1 /\
  |hI4| <= 0x1.0080000000000p+0 /\ |lI4| <= 0x1.4060000000000p-51 /\ |hI4 + lI4 - XI4| <= 0x1.705c000000000p-102 /\
  |hI5| <= 0x1.0080000000000p+0 /\ |lI5| <= 0x1.4060000000000p-51 /\ |hI5 + lI5 - XI5| <= 0x1.705c000000000p-102 /\
  |hI6| <= 0x1.0080000000000p+0 /\ |lI6| <= 0x1.4060000000000p-51 /\ |hI6 + lI6 - XI6| <= 0x1.705c000000000p-102
  -> |err0 * 1b106| <= 3.0009765625 /\
     |hi0| <= 1.0009765625 /\
     |lo0 * 1b53| <= 2.0009765625 /\
     |err1 * 1b106| <= 3.0009765625 /\
     |hi1| <= 1.0009765625 /\
     |lo1 * 1b53| <= 2.0009765625 /\
     |err2 * 1b106| <= 3.0009765625 /\
     |hi2| <= 1.0009765625 /\
     |lo2 * 1b53| <= 2.0009765625 /\
     |err3 * 1b106| <= 23.0224609375 /\
     |hi3| <= 1.001953125 /\
     |lo3 * 1b53| <= 5.005859375 /\
     |err4 * 1b106| <= 42.048828125 /\
     |hi4| <= 1.0029296875 /\
     |lo4 * 1b53| <= 7.0107421875 /\
     |err5 * 1b106| <= 42.048828125 /\
     |hi5| <= 1.0029296875 /\
     |lo5 * 1b53| <= 7.0107421875 /\
     |err6 * 1b106| <= 42.048828125 /\
     |hi6| <= 1.0029296875 /\
     |lo6 * 1b53| <= 7.0107421875 /\
     12 / 5 * 42.048828125 * (1 + 1b-53) - @K@ * ptilde <= 0 }

# Rewritings (Gappa checks each is an identity; check_two_term_constants.cmake fails
# on a warning that one is not).
hi0 + lo0 - (1 - 0) -> (pt0 - qt0) * f1_0 + (s0 + t0) * f2_0;
hi1 + lo1 - (0 - 1) -> (pt1 - qt1) * f1_1 + (s1 + t1) * f2_1;
hi2 + lo2 - (0 - -1) -> (pt2 - qt2) * f1_2 + (s2 + t2) * f2_2;
hi3 + lo3 - XY3 * XZ3 -> hY3 * lZ3 * f1_3 + lY3 * hZ3 * f2_3 + (r1_3 + r2_3) * f3_3 + (e3 + r3_3) * f4_3 - lY3 * lZ3 + (hY3 + lY3) * (hZ3 + lZ3 - XZ3) + (hY3 + lY3 - XY3) * XZ3;
hi4 + lo4 - XI4 -> (hI4 + lI4 - XI4) + (lI4 + 0) * f1_4 + (a4 + 0) * f2_4 + (e1_4 + e2_4) * f3_4 + (b4 + c4) * f4_4;
hi5 + lo5 - XI5 -> (hI5 + lI5 - XI5) + (0 + lI5) * f1_5 + (a5 + 0) * f2_5 + (e1_5 + e2_5) * f3_5 + (b5 + c5) * f4_5;
hi6 + lo6 - XI6 -> (hI6 + lI6 - XI6) + (0 + 0) * f1_6 + (a6 + lI6) * f2_6 + (e1_6 + e2_6) * f3_6 + (b6 + c6) * f4_6;
