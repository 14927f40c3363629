# proofs/gappa/angle_comparisons_3d_filter.g: Gappa proof of the long double filter of
# exactmesh::predicates::compare_dihedral and compare_volume_edge
# (predicates/angle_comparisons_3d.cpp).
#
# The filter evaluates each polynomial in long double (x86-64's 80-bit format, u = 2^-64) with
# its magnitude M (the same expression on absolute values, sums for differences) and a count k
# of the roundings on any monomial's path, and certifies the sign when
#   |value| > angle_comparisons_3d_filter_factor * (k + 1) * u * M,
# the bound computed left to right (factor and k + 1 small integers, u a power of two: one
# rounding, in the last product). k is at most 48 in the code, and the filter abstains above
# angle_comparisons_3d_filter_max_roundings = 64.
#
# Proves: for every k in 1..64, |prod_{i<=k} (1 + d_i) - 1| <= factor (k + 1) u prod_{j<=k+1}
# (1 + e_j): the value's k roundings against the magnitude's k and the bound's one. By the
# monomial argument of proofs/invariants/filters.md ("Relative filters") the computed bound then
# covers |computed - exact| (no underflow or overflow inside the window 2^-500..2^500, see the
# .cpp).
#
# Placeholder, filled in from predicates/filter_constants.hpp by
# proofs/check_relative_constants.cmake (CTest test proofs.angle_comparisons_3d_filter), which
# requires the factor to be a power of two that Gappa proves while factor / 2 fails.
#     @EPS@        angle_comparisons_3d_filter_factor
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-64. value_k: k roundings; bound_k: k roundings.
value1 = 1 + d1;
bound1 = 1 + e1;
value2 = value1 * (1 + d2);
bound2 = bound1 * (1 + e2);
value3 = value2 * (1 + d3);
bound3 = bound2 * (1 + e3);
value4 = value3 * (1 + d4);
bound4 = bound3 * (1 + e4);
value5 = value4 * (1 + d5);
bound5 = bound4 * (1 + e5);
value6 = value5 * (1 + d6);
bound6 = bound5 * (1 + e6);
value7 = value6 * (1 + d7);
bound7 = bound6 * (1 + e7);
value8 = value7 * (1 + d8);
bound8 = bound7 * (1 + e8);
value9 = value8 * (1 + d9);
bound9 = bound8 * (1 + e9);
value10 = value9 * (1 + d10);
bound10 = bound9 * (1 + e10);
value11 = value10 * (1 + d11);
bound11 = bound10 * (1 + e11);
value12 = value11 * (1 + d12);
bound12 = bound11 * (1 + e12);
value13 = value12 * (1 + d13);
bound13 = bound12 * (1 + e13);
value14 = value13 * (1 + d14);
bound14 = bound13 * (1 + e14);
value15 = value14 * (1 + d15);
bound15 = bound14 * (1 + e15);
value16 = value15 * (1 + d16);
bound16 = bound15 * (1 + e16);
value17 = value16 * (1 + d17);
bound17 = bound16 * (1 + e17);
value18 = value17 * (1 + d18);
bound18 = bound17 * (1 + e18);
value19 = value18 * (1 + d19);
bound19 = bound18 * (1 + e19);
value20 = value19 * (1 + d20);
bound20 = bound19 * (1 + e20);
value21 = value20 * (1 + d21);
bound21 = bound20 * (1 + e21);
value22 = value21 * (1 + d22);
bound22 = bound21 * (1 + e22);
value23 = value22 * (1 + d23);
bound23 = bound22 * (1 + e23);
value24 = value23 * (1 + d24);
bound24 = bound23 * (1 + e24);
value25 = value24 * (1 + d25);
bound25 = bound24 * (1 + e25);
value26 = value25 * (1 + d26);
bound26 = bound25 * (1 + e26);
value27 = value26 * (1 + d27);
bound27 = bound26 * (1 + e27);
value28 = value27 * (1 + d28);
bound28 = bound27 * (1 + e28);
value29 = value28 * (1 + d29);
bound29 = bound28 * (1 + e29);
value30 = value29 * (1 + d30);
bound30 = bound29 * (1 + e30);
value31 = value30 * (1 + d31);
bound31 = bound30 * (1 + e31);
value32 = value31 * (1 + d32);
bound32 = bound31 * (1 + e32);
value33 = value32 * (1 + d33);
bound33 = bound32 * (1 + e33);
value34 = value33 * (1 + d34);
bound34 = bound33 * (1 + e34);
value35 = value34 * (1 + d35);
bound35 = bound34 * (1 + e35);
value36 = value35 * (1 + d36);
bound36 = bound35 * (1 + e36);
value37 = value36 * (1 + d37);
bound37 = bound36 * (1 + e37);
value38 = value37 * (1 + d38);
bound38 = bound37 * (1 + e38);
value39 = value38 * (1 + d39);
bound39 = bound38 * (1 + e39);
value40 = value39 * (1 + d40);
bound40 = bound39 * (1 + e40);
value41 = value40 * (1 + d41);
bound41 = bound40 * (1 + e41);
value42 = value41 * (1 + d42);
bound42 = bound41 * (1 + e42);
value43 = value42 * (1 + d43);
bound43 = bound42 * (1 + e43);
value44 = value43 * (1 + d44);
bound44 = bound43 * (1 + e44);
value45 = value44 * (1 + d45);
bound45 = bound44 * (1 + e45);
value46 = value45 * (1 + d46);
bound46 = bound45 * (1 + e46);
value47 = value46 * (1 + d47);
bound47 = bound46 * (1 + e47);
value48 = value47 * (1 + d48);
bound48 = bound47 * (1 + e48);
value49 = value48 * (1 + d49);
bound49 = bound48 * (1 + e49);
value50 = value49 * (1 + d50);
bound50 = bound49 * (1 + e50);
value51 = value50 * (1 + d51);
bound51 = bound50 * (1 + e51);
value52 = value51 * (1 + d52);
bound52 = bound51 * (1 + e52);
value53 = value52 * (1 + d53);
bound53 = bound52 * (1 + e53);
value54 = value53 * (1 + d54);
bound54 = bound53 * (1 + e54);
value55 = value54 * (1 + d55);
bound55 = bound54 * (1 + e55);
value56 = value55 * (1 + d56);
bound56 = bound55 * (1 + e56);
value57 = value56 * (1 + d57);
bound57 = bound56 * (1 + e57);
value58 = value57 * (1 + d58);
bound58 = bound57 * (1 + e58);
value59 = value58 * (1 + d59);
bound59 = bound58 * (1 + e59);
value60 = value59 * (1 + d60);
bound60 = bound59 * (1 + e60);
value61 = value60 * (1 + d61);
bound61 = bound60 * (1 + e61);
value62 = value61 * (1 + d62);
bound62 = bound61 * (1 + e62);
value63 = value62 * (1 + d63);
bound63 = bound62 * (1 + e63);
value64 = value63 * (1 + d64);
bound64 = bound63 * (1 + e64);
bound65 = bound64 * (1 + e65);

{ |d1| <= 1b-64 /\ |d2| <= 1b-64 /\ |d3| <= 1b-64 /\ |d4| <= 1b-64 /\ |d5| <= 1b-64 /\
  |d6| <= 1b-64 /\ |d7| <= 1b-64 /\ |d8| <= 1b-64 /\ |d9| <= 1b-64 /\ |d10| <= 1b-64 /\
  |d11| <= 1b-64 /\ |d12| <= 1b-64 /\ |d13| <= 1b-64 /\ |d14| <= 1b-64 /\ |d15| <= 1b-64 /\
  |d16| <= 1b-64 /\ |d17| <= 1b-64 /\ |d18| <= 1b-64 /\ |d19| <= 1b-64 /\ |d20| <= 1b-64 /\
  |d21| <= 1b-64 /\ |d22| <= 1b-64 /\ |d23| <= 1b-64 /\ |d24| <= 1b-64 /\ |d25| <= 1b-64 /\
  |d26| <= 1b-64 /\ |d27| <= 1b-64 /\ |d28| <= 1b-64 /\ |d29| <= 1b-64 /\ |d30| <= 1b-64 /\
  |d31| <= 1b-64 /\ |d32| <= 1b-64 /\ |d33| <= 1b-64 /\ |d34| <= 1b-64 /\ |d35| <= 1b-64 /\
  |d36| <= 1b-64 /\ |d37| <= 1b-64 /\ |d38| <= 1b-64 /\ |d39| <= 1b-64 /\ |d40| <= 1b-64 /\
  |d41| <= 1b-64 /\ |d42| <= 1b-64 /\ |d43| <= 1b-64 /\ |d44| <= 1b-64 /\ |d45| <= 1b-64 /\
  |d46| <= 1b-64 /\ |d47| <= 1b-64 /\ |d48| <= 1b-64 /\ |d49| <= 1b-64 /\ |d50| <= 1b-64 /\
  |d51| <= 1b-64 /\ |d52| <= 1b-64 /\ |d53| <= 1b-64 /\ |d54| <= 1b-64 /\ |d55| <= 1b-64 /\
  |d56| <= 1b-64 /\ |d57| <= 1b-64 /\ |d58| <= 1b-64 /\ |d59| <= 1b-64 /\ |d60| <= 1b-64 /\
  |d61| <= 1b-64 /\ |d62| <= 1b-64 /\ |d63| <= 1b-64 /\ |d64| <= 1b-64 /\ |e1| <= 1b-64 /\
  |e2| <= 1b-64 /\ |e3| <= 1b-64 /\ |e4| <= 1b-64 /\ |e5| <= 1b-64 /\ |e6| <= 1b-64 /\
  |e7| <= 1b-64 /\ |e8| <= 1b-64 /\ |e9| <= 1b-64 /\ |e10| <= 1b-64 /\ |e11| <= 1b-64 /\
  |e12| <= 1b-64 /\ |e13| <= 1b-64 /\ |e14| <= 1b-64 /\ |e15| <= 1b-64 /\ |e16| <= 1b-64 /\
  |e17| <= 1b-64 /\ |e18| <= 1b-64 /\ |e19| <= 1b-64 /\ |e20| <= 1b-64 /\ |e21| <= 1b-64 /\
  |e22| <= 1b-64 /\ |e23| <= 1b-64 /\ |e24| <= 1b-64 /\ |e25| <= 1b-64 /\ |e26| <= 1b-64 /\
  |e27| <= 1b-64 /\ |e28| <= 1b-64 /\ |e29| <= 1b-64 /\ |e30| <= 1b-64 /\ |e31| <= 1b-64 /\
  |e32| <= 1b-64 /\ |e33| <= 1b-64 /\ |e34| <= 1b-64 /\ |e35| <= 1b-64 /\ |e36| <= 1b-64 /\
  |e37| <= 1b-64 /\ |e38| <= 1b-64 /\ |e39| <= 1b-64 /\ |e40| <= 1b-64 /\ |e41| <= 1b-64 /\
  |e42| <= 1b-64 /\ |e43| <= 1b-64 /\ |e44| <= 1b-64 /\ |e45| <= 1b-64 /\ |e46| <= 1b-64 /\
  |e47| <= 1b-64 /\ |e48| <= 1b-64 /\ |e49| <= 1b-64 /\ |e50| <= 1b-64 /\ |e51| <= 1b-64 /\
  |e52| <= 1b-64 /\ |e53| <= 1b-64 /\ |e54| <= 1b-64 /\ |e55| <= 1b-64 /\ |e56| <= 1b-64 /\
  |e57| <= 1b-64 /\ |e58| <= 1b-64 /\ |e59| <= 1b-64 /\ |e60| <= 1b-64 /\ |e61| <= 1b-64 /\
  |e62| <= 1b-64 /\ |e63| <= 1b-64 /\ |e64| <= 1b-64 /\ |e65| <= 1b-64
  ->
     value1 - 1 - @EPS@ * 2 * 1b-64 * bound2 <= 0 /\ 1 - value1 - @EPS@ * 2 * 1b-64 * bound2 <= 0 /\
     value2 - 1 - @EPS@ * 3 * 1b-64 * bound3 <= 0 /\ 1 - value2 - @EPS@ * 3 * 1b-64 * bound3 <= 0 /\
     value3 - 1 - @EPS@ * 4 * 1b-64 * bound4 <= 0 /\ 1 - value3 - @EPS@ * 4 * 1b-64 * bound4 <= 0 /\
     value4 - 1 - @EPS@ * 5 * 1b-64 * bound5 <= 0 /\ 1 - value4 - @EPS@ * 5 * 1b-64 * bound5 <= 0 /\
     value5 - 1 - @EPS@ * 6 * 1b-64 * bound6 <= 0 /\ 1 - value5 - @EPS@ * 6 * 1b-64 * bound6 <= 0 /\
     value6 - 1 - @EPS@ * 7 * 1b-64 * bound7 <= 0 /\ 1 - value6 - @EPS@ * 7 * 1b-64 * bound7 <= 0 /\
     value7 - 1 - @EPS@ * 8 * 1b-64 * bound8 <= 0 /\ 1 - value7 - @EPS@ * 8 * 1b-64 * bound8 <= 0 /\
     value8 - 1 - @EPS@ * 9 * 1b-64 * bound9 <= 0 /\ 1 - value8 - @EPS@ * 9 * 1b-64 * bound9 <= 0 /\
     value9 - 1 - @EPS@ * 10 * 1b-64 * bound10 <= 0 /\ 1 - value9 - @EPS@ * 10 * 1b-64 * bound10 <= 0 /\
     value10 - 1 - @EPS@ * 11 * 1b-64 * bound11 <= 0 /\ 1 - value10 - @EPS@ * 11 * 1b-64 * bound11 <= 0 /\
     value11 - 1 - @EPS@ * 12 * 1b-64 * bound12 <= 0 /\ 1 - value11 - @EPS@ * 12 * 1b-64 * bound12 <= 0 /\
     value12 - 1 - @EPS@ * 13 * 1b-64 * bound13 <= 0 /\ 1 - value12 - @EPS@ * 13 * 1b-64 * bound13 <= 0 /\
     value13 - 1 - @EPS@ * 14 * 1b-64 * bound14 <= 0 /\ 1 - value13 - @EPS@ * 14 * 1b-64 * bound14 <= 0 /\
     value14 - 1 - @EPS@ * 15 * 1b-64 * bound15 <= 0 /\ 1 - value14 - @EPS@ * 15 * 1b-64 * bound15 <= 0 /\
     value15 - 1 - @EPS@ * 16 * 1b-64 * bound16 <= 0 /\ 1 - value15 - @EPS@ * 16 * 1b-64 * bound16 <= 0 /\
     value16 - 1 - @EPS@ * 17 * 1b-64 * bound17 <= 0 /\ 1 - value16 - @EPS@ * 17 * 1b-64 * bound17 <= 0 /\
     value17 - 1 - @EPS@ * 18 * 1b-64 * bound18 <= 0 /\ 1 - value17 - @EPS@ * 18 * 1b-64 * bound18 <= 0 /\
     value18 - 1 - @EPS@ * 19 * 1b-64 * bound19 <= 0 /\ 1 - value18 - @EPS@ * 19 * 1b-64 * bound19 <= 0 /\
     value19 - 1 - @EPS@ * 20 * 1b-64 * bound20 <= 0 /\ 1 - value19 - @EPS@ * 20 * 1b-64 * bound20 <= 0 /\
     value20 - 1 - @EPS@ * 21 * 1b-64 * bound21 <= 0 /\ 1 - value20 - @EPS@ * 21 * 1b-64 * bound21 <= 0 /\
     value21 - 1 - @EPS@ * 22 * 1b-64 * bound22 <= 0 /\ 1 - value21 - @EPS@ * 22 * 1b-64 * bound22 <= 0 /\
     value22 - 1 - @EPS@ * 23 * 1b-64 * bound23 <= 0 /\ 1 - value22 - @EPS@ * 23 * 1b-64 * bound23 <= 0 /\
     value23 - 1 - @EPS@ * 24 * 1b-64 * bound24 <= 0 /\ 1 - value23 - @EPS@ * 24 * 1b-64 * bound24 <= 0 /\
     value24 - 1 - @EPS@ * 25 * 1b-64 * bound25 <= 0 /\ 1 - value24 - @EPS@ * 25 * 1b-64 * bound25 <= 0 /\
     value25 - 1 - @EPS@ * 26 * 1b-64 * bound26 <= 0 /\ 1 - value25 - @EPS@ * 26 * 1b-64 * bound26 <= 0 /\
     value26 - 1 - @EPS@ * 27 * 1b-64 * bound27 <= 0 /\ 1 - value26 - @EPS@ * 27 * 1b-64 * bound27 <= 0 /\
     value27 - 1 - @EPS@ * 28 * 1b-64 * bound28 <= 0 /\ 1 - value27 - @EPS@ * 28 * 1b-64 * bound28 <= 0 /\
     value28 - 1 - @EPS@ * 29 * 1b-64 * bound29 <= 0 /\ 1 - value28 - @EPS@ * 29 * 1b-64 * bound29 <= 0 /\
     value29 - 1 - @EPS@ * 30 * 1b-64 * bound30 <= 0 /\ 1 - value29 - @EPS@ * 30 * 1b-64 * bound30 <= 0 /\
     value30 - 1 - @EPS@ * 31 * 1b-64 * bound31 <= 0 /\ 1 - value30 - @EPS@ * 31 * 1b-64 * bound31 <= 0 /\
     value31 - 1 - @EPS@ * 32 * 1b-64 * bound32 <= 0 /\ 1 - value31 - @EPS@ * 32 * 1b-64 * bound32 <= 0 /\
     value32 - 1 - @EPS@ * 33 * 1b-64 * bound33 <= 0 /\ 1 - value32 - @EPS@ * 33 * 1b-64 * bound33 <= 0 /\
     value33 - 1 - @EPS@ * 34 * 1b-64 * bound34 <= 0 /\ 1 - value33 - @EPS@ * 34 * 1b-64 * bound34 <= 0 /\
     value34 - 1 - @EPS@ * 35 * 1b-64 * bound35 <= 0 /\ 1 - value34 - @EPS@ * 35 * 1b-64 * bound35 <= 0 /\
     value35 - 1 - @EPS@ * 36 * 1b-64 * bound36 <= 0 /\ 1 - value35 - @EPS@ * 36 * 1b-64 * bound36 <= 0 /\
     value36 - 1 - @EPS@ * 37 * 1b-64 * bound37 <= 0 /\ 1 - value36 - @EPS@ * 37 * 1b-64 * bound37 <= 0 /\
     value37 - 1 - @EPS@ * 38 * 1b-64 * bound38 <= 0 /\ 1 - value37 - @EPS@ * 38 * 1b-64 * bound38 <= 0 /\
     value38 - 1 - @EPS@ * 39 * 1b-64 * bound39 <= 0 /\ 1 - value38 - @EPS@ * 39 * 1b-64 * bound39 <= 0 /\
     value39 - 1 - @EPS@ * 40 * 1b-64 * bound40 <= 0 /\ 1 - value39 - @EPS@ * 40 * 1b-64 * bound40 <= 0 /\
     value40 - 1 - @EPS@ * 41 * 1b-64 * bound41 <= 0 /\ 1 - value40 - @EPS@ * 41 * 1b-64 * bound41 <= 0 /\
     value41 - 1 - @EPS@ * 42 * 1b-64 * bound42 <= 0 /\ 1 - value41 - @EPS@ * 42 * 1b-64 * bound42 <= 0 /\
     value42 - 1 - @EPS@ * 43 * 1b-64 * bound43 <= 0 /\ 1 - value42 - @EPS@ * 43 * 1b-64 * bound43 <= 0 /\
     value43 - 1 - @EPS@ * 44 * 1b-64 * bound44 <= 0 /\ 1 - value43 - @EPS@ * 44 * 1b-64 * bound44 <= 0 /\
     value44 - 1 - @EPS@ * 45 * 1b-64 * bound45 <= 0 /\ 1 - value44 - @EPS@ * 45 * 1b-64 * bound45 <= 0 /\
     value45 - 1 - @EPS@ * 46 * 1b-64 * bound46 <= 0 /\ 1 - value45 - @EPS@ * 46 * 1b-64 * bound46 <= 0 /\
     value46 - 1 - @EPS@ * 47 * 1b-64 * bound47 <= 0 /\ 1 - value46 - @EPS@ * 47 * 1b-64 * bound47 <= 0 /\
     value47 - 1 - @EPS@ * 48 * 1b-64 * bound48 <= 0 /\ 1 - value47 - @EPS@ * 48 * 1b-64 * bound48 <= 0 /\
     value48 - 1 - @EPS@ * 49 * 1b-64 * bound49 <= 0 /\ 1 - value48 - @EPS@ * 49 * 1b-64 * bound49 <= 0 /\
     value49 - 1 - @EPS@ * 50 * 1b-64 * bound50 <= 0 /\ 1 - value49 - @EPS@ * 50 * 1b-64 * bound50 <= 0 /\
     value50 - 1 - @EPS@ * 51 * 1b-64 * bound51 <= 0 /\ 1 - value50 - @EPS@ * 51 * 1b-64 * bound51 <= 0 /\
     value51 - 1 - @EPS@ * 52 * 1b-64 * bound52 <= 0 /\ 1 - value51 - @EPS@ * 52 * 1b-64 * bound52 <= 0 /\
     value52 - 1 - @EPS@ * 53 * 1b-64 * bound53 <= 0 /\ 1 - value52 - @EPS@ * 53 * 1b-64 * bound53 <= 0 /\
     value53 - 1 - @EPS@ * 54 * 1b-64 * bound54 <= 0 /\ 1 - value53 - @EPS@ * 54 * 1b-64 * bound54 <= 0 /\
     value54 - 1 - @EPS@ * 55 * 1b-64 * bound55 <= 0 /\ 1 - value54 - @EPS@ * 55 * 1b-64 * bound55 <= 0 /\
     value55 - 1 - @EPS@ * 56 * 1b-64 * bound56 <= 0 /\ 1 - value55 - @EPS@ * 56 * 1b-64 * bound56 <= 0 /\
     value56 - 1 - @EPS@ * 57 * 1b-64 * bound57 <= 0 /\ 1 - value56 - @EPS@ * 57 * 1b-64 * bound57 <= 0 /\
     value57 - 1 - @EPS@ * 58 * 1b-64 * bound58 <= 0 /\ 1 - value57 - @EPS@ * 58 * 1b-64 * bound58 <= 0 /\
     value58 - 1 - @EPS@ * 59 * 1b-64 * bound59 <= 0 /\ 1 - value58 - @EPS@ * 59 * 1b-64 * bound59 <= 0 /\
     value59 - 1 - @EPS@ * 60 * 1b-64 * bound60 <= 0 /\ 1 - value59 - @EPS@ * 60 * 1b-64 * bound60 <= 0 /\
     value60 - 1 - @EPS@ * 61 * 1b-64 * bound61 <= 0 /\ 1 - value60 - @EPS@ * 61 * 1b-64 * bound61 <= 0 /\
     value61 - 1 - @EPS@ * 62 * 1b-64 * bound62 <= 0 /\ 1 - value61 - @EPS@ * 62 * 1b-64 * bound62 <= 0 /\
     value62 - 1 - @EPS@ * 63 * 1b-64 * bound63 <= 0 /\ 1 - value62 - @EPS@ * 63 * 1b-64 * bound63 <= 0 /\
     value63 - 1 - @EPS@ * 64 * 1b-64 * bound64 <= 0 /\ 1 - value63 - @EPS@ * 64 * 1b-64 * bound64 <= 0 /\
     value64 - 1 - @EPS@ * 65 * 1b-64 * bound65 <= 0 /\ 1 - value64 - @EPS@ * 65 * 1b-64 * bound65 <= 0 }
