// SPDX-License-Identifier: MIT
// Size quadtree (see size_quadtree_2d.hpp). Points are addressed by integer coordinates on the
// grid of resolution 2^(max_depth + 1) over the root square (the centre and edge midpoints of a
// deepest cell included), so that the field values of shared corners are computed once and
// every corner's identity is exact.
#include "generators/sizing/size_quadtree_2d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

namespace {

constexpr std::uint32_t kNone = triangulation::kNone;

/// Build-time state: nodes with their level and integer position, the field cache.
struct Builder {
    const std::function<double(double, double)>& field;
    SizeBox box;
    double x0, y0, side;
    int units;  // the resolution exponent: points are integers in [0, 2^units]
    const QuadtreeSizeOptions& options;
    Builder(const std::function<double(double, double)>& f, const SizeBox& b, double x, double y,
            double s, int u, const QuadtreeSizeOptions& o)
        : field(f), box(b), x0(x), y0(y), side(s), units(u), options(o) {}
    struct Cell {
        std::uint32_t child = kNone;
        int level = 0;
        std::uint64_t ix = 0, iy = 0;
    };
    std::vector<Cell> cells{Cell{}};
    std::uint64_t leaves = 1;
    std::unordered_map<std::uint64_t, double> cache;

    std::uint64_t key(std::uint64_t x, std::uint64_t y) const { return x << 32 | y; }
    double coordinate(double origin, std::uint64_t unit) const {
        return origin + side * std::ldexp(static_cast<double>(unit), -units);
    }
    double value(std::uint64_t x, std::uint64_t y) {
        const auto [it, added] = cache.try_emplace(key(x, y), 0.0);
        if (added) {
            const double px = std::clamp(coordinate(x0, x), box.x0, box.x1);
            const double py = std::clamp(coordinate(y0, y), box.y0, box.y1);
            const double s = field(px, py);
            if (!(std::isfinite(s) && s > 0)) {
                cache.erase(it);
                throw InputError("size quadtree: the size field is " + format_number(s) + " at (" +
                                 format_number(px) + ", " + format_number(py) +
                                 "); it must be finite and > 0 in the box");
            }
            it->second = s;
        }
        return it->second;
    }
    std::uint64_t unit_size(int level) const { return std::uint64_t{1} << (units - level); }
    bool outside_box(const Cell& c) const {
        const std::uint64_t u = unit_size(c.level);
        return coordinate(x0, c.ix * u) >= box.x1 || coordinate(y0, c.iy * u) >= box.y1;
    }
    bool needs_split(const Cell& c) {
        if (outside_box(c)) return false;
        const std::uint64_t u = unit_size(c.level), h = u / 2;
        const std::uint64_t x = c.ix * u, y = c.iy * u;
        const double c00 = value(x, y), c10 = value(x + u, y), c01 = value(x, y + u),
                     c11 = value(x + u, y + u);
        const double probe[5][2] = {{0.25 * (c00 + c10 + c01 + c11), value(x + h, y + h)},
                                    {0.5 * (c00 + c10), value(x + h, y)},
                                    {0.5 * (c01 + c11), value(x + h, y + u)},
                                    {0.5 * (c00 + c01), value(x, y + h)},
                                    {0.5 * (c10 + c11), value(x + u, y + h)}};
        double smallest = std::min({c00, c10, c01, c11});
        for (const auto& [interpolated, exact] : probe) {
            if (std::fabs(exact - interpolated) > options.tolerance * exact) return true;
            smallest = std::min(smallest, exact);
        }
        return options.cell_factor > 0 &&
               std::ldexp(side, -c.level) > options.cell_factor * smallest;
    }
    void split(std::uint32_t n) {
        const Cell c = cells[n];
        if (c.level >= options.max_depth) {
            const double u = std::ldexp(side, -c.level);
            throw GeometryError("size quadtree: a cell at the maximum depth " +
                                std::to_string(options.max_depth) + " near (" +
                                format_number(x0 + (static_cast<double>(c.ix) + 0.5) * u) + ", " +
                                format_number(y0 + (static_cast<double>(c.iy) + 0.5) * u) +
                                ") still needs splitting (the size field varies too fast there)");
        }
        leaves += 3;
        if (leaves > options.max_leaves) {
            throw GeometryError("size quadtree: more than " + std::to_string(options.max_leaves) +
                                " leaves (raise max_leaves, the tolerance or the sizes)");
        }
        cells[n].child = static_cast<std::uint32_t>(cells.size());
        for (std::uint64_t q = 0; q < 4; ++q) {
            cells.push_back({kNone, c.level + 1, 2 * c.ix + (q & 1), 2 * c.iy + (q >> 1)});
        }
    }
    /// The deepest cell containing the cell (level, ix, iy), no deeper than `level`.
    std::uint32_t deepest(int level, std::uint64_t ix, std::uint64_t iy) const {
        std::uint32_t n = 0;
        while (cells[n].child != kNone && cells[n].level < level) {
            const int shift = level - cells[n].level - 1;
            n = cells[n].child +
                static_cast<std::uint32_t>(((ix >> shift) & 1) + 2 * ((iy >> shift) & 1));
        }
        return n;
    }
};

/// Grid cells per side of the root square sampled by estimated_leaves.
constexpr int kEstimateGrid = 128;

/// An estimate from samples of the leaves the cell-factor rule alone asks for: at the centre
/// of each of kEstimateGrid^2 equal parts of the root square (those whose lower-left corner
/// lies in the box: the others are never split), the side a of the coarsest level at or below
/// cell_factor times the field there, and the part's area over a^2 (a fraction of a leaf where
/// a is larger than the part). A leaf's side is at most cell_factor times the smallest of its
/// nine samples, its centre's among them, so where the field is smooth at the grid's scale the
/// tree has at least about this many leaves (the tolerance rule and the 2:1 balance add more).
/// Levels come from the quotient side / (cell_factor s): scaling the box and the field by 2^k
/// changes nothing.
double estimated_leaves(const std::function<double(double, double)>& field, const SizeBox& box,
                        double side, const QuadtreeSizeOptions& options) {
    if (!(options.cell_factor > 0)) return 1;
    const double part = side / kEstimateGrid;
    double total = 0;
    for (int j = 0; j < kEstimateGrid; ++j) {
        const double y = box.y0 + part * j;
        if (y >= box.y1) break;
        for (int i = 0; i < kEstimateGrid; ++i) {
            const double x = box.x0 + part * i;
            if (x >= box.x1) break;
            const double px = std::min(x + 0.5 * part, box.x1);
            const double py = std::min(y + 0.5 * part, box.y1);
            const double s = field(px, py);
            if (!(std::isfinite(s) && s > 0)) {
                throw InputError("size quadtree: the size field is " + format_number(s) + " at (" +
                                 format_number(px) + ", " + format_number(py) +
                                 "); it must be finite and > 0 in the box");
            }
            // The level of a leaf of side at most cell_factor s: side 2^-level.
            const double ratio = side / (options.cell_factor * s);
            int level = 0;
            if (ratio > 1) level = std::min(options.max_depth, std::ilogb(ratio) + 1);
            if (ratio > 1 && std::ldexp(1.0, level - 1) >= ratio) --level;  // ratio a power of 2
            // Leaves of side 2^-level in a part of side 2^-7: 4^(level - 7) (fractional above).
            total += std::ldexp(1.0, 2 * level) / (double{kEstimateGrid} * kEstimateGrid);
        }
    }
    return total;
}

}  // namespace

SizeQuadtree2::SizeQuadtree2(const std::function<double(double, double)>& field, const SizeBox& box,
                             const QuadtreeSizeOptions& options)
    : box_(box) {
    if (!(std::isfinite(box.x0) && std::isfinite(box.y0) && std::isfinite(box.x1) &&
          std::isfinite(box.y1) && box.x0 < box.x1 && box.y0 < box.y1)) {
        throw InputError("size quadtree: the box must be finite with x0 < x1 and y0 < y1");
    }
    if (!(std::isfinite(box.x1 - box.x0) && std::isfinite(box.y1 - box.y0))) {
        throw InputError("size quadtree: the box is too large (its width overflows)");
    }
    if (!(options.tolerance > 0 && std::isfinite(options.tolerance))) {
        throw InputError("size quadtree: the tolerance must be a finite number > 0 (got " +
                         format_number(options.tolerance) + ")");
    }
    if (!(options.cell_factor >= 0 && std::isfinite(options.cell_factor))) {
        throw InputError("size quadtree: the cell factor must be a finite number >= 0 (got " +
                         format_number(options.cell_factor) + ")");
    }
    if (options.max_depth < 1 || options.max_depth > 30) {
        throw InputError("size quadtree: max_depth must be in [1, 30] (got " +
                         std::to_string(options.max_depth) + ")");
    }
    if (options.max_leaves < 4) throw InputError("size quadtree: max_leaves must be at least 4");
    x0_ = box.x0;
    y0_ = box.y0;
    side_ = std::max(box.x1 - box.x0, box.y1 - box.y0);
    // A field asking for far more leaves than the budget fails at once with the estimate,
    // not after building millions of them (a uniform size of 3e-4 on the unit box: 5.7 s to
    // the budget's error, 850 MB, before this estimate).
    const double estimate = estimated_leaves(field, box, side_, options);
    if (estimate > options.max_leaves) {
        throw GeometryError("size quadtree: the size field asks for about " +
                            format_approximate(estimate, 3) + " leaves, more than the budget of " +
                            std::to_string(options.max_leaves) +
                            " (raise max_leaves, the cell factor or the sizes)");
    }
    Builder b(field, box, x0_, y0_, side_, options.max_depth + 1, options);

    // Refinement by the field, depth first.
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const std::uint32_t n = stack.back();
        stack.pop_back();
        if (!b.needs_split(b.cells[n])) continue;
        b.split(n);
        for (std::uint32_t q = 0; q < 4; ++q) stack.push_back(b.cells[n].child + q);
    }

    // 2:1 balance, finest level first: a leaf's edge neighbour more than one level coarser is
    // split (until it is not); the leaves this creates are at most one level below the leaf
    // being processed, so they are handled when their level comes.
    int finest = 0;
    for (const auto& c : b.cells) finest = std::max(finest, c.level);
    std::vector<std::vector<std::uint32_t>> by_level(static_cast<std::size_t>(finest) + 1);
    for (std::uint32_t n = 0; n < b.cells.size(); ++n) {
        if (b.cells[n].child == kNone)
            by_level[static_cast<std::size_t>(b.cells[n].level)].push_back(n);
    }
    for (int level = finest; level >= 2; --level) {
        const std::uint64_t count = std::uint64_t{1} << level;
        for (std::size_t i = 0; i < by_level[static_cast<std::size_t>(level)].size(); ++i) {
            const std::uint32_t n = by_level[static_cast<std::size_t>(level)][i];
            if (b.cells[n].child != kNone) continue;
            const auto ix = static_cast<std::int64_t>(b.cells[n].ix),
                       iy = static_cast<std::int64_t>(b.cells[n].iy);
            const std::int64_t around[4][2] = {
                {ix - 1, iy}, {ix + 1, iy}, {ix, iy - 1}, {ix, iy + 1}};
            for (const auto& [nx, ny] : around) {
                if (nx < 0 || ny < 0 || nx >= static_cast<std::int64_t>(count) ||
                    ny >= static_cast<std::int64_t>(count)) {
                    continue;
                }
                for (;;) {
                    const std::uint32_t m = b.deepest(level, static_cast<std::uint64_t>(nx),
                                                      static_cast<std::uint64_t>(ny));
                    if (b.cells[m].child != kNone || b.cells[m].level >= level - 1) break;
                    b.split(m);
                    for (std::uint32_t q = 0; q < 4; ++q) {
                        const std::uint32_t c = b.cells[m].child + q;
                        by_level[static_cast<std::size_t>(b.cells[c].level)].push_back(c);
                    }
                }
            }
        }
    }

    // Corner values, coarse leaves first: a corner in the middle of a coarser leaf's edge takes
    // the mean of that edge's end values (already known: they are corners of a coarser leaf).
    std::vector<std::uint32_t> leaf_cells;
    for (std::uint32_t n = 0; n < b.cells.size(); ++n) {
        if (b.cells[n].child == kNone) leaf_cells.push_back(n);
    }
    std::stable_sort(leaf_cells.begin(), leaf_cells.end(), [&](std::uint32_t p, std::uint32_t q) {
        return b.cells[p].level < b.cells[q].level;
    });
    std::unordered_map<std::uint64_t, double> resolved;
    const int finest_units = b.units;
    const std::uint64_t extent = std::uint64_t{1} << finest_units;
    auto corner_value = [&](const Builder::Cell& leaf, std::uint64_t px, std::uint64_t py) {
        if (const auto it = resolved.find(b.key(px, py)); it != resolved.end()) return it->second;
        double value = 0;
        bool hanging = false;
        for (int q = 0; q < 4 && !hanging; ++q) {
            const std::int64_t cx = static_cast<std::int64_t>(px) - ((q & 1) ? 0 : 1);
            const std::int64_t cy = static_cast<std::int64_t>(py) - ((q & 2) ? 0 : 1);
            if (cx < 0 || cy < 0 || cx >= static_cast<std::int64_t>(extent) ||
                cy >= static_cast<std::int64_t>(extent)) {
                continue;
            }
            const Builder::Cell& m = b.cells[b.deepest(finest_units, static_cast<std::uint64_t>(cx),
                                                       static_cast<std::uint64_t>(cy))];
            if (m.level >= leaf.level) continue;
            const std::uint64_t u = b.unit_size(m.level), mx = m.ix * u, my = m.iy * u;
            const bool on_x = px == mx || px == mx + u, on_y = py == my || py == my + u;
            if (on_x && on_y) continue;  // a corner of m too
            hanging = true;
            std::uint64_t ax = px, ay = py, bx = px, by = py;
            if (on_x) {
                EM_ASSERT(py == my + u / 2);
                ay = my, by = my + u;
            } else {
                EM_ASSERT(on_y && px == mx + u / 2);
                ax = mx, bx = mx + u;
            }
            const auto a = resolved.find(b.key(ax, ay)), e = resolved.find(b.key(bx, by));
            EM_ASSERT(a != resolved.end() && e != resolved.end());
            value = 0.5 * (a->second + e->second);
        }
        if (!hanging) value = b.value(px, py);
        resolved.emplace(b.key(px, py), value);
        return value;
    };
    nodes_.resize(b.cells.size());
    leaves_.reserve(leaf_cells.size());
    for (std::uint32_t n = 0; n < b.cells.size(); ++n) nodes_[n] = {b.cells[n].child, kNone};
    for (const std::uint32_t n : leaf_cells) {
        const Builder::Cell& c = b.cells[n];
        const std::uint64_t u = b.unit_size(c.level), x = c.ix * u, y = c.iy * u;
        Leaf leaf{b.coordinate(x0_, x),
                  b.coordinate(y0_, y),
                  b.coordinate(x0_, x + u),
                  b.coordinate(y0_, y + u),
                  c.level,
                  {corner_value(c, x, y), corner_value(c, x + u, y), corner_value(c, x, y + u),
                   corner_value(c, x + u, y + u)}};
        nodes_[n].leaf = static_cast<std::uint32_t>(leaves_.size());
        leaves_.push_back(leaf);
        depth_ = std::max(depth_, c.level);
    }
}

std::uint32_t SizeQuadtree2::descend(double x, double y, double& fx, double& fy) const {
    // The fractions of the root square in 52-bit fixed point (truncated below 2^-52; a depth of
    // at most 30 reads only the top 30 bits, so the leaf is the one the rounded fraction lies
    // in); each level reads one bit of each, without a branch, and the bits left over are the
    // position in the leaf.
    constexpr int kBits = 52;
    constexpr std::uint64_t kTop = (std::uint64_t{1} << kBits) - 1;
    double u = (std::clamp(x, box_.x0, box_.x1) - x0_) / side_,
           v = (std::clamp(y, box_.y0, box_.y1) - y0_) / side_;
    u = u >= 0 ? std::min(u, 1.0) : 0.0, v = v >= 0 ? std::min(v, 1.0) : 0.0;  // NaN -> 0
    constexpr double kScale = 4503599627370496.0;                              // 2^52
    const std::uint64_t ix = std::min(kTop, static_cast<std::uint64_t>(u * kScale));
    const std::uint64_t iy = std::min(kTop, static_cast<std::uint64_t>(v * kScale));
    std::uint32_t n = 0;
    int shift = kBits - 1;
    while (nodes_[n].child != kNone) {
        n = nodes_[n].child +
            static_cast<std::uint32_t>(((ix >> shift) & 1) | (((iy >> shift) & 1) << 1));
        --shift;
    }
    const std::uint64_t mask = (std::uint64_t{1} << (shift + 1)) - 1;
    // 2^-(shift + 1) from its exponent bits (shift + 1 in [22, 52]: a normal number).
    const double unit = std::bit_cast<double>(static_cast<std::uint64_t>(1023 - (shift + 1)) << 52);
    fx = static_cast<double>(ix & mask) * unit;
    fy = static_cast<double>(iy & mask) * unit;
    if (u == 1.0 && ((ix & mask) == mask)) fx = 1.0;  // the box's right side
    if (v == 1.0 && ((iy & mask) == mask)) fy = 1.0;
    return nodes_[n].leaf;
}

std::uint32_t SizeQuadtree2::locate_leaf(double x, double y) const {
    double fx, fy;
    return descend(x, y, fx, fy);
}

double SizeQuadtree2::leaf_value(std::uint32_t i, double x, double y) const {
    const Leaf& l = leaves_[i];
    const double fx = (x - l.x0) / (l.x1 - l.x0), fy = (y - l.y0) / (l.y1 - l.y0);
    const auto& c = l.corner;
    return (1 - fy) * ((1 - fx) * c[0] + fx * c[1]) + fy * ((1 - fx) * c[2] + fx * c[3]);
}

double SizeQuadtree2::operator()(double x, double y) const {
    double fx, fy;
    const auto& c = leaves_[descend(x, y, fx, fy)].corner;
    return (1 - fy) * ((1 - fx) * c[0] + fx * c[1]) + fy * ((1 - fx) * c[2] + fx * c[3]);
}

}  // namespace exactmesh::generators
