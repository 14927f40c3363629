// SPDX-License-Identifier: MIT
// Issue 13, Steiner restart in 2D (steiner_restart_2d.hpp): on every sample domain with its
// curves and a front field, after every cycle the exact check (constrained Delaunay, pieces,
// input vertices fixed, curve points on their curve), every vertex the cycle kept at its index
// and curve points kept, the interpolation error falls, the mesh meets the indicator's size;
// a front that moves leaves derefinement behind it; a vertex budget holds by coarser sizes; a
// transferred field keeps the kept vertices' values; an input's repeated or exterior vertex
// stays unused (not an internal error); and the same run on a domain scaled by 2^±600 gives the
// same mesh scaled, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/power_of_two.hpp"
#include "tests/support/adaptation_fixtures_2d.hpp"
#include "tests/support/scaled_coordinates.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using DomainState = exactmesh::testing::SampleDomainState;

// A sample domain meshed by Delaunay refinement, scaled by `scale` (then without curves: a
// scaled curve would be another function), as an adaptive state with the field at t = 0.
DomainState domain_state(gen::SampleDomain d, const gen::AnalyticField& field, double scale = 1,
                         double size = 0) {
    return exactmesh::testing::sample_domain_state(d, field, scale, size, scale == 1);
}

using exactmesh::testing::front_field;

double max_error(const gen::AdaptiveMesh2& s, const gen::AnalyticField& field, double t) {
    return gen::interpolation_error(s.mesh.xy, 2, s.mesh.triangles, s.values, field, t).maximum;
}

std::pair<double, double> point(const gen::AdaptiveMesh2& s, std::size_t v) {
    return {s.mesh.xy[2 * v], s.mesh.xy[2 * v + 1]};
}

// The fractions of the mesh's edges no longer than the size at their midpoint, and not shorter
// than a quarter of it.
struct SizeFit {
    double within = 0, not_too_fine = 0;
};

SizeFit size_fit(const gen::AdaptiveMesh2& s, const gen::SizeFunction& size) {
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(s.mesh.triangles);
    std::size_t within = 0, coarse_enough = 0;
    const std::size_t n = edges.size() / 2;
    for (std::size_t e = 0; e < n; ++e) {
        const double* a = s.mesh.point(edges[2 * e]);
        const double* b = s.mesh.point(edges[2 * e + 1]);
        const double h = exactmesh::predicates::scale_free_norm(b[0] - a[0], b[1] - a[1]);
        const double wanted = size(0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]);
        within += h <= wanted ? 1 : 0;
        coarse_enough += h >= 0.25 * wanted ? 1 : 0;
    }
    const auto total = static_cast<double>(n);
    return {static_cast<double>(within) / total, static_cast<double>(coarse_enough) / total};
}

}  // namespace

TEST(Generators_SteinerRestart2, EveryDomainEveryCycleValidErrorFallsSizeMet) {
    const gen::AnalyticField field = front_field();
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        DomainState m = domain_state(d, field);
        gen::AdaptiveMesh2& state = m.state;
        const std::string name(gen::sample_domain_name(d));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << name;
        const double initial = max_error(state, field, 0);
        double previous = initial;
        const gen::AdaptationOptions options;
        gen::SteinerRestartCounters2 counters;
        for (int cycle = 0; cycle < 3; ++cycle) {
            const gen::SizeFunction size = gen::steiner_restart_size_2d(state, options);
            const gen::AdaptiveMesh2 before = state;
            const std::uint64_t removed_before = counters.removed;
            ASSERT_TRUE(gen::steiner_restart_cycle_2d(state, options, {&field, 0}, counters))
                << name;
            const std::string where = name + " cycle " + std::to_string(cycle);
            ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << where;
            EXPECT_EQ(state.fixed_vertices, before.fixed_vertices);
            // Every vertex the derefinement kept is still there, in the same relative order
            // (the restart keeps indices), and every curve point with its flag.
            const std::uint64_t removed = counters.removed - removed_before;
            const std::size_t kept = before.mesh.vertex_count() - removed;
            ASSERT_GE(state.mesh.vertex_count(), kept) << where;
            std::size_t next = 0;
            for (std::size_t v = 0; v < before.mesh.vertex_count(); ++v) {
                if (next < kept && point(before, v) == point(state, next)) {
                    if (before.on_curve[v]) {
                        EXPECT_TRUE(state.on_curve[next]) << where;
                    }
                    ++next;
                } else {
                    EXPECT_FALSE(before.on_curve[v]) << where << ": curve point " << v << " gone";
                    EXPECT_GE(v, before.fixed_vertices) << where;
                }
            }
            EXPECT_EQ(next, kept) << where;
            const double error = max_error(state, field, 0);
            EXPECT_LE(error, previous * 1.05) << where;
            previous = error;
            const SizeFit fit = size_fit(state, size);
            EXPECT_GE(fit.within, 0.99) << where;
            EXPECT_GE(fit.not_too_fine, 0.9) << where;
        }
        EXPECT_GT(counters.steiner_points, 0u) << name;
        EXPECT_EQ(counters.budget_stops, 0u) << name;
        EXPECT_LT(previous, 0.5 * initial) << name;
    }
}

TEST(Generators_SteinerRestart2, AFrontThatMovesIsDerefinedBehindIt) {
    // The front x + 0.5 y = 0.6 + 0.3 t: refined at t = 0, then followed to t = 2 (x + 0.5 y =
    // 1.2); the field is sampled on the current mesh at the new time before each cycle, as a
    // solver would give it.
    const gen::AnalyticField field = front_field();
    DomainState m = domain_state(gen::SampleDomain::SquareWithHoles, field);
    gen::AdaptiveMesh2& state = m.state;
    gen::AdaptationOptions options;
    options.max_vertices = 20000;
    gen::SteinerRestartCounters2 counters;
    const auto near_old_front = [&] {
        std::size_t n = 0;
        for (std::size_t v = 0; v < state.mesh.vertex_count(); ++v) {
            const double s = state.mesh.xy[2 * v] + 0.5 * state.mesh.xy[2 * v + 1];
            n += std::fabs(s - 0.6) < 0.1 ? 1 : 0;
        }
        return n;
    };
    for (int cycle = 0; cycle < 2; ++cycle)
        ASSERT_TRUE(gen::steiner_restart_cycle_2d(state, options, {&field, 0}, counters));
    const std::size_t refined_there = near_old_front();
    const std::uint64_t removed_at_rest = counters.removed;
    for (int cycle = 0; cycle < 3; ++cycle) {
        state.values = gen::sample_field(field, state.mesh.xy, 2, 2);
        const std::uint64_t removed = counters.removed;
        ASSERT_TRUE(gen::steiner_restart_cycle_2d(state, options, {&field, 2}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << cycle;
        EXPECT_GT(counters.removed, removed) << cycle;
        EXPECT_LE(state.mesh.vertex_count(), options.max_vertices);
    }
    // Behind the front the mesh coarsens: more than half of its vertices there gone in three
    // cycles (the resumed refinement puts back a few where a removal left a bad angle).
    EXPECT_LT(near_old_front(), refined_there / 2);
    EXPECT_GT(counters.removed, 2 * removed_at_rest);
    // The new front is resolved too (the first mesh's error at t = 0 was 0.17).
    EXPECT_LT(max_error(state, field, 2), 0.05);
}

TEST(Generators_SteinerRestart2, VertexBudgetHoldsByCoarserSizes) {
    const gen::AnalyticField field = front_field();
    DomainState m = domain_state(gen::SampleDomain::Naca0012, field);
    gen::AdaptiveMesh2& state = m.state;
    gen::AdaptationOptions options;
    const std::uint32_t initial = state.mesh.vertex_count();
    options.max_vertices = initial + 1500;
    gen::SteinerRestartCounters2 counters;
    const double first_error = max_error(state, field, 0);
    for (int cycle = 0; cycle < 3; ++cycle) {
        gen::steiner_restart_cycle_2d(state, options, {&field, 0}, counters);
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "") << cycle;
        EXPECT_LE(state.mesh.vertex_count(), options.max_vertices) << cycle;
    }
    // The budget was binding (the unlimited cycles make 58254 vertices) and used well.
    EXPECT_GT(counters.budget_scalings + counters.budget_retries, 0u);
    EXPECT_GT(state.mesh.vertex_count(), options.max_vertices - 700);
    EXPECT_LT(max_error(state, field, 0), first_error);
    // A budget below the mesh: the cycle only derefines (the vertex count falls), and says so.
    const std::uint32_t before = state.mesh.vertex_count();
    options.max_vertices = before / 2;
    const std::uint64_t stops = counters.budget_stops, runs = counters.refinement_runs;
    EXPECT_TRUE(gen::steiner_restart_cycle_2d(state, options, {&field, 0}, counters));
    ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "");
    EXPECT_LT(state.mesh.vertex_count(), before);
    EXPECT_EQ(counters.budget_stops, stops + 1);
    EXPECT_EQ(counters.refinement_runs, runs);
}

TEST(Generators_SteinerRestart2, ATransferredFieldKeepsTheKeptVerticesValues) {
    const gen::AnalyticField field = front_field();
    DomainState m = domain_state(gen::SampleDomain::Key, field);
    gen::AdaptiveMesh2& state = m.state;
    const gen::AdaptationOptions options;
    gen::SteinerRestartCounters2 counters;
    for (int cycle = 0; cycle < 2; ++cycle) {
        std::map<std::pair<double, double>, double> old_values;
        for (std::size_t v = 0; v < state.mesh.vertex_count(); ++v)
            old_values[point(state, v)] = state.values[v];
        ASSERT_TRUE(gen::steiner_restart_cycle_2d(state, options, {nullptr, 0}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "");
        ASSERT_EQ(state.values.size(), state.mesh.vertex_count());
        std::size_t found = 0;
        for (std::size_t v = 0; v < state.mesh.vertex_count(); ++v) {
            ASSERT_TRUE(std::isfinite(state.values[v])) << v;
            EXPECT_LE(std::fabs(state.values[v]), 1.0 + 1e-12);
            const auto it = old_values.find(point(state, v));
            if (it == old_values.end()) continue;
            ++found;
            EXPECT_EQ(state.values[v], it->second) << v;
        }
        EXPECT_GT(found, 0u);
    }
    // Interpolated, not sampled: still close to the field where the mesh resolves it.
    EXPECT_LT(max_error(state, field, 0), 0.5);
}

TEST(Generators_SteinerRestart2, SameMeshScaledAtTwoToThePlusMinus600) {
    tri::Triangulation2 reference;
    std::vector<gen::CurvedPiece2> reference_pieces;
    for (const int k : {0, 600, -600}) {
        const double scale = std::ldexp(1.0, k);
        const gen::AnalyticField field = front_field(scale);
        // The PSLG as a .poly gives it: no curves (scaled curves would be other functions).
        DomainState m = domain_state(gen::SampleDomain::SquareWithHoles, field, scale, 0.08);
        gen::AdaptiveMesh2& state = m.state;
        if (k == 0) {
            state.curves.clear();
            for (gen::CurvedPiece2& p : state.pieces) p = {p.a, p.b};
        }
        gen::AdaptationOptions options;
        options.max_vertices = 4000;  // a budget, so that the scaled sizes are exercised too
        gen::SteinerRestartCounters2 counters;
        for (int cycle = 0; cycle < 3; ++cycle) {
            state.values = gen::sample_field(field, state.mesh.xy, 2, 0.5 * cycle);
            ASSERT_TRUE(
                gen::steiner_restart_cycle_2d(state, options, {&field, 0.5 * cycle}, counters));
        }
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, m.domain.xy), "");
        EXPECT_GT(counters.removed, 0u);
        EXPECT_GT(counters.budget_scalings + counters.budget_retries, 0u);
        if (k == 0) {
            reference = state.mesh;
            reference_pieces = state.pieces;
            continue;
        }
        EXPECT_EQ(state.mesh.triangles, reference.triangles) << "2^" << k;
        ASSERT_TRUE(exactmesh::testing::coordinates_scaled_by(state.mesh.xy, reference.xy, k));
        ASSERT_EQ(state.pieces.size(), reference_pieces.size());
        for (std::size_t p = 0; p < reference_pieces.size(); ++p) {
            EXPECT_EQ(state.pieces[p].a, reference_pieces[p].a);
            EXPECT_EQ(state.pieces[p].b, reference_pieces[p].b);
        }
    }
}

TEST(Generators_SteinerRestart2, UnusedInputVerticesStayUnused) {
    // A .poly square with a repeated corner (merged: its copy is in no triangle) and a vertex
    // outside the segments (removed with the exterior): both stay in the numbering, unused.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1, 1, 0, 2, 2};
    const std::vector<tri::VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0};
    gen::MeshOptions2 mesh_options;
    mesh_options.size = gen::SizeFunction::uniform(0.1);
    tri::Cdt2Result mesh = gen::find_mesh_generator_2d("delaunay-refinement")
                               .run({xy, segments, {}, {}}, mesh_options)
                               .mesh;
    gen::AdaptiveMesh2 state =
        gen::make_adaptive_mesh_2d(std::move(mesh), xy, segments, {}, {}, {});
    const gen::AnalyticField field = front_field();
    state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
    const gen::AdaptationOptions options;
    gen::SteinerRestartCounters2 counters;
    for (int cycle = 0; cycle < 2; ++cycle) {
        state.values = gen::sample_field(field, state.mesh.xy, 2, cycle);
        ASSERT_TRUE(gen::steiner_restart_cycle_2d(state, options, {&field, 1.0 * cycle}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, xy), "") << cycle;
        for (const tri::VertIdx v : state.mesh.triangles) {
            EXPECT_NE(v, 4u);
            EXPECT_NE(v, 5u);
        }
    }
    EXPECT_GT(counters.steiner_points, 0u);
}
