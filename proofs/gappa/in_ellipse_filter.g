# proofs/gappa/in_ellipse_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::in_ellipse_filter (predicates/in_ellipse.hpp), written by
# proofs/gappa/in_ellipse_filter.py from the filter's statements, one line per operation (as in
# incircle_filter.g); the hints split every error into the operation's rounding, its underflow
# term and the propagated error of its operands.
#
# Proves: with all coordinate differences scaled by one power of two so that
#   mc = max(maxx, maxy) lies in [1, 2), and the metric entries by another so that
#   mm = max(|M11|, |M12|, |M22|) lies in [1, 2),
#     |det - Det| <= in_ellipse_filter_eps   and no intermediate overflows below in_ellipse_filter_max,
# where det is the double the filter computes and Det the exact determinant
# det [p - d, q(p - d)] of the exact differences and the (exact, double) metric entries.
# proofs/invariants/filters.md, section 6, turns this into the soundness of the filter.
#
# Model: as in incircle_filter.g, with two more inputs:
# - m11, m12, m22 are the metric's doubles (scaled; exact inputs, no rounding), each at most
#   2 - 2^-52 in magnitude; m12x2 = 2 * m12 is exact (a power-of-two scaling with no underflow;
#   its overflow is among the goals).
# - Every product has degree at most 5 in the scaled inputs (4 in the differences, 1 in the
#   metric), so its underflow term is at most 2^(-1074 + 5 L) when both maxima are at least
#   in_ellipse_filter_min = 2^-L (proofs/check_constants.cmake, degree 5).
#
# Placeholders filled in by proofs/check_constants.cmake (CTest test proofs.in_ellipse_filter):
#     @EPS@        in_ellipse_filter_eps
#     @UNDERFLOW@  2^(-1074 + 5 L), L = -log2(in_ellipse_filter_min)
#     @OVERFLOW@   2^(1023 - 5 M), M = log2(in_ellipse_filter_max)
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

@rnd = float<53, ne>;

adx = rnd(Adx); ady = rnd(Ady); bdx = rnd(Bdx); bdy = rnd(Bdy);
cdx = rnd(Cdx); cdy = rnd(Cdy);
m12x2 = 2 * m12;

# const double alift = metric_lift(adx, ady, m);
m11_adx = rnd(m11 * adx) + u1;
m11_adx_adx = rnd(m11_adx * adx) + u2;
m12_adx = rnd(m12x2 * adx) + u3;
m12_adx_ady = rnd(m12_adx * ady) + u4;
m22_ady = rnd(m22 * ady) + u5;
m22_ady_ady = rnd(m22_ady * ady) + u6;
alift_12 = rnd(m11_adx_adx + m12_adx_ady);
alift = rnd(alift_12 + m22_ady_ady);
# const double blift = metric_lift(bdx, bdy, m);
m11_bdx = rnd(m11 * bdx) + u7;
m11_bdx_bdx = rnd(m11_bdx * bdx) + u8;
m12_bdx = rnd(m12x2 * bdx) + u9;
m12_bdx_bdy = rnd(m12_bdx * bdy) + u10;
m22_bdy = rnd(m22 * bdy) + u11;
m22_bdy_bdy = rnd(m22_bdy * bdy) + u12;
blift_12 = rnd(m11_bdx_bdx + m12_bdx_bdy);
blift = rnd(blift_12 + m22_bdy_bdy);
# const double clift = metric_lift(cdx, cdy, m);
m11_cdx = rnd(m11 * cdx) + u13;
m11_cdx_cdx = rnd(m11_cdx * cdx) + u14;
m12_cdx = rnd(m12x2 * cdx) + u15;
m12_cdx_cdy = rnd(m12_cdx * cdy) + u16;
m22_cdy = rnd(m22 * cdy) + u17;
m22_cdy_cdy = rnd(m22_cdy * cdy) + u18;
clift_12 = rnd(m11_cdx_cdx + m12_cdx_cdy);
clift = rnd(clift_12 + m22_cdy_cdy);
# det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
bdx_cdy = rnd(bdx * cdy) + u19;
cdx_bdy = rnd(cdx * bdy) + u20;
minor_a = rnd(bdx_cdy - cdx_bdy);
cdx_ady = rnd(cdx * ady) + u21;
adx_cdy = rnd(adx * cdy) + u22;
minor_b = rnd(cdx_ady - adx_cdy);
adx_bdy = rnd(adx * bdy) + u23;
bdx_ady = rnd(bdx * ady) + u24;
minor_c = rnd(adx_bdy - bdx_ady);
term_a = rnd(alift * minor_a) + u25;
term_b = rnd(blift * minor_b) + u26;
term_c = rnd(clift * minor_c) + u27;
sum_ab = rnd(term_a + term_b);
det = rnd(sum_ab + term_c);
Det = ((((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy))) + (((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy)))) + (((((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) + ((m22 * Cdy) * Cdy)) * ((Adx * Bdy) - (Bdx * Ady)));

{ |Adx| <= 18014398509481983b-53 /\ |Ady| <= 18014398509481983b-53 /\
  |Bdx| <= 18014398509481983b-53 /\ |Bdy| <= 18014398509481983b-53 /\
  |Cdx| <= 18014398509481983b-53 /\ |Cdy| <= 18014398509481983b-53 /\
  |adx| <= 9007199254740991b-52 /\ |ady| <= 9007199254740991b-52 /\
  |bdx| <= 9007199254740991b-52 /\ |bdy| <= 9007199254740991b-52 /\
  |cdx| <= 9007199254740991b-52 /\ |cdy| <= 9007199254740991b-52 /\
  |m11| <= 9007199254740991b-52 /\ |m12| <= 9007199254740991b-52 /\
  |m22| <= 9007199254740991b-52 /\ |u1| <= @UNDERFLOW@ /\ |u2| <= @UNDERFLOW@ /\
  |u3| <= @UNDERFLOW@ /\ |u4| <= @UNDERFLOW@ /\ |u5| <= @UNDERFLOW@ /\ |u6| <= @UNDERFLOW@ /\
  |u7| <= @UNDERFLOW@ /\ |u8| <= @UNDERFLOW@ /\ |u9| <= @UNDERFLOW@ /\ |u10| <= @UNDERFLOW@ /\
  |u11| <= @UNDERFLOW@ /\ |u12| <= @UNDERFLOW@ /\ |u13| <= @UNDERFLOW@ /\ |u14| <= @UNDERFLOW@ /\
  |u15| <= @UNDERFLOW@ /\ |u16| <= @UNDERFLOW@ /\ |u17| <= @UNDERFLOW@ /\ |u18| <= @UNDERFLOW@ /\
  |u19| <= @UNDERFLOW@ /\ |u20| <= @UNDERFLOW@ /\ |u21| <= @UNDERFLOW@ /\ |u22| <= @UNDERFLOW@ /\
  |u23| <= @UNDERFLOW@ /\ |u24| <= @UNDERFLOW@ /\ |u25| <= @UNDERFLOW@ /\ |u26| <= @UNDERFLOW@ /\
  |u27| <= @UNDERFLOW@
  -> |det - Det| <= @EPS@ /\ |m12x2| <= @OVERFLOW@ /\ |m11_adx| <= @OVERFLOW@ /\
     |m11_adx_adx| <= @OVERFLOW@ /\ |m12_adx| <= @OVERFLOW@ /\ |m12_adx_ady| <= @OVERFLOW@ /\
     |m22_ady| <= @OVERFLOW@ /\ |m22_ady_ady| <= @OVERFLOW@ /\ |alift_12| <= @OVERFLOW@ /\
     |alift| <= @OVERFLOW@ /\ |m11_bdx| <= @OVERFLOW@ /\ |m11_bdx_bdx| <= @OVERFLOW@ /\
     |m12_bdx| <= @OVERFLOW@ /\ |m12_bdx_bdy| <= @OVERFLOW@ /\ |m22_bdy| <= @OVERFLOW@ /\
     |m22_bdy_bdy| <= @OVERFLOW@ /\ |blift_12| <= @OVERFLOW@ /\ |blift| <= @OVERFLOW@ /\
     |m11_cdx| <= @OVERFLOW@ /\ |m11_cdx_cdx| <= @OVERFLOW@ /\ |m12_cdx| <= @OVERFLOW@ /\
     |m12_cdx_cdy| <= @OVERFLOW@ /\ |m22_cdy| <= @OVERFLOW@ /\ |m22_cdy_cdy| <= @OVERFLOW@ /\
     |clift_12| <= @OVERFLOW@ /\ |clift| <= @OVERFLOW@ /\ |bdx_cdy| <= @OVERFLOW@ /\
     |cdx_bdy| <= @OVERFLOW@ /\ |minor_a| <= @OVERFLOW@ /\ |cdx_ady| <= @OVERFLOW@ /\
     |adx_cdy| <= @OVERFLOW@ /\ |minor_b| <= @OVERFLOW@ /\ |adx_bdy| <= @OVERFLOW@ /\
     |bdx_ady| <= @OVERFLOW@ /\ |minor_c| <= @OVERFLOW@ /\ |term_a| <= @OVERFLOW@ /\
     |term_b| <= @OVERFLOW@ /\ |term_c| <= @OVERFLOW@ /\ |sum_ab| <= @OVERFLOW@ /\
     |det| <= @OVERFLOW@ }

# Hints.
m11_adx - m11 * Adx -> (rnd(m11 * adx) - m11 * adx) + u1 + (m11 * adx - m11 * Adx);
m11_adx_adx - (m11 * Adx) * Adx -> (rnd(m11_adx * adx) - m11_adx * adx) + u2 + (m11_adx * adx - (m11 * Adx) * Adx);
m12_adx - m12x2 * Adx -> (rnd(m12x2 * adx) - m12x2 * adx) + u3 + (m12x2 * adx - m12x2 * Adx);
m12_adx_ady - (m12x2 * Adx) * Ady -> (rnd(m12_adx * ady) - m12_adx * ady) + u4 + (m12_adx * ady - (m12x2 * Adx) * Ady);
m22_ady - m22 * Ady -> (rnd(m22 * ady) - m22 * ady) + u5 + (m22 * ady - m22 * Ady);
m22_ady_ady - (m22 * Ady) * Ady -> (rnd(m22_ady * ady) - m22_ady * ady) + u6 + (m22_ady * ady - (m22 * Ady) * Ady);
alift_12 - (((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) -> (alift_12 - (m11_adx_adx + m12_adx_ady)) + ((m11_adx_adx - ((m11 * Adx) * Adx)) + (m12_adx_ady - ((m12x2 * Adx) * Ady)));
alift - ((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) -> (alift - (alift_12 + m22_ady_ady)) + ((alift_12 - (((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady))) + (m22_ady_ady - ((m22 * Ady) * Ady)));
m11_bdx - m11 * Bdx -> (rnd(m11 * bdx) - m11 * bdx) + u7 + (m11 * bdx - m11 * Bdx);
m11_bdx_bdx - (m11 * Bdx) * Bdx -> (rnd(m11_bdx * bdx) - m11_bdx * bdx) + u8 + (m11_bdx * bdx - (m11 * Bdx) * Bdx);
m12_bdx - m12x2 * Bdx -> (rnd(m12x2 * bdx) - m12x2 * bdx) + u9 + (m12x2 * bdx - m12x2 * Bdx);
m12_bdx_bdy - (m12x2 * Bdx) * Bdy -> (rnd(m12_bdx * bdy) - m12_bdx * bdy) + u10 + (m12_bdx * bdy - (m12x2 * Bdx) * Bdy);
m22_bdy - m22 * Bdy -> (rnd(m22 * bdy) - m22 * bdy) + u11 + (m22 * bdy - m22 * Bdy);
m22_bdy_bdy - (m22 * Bdy) * Bdy -> (rnd(m22_bdy * bdy) - m22_bdy * bdy) + u12 + (m22_bdy * bdy - (m22 * Bdy) * Bdy);
blift_12 - (((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) -> (blift_12 - (m11_bdx_bdx + m12_bdx_bdy)) + ((m11_bdx_bdx - ((m11 * Bdx) * Bdx)) + (m12_bdx_bdy - ((m12x2 * Bdx) * Bdy)));
blift - ((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) -> (blift - (blift_12 + m22_bdy_bdy)) + ((blift_12 - (((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy))) + (m22_bdy_bdy - ((m22 * Bdy) * Bdy)));
m11_cdx - m11 * Cdx -> (rnd(m11 * cdx) - m11 * cdx) + u13 + (m11 * cdx - m11 * Cdx);
m11_cdx_cdx - (m11 * Cdx) * Cdx -> (rnd(m11_cdx * cdx) - m11_cdx * cdx) + u14 + (m11_cdx * cdx - (m11 * Cdx) * Cdx);
m12_cdx - m12x2 * Cdx -> (rnd(m12x2 * cdx) - m12x2 * cdx) + u15 + (m12x2 * cdx - m12x2 * Cdx);
m12_cdx_cdy - (m12x2 * Cdx) * Cdy -> (rnd(m12_cdx * cdy) - m12_cdx * cdy) + u16 + (m12_cdx * cdy - (m12x2 * Cdx) * Cdy);
m22_cdy - m22 * Cdy -> (rnd(m22 * cdy) - m22 * cdy) + u17 + (m22 * cdy - m22 * Cdy);
m22_cdy_cdy - (m22 * Cdy) * Cdy -> (rnd(m22_cdy * cdy) - m22_cdy * cdy) + u18 + (m22_cdy * cdy - (m22 * Cdy) * Cdy);
clift_12 - (((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) -> (clift_12 - (m11_cdx_cdx + m12_cdx_cdy)) + ((m11_cdx_cdx - ((m11 * Cdx) * Cdx)) + (m12_cdx_cdy - ((m12x2 * Cdx) * Cdy)));
clift - ((((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) + ((m22 * Cdy) * Cdy)) -> (clift - (clift_12 + m22_cdy_cdy)) + ((clift_12 - (((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy))) + (m22_cdy_cdy - ((m22 * Cdy) * Cdy)));
bdx_cdy - Bdx * Cdy -> (rnd(bdx * cdy) - bdx * cdy) + u19 + (bdx * cdy - Bdx * Cdy);
cdx_bdy - Cdx * Bdy -> (rnd(cdx * bdy) - cdx * bdy) + u20 + (cdx * bdy - Cdx * Bdy);
minor_a - ((Bdx * Cdy) - (Cdx * Bdy)) -> (minor_a - (bdx_cdy - cdx_bdy)) + ((bdx_cdy - (Bdx * Cdy)) - (cdx_bdy - (Cdx * Bdy)));
cdx_ady - Cdx * Ady -> (rnd(cdx * ady) - cdx * ady) + u21 + (cdx * ady - Cdx * Ady);
adx_cdy - Adx * Cdy -> (rnd(adx * cdy) - adx * cdy) + u22 + (adx * cdy - Adx * Cdy);
minor_b - ((Cdx * Ady) - (Adx * Cdy)) -> (minor_b - (cdx_ady - adx_cdy)) + ((cdx_ady - (Cdx * Ady)) - (adx_cdy - (Adx * Cdy)));
adx_bdy - Adx * Bdy -> (rnd(adx * bdy) - adx * bdy) + u23 + (adx * bdy - Adx * Bdy);
bdx_ady - Bdx * Ady -> (rnd(bdx * ady) - bdx * ady) + u24 + (bdx * ady - Bdx * Ady);
minor_c - ((Adx * Bdy) - (Bdx * Ady)) -> (minor_c - (adx_bdy - bdx_ady)) + ((adx_bdy - (Adx * Bdy)) - (bdx_ady - (Bdx * Ady)));
term_a - ((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy)) -> (rnd(alift * minor_a) - alift * minor_a) + u25 + (alift * minor_a - ((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy)));
term_b - ((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy)) -> (rnd(blift * minor_b) - blift * minor_b) + u26 + (blift * minor_b - ((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy)));
term_c - ((((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) + ((m22 * Cdy) * Cdy)) * ((Adx * Bdy) - (Bdx * Ady)) -> (rnd(clift * minor_c) - clift * minor_c) + u27 + (clift * minor_c - ((((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) + ((m22 * Cdy) * Cdy)) * ((Adx * Bdy) - (Bdx * Ady)));
sum_ab - ((((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy))) + (((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy)))) -> (sum_ab - (term_a + term_b)) + ((term_a - (((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy)))) + (term_b - (((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy)))));
det - Det -> (det - (sum_ab + term_c)) + ((sum_ab - ((((((m11 * Adx) * Adx) + ((m12x2 * Adx) * Ady)) + ((m22 * Ady) * Ady)) * ((Bdx * Cdy) - (Cdx * Bdy))) + (((((m11 * Bdx) * Bdx) + ((m12x2 * Bdx) * Bdy)) + ((m22 * Bdy) * Bdy)) * ((Cdx * Ady) - (Adx * Cdy))))) + (term_c - (((((m11 * Cdx) * Cdx) + ((m12x2 * Cdx) * Cdy)) + ((m22 * Cdy) * Cdy)) * ((Adx * Bdy) - (Bdx * Ady)))));
