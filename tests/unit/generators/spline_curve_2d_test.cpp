// SPDX-License-Identifier: MIT
// Cubic spline boundaries: the spline passes through its control points exactly, is C2 at every
// knot (one-sided derivatives agree; natural ends have no curvature), its derivatives match
// finite differences, collinear points give the line; discretized points lie on the curve with
// spacing following the size; boundary_loops_domain builds a PSLG with holes that Delaunay
// refinement meshes to a mesh passing check_quality_mesh; bad loops raise InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/spline_curve_2d.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;

namespace {

/// Control points on r(theta) = r0 (1 + a cos(k theta)) about (cx, cy), n of them, ellipse-
/// scaled in y.
std::vector<double> flower(int n, double cx, double cy, double r0, double a, int k,
                           double y_scale = 1) {
    std::vector<double> xy;
    for (int i = 0; i < n; ++i) {
        const double theta = 2 * std::numbers::pi * i / n, r = r0 * (1 + a * std::cos(k * theta));
        xy.insert(xy.end(), {cx + r * std::cos(theta), cy + y_scale * r * std::sin(theta)});
    }
    return xy;
}

/// Distance from p to the spline: the best of a dense sampling, polished by Newton steps on
/// the squared distance.
double distance_to(const gen::CubicSpline2& s, std::array<double, 2> p) {
    double best_u = 0, best = INFINITY;
    const int samples = 4000;
    for (int i = 0; i <= samples; ++i) {
        const double u = s.parameter_end() * i / samples;
        const auto q = s.point(u);
        const double d = std::hypot(q[0] - p[0], q[1] - p[1]);
        if (d < best) best = d, best_u = u;
    }
    double u = best_u;
    for (int it = 0; it < 20; ++it) {
        const auto q = s.point(u), d1 = s.derivative(u), d2 = s.second_derivative(u);
        const double ex = q[0] - p[0], ey = q[1] - p[1];
        const double g = ex * d1[0] + ey * d1[1],
                     h = d1[0] * d1[0] + d1[1] * d1[1] + ex * d2[0] + ey * d2[1];
        if (!(h > 0)) break;
        u -= g / h;
    }
    const auto q = s.point(u);
    return std::min(best, std::hypot(q[0] - p[0], q[1] - p[1]));
}

}  // namespace

TEST(Generators_SplineCurve2, InterpolatesTheControlPointsExactly) {
    for (const bool closed : {true, false}) {
        const std::vector<double> xy = flower(11, 0.2, -0.1, 1.0, 0.3, 3);
        const gen::CubicSpline2 s(xy, closed);
        EXPECT_EQ(s.point_count(), 11u);
        EXPECT_EQ(s.segment_count(), closed ? 11u : 10u);
        for (std::size_t i = 0; i < s.point_count(); ++i) {
            const auto p = s.point(s.knot(i));
            EXPECT_EQ(p[0], xy[2 * i]) << i;
            EXPECT_EQ(p[1], xy[2 * i + 1]) << i;
        }
        const auto end = s.point(s.parameter_end());
        EXPECT_EQ(end[0], closed ? xy[0] : xy[20]);
        EXPECT_EQ(end[1], closed ? xy[1] : xy[21]);
    }
    // A closed spline's repeated first point is dropped.
    std::vector<double> repeated = flower(5, 0, 0, 1, 0, 1);
    repeated.insert(repeated.end(), {repeated[0], repeated[1]});
    EXPECT_EQ(gen::CubicSpline2(repeated, true).point_count(), 5u);
}

TEST(Generators_SplineCurve2, IsC2AtEveryKnot) {
    for (const bool closed : {true, false}) {
        // Uneven spacing: chord lengths vary by a factor of about 10.
        std::vector<double> xy;
        std::mt19937_64 random(closed ? 1 : 2);
        std::uniform_real_distribution<double> jitter(-0.4, 0.4);
        for (int i = 0; i < 14; ++i) {
            const double theta = 2 * std::numbers::pi * (i + jitter(random)) / 14;
            xy.insert(xy.end(), {(1 + 0.2 * jitter(random)) * std::cos(theta),
                                 (1 + 0.2 * jitter(random)) * std::sin(theta)});
        }
        const gen::CubicSpline2 s(xy, closed);
        const std::size_t segments = s.segment_count();
        for (std::size_t i = closed ? 0 : 1; i < (closed ? segments : segments); ++i) {
            const std::size_t before = (i + segments - 1) % segments;
            for (int order = 0; order <= 2; ++order) {
                const auto left = s.on_segment(before, 1.0, order),
                           right = s.on_segment(i, 0.0, order);
                const double scale = order == 0 ? 1.0 : order == 1 ? 1.0 : 10.0;
                EXPECT_NEAR(left[0], right[0], 1e-12 * scale) << "knot " << i << " order " << order;
                EXPECT_NEAR(left[1], right[1], 1e-12 * scale) << "knot " << i << " order " << order;
            }
        }
        if (!closed) {  // natural ends
            EXPECT_EQ(s.second_derivative(0)[0], 0.0);
            EXPECT_EQ(s.second_derivative(s.parameter_end())[1], 0.0);
        }
        // The derivatives are the derivatives: central differences.
        std::uniform_real_distribution<double> u(0.01, s.parameter_end() - 0.01);
        for (int k = 0; k < 200; ++k) {
            const double at = u(random), h = 1e-5;
            const auto p0 = s.point(at - h), p1 = s.point(at + h), d = s.derivative(at);
            const auto q0 = s.derivative(at - h), q1 = s.derivative(at + h),
                       dd = s.second_derivative(at);
            for (int c = 0; c < 2; ++c) {
                const auto cc = static_cast<std::size_t>(c);
                EXPECT_NEAR((p1[cc] - p0[cc]) / (2 * h), d[cc], 1e-6);
                EXPECT_NEAR((q1[cc] - q0[cc]) / (2 * h), dd[cc], 1e-4);
            }
        }
    }
}

TEST(Generators_SplineCurve2, CollinearPointsGiveTheLineAndCirclesStayRound) {
    const gen::CubicSpline2 line({0, 0, 1, 0.5, 3, 1.5, 4, 2}, false);
    for (int k = 0; k <= 100; ++k) {
        const auto p = line.point(line.parameter_end() * k / 100);
        EXPECT_NEAR(p[1], 0.5 * p[0], 1e-15);
    }
    const gen::CubicSpline2 circle(flower(16, 0, 0, 1, 0, 1), true);
    double worst = 0;
    for (int k = 0; k <= 1000; ++k) {
        const auto p = circle.point(circle.parameter_end() * k / 1000);
        worst = std::max(worst, std::fabs(std::hypot(p[0], p[1]) - 1));
    }
    EXPECT_LT(worst, 2e-4);  // a periodic cubic through 16 points of the unit circle
    // Wrapping round (closed) and clamping (open).
    EXPECT_NEAR(circle.point(circle.parameter_end() + 0.1)[0], circle.point(0.1)[0], 1e-12);
    EXPECT_EQ(line.point(-1)[0], 0.0);
}

TEST(Generators_SplineCurve2, BadControlPointsAreInputErrors) {
    EXPECT_THROW(gen::CubicSpline2({0, 0, 1, 1}, true), em::InputError);  // 2 points closed
    EXPECT_THROW(gen::CubicSpline2({0, 0}, false), em::InputError);       // 1 point open
    EXPECT_THROW(gen::CubicSpline2({0, 0, 1}, false), em::InputError);    // odd count
    EXPECT_THROW(gen::CubicSpline2({0, 0, 1, NAN, 2, 0}, false), em::InputError);
    try {
        gen::CubicSpline2({0, 0, 1, 0, 1, 0, 2, 1}, false);
        ADD_FAILURE() << "no error";
    } catch (const em::InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("spline: control points 1 and 2 coincide", 0), 0u)
            << error.what();
    }
    EXPECT_NO_THROW(gen::CubicSpline2({0, 0, 1, 0, 0, 1}, true));
}

TEST(Generators_SplineCurve2, DiscretizedPointsLieOnTheCurveSpacedByTheSize) {
    const gen::CubicSpline2 s(flower(9, 0, 0, 1, 0.25, 2), true);
    // Fine near (1.25, 0), coarse elsewhere.
    const gen::SizeFunction size = gen::SizeFunction::sources({{1.25, 0, 0.01, 0.1, 1}}, {}, 0.15);
    const auto points = s.discretize(size, 8);
    ASSERT_GT(points.size(), 60u);
    double ratio_lo = INFINITY, ratio_hi = 0, short_piece = INFINITY, long_piece = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_LT(distance_to(s, points[i]), 1e-12) << i;
        const auto& a = points[i];
        const auto& b = points[(i + 1) % points.size()];
        const double chord = std::hypot(b[0] - a[0], b[1] - a[1]);
        const double ratio = chord / size(0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]));
        ratio_lo = std::min(ratio_lo, ratio), ratio_hi = std::max(ratio_hi, ratio);
        short_piece = std::min(short_piece, chord), long_piece = std::max(long_piece, chord);
    }
    EXPECT_GT(ratio_lo, 0.75);
    EXPECT_LT(ratio_hi, 1.02);
    EXPECT_LT(short_piece, 0.015);  // graded: about 0.01 at the source, 0.15 far from it
    EXPECT_GT(long_piece, 0.12);
    // Unbounded size: min_pieces pieces equal in the parameter.
    EXPECT_EQ(s.discretize(gen::SizeFunction(), 12).size(), 12u);
    // Open: both ends kept.
    const gen::CubicSpline2 open({0, 0, 1, 1, 2, 0, 3, 1}, false);
    const auto open_points = open.discretize(gen::SizeFunction::uniform(0.1), 1);
    EXPECT_EQ(open_points.front()[0], 0.0);
    EXPECT_EQ(open_points.back()[0], 3.0);
    EXPECT_EQ(open_points.back()[1], 1.0);
}

TEST(Generators_SplineCurve2, SplineDomainMeshesWithDelaunayRefinement) {
    std::vector<gen::BoundaryLoop2> loops(3);
    loops[0].xy = flower(12, 0, 0, 1, 0.2, 3);              // the outer boundary
    loops[1].xy = flower(7, 0.35, 0.1, 0.18, 0.0, 1, 0.6);  // an elliptic spline hole
    loops[1].hole = true;
    loops[2].xy = {-0.55, -0.15, -0.25, -0.15, -0.25, 0.15, -0.55, 0.15};  // a square hole
    loops[2].spline = false;
    loops[2].hole = true;
    const gen::SizeFunction size =
        gen::SizeFunction::sources({{0.35, 0.1, 0.01, 0.05, 1}}, {}, 0.1);
    const gen::DomainPslg d = gen::boundary_loops_domain(loops, size);
    ASSERT_EQ(d.holes.size(), 4u);
    EXPECT_TRUE(em::testing::inside_by_segments(d.holes[0], d.holes[1], d.xy, d.segments) == false);
    gen::RefinementOptions2 options;
    options.size = size;
    const auto refined = gen::delaunay_refinement_2d({d.xy, d.segments, d.holes, {}}, options);
    const auto& m = refined.mesh;
    const auto check =
        em::testing::check_quality_mesh(m.mesh, m.input_vertex_count, d.xy, d.segments, m.pieces,
                                        [&size](double x, double y) { return size(x, y); });
    EXPECT_TRUE(check.ok) << check.problem;
    EXPECT_GE(check.min_angle, gen::kGuaranteedMinAngle - 1e-9);
    EXPECT_LE(check.max_size_ratio, 1.0 + 1e-9);
    EXPECT_GT(m.mesh.triangle_count(), 1000u);
    // No triangle inside a hole: the centroids are inside the outer loop and outside both holes.
    for (std::uint32_t t = 0; t < m.mesh.triangle_count(); ++t) {
        double c[2] = {0, 0};
        for (int k = 0; k < 3; ++k) {
            const double* p = m.mesh.point(m.mesh.triangles[3 * t + static_cast<unsigned>(k)]);
            c[0] += p[0] / 3, c[1] += p[1] / 3;
        }
        ASSERT_FALSE(c[0] > -0.55 && c[0] < -0.25 && c[1] > -0.15 && c[1] < 0.15) << t;
    }
}

TEST(Generators_SplineCurve2, BadLoopsAreInputErrors) {
    auto message = [](std::vector<gen::BoundaryLoop2> loops) {
        try {
            gen::boundary_loops_domain(loops, gen::SizeFunction::uniform(0.1));
        } catch (const em::InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message({}).rfind("boundary loops: no loop", 0), 0u);
    gen::BoundaryLoop2 two{{0, 0, 1, 0}, false, false, {}};
    EXPECT_EQ(message({two}).rfind("boundary loop 0: a polygon needs at least 3 vertices", 0), 0u);
    gen::BoundaryLoop2 repeated{{0, 0, 1, 0, 1, 0, 0, 1}, false, false, {}};
    EXPECT_EQ(message({repeated}).rfind("boundary loop 0: vertices 1 and 2 coincide", 0), 0u);
    gen::BoundaryLoop2 spline_two{{0, 0, 1, 0}, true, false, {}};
    EXPECT_EQ(
        message({spline_two}).rfind("boundary loop 0: spline: a closed spline needs at least 3", 0),
        0u);
    // Two overlapping circles cross; a figure eight crosses itself; a square touching a
    // triangle's corner touches.
    const gen::BoundaryLoop2 a{flower(8, 0, 0, 1, 0, 1), true, false, {}},
        b{flower(8, 1, 0, 1, 0, 1), true, false, {}};
    EXPECT_EQ(message({a, b}).rfind("boundary loops: segments ", 0), 0u) << message({a, b});
    const gen::BoundaryLoop2 eight{{0, 0, 1, 1, 1, 0, 0, 1}, false, false, {}};
    EXPECT_NE(message({eight}).find("cross or touch"), std::string::npos);
    const gen::BoundaryLoop2 square{{0, 0, 1, 0, 1, 1, 0, 1}, false, false, {}};
    const gen::BoundaryLoop2 corner{{1, 1, 2, 1, 2, 2}, false, true, {}};
    EXPECT_NE(message({square, corner}).find("cross or touch"), std::string::npos);
    const gen::BoundaryLoop2 fold{
        {0, 0, 2, 0, 1, 0, 1, 1}, false, false, {}};  // folds back along y = 0
    EXPECT_NE(message({fold}).find("cross or touch"), std::string::npos);
    const gen::BoundaryLoop2 inner{{0.2, 0.2, 0.8, 0.2, 0.5, 0.8}, false, true, {}};
    EXPECT_EQ(message({square, inner}), "no error");
}

TEST(Generators_SplineCurve2, CornersSplitALoopIntoOpenSplines) {
    // A teardrop: a round nose and a sharp tail at control point 0 (1, 0).
    std::vector<double> xy;
    for (int i = 0; i < 12; ++i) {
        const double theta = 2 * std::numbers::pi * i / 12;
        xy.insert(xy.end(), {std::cos(theta), 0.4 * std::sin(theta) * (1 - std::cos(theta)) / 2});
    }
    gen::BoundaryLoop2 tail{xy, true, false, {0}};
    const gen::DomainPslg d =
        gen::boundary_loops_domain(std::vector{tail}, gen::SizeFunction::uniform(0.05));
    ASSERT_GT(d.xy.size() / 2, 40u);
    EXPECT_EQ(d.xy[0], 1.0);  // the corner itself
    EXPECT_EQ(d.xy[1], 0.0);
    // Both sides leave the corner along their own tangent: a corner, not a C1 join.
    const std::size_t n = d.xy.size() / 2;
    const double ax = d.xy[2] - 1, ay = d.xy[3], bx = d.xy[2 * (n - 1)] - 1,
                 by = d.xy[2 * (n - 1) + 1];
    const double angle =
        std::acos((ax * bx + ay * by) / (std::hypot(ax, ay) * std::hypot(bx, by))) * 180 /
        std::numbers::pi;
    EXPECT_LT(angle, 150);
    // Two corners: the points of both corners are in the PSLG.
    gen::BoundaryLoop2 two{xy, true, false, {0, 6}};
    const gen::DomainPslg d2 =
        gen::boundary_loops_domain(std::vector{two}, gen::SizeFunction::uniform(0.05));
    bool found = false;
    for (std::size_t i = 0; i < d2.xy.size() / 2; ++i)
        found = found || (d2.xy[2 * i] == xy[12] && d2.xy[2 * i + 1] == xy[13]);
    EXPECT_TRUE(found);
    gen::RefinementOptions2 options;
    options.size = gen::SizeFunction::uniform(0.05);
    options.min_angle = 0;  // the tail's own angle is small
    const auto refined = gen::delaunay_refinement_2d({d.xy, d.segments, d.holes, {}}, options);
    const auto check = em::testing::check_quality_mesh(
        refined.mesh.mesh, refined.mesh.input_vertex_count, d.xy, d.segments, refined.mesh.pieces);
    EXPECT_TRUE(check.ok) << check.problem;
    gen::BoundaryLoop2 bad{xy, true, false, {3, 3}};
    EXPECT_THROW(gen::boundary_loops_domain(std::vector{bad}, gen::SizeFunction::uniform(0.05)),
                 em::InputError);
    gen::BoundaryLoop2 out{xy, true, false, {12}};
    EXPECT_THROW(gen::boundary_loops_domain(std::vector{out}, gen::SizeFunction::uniform(0.05)),
                 em::InputError);
}
