// SPDX-License-Identifier: MIT
// Tanemura-Merriam 2D (see tanemura_merriam_2d.hpp).
#include "triangulation/tanemura_merriam_2d.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "predicates/constructions.hpp"
#include "predicates/errors.hpp"
#include "triangulation/delaunay_2d_core.hpp"
#include "triangulation/spatial_sort.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// The front: directed edges a -> b whose left side is still empty, each with the half-edge on
/// its right (kNone for hull edges). Kept as short lists per origin vertex: vertices are in
/// Hilbert order and the front advances locally, so lookups stay in cache (a global hash
/// table made every lookup a cache miss).
class OpenEdges {
public:
    explicit OpenEdges(std::uint32_t vertex_count) : head_(vertex_count, kNone) {}

    void insert(VertIdx a, VertIdx b, EdgeIdx value) {
        std::uint32_t slot;
        if (free_ != kNone) {
            slot = free_;
            free_ = pool_[slot].next;
        } else {
            slot = static_cast<std::uint32_t>(pool_.size());
            pool_.push_back({});
        }
        pool_[slot] = {b, value, head_[a]};
        head_[a] = slot;
    }
    /// Removes a -> b and returns true (its value in `value`) if it is open.
    bool take(VertIdx a, VertIdx b, EdgeIdx& value) {
        for (std::uint32_t* link = &head_[a]; *link != kNone; link = &pool_[*link].next) {
            Entry& entry = pool_[*link];
            if (entry.to == b) {
                value = entry.value;
                const std::uint32_t slot = *link;
                *link = entry.next;
                pool_[slot].next = free_;
                free_ = slot;
                return true;
            }
        }
        return false;
    }

private:
    struct Entry {
        VertIdx to;
        EdgeIdx value;
        std::uint32_t next;
    };
    std::vector<std::uint32_t> head_;
    std::vector<Entry> pool_;
    std::uint32_t free_ = kNone;
};

/// Uniform grid over the points, in coordinates scaled by a power of two into about [0, 1]
/// (exact scaling; only the search uses these, never a decision).
class PointGrid {
public:
    PointGrid(const TriMesh2& mesh, const std::vector<bool>& alive, std::uint32_t alive_count) {
        const std::uint32_t n = mesh.vertex_count();
        double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
        for (VertIdx v = 0; v < n; ++v) {
            if (!alive[v]) continue;
            lo_x = std::min(lo_x, mesh.point(v)[0]);
            hi_x = std::max(hi_x, mesh.point(v)[0]);
            lo_y = std::min(lo_y, mesh.point(v)[1]);
            hi_y = std::max(hi_y, mesh.point(v)[1]);
        }
        const double magnitude = std::max({std::fabs(lo_x), std::fabs(hi_x), std::fabs(lo_y),
                                           std::fabs(hi_y), 1e-300});
        int exponent = 0;
        std::frexp(magnitude, &exponent);
        scale_ = std::ldexp(1.0, -exponent);  // |scaled| < 1, so differences cannot overflow
        min_x_ = lo_x * scale_;
        min_y_ = lo_y * scale_;
        const double width = hi_x * scale_ - min_x_, height = hi_y * scale_ - min_y_;
        const double cells = std::max(1.0, alive_count * 1.0);
        cell_ = std::sqrt(std::max(width * height, 1e-300) / cells);
        if (!(cell_ > 0)) cell_ = std::max(width, height);
        cell_ = std::max(cell_, std::max(width, height) / 4096.0);  // keep the grid bounded
        columns_ = static_cast<std::uint32_t>(width / cell_) + 1;
        rows_ = static_cast<std::uint32_t>(height / cell_) + 1;
        start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
        for (VertIdx v = 0; v < n; ++v) {
            if (alive[v]) ++start_[cell_of(mesh.point(v)) + 1];
        }
        for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        members_.resize(alive_count);
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        for (VertIdx v = 0; v < n; ++v) {
            if (alive[v]) members_[fill[cell_of(mesh.point(v))]++] = v;
        }
    }

    double scale() const { return scale_; }
    double cell_size() const { return cell_; }
    std::uint32_t columns() const { return columns_; }
    std::uint32_t rows() const { return rows_; }
    std::uint32_t column(double scaled_x) const { return clamp_index((scaled_x - min_x_) / cell_, columns_); }
    std::uint32_t row(double scaled_y) const { return clamp_index((scaled_y - min_y_) / cell_, rows_); }
    double column_start(std::uint32_t i) const { return min_x_ + i * cell_; }
    std::span<const VertIdx> cell(std::uint32_t i, std::uint32_t j) const {
        const std::size_t c = static_cast<std::size_t>(j) * columns_ + i;
        return {members_.data() + start_[c], members_.data() + start_[c + 1]};
    }

private:
    double scale_ = 1, min_x_ = 0, min_y_ = 0, cell_ = 1;
    std::uint32_t columns_ = 1, rows_ = 1;
    std::vector<std::uint32_t> start_;
    std::vector<VertIdx> members_;

    static std::uint32_t clamp_index(double t, std::uint32_t count) {
        if (!(t > 0)) return 0;
        if (!(t < count)) return count - 1;  // before the cast: huge values do not convert
        return static_cast<std::uint32_t>(t);
    }
    std::size_t cell_of(const double* p) const {
        return static_cast<std::size_t>(row(p[1] * scale_)) * columns_ + column(p[0] * scale_);
    }
};

class GiftWrapper {
public:
    GiftWrapper(detail::Delaunay2Core& core, const PointGrid& grid)
        : core_(core), mesh_(core.mesh), grid_(grid) {}

    /// The point c left of a -> b whose perturbed circle through a, b, c is empty.
    /// Circles through a and b form a pencil whose parts left of ab are nested, so once a
    /// candidate is known only the bounding box of its circle can hold a better one; a better
    /// candidate only shrinks that region, so one scan of the first box suffices.
    VertIdx third_vertex(VertIdx a, VertIdx b) {
        const double s = grid_.scale();
        const double* pa = mesh_.point(a);
        const double* pb = mesh_.point(b);
        const double mx = (pa[0] * s + pb[0] * s) / 2, my = (pa[1] * s + pb[1] * s) / 2;
        const std::uint32_t i0 = grid_.column(mx), j0 = grid_.row(my);
        const std::uint32_t max_ring = std::max(grid_.columns(), grid_.rows());
        VertIdx best = kNone;
        auto consider = [&](VertIdx d) {
            if (d == a || d == b) return;
            ++core_.counters.candidates;
            if (core_.orient(a, b, d) != Sign::Positive) return;
            if (best == kNone || core_.incircle(a, b, best, d) == Sign::Positive) best = d;
        };
        // Phase 1: rings around the midpoint until one holds a candidate (best of the ring).
        std::uint32_t seen = 0;
        for (std::uint32_t r = 0; r <= max_ring && best == kNone; ++r) {
            visit_ring(i0, j0, r, consider);
            seen = r;
        }
        EM_ASSERT(best != kNone);
        // Phase 2: the cells meeting the lens (best's circle left of ab) not yet seen, column by
        // column outwards from the midpoint's column; the lens is recomputed whenever best
        // improves, since the new lens lies inside the old one.
        double ox, oy, radius;
        bool bounded = circle(a, b, best, ox, oy, radius);
        VertIdx circle_of = best;
        const double ax = pa[0] * s, ay = pa[1] * s, bx = pb[0] * s, by = pb[1] * s;
        const double cell = grid_.cell_size();
        const std::uint32_t columns = grid_.columns();
        // Columns i0, i0+1, i0-1, i0+2, ...; a side is done once a column misses the circle,
        // since the lens only shrinks.
        bool right_done = false, left_done = false;
        for (std::uint32_t step = 0; step < 2 * columns && !(right_done && left_done); ++step) {
            const bool right = step % 2 == 0;
            if ((right && right_done) || (!right && left_done)) continue;
            const long long offset = right ? static_cast<long long>(step / 2)
                                           : -static_cast<long long>(step / 2 + 1);
            const long long column = static_cast<long long>(i0) + offset;
            if (column < 0 || column >= columns) {
                (right ? right_done : left_done) = true;
                continue;
            }
            const auto i = static_cast<std::uint32_t>(column);
            if (best != circle_of) {
                bounded = circle(a, b, best, ox, oy, radius);
                circle_of = best;
            }
            std::uint32_t lo_j = 0, hi_j = grid_.rows() - 1;
            if (bounded) {
                // Relative slack for the rounding of the centre, radius and cell assignment.
                const double margin = radius * 1e-9 + cell * 1e-9;
                const double x0 = grid_.column_start(i) - margin, x1 = x0 + cell + 2 * margin;
                const double dx = ox < x0 ? x0 - ox : (ox > x1 ? ox - x1 : 0.0);
                if (dx > radius + margin) {
                    if ((ox < x0) == right) (right ? right_done : left_done) = true;
                    continue;
                }
                const double half = std::sqrt(std::max(0.0, (radius + margin) * (radius + margin) - dx * dx));
                double y_lo = oy - half, y_hi = oy + half;
                // Clip by the half-plane left of a -> b over the column's x-interval.
                if (bx != ax) {
                    const double slope = (by - ay) / (bx - ax);
                    const double l0 = ay + (x0 - ax) * slope, l1 = ay + (x1 - ax) * slope;
                    // The line's rounding error grows with the values met (steep edges):
                    // a relative slack far above it keeps the clip conservative.
                    const double slack =
                        margin + 1e-9 * (std::fabs(l0) + std::fabs(l1) + std::fabs(ay));
                    if (bx > ax) {
                        y_lo = std::max(y_lo, std::min(l0, l1) - slack);
                    } else {
                        y_hi = std::min(y_hi, std::max(l0, l1) + slack);
                    }
                } else if ((by > ay && x0 > ax + margin) || (by < ay && x1 < ax - margin)) {
                    continue;
                }
                if (y_lo > y_hi) continue;
                lo_j = grid_.row(y_lo);
                hi_j = grid_.row(y_hi);
            }
            for (std::uint32_t j = lo_j; j <= hi_j; ++j) {
                const std::uint32_t ring = std::max(i > i0 ? i - i0 : i0 - i, j > j0 ? j - j0 : j0 - j);
                if (ring <= seen) continue;
                for (const VertIdx d : grid_.cell(i, j)) consider(d);
            }
        }
        return best;
    }

private:
    detail::Delaunay2Core& core_;
    TriMesh2& mesh_;
    const PointGrid& grid_;

    template <class Visit>
    void visit_ring(std::uint32_t i0, std::uint32_t j0, std::uint32_t r, Visit&& visit) const {
        const long long lo_i = static_cast<long long>(i0) - r, hi_i = static_cast<long long>(i0) + r;
        const long long lo_j = static_cast<long long>(j0) - r, hi_j = static_cast<long long>(j0) + r;
        const long long cols = grid_.columns(), rows = grid_.rows();
        auto cell = [&](long long i, long long j) {
            if (i < 0 || j < 0 || i >= cols || j >= rows) return;
            for (const VertIdx d : grid_.cell(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j))) visit(d);
        };
        if (r == 0) {
            cell(i0, j0);
            return;
        }
        for (long long i = lo_i; i <= hi_i; ++i) {
            cell(i, lo_j);
            cell(i, hi_j);
        }
        for (long long j = lo_j + 1; j < hi_j; ++j) {
            cell(lo_i, j);
            cell(hi_i, j);
        }
    }

    /// The circle through a, b, c in scaled units: a double circumcenter when the triangle is
    /// well shaped (relative error far below the margin used), the correctly rounded
    /// construction otherwise. False when the centre is beyond the double range.
    bool circle(VertIdx a, VertIdx b, VertIdx c, double& ox, double& oy, double& radius) const {
        const double s = grid_.scale();
        const double* pa = mesh_.point(a);
        const double* pb = mesh_.point(b);
        const double* pc = mesh_.point(c);
        const double bx = (pb[0] - pa[0]) * s, by = (pb[1] - pa[1]) * s;
        const double cx = (pc[0] - pa[0]) * s, cy = (pc[1] - pa[1]) * s;
        const double det = 2 * (bx * cy - by * cx);
        const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        if (std::fabs(det) > 1e-4 * std::sqrt(b2 * c2)) {
            ox = pa[0] * s + (cy * b2 - by * c2) / det;
            oy = pa[1] * s + (bx * c2 - cx * b2) / det;
        } else {
            try {
                const auto o = predicates::circumcenter(pa, pb, pc);
                ox = o[0] * s;
                oy = o[1] * s;
            } catch (const GeometryError&) {
                return false;
            }
        }
        // Scaled coordinates are below 1 in magnitude: no overflow without hypot.
        const double rx = ox - pa[0] * s, ry = oy - pa[1] * s;
        radius = std::sqrt(rx * rx + ry * ry);
        return std::isfinite(radius) && std::isfinite(ox) && std::isfinite(oy);
    }
};

/// Convex hull, counter-clockwise, every point on the boundary kept (collinear ones too), by
/// Andrew's monotone chain with exact orientation. `points` must be distinct and sorted by
/// (x, y). Requires at least 3 non-collinear points.
std::vector<VertIdx> convex_hull(detail::Delaunay2Core& core, const std::vector<VertIdx>& points) {
    std::vector<VertIdx> hull;
    auto chain = [&](auto first, auto last) {
        const std::size_t base = hull.size();
        for (auto it = first; it != last; ++it) {
            while (hull.size() >= base + 2 &&
                   core.orient(hull[hull.size() - 2], hull.back(), *it) == Sign::Negative) {
                hull.pop_back();
            }
            hull.push_back(*it);
        }
        hull.pop_back();  // the last point starts the other chain
    };
    chain(points.begin(), points.end());
    chain(points.rbegin(), points.rend());
    return hull;
}

}  // namespace

Delaunay2Result tanemura_merriam_2d(std::span<const double> xy, const Delaunay2Options&) {
    // Vertices in Hilbert order, so that the points of a grid cell and of neighbouring cells
    // are close in memory: the candidate search is memory-bound otherwise.
    validate_points_2d(xy);
    std::vector<VertIdx> hilbert(xy.size() / 2);
    for (VertIdx v = 0; v < hilbert.size(); ++v) hilbert[v] = v;
    hilbert_sort_2d(xy, hilbert);
    detail::Delaunay2Core core(xy, std::move(hilbert));
    std::vector<bool> skip;
    if (!core.make_first_triangle(skip)) return core.collinear_result();
    // Gift wrapping needs distinct points: merge duplicates first (sorted by coordinates, the
    // smallest caller index kept), then drop the first triangle, which only proved that the
    // points are not all collinear.
    TriMesh2& mesh = core.mesh;
    mesh.tv.clear();
    mesh.twin.clear();
    mesh.free_triangles.clear();
    const std::uint32_t n = mesh.vertex_count();
    std::vector<VertIdx> order(n);
    for (VertIdx v = 0; v < n; ++v) order[v] = v;
    std::sort(order.begin(), order.end(), [&mesh, &core](VertIdx a, VertIdx b) {
        const double* p = mesh.point(a);
        const double* q = mesh.point(b);
        return p[0] < q[0] ||
               (p[0] == q[0] && (p[1] < q[1] || (p[1] == q[1] && core.input_index[a] < core.input_index[b])));
    });
    std::vector<bool> alive(n, true);
    std::vector<VertIdx> distinct;
    distinct.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0 && core.same_point(order[i - 1], order[i])) {
            alive[order[i]] = false;
            core.merged_into[core.input_index[order[i]]] = core.merged_into[core.input_index[order[i - 1]]];
            ++core.counters.duplicates;
        } else {
            distinct.push_back(order[i]);
        }
    }
    const std::vector<VertIdx> hull = convex_hull(core, distinct);
    const PointGrid grid(mesh, alive, static_cast<std::uint32_t>(distinct.size()));
    GiftWrapper wrapper(core, grid);
    // Front: directed edges whose left side is still empty, mapped to the half-edge on their
    // right (kNone for hull edges, whose right side is the outside).
    OpenEdges open(n);
    std::vector<std::pair<VertIdx, VertIdx>> stack;
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const VertIdx a = hull[k], b = hull[(k + 1) % hull.size()];
        open.insert(a, b, kNone);
        stack.emplace_back(a, b);
    }
    mesh.tv.reserve(6 * distinct.size());
    mesh.twin.reserve(6 * distinct.size());
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        EdgeIdx outside;
        if (!open.take(a, b, outside)) continue;  // closed meanwhile by another triangle
        const VertIdx c = wrapper.third_vertex(a, b);
        const TriIdx t = mesh.new_triangle();
        mesh.tv[3 * t] = a;
        mesh.tv[3 * t + 1] = b;
        mesh.tv[3 * t + 2] = c;
        if (outside != kNone) mesh.link(3 * t, outside);
        // Edges b -> c and c -> a: close them if open, else open their reverse.
        const VertIdx ends[2][2] = {{b, c}, {c, a}};
        for (unsigned k = 0; k < 2; ++k) {
            const VertIdx u = ends[k][0], v = ends[k][1];
            EdgeIdx other;
            if (open.take(u, v, other)) {
                if (other != kNone) mesh.link(3 * t + 1 + k, other);
            } else {
                open.insert(v, u, 3 * t + 1 + k);
                stack.emplace_back(v, u);
            }
        }
    }
    return core.take_result();
}

}  // namespace exactmesh::triangulation
