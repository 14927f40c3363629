// SPDX-License-Identifier: MIT
// Helpers shared by the construction commands: the output format named by a file extension,
// and the predicate stage counters printed by --stats.
#pragma once

#include <filesystem>

#include "predicates/stats.hpp"

namespace exactmesh::cli {

enum class OutputFormat { Ele, Msh, Vtu, Svg };

/// The format of `output` from its extension (.ele, .msh, .vtu, .svg; any case).
/// @throws InputError naming the file and the unsupported extension.
OutputFormat output_format(const std::filesystem::path& output);

/// `name.calls: N` ... one line per stage, or a note when the counters are compiled out.
void print_predicate_stats(const predicates::PredicateStats& stats);

}  // namespace exactmesh::cli
