// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands: the output format named by a file extension,
// the --order option, and the predicate stage counters printed by --stats.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include "predicates/stats.hpp"
#include "triangulation/constrained_2d.hpp"
#include "triangulation/delaunay_2d.hpp"

namespace exactmesh::cli {

enum class OutputFormat { Ele, Msh, Vtu, Svg };

/// The format of `output` from its extension (.ele, .msh, .vtu, .svg; any case).
/// @throws InputError naming the file and the unsupported extension.
OutputFormat output_format(const std::filesystem::path& output);

/// The files a command writes for `output`: itself, and for .ele its companions with the given
/// extensions (".neigh", ".node", ...), each replacing the extension of `output`.
std::vector<std::filesystem::path> output_files(const std::filesystem::path& output, OutputFormat format,
                                                std::initializer_list<const char*> ele_companions);

/// @throws InputError when one of `outputs` is the input file (an `-o IN.ele` next to IN.poly
/// would overwrite IN.poly with the .poly of the result), before any work is done.
void refuse_to_overwrite_input(const std::filesystem::path& input, const std::vector<std::filesystem::path>& outputs);

/// The insertion order named by --order (given, random, brio).
/// @throws InputError naming the unknown order and the known ones.
triangulation::InsertionOrder insertion_order(const std::string& name);

/// Writes a constrained triangulation (`cdt`, `mesh`) to `files` (output_files(output, format,
/// {".neigh", ".node", ".poly"})): .ele with .neigh, .node (every vertex) and .poly (the pieces,
/// each marked with its input segment's number); or .msh, .vtu, .svg (with the pieces drawn).
/// Numbers vertices, triangles and segments from `base`; prints "output: <file>" per file.
void write_constrained_result(const triangulation::Cdt2Result& result, const std::vector<std::filesystem::path>& files,
                              OutputFormat format, std::uint32_t base, const std::string& svg_title);

/// Prints the first 10 warnings as "exactmesh: warning: ..." on stderr, then how many more.
void print_warnings(const std::vector<std::string>& warnings);

/// `name.calls: N` ... one line per stage of the predicates of that dimension (orient2d and
/// incircle, or orient3d and insphere), or a note when the counters are compiled out.
void print_predicate_stats(const predicates::PredicateStats& stats, int dimension = 2);

}  // namespace exactmesh::cli
