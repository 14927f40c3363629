// SPDX-License-Identifier: MIT
// Options that several subcommands share (see options.hpp).
#include "cli/options.hpp"

#include <CLI/CLI.hpp>
#include <limits>

#include "cli/output.hpp"

namespace exactmesh::cli {

CLI::Validator whole_number_at_most(std::uint64_t max) {
    // No description of its own: CLI11 appends it to the option's type name, and "UINT:UINT"
    // read as two numbers (a hostile-input campaign tried `--max-steiner 0:30000`).
    return CLI::Validator([max](std::string& text) { return check_unsigned_text(text, max); }, "");
}

CLI::Validator finite_positive_number() {
    return CLI::Validator([](std::string& text) { return check_positive_number_text(text); },
                          "NUMBER > 0");
}

void add_seed_option(CLI::App& command, std::uint64_t& seed) {
    command.add_option("--seed", seed, "Seed of the random and brio orders")
        ->check(whole_number_at_most(std::numeric_limits<std::uint64_t>::max()))
        ->capture_default_str();
}

void add_input_option(CLI::App& command, std::string& path, const std::string& name,
                      const std::string& help, const std::string& type) {
    command.add_option(name, path, help)->required()->type_name(type);
}

void add_output_option(CLI::App& command, std::string& output, const std::string& help,
                       const std::string& type) {
    command.add_option("-o,--output", output, help)->required()->type_name(type);
}

void add_order_options(CLI::App& command, OrderArguments& order, const std::string& help) {
    command.add_option("--order", order.order, help)
        ->check(CLI::IsMember({"given", "random", "brio"}))
        ->capture_default_str();
    add_seed_option(command, order.seed);
}

namespace detail {

void add_algorithm_option(CLI::App& command, std::string& algorithm,
                          const std::vector<std::pair<std::string, std::string>>& entries) {
    std::vector<std::string> names;
    std::string help = "Construction algorithm:";
    for (const auto& [name, description] : entries) {
        names.push_back(name);
        help += "\n  " + name + ": " + description;
    }
    command.add_option("--algorithm", algorithm, help)
        ->check(CLI::IsMember(names))
        ->capture_default_str();
}

}  // namespace detail

void add_picture_options(CLI::App& command, PictureArguments& picture) {
    command
        .add_option("--view", picture.view,
                    ".svg only: draw the window X0 <= x <= X1, Y0 <= y <= Y1 (a zoom): the "
                    "picture's viewBox is the window, triangles outside it are left out and "
                    "the others clipped; line widths follow the triangles in the window")
        ->type_name("X0,Y0,X1,Y1")
        ->check(CLI::Validator([](std::string& text) { return check_view_text(text); }, ""));
    command
        .add_option("--shade", picture.shade,
                    ".svg only: fill the triangles by their smallest angle (5-degree classes, "
                    "red below 15, blue near 60) with a colour bar (min-angle), or in one "
                    "colour (none)")
        ->check(CLI::IsMember({"none", "min-angle"}))
        ->capture_default_str();
}

void add_stats_flag(CLI::App& command, bool& stats, const std::string& what,
                    const std::string& timed) {
    command.add_flag("--stats", stats, "Print " + what + " and construct_seconds (" + timed + ")");
}

}  // namespace exactmesh::cli
