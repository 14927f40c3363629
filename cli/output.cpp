// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands (see output.hpp).
#include "cli/output.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <string>

#include "io/gmsh_format.hpp"
#include "io/svg_picture.hpp"
#include "io/triangle_format.hpp"
#include "io/vtk_format.hpp"
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

void write_constrained_result(const triangulation::Cdt2Result& result, const std::vector<std::filesystem::path>& files,
                              OutputFormat format, std::uint32_t base, const std::string& svg_title) {
    namespace fs = std::filesystem;
    const triangulation::Triangulation2& mesh = result.mesh;
    const fs::path& output = files[0];
    switch (format) {
        case OutputFormat::Ele: {
            const fs::path &neigh = files[1], &node = files[2], &pieces = files[3];
            io::NodeFile vertices;
            vertices.xy = mesh.xy;
            vertices.first_index = base;
            std::vector<std::int32_t> markers;
            for (const std::uint32_t s : result.piece_segment) markers.push_back(static_cast<std::int32_t>(s + base));
            io::write_ele(output, mesh.triangles, base, result.triangle_attributes);
            io::write_neigh(neigh, mesh.neighbors, base);
            io::write_node(node, vertices);
            io::write_poly(pieces, vertices, result.pieces, markers);
            for (const fs::path& p : {output, neigh, node, pieces}) std::cout << "output: " << p.string() << '\n';
            return;
        }
        case OutputFormat::Msh: io::write_msh(output, mesh.xy, mesh.triangles); break;
        case OutputFormat::Vtu: io::write_vtu(output, mesh.xy, mesh.triangles, base); break;
        case OutputFormat::Svg: {
            io::SvgOptions svg;
            svg.title = svg_title;
            svg.segments = result.pieces;
            io::write_svg(output, mesh.xy, mesh.triangles, svg);
            break;
        }
    }
    std::cout << "output: " << output.string() << '\n';
}

void print_warnings(const std::vector<std::string>& warnings) {
    constexpr std::size_t kShownWarnings = 10;
    for (std::size_t i = 0; i < warnings.size() && i < kShownWarnings; ++i) {
        std::cerr << "exactmesh: warning: " << warnings[i] << '\n';
    }
    if (warnings.size() > kShownWarnings) {
        std::cerr << "exactmesh: warning: " << warnings.size() - kShownWarnings << " more warnings\n";
    }
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
