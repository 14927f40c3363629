// SPDX-License-Identifier: MIT
// `--size EXPR` through muParser (see size_expression.hpp). One parser per size function, its
// variables bound to the two doubles the evaluation writes before each call; muParser compiles
// the expression to bytecode on the first Eval, so later calls cost about 50 ns.
#include "cli/size_expression.hpp"

#include <muParser.h>

#include <filesystem>
#include <memory>

#include "base/errors.hpp"
#include "io/text_file.hpp"

namespace exactmesh::cli {

namespace {

struct Evaluator {
    mu::Parser parser;
    double x = 0, y = 0;
};

}  // namespace

generators::SizeFunction size_from_expression(const std::string& expression) {
    auto evaluator = std::make_shared<Evaluator>();
    try {
        evaluator->parser.DefineVar("x", &evaluator->x);
        evaluator->parser.DefineVar("y", &evaluator->y);
        evaluator->parser.SetExpr(expression);
        evaluator->parser.Eval();  // parses now: syntax errors and unknown variables surface here
    } catch (const mu::Parser::exception_type& error) {
        throw InputError("--size '" + expression +
                         "' is neither a number > 0, a readable size file, nor an " +
                         "expression in x and y: " + error.GetMsg());
    }
    return generators::SizeFunction::analytic(
        [evaluator](double x, double y) {
            evaluator->x = x;
            evaluator->y = y;
            return evaluator->parser.Eval();
        },
        "expression " + expression);
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
