// SPDX-License-Identifier: MIT
// `exactmesh fuzz`: a timed differential and validity campaign over the input distributions of
// generators/inputs/inputs. Per case, the three Delaunay constructions must each pass the exact
// check (triangulation/checks/check_2d), return mutual neighbours, agree with each other (same
// canonical triangulation under the shared symbolic perturbation) and, on small inputs, with the
// naive empty-circle oracle (tests/oracles). A failing input is minimized by delta debugging
// [Zeller, Hildebrandt 2002, ddmin] and saved as a Triangle .node file with the commands that
// replay it.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "cli/external_program.hpp"
#include "cli/fuzz_shards.hpp"
#include "generators/inputs/inputs.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/compare_triangulations_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_naive.hpp"

namespace exactmesh::cli {

std::string shell_word(const std::string& text) {
    const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char ch) {
        return std::isalnum(static_cast<unsigned char>(ch)) != 0 ||
               std::string_view("-_./=+,:@%").find(ch) != std::string_view::npos;
    });
    if (plain) return text;
    std::string quoted = "'";
    for (const char ch : text) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return quoted + "'";
}

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using Clock = FuzzClock;

/// The oracle is O(n^4): it runs on inputs up to this size.
constexpr std::size_t kOracleMaxPoints = 60;
/// Largest near-collinear case (see make_case).
constexpr std::uint32_t kNearCollinearMaxPoints = 2000;
/// A minimization stops after the campaign's remaining time, but runs at least the minimum and
/// at most the maximum, and keeps what it has then (a failure on 20000 points where every point
/// matters would otherwise run for hours).
constexpr std::chrono::seconds kMinimizeAtLeast{10};
constexpr std::chrono::seconds kMinimizeAtMost{60};
/// Failures past this many are counted and named in one line, not minimized nor saved: a
/// systematic bug fails most cases, and one file per case would bury the first ones.
constexpr std::uint64_t kMaxSavedFailures = 20;
/// Files the failures are saved as: fuzz-failure-<case seed>.node.
constexpr std::string_view kFilePrefix = "fuzz-failure-";
/// Test-only: set to 1, drops the last triangle of green-sibson's output before the checks, so
/// the tests can watch the failure path (minimization, file, commands) work.
constexpr const char* kInjectFaultVariable = "EXACTMESH_FUZZ_INJECT_FAULT";
constexpr std::size_t kFaultyAlgorithm = 1;

struct FuzzArguments {
    double minutes = 0;
    bool minutes_given = false;
    std::uint64_t seed = 1;
    std::string out = ".";
    bool quiet = false;
    // Fuzzing another program (--command): generators/fuzzing/fuzz_program.hpp, with the program
    // run by cli/external_program.hpp.
    std::string command;
    std::string kind = "points2d";
    std::uint64_t count = 100;
    double timeout = 10;
    std::string output = "{dir}/output.ele";
    std::uint32_t max_points = 1000;
    bool conforming = false;
    bool convex_hull = false;
    bool orient = false;
    double minimize_seconds = 60;
    // Shards (issue 17, cli/fuzz_shards.hpp).
    std::string shard;               ///< --shard I/N
    unsigned jobs = 0;               ///< --jobs N: N local shards
    std::vector<std::string> merge;  ///< --merge DIR...: shard folders to merge into --out
};

/// Every 2D Delaunay algorithm of the registry, compared with each other.
const std::span<const tri::Delaunay2Algorithm> kAlgorithms = tri::delaunay_2d_algorithms();

std::string algorithm_name(std::size_t algorithm) {
    return std::string(kAlgorithms[algorithm].name);
}

struct Order {
    const char* name;
    tri::InsertionOrder order;
};
constexpr std::array<Order, 3> kOrders = {Order{"given", tri::InsertionOrder::Given},
                                          Order{"random", tri::InsertionOrder::Random},
                                          Order{"brio", tri::InsertionOrder::Brio}};

/// One case: the points and how each algorithm is run. Everything follows from the case seed.
struct Case {
    std::uint64_t seed = 0;
    gen::Distribution distribution = gen::Distribution::Uniform;
    std::vector<double> xy;
    std::size_t reference = 0;  ///< the algorithm the others are compared with
    std::vector<std::size_t> orders = std::vector<std::size_t>(kAlgorithms.size());  ///< kOrders

    tri::Delaunay2Options options(std::size_t algorithm) const {
        return tri::Delaunay2Options{kOrders[orders[algorithm]].order, seed};
    }
};

Case make_case(std::uint64_t seed) {
    CaseRandom random(seed);
    Case c;
    c.seed = seed;
    c.distribution = gen::kAllDistributions[random.next() % std::size(gen::kAllDistributions)];
    // Mostly small, where the oracle runs (skewed towards the smallest sizes: the oracle costs
    // n^4 and tiny inputs are where degeneracies are dense), then medium, sometimes large.
    std::uint32_t n = case_size(random, static_cast<std::uint32_t>(kOracleMaxPoints), 20000);
    // Tanemura-Merriam is quadratic on near-collinear points (about 3.5 s for 2000 on this
    // machine, 12 s for 4000): keep those cases from eating the campaign.
    if (c.distribution == gen::Distribution::NearCollinear)
        n = std::min<std::uint32_t>(n, kNearCollinearMaxPoints);
    c.reference = random.next() % kAlgorithms.size();
    for (std::size_t& order : c.orders) order = random.next() % kOrders.size();
    c.xy = gen::generate_points_2d(c.distribution, n, seed);
    return c;
}

/// A failure, identified for the minimizer by (kind, algorithm, other).
struct Failure {
    std::string kind;  ///< exception, check, neighbors, count, merged_into, triangles, oracle
    std::size_t algorithm = 0;         ///< the algorithm to blame (or compared)
    std::optional<std::size_t> other;  ///< the reference, for the agreement kinds
    std::string detail;

    bool same_as(const Failure& f) const {
        return kind == f.kind && algorithm == f.algorithm && other == f.other;
    }
    std::string describe() const {
        std::string s = kind + ": " + algorithm_name(algorithm);
        if (other) s += " vs " + algorithm_name(*other);
        return s + ": " + detail;
    }
};

using Triangles = std::vector<std::array<tri::VertIdx, 3>>;

/// Empty when neighbour slot 3t+k names the triangle across edge (v[k], v[k+1]) and that
/// triangle names t back, with kNone exactly on the hull edges; else the first problem.
std::string check_neighbors(const tri::Delaunay2Result& r) {
    const std::size_t count = r.triangles.size() / 3;
    if (r.neighbors.size() != r.triangles.size()) {
        return std::to_string(r.neighbors.size()) + " neighbour slots for " +
               std::to_string(count) + " triangles";
    }
    for (std::size_t t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::TriIdx u = r.neighbors[3 * t + k];
            if (u == tri::kNone) continue;
            const tri::VertIdx a = r.triangles[3 * t + k], b = r.triangles[3 * t + (k + 1) % 3];
            bool mutual = false;
            for (unsigned j = 0; j < 3 && u < count; ++j) {
                mutual = mutual ||
                         (r.triangles[3 * u + j] == b && r.triangles[3 * u + (j + 1) % 3] == a &&
                          r.neighbors[3 * u + j] == t);
            }
            if (!mutual) {
                return "triangle " + std::to_string(t) + " names triangle " + std::to_string(u) +
                       " across edge " + std::to_string(a) + "-" + std::to_string(b) +
                       ", which does not name it back across that edge";
            }
        }
    }
    // Hull edges: as many kNone slots as edges without a reverse edge.
    std::vector<std::pair<tri::VertIdx, tri::VertIdx>> edges;
    edges.reserve(r.triangles.size());
    for (std::size_t t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            edges.emplace_back(r.triangles[3 * t + k], r.triangles[3 * t + (k + 1) % 3]);
        }
    }
    std::sort(edges.begin(), edges.end());
    std::size_t hull_edges = 0;
    for (const auto& [a, b] : edges) {
        if (!std::binary_search(edges.begin(), edges.end(), std::make_pair(b, a))) ++hull_edges;
    }
    const auto none =
        static_cast<std::size_t>(std::count(r.neighbors.begin(), r.neighbors.end(), tri::kNone));
    if (none != hull_edges) {
        return std::to_string(none) + " hull slots (kNone) for " + std::to_string(hull_edges) +
               " hull edges";
    }
    return {};
}

/// Runs the case's checks on xy. Without `target`, returns the first failure; with it, the
/// first failure the same as `target` (the minimizer's question), skipping what cannot match.
std::optional<Failure> find_failure(const Case& c, std::span<const double> xy, bool inject_fault,
                                    const Failure* target = nullptr) {
    std::vector<std::optional<tri::Delaunay2Result>> results(kAlgorithms.size());
    std::vector<std::size_t> sequence;  // the reference first, then the others in registry order
    for (std::size_t k = 0; k < kAlgorithms.size(); ++k)
        sequence.push_back((c.reference + k) % kAlgorithms.size());
    auto wanted = [target](const Failure& f) { return target == nullptr || f.same_as(*target); };
    // First every algorithm on its own: it runs, and its output is a Delaunay triangulation.
    for (const std::size_t a : sequence) {
        try {
            results[a] = kAlgorithms[a].build(xy, c.options(a));
        } catch (const std::exception& error) {
            const Failure f{"exception", a, std::nullopt, error.what()};
            if (wanted(f)) return f;
            continue;
        } catch (...) {
            const Failure f{"exception", a, std::nullopt, "an exception of unknown type"};
            if (wanted(f)) return f;
            continue;
        }
        tri::Delaunay2Result& r = *results[a];
        if (inject_fault && a == kFaultyAlgorithm && !r.triangles.empty()) {
            r.triangles.resize(r.triangles.size() - 3);
            r.neighbors.resize(r.neighbors.size() - 3);
        }
        // Named as `exactmesh check` names them in the 1-based files this command writes.
        const tri::CheckReport report = tri::check_delaunay_2d(xy, r.triangles, {1, 1});
        if (!report.ok) {
            const Failure f{"check", a, std::nullopt, report.problem};
            if (wanted(f)) return f;
            results[a].reset();  // compared with nothing: its failure is already known
            continue;
        }
        if (std::string problem = check_neighbors(r); !problem.empty()) {
            const Failure f{"neighbors", a, std::nullopt, std::move(problem)};
            if (wanted(f)) return f;
        }
    }
    // Then agreement with the reference: the same perturbation gives the same triangulation.
    // With duplicate points only the counts are compared: which copy is inserted first decides
    // the perturbation index of the point, and so may legitimately change cocircular ties.
    const bool duplicates = tri::has_duplicate_points_2d(xy);
    const std::size_t ref = c.reference;
    for (const std::size_t a : std::span(sequence).subspan(1)) {
        if (!results[ref] || !results[a]) continue;
        const tri::Delaunay2Result& r = *results[a];
        const tri::Delaunay2Result& expected = *results[ref];
        if (r.triangles.size() != expected.triangles.size()) {
            const Failure f{"count", a, ref,
                            std::to_string(r.triangles.size() / 3) + " triangles instead of " +
                                std::to_string(expected.triangles.size() / 3)};
            if (wanted(f)) return f;
        }
        if (r.merged_into != expected.merged_into) {
            std::size_t v = 0;
            while (r.merged_into[v] == expected.merged_into[v]) ++v;
            const Failure f{"merged_into", a, ref,
                            "point " + std::to_string(v) + " merged into " +
                                std::to_string(r.merged_into[v]) + " instead of " +
                                std::to_string(expected.merged_into[v])};
            if (wanted(f)) return f;
        }
        if (!duplicates && r.triangles.size() == expected.triangles.size()) {
            const Triangles ours = tri::canonical_triangles_2d(r.triangles),
                            theirs = tri::canonical_triangles_2d(expected.triangles);
            if (ours != theirs) {
                const auto [mine, other] = std::mismatch(ours.begin(), ours.end(), theirs.begin());
                const Failure f{"triangles", a, ref,
                                "different triangles, first (" + std::to_string((*mine)[0]) + ", " +
                                    std::to_string((*mine)[1]) + ", " + std::to_string((*mine)[2]) +
                                    ") instead of (" + std::to_string((*other)[0]) + ", " +
                                    std::to_string((*other)[1]) + ", " +
                                    std::to_string((*other)[2]) + ") (0-based)"};
                if (wanted(f)) return f;
            }
        }
    }
    // Finally the brute-force definition, on small inputs.
    if (xy.size() / 2 <= kOracleMaxPoints && (target == nullptr || target->kind == "oracle")) {
        const triangulation::NaiveDelaunay2 oracle = triangulation::delaunay_2d_naive(xy);
        for (const std::size_t a : sequence) {
            if (!results[a]) continue;
            std::string problem = triangulation::compare_with_delaunay_2d_naive(
                xy, results[a]->triangles, oracle, results[a]->merged_into);
            if (problem.empty()) continue;
            const Failure f{"oracle", a, std::nullopt, std::move(problem) + " (0-based)"};
            if (wanted(f)) return f;
        }
    }
    return std::nullopt;
}

struct Minimized {
    std::vector<double> xy;
    std::size_t evaluations = 0;
    bool complete = true;  ///< false when the time budget ran out first
};

/// ddmin (generators/fuzzing/fuzz_cases.hpp) over the points, while the same failure persists.
Minimized minimize(const Case& c, const std::vector<double>& xy, const Failure& failure,
                   bool inject_fault, Clock::time_point give_up) {
    const DdminResult small = ddmin(
        xy.size() / 2,
        [&](std::span<const std::size_t> kept) {
            return find_failure(c, kept_coordinates(xy, kept, 2), inject_fault, &failure)
                .has_value();
        },
        give_up);
    return Minimized{kept_coordinates(xy, small.kept, 2), small.evaluations, small.complete};
}

std::string triangulate_command(const std::string& node, const std::string& ele, const Case& c,
                                std::size_t algorithm) {
    return "exactmesh triangulate " + shell_word(node) + " -o " + shell_word(ele) +
           " --algorithm " + algorithm_name(algorithm) + " --order " +
           kOrders[c.orders[algorithm]].name + " --seed " + std::to_string(c.seed);
}

/// Minimizes the failing case, saves it in `out_dir` and prints the report and the commands.
void report_failure(const Case& c, const Failure& failure, const fs::path& out_dir,
                    bool inject_fault, Clock::time_point give_up) {
    std::cout << "FAILURE: case seed " << c.seed << ", " << gen::distribution_name(c.distribution)
              << ", " << c.xy.size() / 2 << " points: " << failure.describe() << '\n';
    const Minimized small = minimize(c, c.xy, failure, inject_fault, give_up);
    const std::optional<Failure> final_failure = find_failure(c, small.xy, inject_fault, &failure);
    io::NodeFile nodes;
    nodes.xy = small.xy;
    nodes.first_index = 1;
    const fs::path file = out_dir / (std::string(kFilePrefix) + std::to_string(c.seed) + ".node");
    io::write_node(file, nodes);
    std::cout << "  minimized to " << small.xy.size() / 2 << " points in " << small.evaluations
              << " runs" << (small.complete ? "" : " (time budget spent: not 1-minimal)") << ": "
              << (final_failure ? final_failure->detail : std::string("(no longer reproduces)"))
              << '\n'
              << "  saved: " << file.string() << '\n'
              << "  reproduce:\n";
    const std::string node = file.string();
    if (failure.other) {
        const std::size_t a = failure.algorithm, b = *failure.other;
        const std::string ele_a = "out-" + algorithm_name(a) + ".ele";
        const std::string ele_b = "out-" + algorithm_name(b) + ".ele";
        std::cout << "    " << triangulate_command(node, ele_a, c, a) << '\n'
                  << "    " << triangulate_command(node, ele_b, c, b) << '\n'
                  << "    exactmesh check " << shell_word(node) << ' ' << shell_word(ele_a) << '\n'
                  << "    exactmesh check " << shell_word(node) << ' ' << shell_word(ele_b) << '\n'
                  << "  (then compare the two triangle sets: they should be equal)\n";
    } else {
        std::cout << "    " << triangulate_command(node, "out.ele", c, failure.algorithm) << '\n'
                  << "    exactmesh check " << shell_word(node) << " out.ele\n";
    }
    // What `check` cannot see: it reads neither .neigh files nor the oracle's verdict.
    if (failure.kind == "neighbors") {
        std::cout << "  (check does not read neighbours: see out.neigh, Triangle's convention)\n";
    } else if (failure.kind == "oracle") {
        std::cout
            << "  (the naive empty-circle oracle, triangulation/delaunay/delaunay_2d_naive.hpp, "
               "disagrees; check may pass)\n";
    }
    if (inject_fault) {
        std::cout << "  (fault injected by " << kInjectFaultVariable << ": the commands run "
                  << "without it)\n";
    }
    std::cout.flush();
}

void check_minutes(double minutes) {
    if (!std::isfinite(minutes) || minutes < 0 || minutes > 1e6) {
        std::ostringstream value;
        value << minutes;
        throw InputError("--minutes must be a number of minutes between 0 and 1000000, not " +
                         value.str());
    }
}

/// The --out (--save) directory, made when missing.
fs::path prepare_out_dir(const FuzzArguments& arguments) {
    const fs::path out_dir = arguments.out.empty() ? fs::path(".") : fs::path(arguments.out);
    std::error_code error;
    if (fs::exists(out_dir, error) && !fs::is_directory(out_dir, error)) {
        throw InputError("--out " + out_dir.string() + ": not a directory");
    }
    if (!fs::exists(out_dir, error) && !fs::create_directories(out_dir, error)) {
        throw InputError("--out " + out_dir.string() + ": cannot create the directory (" +
                         error.message() + ")");
    }
    return out_dir;
}

int run_program_fuzz(const FuzzArguments& arguments);
FuzzKind kind_from_name(const std::string& name);

/// The shard of this run: --shard I/N, else the whole campaign (0/1).
FuzzShard shard_of(const FuzzArguments& arguments) {
    return arguments.shard.empty() ? FuzzShard{} : parse_fuzz_shard(arguments.shard);
}

/// A double as a command-line word that reads back the same.
std::string exact_word(double value) {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    return text.str();
}

/// The arguments a --jobs child runs with (before its --shard, --out and --quiet).
std::vector<std::string> shard_arguments(const FuzzArguments& arguments) {
    std::vector<std::string> words = {"exactmesh", "fuzz", "--seed",
                                      std::to_string(arguments.seed)};
    if (arguments.minutes_given)
        words.insert(words.end(), {"--minutes", exact_word(arguments.minutes)});
    if (arguments.command.empty()) return words;
    words.insert(words.end(), {"--command", arguments.command, "--kind", arguments.kind, "--count",
                               std::to_string(arguments.count), "--timeout",
                               exact_word(arguments.timeout), "--output", arguments.output,
                               "--max-points", std::to_string(arguments.max_points),
                               "--minimize-seconds", exact_word(arguments.minimize_seconds)});
    if (arguments.conforming) words.emplace_back("--conforming");
    if (arguments.convex_hull) words.emplace_back("--convex-hull");
    if (arguments.orient) words.emplace_back("--orient");
    return words;
}

/// --jobs N: the N shards as child processes, then their merge into --out.
int run_fuzz_jobs(const FuzzArguments& arguments) {
    if (arguments.jobs > kMaxFuzzJobs) {
        throw InputError("--jobs " + std::to_string(arguments.jobs) + ": at most " +
                         std::to_string(kMaxFuzzJobs) + " local shards");
    }
    if (!arguments.shard.empty())
        throw InputError("--jobs runs its own shards: not with --shard " + arguments.shard);
    if (!arguments.command.empty())
        kind_from_name(arguments.kind);  // refused before forking
    else if (!arguments.minutes_given)
        throw InputError(
            "fuzz needs --minutes M (a campaign over our own algorithms) or "
            "--command 'PROGRAM {in} {out}' (another program)");
    const fs::path out = prepare_out_dir(arguments);
    if (!arguments.quiet) {
        std::cerr << "fuzz: " << arguments.jobs << " shards in " << (out / "shard-*").string()
                  << std::endl;
    }
    const std::vector<int> statuses =
        run_fuzz_shard_processes(shard_arguments(arguments), arguments.jobs, out);
    std::vector<fs::path> folders;
    int worst = kExitSuccess;
    for (std::size_t i = 0; i < statuses.size(); ++i) {
        const fs::path folder = out / ("shard-" + std::to_string(i));
        folders.push_back(folder);
        if (statuses[i] == kExitSuccess || statuses[i] == kExitCheckFailed) continue;
        std::cout << "fuzz: shard " << i << "/" << statuses.size() << " exited with status "
                  << statuses[i] << "; its output: " << (folder / "fuzz.log").string() << '\n';
        worst = std::max(worst, statuses[i] == kExitBadInput ? kExitBadInput : kExitInternalError);
    }
    if (worst != kExitSuccess) return worst;
    return merge_fuzz_shards(folders, out, std::cout);
}

int run_fuzz(const FuzzArguments& arguments) {
    // Bad arguments are reported before any work (exit 2 through InputError).
    if (!arguments.merge.empty()) {
        std::vector<fs::path> folders(arguments.merge.begin(), arguments.merge.end());
        return merge_fuzz_shards(folders, arguments.out, std::cout);
    }
    if (arguments.jobs > 0) return run_fuzz_jobs(arguments);
    if (!arguments.command.empty()) return run_program_fuzz(arguments);
    if (!arguments.minutes_given)
        throw InputError(
            "fuzz needs --minutes M (a campaign over our own algorithms) or "
            "--command 'PROGRAM {in} {out}' (another program)");
    check_minutes(arguments.minutes);
    const FuzzShard shard = shard_of(arguments);
    const fs::path out_dir = prepare_out_dir(arguments);
    const char* inject = std::getenv(kInjectFaultVariable);
    const bool inject_fault = inject != nullptr && std::string_view(inject) == "1";

    const auto start = Clock::now();
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(arguments.minutes * 60.0));
    ProgressLine progress(arguments.quiet);
    std::uint64_t cases = 0, points = 0, failures = 0;
    std::array<std::uint64_t, std::size(gen::kAllDistributions)> per_distribution{};
    const std::uint64_t first_seed = shard.first_seed(arguments.seed);
    std::uint64_t seed = first_seed;
    auto elapsed = [start] { return std::chrono::duration<double>(Clock::now() - start).count(); };
    while (Clock::now() < deadline) {
        const Case c = make_case(seed);
        const std::optional<Failure> failure = find_failure(c, c.xy, inject_fault);
        ++cases;
        points += c.xy.size() / 2;
        ++per_distribution[static_cast<std::size_t>(c.distribution)];
        if (failure) {
            ++failures;
            if (failures <= kMaxSavedFailures) {
                const auto now = Clock::now();
                const auto give_up = now + std::clamp<Clock::duration>(
                                               deadline - now, kMinimizeAtLeast, kMinimizeAtMost);
                report_failure(c, *failure, out_dir, inject_fault, give_up);
            } else {
                std::cout << "FAILURE: case seed " << c.seed << ": " << failure->describe()
                          << " (not minimized: more than " << kMaxSavedFailures << " failures)\n";
            }
        }
        if (progress.due()) {
            std::cerr << "fuzz: " << format_seconds(elapsed()) << " of "
                      << format_seconds(arguments.minutes * 60) << ", " << cases << " cases, "
                      << points << " points, " << failures << " failures" << std::endl;
        }
        seed += shard.count;
    }
    std::cout << "fuzz: " << cases << " cases";
    if (cases > 0) {
        std::cout << " (case seeds " << first_seed << ".." << seed - shard.count;
        if (shard.count > 1) std::cout << " every " << shard.count << ", shard " << arguments.shard;
        std::cout << ")";
    }
    std::cout << ", " << points << " points, " << failures << " failures in "
              << format_seconds(elapsed()) << '\n';
    std::cout << "fuzz: cases per distribution:";
    for (std::size_t d = 0; d < per_distribution.size(); ++d) {
        std::cout << ' ' << gen::distribution_name(gen::kAllDistributions[d]) << ' '
                  << per_distribution[d];
    }
    std::cout << '\n';
    if (!arguments.shard.empty()) {
        FuzzShardSummary summary{"campaign", arguments.shard, {}};
        summary.numbers = {{"cases", static_cast<double>(cases)},
                           {"bad", static_cast<double>(failures)},
                           {"points", static_cast<double>(points)},
                           {"seconds", elapsed()}};
        if (cases > 0) {
            summary.numbers["first_seed"] = static_cast<double>(first_seed);
            summary.numbers["last_seed"] = static_cast<double>(seed - shard.count);
        }
        write_fuzz_shard_summary(out_dir, summary);
    }
    return failures > 0 ? kExitCheckFailed : kExitSuccess;
}

FuzzKind kind_from_name(const std::string& name) {
    if (name == "points2d") return FuzzKind::Points2d;
    if (name == "pslg") return FuzzKind::Pslg;
    if (name == "points3d") return FuzzKind::Points3d;
    throw InputError("--kind " + name + ": expected points2d, pslg or points3d");
}

std::string describe_input(const FuzzInput& input) {
    std::string text = std::to_string(input.point_count()) + " points";
    if (input.kind == FuzzKind::Pslg)
        text += ", " + std::to_string(input.segments.size() / 2) + " segments";
    return text;
}

/// The reproducer beside the saved input: runs the command on a copy of it in a fresh scratch
/// folder (from the directory the campaign ran in, so relative program paths still work), then
/// `exactmesh check` on its output. Exit status: the command's when it fails, else the check's.
std::string reproducer_script(const FuzzArguments& arguments, const FuzzInput& input,
                              const ProgramFuzzFailure& failure, const fs::path& saved) {
    const std::string in_name = input_file_name(input.kind);
    const std::string in = "$dir/" + in_name;
    const std::string written = output_path(arguments.output, "$dir", in);
    // Another format than .ele is converted by meshio, as the campaign did, and checked so.
    const bool convert = !is_ele_output(arguments.output);
    const std::string out = convert ? "$dir/converted.ele" : written;
    fs::path out_node = out;
    out_node.replace_extension(".node");
    std::error_code error;
    fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (error) exe = "exactmesh";
    std::ostringstream script;
    script << "#!/bin/sh\n"
           << "# exactmesh fuzz --kind " << arguments.kind << ": case seed " << input.seed << " ("
           << input.distribution << ", " << describe_input(failure.input) << "), minimized to "
           << describe_input(input) << ".\n"
           << "# " << verdict_name(failure.minimized_judgement.verdict) << ": "
           << failure.minimized_judgement.detail << "\n"
           << "# Runs the command on a copy of " << saved.filename().string()
           << " in a fresh folder, then checks its output exactly\n"
           << "# (exit status: the command's when it fails, else the check's; the campaign's "
              "time limit was "
           << format_seconds(arguments.timeout) << ").\n"
           << "here=$(cd \"$(dirname \"$0\")\" && pwd) || exit 2\n"
           << "cd " << shell_word(fs::current_path().string()) << " || exit 2\n"
           << "dir=$(mktemp -d) || exit 2\n"
           << "cp \"$here\"/" << shell_word(saved.filename().string()) << " \"" << in
           << "\" || exit 2\n"
           << "echo \"input and output in $dir\"\n"
           << substitute_command(arguments.command, "\"" + in + "\"", "\"" + written + "\"") << '\n'
           << "status=$?\n"
           << "if [ $status -ne 0 ]; then echo \"the command exited with status $status\"; exit "
              "$status; fi\n";
    if (convert) {
        script << meshio_conversion_command(input.kind, "\"" + written + "\"", "\"" + out + "\"")
               << " || exit 2\n";
    }
    if (input.kind == FuzzKind::Pslg) {
        script << shell_word(exe.string()) << " check \"" << in << "\" \"" << out << '"'
               << (arguments.conforming ? " --conforming" : "")
               << (arguments.convex_hull ? " --convex-hull" : "") << '\n';
    } else {
        // The output's own .node (TetGen drops duplicate points from it) names its vertices.
        script << "node=\"" << in << "\"\n"
               << "if [ -e \"" << out_node.string() << "\" ]; then node=\"" << out_node.string()
               << "\"; fi\n"
               << shell_word(exe.string()) << " check \"$node\" \"" << out << "\"\n";
    }
    return script.str();
}

void report_program_failure(const FuzzArguments& arguments, const ProgramFuzzFailure& failure,
                            const fs::path& out_dir) {
    const FuzzInput& input = failure.input;
    std::cout << "FAILURE: case seed " << input.seed << " (" << input.distribution << ", "
              << describe_input(input) << "): " << verdict_name(failure.judgement.verdict) << ": "
              << failure.judgement.detail << '\n';
    if (!failure.minimized_run) {
        std::cout << "  (not minimized nor saved: more than " << kMaxSavedFailures
                  << " failures)\n";
        return;
    }
    std::cout << "  minimized to " << describe_input(failure.minimized) << " in "
              << failure.evaluations << " runs"
              << (failure.complete ? "" : " (time budget spent: not 1-minimal)") << ": "
              << verdict_name(failure.minimized_judgement.verdict) << ": "
              << failure.minimized_judgement.detail << '\n';
    const std::string stem = std::string(kFilePrefix) + std::to_string(input.seed);
    const fs::path saved = out_dir / (stem + (input.kind == FuzzKind::Pslg ? ".poly" : ".node"));
    const fs::path script = out_dir / (stem + ".sh");
    write_fuzz_input(saved, failure.minimized);
    {
        std::ofstream file(script);
        file << reproducer_script(arguments, failure.minimized, failure, saved);
        if (!file) throw InputError(script.string() + ": cannot write");
    }
    fs::permissions(script, fs::perms::owner_exec | fs::perms::group_exec | fs::perms::others_exec,
                    fs::perm_options::add);
    std::cout << "  saved: " << saved.string() << '\n'
              << "  reproduce: sh " << shell_word(script.string()) << '\n';
    std::cout.flush();
}

/// Removes the scratch folder however the campaign ends.
struct ScratchFolder {
    fs::path path;
    explicit ScratchFolder(std::string pattern) {
        if (mkdtemp(pattern.data()) == nullptr)
            throw InputError("fuzz: cannot make a scratch folder " + pattern);
        path = pattern;
    }
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;
    ~ScratchFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

int run_program_fuzz(const FuzzArguments& arguments) {
    ProgramFuzzOptions options;
    options.kind = kind_from_name(arguments.kind);
    if (arguments.minutes_given) {
        check_minutes(arguments.minutes);
        options.minutes = arguments.minutes;
    }
    if (!std::isfinite(arguments.timeout) || arguments.timeout <= 0 || arguments.timeout > 1e6)
        throw InputError("--timeout must be a number of seconds above 0");
    if (!std::isfinite(arguments.minimize_seconds) || arguments.minimize_seconds < 0 ||
        arguments.minimize_seconds > 1e6)
        throw InputError("--minimize-seconds must be a number of seconds, at least 0");
    if (arguments.max_points < 4) throw InputError("--max-points must be at least 4");
    if (arguments.output.find("{dir}") == std::string::npos &&
        arguments.output.find("{stem}") == std::string::npos)
        throw InputError("--output " + arguments.output +
                         ": must name a file in the scratch folder, by {dir} or {stem}");
    if (fs::path(arguments.output).extension().string().size() < 2)
        throw InputError("--output " + arguments.output +
                         ": needs an extension: .ele (Triangle, TetGen) or one meshio reads "
                         "(.vtu, .msh, ...)");
    const FuzzShard shard = shard_of(arguments);
    options.count = shard.share(arguments.count);
    options.seed = shard.first_seed(arguments.seed);
    options.seed_stride = shard.count;
    options.max_points = arguments.max_points;
    options.pslg_check =
        arguments.conforming ? PslgCheck::Conforming : PslgCheck::ConstrainedDelaunay;
    options.minimize_budget =
        std::chrono::milliseconds(std::llround(arguments.minimize_seconds * 1000));
    options.max_minimized = kMaxSavedFailures;
    options.quiet = arguments.quiet;
    if ((arguments.conforming || arguments.convex_hull) && options.kind != FuzzKind::Pslg)
        throw InputError("--conforming and --convex-hull apply to --kind pslg only");
    options.convex_hull = arguments.convex_hull;
    const fs::path out_dir = prepare_out_dir(arguments);

    const ScratchFolder scratch((fs::temp_directory_path() / "exactmesh-fuzz-XXXXXX").string());
    ExternalCommand command;
    command.command = arguments.command;
    command.output = arguments.output;
    command.timeout = std::chrono::milliseconds(std::llround(arguments.timeout * 1000));
    command.orient = arguments.orient;
    const ProgramFuzzSummary summary = fuzz_program(
        external_program(command, scratch.path), options,
        [&](const ProgramFuzzFailure& failure) {
            report_program_failure(arguments, failure, out_dir);
        },
        std::cerr);
    std::cout << "fuzz: " << summary.run << " inputs";
    if (summary.run > 0)
        std::cout << " (" << arguments.kind << ", case seeds " << summary.first_seed << ".."
                  << summary.last_seed
                  << (shard.count > 1
                          ? " every " + std::to_string(shard.count) + ", shard " + arguments.shard
                          : std::string())
                  << ")";
    std::cout << ", " << summary.passed << " passed, " << summary.failed << " failed, "
              << summary.crashed << " crashed, " << summary.timed_out << " timed out, "
              << summary.refused << " refused in " << format_seconds(summary.seconds) << '\n';
    std::cout << "fuzz: failed of run per distribution:";
    for (const auto& [name, tally] : summary.per_distribution)
        std::cout << ' ' << name << ' ' << tally[1] << '/' << tally[0];
    std::cout << '\n';
    if (!arguments.shard.empty()) {
        FuzzShardSummary shard_summary{arguments.kind, arguments.shard, {}};
        const auto number = [](std::uint64_t n) { return static_cast<double>(n); };
        shard_summary.numbers = {
            {"cases", number(summary.run)},           {"bad", number(summary.bad())},
            {"passed", number(summary.passed)},       {"refused", number(summary.refused)},
            {"failed", number(summary.failed)},       {"crashed", number(summary.crashed)},
            {"timed_out", number(summary.timed_out)}, {"seconds", summary.seconds}};
        if (summary.run > 0) {
            shard_summary.numbers["first_seed"] = number(summary.first_seed);
            shard_summary.numbers["last_seed"] = number(summary.last_seed);
        }
        write_fuzz_shard_summary(out_dir, shard_summary);
    }
    return summary.bad() > 0 ? kExitCheckFailed : kExitSuccess;
}

}  // namespace

void add_fuzz_command(CLI::App& app, int& exit_status) {
    auto arguments = std::make_shared<FuzzArguments>();
    CLI::App* command = app.add_subcommand(
        "fuzz",
        "Timed differential campaign: random and degenerate point sets through all three "
        "algorithms, each checked exactly, against the others and (n <= 60) against a naive "
        "empty-circle oracle; or, with --command, the same degenerate inputs (2D points, PSLGs, "
        "3D points) through another program, its output checked exactly. Failures are minimized "
        "and saved");
    CLI::Option* minutes =
        command
            ->add_option("--minutes", arguments->minutes,
                         "How long to run (fractions allowed); needed without --command, a limit "
                         "besides --count with it")
            ->type_name("M");
    // CLI11 2.1 would read "-3" into an unsigned as 2^64 - 3: refuse the sign before conversion.
    const CLI::Validator non_negative(
        [](const std::string& text) {
            return text.find('-') == std::string::npos ? std::string()
                                                       : "must be a non-negative integer";
        },
        "", "non-negative");
    command
        ->add_option("--seed", arguments->seed,
                     "First case seed (cases use seed, seed+1, ...; shard I/N: seed+I, seed+I+N, "
                     "...)")
        ->check(non_negative)
        ->capture_default_str();
    command
        ->add_option("--out,--save", arguments->out,
                     "Directory for the minimized failing inputs, fuzz-failure-<seed>.node "
                     "(.poly), and with --command the reproducers fuzz-failure-<seed>.sh")
        ->capture_default_str()
        ->type_name("DIR");
    command->add_flag("--quiet", arguments->quiet, "No progress lines on stderr");
    command
        ->add_option("--command", arguments->command,
                     "Fuzz another program: a shell command (run by /bin/sh -c) where {in} is the "
                     "input file (Triangle .node or .poly, TetGen .node, 1-based) and {out} the "
                     "output file it must write (Triangle .ele, TetGen .ele, or by --output any "
                     "format meshio reads); do not quote them")
        ->type_name("'PROGRAM {in} {out}'");
    command
        ->add_option("--kind", arguments->kind,
                     "With --command: points2d (Delaunay triangulation), pslg (constrained "
                     "Delaunay, or --conforming) or points3d (Delaunay tetrahedralization)")
        ->capture_default_str()
        ->type_name("points2d|pslg|points3d");
    command->add_option("--count", arguments->count, "With --command: how many inputs to run")
        ->check(non_negative)
        ->capture_default_str()
        ->type_name("N");
    command
        ->add_option("--timeout", arguments->timeout,
                     "With --command: seconds per run; the process group is killed after it, "
                     "and that counts as a failure")
        ->capture_default_str()
        ->type_name("SECONDS");
    command
        ->add_option("--output", arguments->output,
                     "With --command: where the program writes its output, {dir} being the "
                     "scratch folder and {stem} the input file without its extension (for "
                     "TetGen: '{stem}.1.ele'); a .node beside it gives its vertices, for pslg a "
                     ".poly beside it its constrained pieces. Another extension than .ele (.vtu, "
                     ".msh, anything meshio reads) is converted by meshio (python3-meshio): its "
                     "points and triangles (tetrahedra for points3d)")
        ->capture_default_str()
        ->type_name("PATH");
    command->add_option("--max-points", arguments->max_points, "With --command: largest input")
        ->check(non_negative)
        ->capture_default_str()
        ->type_name("N");
    command->add_flag("--conforming", arguments->conforming,
                      "With --kind pslg: check a valid mesh of the domain (as `check "
                      "--conforming`) instead of the constrained Delaunay triangulation");
    command->add_flag("--orient", arguments->orient,
                      "With --command: the program does not orient its triangles (tetrahedra) "
                      "consistently (Qhull): each is oriented by the exact orient2d (orient3d) "
                      "before the checks");
    command->add_flag("--convex-hull", arguments->convex_hull,
                      "With --kind pslg: the output must cover the convex hull (Triangle's -c, "
                      "`exactmesh cdt --convex-hull`); without it, a missing triangle is not "
                      "seen (the checks are local)");
    command
        ->add_option("--minimize-seconds", arguments->minimize_seconds,
                     "With --command: time budget of each minimization")
        ->capture_default_str()
        ->type_name("SECONDS");
    command
        ->add_option("--shard", arguments->shard,
                     "Run shard I of N (0 <= I < N) of the campaign: case seeds seed+I, "
                     "seed+I+N, ... (with --count C, this shard's share of the C cases); writes "
                     "fuzz-summary.txt in --out for --merge. For batch systems, e.g. a Slurm "
                     "array: --shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT")
        ->type_name("I/N");
    command
        ->add_option("--jobs", arguments->jobs,
                     "Run N shards at once as child processes (one per core: N = nproc), each "
                     "in OUT/shard-I with its output in OUT/shard-I/fuzz.log, then merge them "
                     "(failure files copied into --out, one summary); 0: one process")
        ->check(non_negative)
        ->type_name("N");
    command
        ->add_option("--merge", arguments->merge,
                     "Merge shard folders (made by --shard or --jobs, here or on other machines) "
                     "into --out: counts summed, failure files copied, one summary; exit 1 when "
                     "any shard found a failure")
        ->type_name("DIR...");
    command->callback([arguments, minutes, &exit_status] {
        arguments->minutes_given = minutes->count() > 0;
        exit_status = run_fuzz(*arguments);
    });
}

}  // namespace exactmesh::cli
