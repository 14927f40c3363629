// SPDX-License-Identifier: MIT
// The command line's expressions, parsed and evaluated by muParser (Debian's libmuparser-dev):
//  - `--size EXPR` of `mesh` and `adapt`: a size function s(x, y) ("0.01 + 0.1 * sqrt(x^2 +
//    y^2)") as an analytic generators::SizeFunction, and `--size` as a whole (a number, a size
//    file or an expression);
//  - `--metric EXPR` of `mesh`: a metric field 'M11;M12;M22' (three expressions in x and y) or
//    'DIR_X;DIR_Y;SIZE_ALONG;ASPECT_RATIO' (a stretching vector, four), as an
//    analytic generators::MetricField2 (and `--metric` as a whole: an expression or a metric
//    file, cli/metric_file.hpp);
//  - `--field EXPR` of `adapt`: a scalar field u(x, y, z, t), the solver's stand-in of issue 13
//    ("tanh(20 * (x + y - 1 - 0.5 * t))"), as a generators::AnalyticField.
#pragma once

#include <string>

#include "generators/adaptation/vertex_field.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/sizing/size_function_3d.hpp"
#include "generators/stretched/metric_field_2d.hpp"

namespace exactmesh::cli {

/// The expression as a size function; muParser's syntax (+ - * / ^, sqrt, exp, log, sin, min,
/// max, abs, ..., the constants _pi and _e) with the variables x and y.
/// @throws InputError naming the expression and muParser's message when it does not parse, uses
///         a variable other than x and y, or evaluates to NaN at the origin of the parse check.
generators::SizeFunction size_from_expression(const std::string& expression);

/// `--size` of `mesh` and `adapt`: a number (uniform), else a size file
/// (generators/sizing/size_function.hpp) when a file of that name exists (one that exists but
/// cannot be read is reported as such, not as a bad expression), else an expression in x and y.
/// @throws InputError (io::FormatError for a bad file) naming the text.
generators::SizeFunction size_from_option(const std::string& text);

/// `--size` of `tetmesh`: a number (uniform), else an expression in x, y and z (muParser's
/// syntax, as for the 2D --size). Size files are 2D only: an existing file is refused.
/// @throws InputError naming the text (and muParser's message).
generators::SizeFunction3 size3_from_option(const std::string& text);

/// 'M11;M12;M22': three expressions in x and y (muParser's syntax, as for --size) separated by
/// ';', the entries of a symmetric positive definite matrix at (x, y); or
/// 'DIR_X;DIR_Y;SIZE_ALONG;ASPECT_RATIO': four, a stretching vector (metric_from_stretching:
/// sizes, which scale with the domain).
/// @throws InputError naming the text (and muParser's message) when it is not three or four
///         expressions in x and y; the field itself throws InputError "--metric '...' at (x, y):
///         metric (M11, M12, M22) = (...) is not positive definite ..." where its matrix is not.
generators::MetricField2 metric_from_expression(const std::string& text);

/// `--metric` of `mesh`: a metric file (cli/metric_file.hpp) when a file of that name exists,
/// else metric_from_expression.
generators::MetricField2 metric_from_option(const std::string& text);

/// muParser's syntax (+ - * / ^, sqrt, exp, log, sin, tanh, min, max, abs, ..., _pi, _e) with the
/// variables x, y, z and t.
/// @throws InputError naming the expression and muParser's message when it does not parse or
///         uses another variable.
generators::AnalyticField field_from_expression(const std::string& expression);

}  // namespace exactmesh::cli
