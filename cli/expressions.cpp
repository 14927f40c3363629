// SPDX-License-Identifier: MIT
// The command line's expressions through muParser (see expressions.hpp). One parser per
// function, its variables bound to doubles the evaluation writes before each call; muParser
// compiles the expression to bytecode on the first Eval, so later calls cost about 50 ns.
#include "cli/expressions.hpp"

#include <muParser.h>

#include <filesystem>
#include <memory>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "cli/metric_file.hpp"
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

generators::MetricField2 metric_from_expression(const std::string& text) {
    const std::string refusal =
        "--metric '" + text +
        "' is neither a readable metric file (.node with 3 or 4 "
        "attributes and its .ele) nor three expressions 'M11;M12;M22' in x and y";
    std::vector<std::string> parts(1);
    for (const char letter : text) {
        if (letter == ';')
            parts.emplace_back();
        else
            parts.back() += letter;
    }
    if (parts.size() != 3)
        throw InputError(refusal + " (" + std::to_string(parts.size()) + " parts)");
    static constexpr const char* kNames[3] = {"M11", "M12", "M22"};
    std::shared_ptr<Evaluator> entries[3];
    for (int k = 0; k < 3; ++k) {
        entries[k] =
            compile(parts[static_cast<std::size_t>(k)], 2,
                    refusal + ": " + kNames[k] + " '" + parts[static_cast<std::size_t>(k)] + "': ");
    }
    return generators::MetricField2::analytic(
        [m11 = entries[0], m12 = entries[1], m22 = entries[2], text](double x, double y) {
            double value[3];
            const std::shared_ptr<Evaluator>* all[3] = {&m11, &m12, &m22};
            for (int k = 0; k < 3; ++k) {
                Evaluator& evaluator = **all[k];
                evaluator.v[0] = x;
                evaluator.v[1] = y;
                value[k] = evaluator.parser.Eval();
            }
            try {
                return generators::metric_from_matrix(value[0], value[1], value[2]);
            } catch (const InputError& error) {
                throw InputError("--metric '" + text + "' at (" + format_number(x) + ", " +
                                 format_number(y) + "): " + error.what());
            }
        },
        "expression " + text);
}

generators::MetricField2 metric_from_option(const std::string& text) {
    std::error_code error;
    if (std::filesystem::exists(text, error)) return read_metric_file(text);
    return metric_from_expression(text);
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
