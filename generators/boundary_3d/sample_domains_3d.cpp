// SPDX-License-Identifier: MIT
// Built-in 3D sample domains (see sample_domains_3d.hpp).
#include "generators/boundary_3d/sample_domains_3d.hpp"

#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/sample_domains.hpp"

namespace exactmesh::generators {

namespace {

using triangulation::Facet3;
using triangulation::Plc3;
using triangulation::VertIdx;

constexpr std::array<EnumName<SampleDomain3>, 3> kSampleDomain3Names{{
    {"box-with-hole", SampleDomain3::BoxWithHole},
    {"ellipsoid", SampleDomain3::Ellipsoid},
    {"wing", SampleDomain3::Wing},
}};

VertIdx add_point(Plc3& plc, double x, double y, double z) {
    const auto v = static_cast<VertIdx>(plc.vertex_count());
    plc.xyz.insert(plc.xyz.end(), {x, y, z});
    return v;
}

/// The 6 quadrilateral facets of the box [lo, hi]^3.
void add_box(Plc3& plc, double lo, double hi, int marker) {
    VertIdx corner[8];
    for (int k = 0; k < 8; ++k) {
        corner[k] = add_point(plc, (k & 1) ? hi : lo, (k & 2) ? hi : lo, (k & 4) ? hi : lo);
    }
    // Each face: the 4 corners with one coordinate bit fixed, in cyclic order.
    const int faces[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
    for (const auto& face : faces) {
        Facet3 facet;
        facet.polygons.push_back(
            {corner[face[0]], corner[face[1]], corner[face[2]], corner[face[3]]});
        facet.marker = marker;
        plc.facets.push_back(std::move(facet));
    }
}

Plc3 box_with_hole() {
    Plc3 plc;
    add_box(plc, 0.0, 1.0, 1);
    add_box(plc, 0.25, 0.75, 2);
    plc.holes = {0.5, 0.5, 0.5};
    return plc;
}

/// Most surface vertices a built-in domain's sampling may make: finer surfaces take minutes
/// and gigabytes before meshing starts, so they are refused at once with the estimate.
constexpr double kMaxSampleSurfaceVertices = 1e6;

void check_surface_estimate(const char* domain, double size, double vertices) {
    if (vertices <= kMaxSampleSurfaceVertices) return;
    constexpr double kHuge = 1e300;  // inf and beyond: no estimate to print
    throw InputError(std::string(domain) + ": a surface size of " + format_number(size) +
                     (vertices > kHuge ? std::string(" asks for far more than 1e300")
                                       : " asks for about " + format_approximate(vertices, 3)) +
                     " surface vertices, more than " +
                     format_approximate(kMaxSampleSurfaceVertices) + "; give a larger size");
}

Plc3 ellipsoid(double size) {
    constexpr long double kAxes[3] = {1.0L, 0.75L, 0.5L};
    // 4 n^2 + 2 lattice points on the octahedron's faces, n subdivisions of each edge.
    const double subdivisions = std::max(1.0, std::ceil(std::numbers::pi / 2 / size));
    check_surface_estimate("ellipsoid", size, 4 * subdivisions * subdivisions + 2);
    const int n = static_cast<int>(subdivisions);
    Plc3 plc;
    // Lattice points (i, j, k), |i| + |j| + |k| = n, shared by the octants that touch them.
    std::map<std::array<int, 3>, VertIdx> index;
    auto vertex = [&](int i, int j, int k) {
        const std::array<int, 3> key{i, j, k};
        const auto found = index.find(key);
        if (found != index.end()) return found->second;
        const long double d[3] = {static_cast<long double>(i), static_cast<long double>(j),
                                  static_cast<long double>(k)};
        long double q = 0;
        for (int c = 0; c < 3; ++c) q += (d[c] / kAxes[c]) * (d[c] / kAxes[c]);
        const long double t = 1.0L / std::sqrt(q);
        const VertIdx v = add_point(plc, static_cast<double>(d[0] * t),
                                    static_cast<double>(d[1] * t), static_cast<double>(d[2] * t));
        index.emplace(key, v);
        return v;
    };
    for (int octant = 0; octant < 8; ++octant) {
        const int sx = (octant & 1) ? -1 : 1, sy = (octant & 2) ? -1 : 1,
                  sz = (octant & 4) ? -1 : 1;
        // A mirror image reverses the orientation: keep every facet counter-clockwise seen from
        // outside.
        const bool mirrored = sx * sy * sz < 0;
        auto point = [&](int a, int b) { return vertex(sx * a, sy * b, sz * (n - a - b)); };
        auto add_triangle = [&](VertIdx p, VertIdx q, VertIdx r) {
            Facet3 facet;
            facet.polygons.push_back(mirrored ? std::vector<VertIdx>{p, r, q}
                                              : std::vector<VertIdx>{p, q, r});
            facet.marker = 1;
            plc.facets.push_back(std::move(facet));
        };
        for (int a = 0; a < n; ++a) {
            for (int b = 0; a + b < n; ++b) {
                add_triangle(point(a, b), point(a + 1, b), point(a, b + 1));
                if (a + b + 2 <= n)
                    add_triangle(point(a + 1, b), point(a + 1, b + 1), point(a, b + 1));
            }
        }
    }
    return plc;
}

/// The closed loops of a 2D domain's segments, each in its segments' order.
std::vector<std::vector<std::uint32_t>> segment_loops(const DomainPslg& pslg) {
    const std::size_t count = pslg.xy.size() / 2;
    std::vector<std::uint32_t> next(count, triangulation::kNone);
    for (std::size_t s = 0; s + 1 < pslg.segments.size(); s += 2) {
        next[pslg.segments[s]] = pslg.segments[s + 1];
    }
    std::vector<bool> used(count, false);
    std::vector<std::vector<std::uint32_t>> loops;
    for (std::uint32_t start = 0; start < count; ++start) {
        if (used[start] || next[start] == triangulation::kNone) continue;
        std::vector<std::uint32_t> loop;
        for (std::uint32_t v = start; !used[v]; v = next[v]) {
            used[v] = true;
            loop.push_back(v);
            if (next[v] == triangulation::kNone) throw InternalError("open loop in a 2D domain");
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

Plc3 wing(double size) {
    // The section's airfoil (perimeter about 2.04 chords) sampled at `size`, on both walls.
    constexpr double kAirfoilPerimeter = 2.04;
    if (size > 0) check_surface_estimate("wing", size, 2 * std::ceil(kAirfoilPerimeter / size));
    const DomainPslg section = sample_domain(
        SampleDomain::Naca0012, size > 0 ? SizeFunction::uniform(size) : SizeFunction{});
    const auto loops = segment_loops(section);
    EM_ASSERT(loops.size() == 2 && loops[0].size() == 4);
    const auto& box = loops[0];
    const auto& airfoil = loops[1];
    constexpr double kSpan = 1.0;
    Plc3 plc;
    // Two layers of the section's vertices: z = 0 first, z = kSpan after.
    const auto count = static_cast<VertIdx>(section.xy.size() / 2);
    for (const double z : {0.0, kSpan}) {
        for (VertIdx v = 0; v < count; ++v)
            add_point(plc, section.xy[2 * v], section.xy[2 * v + 1], z);
    }
    auto top = [&](VertIdx v) { return v + count; };
    // The walls: the box side with the section cut out (a facet hole inside the section).
    for (int layer = 0; layer < 2; ++layer) {
        Facet3 wall;
        std::vector<VertIdx> outer, inner;
        for (const VertIdx v : box) outer.push_back(layer == 0 ? v : top(v));
        for (const VertIdx v : airfoil) inner.push_back(layer == 0 ? v : top(v));
        wall.polygons = {outer, inner};
        wall.holes = {section.holes[0], section.holes[1], layer == 0 ? 0.0 : kSpan};
        wall.marker = 2;
        plc.facets.push_back(std::move(wall));
    }
    // The far-field sides and the wing's surface: one quadrilateral per loop edge.
    auto extrude = [&](const std::vector<std::uint32_t>& loop, int marker) {
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const VertIdx a = loop[k], b = loop[(k + 1) % loop.size()];
            Facet3 facet;
            facet.polygons.push_back({a, b, top(b), top(a)});
            facet.marker = marker;
            plc.facets.push_back(std::move(facet));
        }
    };
    extrude(box, 1);
    extrude(airfoil, 3);
    // No volume hole: the wing's inside opens to the outside through the walls' cut-outs, so it
    // is outside the domain already (a hole point there was reported as outside the domain).
    return plc;
}

}  // namespace

std::string_view sample_domain_3d_name(SampleDomain3 d) {
    return name_of(kSampleDomain3Names, d);
}

SampleDomain3 sample_domain_3d_from_name(std::string_view name) {
    return parse_name(kSampleDomain3Names, name, "3D domain");
}

triangulation::Plc3 sample_domain_3d(SampleDomain3 d, double size) {
    if (!std::isfinite(size)) {
        throw InputError(
            "3D sample domain: the surface size must be a finite number (<= 0: the "
            "domain's own), got " +
            format_number(size));
    }
    switch (d) {
        case SampleDomain3::BoxWithHole:
            return box_with_hole();
        case SampleDomain3::Ellipsoid:
            return ellipsoid(size > 0 ? size : 0.1);
        case SampleDomain3::Wing:
            return wing(size);
    }
    throw InputError("unknown 3D sample domain");
}

}  // namespace exactmesh::generators
