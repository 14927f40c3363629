// SPDX-License-Identifier: MIT
// The `exactmesh` command: parses the command line and turns every failure into one line on
// stderr, `exactmesh: error: ...`, and an exit status (see commands.hpp). Never a stack trace.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "predicates/errors.hpp"

namespace {

/// Prints `message` as a single line (embedded newlines folded) and returns `status`.
int report_error(std::string_view message, int status) {
    std::string line = "exactmesh: error: ";
    for (const char c : message) line += (c == '\n' || c == '\r') ? ' ' : c;
    while (!line.empty() && line.back() == ' ') line.pop_back();
    std::cout.flush();
    std::cerr << line << '\n';
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace exactmesh::cli;
    try {
        CLI::App app{"exactmesh: robust 2D Delaunay and constrained Delaunay triangulation, quality meshing and "
                     "3D Delaunay tetrahedralization with exact predicates",
                     "exactmesh"};
        // No require_subcommand(): CLI11 would then report a misspelt subcommand as a missing
        // one; without it, `exactmesh frobnicate` is an unexpected argument, as it should be.
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
        try {
            app.parse(argc, argv);
        } catch (const CLI::ParseError& error) {
            if (error.get_exit_code() == 0) return app.exit(error);  // --help
            return report_error(std::string(error.what()) + " (see exactmesh --help)",
                                kExitBadInput);
        }
        if (app.get_subcommands().empty()) {
            return report_error(
                "a subcommand is required: triangulate, tetrahedralize, cdt, mesh, check, fuzz, swap, "
                "min-max or swap3d (see "
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
