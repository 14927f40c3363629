// SPDX-License-Identifier: MIT
// Options that several subcommands share, declared once so that their text and checks agree.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace exactmesh::cli {

/// A CLI11 check that the option's text is a whole decimal number in [0, max]
/// (check_unsigned_text: CLI11's own conversion wraps "-1" and saturates larger numbers).
CLI::Validator whole_number_at_most(std::uint64_t max);

/// A CLI11 check that the option's text is a finite number > 0 (check_positive_number_text:
/// CLI11's PositiveNumber lets "nan" through and names the range with 300 digits).
CLI::Validator finite_positive_number();

/// `--seed S`: the seed of the random and brio insertion orders, any 64-bit unsigned value.
void add_seed_option(CLI::App& command, std::uint64_t& seed);

/// The fields every construction command has: its main input file, its output, --stats.
struct CommandArguments {
    std::string input;
    std::string output;
    bool stats = false;
    bool quiet = false;  ///< --quiet (construction commands): no progress lines on stderr
};

/// An insertion order and its seed (--order, --seed).
struct OrderArguments {
    std::string order = "brio";
    std::uint64_t seed = 1;
};

/// A required positional file argument `name` (type_name e.g. "IN.node").
void add_input_option(CLI::App& command, std::string& path, const std::string& name,
                      const std::string& help, const std::string& type);

/// The required `-o,--output OUT`, its help naming the formats written.
void add_output_option(CLI::App& command, std::string& output, const std::string& help,
                       const std::string& type = "OUT");

/// `--order {given, random, brio}` and `--seed`.
void add_order_options(CLI::App& command, OrderArguments& order, const std::string& help);

/// `--algorithm NAME` among a registry's entries (each with .name and .description): the
/// names checked, the help listing each with its description.
template <class Registry>
void add_algorithm_option(CLI::App& command, std::string& algorithm, const Registry& registry);

/// The picture options of a command that writes .svg (`--view`, `--shade`), as given.
struct PictureArguments {
    std::string view;            ///< "X0,Y0,X1,Y1" or empty
    std::string shade = "none";  ///< none | min-angle
};

/// `--view X0,Y0,X1,Y1` (checked at parse time: four finite numbers, X0 < X1, Y0 < Y1) and
/// `--shade {none, min-angle}`.
void add_picture_options(CLI::App& command, PictureArguments& picture);

/// `--stats`: "Print <what> and construct_seconds (<timed>)".
void add_stats_flag(CLI::App& command, bool& stats, const std::string& what,
                    const std::string& timed);

namespace detail {
void add_algorithm_option(CLI::App& command, std::string& algorithm,
                          const std::vector<std::pair<std::string, std::string>>& entries);
}  // namespace detail

template <class Registry>
void add_algorithm_option(CLI::App& command, std::string& algorithm, const Registry& registry) {
    std::vector<std::pair<std::string, std::string>> entries;
    for (const auto& entry : registry)
        entries.emplace_back(std::string(entry.name), std::string(entry.description));
    detail::add_algorithm_option(command, algorithm, entries);
}

}  // namespace exactmesh::cli
