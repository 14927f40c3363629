// SPDX-License-Identifier: MIT
// Advancing front: every output is a valid mesh of its domain (exact check_conforming_mesh_2d:
// counter-clockwise triangles, no fold, closed by pieces, every segment a chain of pieces; no
// triangle outside the domain), on the four sample domains with their size functions, a square
// with a hole and a slit, graded sizes, and degenerate inputs (collinear vertices on segments, a
// tiny notch, nearly touching holes, a 5-degree wedge, ulp-scale features, a triangle); the
// wide search alone (no new point) triangulates every sample boundary; the mesh's boundary is
// exactly the discretized boundary (slit pieces with a triangle on both sides); edges follow the
// size within the measured bounds; the closure by constrained Delaunay triangulation (forced by
// a small budget) still gives a valid mesh; bad input raises InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "generators/mesh_2d/advancing_front_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "tests/support/generated_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using exactmesh::testing::add_loop;
using exactmesh::testing::from_domain;
using exactmesh::testing::Input;
using exactmesh::testing::square_with_hole_and_slit;

using Meshed = em::testing::GeneratedMesh2<gen::AdvancingFrontResult2>;

Meshed mesh(const Input& in, const gen::SizeFunction& size, bool closed_loops = true,
            std::uint64_t max_triangles = 0) {
    gen::AdvancingFrontOptions2 options;
    options.size = size;
    options.max_triangles = max_triangles;
    return em::testing::check_generated_mesh(gen::advancing_front_2d(in.pslg(), options), in, size,
                                             closed_loops, false);
}

void report(const std::string& name, const Meshed& m) {
    std::cout << name << ": triangles " << m.result.counters.triangles << ", min angle "
              << m.quality.min_angle << ", mean min angle " << m.quality.mean_min_angle
              << ", size ratio " << m.quality.size_ratio_min << " .. " << m.quality.size_ratio_max
              << ", closure " << m.result.counters.closure_triangles << ", wide "
              << m.result.counters.wide_searches << ", postponed "
              << m.result.counters.postponed_edges << "\n";
}

/// Measured on these inputs: edges are at most 1.76 times the size at their midpoint (an apex
/// reused within 0.65 delta of the ideal point lengthens its edges by up to that much); the
/// shortest are beside short input segments and small input angles (down to 0.002 of the size
/// at a 1e-4 notch in a mesh of size 0.05).
constexpr double kMaxSizeRatio = 1.8;

/// The exact checks, the size bound, and the measured angle bounds (degrees).
void expect_good(const std::string& name, const Meshed& m, double min_angle,
                 double mean_min_angle) {
    ASSERT_TRUE(m.check.ok) << name << ": " << m.check.problem;
    EXPECT_LE(m.check.max_size_ratio, kMaxSizeRatio) << name;
    EXPECT_GE(m.quality.min_angle, min_angle) << name;
    EXPECT_GE(m.quality.mean_min_angle, mean_min_angle) << name;
    EXPECT_EQ(m.result.counters.closure_triangles, 0u) << name;
    EXPECT_EQ(m.result.counters.triangles, m.result.mesh.mesh.triangle_count()) << name;
    EXPECT_EQ(m.result.counters.triangles,
              m.result.counters.new_points + m.result.counters.reused_points)
        << name;
}

/// Directed edges u -> v of the mesh's triangles.
std::set<std::pair<std::uint32_t, std::uint32_t>> directed_edges(const tri::Triangulation2& t) {
    std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (std::size_t e = 0; e < t.triangles.size(); ++e)
        edges.insert({t.triangles[e], t.triangles[e - e % 3 + (e + 1) % 3]});
    return edges;
}

}  // namespace

TEST(Generators_AdvancingFront, SampleDomainsWithTheirSizeFunctions) {
    // No angle guarantee: the smallest angles sit where fronts meet and move by degrees when
    // the size function changes in its last bits (naca0012: 22.1 before, 17.3 after the gamma
    // 1.5 source term became r sqrt(r)). Measured 17-22 (key 9.8, beside its 10-degree tooth);
    // the floor asserted is 15. Mean minimum angles 56.4, 47.6, 55.7, 50.5 (square-with-holes
    // 55.96 once boundary split points that rounded outside the domain moved one ulp in).
    const double min_angles[] = {15, 15, 9.5, 15}, means[] = {55.5, 47, 55, 50};
    std::size_t i = 0;
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const Input in = from_domain(gen::sample_domain(d, size));
        const Meshed m = mesh(in, size);
        const std::string name(gen::sample_domain_name(d));
        report(name, m);
        expect_good(name, m, min_angles[i], means[i]);
        EXPECT_GT(m.result.counters.new_points, 1000u) << name;
        EXPECT_GT(m.result.counters.reused_points, 1000u) << name;
        ++i;
    }
}

TEST(Generators_AdvancingFront, SquareWithHoleAndSlitAndItsBoundaryIsTheDiscretizedBoundary) {
    const Input in = square_with_hole_and_slit();
    const gen::SizeFunction size = gen::SizeFunction::uniform(0.05);
    const Meshed m = mesh(in, size, false);
    report("square with hole and slit", m);
    expect_good("square with hole and slit", m, 17.5, 55);  // measured 17.6, 55.1
    EXPECT_EQ(m.result.counters.wide_searches, 0u);
    // The boundary the generator started from (deterministic: the same call).
    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(in.pslg(), size);
    const auto edges = directed_edges(m.result.mesh.mesh);
    std::set<std::pair<std::uint32_t, std::uint32_t>> front, open;
    for (std::size_t e = 0; 2 * e + 1 < b.front.size(); ++e)
        front.insert({b.front[2 * e], b.front[2 * e + 1]});
    for (const auto& [u, v] : edges) {
        if (!edges.count({v, u})) open.insert({u, v});
    }
    // Every front edge is a triangle's edge (the slit's pieces on both sides) ...
    for (const auto& edge : front)
        EXPECT_TRUE(edges.count(edge)) << edge.first << "-" << edge.second;
    // ... and the edges with one triangle are exactly the front's, slit pieces aside.
    std::set<std::pair<std::uint32_t, std::uint32_t>> one_sided;
    std::size_t slit = 0;
    for (const auto& [u, v] : front) {
        if (front.count({v, u})) {
            ++slit;
        } else {
            one_sided.insert({u, v});
        }
    }
    EXPECT_EQ(slit, 2u * 4);  // the slit (length 0.2) in 4 pieces, both ways
    EXPECT_EQ(open, one_sided);
    EXPECT_EQ(m.result.mesh.pieces, b.pieces);
}

TEST(Generators_AdvancingFront, GradedSizesFromPointAndLineSources) {
    const Input in = square_with_hole_and_slit();
    const gen::SizeFunction point = gen::SizeFunction::sources({{0, 0, 0.005, 0.05, 1}}, {}, 0.1);
    const gen::SizeFunction line =
        gen::SizeFunction::sources({}, {{0.2, 0.9, 0.8, 0.9, 0.004, 0.05, 1.5}}, 0.08);
    const gen::SizeFunction both = gen::SizeFunction::sources(
        {{1, 0, 0.003, 0.02, 1}}, {{0, 0.2, 1, 0.25, 0.01, 0.1, 1}}, 0.06);
    // Measured: minimum angles 23.4, 20.9, 24.3; mean minimum angles 47.4, 49.9, 52.2.
    int k = 0;
    for (const gen::SizeFunction& size : {point, line, both}) {
        const std::string name = "graded " + std::to_string(k++);
        const Meshed m = mesh(in, size, false);
        report(name, m);
        expect_good(name, m, 15, 47);  // measured 19.8-20.9 (no guarantee; see above)
    }
    // Near the point source the mesh is fine: a triangle with a corner within 0.01 of (0, 0)
    // has edges no longer than 0.02.
    const Meshed m = mesh(in, point, false);
    const tri::Triangulation2& t = m.result.mesh.mesh;
    std::size_t near = 0;
    for (std::uint32_t f = 0; f < t.triangle_count(); ++f) {
        const double* p = t.point(t.triangles[3 * f]);
        if (std::hypot(p[0], p[1]) > 0.01) continue;
        ++near;
        for (unsigned j = 0; j < 3; ++j) {
            const double* u = t.point(t.triangles[3 * f + j]);
            const double* v = t.point(t.triangles[3 * f + (j + 1) % 3]);
            EXPECT_LT(std::hypot(u[0] - v[0], u[1] - v[1]), 0.02);
        }
    }
    EXPECT_GT(near, 3u);
}

TEST(Generators_AdvancingFront, GridLinesBesideFeaturesAtTheResolutionOfDoubles) {
    // Rounded crossings one ulp from lattice vertices: before discretize_domain_boundary kept
    // its split points in the triangles beside their piece, some landed on other pieces there
    // and these seeds ended in a GeometryError. Now each gives a valid mesh (dangling segments:
    // no closed-loop test).
    for (const std::uint64_t seed : {11, 14, 16, 25, 41, 54}) {
        const gen::PslgInput p =
            gen::generate_pslg(gen::PslgDistribution::GridLines,
                               60 + 20 * static_cast<std::uint32_t>(seed % 5), 30, seed);
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        for (std::size_t i = 0; i + 1 < p.xy.size(); i += 2) {
            x0 = std::min(x0, p.xy[i]), x1 = std::max(x1, p.xy[i]);
            y0 = std::min(y0, p.xy[i + 1]), y1 = std::max(y1, p.xy[i + 1]);
        }
        const Meshed m = mesh({p.xy, p.segments, p.holes, {}},
                              gen::SizeFunction::uniform(std::max(x1 - x0, y1 - y0) / 30), false);
        EXPECT_TRUE(m.check.ok) << "seed " << seed << ": " << m.check.problem;
        EXPECT_GT(m.result.mesh.mesh.triangle_count(), 0u) << "seed " << seed;
    }
}

TEST(Generators_AdvancingFront, DegenerateInputs) {
    const gen::SizeFunction h = gen::SizeFunction::uniform(0.05);
    {
        // Collinear vertices on the square's sides: consecutive segments in a line, and an
        // isolated vertex on a side (the CDT splits the side there).
        Input in;
        add_loop(in, {0, 0, 0.3, 0, 0.5, 0, 0.7, 0, 1, 0, 1, 0.5, 1, 1, 0.5, 1, 0, 1, 0, 0.5});
        in.xy.insert(in.xy.end(), {0.25, 1});
        const Meshed m = mesh(in, h);
        report("collinear", m);
        expect_good("collinear", m, 17.5, 56);  // measured 17.6, 56.5
    }
    {
        // A tiny notch (1e-4 wide, 1e-4 deep) in the bottom side.
        Input in;
        add_loop(in, {0, 0, 0.5, 0, 0.5, 1e-4, 0.5001, 1e-4, 0.5001, 0, 1, 0, 1, 1, 0, 1});
        const Meshed m = mesh(in, h);
        report("tiny notch", m);
        // A 1e-4 edge beside 0.05 ones makes 0.1-degree corners whatever the generator (the
        // size function does not grade towards the notch): measured 0.07, 55.4.
        expect_good("tiny notch", m, 0.05, 55);
    }
    {
        // Two square holes 1e-3 apart.
        Input in;
        add_loop(in, {0, 0, 1, 0, 1, 1, 0, 1});
        add_loop(in, {0.2, 0.3, 0.4995, 0.3, 0.4995, 0.7, 0.2, 0.7});
        add_loop(in, {0.5005, 0.3, 0.8, 0.3, 0.8, 0.7, 0.5005, 0.7});
        in.holes = {0.3, 0.5, 0.7, 0.5};
        const Meshed m = mesh(in, h);
        report("nearly touching holes", m);
        expect_good("nearly touching holes", m, 0.9, 53);  // measured 0.98 (in the gap), 53.1
    }
    {
        // A 5-degree wedge opening into a rectangle.
        Input in;
        const double c = 2 * std::cos(5 * std::numbers::pi / 180),
                     s = 2 * std::sin(5 * std::numbers::pi / 180);
        add_loop(in, {0, 0, 2, 0, 3, 0, 3, 2, 2, 2, c, s});
        const Meshed m = mesh(in, gen::SizeFunction::uniform(0.1));
        report("5-degree wedge", m);
        // Measured 4.96 (the input angle), 54.1; 53.9 with boundary points moved one ulp in.
        expect_good("5-degree wedge", m, 4.9, 53.5);
    }
    {
        // A boundary vertex one ulp below the top side's line, and a hole whose corner is 1e-15
        // from the bottom side: exact decisions at ulp scale.
        Input in;
        add_loop(in, {0, 0, 1, 0, 1, 1, 0.5, std::nextafter(1.0, 0.0), 0, 1});
        add_loop(in, {0.4, 1e-15, 0.6, 0.3, 0.3, 0.3});
        in.holes = {0.43, 0.25};
        const Meshed m = mesh(in, h);
        report("ulp-scale features", m);
        ASSERT_TRUE(m.check.ok) << m.check.problem;
        EXPECT_EQ(m.result.counters.closure_triangles, 0u);
        EXPECT_GT(m.quality.mean_min_angle, 50);
    }
    {
        // A triangle domain, coarse and fine.
        for (const double size : {0.6, 0.02}) {
            Input in;
            add_loop(in, {0, 0, 1, 0, 0.3, 0.8});
            const Meshed m = mesh(in, gen::SizeFunction::uniform(size));
            report("triangle " + std::to_string(size), m);
            // Measured 48.8 (4 triangles) and 28.4, 57.3; 25.0, 57.6 once the boundary points
            // that rounded outside the domain moved one ulp in (no angle guarantee: a front
            // meeting moves by degrees with the last bits of its points).
            expect_good("triangle", m, size > 0.1 ? 48 : 24, size > 0.1 ? 48 : 57);
        }
    }
}

TEST(Generators_AdvancingFront, TheBudgetClosesTheFrontByItsConstrainedDelaunayTriangulation) {
    const Input in = square_with_hole_and_slit();
    for (const std::uint64_t budget : {1u, 10u, 100u, 500u}) {
        const Meshed m = mesh(in, gen::SizeFunction::uniform(0.05), false, budget);
        ASSERT_TRUE(m.check.ok) << budget << ": " << m.check.problem;
        EXPECT_EQ(m.result.counters.closure_runs, 1u) << budget;
        EXPECT_GT(m.result.counters.closure_triangles, 0u) << budget;
        EXPECT_EQ(m.result.counters.triangles - m.result.counters.closure_triangles, budget);
        EXPECT_EQ(m.result.counters.triangles, m.result.mesh.mesh.triangle_count());
    }
    // Also with holes and several loops left open (the sample square's three holes).
    const Input holes = from_domain(gen::sample_domain(gen::SampleDomain::SquareWithHoles));
    const Meshed m = mesh(holes, gen::SizeFunction::uniform(0.05), true, 300);
    ASSERT_TRUE(m.check.ok) << m.check.problem;
    EXPECT_GT(m.result.counters.closure_triangles, 0u);
}

TEST(Generators_AdvancingFront, BadInputIsAnInputError) {
    const Input in = square_with_hole_and_slit();
    gen::AdvancingFrontOptions2 options;
    EXPECT_THROW(gen::advancing_front_2d(in.pslg(), options), em::InputError);  // unbounded
    options.size = gen::SizeFunction::uniform(0.1);
    Input nan = in;
    nan.xy[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(gen::advancing_front_2d(nan.pslg(), options), em::InputError);
    Input open;
    open.xy = {0, 0, 1, 0, 1, 1};
    open.segments = {0, 1, 1, 2};
    EXPECT_THROW(gen::advancing_front_2d(open.pslg(), options), em::InputError);
    // Each option out of its range, the others valid.
    const std::function<void(gen::AdvancingFrontOptions2&)> breaks[] = {
        [](gen::AdvancingFrontOptions2& o) { o.min_side_ratio = 0.4; },
        [](gen::AdvancingFrontOptions2& o) { o.max_side_ratio = 0.5; },
        [](gen::AdvancingFrontOptions2& o) { o.local_attempts = 0; },
        [](gen::AdvancingFrontOptions2& o) { o.min_shape = 2; },
        // A size that is not > 0 inside the domain.
        [](gen::AdvancingFrontOptions2& o) {
            o.size = gen::SizeFunction::analytic(
                [](double x, double) { return x < 0.5 ? 0.1 : -1.0; }, "negative on the right");
        },
    };
    for (const auto& make_bad : breaks) {
        gen::AdvancingFrontOptions2 bad = options;
        make_bad(bad);
        EXPECT_THROW(gen::advancing_front_2d(in.pslg(), bad), em::InputError);
    }
}

TEST(Generators_AdvancingFront, CounterListNamesEveryCounter) {
    const Input in = square_with_hole_and_slit();
    gen::AdvancingFrontOptions2 options;
    options.size = gen::SizeFunction::uniform(0.1);
    const gen::AdvancingFrontResult2 r = gen::advancing_front_2d(in.pslg(), options);
    const auto list = gen::counter_list(r.counters);
    ASSERT_EQ(list.size(), 13u);
    EXPECT_EQ(list[0].first, "triangles");
    EXPECT_EQ(list[0].second, r.mesh.mesh.triangle_count());
    std::set<std::string> names;
    for (const auto& [name, value] : list) names.insert(name);
    EXPECT_EQ(names.size(), list.size());
    EXPECT_GT(r.counters.crossing_tests, 0u);
    EXPECT_GT(r.counters.containment_tests, 0u);
    EXPECT_GT(r.counters.orient_calls, r.counters.crossing_tests);
}

TEST(Generators_AdvancingFront, TheWideSearchAloneTriangulatesTheBoundary) {
    // No new point is ever placeable and no first-attempt vertex has the shape asked for: every
    // triangle comes from the wide search over existing front vertices, which always finds one
    // (the constrained Delaunay triangle on the edge), so the closure is never needed.
    gen::AdvancingFrontOptions2 options;
    options.min_vertex_distance = 1e3;
    options.min_edge_distance = 1e3;
    options.min_shape = 1;
    options.local_attempts = 1;
    std::vector<Input> inputs{square_with_hole_and_slit()};
    for (const gen::SampleDomain d : gen::kAllSampleDomains)
        inputs.push_back(from_domain(gen::sample_domain(d)));
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const Input& in = inputs[i];
        options.size = gen::SizeFunction::uniform(i == 0 ? 0.05 : 0.2);
        const gen::AdvancingFrontResult2 r = gen::advancing_front_2d(in.pslg(), options);
        const auto check =
            em::testing::check_quality_mesh(r.mesh.mesh, r.mesh.input_vertex_count, in.xy,
                                            in.segments, r.mesh.pieces, {}, i != 0, false);
        ASSERT_TRUE(check.ok) << i << ": " << check.problem;
        EXPECT_EQ(r.counters.new_points, 0u) << i;
        EXPECT_EQ(r.counters.closure_triangles, 0u) << i;
        EXPECT_GT(r.counters.wide_searches, r.counters.triangles / 2) << i;
        EXPECT_EQ(r.counters.triangles, r.mesh.mesh.triangle_count()) << i;
        EXPECT_EQ(r.counters.triangles, r.counters.reused_points) << i;
    }
}

TEST(Generators_AdvancingFront, ProgressReportsTrianglesAndKeepsTheResult) {
    // The unit square at size 0.008: several calls of the hook (every 2^14 triangles made), each
    // with the expected count as total; the mesh is the same without the hook.
    const Input in = exactmesh::testing::polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::AdvancingFrontOptions2 options;
    options.size = gen::SizeFunction::uniform(0.008);
    const auto plain = gen::advancing_front_2d(in.pslg(), options);
    std::vector<std::uint64_t> done, total;
    options.cdt.progress.report = [&](std::uint64_t d, std::uint64_t t, const char* what) {
        EXPECT_EQ(std::string(what), "triangles made");
        done.push_back(d);
        total.push_back(t);
    };
    const auto hooked = gen::advancing_front_2d(in.pslg(), options);
    EXPECT_EQ(plain.mesh.mesh.triangles, hooked.mesh.mesh.triangles);
    EXPECT_EQ(plain.mesh.mesh.xy, hooked.mesh.mesh.xy);
    const std::uint64_t step = std::uint64_t{1} << em::ProgressCounter::kProgressShift;
    const std::uint64_t made = hooked.counters.triangles;
    ASSERT_GE(made, 2 * step);
    ASSERT_EQ(done.size(), made / step);
    for (std::size_t k = 0; k < done.size(); ++k) {
        EXPECT_EQ(done[k], (k + 1) * step);
        EXPECT_EQ(total[k], total[0]);
    }
    EXPECT_GT(total[0], made / 2);
    EXPECT_LT(total[0], 2 * made);
}
