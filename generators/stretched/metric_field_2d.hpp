// SPDX-License-Identifier: MIT
// Metric fields M(x, y): the target size and stretching of an anisotropic mesh near (x, y)
// [issue 14], the metric counterpart of SizeFunction (generators/sizing/size_function.hpp).
// Kinds:
//  - uniform: one constant Metric2;
//  - analytic: any callable the caller supplies (an expression 'M11;M12;M22' of the command
//    line, a stretching field of a boundary layer, tests);
//  - background mesh: a Metric2 per vertex of a triangulation, log-Euclidean linear inside its
//    triangles, the nearest boundary point's value outside it
//    (generators/stretched/metric_background_2d.hpp).
// Copies share the analytic function and the background mesh (both immutable).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "generators/stretched/metric_2d.hpp"

namespace exactmesh::generators {

class BackgroundMetricMesh2;

class MetricField2 {
  public:
    /// The identity metric (unit sizes) everywhere.
    MetricField2();
    /// `metric` everywhere. @throws InputError when check_metric refuses it.
    static MetricField2 uniform(const Metric2& metric);
    /// M = f(x, y); f returns a valid metric (it may throw InputError, e.g. from
    /// metric_from_matrix, naming the point) at every point it is asked about.
    static MetricField2 analytic(std::function<Metric2(double, double)> f, std::string description);
    /// A background mesh (BackgroundMetricMesh2's constructor: @throws BackgroundMeshError).
    static MetricField2 background_mesh(std::vector<double> xy, std::vector<Metric2> metrics,
                                        std::vector<std::uint32_t> triangles);
    /// A background mesh already built (e.g. by background_metric_from_file).
    static MetricField2 background_mesh(BackgroundMetricMesh2 mesh);

    /// The metric at (x, y) (finite).
    Metric2 operator()(double x, double y) const;
    /// True for a uniform field (the same metric everywhere).
    bool is_uniform() const { return kind_ == Kind::Uniform; }
    /// One line: "uniform: sizes 0.1, 0.001 along (1, 0)", the analytic description,
    /// "background mesh: 4 vertices, 2 triangles".
    std::string describe() const;
    /// The background mesh behind that kind (else null).
    const BackgroundMetricMesh2* background() const { return background_.get(); }

  private:
    enum class Kind { Uniform, Analytic, Background };
    Kind kind_ = Kind::Uniform;
    Metric2 uniform_;
    std::shared_ptr<const std::function<Metric2(double, double)>> analytic_;
    std::shared_ptr<const BackgroundMetricMesh2> background_;
    std::string description_;
};

}  // namespace exactmesh::generators
