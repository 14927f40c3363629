// SPDX-License-Identifier: MIT
// Point location by a uniform bucket grid (issue 12: the one grid the generators share, where
// the domain locator and the background size mesh each had their own):
//  - BucketGrid2: a uniform grid over the bounding box of a set of vertices, each cell listing
//    (CSR, in increasing item order) the items (triangles, edges: a few vertex indices each)
//    whose vertices' bounding box meets it; about `per_cell` items per cell, coarser while the
//    lists would hold more than 16 entries per item (long slivers meet many cells; a fan of
//    them would otherwise need memory quadratic in their number), at most 4096 cells a side.
//  - TriangleLocator2: over a grid of triangles, the triangle containing a point (closed),
//    by exact orient2d tests. The answer is the lowest-numbered triangle containing the point,
//    whatever the grid's cells: the cell index is monotone in x and in y, so every triangle
//    whose box holds the point is listed in the point's cell, in increasing order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

class BucketGrid2 {
  public:
    BucketGrid2() = default;
    /// @param xy 2·#V coordinates (finite where used).
    /// @param box_vertices the vertices whose bounding box the grid covers (with repeats).
    /// @param items per_item vertex indices per item, each among box_vertices.
    /// @param per_cell the items per cell aimed at.
    BucketGrid2(std::span<const double> xy, std::span<const VertIdx> box_vertices,
                std::span<const VertIdx> items, std::size_t per_item, double per_cell);

    bool empty() const { return columns_ == 0; }
    /// The column and row of a point, clamped to the grid (monotone in x and in y).
    std::uint32_t column(double x) const;
    std::uint32_t row(double y) const;
    /// The items listed in cell (c, r), in increasing order.
    std::span<const std::uint32_t> cell(std::uint32_t c, std::uint32_t r) const {
        const std::size_t k = std::size_t{r} * columns_ + c;
        return {items_.data() + start_[k], items_.data() + start_[k + 1]};
    }
    /// True when (x, y) lies in the closed bounding box of the box vertices (exact).
    bool in_box(double x, double y) const { return x >= x0_ && x <= x1_ && y >= y0_ && y <= y1_; }

    double x0() const { return x0_; }
    double y0() const { return y0_; }
    double cell_width() const { return cell_; }
    std::uint32_t columns() const { return columns_; }
    std::uint32_t rows() const { return rows_; }

  private:
    double x0_ = 0, y0_ = 0, x1_ = -1, y1_ = -1, cell_ = 1;
    std::uint32_t columns_ = 0, rows_ = 0;
    std::vector<std::uint32_t> start_, items_;
};

class TriangleLocator2 {
  public:
    TriangleLocator2() = default;
    /// Over the triangles of `mesh` (3 vertex indices each, counter-clockwise); about
    /// `per_cell` triangles per cell.
    explicit TriangleLocator2(const Triangulation2& mesh, double per_cell = 1.0);
    TriangleLocator2(std::span<const double> xy, std::span<const VertIdx> triangles,
                     double per_cell = 1.0);

    /// The lowest-numbered triangle of `mesh` (the one given to the constructor, unchanged)
    /// containing (x, y) (closed), or kNone when none does or (x, y) is not finite.
    TriIdx locate(const Triangulation2& mesh, double x, double y) const {
        return locate(mesh.xy, mesh.triangles, x, y);
    }
    TriIdx locate(std::span<const double> xy, std::span<const VertIdx> triangles, double x,
                  double y) const;

  private:
    BucketGrid2 grid_;
};

}  // namespace exactmesh::triangulation
