// SPDX-License-Identifier: MIT
// A size field given on a background triangulation (issue 6, "a background mesh with linear
// interpolation"): each vertex carries a size; inside a triangle the size is the barycentric
// (linear) interpolation of its three vertices' sizes (in a sliver whose area rounds to 0 in
// doubles, the value on its nearest side, linear along it); at a point outside every triangle it is
// the value at the nearest point of the triangulation (on one of its boundary edges, linear
// along that edge) [Peraire-Vahdati-Morgan-Zienkiewicz87 §3: the background grid].
// Invariants: every triangle strictly counter-clockwise (exact orient2d), no directed edge in
// two triangles; the value at any point lies between the smallest and largest vertex size.
// Cost: O(V + T) to build (two bucket grids); a query O(1) expected on meshes of bounded
// triangle size ratio (the triangles listed in the point's cell: every triangle is listed in
// each cell its bounding box meets, and cells are found by one monotone rounding, so the
// containing triangle is always among them). Predicates:
// orient2d (validation, and every inside decision: a point is inside a closed triangle when no
// orient2d is negative); the interpolation and the nearest point are plain double arithmetic.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/mesh/locate_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// Bad background mesh input, naming the item: a vertex (coordinate, size) or a triangle
/// (index, orientation, overlap), 0-based.
class BackgroundMeshError : public InputError {
  public:
    enum class Item { Mesh, Vertex, Triangle };
    BackgroundMeshError(Item item, std::size_t index, const std::string& detail,
                        SourceLocation where = SourceLocation::current());
    Item item() const { return item_; }
    std::size_t index() const { return index_; }
    /// The problem without the "background mesh: triangle 3: " prefix.
    const std::string& detail() const { return detail_; }

  private:
    Item item_;
    std::size_t index_;
    std::string detail_;
};

class BackgroundSizeMesh2 {
  public:
    /// `xy`: 2·#V finite coordinates; `sizes`: #V finite values > 0; `triangles`: 3·#T > 0
    /// vertex indices, each triangle counter-clockwise with three distinct, non-collinear
    /// vertices, no two triangles with the same directed edge (such triangles overlap). Other
    /// overlaps are not detected: where triangles overlap, the first one found decides.
    /// Vertices no triangle uses are ignored.
    /// @throws BackgroundMeshError naming the first bad item.
    BackgroundSizeMesh2(std::vector<double> xy, std::vector<double> sizes,
                        std::vector<std::uint32_t> triangles);

    /// The interpolated size at (x, y) (see the file comment); (x, y) must be finite.
    double operator()(double x, double y) const;
    /// The triangle containing (x, y) (closed; the first found on a shared edge), or kNone.
    triangulation::TriIdx locate(double x, double y) const;

    std::uint32_t vertex_count() const { return mesh_.vertex_count(); }
    std::uint32_t triangle_count() const { return mesh_.triangle_count(); }
    /// 2·#B: the boundary edges (directed edges whose reverse is in no triangle).
    const std::vector<std::uint32_t>& boundary_edges() const { return boundary_; }

  private:
    triangulation::Triangulation2 mesh_;  // xy and triangles only
    std::vector<double> sizes_;
    std::vector<std::uint32_t> boundary_;
    std::vector<double> boxes_;  // 4·#T: each triangle's x0, y0, x1, y1
    // The shared bucket grids (triangulation/mesh/locate_2d.hpp): triangles (about 2 per cell) for
    // point location, boundary edges (about 1 per cell) for the nearest boundary value.
    triangulation::TriangleLocator2 locator_;
    triangulation::BucketGrid2 edge_buckets_;
    double interpolate(triangulation::TriIdx t, double x, double y) const;
    double nearest_boundary_value(double x, double y) const;
};

}  // namespace exactmesh::generators
