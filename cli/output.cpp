// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands (see output.hpp).
#include "cli/output.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <string>

#include "predicates/errors.hpp"

namespace exactmesh::cli {

namespace {

void print_stage_counts(const char* name, const predicates::StageCounts& counts) {
    const std::string prefix = std::string(name) + ".";
    std::cout << prefix << "calls: " << counts.calls << '\n'
              << prefix << "filter: " << counts.filter << '\n'
              << prefix << "exact_differences: " << counts.exact_differences << '\n'
              << prefix << "adaptive: " << counts.adaptive << '\n'
              << prefix << "expansion: " << counts.expansion << '\n'
              << prefix << "gmp: " << counts.gmp << '\n';
}

}  // namespace

OutputFormat output_format(const std::filesystem::path& output) {
    std::string extension = output.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".ele") return OutputFormat::Ele;
    if (extension == ".msh") return OutputFormat::Msh;
    if (extension == ".vtu") return OutputFormat::Vtu;
    if (extension == ".svg") return OutputFormat::Svg;
    throw InputError(output.string() + ": unsupported output extension '" + extension +
                     "' (use .ele, .msh, .vtu or .svg)");
}

std::vector<std::filesystem::path> output_files(const std::filesystem::path& output, OutputFormat format,
                                                std::initializer_list<const char*> ele_companions) {
    std::vector<std::filesystem::path> files{output};
    if (format == OutputFormat::Ele) {
        for (const char* extension : ele_companions) {
            std::filesystem::path companion = output;
            files.push_back(companion.replace_extension(extension));
        }
    }
    return files;
}

void refuse_to_overwrite_input(const std::filesystem::path& input, const std::vector<std::filesystem::path>& outputs) {
    std::error_code error;
    for (const std::filesystem::path& output : outputs) {
        if (std::filesystem::exists(output, error) && std::filesystem::equivalent(input, output, error)) {
            throw InputError(output.string() + ": this output would overwrite the input file; choose another -o name "
                             "(Triangle's convention: IN.1.ele)");
        }
    }
}

triangulation::InsertionOrder insertion_order(const std::string& name) {
    if (name == "given") return triangulation::InsertionOrder::Given;
    if (name == "random") return triangulation::InsertionOrder::Random;
    if (name == "brio") return triangulation::InsertionOrder::Brio;
    throw InputError("unknown insertion order '" + name + "' (known: given, random, brio)");
}

void print_predicate_stats(const predicates::PredicateStats& stats, int dimension) {
    if (predicates::stats_enabled() && dimension == 3) {
        print_stage_counts("orient3d", stats.orient3d);
        print_stage_counts("insphere", stats.insphere);
    } else if (predicates::stats_enabled()) {
        print_stage_counts("orient2d", stats.orient2d);
        print_stage_counts("incircle", stats.incircle);
    } else {
        std::cout << "predicate_stages: compiled out (configure with -DEXACTMESH_PREDICATE_STATS=ON)\n";
    }
}

}  // namespace exactmesh::cli
