// SPDX-License-Identifier: MIT
// Point location by a uniform bucket grid (see locate_2d.hpp).
#include "triangulation/mesh/locate_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "predicates/orient2d.hpp"

namespace exactmesh::triangulation {

BucketGrid2::BucketGrid2(std::span<const double> xy, std::span<const VertIdx> box_vertices,
                         std::span<const VertIdx> items, std::size_t per_item, double per_cell) {
    if (box_vertices.empty() || per_item == 0) return;
    const std::size_t count = items.size() / per_item;
    x0_ = y0_ = std::numeric_limits<double>::infinity();
    x1_ = y1_ = -std::numeric_limits<double>::infinity();
    for (const VertIdx v : box_vertices) {
        x0_ = std::min(x0_, xy[2 * std::size_t{v}]),
        y0_ = std::min(y0_, xy[2 * std::size_t{v} + 1]);
        x1_ = std::max(x1_, xy[2 * std::size_t{v}]),
        y1_ = std::max(y1_, xy[2 * std::size_t{v} + 1]);
    }
    // Widths in long double so that extents near the largest double do not overflow.
    const long double width = static_cast<long double>(x1_) - x0_,
                      height = static_cast<long double>(y1_) - y0_;
    auto range = [&](std::size_t item, std::uint32_t& c0, std::uint32_t& c1, std::uint32_t& r0,
                     std::uint32_t& r1) {
        c0 = columns_, c1 = 0, r0 = rows_, r1 = 0;
        for (std::size_t k = 0; k < per_item; ++k) {
            const std::size_t v = items[per_item * item + k];
            c0 = std::min(c0, column(xy[2 * v])), c1 = std::max(c1, column(xy[2 * v]));
            r0 = std::min(r0, row(xy[2 * v + 1])), r1 = std::max(r1, row(xy[2 * v + 1]));
        }
    };
    for (double cells = std::max(1.0, std::sqrt(static_cast<double>(count) / per_cell));;
         cells = std::max(1.0, cells / 2)) {
        cell_ = static_cast<double>(std::max(width, height) / cells);
        if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::numeric_limits<double>::max();
        columns_ = static_cast<std::uint32_t>(std::clamp<long double>(width / cell_, 0, 4095)) + 1;
        rows_ = static_cast<std::uint32_t>(std::clamp<long double>(height / cell_, 0, 4095)) + 1;
        if (cells == 1.0) break;
        std::uint64_t total = 0;
        for (std::size_t item = 0; item < count; ++item) {
            std::uint32_t c0, c1, r0, r1;
            range(item, c0, c1, r0, r1);
            total += std::uint64_t{c1 - c0 + 1} * (r1 - r0 + 1);
        }
        if (total <= 16 * std::uint64_t{count} + 4096) break;
    }
    start_.assign(std::size_t{columns_} * rows_ + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> next;
        if (pass == 1) {
            for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
            items_.resize(start_.back());
            next.assign(start_.begin(), start_.end() - 1);
        }
        for (std::size_t item = 0; item < count; ++item) {
            std::uint32_t c0, c1, r0, r1;
            range(item, c0, c1, r0, r1);
            for (std::uint32_t r = r0; r <= r1; ++r) {
                for (std::uint32_t c = c0; c <= c1; ++c) {
                    const std::size_t k = std::size_t{r} * columns_ + c;
                    if (pass == 0) {
                        ++start_[k + 1];
                    } else {
                        items_[next[k]++] = static_cast<std::uint32_t>(item);
                    }
                }
            }
        }
    }
}

std::uint32_t BucketGrid2::column(double x) const {
    const long double f = (static_cast<long double>(x) - x0_) / cell_;
    return static_cast<std::uint32_t>(std::clamp<long double>(f, 0, columns_ - 1));
}

std::uint32_t BucketGrid2::row(double y) const {
    const long double f = (static_cast<long double>(y) - y0_) / cell_;
    return static_cast<std::uint32_t>(std::clamp<long double>(f, 0, rows_ - 1));
}

TriangleLocator2::TriangleLocator2(const Triangulation2& mesh, double per_cell)
    : TriangleLocator2(mesh.xy, mesh.triangles, per_cell) {}

TriangleLocator2::TriangleLocator2(std::span<const double> xy, std::span<const VertIdx> triangles,
                                   double per_cell)
    : grid_(xy, triangles, triangles, 3, per_cell) {}

TriIdx TriangleLocator2::locate(std::span<const double> xy, std::span<const VertIdx> triangles,
                                double x, double y) const {
    // Outside the vertices' box no triangle can contain the point (exact comparisons; NaN
    // fails them).
    if (grid_.empty() || !grid_.in_box(x, y)) return kNone;
    const double p[2] = {x, y};
    for (const std::uint32_t t : grid_.cell(grid_.column(x), grid_.row(y))) {
        const double* a = &xy[2 * std::size_t{triangles[3 * std::size_t{t}]}];
        const double* b = &xy[2 * std::size_t{triangles[3 * std::size_t{t} + 1]}];
        const double* c = &xy[2 * std::size_t{triangles[3 * std::size_t{t} + 2]}];
        // The triangle's box first (exact comparisons: a point outside it is outside).
        if (x < std::min({a[0], b[0], c[0]}) || x > std::max({a[0], b[0], c[0]}) ||
            y < std::min({a[1], b[1], c[1]}) || y > std::max({a[1], b[1], c[1]}))
            continue;
        if (predicates::orient2d(a, b, p) != predicates::Sign::Negative &&
            predicates::orient2d(b, c, p) != predicates::Sign::Negative &&
            predicates::orient2d(c, a, p) != predicates::Sign::Negative) {
            return t;
        }
    }
    return kNone;
}

}  // namespace exactmesh::triangulation
