// SPDX-License-Identifier: MIT
// ConstrainedTriangulation2: without edits it returns exactly constrained_delaunay_2d's result;
// cavity insertions and constrained edge splits keep it constrained Delaunay (exact check) with
// every segment a chain of pieces; encroaching points are refused and name the edges; points
// off a skew segment's line (rounded midpoints) bend its pieces by rounding only; hull edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <gmpxx.h>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;

namespace {

using exactmesh::testing::canonical_triangles;

using exactmesh::testing::Input;

/// The unit square with a square hole [0.4, 0.6]^2 and a skew segment inside.
Input square_with_hole() {
    Input in;
    in.xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.4, 0.6, 0.4, 0.6, 0.6, 0.4, 0.6, 0.1, 0.13, 0.3, 0.77};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9};
    in.holes = {0.5, 0.5};
    return in;
}

void expect_valid(const Input& in, const tri::Cdt2Result& r, const char* label) {
    const auto report =
        tri::check_constrained_delaunay_2d(r.mesh, r.input_vertex_count, in.segments, r.pieces);
    EXPECT_TRUE(report.ok) << label << ": " << report.problem;
}

double area(const tri::Triangulation2& m) {
    double sum = 0;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        const double* a = m.point(m.triangles[3 * t]);
        const double* b = m.point(m.triangles[3 * t + 1]);
        const double* c = m.point(m.triangles[3 * t + 2]);
        sum += 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
    }
    return sum;
}

}  // namespace

TEST(ConstrainedTriangulation2, WithoutEditsEqualsConstrainedDelaunay) {
    const Input in = square_with_hole();
    const tri::Cdt2Result expected = tri::constrained_delaunay_2d(in.pslg());
    tri::ConstrainedTriangulation2 cdt(in.pslg());
    EXPECT_FALSE(cdt.collinear());
    const tri::Cdt2Result got = std::move(cdt).take_result();
    // The same vertices (the box's corners are left out) and the same triangles inside the
    // domain: the box only adds exterior triangles.
    EXPECT_EQ(got.mesh.xy, expected.mesh.xy);
    EXPECT_EQ(canonical_triangles(got.mesh.triangles),
              canonical_triangles(expected.mesh.triangles));
    EXPECT_EQ(got.pieces.size(), expected.pieces.size());
    expect_valid(in, got, "no edits");
}

TEST(ConstrainedTriangulation2, CavityInsertionsStayConstrainedDelaunay) {
    const Input in = square_with_hole();
    tri::ConstrainedTriangulation2 cdt(in.pslg());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int inserted = 0, refused = 0;
    for (int k = 0; k < 2000; ++k) {
        const double x = u(rng), y = u(rng);
        const tri::TriIdx t = cdt.locate(x, y);
        if (!cdt.in_domain(t)) {
            // Outside the domain (the hole): never edited.
            EXPECT_TRUE(x >= 0.4 && x <= 0.6 && y >= 0.4 && y <= 0.6) << x << " " << y;
            continue;
        }
        const auto outcome = cdt.insert_in_cavity(t, x, y);
        if (outcome == tri::CavityInsertion::Inserted) {
            ++inserted;
            EXPECT_FALSE(cdt.touched().empty());
        } else {
            // Refused: every edge named is constrained, and the point lies in its closed
            // diametral circle; split those edges at their midpoints instead (as Ruppert does).
            ASSERT_EQ(outcome, tri::CavityInsertion::Encroaches);
            ASSERT_FALSE(cdt.encroached_edges().empty());
            ++refused;
            std::vector<std::pair<tri::VertIdx, tri::VertIdx>> split;
            for (const tri::EdgeIdx e : cdt.encroached_edges()) {
                EXPECT_NE(cdt.segment_of(e), tri::kNone);
                const double* a = cdt.mesh().point(cdt.mesh().origin(e));
                const double* b = cdt.mesh().point(cdt.mesh().destination(e));
                EXPECT_LE((a[0] - x) * (b[0] - x) + (a[1] - y) * (b[1] - y), 1e-15);
                split.emplace_back(cdt.mesh().origin(e), cdt.mesh().destination(e));
            }
            for (const auto& [a, b] : split) {
                const tri::EdgeIdx e = cdt.find_edge(a, b);
                if (e == tri::kNone) continue;
                const double* pa = cdt.mesh().point(a);
                const double* pb = cdt.mesh().point(b);
                cdt.split_constrained_edge(e, 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]));
            }
        }
        cdt.clear_touched();
    }
    EXPECT_GT(inserted, 1000);
    EXPECT_GT(refused, 10);
    EXPECT_EQ(cdt.counters().cavity_insertions, static_cast<std::uint64_t>(inserted));
    const tri::Cdt2Result r = std::move(cdt).take_result();
    expect_valid(in, r, "cavity insertions");
    EXPECT_NEAR(area(r.mesh), 1.0 - 0.04, 1e-12);
}

TEST(ConstrainedTriangulation2, EncroachingPointIsRefused) {
    // A point just inside the unit square's bottom edge, in its diametral circle.
    const Input in = square_with_hole();
    tri::ConstrainedTriangulation2 cdt(in.pslg());
    const tri::TriIdx t = cdt.locate(0.5, 0.01);
    ASSERT_TRUE(cdt.in_domain(t));
    const std::uint32_t before = cdt.mesh().vertex_count();
    ASSERT_EQ(cdt.insert_in_cavity(t, 0.5, 0.01), tri::CavityInsertion::Encroaches);
    EXPECT_EQ(cdt.mesh().vertex_count(), before);  // nothing changed
    bool bottom = false;
    for (const tri::EdgeIdx e : cdt.encroached_edges()) bottom |= cdt.segment_of(e) == 0;
    EXPECT_TRUE(bottom);
}

TEST(ConstrainedTriangulation2, SplitsAtRoundedPointsBendByRoundingOnly) {
    const Input in = square_with_hole();
    tri::ConstrainedTriangulation2 cdt(in.pslg());
    // Split every piece of every segment at its rounded midpoint, five times over.
    for (int round = 0; round < 5; ++round) {
        std::vector<std::pair<tri::VertIdx, tri::VertIdx>> pieces;
        const tri::TriMesh2& m = cdt.mesh();
        for (tri::EdgeIdx e = 0; e < m.tv.size(); ++e) {
            if (m.is_dead(tri::triangle_of(e)) || cdt.segment_of(e) == tri::kNone) continue;
            if (m.origin(e) < m.destination(e)) pieces.emplace_back(m.origin(e), m.destination(e));
        }
        for (const auto& [a, b] : pieces) {
            const tri::EdgeIdx e = cdt.find_edge(a, b);
            ASSERT_NE(e, tri::kNone);
            const double* pa = cdt.mesh().point(a);
            const double* pb = cdt.mesh().point(b);
            const tri::VertIdx v =
                cdt.split_constrained_edge(e, 0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]));
            EXPECT_NE(cdt.find_edge(a, v), tri::kNone);
            EXPECT_NE(cdt.find_edge(v, b), tri::kNone);
        }
    }
    EXPECT_GT(cdt.counters().edge_splits, 200u);
    const tri::Cdt2Result r = std::move(cdt).take_result();
    expect_valid(in, r, "rounded splits");
    EXPECT_NEAR(area(r.mesh), 1.0 - 0.04, 1e-12);
}

TEST(ConstrainedTriangulation2, SkewBoundarySegmentSplitsBendByRoundingOnly) {
    // A skew boundary segment: the rounded split points fall on either side of its line.
    Input in;
    in.xy = {0, 0, 1, 0.1, 0.9, 1.3, 0.1, 0.7};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0};
    tri::ConstrainedTriangulation2 cdt(in.pslg());
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.2, 0.8);
    // Split the pieces of segment 0 (0, 0) - (1, 0.1) at random points of its line, rounded.
    for (int k = 0; k < 300; ++k) {
        const tri::TriMesh2& m = cdt.mesh();
        std::vector<tri::EdgeIdx> candidates;
        for (tri::EdgeIdx e = 0; e < m.tv.size(); ++e) {
            if (!m.is_dead(tri::triangle_of(e)) && cdt.segment_of(e) == 0) candidates.push_back(e);
        }
        const tri::EdgeIdx e = candidates[static_cast<std::size_t>(k) % candidates.size()];
        const double* pa = m.point(m.origin(e));
        const double* pb = m.point(m.destination(e));
        const double t = 0.25 + 0.5 * u(rng);
        const double x = pa[0] + t * (pb[0] - pa[0]);
        cdt.split_constrained_edge(e, x, x / 10);
    }
    EXPECT_EQ(cdt.counters().edge_splits, 300u);
    const tri::Cdt2Result r = std::move(cdt).take_result();
    expect_valid(in, r, "skew boundary splits");
    const double expected_area = 0.5 * (1 * 1.3 - 0.1 * 0.9) + 0.5 * (0.9 * 0.7 - 1.3 * 0.1);
    EXPECT_NEAR(area(r.mesh), expected_area, 1e-12);
}

TEST(ConstrainedTriangulation2, RejectsConformingRecovery) {
    const Input in = square_with_hole();
    tri::Cdt2Options options;
    options.recovery = tri::SegmentRecovery::Conforming;
    EXPECT_THROW(tri::ConstrainedTriangulation2(in.pslg(), options), em::InputError);
}

TEST(ConstrainedTriangulation2, CornerDotSignIsExactNearRightAngles) {
    // o on the circle with diameter p q (Thales): exactly right, then one ulp either way;
    // sums of products that cancel exactly, far below the filter's reach.
    const double p[2] = {0, 0}, q[2] = {4, 0};
    const double o[2] = {2, 2};
    EXPECT_EQ(em::predicates::corner_dot_sign(o, p, q), em::predicates::Sign::Zero);
    const double inside[2] = {2, std::nextafter(2.0, 0.0)},
                 outside[2] = {2, std::nextafter(2.0, 3.0)};
    EXPECT_EQ(em::predicates::corner_dot_sign(inside, p, q), em::predicates::Sign::Negative);
    EXPECT_EQ(em::predicates::corner_dot_sign(outside, p, q), em::predicates::Sign::Positive);
    // Large offsets: differences not exact in double (GMP stage), against a GMP oracle.
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        const double a[2] = {1e10 + u(rng), u(rng)}, b[2] = {1e10 + u(rng), u(rng)};
        const double m[2] = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        const double r = 0.5 * std::hypot(b[0] - a[0], b[1] - a[1]);
        const double angle = u(rng) * 3.14159;
        const double c[2] = {m[0] + r * std::cos(angle), m[1] + r * std::sin(angle)};
        const mpq_class ux = mpq_class(a[0]) - mpq_class(c[0]),
                        uy = mpq_class(a[1]) - mpq_class(c[1]);
        const mpq_class vx = mpq_class(b[0]) - mpq_class(c[0]),
                        vy = mpq_class(b[1]) - mpq_class(c[1]);
        const int expected = sgn(ux * vx + uy * vy);
        EXPECT_EQ(static_cast<int>(em::predicates::corner_dot_sign(c, a, b)), expected) << k;
    }
}
