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

/// An expression as messages show it: control bytes escaped, cut after 200 characters (a
/// 40 kB expression was echoed whole, twice, in one error line).
std::string shown(const std::string& expression) {
    return io::printable(expression, 200);
}

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
                             "--size '" + shown(expression) +
                                 "' is neither a number > 0, a readable size file, nor an " +
                                 "expression in x and y: ");
    return generators::SizeFunction::analytic(
        [evaluator](double x, double y) {
            evaluator->v[0] = x;
            evaluator->v[1] = y;
            return evaluator->parser.Eval();
        },
        "expression " + shown(expression));
}

generators::SizeFunction3 size3_from_option(const std::string& text) {
    double uniform = 0;
    if (generators::parse_uniform_size(text, uniform))
        return generators::SizeFunction3::uniform(uniform);
    std::error_code error;
    if (std::filesystem::exists(text, error)) {
        throw InputError("--size '" + shown(text) +
                         "': size files are 2D only; give a number or an expression in x, y, z");
    }
    auto evaluator = compile(
        text, 3,
        "--size '" + shown(text) + "' is neither a number > 0 nor an expression in x, y and z: ");
    return generators::SizeFunction3::analytic(
        [evaluator](double x, double y, double z) {
            evaluator->v[0] = x;
            evaluator->v[1] = y;
            evaluator->v[2] = z;
            return evaluator->parser.Eval();
        },
        "expression " + shown(text));
}

generators::MetricField2 metric_from_expression(const std::string& text) {
    const std::string refusal =
        "--metric '" + shown(text) +
        "' is neither a readable metric file (.node with 3 or 4 "
        "attributes and its .ele) nor three expressions 'M11;M12;M22' or four "
        "'DIR_X;DIR_Y;SIZE_ALONG;ASPECT_RATIO' in x and y";
    std::vector<std::string> parts(1);
    for (const char letter : text) {
        if (letter == ';')
            parts.emplace_back();
        else
            parts.back() += letter;
    }
    if (parts.size() != 3 && parts.size() != 4)
        throw InputError(refusal + " (" + std::to_string(parts.size()) + " parts)");
    // Three parts: a matrix; four: a stretching vector (sizes, so a domain scaled by 2^k takes
    // its sizes scaled by 2^k, where a matrix would need 2^-2k).
    const bool stretching = parts.size() == 4;
    static constexpr const char* kMatrixNames[3] = {"M11", "M12", "M22"};
    static constexpr const char* kStretchingNames[4] = {"DIR_X", "DIR_Y", "SIZE_ALONG",
                                                        "ASPECT_RATIO"};
    std::vector<std::shared_ptr<Evaluator>> entries;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const char* name = stretching ? kStretchingNames[k] : kMatrixNames[k];
        entries.push_back(
            compile(parts[k], 2, refusal + ": " + name + " '" + shown(parts[k]) + "': "));
    }
    return generators::MetricField2::analytic(
        [entries, text, stretching](double x, double y) {
            double value[4] = {};
            for (std::size_t k = 0; k < entries.size(); ++k) {
                Evaluator& evaluator = *entries[k];
                evaluator.v[0] = x;
                evaluator.v[1] = y;
                value[k] = evaluator.parser.Eval();
            }
            try {
                return stretching ? generators::metric_from_stretching(value[0], value[1], value[2],
                                                                       value[3])
                                  : generators::metric_from_matrix(value[0], value[1], value[2]);
            } catch (const InputError& error) {
                throw InputError("--metric '" + shown(text) + "' at (" + format_number(x) + ", " +
                                 format_number(y) + "): " + error.what());
            }
        },
        "expression " + shown(text));
}

generators::MetricField2 metric_from_option(const std::string& text) {
    std::error_code error;
    if (std::filesystem::exists(text, error)) return read_metric_file(text);
    return metric_from_expression(text);
}

generators::AnalyticField field_from_expression(const std::string& expression) {
    auto evaluator =
        compile(expression, 4,
                "--field '" + shown(expression) + "' is not an expression in x, y, z and t: ");
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
