// SPDX-License-Identifier: MIT
// Built-in sample domains for the mesh generators (issue 6), so that `exactmesh mesh --domain`
// and the benchmarks need no input file:
//  - square-with-holes: the unit square with two circular holes and a diamond-shaped one; no
//    input angle below 60 degrees (the angle guarantee holds everywhere);
//  - naca0012: the NACA 0012 airfoil (4-digit formula with the closed trailing edge, chord 1)
//    in a far-field box [-1.5, 2.5] x [-2, 2]; trailing edge angle 16.5 degrees;
//  - key: a key (a ring with a hole, a shaft with teeth) with one sharp tooth of 10 degrees;
//  - three-element: a high-lift layout of NACA 4412 sections, a slat (chord 0.15, drooped 25
//    degrees), the main element (chord 1) and a flap (chord 0.3, deflected 20 degrees), in a
//    far-field box [-2, 3] x [-2.5, 2.5]; gaps between the elements about 0.01 to 0.03.
// Curved boundaries are discretized by the size function: points on the curve itself, spaced so
// that each piece is about the size at its place (the integral of ds / s between consecutive
// points is 1, rounded up to whole pieces per curve). Straight sides are single segments (the
// generators split them as they need).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "generators/sizing/size_function.hpp"

namespace exactmesh::generators {

enum class SampleDomain { SquareWithHoles, Naca0012, Key, ThreeElement };

inline constexpr SampleDomain kAllSampleDomains[] = {SampleDomain::SquareWithHoles,
                                                     SampleDomain::Naca0012, SampleDomain::Key,
                                                     SampleDomain::ThreeElement};

/// "square-with-holes", "naca0012", "key", "three-element".
std::string_view sample_domain_name(SampleDomain d);
/// @throws InputError naming the unknown domain and the known ones.
SampleDomain sample_domain_from_name(std::string_view name);

/// A parametric curve of the plane (a spline, an arc, an airfoil's surface).
using Curve2 = std::function<std::array<double, 2>(double)>;

/// Where a segment of a domain came from: the piece of curves[curve] between parameters u0 (at
/// its first vertex) and u1 (at its second), or a straight side (curve == kStraightSide).
struct SegmentCurve {
    std::uint32_t curve = 0xFFFFFFFFu;
    double u0 = 0, u1 = 0;
};
inline constexpr std::uint32_t kStraightSide = 0xFFFFFFFFu;

struct DomainPslg {
    std::vector<double> xy;               ///< 2·#V
    std::vector<std::uint32_t> segments;  ///< 2·#S, 0-based
    std::vector<double> holes;            ///< 2·#H points inside holes
    /// The curves the segments were sampled from and, per segment (#S, or empty when every side
    /// is straight), which piece of which curve: adaptation (issue 13) puts new boundary points
    /// on the curve itself, not on the polyline. Each segment's end points are curve(u0) and
    /// curve(u1), except where a loop's shared end is written exactly ((1, 0), (0, 0) of the
    /// NACA 0012 section).
    std::vector<Curve2> curves;
    std::vector<SegmentCurve> segment_curves;
};

/// The domain's own size function (graded for the airfoil, uniform for the others).
SizeFunction sample_domain_size(SampleDomain d);

/// The domain's PSLG, its curves discretized by `size` (none: by sample_domain_size(d)).
DomainPslg sample_domain(SampleDomain d, const SizeFunction& size = {});

/// NACA 4-digit symmetric thickness y_t(x) for thickness t (0.12 for NACA 0012), chord 1, with
/// the closed trailing edge coefficient (-0.1036), x in [0, 1].
double naca_thickness(double t, double x);

/// A point of a NACA 4-digit section (max camber m at chord fraction p, thickness t; NACA 4412:
/// m = 0.04, p = 0.4, t = 0.12), chord 1 from (0, 0) to (1, 0): at x = (1 + cos beta) / 2 on the
/// upper (upper true) or lower surface, offset from the camber line normally by y_t
/// [Abbott-von Doenhoff, Theory of Wing Sections, §6.4].
std::array<double, 2> naca4_point(double m, double p, double t, double beta, bool upper);

}  // namespace exactmesh::generators
