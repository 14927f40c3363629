// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands: the output format named by a file extension,
// all-or-nothing output sets (io::OutputSet) and the refusal of outputs that are inputs, the
// --order option, and the predicate stage counters printed by --stats.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "cli/options.hpp"
#include "io/point_set_2d.hpp"
#include "io/svg_picture.hpp"
#include "io/text_file.hpp"
#include "predicates/stats.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::cli {

enum class OutputFormat { Ele, Msh, Vtu, Svg };

/// The format of `output` from its extension (.ele, .msh, .vtu, .svg; any case).
/// @throws InputError naming the file and the unsupported extension.
OutputFormat output_format(const std::filesystem::path& output);

/// The files a command writes for `output`: itself, and for .ele its companions with the given
/// extensions (".neigh", ".node", ...), each replacing the extension of `output`.
std::vector<std::filesystem::path> output_files(const std::filesystem::path& output,
                                                OutputFormat format,
                                                std::initializer_list<const char*> ele_companions);

/// @throws InputError when one of `outputs` resolves to one of `inputs` (the same file by
/// std::filesystem::equivalent, so through links, hard links and `./` spellings: `swap IN.node
/// IN.ele -o IN.ele`, or an `-o IN.ele` next to IN.poly that would overwrite IN.poly with the
/// .poly of the result), before any work is done. Inputs that do not exist are skipped.
void refuse_to_overwrite_inputs(const std::vector<std::filesystem::path>& inputs,
                                const std::vector<std::filesystem::path>& outputs);

/// Whether `path` names an existing file (not a directory): for optional inputs such as the
/// .node companion of a .poly, or a --size file.
bool is_existing_file(const std::filesystem::path& path);

/// Moves every file of `set` into place (io::OutputSet::commit) and prints "output: <file>"
/// for each, in order. Every command writes its outputs through one set: a failing companion
/// or a full disk then leaves every previous output as it was.
void commit_outputs(io::OutputSet& set);

/// The output extension check of swap, swap3d and min-max (any case: .ELE is a .ele).
/// @throws InputError naming the file when it does not end in .ele.
void require_ele_output(const std::filesystem::path& output);

/// Rethrows `error` as an io::FormatError located at the line of its hole or region in `file`
/// (the .poly it was read from), so the message names the file and the line.
[[noreturn]] void rethrow_at_line(const triangulation::AmbiguousMarkPoint& error,
                                  const io::PolyFile& poly, const std::string& file);

/// `work()`, with a hole or region point on a segment or a vertex reported at its line of `file`.
template <class Work>
auto locating_mark_points(const io::PolyFile& poly, const std::string& file, Work&& work) {
    try {
        return work();
    } catch (const triangulation::AmbiguousMarkPoint& error) {
        rethrow_at_line(error, poly, file);
    }
}

/// `work()` (a command's construction from its input `file`), with an InputError or
/// GeometryError whose message does not name `file` rethrown with "file: " in front: a
/// generator's refusal ("segment 4: its piece ... is too short to split", a Steiner budget)
/// then names the file it is about, as the readers' errors do. The exception's class is kept
/// as the command's exit status sees it (InputError or GeometryError: exit 2).
template <class Work>
auto naming_the_input(const std::string& file, Work&& work) {
    try {
        return work();
    } catch (const InputError& error) {
        if (file.empty() || std::string_view(error.what()).find(file) != std::string_view::npos)
            throw;
        throw InputError(file + ": " + error.what());
    } catch (const GeometryError& error) {
        if (file.empty() || std::string_view(error.what()).find(file) != std::string_view::npos)
            throw;
        throw GeometryError(file + ": " + error.what());
    }
}

/// The check of an integer option (--seed, --max-steiner, --smooth) as a CLI11 validator
/// body: "" when `text` is a whole decimal integer in [0, max], else the reason. CLI11's own
/// conversion to an unsigned type wraps "-1" to 2^64 - 1 and saturates larger numbers.
std::string check_unsigned_text(const std::string& text, std::uint64_t max);
/// "" when `text` is a whole decimal number (as strtod reads it, all of it) that is finite and
/// > 0; else why not.
std::string check_positive_number_text(const std::string& text);

/// The window of `--view X0,Y0,X1,Y1`: four comma-separated decimal numbers.
/// @throws InputError naming the problem (not four numbers, not finite, X1 <= X0, Y1 <= Y0).
io::SvgWindow parse_view(const std::string& text);

/// parse_view's check as a CLI11 validator body: "" when `text` is a usable window, else why.
std::string check_view_text(const std::string& text);

/// The options of a picture titled `title` from --view and --shade. @throws InputError when
/// either is given for an output `format` other than .svg (it would be silently ignored).
io::SvgOptions picture_options(const PictureArguments& picture, OutputFormat format,
                               const std::string& title);

/// Stages a constrained triangulation (`cdt`, `mesh`) into `set` for `files` (output_files(output,
/// format,
/// {".neigh", ".node", ".poly"})): .ele with .neigh, .node (every vertex) and .poly (the pieces,
/// each marked with its input segment's number); or .msh, .vtu, .svg (with the pieces drawn).
/// `svg`: the picture's options (picture_options), its segments filled in here.
/// Numbers vertices, triangles and segments from `base`. `quads` (4·#Q, a mixed mesh) go to .msh
/// and .vtu as quadrilaterals and to .svg drawn as two triangles each; .ele refuses them.
/// `vertex_field` (#V, or empty) is the .node's attribute, the .msh's node data and the .vtu's
/// point array "u". Nothing is in place until commit.
void stage_constrained_result(io::OutputSet& set, const triangulation::Cdt2Result& result,
                              const std::vector<std::filesystem::path>& files, OutputFormat format,
                              std::uint32_t base, const io::SvgOptions& svg,
                              std::span<const double> vertex_field = {},
                              std::span<const triangulation::VertIdx> quads = {});

/// Region maximum areas (Triangle's -a per region) are read but not applied by `cdt`: warns once,
/// at the first region that gives one, with `why`.
void warn_unused_region_areas(const io::PolyFile& poly, const std::string& file,
                              const std::string& why);

/// Prints the first 10 warnings as "exactmesh: warning: ..." on stderr, then how many more.
void print_warnings(const std::vector<std::string>& warnings);

/// `name.calls: N` ... one line per stage of the predicates of that dimension (orient2d and
/// incircle, or orient3d and insphere), or a note when the counters are compiled out.
void print_predicate_stats(const predicates::PredicateStats& stats, int dimension = 2);

/// `name: value`, one line each, in order (a counters table: base/counter_table.hpp).
void print_counters(const std::vector<std::pair<std::string, std::uint64_t>>& counters);

/// `construct_seconds: T` on a line of its own (fixed, 6 decimals; the stream's format restored).
void print_construct_seconds(double seconds);

/// Seconds of wall time since `start` (steady clock).
double seconds_since(std::chrono::steady_clock::time_point start);

/// The --stats lines of a construction: its work counters (print_counters), the predicate
/// stages of that dimension (print_predicate_stats), construct_seconds.
void print_construction_stats(const std::vector<std::pair<std::string, std::uint64_t>>& counters,
                              const predicates::PredicateStats& stats, double seconds,
                              int dimension = 2);

/// The --quality report of a tetrahedralization (triangulation/checks/quality_3d): dihedral
/// extremes, volume-edge, radius-edge, slivers, the 10-degree dihedral histogram, the count of
/// radius-edge ratios over 2 and their histogram (bins of 0.2 up to 4, then [4, inf)).
void print_quality_3d(const triangulation::Tetrahedralization3& mesh,
                      const std::string& prefix = "");

/// What a timed construction returned, with its predicate stages and its wall time.
template <class Result>
struct TimedConstruction {
    Result result;
    predicates::PredicateStats stats;
    double seconds;
};

/// Runs `construct()` alone (no file I/O) on the clock, with the predicate counters reset
/// before it and read right after it.
template <class Construct>
auto timed_construction(Construct&& construct) {
    predicates::reset_thread_stats();
    const auto start = std::chrono::steady_clock::now();
    auto result = construct();
    const double seconds = seconds_since(start);
    return TimedConstruction<decltype(result)>{std::move(result), predicates::thread_stats(),
                                               seconds};
}

}  // namespace exactmesh::cli
