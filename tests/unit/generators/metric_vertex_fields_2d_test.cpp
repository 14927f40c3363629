// SPDX-License-Identifier: MIT
// Metrics per vertex of a triangulation: smoothing (generators/stretched/metric_smoothing_2d.hpp)
// keeps a constant field, moves a spike by the log-Euclidean rule, respects per-vertex weights;
// gradation (metric_gradation_2d.hpp) bounds the growth along every edge by 1 + beta * l in
// every direction, reaches its fixed point, keeps the smallest metric, and is scale invariant.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "base/errors.hpp"
#include "generators/stretched/metric_gradation_2d.hpp"
#include "generators/stretched/metric_smoothing_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

/// A 3 x 3 grid of vertices (spacing 1) split into 8 triangles; vertex 4 is the centre.
tri::Triangulation2 grid_mesh() {
    tri::Triangulation2 mesh;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i) mesh.xy.push_back(i), mesh.xy.push_back(j);
    for (std::uint32_t j = 0; j < 2; ++j) {
        for (std::uint32_t i = 0; i < 2; ++i) {
            const std::uint32_t a = 3 * j + i, b = a + 1, c = a + 4, d = a + 3;
            mesh.triangles.insert(mesh.triangles.end(), {a, b, c, a, c, d});
        }
    }
    return mesh;
}

/// Every edge (both ways) and 72 directions: l_q(v) >= l_p(v) / (1 + beta l_p(pq)).
void expect_graded(const tri::Triangulation2& mesh, const std::vector<gen::Metric2>& metrics,
                   double beta) {
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t p = mesh.triangles[3 * t + k],
                                q = mesh.triangles[3 * t + (k + 1) % 3];
            for (const auto& [a, b] : {std::pair{p, q}, std::pair{q, p}}) {
                const double* x = mesh.point(a);
                const double* y = mesh.point(b);
                const double eta =
                    1 + beta * gen::metric_length(metrics[a], y[0] - x[0], y[1] - x[1]);
                for (int d = 0; d < 72; ++d) {
                    const double vx = std::cos(d * 0.0872665), vy = std::sin(d * 0.0872665);
                    EXPECT_GE(gen::metric_length(metrics[b], vx, vy),
                              gen::metric_length(metrics[a], vx, vy) / eta * (1 - 1e-9))
                        << a << " -> " << b << " direction " << d;
                }
            }
        }
    }
}

}  // namespace

TEST(Generators_MetricSmoothing2d, ConstantSpikeAndWeights) {
    const tri::Triangulation2 mesh = grid_mesh();
    const gen::Metric2 m{0.5, 0.005, 0.8, -0.6};
    std::vector<gen::Metric2> constant(9, m);
    gen::smooth_vertex_metrics(mesh, constant, 5, 0.5);
    for (const gen::Metric2& at : constant) {
        // The same ellipse (its sizes may come back in the other order, h1 <= h2).
        for (int d = 0; d < 36; ++d) {
            const double vx = std::cos(d * 0.174533), vy = std::sin(d * 0.174533);
            const double expected = gen::metric_length(m, vx, vy);
            EXPECT_NEAR(gen::metric_length(at, vx, vy), expected, 1e-13 * expected) << d;
        }
    }
    // An isotropic spike at the centre (size e^-4 among sizes 1): one pass of weight 0.5 gives
    // the centre exp(0.5 * -4 + 0.5 * 0) = e^-2, and each of its 4 to 6 neighbours
    // exp(0.5 * 0 + 0.5 * (-4 / degree)).
    std::vector<gen::Metric2> spike(9, gen::isotropic(1));
    spike[4] = gen::isotropic(std::exp(-4.0));
    gen::smooth_vertex_metrics(mesh, spike, 1, 0.5);
    EXPECT_NEAR(spike[4].h1, std::exp(-2.0), 1e-14);
    EXPECT_NEAR(spike[1].h1, std::exp(-2.0 / 4), 1e-14);  // vertex 1: neighbours 0, 2, 4, 5
    EXPECT_NEAR(spike[0].h1, std::exp(-2.0 / 3), 1e-14);  // vertex 0: neighbours 1, 3, 4
    EXPECT_EQ(spike[2].h1, 1);                            // not a neighbour of the centre
    // Progressive: weight 0 at the centre (a wall) keeps it; weight 0 everywhere changes nothing.
    std::vector<gen::Metric2> held(9, gen::isotropic(1));
    held[4] = gen::isotropic(0.01);
    std::vector<double> weights(9, 0.5);
    weights[4] = 0;
    gen::smooth_vertex_metrics(mesh, held, 3, 0, weights);
    EXPECT_EQ(held[4].h1, 0.01);
    EXPECT_LT(held[1].h1, 1);
    EXPECT_THROW(gen::smooth_vertex_metrics(mesh, held, 1, 1.5), exactmesh::InputError);
    EXPECT_THROW(gen::smooth_vertex_metrics(mesh, held, -1, 0.5), exactmesh::InputError);
}

TEST(Generators_MetricGradation2d, BoundsGrowthAlongEdges) {
    const tri::Triangulation2 mesh = grid_mesh();
    std::vector<gen::Metric2> metrics(9, gen::isotropic(1));
    metrics[0] = gen::isotropic(0.01);
    const double beta = 0.1;
    const gen::GradationResult result = gen::limit_metric_gradation(mesh, metrics, beta);
    EXPECT_TRUE(result.converged);
    EXPECT_GT(result.corrections, 0u);
    EXPECT_EQ(metrics[0].h1, 0.01);  // the smallest metric is never changed
    // Vertex 1, one unit from vertex 0: l = 100 in its metric, so at most 0.01 * 11 = 0.11.
    EXPECT_NEAR(metrics[1].h1, 0.11, 1e-12);
    EXPECT_NEAR(metrics[1].h2, 0.11, 1e-12);
    // Vertex 4 across the diagonal (0, 4): at most 0.01 * (1 + 0.1 * 141.42...).
    EXPECT_LE(metrics[4].h1, 0.01 * (1 + beta * 100 * std::sqrt(2.0)) * (1 + 1e-12));
    expect_graded(mesh, metrics, beta);
}

TEST(Generators_MetricGradation2d, AnisotropicFixedPointAndScale) {
    const tri::Triangulation2 mesh = grid_mesh();
    std::vector<gen::Metric2> metrics(9, gen::isotropic(2));
    metrics[3] = gen::Metric2{1, 0.001, 0, 1};  // a boundary-layer needle at (0, 1)
    metrics[7] = gen::Metric2{0.05, 0.5, 0.6, 0.8};
    std::vector<gen::Metric2> original = metrics;
    const double beta = 0.3;
    const gen::GradationResult result = gen::limit_metric_gradation(mesh, metrics, beta);
    EXPECT_TRUE(result.converged);
    expect_graded(mesh, metrics, beta);
    // Only shrinks: every graded metric is at least as long as its original in all directions.
    for (std::size_t v = 0; v < 9; ++v) {
        for (int d = 0; d < 36; ++d) {
            const double vx = std::cos(d * 0.174533), vy = std::sin(d * 0.174533);
            EXPECT_GE(gen::metric_length(metrics[v], vx, vy),
                      gen::metric_length(original[v], vx, vy) * (1 - 1e-12));
        }
    }
    // The mesh and the metrics times 2^600 (and 2^-600): the same metrics times 2^k, bit for bit.
    for (const int k : {600, -600}) {
        tri::Triangulation2 scaled_mesh = mesh;
        for (double& x : scaled_mesh.xy) x = std::ldexp(x, k);
        std::vector<gen::Metric2> scaled = original;
        for (gen::Metric2& m : scaled) m.h1 = std::ldexp(m.h1, k), m.h2 = std::ldexp(m.h2, k);
        gen::limit_metric_gradation(scaled_mesh, scaled, beta);
        for (std::size_t v = 0; v < 9; ++v) {
            EXPECT_EQ(scaled[v].h1, std::ldexp(metrics[v].h1, k)) << k << " " << v;
            EXPECT_EQ(scaled[v].h2, std::ldexp(metrics[v].h2, k)) << k << " " << v;
            EXPECT_EQ(scaled[v].c, metrics[v].c);
        }
    }
    EXPECT_THROW(gen::limit_metric_gradation(mesh, metrics, -1), exactmesh::InputError);
}
