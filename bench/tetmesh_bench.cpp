// SPDX-License-Identifier: MIT
// tetmesh_bench: 3D quality meshing of the sample domains (generators/boundary_3d: box-with-hole,
// ellipsoid, wing), exactmesh's boundary recovery + Delaunay refinement (generators/mesh_3d)
// against TetGen, CGAL's Mesh_3 and Gmsh's 3D Delaunay, each run as a process on the same PLC
// (issue 15). The bound: radius-edge 2 and a volume bound V, as `exactmesh tetmesh --radius-edge
// 2 --max-volume V`; V runs from 1e-2 down by factors of 4 to EXACTMESH_TETMESH_BENCH_MIN_VOLUME
// (default 1e-5) for box-with-hole (volume 0.875) and is scaled by each other domain's volume
// over the box's (about the same counts). Names BM_<mesher>/<domain>/<V>:
//   exactmesh          recovery + refinement (no sliver removal), no file I/O, timed by Google
//                      Benchmark (wall);
//   exactmesh_slivers  the same + sliver_removal_3d (B = 2, V kept), as `exactmesh tetmesh`;
//   tetgen             `tetgen -pq2a<V>` on the PLC as a .poly: its "Total running seconds"
//                      minus "Output seconds" (CPU; includes its default mesh optimization);
//   cgal_mesh_3        bench/cgal_mesh_3d_tool.cpp on the same .poly: domain construction +
//                      make_mesh_3 (CPU), no Lloyd/ODT/perturb/exude; cell_radius_edge_ratio 2,
//                      cell_size c V^(1/3), facet_size = edge_size = cell_size, facet_angle 25,
//                      facet_distance cell_size / 10 (see kCgalCellSizePerCubeRoot);
//   cgal_mesh_3_optimized  the same + perturb_mesh_3 + exude_mesh_3 (CGAL's defaults), timed too;
//   gmsh               the PLC as a .geo (plane surfaces, surface loops, a volume),
//                      Mesh.Algorithm3D = 1 (Delaunay), Mesh.MeshSizeMin = MeshSizeMax = h with
//                      h = c V^(1/3) (see kGmshSizePerCubeRoot), Mesh.Optimize = 0: the CPU time
//                      of "Done meshing 3D" (its 2D surface meshing excluded, in counter
//                      gmsh_2d_cpu_seconds);
//   gmsh_optimized     Mesh.Optimize = 1 (Gmsh's default): 3D meshing + "Done optimizing mesh".
// Peers are run with manual time; one that is not installed (tetgen, gmsh on PATH; cgal_mesh_3d
// beside this binary, built with EXACTMESH_WITH_CGAL) or that fails is a skip, not a failure.
// Counters, measured by the same code on every mesh (triangulation/checks/quality_3d): tets,
// tets_per_second (of the timed construction), min/max_dihedral_degrees, dihedrals_below_10 and
// dihedrals_below_20 (of the 6 #T angles), slivers (below 5 degrees with radius-edge <= 2),
// max_radius_edge, mean_volume_edge; memory: peak_heap_bytes for exactmesh (peak live heap of
// the construction, bench/heap_accounting.cpp) and peak_rss_bytes for a peer (its process's
// maximum resident set, measured by GNU time in bench_support's run_shell_command: everything the
// program holds, input and libraries included, so the two are not the same measure).
#include <benchmark/benchmark.h>
#include <unistd.h>  // getpid: a scratch directory per process

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.hpp"
#include "bench/gmsh_peer.hpp"
#include "bench/heap_accounting.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "io/tetgen_format.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

/// The peers' size parameter per cube root of V, chosen once so that their tetrahedron counts
/// come near exactmesh's (without sliver removal) on box-with-hole at V = 1e-2 / 4^k: a peer's
/// counters show how near, per case. A regular tetrahedron of volume V has circumradius
/// 1.25 V^(1/3) and edge 2.04 V^(1/3); Delaunay refinement with a volume bound leaves most
/// tetrahedra well under V, hence the smaller factors.
constexpr double kCgalCellSizePerCubeRoot = 1.1;
constexpr double kGmshSizePerCubeRoot = 1.2;

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

void set_quality_counters(benchmark::State& state, const tri::Tetrahedralization3& mesh,
                          double seconds) {
    const tri::QualityStats3 q = tri::quality_stats_3d(mesh);
    state.counters["tets"] = static_cast<double>(mesh.tet_count());
    state.counters["tets_per_second"] = seconds > 0 ? mesh.tet_count() / seconds : 0;
    state.counters["min_dihedral_degrees"] = q.min_dihedral_degrees;
    state.counters["max_dihedral_degrees"] = q.max_dihedral_degrees;
    // 10-degree bins (QualityOptions' default): bin 0 is [0, 10), bin 1 [10, 20).
    const auto bin = [&q](std::size_t k) {
        return k < q.dihedral_histogram.size() ? static_cast<double>(q.dihedral_histogram[k]) : 0;
    };
    state.counters["dihedrals_below_10"] = bin(0);
    state.counters["dihedrals_below_20"] = bin(0) + bin(1);
    state.counters["slivers"] = static_cast<double>(q.slivers);
    state.counters["max_radius_edge"] = q.max_radius_edge;
    state.counters["mean_volume_edge"] = q.mean_volume_edge;
}

void bm_exactmesh(benchmark::State& state, DomainCase domain, double max_volume,
                  bool remove_slivers) {
    const tri::Plc3& plc = plc_of(domain.domain);
    gen::DelaunayRefinement3Options options;
    options.radius_edge_bound = 2.0;
    options.max_volume = max_volume;
    gen::SliverRemoval3Options sliver_options;
    sliver_options.radius_edge_bound = 2.0;
    sliver_options.max_volume = max_volume;
    tri::Tetrahedralization3 last;
    double seconds = 0, peak_bytes = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        const std::size_t heap_before = exactmesh::bench::start_heap_measurement();
        const auto start = std::chrono::steady_clock::now();
        auto recovered = tri::boundary_recovery_3d(plc).mesh;
        auto refined = gen::delaunay_refinement_3d(plc, std::move(recovered), options).mesh;
        if (remove_slivers)
            refined = gen::sliver_removal_3d(std::move(refined), sliver_options).mesh;
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++runs;
        state.PauseTiming();
        peak_bytes = exactmesh::bench::heap_growth_since(heap_before);
        last = std::move(refined.mesh);
        exactmesh::bench::after_construction();
        state.ResumeTiming();
    }
    set_quality_counters(state, last, runs > 0 ? seconds / static_cast<double>(runs) : 0);
    state.counters["peak_heap_bytes"] = peak_bytes;
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

void bm_tetgen(benchmark::State& state, DomainCase domain, double max_volume) {
    if (!on_path("tetgen")) {
        state.SkipWithError("tetgen not found on PATH");
        return;
    }
    const Scratch scratch("tetgen");
    const fs::path poly = scratch.dir / "domain.poly", log = scratch.dir / "tetgen.log";
    std::ofstream(poly) << poly_text(plc_of(domain.domain));
    // No -Q: TetGen then prints its phase timings, which give the construction without I/O.
    const std::string command = "tetgen -pq2a" + number_text(max_volume) + " '" + poly.string() +
                                "' > '" + log.string() + "' 2>&1";
    double seconds = 0, rss = 0;
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
    }
    set_quality_counters(state, read_node_ele(scratch.dir / "domain.1"), seconds);
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
    const double cell_size = kCgalCellSizePerCubeRoot * std::cbrt(max_volume);
    const std::string command = "'" + tool.string() + "' '" + poly.string() + "' '" +
                                (scratch.dir / "mesh").string() + "' --radius-edge 2 --cell-size " +
                                number_text(cell_size) + (optimize ? " --optimize" : "") + " > '" +
                                log.string() + "' 2>&1";
    double seconds = 0, rss = 0, domain_seconds = 0, optimize_seconds = 0;
    for (auto _ : state) {
        const exactmesh::bench::ProcessRun run = exactmesh::bench::run_shell_command(command);
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
    }
    set_quality_counters(state, read_node_ele(scratch.dir / "mesh"), seconds);
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
    const double size = kGmshSizePerCubeRoot * std::cbrt(max_volume);
    std::string geo;
    try {
        geo = exactmesh::bench::gmsh_plc_geo(plc_of(domain.domain));
    } catch (const std::exception& error) {
        state.SkipWithError(error.what());
        return;
    }
    geo += "Mesh.Algorithm3D = 1;\nMesh.MeshSizeMin = " + number_text(size) +
           ";\nMesh.MeshSizeMax = " + number_text(size) +
           ";\nMesh.MeshSizeFromCurvature = 0;\nMesh.Optimize = " + (optimize ? "1" : "0") + ";\n";
    exactmesh::bench::GmshMesh3 last;
    double seconds = 0;
    for (auto _ : state) {
        try {
            last = exactmesh::bench::run_gmsh_geo_3d(geo, scratch.dir);
        } catch (const std::exception& error) {
            state.SkipWithError(error.what());
            return;
        }
        seconds = last.cpu_seconds_3d + (optimize ? last.cpu_seconds_optimize : 0.0);
        state.SetIterationTime(seconds);
    }
    if (last.mesh.tet_count() == 0) {
        state.SkipWithError("gmsh wrote no tetrahedra");
        return;
    }
    set_quality_counters(state, last.mesh, seconds);
    state.counters["peak_rss_bytes"] = last.max_rss_bytes;
    state.counters["gmsh_2d_cpu_seconds"] = last.cpu_seconds_2d;
    state.counters["gmsh_optimize_cpu_seconds"] = last.cpu_seconds_optimize;
    state.counters["gmsh_size"] = size;
}

void register_all() {
    double smallest = 1e-5;
    if (const char* text = std::getenv("EXACTMESH_TETMESH_BENCH_MIN_VOLUME")) {
        smallest = std::strtod(text, nullptr);
        if (!(smallest > 0)) throw std::runtime_error("EXACTMESH_TETMESH_BENCH_MIN_VOLUME > 0");
    }
    for (const DomainCase& domain : kDomains) {
        const std::string domain_name(gen::sample_domain_3d_name(domain.domain));
        for (double box_v = 1e-2; box_v >= smallest * (1 - 1e-9); box_v /= 4) {
            const double v = box_v * domain.volume / kBoxVolume;
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
            benchmark::RegisterBenchmark(name("tetgen").c_str(), &bm_tetgen, domain, v)
                ->Unit(benchmark::kMillisecond)
                ->UseManualTime();
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
