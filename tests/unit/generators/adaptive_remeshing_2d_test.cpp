// SPDX-License-Identifier: MIT
// Issue 13, adaptive remeshing in 2D: global remeshing with every generator of the registry on
// every sample domain (after every cycle the exact check, input vertices kept, the error falls,
// the vertex budget holds), local remeshing (kept triangles bit for bit, voids conforming,
// pieces unchanged, a moving front leaves a coarser mesh behind it), and the same global
// Delaunay-refinement run on the domain scaled by 2^±600 giving the same mesh scaled.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/adaptive_remeshing_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/adaptation_fixtures_2d.hpp"
#include "tests/support/scaled_coordinates.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using Start = em::testing::SampleDomainState;

// The domain meshed by Delaunay refinement (with a uniform size when size > 0), the state built
// with the domain's curves (none when `curves` is false: a .poly input), the field sampled.
Start start(gen::SampleDomain d, const gen::AnalyticField& field, double scale = 1.0,
            double size = 0, bool curves = true) {
    Start r = em::testing::sample_domain_state(d, field, scale, size, curves);
    if (!curves) {
        r.domain.curves.clear();
        r.domain.segment_curves.clear();
    }
    return r;
}

using em::testing::front_field;

gen::InterpolationError error_of(const gen::AdaptiveMesh2& state, const gen::AnalyticField& field,
                                 double t) {
    return gen::interpolation_error(state.mesh.xy, 2, state.mesh.triangles, state.values, field, t);
}

using Corner = std::array<double, 2>;
using TriangleKey = std::array<Corner, 3>;

// Each triangle by its corners' coordinates, rotated to start at its smallest corner (the
// orientation kept): equal keys are the same triangle, bit for bit.
std::set<TriangleKey> triangle_keys(const tri::Triangulation2& mesh) {
    std::set<TriangleKey> keys;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        TriangleKey key;
        for (unsigned k = 0; k < 3; ++k) {
            const double* p = mesh.point(mesh.triangles[3 * t + k]);
            key[k] = {p[0], p[1]};
        }
        std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
        keys.insert(key);
    }
    return keys;
}

std::set<std::array<Corner, 2>> piece_keys(const gen::AdaptiveMesh2& state) {
    std::set<std::array<Corner, 2>> keys;
    for (const gen::CurvedPiece2& p : state.pieces) {
        Corner a{state.mesh.point(p.a)[0], state.mesh.point(p.a)[1]};
        Corner b{state.mesh.point(p.b)[0], state.mesh.point(p.b)[1]};
        if (b < a) std::swap(a, b);
        keys.insert({a, b});
    }
    return keys;
}

// The number of vertices within `band` of the line x + 0.5 y = c.
std::size_t vertices_near(const tri::Triangulation2& mesh, double c, double band) {
    std::size_t n = 0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v)
        if (std::fabs(mesh.xy[2 * v] + 0.5 * mesh.xy[2 * v + 1] - c) < band) ++n;
    return n;
}

}  // namespace

TEST(Generators_AdaptiveRemeshing2, EveryGeneratorEveryDomainValidErrorFallsWithinBudget) {
    const gen::AnalyticField field = front_field();
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
            Start s = start(d, field);
            const std::string name =
                std::string(gen::sample_domain_name(d)) + " " + std::string(generator.name);
            gen::AdaptationOptions options;
            options.max_vertices = 6000;
            gen::RemeshCounters2 counters;
            const gen::RemeshDomain2 domain = gen::remesh_domain_2d(s.domain);
            const double initial = error_of(s.state, field, 0).l2;
            double previous = initial;
            for (int cycle = 0; cycle < 2; ++cycle) {
                ASSERT_TRUE(gen::remesh_cycle_2d(s.state, domain, generator, options, {&field, 0},
                                                 counters))
                    << name;
                ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy, generator.delaunay), "")
                    << name << " cycle " << cycle;
                EXPECT_EQ(s.state.fixed_vertices, s.domain.xy.size() / 2) << name;
                EXPECT_LE(s.state.mesh.vertex_count(), options.max_vertices) << name;
                const double error = error_of(s.state, field, 0).l2;
                EXPECT_LE(error, previous * 1.1) << name << " cycle " << cycle;
                previous = error;
            }
            EXPECT_LT(previous, 0.8 * initial) << name;
            EXPECT_EQ(counters.cycles, 2u);
        }
    }
}

TEST(Generators_AdaptiveRemeshing2, TightBudgetScalesTheSizeAndATransferredFieldWorks) {
    const gen::AnalyticField field = front_field();
    Start s = start(gen::SampleDomain::Naca0012, field);
    gen::AdaptationOptions options;
    options.max_vertices = s.state.mesh.vertex_count() + 100;
    gen::RemeshCounters2 counters;
    const gen::RemeshDomain2 domain = gen::remesh_domain_2d(s.domain);
    for (int cycle = 0; cycle < 3; ++cycle) {
        // No analytic field: the old mesh's values transferred.
        ASSERT_TRUE(
            gen::remesh_cycle_2d(s.state, domain, "frontal", options, {nullptr, 0}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy), "");
        EXPECT_LE(s.state.mesh.vertex_count(), options.max_vertices);
        ASSERT_EQ(s.state.values.size(), s.state.mesh.vertex_count());
        // Interpolated between values of tanh (in [-1, 1]), rounded.
        for (const double v : s.state.values) ASSERT_LE(std::fabs(v), 1 + 1e-15) << v;
    }
    EXPECT_GT(counters.budget_scalings + counters.budget_reruns, 0u);
    // A budget below the input's own vertices fits no run: the state is left as it was.
    gen::AdaptationOptions impossible;
    impossible.max_vertices = 3;
    const std::vector<double> before = s.state.mesh.xy;
    const std::uint64_t runs = counters.generator_runs;
    EXPECT_FALSE(gen::remesh_cycle_2d(s.state, domain, "delaunay-refinement", impossible,
                                      {&field, 0}, counters));
    EXPECT_EQ(s.state.mesh.xy, before);
    EXPECT_EQ(counters.budget_refusals, 1u);
    // A mesh at or over the budget is refused before any generator run (a domain whose own
    // features need more vertices made up to 8 runs of seconds each).
    EXPECT_EQ(counters.generator_runs, runs);
    EXPECT_THROW((void)gen::remesh_cycle_2d(s.state, domain, "marching-squares", options,
                                            {&field, 0}, counters),
                 em::InputError);
}

TEST(Generators_AdaptiveRemeshing2, GlobalDelaunayRefinementSameMeshScaledAtTwoToThe600) {
    tri::Triangulation2 reference;
    for (const int k : {0, 600, -600}) {
        const double scale = std::ldexp(1.0, k);
        const gen::AnalyticField field = front_field(scale);
        // The PSLG as a .poly gives it: no curves (scaled curves would be other functions).
        Start s = start(gen::SampleDomain::SquareWithHoles, field, scale, 0.08, false);
        gen::AdaptationOptions options;
        gen::RemeshCounters2 counters;
        const gen::RemeshDomain2 domain = gen::remesh_domain_2d(s.domain);
        for (int cycle = 0; cycle < 2; ++cycle)
            ASSERT_TRUE(gen::remesh_cycle_2d(s.state, domain, "delaunay-refinement", options,
                                             {&field, 0}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy), "");
        if (k == 0) {
            reference = s.state.mesh;
            continue;
        }
        EXPECT_EQ(s.state.mesh.triangles, reference.triangles) << "2^" << k;
        ASSERT_TRUE(exactmesh::testing::coordinates_scaled_by(s.state.mesh.xy, reference.xy, k));
    }
}

TEST(Generators_LocalRemeshing2, KeptTrianglesBitForBitVoidsConformEveryDomain) {
    const gen::AnalyticField field = front_field();
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        Start s = start(d, field);
        const std::string name(gen::sample_domain_name(d));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy), "") << name;
        const std::set<std::array<Corner, 2>> pieces = piece_keys(s.state);
        const double initial = error_of(s.state, field, 0).l2;
        gen::AdaptationOptions options;
        gen::LocalRemeshCounters2 counters;
        for (int cycle = 0; cycle < 3; ++cycle) {
            const std::vector<std::uint8_t> flags = gen::local_remesh_flags_2d(s.state, options, 2);
            tri::Triangulation2 kept = s.state.mesh;
            kept.triangles.clear();
            for (std::size_t t = 0; t < flags.size(); ++t)
                if (flags[t] == 0)
                    kept.triangles.insert(kept.triangles.end(),
                                          s.state.mesh.triangles.begin() + 3 * t,
                                          s.state.mesh.triangles.begin() + 3 * t + 3);
            const std::size_t gone = flags.size() - kept.triangle_count();
            const std::uint64_t removed = counters.too_large + counters.too_small;
            const std::uint64_t made = counters.new_triangles;
            if (!gen::local_remesh_cycle_2d(s.state, options, {&field, 0}, counters)) break;
            ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy, false), "")
                << name << " cycle " << cycle;
            EXPECT_EQ(counters.too_large + counters.too_small - removed, gone) << name;
            // Every old triangle that was not flagged is in the new mesh, bit for bit (its
            // corners' coordinates, its orientation); the others are the fronts'.
            const std::set<TriangleKey> after = triangle_keys(s.state.mesh);
            for (const TriangleKey& key : triangle_keys(kept))
                ASSERT_TRUE(after.contains(key)) << name << " cycle " << cycle;
            EXPECT_EQ(after.size(), kept.triangle_count() + (counters.new_triangles - made))
                << name;
            // The pieces (the domain's boundary) are never split nor moved.
            EXPECT_EQ(piece_keys(s.state), pieces) << name;
        }
        EXPECT_GT(counters.voids, 0u) << name;
        EXPECT_LT(error_of(s.state, field, 0).l2, initial) << name;
    }
}

TEST(Generators_LocalRemeshing2, MovingFrontCoarsensWhereTheFrontLeft) {
    const gen::AnalyticField field = front_field();
    Start s = start(gen::SampleDomain::SquareWithHoles, field, 1.0, 0.05);
    gen::AdaptationOptions options;
    gen::LocalRemeshCounters2 counters;
    for (int cycle = 0; cycle < 3; ++cycle)
        ASSERT_TRUE(gen::local_remesh_cycle_2d(s.state, options, {&field, 0}, counters));
    // The front at t = 0 lies on x + 0.5 y = 0.6; at t = 2 it has left for x + 0.5 y = 1.2.
    const std::size_t refined = vertices_near(s.state.mesh, 0.6, 0.06);
    const std::size_t ahead = vertices_near(s.state.mesh, 1.2, 0.06);
    for (int cycle = 0; cycle < 3; ++cycle) {
        s.state.values = gen::sample_field(field, s.state.mesh.xy, 2, 2.0);
        ASSERT_TRUE(gen::local_remesh_cycle_2d(s.state, options, {&field, 2.0}, counters));
        ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy, false), "") << cycle;
    }
    EXPECT_LT(vertices_near(s.state.mesh, 0.6, 0.06), refined / 2);
    EXPECT_GT(vertices_near(s.state.mesh, 1.2, 0.06), ahead);
    EXPECT_GT(counters.removed_vertices, 0u);
}

TEST(Generators_LocalRemeshing2, BudgetHoldsTransferAndBadFactor) {
    const gen::AnalyticField field = front_field();
    Start s = start(gen::SampleDomain::Key, field);
    gen::AdaptationOptions options;
    options.max_vertices = s.state.mesh.vertex_count() + 150;
    gen::LocalRemeshCounters2 counters;
    for (int cycle = 0; cycle < 4; ++cycle) {
        const std::vector<double> old_xy = s.state.mesh.xy;
        const std::vector<double> old_values = s.state.values;
        if (!gen::local_remesh_cycle_2d(s.state, options, {nullptr, 0}, counters)) break;
        ASSERT_EQ(gen::check_adaptive_mesh_2d(s.state, s.domain.xy, false), "");
        EXPECT_LE(s.state.mesh.vertex_count(), options.max_vertices);
        // The input vertices keep their numbers and, with no analytic field, their values.
        for (std::uint32_t v = 0; v < s.state.fixed_vertices; ++v)
            EXPECT_EQ(s.state.values[v], old_values[v]) << v;
    }
    EXPECT_GT(counters.voids, 0u);
    EXPECT_THROW((void)gen::local_remesh_cycle_2d(s.state, options, {&field, 0}, counters, 1.0),
                 em::InputError);
    EXPECT_THROW(
        (void)gen::local_remesh_cycle_2d(s.state, options, {&field, 0}, counters, std::nan("")),
        em::InputError);
}

namespace {

// The unit square with extra vertices on its sides (collinear boundary points), a slit (a
// dangling segment inside the domain, across the front) and two free input vertices, meshed on
// a uniform grid-like Delaunay refinement (cocircular points); scaled by `scale`.
struct SlitSquare {
    std::vector<double> xy{0, 0, 0.5, 0,   1,   0,   1,   0.5, 1,   1,    0.5, 1,
                           0, 1, 0,   0.5, 0.3, 0.5, 0.7, 0.5, 0.5, 0.25, 0.8, 0.8};
    std::vector<tri::VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 0, 8, 9};
    explicit SlitSquare(double scale) {
        for (double& c : xy) c *= scale;
    }
};

gen::AdaptiveMesh2 slit_square_state(const SlitSquare& square, const gen::AnalyticField& field,
                                     double scale) {
    gen::MeshOptions2 options;
    options.size = gen::SizeFunction::uniform(0.0625 * scale);
    tri::Cdt2Result mesh = gen::find_mesh_generator_2d("delaunay-refinement")
                               .run({square.xy, square.segments, {}, {}}, options)
                               .mesh;
    gen::AdaptiveMesh2 state =
        gen::make_adaptive_mesh_2d(std::move(mesh), square.xy, square.segments, {}, {}, {});
    state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
    return state;
}

// Every input vertex is a corner of some triangle (none dropped inside a void).
bool input_vertices_used(const gen::AdaptiveMesh2& state) {
    std::vector<std::uint8_t> used(state.mesh.vertex_count(), 0);
    for (const tri::VertIdx v : state.mesh.triangles) used[v] = 1;
    return std::all_of(used.begin(), used.begin() + state.fixed_vertices,
                       [](std::uint8_t u) { return u != 0; });
}

}  // namespace

TEST(Generators_LocalRemeshing2, SlitFreeVerticesCollinearSidesAndSameMeshScaled) {
    tri::Triangulation2 reference;
    for (const int k : {0, 600, -600}) {
        const double scale = std::ldexp(1.0, k);
        const SlitSquare square(scale);
        const gen::AnalyticField field = front_field(scale);
        gen::AdaptiveMesh2 state = slit_square_state(square, field, scale);
        ASSERT_EQ(gen::check_adaptive_mesh_2d(state, square.xy), "");
        const std::size_t pieces = state.pieces.size();
        gen::AdaptationOptions options;
        gen::LocalRemeshCounters2 counters;
        for (int cycle = 0; cycle < 3; ++cycle) {
            ASSERT_TRUE(gen::local_remesh_cycle_2d(state, options, {&field, 0}, counters));
            ASSERT_EQ(gen::check_adaptive_mesh_2d(state, square.xy, false), "") << cycle;
            EXPECT_TRUE(input_vertices_used(state)) << cycle;
            EXPECT_EQ(state.pieces.size(), pieces);
        }
        EXPECT_GT(counters.removed_vertices, 0u);
        // The slit and a free input vertex were inside voids (the front at t = 0 crosses both).
        EXPECT_GT(counters.slit_pieces, 0u);
        EXPECT_GT(counters.inner_inputs, 0u);
        if (k == 0) {
            reference = state.mesh;
            continue;
        }
        EXPECT_EQ(state.mesh.triangles, reference.triangles) << "2^" << k;
        ASSERT_TRUE(exactmesh::testing::coordinates_scaled_by(state.mesh.xy, reference.xy, k));
    }
}

TEST(Generators_AdaptiveRemeshing2, SlitFreeVerticesAndCollinearSidesWithEveryGenerator) {
    const SlitSquare square(1.0);
    const gen::AnalyticField field = front_field();
    const gen::RemeshDomain2 domain{{square.xy, square.segments, {}, {}}, {}, {}};
    for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
        gen::AdaptiveMesh2 state = slit_square_state(square, field, 1.0);
        gen::AdaptationOptions options;
        gen::RemeshCounters2 counters;
        for (int cycle = 0; cycle < 2; ++cycle) {
            ASSERT_TRUE(
                gen::remesh_cycle_2d(state, domain, generator, options, {&field, 0}, counters));
            ASSERT_EQ(gen::check_adaptive_mesh_2d(state, square.xy, generator.delaunay), "")
                << generator.name << " " << cycle;
            EXPECT_TRUE(input_vertices_used(state)) << generator.name;
        }
    }
    // A segment naming a curve the state does not have is an input error.
    gen::AdaptiveMesh2 state = slit_square_state(square, field, 1.0);
    const std::vector<gen::SegmentCurve> curves(square.segments.size() / 2, {3, 0, 1});
    const gen::RemeshDomain2 bad{{square.xy, square.segments, {}, {}}, {}, curves};
    gen::RemeshCounters2 counters;
    EXPECT_THROW((void)gen::remesh_cycle_2d(state, bad, "frontal", {}, {&field, 0}, counters),
                 em::InputError);
}
