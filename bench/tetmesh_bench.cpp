// SPDX-License-Identifier: MIT
// tetmesh_bench: 3D quality meshing of the box-with-hole sample domain (generators/boundary_3d),
// exactmesh's boundary recovery + Delaunay refinement (generators/mesh_3d) against TetGen run as
// a process on the same PLC written as a .poly (`tetgen -pq2a<V>`: radius-edge 2 and volume
// bound V, like `exactmesh tetmesh --radius-edge 2 --max-volume V`). Names:
//   BM_exactmesh/<V>   the construction alone (no file I/O), timed by Google Benchmark;
//   BM_tetgen/<V>      TetGen's own "Total running seconds" minus its "Output seconds" (reading
//                      the .poly is not in its total), reported as manual time; skipped when
//                      /usr/bin/tetgen (or `tetgen` on PATH) is missing.
// Counters: tets, tets_per_second (of the timed construction), min_dihedral_degrees and
// max_radius_edge (triangulation/checks/quality_3d, the same code on both meshes).
// V runs from 1e-2 down by factors of 4 to EXACTMESH_TETMESH_BENCH_MIN_VOLUME (default 1e-5).
#include <benchmark/benchmark.h>

#include <unistd.h>  // getpid: a scratch directory per process

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "io/tetgen_format.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

namespace {

namespace fs = std::filesystem;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

const tri::Plc3& box_with_hole() {
    static const tri::Plc3 plc = gen::sample_domain_3d(gen::SampleDomain3::BoxWithHole);
    return plc;
}

void set_quality_counters(benchmark::State& state, const tri::Tetrahedralization3& mesh,
                          double seconds) {
    const tri::QualityStats3 q = tri::quality_stats_3d(mesh);
    state.counters["tets"] = static_cast<double>(mesh.tet_count());
    state.counters["tets_per_second"] = seconds > 0 ? mesh.tet_count() / seconds : 0;
    state.counters["min_dihedral_degrees"] = q.min_dihedral_degrees;
    state.counters["max_radius_edge"] = q.max_radius_edge;
}

void bm_exactmesh(benchmark::State& state, double max_volume) {
    gen::DelaunayRefinement3Options options;
    options.radius_edge_bound = 2.0;
    options.max_volume = max_volume;
    tri::Tetrahedralization3 last;
    double seconds = 0;
    std::uint64_t runs = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        auto recovered = tri::boundary_recovery_3d(box_with_hole()).mesh;
        auto refined = gen::delaunay_refinement_3d(box_with_hole(), std::move(recovered), options);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        ++runs;
        state.PauseTiming();
        last = std::move(refined.mesh.mesh);
        exactmesh::bench::after_construction();
        state.ResumeTiming();
    }
    set_quality_counters(state, last, runs > 0 ? seconds / static_cast<double>(runs) : 0);
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

bool have_tetgen() {
    return std::system("command -v tetgen > /dev/null 2>&1") == 0;
}

/// The number after `label` on a line of TetGen's log, or NaN.
double log_seconds(const fs::path& log, const std::string& label) {
    std::ifstream text(log);
    std::string line;
    while (std::getline(text, line)) {
        const auto at = line.find(label);
        if (at == 0) return std::stod(line.substr(label.size()));
    }
    return std::nan("");
}

void bm_tetgen(benchmark::State& state, double max_volume) {
    if (!have_tetgen()) {
        state.SkipWithError("tetgen not found on PATH");
        return;
    }
    const fs::path dir =
        fs::temp_directory_path() / ("exactmesh_tetmesh_bench_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path poly = dir / "box.poly", log = dir / "tetgen.log";
    std::ofstream(poly) << poly_text(box_with_hole());
    char volume[64];
    std::snprintf(volume, sizeof volume, "%.17g", max_volume);
    // No -Q: TetGen then prints its phase timings, which give the construction without I/O.
    const std::string command = "tetgen -pq2a" + std::string(volume) + " '" + poly.string() +
                                "' > '" + log.string() + "' 2>&1";
    double seconds = 0;
    for (auto _ : state) {
        if (std::system(command.c_str()) != 0) {
            state.SkipWithError("tetgen failed");
            return;
        }
        const double total = log_seconds(log, "Total running seconds:");
        const double output = log_seconds(log, "Output seconds:");
        seconds = total - (std::isnan(output) ? 0.0 : output);
        state.SetIterationTime(seconds);
    }
    const auto nodes = exactmesh::io::read_tetgen_node(dir / "box.1.node");
    const auto ele =
        exactmesh::io::read_tetgen_ele(dir / "box.1.ele", nodes.first_index, nodes.vertex_count());
    tri::Tetrahedralization3 mesh;
    mesh.xyz = nodes.xyz;
    mesh.tets = ele.tets;
    set_quality_counters(state, mesh, seconds);
    fs::remove_all(dir);
}

void register_all() {
    double smallest = 1e-5;
    if (const char* text = std::getenv("EXACTMESH_TETMESH_BENCH_MIN_VOLUME")) {
        smallest = std::strtod(text, nullptr);
        if (!(smallest > 0)) throw std::runtime_error("EXACTMESH_TETMESH_BENCH_MIN_VOLUME > 0");
    }
    for (double v = 1e-2; v >= smallest * (1 - 1e-9); v /= 4) {
        char name[64];
        std::snprintf(name, sizeof name, "%.3g", v);
        benchmark::RegisterBenchmark((std::string("BM_exactmesh/") + name).c_str(), &bm_exactmesh,
                                     v)
            ->Unit(benchmark::kMillisecond);
        benchmark::RegisterBenchmark((std::string("BM_tetgen/") + name).c_str(), &bm_tetgen, v)
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
    }
}

}  // namespace

int main(int argc, char** argv) {
    exactmesh::bench::set_heap_regime();
    register_all();
    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    exactmesh::bench::add_peak_memory_context();
    return exactmesh::bench::run_benchmarks(argc, argv);
}
