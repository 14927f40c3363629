// SPDX-License-Identifier: MIT
// Background size mesh (see background_size_2d.hpp). Point location: a bucket grid of
// triangles, exact orient2d; the nearest boundary edge of a point outside the mesh: a ring
// search over a second bucket grid, stopped by a lower bound on the distance to the cells not
// yet searched.
#include "generators/sizing/background_size_2d.hpp"
#include "base/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

#include "predicates/orient2d.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;

namespace {

std::string item_prefix(BackgroundMeshError::Item item, std::size_t index) {
    switch (item) {
        case BackgroundMeshError::Item::Vertex:
            return "vertex " + std::to_string(index) + ": ";
        case BackgroundMeshError::Item::Triangle:
            return "triangle " + std::to_string(index) + ": ";
        case BackgroundMeshError::Item::Mesh:
            break;
    }
    return "";
}

}  // namespace

BackgroundMeshError::BackgroundMeshError(Item item, std::size_t index, const std::string& detail,
                                         SourceLocation where)
    : InputError("background mesh: " + item_prefix(item, index) + detail, where),
      item_(item),
      index_(index),
      detail_(detail) {}

BackgroundSizeMesh2::BackgroundSizeMesh2(std::vector<double> xy, std::vector<double> sizes,
                                         std::vector<std::uint32_t> triangles) {
    using Item = BackgroundMeshError::Item;
    if (xy.size() % 2 != 0) throw BackgroundMeshError(Item::Mesh, 0, "odd number of coordinates");
    const std::size_t vertices = xy.size() / 2;
    if (vertices >= tri::kNone)
        throw BackgroundMeshError(Item::Mesh, 0, "more than 2^32 - 2 vertices");
    if (sizes.size() != vertices) {
        throw BackgroundMeshError(
            Item::Mesh, 0,
            std::to_string(vertices) + " vertices but " + std::to_string(sizes.size()) + " sizes");
    }
    if (triangles.size() % 3 != 0)
        throw BackgroundMeshError(Item::Mesh, 0, "triangle indices not a multiple of 3");
    if (triangles.empty()) throw BackgroundMeshError(Item::Mesh, 0, "no triangle");
    if (triangles.size() / 3 >= tri::kNone)
        throw BackgroundMeshError(Item::Mesh, 0, "more than 2^32 - 2 triangles");
    for (std::size_t v = 0; v < vertices; ++v) {
        if (!std::isfinite(xy[2 * v]) || !std::isfinite(xy[2 * v + 1])) {
            throw BackgroundMeshError(Item::Vertex, v,
                                      "non-finite coordinate (" + format_number(xy[2 * v]) + ", " +
                                          format_number(xy[2 * v + 1]) + ")");
        }
        if (!(std::isfinite(sizes[v]) && sizes[v] > 0)) {
            throw BackgroundMeshError(
                Item::Vertex, v,
                "size must be a finite number > 0 (got " + format_number(sizes[v]) + ")");
        }
    }
    const std::size_t count = triangles.size() / 3;
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t* v = &triangles[3 * t];
        const std::string names = " (" + std::to_string(v[0]) + " " + std::to_string(v[1]) + " " +
                                  std::to_string(v[2]) + ")";
        for (int k = 0; k < 3; ++k) {
            if (v[k] >= vertices) {
                throw BackgroundMeshError(Item::Triangle, t,
                                          "vertex index " + std::to_string(v[k]) +
                                              " out of range (" + std::to_string(vertices) +
                                              " vertices)");
            }
        }
        if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) {
            throw BackgroundMeshError(Item::Triangle, t, "repeats a vertex" + names);
        }
        const predicates::Sign sign =
            predicates::orient2d(&xy[2 * v[0]], &xy[2 * v[1]], &xy[2 * v[2]]);
        if (sign == predicates::Sign::Negative)
            throw BackgroundMeshError(Item::Triangle, t, "inverted (clockwise)" + names);
        if (sign == predicates::Sign::Zero)
            throw BackgroundMeshError(Item::Triangle, t, "degenerate (collinear vertices)" + names);
    }
    // Directed edges, sorted: a repeat means two triangles on the same side of one edge; an
    // edge whose reverse is absent bounds the mesh.
    struct Directed {
        std::uint64_t key;
        std::uint32_t triangle;
    };
    std::vector<Directed> edges;
    edges.reserve(triangles.size());
    for (std::size_t t = 0; t < count; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint64_t a = triangles[3 * t + k], b = triangles[3 * t + (k + 1) % 3];
            edges.push_back({a << 32 | b, static_cast<std::uint32_t>(t)});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const Directed& p, const Directed& q) {
        return p.key != q.key ? p.key < q.key : p.triangle < q.triangle;
    });
    for (std::size_t i = 1; i < edges.size(); ++i) {
        if (edges[i].key == edges[i - 1].key) {
            throw BackgroundMeshError(Item::Triangle, edges[i].triangle,
                                      "overlaps triangle " + std::to_string(edges[i - 1].triangle) +
                                          " (both have the edge " +
                                          std::to_string(edges[i].key >> 32) + " -> " +
                                          std::to_string(edges[i].key & 0xFFFFFFFFu) + ")");
        }
    }
    for (const Directed& e : edges) {
        const std::uint64_t reverse = (e.key & 0xFFFFFFFFu) << 32 | e.key >> 32;
        const bool found =
            std::binary_search(edges.begin(), edges.end(), Directed{reverse, 0},
                               [](const Directed& p, const Directed& q) { return p.key < q.key; });
        if (!found) {
            boundary_.push_back(static_cast<std::uint32_t>(e.key >> 32));
            boundary_.push_back(static_cast<std::uint32_t>(e.key & 0xFFFFFFFFu));
        }
    }

    mesh_.xy = std::move(xy);
    mesh_.triangles = std::move(triangles);
    sizes_ = std::move(sizes);
    boxes_.resize(4 * count);
    for (std::size_t t = 0; t < count; ++t) {
        const double* a = mesh_.point(mesh_.triangles[3 * t]);
        const double* b = mesh_.point(mesh_.triangles[3 * t + 1]);
        const double* c = mesh_.point(mesh_.triangles[3 * t + 2]);
        boxes_[4 * t] = std::min({a[0], b[0], c[0]}),
                   boxes_[4 * t + 1] = std::min({a[1], b[1], c[1]});
        boxes_[4 * t + 2] = std::max({a[0], b[0], c[0]}),
                       boxes_[4 * t + 3] = std::max({a[1], b[1], c[1]});
    }
    locator_ = tri::TriangleLocator2(mesh_, 0.5);
    edge_buckets_ = tri::BucketGrid2(mesh_.xy, mesh_.triangles, boundary_, 2, 1.0);
}

tri::TriIdx BackgroundSizeMesh2::locate(double x, double y) const {
    return locator_.locate(mesh_, x, y);
}

double BackgroundSizeMesh2::interpolate(tri::TriIdx t, double x, double y) const {
    const std::uint32_t* v = &mesh_.triangles[3 * std::size_t{t}];
    const double* a = mesh_.point(v[0]);
    const double* b = mesh_.point(v[1]);
    const double* c = mesh_.point(v[2]);
    // The vectors from a scaled exactly by the power of two that brings the triangle's box to
    // [1, 2): the areas neither overflow nor underflow, and a mesh scaled by 2^k interpolates
    // the same, bit for bit (scale invariance of the generators' default size).
    const double* box = &boxes_[4 * std::size_t{t}];
    const double extent = std::max(box[2] - box[0], box[3] - box[1]);
    const int shift = extent > 0 && std::isfinite(extent) ? -std::ilogb(extent) : 0;
    const auto scaled = [shift](double d) { return std::ldexp(d, shift); };
    const double bx = scaled(b[0] - a[0]), by = scaled(b[1] - a[1]);
    const double cx = scaled(c[0] - a[0]), cy = scaled(c[1] - a[1]);
    const double px = scaled(x - a[0]), py = scaled(y - a[1]);
    const double area = bx * cy - by * cx;
    const double sa = sizes_[v[0]], sb = sizes_[v[1]], sc = sizes_[v[2]];
    if (area > 0) {
        // Barycentric coordinates of (x, y): the sub-areas opposite b and c over the whole.
        const double lb = (cx * py - cy * px) / -area;
        const double lc = (bx * py - by * px) / area;
        const double s = sa + lb * (sb - sa) + lc * (sc - sa);
        // The point is inside (exactly); rounding may carry s a few ulps past the vertex values.
        if (!std::isnan(s)) return std::clamp(s, std::min({sa, sb, sc}), std::max({sa, sb, sc}));
    }
    // A sliver: counter-clockwise by exact orient2d, but flat in doubles (its area rounds to 0,
    // or the coordinates' ratios overflow into inf * 0). Barycentric coordinates mean nothing
    // there (0 / 0 gave NaN sizes: fuzz_adaptation_2d, tests/data/fuzz/
    // adaptation_2d_local_remesh_flat_background_triangle.bin); the value on the nearest of its
    // sides, linear along it, is within the corners' values and agrees with the neighbour there.
    const double ex[3] = {0, bx, cx}, ey[3] = {0, by, cy}, es[3] = {sa, sb, sc};
    double best2 = std::numeric_limits<double>::infinity(), value = sa;
    for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const double dx = ex[j] - ex[k], dy = ey[j] - ey[k], length2 = dx * dx + dy * dy;
        const double f =
            length2 > 0 ? std::clamp(((px - ex[k]) * dx + (py - ey[k]) * dy) / length2, 0.0, 1.0)
                        : 0.0;
        const double qx = px - (ex[k] + f * dx), qy = py - (ey[k] + f * dy);
        const double d2 = qx * qx + qy * qy;
        if (d2 < best2) {
            best2 = d2;
            value = std::clamp(es[k] + f * (es[j] - es[k]), std::min(es[k], es[j]),
                               std::max(es[k], es[j]));
        }
    }
    return value;
}

double BackgroundSizeMesh2::nearest_boundary_value(double x, double y) const {
    // q' = the nearest point of the grid's box to q. For every point p of the box,
    // |q - p|^2 >= |q - q'|^2 + |q' - p|^2 (projection onto a convex set), and a cell k rings
    // away from q's cell is at least (k - 1) cells from q'.
    // Distances in units of 2^-shift, the power of two at the cell width or, for a point far
    // outside the grid, at its distance from it: the squares do not overflow (a point 2^520
    // cells away squared to infinity, no edge was ever nearer than that, and the size came out
    // 0: fuzz_adaptation_2d, tests/data/fuzz/adaptation_2d_remesh_zero_size_far_vertex.bin), an
    // edge whose square underflows is a point at that scale, and a mesh scaled by 2^k finds the
    // same edge, bit for bit.
    const tri::BucketGrid2& g = edge_buckets_;
    const double cell = g.cell_width();
    const std::uint32_t columns = g.columns(), rows = g.rows();
    const double qx = std::clamp(x, g.x0(), g.x0() + columns * cell);
    const double qy = std::clamp(y, g.y0(), g.y0() + rows * cell);
    const double reach =
        std::max({cell, std::abs(0.5 * x - 0.5 * qx), std::abs(0.5 * y - 0.5 * qy)});
    const int shift = std::isfinite(reach) && reach > 0 ? -std::ilogb(reach) : 0;
    const auto scaled = [shift](double d) { return std::ldexp(d, shift); };
    const double ox = scaled(x - qx), oy = scaled(y - qy);
    const double outside2 = ox * ox + oy * oy;
    const auto column = static_cast<std::int64_t>(g.column(qx));
    const auto row = static_cast<std::int64_t>(g.row(qy));
    double best2 = std::numeric_limits<double>::infinity(), value = 0;
    auto visit = [&](std::int64_t c, std::int64_t r) {
        if (c < 0 || r < 0 || c >= columns || r >= rows) return;
        for (const std::uint32_t e :
             g.cell(static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(r))) {
            const std::uint32_t va = boundary_[2 * std::size_t{e}],
                                vb = boundary_[2 * std::size_t{e} + 1];
            const double* a = mesh_.point(va);
            const double* b = mesh_.point(vb);
            const double dx = b[0] - a[0], dy = b[1] - a[1];
            const double sx = scaled(dx), sy = scaled(dy), length2 = sx * sx + sy * sy;
            // An edge whose scaled length squared underflows (far shorter than the distance to a
            // far point) is a point at this scale: no 0 / 0.
            const double t =
                length2 > 0 ? std::clamp((scaled(x - a[0]) * sx + scaled(y - a[1]) * sy) / length2,
                                         0.0, 1.0)
                            : 0.0;
            const double ex = scaled(x - (a[0] + t * dx)), ey = scaled(y - (a[1] + t * dy));
            const double d2 = ex * ex + ey * ey;
            if (d2 < best2) {
                best2 = d2;
                value =
                    std::clamp(sizes_[va] + t * (sizes_[vb] - sizes_[va]),
                               std::min(sizes_[va], sizes_[vb]), std::max(sizes_[va], sizes_[vb]));
            }
        }
    };
    const std::int64_t rings = std::max(columns, rows);
    for (std::int64_t k = 0; k <= rings; ++k) {
        if (k >= 1) {
            const double gap = static_cast<double>(k - 1) * scaled(cell);
            if (outside2 + gap * gap > best2) break;
        }
        if (k == 0) {
            visit(column, row);
            continue;
        }
        for (std::int64_t c = column - k; c <= column + k; ++c)
            visit(c, row - k), visit(c, row + k);
        for (std::int64_t r = row - k + 1; r <= row + k - 1; ++r)
            visit(column - k, r), visit(column + k, r);
    }
    return value;
}

double BackgroundSizeMesh2::operator()(double x, double y) const {
    const tri::TriIdx t = locate(x, y);
    if (t != tri::kNone) return interpolate(t, x, y);
    return nearest_boundary_value(x, y);
}

}  // namespace exactmesh::generators
