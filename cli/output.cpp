// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands (see output.hpp).
#include "cli/output.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <span>
#include <string>

#include "base/errors.hpp"
#include "io/format_error.hpp"
#include "io/gmsh_format.hpp"
#include "io/svg_picture.hpp"
#include "io/triangle_format.hpp"
#include "io/vtk_format.hpp"
#include "triangulation/checks/quality_3d.hpp"

namespace exactmesh::cli {

namespace {

void print_stage_counts(const char* name, const predicates::StageCounts& counts) {
    const std::string prefix = std::string(name) + ".";
    std::cout << prefix << "calls: " << counts.calls << '\n'
              << prefix << "filter: " << counts.filter << '\n'
              << prefix << "exact_differences: " << counts.exact_differences << '\n'
              << prefix << "adaptive: " << counts.adaptive << '\n'
              << prefix << "expansion: " << counts.expansion << '\n'
              << prefix << "gmp: " << counts.gmp << '\n'
              << prefix << "rescaled: " << counts.rescaled << '\n';
}

/// The predicates --stats reports, in order, for a 2D and a 3D command.
using Stats = predicates::PredicateStats;
using StageRow = std::pair<const char*, predicates::StageCounts Stats::*>;
constexpr StageRow kStages2d[] = {
    {"orient2d", &Stats::orient2d},
    {"incircle", &Stats::incircle},
    {"compare_angles", &Stats::compare_angles},
    {"compare_lengths", &Stats::compare_lengths},
    {"corner_dot_sign", &Stats::corner_dot_sign},
    {"direction_dot_sign", &Stats::direction_dot_sign},
    {"within_rounding_of_segment", &Stats::within_rounding_of_segment},
    {"in_ellipse", &Stats::in_ellipse},
    {"compare_metric_lengths", &Stats::compare_metric_lengths},
};
constexpr StageRow kStages3d[] = {
    {"orient3d", &Stats::orient3d},
    {"insphere", &Stats::insphere},
    {"compare_dihedral", &Stats::compare_dihedral},
    {"compare_volume_edge", &Stats::compare_volume_edge},
    {"dot_sign_3d", &Stats::dot_sign_3d},
    {"compare_radius_edge_3d", &Stats::compare_radius_edge_3d},
    {"compare_tet_volume_3d", &Stats::compare_tet_volume_3d},
    {"in_equatorial_sphere_3d", &Stats::in_equatorial_sphere_3d},
    {"compare_angle_60_3d", &Stats::compare_angle_60_3d},
    {"compare_lengths_3d", &Stats::compare_lengths_3d},
};

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

std::vector<std::filesystem::path> output_files(const std::filesystem::path& output,
                                                OutputFormat format,
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

void refuse_to_overwrite_inputs(const std::vector<std::filesystem::path>& inputs,
                                const std::vector<std::filesystem::path>& outputs) {
    for (const std::filesystem::path& output : outputs) {
        for (const std::filesystem::path& input : inputs) {
            // equivalent() follows links on both sides and compares the files themselves (device
            // and inode), so a link to the input or a hard link is refused too.
            std::error_code error;
            if (!std::filesystem::exists(output, error) || !std::filesystem::exists(input, error))
                continue;
            if (std::filesystem::equivalent(input, output, error) && !error) {
                throw InputError(output.string() + ": this output would overwrite the input file " +
                                 input.string() +
                                 "; choose another -o name "
                                 "(Triangle's convention: IN.1.ele)");
            }
        }
    }
}

bool is_existing_file(const std::filesystem::path& path) {
    std::error_code error;
    return std::filesystem::exists(path, error) && !std::filesystem::is_directory(path, error);
}

void commit_outputs(io::OutputSet& set) {
    set.commit();
    for (const std::filesystem::path& file : set.targets())
        std::cout << "output: " << file.string() << '\n';
}

void require_ele_output(const std::filesystem::path& output) {
    if (!io::has_extension(output, ".ele"))
        throw InputError(output.string() + ": the output must be a .ele file");
}

void rethrow_at_line(const triangulation::AmbiguousMarkPoint& error, const io::PolyFile& poly,
                     const std::string& file) {
    const bool hole = error.kind() == triangulation::AmbiguousMarkPoint::Kind::Hole;
    const std::vector<std::uint64_t>& lines = hole ? poly.hole_lines : poly.region_lines;
    const std::uint64_t line = error.index() < lines.size() ? lines[error.index()] : 0;
    throw io::FormatError(file, line, error.what());
}

std::string check_unsigned_text(const std::string& text, std::uint64_t max) {
    std::uint64_t value = 0;
    const char* const end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (!text.empty() && text[0] == '-')
        return "'" + text + "' is negative (expected an integer in [0, " + std::to_string(max) +
               "])";
    if (error == std::errc::result_out_of_range ||
        (error == std::errc{} && stop == end && value > max)) {
        return "'" + text + "' is too large (at most " + std::to_string(max) + ")";
    }
    if (error != std::errc{} || stop != end)
        return "'" + text + "' is not an integer in [0, " + std::to_string(max) + "]";
    return "";
}

std::string check_positive_number_text(const std::string& text) {
    double value = 0;
    const char* const end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (error == std::errc::result_out_of_range)
        return "'" + text + "' is beyond the range of doubles (expected a finite number > 0)";
    if (error != std::errc{} || stop != end || text.empty())
        return "'" + text + "' is not a number (expected a finite number > 0)";
    if (!std::isfinite(value) || !(value > 0)) return "'" + text + "' is not a finite number > 0";
    return "";
}

namespace {

/// Reads "X0,Y0,X1,Y1" into `values`: "" on success, else why not.
std::string read_view_fields(const std::string& text, double (&values)[4]) {
    const char* at = text.data();
    const char* const end = text.data() + text.size();
    for (int k = 0; k < 4; ++k) {
        const auto [stop, error] = std::from_chars(at, end, values[k]);
        if (error == std::errc::result_out_of_range)
            return "'" + text + "': a coordinate is beyond the range of doubles";
        const bool last = k == 3;
        if (error != std::errc{} || (last ? stop != end : stop == end || *stop != ','))
            return "'" + text + "' is not four comma-separated numbers X0,Y0,X1,Y1";
        at = last ? stop : stop + 1;
    }
    return "";
}

}  // namespace

io::SvgWindow parse_view(const std::string& text) {
    double values[4] = {};
    std::string problem = read_view_fields(text, values);
    if (problem.empty())
        problem = io::svg_window_problem({values[0], values[1], values[2], values[3]});
    if (!problem.empty()) throw InputError("--view: " + problem);
    return {values[0], values[1], values[2], values[3]};
}

std::string check_view_text(const std::string& text) {
    double values[4] = {};
    if (std::string problem = read_view_fields(text, values); !problem.empty()) return problem;
    return io::svg_window_problem({values[0], values[1], values[2], values[3]});
}

io::SvgOptions picture_options(const PictureArguments& picture, OutputFormat format,
                               const std::string& title) {
    io::SvgOptions svg;
    svg.title = title;
    if (format != OutputFormat::Svg) {
        if (!picture.view.empty() || picture.shade != "none")
            throw InputError("--view and --shade draw .svg pictures; the output is not a .svg");
        return svg;
    }
    if (!picture.view.empty()) svg.view = parse_view(picture.view);
    if (picture.shade == "min-angle") svg.shade = io::SvgShade::MinAngle;
    return svg;
}

void stage_constrained_result(io::OutputSet& set, const triangulation::Cdt2Result& result,
                              const std::vector<std::filesystem::path>& files, OutputFormat format,
                              std::uint32_t base, const io::SvgOptions& svg_options,
                              std::span<const double> vertex_field,
                              std::span<const triangulation::VertIdx> quads) {
    namespace fs = std::filesystem;
    const triangulation::Triangulation2& mesh = result.mesh;
    const fs::path& output = files[0];
    switch (format) {
        case OutputFormat::Ele: {
            if (!quads.empty())
                throw InputError(output.string() + ": a .ele file holds triangles only");
            const fs::path &neigh = files[1], &node = files[2], &pieces = files[3];
            io::NodeFile vertices;
            vertices.xy = mesh.xy;
            vertices.first_index = base;
            if (!vertex_field.empty()) {
                // A field at the vertices (exactmesh adapt): the .node's one attribute.
                vertices.attribute_count = 1;
                vertices.attributes.assign(vertex_field.begin(), vertex_field.end());
            }
            std::vector<std::int32_t> markers;
            for (const std::uint32_t s : result.piece_segment)
                markers.push_back(static_cast<std::int32_t>(s + base));
            set.stage(output, io::format_ele(mesh.triangles, base, result.triangle_attributes));
            set.stage(neigh, io::format_neigh(mesh.neighbors, base));
            set.stage(node, io::format_node(vertices));
            set.stage(pieces, io::format_poly(vertices, result.pieces, markers));
            return;
        }
        case OutputFormat::Msh:
            set.stage(output, io::format_msh(mesh.xy, mesh.triangles, vertex_field, quads));
            return;
        case OutputFormat::Vtu:
            set.stage(output, io::format_vtu(mesh.xy, mesh.triangles, base, vertex_field, quads));
            return;
        case OutputFormat::Svg: {
            io::SvgOptions svg = svg_options;
            svg.segments = result.pieces;
            // A picture: each quadrilateral drawn as two triangles.
            std::vector<triangulation::VertIdx> drawn(mesh.triangles);
            for (std::size_t q = 0; q < quads.size() / 4; ++q) {
                const auto c = quads.subspan(4 * q, 4);
                drawn.insert(drawn.end(), {c[0], c[1], c[2], c[0], c[2], c[3]});
            }
            set.stage(output, io::format_svg(mesh.xy, drawn, svg));
            return;
        }
    }
}

void warn_unused_region_areas(const io::PolyFile& poly, const std::string& file,
                              const std::string& why) {
    for (std::size_t r = 0; r < poly.regions.size() / 4; ++r) {
        if (poly.regions[4 * r + 3] > 0) {
            print_warnings({file + ":" + std::to_string(poly.region_lines[r]) +
                            ": region maximum areas are not applied (" + why + ")"});
            return;
        }
    }
}

void print_warnings(const std::vector<std::string>& warnings) {
    constexpr std::size_t kShownWarnings = 10;
    for (std::size_t i = 0; i < warnings.size() && i < kShownWarnings; ++i) {
        std::cerr << "exactmesh: warning: " << warnings[i] << '\n';
    }
    if (warnings.size() > kShownWarnings) {
        std::cerr << "exactmesh: warning: " << warnings.size() - kShownWarnings
                  << " more warnings\n";
    }
}

void print_predicate_stats(const predicates::PredicateStats& stats, int dimension) {
    if (!predicates::stats_enabled()) {
        std::cout
            << "predicate_stages: compiled out (configure with -DEXACTMESH_PREDICATE_STATS=ON)\n";
        return;
    }
    std::span<const StageRow> stages = kStages2d;
    if (dimension == 3) stages = kStages3d;
    for (const auto& [name, counts] : stages) print_stage_counts(name, stats.*counts);
}

void print_counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters) {
    for (const auto& [name, value] : counters) std::cout << name << ": " << value << '\n';
}

void print_construct_seconds(double seconds) {
    const std::ios_base::fmtflags flags = std::cout.flags();
    const std::streamsize precision = std::cout.precision();
    std::cout << "construct_seconds: " << std::fixed << std::setprecision(6) << seconds << '\n';
    std::cout.flags(flags);
    std::cout.precision(precision);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void print_construction_stats(const std::vector<std::pair<std::string, std::uint64_t>>& counters,
                              const predicates::PredicateStats& stats, double seconds,
                              int dimension) {
    print_counters(counters);
    print_predicate_stats(stats, dimension);
    print_construct_seconds(seconds);
}

void print_quality_3d(const triangulation::Tetrahedralization3& mesh, const std::string& prefix) {
    const triangulation::QualityStats3 q = triangulation::quality_stats_3d(mesh);
    const auto precision = std::cout.precision(10);
    std::cout << prefix << "min_dihedral_degrees: " << q.min_dihedral_degrees << '\n'
              << prefix << "max_dihedral_degrees: " << q.max_dihedral_degrees << '\n'
              << prefix << "min_volume_edge: " << q.min_volume_edge << '\n'
              << prefix << "mean_volume_edge: " << q.mean_volume_edge << '\n'
              << prefix << "max_radius_edge: " << q.max_radius_edge << '\n'
              << prefix << "slivers: " << q.slivers << '\n';
    for (std::size_t b = 0; b < q.dihedral_histogram.size(); ++b) {
        const auto lo = static_cast<int>(static_cast<double>(b) * q.histogram_bin_degrees);
        const auto hi = static_cast<int>(static_cast<double>(b + 1) * q.histogram_bin_degrees);
        std::cout << prefix << "dihedral_degrees[" << lo << "," << hi
                  << (b + 1 == q.dihedral_histogram.size() ? "]" : ")") << ": "
                  << q.dihedral_histogram[b] << '\n';
    }
    // Radius-edge bins [lo, hi), the last one [max, inf): flat tetrahedra have an infinite ratio.
    std::cout << prefix << "radius_edge_over_2: " << q.over_radius_edge_bound << '\n';
    const std::size_t last = q.radius_edge_histogram.size() - 1;
    for (std::size_t b = 0; b <= last; ++b) {
        std::cout << prefix << "radius_edge[" << static_cast<double>(b) * q.radius_edge_bin_width
                  << ",";
        if (b == last)
            std::cout << "inf";
        else
            std::cout << static_cast<double>(b + 1) * q.radius_edge_bin_width;
        std::cout << "): " << q.radius_edge_histogram[b] << '\n';
    }
    std::cout.precision(precision);
}

}  // namespace exactmesh::cli
