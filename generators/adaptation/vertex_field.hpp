// SPDX-License-Identifier: MIT
// A scalar field at the vertices of a mesh, the "solution" adaptation follows (issue 13). There
// is no solver in scope: the field is either given at the vertices (a .node attribute column,
// carried to new meshes by field_transfer_2d/3d) or evaluated from an analytic function of
// x, y, z and t (the solver's stand-in), so that every error can be measured against the exact
// field (interpolation_error.hpp). The CLI compiles `--field EXPR` into an AnalyticField.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

namespace exactmesh::generators {

struct AnalyticField {
    std::string name;  ///< how errors name it (the expression's text)
    std::function<double(double x, double y, double z, double t)> value;
};

/// The field at each point (dim = 2: x, y with z = 0; dim = 3: x, y, z) at time t.
/// @throws InputError naming the field, the point and the value when a value is not finite.
std::vector<double> sample_field(const AnalyticField& field, std::span<const double> coordinates,
                                 unsigned dim, double t);

/// The field at one point; the same check.
double field_at(const AnalyticField& field, const double* point, unsigned dim, double t);

}  // namespace exactmesh::generators
