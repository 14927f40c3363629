// SPDX-License-Identifier: MIT
// Options that several subcommands share, declared once so that their text and checks agree.
#pragma once

#include <cstdint>
#include <string>

namespace CLI {
class App;
class Validator;
}  // namespace CLI

namespace exactmesh::cli {

/// A CLI11 check that the option's text is a whole decimal number in [0, max]
/// (check_unsigned_text: CLI11's own conversion wraps "-1" and saturates larger numbers).
CLI::Validator whole_number_at_most(std::uint64_t max);

/// `--seed S`: the seed of the random and brio insertion orders, any 64-bit unsigned value.
void add_seed_option(CLI::App& command, std::uint64_t& seed);

}  // namespace exactmesh::cli
