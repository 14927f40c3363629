// SPDX-License-Identifier: MIT
// One case of fuzz_adaptation_2d (issue 13), decoded and run once for the target and for the
// sanitizer-free smoke test that replays fixed seeds (tests/unit/generators/
// adaptation_2d_fuzz_cases_test.cpp): a PSLG (fuzz_pslg.hpp, kAdaptationHeader-byte header)
// meshed by Delaunay refinement of the registry at a uniform size, then 1 to 3 adaptation cycles
// of one method (insertion, h-refinement, steiner, remesh, local-remesh) following a field from a
// small family (a tanh front, a tanh ring, a linear and a constant field: the last two make the
// second-difference indicators degenerate), optionally a transient run with derefinement
// (insertion and h-refinement), and for h-refinement the refine-then-derefine identity.
//
// After every cycle and every derefinement pass the exact check of the method runs
// (check_adaptive_mesh_2d, Delaunay unless the mesh was moved or a method only promises a
// conforming mesh; check_h_refined_mesh_2d for h-refinement); a failed check, an exception other
// than the expected ones, or a budget overrun is a failure. Expected outcomes: InputError from
// the first mesh (nothing enclosed, collinear, non-finite, ...) and GeometryError from it (its
// Steiner budget, features finer than doubles resolve), exactly as fuzz_mesh_generators_2d; and
// from a cycle the InputErrors the methods document (kExpectedCycleInputErrors: a remeshing
// generator's refusal of the size field, tests/data/fuzz/
// adaptation_2d_remesh_boundary_size_refused.bin; global remeshing: its generator's refusals,
// e.g. the quadtree's leaf budget, but never a NaN size); any other is a failure. A
// GeometryError from a Steiner restart or remeshing cycle is expected when it is the generator's
// documented one (a piece too short to split in doubles); any other, and any from the other
// methods (which raise it only on a bug), is a failure.
//
// Parameter bytes (between the mode byte 0 and the segment count, byte kAdaptationHeader - 1):
//   1 method (% 5: insertion, h-refinement, steiner, remesh, local-remesh)
//   2 indicator (% 4, kAllEdgeIndicators)
//   3 threshold (% 8: 0, 0.25, 0.5, 1, 1.5, 2, 4, 16 times the mean)
//   4 cycles 1 + b % 3; transient (b / 3) % 2; smoothing sweeps (b / 6) % 3, movement sweeps
//     (b / 18) % 3 (insertion only)
//   5 field family b % 4 (front, ring, linear, constant); field transfer instead of sampling
//     (b / 4) % 2; steepness k = 2^((b / 8) % 12)
//   6, 7, 8 the field's a, b in [-2, 2) ((byte - 128) / 64) and c in [0, 2) (byte / 128), in
//     coordinates u, v of the bounding box mapped to [0, 1] (so every scale sees the same field)
//   9 first mesh size 2^-(b % 5) times the bounding box's larger side; the remeshing generator
//     (b / 5) % 5 (registry order); local remeshing's factor 1.5, 2, 4 ((b / 25) % 3)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/adaptive_remeshing_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/h_adaptation_2d.hpp"
#include "generators/adaptation/h_refinement_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/adaptation/vertex_field.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"

namespace exactmesh::fuzz {

inline constexpr std::size_t kAdaptationHeader = 11;
inline constexpr std::size_t kAdaptationMaxPoints = 24;

enum class AdaptationMethod { Insertion, HRefinement, Steiner, Remesh, LocalRemesh };
inline constexpr const char* kAdaptationMethodNames[] = {"insertion", "h-refinement", "steiner",
                                                         "remesh", "local-remesh"};
enum class FieldFamily { Front, Ring, Linear, Constant };
inline constexpr const char* kFieldFamilyNames[] = {"front", "ring", "linear", "constant"};

/// The limits that keep a case fast (the target's defaults; the smoke test uses the same).
struct AdaptationLimits {
    std::uint64_t initial_steiner_points = 1000;  ///< the first mesh's Steiner budget
    std::uint64_t max_vertices = 4000;            ///< the adaptation's vertex budget
    int derefine_all_limit = 64;                  ///< derefine() calls for the identity
};

struct AdaptationCase {
    FuzzPslg input;
    AdaptationMethod method = AdaptationMethod::Insertion;
    generators::EdgeIndicator indicator = generators::EdgeIndicator::SecondDifference;
    double threshold = 1;
    std::uint32_t cycles = 1;
    bool transient = false;
    std::uint32_t smoothing = 0, movement = 0;
    FieldFamily family = FieldFamily::Front;
    bool transfer = false;  ///< cycles transfer the field instead of sampling it
    double k = 1, a = 0, b = 0, c = 0;
    int size_exponent = 0;
    std::size_t remesh_generator = 0;
    double local_factor = 2;
    // The bounding box, as the field's u = (x - x0) / w, v = (y - y0) / w in halves (no overflow).
    double x0 = 0, y0 = 0, half_w = 0;
};

/// The case in data, or nothing when the bytes decode to no PSLG with a vertex.
inline std::optional<AdaptationCase> decode_adaptation_case(const std::uint8_t* data,
                                                            std::size_t size) {
    std::optional<FuzzPslg> input =
        decode_pslg(data, size, kAdaptationHeader, kAdaptationMaxPoints);
    if (!input || input->xy.empty()) return std::nullopt;
    static constexpr double kThresholds[] = {0, 0.25, 0.5, 1, 1.5, 2, 4, 16};
    static constexpr double kFactors[] = {1.5, 2, 4};
    AdaptationCase c;
    c.input = std::move(*input);
    c.method = static_cast<AdaptationMethod>(data[1] % 5);
    c.indicator = generators::kAllEdgeIndicators[data[2] % 4];
    c.threshold = kThresholds[data[3] % 8];
    c.cycles = 1 + data[4] % 3;
    c.transient = (data[4] / 3) % 2 != 0;
    c.smoothing = (data[4] / 6) % 3;
    c.movement = (data[4] / 18) % 3;
    c.family = static_cast<FieldFamily>(data[5] % 4);
    c.transfer = (data[5] / 4) % 2 != 0;
    c.k = std::ldexp(1.0, (data[5] / 8) % 12);
    c.a = (data[6] - 128) / 64.0;
    c.b = (data[7] - 128) / 64.0;
    c.c = data[8] / 128.0;
    c.size_exponent = data[9] % 5;
    c.remesh_generator = (data[9] / 5) % 5;
    c.local_factor = kFactors[(data[9] / 25) % 3];
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    const std::vector<double>& xy = c.input.xy;
    for (std::size_t i = 0; i < xy.size() / 2; ++i) {
        x0 = std::min(x0, xy[2 * i]), x1 = std::max(x1, xy[2 * i]);
        y0 = std::min(y0, xy[2 * i + 1]), y1 = std::max(y1, xy[2 * i + 1]);
    }
    c.x0 = x0, c.y0 = y0;
    c.half_w = std::max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2);
    return c;
}

/// The case's field at time t (the front and the ring move with t).
inline generators::AnalyticField adaptation_case_field(const AdaptationCase& c) {
    const double half_w = std::isfinite(c.half_w) && c.half_w > 0 ? c.half_w : 1.0;
    return {kFieldFamilyNames[static_cast<int>(c.family)],
            [c, half_w](double x, double y, double, double t) {
                const double u = (x / 2 - c.x0 / 2) / half_w, v = (y / 2 - c.y0 / 2) / half_w;
                switch (c.family) {
                    case FieldFamily::Front:
                        return std::tanh(c.k * (c.a * u + c.b * v - c.c - 0.25 * t));
                    case FieldFamily::Ring: {
                        const double du = u - 0.5 - c.a / 4, dv = v - 0.5 - c.b / 4;
                        const double r = c.c / 4 + 0.1 * t;
                        return std::tanh(c.k * (du * du + dv * dv - r * r));
                    }
                    case FieldFamily::Linear:
                        return c.a * u + c.b * v + c.c;
                    case FieldFamily::Constant:
                        return c.c;
                }
                return 0.0;
            }};
}

/// The InputErrors a cycle of any method may end in (documented by the methods): a generator's
/// boundary discretization refusing a size graded over dozens of orders of magnitude. Global
/// remeshing may also end in any refusal of its generator except one about a NaN or zero size.
inline constexpr const char* kExpectedCycleInputErrors[] = {
    "boundary discretization: the size function asks for more than 2^30 pieces"};

/// Texts of an InputError that blames the size (NaN, 0), never expected from a cycle.
inline constexpr const char* kSizeFaults[] = {"NaN", "not > 0", "> 0 everywhere"};

/// What a case ended in: `problem` empty unless it failed (the target traps then).
struct AdaptationOutcome {
    bool meshed = false;  ///< the first mesh was made (else an expected InputError/GeometryError)
    std::string expected_error;         ///< that error's text
    bool cycle_input_error = false;     ///< an InputError ended the cycles (after the first mesh)
    bool cycle_geometry_error = false;  ///< a generator's GeometryError ended them
    std::uint32_t cycles_run = 0, derefinement_passes = 0;
    std::uint32_t final_vertices = 0;
    /// Global remeshing's budget counters (RemeshCounters2::budget_reruns, budget_refusals).
    std::uint64_t remesh_budget_reruns = 0, remesh_budget_refusals = 0;
    std::string problem;
};

namespace adaptation_case_detail {

inline bool same_triangulation(const triangulation::Triangulation2& a,
                               const triangulation::Triangulation2& b, std::string& what) {
    if (a.xy != b.xy)
        what = "xy";
    else if (a.triangles != b.triangles)
        what = "triangles";
    else if (a.neighbors != b.neighbors)
        what = "neighbors";
    else if (a.constrained != b.constrained)
        what = "constrained";
    else
        return true;
    return false;
}

}  // namespace adaptation_case_detail

/// Runs the case: the first mesh, the cycles (or transient steps) with their exact checks, the
/// h-refinement identity. Exceptions other than the expected ones become the outcome's problem.
inline AdaptationOutcome run_adaptation_case(const AdaptationCase& c,
                                             const AdaptationLimits& limits = {}) {
    namespace gen = generators;
    namespace tri = triangulation;
    AdaptationOutcome out;
    const gen::AnalyticField field = adaptation_case_field(c);
    const tri::Pslg pslg{c.input.xy, c.input.segments, {}, {}};
    gen::MeshRun2 initial;
    {
        gen::MeshOptions2 options;
        const double extent = 2 * c.half_w;
        const double size =
            std::ldexp(std::isfinite(extent) && extent > 0 ? extent : 1.0, -c.size_exponent);
        if (std::isfinite(size) && size > 0) options.size = gen::SizeFunction::uniform(size);
        options.max_steiner_points = limits.initial_steiner_points;
        try {
            initial = gen::find_mesh_generator_2d("delaunay-refinement").run(pslg, options);
        } catch (const InputError& e) {
            out.expected_error = e.what();
            return out;
        } catch (const GeometryError& e) {
            out.expected_error = e.what();
            return out;
        } catch (const std::exception& e) {
            out.problem = std::string("first mesh threw: ") + e.what();
            return out;
        }
    }
    out.meshed = true;
    std::string stage = "start";
    const auto at = [&](const char* what, std::uint32_t n) {
        stage = std::string(what) + " " + std::to_string(n);
    };
    try {
        gen::AdaptationOptions options;
        options.indicator = c.indicator;
        options.threshold = c.threshold;
        options.max_vertices = limits.max_vertices;
        const double dt = 1.0;
        gen::FieldSource source{c.transfer ? nullptr : &field, 0};
        const std::uint32_t steps = c.transient ? 2 : 0;
        if (c.method == AdaptationMethod::HRefinement) {
            const tri::Triangulation2 root = initial.mesh.mesh;
            gen::HAdaptiveMesh2 state{gen::HRefinedMesh2(root),
                                      gen::sample_field(field, root.xy, 2, 0)};
            gen::HAdaptationCounters2 counters;
            const auto check = [&]() {
                const tri::CheckReport report = gen::check_h_refined_mesh_2d(state.hierarchy);
                if (!report.ok) {
                    out.problem = stage + ": check_h_refined_mesh_2d: " + report.problem;
                    return false;
                }
                if (state.values.size() != state.hierarchy.leaf_mesh().vertex_count()) {
                    out.problem = stage + ": values and vertices differ in number";
                    return false;
                }
                if (state.hierarchy.leaf_mesh().vertex_count() >
                    std::max<std::uint64_t>(limits.max_vertices, root.vertex_count())) {
                    out.problem = stage + ": over the vertex budget";
                    return false;
                }
                return true;
            };
            const auto refine = [&](double t) {
                source.t = t;
                const bool changed = gen::h_refinement_cycle_2d(state, options, source, counters);
                ++out.cycles_run;
                return changed;
            };
            if (steps == 0) {
                for (std::uint32_t k = 1; k <= c.cycles; ++k) {
                    at("cycle", k);
                    const bool changed = refine(0);
                    if (!check()) return out;
                    if (!changed) break;
                }
            } else {
                options.reference_mean = gen::mean_indicator(
                    gen::mesh_edge_indicator(options.indicator, root.xy, 2, root.triangles,
                                             gen::mesh_edges_2d(root.triangles), state.values));
                for (std::uint32_t step = 1; step <= steps; ++step) {
                    const double t = step * dt;
                    source.t = t;
                    state.values = gen::sample_field(field, state.hierarchy.leaf_mesh().xy, 2, t);
                    for (std::uint32_t pass = 1; pass <= 8; ++pass) {
                        at("step derefinement pass", step * 100 + pass);
                        const std::uint64_t removed =
                            gen::h_derefinement_pass_2d(state, options.indicator, 0.2,
                                                        options.reference_mean, source, counters);
                        ++out.derefinement_passes;
                        if (!check()) return out;
                        if (removed == 0) break;
                    }
                    for (std::uint32_t k = 1; k <= c.cycles; ++k) {
                        at("step cycle", step * 100 + k);
                        const bool changed = refine(t);
                        if (!check()) return out;
                        if (!changed) break;
                    }
                }
            }
            out.final_vertices = state.hierarchy.leaf_mesh().vertex_count();
            // Refine-then-derefine: coarsening every leaf until nothing changes gives the root
            // back, array for array.
            std::vector<tri::TriIdx> all;
            bool settled = false;
            for (int i = 0; i < limits.derefine_all_limit && !settled; ++i) {
                at("derefine everything", static_cast<std::uint32_t>(i));
                const std::uint32_t before = state.hierarchy.leaf_mesh().triangle_count();
                all.resize(before);
                for (std::uint32_t t = 0; t < before; ++t) all[t] = t;
                (void)state.hierarchy.derefine(all);
                const tri::CheckReport report = gen::check_h_refined_mesh_2d(state.hierarchy);
                if (!report.ok) {
                    out.problem = stage + ": check_h_refined_mesh_2d: " + report.problem;
                    return out;
                }
                settled = state.hierarchy.leaf_mesh().triangle_count() == before;
            }
            if (!settled) {
                out.problem = "derefine everything: still changing after " +
                              std::to_string(limits.derefine_all_limit) + " calls";
                return out;
            }
            std::string what;
            if (!adaptation_case_detail::same_triangulation(state.hierarchy.leaf_mesh(), root,
                                                            what))
                out.problem =
                    "derefine everything: the leaf mesh's " + what + " differ from the root's";
            return out;
        }

        // The other methods share AdaptiveMesh2.
        gen::AdaptiveMesh2 state = gen::make_adaptive_mesh_2d(std::move(initial.mesh), c.input.xy,
                                                              c.input.segments, {}, {}, {});
        state.values = gen::sample_field(field, state.mesh.xy, 2, 0);
        const auto generators = gen::mesh_generators_2d();
        const gen::MeshGenerator2& remesher = generators[c.remesh_generator % generators.size()];
        const gen::RemeshDomain2 domain{pslg, {}, {}};
        const bool insertion = c.method == AdaptationMethod::Insertion;
        if (insertion) {
            options.smoothing_sweeps = c.smoothing;
            options.movement_sweeps = c.movement;
        }
        const bool delaunay = !(insertion && c.movement > 0) &&
                              c.method != AdaptationMethod::LocalRemesh &&
                              (c.method != AdaptationMethod::Remesh || remesher.delaunay);
        gen::InsertionCounters2 insertion_counters;
        gen::SteinerRestartCounters2 steiner;
        gen::RemeshCounters2 remesh;
        gen::LocalRemeshCounters2 local;
        gen::DerefinementCounters2 derefinement;
        const std::uint64_t start_vertices = state.mesh.vertex_count();
        const auto check = [&]() {
            const std::string problem = gen::check_adaptive_mesh_2d(state, c.input.xy, delaunay);
            if (!problem.empty()) {
                out.problem = stage + ": check_adaptive_mesh_2d: " + problem;
                return false;
            }
            if (state.values.size() != state.mesh.vertex_count()) {
                out.problem = stage + ": values and vertices differ in number";
                return false;
            }
            if (state.mesh.vertex_count() > std::max(limits.max_vertices, start_vertices)) {
                out.problem = stage + ": over the vertex budget";
                return false;
            }
            return true;
        };
        const auto refine = [&](double t) {
            source.t = t;
            ++out.cycles_run;
            switch (c.method) {
                case AdaptationMethod::Insertion:
                    return gen::insertion_cycle_2d(state, options, source, insertion_counters);
                case AdaptationMethod::Steiner:
                    return gen::steiner_restart_cycle_2d(state, options, source, steiner);
                case AdaptationMethod::Remesh: {
                    const bool changed =
                        gen::remesh_cycle_2d(state, domain, remesher, options, source, remesh);
                    out.remesh_budget_reruns = remesh.budget_reruns;
                    out.remesh_budget_refusals = remesh.budget_refusals;
                    return changed;
                }
                case AdaptationMethod::LocalRemesh:
                    return gen::local_remesh_cycle_2d(state, options, source, local,
                                                      c.local_factor);
                case AdaptationMethod::HRefinement:
                    break;
            }
            return false;
        };
        if (!c.transient || !insertion) {
            for (std::uint32_t k = 1; k <= c.cycles; ++k) {
                at("cycle", k);
                const bool changed = refine(0);
                if (!check()) return out;
                if (!changed) break;
            }
        } else {
            options.reference_mean = gen::mean_indicator(
                gen::mesh_edge_indicator(options.indicator, state.mesh.xy, 2, state.mesh.triangles,
                                         gen::mesh_edges_2d(state.mesh.triangles), state.values));
            const gen::DerefinementOptions derefine{options.indicator, 0.2, options.reference_mean};
            for (std::uint32_t step = 1; step <= steps; ++step) {
                const double t = step * dt;
                source.t = t;
                state.values = gen::sample_field(field, state.mesh.xy, 2, t);
                for (std::uint32_t pass = 1; pass <= 8; ++pass) {
                    at("step derefinement pass", step * 100 + pass);
                    const std::uint64_t removed =
                        gen::derefinement_pass_2d(state, derefine, derefinement);
                    ++out.derefinement_passes;
                    // Removal keeps a constrained Delaunay mesh so (a moved one: valid).
                    if (!check()) return out;
                    if (removed == 0) break;
                }
                for (std::uint32_t k = 1; k <= c.cycles; ++k) {
                    at("step cycle", step * 100 + k);
                    const bool changed = refine(t);
                    if (!check()) return out;
                    if (!changed) break;
                }
            }
        }
        out.final_vertices = state.mesh.vertex_count();
    } catch (const InputError& e) {
        // The size is the adaptation's own, the field finite: only the refusals the methods
        // document are expected (kExpectedCycleInputErrors); any other InputError blames the
        // user for the library's doing (as "the size function is NaN" did, a background sliver).
        const std::string what = e.what();
        // Global remeshing passes on its generator's refusals (a quadtree's leaf budget on
        // features far finer than the size, ...), as `exactmesh mesh` would give them; a size
        // that is NaN or not > 0 is never the domain's (the size is the adaptation's own).
        bool documented = c.method == AdaptationMethod::Remesh;
        for (const char* text : kSizeFaults)
            documented = documented && what.find(text) == std::string::npos;
        for (const char* text : kExpectedCycleInputErrors)
            documented = documented || what.find(text) != std::string::npos;
        if (documented) {
            out.expected_error = stage + ": " + e.what();
            out.cycle_input_error = true;
        } else {
            out.problem = stage + ": threw InputError: " + e.what();
        }
    } catch (const GeometryError& e) {
        // Steiner restart and global remeshing run a generator, whose documented GeometryError
        // (a piece too short to split in doubles: a graded size reaching features the first,
        // uniform mesh did not resolve) they pass on; one naming itself a bug is a failure, and
        // the other methods raise GeometryError only on a bug.
        const bool generator =
            c.method == AdaptationMethod::Steiner || c.method == AdaptationMethod::Remesh;
        if (generator && std::string(e.what()).find("a bug") == std::string::npos) {
            out.expected_error = stage + ": " + e.what();
            out.cycle_geometry_error = true;
        } else {
            out.problem = stage + ": threw: " + e.what();
        }
    } catch (const std::exception& e) {
        out.problem = stage + ": threw: " + e.what();
    }
    return out;
}

/// A one-line description of the case's parameters, for failure reports.
inline std::string describe_adaptation_case(const AdaptationCase& c) {
    std::string s = std::string("method ") + kAdaptationMethodNames[static_cast<int>(c.method)] +
                    ", indicator " + std::string(generators::edge_indicator_name(c.indicator)) +
                    ", threshold " + std::to_string(c.threshold) + ", cycles " +
                    std::to_string(c.cycles) + (c.transient ? ", transient" : "") + ", smoothing " +
                    std::to_string(c.smoothing) + ", movement " + std::to_string(c.movement) +
                    ", field " + kFieldFamilyNames[static_cast<int>(c.family)] +
                    (c.transfer ? " (transferred)" : " (sampled)") + " k " + std::to_string(c.k) +
                    " a " + std::to_string(c.a) + " b " + std::to_string(c.b) + " c " +
                    std::to_string(c.c) + ", size 2^-" + std::to_string(c.size_exponent) +
                    ", remesh generator " + std::to_string(c.remesh_generator) + ", local factor " +
                    std::to_string(c.local_factor);
    return s;
}

}  // namespace exactmesh::fuzz
