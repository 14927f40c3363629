// SPDX-License-Identifier: MIT
// 2D mesh generation benchmarks: every generator of the registry
// (generators/mesh_2d/mesh_generators_2d) against CGAL's Delaunay_mesher_2 (with
// EXACTMESH_WITH_CGAL) and Gmsh's Delaunay and Frontal-Delaunay algorithms (the `gmsh` program,
// when found), same run, same domains, same size function [Ruppert95, Shewchuk02, Rebay93,
// Mavriplis97; DESIGN.md "Benchmarks and reports"; issues 6 and 11].
//
// Names: BM_mesh/<mesher>/<domain>/<angle>/<target triangles>; mesher is a registry name, `cgal`,
// `gmsh-delaunay`, `gmsh-frontal` or `delaunay-refinement-rounds-<T>t` (Delaunay refinement in
// rounds, RefinementOrder::Rounds, on T = 1 .. EXACTMESH_BENCH_MAX_THREADS threads, default the
// hardware's; wherever the 30-degree bound is, at 30p32 only, real time: its like-for-like
// row is delaunay-refinement's 30p32, the worst-first order on one thread). <angle> is the
// minimum-angle bound given, in like-for-like pairs of Delaunay refinement and CGAL:
//   delaunay-refinement  <t>        bound t, polish off (polish_angle 0)
//                        <t>p<P>    bound t, then its polish to P = min(t + 10, 32) (the default)
//   cgal                 <t>, <P>   CGAL's bound t or P (sin^2 of it is its shape bound)
// with t = 20.7 (the proven bound) at every target and t = 30 at 10^5 and 10^6 (and a quick
// target; 10^6 at 30 degrees is issue 17's measure of refinement throughput), so
// "ours <t> vs cgal <t>" compares the refinements and "ours <t>p<P> vs cgal <P>" the polished mesh
// with CGAL asked for the angle the polish aims at; `none` for meshers without an angle criterion.
// Domains: the built-in sample domains (generators/boundary/sample_domains), each with its own size
// function scaled by a constant so that Delaunay refinement (default options) makes about the
// target number of triangles (10^4, 10^5, 10^6; the largest is capped by
// EXACTMESH_MESH_BENCH_MAX_TRIANGLES, and a cap below 10^4 is the only target: a quick check of the
// pipeline). The boundary is discretized by that size once, outside the timed loop, and every
// mesher gets the same PSLG and size function:
//  - ours: the SizeFunction (Delaunay refinement keeps the size at each edge's midpoint per
//    half-edge while its triangles live);
//  - CGAL: Delaunay_mesh_size_criteria_2 when the size is uniform, else the same criteria with
//    the size function at edge midpoints, memoized per edge in the faces as ours
//    (bench/cgal_mesh_2d.hpp), so both pay the same for the size function;
//  - Gmsh: a .geo of the same points and segments; a uniform size through its mesh-size options
//    (Mesh.MeshSizeMin = Mesh.MeshSizeMax = h), a graded one as a background mesh (a .pos view of
//    the size at the vertices of a Delaunay refinement of the domain's bounding box at the size,
//    as a PostView background field: what `-bgm` and `Background Mesh View` set up), nothing
//    interpreted in the timed region (the view is read with the .geo; each size query is an
//    octree search in compiled code). EXACTMESH_MESH_BENCH_GMSH_SIZE=formula gives a graded size
//    as before instead (MathEval of the source formula over sampled Distance fields, interpreted
//    at every query), for comparison: on a busy 2-core machine the view was not cheaper for
//    Gmsh (naca0012 at 10^5: about 450-490 ms against 390-460 ms, uniform domains of the same
//    size about 410 ms). MeshSizeFromPoints, MeshSizeFromCurvature and
//    MeshSizeExtendFromBoundary are off in every case. The label says which, with the
//    background's triangle count and how closely its linear interpolation follows the size.
// Timed: ours and CGAL everything from the PSLG to the finished mesh, in process (CPU time; the
// previous iteration's mesh is destroyed with the timer paused, on both sides); Gmsh its own
// "Done meshing 2D" CPU time (file reading, 1D meshing of the segments and writing excluded),
// reported as manual time. Each repetition runs iterations for at least
// EXACTMESH_MESH_BENCH_MIN_TIME seconds (default 0.5: a 10^4 mesh takes 6-30 ms, one iteration
// is noise) and there are EXACTMESH_MESH_BENCH_REPETITIONS repetitions (default 5), reported
// individually (the report takes medians and the spread); run with
// --benchmark_enable_random_interleaving=true so that a burst of load spreads over all meshers.
//
// Counters: triangles, items_per_second (triangles per second), min_angle, mean_min_angle
// (mean of the triangles' smallest angles), max_size_ratio / median_size_ratio (edge length over
// the size at its midpoint), angle_hist_<k> (fraction of corners in [10k, 10k + 10) degrees),
// and the generator's own counters (steiner_points etc.), all of the last iteration's mesh.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/gmsh_peer.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include "bench/cgal_mesh_2d.hpp"
#endif

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using exactmesh::bench::gmsh_pslg_geo;
using exactmesh::bench::GmshMesh;
using exactmesh::bench::have_gmsh;
using exactmesh::bench::run_gmsh_geo;

struct Workload {
    gen::SizeFunction size;
    gen::DomainPslg pslg;
    tri::Pslg view() const { return {pslg.xy, pslg.segments, pslg.holes, {}}; }
};

/// The triangle count of Delaunay refinement of domain d with its own size function at 20.7
/// degrees: the calibration that maps a target count to a size factor.
double calibration(gen::SampleDomain d) {
    static std::map<int, double> cache;
    auto it = cache.find(static_cast<int>(d));
    if (it == cache.end()) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const gen::DomainPslg pslg = gen::sample_domain(d, size);
        gen::RefinementOptions2 options;
        options.size = size;
        const auto r =
            gen::delaunay_refinement_2d(tri::Pslg{pslg.xy, pslg.segments, pslg.holes, {}}, options);
        it = cache.emplace(static_cast<int>(d), static_cast<double>(r.mesh.mesh.triangle_count()))
                 .first;
    }
    return it->second;
}

const Workload& workload(gen::SampleDomain d, std::int64_t target) {
    static std::map<std::pair<int, std::int64_t>, Workload> cache;
    const auto key = std::make_pair(static_cast<int>(d), target);
    auto it = cache.find(key);
    if (it == cache.end()) {
        // Triangle count ~ 1 / size^2.
        const double factor = std::sqrt(calibration(d) / static_cast<double>(target));
        Workload w;
        w.size = gen::sample_domain_size(d).scaled(factor);
        w.pslg = gen::sample_domain(d, w.size);
        it = cache.emplace(key, std::move(w)).first;
    }
    return it->second;
}

void report_quality(benchmark::State& state, std::span<const double> xy,
                    std::span<const tri::VertIdx> triangles, const gen::SizeFunction& size) {
    const gen::QualityReport2 q = gen::quality_report_2d(xy, triangles, size);
    state.SetItemsProcessed(static_cast<std::int64_t>(q.triangles) * state.iterations());
    state.counters["triangles"] = static_cast<double>(q.triangles);
    state.counters["min_angle"] = q.min_angle;
    state.counters["mean_min_angle"] = q.mean_min_angle;
    state.counters["max_size_ratio"] = q.size_ratio_max;
    state.counters["median_size_ratio"] = q.size_ratio_median;
    std::uint64_t corners = 0;
    for (const std::uint64_t n : q.angle_histogram) corners += n;
    for (std::size_t k = 0; k < q.angle_histogram.size(); ++k) {
        state.counters["angle_hist_" + std::to_string(k)] =
            corners == 0 ? 0.0
                         : static_cast<double>(q.angle_histogram[k]) / static_cast<double>(corners);
    }
}

/// polish: Delaunay refinement's polish angle (0: off; ignored by the other generators);
/// threads > 0: Delaunay refinement in rounds on that many threads (RefinementOrder::Rounds).
void BM_mesh_generator(benchmark::State& state, const gen::MeshGenerator2* generator,
                       gen::SampleDomain d, double angle, double polish, unsigned threads) {
    const Workload& w = workload(d, state.range(0));
    gen::MeshOptions2 options;
    options.min_angle = angle;
    options.polish_angle = polish;
    options.size = w.size;
    if (threads > 0) {
        options.refinement_order = gen::RefinementOrder::Rounds;
        options.threads = threads;
    }
    gen::MeshRun2 run;
    for (auto _ : state) {
        gen::MeshRun2 next;
        try {
            next = generator->run(w.view(), options);
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        state.PauseTiming();
        run = std::move(next);  // frees the previous mesh untimed, as for CGAL
        state.ResumeTiming();
    }
    report_quality(state, run.mesh.mesh.xy, run.mesh.mesh.triangles, w.size);
    for (const auto& [name, value] : run.counters) {
        if (name == "steiner_points" || name == "points_inserted" || name == "new_points" ||
            name == "polish_points" || name == "rounds" || name == "round_conflicts") {
            state.counters[name] = static_cast<double>(value);
        }
    }
}

#if defined(EXACTMESH_WITH_CGAL)
void BM_mesh_cgal(benchmark::State& state, gen::SampleDomain d, double angle) {
    const Workload& w = workload(d, state.range(0));
    exactmesh::testing::CgalMesh last;
    for (auto _ : state) {
        auto mesh = exactmesh::testing::cgal_delaunay_mesh_2d(w.pslg.xy, w.pslg.segments,
                                                              w.pslg.holes, angle, w.size);
        state.PauseTiming();
        last = std::move(mesh);  // frees the previous mesh untimed
        state.ResumeTiming();
    }
    std::vector<std::uint32_t> pieces;
    const tri::Triangulation2 flat = exactmesh::testing::cgal_mesh_triangulation(last, pieces);
    report_quality(state, flat.xy, flat.triangles, w.size);
}
#endif

// ---- Gmsh as a process -------------------------------------------------------------------

/// The size function as interpreted Gmsh fields (EXACTMESH_MESH_BENCH_GMSH_SIZE=formula, for
/// comparison: what this bench gave Gmsh before issue 11): Distance fields to each source
/// (sampled, 4000 points per line), one MathEval of the source formula (each source times the
/// factor), Min with the cap times the factor, at most the ceiling of a scaled size. Returns the
/// background field's number, or 0 when the size is of a kind Gmsh cannot be given this way
/// (analytic).
int write_gmsh_size_field(std::ostream& geo, const gen::SizeFunction& size, int first_point,
                          int first_line) {
    char buffer[1024];
    const double f = size.factor();
    // The whole function is min(f * min(cap, sum), ceiling) = min(f * sum, top).
    const double top = std::min(f * size.cap(), size.ceiling());
    if (size.is_uniform()) {
        std::snprintf(buffer, sizeof buffer, "Field[1] = MathEval; Field[1].F = \"%.17g\";\n", top);
        geo << buffer << "Background Field = 1;\n";
        return 1;
    }
    if (!size.is_sources()) return 0;
    int field = 0, point = first_point, line = first_line;
    std::string sum;
    auto term = [&](int distance_field, double s, double radius, double exponent) {
        std::snprintf(buffer, sizeof buffer, "%s%.17g*(1+(F%d/%.17g)^%.17g)",
                      sum.empty() ? "" : "+", f * s, distance_field, radius, exponent);
        sum += buffer;
    };
    for (const gen::PointSource& p : size.point_sources()) {
        ++field;
        std::snprintf(
            buffer, sizeof buffer,
            "Point(%d) = {%.17g, %.17g, 0};\nField[%d] = Distance; Field[%d].PointsList = {%d};\n",
            point, p.x, p.y, field, field, point);
        geo << buffer;
        ++point;
        term(field, p.size, p.radius, p.exponent);
    }
    for (const gen::LineSource& l : size.line_sources()) {
        ++field;
        std::snprintf(
            buffer, sizeof buffer,
            "Point(%d) = {%.17g, %.17g, 0};\nPoint(%d) = {%.17g, %.17g, 0};\nLine(%d) = {%d, %d};\n"
            "Field[%d] = Distance; Field[%d].CurvesList = {%d}; Field[%d].NumPointsPerCurve = "
            "4000;\n",
            point, l.x0, l.y0, point + 1, l.x1, l.y1, line, point, point + 1, field, field, line,
            field);
        geo << buffer;
        point += 2;
        ++line;
        term(field, l.size, l.radius, l.exponent);
    }
    const int sources = ++field;
    geo << "Field[" << sources << "] = MathEval; Field[" << sources << "].F = \"" << sum << "\";\n";
    if (!std::isfinite(top)) {
        geo << "Background Field = " << sources << ";\n";
        return sources;
    }
    const int cap = ++field;
    std::snprintf(buffer, sizeof buffer, "Field[%d] = MathEval; Field[%d].F = \"%.17g\";\n", cap,
                  cap, top);
    geo << buffer;
    const int min = ++field;
    geo << "Field[" << min << "] = Min; Field[" << min << "].FieldsList = {" << sources << ", "
        << cap << "};\n"
        << "Background Field = " << min << ";\n";
    return min;
}

/// How Gmsh is given the size: .geo lines (after the surface) and a one-line description.
struct GmshSize {
    std::string geo;
    std::string label;
};

/// The size function as Gmsh input, outside its timed region: a uniform size by its mesh-size
/// options; any other as a background mesh, a .pos view (written into dir once per workload) of
/// the size at the vertices of our Delaunay refinement of the PSLG's bounding box (2% margin) at
/// the size itself: edges as long as the mesh's, so the view resolves the size as finely as the
/// mesh can. The label gives the largest relative error of linear interpolation between the
/// vertices, at the background's centroids and edge midpoints: a few percent, at the kink where
/// the sources meet the cap (min(cap, sources) is concave there, so the view is below the size,
/// never above it by more than the sources' own curvature allows).
/// EXACTMESH_MESH_BENCH_GMSH_SIZE=formula: the interpreted fields of write_gmsh_size_field.
const GmshSize& gmsh_size(const Workload& w, const fs::path& dir) {
    static std::map<const Workload*, GmshSize> cache;
    if (const auto it = cache.find(&w); it != cache.end()) return it->second;
    char buffer[512];
    GmshSize out;
    if (w.size.is_uniform()) {
        const double h = w.size(0, 0);
        std::snprintf(buffer, sizeof buffer,
                      "Mesh.MeshSizeMin = %.17g;\nMesh.MeshSizeMax = %.17g;\n", h, h);
        out.geo = buffer;
        out.label = "uniform: Mesh.MeshSizeMin = Mesh.MeshSizeMax";
        return cache.emplace(&w, std::move(out)).first->second;
    }
    if (const char* how = std::getenv("EXACTMESH_MESH_BENCH_GMSH_SIZE");
        how != nullptr && std::string(how) == "formula") {
        std::ostringstream geo;
        geo.precision(17);
        const auto n = static_cast<int>(w.pslg.xy.size() / 2);
        const auto m = static_cast<int>(w.pslg.segments.size() / 2);
        if (write_gmsh_size_field(geo, w.size, n + 1, m + 1) == 0) {
            throw std::runtime_error("this size function cannot be given to Gmsh as a formula");
        }
        out.geo = geo.str();
        out.label = "formula: MathEval of the source formula over sampled Distance fields";
        return cache.emplace(&w, std::move(out)).first->second;
    }
    const auto& xy = w.pslg.xy;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t v = 0; v + 1 < xy.size(); v += 2) {
        x0 = std::min(x0, xy[v]), x1 = std::max(x1, xy[v]);
        y0 = std::min(y0, xy[v + 1]), y1 = std::max(y1, xy[v + 1]);
    }
    const double margin = 0.02 * std::max(x1 - x0, y1 - y0);
    x0 -= margin, x1 += margin, y0 -= margin, y1 += margin;
    const std::vector<double> box{x0, y0, x1, y0, x1, y1, x0, y1};
    const std::vector<tri::VertIdx> sides{0, 1, 1, 2, 2, 3, 3, 0};
    gen::RefinementOptions2 options;
    options.size = w.size;
    options.polish_angle = 0;
    const tri::Triangulation2 bg =
        gen::delaunay_refinement_2d(tri::Pslg{box, sides, {}, {}}, options).mesh.mesh;
    std::vector<double> at(bg.xy.size() / 2);
    for (std::size_t v = 0; v < at.size(); ++v) at[v] = w.size(bg.xy[2 * v], bg.xy[2 * v + 1]);
    double worst = 0;
    auto check = [&](double x, double y, double interpolated) {
        const double s = w.size(x, y);
        worst = std::max(worst, std::abs(interpolated - s) / s);
    };
    for (std::size_t t = 0; t < bg.triangles.size(); t += 3) {
        const tri::VertIdx v[3] = {bg.triangles[t], bg.triangles[t + 1], bg.triangles[t + 2]};
        check((bg.xy[2 * v[0]] + bg.xy[2 * v[1]] + bg.xy[2 * v[2]]) / 3,
              (bg.xy[2 * v[0] + 1] + bg.xy[2 * v[1] + 1] + bg.xy[2 * v[2] + 1]) / 3,
              (at[v[0]] + at[v[1]] + at[v[2]]) / 3);
        for (int k = 0; k < 3; ++k) {
            const tri::VertIdx p = v[k], q = v[(k + 1) % 3];
            check(0.5 * (bg.xy[2 * p] + bg.xy[2 * q]), 0.5 * (bg.xy[2 * p + 1] + bg.xy[2 * q + 1]),
                  0.5 * (at[p] + at[q]));
        }
    }
    const fs::path pos = dir / ("size_" + std::to_string(cache.size()) + ".pos");
    std::ofstream file(pos);
    file << "View \"size\" {\n";
    for (std::size_t t = 0; t < bg.triangles.size(); t += 3) {
        const tri::VertIdx v[3] = {bg.triangles[t], bg.triangles[t + 1], bg.triangles[t + 2]};
        std::snprintf(buffer, sizeof buffer,
                      "ST(%.17g,%.17g,0,%.17g,%.17g,0,%.17g,%.17g,0){%.17g,%.17g,%.17g};\n",
                      bg.xy[2 * v[0]], bg.xy[2 * v[0] + 1], bg.xy[2 * v[1]], bg.xy[2 * v[1] + 1],
                      bg.xy[2 * v[2]], bg.xy[2 * v[2] + 1], at[v[0]], at[v[1]], at[v[2]]);
        file << buffer;
    }
    file << "};\n";
    if (!file) throw std::runtime_error("cannot write " + pos.string());
    out.geo = "Merge \"" + pos.string() +
              "\";\nField[1] = PostView;\nField[1].ViewIndex = 0;\n"
              "Background Field = 1;\n";
    std::snprintf(buffer, sizeof buffer,
                  "background mesh: .pos view of %zu triangles, interpolation within %.1f%% of "
                  "the size",
                  bg.triangles.size() / 3, 100 * worst);
    out.label = buffer;
    return cache.emplace(&w, std::move(out)).first->second;
}

/// A .geo of the workload's PSLG (bench/gmsh_peer.hpp) with the size as gmsh_size gives it.
std::string gmsh_geo(const Workload& w, const GmshSize& size, int algorithm) {
    std::string geo = gmsh_pslg_geo(w.pslg.xy, w.pslg.segments);
    geo += size.geo;
    geo +=
        "Mesh.MeshSizeExtendFromBoundary = 0;\nMesh.MeshSizeFromPoints = 0;\n"
        "Mesh.MeshSizeFromCurvature = 0;\nMesh.Algorithm = " +
        std::to_string(algorithm) + ";\n";
    return geo;
}

/// The directory of Gmsh's files (removed by main at the end).
const fs::path& gmsh_dir() {
    static const fs::path dir = [] {
        fs::path d =
            fs::temp_directory_path() / ("exactmesh_mesh_bench_" + std::to_string(getpid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}
bool gmsh_dir_used = false;

/// Runs `gmsh` on the workload (algorithm 5: Delaunay, 6: Frontal-Delaunay), one thread.
GmshMesh run_gmsh(const Workload& w, const GmshSize& size, int algorithm) {
    return run_gmsh_geo(gmsh_geo(w, size, algorithm), gmsh_dir());
}

void BM_mesh_gmsh(benchmark::State& state, int algorithm, gen::SampleDomain d) {
    const Workload& w = workload(d, state.range(0));
    GmshMesh mesh;
    gmsh_dir_used = true;
    const GmshSize* size = nullptr;
    try {
        size = &gmsh_size(w, gmsh_dir());
    } catch (const std::exception& error) {
        state.SkipWithError(error.what());
        return;
    }
    state.SetLabel("size: " + size->label);
    for (auto _ : state) {
        try {
            mesh = run_gmsh(w, *size, algorithm);
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        state.SetIterationTime(mesh.cpu_seconds);
    }
    report_quality(state, mesh.xy, mesh.triangles, w.size);
}

double env_number(const char* name, double fallback) {
    const char* text = std::getenv(name);
    return text ? std::atof(text) : fallback;
}

std::string angle_name(double angle) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", angle);
    return text;
}

/// Issue 11's plain input: a polygon of 10^4 vertices cos/sin(2 pi k / 10^4), meshed as
/// `exactmesh mesh circ.poly` does without --size: Delaunay refinement with none, the other
/// generators with the graded default (generators/boundary/graded_boundary_size_2d.hpp), built
/// inside the timed region as the command does. Name: BM_mesh/<mesher>/near-circle-10000/default.
void BM_mesh_near_circle(benchmark::State& state, const gen::MeshGenerator2* generator) {
    std::vector<double> xy;
    std::vector<std::uint32_t> segments;
    for (std::uint32_t k = 0; k < 10000; ++k) {
        const double t = 2 * 3.14159265358979323846 * k / 10000;
        xy.insert(xy.end(), {std::cos(t), std::sin(t)});
        segments.insert(segments.end(), {k, (k + 1) % 10000});
    }
    const tri::Pslg pslg{xy, segments, {}, {}};
    gen::MeshOptions2 options;
    gen::MeshRun2 run;
    for (auto _ : state) {
        // One domain triangulation for the default size and the generator, as the command
        // builds it (cli/mesh_command.cpp), not one for each.
        const gen::MeshDomain2 domain(pslg, options.cdt);
        if (generator->needs_size) options.size = gen::graded_size_from_boundary(domain);
        run = generator->run_on_domain(domain, options);
    }
    report_quality(state, run.mesh.mesh.xy, run.mesh.mesh.triangles, options.size);
}

void register_all() {
    const bool gmsh = have_gmsh();
    const auto max_triangles =
        static_cast<std::int64_t>(env_number("EXACTMESH_MESH_BENCH_MAX_TRIANGLES", 1e6));
    const double min_time = env_number("EXACTMESH_MESH_BENCH_MIN_TIME", 0.5);
    const int repetitions = static_cast<int>(env_number("EXACTMESH_MESH_BENCH_REPETITIONS", 5));
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const std::string domain(gen::sample_domain_name(d));
        // A cap below 10^4 is itself the only target (a quick check of the whole pipeline).
        std::vector<std::int64_t> targets;
        for (const std::int64_t target : {10000, 100000, 1000000}) {
            if (target <= max_triangles) targets.push_back(target);
        }
        if (targets.empty() && max_triangles > 0) targets.push_back(max_triangles);
        for (const std::int64_t target : targets) {
            auto configure = [&](benchmark::internal::Benchmark* b) {
                b->Arg(target)
                    ->MinTime(min_time)
                    ->Repetitions(repetitions)
                    ->ReportAggregatesOnly(false)
                    ->Unit(benchmark::kMillisecond);
                return b;
            };
            // The angle bounds of the like-for-like pairs (see the names above).
            std::vector<double> bounds{gen::kGuaranteedMinAngle};
            if (target == 100000 || target == 1000000 || target < 10000) bounds.push_back(30.0);
            for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
                // advancing-layers needs its --layers (without them it is frontal again).
                if (g.honours.contains(gen::MeshOption::Layers)) continue;
                const std::string prefix = "BM_mesh/" + std::string(g.name) + "/" + domain + "/";
                if (g.name != "delaunay-refinement") {
                    configure(benchmark::RegisterBenchmark((prefix + "none").c_str(),
                                                           BM_mesh_generator, &g, d,
                                                           gen::kGuaranteedMinAngle, -1.0, 0u));
                    continue;
                }
                for (const double angle : bounds) {
                    const double polish = std::min(gen::kMaxPolishAngle, angle + 10);
                    configure(benchmark::RegisterBenchmark((prefix + angle_name(angle)).c_str(),
                                                           BM_mesh_generator, &g, d, angle, 0.0,
                                                           0u));
                    configure(benchmark::RegisterBenchmark(
                        (prefix + angle_name(angle) + "p" + angle_name(polish)).c_str(),
                        BM_mesh_generator, &g, d, angle, polish, 0u));
                }
                // The rounds on 1 .. max_bench_threads() threads, beside the worst-first row of
                // the same bound and polish (issue 17's 30 degrees): real time.
                if (bounds.back() != 30.0) continue;
                const double polish = std::min(gen::kMaxPolishAngle, 30.0 + 10);
                for (unsigned threads = 1; threads <= exactmesh::bench::max_bench_threads();
                     ++threads) {
                    configure(benchmark::RegisterBenchmark(
                                  ("BM_mesh/delaunay-refinement-rounds-" + std::to_string(threads) +
                                   "t/" + domain + "/30p" + angle_name(polish))
                                      .c_str(),
                                  BM_mesh_generator, &g, d, 30.0, polish, threads))
                        ->UseRealTime();
                }
            }
#if defined(EXACTMESH_WITH_CGAL)
            for (const double angle : bounds) {
                const double polish = std::min(gen::kMaxPolishAngle, angle + 10);
                for (const double bound : {angle, polish}) {
                    const std::string name = "BM_mesh/cgal/" + domain + "/" + angle_name(bound);
                    configure(benchmark::RegisterBenchmark(name.c_str(), BM_mesh_cgal, d, bound));
                }
            }
#endif
            if (gmsh) {
                configure(
                    benchmark::RegisterBenchmark(
                        ("BM_mesh/gmsh-delaunay/" + domain + "/none").c_str(), BM_mesh_gmsh, 5, d))
                    ->UseManualTime();
                configure(
                    benchmark::RegisterBenchmark(
                        ("BM_mesh/gmsh-frontal/" + domain + "/none").c_str(), BM_mesh_gmsh, 6, d))
                    ->UseManualTime();
            }
        }
    }
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        if (g.honours.contains(gen::MeshOption::Layers)) continue;
        benchmark::RegisterBenchmark(
            ("BM_mesh/" + std::string(g.name) + "/near-circle-10000/default").c_str(),
            BM_mesh_near_circle, &g)
            ->MinTime(min_time)
            ->Repetitions(repetitions)
            ->ReportAggregatesOnly(false)
            ->Unit(benchmark::kMillisecond);
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_all();
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    exactmesh::bench::add_threads_context();
    const int status = exactmesh::bench::run_benchmarks(argc, argv);
    if (gmsh_dir_used) {
        std::error_code ignored;
        fs::remove_all(gmsh_dir(), ignored);
    }
    return status;
}
