// SPDX-License-Identifier: MIT
#include "generators/mesh_2d/quadtree_leaf_bound_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>
#include <utility>

namespace exactmesh::generators {

namespace {

/// A piece in the square's coordinates: [0, 1]^2 for the tree's square (a power-of-two scaling
/// of the input, so the same numbers at every scale).
struct UnitPiece {
    double a[2], b[2];
    double length;
    double run;  ///< its extent along its longer axis: a square of side s holds at most
                 ///< s·length/run of it
};

double distance_to(const UnitPiece& s, double x, double y) {
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1];
    const double squared = dx * dx + dy * dy;
    double t = 0.0;
    if (squared > 0) t = std::clamp(((x - s.a[0]) * dx + (y - s.a[1]) * dy) / squared, 0.0, 1.0);
    return std::hypot(x - (s.a[0] + t * dx), y - (s.a[1] + t * dy));
}

struct Interval {
    double t0, t1, d0, d1;
    int depth;
};

/// A lower bound on the integral over p of min(c / d_q, 1 / s_min)·run / length, d_q the
/// distance to q: d_q is convex along p, so on an interval it is at most its larger end value;
/// intervals are halved while d_q varies over them by more than a quarter (at most 40 levels, 512
/// intervals). `closest` receives the smallest distance sampled.
double separation_integral(const UnitPiece& p, const UnitPiece& q, const QuadtreeFrame2& unit,
                           double& closest) {
    const double cap = 1.0 / unit.smallest_side;
    auto integrand = [&](double d) { return std::min(d > 0 ? unit.margin / d : cap, cap); };
    auto at = [&](double t) {
        return distance_to(q, p.a[0] + t * (p.b[0] - p.a[0]), p.a[1] + t * (p.b[1] - p.a[1]));
    };
    const double saturated = unit.margin * unit.smallest_side;  // below: the integrand is cap
    double total = 0;
    std::vector<Interval> work{{0.0, 1.0, at(0.0), at(1.0), 0}};
    closest = std::min(work[0].d0, work[0].d1);
    int intervals = 1;
    while (!work.empty()) {
        const Interval i = work.back();
        work.pop_back();
        const double high = std::max(i.d0, i.d1);
        if (high > saturated && i.depth < 40 && intervals < 512) {
            const double mid = 0.5 * (i.t0 + i.t1), dm = at(mid);
            closest = std::min(closest, dm);
            const double low = std::min({i.d0, i.d1, dm}), top = std::max(high, dm);
            if (top > 1.25 * low) {
                work.push_back({i.t0, mid, i.d0, dm, i.depth + 1});
                work.push_back({mid, i.t1, dm, i.d1, i.depth + 1});
                ++intervals;
                continue;
            }
        }
        total += (i.t1 - i.t0) * p.run * integrand(high);
    }
    return total;
}

/// A grid over the unit square: which pieces pass near each cell (a piece sampled every half
/// cell, each sample entered in its cell and in the neighbours within a quarter cell).
std::vector<std::pair<std::uint32_t, std::uint32_t>> grid_entries(
    const std::vector<UnitPiece>& pieces, std::uint32_t cells) {
    const double h = 1.0 / cells;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;  // (cell, piece)
    std::vector<std::uint32_t> mine;
    auto cell_of = [&](double v) {
        return static_cast<std::uint32_t>(std::clamp(std::floor(v * cells), 0.0, cells - 1.0));
    };
    for (std::uint32_t k = 0; k < pieces.size(); ++k) {
        const UnitPiece& p = pieces[k];
        const auto samples = static_cast<std::uint32_t>(std::min(2.0 * p.length / h, 1e7)) + 2;
        mine.clear();
        for (std::uint32_t m = 0; m < samples; ++m) {
            const double t = static_cast<double>(m) / (samples - 1);
            const double x = p.a[0] + t * (p.b[0] - p.a[0]), y = p.a[1] + t * (p.b[1] - p.a[1]);
            const std::uint32_t i0 = cell_of(x - 0.25 * h), i1 = cell_of(x + 0.25 * h);
            const std::uint32_t j0 = cell_of(y - 0.25 * h), j1 = cell_of(y + 0.25 * h);
            for (std::uint32_t j = j0; j <= j1; ++j) {
                for (std::uint32_t i = i0; i <= i1; ++i) mine.push_back(j * cells + i);
            }
        }
        std::sort(mine.begin(), mine.end());
        mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
        for (const std::uint32_t c : mine) entries.emplace_back(c, k);
    }
    std::sort(entries.begin(), entries.end());
    return entries;
}

}  // namespace

QuadtreeLeafBound2 quadtree_leaf_bound_2d(
    const std::vector<FeaturePiece2>& pieces, const QuadtreeFrame2& frame,
    const std::function<bool(std::uint32_t, std::uint32_t)>& narrow, std::uint64_t max_pairs) {
    QuadtreeLeafBound2 bound;
    bound.closest_gap = std::numeric_limits<double>::infinity();
    if (pieces.size() < 2 || !(frame.side > 0) || !(frame.smallest_side > 0)) return bound;
    const double inverse = 1.0 / frame.side;  // a power of two: exact
    QuadtreeFrame2 unit = frame;
    unit.smallest_side = frame.smallest_side * inverse;
    std::vector<UnitPiece> local(pieces.size());
    double total_length = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const FeaturePiece2& p = pieces[k];
        UnitPiece& u = local[k];
        u.a[0] = (p.a[0] - frame.x0) * inverse, u.a[1] = (p.a[1] - frame.y0) * inverse;
        u.b[0] = (p.b[0] - frame.x0) * inverse, u.b[1] = (p.b[1] - frame.y0) * inverse;
        u.length = std::hypot(u.b[0] - u.a[0], u.b[1] - u.a[1]);
        u.run = std::max(std::fabs(u.b[0] - u.a[0]), std::fabs(u.b[1] - u.a[1]));
        total_length += u.length;
    }

    // K: a leaf meets pieces of at most this many input segments without being split.
    std::vector<std::pair<triangulation::VertIdx, std::uint32_t>> at_vertex;
    at_vertex.reserve(2 * pieces.size());
    for (const FeaturePiece2& p : pieces) {
        at_vertex.emplace_back(p.va, p.segment);
        at_vertex.emplace_back(p.vb, p.segment);
    }
    std::sort(at_vertex.begin(), at_vertex.end());
    at_vertex.erase(std::unique(at_vertex.begin(), at_vertex.end()), at_vertex.end());
    std::size_t degree = 0;
    for (std::size_t i = 0, j = 0; i < at_vertex.size(); i = j) {
        while (j < at_vertex.size() && at_vertex[j].first == at_vertex[i].first) ++j;
        degree = std::max(degree, j - i);
    }
    const double segments_per_leaf = static_cast<double>(std::max<std::size_t>(degree, 3) + 2);

    // The grid: about two cells per piece, at most 2^10 a side and 2^23 entries.
    std::uint32_t cells = 1;
    while (cells < 1024 &&
           static_cast<double>(cells) * cells < 4.0 * static_cast<double>(pieces.size()))
        cells *= 2;
    while (cells > 1 &&
           4.0 * (2.0 * total_length * cells + 2.0 * static_cast<double>(pieces.size())) > 0x1p23)
        cells /= 2;
    const auto entries = grid_entries(local, cells);

    auto apart = [&](const FeaturePiece2& f, const FeaturePiece2& g) {
        if (f.segment == g.segment) return false;
        if (f.va == g.va || f.va == g.vb || f.vb == g.va || f.vb == g.vb) return false;
        return !narrow(f.segment, g.segment);
    };
    std::vector<double> best(pieces.size(), 0.0);  // per piece: its largest integral
    std::unordered_set<std::uint64_t> done;
    std::uint64_t enumerated = 0;
    const std::uint64_t max_enumerated = std::uint64_t{1} << 26;
    for (std::size_t i = 0, j = 0;
         i < entries.size() && bound.pairs < max_pairs && enumerated < max_enumerated; i = j) {
        while (j < entries.size() && entries[j].first == entries[i].first) ++j;
        for (std::size_t m = i; m < j && bound.pairs < max_pairs; ++m) {
            for (std::size_t n = m + 1; n < j && bound.pairs < max_pairs; ++n) {
                ++enumerated;
                const std::uint32_t p = entries[m].second, q = entries[n].second;
                if (!apart(pieces[p], pieces[q])) continue;
                if (!done.insert((std::uint64_t{p} << 32) | q).second) continue;
                ++bound.pairs;
                double closest_pq = 0, closest_qp = 0;
                best[p] =
                    std::max(best[p], separation_integral(local[p], local[q], unit, closest_pq));
                best[q] =
                    std::max(best[q], separation_integral(local[q], local[p], unit, closest_qp));
                bound.closest_gap = std::min({bound.closest_gap, closest_pq, closest_qp});
            }
        }
    }

    // Per input segment: the sum over its pieces.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_segment(pieces.size());
    for (std::uint32_t k = 0; k < pieces.size(); ++k) by_segment[k] = {pieces[k].segment, k};
    std::sort(by_segment.begin(), by_segment.end());
    double sum = 0, largest = 0;
    std::uint32_t densest = 0;
    for (std::size_t i = 0, j = 0; i < by_segment.size(); i = j) {
        double segment_sum = 0;
        while (j < by_segment.size() && by_segment[j].first == by_segment[i].first) {
            segment_sum += best[by_segment[j].second];
            if (best[by_segment[j].second] > best[densest]) densest = by_segment[j].second;
            ++j;
        }
        sum += segment_sum;
        largest = std::max(largest, segment_sum);
    }
    // Pieces of one segment bend around slivers by a few units in the last place: a hair off
    // straight, so a hair more of them fits in a square.
    bound.leaves = std::max(largest, sum / segments_per_leaf) * (1 - 0x1p-20);
    bound.densest_x = 0.5 * (pieces[densest].a[0] + pieces[densest].b[0]);
    bound.densest_y = 0.5 * (pieces[densest].a[1] + pieces[densest].b[1]);
    bound.closest_gap *= frame.side;
    return bound;
}

}  // namespace exactmesh::generators
