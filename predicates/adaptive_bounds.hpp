// SPDX-License-Identifier: MIT
// Error bounds of the adaptive stages B and C [Shewchuk97 §4.2-4.5, Lemmas 3-5 and the
// bounds of predicates.c's *adapt routines], eps = 2^-53. Stage B: the determinant of the
// rounded differences is exact, so only the rounding of the differences is bounded. Stage C:
// first-order tail terms are added in floating point. Valid without underflow: the
// expansion-safe range check before these stages keeps every value of the determinants and of
// the permanents a multiple of 2^-1074 (exact below 2^-1022, relatively rounded above), but
// the bound itself, a constant near 2^-50 or 2^-100 times a permanent, can fall below 2^-1022,
// where its rounding is no longer relative: certified() then refuses it
// (proofs/invariants/filters.md).
// B and C are Shewchuk's and not re-proved here; the two-term constants are checked by Gappa
// (proofs/gappa/two_term_*.g, CTest proofs.two_term_*).
#pragma once

namespace exactmesh::predicates::adaptive {

inline constexpr double kEpsilon = 0x1p-53;
inline constexpr double result_errbound = (3.0 + 8.0 * kEpsilon) * kEpsilon;
inline constexpr double ccw_errbound_b = (2.0 + 12.0 * kEpsilon) * kEpsilon;
inline constexpr double ccw_errbound_c = (9.0 + 64.0 * kEpsilon) * kEpsilon * kEpsilon;
inline constexpr double o3d_errbound_b = (3.0 + 28.0 * kEpsilon) * kEpsilon;
inline constexpr double o3d_errbound_c = (26.0 + 288.0 * kEpsilon) * kEpsilon * kEpsilon;
inline constexpr double icc_errbound_b = (4.0 + 48.0 * kEpsilon) * kEpsilon;
inline constexpr double icc_errbound_c = (44.0 + 576.0 * kEpsilon) * kEpsilon * kEpsilon;
inline constexpr double isp_errbound_b = (5.0 + 72.0 * kEpsilon) * kEpsilon;
inline constexpr double isp_errbound_c = (71.0 + 1408.0 * kEpsilon) * kEpsilon * kEpsilon;

// The two-term evaluation of stage B (predicates/two_term.hpp): |hi + lo - B| is at most
// 42.05 u^2 (incircle) and 100.18 u^2 (insphere) times the permanent, u = kEpsilon
// (proofs/gappa/two_term_incircle.g, two_term_insphere.g); the constants below are more than
// 12/5 times that after the rounding of the permanent and of fl(hi + lo), as the stages using
// them need (proofs/invariants/filters.md, "Two-term stage"). Written K * kEpsilon * kEpsilon:
// proofs/check_two_term_constants.cmake reads K.
inline constexpr double icc_errbound_two_term = 128.0 * kEpsilon * kEpsilon;
inline constexpr double isp_errbound_two_term = 512.0 * kEpsilon * kEpsilon;

// in_ellipse's two-term stage (predicates/two_term.hpp, in_ellipse_two_term) evaluates the
// determinant of the exact differences: |hi + lo - Det| is at most 138.32 u^2 times the
// permanent in the exact differences (proofs/gappa/two_term_in_ellipse.g); the constant is more
// than 2 times that after the rounding of the differences and of the permanent computed from
// them, and of fl(hi + lo) (proofs/invariants/filters.md, "Two-term stage of in_ellipse").
inline constexpr double in_ellipse_errbound_two_term = 512.0 * kEpsilon * kEpsilon;

/// True when |det| certainly exceeds the error bound (the sign of det is then exact). A bound
/// below the normal range (2^-1022) certifies nothing: its own rounding may have lowered it by
/// more than the relative margin the proofs give it (integer points scaled by 2^-250 are
/// expansion-safe, and their permanents of degree 4 make such bounds); the exact stages decide.
inline bool certified(double det, double errbound) {
    return errbound >= 0x1p-1022 && (det >= errbound || -det >= errbound);
}

}  // namespace exactmesh::predicates::adaptive
