// SPDX-License-Identifier: MIT
// The `exactmesh` command: parses the command line and turns every failure into one line on
// stderr, `exactmesh: error: ...`, and an exit status (see commands.hpp). Never a stack trace.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <string_view>

#include "base/errors.hpp"
#include "base/version.hpp"
#include "cli/commands.hpp"

namespace {

/// The length of the valid UTF-8 sequence at `text[i]` that is not a C1 control (U+0080 to
/// U+009F, which some terminals obey), or 0.
std::size_t utf8_length(std::string_view text, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char c = byte(i);
    const std::size_t length = c >= 0xF0 && c <= 0xF4  ? 4
                               : c >= 0xE0             ? 3
                               : c >= 0xC2 && c < 0xE0 ? 2
                                                       : 0;
    if (length == 0 || c >= 0xF5 || i + length > text.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return 0;
    }
    if (c == 0xC2 && byte(i + 1) < 0xA0) return 0;  // C1 control
    return length;
}

/// Prints `message` as a single line and returns `status`. Newlines fold to spaces; every other
/// control byte and every byte outside valid UTF-8 is printed as \xNN, so a message that quotes
/// a binary file (a size file, a file name) never writes raw bytes to the terminal.
int report_error(std::string_view message, int status) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string line = "exactmesh: error: ";
    for (std::size_t i = 0; i < message.size(); ++i) {
        const auto c = static_cast<unsigned char>(message[i]);
        if (c == '\n' || c == '\r') {
            line += ' ';
        } else if (c >= 0x20 && c < 0x7f) {
            line += static_cast<char>(c);
        } else if (const std::size_t length = c >= 0x80 ? utf8_length(message, i) : 0; length > 0) {
            line.append(message.substr(i, length));
            i += length - 1;
        } else {
            line += "\\x";
            line += kHex[c >> 4];
            line += kHex[c & 0xF];
        }
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    std::cout.flush();
    std::cerr << line << '\n';
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace exactmesh::cli;
    try {
        CLI::App app{
            "exactmesh: robust 2D Delaunay and constrained Delaunay triangulation, quality meshing "
            "and "
            "3D Delaunay tetrahedralization with exact predicates",
            "exactmesh"};
        // No require_subcommand(): CLI11 would then report a misspelt subcommand as a missing
        // one; without it, `exactmesh frobnicate` is an unexpected argument, as it should be.
        app.set_version_flag("--version", std::string("exactmesh ") + exactmesh::kVersion,
                             "Print the version and exit");
        app.footer(
            "Exit status: 0 success, 1 `check` or `fuzz` found a problem, 2 bad input or usage, "
            "3 internal error.");
        int exit_status = kExitSuccess;
        add_triangulate_command(app);
        add_tetrahedralize_command(app);
        add_cdt_command(app);
        add_mesh_command(app);
        add_check_command(app, exit_status);
        add_fuzz_command(app, exit_status);
        add_swap_command(app);
        add_min_max_command(app);
        add_swap3d_command(app);
        add_adapt_command(app);
        add_tetmesh_command(app);
        try {
            app.parse(argc, argv);
        } catch (const CLI::ParseError& error) {
            if (error.get_exit_code() == 0) return app.exit(error);  // --help
            return report_error(std::string(error.what()) + " (see exactmesh --help)",
                                kExitBadInput);
        }
        if (app.get_subcommands().empty()) {
            return report_error(
                "a subcommand is required: triangulate, tetrahedralize, cdt, mesh, check, fuzz, "
                "swap, "
                "min-max, swap3d, adapt or tetmesh (see "
                "exactmesh --help)",
                kExitBadInput);
        }
        return exit_status;
    } catch (const exactmesh::InputError& error) {
        return report_error(error.what(), kExitBadInput);
    } catch (const exactmesh::GeometryError& error) {
        return report_error(error.what(), kExitBadInput);
    } catch (const exactmesh::Error& error) {
        return report_error(std::string("internal error: ") + error.what() + " (at " +
                                error.where().file_name() + ":" +
                                std::to_string(error.where().line()) + ")",
                            kExitInternalError);
    } catch (const std::bad_alloc&) {
        return report_error("out of memory", kExitInternalError);
    } catch (const std::exception& error) {
        return report_error(std::string("internal error: ") + error.what(), kExitInternalError);
    } catch (...) {
        return report_error("internal error: unknown exception", kExitInternalError);
    }
}
