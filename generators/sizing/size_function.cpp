// SPDX-License-Identifier: MIT
// Size functions (see size_function.hpp). The source term (d / rbar)^gamma is evaluated without
// pow for gamma 0, 1, 1.5 and 2 (gamma 2 of a point source needs no square root either): the
// refinement evaluates the size at three edge midpoints per new triangle.
#include "generators/sizing/size_function.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/sizing/background_size_2d.hpp"
#include "generators/sizing/size_quadtree_2d.hpp"
#include "generators/sizing/size_smoothing_2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace {

void require_positive(double value, const std::string& what) {
    if (!(std::isfinite(value) && value > 0)) {
        throw InputError(what + " must be a finite number > 0 (got " + format_number(value) + ")");
    }
}

void require_exponent(double value, const std::string& what) {
    if (!(std::isfinite(value) && value >= 0)) {
        throw InputError(what + " must be a finite number >= 0 (got " + format_number(value) + ")");
    }
}

/// Scale invariance: distances and radii are first scaled exactly by the power of two that
/// brings the radius to [1, 2), so that no square overflows or underflows and a size function
/// scaled with its domain by a power of two gives the same values, scaled, bit for bit (and the
/// values of unscaled inputs are those of the plain formula).
predicates::PowerOfTwo radius_unit(double radius) {
    return predicates::PowerOfTwo(radius > 0 ? predicates::unit_shift(radius) : 0);
}

/// (d / radius)^exponent from the squared distance d2, both in the radius' unit (radius_unit).
double growth(double d2, double radius, double exponent) {
    if (exponent == 2.0) return d2 / (radius * radius);
    if (exponent == 0.0) return 1.0;
    const double ratio = std::sqrt(d2) / radius;
    if (exponent == 1.0) return ratio;
    if (exponent == 1.5) return ratio * std::sqrt(ratio);  // the sample airfoils' grading
    return std::pow(ratio, exponent);
}

/// The squared distance from (x, y) to the segment, in the radius' unit, squared.
double squared_distance_to_segment(double x, double y, const LineSource& l,
                                   const predicates::PowerOfTwo& unit) {
    const double dx = l.x1 - l.x0, dy = l.y1 - l.y0;
    const double sx = unit(dx), sy = unit(dy);
    const double length2 = sx * sx + sy * sy;
    double t = 0.0;
    if (length2 > 0)
        t = std::clamp((unit(x - l.x0) * sx + unit(y - l.y0) * sy) / length2, 0.0, 1.0);
    const double ex = unit(x - (l.x0 + t * dx)), ey = unit(y - (l.y0 + t * dy));
    return ex * ex + ey * ey;
}

}  // namespace

SizeFunction::SizeFunction() = default;

SizeFunction SizeFunction::uniform(double h) {
    require_positive(h, "uniform size");
    SizeFunction f;
    f.kind_ = Kind::Uniform;
    f.cap_ = h;
    return f;
}

SizeFunction SizeFunction::sources(std::vector<PointSource> points, std::vector<LineSource> lines,
                                   double cap) {
    if (!(cap > 0) || std::isnan(cap))
        throw InputError("size cap must be > 0 (got " + format_number(cap) + ")");
    for (std::size_t k = 0; k < points.size(); ++k) {
        const PointSource& p = points[k];
        const std::string name = "point source " + std::to_string(k + 1);
        if (!std::isfinite(p.x) || !std::isfinite(p.y))
            throw InputError(name + ": non-finite position");
        require_positive(p.size, name + ": size");
        require_positive(p.radius, name + ": radius");
        require_exponent(p.exponent, name + ": exponent");
    }
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const LineSource& l = lines[k];
        const std::string name = "line source " + std::to_string(k + 1);
        if (!std::isfinite(l.x0) || !std::isfinite(l.y0) || !std::isfinite(l.x1) ||
            !std::isfinite(l.y1)) {
            throw InputError(name + ": non-finite end point");
        }
        require_positive(l.size, name + ": size");
        require_positive(l.radius, name + ": radius");
        require_exponent(l.exponent, name + ": exponent");
    }
    if (points.empty() && lines.empty()) {
        if (std::isinf(cap)) throw InputError("size function: no source and no uniform size");
        return uniform(cap);
    }
    SizeFunction f;
    f.kind_ = Kind::Sources;
    f.cap_ = cap;
    f.points_ = std::move(points);
    f.lines_ = std::move(lines);
    return f;
}

SizeFunction SizeFunction::analytic(std::function<double(double, double)> function,
                                    std::string description) {
    SizeFunction f;
    f.kind_ = Kind::Analytic;
    f.analytic_ =
        std::make_shared<const std::function<double(double, double)>>(std::move(function));
    f.description_ = std::move(description);
    return f;
}

SizeFunction SizeFunction::analytic(std::function<double(double, double)> function,
                                    std::string description, BoxLowerBound lower_bound) {
    SizeFunction f = analytic(std::move(function), std::move(description));
    f.analytic_lower_ = std::make_shared<const BoxLowerBound>(std::move(lower_bound));
    return f;
}

SizeFunction SizeFunction::background_mesh(std::vector<double> xy, std::vector<double> sizes,
                                           std::vector<std::uint32_t> triangles) {
    SizeFunction f;
    f.kind_ = Kind::Background;
    f.background_ = std::make_shared<const BackgroundSizeMesh2>(std::move(xy), std::move(sizes),
                                                                std::move(triangles));
    return f;
}

template <class Grid, class Options>
SizeFunction SizeFunction::sampled(const SizeFunction& field, const SizeBox& box,
                                   const Options& options, Kind kind,
                                   std::shared_ptr<const Grid> SizeFunction::*grid,
                                   const char* what) {
    if (!field.bounded()) {
        throw InputError(std::string(what) + ": the size field is unbounded (none)");
    }
    SizeFunction f;
    f.kind_ = kind;
    f.*grid = std::make_shared<const Grid>([&field](double x, double y) { return field(x, y); },
                                           box, options);
    f.description_ = field.describe();
    return f;
}

SizeFunction SizeFunction::quadtree(const SizeFunction& field, const SizeBox& box,
                                    const QuadtreeSizeOptions& options) {
    return sampled(field, box, options, Kind::Quadtree, &SizeFunction::quadtree_, "size quadtree");
}

SizeFunction SizeFunction::smoothed(const SizeFunction& field, const SizeBox& box,
                                    const SmoothingOptions& options) {
    return sampled(field, box, options, Kind::Smoothed, &SizeFunction::smoothed_, "size smoothing");
}

double SizeFunction::evaluate(double x, double y) const {
    switch (kind_) {
        case Kind::Analytic:
            return (*analytic_)(x, y);
        case Kind::Background:
            return (*background_)(x, y);
        case Kind::Quadtree:
            return (*quadtree_)(x, y);
        case Kind::Smoothed:
            return (*smoothed_)(x, y);
        default:
            break;
    }
    double s = 0.0;
    for (const PointSource& p : points_) {
        const predicates::PowerOfTwo unit = radius_unit(p.radius);
        const double dx = unit(x - p.x), dy = unit(y - p.y);
        s += p.size * (1.0 + growth(dx * dx + dy * dy, unit(p.radius), p.exponent));
    }
    for (const LineSource& l : lines_) {
        const predicates::PowerOfTwo unit = radius_unit(l.radius);
        s += l.size *
             (1.0 + growth(squared_distance_to_segment(x, y, l, unit), unit(l.radius), l.exponent));
    }
    return std::min(s, cap_);
}

SizeFunction SizeFunction::scaled(double factor, double ceiling) const {
    require_positive(factor, "size scale factor");
    if (!(ceiling > 0)) {
        throw InputError("size ceiling must be > 0 (got " + format_number(ceiling) + ")");
    }
    SizeFunction f = *this;
    f.factor_ *= factor;
    f.ceiling_ = std::min(ceiling_, ceiling);
    return f;
}

double size_ceiling_2d(std::span<const double> xy) {
    if (xy.size() < 2) return std::numeric_limits<double>::max();
    double x0 = xy[0], x1 = xy[0], y0 = xy[1], y1 = xy[1];
    for (std::size_t i = 2; i + 1 < xy.size(); i += 2) {
        x0 = std::min(x0, xy[i]);
        x1 = std::max(x1, xy[i]);
        y0 = std::min(y0, xy[i + 1]);
        y1 = std::max(y1, xy[i + 1]);
    }
    // The halves are exact but for subnormal coordinates (off by half a unit at most); the
    // ceiling, twice the side, exceeds every edge (at most sqrt(2) sides) by a margin that
    // covers that rounding.
    const double half = std::max(0.5 * x1 - 0.5 * x0, 0.5 * y1 - 0.5 * y0);
    const double ceiling = 4 * half;
    return std::isfinite(ceiling) && ceiling > 0 ? ceiling : std::numeric_limits<double>::max();
}

std::string SizeFunction::describe() const {
    std::string text;
    switch (kind_) {
        case Kind::None:
            return "none";
        case Kind::Uniform:
            return "uniform " + format_number(factor_ * cap_);
        case Kind::Sources:
            text = "sources: " + std::to_string(points_.size()) + " point, " +
                   std::to_string(lines_.size()) + " line";
            if (std::isfinite(cap_)) text += ", cap " + format_number(cap_);
            break;
        case Kind::Analytic:
            text = description_;
            break;
        case Kind::Background:
            text = "background mesh: " + std::to_string(background_->vertex_count()) +
                   " vertices, " + std::to_string(background_->triangle_count()) + " triangles";
            break;
        case Kind::Quadtree:
            text = "quadtree of (" + description_ +
                   "): " + std::to_string(quadtree_->leaf_count()) + " leaves, depth " +
                   std::to_string(quadtree_->depth());
            break;
        case Kind::Smoothed:
            text = "smoothed (" + description_ + ") on a " + std::to_string(smoothed_->nx()) +
                   " x " + std::to_string(smoothed_->ny()) + " grid, gradation " +
                   format_number(smoothed_->gradation()) + ", length " +
                   format_number(smoothed_->length());
            break;
    }
    if (factor_ != 1.0) text += ", scaled by " + format_number(factor_);
    if (std::isfinite(ceiling_)) text += ", at most " + format_number(ceiling_);
    return text;
}

bool parse_uniform_size(std::string_view text, double& size) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front())))
        text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back())))
        text.remove_suffix(1);
    if (text.empty()) return false;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return false;
    if (!(std::isfinite(value) && value > 0)) return false;
    size = value;
    return true;
}

namespace {

/// The parser's state: what the lines said, with the line of each item for later errors.
struct SizeText {
    std::vector<PointSource> points;
    std::vector<LineSource> lines;
    double cap = std::numeric_limits<double>::infinity();
    int cap_line = 0, source_line = 0;
    SizeBox box;
    int box_line = 0;
    QuadtreeSizeOptions quadtree;
    int quadtree_line = 0;
    SmoothingOptions smoothing;
    int smooth_line = 0;
    std::vector<double> xy, sizes;
    std::vector<std::uint32_t> triangles;
    std::vector<int> vertex_lines, triangle_lines;
};

std::uint32_t grid_count(double value, const char* what) {
    if (!(value >= 2 && value <= 16384 && value == std::floor(value))) {
        throw InputError(std::string(what) + " must be an integer in [2, 16384] (got " +
                         format_number(value) + ")");
    }
    return static_cast<std::uint32_t>(value);
}

std::uint32_t vertex_number(double value) {
    if (!(value >= 0 && value < 4294967295.0 && value == std::floor(value))) {
        throw InputError("'" + format_number(value) + "' is not a vertex number (an integer >= 0)");
    }
    return static_cast<std::uint32_t>(value);
}

void parse_item(SizeText& t, const std::string& keyword, const std::vector<double>& values,
                int number, const std::string& where) {
    auto expect = [&](std::size_t low, std::size_t high, const char* form) {
        if (values.size() < low || values.size() > high) {
            const std::string count = low == high
                                          ? std::to_string(low)
                                          : std::to_string(low) + " to " + std::to_string(high);
            throw InputError(where + keyword + " takes " + count + " numbers (" + form + "), got " +
                             std::to_string(values.size()));
        }
    };
    const bool mesh_item = keyword == "vertex" || keyword == "triangle";
    const bool source_item = keyword == "uniform" || keyword == "point" || keyword == "line";
    if ((mesh_item && t.source_line != 0) || (source_item && !t.vertex_lines.empty())) {
        throw InputError(
            "sources (uniform, point, line) and a background mesh (vertex, triangle) do not mix "
            "(line " +
            std::to_string(mesh_item ? t.source_line : t.vertex_lines.front()) + ")");
    }
    if (keyword == "uniform") {
        expect(1, 1, "H");
        if (t.cap_line != 0) throw InputError("a second uniform line");
        require_positive(values[0], "uniform size");
        t.cap = values[0];
        t.cap_line = number;
    } else if (keyword == "point") {
        expect(5, 5, "X Y S RBAR GAMMA");
        t.points.push_back({values[0], values[1], values[2], values[3], values[4]});
        SizeFunction::sources({t.points.back()}, {});  // validates this one
    } else if (keyword == "line") {
        expect(7, 7, "X0 Y0 X1 Y1 S RBAR GAMMA");
        t.lines.push_back(
            {values[0], values[1], values[2], values[3], values[4], values[5], values[6]});
        SizeFunction::sources({}, {t.lines.back()});
    } else if (keyword == "vertex") {
        expect(3, 3, "X Y S");
        require_positive(values[2], "vertex size");
        t.xy.insert(t.xy.end(), {values[0], values[1]});
        t.sizes.push_back(values[2]);
        t.vertex_lines.push_back(number);
    } else if (keyword == "triangle") {
        expect(3, 3, "I J K");
        for (const double v : values) t.triangles.push_back(vertex_number(v));
        t.triangle_lines.push_back(number);
    } else if (keyword == "box") {
        expect(4, 4, "X0 Y0 X1 Y1");
        if (t.box_line != 0) throw InputError("a second box line");
        if (!(values[0] < values[2] && values[1] < values[3]))
            throw InputError("box needs X0 < X1 and Y0 < Y1");
        t.box = {values[0], values[1], values[2], values[3]};
        t.box_line = number;
    } else if (keyword == "quadtree") {
        expect(0, 2, "[TOL [FACTOR]]");
        if (t.quadtree_line != 0 || t.smooth_line != 0)
            throw InputError("at most one quadtree or smooth line");
        if (!values.empty()) t.quadtree.tolerance = values[0];
        if (values.size() > 1) t.quadtree.cell_factor = values[1];
        t.quadtree_line = number;
    } else if (keyword == "smooth") {
        expect(2, 4, "NX NY [GRADE [LENGTH]]");
        if (t.quadtree_line != 0 || t.smooth_line != 0)
            throw InputError("at most one quadtree or smooth line");
        t.smoothing.nx = grid_count(values[0], "NX");
        t.smoothing.ny = grid_count(values[1], "NY");
        if (values.size() > 2) t.smoothing.gradation = values[2];
        if (values.size() > 3) t.smoothing.length = values[3];
        t.smooth_line = number;
    } else {
        throw InputError(
            "unknown item '" + keyword +
            "' (expected uniform, point, line, vertex, triangle, box, quadtree or smooth)");
    }
    if (source_item) t.source_line = t.source_line != 0 ? t.source_line : number;
}

std::string at_line(std::string_view name, int line) {
    return std::string(name) + ":" + std::to_string(line) + ": ";
}

/// Rethrows the error of building a quadtree or a smoothing grid with its line in front.
[[noreturn]] void rethrow_at(const std::string& where) {
    try {
        throw;
    } catch (const GeometryError& error) {
        throw GeometryError(where + error.what());
    } catch (const InputError& error) {
        throw InputError(where + error.what());
    }
}

}  // namespace

SizeFunction parse_size_sources(std::string_view text, std::string_view name) {
    SizeText t;
    // A UTF-8 byte order mark (an editor's) is skipped, as the mesh files' readers skip it.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    std::istringstream in{std::string(text)};
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = at_line(name, number);
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::string keyword;
        if (!(words >> keyword)) continue;
        std::vector<double> values;
        std::string word;
        while (words >> word) {
            double value = 0;
            const auto [end, error] =
                std::from_chars(word.data(), word.data() + word.size(), value);
            if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
                throw InputError(where + "'" + word + "' is not a finite number");
            }
            values.push_back(value);
        }
        try {
            parse_item(t, keyword, values, number, where);
        } catch (const InputError& error) {
            const std::string message = error.what();
            if (message.rfind(where, 0) == 0) throw;
            throw InputError(where + message);
        }
    }
    SizeFunction field;
    if (!t.vertex_lines.empty() || !t.triangle_lines.empty()) {
        if (t.triangle_lines.empty()) {
            throw InputError(at_line(name, t.vertex_lines.back()) +
                             "vertex lines but no triangle line");
        }
        try {
            field = SizeFunction::background_mesh(std::move(t.xy), std::move(t.sizes),
                                                  std::move(t.triangles));
        } catch (const BackgroundMeshError& error) {
            using Item = BackgroundMeshError::Item;
            if (error.item() == Item::Vertex) {
                throw InputError(at_line(name, t.vertex_lines[error.index()]) + "vertex " +
                                 std::to_string(error.index()) + ": " + error.detail());
            }
            if (error.item() == Item::Triangle) {
                throw InputError(at_line(name, t.triangle_lines[error.index()]) + "triangle " +
                                 std::to_string(error.index()) + ": " + error.detail());
            }
            throw InputError(std::string(name) + ": background mesh: " + error.detail());
        }
    } else {
        if (t.points.empty() && t.lines.empty() && t.cap_line == 0) {
            throw InputError(std::string(name) +
                             ": no size given (expected uniform, point or line lines, or vertex "
                             "and triangle lines)");
        }
        field = SizeFunction::sources(std::move(t.points), std::move(t.lines), t.cap);
    }
    const int directive = t.quadtree_line != 0 ? t.quadtree_line : t.smooth_line;
    if (directive == 0) return field;
    const std::string where = at_line(name, directive);
    if (t.box_line == 0) {
        throw InputError(where + (t.quadtree_line != 0 ? "quadtree" : "smooth") +
                         " needs a box line (box X0 Y0 X1 Y1)");
    }
    try {
        if (t.quadtree_line != 0) return SizeFunction::quadtree(field, t.box, t.quadtree);
        return SizeFunction::smoothed(field, t.box, t.smoothing);
    } catch (const Error&) {
        rethrow_at(where);
    }
}

double equilateral_count_in_box(const SizeFunction& size, double x0, double y0, double x1,
                                double y1) {
    if (!size.bounded()) return 0;
    constexpr int kSamples = 64;
    const double dx = (x1 - x0) / kSamples, dy = (y1 - y0) / kSamples;
    double estimate = 0;
    for (int i = 0; i < kSamples; ++i) {
        for (int j = 0; j < kSamples; ++j) {
            const double s = size(x0 + (i + 0.5) * dx, y0 + (j + 0.5) * dy);
            // In units of s (no overflow or underflow of the squares at any scale).
            if (s > 0 && std::isfinite(s)) estimate += 2.31 * (dx / s) * (dy / s);
        }
    }
    return std::isnan(estimate) ? 0 : estimate;
}

}  // namespace exactmesh::generators
