// SPDX-License-Identifier: MIT
// Metric fields (see metric_field_2d.hpp).
#include "generators/stretched/metric_field_2d.hpp"

#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/stretched/metric_background_2d.hpp"

namespace exactmesh::generators {

MetricField2::MetricField2() : uniform_(isotropic(1.0)) {}

MetricField2 MetricField2::uniform(const Metric2& metric) {
    check_metric(metric);
    MetricField2 field;
    field.kind_ = Kind::Uniform;
    field.uniform_ = metric;
    return field;
}

MetricField2 MetricField2::analytic(std::function<Metric2(double, double)> f,
                                    std::string description) {
    if (!f) throw InputError("analytic metric field '" + description + "': no function");
    MetricField2 field;
    field.kind_ = Kind::Analytic;
    field.analytic_ = std::make_shared<const std::function<Metric2(double, double)>>(std::move(f));
    field.description_ = std::move(description);
    return field;
}

MetricField2 MetricField2::background_mesh(std::vector<double> xy, std::vector<Metric2> metrics,
                                           std::vector<std::uint32_t> triangles) {
    return background_mesh(
        BackgroundMetricMesh2(std::move(xy), std::move(metrics), std::move(triangles)));
}

MetricField2 MetricField2::background_mesh(BackgroundMetricMesh2 mesh) {
    MetricField2 field;
    field.kind_ = Kind::Background;
    field.background_ = std::make_shared<const BackgroundMetricMesh2>(std::move(mesh));
    return field;
}

Metric2 MetricField2::operator()(double x, double y) const {
    switch (kind_) {
        case Kind::Uniform:
            return uniform_;
        case Kind::Analytic:
            return (*analytic_)(x, y);
        case Kind::Background:
            return (*background_)(x, y);
    }
    return uniform_;
}

std::string MetricField2::describe() const {
    switch (kind_) {
        case Kind::Uniform:
            return "uniform: sizes " + format_number(uniform_.h1) + ", " +
                   format_number(uniform_.h2) + " along (" + format_number(uniform_.c) + ", " +
                   format_number(uniform_.s) + ")";
        case Kind::Analytic:
            return description_;
        case Kind::Background:
            return "background mesh: " + std::to_string(background_->vertex_count()) +
                   " vertices, " + std::to_string(background_->triangle_count()) + " triangles";
    }
    return "";
}

}  // namespace exactmesh::generators
