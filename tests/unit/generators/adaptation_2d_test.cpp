// SPDX-License-Identifier: MIT
// Issue 13, the 2D adaptation foundation: edge indicators (linear fields have no second
// difference; every indicator the same bit for bit at 2^±600), the flagging rules (threshold,
// budget, closure), P1 transfer by exact location (linear fields reproduced, vertices exact,
// points on edges the same from both sides, points outside NaN), the interpolation error, and
// Delaunay point-insertion adaptation on every sample domain: after every cycle the exact check
// (constrained Delaunay, pieces, input vertices fixed, curve points on their curve), the error
// falls, a vertex budget holds, and the same run on the domain scaled by 2^±600 gives the same
// mesh scaled.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/field_transfer.hpp"
#include "generators/adaptation/indicator_size_field.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "tests/support/adaptation_fixtures_2d.hpp"
#include "tests/support/scaled_coordinates.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using DomainMesh = em::testing::SampleDomainMesh;

DomainMesh domain_mesh(gen::SampleDomain d, double scale = 1.0, double size = 0) {
    return em::testing::sample_domain_mesh(d, scale, size);
}

using em::testing::front_field;

gen::AnalyticField linear_field() {
    return {"linear", [](double x, double y, double, double) { return 2 * x - 3 * y + 1; }};
}

}  // namespace

TEST(Generators_EdgeIndicators, LinearFieldsHaveNoSecondDifference) {
    const DomainMesh m = domain_mesh(gen::SampleDomain::SquareWithHoles);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const std::vector<double> values = gen::sample_field(linear_field(), mesh.xy, 2, 0);
    const int e = gen::unit_scale_exponent(mesh.xy, 2, mesh.triangles);
    const std::vector<double> unit = gen::scaled_coordinates(mesh.xy, e);
    const std::vector<double> g = gen::recover_gradients(unit, 2, mesh.triangles, values);
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(mesh.triangles);
    // The gradient in unit coordinates is the field's gradient times 2^e.
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        EXPECT_NEAR(g[2 * v], std::ldexp(2.0, e), 1e-9);
        EXPECT_NEAR(g[2 * v + 1], std::ldexp(-3.0, e), 1e-9);
    }
    const auto first =
        gen::edge_indicator(gen::EdgeIndicator::FirstDifference, unit, 2, edges, values, g);
    const auto second =
        gen::edge_indicator(gen::EdgeIndicator::SecondDifference, unit, 2, edges, values, g);
    const auto loehner =
        gen::edge_indicator(gen::EdgeIndicator::Loehner, unit, 2, edges, values, g);
    for (std::size_t k = 0; k < first.size(); ++k) {
        EXPECT_EQ(first[k], std::fabs(values[edges[2 * k + 1]] - values[edges[2 * k]]));
        EXPECT_LE(second[k], 1e-9 * (first[k] + 1e-300));
        EXPECT_LE(loehner[k], 1e-9);
        EXPECT_GE(loehner[k], 0.0);
    }
}

TEST(Generators_EdgeIndicators, SameBitForBitAtEveryPowerOfTwoScale) {
    const DomainMesh m = domain_mesh(gen::SampleDomain::Key);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const std::vector<double> values = gen::sample_field(front_field(), mesh.xy, 2, 0);
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(mesh.triangles);
    for (const gen::EdgeIndicator indicator : gen::kAllEdgeIndicators) {
        std::vector<double> reference;
        for (const int k : {0, 600, -600}) {
            std::vector<double> xy = mesh.xy;
            for (double& c : xy) c = std::ldexp(c, k);
            const int e = gen::unit_scale_exponent(xy, 2, mesh.triangles);
            const std::vector<double> unit = gen::scaled_coordinates(xy, e);
            const std::vector<double> g = gen::recover_gradients(unit, 2, mesh.triangles, values);
            const std::vector<double> ind =
                gen::edge_indicator(indicator, unit, 2, edges, values, g);
            for (const double x : ind) ASSERT_TRUE(std::isfinite(x));
            if (k == 0)
                reference = ind;
            else
                EXPECT_EQ(ind, reference) << gen::edge_indicator_name(indicator) << " at 2^" << k;
        }
    }
    EXPECT_THROW((void)gen::edge_indicator_from_name("curvature"), em::InputError);
}

TEST(Generators_EdgeFlags, ThresholdBudgetAndClosure) {
    const std::vector<double> ind{1, 5, 0, 2, 5, 3};
    // Mean 16 / 6: above 1 x mean: 5, 5, 3.
    EXPECT_EQ(gen::flag_above_mean(ind, 1.0), (std::vector<std::uint8_t>{0, 1, 0, 0, 1, 1}));
    // The two largest, ties by the lower number; zero is never flagged.
    EXPECT_EQ(gen::flag_largest(ind, 2), (std::vector<std::uint8_t>{0, 1, 0, 0, 1, 0}));
    EXPECT_EQ(gen::flag_largest(ind, 6), (std::vector<std::uint8_t>{1, 1, 0, 1, 1, 1}));

    const DomainMesh m = domain_mesh(gen::SampleDomain::SquareWithHoles);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(mesh.triangles);
    std::vector<double> indicator(edges.size() / 2);
    std::mt19937_64 random(7);
    for (double& x : indicator) x = std::uniform_real_distribution<double>(0, 1)(random);
    std::uint64_t flagged = 0, closure = 0;
    const auto flags = gen::refinement_flags(mesh.triangles, 2, edges, indicator, 1.5, 0, false,
                                             &flagged, &closure);
    // Closed (one pass, on the indicator's flags): every triangle with an edge the indicator
    // flagged has all three flagged; an edge is flagged only by the indicator or by a triangle
    // with such an edge.
    const auto by_indicator = gen::flag_above_mean(indicator, 1.5);
    std::vector<std::uint8_t> expected(by_indicator);
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        std::uint32_t e[3];
        int n = 0;
        for (int k = 0; k < 3; ++k) {
            e[k] = gen::find_mesh_edge(edges, mesh.triangles[3 * t + k],
                                       mesh.triangles[3 * t + (k + 1) % 3]);
            n += by_indicator[e[k]];
        }
        if (n > 0) expected[e[0]] = expected[e[1]] = expected[e[2]] = 1;
    }
    EXPECT_EQ(flags, expected);
    EXPECT_EQ(flagged + closure,
              static_cast<std::uint64_t>(std::count(flags.begin(), flags.end(), 1)));
    // A budget of 40 new vertices: the closure fits it.
    const auto budgeted = gen::refinement_flags(mesh.triangles, 2, edges, indicator, 1.5, 40, true,
                                                &flagged, &closure);
    const auto count = std::count(budgeted.begin(), budgeted.end(), 1);
    EXPECT_LE(count, 40);
    EXPECT_GT(count, 0);
}

TEST(Generators_IndicatorSizeField, AFixedReferenceMeanMakesTheSizesAbsolute) {
    // Edges (0,1), (0,2) of length 1 and (3,4) elsewhere; a second-order indicator, threshold 1:
    // an edge of length h asks for h sqrt(target / I).
    const std::vector<double> xy{0, 0, 1, 0, 0, 1, 5, 5, 5, 6};
    const std::vector<tri::VertIdx> edges{0, 1, 0, 2, 3, 4};
    const auto sizes = [&](std::vector<double> indicator, double reference) {
        return gen::indicator_vertex_sizes(
            xy, 2, edges, indicator, gen::EdgeIndicator::SecondDifference, 1.0, 4.0, reference);
    };
    // The current mean (2): the first edge asks for sqrt(1/2), the others for sqrt(2).
    const std::vector<double> relative = sizes({4, 1, 1}, 0);
    EXPECT_DOUBLE_EQ(relative[0], std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(relative[2], std::sqrt(2.0));
    // A fixed mean of 4: lengths 1 and 2, whatever the far edge's indicator; the current mean
    // would move them (the transient's wake, indicator 0, would make the front finer and finer).
    for (const double far : {1.0, 0.0, 100.0}) {
        const std::vector<double> fixed = sizes({4, 1, far}, 4.0);
        EXPECT_DOUBLE_EQ(fixed[0], 1.0);
        EXPECT_DOUBLE_EQ(fixed[1], 1.0);
        EXPECT_DOUBLE_EQ(fixed[2], 2.0);
    }
    EXPECT_NE(sizes({4, 1, 0}, 0)[0], relative[0]);
}

TEST(Generators_MeshEdgeIndex, FindsWhatTheBinarySearchFinds) {
    const DomainMesh m = domain_mesh(gen::SampleDomain::Key);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(mesh.triangles);
    const gen::MeshEdgeIndex index(edges);
    for (std::uint32_t e = 0; e < edges.size() / 2; ++e) {
        ASSERT_EQ(index.find(edges[2 * e], edges[2 * e + 1]), e);
        ASSERT_EQ(index.find(edges[2 * e + 1], edges[2 * e]), e);
    }
    // Every vertex pair of a few vertices, edges or not, and vertices past the last edge.
    const tri::VertIdx n = mesh.vertex_count();
    for (tri::VertIdx u = 0; u < std::min<tri::VertIdx>(n, 40); ++u)
        for (tri::VertIdx v = 0; v < n + 3; ++v)
            ASSERT_EQ(index.find(u, v), gen::find_mesh_edge(edges, u, v)) << u << ' ' << v;
    EXPECT_EQ(gen::MeshEdgeIndex({}).find(0, 1), tri::kNone);
}

TEST(Generators_FieldTransfer, LinearFieldsVerticesEdgesAndOutside) {
    const DomainMesh m = domain_mesh(gen::SampleDomain::Naca0012);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const std::vector<double> values = gen::sample_field(linear_field(), mesh.xy, 2, 0);
    std::vector<double> points;
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> x(-1.5, 2.5), y(-2, 2);
    for (int i = 0; i < 2000; ++i) points.insert(points.end(), {x(random), y(random)});
    const std::vector<double> moved =
        gen::transfer_field_2d(mesh.xy, mesh.triangles, values, points);
    std::size_t located = 0;
    for (std::size_t i = 0; i < moved.size(); ++i) {
        if (std::isnan(moved[i])) continue;  // inside the airfoil
        ++located;
        EXPECT_NEAR(moved[i], 2 * points[2 * i] - 3 * points[2 * i + 1] + 1, 1e-12);
    }
    EXPECT_GT(located, 1900u);
    // At the vertices: the vertex's value exactly.
    EXPECT_EQ(gen::transfer_field_2d(mesh.xy, mesh.triangles, values, mesh.xy), values);
    // Outside the far-field box: NaN.
    const std::vector<double> far{10.0, 10.0};
    EXPECT_TRUE(std::isnan(gen::transfer_field_2d(mesh.xy, mesh.triangles, values, far)[0]));
}

TEST(Generators_FieldTransfer, PointsOnEdgesTakeTheEdgeValueWhicheverTriangle) {
    // A dyadic grid split along both diagonals' directions: midpoints of its edges are exact,
    // so they lie exactly on the edge; a nonlinear field shows whether a third vertex leaked in.
    std::vector<double> xy;
    std::vector<tri::VertIdx> triangles;
    const int n = 8;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) xy.insert(xy.end(), {i / 8.0, j / 8.0});
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const tri::VertIdx a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
            triangles.insert(triangles.end(), {a, b, d, a, d, c});
        }
    std::vector<double> values(xy.size() / 2);
    for (std::size_t v = 0; v < values.size(); ++v)
        values[v] = std::sin(7 * xy[2 * v]) * std::cos(5 * xy[2 * v + 1]);
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(triangles);
    std::vector<double> mids;
    for (std::size_t e = 0; e < edges.size() / 2; ++e) {
        const double* a = &xy[2 * edges[2 * e]];
        const double* b = &xy[2 * edges[2 * e + 1]];
        mids.insert(mids.end(), {0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]});
    }
    const std::vector<double> at = gen::transfer_field_2d(xy, triangles, values, mids);
    // The reversed triangle order makes the locator find the other triangle of each edge.
    std::vector<tri::VertIdx> reversed;
    for (std::size_t t = triangles.size() / 3; t-- > 0;)
        reversed.insert(reversed.end(), triangles.begin() + 3 * t, triangles.begin() + 3 * t + 3);
    EXPECT_EQ(gen::transfer_field_2d(xy, reversed, values, mids), at);
    for (std::size_t e = 0; e < edges.size() / 2; ++e)
        EXPECT_NEAR(at[e], 0.5 * values[edges[2 * e]] + 0.5 * values[edges[2 * e + 1]], 1e-15);
}

TEST(Generators_InterpolationError, ZeroForLinearFieldsPositiveOtherwise) {
    const DomainMesh m = domain_mesh(gen::SampleDomain::SquareWithHoles);
    const tri::Triangulation2& mesh = m.mesh.mesh;
    const gen::AnalyticField linear = linear_field();
    const auto e0 = gen::interpolation_error(mesh.xy, 2, mesh.triangles,
                                             gen::sample_field(linear, mesh.xy, 2, 0), linear, 0);
    EXPECT_LE(e0.maximum, 1e-14);
    const gen::AnalyticField front = front_field();
    const auto e1 = gen::interpolation_error(mesh.xy, 2, mesh.triangles,
                                             gen::sample_field(front, mesh.xy, 2, 0), front, 0);
    EXPECT_GT(e1.maximum, 0.01);
    EXPECT_GT(e1.l2, 0.0);
    EXPECT_LT(e1.l2, e1.maximum);
    const gen::AnalyticField bad{
        "log(x - 0.5)", [](double x, double, double, double) { return std::log(x - 0.5); }};
    EXPECT_THROW((void)gen::sample_field(bad, mesh.xy, 2, 0), em::InputError);
}

TEST(Generators_InsertionAdaptation2, EveryDomainEveryCycleValidAndTheErrorFalls) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        DomainMesh m = domain_mesh(d);
        const gen::AnalyticField field = front_field();
        gen::AdaptiveMesh2 state =
            gen::make_adaptive_mesh_2d(std::move(m.mesh), m.domain.xy, m.domain.segments,
                                       m.domain.holes, m.domain.curves, m.domain.segment_curves);
        state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
        const std::string name(gen::sample_domain_name(d));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << name;
        double previous =
            gen::interpolation_error(state.mesh.xy, 2, state.mesh.triangles, state.values, field, 0)
                .maximum;
        gen::AdaptationOptions options;
        options.smoothing_sweeps = d == gen::SampleDomain::Key ? 2 : 0;
        gen::InsertionCounters2 counters;
        for (int cycle = 0; cycle < 3; ++cycle) {
            const std::uint32_t before = state.mesh.vertex_count();
            ASSERT_TRUE(gen::insertion_cycle_2d(state, options, {&field, 0}, counters)) << name;
            EXPECT_GT(state.mesh.vertex_count(), before);
            ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << name << " " << cycle;
            const double error = gen::interpolation_error(state.mesh.xy, 2, state.mesh.triangles,
                                                          state.values, field, 0)
                                     .maximum;
            EXPECT_LE(error, previous * 1.05) << name << " cycle " << cycle;
            previous = error;
        }
        EXPECT_GT(counters.inserted, 0u);
        // Boundary points on a domain with curves go on them (unless a retry put them on chords).
        if (!m.domain.curves.empty() && counters.boundary_points > 0 &&
            counters.curve_retries == 0) {
            EXPECT_GT(counters.curve_points, 0u) << name;
        }
    }
}

TEST(Generators_InsertionAdaptation2, VertexBudgetHoldsAndAFileFieldIsTransferred) {
    DomainMesh m = domain_mesh(gen::SampleDomain::Naca0012);
    const gen::AnalyticField field = front_field();
    gen::AdaptiveMesh2 state =
        gen::make_adaptive_mesh_2d(std::move(m.mesh), m.domain.xy, m.domain.segments,
                                   m.domain.holes, m.domain.curves, m.domain.segment_curves);
    state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
    gen::AdaptationOptions options;
    options.max_vertices = state.mesh.vertex_count() + 500;
    options.smoothing_sweeps = 1;
    gen::InsertionCounters2 counters;
    for (int cycle = 0; cycle < 5; ++cycle) {
        const std::vector<double> old_xy = state.mesh.xy;
        const std::vector<double> old_values = state.values;
        const std::uint32_t old_count = state.mesh.vertex_count();
        // No analytic field: the values are carried over (injection at vertices that stay).
        if (!gen::insertion_cycle_2d(state, options, {nullptr, 0}, counters)) break;
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "");
        for (std::uint32_t v = 0; v < old_count; ++v)
            if (state.mesh.xy[2 * v] == old_xy[2 * v] &&
                state.mesh.xy[2 * v + 1] == old_xy[2 * v + 1]) {
                EXPECT_EQ(state.values[v], old_values[v]) << v;
            }
    }
    EXPECT_LE(state.mesh.vertex_count(), options.max_vertices);
    EXPECT_GT(state.mesh.vertex_count(), options.max_vertices - 500);
}

TEST(Generators_InsertionAdaptation2, SameMeshScaledAtTwoToThePlusMinus600) {
    tri::Triangulation2 reference;
    for (const int k : {0, 600, -600}) {
        const double scale = std::ldexp(1.0, k);
        DomainMesh m = domain_mesh(gen::SampleDomain::SquareWithHoles, scale, 0.08);
        const gen::AnalyticField field = front_field(scale);
        // The PSLG as a .poly gives it: no curves (scaled curves would be other functions).
        gen::AdaptiveMesh2 state = gen::make_adaptive_mesh_2d(
            std::move(m.mesh), m.domain.xy, m.domain.segments, m.domain.holes, {}, {});
        state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
        gen::AdaptationOptions options;
        options.smoothing_sweeps = 1;
        gen::InsertionCounters2 counters;
        for (int cycle = 0; cycle < 2; ++cycle)
            ASSERT_TRUE(gen::insertion_cycle_2d(state, options, {&field, 0}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "");
        if (k == 0) {
            reference = state.mesh;
            continue;
        }
        EXPECT_EQ(state.mesh.triangles, reference.triangles) << "2^" << k;
        ASSERT_TRUE(exactmesh::testing::coordinates_scaled_by(state.mesh.xy, reference.xy, k));
    }
}

TEST(Generators_Derefinement2, TheAngleGuardAllowsRegularStarsAndRefusesSlivers) {
    // A 5 x 5 grid with its diagonals by SoS: every interior vertex's hole keeps angles >= 20
    // degrees (45-degree corners), so the guard lets each go.
    std::vector<double> xy;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) xy.insert(xy.end(), {1.0 * i, 1.0 * j});
    const tri::Triangulation2 mesh = tri::constrained_delaunay_2d({xy, {}, {}, {}}, {}).mesh;
    std::vector<tri::TriIdx> star;
    const auto star_of = [&](const tri::Triangulation2& m, tri::VertIdx v) {
        star.clear();
        for (std::size_t t = 0; t < m.triangle_count(); ++t)
            for (int k = 0; k < 3; ++k)
                if (m.triangles[3 * t + k] == v) star.push_back(static_cast<tri::TriIdx>(t));
        return std::span<const tri::TriIdx>(star);
    };
    for (const tri::VertIdx v : {6u, 7u, 8u, 11u, 12u, 13u, 16u, 17u, 18u})
        EXPECT_TRUE(gen::removal_keeps_angles_2d(mesh, star_of(mesh, v), v)) << v;
    // A vertex in the middle of a straight bottom side under a flat trapezoid: its star's
    // smallest angle is atan(0.2) (11.3 degrees); removing it (the two boundary edges merge)
    // leaves a triangle with atan(0.1 / 1.5) (3.8 degrees) at a bottom corner: refused.
    const std::vector<double> flat{-1, 0, 1, 0, 0.5, 0.1, -0.5, 0.1, 0, 0};
    const tri::Triangulation2 m2 = tri::constrained_delaunay_2d({flat, {}, {}, {}}, {}).mesh;
    ASSERT_EQ(star_of(m2, 4).size(), 3u);
    EXPECT_FALSE(gen::removal_keeps_angles_2d(m2, star_of(m2, 4), 4));
}
