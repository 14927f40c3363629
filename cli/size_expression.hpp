// SPDX-License-Identifier: MIT
// `--size EXPR`: a size function s(x, y) given as an expression in x and y ("0.01 + 0.1 *
// sqrt(x^2 + y^2)"), parsed and evaluated by muParser (Debian's libmuparser-dev) into an analytic
// generators::SizeFunction.
#pragma once

#include <string>

#include "generators/sizing/size_function.hpp"

namespace exactmesh::cli {

/// The expression as a size function; muParser's syntax (+ - * / ^, sqrt, exp, log, sin, min,
/// max, abs, ..., the constants _pi and _e) with the variables x and y.
/// @throws InputError naming the expression and muParser's message when it does not parse, uses
///         a variable other than x and y, or evaluates to NaN at the origin of the parse check.
generators::SizeFunction size_from_expression(const std::string& expression);

}  // namespace exactmesh::cli
