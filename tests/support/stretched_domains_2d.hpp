// SPDX-License-Identifier: MIT
// What the stretched-mesh generator tests share (stretched and metric Delaunay, min-max front,
// metric conditioning): a square with a hole, a sample
// domain's PSLG scaled by 2^k, the exact validity of a mesh of it, and the aspect ratios of the
// triangles on its walls. Test support, not a library algorithm.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_2d.hpp"
#include "generators/stretched/metric_delaunay_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::testing {

/// The square [0, s]^2 with a square hole [0.4 s, 0.6 s]^2 (the metric Delaunay tests' domain).
struct SquareWithHole {
    std::vector<double> xy;
    std::vector<triangulation::VertIdx> segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    std::vector<double> holes;
    explicit SquareWithHole(double s)
        : xy{0,       0,       s,       0,       s,       s,       0,       s,
             0.4 * s, 0.4 * s, 0.6 * s, 0.4 * s, 0.6 * s, 0.6 * s, 0.4 * s, 0.6 * s},
          holes{0.5 * s, 0.5 * s} {}
    triangulation::Pslg pslg() const { return {xy, segments, holes, {}}; }
};

/// A boundary layer curved around the circle of radius 0.3 s about (0.5 s, 0.5 s) (issue 14's
/// curved layer): size 0.05 s along the circle's tangent, s (first + 0.3 |r / s - 0.3|) across it
/// (aspect ratio 0.05 / first on the circle), the metric rotating with the tangent.
inline generators::MetricField2 circle_layer(double first, double s = 1) {
    return generators::MetricField2::analytic(
        [first, s](double x, double y) {
            const double dx = x - 0.5 * s, dy = y - 0.5 * s, r = std::hypot(dx, dy);
            generators::Metric2 m;
            m.h1 = s * (first + 0.3 * std::fabs(r / s - 0.3));
            m.h2 = 0.05 * s;
            if (r > 0) {
                m.c = dx / r;
                m.s = dy / r;
            }
            return m;
        },
        "circle boundary layer");
}

/// metric_delaunay_2d of `domain` in `metric`.
inline generators::MetricDelaunayResult2 metric_delaunay_of(
    const SquareWithHole& domain, const generators::MetricField2& metric) {
    const generators::MeshDomain2 mesh_domain(domain.pslg());
    generators::MetricDelaunayOptions2 options;
    options.metric = metric;
    return generators::metric_delaunay_2d(mesh_domain, options);
}

/// The mesh is exactly valid (conforming, segments as chains) and keeps the input vertices.
inline void expect_valid_metric_mesh(const SquareWithHole& domain,
                                     const generators::MetricDelaunayResult2& r) {
    const triangulation::CheckReport report = triangulation::detail::check_constrained_mesh_2d(
        r.mesh.mesh, r.mesh.input_vertex_count, domain.segments, r.mesh.pieces, {}, false);
    EXPECT_TRUE(report.ok) << report.problem;
    for (std::size_t i = 0; i < domain.xy.size(); ++i) EXPECT_EQ(r.mesh.mesh.xy[i], domain.xy[i]);
}

/// A sample domain's PSLG (pslg_fixtures_2d's Input), every coordinate scaled by 2^k.
inline Input scaled_sample_domain(generators::SampleDomain d, int k,
                                  const generators::SizeFunction& size = {}) {
    Input in = from_domain(generators::sample_domain(d, size));
    for (double& x : in.xy) x = std::ldexp(x, k);
    for (double& x : in.holes) x = std::ldexp(x, k);
    return in;
}

/// A generator's mesh of `domain` is exactly valid (conforming, every segment a chain of
/// pieces: check_constrained_mesh_2d without the Delaunay test) and keeps every input vertex
/// at its number and coordinates.
inline void expect_valid_mesh_of(const Input& domain, const triangulation::Cdt2Result& mesh) {
    const triangulation::CheckReport report = triangulation::detail::check_constrained_mesh_2d(
        mesh.mesh, mesh.input_vertex_count, domain.segments, mesh.pieces, {}, false);
    EXPECT_TRUE(report.ok) << report.problem;
    ASSERT_GE(mesh.mesh.xy.size(), domain.xy.size());
    for (std::size_t i = 0; i < domain.xy.size(); ++i) EXPECT_EQ(mesh.mesh.xy[i], domain.xy[i]);
    EXPECT_EQ(mesh.input_vertex_count, domain.xy.size() / 2);
}

/// Longest edge over smallest altitude (L_max^2 / (2 area), in doubles: unscaled coordinates)
/// of the triangles with a constrained side whose ends are both vertices in [first, end) (a
/// wall's input vertices): median and maximum, (0, 0) when there is none.
inline std::pair<double, double> wall_aspect_ratios(const triangulation::Triangulation2& mesh,
                                                    triangulation::VertIdx first,
                                                    triangulation::VertIdx end) {
    std::vector<double> ratios;
    const auto on_wall = [&](triangulation::VertIdx v) { return v >= first && v < end; };
    for (triangulation::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        bool at_wall = false;
        for (unsigned k = 0; k < 3; ++k) {
            at_wall = at_wall || (mesh.is_constrained(t, static_cast<int>(k)) &&
                                  on_wall(mesh.triangles[3 * t + k]) &&
                                  on_wall(mesh.triangles[3 * t + (k + 1) % 3]));
        }
        if (!at_wall) continue;
        const double* a = mesh.point(mesh.triangles[3 * t]);
        const double* b = mesh.point(mesh.triangles[3 * t + 1]);
        const double* c = mesh.point(mesh.triangles[3 * t + 2]);
        const double area2 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        const auto sq = [](const double* p, const double* q) {
            return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]);
        };
        ratios.push_back(std::max({sq(a, b), sq(b, c), sq(c, a)}) / area2);
    }
    if (ratios.empty()) return {0, 0};
    std::sort(ratios.begin(), ratios.end());
    return {ratios[ratios.size() / 2], ratios.back()};
}

}  // namespace exactmesh::testing
