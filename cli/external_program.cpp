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
        if (run.status == RunStatus::Finished) read_program_output(input, in, out, output);
        output.oriented = !command.orient;
        return output;
    };
}

}  // namespace exactmesh::cli
