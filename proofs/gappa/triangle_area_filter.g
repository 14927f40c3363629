# proofs/gappa/triangle_area_filter.g: Gappa proof of the stage-A filter of
# exactmesh::predicates::triangle_area_sign (predicates/triangle_area.cpp).
#
# Proves: with D0..D3 the exact coordinate differences a - c, b - c scaled by 2^shift, B the
#   exact 2 area 2^(2 shift) and R = D0 D3 - D1 D2 - B (whose sign is the answer), the computed
#   r = fl(fl(fl(d0 d3) - fl(d1 d2)) - bound) is within
#     error = fl(fl(eps fl(|p| + |q|)) + fl(result_eps fl(|det| + |bound|)) + floor)
#   of R, so r > error gives R > 0 and -r > error gives R < 0.
#
# Model (proofs/invariants/filters.md, "triangle_area_sign"): d_i = D_i (1 + k_i) + h_i 2^-1075
# (the difference rounded, then scaled exactly but for subnormal results), |d_i| < 2 (the
# largest is in [1, 2)), so |D_i| < 2.001; products p = fl(d0 d3), q = fl(d1 d2) get (1 + k) and
# an underflow term h 2^-1075; additions and subtractions are exact in the subnormal range, so
# they get (1 + k) only; bound = ldexp(area, 2 shift + 1) = B + hb 2^-1075 (its overflow returns
# before); eps fl(...) and result_eps fl(...) get an underflow term t 2^-1075 (the product by a
# power of two is otherwise exact). No overflow: |d_i| < 2, |det| <= 8, |bound| <= DBL_MAX.
# Every k, e is a free |.| <= u = 2^-53, every h, t a free |.| <= 1.
#
# Goals: (1) the split of r - R into parts proportional to |D0 D3|, |D1 D2|, |det|, |B| and
# 2^-1075 is an identity (Gappa checks the rewriting; proofs/check_triangle_area_constants.cmake
# fails on a warning that it is not); (2)-(6) each part is covered by its share of the computed
# error: the |det| part up to 8 u^2 |det|, which (2) leaves over and (4)-(6) pay for, since
# |det| <= (1 + u)(|p| + |q|). The sum of the parts is by hand (filters.md).
#
# Placeholders, filled in from predicates/filter_constants.hpp by
# proofs/check_triangle_area_constants.cmake (CTest test proofs.triangle_area_filter):
#     @PRODUCT_EPS@  triangle_area_filter_eps
#     @RESULT_EPS@   triangle_area_filter_result_eps
#     @FLOOR@        triangle_area_filter_floor
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# The evaluation as the code does it, every rounding explicit (model in the header).
d0 = D0 * (1 + k0) + h0 * 1b-1075;
d1 = D1 * (1 + k1) + h1 * 1b-1075;
d2 = D2 * (1 + k2) + h2 * 1b-1075;
d3 = D3 * (1 + k3) + h3 * 1b-1075;
p = d0 * d3 * (1 + kp) + hp * 1b-1075;
q = d1 * d2 * (1 + kq) + hq * 1b-1075;
det = (p - q) * (1 + kd);
bound = B + hb * 1b-1075;
r = (det - bound) * (1 + kr);
R = D0 * D3 - D1 * D2 - B;

# Its error, split into parts proportional to |D0 D3|, |D1 D2|, |det|, |B| and 2^-1075; the
# rounding of det is charged to |det| (det - (p - q) = det kd / (1 + kd)).
alpha = (1 + k0) * (1 + k3) * (1 + kp);
beta = (1 + k1) * (1 + k2) * (1 + kq);
jp = (h0 * d3 + D0 * (1 + k0) * h3) * (1 + kp) + hp;
jq = (h1 * d2 + D1 * (1 + k1) * h2) * (1 + kq) + hq;
junk = jp - jq - hb * (1 + kr);
split = D0 * D3 * (alpha - 1) - D1 * D2 * (beta - 1) + det * (kr + kd / (1 + kd)) - B * kr
        + junk * 1b-1075;
# Factors of the computed error bound: F1 on 4u (|p| + |q|), F2 on 2u (|det| + |bound|).
F1 = (1 + e1) * (1 + e3) * (1 + e4);
F2 = (1 + e2) * (1 + e3) * (1 + e4);

{ |k0| <= 1b-53 /\ |k1| <= 1b-53 /\ |k2| <= 1b-53 /\ |k3| <= 1b-53 /\ |kp| <= 1b-53 /\
  |kq| <= 1b-53 /\ |kd| <= 1b-53 /\ |kr| <= 1b-53 /\ |e1| <= 1b-53 /\ |e2| <= 1b-53 /\
  |e3| <= 1b-53 /\ |e4| <= 1b-53 /\
  |h0| <= 1 /\ |h1| <= 1 /\ |h2| <= 1 /\ |h3| <= 1 /\ |hp| <= 1 /\ |hq| <= 1 /\ |hb| <= 1 /\
  |t1| <= 1 /\ |t2| <= 1 /\
  |d2| <= 2 /\ |d3| <= 2 /\ |D0| <= 2.001 /\ |D1| <= 2.001
  -> r - R - split in [0, 0] /\
     |kr + kd / (1 + kd)| - @RESULT_EPS@ * F2 - 8b-106 <= 0 /\
     |kr| - @RESULT_EPS@ * F2 <= 0 /\
     |alpha - 1| + alpha * (1 + 1b-53) * 8b-106 - @PRODUCT_EPS@ * alpha * F1 <= 0 /\
     |beta - 1| + beta * (1 + 1b-53) * 8b-106 - @PRODUCT_EPS@ * beta * F1 <= 0 /\
     |junk| + (|jp| + |jq|) * (@PRODUCT_EPS@ * F1 + (1 + 1b-53) * 8b-106)
       + @RESULT_EPS@ * |hb| * F2 + (|t1| + |t2|) * (1 + e3) * (1 + e4)
       - @FLOOR@ * 1b1075 * (1 + e4) <= 0 }

r - R - split -> 0;
