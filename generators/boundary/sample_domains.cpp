// SPDX-License-Identifier: MIT
// Built-in sample domains (see sample_domains.hpp).
#include "generators/boundary/sample_domains.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"

namespace exactmesh::generators {

namespace {

using Point = std::array<double, 2>;

class Builder {
  public:
    DomainPslg pslg;

    std::uint32_t vertex(Point p) {
        pslg.xy.push_back(p[0]);
        pslg.xy.push_back(p[1]);
        return static_cast<std::uint32_t>(pslg.xy.size() / 2 - 1);
    }
    void segment(std::uint32_t a, std::uint32_t b) {
        pslg.segments.push_back(a);
        pslg.segments.push_back(b);
    }
    /// A curve; its number for curve_segments.
    std::uint32_t curve(Curve2 c) {
        pslg.curves.push_back(std::move(c));
        return static_cast<std::uint32_t>(pslg.curves.size() - 1);
    }
    /// Records the curve pieces of the segments added since `first_segment`: the k-th of them
    /// runs from parameter u[k] to u[k + 1] of curve c (straight sides before them keep theirs).
    void curve_segments(std::size_t first_segment, std::uint32_t c, const std::vector<double>& u) {
        pslg.segment_curves.resize(pslg.segments.size() / 2);
        for (std::size_t k = 0; first_segment + k < pslg.segment_curves.size() && k + 1 < u.size();
             ++k)
            pslg.segment_curves[first_segment + k] = {c, u[k], u[k + 1]};
    }
    std::size_t segment_count() const { return pslg.segments.size() / 2; }
    /// A closed polygon through the points (first not repeated at the end).
    void loop(const std::vector<Point>& points) {
        const std::uint32_t first = static_cast<std::uint32_t>(pslg.xy.size() / 2);
        for (const Point& p : points) vertex(p);
        const auto n = static_cast<std::uint32_t>(points.size());
        for (std::uint32_t k = 0; k < n; ++k) segment(first + k, first + (k + 1) % n);
    }
    void circle_hole(Point centre, double radius, const SizeFunction& size) {
        const Curve2 circle = [centre, radius](double u) {
            return Point{centre[0] + radius * std::cos(u), centre[1] + radius * std::sin(u)};
        };
        std::vector<double> u =
            discretize_curve_parameters(circle, 0.0, 2 * std::numbers::pi, size, 8);
        std::vector<Point> points;
        for (const double p : u) points.push_back(circle(p));
        points.pop_back();  // u = 2 pi is u = 0
        const std::size_t first = segment_count();
        loop(points);
        curve_segments(first, curve(circle), u);
        pslg.holes.insert(pslg.holes.end(), {centre[0], centre[1]});
    }
};

DomainPslg square_with_holes(const SizeFunction& size) {
    Builder b;
    b.loop({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    b.circle_hole({0.3, 0.3}, 0.12, size);
    b.circle_hole({0.7, 0.62}, 0.16, size);
    // A diamond (a square turned 45 degrees): right angles, its corners on the axes' lines.
    b.loop({{0.3, 0.62}, {0.4, 0.72}, {0.3, 0.82}, {0.2, 0.72}});
    b.pslg.holes.insert(b.pslg.holes.end(), {0.3, 0.72});
    return std::move(b.pslg);
}

DomainPslg naca0012(const SizeFunction& size) {
    Builder b;
    b.loop({{-1.5, -2}, {2.5, -2}, {2.5, 2}, {-1.5, 2}});
    // From the trailing edge (x = 1) to the leading edge (x = 0) on both surfaces, with
    // x = (1 + cos beta) / 2, which gives the fine sampling its cosine clustering at both ends.
    const auto surface_curve = [](double sign) -> Curve2 {
        return [sign](double beta) {
            const double x = 0.5 * (1 + std::cos(beta));
            return Point{x, sign * naca_thickness(0.12, x)};
        };
    };
    const Curve2 upper_curve = surface_curve(1.0), lower_curve = surface_curve(-1.0);
    const std::vector<double> upper_u =
        discretize_curve_parameters(upper_curve, 0.0, std::numbers::pi, size, 16);
    const std::vector<double> lower_u =
        discretize_curve_parameters(lower_curve, 0.0, std::numbers::pi, size, 16);
    // Exactly (1, 0) and (0, 0) at the ends, shared by both surfaces.
    std::vector<Point> loop{{1.0, 0.0}};
    for (std::size_t k = 1; k + 1 < upper_u.size(); ++k) loop.push_back(upper_curve(upper_u[k]));
    loop.push_back({0.0, 0.0});
    for (std::size_t k = lower_u.size() - 2; k >= 1; --k) loop.push_back(lower_curve(lower_u[k]));
    const std::size_t first = b.segment_count();
    b.loop(loop);
    b.curve_segments(first, b.curve(upper_curve), upper_u);
    b.curve_segments(first + upper_u.size() - 1, b.curve(lower_curve),
                     std::vector<double>(lower_u.rbegin(), lower_u.rend()));
    b.pslg.holes.insert(b.pslg.holes.end(), {0.3, 0.0});
    return std::move(b.pslg);
}

DomainPslg key(const SizeFunction& size) {
    Builder b;
    // The ring: radius 0.5 about the origin, cut by the shaft y = +-0.1 at x = sqrt(0.24).
    const double r = 0.5, h = 0.1, cut = std::sqrt(r * r - h * h);
    const double a0 = std::asin(h / r);
    std::vector<Point> outline{{cut, h}, {2.0, h}, {2.0, -h}};
    // Teeth on the lower side of the shaft, from the tip back to the ring: a square tooth, the
    // sharp one (tip angle 2 atan(0.022 / 0.25) = 10.06 degrees), a trapezoid.
    const std::vector<Point> teeth{{1.9, -h},     {1.9, -0.25}, {1.75, -0.25}, {1.75, -h},
                                   {1.422, -h},   {1.4, -0.35}, {1.378, -h},   {1.2, -h},
                                   {1.15, -0.22}, {1.0, -0.22}, {0.95, -h}};
    outline.insert(outline.end(), teeth.begin(), teeth.end());
    // The ring's outer arc from angle -a0 down through pi back to a0 - 2 pi, i.e. (cut, -h) to
    // (cut, h) the long way round; both ends are already there.
    const Curve2 ring = [r](double u) { return Point{r * std::cos(u), r * std::sin(u)}; };
    const std::vector<double> arc =
        discretize_curve_parameters(ring, -a0, a0 - 2 * std::numbers::pi, size, 16);
    outline.push_back({cut, -h});
    const std::size_t arc_first = b.segment_count() + outline.size() - 1;
    for (std::size_t k = 1; k + 1 < arc.size(); ++k) outline.push_back(ring(arc[k]));
    b.loop(outline);
    b.curve_segments(arc_first, b.curve(ring), arc);
    b.circle_hole({0.0, 0.0}, 0.2, size);
    return std::move(b.pslg);
}

/// A NACA 4412 element: chord c with its leading edge at `le`, rotated by `deflection` degrees
/// clockwise (trailing edge down) about the leading edge; a closed loop, a hole point inside.
void naca4412_element(Builder& b, Point le, double chord, double deflection,
                      const SizeFunction& size) {
    const double angle = -deflection * std::numbers::pi / 180, c = std::cos(angle),
                 s = std::sin(angle);
    auto place = [=](Point local) {
        return Point{le[0] + chord * (c * local[0] - s * local[1]),
                     le[1] + chord * (s * local[0] + c * local[1])};
    };
    const auto surface_curve = [&](bool upper) -> Curve2 {
        return [=](double beta) { return place(naca4_point(0.04, 0.4, 0.12, beta, upper)); };
    };
    const Curve2 upper_curve = surface_curve(true), lower_curve = surface_curve(false);
    const std::vector<double> upper_u =
        discretize_curve_parameters(upper_curve, 0.0, std::numbers::pi, size, 16);
    const std::vector<double> lower_u =
        discretize_curve_parameters(lower_curve, 0.0, std::numbers::pi, size, 16);
    // Trailing edge and leading edge shared by both surfaces (the upper surface's ends).
    std::vector<Point> loop{upper_curve(upper_u.front())};
    for (std::size_t k = 1; k + 1 < upper_u.size(); ++k) loop.push_back(upper_curve(upper_u[k]));
    loop.push_back(upper_curve(upper_u.back()));
    for (std::size_t k = lower_u.size() - 2; k >= 1; --k) loop.push_back(lower_curve(lower_u[k]));
    const std::size_t first = b.segment_count();
    b.loop(loop);
    b.curve_segments(first, b.curve(upper_curve), upper_u);
    b.curve_segments(first + upper_u.size() - 1, b.curve(lower_curve),
                     std::vector<double>(lower_u.rbegin(), lower_u.rend()));
    // On the camber line at 30 % of the chord: inside the section.
    const Point inside = place({0.3, 0.04 / (0.4 * 0.4) * (2 * 0.4 * 0.3 - 0.3 * 0.3)});
    b.pslg.holes.insert(b.pslg.holes.end(), {inside[0], inside[1]});
}

DomainPslg three_element(const SizeFunction& size) {
    Builder b;
    b.loop({{-2, -2.5}, {3, -2.5}, {3, 2.5}, {-2, 2.5}});
    // Slat: trailing edge at (0.03, 0.045), above the main element's nose, drooped 25 degrees.
    const double droop = 25 * std::numbers::pi / 180;
    naca4412_element(b, {0.03 - 0.15 * std::cos(droop), 0.045 - 0.15 * std::sin(droop)}, 0.15, -25,
                     size);
    naca4412_element(b, {0.0, 0.0}, 1.0, 0.0, size);
    naca4412_element(b, {0.92, -0.03}, 0.3, 20.0, size);
    return std::move(b.pslg);
}

}  // namespace

std::array<double, 2> naca4_point(double m, double p, double t, double beta, bool upper) {
    const double x = 0.5 * (1 + std::cos(beta));
    double yc = 0, slope = 0;
    if (m > 0 && p > 0) {
        if (x < p) {
            yc = m / (p * p) * (2 * p * x - x * x);
            slope = 2 * m / (p * p) * (p - x);
        } else {
            yc = m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
            slope = 2 * m / ((1 - p) * (1 - p)) * (p - x);
        }
    }
    const double yt = naca_thickness(t, x), theta = std::atan(slope);
    // Exactly (1, 0) and (0, 0) at the trailing and leading edges (y_t = 0 there).
    if (beta == 0.0) return {1.0, 0.0};
    if (x == 0.0) return {0.0, 0.0};
    return upper ? std::array<double, 2>{x - yt * std::sin(theta), yc + yt * std::cos(theta)}
                 : std::array<double, 2>{x + yt * std::sin(theta), yc - yt * std::cos(theta)};
}

double naca_thickness(double t, double x) {
    return 5 * t *
           (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x -
            0.1036 * x * x * x * x);
}

/// The names, in kAllSampleDomains' order (the order an unknown name's error lists them).
constexpr std::array<EnumName<SampleDomain>, 4> kSampleDomainNames{{
    {"square-with-holes", SampleDomain::SquareWithHoles},
    {"naca0012", SampleDomain::Naca0012},
    {"key", SampleDomain::Key},
    {"three-element", SampleDomain::ThreeElement},
}};

std::string_view sample_domain_name(SampleDomain d) {
    return name_of(kSampleDomainNames, d);
}

SampleDomain sample_domain_from_name(std::string_view name) {
    return parse_name(kSampleDomainNames, name, "domain");
}

SizeFunction sample_domain_size(SampleDomain d) {
    switch (d) {
        case SampleDomain::SquareWithHoles:
            return SizeFunction::uniform(0.025);
        case SampleDomain::Naca0012:
            // A line source along the chord: 0.01 on the airfoil, 0.01 (1 + (d / 0.1)^1.5) away
            // from it (0.9 at the far field's nearest side), capped at 0.5.
            return SizeFunction::sources({}, {{0.0, 0.0, 1.0, 0.0, 0.01, 0.1, 1.5}}, 0.5);
        case SampleDomain::Key:
            return SizeFunction::uniform(0.02);
        case SampleDomain::ThreeElement:
            // One line source from the slat's nose to the flap's trailing edge (the source
            // formula sums its sources, so one per element would coarsen each by the others):
            // 0.004 on the elements, 0.004 (1 + (d / 0.1)^1.5) away from them, capped at 0.5.
            return SizeFunction::sources({}, {{-0.106, -0.018, 1.202, -0.133, 0.004, 0.1, 1.5}},
                                         0.5);
    }
    return {};
}

DomainPslg sample_domain(SampleDomain d, const SizeFunction& size) {
    const SizeFunction& s = size.bounded() ? size : sample_domain_size(d);
    DomainPslg pslg;
    switch (d) {
        case SampleDomain::SquareWithHoles:
            pslg = square_with_holes(s);
            break;
        case SampleDomain::Naca0012:
            pslg = naca0012(s);
            break;
        case SampleDomain::Key:
            pslg = key(s);
            break;
        case SampleDomain::ThreeElement:
            pslg = three_element(s);
            break;
    }
    // Straight sides added after the last curve keep the default record.
    pslg.segment_curves.resize(pslg.segments.size() / 2);
    return pslg;
}

}  // namespace exactmesh::generators
