// SPDX-License-Identifier: MIT
// SVG pictures of triangulations (see svg_picture.hpp).
#include "io/svg_picture.hpp"

#include <algorithm>
#include <cmath>

#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

/// Maps data coordinates to the picture. long double, because extents such as
/// 1e308 - (-1e308) overflow a double but not x87's 15-bit exponent.
struct Frame {
    long double min_x = 0, max_y = 0, scale = 1, margin = 0;
    double width = 0, height = 0;

    double x(double value) const { return static_cast<double>(margin + (value - min_x) * scale); }
    double y(double value) const { return static_cast<double>(margin + (max_y - value) * scale); }
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
    frame.scale = extent > 0 ? inner / extent : 1;
    if (extent == 0) frame.margin = longer_side / 2;
    frame.width = static_cast<double>(2 * frame.margin + (max_x - min_x) * frame.scale);
    frame.height = static_cast<double>(2 * frame.margin + (max_y - min_y) * frame.scale);
    return frame;
}

void append_point(std::string& out, const Frame& frame, const double* p) {
    append_fixed(out, frame.x(p[0]), 2);
    out += ' ';
    append_fixed(out, frame.y(p[1]), 2);
}

}  // namespace

std::string format_svg(std::span<const double> xy, std::span<const VertIdx> triangles,
                       const SvgOptions& options) {
    const std::size_t points = xy.size() / 2;
    const std::size_t count = triangles.size() / 3;
    const Frame frame = fit(xy, options.width);
    // Typical triangle size in picture units: area per triangle (or per point), square-rooted.
    const double cells = static_cast<double>(std::max<std::size_t>(count > 0 ? count : points, 1));
    const double typical = std::sqrt(frame.width * frame.height / cells);
    const double stroke = std::clamp(0.03 * typical, 0.05, 1.5);
    const double dot = std::clamp(0.12 * typical, 0.4, 6.0);

    std::string out;
    out.reserve(60 * count + 24 * points + 1024);
    out += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
    append_fixed(out, frame.width, 2);
    out += "\" height=\"";
    append_fixed(out, frame.height, 2);
    out += "\" viewBox=\"0 0 ";
    append_fixed(out, frame.width, 2);
    out += ' ';
    append_fixed(out, frame.height, 2);
    out += "\">\n";
    if (!options.title.empty()) {
        std::string escaped;
        for (const char c : options.title) {
            if (c == '<')
                escaped += "&lt;";
            else if (c == '>')
                escaped += "&gt;";
            else if (c == '&')
                escaped += "&amp;";
            else
                escaped += c;
        }
        out += "<title>" + escaped + "</title>\n";
    }
    out += "<desc>";
    append_unsigned(out, points);
    out += " points, ";
    append_unsigned(out, count);
    out += " triangles; y points up</desc>\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

    if (count > 0) {
        out +=
            "<path fill=\"#dbe9f6\" stroke=\"#1f4e79\" stroke-linejoin=\"round\" stroke-width=\"";
        append_fixed(out, stroke, 3);
        out += "\" d=\"";
        for (std::size_t t = 0; t < count; ++t) {
            out += t == 0 ? "M" : "\nM";
            append_point(out, frame, xy.data() + 2 * std::size_t{triangles[3 * t]});
            out += 'L';
            append_point(out, frame, xy.data() + 2 * std::size_t{triangles[3 * t + 1]});
            out += 'L';
            append_point(out, frame, xy.data() + 2 * std::size_t{triangles[3 * t + 2]});
            out += 'Z';
        }
        out += "\"/>\n";
    }
    if (!options.segments.empty()) {
        out += "<path fill=\"none\" stroke=\"#111111\" stroke-linecap=\"round\" stroke-width=\"";
        append_fixed(out, 3 * stroke, 3);
        out += "\" d=\"";
        for (std::size_t s = 0; 2 * s + 1 < options.segments.size(); ++s) {
            out += s == 0 ? "M" : "\nM";
            append_point(out, frame, xy.data() + 2 * std::size_t{options.segments[2 * s]});
            out += 'L';
            append_point(out, frame, xy.data() + 2 * std::size_t{options.segments[2 * s + 1]});
        }
        out += "\"/>\n";
    }
    if (options.draw_points && points > 0) {
        // Zero-length segments with round caps: one element for all dots, cheap to render.
        out += "<path fill=\"none\" stroke=\"#c0392b\" stroke-linecap=\"round\" stroke-width=\"";
        append_fixed(out, dot, 3);
        out += "\" d=\"";
        for (std::size_t v = 0; v < points; ++v) {
            out += v == 0 ? "M" : (v % 8 == 0 ? "\nM" : "M");
            append_point(out, frame, xy.data() + 2 * v);
            out += "h0";
        }
        out += "\"/>\n";
    }
    out += "</svg>\n";
    return out;
}

void write_svg(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, const SvgOptions& options) {
    write_text_file(path, format_svg(xy, triangles, options));
}

}  // namespace exactmesh::io
