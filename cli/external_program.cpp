// SPDX-License-Identifier: MIT
// The external program under test of `exactmesh fuzz --command` (cli/external_program.hpp): run
// by /bin/sh in its own process group under a time limit (POSIX fork/exec/waitpid), its output
// files read back by io/.
#include "cli/external_program.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "io/tetgen_format.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"

namespace exactmesh::cli {

namespace fs = std::filesystem;

std::string input_file_name(FuzzKind kind) {
    return kind == FuzzKind::Pslg ? "input.poly" : "input.node";
}

void write_fuzz_input(const fs::path& path, const FuzzInput& input) {
    if (input.kind == FuzzKind::Points3d) {
        io::write_tetgen_node(path, input.coordinates, 1);
        return;
    }
    io::NodeFile nodes;
    nodes.xy = input.coordinates;
    nodes.first_index = 1;
    if (input.kind == FuzzKind::Pslg) {
        io::write_poly(path, nodes, input.segments);
    } else {
        io::write_node(path, nodes);
    }
}

namespace {

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// The last `lines` lines of a file, for a crash report.
std::string tail_of(const fs::path& path, std::size_t lines) {
    std::vector<std::string> all;
    std::ifstream stream(path);
    for (std::string one; std::getline(stream, one);) {
        if (one.find_first_not_of(" \t\r") != std::string::npos) all.push_back(one);
    }
    std::string out;
    for (std::size_t k = all.size() > lines ? all.size() - lines : 0; k < all.size(); ++k)
        out += (out.empty() ? "" : " | ") + all[k];
    return out;
}

}  // namespace

std::string substitute_command(const std::string& command, const std::string& in,
                               const std::string& out) {
    return replace_all(replace_all(command, "{in}", in), "{out}", out);
}

std::string output_path(const std::string& output, const fs::path& dir, const fs::path& in) {
    fs::path stem = in;
    stem.replace_extension();
    return replace_all(replace_all(output, "{dir}", dir.string()), "{stem}", stem.string());
}

namespace {

/// The converter of meshio_conversion_command (no single quote: it is one shell word in quotes).
constexpr const char* kMeshioConversion = R"PY(
import sys
kind, source, target = sys.argv[1:4]
name = source.rsplit("/", 1)[-1]
def fail(message):
    sys.stderr.write(message.replace("\n", " ") + "\n")
    sys.exit(1)
try:
    import meshio
except ImportError as error:
    fail("cannot convert " + name + ": no meshio module (" + str(error) + ")")
def empty_vtu():
    # meshio 5.0 (Debian 12) fails on a VTU without cells (an IndexError on its empty types):
    # every Piece with NumberOfCells="0" is read here as no cells.
    import xml.etree.ElementTree as tree
    try:
        pieces = [e for e in tree.parse(source).iter() if str(e.tag).endswith("Piece")]
    except Exception:
        return False
    return bool(pieces) and all(e.get("NumberOfCells") == "0" for e in pieces)
import contextlib, io
try:
    # Quiet: meshio prints its own complaints (the reproducer shows ours).
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        mesh = meshio.read(source)
except (Exception, SystemExit) as error:  # meshio 5.0 ends some failures with sys.exit
    if source.lower().endswith(".vtu") and empty_vtu():
        with open(target, "w") as ele:
            ele.write("0 " + ("4" if kind == "tetra" else "3") + " 0\n")
        sys.exit(0)
    said = str(error).strip() if isinstance(error, Exception) else ""
    fail("meshio cannot read " + name + (": " + said if said else ""))
# No such cells is an empty .ele: right for collinear (coplanar) input, and otherwise judged
# wrong as any empty output is ("no triangles, but points ... are not collinear").
blocks = [block.data for block in mesh.cells if block.type == kind]
count = sum(len(block) for block in blocks)
dimension = 3 if kind == "tetra" else 2
if mesh.points.ndim != 2 or mesh.points.shape[1] < dimension:
    fail(name + ": points of dimension " + str(mesh.points.shape[-1]) + ", not " + str(dimension))
with open(target[:-4] + ".node", "w") as node:
    node.write(str(len(mesh.points)) + " " + str(dimension) + " 0 0\n")
    for index, point in enumerate(mesh.points, 1):
        node.write(str(index) + " " + " ".join(repr(float(x)) for x in point[:dimension]) + "\n")
with open(target, "w") as ele:
    ele.write(str(count) + " " + str(dimension + 1) + " 0\n")
    index = 1
    for block in blocks:
        for cell in block:
            ele.write(str(index) + " " + " ".join(str(int(v) + 1) for v in cell) + "\n")
            index += 1
# 2D: line cells are the constrained pieces, a .poly beside (its vertices: the .node).
lines = [block.data for block in mesh.cells if block.type == "line"]
if kind == "triangle" and lines:
    with open(target[:-4] + ".poly", "w") as poly:
        poly.write("0 2 0 0\n" + str(sum(len(block) for block in lines)) + " 0\n")
        index = 1
        for block in lines:
            for cell in block:
                poly.write(str(index) + " " + str(int(cell[0]) + 1) + " " +
                           str(int(cell[1]) + 1) + "\n")
                index += 1
        poly.write("0\n")
)PY";

}  // namespace

std::string meshio_conversion_command(FuzzKind kind, const std::string& in,
                                      const std::string& out) {
    return "/usr/bin/python3 -c " + shell_word(kMeshioConversion) + " " +
           (kind == FuzzKind::Points3d ? "tetra" : "triangle") + " " + in + " " + out;
}

bool is_ele_output(const std::string& output) {
    return io::has_extension(output, ".ele");
}

namespace {

struct ShellRun {
    RunStatus status = RunStatus::Finished;
    std::string message;
};

/// Runs `command` by /bin/sh -c in a process group of its own (stdin /dev/null, stdout and
/// stderr to files); on timeout the whole group is killed. The group is also killed when the
/// shell ends, before the shell is reaped (so its id cannot have been reused): nothing the
/// command started in the background outlives the run.
ShellRun run_shell(const std::string& command, const fs::path& stdout_path,
                   const fs::path& stderr_path, std::chrono::milliseconds timeout) {
    std::cout.flush();
    std::cerr.flush();
    const pid_t pid = fork();
    if (pid < 0) throw Error(std::string("fuzz: cannot start /bin/sh: ") + std::strerror(errno));
    if (pid == 0) {
        setpgid(0, 0);
        const int in = open("/dev/null", O_RDONLY);
        const int out = open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (in >= 0) dup2(in, 0);
        if (out >= 0) dup2(out, 1);
        if (err >= 0) dup2(err, 2);
        execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    setpgid(pid, pid);  // from both sides: the group exists before the parent may kill it
    const auto deadline = FuzzClock::now() + timeout;
    std::chrono::microseconds pause{100};
    ShellRun run;
    for (;;) {
        siginfo_t info{};
        if (waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) != 0) {
            if (errno == EINTR) continue;
            throw Error(std::string("fuzz: waitid failed: ") + std::strerror(errno));
        }
        if (info.si_pid == pid) break;  // ended (not yet reaped)
        if (FuzzClock::now() >= deadline) {
            run.status = RunStatus::TimedOut;
            run.message =
                "killed after " + format_seconds(static_cast<double>(timeout.count()) / 1000);
            break;
        }
        std::this_thread::sleep_for(pause);
        pause = std::min<std::chrono::microseconds>(2 * pause, std::chrono::milliseconds(20));
    }
    kill(-pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (run.status == RunStatus::TimedOut) return run;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return run;
    run.status = RunStatus::Crashed;
    if (WIFEXITED(status)) {
        run.message = "exit status " + std::to_string(WEXITSTATUS(status));
    } else if (WIFSIGNALED(status)) {
        run.message = "killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
                      strsignal(WTERMSIG(status)) + ")";
    } else {
        run.message = "ended abnormally";
    }
    return run;
}

/// Reads the program's output files into `output` (readable = false with the reader's message
/// when they are missing or malformed).
void read_program_output(const FuzzInput& input, const fs::path& in, const fs::path& out,
                         ProgramOutput& output) {
    try {
        if (!fs::exists(out)) {
            output.readable = false;
            output.message = "the program wrote no " + out.filename().string();
            return;
        }
        fs::path node = out;
        node.replace_extension(".node");
        const bool own_node = fs::exists(node) && !fs::equivalent(node, in);
        std::uint32_t base = 1;
        auto count = static_cast<std::uint32_t>(input.point_count());
        if (input.kind == FuzzKind::Points3d) {
            if (own_node) {
                io::TetgenNodeFile nodes = io::read_tetgen_node(node);
                base = nodes.first_index;
                count = nodes.vertex_count();
                output.points = std::move(nodes.xyz);
            }
            io::TetgenEleFile ele = io::read_tetgen_ele(out, base, count);
            output.cells = std::move(ele.tets);
            output.first_cell = ele.first_index;
            output.corner_order = io::kTetgenFileCorners;
            return;
        }
        if (own_node) {
            io::NodeFile nodes = io::read_node(node);
            base = nodes.first_index;
            count = nodes.vertex_count();
            output.points = std::move(nodes.xy);
        }
        io::EleFile ele = io::read_ele(out, base, count);
        output.cells = std::move(ele.triangles);
        output.first_cell = ele.first_index;
        fs::path poly = out;
        poly.replace_extension(".poly");
        if (input.kind == FuzzKind::Pslg && fs::exists(poly) && !fs::equivalent(poly, in))
            output.pieces = io::read_poly(poly).segments;
    } catch (const std::exception& error) {
        output = ProgramOutput{};
        output.readable = false;
        output.message = error.what();
    }
}

}  // namespace

namespace {
/// meshio's import alone takes about a second; a conversion is not the program's time.
constexpr std::chrono::milliseconds kConversionTimeout{60000};
}  // namespace

ProgramUnderTest external_program(const ExternalCommand& command, const fs::path& scratch) {
    return [command, scratch](const FuzzInput& input) {
        const fs::path dir = scratch / "run";
        std::error_code ignored;
        fs::remove_all(dir, ignored);
        fs::create_directories(dir);
        const fs::path in = dir / input_file_name(input.kind);
        write_fuzz_input(in, input);
        const fs::path out = output_path(command.output, dir, in);
        const ShellRun run = run_shell(
            substitute_command(command.command, shell_word(in.string()), shell_word(out.string())),
            dir / "program.stdout", dir / "program.stderr", command.timeout);
        ProgramOutput output;
        output.status = run.status;
        output.message = run.message;
        if (run.status == RunStatus::Crashed) {
            if (const std::string said = tail_of(dir / "program.stderr", 3); !said.empty())
                output.message += ": " + said;
        }
        if (run.status == RunStatus::Finished) {
            if (is_ele_output(out.string())) {
                read_program_output(input, in, out, output);
            } else if (!fs::exists(out)) {
                output.readable = false;
                output.message = "the program wrote no " + out.filename().string();
            } else {
                // Not a Triangle/TetGen .ele: meshio converts it. A failure is an unreadable
                // output (the program's), not an error of the campaign.
                const fs::path converted = dir / "converted.ele";
                const ShellRun conversion =
                    run_shell(meshio_conversion_command(input.kind, shell_word(out.string()),
                                                        shell_word(converted.string())),
                              dir / "convert.stdout", dir / "convert.stderr", kConversionTimeout);
                if (conversion.status == RunStatus::Finished) {
                    read_program_output(input, in, converted, output);
                } else {
                    output.readable = false;
                    const std::string said = tail_of(dir / "convert.stderr", 1);
                    output.message = "cannot convert " + out.filename().string() +
                                     " with meshio: " + (said.empty() ? conversion.message : said);
                }
            }
        }
        output.oriented = !command.orient;
        return output;
    };
}

}  // namespace exactmesh::cli
