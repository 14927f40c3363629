// SPDX-License-Identifier: MIT
// `--field EXPR` of `exactmesh adapt`: a scalar field u(x, y, z, t) given as an expression,
// parsed and evaluated by muParser (Debian's libmuparser-dev) into a generators::AnalyticField,
// the solver's stand-in of issue 13 ("tanh(20 * (x + y - 1 - 0.5 * t))").
#pragma once

#include <string>

#include "generators/adaptation/vertex_field.hpp"

namespace exactmesh::cli {

/// muParser's syntax (+ - * / ^, sqrt, exp, log, sin, tanh, min, max, abs, ..., _pi, _e) with the
/// variables x, y, z and t.
/// @throws InputError naming the expression and muParser's message when it does not parse or
///         uses another variable.
generators::AnalyticField field_from_expression(const std::string& expression);

}  // namespace exactmesh::cli
