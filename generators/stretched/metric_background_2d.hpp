// SPDX-License-Identifier: MIT
// A metric field given on a background triangulation [issue 14; the background grid of
// Peraire-Vahdati-Morgan-Zienkiewicz87 §3 with tensors at its vertices, interpolated
// log-Euclidean as Arsigny-Fillard-Pennec-Ayache06]: each vertex carries a Metric2; inside a
// triangle the metric is the log-Euclidean mean of its three vertices' metrics with the point's
// barycentric coordinates as weights (positive definite, and a constant field is reproduced);
// at a point outside every triangle it is the value at the nearest point of the triangulation's
// boundary (log-Euclidean linear along that boundary edge). In a sliver whose area rounds to 0
// in doubles the metric of its nearest vertex is taken.
// Point location: the shared bucket grid of triangles (triangulation/mesh/locate_2d.hpp) whose
// every inside decision is the exact orient2d (a point is in a closed triangle when no orient2d
// is negative). That replaces a walk on purpose: a background mesh need not be convex, Delaunay
// or connected (holes, several parts), where a visibility walk can cycle or stop at the
// boundary before reaching the triangle. The mesh's validation and the locator are those of the
// background size mesh (generators/sizing/background_size_2d.hpp).
// Cost: O(V + T) to build; a query inside the mesh O(1) expected, outside it O(#boundary edges)
// (a background mesh normally covers the domain, so such queries are rare).
// Scale invariance: coordinates and sizes scaled together by 2^k give the same metrics scaled
// by 2^k, bit for bit (barycentric coordinates and closest points are computed on vectors
// scaled by a power of two, log-Euclidean means in units of a power of two).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "generators/sizing/background_size_2d.hpp"
#include "generators/stretched/metric_2d.hpp"

namespace exactmesh::generators {

class BackgroundMetricMesh2 {
  public:
    /// `xy`: 2·#V finite coordinates; `metrics`: #V valid metrics (check_metric); `triangles`:
    /// 3·#T as for BackgroundSizeMesh2 (counter-clockwise, no two triangles with the same
    /// directed edge).
    /// @throws BackgroundMeshError naming the first bad vertex (coordinate or metric) or
    ///         triangle.
    BackgroundMetricMesh2(std::vector<double> xy, std::vector<Metric2> metrics,
                          std::vector<std::uint32_t> triangles);

    /// The interpolated metric at (x, y) (finite), see the file comment.
    Metric2 operator()(double x, double y) const;

    std::uint32_t vertex_count() const { return geometry_.vertex_count(); }
    std::uint32_t triangle_count() const { return geometry_.triangle_count(); }
    /// The vertices (2·#V), their metrics (#V) and the triangles (3·#T) it was built from.
    const std::vector<double>& xy() const { return xy_; }
    const std::vector<Metric2>& metrics() const { return metrics_; }
    const std::vector<std::uint32_t>& triangles() const { return triangles_; }

  private:
    BackgroundSizeMesh2 geometry_;  // validation, location and boundary edges (sizes unused)
    std::vector<double> xy_;
    std::vector<std::uint32_t> triangles_;
    std::vector<Metric2> metrics_;
    Metric2 inside(std::uint32_t t, double x, double y) const;
    Metric2 nearest_boundary(double x, double y) const;
};

/// Where a metric file's data came from, for messages: the .node file (its vertices' lines and
/// numbering base) and the .ele file.
struct MetricFileSource {
    std::string node_file;
    std::string ele_file;
    std::uint32_t first_index = 0;              ///< the .node file's first vertex number
    std::span<const std::uint64_t> node_lines;  ///< #V: each vertex's line in the .node file
};

/// What a metric file's vertices carry.
enum class MetricFileForm {
    Matrices,           ///< 3 attributes M11 M12 M22 (metric_from_matrix)
    StretchingVectors,  ///< 4 attributes DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO
                        ///< (metric_from_stretching)
};

/// The attributes per vertex of a form (3 or 4).
std::size_t metric_file_values(MetricFileForm form);

/// The background metric mesh of a metric file: vertex v at (xy[2v], xy[2v+1]) with the metric
/// of values[k v .. k v + k - 1], k = metric_file_values(form).
/// @throws InputError "node_file:line: vertex N: metric (M11, M12, M22) = (...) is not positive
///         definite ..." (or the stretching vector's complaint) for a bad metric (N in the file's
///         numbering), "ele_file: background mesh: triangle T: ..." for a bad triangle.
BackgroundMetricMesh2 background_metric_from_file(std::vector<double> xy, MetricFileForm form,
                                                  std::span<const double> values,
                                                  std::vector<std::uint32_t> triangles,
                                                  const MetricFileSource& source);

}  // namespace exactmesh::generators
