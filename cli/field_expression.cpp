// SPDX-License-Identifier: MIT
// `--field EXPR` through muParser (see field_expression.hpp), as size_expression.cpp does for
// sizes: one parser per field, its variables bound to four doubles written before each call.
#include "cli/field_expression.hpp"

#include <muParser.h>

#include <memory>

#include "base/errors.hpp"

namespace exactmesh::cli {

namespace {

struct FieldEvaluator {
    mu::Parser parser;
    double x = 0, y = 0, z = 0, t = 0;
};

}  // namespace

generators::AnalyticField field_from_expression(const std::string& expression) {
    auto evaluator = std::make_shared<FieldEvaluator>();
    try {
        evaluator->parser.DefineVar("x", &evaluator->x);
        evaluator->parser.DefineVar("y", &evaluator->y);
        evaluator->parser.DefineVar("z", &evaluator->z);
        evaluator->parser.DefineVar("t", &evaluator->t);
        evaluator->parser.SetExpr(expression);
        evaluator->parser.Eval();  // parses now: syntax errors and unknown variables surface here
    } catch (const mu::Parser::exception_type& error) {
        throw InputError("--field '" + expression +
                         "' is not an expression in x, y, z and t: " + error.GetMsg());
    }
    return {expression, [evaluator](double x, double y, double z, double t) {
                evaluator->x = x;
                evaluator->y = y;
                evaluator->z = z;
                evaluator->t = t;
                return evaluator->parser.Eval();
            }};
}

}  // namespace exactmesh::cli
