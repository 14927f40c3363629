// SPDX-License-Identifier: MIT
// Fuzzing and judging other people's triangulators (issue 16): the project's degenerate inputs
// (generators/inputs: 2D points, PSLGs, 3D points) are given to a program under test, its output
// is checked exactly (triangulation/checks: Delaunay, constrained Delaunay after Chew, conforming
// mesh, Delaunay tetrahedralization) and every failing input is minimized by ddmin
// (generators/fuzzing/fuzz_cases.hpp) with the program as the oracle. The driver takes the
// program as a std::function and knows nothing of processes or files: `exactmesh fuzz --command`
// passes a shell command on Triangle/TetGen files (cli/external_program.hpp), the Python module
// (exactmesh.fuzz) a Python callable.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "generators/fuzzing/fuzz_cases.hpp"

namespace exactmesh::generators {

enum class FuzzKind { Points2d, Pslg, Points3d };

/// One generated input: points (2 or 3 coordinates each) and, for a PSLG, segments.
struct FuzzInput {
    FuzzKind kind = FuzzKind::Points2d;
    std::uint64_t seed = 0;               ///< the case seed it was made from
    std::string distribution;             ///< the generator's distribution name
    std::vector<double> coordinates;      ///< 2·#V (points2d, pslg) or 3·#V (points3d)
    std::vector<std::uint32_t> segments;  ///< 2·#S 0-based vertex indices (pslg only)

    std::size_t dimension() const { return kind == FuzzKind::Points3d ? 3 : 2; }
    std::size_t point_count() const { return coordinates.size() / dimension(); }
};

/// The case of `seed`: a distribution of the kind and a size (case_size, at most max_points).
FuzzInput make_fuzz_input(FuzzKind kind, std::uint64_t seed, std::uint32_t max_points);

enum class RunStatus { Finished, Crashed, TimedOut };

/// What a program under test returned for one input.
struct ProgramOutput {
    RunStatus status = RunStatus::Finished;
    std::string message;   ///< why it crashed, or why its output could not be read
    bool readable = true;  ///< false: no output or a malformed one (a failure)
    /// The output's vertices (dimension() doubles each); empty means the input's points in the
    /// input's order. Output vertices are matched to input points by exact coordinates.
    std::vector<double> points;
    /// 3·#T triangles (counter-clockwise) or 4·#T tetrahedra (exactmesh's orientation, positive
    /// orient3d: a TetGen .ele as io::read_tetgen_ele returns it), 0-based into `points`.
    std::vector<std::uint32_t> cells;
    /// PSLGs: the constrained edges (2·#P into `points`) when the program reports them (the
    /// pieces a Triangle/`exactmesh cdt` output .poly lists); empty: the input's segments.
    std::vector<std::uint32_t> pieces;
    std::uint32_t first_cell = 1;    ///< how messages number the cells (the .ele's base)
    std::uint32_t first_vertex = 1;  ///< how messages number the input's points (the file's base)
    /// 3D: the order messages list a cell's corners in, the producer's (its corner k is
    /// cells[4t + corner_order[k]]; a TetGen .ele passes io::kTetgenFileCorners).
    std::array<std::uint8_t, 4> corner_order{0, 1, 2, 3};
    /// False: the producer does not orient its cells (Qhull, scipy.spatial.Delaunay); each cell
    /// is then put in the expected orientation by the exact orient2d/orient3d before the checks
    /// (a flat cell is left as it is, and the checks report it).
    bool oriented = true;
};

using ProgramUnderTest = std::function<ProgramOutput(const FuzzInput&)>;

/// What a PSLG's output must be.
enum class PslgCheck {
    ConstrainedDelaunay,  ///< Chew's constrained Delaunay (`exactmesh check IN.poly OUT.ele`)
    Conforming,           ///< a valid mesh of the domain (`exactmesh check --conforming`)
};

enum class Verdict {
    Passed,
    Refused,   ///< nonzero exit on an input that has no triangulation (all collinear/coplanar)
    Failed,    ///< finished, but the output is missing, unreadable or not exactly right
    Crashed,   ///< nonzero exit (or killed by a signal), or an exception
    TimedOut,  ///< killed after the time limit
};
const char* verdict_name(Verdict verdict);

struct Judgement {
    Verdict verdict = Verdict::Passed;
    std::string detail;  ///< the check's first problem, numbered as ProgramOutput says
    bool bad() const { return verdict != Verdict::Passed && verdict != Verdict::Refused; }
};

/// Judges `output` as the program's answer to `input`, exactly. For a PSLG the checks are local
/// (Chew's property or no fold, segments as chains of edges, input vertices kept): a triangle
/// missing where the program should have kept one is seen only with `convex_hull`, which also
/// asks the whole convex hull to be covered once (check_topology_2d).
Judgement judge_output(const FuzzInput& input, const ProgramOutput& output, PslgCheck pslg_check,
                       bool convex_hull = false);

/// The input without the units ddmin removed: points (a PSLG's vertices come first, then its
/// segments as units; a removed vertex takes its segments with it).
FuzzInput restrict_input(const FuzzInput& input, std::span<const std::size_t> kept_units);
std::size_t unit_count(const FuzzInput& input);

struct ProgramFuzzOptions {
    FuzzKind kind = FuzzKind::Points2d;
    std::uint64_t count = 100;        ///< inputs to run
    double minutes = 0;               ///< > 0: stop after this long, even before `count`
    std::uint64_t seed = 1;           ///< first case seed
    std::uint64_t seed_stride = 1;    ///< case k has seed + k * seed_stride (shards: their count)
    std::uint32_t max_points = 1000;  ///< largest input
    PslgCheck pslg_check = PslgCheck::ConstrainedDelaunay;
    bool convex_hull = false;  ///< PSLGs: the output must cover the convex hull (Triangle -c)
    std::chrono::milliseconds minimize_budget{60000};  ///< per failure
    std::uint64_t max_minimized = 20;  ///< failures past this many are counted, not minimized
    bool quiet = false;                ///< no progress lines
};

struct ProgramFuzzFailure {
    FuzzInput input;      ///< as generated
    FuzzInput minimized;  ///< after ddmin (the input itself when not minimized)
    Judgement judgement;  ///< of the input as generated
    Judgement minimized_judgement;
    bool minimized_run = false;  ///< false: past max_minimized
    std::size_t evaluations = 0;
    bool complete = true;  ///< ddmin reached 1-minimality within its budget
};

struct ProgramFuzzSummary {
    std::uint64_t run = 0, passed = 0, refused = 0, failed = 0, crashed = 0, timed_out = 0;
    std::uint64_t first_seed = 0, last_seed = 0;
    double seconds = 0;
    /// Per distribution name: inputs run, and how many of them failed, crashed or timed out.
    std::map<std::string, std::array<std::uint64_t, 2>> per_distribution;
    std::uint64_t bad() const { return failed + crashed + timed_out; }
};

/// Runs `program` on options.count inputs (case seeds seed, seed + stride, ...), judges each, and
/// minimizes each bad one with `program` as the oracle (the same verdict must persist), handing
/// it to `on_failure`. Progress lines go to `progress` every 2 s unless options.quiet.
ProgramFuzzSummary fuzz_program(const ProgramUnderTest& program, const ProgramFuzzOptions& options,
                                const std::function<void(const ProgramFuzzFailure&)>& on_failure,
                                std::ostream& progress);

}  // namespace exactmesh::generators
