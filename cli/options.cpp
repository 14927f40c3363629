// SPDX-License-Identifier: MIT
// Options that several subcommands share (see options.hpp).
#include "cli/options.hpp"

#include <CLI/CLI.hpp>
#include <limits>

#include "cli/output.hpp"

namespace exactmesh::cli {

CLI::Validator whole_number_at_most(std::uint64_t max) {
    return CLI::Validator([max](std::string& text) { return check_unsigned_text(text, max); },
                          max == std::numeric_limits<std::uint64_t>::max() ? "UINT64" : "UINT");
}

void add_seed_option(CLI::App& command, std::uint64_t& seed) {
    command.add_option("--seed", seed, "Seed of the random and brio orders")
        ->check(whole_number_at_most(std::numeric_limits<std::uint64_t>::max()))
        ->capture_default_str();
}

}  // namespace exactmesh::cli
