// SPDX-License-Identifier: MIT
// Edge-face swapping and vertex removal in 3D [Joe91; Shewchuk03]: time against N with
// Complexity() fits and work counters.
//
// BM_swap3d_delaunay/perturbed/<n>: n uniform points in the unit cube, CGAL's Delaunay
// tetrahedralization of them (the reference, built once per n outside the timer), then every
// point moved by a random offset of up to 0.4 of the mean spacing n^(-1/3) per coordinate when
// that keeps all its tetrahedra positive (exact orient3d): the same connectivity over moved
// points, far from Delaunay (the mesh-motion scenario). Timed: Delaunay edge-face swapping back
// to the Delaunay tetrahedralization of the moved points (TetMesh3 construction included).
// Counters: flips/pt, flips/s (swaps per second), stalled (faces left not locally Delaunay).
// BM_max_min_dihedral/perturbed/<n>/<removal>: the same moved meshes, MaxMinDihedral edge-face
// swapping (removal 0), or then edge removal (edge_removal_3d, rings of 3 to 7) on the edges of
// every tetrahedron whose smallest dihedral angle is below 15 degrees and the face swaps again
// (removal 1): what edge removal buys (counters min_dihedral_degrees and below_10, the
// tetrahedra with an angle under 10 degrees) and what it costs (the time, same start).
// BM_vertex_removal/uniform/<n>: from CGAL's tetrahedralization of n uniform points, remove
// n/10 random interior vertices one by one; counters removals/s, flips/removal, star/removal.
// The fitted exponent: Complexity() (oAuto) per family, or the slope of log time on log n.
// CGAL appears here only as the builder of the start meshes (EXACTMESH_WITH_CGAL).
#include <benchmark/benchmark.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cmath>
#include <map>
#include <random>
#include <vector>

#include "bench/bench_support.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/edge_removal_3d.hpp"
#include "triangulation/modification/vertex_removal_3d.hpp"

namespace {

namespace tri = exactmesh::triangulation;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<K, Tds>;
constexpr std::uint64_t kSeed = 20240611;

tri::Tetrahedralization3 cgal_delaunay(const std::vector<double>& xyz) {
    std::vector<std::pair<K::Point_3, std::uint32_t>> points;
    for (std::uint32_t v = 0; v < xyz.size() / 3; ++v) {
        points.emplace_back(K::Point_3(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]), v);
    }
    CgalDelaunay dt(points.begin(), points.end());
    tri::Tetrahedralization3 mesh;
    mesh.xyz = xyz;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        std::array<std::uint32_t, 4> t{c->vertex(0)->info(), c->vertex(1)->info(),
                                       c->vertex(2)->info(), c->vertex(3)->info()};
        if (exactmesh::predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                            mesh.point(t[3])) ==
            exactmesh::predicates::Sign::Negative) {
            std::swap(t[0], t[1]);
        }
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    tri::link_neighbors_3d(mesh);
    return mesh;
}

std::vector<double> uniform(std::uint32_t n) {
    std::mt19937_64 rng(kSeed + n);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xyz(3 * std::size_t{n});
    for (double& x : xyz) x = unit(rng);
    return xyz;
}

const tri::Tetrahedralization3& delaunay_start(std::uint32_t n) {
    static std::map<std::uint32_t, tri::Tetrahedralization3> cache;
    auto it = cache.find(n);
    if (it == cache.end()) it = cache.emplace(n, cgal_delaunay(uniform(n))).first;
    return it->second;
}

const tri::Tetrahedralization3& perturbed_start(std::uint32_t n) {
    static std::map<std::uint32_t, tri::Tetrahedralization3> cache;
    auto it = cache.find(n);
    if (it != cache.end()) return it->second;
    tri::TetMesh3 mesh = tri::make_tet_mesh_3d(delaunay_start(n));
    std::mt19937_64 rng(kSeed);
    const double step = 0.4 * std::cbrt(1.0 / n);
    std::uniform_real_distribution<double> offset(-step, step);
    for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        const std::vector<tri::TetIdx> star = tri::vertex_star(mesh, v);
        const double old[3] = {mesh.xyz[3 * v], mesh.xyz[3 * v + 1], mesh.xyz[3 * v + 2]};
        for (int k = 0; k < 3; ++k) mesh.xyz[3 * v + static_cast<std::size_t>(k)] += offset(rng);
        bool ok = true;
        for (const tri::TetIdx t : star) {
            const tri::Tet q = mesh.tet(t);
            ok = ok && exactmesh::predicates::orient3d(mesh.point(q[0]), mesh.point(q[1]),
                                                       mesh.point(q[2]), mesh.point(q[3])) ==
                           exactmesh::predicates::Sign::Positive;
        }
        if (!ok) {
            for (int k = 0; k < 3; ++k) mesh.xyz[3 * v + static_cast<std::size_t>(k)] = old[k];
        }
    }
    return cache.emplace(n, tri::to_tetrahedralization_3d(mesh)).first->second;
}

void swap_benchmark(benchmark::State& state) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const tri::Tetrahedralization3& start = perturbed_start(n);
    std::uint64_t flips = 0, stalled = 0;
    double seconds = 0;
    for (auto _ : state) {
        const auto begin = std::chrono::steady_clock::now();
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(start);
        const tri::EdgeFaceSwapCounters counters =
            tri::swap_faces_3d(mesh, tri::SwapCriterion3::Delaunay);
        benchmark::DoNotOptimize(mesh.tv.data());
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        flips += counters.flips();
        stalled = counters.stalled_faces;
    }
    state.counters["flips/pt"] =
        static_cast<double>(flips) / static_cast<double>(state.iterations()) / n;
    state.counters["flips/s"] = static_cast<double>(flips) / seconds;
    state.counters["stalled"] = static_cast<double>(stalled);
    state.SetComplexityN(n);
}

/// The smallest dihedral angle of tetrahedron t, in degrees (rounded: a selection and a report).
double smallest_degrees(const tri::TetMesh3& mesh, tri::TetIdx t) {
    const tri::Tet q = mesh.tet(t);
    const exactmesh::predicates::TetCorners p{mesh.point(q[0]), mesh.point(q[1]), mesh.point(q[2]),
                                              mesh.point(q[3])};
    return static_cast<double>(exactmesh::predicates::dihedral_radians(
               exactmesh::predicates::smallest_dihedral(p))) *
           180 / M_PI;
}

void max_min_benchmark(benchmark::State& state) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const bool removal = state.range(1) != 0;
    const tri::Tetrahedralization3& start = perturbed_start(n);
    double seconds = 0, smallest = 0;
    std::uint64_t below_10 = 0, removals = 0;
    for (auto _ : state) {
        const auto begin = std::chrono::steady_clock::now();
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(start);
        tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral);
        if (removal) {
            std::vector<tri::TetIdx> bad;
            for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t)
                if (!mesh.is_dead(t) && smallest_degrees(mesh, t) < 15) bad.push_back(t);
            removals =
                tri::remove_edges_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, bad, {}).removals;
            tri::swap_faces_3d(mesh, tri::SwapCriterion3::MaxMinDihedral);
        }
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        state.PauseTiming();
        smallest = 180;
        below_10 = 0;
        for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t) {
            if (mesh.is_dead(t)) continue;
            const double angle = smallest_degrees(mesh, t);
            smallest = std::min(smallest, angle);
            below_10 += angle < 10 ? 1 : 0;
        }
        state.ResumeTiming();
    }
    state.counters["min_dihedral_degrees"] = smallest;
    state.counters["below_10"] = static_cast<double>(below_10);
    state.counters["edge_removals"] = static_cast<double>(removals);
    state.counters["seconds"] = seconds / static_cast<double>(state.iterations());
}

void removal_benchmark(benchmark::State& state) {
    const auto n = static_cast<std::uint32_t>(state.range(0));
    const tri::Tetrahedralization3& start = delaunay_start(n);
    // Interior vertices in a fixed random order.
    tri::TetMesh3 probe = tri::make_tet_mesh_3d(start);
    std::vector<tri::VertIdx> interior;
    for (tri::VertIdx v = 0; v < probe.vertex_count(); ++v) {
        bool inside = true;
        for (const tri::TetIdx t : tri::vertex_star(probe, v)) {
            const unsigned lv = probe.slot_of(t, v);
            for (unsigned k = 0; k < 4; ++k)
                inside = inside && (k == lv || probe.adj[4 * t + k] != tri::kNone);
        }
        if (inside) interior.push_back(v);
    }
    std::shuffle(interior.begin(), interior.end(), std::mt19937_64(kSeed));
    interior.resize(n / 10);
    tri::VertexRemovalCounters counters;
    double seconds = 0;
    for (auto _ : state) {
        state.PauseTiming();
        tri::TetMesh3 mesh = tri::make_tet_mesh_3d(start);
        counters = {};
        state.ResumeTiming();
        const auto begin = std::chrono::steady_clock::now();
        tri::remove_vertices_3d(mesh, interior, &counters);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        benchmark::DoNotOptimize(mesh.tv.data());
    }
    const auto removed = static_cast<double>(counters.removed);
    state.counters["removals/s"] = removed * static_cast<double>(state.iterations()) / seconds;
    state.counters["flips/removal"] = static_cast<double>(counters.flips_23 + counters.flips_32 +
                                                          counters.flips_44 + counters.flips_41) /
                                      removed;
    state.counters["star/removal"] = static_cast<double>(counters.star_tets) / removed;
    state.counters["cavity"] = static_cast<double>(counters.cavity_fallbacks);
    state.SetComplexityN(n);
}

}  // namespace

BENCHMARK(swap_benchmark)
    ->Name("BM_swap3d_delaunay/perturbed")
    ->Arg(1000)
    ->Arg(3162)
    ->Arg(10000)
    ->Arg(31623)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();
BENCHMARK(max_min_benchmark)
    ->Name("BM_max_min_dihedral/perturbed")
    ->ArgsProduct({{10000, 100000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(removal_benchmark)
    ->Name("BM_vertex_removal/uniform")
    ->Arg(1000)
    ->Arg(3162)
    ->Arg(10000)
    ->Arg(31623)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->Complexity();

int main(int argc, char** argv) {
    benchmark::AddCustomContext("build_type", EXACTMESH_BENCH_BUILD_TYPE);
    return exactmesh::bench::run_benchmarks(argc, argv);
}
