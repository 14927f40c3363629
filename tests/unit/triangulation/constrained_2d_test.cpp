// SPDX-License-Identifier: MIT
// Constrained and conforming Delaunay: exact validity of every output, swap and cavity recovery
// give the same triangles, crossings and vertices on segments are split, holes, exterior and
// regions, degenerate and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;

namespace {

using Triangles = exactmesh::testing::CanonicalTriangles;
using exactmesh::testing::canonical_triangles;

using exactmesh::testing::Input;

tri::Cdt2Result build(const Input& in, tri::SegmentRecovery recovery,
                      bool remove_exterior = false) {
    tri::Cdt2Options options;
    options.recovery = recovery;
    options.remove_exterior = remove_exterior;
    return tri::constrained_delaunay_2d(in.pslg(), options);
}

/// Exact checks of one output: constrained Delaunay (or plain Delaunay when conforming), every
/// segment present, and with the exterior kept, the convex-hull topology.
void expect_valid(const Input& in, const tri::Cdt2Result& r, tri::SegmentRecovery recovery,
                  bool hull, const std::string& label) {
    const auto report = tri::check_constrained_delaunay_2d(
        r.mesh, r.input_vertex_count, in.segments,
        hull ? std::span<const tri::VertIdx>{} : std::span(r.pieces));
    EXPECT_TRUE(report.ok) << label << ": " << report.problem;
    if (hull) {
        const auto topology = tri::check_topology_2d(r.mesh.xy, r.mesh.triangles);
        EXPECT_TRUE(topology.ok) << label << ": " << topology.problem;
    }
    if (recovery == tri::SegmentRecovery::Conforming && hull) {
        const auto delaunay = tri::check_delaunay_2d(r.mesh.xy, r.mesh.triangles);
        EXPECT_TRUE(delaunay.ok) << label << " (conforming is Delaunay): " << delaunay.problem;
    }
    ASSERT_EQ(r.pieces.size(), 2 * r.piece_segment.size());
    // Every piece is an edge of the output flagged constrained (or lies in a removed region).
    std::set<std::pair<tri::VertIdx, tri::VertIdx>> flagged, edges;
    for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const tri::VertIdx a = r.mesh.triangles[3 * t + k],
                               b = r.mesh.triangles[3 * t + (k + 1) % 3];
            edges.insert({std::min(a, b), std::max(a, b)});
            if (r.mesh.is_constrained(static_cast<tri::TriIdx>(t), k))
                flagged.insert({std::min(a, b), std::max(a, b)});
        }
    }
    for (std::size_t p = 0; p < r.piece_segment.size(); ++p) {
        const std::pair<tri::VertIdx, tri::VertIdx> e{r.pieces[2 * p], r.pieces[2 * p + 1]};
        if (edges.count(e)) {
            EXPECT_TRUE(flagged.count(e)) << label << ": piece not flagged";
        }
        if (hull) {
            EXPECT_TRUE(flagged.count(e))
                << label << ": piece " << e.first << "-" << e.second << " missing";
        }
    }
    if (hull) {
        EXPECT_EQ(flagged.size(), r.piece_segment.size()) << label;
    }
}

/// Random points and random segments among them, crossing ones dropped greedily (exactly).
Input random_non_crossing(std::uint32_t n, std::uint32_t tries, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Input in;
    for (std::uint32_t i = 0; i < 2 * n; ++i) in.xy.push_back(u(rng));
    auto p = [&](tri::VertIdx v) { return in.xy.data() + 2 * v; };
    auto crosses = [&](tri::VertIdx a, tri::VertIdx b, tri::VertIdx c, tri::VertIdx d) {
        if (a == c || a == d || b == c || b == d) return false;
        const auto s1 = em::predicates::orient2d(p(a), p(b), p(c)),
                   s2 = em::predicates::orient2d(p(a), p(b), p(d));
        const auto s3 = em::predicates::orient2d(p(c), p(d), p(a)),
                   s4 = em::predicates::orient2d(p(c), p(d), p(b));
        return s1 != s2 && s3 != s4;
    };
    std::uniform_int_distribution<tri::VertIdx> pick(0, n - 1);
    for (std::uint32_t k = 0; k < tries; ++k) {
        const tri::VertIdx a = pick(rng), b = pick(rng);
        if (a == b) continue;
        bool ok = true;
        for (std::size_t s = 0; ok && s < in.segments.size(); s += 2) {
            ok = !crosses(a, b, in.segments[s], in.segments[s + 1]);
        }
        if (ok) in.segments.insert(in.segments.end(), {a, b});
    }
    return in;
}

constexpr tri::SegmentRecovery kRecoveries[] = {
    tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity, tri::SegmentRecovery::Conforming};

}  // namespace

TEST(Constrained2d, ForcedNonDelaunayDiagonal) {
    // A flat rhombus: Delaunay joins the two near points (1,-0.2)-(1,0.2); the segment joins
    // the far ones.
    Input in{{0, 0, 1, -0.2, 2, 0, 1, 0.2}, {0, 2}, {}, {}};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        if (recovery != tri::SegmentRecovery::Conforming) {
            EXPECT_EQ(canonical_triangles(r.mesh.triangles), (Triangles{{0, 1, 2}, {0, 2, 3}}));
        } else {
            EXPECT_GT(r.counters.conforming_splits, 0u);
        }
    }
}

TEST(Constrained2d, SwapAndCavityAgreeOnRandomPslgs) {
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        const Input in =
            random_non_crossing(60 + 10 * static_cast<std::uint32_t>(seed % 5), 80, seed);
        const auto swap = build(in, tri::SegmentRecovery::Swap);
        const auto cavity = build(in, tri::SegmentRecovery::Cavity);
        const auto conforming = build(in, tri::SegmentRecovery::Conforming);
        const std::string label = "seed " + std::to_string(seed);
        expect_valid(in, swap, tri::SegmentRecovery::Swap, true, label + " swap");
        expect_valid(in, cavity, tri::SegmentRecovery::Cavity, true, label + " cavity");
        expect_valid(in, conforming, tri::SegmentRecovery::Conforming, true, label + " conforming");
        EXPECT_EQ(canonical_triangles(swap.mesh.triangles),
                  canonical_triangles(cavity.mesh.triangles))
            << label;
        EXPECT_EQ(swap.counters.intersections, 0u);
    }
}

TEST(Constrained2d, CocircularGridWithSegmentsIsUnique) {
    // An integer grid is massively cocircular: the perturbation must still make swap and
    // cavity recovery agree triangle for triangle, in every insertion order.
    Input in;
    const int side = 9;
    for (int y = 0; y < side; ++y) {
        for (int x = 0; x < side; ++x) in.xy.insert(in.xy.end(), {double(x), double(y)});
    }
    auto id = [&](int x, int y) { return static_cast<tri::VertIdx>(y * side + x); };
    in.segments = {id(0, 0), id(8, 3), id(1, 7), id(7, 8), id(2, 2),
                   id(5, 6), id(0, 8), id(3, 1), id(6, 0), id(8, 8)};
    Triangles reference;
    for (const auto order :
         {tri::InsertionOrder::Given, tri::InsertionOrder::Random, tri::InsertionOrder::Brio}) {
        for (const auto recovery : {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity}) {
            tri::Cdt2Options options;
            options.recovery = recovery;
            options.order = order;
            options.remove_exterior = false;
            const auto r = tri::constrained_delaunay_2d(in.pslg(), options);
            expect_valid(in, r, recovery, true, "grid");
            if (reference.empty()) reference = canonical_triangles(r.mesh.triangles);
            EXPECT_EQ(canonical_triangles(r.mesh.triangles), reference);
        }
    }
}

TEST(Constrained2d, CrossingSegmentsAreSplitAtTheRoundedIntersection) {
    // Two crossing diagonals of a square, and a third segment crossing both.
    Input in{{0, 0, 1, 0, 1, 1, 0, 1, 0, 0.3, 1, 0.6}, {0, 2, 1, 3, 4, 5}, {}, {}};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        EXPECT_EQ(r.counters.intersections, 3u) << tri::segment_recovery_name(recovery);
        EXPECT_EQ(r.input_vertex_count, 6u);
        EXPECT_GE(r.mesh.vertex_count(), 9u);
        EXPECT_FALSE(r.warnings.empty());
    }
    // The centre of the square is exact: both diagonals pass through the added vertex (0.5, 0.5).
    const auto r =
        build(Input{{0, 0, 1, 0, 1, 1, 0, 1}, {0, 2, 1, 3}, {}, {}}, tri::SegmentRecovery::Swap);
    ASSERT_EQ(r.mesh.vertex_count(), 5u);
    EXPECT_EQ(r.mesh.point(4)[0], 0.5);
    EXPECT_EQ(r.mesh.point(4)[1], 0.5);
    EXPECT_EQ(r.pieces.size(), 8u);
    EXPECT_EQ(r.mesh.triangle_count(), 4u);
}

TEST(Constrained2d, ManyCrossingSegments) {
    // 30 random long segments: hundreds of crossings, all split, every output valid.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Input in;
    for (int i = 0; i < 60; ++i) in.xy.insert(in.xy.end(), {u(rng), u(rng)});
    for (tri::VertIdx i = 0; i < 60; i += 2) in.segments.insert(in.segments.end(), {i, i + 1});
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        EXPECT_GT(r.counters.intersections, 50u);
    }
}

TEST(Constrained2d, SegmentThroughVerticesIsSplit) {
    // Collinear vertices on the segment, and overlapping collinear segments.
    Input in{{0, 0, 4, 0, 1, 0, 2, 0, 3, 0, 2, 1, 2, -1}, {0, 1, 2, 4, 5, 6}, {}, {}};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        EXPECT_GE(r.counters.vertices_on_segments, 2u);
        EXPECT_EQ(r.counters.intersections, 0u);
    }
}

TEST(Constrained2d, ZeroLengthAndRepeatedSegmentsAreDroppedWithWarnings) {
    Input in{{0, 0, 1, 0, 1, 1, 0, 1, 1, 1}, {0, 0, 0, 2, 2, 0, 2, 4, 1, 3}, {}, {}};
    const auto r = build(in, tri::SegmentRecovery::Swap);
    EXPECT_EQ(r.counters.dropped_segments, 3u);  // 0-0, 2-0 repeats 0-2, 2-4 are equal points
    EXPECT_EQ(r.counters.duplicates, 1u);
    EXPECT_GE(r.warnings.size(), 3u);
    expect_valid(in, r, tri::SegmentRecovery::Swap, true, "dropped");
    EXPECT_EQ(r.merged_into[4], 2u);
}

TEST(Constrained2d, BadInputIsRejectedWithAClearError) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    Input dangling{{0, 0, 1, 0, 0, 1}, {0, 3}, {}, {}};
    try {
        build(dangling, tri::SegmentRecovery::Swap);
        FAIL() << "dangling index accepted";
    } catch (const em::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("segment 0: vertex 3 does not exist"),
                  std::string::npos)
            << e.what();
    }
    Input not_finite{{0, 0, 1, nan, 0, 1}, {0, 1}, {}, {}};
    EXPECT_THROW(build(not_finite, tri::SegmentRecovery::Swap), em::NonFiniteCoordinate);
    Input hole{{0, 0, 1, 0, 0, 1}, {0, 1}, {inf, 0}, {}};
    try {
        build(hole, tri::SegmentRecovery::Swap);
        FAIL() << "infinite hole accepted";
    } catch (const em::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("hole 0"), std::string::npos) << e.what();
    }
    EXPECT_THROW(tri::segment_recovery_from_name("magic"), em::InputError);
}

TEST(Constrained2d, HolesAndExteriorAreRemoved) {
    // Square [0,4]^2 with a square hole [1,3]^2 and a notch making the outside non-convex.
    Input in;
    in.xy = {0, 0, 4, 0, 4, 4, 2, 3.5, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 0, 5, 6, 6, 7, 7, 8, 8, 5};
    in.holes = {2, 2};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery, true);
        expect_valid(in, r, recovery, false, tri::segment_recovery_name(recovery));
        double area = 0;
        for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
            const double* a = r.mesh.point(r.mesh.triangles[3 * t]);
            const double* b = r.mesh.point(r.mesh.triangles[3 * t + 1]);
            const double* c = r.mesh.point(r.mesh.triangles[3 * t + 2]);
            area += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
            const double cx = (a[0] + b[0] + c[0]) / 3, cy = (a[1] + b[1] + c[1]) / 3;
            EXPECT_FALSE(cx > 1 && cx < 3 && cy > 1 && cy < 3) << "triangle in the hole";
        }
        // Outer polygon 16 - notch triangle (4,4),(2,3.5),(0,4) of area 1 - hole 4.
        EXPECT_DOUBLE_EQ(area, 16.0 - 1.0 - 4.0) << tri::segment_recovery_name(recovery);
        EXPECT_GT(r.counters.removed_triangles, 0u);
        // Every boundary edge of the domain is a segment piece.
        std::set<std::pair<tri::VertIdx, tri::VertIdx>> directed;
        for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
            for (int k = 0; k < 3; ++k) {
                if (r.mesh.neighbors[3 * t + k] == tri::kNone) {
                    EXPECT_TRUE(r.mesh.is_constrained(static_cast<tri::TriIdx>(t), k));
                }
            }
        }
    }
}

TEST(Constrained2d, RegionalAttributesFillTheirRegion) {
    // Two squares side by side, separated by a segment; one region point in each.
    Input in;
    in.xy = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1, 0.5, 0.5, 1.5, 0.5};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4};
    in.regions = {0.25, 0.5, 7.0, 0.0, 1.75, 0.25, 9.0, 0.0};
    const auto r = build(in, tri::SegmentRecovery::Swap, true);
    ASSERT_EQ(r.triangle_attributes.size(), r.mesh.triangle_count());
    for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
        double cx = 0;
        for (int k = 0; k < 3; ++k) cx += r.mesh.point(r.mesh.triangles[3 * t + k])[0] / 3;
        EXPECT_EQ(r.triangle_attributes[t], cx < 1 ? 7.0 : 9.0);
    }
}

TEST(Constrained2d, CollinearInputHasNoTriangleButKeepsPieces) {
    Input in{{0, 0, 3, 3, 1, 1, 2, 2, 1, 1}, {0, 1, 2, 3}, {}, {}};
    const auto r = build(in, tri::SegmentRecovery::Swap);
    EXPECT_EQ(r.mesh.triangle_count(), 0u);
    EXPECT_EQ(r.counters.duplicates, 1u);
    // 0-1 splits at 2 and 3: pieces 0-2, 2-3, 3-1 (2-3 also is segment 1, kept once).
    EXPECT_EQ(r.piece_segment.size(), 3u);
}

TEST(Constrained2d, ConformingOutputIsDelaunayAndContainsTheSegments) {
    for (std::uint64_t seed = 100; seed < 110; ++seed) {
        const Input in = random_non_crossing(80, 60, seed);
        const auto r = build(in, tri::SegmentRecovery::Conforming);
        expect_valid(in, r, tri::SegmentRecovery::Conforming, true, "seed " + std::to_string(seed));
    }
}

TEST(Constrained2d, ConformingSegmentsAtSubnormalAnglesTerminate) {
    // libFuzzer timeouts (fuzz_constrained_2d, CI of 2026-11-23): two segments meeting at an
    // angle near 1e-312 radians among subnormal abscissas; midpoint splitting ran past 100,000
    // splits. Concentric shells and splits at vertices within rounding of a segment end it.
    const Input cases[] = {
        {{0x0.0000000ffffffp-1022, 0x1.1p+1, 0x1p-1007, -0x1.e8e8e8e8e8e8ep-791,
          -0x1.18e8e8e8e8e8ep-798, 0x0.00000008e8e8ep-1022, 0x0.000003f5602p-1022, 0,
          0x0.0004010005bp-1022, -1},
         {0, 4, 3, 4},
         {},
         {}},
        {{0x1.0602000b9f513p-223, 0, 0x1p-1007, 0x1p-1007, -0x1.e8e8e8e8e2a8ep-791, -0x1p-799,
          -0x1.e8e8e8e8e8e8ep-791, 0x0.08e8e8e8e8e8ep-1022, 0x0.03f02p-1022, 0},
         {0, 4, 3, 0},
         {},
         {}},
    };
    for (const Input& in : cases) {
        const auto r = build(in, tri::SegmentRecovery::Conforming);
        expect_valid(in, r, tri::SegmentRecovery::Conforming, true, "subnormal angle");
        EXPECT_LT(r.counters.conforming_splits, 5000u);
    }
}

TEST(Constrained2d, ConformingNearlyOverlappingSegmentsSplitOnTheInputLine) {
    // libFuzzer timeout (2026-11-23): segments (0, 2^465) - (1e-312, 0) and (2e-317, 2^641) -
    // (3e-322, -2^769) run side by side about 1e-312 apart over 2^465: conforming would need
    // pieces as short as that gap all along (the split budget stopped it with GeometryError after
    // 4,672 splits); swap and cavity recovery are unaffected.
    const Input in{
        {0, 0x1.03ffp+465, 0, 0, 0x0.00000003ffp-1022, 0x1p+641, 0x0.000000000004p-1022,
         -0x1.00000004p+769, 0x0.000400000003fp-1022, 0, 0x1.0003ffp-511, 0x0.000003e3e0000p-1022},
        {0, 4, 2, 3},
        {},
        {}};
    // Conforming stopped with GeometryError (a split point off the segment's way, since issue
    // 11's chain rule; before, the split budget). Since split points that the midpoint of the
    // rounded piece ends cannot give are taken on the input segment's line, rounded once
    // (issue_11_subnormal_gap_test), it succeeds: the pieces need to be short only where the
    // segments' allowance 2^-40 |w| is below their gap, near the origin.
    const auto conforming = build(in, tri::SegmentRecovery::Conforming);
    expect_valid(in, conforming, tri::SegmentRecovery::Conforming, true, "conforming");
    for (const auto recovery : {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity}) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
    }
}

TEST(Constrained2d, ConformingSplitsOfASubnormalSegmentPassTheCheck) {
    // fuzz_constrained_2d, 2026-11-23: split points of a segment 1.4e-312 long are rounded by up
    // to half of 2^-1074; the check's tolerance (2^-40 of the extent) rounded to 0 there.
    const Input in{{3.844e-321, 0, 0, 8.087e-320, 0, 1.35807730622e-312, 0, 1.35675105885e-312,
                    1.35675105885e-312, 1.3587404299e-312, 0, 1.35675105885e-312},
                   {0, 4, 2, 0},
                   {},
                   {}};
    const auto r = build(in, tri::SegmentRecovery::Conforming);
    expect_valid(in, r, tri::SegmentRecovery::Conforming, true, "subnormal segment");
}

TEST(Constrained2d, ConformingCascadesOnTwoAxesFlipAFewEdgesPerSplit) {
    // libFuzzer timeout (CI, 2026-12-07: over 150 s under ASan; 4.2 s without): segments along
    // the x axis to 1.4e188 and along the y axis to 5.7e170 from a cluster of points 1e-307
    // across at the origin, where both grade down 1,590 binades. Split depth-first, the y axis's
    // 1,550 points came each below every earlier one, and each flipped the fan of x-axis points
    // under it: 622,623 flips and 1.26 million incircle tests, nearly all in GMP, for 3,151
    // splits. Split by bands of piece size, largest first, both cascades descend together
    // (15,348 flips).
    const Input in{{0x0.08c0000004008p-1022, 0x0.000000a000000p-1022, 0x1.0006363630000p+625,
                    0x1.0400800000000p-975, 0x1.0000000000000p-863, 0x1.3000000000000p+567,
                    0x1.0f0019ef1ad63p-1017, 0x0.0000003004000p-1022, 0x1.ffffba6000000p-1008,
                    0x1.7000000400000p-1008},
                   {0, 1, 0, 2, 2, 3, 3, 0, 4, 0},
                   {},
                   {}};
    const auto r = build(in, tri::SegmentRecovery::Conforming);
    expect_valid(in, r, tri::SegmentRecovery::Conforming, true, "two cascades");
    EXPECT_GT(r.counters.conforming_splits, 3000u);  // the grading is needed: 1,590 binades
    EXPECT_LT(r.counters.delaunay_flips, 8 * r.counters.conforming_splits);
}

TEST(Constrained2d, ConformingPieceBendsAtAVertexWithinRoundingOfItsSegment) {
    // Segment 1, (0, 2) - (2, 0), passes exactly through (1, 1), but segment 0, (0, 1.3) -
    // (3, 1.8), crosses it first at a rounded point, so its piece from there to (2, 0) misses
    // (1, 1) by rounding. Conforming recovery bends that piece at (1, 1) (as grid-lines seed 5
    // needs) instead of homing in on (1, 1) with new points until no double is left between.
    const Input in{{0, 2, 2, 0, 1, 1, 0, 1.3, 3, 1.8, 0, 0, 2, 2}, {3, 4, 0, 1}, {}, {}};
    const auto r = build(in, tri::SegmentRecovery::Conforming);
    expect_valid(in, r, tri::SegmentRecovery::Conforming, true, "bend");
    EXPECT_EQ(r.counters.intersections, 1u);
    EXPECT_EQ(r.counters.conforming_bends, 1u);
}

TEST(Constrained2d, HugeAndTinyCoordinates) {
    for (const double scale : {1e-300, 1e-150, 1e150, 1e300}) {
        Input in = random_non_crossing(40, 30, 5);
        for (double& c : in.xy) c *= scale;
        for (const auto recovery : kRecoveries) {
            const auto r = build(in, recovery);
            expect_valid(in, r, recovery, true, "scale " + std::to_string(scale));
        }
    }
}

TEST(CheckConstrained2d, RejectsMissingSegmentsNonDelaunayEdgesAndOneSidedFlags) {
    // The flat rhombus: Delaunay (1-3 diagonal) vs the segment 0-2.
    tri::Triangulation2 delaunay;
    delaunay.xy = {0, 0, 1, -0.2, 2, 0, 1, 0.2};
    delaunay.triangles = {0, 1, 3, 1, 2, 3};
    delaunay.neighbors = {tri::kNone, 1, tri::kNone, tri::kNone, tri::kNone, 0};
    const std::vector<tri::VertIdx> segment{0, 2};
    auto report = tri::check_constrained_delaunay_2d(delaunay, 4, segment);
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("segment 0 (0, 2) is missing: no chain of constrained pieces "
                                  "continues it beyond vertex 0"),
              std::string::npos)
        << report.problem;
    // The other diagonal without its flag is not locally Delaunay.
    tri::Triangulation2 forced = delaunay;
    forced.triangles = {0, 1, 2, 0, 2, 3};
    forced.neighbors = {tri::kNone, tri::kNone, 1, 0, tri::kNone, tri::kNone};
    report = tri::check_constrained_delaunay_2d(forced, 4, {});
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("not locally Delaunay"), std::string::npos) << report.problem;
    forced.constrained = {0, 0, 1, 0, 0, 0};
    report = tri::check_constrained_delaunay_2d(forced, 4, segment);
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("one side only"), std::string::npos) << report.problem;
    forced.constrained = {0, 0, 1, 1, 0, 0};
    report = tri::check_constrained_delaunay_2d(forced, 4, segment);
    EXPECT_TRUE(report.ok) << report.problem;
}

// Regressions found by the CGAL differential campaign and the CDT corpus (minimized inputs).

TEST(Constrained2d, HullSegmentThroughHullVertex) {
    // (0,0)-(0,2) along the hull through (0,1): the half-edge a -> (0,1) borders the infinite
    // vertex, and the vertex on the segment must still be found.
    Input in{{0, 0, 0, 2, 0, 1, 1, 1}, {0, 1}, {}, {}};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        EXPECT_EQ(r.piece_segment.size(), 2u);
    }
}

TEST(Constrained2d, PieceBentThroughAnInputVertex) {
    // Two segments a few ulps from y = x cross; the rounded crossing v6 lies off segment 0, and
    // the piece v6 -> 1 passes exactly through input vertex 0.
    Input in{
        {0x1.b6a75ac694193p-1, 0x1.b6a75ac694191p-1, 0x1.a1f25e144f579p-1, 0x1.a1f25e144f577p-1,
         0x1.53dab466f285ap+0, 0x1.53dab466f2857p+0, 0x1.8c20e6321e5c8p-1, 0x1.8c20e6321e5c8p-1,
         0x1.3818b352f616ap+0, 0x1.3818b352f6169p+0, 0x1.079c186ee83d8p-1, 0x1.079c186ee83d5p-1},
        {2, 1, 4, 5},
        {},
        {}};
    for (const auto recovery : kRecoveries) {
        expect_valid(in, build(in, recovery), recovery, true, tri::segment_recovery_name(recovery));
    }
}

TEST(Constrained2d, ReleasedConstraintIsMadeDelaunayAgain) {
    // Three segments a few ulps from y = x, crossing twice over: the constrained edge released
    // at a crossing whose rounded point is not next to it must be flipped if not Delaunay.
    Input in{
        {0x1.5804a971442eap+0, 0x1.5804a971442eep+0, 0x1.75b112c8b81efp+0, 0x1.75b112c8b81ebp+0,
         0x1.4b6b40eea9bdp+0, 0x1.4b6b40eea9bd3p+0, 0x1.4e3751ad40fa8p+0, 0x1.4e3751ad40faap+0,
         0x1.252a905a50e2dp+0, 0x1.252a905a50e2cp+0, 0x1.5711b8581add2p+0, 0x1.5711b8581add3p+0,
         0x1.6145d6e125528p+0, 0x1.6145d6e125529p+0},
        {1, 2, 4, 0, 3, 6},
        {},
        {}};
    Triangles swap_triangles;
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
        if (recovery == tri::SegmentRecovery::Swap)
            swap_triangles = canonical_triangles(r.mesh.triangles);
        if (recovery == tri::SegmentRecovery::Cavity) {
            EXPECT_EQ(canonical_triangles(r.mesh.triangles), swap_triangles);
        }
    }
}

TEST(CheckConstrained2d, DuplicateLookupIsByCoordinatesNotByTheirHash) {
    // fuzz_constrained_2d, 2026-11-23: vertex 4 repeats (-4, -1); the check looked the used copy
    // up by a hash of the coordinates used as the key, and (-1, -4) hashed the same.
    Input in{{-2, 2, -4, -4, -1, -4, -4, -1, -4, -1}, {0, 1, 1, 2, 2, 3, 3, 0, 4, 0}, {}, {}};
    for (const auto recovery : kRecoveries) {
        const auto r = build(in, recovery);
        expect_valid(in, r, recovery, true, tri::segment_recovery_name(recovery));
    }
}

TEST(CheckConstrained2d, SegmentNamingAnUnusedDuplicateFollowsTheKeptCopy) {
    // Vertex 4 repeats vertex 2 and no triangle uses it; a segment naming it is still present.
    Input in{{0, 0, 1, 0, 1, 1, 0, 1, 1, 1}, {0, 4}, {}, {}};
    const auto r = build(in, tri::SegmentRecovery::Swap);
    ASSERT_EQ(r.merged_into[4], 2u);
    const auto report =
        tri::check_constrained_delaunay_2d(r.mesh, r.input_vertex_count, in.segments);
    EXPECT_TRUE(report.ok) << report.problem;
}
