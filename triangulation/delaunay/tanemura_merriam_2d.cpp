// SPDX-License-Identifier: MIT
// Tanemura-Merriam 2D (see tanemura_merriam_2d.hpp).
#include "triangulation/delaunay/tanemura_merriam_2d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include "base/errors.hpp"
#include "predicates/constructions.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/delaunay/delaunay_2d_core.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// The nodes of singly linked lists (Node has a `next` link) in one vector, with a free list:
/// a released slot is reused before the vector grows, so the lists stay compact in memory.
template <class Node>
class NodePool {
  public:
    /// A slot holding `node`.
    std::uint32_t allocate(const Node& node) {
        std::uint32_t slot;
        if (free_ != kNone) {
            slot = free_;
            free_ = nodes_[slot].next;
        } else {
            slot = static_cast<std::uint32_t>(nodes_.size());
            nodes_.push_back({});
        }
        nodes_[slot] = node;
        return slot;
    }
    /// Puts `slot`, unlinked from its list by the caller, on the free list.
    void release(std::uint32_t slot) {
        nodes_[slot].next = free_;
        free_ = slot;
    }
    Node& operator[](std::uint32_t slot) { return nodes_[slot]; }

  private:
    std::vector<Node> nodes_;
    std::uint32_t free_ = kNone;
};

/// The front: directed edges a -> b whose left side is still empty, each with the half-edge on
/// its right (kNone for hull edges). Kept as short lists per origin vertex: vertices are in
/// grid-cell order and the front advances locally, so lookups stay in cache (a global hash
/// table made every lookup a cache miss).
class OpenEdges {
  public:
    explicit OpenEdges(std::uint32_t vertex_count) : head_(vertex_count, kNone) {}

    void insert(VertIdx a, VertIdx b, EdgeIdx value) {
        head_[a] = pool_.allocate({b, value, head_[a]});
    }
    /// Removes a -> b and returns true (its value in `value`) if it is open.
    bool take(VertIdx a, VertIdx b, EdgeIdx& value) {
        for (std::uint32_t* link = &head_[a]; *link != kNone; link = &pool_[*link].next) {
            Entry& entry = pool_[*link];
            if (entry.to == b) {
                value = entry.value;
                const std::uint32_t slot = *link;
                *link = entry.next;
                pool_.release(slot);
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
    NodePool<Entry> pool_;
};

/// The geometry of the uniform grid, in coordinates scaled by a power of two into (-1, 1)
/// (exact scaling, so differences of scaled points cannot overflow; only the search uses these,
/// never a decision). Cell indices are monotone functions of the coordinates: a point in a
/// column left of another's has the smaller x, exactly (the hull filter relies on it).
struct GridLayout {
    double scale = 1, min_x = 0, min_y = 0, max_x = 0, max_y = 0, cell = 1, inv_cell = 1;
    std::uint32_t columns = 1, rows = 1;

    std::uint32_t column(double scaled_x) const {
        return clamp_index((scaled_x - min_x) * inv_cell, columns);
    }
    std::uint32_t row(double scaled_y) const {
        return clamp_index((scaled_y - min_y) * inv_cell, rows);
    }
    std::size_t cell_count() const { return static_cast<std::size_t>(columns) * rows; }
    std::size_t cell_of(const double* p) const {
        return static_cast<std::size_t>(row(p[1] * scale)) * columns + column(p[0] * scale);
    }

    static std::uint32_t clamp_index(double t, std::uint32_t count) {
        if (!(t > 0)) return 0;
        if (!(t < count)) return count - 1;  // before the cast: huge values do not convert
        return static_cast<std::uint32_t>(t);
    }
};

/// Points per cell aimed at. Measured at 2^20 uniform points (delaunay2d_bench, CPU time):
/// 1, 2 and 3 within the noise of the machine; 2 visits fewer cells than 1, and fewer
/// candidates than 3.
constexpr double kPointsPerCell = 2.0;

/// The grid for xy: scale and bounding box, then a cell size for kPointsPerCell points per
/// cell over the bounding box, refined once where the points crowd: if the cell of a typical
/// point (weighted by points, not by cells) holds far more than that, as on clustered input,
/// the cells shrink by the measured excess, up to 4 cells per point.
GridLayout grid_layout(std::span<const double> xy) {
    const std::size_t n = xy.size() / 2;
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (std::size_t v = 0; v < n; ++v) {
        lo_x = std::min(lo_x, xy[2 * v]);
        hi_x = std::max(hi_x, xy[2 * v]);
        lo_y = std::min(lo_y, xy[2 * v + 1]);
        hi_y = std::max(hi_y, xy[2 * v + 1]);
    }
    if (n == 0) lo_x = lo_y = hi_x = hi_y = 0;  // no point: a one-cell grid, no NaN extents
    GridLayout g;
    const double magnitude =
        std::max({std::fabs(lo_x), std::fabs(hi_x), std::fabs(lo_y), std::fabs(hi_y), 1e-300});
    int exponent = 0;
    std::frexp(magnitude, &exponent);
    g.scale = std::ldexp(1.0, -exponent);  // |scaled| < 1
    g.min_x = lo_x * g.scale;
    g.min_y = lo_y * g.scale;
    g.max_x = hi_x * g.scale;
    g.max_y = hi_y * g.scale;
    const double width = g.max_x - g.min_x, height = g.max_y - g.min_y;
    const double extent = std::max(width, height);
    const double max_cells = std::min(4.0 * static_cast<double>(n) + 64.0, 0x1p30);
    auto set_cell = [&](double cell) {
        if (!(cell > 0)) cell = extent > 0 ? extent : 1.0;
        cell = std::max(cell, extent / 65000.0);  // at most 2^16 columns and rows
        // Keep columns * rows within max_cells (the +1 per dimension included).
        while ((width / cell + 1) * (height / cell + 1) > max_cells) cell *= 1.25;
        g.cell = cell;
        g.inv_cell = 1 / cell;
        g.columns = static_cast<std::uint32_t>(width / cell) + 1;
        g.rows = static_cast<std::uint32_t>(height / cell) + 1;
    };
    set_cell(std::sqrt(std::max(width * height, 1e-300) * kPointsPerCell /
                       std::max(1.0, static_cast<double>(n))));
    if (n >= 256) {
        std::vector<std::uint32_t> count(g.cell_count(), 0);
        for (std::size_t v = 0; v < n; ++v) ++count[g.cell_of(&xy[2 * v])];
        double weighted = 0;  // sum over points of the occupancy of their cell
        for (const std::uint32_t c : count) weighted += static_cast<double>(c) * c;
        // A Poisson cell around a point holds the point plus kPointsPerCell on average.
        const double excess = (weighted / static_cast<double>(n) - 1) / kPointsPerCell;
        if (excess > 2) set_cell(g.cell / std::sqrt(excess));
    }
    return g;
}

/// The points grouped by grid cell, cells in row-major order, each cell's points by increasing
/// caller index (until kd_forest reorders the crowded cells); duplicates removed. Row-major
/// suits the sweep of the front (see RowQueue): the points it meets lie in a band of rows, a
/// few contiguous ranges of memory.
struct CellOrder {
    std::vector<VertIdx> order;  ///< mesh vertex -> caller's index: distinct, then duplicates
    std::uint32_t distinct = 0;  ///< the first `distinct` mesh vertices are distinct points
    std::vector<std::pair<VertIdx, VertIdx>> duplicates;  ///< (caller's index, the one it equals)
    std::vector<std::uint32_t> start;  ///< cell c holds mesh vertices start[c] .. start[c + 1] - 1
};

CellOrder cell_order(std::span<const double> xy, const GridLayout& g) {
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    const std::size_t cells = g.cell_count();
    // Counting sort by cell: stable, so each cell lists its points by caller index.
    std::vector<std::uint32_t> cell_of(n);
    std::vector<std::uint32_t> start(cells + 1, 0);
    for (std::uint32_t v = 0; v < n; ++v) {
        cell_of[v] = static_cast<std::uint32_t>(g.cell_of(&xy[2 * std::size_t{v}]));
        ++start[cell_of[v] + 1];
    }
    for (std::size_t c = 1; c <= cells; ++c) start[c] += start[c - 1];
    std::vector<VertIdx> sorted(n);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t v = 0; v < n; ++v) sorted[fill[cell_of[v]]++] = v;
    }
    cell_of = {};
    CellOrder out;
    out.order.reserve(n);
    out.start.assign(cells + 1, 0);
    std::vector<VertIdx> group, kept;
    std::vector<bool> copy;
    auto equal = [&xy](VertIdx u, VertIdx v) {
        return xy[2 * std::size_t{u}] == xy[2 * std::size_t{v}] &&
               xy[2 * std::size_t{u} + 1] == xy[2 * std::size_t{v} + 1];
    };
    // Equal points share a cell, where they come by increasing caller index: the first of each
    // set of equal points is kept, the others merge into it.
    for (std::size_t c = 0; c < cells; ++c) {
        const std::uint32_t first = start[c], last = start[c + 1];
        out.start[c] = static_cast<std::uint32_t>(out.order.size());
        if (last - first <= 8) {
            for (std::uint32_t k = first; k < last; ++k) {
                const VertIdx v = sorted[k];
                VertIdx same = kNone;
                for (std::size_t m = out.start[c]; m < out.order.size() && same == kNone; ++m) {
                    if (equal(out.order[m], v)) same = out.order[m];
                }
                if (same == kNone) {
                    out.order.push_back(v);
                } else {
                    out.duplicates.emplace_back(v, same);
                }
            }
            continue;
        }
        group.assign(sorted.begin() + first, sorted.begin() + last);
        std::stable_sort(group.begin(), group.end(), [&xy](VertIdx u, VertIdx v) {
            const double* p = &xy[2 * std::size_t{u}];
            const double* q = &xy[2 * std::size_t{v}];
            return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
        });
        // Mark the later copies, then list the kept points by caller index.
        copy.assign(group.size(), false);
        for (std::size_t k = 1; k < group.size(); ++k) copy[k] = equal(group[k - 1], group[k]);
        kept.clear();
        for (std::size_t k = 0, head = 0; k < group.size(); ++k) {
            if (!copy[k]) {
                head = k;
                kept.push_back(group[k]);
            } else {
                out.duplicates.emplace_back(group[k], group[head]);
            }
        }
        std::sort(kept.begin(), kept.end());
        out.order.insert(out.order.end(), kept.begin(), kept.end());
    }
    out.distinct = static_cast<std::uint32_t>(out.order.size());
    out.start[cells] = out.distinct;
    for (const auto& [duplicate, first_copy] : out.duplicates) out.order.push_back(duplicate);
    return out;
}

/// Uniform grid over the distinct points (the first mesh vertices), each cell a contiguous
/// range of mesh vertices.
struct PointGrid {
    GridLayout layout;
    std::vector<std::uint32_t> start;  ///< cells + 1 entries, row-major (see CellOrder)

    std::uint32_t columns() const { return layout.columns; }
    std::uint32_t rows() const { return layout.rows; }
    std::size_t index(std::uint32_t i, std::uint32_t j) const {
        return static_cast<std::size_t>(j) * layout.columns + i;
    }
    bool empty(std::size_t c) const { return start[c] == start[c + 1]; }
};

/// A cell holding more points than this gets a kd-tree. A cluster far smaller than the cells
/// (a dense spot in a wide bounding box, or points spread over many magnitudes, which all but
/// the largest collapse into the cells around zero) would otherwise put all of its points in
/// every search near it: O(k^2) for k points. About two points per cell on uniform input
/// (Poisson: more than 64 is beyond 1e-60), so uniform input never builds one. Below some
/// hundreds of points a scan beats the tree (Gaussian clusters at 2^12 points, delaunay2d_bench:
/// 4.5 ms with 64, as without trees; 5.5 ms with 32, 6.7 ms with 8, though they look at 30%
/// to 70% fewer candidates).
constexpr std::uint32_t kCrowdedCell = 64;
/// Points per kd-tree leaf (16: 20-30% slower on a 2^-10 cluster of 200,000 points).
constexpr std::uint32_t kLeafSize = 8;

/// kd-trees over the crowded cells, all nodes in one array. A node covers the mesh vertices
/// first .. last - 1 and holds their bounding box exactly (input doubles, never scaled, so
/// any magnitude is represented); an inner node's children are node + 1 (the points below
/// `split` along `axis`, by the median) and `right`, a leaf has right = kNone. Depth is at
/// most log2(k / kLeafSize) + 1 whatever the distribution.
struct KdForest {
    struct Node {
        double lo_x, lo_y, hi_x, hi_y;
        double split;
        std::uint32_t first, last, right, axis;
    };
    std::vector<Node> nodes;
    std::vector<std::pair<std::size_t, std::uint32_t>> roots;  ///< (cell, root node), by cell

    std::uint32_t root_of(std::size_t cell) const {
        const auto it =
            std::lower_bound(roots.begin(), roots.end(), std::make_pair(cell, std::uint32_t{0}));
        EM_ASSERT(it != roots.end() && it->first == cell);
        return it->second;
    }
};

/// The kd-tree over order[first .. last) (caller's indices of distinct points), reordering
/// that range so each node's points are contiguous; returns the root's index.
std::uint32_t build_kd_tree(KdForest& forest, std::span<const double> xy,
                            std::vector<VertIdx>& order, std::uint32_t first, std::uint32_t last) {
    const auto node = static_cast<std::uint32_t>(forest.nodes.size());
    forest.nodes.push_back({INFINITY, INFINITY, -INFINITY, -INFINITY, 0, first, last, kNone, 0});
    KdForest::Node box = forest.nodes[node];
    for (std::uint32_t k = first; k < last; ++k) {
        const double* p = &xy[2 * std::size_t{order[k]}];
        box.lo_x = std::min(box.lo_x, p[0]);
        box.hi_x = std::max(box.hi_x, p[0]);
        box.lo_y = std::min(box.lo_y, p[1]);
        box.hi_y = std::max(box.hi_y, p[1]);
    }
    if (last - first > kLeafSize) {
        // Split the wider side (halved: the full extent may overflow) at the median; ties by
        // the other coordinate, so distinct points order strictly.
        box.axis = 0.5 * box.hi_x - 0.5 * box.lo_x >= 0.5 * box.hi_y - 0.5 * box.lo_y ? 0 : 1;
        const unsigned axis = box.axis;
        const std::uint32_t mid = first + (last - first) / 2;
        std::nth_element(order.begin() + first, order.begin() + mid, order.begin() + last,
                         [&xy, axis](VertIdx u, VertIdx v) {
                             const double* p = &xy[2 * std::size_t{u}];
                             const double* q = &xy[2 * std::size_t{v}];
                             return p[axis] < q[axis] ||
                                    (p[axis] == q[axis] && p[1 - axis] < q[1 - axis]);
                         });
        box.split = xy[2 * std::size_t{order[mid]} + axis];
        forest.nodes[node] = box;
        build_kd_tree(forest, xy, order, first, mid);  // node + 1
        forest.nodes[node].right = build_kd_tree(forest, xy, order, mid, last);
    } else {
        forest.nodes[node] = box;
    }
    return node;
}

/// kd-trees for the crowded cells of `cells` (reordering their points within the cells).
KdForest kd_forest(std::span<const double> xy, CellOrder& cells) {
    KdForest forest;
    for (std::size_t c = 0; c + 1 < cells.start.size(); ++c) {
        if (cells.start[c + 1] - cells.start[c] <= kCrowdedCell) continue;
        forest.roots.emplace_back(
            c, build_kd_tree(forest, xy, cells.order, cells.start[c], cells.start[c + 1]));
    }
    return forest;
}

/// The open edges still to wrap, by the grid row of their midpoint, the lowest row first. Any
/// open edge may be wrapped next (its third vertex does not depend on the order), and this
/// order makes the front sweep the grid upwards: the points and cells searched lie in a band
/// of a few rows, which stays in cache (a depth-first order wandered over the whole grid and
/// missed the cache on most candidates). An edge closed before its turn is skipped then.
class RowQueue {
  public:
    explicit RowQueue(std::uint32_t rows) : head_(rows, kNone) {}

    void push(std::uint32_t row, VertIdx a, VertIdx b) {
        head_[row] = nodes_.allocate({a, b, head_[row]});
        current_ = std::min(current_, row);
    }
    /// The last edge pushed into the lowest non-empty row; false when the queue is empty.
    bool pop(VertIdx& a, VertIdx& b) {
        while (current_ < head_.size() && head_[current_] == kNone) ++current_;
        if (current_ == head_.size()) return false;
        const std::uint32_t slot = head_[current_];
        a = nodes_[slot].a;
        b = nodes_[slot].b;
        head_[current_] = nodes_[slot].next;
        nodes_.release(slot);
        return true;
    }

  private:
    struct Node {
        VertIdx a, b;
        std::uint32_t next;
    };
    std::vector<std::uint32_t> head_;
    NodePool<Node> nodes_;
    std::uint32_t current_ = 0;
};

/// 2^k, exactly, for -1022 <= k <= 1023 (built from its bits: std::ldexp is a library call).
double power_of_two(int k) {
    return std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
}

/// floor(log2 |x|) for finite x != 0 (read from the bits when x is normal); INT_MIN for 0.
int exponent_of(double x) {
    const auto biased = static_cast<int>((std::bit_cast<std::uint64_t>(x) >> 52) & 0x7ff);
    if (biased != 0) return biased - 1023;
    return x == 0 ? std::numeric_limits<int>::min() : std::ilogb(x);
}

/// floor(log2 |p - q|), or one more; INT_MIN when p == q. A difference of doubles is exact
/// when it is subnormal and overflows only when |p| and |q| exceed 2^1022, where halving
/// them is exact.
int difference_exponent(double p, double q) {
    const double d = p - q;
    if (std::isfinite(d)) return exponent_of(d);
    return exponent_of(0.5 * p - 0.5 * q) + 1;
}

/// Bounds of the gift-wrapping search in double precision; none is a filter of predicates/, and
/// all are PRUNE-ONLY: they never decide a sign. They only skip what certainly cannot be a
/// better third vertex: cells, kd boxes and single candidates that lie certainly right of ab,
/// or certainly outside a safe over-estimate of the current circle (its computed centre and
/// radius widened by `slack`, which bounds their error: proof at circle()). Every candidate
/// they do not skip is decided by the exact orient2d and the perturbed incircle of predicates/,
/// so a bound that were too tight could only lose a better candidate, never take a wrong one;
/// that is why their proofs are over-estimates with wide margins. (Before issue 12 a candidate
/// certainly inside by these bounds was taken without incircle; now incircle decides it, which
/// costs about one incircle call per taken candidate.)
// Cells, boxes and the lens.
constexpr double kBoxCrossRelative = 0x1p-48;     ///< cross product of a box corner with fb
constexpr double kBoxCrossUnderflow = 0x1p-1066;  ///< its underflow share
constexpr double kPowerBoxSize = 0x1p-20;         ///< boxes below this times r get the power test
constexpr double kTinySpan = 0x1p-900;            ///< spans whose frame offsets may underflow
constexpr double kSquareRelative = 0x1p-48;       ///< rounding of squared cell distances, chords
constexpr double kPositionRelative = 0x1p-51;     ///< rounding of an absolute centre position
constexpr double kGridAbsolute = 1e-14;       ///< absolute error in grid units (coordinates < 1)
constexpr double kCellRelative = 1e-9;        ///< error of cell boundaries, per cell size
constexpr double kGridUnderflow = 0x1p-1070;  ///< underflow of a and b in grid units
// The circle's safe over-estimate (circle()) and the tests against it (candidates and boxes).
constexpr double kDoubleCentreMinSine = 1e-4;  ///< sin(angle at a) above which the centre is double
constexpr double kDoubleCentreRange = 0x1p600;   ///< |c - a|^2 range of the double centre
constexpr double kDoubleCentreSlack = 1e-8;      ///< slack of the double centre, per r
constexpr double kRoundedCentreSlack = 0x1p-48;  ///< slack of the rounded centre, per r
constexpr double kFrameUnderflow = 0x1p-1073;    ///< a coordinate's underflow, per frame unit
constexpr double kCircleAbsolute = 0x1p-1000;    ///< products' underflow, absolute or per r
constexpr double kLargestRadius = 0x1p400;       ///< larger circles go to the exact predicates
constexpr double kCertainRelative = 0x1p-50;     ///< distance rounding of the certain tests
constexpr double kCertainSquares = 0x1p-40;      ///< rounding of dist2 and the squared bounds
constexpr double kSmallestInner = 0x1p-400;      ///< smallest inner radius (skips power tests)
constexpr double kPowerRelative = 0x1p-46;       ///< the power's relative rounding

/// The circle through a, b and the current best third vertex, relative to a: centre
/// a + (ux, uy), radius r; `slack` bounds the error of the centre and of r (at least twice the
/// centre's error sigma); `absolute` is the part of the centre's error not relative to r.
/// Candidates are tested in the edge's frame (see GiftWrapper::frame_), where r >= 2^-53 and
/// r <= 2^400, so no square under- or overflows: first |w - u|^2 against outer2 (w = d - a),
/// beyond which d is certainly outside and skipped; then, unless within inner2 (certainly
/// inside), the power r^2 - |w - u|^2 = 2 w.u - |w|^2 (the circle passes through a, so
/// |u| = r), positive inside, skips d when certainly negative. These only skip candidates:
/// the exact predicates decide the rest.
/// The power's computed error is below |w| (2 sigma + 22 u (r + |w|)) + 2^-1015 r, u = 2^-53:
/// the centre's error times 2|w|, w's own rounding (u |w| per coordinate plus underflow) times
/// 2r + 2|w|, and about 7u relative roundings of products and sums; power_slack and
/// power_absolute bound it as |w|_1 (power_slack + 2^-46 |w|_1) + power_absolute. Unlike
/// |w - u|^2 against r^2, whose error is relative to r^2, this is relative to |w| r: a point
/// near a on a huge circle (an edge from a cluster to a far point) is decided at its own scale.
/// cells_ holds the circle in grid units, with the absolute centre (ox, oy), `widen`, which
/// bounds the distance from the computed circle to the true one including the absolute
/// rounding, and `tolerance`, the slack of a cross product with ab for points within `widen`.
struct Circle {
    bool bounded = false;
    double ux = 0, uy = 0, r = 0, slack = 0, absolute = 0, outer2 = 0, inner2 = -1;
    double power_slack = 0, power_absolute = 0;
    double ox = 0, oy = 0, widen = 0, tolerance = 0;  // set by GiftWrapper::refresh_cells
};

class GiftWrapper {
  public:
    GiftWrapper(detail::Delaunay2Core& core, const PointGrid& grid, const KdForest& forest)
        : core_(core), mesh_(core.mesh), grid_(grid), layout_(grid.layout), forest_(forest) {}

    /// The point c left of a -> b whose perturbed circle through a, b, c is empty.
    /// Circles through a and b form a pencil whose parts left of ab are nested, so once a
    /// candidate is known only its circle's part left of ab (the lens) can hold a better one,
    /// and a better candidate only shrinks the lens. Cells are searched in square rings
    /// around a start point, nearest first, each ring clipped to the cells that may meet the
    /// current lens, until the rings hold all of those. A candidate outside the circle by more
    /// than its error bound is skipped (prune-only); every other one is decided by the exact
    /// orient2d and the perturbed incircle.
    VertIdx third_vertex(VertIdx a, VertIdx b) {
        const double s = layout_.scale;
        a_ = a;
        b_ = b;
        pa_ = mesh_.point(a);
        pb_ = mesh_.point(b);
        ax_ = pa_[0] * s;
        ay_ = pa_[1] * s;
        bx_ = pb_[0] * s;
        by_ = pb_[1] * s;
        // The frame of this edge: b - a has its larger coordinate in [1, 2) (unless clamped:
        // in [2^-52, 8) at the ends of the double range). If a * frame_ overflows (a huge
        // coordinate, the edge tiny), fb is NaN and so is every circle: exact tests only.
        const int m = std::clamp(
            std::max(difference_exponent(pb_[0], pa_[0]), difference_exponent(pb_[1], pa_[1])),
            -1022, 1022);
        frame_ = power_of_two(-m);
        frame_to_grid_ = s / frame_;
        fax_ = pa_[0] * frame_;
        fay_ = pa_[1] * frame_;
        fbx_ = pb_[0] * frame_ - fax_;
        fby_ = pb_[1] * frame_ - fay_;
        best_ = kNone;
        circle_ = cells_ = {};
        stale_ = boxed_ = false;
        lo_i_ = lo_j_ = 0;
        hi_i_ = grid_.columns() - 1;
        hi_j_ = grid_.rows() - 1;
        // Start left of the midpoint, at the apex of the right isosceles triangle on ab but at
        // most a cell away from ab: on evenly spread points the first candidate found there
        // is nearly always the answer (about 1.05 circles per triangle on uniform points), and
        // the third vertex of a long edge (on the hull) lies close to it.
        const double length = std::fabs(bx_ - ax_) + std::fabs(by_ - ay_);
        const double offset = std::min(0.5, layout_.cell / length);
        const double qx = (ax_ + bx_) / 2 - (by_ - ay_) * offset;
        const double qy = (ay_ + by_) / 2 + (bx_ - ax_) * offset;
        const std::uint32_t i0 = layout_.column(qx), j0 = layout_.row(qy);
        // Rings, each clipped to the cell box of the current lens, until the square of rings
        // seen holds the box.
        const std::uint32_t max_ring = std::max(grid_.columns(), grid_.rows());
        visit_cell(i0, j0);
        for (std::uint32_t r = 1;; ++r) {
            if (stale_) refresh_cells();
            if (boxed_ && lo_i_ + (r - 1) >= i0 && hi_i_ <= i0 + (r - 1) && lo_j_ + (r - 1) >= j0 &&
                hi_j_ <= j0 + (r - 1)) {
                break;
            }
            if (r > max_ring) break;
            visit_ring(i0, j0, r);
        }
        EM_ASSERT(best_ != kNone);
        return best_;
    }

  private:
    detail::Delaunay2Core& core_;
    TriMesh2& mesh_;
    const PointGrid& grid_;
    const GridLayout& layout_;
    const KdForest& forest_;
    // The current search.
    VertIdx a_ = kNone, b_ = kNone, best_ = kNone;
    const double* pa_ = nullptr;
    const double* pb_ = nullptr;
    double ax_ = 0, ay_ = 0, bx_ = 0, by_ = 0;  // a and b in grid units (for cells)
    // The frame of the circles and of the candidate test: coordinates times frame_, a power of
    // two that brings b - a to length about 1, so that the squares of distances comparable to
    // the circle's radius neither underflow nor overflow whatever the magnitudes of a and b.
    // (In grid units an edge of length 2^-600, among points reaching 2^400, has squared
    // lengths below the subnormals: every circle had radius 0 and every point was "certainly
    // outside", which picked wrong triangles and sent the front round a vertex forever.)
    // fa = a * frame_, fb = b * frame_ - fa; frame_to_grid_ = layout_.scale / frame_.
    double frame_ = 1, frame_to_grid_ = 1, fax_ = 0, fay_ = 0, fbx_ = 0, fby_ = 0;
    // The start point in input coordinates (the apex of the right isosceles triangle on ab,
    // left of it): kd-trees visit the child on its side first.
    double qx_ = 0, qy_ = 0;
    Circle circle_;
    // The cells that may meet the lens: columns lo_i_..hi_i_, rows lo_j_..hi_j_, narrowed from
    // the whole grid (boxed_ once narrowed) by the circle cells_, which is circle_ as it was at
    // the start of the current ring (stale_ when circle_ has changed since): the lens only
    // shrinks, so an older circle bounds the cells to visit too, and refreshing once per ring
    // keeps the box arithmetic off the many early improvements.
    Circle cells_;
    bool stale_ = false, boxed_ = false;
    std::uint32_t lo_i_ = 0, hi_i_ = 0, lo_j_ = 0, hi_j_ = 0;

    void visit_cell(std::uint32_t i, std::uint32_t j) {
        const std::size_t c = grid_.index(i, j);
        const std::uint32_t first = grid_.start[c], last = grid_.start[c + 1];
        if (last - first > kCrowdedCell) {
            visit_crowded_cell(c);
            return;
        }
        for (std::uint32_t d = first; d < last; ++d) consider(d);
    }

    /// Through its kd-tree. Kept out of line, as visit_tree: crowded cells are rare, and
    /// inlined they pushed the hot path of the grid search out of line (10% slower).
    [[gnu::noinline]] void visit_crowded_cell(std::size_t c) {
        // Halves first, so that no sum of two coordinates overflows (an infinite q only makes
        // the visiting order arbitrary).
        qx_ = (0.5 * pa_[0] + 0.5 * pb_[0]) + (0.5 * pa_[1] - 0.5 * pb_[1]);
        qy_ = (0.5 * pa_[1] + 0.5 * pb_[1]) + (0.5 * pb_[0] - 0.5 * pa_[0]);
        visit_tree(forest_.root_of(c));
    }

    /// The points of kd-tree node `node` that may be better, the child on q's side first.
    /// Recursion depth is the tree's, at most about 30.
    [[gnu::noinline]] void visit_tree(std::uint32_t node) {
        const KdForest::Node& k = forest_.nodes[node];
        if (!may_hold_better(k)) return;
        if (k.right == kNone) {
            for (std::uint32_t d = k.first; d < k.last; ++d) consider(d);
            return;
        }
        const bool q_right = (k.axis == 0 ? qx_ : qy_) >= k.split;
        visit_tree(q_right ? k.right : node + 1);
        visit_tree(q_right ? node + 1 : k.right);
    }

    /// False when the node's box lies certainly right of ab, or certainly outside the current
    /// circle. Both in the edge's frame, the box's corners computed as the candidate test
    /// computes points (so the bound outer2 holds for the box's nearest point as for a
    /// candidate: a rounding of 2^-53 relative to its offset from a, plus underflow). A corner
    /// that overflows the frame is at least 2^971 from a: an infinite distance is right to
    /// prune, and an infinite or NaN cross product prunes nothing.
    bool may_hold_better(const KdForest::Node& k) const {
        const double x0 = k.lo_x * frame_ - fax_, x1 = k.hi_x * frame_ - fax_;
        const double y0 = k.lo_y * frame_ - fay_, y1 = k.hi_y * frame_ - fay_;
        // The corner farthest left of ab; the cross product's error is below 5u |fb|_1 |p|_1
        // for the roundings of fb, p and the products, plus 2^-1072 (|fb|_1 + |p|_1) for
        // underflow (a component of fb that underflowed to zero included); |fb|_1 <= 16.
        const double px = fby_ < 0 ? x1 : x0, py = fbx_ > 0 ? y1 : y0;
        const double reach = std::fabs(x0) + std::fabs(x1) + std::fabs(y0) + std::fabs(y1);
        const double tolerance = kBoxCrossRelative * (std::fabs(fbx_) + std::fabs(fby_)) * reach +
                                 kBoxCrossUnderflow * (16 + reach);
        if (fbx_ * py - fby_ * px < -tolerance) return false;
        if (!circle_.bounded) return true;
        const Circle& c = circle_;
        const double dx = c.ux < x0 ? x0 - c.ux : (c.ux > x1 ? c.ux - x1 : 0.0);
        const double dy = c.uy < y0 ? y0 - c.uy : (c.uy > y1 ? c.uy - y1 : 0.0);
        if (dx * dx + dy * dy > c.outer2) return false;
        // The power over the box is at most 2 max(p.u) - min |p|^2, from each of a, b and c: a
        // box near one of them, small against a huge circle, is decided at its own scale (an
        // edge from a far point to a cluster, whose circle passes through the cluster as a
        // straight line would). A box not that small is resolved by the distance test above
        // as well as by this one (to about the slack, 1e-8 r), so it is spared the cost.
        if (!((x1 - x0) + (y1 - y0) < kPowerBoxSize * c.r)) return true;
        for (unsigned from = 0; from < 3; ++from) {
            const OnCircle o = on_circle(from);
            const double px0 = k.lo_x * frame_ - o.x, px1 = k.hi_x * frame_ - o.x;
            const double py0 = k.lo_y * frame_ - o.y, py1 = k.hi_y * frame_ - o.y;
            const double cx = o.centre_x, cy = o.centre_y;
            const double mx = px0 > 0 ? px0 : (px1 < 0 ? px1 : 0.0);
            const double my = py0 > 0 ? py0 : (py1 < 0 ? py1 : 0.0);
            const double power =
                2 * ((cx > 0 ? px1 : px0) * cx + (cy > 0 ? py1 : py0) * cy) - (mx * mx + my * my);
            const double span = std::fabs(px0) + std::fabs(px1) + std::fabs(py0) + std::fabs(py1);
            if (power < -(span * (c.power_slack + kPowerRelative * span) + c.power_absolute))
                return false;
            if (span < kTinySpan) {
                // A box near this point, far below the edge's length: its offsets may have
                // underflowed in the frame; the same test from input coordinates.
                const ScaledPower scaled = scaled_power(from, k.lo_x, k.hi_x, k.lo_y, k.hi_y);
                if (scaled.value < -scaled.bound) return false;
            }
        }
        return true;
    }

    /// Point `from` of the circle (0, 1, 2: a, b, c) as the frame has it (its coordinates
    /// times frame_) and the circle's centre relative to it. Relative to b or c the centre
    /// has the error of u plus that of fb or of c - a (u |b - a| + underflow <= 3u r), within
    /// the slack.
    struct OnCircle {
        double x, y, centre_x, centre_y;
    };
    OnCircle on_circle(unsigned from) const {
        if (from == 0) return {fax_, fay_, circle_.ux, circle_.uy};
        if (from == 1)
            return {pb_[0] * frame_, pb_[1] * frame_, circle_.ux - fbx_, circle_.uy - fby_};
        const double* pc = mesh_.point(best_);
        const double cx = pc[0] * frame_, cy = pc[1] * frame_;
        return {cx, cy, circle_.ux - (cx - fax_), circle_.uy - (cy - fay_)};
    }

    /// The power test (see Circle) of candidate d near the circle (neither beyond outer2 nor
    /// within inner2): from a, b and c in the frame, then from them in input coordinates (for
    /// offsets that underflowed in the frame). True when d lies certainly outside the circle,
    /// which only skips d (prune-only: a false answer sends d to the exact predicates, whatever
    /// the power's sign). Rare but for points within about 2^-40 of the circle and for
    /// clusters far below the edge's length.
    [[gnu::noinline]] bool certainly_outside_by_power(const double* pd) const {
        for (unsigned from = 0; from < 3; ++from) {
            const OnCircle o = on_circle(from);
            const double vx = pd[0] * frame_ - o.x, vy = pd[1] * frame_ - o.y;
            const double power = 2 * (vx * o.centre_x + vy * o.centre_y) - (vx * vx + vy * vy);
            const double reach = std::fabs(vx) + std::fabs(vy);
            const double bound =
                reach * (circle_.power_slack + kPowerRelative * reach) + circle_.power_absolute;
            if (power < -bound) return true;
            if (power > bound) return false;  // certainly inside: the power cannot skip it
        }
        for (unsigned from = 0; from < 3; ++from) {
            const ScaledPower scaled = scaled_power(from, pd[0], pd[0], pd[1], pd[1]);
            if (scaled.value < -scaled.bound) return true;
            if (scaled.value > scaled.bound) return false;
        }
        return false;
    }

    /// The power test (see Circle) of the box [x0, x1] x [y0, y1] in input coordinates (a point
    /// when x0 == x1 and y0 == y1) from point `from` of the circle (0, 1, 2: a, b, c), taken
    /// from the input coordinates: their offsets from that point (exact when subnormal, one
    /// rounding otherwise) scaled by 2^-e to below 2 in magnitude, so that no offset small
    /// against the edge underflows. With x = offset 2^-e and rho = frame_ 2^e (so w = x rho),
    /// value = 2 max(x.u) - rho min |x|^2 is the frame's power divided by rho; its error
    /// bound, divided the same way, is |x|_1 (power_slack + 2^-46 rho |x|_1) plus underflow
    /// below 2^-1070, within power_absolute (r >= 2^-53). A value below -bound puts the whole
    /// box certainly outside; a point's value above +bound puts it certainly inside.
    struct ScaledPower {
        double value, bound;
    };
    ScaledPower scaled_power(unsigned from, double x0, double x1, double y0, double y1) const {
        const double* o = from == 0 ? pa_ : (from == 1 ? pb_ : mesh_.point(best_));
        double vx0 = x0 - o[0], vx1 = x1 - o[0], vy0 = y0 - o[1], vy1 = y1 - o[1];
        const double m = std::max({std::fabs(vx0), std::fabs(vx1), std::fabs(vy0), std::fabs(vy1)});
        // At the point itself, or an offset that overflowed: undecided.
        if (!(m > 0) || !(m <= std::numeric_limits<double>::max())) return {0, INFINITY};
        const int e = std::ilogb(m);
        vx0 = std::ldexp(vx0, -e);
        vx1 = std::ldexp(vx1, -e);
        vy0 = std::ldexp(vy0, -e);
        vy1 = std::ldexp(vy1, -e);
        const double rho = std::ldexp(frame_, e);
        const OnCircle on = on_circle(from);
        const double cx = on.centre_x, cy = on.centre_y;
        const double mx = vx0 > 0 ? vx0 : (vx1 < 0 ? vx1 : 0.0),
                     my = vy0 > 0 ? vy0 : (vy1 < 0 ? vy1 : 0.0);
        const double value =
            2 * ((cx > 0 ? vx1 : vx0) * cx + (cy > 0 ? vy1 : vy0) * cy) - (mx * mx + my * my) * rho;
        const double span =
            std::max(std::fabs(vx0), std::fabs(vx1)) + std::max(std::fabs(vy0), std::fabs(vy1));
        return {value, span * (circle_.power_slack + kPowerRelative * rho * span) +
                           circle_.power_absolute};
    }

    /// The cells of the square ring at Chebyshev distance r from (i0, j0) that lie in the
    /// current cell box and may meet the lens. The box may narrow while the ring is visited.
    void visit_ring(std::uint32_t i0, std::uint32_t j0, std::uint32_t r) {
        const long long lo_i = static_cast<long long>(i0) - r,
                        hi_i = static_cast<long long>(i0) + r;
        const long long lo_j = static_cast<long long>(j0) - r,
                        hi_j = static_cast<long long>(j0) + r;
        for (const long long j : {lo_j, hi_j}) {
            if (j < lo_j_ || j > hi_j_) continue;
            for (long long i = std::max<long long>(lo_i, lo_i_);
                 i <= std::min<long long>(hi_i, hi_i_); ++i) {
                visit_cell_if_near(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
            }
        }
        for (const long long i : {lo_i, hi_i}) {
            if (i < lo_i_ || i > hi_i_) continue;
            for (long long j = std::max<long long>(lo_j + 1, lo_j_);
                 j <= std::min<long long>(hi_j - 1, hi_j_); ++j) {
                visit_cell_if_near(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
            }
        }
    }

    /// Visits cell (i, j) unless it lies certainly outside the circle or right of ab.
    void visit_cell_if_near(std::uint32_t i, std::uint32_t j) {
        if (cells_.bounded) {
            const Circle& c = cells_;
            const double x0 = layout_.min_x + i * layout_.cell - c.widen;
            const double x1 = x0 + layout_.cell + 2 * c.widen;
            const double y0 = layout_.min_y + j * layout_.cell - c.widen;
            const double y1 = y0 + layout_.cell + 2 * c.widen;
            const double dx = c.ox < x0 ? x0 - c.ox : (c.ox > x1 ? c.ox - x1 : 0.0);
            const double dy = c.oy < y0 ? y0 - c.oy : (c.oy > y1 ? c.oy - y1 : 0.0);
            const double radius = c.r + c.widen;
            if (dx * dx + dy * dy > radius * radius * (1 + kSquareRelative)) return;
            // The corner farthest left of ab.
            const double ex = bx_ - ax_, ey = by_ - ay_;
            const double px = (ey < 0 ? x1 : x0) - ax_, py = (ex > 0 ? y1 : y0) - ay_;
            if (ex * py - ey * px < -c.tolerance) return;
        }
        visit_cell(i, j);
    }

    /// True when d lies strictly left of a -> b (exact: the filter, then the exact stages).
    bool left_of_edge(const double* pd) {
        ++core_.counters.orient_calls;
        if (const auto sign = predicates::orient2d_filter(pa_, pb_, pd))
            return *sign == Sign::Positive;
        return predicates::orient2d_exact(pa_, pb_, pd) == Sign::Positive;
    }

    /// Takes d if it is left of ab and better than the current best. Inlined by force: the
    /// per-candidate call, once visit_tree also calls it, cost about 5%.
    [[gnu::always_inline]] void consider(VertIdx d) {
        if (d == a_ || d == b_) return;
        ++core_.counters.candidates;
        const double* pd = mesh_.point(d);
        if (best_ == kNone) {
            if (left_of_edge(pd)) take(d);
            return;
        }
        if (circle_.bounded) {
            // Prune-only (see the constants): skip d when it lies certainly outside a safe
            // over-estimate of the current circle, the same argument as for a cell or a kd box
            // (a point is a box of size zero). Whatever passes is decided by the exact
            // predicates below: no double bound takes a candidate.
            // w = d - a in the frame: one rounding per coordinate, at most 2^-53 (|e| + r) in
            // length, plus underflow below 2^-1073 (covered by the slack). A product d * frame_
            // that overflows puts d at least 2^971 from a, certainly outside (r <= 2^400); one
            // that meets an overflowed a * frame_ gives NaN, which no bound passes: exact test.
            const double wx = pd[0] * frame_ - fax_, wy = pd[1] * frame_ - fay_;
            const double ex = wx - circle_.ux, ey = wy - circle_.uy;
            const double dist2 = ex * ex + ey * ey;
            if (dist2 > circle_.outer2) return;  // certainly outside: not better
            // Within inner2 the power test cannot skip d: spare it (a shortcut, no decision).
            if (!(dist2 < circle_.inner2) && certainly_outside_by_power(pd)) return;
        }
        if (!left_of_edge(pd)) return;
        if (core_.incircle(a_, b_, best_, d) == Sign::Positive) take(d);
    }

    void take(VertIdx d) {
        best_ = d;
        circle_ = circle(d);
        stale_ = true;
    }

    /// cells_ = circle_ with its cell-picking bounds, and the box narrowed to its lens: the
    /// bounding box of a, b and those of the circle's leftmost, rightmost, lowest and highest
    /// points not certainly right of ab, widened by the circle's error bound.
    void refresh_cells() {
        stale_ = false;
        if (!circle_.bounded) return;  // keep the older, larger bound
        Circle& c = cells_;
        c = circle_;
        // From the edge's frame to grid units: exact powers of two (r <= 2^400 and the frame
        // is at most as coarse as the grid), but for underflow, which 1e-14 below covers.
        const double f = frame_to_grid_;
        c.ux *= f;
        c.uy *= f;
        c.r *= f;
        c.slack *= f;
        c.absolute *= f;
        // The error of the circle, of its absolute position (coordinates below 1 in magnitude:
        // a few units in the last place, under 1e-14) and of the cell boundaries.
        c.ox = ax_ + c.ux;
        c.oy = ay_ + c.uy;
        c.widen = 2 * c.slack + 2 * c.absolute +
                  kPositionRelative * (std::fabs(c.ox) + std::fabs(c.oy)) + kGridAbsolute +
                  kCellRelative * layout_.cell;
        const double ex = bx_ - ax_, ey = by_ - ay_;
        // A double cross product (b - a) x (p - a) for p within `widen` of where it is
        // computed: the shift plus a relative rounding error far above the true one, plus the
        // underflow of a and b in grid units (2^-1075 per coordinate, which can turn the
        // direction of a very short edge around; points p here lie within 4 + r + widen + cell).
        c.tolerance =
            (2 * c.widen + kCellRelative * (c.r + layout_.cell)) * (std::fabs(ex) + std::fabs(ey)) +
            kGridUnderflow * (4 + c.r + c.widen + layout_.cell);
        double lo_x = std::min(ax_, bx_), hi_x = std::max(ax_, bx_);
        double lo_y = std::min(ay_, by_), hi_y = std::max(ay_, by_);
        auto maybe_left = [&](double px, double py) { return ex * py - ey * px > -c.tolerance; };
        if (maybe_left(c.ux + c.r, c.uy)) hi_x = std::max(hi_x, c.ox + c.r);
        if (maybe_left(c.ux - c.r, c.uy)) lo_x = std::min(lo_x, c.ox - c.r);
        if (maybe_left(c.ux, c.uy + c.r)) hi_y = std::max(hi_y, c.oy + c.r);
        if (maybe_left(c.ux, c.uy - c.r)) lo_y = std::min(lo_y, c.oy - c.r);
        // Within the current box and the points' bounding box, the disk reaches only so far
        // along each axis: clip the x range by the disk over the y range, then the y range
        // over that x range (a circle far larger than the point set, through nearly collinear
        // points, would otherwise span the whole grid).
        const double w = c.widen, cell = layout_.cell;
        lo_x = std::max({lo_x, layout_.min_x + lo_i_ * cell, layout_.min_x}) - w;
        hi_x = std::min({hi_x, layout_.min_x + (hi_i_ + 1.0) * cell, layout_.max_x}) + w;
        lo_y = std::max({lo_y, layout_.min_y + lo_j_ * cell, layout_.min_y}) - w;
        hi_y = std::min({hi_y, layout_.min_y + (hi_j_ + 1.0) * cell, layout_.max_y}) + w;
        const double radius2 = (c.r + w) * (c.r + w) * (1 + kSquareRelative);
        auto half_chord = [radius2](double offset) {  // >= the true half chord at that offset
            return std::sqrt(std::max(0.0, radius2 - offset * offset * (1 - kSquareRelative))) *
                   (1 + kSquareRelative);
        };
        auto distance = [](double value, double lo, double hi) {
            return value < lo ? lo - value : (value > hi ? value - hi : 0.0);
        };
        const double half_x = half_chord(distance(c.oy, lo_y, hi_y));
        lo_x = std::max(lo_x, c.ox - half_x);
        hi_x = std::min(hi_x, c.ox + half_x);
        const double half_y = half_chord(distance(c.ox, lo_x, hi_x));
        lo_y = std::max(lo_y, c.oy - half_y);
        hi_y = std::min(hi_y, c.oy + half_y);
        lo_i_ = std::max(lo_i_, layout_.column(lo_x - w));
        hi_i_ = std::min(hi_i_, layout_.column(hi_x + w));
        lo_j_ = std::max(lo_j_, layout_.row(lo_y - w));
        hi_j_ = std::min(hi_j_, layout_.row(hi_y + w));
        boxed_ = true;
    }

    /// The circle through a, b, c in the edge's frame, with `slack` bounding the error of its
    /// centre and radius: the over-estimate the prunes use (and nothing else). The centre is
    /// computed in double when the angle at a is not tiny and c - a is neither tiny nor huge
    /// against b - a, else correctly rounded (predicates::circumcenter).
    /// Proof of the double centre's bound (u = 2^-53, first order; the second-order terms are
    /// below u times the first): let B, C be the exact offsets b - a, c - a in the frame, U the
    /// exact centre (2 B.U = |B|^2, 2 C.U = |C|^2), r = |U|, s = sin(angle at a), so that
    /// det(B, C) = |B| |C| s, and |B|, |C| <= 2r (chords).
    ///  1. The computed offsets b, c differ from B, C by at most u |B|, u |C| (the products by
    ///     frame_ are exact powers of two but for underflow, covered by kCircleAbsolute).
    ///     Differentiating the two equations, dU = M^-1 (dB.(B - U), dC.(C - U)) with
    ///     M = [B; C]; |B - U| = |C - U| = r and |M^-1 v| <= (|C| |v1| + |B| |v2|) / det, so
    ///     the circle of (0, b, c) has its centre within 2u r / s of U.
    ///  2. det = 2 (bx cy - by cx): error at most 3u (|bx cy| + |by cx|) <= 3u |b| |c|
    ///     (Cauchy-Schwarz), a relative error of 3u / s, which moves the quotient by 3u r / s.
    ///  3. The numerators cy b2 - by c2 and bx c2 - cx b2: each term is a product of 4 roundings
    ///     and the difference one more, error at most 5u (|c| |b|^2 + |b| |c|^2) for the pair
    ///     (as a vector); over |det| = 2 |b| |c| s that is 5u (|b| + |c|) / (2s) <= 10u r / s.
    ///  4. The divisions: u |U| <= u r per coordinate, 2u r in length.
    /// So the centre is within (2 + 3 + 10) u r / s + 2u r < 16u r / s + 2u r of U. The test
    /// below accepts the double centre when the computed |det| = 2 |b| |c| s exceeds
    /// 1e-4 |b| |c| (both as computed, relative errors below 8u), i.e. s > 5e-5 (1 - 16u) >
    /// 4.9e-5: the error is below 16u r / 4.9e-5 + 2u r < 3.7e-11 r. r is formed from the
    /// centre with a relative error below 2u, so the radius is within 3.8e-11 r of the true
    /// one. The slack is 1e-8 r (kDoubleCentreSlack), over 250 times that (the tests
    /// against it add their own rounding: kCertainRelative, kCertainSquares, kPowerRelative,
    /// at Circle and below); and 2^-300 < |c - a| < 2^300 (c2 in
    /// kDoubleCentreRange) with 1 <= |b - a|_inf < 2 keeps every product above 2^-1000 r and
    /// below overflow, but for a component of b or c near zero, whose products' underflow
    /// (2^-1074 each) kCircleAbsolute covers.
    Circle circle(VertIdx c) const {
        const double* pc = mesh_.point(c);
        const double bx = fbx_, by = fby_;
        const double cx = pc[0] * frame_ - fax_, cy = pc[1] * frame_ - fay_;
        const double det = 2 * (bx * cy - by * cx);
        const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
        Circle out;
        double absolute = 0;  // error of the centre not relative to r
        if (std::fabs(det) > kDoubleCentreMinSine * std::sqrt(b2 * c2) &&
            c2 > 1 / kDoubleCentreRange && c2 < kDoubleCentreRange) {
            out.ux = (cy * b2 - by * c2) / det;
            out.uy = (bx * c2 - cx * b2) / det;
        } else {
            try {
                const auto o = predicates::circumcenter(pa_, pb_, pc);
                const double ox = o[0] * frame_, oy = o[1] * frame_;
                out.ux = ox - fax_;
                out.uy = oy - fay_;
                // The centre's rounding (2^-53 relative, or 2^-1075 if subnormal, times the
                // frame) and the underflow of the products.
                absolute = kPositionRelative * (std::fabs(ox) + std::fabs(oy)) +
                           kFrameUnderflow * frame_ + kCircleAbsolute;
            } catch (const GeometryError&) {
                return out;
            }
        }
        const double r = std::sqrt(out.ux * out.ux + out.uy * out.uy);
        // The double centre: 1e-8 r. The correctly rounded one: its absolute rounding, and
        // a few units in the last place of r for forming u and r. Either way 2^-1000 covers
        // the underflow of the frame's products (2^-1075 each), and r >= |b - a| / 2 >= 2^-53.
        out.slack = (absolute > 0 ? kRoundedCentreSlack : kDoubleCentreSlack) * r + 2 * absolute +
                    kCircleAbsolute;
        out.r = r;
        // Beyond 2^400 (three points collinear to 2^-400 or so) the squares would overflow:
        // such a circle, or a non-finite one, is left to the exact predicates.
        if (!(r <= kLargestRadius) || !(out.slack <= 2 * kLargestRadius)) return out;
        // Certainly outside (skipped): |e| > r + slack + 2^-53 (|e| + r); certainly inside
        // (only spared the power test, see consider()): |e| below r - slack - 2^-53 (|e| + r). The
        // factors on the squares cover the rounding of dist2 and of these bounds, and (r and the
        // inner bound being above 2^-400) its underflow. The power's bound: see Circle (the slack
        // is at least twice sigma).
        const double outer = r * (1 + kCertainRelative) + out.slack;
        const double inner = r * (1 - kCertainRelative) - out.slack;
        out.outer2 = outer * outer * (1 + kCertainSquares);
        out.inner2 = inner > kSmallestInner ? inner * inner * (1 - kCertainSquares) : -1.0;
        out.power_slack = 2 * out.slack + kPowerRelative * r;
        out.power_absolute = kCircleAbsolute * r;
        out.absolute = absolute;
        out.bounded = true;
        return out;
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

/// The distinct points that may lie on the hull's boundary, sorted by (x, y). A cell with a
/// non-empty cell strictly left-below, left-above, right-below and right-above it holds only
/// interior points: cell indices are monotone in the coordinates, so such a point p has other
/// points strictly in its four open quadrants, and the segments joining the lower two and the
/// upper two pass below and above p, putting a neighbourhood of p inside the hull.
std::vector<VertIdx> hull_candidates(const detail::Delaunay2Core& core, const PointGrid& grid) {
    const std::uint32_t cols = grid.columns(), rows = grid.rows();
    constexpr std::uint32_t kEmpty = kNone;
    std::vector<std::uint32_t> low(cols, kEmpty), high(cols, 0);
    for (std::uint32_t j = 0; j < rows; ++j) {
        for (std::uint32_t i = 0; i < cols; ++i) {
            if (grid.empty(grid.index(i, j))) continue;
            low[i] = std::min(low[i], j);
            high[i] = std::max(high[i], j);
        }
    }
    // Lowest and highest non-empty row over the columns left of i, and right of i.
    std::vector<std::uint32_t> left_low(cols, kEmpty), left_high(cols, 0);
    std::vector<std::uint32_t> right_low(cols, kEmpty), right_high(cols, 0);
    for (std::uint32_t i = 1; i < cols; ++i) {
        left_low[i] = std::min(left_low[i - 1], low[i - 1]);
        left_high[i] = std::max(left_high[i - 1], high[i - 1]);
    }
    for (std::uint32_t i = cols - 1; i-- > 0;) {
        right_low[i] = std::min(right_low[i + 1], low[i + 1]);
        right_high[i] = std::max(right_high[i + 1], high[i + 1]);
    }
    std::vector<VertIdx> points;
    for (std::uint32_t j = 0; j < rows; ++j) {
        for (std::uint32_t i = 0; i < cols; ++i) {
            const std::size_t c = grid.index(i, j);
            if (grid.empty(c)) continue;
            // (An empty side has low = kEmpty and high = 0, failing both tests.)
            const bool interior =
                left_low[i] < j && left_high[i] > j && right_low[i] < j && right_high[i] > j;
            if (interior) continue;
            for (VertIdx v = grid.start[c]; v < grid.start[c + 1]; ++v) points.push_back(v);
        }
    }
    const TriMesh2& mesh = core.mesh;
    std::sort(points.begin(), points.end(), [&mesh](VertIdx a, VertIdx b) {
        const double* p = mesh.point(a);
        const double* q = mesh.point(b);
        return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
    });
    return points;
}

}  // namespace

Delaunay2Result tanemura_merriam_2d(std::span<const double> xy, const Delaunay2Options&) {
    // Vertices grouped by grid cell, cells in row-major order: the points of a cell are a
    // contiguous range of mesh vertices and neighbouring cells are mostly close in memory (the
    // candidate search is memory-bound otherwise); a crowded cell's range is in kd-tree order.
    // Gift wrapping needs distinct points, so duplicates (found within cells) go last and stay
    // out of the grid.
    validate_points_2d(xy);
    PointGrid grid;
    grid.layout = grid_layout(xy);
    CellOrder cells = cell_order(xy, grid.layout);
    const KdForest forest = kd_forest(xy, cells);
    grid.start = std::move(cells.start);
    detail::Delaunay2Core core(xy, std::move(cells.order));
    std::vector<bool> skip;
    if (!core.make_first_triangle(skip)) return core.collinear_result();
    // The first triangle only proved that the points are not all collinear.
    TriMesh2& mesh = core.mesh;
    mesh.tv.clear();
    mesh.twin.clear();
    mesh.free_triangles.clear();
    for (const auto& [copy, kept] : cells.duplicates) {
        core.merged_into[copy] = kept;
        ++core.counters.duplicates;
    }
    const std::uint32_t n = mesh.vertex_count();
    const std::vector<VertIdx> hull = convex_hull(core, hull_candidates(core, grid));
    GiftWrapper wrapper(core, grid, forest);
    // Front: directed edges whose left side is still empty, mapped to the half-edge on their
    // right (kNone for hull edges, whose right side is the outside).
    OpenEdges open(n);
    RowQueue queue(grid.rows());
    const double scale = grid.layout.scale;
    auto midpoint_row = [&](VertIdx a, VertIdx b) {
        return grid.layout.row((mesh.point(a)[1] * scale + mesh.point(b)[1] * scale) / 2);
    };
    for (std::size_t k = 0; k < hull.size(); ++k) {
        const VertIdx a = hull[k], b = hull[(k + 1) % hull.size()];
        open.insert(a, b, kNone);
        queue.push(midpoint_row(a, b), a, b);
    }
    mesh.tv.reserve(6 * std::size_t{cells.distinct});
    mesh.twin.reserve(6 * std::size_t{cells.distinct});
    VertIdx a, b;
    while (queue.pop(a, b)) {
        EdgeIdx outside;
        if (!open.take(a, b, outside)) continue;  // closed meanwhile by another triangle
        const VertIdx c = wrapper.third_vertex(a, b);
        // Appended directly: gift wrapping never frees a triangle. A triangulation of n points
        // has at most 2n - 5 triangles: a wrong third vertex would overlap earlier triangles
        // and could keep the front open forever, so stop with an internal error instead.
        const auto t = static_cast<TriIdx>(mesh.tv.size() / 3);
        EM_ASSERT(std::size_t{t} < 2 * std::size_t{cells.distinct});
        mesh.tv.insert(mesh.tv.end(), {a, b, c});
        mesh.twin.insert(mesh.twin.end(), {kNone, kNone, kNone});
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
                queue.push(midpoint_row(v, u), v, u);
            }
        }
    }
    return core.take_result();
}

}  // namespace exactmesh::triangulation
