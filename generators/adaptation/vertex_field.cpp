// SPDX-License-Identifier: MIT
// Sampling an analytic field at vertices (see vertex_field.hpp).
#include "generators/adaptation/vertex_field.hpp"

#include <cmath>

#include "base/errors.hpp"
#include "base/number_text.hpp"

namespace exactmesh::generators {

double field_at(const AnalyticField& field, const double* point, unsigned dim, double t) {
    const double z = dim == 3 ? point[2] : 0.0;
    const double value = field.value(point[0], point[1], z, t);
    if (!std::isfinite(value)) {
        throw InputError("field '" + field.name + "' is " + format_number(value) + " at " +
                         format_point(point, static_cast<int>(dim)) + " (t = " + format_number(t) +
                         "): a field must be finite");
    }
    return value;
}

std::vector<double> sample_field(const AnalyticField& field, std::span<const double> coordinates,
                                 unsigned dim, double t) {
    std::vector<double> values(coordinates.size() / dim);
    for (std::size_t v = 0; v < values.size(); ++v)
        values[v] = field_at(field, coordinates.data() + dim * v, dim, t);
    return values;
}

}  // namespace exactmesh::generators
