// SPDX-License-Identifier: MIT
// Python bindings of the fuzzing driver (generators/fuzzing/fuzz_program.hpp): exactmesh.fuzz
// judges a Python callable on the project's degenerate inputs, exactly, and minimizes what it
// gets wrong. Wiring only: the driver runs with the GIL released and takes it back for each call
// of the callable. The callable is wrapped on the Python side (exactmesh/__init__.py,
// _fuzz_adapter), which catches its exceptions and normalizes its answer, so this file sees one
// of ("ok", points or None, cells, pieces or None), ("crashed", text), ("unreadable", text).
#include <pybind11/iostream.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/fuzzing/fuzz_program.hpp"
#include "python/bindings.hpp"
#include "python/numpy_arrays.hpp"

namespace exactmesh::python {

namespace gen = exactmesh::generators;
using namespace pybind11::literals;

namespace {

gen::FuzzKind fuzz_kind_from_name(const std::string& name) {
    if (name == "points2d") return gen::FuzzKind::Points2d;
    if (name == "pslg") return gen::FuzzKind::Pslg;
    if (name == "points3d") return gen::FuzzKind::Points3d;
    throw InputError("kind: '" + name +
                     "' is not one of the known kinds: points2d, pslg, points3d");
}

/// The input's points as a fresh (n, 2|3) float64 array and its segments as a fresh (m, 2)
/// int64 array: the callable may change them without changing the driver's copy.
py::tuple input_arrays(const gen::FuzzInput& input) {
    const auto dimension = static_cast<py::ssize_t>(input.dimension());
    std::vector<double> points = input.coordinates;
    std::vector<std::int64_t> segments(input.segments.begin(), input.segments.end());
    return py::make_tuple(to_numpy(std::move(points), dimension), to_numpy(std::move(segments), 2));
}

/// Indices from the adapter's int64 array (already checked non-negative there), or why not.
std::optional<std::string> read_indices(const py::handle& object, std::vector<std::uint32_t>& out) {
    const auto array = py::cast<IndexArray>(object);
    const std::int64_t* data = array.data();
    out.resize(static_cast<std::size_t>(array.size()));
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (data[i] < 0 || data[i] > std::int64_t{UINT32_MAX})
            return "index " + std::to_string(data[i]) + " is not a vertex number";
        out[i] = static_cast<std::uint32_t>(data[i]);
    }
    return std::nullopt;
}

/// The adapter's answer as the driver's ProgramOutput. Needs the GIL.
gen::ProgramOutput program_output(const py::object& answer, bool oriented) {
    gen::ProgramOutput output;
    output.first_vertex = 0;  // Python numbers from 0
    output.first_cell = 0;
    output.oriented = oriented;
    const auto parts = py::cast<py::tuple>(answer);
    const auto status = py::cast<std::string>(parts[0]);
    if (status == "crashed") {
        output.status = gen::RunStatus::Crashed;
        output.message = py::cast<std::string>(parts[1]);
        return output;
    }
    if (status == "unreadable") {
        output.readable = false;
        output.message = py::cast<std::string>(parts[1]);
        return output;
    }
    if (!parts[1].is_none()) {
        const auto points = py::cast<CoordinateArray>(parts[1]);
        output.points.assign(points.data(), points.data() + points.size());
    }
    std::optional<std::string> problem = read_indices(parts[2], output.cells);
    if (!problem && !parts[3].is_none()) problem = read_indices(parts[3], output.pieces);
    if (problem) {
        output.readable = false;
        output.message = *problem;
    }
    return output;
}

void add_input(const gen::FuzzInput& input, const std::string& prefix, py::dict& into) {
    const py::tuple arrays = input_arrays(input);
    into[py::str(prefix + "points")] = arrays[0];
    into[py::str(prefix + "segments")] = arrays[1];
}

py::dict failure_dict(const gen::ProgramFuzzFailure& failure) {
    py::dict d(
        "seed"_a = failure.input.seed, "distribution"_a = failure.input.distribution,
        "verdict"_a = std::string(gen::verdict_name(failure.judgement.verdict)),
        "judgement"_a = failure.judgement.detail,
        "minimized_verdict"_a = std::string(gen::verdict_name(failure.minimized_judgement.verdict)),
        "minimized_judgement"_a = failure.minimized_judgement.detail,
        "minimized"_a = failure.minimized_run, "complete"_a = failure.complete,
        "evaluations"_a = failure.evaluations);
    add_input(failure.input, "", d);
    add_input(failure.minimized, "minimized_", d);
    return d;
}

py::dict fuzz(const py::object& adapter, const std::string& kind, std::uint64_t count,
              std::uint64_t seed, std::uint32_t max_points, bool conforming, bool convex_hull,
              bool oriented, double minimize_seconds, std::uint64_t max_minimized, bool quiet) {
    gen::ProgramFuzzOptions options;
    options.kind = fuzz_kind_from_name(kind);
    if ((conforming || convex_hull) && options.kind != gen::FuzzKind::Pslg)
        throw InputError("conforming and convex_hull apply to kind='pslg' only");
    if (max_points < 4) throw InputError("max_points: at least 4");
    if (!(minimize_seconds >= 0) || minimize_seconds > 1e6)
        throw InputError("minimize_seconds: a number of seconds in [0, 1e6]");
    options.count = count;
    options.seed = seed;
    options.max_points = max_points;
    options.pslg_check =
        conforming ? gen::PslgCheck::Conforming : gen::PslgCheck::ConstrainedDelaunay;
    options.convex_hull = convex_hull;
    options.minimize_budget = std::chrono::milliseconds(std::llround(minimize_seconds * 1000));
    options.max_minimized = max_minimized;
    options.quiet = quiet;

    // The driver runs without the GIL; each call of the callable takes it back. An exception
    // the adapter lets through (KeyboardInterrupt, SystemExit) ends the run and reaches Python.
    const gen::ProgramUnderTest program = [&adapter, oriented](const gen::FuzzInput& input) {
        py::gil_scoped_acquire hold;
        const py::tuple arrays = input_arrays(input);
        return program_output(adapter(arrays[0], arrays[1]), oriented);
    };
    std::vector<gen::ProgramFuzzFailure> failures;
    gen::ProgramFuzzSummary summary;
    {
        // Progress lines go to Python's sys.stderr (flushed under the GIL by pybind11).
        std::optional<py::scoped_estream_redirect> to_python;
        if (!quiet) to_python.emplace();
        py::gil_scoped_release release;
        summary = gen::fuzz_program(
            program, options,
            [&failures](const gen::ProgramFuzzFailure& failure) { failures.push_back(failure); },
            std::cerr);
    }
    py::dict per_distribution;
    for (const auto& [name, tally] : summary.per_distribution)
        per_distribution[py::str(name)] = py::make_tuple(tally[0], tally[1]);
    py::list failure_list;
    for (const gen::ProgramFuzzFailure& failure : failures)
        failure_list.append(failure_dict(failure));
    return py::dict("run"_a = summary.run, "passed"_a = summary.passed,
                    "refused"_a = summary.refused, "failed"_a = summary.failed,
                    "crashed"_a = summary.crashed, "timed_out"_a = summary.timed_out,
                    "first_seed"_a = summary.first_seed, "last_seed"_a = summary.last_seed,
                    "seconds"_a = summary.seconds, "per_distribution"_a = per_distribution,
                    "failures"_a = failure_list);
}

}  // namespace

void bind_fuzzing(py::module_& m) {
    m.def("_fuzz", &fuzz, "adapter"_a, "kind"_a, "count"_a, "seed"_a, "max_points"_a,
          "conforming"_a, "convex_hull"_a, "oriented"_a, "minimize_seconds"_a, "max_minimized"_a,
          "quiet"_a);
}

}  // namespace exactmesh::python
