// SPDX-License-Identifier: MIT
// The program under test of `exactmesh fuzz --command` (issue 16): a shell command run on
// Triangle/TetGen files, in its own process group under a time limit. The driver, the inputs and
// the judgement are the library's (generators/fuzzing/fuzz_program.hpp); this file holds only
// what needs processes and files.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

#include "generators/fuzzing/fuzz_cases.hpp"
#include "generators/fuzzing/fuzz_program.hpp"

namespace exactmesh::cli {

// The command's fuzzing code names the library's fuzzing types as its own.
using generators::case_size;
using generators::CaseRandom;
using generators::ddmin;
using generators::DdminResult;
using generators::format_seconds;
using generators::fuzz_program;
using generators::FuzzClock;
using generators::FuzzInput;
using generators::FuzzKind;
using generators::Judgement;
using generators::kept_coordinates;
using generators::ProgramFuzzFailure;
using generators::ProgramFuzzOptions;
using generators::ProgramFuzzSummary;
using generators::ProgramOutput;
using generators::ProgramUnderTest;
using generators::ProgressLine;
using generators::PslgCheck;
using generators::RunStatus;
using generators::Verdict;
using generators::verdict_name;

/// The text as one shell word: unchanged when it is plain, else in single quotes.
std::string shell_word(const std::string& text);

/// A shell command run on files: `{in}` becomes the input file (a Triangle .node for points2d,
/// .poly for pslg, a TetGen .node for points3d, 1-based), `{out}` the output file the program
/// must write, both quoted for the shell. The output is read as a Triangle .ele (2D) or TetGen
/// .ele (3D); a .node beside it (same name, extension .node) gives the output's vertices and,
/// for PSLGs, a .poly beside it the constrained pieces, as `exactmesh check` reads them. Any
/// other extension is converted first by meshio (meshio_conversion_command) into
/// converted.node and converted.ele in the scratch folder, which are then read the same way.
struct ExternalCommand {
    std::string command;                      ///< with {in} and {out}
    std::string output = "{dir}/output.ele";  ///< {dir}: the scratch folder, {stem}: {in}
                                              ///< without its extension
    std::chrono::milliseconds timeout{10000};
    bool orient = false;  ///< the program's cells are not oriented (ProgramOutput::oriented)
};

/// The program under test for `command`: each run gets a fresh scratch folder under `scratch`,
/// runs `/bin/sh -c` in its own process group (killed whole on timeout), stdout and stderr kept
/// in files there.
ProgramUnderTest external_program(const ExternalCommand& command,
                                  const std::filesystem::path& scratch);

/// The input file name for a kind: input.node or input.poly.
std::string input_file_name(FuzzKind kind);
/// Writes the input as the program reads it.
void write_fuzz_input(const std::filesystem::path& path, const FuzzInput& input);
/// The command with {in}, {out} replaced by the quoted paths.
std::string substitute_command(const std::string& command, const std::string& in,
                               const std::string& out);
/// The shell command converting a program's output `in` (any format meshio reads) to a 1-based
/// Triangle/TetGen `out` .ele and the .node beside it, keeping meshio's points in their order and
/// the triangles (2D kinds) or tetrahedra (points3d) in their corner order (none: an empty .ele,
/// which the checks judge), and in 2D its line cells as the constrained pieces of a .poly beside
/// them (for pslg): /usr/bin/python3 -c SCRIPT triangle|tetra IN OUT (Debian's
/// python3-meshio). It exits non-zero with one line on stderr when meshio cannot read the file
/// (or is missing). `in` and `out` are used as given (quote them for the shell).
std::string meshio_conversion_command(FuzzKind kind, const std::string& in, const std::string& out);
/// True when `output` (an --output pattern or path) is read without conversion: a .ele.
bool is_ele_output(const std::string& output);

/// The output path for `output` with {dir} and {stem}.
std::string output_path(const std::string& output, const std::filesystem::path& dir,
                        const std::filesystem::path& in);

}  // namespace exactmesh::cli
