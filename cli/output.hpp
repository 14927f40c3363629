// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands: the output format named by a file extension,
// the --order option, and the predicate stage counters printed by --stats.
#pragma once

#include <filesystem>
#include <string>

#include "predicates/stats.hpp"
#include "triangulation/delaunay_2d.hpp"

namespace exactmesh::cli {

enum class OutputFormat { Ele, Msh, Vtu, Svg };

/// The format of `output` from its extension (.ele, .msh, .vtu, .svg; any case).
/// @throws InputError naming the file and the unsupported extension.
OutputFormat output_format(const std::filesystem::path& output);

/// The insertion order named by --order (given, random, brio).
/// @throws InputError naming the unknown order and the known ones.
triangulation::InsertionOrder insertion_order(const std::string& name);

/// `name.calls: N` ... one line per stage, or a note when the counters are compiled out.
void print_predicate_stats(const predicates::PredicateStats& stats);

}  // namespace exactmesh::cli
