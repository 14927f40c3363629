// SPDX-License-Identifier: MIT
// Size functions s(x, y) > 0: the target edge length of a mesh near (x, y). Kinds:
//  - none: +infinity everywhere (no size criterion);
//  - uniform: s = H;
//  - sources [seed material, issue 6]: point and line sources combined by the source formula
//        s(x) = min(H, sum_k s_k [1 + (d_k(x) / rbar_k)^gamma_k]),
//    d_k the distance from x to source k (a point r_k, or the closest point of a line segment),
//    s_k > 0 the source's size, rbar_k > 0 its radius of influence, gamma_k >= 0 its growth
//    exponent, and H (default +infinity) an optional cap;
//  - analytic: any callable the caller supplies (tests, built-in domains).
// Every kind can be scaled by a constant factor (benchmarks reach a target element count that
// way). The text form (`--size NUM|FILE`) is documented at parse_size_sources.
#pragma once

#include <functional>
#include <limits>
#include <memory>
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

    /// The size at (x, y).
    double operator()(double x, double y) const {
        return kind_ == Kind::None ? kInfinity : kind_ == Kind::Uniform ? factor_ * cap_ : factor_ * evaluate(x, y);
    }
    /// False for the "none" function (no size criterion).
    bool bounded() const { return kind_ != Kind::None; }
    /// True for a uniform size (then the size is the same everywhere).
    bool is_uniform() const { return kind_ == Kind::Uniform; }
    /// True for point and line sources (point_sources(), line_sources(), cap(), factor() then
    /// give the whole function: factor * min(cap, sum of the sources)).
    bool is_sources() const { return kind_ == Kind::Sources; }
    /// H: the uniform size (uniform), the cap of the sources (+infinity for none).
    double cap() const { return cap_; }
    /// The constant factor of scaled() (1 unless scaled).
    double factor() const { return factor_; }
    /// s * factor (factor finite and > 0).
    SizeFunction scaled(double factor) const;
    /// One line: "uniform 0.1", "sources: 2 point, 1 line, cap 0.5", the analytic description.
    std::string describe() const;

    const std::vector<PointSource>& point_sources() const { return points_; }
    const std::vector<LineSource>& line_sources() const { return lines_; }

private:
    static constexpr double kInfinity = std::numeric_limits<double>::infinity();
    enum class Kind { None, Uniform, Sources, Analytic };
    Kind kind_ = Kind::None;
    double cap_ = kInfinity;
    double factor_ = 1.0;
    std::vector<PointSource> points_;
    std::vector<LineSource> lines_;
    std::shared_ptr<const std::function<double(double, double)>> analytic_;
    std::string description_;
    double evaluate(double x, double y) const;
};

/// `--size` text: a number (a uniform size), else the content of a size file. The file holds
/// one item per line; `#` starts a comment; blank lines are ignored:
///     uniform H                        the cap H (alone: s = H everywhere)
///     point X Y S RBAR GAMMA           a point source at (X, Y)
///     line X0 Y0 X1 Y1 S RBAR GAMMA    a line source along the segment (X0, Y0) - (X1, Y1)
/// with the meaning of SizeFunction::sources. `name` names the text in errors (a file name).
/// @throws InputError "name:line: ..." on anything else.
SizeFunction parse_size_sources(std::string_view text, std::string_view name);

/// The number, when `text` is one finite number > 0 (the whole text, e.g. "0.05"); else false.
bool parse_uniform_size(std::string_view text, double& size);

}  // namespace exactmesh::generators
