// SPDX-License-Identifier: MIT
// Issue 11 family, found by the CI's libFuzzer runs on 2026-12-03 (after the issue was closed):
//  1. fuzz_constrained_2d: segment (3, 4) runs from (-2^1009, 1) to (2^-432, 63 * 2^-1074), so
//     it passes 3.1e-322 above the input vertices (2^-975, 0) and (2.07e-317, 0) of segment 0 - 4,
//     which lies on y = 0. The conforming recovery bent the first segment's chain along y = 0
//     (allowed far from the origin, where the rounding allowance 2^-40 |w| is large) and then
//     through vertex 4 at (2.07e-317, 0), which lay exactly on the piece but 63 ulps off its
//     segment, beyond its allowance of one ulp: the check found the chain broken. A vertex
//     exactly on a piece now bends it only under the chain rule; otherwise, and wherever the
//     cheap midpoint of the piece's rounded ends falls outside rounding of the segment, the split
//     point is taken on the input segment's line, rounded once (predicates::point_on_line_at).
//  2. fuzz_delaunay_2d: the brute-force oracle's static filter trusted a permanent inside
//     [2^-600, 2^1000], but a product of two subnormal-sized differences underflows by up to
//     2^-1074 and a lift of 2^748 multiplies that error past the bound: the oracle called a point
//     inside a circumcircle that the exact value (-6.9e-111) puts outside. The filter now answers
//     only when every nonzero difference lies in [2^-250, 2^250].
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/constructions.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/incircle.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_naive.hpp"

namespace {

namespace pr = exactmesh::predicates;
namespace tri = exactmesh::triangulation;

// fuzz_constrained_2d crash-5ddbe843 (CI, 2026-12-03).
const std::vector<double> kGapPoints = {0x1p-975,
                                        0.0,
                                        0.0,
                                        1.0,
                                        -0x1p+1009,
                                        0x1.0000000f2fbffp+0,
                                        0x1.00000002e19p-432,
                                        0x0.000000000003fp-1022,
                                        0x0.00000003ffp-1022,
                                        0.0,
                                        0x0.00000000031p-1022,
                                        0x0.0000000003ffp-1022};
const std::vector<tri::VertIdx> kGapSegments = {0, 4, 2, 3};

// fuzz_delaunay_2d crash-c5c4ad18 (local CI run, 2026-12-03).
const std::vector<double> kOraclePoints = {0.0,
                                           -0x1.0306p-783,
                                           0x0.000000000b8fp-1022,
                                           1.0,
                                           0x1.7p+374,
                                           0x0.0000057575757p-1022,
                                           0x0.00000003ffp-1022,
                                           0.0,
                                           0.0,
                                           0x0.000000000f03fp-1022,
                                           0.0,
                                           -0x1p-63};

tri::Cdt2Result conforming_cdt(const std::vector<double>& xy) {
    tri::Cdt2Options options;
    options.recovery = tri::SegmentRecovery::Conforming;
    options.remove_exterior = false;
    return tri::constrained_delaunay_2d(tri::Pslg{xy, kGapSegments, {}, {}}, options);
}

}  // namespace

TEST(Issue11SubnormalGap, issue_11_conforming_chain_keeps_off_a_vertex_outside_rounding) {
    // (No power of two scales this input exactly: it spans 2^-1074 to 2^1009.)
    const tri::Cdt2Result cdt = conforming_cdt(kGapPoints);
    const auto report =
        tri::check_constrained_delaunay_2d(cdt.mesh, cdt.input_vertex_count, kGapSegments, {});
    EXPECT_TRUE(report.ok) << report.problem;
    const auto delaunay = tri::check_delaunay_2d(cdt.mesh.xy, cdt.mesh.triangles);
    EXPECT_TRUE(delaunay.ok) << delaunay.problem;
    EXPECT_GT(cdt.counters.conforming_splits, 1000U);  // pieces down to the 3e-322 gap
}

TEST(Issue11SubnormalGap, issue_11_swap_and_cavity_agree_on_the_gap) {
    for (const auto recovery : {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity}) {
        tri::Cdt2Options options;
        options.recovery = recovery;
        options.remove_exterior = false;
        const tri::Cdt2Result cdt =
            tri::constrained_delaunay_2d(tri::Pslg{kGapPoints, kGapSegments, {}, {}}, options);
        const auto report =
            tri::check_constrained_delaunay_2d(cdt.mesh, cdt.input_vertex_count, kGapSegments, {});
        EXPECT_TRUE(report.ok) << report.problem;
    }
}

TEST(Issue11SubnormalGap, issue_11_point_on_line_at_is_rounded_once) {
    // The line of segment (3, 4) above: at x = 0 its exact y is 63 * 2^-1074 plus about 1.6e-434,
    // which rounds to 63 * 2^-1074; at x = -2^1008 (half way but for 2^-1441) y rounds to half
    // of the far end's.
    const double s0[2] = {-0x1p+1009, 0x1.0000000f2fbffp+0};
    const double s1[2] = {0x1.00000002e19p-432, 0x0.000000000003fp-1022};
    const auto origin = pr::point_on_line_at(s0, s1, 0, 0.0);
    EXPECT_EQ(origin[0], 0.0);
    EXPECT_EQ(origin[1], 0x0.000000000003fp-1022);
    const auto half = pr::point_on_line_at(s0, s1, 0, -0x1p+1008);
    EXPECT_EQ(half[0], -0x1p+1008);
    EXPECT_EQ(half[1], 0x1.0000000f2fbffp-1);
    // Along y for a steep line, and the refusals.
    const double v0[2] = {1.0, -1.0}, v1[2] = {3.0, 1.0};
    const auto steep = pr::point_on_line_at(v0, v1, 1, 0.5);
    EXPECT_EQ(steep[0], 2.5);
    EXPECT_EQ(steep[1], 0.5);
    const double flat0[2] = {0.0, 1.0}, flat1[2] = {1.0, 1.0};
    EXPECT_THROW(pr::point_on_line_at(flat0, flat1, 1, 2.0), exactmesh::GeometryError);
    EXPECT_THROW(pr::point_on_line_at(flat0, flat1, 0, NAN), exactmesh::GeometryError);
}

TEST(Issue11SubnormalGap, issue_11_naive_oracle_filter_leaves_underflow_to_gmp) {
    const auto n = static_cast<std::uint32_t>(kOraclePoints.size() / 2);
    const std::span<const double> xy(kOraclePoints);
    // Every incircle of the oracle agrees with the GMP reference, the triangle (2, 3, 5) with
    // point 0 (exactly -6.9e-111 after orientation: outside) included.
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = 0; b < n; ++b) {
            for (std::uint32_t c = 0; c < n; ++c) {
                for (std::uint32_t d = 0; d < n; ++d) {
                    const double *pa = &xy[2 * a], *pb = &xy[2 * b], *pc = &xy[2 * c],
                                 *pd = &xy[2 * d];
                    EXPECT_EQ(tri::naive_detail::incircle(xy, a, b, c, d),
                              pr::reference::incircle_differences(pa, pb, pc, pd))
                        << a << b << c << d;
                }
                EXPECT_EQ(tri::naive_detail::orient(xy, a, b, c),
                          pr::reference::orient2d_differences(&xy[2 * a], &xy[2 * b], &xy[2 * c]));
            }
        }
    }
    EXPECT_EQ(tri::naive_detail::incircle(xy, 2, 3, 5, 0), pr::Sign::Negative);
    // And Bowyer-Watson's triangulation (given order, as found) passes the oracle.
    tri::Delaunay2Options options;
    options.order = tri::InsertionOrder::Given;
    const auto bw = tri::delaunay_2d_algorithm("bowyer-watson")(xy, options);
    const auto oracle = tri::delaunay_2d_naive(xy);
    EXPECT_EQ(tri::compare_with_delaunay_2d_naive(xy, bw.triangles, oracle, bw.merged_into), "");
}
