// SPDX-License-Identifier: MIT
// Progress lines of the construction commands (see progress_output.hpp).
#include "cli/progress_output.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>

namespace exactmesh::cli {

namespace {

using Clock = std::chrono::steady_clock;

/// 3145728 -> "3,145,728".
std::string grouped(std::uint64_t n) {
    const std::string digits = std::to_string(n);
    std::string text;
    for (std::size_t k = 0; k < digits.size(); ++k) {
        // (Appending, not inserting: GCC 12 warns falsely on string::insert here.)
        if (k > 0 && (digits.size() - k) % 3 == 0) text += ',';
        text += digits[k];
    }
    return text;
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, seconds < 100 ? "%.1f s" : "%.0f s", seconds);
    return text;
}

/// EXACTMESH_PROGRESS_SECONDS when it is a number of seconds >= 0, else 2.
double progress_interval() {
    if (const char* text = std::getenv("EXACTMESH_PROGRESS_SECONDS")) {
        char* end = nullptr;
        const double seconds = std::strtod(text, &end);
        if (end != text && *end == '\0' && seconds >= 0 && seconds <= 1e6) return seconds;
    }
    return 2;
}

struct PrinterState {
    std::string name;
    Clock::duration interval;
    Clock::time_point start, last, phase_start;
    const char* phase = nullptr;
    std::uint64_t phase_first = 0, phase_done = 0;  // done at the phase's first and last call
};

}  // namespace

void add_quiet_flag(CLI::App& command, bool& quiet) {
    command.add_flag("--quiet", quiet,
                     "No progress lines on stderr (long runs print one every 2 s otherwise)");
}

std::string progress_line(const std::string& name, std::uint64_t done, std::uint64_t total,
                          const char* what, double seconds, double left_seconds) {
    std::string line = "exactmesh: " + name + ": " + grouped(done);
    if (total > 0 && done <= total) {
        line += " of " + grouped(total) + " " + what + " (" + std::to_string(100 * done / total) +
                "%), " + seconds_text(seconds) + " elapsed";
        if (left_seconds >= 0) line += ", about " + seconds_text(left_seconds) + " left";
    } else if (total > 0) {
        line += std::string(" ") + what + " (about " + grouped(total) + " expected), " +
                seconds_text(seconds) + " elapsed";
    } else {
        line += std::string(" ") + what + ", " + seconds_text(seconds) + " elapsed";
    }
    return line;
}

Progress progress_printer(const std::string& name, bool quiet) {
    if (quiet) return {};
    auto state = std::make_shared<PrinterState>();
    state->name = name;
    state->interval = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(progress_interval()));
    state->start = state->last = state->phase_start = Clock::now();
    Progress progress;
    progress.report = [state](std::uint64_t done, std::uint64_t total, const char* what) {
        const Clock::time_point now = Clock::now();
        // A new count (another phase or a second run): its own time gives the time left.
        if (state->phase == nullptr || std::strcmp(state->phase, what) != 0 ||
            done < state->phase_done) {
            state->phase = what;
            state->phase_start = now;
            state->phase_first = done;
        }
        state->phase_done = done;
        if (now - state->last < state->interval) return;
        state->last = now;
        const auto seconds = [&](Clock::time_point from) {
            return std::chrono::duration<double>(now - from).count();
        };
        // The time left at the phase's rate so far (unknown until it has one).
        double left = -1;
        const double phase_seconds = seconds(state->phase_start);
        if (total > done && done > state->phase_first && phase_seconds > 0) {
            left = phase_seconds * static_cast<double>(total - done) /
                   static_cast<double>(done - state->phase_first);
        }
        std::cerr << progress_line(state->name, done, total, what, seconds(state->start), left)
                  << std::endl;
    };
    return progress;
}

}  // namespace exactmesh::cli
