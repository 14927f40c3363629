// SPDX-License-Identifier: MIT
// SVG pictures of triangulations (see svg_picture.hpp).
#include "io/svg_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <tuple>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

/// Maps data coordinates to the picture. long double, because extents such as
/// 1e308 - (-1e308) overflow a double but not x87's 15-bit exponent; so do the coordinates of
/// a vertex far outside a small window, which are clipped in long double before printing.
struct Frame {
    long double min_x = 0, max_y = 0, scale = 1, margin = 0;
    double width = 0, height = 0;

    long double long_x(double value) const { return margin + (value - min_x) * scale; }
    long double long_y(double value) const { return margin + (max_y - value) * scale; }
    double x(double value) const { return static_cast<double>(long_x(value)); }
    double y(double value) const { return static_cast<double>(long_y(value)); }
};

Frame fit(std::span<const double> xy, double longer_side) {
    Frame frame;
    frame.margin = 0.02L * longer_side;
    if (xy.size() < 2) {
        frame.width = frame.height = longer_side;
        return frame;
    }
    long double min_x = xy[0], max_x = xy[0], min_y = xy[1], max_y = xy[1];
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
        min_x = std::min<long double>(min_x, xy[i]);
        max_x = std::max<long double>(max_x, xy[i]);
        min_y = std::min<long double>(min_y, xy[i + 1]);
        max_y = std::max<long double>(max_y, xy[i + 1]);
    }
    const long double extent = std::max(max_x - min_x, max_y - min_y);
    const long double inner = longer_side - 2 * frame.margin;
    frame.min_x = min_x;
    frame.max_y = max_y;
    // A single point (or all points equal): any scale will do; centre it.
    const bool single = !(extent > 0);
    frame.scale = single ? 1 : inner / extent;
    if (single) frame.margin = longer_side / 2;
    frame.width = static_cast<double>(2 * frame.margin + (max_x - min_x) * frame.scale);
    frame.height = static_cast<double>(2 * frame.margin + (max_y - min_y) * frame.scale);
    return frame;
}

/// The window fills the picture exactly: no margin, the longer side `longer_side` long.
Frame fit_window(const SvgWindow& window, double longer_side) {
    Frame frame;
    const long double dx = static_cast<long double>(window.x1) - window.x0;
    const long double dy = static_cast<long double>(window.y1) - window.y0;
    frame.min_x = window.x0;
    frame.max_y = window.y1;
    frame.scale = longer_side / std::max(dx, dy);
    frame.width = static_cast<double>(dx * frame.scale);
    frame.height = static_cast<double>(dy * frame.scale);
    return frame;
}

struct PicturePoint {
    long double x, y;
};

/// Sutherland-Hodgman: `polygon` clipped to the rectangle [lo, hi_x] x [lo, hi_y] of the
/// picture. The rectangle is the window grown by a pad, so clipped edges stay outside the
/// clipPath and only ever bound what is printed (no 1e30 coordinates in the file).
std::vector<PicturePoint> clip_polygon(std::vector<PicturePoint> polygon, long double lo,
                                       long double hi_x, long double hi_y) {
    // Each side as (axis, bound, keep-below).
    const std::array<std::tuple<int, long double, bool>, 4> sides{
        {{0, lo, false}, {0, hi_x, true}, {1, lo, false}, {1, hi_y, true}}};
    for (const auto& side : sides) {
        // Plain copies, not structured bindings: clang 14 (the fuzz and sanitizer builds)
        // cannot capture a structured binding in a lambda.
        const int axis = std::get<0>(side);
        const long double bound = std::get<1>(side);
        const bool below = std::get<2>(side);
        if (polygon.empty()) break;
        std::vector<PicturePoint> kept;
        const auto coordinate = [axis](const PicturePoint& p) { return axis == 0 ? p.x : p.y; };
        const auto inside = [&](const PicturePoint& p) {
            return below ? coordinate(p) <= bound : coordinate(p) >= bound;
        };
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            const PicturePoint& p = polygon[i];
            const PicturePoint& q = polygon[(i + 1) % polygon.size()];
            const bool p_in = inside(p), q_in = inside(q);
            if (p_in) kept.push_back(p);
            if (p_in != q_in) {
                const long double t = (bound - coordinate(p)) / (coordinate(q) - coordinate(p));
                kept.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
            }
        }
        polygon = std::move(kept);
    }
    return polygon;
}

void append_picture_point(std::string& out, const PicturePoint& p) {
    append_fixed(out, static_cast<double>(p.x), 2);
    out += ' ';
    append_fixed(out, static_cast<double>(p.y), 2);
}

void append_point(std::string& out, const Frame& frame, const double* p) {
    append_fixed(out, frame.x(p[0]), 2);
    out += ' ';
    append_fixed(out, frame.y(p[1]), 2);
}

bool overlaps(const SvgWindow& window, std::initializer_list<const double*> corners) {
    bool left = true, right = true, below = true, above = true;
    for (const double* p : corners) {
        left = left && p[0] < window.x0;
        right = right && p[0] > window.x1;
        below = below && p[1] < window.y0;
        above = above && p[1] > window.y1;
    }
    return !(left || right || below || above);
}

/// 5-degree classes of the smallest angle, 0 to 60 degrees.
constexpr int kAngleClasses = 12;
constexpr double kDegreesPerClass = 5.0;

/// Colour of class k: matplotlib's RdYlBu from 0 to 0.8 (the darkest blues left out so edges
/// stay visible on good triangles), sampled at the class's middle. scripts/picture_panels.py
/// uses the same map.
const char* class_colour(int k) {
    static constexpr const char* kColours[kAngleClasses] = {
        "#a50026", "#c0272d", "#dc3d2d", "#f0633e", "#f88d52", "#fdb366",
        "#fed384", "#fff0a8", "#f4fad9", "#d9eff6", "#b4ddec", "#8ec2dd"};
    return kColours[std::clamp(k, 0, kAngleClasses - 1)];
}

int angle_class(double degrees) {
    return std::clamp(static_cast<int>(degrees / kDegreesPerClass), 0, kAngleClasses - 1);
}

std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

/// The colour bar under the picture: the 12 classes left to right, ticks every 10 degrees.
void append_colour_bar(std::string& out, double top, double width, double bar_height) {
    const double left = 0.1 * width, span = 0.8 * width;
    const double cell = span / kAngleClasses;
    const double font = 0.2 * bar_height;
    const double box_top = top + 0.36 * bar_height, box_height = 0.3 * bar_height;
    out += "<g font-family=\"sans-serif\" font-size=\"";
    append_fixed(out, font, 2);
    out += "\" fill=\"#222222\">\n";
    for (int k = 0; k < kAngleClasses; ++k) {
        out += "<rect x=\"";
        append_fixed(out, left + k * cell, 2);
        out += "\" y=\"";
        append_fixed(out, box_top, 2);
        out += "\" width=\"";
        append_fixed(out, cell, 2);
        out += "\" height=\"";
        append_fixed(out, box_height, 2);
        out += "\" fill=\"";
        out += class_colour(k);
        out += "\"/>\n";
    }
    for (int degrees = 0; degrees <= 60; degrees += 10) {
        out += "<text text-anchor=\"middle\" x=\"";
        append_fixed(out, left + degrees / kDegreesPerClass * cell, 2);
        out += "\" y=\"";
        append_fixed(out, box_top + box_height + 1.1 * font, 2);
        out += "\">";
        append_unsigned(out, static_cast<std::uint64_t>(degrees));
        out += "</text>\n";
    }
    out += "<text text-anchor=\"start\" x=\"";
    append_fixed(out, left, 2);
    out += "\" y=\"";
    append_fixed(out, box_top - 0.4 * font, 2);
    out += "\">smallest angle of each triangle (degrees)</text>\n</g>\n";
}

}  // namespace

std::string svg_window_problem(const SvgWindow& window) {
    for (const double value : {window.x0, window.y0, window.x1, window.y1}) {
        if (!std::isfinite(value))
            return "a window coordinate is not finite (" + format_number(value) + ")";
    }
    if (!(window.x0 < window.x1))
        return "X1 (" + format_number(window.x1) + ") must be greater than X0 (" +
               format_number(window.x0) + ")";
    if (!(window.y0 < window.y1))
        return "Y1 (" + format_number(window.y1) + ") must be greater than Y0 (" +
               format_number(window.y0) + ")";
    return "";
}

double triangle_min_angle_degrees(const double* a, const double* b, const double* c) {
    // Corners scaled by 2^-e so the largest coordinate is below 1 in magnitude: the edge
    // vectors cannot overflow. Then the edges scaled again so the longest is about 1: their
    // products cannot underflow either, however small the triangle against its position.
    double largest = 0;
    for (const double* p : {a, b, c}) largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
    if (!(largest > 0)) return 0;
    int exponent = 0;
    std::frexp(largest, &exponent);
    const auto scaled = [&](double value) { return std::ldexp(value, -exponent); };
    double edges[3][2] = {{scaled(b[0]) - scaled(a[0]), scaled(b[1]) - scaled(a[1])},
                          {scaled(c[0]) - scaled(b[0]), scaled(c[1]) - scaled(b[1])},
                          {scaled(a[0]) - scaled(c[0]), scaled(a[1]) - scaled(c[1])}};
    double longest = 0;
    for (const auto& edge : edges)
        longest = std::max({longest, std::abs(edge[0]), std::abs(edge[1])});
    if (!(longest > 0)) return 0;
    std::frexp(longest, &exponent);
    for (auto& edge : edges) {
        edge[0] = std::ldexp(edge[0], -exponent);
        edge[1] = std::ldexp(edge[1], -exponent);
    }
    // The angle at the corner where edge k ends and edge k+1 starts: between -edge k and
    // edge k+1; atan2 of |cross| and dot is accurate for small and large angles alike.
    double smallest = std::numbers::pi;
    for (int k = 0; k < 3; ++k) {
        const double* u = edges[k];
        const double* v = edges[(k + 1) % 3];
        const double cross = -(u[0] * v[1] - u[1] * v[0]);
        const double dot = -(u[0] * v[0] + u[1] * v[1]);
        smallest = std::min(smallest, std::atan2(std::abs(cross), dot));
    }
    return std::clamp(smallest * 180.0 / std::numbers::pi, 0.0, 60.0);
}

std::string format_svg(std::span<const double> xy, std::span<const VertIdx> triangles,
                       const SvgOptions& options) {
    if (options.view) {
        if (const std::string problem = svg_window_problem(*options.view); !problem.empty())
            throw InputError("--view: " + problem);
    }
    const std::size_t points = xy.size() / 2;
    const std::size_t count = triangles.size() / 3;
    const Frame frame =
        options.view ? fit_window(*options.view, options.width) : fit(xy, options.width);
    const auto corner = [&](std::size_t t, int k) {
        return xy.data() + 2 * std::size_t{triangles[3 * t + static_cast<std::size_t>(k)]};
    };
    // The triangles drawn: all, or those not entirely outside the window.
    std::vector<std::size_t> drawn;
    drawn.reserve(count);
    for (std::size_t t = 0; t < count; ++t) {
        if (!options.view || overlaps(*options.view, {corner(t, 0), corner(t, 1), corner(t, 2)}))
            drawn.push_back(t);
    }
    // Typical triangle size in picture units: area per drawn triangle (or per point),
    // square-rooted. With a window, a triangle partly inside counts as one: the line width
    // follows what is on screen, not the whole mesh.
    const double cells =
        static_cast<double>(std::max<std::size_t>(count > 0 ? drawn.size() : points, 1));
    const double typical = std::sqrt(frame.width * frame.height / cells);
    const double stroke = std::clamp(0.03 * typical, 0.05, 1.5);
    const double dot = std::clamp(0.12 * typical, 0.4, 6.0);
    const bool shaded = options.shade == SvgShade::MinAngle && count > 0;
    const double bar_height = shaded ? 0.12 * std::max(frame.width, frame.height) : 0.0;
    const double total_height = frame.height + bar_height;

    // Clipping: polygons are cut to the window grown by a pad (beyond any stroke), and a
    // clipPath of the window itself trims the rest exactly.
    const long double pad = 0.05L * options.width;
    const auto triangle_outline = [&](std::size_t t) {
        std::vector<PicturePoint> polygon;
        for (int k = 0; k < 3; ++k) {
            const double* p = corner(t, k);
            polygon.push_back({frame.long_x(p[0]), frame.long_y(p[1])});
        }
        if (options.view)
            polygon = clip_polygon(std::move(polygon), -pad, frame.width + pad, frame.height + pad);
        return polygon;
    };
    const auto append_polygon = [](std::string& out, const std::vector<PicturePoint>& polygon,
                                   bool first) {
        for (std::size_t i = 0; i < polygon.size(); ++i) {
            out += i == 0 ? (first ? "M" : "\nM") : "L";
            append_picture_point(out, polygon[i]);
        }
        out += 'Z';
    };

    std::string out;
    out.reserve(60 * drawn.size() + 24 * points + 1024);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    append_fixed(out, frame.width, 2);
    out += "\" height=\"";
    append_fixed(out, total_height, 2);
    out += "\" viewBox=\"0 0 ";
    append_fixed(out, frame.width, 2);
    out += ' ';
    append_fixed(out, total_height, 2);
    out += "\">\n";
    if (!options.title.empty()) out += "<title>" + escaped(options.title) + "</title>\n";
    out += "<desc>";
    append_unsigned(out, points);
    out += " points, ";
    append_unsigned(out, count);
    out += " triangles";
    if (options.view) {
        out += ", ";
        append_unsigned(out, drawn.size());
        out += " in the window [" + format_number(options.view->x0) + ", " +
               format_number(options.view->x1) + "] x [" + format_number(options.view->y0) + ", " +
               format_number(options.view->y1) + "]";
    }
    out += "; y points up</desc>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    if (options.view) {
        out += "<clipPath id=\"view\"><rect x=\"0\" y=\"0\" width=\"";
        append_fixed(out, frame.width, 2);
        out += "\" height=\"";
        append_fixed(out, frame.height, 2);
        out += "\"/></clipPath>\n<g clip-path=\"url(#view)\">\n";
    }

    if (!drawn.empty() && !shaded) {
        out +=
            "<path fill=\"#dbe9f6\" stroke=\"#1f4e79\" stroke-linejoin=\"round\" stroke-width=\"";
        append_fixed(out, stroke, 3);
        out += "\" d=\"";
        bool first = true;
        for (const std::size_t t : drawn) {
            const std::vector<PicturePoint> polygon = triangle_outline(t);
            if (polygon.empty()) continue;
            append_polygon(out, polygon, first);
            first = false;
        }
        out += "\"/>\n";
    } else if (shaded) {
        // One path per angle class, so a 10^5-triangle picture stays 12 elements.
        std::vector<std::vector<std::size_t>> classes(kAngleClasses);
        for (const std::size_t t : drawn) {
            const double angle =
                triangle_min_angle_degrees(corner(t, 0), corner(t, 1), corner(t, 2));
            classes[static_cast<std::size_t>(angle_class(angle))].push_back(t);
        }
        for (int k = 0; k < kAngleClasses; ++k) {
            const std::vector<std::size_t>& members = classes[static_cast<std::size_t>(k)];
            if (members.empty()) continue;
            out += "<path fill=\"";
            out += class_colour(k);
            out += "\" stroke=\"#333333\" stroke-linejoin=\"round\" stroke-width=\"";
            append_fixed(out, stroke, 3);
            out += "\" d=\"";
            bool first = true;
            for (const std::size_t t : members) {
                const std::vector<PicturePoint> polygon = triangle_outline(t);
                if (polygon.empty()) continue;
                append_polygon(out, polygon, first);
                first = false;
            }
            out += "\"/>\n";
        }
    }
    if (!options.segments.empty()) {
        out += "<path fill=\"none\" stroke=\"#111111\" stroke-linecap=\"round\" stroke-width=\"";
        append_fixed(out, 3 * stroke, 3);
        out += "\" d=\"";
        bool first = true;
        for (std::size_t s = 0; 2 * s + 1 < options.segments.size(); ++s) {
            const double* p = xy.data() + 2 * std::size_t{options.segments[2 * s]};
            const double* q = xy.data() + 2 * std::size_t{options.segments[2 * s + 1]};
            if (options.view) {
                if (!overlaps(*options.view, {p, q})) continue;
                // A segment is a degenerate polygon: clipping p, q, p keeps the visible piece.
                const PicturePoint a{frame.long_x(p[0]), frame.long_y(p[1])};
                const PicturePoint b{frame.long_x(q[0]), frame.long_y(q[1])};
                const std::vector<PicturePoint> piece =
                    clip_polygon({a, b}, -pad, frame.width + pad, frame.height + pad);
                if (piece.size() < 2) continue;
                out += first ? "M" : "\nM";
                append_picture_point(out, piece[0]);
                for (std::size_t i = 1; i < piece.size(); ++i) {
                    out += 'L';
                    append_picture_point(out, piece[i]);
                }
            } else {
                out += first ? "M" : "\nM";
                append_point(out, frame, p);
                out += 'L';
                append_point(out, frame, q);
            }
            first = false;
        }
        out += "\"/>\n";
    }
    // No dots on a shaded picture: they would read as the red of the small angles.
    if (options.draw_points && points > 0 && !shaded) {
        // Zero-length segments with round caps: one element for all dots, cheap to render.
        out += "<path fill=\"none\" stroke=\"#c0392b\" stroke-linecap=\"round\" stroke-width=\"";
        append_fixed(out, dot, 3);
        out += "\" d=\"";
        std::size_t written = 0;
        for (std::size_t v = 0; v < points; ++v) {
            const double* p = xy.data() + 2 * v;
            if (options.view && !overlaps(*options.view, {p})) continue;
            out += written == 0 ? "M" : (written % 8 == 0 ? "\nM" : "M");
            append_point(out, frame, p);
            out += "h0";
            ++written;
        }
        out += "\"/>\n";
    }
    if (options.view) out += "</g>\n";
    if (shaded) append_colour_bar(out, frame.height, frame.width, bar_height);
    out += "</svg>\n";
    return out;
}

void write_svg(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, const SvgOptions& options) {
    write_text_file(path, format_svg(xy, triangles, options));
}

}  // namespace exactmesh::io
