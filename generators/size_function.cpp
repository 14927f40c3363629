// SPDX-License-Identifier: MIT
// Size functions (see size_function.hpp). The source term (d / rbar)^gamma is evaluated without
// pow for gamma 0, 1 and 2 (gamma 2 of a point source needs no square root either): the
// refinement evaluates the size at three edge midpoints per new triangle.
#include "generators/size_function.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <utility>

#include "predicates/errors.hpp"

namespace exactmesh::generators {

namespace {

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void require_positive(double value, const std::string& what) {
    if (!(std::isfinite(value) && value > 0)) {
        throw InputError(what + " must be a finite number > 0 (got " + number_text(value) + ")");
    }
}

void require_exponent(double value, const std::string& what) {
    if (!(std::isfinite(value) && value >= 0)) {
        throw InputError(what + " must be a finite number >= 0 (got " + number_text(value) + ")");
    }
}

/// (d / radius)^exponent from the squared distance d2.
double growth(double d2, double radius, double exponent) {
    if (exponent == 2.0) return d2 / (radius * radius);
    if (exponent == 0.0) return 1.0;
    const double ratio = std::sqrt(d2) / radius;
    if (exponent == 1.0) return ratio;
    return std::pow(ratio, exponent);
}

double squared_distance_to_segment(double x, double y, const LineSource& l) {
    const double dx = l.x1 - l.x0, dy = l.y1 - l.y0;
    const double length2 = dx * dx + dy * dy;
    double t = 0.0;
    if (length2 > 0) t = std::clamp(((x - l.x0) * dx + (y - l.y0) * dy) / length2, 0.0, 1.0);
    const double ex = x - (l.x0 + t * dx), ey = y - (l.y0 + t * dy);
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

SizeFunction SizeFunction::sources(std::vector<PointSource> points, std::vector<LineSource> lines, double cap) {
    if (!(cap > 0) || std::isnan(cap)) throw InputError("size cap must be > 0 (got " + number_text(cap) + ")");
    for (std::size_t k = 0; k < points.size(); ++k) {
        const PointSource& p = points[k];
        const std::string name = "point source " + std::to_string(k + 1);
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InputError(name + ": non-finite position");
        require_positive(p.size, name + ": size");
        require_positive(p.radius, name + ": radius");
        require_exponent(p.exponent, name + ": exponent");
    }
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const LineSource& l = lines[k];
        const std::string name = "line source " + std::to_string(k + 1);
        if (!std::isfinite(l.x0) || !std::isfinite(l.y0) || !std::isfinite(l.x1) || !std::isfinite(l.y1)) {
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

SizeFunction SizeFunction::analytic(std::function<double(double, double)> function, std::string description) {
    SizeFunction f;
    f.kind_ = Kind::Analytic;
    f.analytic_ = std::make_shared<const std::function<double(double, double)>>(std::move(function));
    f.description_ = std::move(description);
    return f;
}

double SizeFunction::evaluate(double x, double y) const {
    if (kind_ == Kind::Analytic) return (*analytic_)(x, y);
    double s = 0.0;
    for (const PointSource& p : points_) {
        const double dx = x - p.x, dy = y - p.y;
        s += p.size * (1.0 + growth(dx * dx + dy * dy, p.radius, p.exponent));
    }
    for (const LineSource& l : lines_) {
        s += l.size * (1.0 + growth(squared_distance_to_segment(x, y, l), l.radius, l.exponent));
    }
    return std::min(s, cap_);
}

SizeFunction SizeFunction::scaled(double factor) const {
    require_positive(factor, "size scale factor");
    SizeFunction f = *this;
    f.factor_ *= factor;
    return f;
}

std::string SizeFunction::describe() const {
    std::string text;
    switch (kind_) {
        case Kind::None: return "none";
        case Kind::Uniform: return "uniform " + number_text(factor_ * cap_);
        case Kind::Sources:
            text = "sources: " + std::to_string(points_.size()) + " point, " + std::to_string(lines_.size()) + " line";
            if (std::isfinite(cap_)) text += ", cap " + number_text(cap_);
            break;
        case Kind::Analytic: text = description_; break;
    }
    if (factor_ != 1.0) text += ", scaled by " + number_text(factor_);
    return text;
}

bool parse_uniform_size(std::string_view text, double& size) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
    if (text.empty()) return false;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size()) return false;
    if (!(std::isfinite(value) && value > 0)) return false;
    size = value;
    return true;
}

SizeFunction parse_size_sources(std::string_view text, std::string_view name) {
    std::vector<PointSource> points;
    std::vector<LineSource> lines;
    double cap = std::numeric_limits<double>::infinity();
    bool have_cap = false;
    std::istringstream in{std::string(text)};
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = std::string(name) + ":" + std::to_string(number) + ": ";
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::string keyword;
        if (!(words >> keyword)) continue;
        std::vector<double> values;
        std::string word;
        while (words >> word) {
            double value = 0;
            const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
            if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
                throw InputError(where + "'" + word + "' is not a finite number");
            }
            values.push_back(value);
        }
        auto expect = [&](std::size_t count, const char* form) {
            if (values.size() != count) {
                throw InputError(where + keyword + " takes " + std::to_string(count) + " numbers (" + form + "), got " +
                                 std::to_string(values.size()));
            }
        };
        try {
            if (keyword == "uniform") {
                expect(1, "H");
                if (have_cap) throw InputError("a second uniform line");
                require_positive(values[0], "uniform size");
                cap = values[0];
                have_cap = true;
            } else if (keyword == "point") {
                expect(5, "X Y S RBAR GAMMA");
                points.push_back({values[0], values[1], values[2], values[3], values[4]});
                SizeFunction::sources({points.back()}, {});  // validates this one
            } else if (keyword == "line") {
                expect(7, "X0 Y0 X1 Y1 S RBAR GAMMA");
                lines.push_back({values[0], values[1], values[2], values[3], values[4], values[5], values[6]});
                SizeFunction::sources({}, {lines.back()});
            } else {
                throw InputError("unknown item '" + keyword + "' (expected uniform, point or line)");
            }
        } catch (const InputError& error) {
            const std::string message = error.what();
            if (message.rfind(where, 0) == 0) throw;
            throw InputError(where + message);
        }
    }
    if (points.empty() && lines.empty() && !have_cap) {
        throw InputError(std::string(name) + ": no size given (expected uniform, point or line lines)");
    }
    return SizeFunction::sources(std::move(points), std::move(lines), cap);
}

}  // namespace exactmesh::generators
