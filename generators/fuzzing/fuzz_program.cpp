// SPDX-License-Identifier: MIT
// Fuzzing other people's triangulators (generators/fuzzing/fuzz_program.hpp): inputs from
// generators/inputs, exact judgement by triangulation/checks, ddmin from fuzz_cases.hpp.
#include "generators/fuzzing/fuzz_program.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <ostream>
#include <sstream>
#include <utility>

#include "base/errors.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/inputs/inputs_3d.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/mesh/constrained_flags_2d.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;

/// Small inputs below this many points are where the case sizes cluster (case_size).
constexpr std::uint32_t kSmallMax = 60;

std::string format_point(std::span<const double> coordinates) {
    std::ostringstream text;
    text.precision(17);
    text << '(';
    for (std::size_t d = 0; d < coordinates.size(); ++d) text << (d ? ", " : "") << coordinates[d];
    return text.str() + ')';
}

/// True when the points have no triangulation (no cell at all is a valid answer): all
/// collinear in 2D, all coplanar in 3D, decided exactly by the checks on an empty mesh.
bool has_no_triangulation(const FuzzInput& input) {
    if (input.kind == FuzzKind::Points3d)
        return tri::check_delaunay_3d(input.coordinates, std::span<const tri::VertIdx>{}).ok;
    return tri::check_delaunay_2d(input.coordinates, std::span<const tri::VertIdx>{}).ok;
}

/// Each cell counter-clockwise (2D) or with orient3d > 0 (Tetrahedralization3), exactly.
void orient_cells(std::span<const double> points, std::size_t dimension,
                  std::vector<std::uint32_t>& cells) {
    const std::size_t corners = dimension + 1;
    for (std::size_t c = 0; c + corners <= cells.size(); c += corners) {
        const auto at = [&](std::size_t k) { return &points[dimension * cells[c + k]]; };
        const predicates::Sign sign = dimension == 2
                                          ? predicates::orient2d(at(0), at(1), at(2))
                                          : predicates::orient3d(at(0), at(1), at(2), at(3));
        if (sign == predicates::Sign::Negative) std::swap(cells[c], cells[c + 1]);
    }
}

/// The minimizer's question: the same verdict, and for a crash the same exit status or signal
/// (the words before the program's own message). Any check failure counts as the same: a
/// smaller input names other vertices.
bool same_failure(const Judgement& candidate, const Judgement& original) {
    if (candidate.verdict != original.verdict) return false;
    if (original.verdict != Verdict::Crashed) return true;
    const auto how = [](const std::string& detail) { return detail.substr(0, detail.find(':')); };
    return how(candidate.detail) == how(original.detail);
}

}  // namespace

const char* verdict_name(Verdict verdict) {
    switch (verdict) {
        case Verdict::Passed:
            return "passed";
        case Verdict::Refused:
            return "refused";
        case Verdict::Failed:
            return "failed";
        case Verdict::Crashed:
            return "crashed";
        case Verdict::TimedOut:
            return "timed out";
    }
    return "?";
}

FuzzInput make_fuzz_input(FuzzKind kind, std::uint64_t seed, std::uint32_t max_points) {
    // The first two draws are the ones `exactmesh fuzz --minutes` makes (distribution, then
    // size), so a points2d case is that campaign's case of the same seed, cut to max_points.
    CaseRandom random(seed);
    FuzzInput input;
    input.kind = kind;
    input.seed = seed;
    max_points = std::max<std::uint32_t>(max_points, 4);
    switch (kind) {
        case FuzzKind::Points2d: {
            const Distribution d = kAllDistributions[random.next() % std::size(kAllDistributions)];
            const std::uint32_t n = std::min(case_size(random, kSmallMax, max_points), max_points);
            input.distribution = distribution_name(d);
            input.coordinates = generate_points_2d(d, n, seed);
            break;
        }
        case FuzzKind::Points3d: {
            const Distribution3 d =
                kAllDistributions3[random.next() % std::size(kAllDistributions3)];
            // At least 5 points: 3 or 4 are mostly a plane or a single tetrahedron.
            const std::uint32_t n = std::max<std::uint32_t>(
                std::min(case_size(random, kSmallMax, max_points), max_points), 5);
            input.distribution = distribution_name(d);
            input.coordinates = generate_points_3d(d, n, seed);
            break;
        }
        case FuzzKind::Pslg: {
            const PslgDistribution d =
                kAllPslgDistributions[random.next() % std::size(kAllPslgDistributions)];
            const std::uint32_t n = std::max<std::uint32_t>(
                std::min(case_size(random, kSmallMax, max_points), max_points), 4);
            const std::uint32_t segments = random.between(1, n);
            input.distribution = pslg_distribution_name(d);
            PslgInput pslg = generate_pslg(d, n, segments, seed);
            // Holes are not written: the program is asked for the triangulation of the whole
            // PSLG (a program that removes regions reports its pieces, see judge_output).
            input.coordinates = std::move(pslg.xy);
            input.segments = std::move(pslg.segments);
            break;
        }
    }
    return input;
}

std::size_t unit_count(const FuzzInput& input) {
    return input.point_count() + input.segments.size() / 2;
}

FuzzInput restrict_input(const FuzzInput& input, std::span<const std::size_t> kept_units) {
    FuzzInput out;
    out.kind = input.kind;
    out.seed = input.seed;
    out.distribution = input.distribution;
    const std::size_t points = input.point_count(), dimension = input.dimension();
    std::vector<std::uint32_t> renumber(points, UINT32_MAX);
    std::uint32_t next = 0;
    for (const std::size_t unit : kept_units) {
        if (unit < points) {
            renumber[unit] = next++;
            for (std::size_t d = 0; d < dimension; ++d)
                out.coordinates.push_back(input.coordinates[dimension * unit + d]);
        } else {
            const std::size_t s = unit - points;
            const std::uint32_t a = renumber[input.segments[2 * s]],
                                b = renumber[input.segments[2 * s + 1]];
            // kept_units is increasing: the vertices come first, so both ends are numbered.
            if (a != UINT32_MAX && b != UINT32_MAX) {
                out.segments.push_back(a);
                out.segments.push_back(b);
            }
        }
    }
    return out;
}

Judgement judge_output(const FuzzInput& input, const ProgramOutput& output, PslgCheck pslg_check,
                       bool convex_hull) {
    if (output.status == RunStatus::TimedOut) return {Verdict::TimedOut, output.message};
    if (output.status == RunStatus::Crashed) {
        if (has_no_triangulation(input))
            return {Verdict::Refused, output.message + " (the input has no triangulation)"};
        return {Verdict::Crashed, output.message};
    }
    if (!output.readable) return {Verdict::Failed, output.message};

    // Output vertices to input points by exact coordinates (first occurrence); the others are
    // vertices the program added, numbered after the input's.
    const std::size_t dimension = input.dimension(), input_points = input.point_count();
    std::vector<double> all = input.coordinates;
    std::vector<std::uint32_t> to_mesh;  // output vertex -> index into `all`
    std::vector<bool> added;
    if (output.points.empty()) {
        to_mesh.resize(input_points);
        for (std::uint32_t v = 0; v < input_points; ++v) to_mesh[v] = v;
        added.assign(input_points, false);
    } else {
        std::map<std::array<double, 3>, std::uint32_t> where;
        for (std::uint32_t v = 0; v < input_points; ++v) {
            std::array<double, 3> key{};
            for (std::size_t d = 0; d < dimension; ++d)
                key[d] = input.coordinates[dimension * v + d];
            where.emplace(key, v);
        }
        const std::size_t output_points = output.points.size() / dimension;
        for (std::size_t v = 0; v < output_points; ++v) {
            std::array<double, 3> key{};
            for (std::size_t d = 0; d < dimension; ++d) key[d] = output.points[dimension * v + d];
            if (const auto found = where.find(key); found != where.end()) {
                to_mesh.push_back(found->second);
                added.push_back(false);
            } else {
                to_mesh.push_back(static_cast<std::uint32_t>(all.size() / dimension));
                added.push_back(true);
                all.insert(all.end(), key.begin(),
                           key.begin() + static_cast<std::ptrdiff_t>(dimension));
            }
        }
    }
    std::vector<std::uint32_t> cells;
    cells.reserve(output.cells.size());
    for (const std::uint32_t v : output.cells) {
        if (v >= to_mesh.size())
            return {Verdict::Failed, "a cell names vertex " + std::to_string(v) + " of " +
                                         std::to_string(to_mesh.size()) + " (0-based)"};
        if (input.kind != FuzzKind::Pslg && added[v]) {
            return {Verdict::Failed,
                    "a cell uses output vertex " + std::to_string(v + 1) + " " +
                        format_point(std::span(output.points).subspan(dimension * v, dimension)) +
                        ", which is not an input point"};
        }
        cells.push_back(to_mesh[v]);
    }
    if (!output.oriented) orient_cells(all, dimension, cells);

    if (input.kind == FuzzKind::Points2d) {
        const tri::CheckReport report = tri::check_delaunay_2d(
            input.coordinates, cells, {output.first_vertex, output.first_cell});
        return report.ok ? Judgement{} : Judgement{Verdict::Failed, report.problem};
    }
    if (input.kind == FuzzKind::Points3d) {
        const tri::Check3Report report = tri::check_delaunay_3d(
            input.coordinates, cells, {},
            tri::Check3Numbering{output.first_vertex, output.first_cell, output.corner_order});
        return report.ok ? Judgement{} : Judgement{Verdict::Failed, report.problem};
    }
    // A PSLG, as `exactmesh check IN.poly OUT.ele [--conforming]` checks it.
    tri::Triangulation2 mesh;
    mesh.xy = std::move(all);
    mesh.triangles = std::move(cells);
    std::vector<tri::VertIdx> pieces;
    for (const std::uint32_t v : output.pieces) {
        if (v >= to_mesh.size())
            return {Verdict::Failed, "a constrained piece names vertex " + std::to_string(v) +
                                         " of " + std::to_string(to_mesh.size()) + " (0-based)"};
        pieces.push_back(to_mesh[v]);
    }
    tri::flag_constrained_edges_2d(mesh, pieces.empty()
                                             ? std::span<const tri::VertIdx>(input.segments)
                                             : std::span<const tri::VertIdx>(pieces));
    const tri::CheckNumbering numbering{output.first_vertex, output.first_cell};
    if (convex_hull) {
        // Added vertices (crossings, splits) lie on segments, inside the hull: the mesh of all
        // its vertices must tile the convex hull, every distinct vertex used.
        const tri::CheckReport cover = tri::check_topology_2d(mesh.xy, mesh.triangles, numbering);
        if (!cover.ok) return {Verdict::Failed, cover.problem + " (convex hull expected)"};
    }
    const auto count = static_cast<std::uint32_t>(input_points);
    tri::CheckReport report =
        pslg_check == PslgCheck::Conforming
            ? tri::check_conforming_mesh_2d(mesh, count, input.segments, pieces, numbering)
            : tri::check_constrained_delaunay_2d(mesh, count, input.segments, pieces, numbering);
    if (report.ok && pslg_check == PslgCheck::ConstrainedDelaunay)
        report = tri::check_input_vertices_kept_2d(mesh, input.coordinates, numbering);
    return report.ok ? Judgement{} : Judgement{Verdict::Failed, report.problem};
}

ProgramFuzzSummary fuzz_program(const ProgramUnderTest& program, const ProgramFuzzOptions& options,
                                const std::function<void(const ProgramFuzzFailure&)>& on_failure,
                                std::ostream& progress) {
    if (options.seed_stride == 0) throw InputError("fuzz: the case seed stride must be at least 1");
    ProgramFuzzSummary summary;
    summary.first_seed = options.seed;
    ProgressLine line(options.quiet);
    const auto start = FuzzClock::now();
    const auto deadline = start + std::chrono::duration_cast<FuzzClock::duration>(
                                      std::chrono::duration<double>(options.minutes * 60.0));
    auto judge = [&](const FuzzInput& input) {
        return judge_output(input, program(input), options.pslg_check, options.convex_hull);
    };
    for (std::uint64_t i = 0; i < options.count; ++i) {
        if (options.minutes > 0 && FuzzClock::now() >= deadline) break;
        const FuzzInput input = make_fuzz_input(
            options.kind, options.seed + i * options.seed_stride, options.max_points);
        const Judgement judgement = judge(input);
        ++summary.run;
        summary.last_seed = input.seed;
        switch (judgement.verdict) {
            case Verdict::Passed:
                ++summary.passed;
                break;
            case Verdict::Refused:
                ++summary.refused;
                break;
            case Verdict::Failed:
                ++summary.failed;
                break;
            case Verdict::Crashed:
                ++summary.crashed;
                break;
            case Verdict::TimedOut:
                ++summary.timed_out;
                break;
        }
        std::array<std::uint64_t, 2>& tally = summary.per_distribution[input.distribution];
        ++tally[0];
        if (judgement.bad()) ++tally[1];
        if (judgement.bad()) {
            ProgramFuzzFailure failure{input, input, judgement, judgement};
            if (summary.bad() <= options.max_minimized) {
                failure.minimized_run = true;
                const auto give_up = FuzzClock::now() + options.minimize_budget;
                const DdminResult small = ddmin(
                    unit_count(input),
                    [&](std::span<const std::size_t> kept) {
                        if (line.due()) {
                            progress << "fuzz: minimizing case seed " << input.seed << ": "
                                     << kept.size() << " of " << unit_count(input)
                                     << " units in the candidate, "
                                     << format_seconds(line.elapsed_seconds()) << " elapsed"
                                     << std::endl;
                        }
                        return same_failure(judge(restrict_input(input, kept)), judgement);
                    },
                    give_up);
                failure.minimized = restrict_input(input, small.kept);
                failure.minimized_judgement = judge(failure.minimized);
                failure.evaluations = small.evaluations;
                failure.complete = small.complete;
            }
            on_failure(failure);
        }
        if (line.due()) {
            progress << "fuzz: " << summary.run << '/' << options.count << " inputs, "
                     << summary.bad() << " failures (" << summary.crashed << " crashed, "
                     << summary.timed_out << " timed out), "
                     << format_seconds(line.elapsed_seconds()) << " elapsed" << std::endl;
        }
    }
    summary.seconds = line.elapsed_seconds();
    return summary;
}

}  // namespace exactmesh::generators
