// SPDX-License-Identifier: MIT
// What the adaptation benchmark (adaptation_bench.cpp) and the convergence driver
// (adaptation_convergence.cpp) share (issue 13): the domain (the built-in NACA 0012 in its
// far-field box [-1.5, 2.5] x [-2, 2]), the four analytic test fields, the initial mesh by
// Delaunay refinement at a uniform size, and one driver over every 2D adaptation method
// (insertion, h-refinement, steiner, remesh, local-remesh) so that both programs run a method
// exactly as `exactmesh adapt` does (cli/adapt_command.cpp: the same calls, options and
// transient rule: thresholds relative to the first mesh's mean, derefinement passes until one
// removes nothing, then the refinement cycles).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/adaptive_remeshing_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/h_adaptation_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/adaptation/mesh_edges.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/adaptation/vertex_field.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"

namespace exactmesh::bench::adaptation {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

enum class Method { Insertion, HRefinement, Steiner, Remesh, LocalRemesh };

inline constexpr std::array<std::pair<Method, std::string_view>, 5> kMethods{{
    {Method::Insertion, "insertion"},
    {Method::HRefinement, "h-refinement"},
    {Method::Steiner, "steiner"},
    {Method::Remesh, "remesh"},
    {Method::LocalRemesh, "local-remesh"},
}};

inline std::string_view method_name(Method method) {
    for (const auto& [m, name] : kMethods)
        if (m == method) return name;
    return "?";
}

/// The generator of the initial mesh, of the uniform baseline and of "from scratch".
inline constexpr std::string_view kGenerator = "delaunay-refinement";

/// The test fields, all on the NACA 0012 domain (airfoil chord (0, 0)-(1, 0)).
/// front: an oblique shock-like front tanh(k (x cos a + y sin a - c)), k = 50 (width 1/50),
///   a = 30 degrees, c = 0.5 (crossing the airfoil); transient: c = -0.5 + t.
inline constexpr double kFrontSteepness = 50;
inline constexpr double kFrontAngle = std::numbers::pi / 6;
inline double front_value(double x, double y, double c) {
    return std::tanh(kFrontSteepness * (x * std::cos(kFrontAngle) + y * std::sin(kFrontAngle) - c));
}

/// boundary-layer: 1 - exp(-d / delta), delta = 0.02, with d an approximate distance to the
/// airfoil's surface: with xc = clamp(x, 0, 1), d = hypot(x - xc, max(|y| - y_t(xc), 0)) (the
/// vertical distance above the surface over the chord, the distance to the nearest chord end
/// ahead and behind it): cheap and continuous, exact only where the surface is flat.
inline constexpr double kBoundaryLayerThickness = 0.02;
inline double airfoil_distance(double x, double y) {
    const double xc = std::clamp(x, 0.0, 1.0);
    const double above = std::max(std::abs(y) - gen::naca_thickness(0.12, xc), 0.0);
    return std::hypot(x - xc, above);
}

/// The four fields of the convergence study, by name; t is the front's time (0 for the others).
inline constexpr std::array<std::string_view, 4> kFieldNames{"front", "boundary-layer",
                                                             "singularity", "smooth"};

inline std::string field_formula(std::string_view name) {
    if (name == "front") return "tanh(50 (x cos 30deg + y sin 30deg - 0.5))";
    if (name == "boundary-layer")
        return "1 - exp(-d / 0.02), d ~ distance to the NACA 0012 surface (vertical, see text)";
    if (name == "singularity") return "r^(2/3), r = distance to the trailing edge (1, 0)";
    return "sin(pi x) sin(pi y)";
}

inline gen::AnalyticField field_by_name(std::string_view name) {
    gen::AnalyticField field;
    field.name = std::string(name);
    if (name == "front") {
        field.value = [](double x, double y, double, double) { return front_value(x, y, 0.5); };
    } else if (name == "boundary-layer") {
        field.value = [](double x, double y, double, double) {
            return 1 - std::exp(-airfoil_distance(x, y) / kBoundaryLayerThickness);
        };
    } else if (name == "singularity") {
        // A point singularity (gradient ~ r^(-1/3)) at the trailing edge, a vertex of the domain
        // where its boundary turns by almost 2 pi. Without the angular factor sin(2 theta / 3):
        // its branch cut would cross the domain ahead of the leading edge.
        field.value = [](double x, double y, double, double) {
            return std::pow(std::hypot(x - 1, y), 2.0 / 3.0);
        };
    } else if (name == "smooth") {
        field.value = [](double x, double y, double, double) {
            return std::sin(std::numbers::pi * x) * std::sin(std::numbers::pi * y);
        };
    } else {
        throw std::invalid_argument("unknown field " + std::string(name));
    }
    return field;
}

/// The transient front: c = -0.5 + t (it crosses the airfoil for t in [0.5, 1.5]).
inline gen::AnalyticField moving_front() {
    gen::AnalyticField field;
    field.name = "moving-front";
    field.value = [](double x, double y, double, double t) { return front_value(x, y, -0.5 + t); };
    return field;
}

/// The domain with its boundary discretized at the uniform size h.
inline gen::DomainPslg naca_domain(double h) {
    return gen::sample_domain(gen::SampleDomain::Naca0012, gen::SizeFunction::uniform(h));
}

inline tri::Pslg pslg_view(const gen::DomainPslg& domain) {
    return {domain.xy, domain.segments, domain.holes, {}};
}

/// Delaunay refinement (the registry's, default angle and polish) of `domain` with `size`.
inline tri::Cdt2Result generate(const gen::DomainPslg& domain, const gen::SizeFunction& size) {
    gen::MeshOptions2 options;
    options.size = size;
    return gen::find_mesh_generator_2d(kGenerator).run(pslg_view(domain), options).mesh;
}

inline gen::InterpolationError mesh_error(const tri::Triangulation2& mesh,
                                          const std::vector<double>& values,
                                          const gen::AnalyticField& field, double t) {
    return gen::interpolation_error(mesh.xy, 2, mesh.triangles, values, field, t);
}

/// One adaptive run of any method, the state of the CLI's run_adapt_2d.
class Adapter {
  public:
    Adapter(Method method, const gen::DomainPslg& domain, tri::Cdt2Result initial,
            const gen::AnalyticField& field, gen::AdaptationOptions options, double t = 0,
            bool transient = false, double derefine_threshold = 0.2)
        : method_(method),
          domain_(&domain),
          field_(&field),
          options_(options),
          source_{&field, t},
          derefine_threshold_(derefine_threshold) {
        if (method == Method::HRefinement) {
            h_.emplace(gen::HAdaptiveMesh2{gen::HRefinedMesh2(initial.mesh), {}});
            h_->values = gen::sample_field(field, h_->hierarchy.leaf_mesh().xy, 2, t);
        } else {
            flat_.emplace(gen::make_adaptive_mesh_2d(std::move(initial), domain.xy, domain.segments,
                                                     domain.holes, domain.curves,
                                                     domain.segment_curves));
            flat_->values = gen::sample_field(field, flat_->mesh.xy, 2, t);
        }
        if (transient)
            options_.reference_mean = gen::mean_indicator(
                gen::mesh_edge_indicator(options_.indicator, mesh().xy, 2, mesh().triangles,
                                         gen::mesh_edges_2d(mesh().triangles), values()));
    }

    const tri::Triangulation2& mesh() const { return h_ ? h_->hierarchy.leaf_mesh() : flat_->mesh; }
    const std::vector<double>& values() const { return h_ ? h_->values : flat_->values; }
    const gen::AdaptiveMesh2* flat() const { return flat_ ? &*flat_ : nullptr; }
    const gen::AdaptationOptions& options() const { return options_; }

    /// One refinement cycle at time t; false when the method changed nothing.
    bool cycle(double t) {
        source_.t = t;
        switch (method_) {
            case Method::Insertion:
                return gen::insertion_cycle_2d(*flat_, options_, source_, insertion_);
            case Method::HRefinement:
                return gen::h_refinement_cycle_2d(*h_, options_, source_, h_counters_);
            case Method::Steiner:
                return gen::steiner_restart_cycle_2d(*flat_, options_, source_, steiner_);
            case Method::Remesh:
                return gen::remesh_cycle_2d(*flat_, gen::remesh_domain_2d(*domain_),
                                            gen::find_mesh_generator_2d(kGenerator), options_,
                                            source_, remesh_);
            case Method::LocalRemesh:
                return gen::local_remesh_cycle_2d(*flat_, options_, source_, local_);
        }
        return false;
    }

    /// One derefinement pass (insertion: by the indicator; h-refinement: by the history);
    /// the vertices removed. Other methods coarsen by their size field: 0.
    std::uint64_t derefine() {
        if (method_ == Method::HRefinement)
            return gen::h_derefinement_pass_2d(*h_, options_.indicator, derefine_threshold_,
                                               options_.reference_mean, source_, h_counters_);
        if (method_ != Method::Insertion) return 0;
        const gen::DerefinementOptions options{options_.indicator, derefine_threshold_,
                                               options_.reference_mean};
        return gen::derefinement_pass_2d(*flat_, options, derefinement_);
    }

    void resample(double t) {
        source_.t = t;
        std::vector<double>& v = h_ ? h_->values : flat_->values;
        v = gen::sample_field(*field_, mesh().xy, 2, t);
    }

    /// A transient step as `exactmesh adapt --steps` runs it: resample, derefinement passes
    /// (at most 8, until one removes nothing), then up to `cycles` refinement cycles.
    void step(double t, std::uint32_t cycles) {
        resample(t);
        for (int pass = 0; pass < 8; ++pass)
            if (derefine() == 0) break;
        for (std::uint32_t c = 0; c < cycles; ++c)
            if (!cycle(t)) break;
    }

  private:
    Method method_;
    const gen::DomainPslg* domain_;
    const gen::AnalyticField* field_;
    gen::AdaptationOptions options_;
    gen::FieldSource source_;
    double derefine_threshold_;
    std::optional<gen::AdaptiveMesh2> flat_;
    std::optional<gen::HAdaptiveMesh2> h_;
    gen::InsertionCounters2 insertion_;
    gen::HAdaptationCounters2 h_counters_;
    gen::SteinerRestartCounters2 steiner_;
    gen::RemeshCounters2 remesh_;
    gen::LocalRemeshCounters2 local_;
    gen::DerefinementCounters2 derefinement_;
};

/// Per vertex, the mean length of the edges at it: the local spacing of a mesh, what a
/// background size must reproduce to regenerate the same density.
inline std::vector<double> vertex_spacing(const tri::Triangulation2& mesh) {
    const std::vector<tri::VertIdx> edges = gen::mesh_edges_2d(mesh.triangles);
    std::vector<double> sum(mesh.vertex_count(), 0.0);
    std::vector<std::uint32_t> count(mesh.vertex_count(), 0);
    for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
        const tri::VertIdx a = edges[e], b = edges[e + 1];
        const double length =
            std::hypot(mesh.xy[2 * b] - mesh.xy[2 * a], mesh.xy[2 * b + 1] - mesh.xy[2 * a + 1]);
        sum[a] += length;
        sum[b] += length;
        ++count[a];
        ++count[b];
    }
    double largest = 0;
    for (std::size_t v = 0; v < sum.size(); ++v)
        if (count[v] > 0) largest = std::max(largest, sum[v] /= count[v]);
    // Vertices of no edge (merged duplicates) take the largest spacing: never a size of 0.
    for (std::size_t v = 0; v < sum.size(); ++v)
        if (count[v] == 0) sum[v] = largest;
    return sum;
}

}  // namespace exactmesh::bench::adaptation
