// SPDX-License-Identifier: MIT
// Python bindings of the triangulation layer: Delaunay triangulation (2D) and tetrahedralization
// (3D), constrained Delaunay triangulation, and the exact checks. Wiring only: each function
// converts arrays, releases the GIL for the construction and returns plain dicts of numpy
// arrays (exactmesh/__init__.py wraps them in Mesh objects).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <string>
#include <utility>
#include <vector>

#include "python/bindings.hpp"
#include "python/numpy_arrays.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // kMaxThreads
#include "triangulation/mesh/constrained_flags_2d.hpp"

namespace exactmesh::python {

namespace tri = exactmesh::triangulation;
using namespace pybind11::literals;

namespace {

py::dict triangulate(const CoordinateArray& points, const std::string& algorithm,
                     const std::string& order, std::uint64_t seed, unsigned threads) {
    const std::span<const double> xy = coordinates(points, 2, "points");
    const tri::Delaunay2Function build = tri::delaunay_2d_algorithm(algorithm);
    tri::Delaunay2Options options{tri::insertion_order_from_name(order), seed,
                                  tri::PointLocation::Auto};
    options.threads = checked_threads(threads);
    tri::Delaunay2Result result;
    double seconds = 0;
    {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        result = build(xy, options);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return py::dict("triangles"_a = indices_to_numpy(std::move(result.triangles), 3),
                    "neighbors"_a = indices_to_numpy(std::move(result.neighbors), 3),
                    "merged_into"_a = indices_to_numpy(std::move(result.merged_into), 1),
                    "counters"_a = counters_dict(tri::kDelaunay2CounterNames, result.counters),
                    "construct_seconds"_a = seconds);
}

py::dict tetrahedralize(const CoordinateArray& points, const std::string& algorithm,
                        const std::string& order, std::uint64_t seed, unsigned threads) {
    const std::span<const double> xyz = coordinates(points, 3, "points");
    const tri::Delaunay3Function build = tri::delaunay_3d_algorithm(algorithm);
    tri::Delaunay3Options options{tri::insertion_order_from_name(order), seed};
    options.threads = checked_threads(threads);
    tri::Delaunay3Result result;
    double seconds = 0;
    {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        result = build(xyz, options);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return py::dict("tetrahedra"_a = indices_to_numpy(std::move(result.mesh.tets), 4),
                    "neighbors"_a = indices_to_numpy(std::move(result.mesh.neighbors), 4),
                    "merged_into"_a = indices_to_numpy(std::move(result.merged_into), 1),
                    "coplanar"_a = result.coplanar,
                    "counters"_a = counters_dict(tri::kDelaunay3CounterNames, result.counters),
                    "construct_seconds"_a = seconds);
}

/// The dict of a constrained result (cdt(), and mesh() through constrained_result_dict).
py::dict cdt(const CoordinateArray& points, const IndexArray& segments,
             const CoordinateArray& holes, const std::string& recovery, bool remove_exterior,
             const std::string& order, std::uint64_t seed) {
    const std::span<const double> xy = coordinates(points, 2, "points");
    const std::vector<std::uint32_t> segment_indices =
        indices(segments, 2, xy.size() / 2, "segments");
    const std::span<const double> hole_points =
        holes.size() == 0 ? std::span<const double>{} : coordinates(holes, 2, "holes");
    tri::Cdt2Options options;
    options.recovery = tri::segment_recovery_from_name(recovery);
    options.remove_exterior = remove_exterior;
    options.order = tri::insertion_order_from_name(order);
    options.seed = seed;
    tri::Cdt2Result result;
    {
        py::gil_scoped_release release;
        result =
            tri::constrained_delaunay_2d(tri::Pslg{xy, segment_indices, hole_points, {}}, options);
    }
    return constrained_result_dict(std::move(result), {});
}

py::dict report_dict(const tri::CheckReport& report) {
    return py::dict(
        "ok"_a = report.ok, "problem"_a = report.problem,
        "triangle"_a = report.triangle == tri::kNone ? -1 : std::int64_t{report.triangle},
        "vertices"_a = report.vertices);
}

py::dict report_dict(const tri::Check3Report& report) {
    return py::dict("ok"_a = report.ok, "problem"_a = report.problem,
                    "tetrahedron"_a = report.tet == tri::kNone ? -1 : std::int64_t{report.tet},
                    "vertices"_a = report.vertices);
}

py::dict check_delaunay(const CoordinateArray& points, const IndexArray& triangles) {
    const std::span<const double> xy = coordinates(points, 2, "points");
    const std::vector<std::uint32_t> cells = indices(triangles, 3, xy.size() / 2, "triangles");
    tri::CheckReport report;
    {
        py::gil_scoped_release release;
        report = tri::check_delaunay_2d(xy, cells);
    }
    return report_dict(report);
}

py::dict check_triangulation(const CoordinateArray& points, const IndexArray& triangles) {
    const std::span<const double> xy = coordinates(points, 2, "points");
    const std::vector<std::uint32_t> cells = indices(triangles, 3, xy.size() / 2, "triangles");
    tri::CheckReport report;
    {
        py::gil_scoped_release release;
        report = tri::check_topology_2d(xy, cells);
    }
    return report_dict(report);
}

py::dict check_tetrahedralization(const CoordinateArray& points, const IndexArray& tetrahedra,
                                  bool delaunay) {
    const std::span<const double> xyz = coordinates(points, 3, "points");
    const std::vector<std::uint32_t> cells = indices(tetrahedra, 4, xyz.size() / 3, "tetrahedra");
    tri::Check3Report report;
    {
        py::gil_scoped_release release;
        report = delaunay ? tri::check_delaunay_3d(xyz, cells)
                          : tri::check_tetrahedralization_3d(xyz, cells);
    }
    return report_dict(report);
}

/// Constrained (Chew's definition) or conforming checks of a mesh of a PSLG: `points` the mesh's
/// vertices, the input's first (input_vertex_count of them), `pieces` the constrained edges
/// (empty: the segments themselves).
py::dict check_constrained(const CoordinateArray& points, const IndexArray& triangles,
                           std::uint32_t input_vertex_count, const IndexArray& segments,
                           const IndexArray& pieces, bool delaunay) {
    tri::Triangulation2 mesh;
    const std::span<const double> xy = coordinates(points, 2, "points");
    if (input_vertex_count > xy.size() / 2) {
        throw InputError("input_vertex_count " + std::to_string(input_vertex_count) +
                         " exceeds the mesh's " + std::to_string(xy.size() / 2) + " points");
    }
    mesh.xy.assign(xy.begin(), xy.end());
    mesh.triangles = indices(triangles, 3, xy.size() / 2, "triangles");
    const std::vector<std::uint32_t> segment_indices =
        indices(segments, 2, input_vertex_count, "segments");
    const std::vector<std::uint32_t> piece_indices = indices(pieces, 2, xy.size() / 2, "pieces");
    tri::CheckReport report;
    {
        py::gil_scoped_release release;
        tri::flag_constrained_edges_2d(mesh,
                                       piece_indices.empty() ? segment_indices : piece_indices);
        report = delaunay ? tri::check_constrained_delaunay_2d(mesh, input_vertex_count,
                                                               segment_indices, piece_indices)
                          : tri::check_conforming_mesh_2d(mesh, input_vertex_count, segment_indices,
                                                          piece_indices);
        if (report.ok && delaunay) {
            report = tri::check_input_vertices_kept_2d(
                mesh, std::span<const double>(mesh.xy).first(2 * std::size_t{input_vertex_count}));
        }
    }
    return report_dict(report);
}

}  // namespace

unsigned checked_threads(unsigned threads) {
    if (threads > triangulation::kMaxThreads) {
        throw InputError("threads " + std::to_string(threads) + " is above " +
                         std::to_string(triangulation::kMaxThreads));
    }
    return threads;
}

py::dict constrained_result_dict(tri::Cdt2Result&& result, std::vector<tri::VertIdx>&& quads) {
    py::list warnings;
    for (const std::string& w : result.warnings) warnings.append(w);
    tri::Triangulation2& mesh = result.mesh;
    return py::dict("points"_a = to_numpy(std::move(mesh.xy), 2),
                    "triangles"_a = indices_to_numpy(std::move(mesh.triangles), 3),
                    "neighbors"_a = indices_to_numpy(std::move(mesh.neighbors), 3),
                    "input_vertex_count"_a = result.input_vertex_count,
                    "merged_into"_a = indices_to_numpy(std::move(result.merged_into), 1),
                    "pieces"_a = indices_to_numpy(std::move(result.pieces), 2),
                    "piece_segment"_a = indices_to_numpy(std::move(result.piece_segment), 1),
                    "quads"_a = indices_to_numpy(std::move(quads), 4), "warnings"_a = warnings,
                    "counters"_a = counters_dict(tri::kCdt2CounterNames, result.counters));
}

void bind_triangulation(py::module_& m) {
    m.def("_triangulate", &triangulate, "points"_a, "algorithm"_a, "order"_a, "seed"_a,
          "threads"_a);
    m.def("_tetrahedralize", &tetrahedralize, "points"_a, "algorithm"_a, "order"_a, "seed"_a,
          "threads"_a);
    m.def("_cdt", &cdt, "points"_a, "segments"_a, "holes"_a, "recovery"_a, "remove_exterior"_a,
          "order"_a, "seed"_a);
    m.def("_check_delaunay", &check_delaunay, "points"_a, "triangles"_a);
    m.def("_check_triangulation", &check_triangulation, "points"_a, "triangles"_a);
    m.def("_check_tetrahedralization", &check_tetrahedralization, "points"_a, "tetrahedra"_a,
          "delaunay"_a);
    m.def("_check_constrained", &check_constrained, "points"_a, "triangles"_a,
          "input_vertex_count"_a, "segments"_a, "pieces"_a, "delaunay"_a);
}

}  // namespace exactmesh::python
