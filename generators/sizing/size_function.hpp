// SPDX-License-Identifier: MIT
// Size functions s(x, y) > 0: the target edge length of a mesh near (x, y). Kinds:
//  - none: +infinity everywhere (no size criterion; a generator that needs a size then gets
//    graded_size_from_boundary from `exactmesh mesh`:
//    generators/boundary/graded_boundary_size_2d.hpp);
//  - uniform: s = H;
//  - sources [seed material, issue 6]: point and line sources combined by the source formula
//        s(x) = min(H, sum_k s_k [1 + (d_k(x) / rbar_k)^gamma_k]),
//    d_k the distance from x to source k (a point r_k, or the closest point of a line segment),
//    s_k > 0 the source's size, rbar_k > 0 its radius of influence, gamma_k >= 0 its growth
//    exponent, and H (default +infinity) an optional cap;
//  - analytic: any callable the caller supplies (tests, built-in domains);
//  - background mesh: linear interpolation of sizes at the vertices of a triangulation
//    (generators/sizing/background_size_2d.hpp);
//  - quadtree: a 2:1 balanced quadtree refined where another size field varies, bilinear in
//    its leaves (generators/sizing/size_quadtree_2d.hpp);
//  - smoothed: another size field on a background grid, its gradient limited, smoothed by a
//    screened Poisson (elliptic) equation with its local minima kept, limited again, bilinear
//    between the grid's nodes (generators/sizing/size_smoothing_2d.hpp).
// Every kind can be scaled by a constant factor (benchmarks reach a target element count that
// way), with an optional ceiling (a budget's scaling reaching sizes beyond the domain: they
// would overflow to infinity, and a size above the domain's extent asks nothing of a mesh:
// size_ceiling_2d). The text form (`--size NUM|FILE`) is documented at parse_size_sources.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace exactmesh::generators {

struct PointSource {
    double x = 0, y = 0;
    double size = 1;      ///< s_k > 0
    double radius = 1;    ///< rbar_k > 0
    double exponent = 1;  ///< gamma_k >= 0
};

struct LineSource {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  ///< the segment (may be a point)
    double size = 1;
    double radius = 1;
    double exponent = 1;
};

/// The box a quadtree or a smoothing grid covers (x0 < x1, y0 < y1). Outside it, those kinds
/// take the value at the nearest point of the box.
struct SizeBox {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

/// How SizeFunction::quadtree refines (generators/sizing/size_quadtree_2d.hpp).
struct QuadtreeSizeOptions {
    /// Split a cell while the field at its centre or an edge midpoint differs from the bilinear
    /// interpolation of the cell's corners by more than tolerance times the field there.
    double tolerance = 0.05;
    /// Split a cell while its side exceeds cell_factor times the smallest of those nine values
    /// (0: no such rule).
    double cell_factor = 1.0;
    /// Budgets: a cell that would have to be split below max_depth, or a tree of more than
    /// max_leaves leaves, is a GeometryError (the field varies too fast to follow).
    int max_depth = 24;
    std::uint32_t max_leaves = 1u << 22;
};

/// How SizeFunction::smoothed smooths (generators/sizing/size_smoothing_2d.hpp).
struct SmoothingOptions {
    std::uint32_t nx = 64, ny = 64;  ///< grid nodes in x and y (each at least 2)
    /// The gradient limit g > 0: inside every grid cell |ds/dx| <= g and |ds/dy| <= g (+infinity:
    /// no limit).
    double gradation = 0.3;
    /// The smoothing length L >= 0 (the screened Poisson equation s - L^2 laplace(s) = s1); 0
    /// means twice the larger grid spacing.
    double length = 0;
    /// The conjugate gradient iteration stops at ||r||_2 <= residual * ||b||_2.
    double residual = 1e-10;
    /// Keep the field's value at the nodes where it has a local minimum (the sources' own
    /// places: a point source's apex, the nodes along a line source) as Dirichlet values.
    bool pin_minima = true;
};

class BackgroundSizeMesh2;
class SizeQuadtree2;
class SmoothedSizeGrid2;

class SizeFunction {
  public:
    /// No size criterion: +infinity everywhere.
    SizeFunction();
    /// s = h everywhere. @throws InputError unless h is finite and > 0.
    static SizeFunction uniform(double h);
    /// The source formula above; cap = H (+infinity for none). At least one source or a finite
    /// cap. @throws InputError on a non-finite or non-positive size, radius or cap, or a negative
    /// or non-finite exponent.
    static SizeFunction sources(std::vector<PointSource> points, std::vector<LineSource> lines,
                                double cap = std::numeric_limits<double>::infinity());
    /// s = f(x, y); f must return a value > 0 (+infinity allowed) at every point of the domain.
    static SizeFunction analytic(std::function<double(double, double)> f, std::string description);
    /// At most f anywhere in the box [x0, x1] x [y0, y1], but for a few units in the last place.
    using BoxLowerBound = std::function<double(double x0, double y0, double x1, double y1)>;
    /// The same with a lower bound over boxes (lower_bound_in_box).
    static SizeFunction analytic(std::function<double(double, double)> f, std::string description,
                                 BoxLowerBound lower_bound);
    /// Linear interpolation of `sizes` over a triangulation (barycentric inside a triangle; at a
    /// point outside every triangle, the value at the nearest point of the triangulation).
    /// `xy`: 2·#V, `sizes`: #V finite > 0, `triangles`: 3·#T counter-clockwise, 0-based.
    /// @throws BackgroundMeshError (an InputError) naming the bad vertex or triangle.
    static SizeFunction background_mesh(std::vector<double> xy, std::vector<double> sizes,
                                        std::vector<std::uint32_t> triangles);
    /// A quadtree over `box` following `field` (bounded, finite > 0 in the box), bilinear in its
    /// leaves and continuous across them. @throws InputError on a bad box, options or field
    /// value; GeometryError when a budget of the options is exhausted.
    static SizeFunction quadtree(const SizeFunction& field, const SizeBox& box,
                                 const QuadtreeSizeOptions& options = {});
    /// `field` (finite > 0 in the box) sampled on a grid over `box`, gradient-limited and
    /// smoothed, bilinear between the nodes; never outside the range of the field's node values.
    /// @throws InputError on a bad box, options or field value; GeometryError when the solver
    /// does not reach its residual within its iteration budget.
    static SizeFunction smoothed(const SizeFunction& field, const SizeBox& box,
                                 const SmoothingOptions& options = {});

    /// The size at (x, y).
    double operator()(double x, double y) const {
        return kind_ == Kind::None      ? kInfinity
               : kind_ == Kind::Uniform ? std::min(factor_ * cap_, ceiling_)
                                        : std::min(factor_ * evaluate(x, y), ceiling_);
    }
    /// At most the size anywhere in the box [x0, x1] x [y0, y1], but for a few units in the last
    /// place: the uniform size, an analytic function's given bound, +infinity for none, 0
    /// (nothing known) for the other kinds. A generator settles its size criterion over a whole
    /// box by it, without sampling (the quadtree: the same splits as its samples make).
    double lower_bound_in_box(double x0, double y0, double x1, double y1) const {
        if (kind_ == Kind::None || kind_ == Kind::Uniform) return (*this)(x0, y0);
        if (kind_ != Kind::Analytic || !analytic_lower_) return 0.0;
        return std::min(factor_ * (*analytic_lower_)(x0, y0, x1, y1), ceiling_);
    }
    /// False for the "none" function (no size criterion).
    bool bounded() const { return kind_ != Kind::None; }
    /// True for a uniform size (then the size is the same everywhere).
    bool is_uniform() const { return kind_ == Kind::Uniform; }
    /// True when the size may be evaluated on several threads at once: every kind but analytic
    /// (a caller's function may keep state, as the command's muParser expressions do: each
    /// writes its variables before evaluating); the others only read what they were built with.
    bool concurrent() const { return kind_ != Kind::Analytic; }
    /// True for point and line sources (point_sources(), line_sources(), cap(), factor() then
    /// give the whole function: factor * min(cap, sum of the sources), at most ceiling()).
    bool is_sources() const { return kind_ == Kind::Sources; }
    /// H: the uniform size (uniform), the cap of the sources (+infinity for none).
    double cap() const { return cap_; }
    /// The constant factor of scaled() (1 unless scaled).
    double factor() const { return factor_; }
    /// The ceiling of scaled() (+infinity unless given): every value is at most this.
    double ceiling() const { return ceiling_; }
    /// min(s * factor, ceiling) (factor finite and > 0, ceiling > 0; a product that overflows
    /// takes the ceiling). A ceiling lowers an earlier one, never raises it.
    SizeFunction scaled(double factor, double ceiling = kInfinity) const;
    /// One line: "uniform 0.1", "sources: 2 point, 1 line, cap 0.5", the analytic description,
    /// "background mesh: 4 vertices, 2 triangles", "quadtree of (...): 120 leaves, depth 7",
    /// "smoothed (...) on a 64 x 64 grid, gradation 0.3, length 0.03".
    std::string describe() const;

    const std::vector<PointSource>& point_sources() const { return points_; }
    const std::vector<LineSource>& line_sources() const { return lines_; }
    /// The background mesh, quadtree or smoothing grid behind those kinds (else null).
    const BackgroundSizeMesh2* background_mesh() const { return background_.get(); }
    const SizeQuadtree2* quadtree() const { return quadtree_.get(); }
    const SmoothedSizeGrid2* smoothing_grid() const { return smoothed_.get(); }
    /// Whether the size drops far below its usual values over short distances (a size graded
    /// down to fine features: graded_to_fine_features), so that a boundary's discretization
    /// must sample it adaptively rather than uniformly.
    bool is_steep() const { return steep_; }
    /// The same function marked steep.
    SizeFunction marked_steep() const {
        SizeFunction s = *this;
        s.steep_ = true;
        return s;
    }

  private:
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    enum class Kind { None, Uniform, Sources, Analytic, Background, Quadtree, Smoothed };
    Kind kind_ = Kind::None;
    double cap_ = kInfinity;
    double factor_ = 1.0;
    double ceiling_ = kInfinity;
    std::vector<PointSource> points_;
    std::vector<LineSource> lines_;
    std::shared_ptr<const std::function<double(double, double)>> analytic_;
    std::shared_ptr<const BoxLowerBound> analytic_lower_;
    std::shared_ptr<const BackgroundSizeMesh2> background_;
    std::shared_ptr<const SizeQuadtree2> quadtree_;
    std::shared_ptr<const SmoothedSizeGrid2> smoothed_;
    std::string description_;
    bool steep_ = false;
    double evaluate(double x, double y) const;
    /// quadtree() and smoothed(): a function of `kind` described as `field`, which must be
    /// bounded (InputError "<what>: the size field is unbounded (none)"), evaluated by a Grid
    /// sampled from the field over `box` and kept in `grid`.
    template <class Grid, class Options>
    static SizeFunction sampled(const SizeFunction& field, const SizeBox& box,
                                const Options& options, Kind kind,
                                std::shared_ptr<const Grid> SizeFunction::*grid, const char* what);
};

/// The number of equilateral triangles of edge s(x, y) that cover the box [x0, x1] x [y0, y1]:
/// a 64 x 64 sample of 2.31 / s^2 times the cell's area (the generators' automatic budgets and
/// reservations; a rough estimate in double precision). 0 for an unbounded size, and when the
/// estimate is unknown (a subnormal box, where the cells' areas and s^2 underflow to 0 / 0).
double equilateral_count_in_box(const SizeFunction& size, double x0, double y0, double x1,
                                double y1);

/// Twice the larger side of the bounding box of the points `xy` (2·#V, finite; the largest
/// double when that overflows or is 0): no edge of a mesh of a domain with those points is as long,
/// so a size at or above it asks nothing of a generator, and a scaled size may be capped there.
/// Scales with the points by powers of two (halves of coordinates subtracted: no overflow
/// before the doubling).
double size_ceiling_2d(std::span<const double> xy);

/// `--size` text: a number (a uniform size), else the content of a size file. The file holds
/// one item per line; `#` starts a comment; blank lines are ignored:
///     uniform H                        the cap H (alone: s = H everywhere)
///     point X Y S RBAR GAMMA           a point source at (X, Y)
///     line X0 Y0 X1 Y1 S RBAR GAMMA    a line source along the segment (X0, Y0) - (X1, Y1)
/// with the meaning of SizeFunction::sources; or, instead of those (they do not mix), a
/// background mesh (SizeFunction::background_mesh):
///     vertex X Y S                     a vertex with size S > 0 (numbered 0, 1, ... in order)
///     triangle I J K                   a counter-clockwise triangle of vertices I, J, K
/// and then at most one of these, turning the field above into another kind over a box:
///     box X0 Y0 X1 Y1                  the box (required by quadtree and smooth)
///     quadtree [TOL [FACTOR]]          SizeFunction::quadtree, tolerance TOL (0.05), cell
///                                      factor FACTOR (1)
///     smooth NX NY [GRADE [LENGTH]]    SizeFunction::smoothed on an NX x NY grid (2 to 16384
///                                      each, at most 2^20 nodes, and a solve estimated at at
///                                      most 2^29 node-iterations: size_smoothing_2d.hpp),
///                                      gradation GRADE (0.3), length LENGTH (0: twice the
///                                      grid spacing)
/// Items may come in any order. `name` names the text in errors (a file name).
/// @throws InputError "name:line: ..." on anything else (a bad vertex or triangle of the
///         background mesh names its line; a bad quadtree or smoothing the directive's line);
///         GeometryError "name:line: ..." when a quadtree or smoothing budget is exhausted.
SizeFunction parse_size_sources(std::string_view text, std::string_view name);

/// The number, when `text` is one finite number > 0 (the whole text, e.g. "0.05"); else false.
bool parse_uniform_size(std::string_view text, double& size);

}  // namespace exactmesh::generators
