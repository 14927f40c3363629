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
#include "generators/adaptation/adaptive_run_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/h_adaptation_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/interpolation_error.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/adaptation/vertex_field.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::bench::adaptation {

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

using Method = gen::AdaptMethod2;

/// Every method with its name, in the library's order.
inline std::vector<std::pair<Method, std::string_view>> methods() {
    std::vector<std::pair<Method, std::string_view>> all;
    for (const Method m : gen::kAllAdaptMethods2) all.emplace_back(m, gen::adapt_method_name(m));
    return all;
}

inline std::string_view method_name(Method method) {
    return gen::adapt_method_name(method);
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

/// One adaptive run of any method: the library's driver (generators/adaptation/adaptive_run_2d),
/// the one `exactmesh adapt` runs, over the sample domain with the benchmark's generator.
class Adapter : public gen::AdaptiveRun2 {
  public:
    Adapter(Method method, const gen::DomainPslg& domain, tri::Cdt2Result initial,
            const gen::AnalyticField& field, gen::AdaptationOptions options, double t = 0,
            bool transient = false)
        : gen::AdaptiveRun2(gen::remesh_domain_2d(domain), domain.curves, std::move(initial),
                            gen::find_mesh_generator_2d(kGenerator), &field, t,
                            run_options(method, options, transient)),
          domain_(&domain) {}

    /// The exact check, as the CLI makes it.
    std::string check() const { return gen::AdaptiveRun2::check(domain_->xy); }

  private:
    static gen::AdaptiveRunOptions2 run_options(Method method, gen::AdaptationOptions options,
                                                bool transient) {
        gen::AdaptiveRunOptions2 o;
        o.method = method;
        o.adaptation = options;
        o.transient = transient;
        return o;
    }
    const gen::DomainPslg* domain_;
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
