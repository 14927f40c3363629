// SPDX-License-Identifier: MIT
// The command line's expressions through muParser (see expressions.hpp). One parser per
// function, its variables bound to doubles the evaluation writes before each call; muParser
// compiles the expression to bytecode on the first Eval, so later calls cost about 50 ns.
#include "cli/expressions.hpp"

#include <muParser.h>

#include <filesystem>
#include <memory>

#include "base/errors.hpp"
#include "io/text_file.hpp"

namespace exactmesh::cli {

namespace {

/// A parser and the variables it reads, x, y, z, t in that order (v[0..3]).
struct Evaluator {
    mu::Parser parser;
    double v[4] = {0, 0, 0, 0};
};

/// `expression` parsed over the first `count` of x, y, z, t.
/// @throws InputError: `refusal` followed by muParser's message.
std::shared_ptr<Evaluator> compile(const std::string& expression, int count,
                                   const std::string& refusal) {
    static constexpr const char* kNames[4] = {"x", "y", "z", "t"};
    auto evaluator = std::make_shared<Evaluator>();
    try {
        for (int k = 0; k < count; ++k) evaluator->parser.DefineVar(kNames[k], &evaluator->v[k]);
        evaluator->parser.SetExpr(expression);
        evaluator->parser.Eval();  // parses now: syntax errors and unknown variables surface here
    } catch (const mu::Parser::exception_type& error) {
        throw InputError(refusal + error.GetMsg());
    }
    return evaluator;
}

}  // namespace

generators::SizeFunction size_from_expression(const std::string& expression) {
    auto evaluator = compile(expression, 2,
                             "--size '" + expression +
                                 "' is neither a number > 0, a readable size file, nor an " +
                                 "expression in x and y: ");
    return generators::SizeFunction::analytic(
        [evaluator](double x, double y) {
            evaluator->v[0] = x;
            evaluator->v[1] = y;
            return evaluator->parser.Eval();
        },
        "expression " + expression);
}

generators::AnalyticField field_from_expression(const std::string& expression) {
    auto evaluator = compile(
        expression, 4, "--field '" + expression + "' is not an expression in x, y, z and t: ");
    return {expression, [evaluator](double x, double y, double z, double t) {
                evaluator->v[0] = x;
                evaluator->v[1] = y;
                evaluator->v[2] = z;
                evaluator->v[3] = t;
                return evaluator->parser.Eval();
            }};
}

namespace {

/// The longest size file read (a background mesh of about a million lines).
constexpr std::size_t kMaxSizeFileBytes = std::size_t{64} << 20;

}  // namespace

generators::SizeFunction size_from_option(const std::string& text) {
    double uniform = 0;
    if (generators::parse_uniform_size(text, uniform))
        return generators::SizeFunction::uniform(uniform);
    std::error_code error;
    if (!std::filesystem::exists(text, error)) return size_from_expression(text);
    return generators::parse_size_sources(io::read_text_file(text, kMaxSizeFileBytes), text);
}

}  // namespace exactmesh::cli
