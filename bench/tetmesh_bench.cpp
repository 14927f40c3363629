// SPDX-License-Identifier: MIT
// tetmesh_bench: 3D quality meshing of the sample domains (generators/boundary_3d: box-with-hole,
// ellipsoid, wing), exactmesh's boundary recovery + Delaunay refinement, frontal insertion and
// octree (generators/mesh_3d) against TetGen, CGAL's Mesh_3 and Gmsh's 3D Delaunay, each peer run
// as a process on the same PLC (issue 15). The bound: radius-edge 2 and a volume bound V, as
// `exactmesh tetmesh --radius-edge 2 --max-volume V`; V runs from 1e-2 down by factors of 4 to
// EXACTMESH_TETMESH_BENCH_MIN_VOLUME (default 1e-5) for box-with-hole (volume 0.875) and is scaled
// by each other domain's volume over the box's; with EXACTMESH_TETMESH_BENCH_MAX_TETS = M, only
// the coarsest bound of each domain and the finer ones where exactmesh's count (computed once,
// untimed, at registration; the wing's surface alone gives about 5 10^4) is at most M, a finer
// bound computed only while the growth of the last two predicts at most 2 M. Names
// BM_<mesher>/<domain>/<V>:
//   exactmesh          recovery + refinement (no sliver removal), no file I/O, timed by Google
//                      Benchmark (wall); its count at (domain, V) is the target count N below;
//   exactmesh_slivers  the same + sliver_removal_3d (B = 2, V kept), as `exactmesh tetmesh`;
//   exactmesh_frontal  recovery + frontal_delaunay_3d at a uniform size h + sliver removal, as
//                      `exactmesh tetmesh --generator frontal --size h`;
//   exactmesh_octree   recovery + octree_mesh_3d at h + sliver removal (--generator octree);
//   tetgen             `tetgen -pq2a<V>` on the PLC as a .poly: its "Total running seconds"
//                      minus "Output seconds" (CPU; includes its default mesh optimization);
//   tetgen_no_optimization  `tetgen -pq2a<V>O0`: the same without its optimization, the peer
//                      of the exactmesh row (refinement alone) as tetgen is of exactmesh_slivers;
//   cgal_mesh_3        bench/cgal_mesh_3d_tool.cpp on the same .poly: domain construction +
//                      make_mesh_3 (CPU), no Lloyd/ODT/perturb/exude; cell_radius_edge_ratio 2,
//                      cell_size s, facet_size = edge_size = cell_size, facet_angle 25,
//                      facet_distance cell_size / 10;
//   cgal_mesh_3_optimized  the same + perturb_mesh_3 + exude_mesh_3 (CGAL's defaults), timed too;
//   gmsh               the PLC as a .geo (plane surfaces, surface loops, a volume),
//                      Mesh.Algorithm3D = 1 (Delaunay), Mesh.MeshSizeMin = MeshSizeMax = s,
//                      Mesh.Optimize = 0: the CPU time of "Done meshing 3D" (its 2D surface
//                      meshing excluded, in counter gmsh_2d_cpu_seconds);
//   gmsh_optimized     Mesh.Optimize = 1 (Gmsh's default): 3D meshing + "Done optimizing mesh".
// Size matching. TetGen gets the same bound V (the "equal bounds"). The meshers that
// take a length instead (frontal and octree h, CGAL's cell_size, Gmsh's mesh size) get one matched
// per domain and V to the target count N, exactmesh's own count at (domain, V), so that the rows
// of a case have comparable counts: a first untimed run at s0 = g (domain volume / N)^(1/3) (g a
// per-mesher guess: a regular tetrahedron of edge h has volume h^3 / (6 sqrt 2), so g = 2 for an
// edge length), then s1 = s0 (N / n0)^(1/3) (the count falls about as s^-3), then a secant
// step in log-log from the two runs (the exponent clamped to [-6, -0.5]: a mesh held by its
// boundary hardly moves), at most three untimed runs, stopping once a count is within 15% of N;
// the timed runs use the size whose count came nearest. Once per (mesher, domain, V) and
// process (the optimized rows share their plain row's size); counters target_tets and
// tets_over_target show how near each row came. No constant is tuned on one domain.
// Peers are run with manual time; one that is not installed (tetgen, gmsh on PATH; cgal_mesh_3d
// beside this binary, built with EXACTMESH_WITH_CGAL) or that fails is a skip, not a failure.
// Counters, measured by the same code on every mesh (triangulation/checks/quality_3d): tets,
// tets_per_second (over the mean time of the iterations), min/max_dihedral_degrees,
// dihedrals_below_10 and dihedrals_below_20 (of the 6 #T angles) and their shares (_share: of the 6
// #T), slivers (below 5 degrees with radius-edge <= 2), max_radius_edge, radius_edge_over_2 and its
// share of #T, mean_volume_edge; with EXACTMESH_TETMESH_BENCH_HISTOGRAMS=1 also the histograms,
// counters dihedral_bin_<k> (10-degree bins, k = 0..17) and radius_edge_bin_<k> (0.2-wide bins, k =
// 0..19, then k = 20 for [4, inf)), for scripts/tetmesh_report.py; memory: peak_heap_bytes for
// exactmesh's rows (peak live heap of the construction, bench/heap_accounting.cpp) and
// peak_rss_bytes for a peer (its process's maximum resident set, measured by GNU time in
// bench_support's run_shell_command: everything the program holds, input and libraries
// included, so the two are not the same measure).
#include <benchmark/benchmark.h>
#include <unistd.h>  // getpid: a scratch directory per process

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/gmsh_peer.hpp"
#include "bench/heap_accounting.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_mesh_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "io/tetgen_format.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

/// The first guess g of each length-driven mesher's size parameter per (domain volume / N)^(1/3)
/// (N the target count; see the header): an edge length (frontal, octree, Gmsh) about 2, CGAL's
/// cell_size (a circumradius bound) less. Only the untimed first run uses them.
constexpr double kEdgeLengthGuess = 2.0;
constexpr double kGmshSizeGuess = 1.8;
constexpr double kCgalCellSizeGuess = 1.7;
/// Size matching: at most this many untimed runs, stopping when a count is within the tolerance
/// (relative) of the target; the timed runs use the size whose count came nearest.
constexpr int kMatchingRuns = 3;
constexpr double kMatchingTolerance = 0.15;

struct DomainCase {
    gen::SampleDomain3 domain;
    double volume;  ///< about: it only scales the volume bounds
};

constexpr double kBoxVolume = 0.875;
const DomainCase kDomains[] = {
    {gen::SampleDomain3::BoxWithHole, kBoxVolume},
    {gen::SampleDomain3::Ellipsoid, 4.0 / 3.0 * std::numbers::pi * 0.75 * 0.5},
    {gen::SampleDomain3::Wing, 16.0},  // the far-field box; the wing takes 0.08 of it
};

const tri::Plc3& plc_of(gen::SampleDomain3 domain) {
    static const tri::Plc3 plcs[] = {gen::sample_domain_3d(gen::SampleDomain3::BoxWithHole),
                                     gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid),
                                     gen::sample_domain_3d(gen::SampleDomain3::Wing)};
    return plcs[static_cast<int>(domain)];
}

/// Whether the histogram counters are wanted (EXACTMESH_TETMESH_BENCH_HISTOGRAMS=1).
bool histogram_counters() {
    static const bool wanted = [] {
        const char* text = std::getenv("EXACTMESH_TETMESH_BENCH_HISTOGRAMS");
        return text != nullptr && std::string(text) == "1";
    }();
    return wanted;
}

void set_quality_counters(benchmark::State& state, const tri::Tetrahedralization3& mesh,
                          double seconds) {
    const tri::QualityStats3 q = tri::quality_stats_3d(mesh);
    const auto tets = static_cast<double>(mesh.tet_count());
    state.counters["tets"] = tets;
    state.counters["tets_per_second"] = seconds > 0 ? tets / seconds : 0;
    state.counters["min_dihedral_degrees"] = q.min_dihedral_degrees;
    state.counters["max_dihedral_degrees"] = q.max_dihedral_degrees;
    // 10-degree bins (QualityOptions' default): bin 0 is [0, 10), bin 1 [10, 20).
    const auto bin = [&q](std::size_t k) {
        return k < q.dihedral_histogram.size() ? static_cast<double>(q.dihedral_histogram[k]) : 0;
    };
    const double angles = 6 * tets;
    state.counters["dihedrals_below_10"] = bin(0);
    state.counters["dihedrals_below_20"] = bin(0) + bin(1);
    state.counters["dihedrals_below_10_share"] = angles > 0 ? bin(0) / angles : 0;
    state.counters["dihedrals_below_20_share"] = angles > 0 ? (bin(0) + bin(1)) / angles : 0;
    state.counters["slivers"] = static_cast<double>(q.slivers);
    state.counters["max_radius_edge"] = q.max_radius_edge;
    state.counters["radius_edge_over_2"] = static_cast<double>(q.over_radius_edge_bound);
    state.counters["radius_edge_over_2_share"] =
        tets > 0 ? static_cast<double>(q.over_radius_edge_bound) / tets : 0;
    state.counters["mean_volume_edge"] = q.mean_volume_edge;
    if (histogram_counters()) {
        for (std::size_t k = 0; k < q.dihedral_histogram.size(); ++k)
            state.counters["dihedral_bin_" + std::to_string(k)] =
                static_cast<double>(q.dihedral_histogram[k]);
        for (std::size_t k = 0; k < q.radius_edge_histogram.size(); ++k)
            state.counters["radius_edge_bin_" + std::to_string(k)] =
                static_cast<double>(q.radius_edge_histogram[k]);
    }
}

tri::Tetrahedralization3 refine(const tri::Plc3& plc, double max_volume, bool remove_slivers) {
    gen::DelaunayRefinement3Options options;
    options.radius_edge_bound = 2.0;
    options.max_volume = max_volume;
    if (remove_slivers) {
        // As `exactmesh tetmesh` runs it: refinement hands its working mesh over.
        gen::SliverRemoval3Options sliver_options;
        sliver_options.radius_edge_bound = 2.0;
        sliver_options.max_volume = max_volume;
        options.sliver_removal = sliver_options;
    }
    return std::move(
        gen::delaunay_refinement_3d(plc, tri::boundary_recovery_3d(plc).mesh, options).mesh.mesh);
}

/// exactmesh's count at (domain, V) without sliver removal: the target of size matching,
/// remembered from the exactmesh row or computed once, untimed.
std::map<std::pair<int, double>, double>& target_cache() {
    static std::map<std::pair<int, double>, double> cache;
    return cache;
}

double target_tets(const DomainCase& domain, double max_volume) {
    const std::pair<int, double> key{static_cast<int>(domain.domain), max_volume};
    auto found = target_cache().find(key);
    if (found == target_cache().end()) {
        const double tets =
            static_cast<double>(refine(plc_of(domain.domain), max_volume, false).tet_count());
        found = target_cache().emplace(key, tets).first;
    }
    return found->second;
}

/// A size parameter s of `mesher` (a length: its count falls about as s^-3) matched to the
/// target count (the header's rule); `count_at(s)` runs the mesher once, untimed, and returns
/// its count (0: it failed, which ends the matching). Once per (mesher, domain, V) and process.
double matched_size(const std::string& mesher, const DomainCase& domain, double max_volume,
                    double guess, const std::function<double(double)>& count_at) {
    static std::map<std::tuple<std::string, int, double>, double> cache;
    const std::tuple<std::string, int, double> key{mesher, static_cast<int>(domain.domain),
                                                   max_volume};
    if (const auto found = cache.find(key); found != cache.end()) return found->second;
    const double target = target_tets(domain, max_volume);
    const double first = guess * std::cbrt(domain.volume / target);
    double size = first, best = first, best_miss = HUGE_VAL, last_size = 0, last_count = 0;
    for (int run = 0; run < kMatchingRuns; ++run) {
        const double count = count_at(size);
        if (!(count > 0)) break;
        const double miss = std::fabs(std::log(count / target));
        if (miss < best_miss) {
            best = size;
            best_miss = miss;
        }
        if (miss <= std::log(1 + kMatchingTolerance)) break;
        // The count's exponent in the size, from the last two runs (a boundary-dominated mesh
        // follows s^-2, a coarse one hardly moves), clamped; -3 from a single run.
        double exponent = -3;
        if (last_count > 0 && size != last_size && count != last_count)
            exponent =
                std::clamp(std::log(count / last_count) / std::log(size / last_size), -6.0, -0.5);
        last_size = size;
        last_count = count;
        size *= std::pow(target / count, 1 / exponent);
    }
    cache.emplace(key, best);
    return best;
}

void set_target_counters(benchmark::State& state, const DomainCase& domain, double max_volume,
                         double tets) {
    const double target = target_tets(domain, max_volume);
    state.counters["target_tets"] = target;
    state.counters["tets_over_target"] = target > 0 ? tets / target : 0;
}

/// The mean of `runs` iteration times (0 without one): tets_per_second's time.
double mean_seconds(double total, std::uint64_t runs) {
    return runs > 0 ? total / static_cast<double>(runs) : 0;
}

/// One timed in-process construction per iteration, its peak heap and quality counters.
void run_in_process(benchmark::State& state,
                    const std::function<tri::Tetrahedralization3()>& construct) {
    tri::Tetrahedralization3 last;
    double seconds = 0, peak_bytes = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        const std::size_t heap_before = exactmesh::bench::start_heap_measurement();
        const auto start = std::chrono::steady_clock::now();
        tri::Tetrahedralization3 mesh = construct();
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++runs;
        state.PauseTiming();
        peak_bytes = exactmesh::bench::heap_growth_since(heap_before);
        last = std::move(mesh);
        exactmesh::bench::after_construction();
        state.ResumeTiming();
    }
    set_quality_counters(state, last, runs > 0 ? seconds / static_cast<double>(runs) : 0);
    state.counters["peak_heap_bytes"] = peak_bytes;
}

void bm_exactmesh(benchmark::State& state, DomainCase domain, double max_volume,
                  bool remove_slivers) {
    const tri::Plc3& plc = plc_of(domain.domain);
    run_in_process(state, [&] { return refine(plc, max_volume, remove_slivers); });
    if (!remove_slivers) {
        target_cache()[{static_cast<int>(domain.domain), max_volume}] = state.counters["tets"];
    }
    set_target_counters(state, domain, max_volume, state.counters["tets"]);
}

enum class SizeGenerator { Frontal, Octree };

/// Recovery + frontal or octree at the uniform size h + sliver removal, as `exactmesh tetmesh
/// --generator frontal|octree --size h` runs them.
tri::Tetrahedralization3 size_driven(const tri::Plc3& plc, SizeGenerator generator, double h) {
    tri::ConformingMesh3 recovered = tri::boundary_recovery_3d(plc).mesh;
    tri::ConformingMesh3 meshed;
    if (generator == SizeGenerator::Frontal) {
        gen::FrontalDelaunay3Options options;
        options.size = gen::SizeFunction3::uniform(h);
        meshed = gen::frontal_delaunay_3d(plc, std::move(recovered), options).mesh;
    } else {
        gen::OctreeMesh3Options options;
        options.size = gen::SizeFunction3::uniform(h);
        meshed = gen::octree_mesh_3d(plc, recovered, options).mesh;
    }
    gen::SliverRemoval3Options sliver_options;
    sliver_options.radius_edge_bound = 2.0;
    return std::move(gen::sliver_removal_3d(std::move(meshed), sliver_options).mesh.mesh);
}

void bm_size_driven(benchmark::State& state, DomainCase domain, double max_volume,
                    SizeGenerator generator) {
    const tri::Plc3& plc = plc_of(domain.domain);
    const char* mesher = generator == SizeGenerator::Frontal ? "frontal" : "octree";
    double h = 0;
    try {
        h = matched_size(mesher, domain, max_volume, kEdgeLengthGuess, [&](double size) {
            return static_cast<double>(size_driven(plc, generator, size).tet_count());
        });
        run_in_process(state, [&] { return size_driven(plc, generator, h); });
    } catch (const std::exception& error) {
        state.SkipWithError((std::string(mesher) + ": " + error.what()).c_str());
        return;
    }
    set_target_counters(state, domain, max_volume, state.counters["tets"]);
    state.counters["size_h"] = h;
}

/// The PLC as a TetGen .poly (0-based points, one polygon per facet with its marker, volume
/// holes).
std::string poly_text(const tri::Plc3& plc) {
    std::ostringstream out;
    out.precision(17);
    out << plc.vertex_count() << " 3 0 0\n";
    for (std::uint32_t v = 0; v < plc.vertex_count(); ++v)
        out << v << ' ' << plc.point(v)[0] << ' ' << plc.point(v)[1] << ' ' << plc.point(v)[2]
            << '\n';
    out << plc.facets.size() << " 1\n";
    for (const tri::Facet3& facet : plc.facets) {
        out << facet.polygons.size() << ' ' << facet.holes.size() / 3 << ' ' << facet.marker
            << '\n';
        for (const auto& polygon : facet.polygons) {
            out << polygon.size();
            for (const auto corner : polygon) out << ' ' << corner;
            out << '\n';
        }
        for (std::size_t h = 0; h + 2 < facet.holes.size(); h += 3)
            out << h / 3 + 1 << ' ' << facet.holes[h] << ' ' << facet.holes[h + 1] << ' '
                << facet.holes[h + 2] << '\n';
    }
    out << plc.holes.size() / 3 << '\n';
    for (std::size_t h = 0; h + 2 < plc.holes.size(); h += 3)
        out << h / 3 + 1 << ' ' << plc.holes[h] << ' ' << plc.holes[h + 1] << ' '
            << plc.holes[h + 2] << '\n';
    out << "0\n";
    return out.str();
}

/// A scratch directory of this process for one case, removed when the case ends.
struct Scratch {
    fs::path dir;
    explicit Scratch(const std::string& name)
        : dir(fs::temp_directory_path() /
              ("exactmesh_tetmesh_bench_" + std::to_string(::getpid())) / name) {
        fs::create_directories(dir);
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(dir.parent_path(), ignored);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
};

bool on_path(const std::string& program) {
    return std::system(("command -v " + program + " > /dev/null 2>&1").c_str()) == 0;
}

/// The number after `label` on a line of a log, or NaN.
double log_seconds(const fs::path& log, const std::string& label) {
    std::ifstream text(log);
    std::string line;
    while (std::getline(text, line)) {
        const auto at = line.find(label);
        if (at == 0) return std::stod(line.substr(label.size()));
    }
    return std::nan("");
}

std::string number_text(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

/// Reads back a peer's .node/.ele (TetGen orientation in the files, exactmesh's in memory).
tri::Tetrahedralization3 read_node_ele(const fs::path& stem) {
    const auto nodes = exactmesh::io::read_tetgen_node(stem.string() + ".node");
    const auto ele = exactmesh::io::read_tetgen_ele(stem.string() + ".ele", nodes.first_index,
                                                    nodes.vertex_count());
    tri::Tetrahedralization3 mesh;
    mesh.xyz = nodes.xyz;
    mesh.tets = ele.tets;
    return mesh;
}

void bm_tetgen(benchmark::State& state, DomainCase domain, double max_volume, bool optimize) {
    if (!on_path("tetgen")) {
        state.SkipWithError("tetgen not found on PATH");
        return;
    }
    const Scratch scratch("tetgen");
    const fs::path poly = scratch.dir / "domain.poly", log = scratch.dir / "tetgen.log";
    std::ofstream(poly) << poly_text(plc_of(domain.domain));
    // No -Q: TetGen then prints its phase timings, which give the construction without I/O.
    const std::string command = "tetgen -pq2a" + number_text(max_volume) + (optimize ? "" : "O0") +
                                " '" + poly.string() + "' > '" + log.string() + "' 2>&1";
    double seconds = 0, rss = 0, total_seconds = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        const exactmesh::bench::ProcessRun run = exactmesh::bench::run_shell_command(command);
        if (!run.ok) {
            state.SkipWithError("tetgen failed");
            return;
        }
        rss = run.max_rss_bytes;
        const double total = log_seconds(log, "Total running seconds:");
        const double output = log_seconds(log, "Output seconds:");
        seconds = total - (std::isnan(output) ? 0.0 : output);
        state.SetIterationTime(seconds);
        total_seconds += seconds;
        ++runs;
    }
    const tri::Tetrahedralization3 mesh = read_node_ele(scratch.dir / "domain.1");
    set_quality_counters(state, mesh, mean_seconds(total_seconds, runs));
    set_target_counters(state, domain, max_volume, static_cast<double>(mesh.tet_count()));
    state.counters["peak_rss_bytes"] = rss;
}

/// cgal_mesh_3d beside this binary (bench/CMakeLists.txt builds it there), or empty.
fs::path cgal_tool() {
    std::error_code error;
    const fs::path self = fs::read_symlink("/proc/self/exe", error);
    if (error) return {};
    const fs::path tool = self.parent_path() / "cgal_mesh_3d";
    return fs::exists(tool) ? tool : fs::path{};
}

void bm_cgal_mesh_3(benchmark::State& state, DomainCase domain, double max_volume, bool optimize) {
    const fs::path tool = cgal_tool();
    if (tool.empty()) {
        state.SkipWithError("cgal_mesh_3d not built beside tetmesh_bench (EXACTMESH_WITH_CGAL)");
        return;
    }
    const Scratch scratch("cgal");
    const fs::path poly = scratch.dir / "domain.poly", log = scratch.dir / "cgal.log";
    std::ofstream(poly) << poly_text(plc_of(domain.domain));
    auto command = [&](double cell_size, bool with_optimization) {
        // Appended piece by piece: GCC 12's -Wrestrict misfires on "'" + std::string here.
        std::string text = "'";
        text += tool.string();
        text += "' '" + poly.string() + "' '" + (scratch.dir / "mesh").string();
        text += "' --radius-edge 2 --cell-size " + number_text(cell_size);
        if (with_optimization) text += " --optimize";
        text += " > '" + log.string() + "' 2>&1";
        return text;
    };
    // Matched without the optimization (it moves vertices, it does not refine): both rows use
    // the same cell_size.
    const double cell_size =
        matched_size("cgal_mesh_3", domain, max_volume, kCgalCellSizeGuess, [&](double size) {
            if (!exactmesh::bench::run_shell_command(command(size, false)).ok) return 0.0;
            return static_cast<double>(read_node_ele(scratch.dir / "mesh").tet_count());
        });
    double seconds = 0, rss = 0, domain_seconds = 0, optimize_seconds = 0, total_seconds = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        const exactmesh::bench::ProcessRun run =
            exactmesh::bench::run_shell_command(command(cell_size, optimize));
        if (!run.ok) {
            std::ifstream text(log);
            std::string line;
            std::getline(text, line);
            state.SkipWithError(("cgal_mesh_3d failed: " + line).c_str());
            return;
        }
        rss = run.max_rss_bytes;
        domain_seconds = log_seconds(log, "domain_seconds:");
        optimize_seconds =
            log_seconds(log, "perturb_seconds:") + log_seconds(log, "exude_seconds:");
        seconds = domain_seconds + log_seconds(log, "refine_seconds:") + optimize_seconds;
        state.SetIterationTime(seconds);
        total_seconds += seconds;
        ++runs;
    }
    const tri::Tetrahedralization3 mesh = read_node_ele(scratch.dir / "mesh");
    set_quality_counters(state, mesh, mean_seconds(total_seconds, runs));
    set_target_counters(state, domain, max_volume, static_cast<double>(mesh.tet_count()));
    state.counters["peak_rss_bytes"] = rss;
    state.counters["cgal_domain_seconds"] = domain_seconds;
    state.counters["cgal_optimize_seconds"] = optimize_seconds;
    state.counters["cgal_cell_size"] = cell_size;
}

void bm_gmsh(benchmark::State& state, DomainCase domain, double max_volume, bool optimize) {
    if (!exactmesh::bench::have_gmsh()) {
        state.SkipWithError("gmsh not found on PATH");
        return;
    }
    const Scratch scratch("gmsh");
    std::string plc_geo;
    try {
        plc_geo = exactmesh::bench::gmsh_plc_geo(plc_of(domain.domain));
    } catch (const std::exception& error) {
        state.SkipWithError(error.what());
        return;
    }
    auto geo = [&](double size, bool with_optimization) {
        return plc_geo + "Mesh.Algorithm3D = 1;\nMesh.MeshSizeMin = " + number_text(size) +
               ";\nMesh.MeshSizeMax = " + number_text(size) +
               ";\nMesh.MeshSizeFromCurvature = 0;\nMesh.Optimize = " +
               (with_optimization ? "1" : "0") + ";\n";
    };
    // Matched without Gmsh's optimization, which both rows then share.
    const double size = matched_size("gmsh", domain, max_volume, kGmshSizeGuess, [&](double h) {
        try {
            return static_cast<double>(
                exactmesh::bench::run_gmsh_geo_3d(geo(h, false), scratch.dir).mesh.tet_count());
        } catch (const std::exception&) {
            return 0.0;
        }
    });
    exactmesh::bench::GmshMesh3 last;
    double seconds = 0, total_seconds = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        try {
            last = exactmesh::bench::run_gmsh_geo_3d(geo(size, optimize), scratch.dir);
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        seconds = last.cpu_seconds_3d + (optimize ? last.cpu_seconds_optimize : 0.0);
        state.SetIterationTime(seconds);
        total_seconds += seconds;
        ++runs;
    }
    if (last.mesh.tet_count() == 0) {
        state.SkipWithError("gmsh wrote no tetrahedra");
        return;
    }
    set_quality_counters(state, last.mesh, mean_seconds(total_seconds, runs));
    set_target_counters(state, domain, max_volume, static_cast<double>(last.mesh.tet_count()));
    state.counters["peak_rss_bytes"] = last.max_rss_bytes;
    state.counters["gmsh_2d_cpu_seconds"] = last.cpu_seconds_2d;
    state.counters["gmsh_optimize_cpu_seconds"] = last.cpu_seconds_optimize;
    state.counters["gmsh_size"] = size;
}

/// A positive number from the environment, or `fallback` when unset.
double positive_from_environment(const char* name, double fallback) {
    const char* text = std::getenv(name);
    if (text == nullptr || *text == '\0') return fallback;
    const double value = std::strtod(text, nullptr);
    if (!(value > 0)) throw std::runtime_error(std::string(name) + " must be > 0");
    return value;
}

void register_all() {
    const double smallest = positive_from_environment("EXACTMESH_TETMESH_BENCH_MIN_VOLUME", 1e-5);
    const double most_tets = positive_from_environment("EXACTMESH_TETMESH_BENCH_MAX_TETS", 0);
    for (const DomainCase& domain : kDomains) {
        const std::string domain_name(gen::sample_domain_3d_name(domain.domain));
        double predicted = 0, last_tets = 0;
        for (double box_v = 1e-2; box_v >= smallest * (1 - 1e-9); box_v /= 4) {
            const double v = box_v * domain.volume / kBoxVolume;
            if (most_tets > 0) {
                if (predicted > 2 * most_tets) break;
                const double tets = target_tets(domain, v);
                if (tets > most_tets && last_tets > 0) break;  // the coarsest bound always runs
                predicted = tets * (last_tets > 0 ? std::clamp(tets / last_tets, 1.0, 8.0) : 4.0);
                last_tets = tets;
            }
            char bound[64];
            std::snprintf(bound, sizeof bound, "%.3g", v);
            auto name = [&](const char* mesher) {
                return std::string("BM_") + mesher + "/" + domain_name + "/" + bound;
            };
            benchmark::RegisterBenchmark(name("exactmesh").c_str(), &bm_exactmesh, domain, v, false)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(name("exactmesh_slivers").c_str(), &bm_exactmesh, domain,
                                         v, true)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(name("exactmesh_frontal").c_str(), &bm_size_driven, domain,
                                         v, SizeGenerator::Frontal)
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark(name("exactmesh_octree").c_str(), &bm_size_driven, domain,
                                         v, SizeGenerator::Octree)
                ->Unit(benchmark::kMillisecond);
            for (const bool optimize : {true, false}) {
                benchmark::RegisterBenchmark(
                    name(optimize ? "tetgen" : "tetgen_no_optimization").c_str(), &bm_tetgen,
                    domain, v, optimize)
                    ->Unit(benchmark::kMillisecond)
                    ->UseManualTime();
            }
            for (const bool optimize : {false, true}) {
                benchmark::RegisterBenchmark(
                    name(optimize ? "cgal_mesh_3_optimized" : "cgal_mesh_3").c_str(),
                    &bm_cgal_mesh_3, domain, v, optimize)
                    ->Unit(benchmark::kMillisecond)
                    ->UseManualTime();
                benchmark::RegisterBenchmark(name(optimize ? "gmsh_optimized" : "gmsh").c_str(),
                                             &bm_gmsh, domain, v, optimize)
                    ->Unit(benchmark::kMillisecond)
                    ->UseManualTime();
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    exactmesh::bench::set_heap_regime();
    register_all();
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    exactmesh::bench::add_peak_memory_context();
    benchmark::AddCustomContext("exactmesh_peer_peak_memory",
                                "peak_rss_bytes: the peer process's maximum resident set "
                                "(/usr/bin/time %M; 0 without it)");
    return exactmesh::bench::run_benchmarks(argc, argv);
}
