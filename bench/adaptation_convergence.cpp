// SPDX-License-Identifier: MIT
// The convergence study of issue 13 (Warren et al.'s comparison of indicators): for each test
// field (bench/adaptation_support.hpp: front, boundary-layer, singularity, smooth on the NACA
// 0012 domain), every indicator x every 2D method, the vertex count and the maximum and L2
// error of the piecewise-linear interpolant (interpolation_error.hpp) after each cycle; the
// uniform baseline (Delaunay refinement at uniform sizes); and the transient run (the front
// moving; insertion and h-refinement with derefinement, Steiner restart and global remeshing
// coarsening through their size field; the first mesh adapted at t = 0 by up to 10 cycles, as
// `exactmesh adapt --initial-cycles 10`), count and error per step. Writes one JSON file that
// scripts/adaptation_report.py reads.
//
// Usage: adaptation_convergence OUT.json [--budget N] [--cycles C] [--steps S] [--h0 H]
//   --budget   vertex budget of every adaptive run (max_vertices, default 40000; the transient
//              runs get 4 times as much: a safety net, not a cap they should reach)
//   --cycles   cycles per run at most (default 8); a run stops early when a cycle changes
//              nothing or the mesh is within 5% of the budget
//   --steps    transient steps (default 100, dt 0.02: the front moves by 2)
//   --h0       the initial mesh's uniform size (default 0.15), also the coarsest uniform mesh
// Seconds are wall time of the cycles alone (no error measurement), one thread.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "bench/adaptation_support.hpp"

namespace {

namespace ad = exactmesh::bench::adaptation;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

struct Settings {
    std::uint64_t budget = 40000;
    std::uint32_t cycles = 8;
    std::uint32_t steps = 100;
    double dt = 0.02;
    double h0 = 0.15;
    std::uint32_t transient_cycles = 3;  ///< refinement cycles per step (the CLI's default)
    std::uint32_t initial_cycles = 10;   ///< cycles adapting the first mesh at t = 0
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string number(double value) {
    if (!std::isfinite(value)) return "null";
    std::ostringstream out;
    out.precision(9);
    out << value;
    return out.str();
}

std::string quoted(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + '"';
}

/// One sample: {"vertices": .., "triangles": .., "max_error": .., "l2_error": .., "seconds": ..}
/// plus the leading fields given.
std::string sample(const std::string& lead, const tri::Triangulation2& mesh,
                   const std::vector<double>& values, const gen::AnalyticField& field, double t,
                   double seconds) {
    const gen::InterpolationError error = ad::mesh_error(mesh, values, field, t);
    return "{" + lead + "\"vertices\": " + std::to_string(mesh.vertex_count()) +
           ", \"triangles\": " + std::to_string(mesh.triangle_count()) +
           ", \"max_error\": " + number(error.maximum) + ", \"l2_error\": " + number(error.l2) +
           ", \"seconds\": " + number(seconds) + "}";
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) out += (i ? separator : "") + items[i];
    return out;
}

std::string adaptive_run(const Settings& s, std::string_view field_name,
                         gen::EdgeIndicator indicator, ad::Method method,
                         const gen::DomainPslg& domain, const tri::Cdt2Result& initial) {
    const gen::AnalyticField field = ad::field_by_name(field_name);
    gen::AdaptationOptions options;
    options.indicator = indicator;
    options.max_vertices = s.budget;
    std::vector<std::string> cycles;
    std::string problem;
    const auto start = std::chrono::steady_clock::now();
    try {
        ad::Adapter adapter(method, domain, initial, field, options);
        cycles.push_back(sample("\"cycle\": 0, ", adapter.mesh(), adapter.values(), field, 0, 0));
        double seconds = 0;
        for (std::uint32_t c = 1; c <= s.cycles; ++c) {
            const auto t0 = std::chrono::steady_clock::now();
            const bool changed = adapter.cycle(0);
            seconds += seconds_since(t0);
            if (!changed) break;
            cycles.push_back(sample("\"cycle\": " + std::to_string(c) + ", ", adapter.mesh(),
                                    adapter.values(), field, 0, seconds));
            if (static_cast<double>(adapter.mesh().vertex_count()) >=
                0.95 * static_cast<double>(s.budget))
                break;
        }
        // The exact check of the methods' meshes (the CLI's, outside every time).
        problem = adapter.check();
    } catch (const std::exception& error) {
        problem = error.what();
    }
    std::cerr << field_name << ' ' << gen::edge_indicator_name(indicator) << ' '
              << ad::method_name(method) << ": " << cycles.size() - 1 << " cycles, "
              << seconds_since(start) << " s" << (problem.empty() ? "" : " PROBLEM: " + problem)
              << '\n';
    return "{\"field\": " + quoted(field_name) +
           ", \"indicator\": " + quoted(gen::edge_indicator_name(indicator)) +
           ", \"method\": " + quoted(ad::method_name(method)) +
           ", \"problem\": " + quoted(problem) + ", \"cycles\": [\n    " + join(cycles, ",\n    ") +
           "]}";
}

std::string uniform_runs(const Settings& s) {
    std::vector<std::string> rows;
    // Sizes from h0 down by 2^(1/4) steps to about h0 / 8: vertex counts from about 2 10^3 to
    // 1.3 10^5, past every adaptive run's budget.
    for (int k = 0; k <= 12; ++k) {
        const double h = s.h0 * std::pow(2.0, -k / 4.0);
        const gen::DomainPslg domain = ad::naca_domain(h);
        const auto t0 = std::chrono::steady_clock::now();
        const tri::Cdt2Result mesh = ad::generate(domain, gen::SizeFunction::uniform(h));
        const double seconds = seconds_since(t0);
        for (const std::string_view name : ad::kFieldNames) {
            const gen::AnalyticField field = ad::field_by_name(name);
            const std::vector<double> values = gen::sample_field(field, mesh.mesh.xy, 2, 0);
            rows.push_back(sample("\"field\": " + quoted(name) + ", \"h\": " + number(h) + ", ",
                                  mesh.mesh, values, field, 0, seconds));
        }
        std::cerr << "uniform h " << h << ": " << mesh.mesh.vertex_count() << " vertices\n";
    }
    return "[\n  " + join(rows, ",\n  ") + "]";
}

std::string transient_run(const Settings& s, ad::Method method, const gen::DomainPslg& domain,
                          const tri::Cdt2Result& initial) {
    const gen::AnalyticField field = ad::moving_front();
    gen::AdaptationOptions options;
    options.max_vertices = 4 * s.budget;
    std::vector<std::string> steps;
    std::string problem;
    const auto start = std::chrono::steady_clock::now();
    try {
        ad::Adapter adapter(method, domain, initial, field, options, 0, true);
        for (std::uint32_t c = 0; c < s.initial_cycles; ++c)
            if (!adapter.cycle(0)) break;
        steps.push_back(
            sample("\"step\": 0, \"t\": 0, ", adapter.mesh(), adapter.values(), field, 0, 0));
        for (std::uint32_t k = 1; k <= s.steps; ++k) {
            const double t = k * s.dt;
            const auto t0 = std::chrono::steady_clock::now();
            adapter.step(t, s.transient_cycles);
            const double seconds = seconds_since(t0);
            steps.push_back(
                sample("\"step\": " + std::to_string(k) + ", \"t\": " + number(t) + ", ",
                       adapter.mesh(), adapter.values(), field, t, seconds));
        }
        problem = adapter.check();
    } catch (const std::exception& error) {
        problem = error.what();
    }
    std::cerr << "transient " << ad::method_name(method) << ": " << seconds_since(start) << " s"
              << (problem.empty() ? "" : " PROBLEM: " + problem) << '\n';
    return "{\"method\": " + quoted(ad::method_name(method)) +
           ", \"indicator\": \"second-difference\", \"derefine_fraction\": 0.1, "
           "\"cycles_per_step\": " +
           std::to_string(s.transient_cycles) + ", \"dt\": " + number(s.dt) +
           ", \"initial_cycles\": " + std::to_string(s.initial_cycles) +
           ", \"budget\": " + std::to_string(options.max_vertices) +
           ", \"problem\": " + quoted(problem) + ", \"steps\": [\n    " + join(steps, ",\n    ") +
           "]}";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: adaptation_convergence OUT.json [--budget N] [--cycles C] "
                     "[--steps S] [--h0 H]\n";
        return 2;
    }
    Settings s;
    for (int i = 2; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        const char* value = argv[i + 1];
        if (flag == "--budget")
            s.budget = std::strtoull(value, nullptr, 10);
        else if (flag == "--cycles")
            s.cycles = static_cast<std::uint32_t>(std::atoi(value));
        else if (flag == "--steps")
            s.steps = static_cast<std::uint32_t>(std::atoi(value));
        else if (flag == "--h0")
            s.h0 = std::strtod(value, nullptr);
        else {
            std::cerr << "unknown option " << flag << '\n';
            return 2;
        }
    }
    const gen::DomainPslg domain = ad::naca_domain(s.h0);
    const tri::Cdt2Result initial = ad::generate(domain, gen::SizeFunction::uniform(s.h0));
    std::vector<std::string> runs;
    for (const std::string_view field : ad::kFieldNames)
        for (const gen::EdgeIndicator indicator : gen::kAllEdgeIndicators)
            for (const auto& [method, name] : ad::methods())
                runs.push_back(adaptive_run(s, field, indicator, method, domain, initial));
    std::vector<std::string> fields;
    for (const std::string_view name : ad::kFieldNames)
        fields.push_back("{\"name\": " + quoted(name) +
                         ", \"formula\": " + quoted(ad::field_formula(name)) + "}");
    const std::string uniform = uniform_runs(s);
    std::vector<std::string> transient;
    for (const ad::Method method :
         {ad::Method::Insertion, ad::Method::HRefinement, ad::Method::Steiner, ad::Method::Remesh})
        transient.push_back(transient_run(s, method, domain, initial));
    std::ofstream out(argv[1]);
    out << "{\"domain\": \"naca0012\", \"generator\": " << quoted(ad::kGenerator)
        << ", \"h0\": " << number(s.h0) << ", \"budget\": " << s.budget
        << ", \"max_cycles\": " << s.cycles << ", \"threshold\": 1,\n \"fields\": ["
        << join(fields, ", ") << "],\n \"runs\": [\n  " << join(runs, ",\n  ")
        << "],\n \"uniform\": " << uniform << ",\n \"transient\": [\n  " << join(transient, ",\n  ")
        << "]}\n";
    if (!out) {
        std::cerr << "cannot write " << argv[1] << '\n';
        return 1;
    }
    return 0;
}
