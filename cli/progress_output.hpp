// SPDX-License-Identifier: MIT
// Progress lines of the construction commands (issue 16, "Long runs"): the hook of
// base/progress.hpp printing at most one line every 2 seconds to stderr, the first only once the
// run has taken 2 seconds (so short runs print nothing), off with --quiet.
#pragma once

#include <cstdint>
#include <string>

#include "base/progress.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace exactmesh::cli {

/// `--quiet`: no progress lines on stderr.
void add_quiet_flag(CLI::App& command, bool& quiet);

/// The hook for command `name` ("triangulate"), started now: lines like
/// `exactmesh: triangulate: 3,145,728 of 10,000,000 points inserted (31%), 4.1 s elapsed, about
/// 9 s left`. Empty when `quiet`. The interval is 2 seconds, or the environment variable
/// EXACTMESH_PROGRESS_SECONDS (tests: a tiny interval without a long run).
Progress progress_printer(const std::string& name, bool quiet);

/// The one line the printer writes (without the newline), for `seconds` elapsed and about
/// `left_seconds` to go (negative: unknown).
std::string progress_line(const std::string& name, std::uint64_t done, std::uint64_t total,
                          const char* what, double seconds, double left_seconds);

}  // namespace exactmesh::cli
