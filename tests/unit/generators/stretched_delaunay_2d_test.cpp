// SPDX-License-Identifier: MIT
// The stretched Delaunay generator (issue 14, the seed's seven steps) on the built-in airfoil
// domains: valid constrained meshes (exact check) that keep every input vertex and segment,
// stretched cells at the wall (aspect ratio >= 100 with a first height of 1e-4 on the NACA
// 0012), in-ellipse swaps that change edges, and the same mesh scaled when the domain, the first
// height and the sizes are scaled by 2^600 or 2^-600.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "generators/stretched/metric_quality_2d.hpp"
#include "generators/stretched/stretched_delaunay_2d.hpp"
#include "generators/stretched/wall_loops_2d.hpp"
#include "tests/support/scaled_coordinates.hpp"
#include "tests/support/stretched_domains_2d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using Domain = exactmesh::testing::Input;

Domain scaled(gen::SampleDomain d, int k, const gen::SizeFunction& size = {}) {
    return exactmesh::testing::scaled_sample_domain(d, k, size);
}

gen::StretchedDelaunayResult2 run(const Domain& domain, double first_height) {
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = first_height;
    return gen::stretched_delaunay_2d(mesh_domain, options);
}

void expect_valid(const Domain& domain, const gen::StretchedDelaunayResult2& r) {
    exactmesh::testing::expect_valid_mesh_of(domain, r.mesh);
    // The neighbours after the swaps are those the triangles define.
    tri::Triangulation2 relinked = r.mesh.mesh;
    relinked.neighbors.clear();
    tri::link_neighbors_2d(relinked);
    EXPECT_EQ(relinked.neighbors, r.mesh.mesh.neighbors);
}

using exactmesh::testing::wall_aspect_ratios;

std::set<std::pair<tri::VertIdx, tri::VertIdx>> edges(const tri::Triangulation2& mesh) {
    std::set<std::pair<tri::VertIdx, tri::VertIdx>> result;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const tri::VertIdx a = mesh.triangles[i];
        const tri::VertIdx b = mesh.triangles[i % 3 == 2 ? i - 2 : i + 1];
        result.insert({std::min(a, b), std::max(a, b)});
    }
    return result;
}

/// The quality report in the vertices' own metrics (log-Euclidean linear in the triangles).
gen::MetricQualityReport2 quality(const gen::StretchedDelaunayResult2& r) {
    const tri::Triangulation2& mesh = r.mesh.mesh;
    const gen::MetricField2 field =
        gen::MetricField2::background_mesh(mesh.xy, r.metrics, mesh.triangles);
    return gen::metric_quality_report_2d(mesh.xy, mesh.triangles, field);
}

/// The triangles whose Euclidean largest angle exceeds 150 degrees and that are flat in their
/// metric too (mean ratio below 0.5 in the log-Euclidean mean of their corners' metrics): the
/// staggered layers' triangles are equilateral in their metric and near 180 degrees in the
/// plane by design, so only these are defects.
std::size_t flat_in_metric_above_150(const gen::StretchedDelaunayResult2& r) {
    const tri::Triangulation2& mesh = r.mesh.mesh;
    std::size_t count = 0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const tri::VertIdx* v = &mesh.triangles[3 * t];
        const gen::QualityReport2 plane = gen::quality_report_2d(
            mesh.xy, std::span<const tri::VertIdx>(v, 3), gen::SizeFunction{});
        if (!(plane.max_angle > 150)) continue;
        const std::array<gen::Metric2, 3> at = {r.metrics[v[0]], r.metrics[v[1]], r.metrics[v[2]]};
        const double weights[3] = {1, 1, 1};
        const gen::Metric2 mean = gen::log_euclidean_mean(at, weights);
        double ex[3], ey[3], squares = 0;
        for (int k = 0; k < 3; ++k) {
            const double* a = mesh.point(v[k]);
            const double* b = mesh.point(v[(k + 1) % 3]);
            gen::metric_map(mean, b[0] - a[0], b[1] - a[1], ex[k], ey[k]);
            squares += ex[k] * ex[k] + ey[k] * ey[k];
        }
        const double shape = 2 * std::sqrt(3.0) * (ex[0] * ey[1] - ey[0] * ex[1]) / squares;
        if (shape < 0.5) ++count;
    }
    return count;
}

void print(const char* name, const gen::StretchedDelaunayResult2& r, double median,
           double largest) {
    const gen::MetricQualityReport2 q = quality(r);
    std::cout << name << ": " << r.mesh.mesh.vertex_count() << " points, "
              << r.mesh.mesh.triangle_count() << " triangles, wall aspect ratio median " << median
              << " max " << largest << ", unit metric edges " << q.unit_length_share
              << ", metric shape median " << q.shape_median << ", above 150 degrees "
              << q.above_150_degrees << ", max angle " << q.max_angle << "\n";
    for (const auto& [counter, value] : gen::counter_list(r.counters))
        std::cout << "  " << counter << " " << value << "\n";
}

TEST(StretchedDelaunay2d, Naca0012IsValidAndStretchedAtTheWall) {
    const Domain domain = scaled(gen::SampleDomain::Naca0012, 0);
    const gen::StretchedDelaunayResult2 r = run(domain, 1e-4);
    expect_valid(domain, r);
    EXPECT_EQ(r.counters.components, 1u);
    EXPECT_GT(r.counters.omesh_points, 10 * r.counters.wall_vertices);
    EXPECT_GT(r.counters.swaps, 0u);
    EXPECT_GT(r.counters.smoothing_moves, 0u);
    // The airfoil's vertices follow the far-field box's four corners.
    const auto [median, largest] = wall_aspect_ratios(r.mesh.mesh, 4, r.mesh.input_vertex_count);
    print("naca0012", r, median, largest);
    // A few stay where the swap would not lower the pair's largest angle (measured 0.15% to
    // 0.34% of the triangles).
    EXPECT_LT(flat_in_metric_above_150(r), r.mesh.mesh.triangle_count() / 200);
    // Right-angled cells (the default, unstaggered): no triangle above 150 degrees; 79% of the
    // edges unit in the metric (staggered layers give 94%: the test below).
    EXPECT_EQ(quality(r).above_150_degrees, 0u);
    EXPECT_GE(quality(r).unit_length_share, 0.75);
    EXPECT_GE(largest, 100.0);
    EXPECT_GE(median, 100.0);
}

TEST(StretchedDelaunay2d, ThreeElementIsValidWithOverlapsRemoved) {
    const Domain domain = scaled(gen::SampleDomain::ThreeElement, 0);
    const gen::StretchedDelaunayResult2 r = run(domain, 1e-4);
    expect_valid(domain, r);
    EXPECT_EQ(r.counters.components, 3u);
    EXPECT_GT(r.counters.overlap_dropped, 0u);
    EXPECT_GT(r.counters.swaps, 0u);
    const auto [median, largest] = wall_aspect_ratios(r.mesh.mesh, 4, r.mesh.input_vertex_count);
    print("three-element", r, median, largest);
    // A few stay where the swap would not lower the pair's largest angle (measured 0.15% to
    // 0.34% of the triangles).
    EXPECT_LT(flat_in_metric_above_150(r), r.mesh.mesh.triangle_count() / 200);
    EXPECT_EQ(quality(r).above_150_degrees, 0u);  // right-angled cells (measured 80% unit edges)
    EXPECT_GE(quality(r).unit_length_share, 0.75);
    EXPECT_GE(largest, 30.0);
}

TEST(StretchedDelaunay2d, StaggeredLayersGiveMoreUnitEdgesThanUnstaggered) {
    const Domain domain = scaled(gen::SampleDomain::Naca0012, 0);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = 1e-4;
    options.staggered_layers = false;
    const gen::StretchedDelaunayResult2 plain = gen::stretched_delaunay_2d(mesh_domain, options);
    options.staggered_layers = true;
    const gen::StretchedDelaunayResult2 staggered =
        gen::stretched_delaunay_2d(mesh_domain, options);
    expect_valid(domain, plain);
    expect_valid(domain, staggered);
    const gen::MetricQualityReport2 before = quality(plain), after = quality(staggered);
    std::cout << "unit metric edges: unstaggered " << before.unit_length_share << ", staggered "
              << after.unit_length_share << "; metric shape median " << before.shape_median << ", "
              << after.shape_median << "\n";
    EXPECT_GT(after.unit_length_share, before.unit_length_share + 0.1);
    EXPECT_GT(after.shape_median, before.shape_median);
    // Unstaggered, the cells split by a diagonal have right angles: none above 150 degrees.
    EXPECT_EQ(before.above_150_degrees, 0u);
}

/// The mesh with a wake of `chords` chords behind each trailing edge, the domain and sizes
/// scaled by 2^k.
gen::StretchedDelaunayResult2 run_wake(gen::SampleDomain d, int k, double chords) {
    const Domain domain = scaled(d, k);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = std::ldexp(1e-4, k);
    options.wake_length = chords;
    gen::StretchedDelaunayResult2 r = gen::stretched_delaunay_2d(mesh_domain, options);
    expect_valid(domain, r);
    return r;
}

/// Mesh vertices strictly behind x0 (downstream of a trailing edge at x0), within |y - y0| <
/// band, whose metric is stretched along the x axis (the wake's direction, within 30 degrees)
/// by an aspect ratio of at least `aspect`.
std::size_t stretched_points_behind(const gen::StretchedDelaunayResult2& r, double x0, double y0,
                                    double x1, double band, double aspect) {
    const tri::Triangulation2& mesh = r.mesh.mesh;
    std::size_t count = 0;
    for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        const double* p = mesh.point(v);
        if (!(p[0] > x0 && p[0] < x1 && std::fabs(p[1] - y0) < band)) continue;
        // Sizes along x and along y: the metric lengths of the unit vectors are 1 / size.
        const double along = 1 / gen::metric_length(r.metrics[v], 1, 0);
        const double across = 1 / gen::metric_length(r.metrics[v], 0, 1);
        if (along >= aspect * across) ++count;
    }
    return count;
}

TEST(StretchedDelaunay2d, WakesFollowEachTrailingEdge) {
    // The NACA 0012's trailing edge is (1, 0); without a wake nothing behind it is stretched
    // along the flow beyond the O-mesh, with one of 2 chords a strip of stretched points is.
    const gen::StretchedDelaunayResult2 none = run_wake(gen::SampleDomain::Naca0012, 0, 0);
    const gen::StretchedDelaunayResult2 wake = run_wake(gen::SampleDomain::Naca0012, 0, 2);
    EXPECT_EQ(none.counters.trailing_edges, 0u);
    EXPECT_EQ(none.counters.wake_points, 0u);
    EXPECT_EQ(wake.counters.trailing_edges, 1u);
    EXPECT_GT(wake.counters.wake_points, wake.counters.wake_dropped);
    EXPECT_GT(wake.counters.wake_omesh_dropped, 0u);  // the trailing edge fan's
    print("naca0012, wake 2 chords", wake, 0, 0);
    const std::size_t behind = stretched_points_behind(wake, 1.05, 0, 3, 0.05, 5);
    EXPECT_GT(behind, 100u);
    EXPECT_EQ(stretched_points_behind(none, 1.05, 0, 3, 0.05, 5), 0u);
    EXPECT_EQ(stretched_points_behind(wake, 3.2, 0, 1e9, 1e9, 5), 0u);  // within 2 chords
    EXPECT_GT(wake.mesh.mesh.vertex_count(), none.mesh.mesh.vertex_count());
    // The three-element domain: a wake behind each element that has a sharp rear corner.
    const gen::StretchedDelaunayResult2 three = run_wake(gen::SampleDomain::ThreeElement, 0, 1);
    print("three-element, wake 1 chord", three, 0, 0);
    EXPECT_EQ(three.counters.trailing_edges, 3u);
    EXPECT_GT(three.counters.wake_points, three.counters.wake_dropped);
    // Behind each element's rearmost vertex, along its corner's bisector: wake points stretched
    // along the bisector (aspect ratio 5 or more) within a tenth of a chord of the line.
    const Domain domain = scaled(gen::SampleDomain::ThreeElement, 0);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    const tri::Triangulation2& boundary = mesh_domain.triangulation().mesh;
    const std::vector<gen::WallLoop2> walls = gen::wall_loops_2d(boundary);
    ASSERT_EQ(walls.size(), 3u);
    for (const gen::WallLoop2& wall : walls) {
        const std::size_t n = wall.vertices.size();
        std::size_t rear = 0;
        double chord = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const double* p = boundary.point(wall.vertices[i]);
            const double* r = boundary.point(wall.vertices[rear]);
            if (p[0] > r[0] || (p[0] == r[0] && p[1] < r[1])) rear = i;
        }
        const double* v = boundary.point(wall.vertices[rear]);
        const double* a = boundary.point(wall.vertices[(rear + n - 1) % n]);
        const double* b = boundary.point(wall.vertices[(rear + 1) % n]);
        for (const tri::VertIdx w : wall.vertices) {
            const double* p = boundary.point(w);
            chord = std::max(chord, std::hypot(p[0] - v[0], p[1] - v[1]));
        }
        const double la = std::hypot(a[0] - v[0], a[1] - v[1]);
        const double lb = std::hypot(b[0] - v[0], b[1] - v[1]);
        double dx = -((a[0] - v[0]) / la + (b[0] - v[0]) / lb);
        double dy = -((a[1] - v[1]) / la + (b[1] - v[1]) / lb);
        const double ld = std::hypot(dx, dy);
        dx /= ld;
        dy /= ld;
        std::size_t stretched_behind = 0;
        const tri::Triangulation2& mesh = three.mesh.mesh;
        for (tri::VertIdx u = 0; u < mesh.vertex_count(); ++u) {
            const double* p = mesh.point(u);
            const double along = (p[0] - v[0]) * dx + (p[1] - v[1]) * dy;
            const double off = (p[0] - v[0]) * -dy + (p[1] - v[1]) * dx;
            if (!(along > 0 && along < chord && std::fabs(off) < 0.1 * chord)) continue;
            const double size_along = 1 / gen::metric_length(three.metrics[u], dx, dy);
            const double size_across = 1 / gen::metric_length(three.metrics[u], -dy, dx);
            if (size_along >= 5 * size_across) ++stretched_behind;
        }
        std::cout << "trailing edge (" << v[0] << ", " << v[1] << "), chord " << chord << ": "
                  << stretched_behind << " stretched points behind it\n";
        EXPECT_GT(stretched_behind, 20u);
    }
}

TEST(StretchedDelaunay2d, WakeScaledGivesTheSameMeshScaled) {
    const gen::StretchedDelaunayResult2 reference = run_wake(gen::SampleDomain::Naca0012, 0, 2);
    for (const int k : {600, -600}) {
        const gen::StretchedDelaunayResult2 r = run_wake(gen::SampleDomain::Naca0012, k, 2);
        EXPECT_EQ(r.mesh.mesh.triangles, reference.mesh.mesh.triangles) << "2^" << k;
        EXPECT_TRUE(
            exactmesh::testing::coordinates_scaled_by(r.mesh.mesh.xy, reference.mesh.mesh.xy, k));
        EXPECT_EQ(r.counters.wake_points, reference.counters.wake_points);
        EXPECT_EQ(r.counters.wake_dropped, reference.counters.wake_dropped);
    }
}

TEST(StretchedDelaunay2d, StaggeredLayersGiveNinetyFivePercentUnitEdges) {
    // Issue 14's goal, as the command meshes the built-in domains (their own size functions as
    // the far-field size) with --staggered-layers: at least 95% of the edges unit in the mesh's
    // own metric (measured 95.8% on the NACA 0012, 98.1% on the three-element domain; 83.7%
    // and 93.9% with the default right-angled cells).
    for (const gen::SampleDomain d :
         {gen::SampleDomain::Naca0012, gen::SampleDomain::ThreeElement}) {
        const Domain domain = scaled(d, 0);
        const gen::MeshDomain2 mesh_domain(domain.pslg());
        gen::StretchedDelaunayOptions2 options;
        options.first_height = 1e-4;
        options.far_field_size = gen::sample_domain_size(d);
        options.staggered_layers = true;
        const gen::StretchedDelaunayResult2 r = gen::stretched_delaunay_2d(mesh_domain, options);
        expect_valid(domain, r);
        const gen::MetricQualityReport2 q = quality(r);
        std::cout << gen::sample_domain_name(d) << ", its own size: " << q.unit_length_share
                  << " unit metric edges\n";
        EXPECT_GE(q.unit_length_share, 0.95) << gen::sample_domain_name(d);
    }
}

TEST(StretchedDelaunay2d, SwapsChangeTheEuclideanTriangulation) {
    const Domain domain = scaled(gen::SampleDomain::Naca0012, 0);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = 1e-4;
    options.point_smoothing_passes = 0;
    const gen::StretchedDelaunayResult2 swapped = gen::stretched_delaunay_2d(mesh_domain, options);
    EXPECT_GT(swapped.counters.swaps, 0u);
    // The Euclidean CDT of the same points and pieces (step 4's triangulation): the in-ellipse
    // swaps replaced some of its edges.
    const tri::Cdt2Result euclidean = tri::constrained_delaunay_2d(
        tri::Pslg{swapped.mesh.mesh.xy, swapped.mesh.pieces, domain.holes, {}});
    EXPECT_EQ(euclidean.mesh.triangle_count(), swapped.mesh.mesh.triangle_count());
    const std::set<std::pair<tri::VertIdx, tri::VertIdx>> before = edges(euclidean.mesh);
    const std::set<std::pair<tri::VertIdx, tri::VertIdx>> after = edges(swapped.mesh.mesh);
    std::size_t changed = 0;
    for (const auto& e : after) changed += before.count(e) == 0 ? 1 : 0;
    std::cout << "edges changed by the in-ellipse swaps: " << changed << " of " << after.size()
              << " (" << swapped.counters.swaps << " swaps)\n";
    EXPECT_GT(changed, 0u);
}

gen::StretchedDelaunayResult2 run_scaled(int k, bool given_size, bool staggered) {
    const Domain domain = scaled(gen::SampleDomain::Naca0012, k);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = std::ldexp(1e-3, k);
    if (given_size) options.far_field_size = gen::SizeFunction::uniform(std::ldexp(0.25, k));
    options.staggered_layers = staggered;
    gen::StretchedDelaunayResult2 r = gen::stretched_delaunay_2d(mesh_domain, options);
    expect_valid(domain, r);
    return r;
}

TEST(StretchedDelaunay2d, ScaledDomainGivesTheSameMeshScaled) {
    // The far-field size graded from the boundary (scaled with it), then a given one; right-
    // angled cells (the default), then staggered layers.
    for (const bool staggered : {false, true}) {
        for (const bool given_size : {false, true}) {
            const gen::StretchedDelaunayResult2 reference = run_scaled(0, given_size, staggered);
            for (const int k : {600, -600}) {
                const gen::StretchedDelaunayResult2 r = run_scaled(k, given_size, staggered);
                EXPECT_EQ(r.mesh.mesh.triangles, reference.mesh.mesh.triangles)
                    << "2^" << k << (staggered ? " staggered" : "");
                EXPECT_TRUE(exactmesh::testing::coordinates_scaled_by(r.mesh.mesh.xy,
                                                                      reference.mesh.mesh.xy, k));
                EXPECT_EQ(r.counters.swaps, reference.counters.swaps);
                EXPECT_EQ(r.counters.smoothing_moves, reference.counters.smoothing_moves);
            }
        }
    }
}

TEST(StretchedDelaunay2d, DomainWithoutComponentsGetsTheFarFieldOnly) {
    const Domain domain = scaled(gen::SampleDomain::SquareWithHoles, 0);
    // The holes are components too; the outer square alone has none.
    const std::vector<double> xy(domain.xy.begin(), domain.xy.begin() + 8);
    const std::vector<tri::VertIdx> segments = {0, 1, 1, 2, 2, 3, 3, 0};
    const gen::MeshDomain2 mesh_domain(tri::Pslg{xy, segments, {}, {}});
    gen::StretchedDelaunayOptions2 options;
    options.far_field_size = gen::SizeFunction::uniform(0.05);
    const gen::StretchedDelaunayResult2 r = gen::stretched_delaunay_2d(mesh_domain, options);
    const tri::CheckReport report = tri::detail::check_constrained_mesh_2d(
        r.mesh.mesh, r.mesh.input_vertex_count, segments, r.mesh.pieces, {}, false);
    EXPECT_TRUE(report.ok) << report.problem;
    EXPECT_EQ(r.counters.components, 0u);
    EXPECT_EQ(r.counters.omesh_points, 0u);
    EXPECT_GT(r.mesh.mesh.triangle_count(), 400u);
    const gen::StretchedDelaunayResult2 holes = run(domain, 1e-3);
    expect_valid(domain, holes);
    EXPECT_EQ(holes.counters.components, 3u);
}

TEST(StretchedDelaunay2d, UniformlySampledAirfoilReachesAspectRatio1000) {
    // The airfoil sampled uniformly (finer with EXACTMESH_TEST_SCALE above 1; never coarser than
    // 0.02, which the aspect ratio asked for needs: at the sanitizer pass's 0.02 the airfoil
    // would have a handful of vertices), a first height 1000 times below its spacing.
    const double spacing = 0.02 / std::max(1.0, exactmesh::testing::test_scale());
    const Domain domain =
        scaled(gen::SampleDomain::Naca0012, 0, gen::SizeFunction::uniform(spacing));
    const gen::StretchedDelaunayResult2 r = run(domain, spacing / 1000);
    expect_valid(domain, r);
    const auto [median, largest] = wall_aspect_ratios(r.mesh.mesh, 4, r.mesh.input_vertex_count);
    print("naca0012, uniform sampling", r, median, largest);
    // A few stay where the swap would not lower the pair's largest angle (measured 0.15% to
    // 0.34% of the triangles).
    EXPECT_LT(flat_in_metric_above_150(r), r.mesh.mesh.triangle_count() / 200);
    EXPECT_GE(median, 500.0);
}

TEST(StretchedDelaunay2d, BadOptionsAreInputErrors) {
    const Domain domain = scaled(gen::SampleDomain::Naca0012, 0);
    const gen::MeshDomain2 mesh_domain(domain.pslg());
    gen::StretchedDelaunayOptions2 options;
    options.first_height = 0;
    EXPECT_THROW(gen::stretched_delaunay_2d(mesh_domain, options), exactmesh::InputError);
    options.first_height = 1e-3;
    options.growth = 0.5;
    EXPECT_THROW(gen::stretched_delaunay_2d(mesh_domain, options), exactmesh::InputError);
    options.growth = 1.2;
    options.wake_length = -1;
    EXPECT_THROW(gen::stretched_delaunay_2d(mesh_domain, options), exactmesh::InputError);
    options.wake_length = std::numeric_limits<double>::infinity();
    EXPECT_THROW(gen::stretched_delaunay_2d(mesh_domain, options), exactmesh::InputError);
    options.wake_length = 0;
    // An airfoil of 4000 wall vertices with 10000 uniform layers of 1e-9 each: 4 10^7 points,
    // refused before any point is made.
    const Domain fine = scaled(gen::SampleDomain::Naca0012, 0, gen::SizeFunction::uniform(5e-4));
    const gen::MeshDomain2 fine_domain(fine.pslg());
    options.growth = 1;
    options.first_height = 1e-9;
    options.max_layers = 10000;
    try {
        gen::stretched_delaunay_2d(fine_domain, options);
        FAIL() << "no error";
    } catch (const exactmesh::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ask for"), std::string::npos) << e.what();
    }
}

}  // namespace
