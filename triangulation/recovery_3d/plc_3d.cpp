// SPDX-License-Identifier: MIT
// Piecewise linear complexes: input checks, facet triangulation in the facet's plane, and the
// exact surface self-intersection and closedness checks (see plc_3d.hpp). The triangle-triangle
// test is the classic reduction to segment-triangle tests [Guigue-Devillers03, "Fast and robust
// triangle-triangle overlap test using orientation predicates"], here with every sign exact.
#include "triangulation/recovery_3d/plc_3d.hpp"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::orient2d;
using predicates::orient3d;
using predicates::Sign;

/// How the messages name things: in the file's numbering.
struct Names {
    const Plc3& plc;
    std::string vertex(VertIdx v) const { return std::to_string(plc.vertex_number(v)); }
    std::string facet(std::uint32_t f) const {
        std::string text = "facet " + std::to_string(std::uint64_t{f} + plc.first_index);
        if (f < plc.facet_origin.size() && plc.facet_origin[f] != 0) {
            text += " (";
            text += plc.facet_origin_kind;
            text += ' ';
            text += std::to_string(plc.facet_origin[f]);
            text += ')';
        }
        return text;
    }
    std::string edge(VertIdx a, VertIdx b) const {
        std::string text(1, '(');
        text += vertex(a);
        text += ", ";
        text += vertex(b);
        text += ')';
        return text;
    }
    std::string triangle(const VertIdx* t) const {
        std::string text(1, '(');
        text += vertex(t[0]);
        text += ", ";
        text += vertex(t[1]);
        text += ", ";
        text += vertex(t[2]);
        text += ')';
        return text;
    }
};

/// Lexicographic order of 2D points (monotone along any line: orders collinear points).
bool less_2d(const std::array<double, 2>& p, const std::array<double, 2>& q) {
    return p[0] < q[0] || (p[0] == q[0] && p[1] < q[1]);
}

/// Closed segments pq and rs of the plane (exact).
bool segments_meet_2d(const std::array<double, 2>& p, const std::array<double, 2>& q,
                      const std::array<double, 2>& r, const std::array<double, 2>& s) {
    const Sign o1 = orient2d(p.data(), q.data(), r.data());
    const Sign o2 = orient2d(p.data(), q.data(), s.data());
    if (o1 == o2 && o1 != Sign::Zero) return false;
    const Sign o3 = orient2d(r.data(), s.data(), p.data());
    const Sign o4 = orient2d(r.data(), s.data(), q.data());
    if (o3 == o4 && o3 != Sign::Zero) return false;
    if (o1 == Sign::Zero && o2 == Sign::Zero) {
        // Collinear: the lexicographic intervals overlap.
        const auto& pq_lo = less_2d(q, p) ? q : p;
        const auto& pq_hi = less_2d(q, p) ? p : q;
        const auto& rs_lo = less_2d(s, r) ? s : r;
        const auto& rs_hi = less_2d(s, r) ? r : s;
        return !less_2d(pq_hi, rs_lo) && !less_2d(rs_hi, pq_lo);
    }
    return true;
}

/// Closed triangle abc (non-degenerate) contains p, in the plane.
bool triangle_contains_2d(const std::array<double, 2>& a, const std::array<double, 2>& b,
                          const std::array<double, 2>& c, const std::array<double, 2>& p) {
    const Sign s1 = orient2d(a.data(), b.data(), p.data());
    const Sign s2 = orient2d(b.data(), c.data(), p.data());
    const Sign s3 = orient2d(c.data(), a.data(), p.data());
    const bool negative = s1 == Sign::Negative || s2 == Sign::Negative || s3 == Sign::Negative;
    const bool positive = s1 == Sign::Positive || s2 == Sign::Positive || s3 == Sign::Positive;
    return !(negative && positive);
}

/// Closed segment pq meets closed triangle abc (non-degenerate), in space (exact).
bool segment_meets_triangle(const double* p, const double* q, const double* a, const double* b,
                            const double* c) {
    const Sign sp = orient3d(a, b, c, p);
    const Sign sq = orient3d(a, b, c, q);
    if (sp == sq && sp != Sign::Zero) return false;
    if (sp == Sign::Zero && sq == Sign::Zero) {
        const int drop = drop_axis(a, b, c);
        const auto pa = project_facet_point(a, drop), pb = project_facet_point(b, drop),
                   pc = project_facet_point(c, drop);
        const auto pp = project_facet_point(p, drop), pq = project_facet_point(q, drop);
        return triangle_contains_2d(pa, pb, pc, pp) || triangle_contains_2d(pa, pb, pc, pq) ||
               segments_meet_2d(pp, pq, pa, pb) || segments_meet_2d(pp, pq, pb, pc) ||
               segments_meet_2d(pp, pq, pc, pa);
    }
    // The segment reaches the plane at one point: it lies in the triangle iff the line pq
    // passes through it, i.e. the three volumes of pq with the edges do not disagree in sign.
    const Sign s1 = orient3d(p, q, a, b);
    const Sign s2 = orient3d(p, q, b, c);
    const Sign s3 = orient3d(p, q, c, a);
    const bool negative = s1 == Sign::Negative || s2 == Sign::Negative || s3 == Sign::Negative;
    const bool positive = s1 == Sign::Positive || s2 == Sign::Positive || s3 == Sign::Positive;
    return !(negative && positive);
}

/// Two non-degenerate triangles (vertex indices) meet other than in shared vertices or a shared
/// edge. The intersection of two triangles is convex; if it is not just shared corners, one of
/// its extreme points lies on an edge of one triangle inside the other, except for edges the
/// triangles share, which are treated by cases.
bool triangles_meet_improperly(const Plc3& plc, const VertIdx* ta, const VertIdx* tb) {
    int shared = 0;
    int a_shared[3] = {-1, -1, -1};  // a_shared[i]: the corner of tb equal to corner i of ta
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            if (ta[i] == tb[j]) {
                a_shared[i] = j;
                ++shared;
            }
        }
    }
    auto pt = [&](VertIdx v) { return plc.point(v); };
    if (shared == 3) return true;  // the same triangle in two facets: they overlap
    if (shared == 2) {
        int apex_a = 0;
        while (a_shared[apex_a] >= 0) ++apex_a;
        int apex_b = 0;
        while (tb[apex_b] == ta[(apex_a + 1) % 3] || tb[apex_b] == ta[(apex_a + 2) % 3]) ++apex_b;
        const double* e0 = pt(ta[(apex_a + 1) % 3]);
        const double* e1 = pt(ta[(apex_a + 2) % 3]);
        const double* c = pt(ta[apex_a]);
        const double* d = pt(tb[apex_b]);
        if (orient3d(e0, e1, c, d) != Sign::Zero) return false;
        // Coplanar: they overlap iff both apexes lie on the same side of the shared edge.
        const int drop = drop_axis(e0, e1, c);
        return projected_orient(e0, e1, c, drop) == projected_orient(e0, e1, d, drop);
    }
    if (shared == 1) {
        int ia = 0;
        while (a_shared[ia] < 0) ++ia;
        const int ib = a_shared[ia];
        // The intersection is a segment from the shared corner v, ending on the edge of one
        // triangle opposite v; that edge then meets the other triangle.
        return segment_meets_triangle(pt(ta[(ia + 1) % 3]), pt(ta[(ia + 2) % 3]), pt(tb[0]),
                                      pt(tb[1]), pt(tb[2])) ||
               segment_meets_triangle(pt(tb[(ib + 1) % 3]), pt(tb[(ib + 2) % 3]), pt(ta[0]),
                                      pt(ta[1]), pt(ta[2]));
    }
    for (int k = 0; k < 3; ++k) {
        if (segment_meets_triangle(pt(ta[k]), pt(ta[(k + 1) % 3]), pt(tb[0]), pt(tb[1]),
                                   pt(tb[2])) ||
            segment_meets_triangle(pt(tb[k]), pt(tb[(k + 1) % 3]), pt(ta[0]), pt(ta[1]),
                                   pt(ta[2]))) {
            return true;
        }
    }
    return false;
}

[[noreturn]] void fail(const std::string& message) {
    throw InputError(message);
}

/// The polygon edges of facet f (global vertex pairs): closed loops and segments.
std::vector<std::array<VertIdx, 2>> facet_edges(const Facet3& facet) {
    std::vector<std::array<VertIdx, 2>> edges;
    for (const auto& polygon : facet.polygons) {
        const std::size_t n = polygon.size();
        if (n == 2) edges.push_back({polygon[0], polygon[1]});
        if (n >= 3) {
            for (std::size_t k = 0; k < n; ++k) edges.push_back({polygon[k], polygon[(k + 1) % n]});
        }
    }
    return edges;
}

/// Names two polygon edges of facet f whose interiors cross (the 2D triangulation had to add a
/// vertex); only called on that error path, so all pairs are tried.
[[noreturn]] void fail_crossing(const Plc3& plc, std::uint32_t f, int drop) {
    const Names names{plc};
    const auto edges = facet_edges(plc.facets[f]);
    for (std::size_t i = 0; i < edges.size(); ++i) {
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const auto p = project_facet_point(plc.point(edges[i][0]), drop);
            const auto q = project_facet_point(plc.point(edges[i][1]), drop);
            const auto r = project_facet_point(plc.point(edges[j][0]), drop);
            const auto s = project_facet_point(plc.point(edges[j][1]), drop);
            const Sign o1 = orient2d(p.data(), q.data(), r.data());
            const Sign o2 = orient2d(p.data(), q.data(), s.data());
            const Sign o3 = orient2d(r.data(), s.data(), p.data());
            const Sign o4 = orient2d(r.data(), s.data(), q.data());
            if (o1 != Sign::Zero && o2 == -o1 && o3 != Sign::Zero && o4 == -o3) {
                fail(names.facet(f) + ": polygon edges " + names.edge(edges[i][0], edges[i][1]) +
                     " and " + names.edge(edges[j][0], edges[j][1]) + " cross");
            }
        }
    }
    fail(names.facet(f) + ": its polygons cross (the planar triangulation needs new vertices)");
}

/// Checks facet f's polygons (corners, no corner repeated consecutively, one with an area,
/// not all collinear) and returns its reference corners.
std::array<VertIdx, 3> checked_reference_corners(const Plc3& plc, std::uint32_t f) {
    const Names names{plc};
    const Facet3& facet = plc.facets[f];
    bool has_area_polygon = false;
    for (std::size_t p = 0; p < facet.polygons.size(); ++p) {
        const auto& polygon = facet.polygons[p];
        const std::size_t n = polygon.size();
        if (n == 0) {
            fail(names.facet(f) + ": polygon " + std::to_string(p + 1) + " has no corners");
        }
        if (n >= 3) has_area_polygon = true;
        for (std::size_t k = 0; k + 1 < n || (n >= 3 && k < n); ++k) {
            if (polygon[k] == polygon[(k + 1) % n]) {
                fail("degenerate " + names.facet(f) + ": polygon " + std::to_string(p + 1) +
                     " repeats vertex " + names.vertex(polygon[k]) + " at consecutive corners");
            }
        }
    }
    if (!has_area_polygon) {
        fail("degenerate " + names.facet(f) + ": no polygon with 3 or more corners");
    }
    // The reference corners: the first three non-collinear ones in the order listed.
    const auto ref = facet_reference_corners(plc, facet);
    if (ref[2] == kNone) fail("degenerate " + names.facet(f) + ": its corners are collinear");
    return ref;
}

/// A corner of facet f off the plane of three of its corners (`plane`, set to them in index
/// order): beyond rounding of it, or with `exactly` off it at all (exact orient3d); kNone when
/// there is none. See off_plane_corner below.
VertIdx off_plane_corner(const Plc3& plc, std::uint32_t f, const std::array<VertIdx, 3>& ref,
                         std::array<VertIdx, 3>& plane, bool exactly = false);

/// The triangles (global corners, 3 per triangle) of facet f's polygons and holes projected
/// along axis `drop`: the constrained Delaunay triangulation of the projection, no vertex added,
/// every corner used; reversed when `flip`.
std::vector<VertIdx> projected_facet_triangles(const Plc3& plc, std::uint32_t f, int drop,
                                               bool flip) {
    const Names names{plc};
    const Facet3& facet = plc.facets[f];
    std::vector<VertIdx> corners;
    for (const auto& polygon : facet.polygons)
        corners.insert(corners.end(), polygon.begin(), polygon.end());
    std::sort(corners.begin(), corners.end());
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    auto local = [&](VertIdx v) {
        return static_cast<VertIdx>(std::lower_bound(corners.begin(), corners.end(), v) -
                                    corners.begin());
    };
    std::vector<double> xy;
    xy.reserve(2 * corners.size());
    for (const VertIdx v : corners) {
        const auto p = project_facet_point(plc.point(v), drop);
        xy.push_back(p[0]);
        xy.push_back(p[1]);
    }
    std::vector<VertIdx> segments;
    for (const auto& edge : facet_edges(facet)) {
        segments.push_back(local(edge[0]));
        segments.push_back(local(edge[1]));
    }
    std::vector<double> holes;
    for (std::size_t h = 0; h + 2 < facet.holes.size(); h += 3) {
        const auto p = project_facet_point(&facet.holes[h], drop);
        holes.push_back(p[0]);
        holes.push_back(p[1]);
    }
    Pslg pslg;
    pslg.xy = xy;
    pslg.segments = segments;
    pslg.holes = holes;
    Cdt2Result cdt;
    try {
        cdt = constrained_delaunay_2d(pslg);
    } catch (const AmbiguousMarkPoint& error) {
        fail(names.facet(f) + ": hole point " + std::to_string(error.index() + 1) +
             " lies on a polygon edge or corner of the facet");
    }
    if (cdt.mesh.vertex_count() > corners.size() || cdt.counters.intersections > 0) {
        fail_crossing(plc, f, drop);
    }
    const std::uint32_t count = cdt.mesh.triangle_count();
    if (count == 0) {
        fail("degenerate " + names.facet(f) + ": no area is left inside its polygons and holes");
    }
    // Every corner must be part of the facet's surface: a point or segment outside the
    // polygons (or inside a hole) would be a dangling piece no tetrahedralization could keep.
    std::vector<bool> used(corners.size(), false);
    for (const VertIdx v : cdt.mesh.triangles) used[v] = true;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        if (!used[k]) {
            fail(names.facet(f) + ": vertex " + names.vertex(corners[k]) +
                 " lies outside the facet's area (outside its polygons or in a hole)");
        }
    }
    std::vector<VertIdx> triangles;
    triangles.reserve(3 * std::size_t{count});
    for (std::uint32_t t = 0; t < count; ++t) {
        const VertIdx* tv = &cdt.mesh.triangles[3 * std::size_t{t}];
        const VertIdx v0 = corners[tv[0]], v1 = corners[tv[1]], v2 = corners[tv[2]];
        triangles.insert(triangles.end(), {v0, flip ? v2 : v1, flip ? v1 : v2});
    }
    return triangles;
}

/// Triangulates facet f into `out` (see triangulate_facets_3d).
void triangulate_facet(const Plc3& plc, std::uint32_t f, SurfaceTriangles3& out) {
    const Names names{plc};
    const Facet3& facet = plc.facets[f];
    const auto ref = checked_reference_corners(plc, f);
    std::array<VertIdx, 3> corners{};
    const VertIdx off = off_plane_corner(plc, f, ref, corners);
    if (off != kNone) {
        fail(names.facet(f) + " is not planar: vertex " + names.vertex(off) +
             " is off the plane of vertices " + names.vertex(corners[0]) + ", " +
             names.vertex(corners[1]) + ", " + names.vertex(corners[2]));
    }
    if (facet.polygons.size() == 1 && facet.polygons[0].size() == 3 && facet.holes.empty()) {
        // A triangle (STL, OFF, most .smesh facets) is its own triangulation; it is the
        // reference triangle, so its orientation is the facet's.
        out.triangles.insert(out.triangles.end(), facet.polygons[0].begin(),
                             facet.polygons[0].end());
        out.facets.push_back(f);
        return;
    }
    const FacetPlane plane = facet_plane(plc, facet);
    const std::vector<VertIdx> triangles =
        projected_facet_triangles(plc, f, plane.drop, plane.flip);
    out.triangles.insert(out.triangles.end(), triangles.begin(), triangles.end());
    out.facets.insert(out.facets.end(), triangles.size() / 3, f);
}

void check_finite_points(std::span<const double> values, const std::string& what) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            fail(what + " " + std::to_string(i / 3 + 1) + " has a non-finite coordinate (" +
                 format_number(values[i]) + ")");
        }
    }
}

/// Axis-aligned box of a few points: selects candidates only (every decision is exact).
struct Box3 {
    double lo[3], hi[3];
    bool contains(const double* p) const {
        return lo[0] <= p[0] && p[0] <= hi[0] && lo[1] <= p[1] && p[1] <= hi[1] && lo[2] <= p[2] &&
               p[2] <= hi[2];
    }
};

Box3 box_of(std::initializer_list<const double*> points) {
    Box3 b{};
    bool first = true;
    for (const double* p : points) {
        for (int k = 0; k < 3; ++k) {
            b.lo[k] = first ? p[k] : std::min(b.lo[k], p[k]);
            b.hi[k] = first ? p[k] : std::max(b.hi[k], p[k]);
        }
        first = false;
    }
    return b;
}

/// p lies strictly inside segment ab (a != b), exactly: collinear in every coordinate
/// projection, and strictly between a and b along an axis where they differ.
bool strictly_inside_segment_3d(const double* a, const double* b, const double* p) {
    if (!collinear_3d(a, b, p)) return false;
    for (int k = 0; k < 3; ++k) {
        if (a[k] != b[k]) return std::min(a[k], b[k]) < p[k] && p[k] < std::max(a[k], b[k]);
    }
    return false;
}

/// Adds facet f (once) to `facets` when p, a point of the plane of its triangle (a, b, c) up
/// to rounding, projects into the triangle in its best coordinate plane.
void add_facet_holding(const double* a, const double* b, const double* c, const double* p,
                       std::uint32_t f, std::vector<std::uint32_t>& facets) {
    const int drop = drop_axis(a, b, c);
    if (!triangle_contains_2d(project_facet_point(a, drop), project_facet_point(b, drop),
                              project_facet_point(c, drop), project_facet_point(p, drop)))
        return;
    if (std::find(facets.begin(), facets.end(), f) == facets.end()) facets.push_back(f);
}

/// Where the free vertices on the surface lie: on a segment (its ends, smaller index first),
/// or in the areas of facets.
struct SurfacePlacement3 {
    VertIdx vertex = kNone;
    std::array<VertIdx, 2> segment{kNone, kNone};  ///< kNone: not on a segment
    std::vector<std::uint32_t> facets;             ///< when not on a segment
};

std::vector<SurfacePlacement3> free_vertices_on_surface(const Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    std::vector<bool> used(n, false);
    for (const Facet3& facet : plc.facets) {
        for (const auto& polygon : facet.polygons) {
            for (const VertIdx v : polygon) used[v] = true;
        }
    }
    std::vector<VertIdx> free;
    for (VertIdx v = 0; v < n; ++v) {
        if (!used[v]) free.push_back(v);
    }
    std::vector<SurfacePlacement3> placements;
    if (free.empty()) return placements;
    std::vector<std::array<VertIdx, 2>> segments;
    for (const Facet3& facet : plc.facets) {
        for (const auto& e : facet_edges(facet)) {
            segments.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
        }
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    std::vector<Box3> segment_boxes;
    segment_boxes.reserve(segments.size());
    for (const auto& e : segments)
        segment_boxes.push_back(box_of({plc.point(e[0]), plc.point(e[1])}));
    const SurfaceTriangles3 surface = triangulate_facets_3d(plc);
    std::vector<Box3> triangle_boxes;
    triangle_boxes.reserve(surface.triangle_count());
    for (std::uint32_t t = 0; t < surface.triangle_count(); ++t) {
        const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
        triangle_boxes.push_back(box_of({plc.point(tv[0]), plc.point(tv[1]), plc.point(tv[2])}));
    }
    for (const VertIdx v : free) {
        const double* p = plc.point(v);
        SurfacePlacement3 placement;
        placement.vertex = v;
        for (std::size_t i = 0; i < segments.size(); ++i) {
            if (!segment_boxes[i].contains(p)) continue;
            if (strictly_inside_segment_3d(plc.point(segments[i][0]), plc.point(segments[i][1]),
                                           p)) {
                placement.segment = segments[i];
                break;
            }
        }
        if (placement.segment[0] == kNone) {
            for (std::uint32_t t = 0; t < surface.triangle_count(); ++t) {
                if (!triangle_boxes[t].contains(p)) continue;
                const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
                const double* a = plc.point(tv[0]);
                const double* b = plc.point(tv[1]);
                const double* c = plc.point(tv[2]);
                if (orient3d(a, b, c, p) != Sign::Zero) continue;
                add_facet_holding(a, b, c, p, surface.facets[t], placement.facets);
            }
            if (placement.facets.empty()) continue;
        }
        placements.push_back(std::move(placement));
    }
    return placements;
}

/// The box of points within w of p (w >= 0) in each coordinate, its corners rounded outward
/// (one step past the rounded sum), so that it holds the exact box. Rounding and the steps
/// commute with scaling by a power of two (normal numbers): the same box, scaled.
Box3 grown_box(const double* p, double w) {
    Box3 b{};
    for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::nextafter(p[k] - w, -std::numeric_limits<double>::infinity());
        b.hi[k] = std::nextafter(p[k] + w, std::numeric_limits<double>::infinity());
    }
    return b;
}

bool boxes_meet(const Box3& a, const Box3& b) {
    for (int k = 0; k < 3; ++k)
        if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
    return true;
}

/// The half-width of the box within which a free vertex counts as on a feature: 2^-48 of the
/// largest coordinate magnitude of the vertex and the feature's corners (16 units in the last
/// place at that magnitude; the rounding noise of points computed on the feature is under 1).
double near_tolerance(std::initializer_list<const double*> points) {
    double largest = 0;
    for (const double* p : points)
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(p[k]));
    if (!(largest > 0)) return 0;
    return std::ldexp(1.0, std::ilogb(largest) - 48);
}

/// The plane through a, b, c (not collinear) meets box b (exact orient3d at its corners).
bool plane_meets_box(const double* a, const double* b, const double* c, const Box3& box) {
    bool negative = false, positive = false;
    for (int corner = 0; corner < 8; ++corner) {
        const double q[3] = {corner & 1 ? box.hi[0] : box.lo[0], corner & 2 ? box.hi[1] : box.lo[1],
                             corner & 4 ? box.hi[2] : box.lo[2]};
        const Sign s = orient3d(a, b, c, q);
        if (s == Sign::Zero) return true;
        (s == Sign::Negative ? negative : positive) = true;
        if (negative && positive) return true;
    }
    return false;
}

/// Closed segment ab meets box `box` (exact): by separating axes, the coordinate intervals
/// overlap and, in each coordinate-plane projection where the segment is not a point, the
/// line through its projection does not leave every projected box corner strictly on one side.
bool segment_meets_box(const double* a, const double* b, const Box3& box) {
    if (!boxes_meet(box_of({a, b}), box)) return false;
    for (int drop = 0; drop < 3; ++drop) {
        const int i = (drop + 1) % 3, j = (drop + 2) % 3;
        if (a[i] == b[i] && a[j] == b[j]) continue;
        const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]};
        bool negative = false, positive = false;
        for (int corner = 0; corner < 4; ++corner) {
            const double q[2] = {corner & 1 ? box.hi[i] : box.lo[i],
                                 corner & 2 ? box.hi[j] : box.lo[j]};
            const Sign s = orient2d(pa, pb, q);
            if (s != Sign::Positive) negative = true;
            if (s != Sign::Negative) positive = true;
        }
        if (!(negative && positive)) return false;
    }
    return true;
}

/// Three corners of facet f spanning a wide triangle, whose plane rounding tilts least: the
/// corner farthest from the first, the one farthest from that, then the one farthest from
/// their line. A choice (doubles on halved differences scaled by the power of two of the
/// largest difference from the first corner: the same at 2^+-600, and a facet far smaller than
/// its coordinates keeps its differences), not a decision; `ref` (the reference corners) when
/// the doubles see the corners collinear.
std::array<VertIdx, 3> wide_corners(const Plc3& plc, std::uint32_t f,
                                    const std::array<VertIdx, 3>& ref) {
    std::vector<VertIdx> corners;
    for (const auto& polygon : plc.facets[f].polygons)
        corners.insert(corners.end(), polygon.begin(), polygon.end());
    const double* origin = plc.point(corners.front());
    double largest = 0;
    for (const VertIdx v : corners)
        for (int k = 0; k < 3; ++k)
            largest = std::max(largest, std::fabs(plc.point(v)[k] / 2 - origin[k] / 2));
    if (!(largest > 0)) return ref;
    const int e = std::ilogb(largest);
    const auto difference = [&](VertIdx u, VertIdx w) {
        std::array<double, 3> d{};
        for (int k = 0; k < 3; ++k)
            d[k] = std::ldexp(plc.point(w)[k] / 2 - plc.point(u)[k] / 2, -e);
        return d;
    };
    const auto norm2 = [](const std::array<double, 3>& d) {
        return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    };
    const auto farthest = [&](VertIdx from) {
        VertIdx best = from;
        double best_d = 0;
        for (const VertIdx v : corners) {
            const double d = norm2(difference(from, v));
            if (d > best_d) {
                best_d = d;
                best = v;
            }
        }
        return best;
    };
    const VertIdx a = farthest(corners.front());
    const VertIdx b = farthest(a);
    const std::array<double, 3> ab = difference(a, b);
    VertIdx c = kNone;
    double best = 0;
    for (const VertIdx v : corners) {
        const std::array<double, 3> av = difference(a, v);
        const std::array<double, 3> cross{ab[1] * av[2] - ab[2] * av[1],
                                          ab[2] * av[0] - ab[0] * av[2],
                                          ab[0] * av[1] - ab[1] * av[0]};
        const double d = norm2(cross);
        if (d > best) {
            best = d;
            c = v;
        }
    }
    if (c == kNone || a == b) return ref;
    return {a, b, c};
}

/// Unless `exactly`, a facet corner within 2^-46 of the largest coordinate magnitude (of it and
/// the three corners; 4 times near_tolerance, so that a vertex attached to a facet by
/// attach_free_vertices_near_surface_3d keeps it whole) of the plane of three corners spanning
/// a wide triangle (wide_corners) counts as on it: a rotated box's facet, its corners rounded an
/// ulp off one plane, stays one facet, triangulated in its projection like a planar one, its
/// inner edges free to flip (splitting it into triangles made their diagonals segments: small
/// input angles the input does not have, where refinement ran into its Steiner budget). Exact
/// (orient3d at the corners of a box rounded outward, which scales with the input).
VertIdx off_plane_corner(const Plc3& plc, std::uint32_t f, const std::array<VertIdx, 3>& ref,
                         std::array<VertIdx, 3>& plane, bool exactly) {
    plane = wide_corners(plc, f, ref);
    const double* a = plc.point(plane[0]);
    const double* b = plc.point(plane[1]);
    const double* c = plc.point(plane[2]);
    std::sort(plane.begin(), plane.end());
    for (const auto& polygon : plc.facets[f].polygons) {
        for (const VertIdx v : polygon) {
            const double* p = plc.point(v);
            if (orient3d(a, b, c, p) == Sign::Zero) continue;
            if (exactly ||
                !plane_meets_box(a, b, c, grown_box(p, 4 * near_tolerance({p, a, b, c}))))
                return v;
        }
    }
    return kNone;
}

/// The free vertices off the surface but within rounding of it (near_tolerance): inside the
/// box of a segment's point (not of its ends), or of a facet triangle's plane with the vertex
/// in the triangle's projection. Same form as free_vertices_on_surface.
std::vector<SurfacePlacement3> free_vertices_near_surface(const Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    std::vector<bool> used(n, false);
    for (const Facet3& facet : plc.facets)
        for (const auto& polygon : facet.polygons)
            for (const VertIdx v : polygon) used[v] = true;
    std::vector<SurfacePlacement3> placements;
    std::vector<std::array<VertIdx, 2>> segments;
    for (const Facet3& facet : plc.facets) {
        for (const auto& e : facet_edges(facet))
            segments.push_back({std::min(e[0], e[1]), std::max(e[0], e[1])});
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    std::vector<VertIdx> free;
    for (VertIdx v = 0; v < n; ++v)
        if (!used[v]) free.push_back(v);
    if (free.empty()) return placements;
    const SurfaceTriangles3 surface = triangulate_facets_3d(plc);
    for (const VertIdx v : free) {
        const double* p = plc.point(v);
        SurfacePlacement3 placement;
        placement.vertex = v;
        for (const auto& e : segments) {
            const double* a = plc.point(e[0]);
            const double* b = plc.point(e[1]);
            const Box3 box = grown_box(p, near_tolerance({p, a, b}));
            if (box.contains(a) || box.contains(b)) continue;  // beside a corner: left free
            if (segment_meets_box(a, b, box)) {
                placement.segment = e;
                break;
            }
        }
        if (placement.segment[0] == kNone) {
            for (std::uint32_t t = 0; t < surface.triangle_count(); ++t) {
                const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
                const double* a = plc.point(tv[0]);
                const double* b = plc.point(tv[1]);
                const double* c = plc.point(tv[2]);
                const Box3 box = grown_box(p, near_tolerance({p, a, b, c}));
                if (!boxes_meet(box_of({a, b, c}), box) || !plane_meets_box(a, b, c, box)) continue;
                add_facet_holding(a, b, c, p, surface.facets[t], placement.facets);
            }
            if (placement.facets.empty()) continue;
        }
        placements.push_back(std::move(placement));
    }
    return placements;
}

/// Inserts each placed vertex into its segment (in every facet polygon that has it) or adds it
/// to its facets as a 1-corner polygon.
FreeVertexEmbedding3 apply_placements(Plc3& plc, const std::vector<SurfacePlacement3>& placements) {
    FreeVertexEmbedding3 done;
    if (placements.empty()) return done;
    // Each segment's new vertices in order from its first end (smaller index) to its second:
    // along an axis where the ends differ, the coordinates are monotone on the line.
    std::map<std::array<VertIdx, 2>, std::vector<VertIdx>> on_segment;
    for (const SurfacePlacement3& placement : placements) {
        if (placement.segment[0] != kNone) {
            on_segment[placement.segment].push_back(placement.vertex);
            done.vertices.push_back(placement.vertex);
            ++done.on_segments;
        } else {
            for (const std::uint32_t f : placement.facets)
                plc.facets[f].polygons.push_back({placement.vertex});
            done.vertices.push_back(placement.vertex);
            ++done.on_facets;
        }
    }
    for (auto& [segment, chain] : on_segment) {
        const double* a = plc.point(segment[0]);
        const double* b = plc.point(segment[1]);
        int axis = 0;
        while (a[axis] == b[axis]) ++axis;
        const bool increasing = a[axis] < b[axis];
        std::sort(chain.begin(), chain.end(), [&](VertIdx u, VertIdx w) {
            return increasing ? plc.point(u)[axis] < plc.point(w)[axis]
                              : plc.point(u)[axis] > plc.point(w)[axis];
        });
    }
    // The chain between u and w, in the direction u -> w.
    const auto chain_between = [&on_segment](VertIdx u, VertIdx w) -> std::vector<VertIdx> {
        const auto it = on_segment.find({std::min(u, w), std::max(u, w)});
        if (it == on_segment.end()) return {};
        std::vector<VertIdx> chain = it->second;
        if (u > w) std::reverse(chain.begin(), chain.end());
        return chain;
    };
    for (Facet3& facet : plc.facets) {
        std::vector<std::vector<VertIdx>> polygons;
        for (const auto& polygon : facet.polygons) {
            const std::size_t n = polygon.size();
            if (n == 2) {
                // A segment inside the facet: one 2-corner polygon per piece.
                std::vector<VertIdx> path{polygon[0]};
                for (const VertIdx v : chain_between(polygon[0], polygon[1])) path.push_back(v);
                path.push_back(polygon[1]);
                for (std::size_t k = 0; k + 1 < path.size(); ++k)
                    polygons.push_back({path[k], path[k + 1]});
            } else if (n >= 3) {
                std::vector<VertIdx> loop;
                for (std::size_t k = 0; k < n; ++k) {
                    loop.push_back(polygon[k]);
                    for (const VertIdx v : chain_between(polygon[k], polygon[(k + 1) % n]))
                        loop.push_back(v);
                }
                polygons.push_back(std::move(loop));
            } else {
                polygons.push_back(polygon);
            }
        }
        facet.polygons = std::move(polygons);
    }
    return done;
}

/// Per vertex, the lowest-numbered vertex at the same point (exactly; -0 equals 0), itself when
/// it is the first there: a lexicographic sort, equal points by index, then equal neighbours.
/// @pre every coordinate finite.
std::vector<VertIdx> first_at_same_point(const Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    std::vector<VertIdx> order(n);
    for (VertIdx v = 0; v < n; ++v) order[v] = v;
    std::sort(order.begin(), order.end(), [&](VertIdx u, VertIdx v) {
        const double* p = plc.point(u);
        const double* q = plc.point(v);
        for (int k = 0; k < 3; ++k)
            if (p[k] != q[k]) return p[k] < q[k];
        return u < v;
    });
    std::vector<VertIdx> first(n);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const VertIdx v = order[i];
        const double* p = i == 0 ? nullptr : plc.point(order[i - 1]);
        const double* q = plc.point(v);
        first[v] =
            p != nullptr && p[0] == q[0] && p[1] == q[1] && p[2] == q[2] ? first[order[i - 1]] : v;
    }
    return first;
}

}  // namespace

void validate_plc_3d_input(const Plc3& plc) {
    const Names names{plc};
    if (plc.xyz.size() % 3 != 0) fail("PLC coordinates are not a multiple of 3 values");
    if (plc.holes.size() % 3 != 0) fail("PLC hole coordinates are not a multiple of 3 values");
    if (plc.vertex_count() > kMaxPoints) {
        fail("too many vertices: " + std::to_string(plc.vertex_count()) + " (at most " +
             std::to_string(kMaxPoints) + ")");
    }
    const std::uint32_t n = plc.vertex_count();
    for (std::size_t i = 0; i < plc.xyz.size(); ++i) {
        if (!std::isfinite(plc.xyz[i])) {
            const auto v = static_cast<VertIdx>(i / 3);
            throw NonFiniteCoordinate("vertex " + names.vertex(v) +
                                          " has a non-finite coordinate (" +
                                          format_number(plc.xyz[i]) + ")",
                                      v);
        }
    }
    if (plc.facets.empty()) fail("the PLC has no facets");
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        const Facet3& facet = plc.facets[f];
        if (facet.polygons.empty()) fail(names.facet(f) + " has no polygons");
        if (facet.holes.size() % 3 != 0) {
            fail(names.facet(f) + ": hole coordinates are not a multiple of 3 values");
        }
        for (std::size_t p = 0; p < facet.polygons.size(); ++p) {
            for (const VertIdx v : facet.polygons[p]) {
                if (v >= n) {
                    fail(names.facet(f) + ", polygon " + std::to_string(p + 1) + ": vertex " +
                         names.vertex(v) + " out of range (" +
                         (n == 0 ? std::string("there are no vertices")
                                 : "the vertices are numbered " + names.vertex(0) + " to " +
                                       names.vertex(n - 1)) +
                         ")");
                }
            }
        }
        check_finite_points(facet.holes, names.facet(f) + ": hole point");
    }
    check_finite_points(plc.holes, "volume hole point");
    for (std::size_t r = 0; r < plc.regions.size(); ++r) {
        const Region3& region = plc.regions[r];
        for (const double value :
             {region.x, region.y, region.z, region.attribute, region.max_volume}) {
            if (!std::isfinite(value)) {
                fail("region " + std::to_string(r + 1) + " has a non-finite value (" +
                     format_number(value) + ")");
            }
        }
    }
    // Duplicate points, exactly (merge_duplicate_vertices_3d merges them first for tetmesh).
    const std::vector<VertIdx> first = first_at_same_point(plc);
    for (VertIdx v = 0; v < n; ++v) {
        if (first[v] != v) {
            fail("vertices " + names.vertex(first[v]) + " and " + names.vertex(v) +
                 " are the same point " + format_point(plc.point(v), 3));
        }
    }
}

SurfaceTriangles3 triangulate_facets_3d(const Plc3& plc) {
    SurfaceTriangles3 surface;
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) triangulate_facet(plc, f, surface);
    return surface;
}

/// The half-width within which corner p counts as touching triangle abc: 2^-48 of the larger of
/// p's largest coordinate magnitude and that of abc's corner of least magnitude, the rounding
/// noise of input computed at that place (a turned box's corners), not of the triangle's far
/// corners: a needle's vertex (0, 1, 0) lies 4.7e-10 from its edge to (1, 2^31, 0), exactly
/// and on purpose, far beyond the noise of anything near 1.
double contact_tolerance(const double* p, const double* a, const double* b, const double* c) {
    const auto magnitude = [](const double* q) {
        return std::max({std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2])});
    };
    const double local =
        std::max(magnitude(p), std::min({magnitude(a), magnitude(b), magnitude(c)}));
    if (!(local > 0)) return 0;
    return std::ldexp(1.0, std::ilogb(local) - 48);
}

/// A corner of triangle ta (not one of tb's) within rounding of tb (contact_tolerance: the box
/// around it meets an edge of tb away from tb's corners, or tb's plane inside tb's
/// projection), or the other way round; kNone when there is none, else
/// that corner, with `near` the triangle it lies beside. Exact (orient3d, orient2d on boxes
/// rounded outward), like the free vertices' attachment: two facets meeting within rounding
/// (holes whose facets touch, turned by a rotation) pass the exact intersection test, and
/// boundary recovery then split a segment beside the other facet's corner without end.
VertIdx corner_within_rounding(const Plc3& plc, const VertIdx* ta, const VertIdx* tb,
                               const VertIdx*& near) {
    for (const auto& [from, to] : {std::pair{ta, tb}, std::pair{tb, ta}}) {
        const double* a = plc.point(to[0]);
        const double* b = plc.point(to[1]);
        const double* c = plc.point(to[2]);
        const Box3 triangle_box = box_of({a, b, c});
        for (int i = 0; i < 3; ++i) {
            const VertIdx v = from[i];
            if (v == to[0] || v == to[1] || v == to[2]) continue;
            const double* p = plc.point(v);
            const Box3 box = grown_box(p, contact_tolerance(p, a, b, c));
            if (!boxes_meet(triangle_box, box)) continue;
            bool beside = false;
            for (int k = 0; k < 3 && !beside; ++k) {
                const double* e0 = plc.point(to[k]);
                const double* e1 = plc.point(to[(k + 1) % 3]);
                if (box.contains(e0) || box.contains(e1)) {
                    beside = true;  // within rounding of a corner
                } else if (segment_meets_box(e0, e1, box)) {
                    beside = true;
                }
            }
            if (!beside && plane_meets_box(a, b, c, box)) {
                const int drop = drop_axis(a, b, c);
                beside = triangle_contains_2d(
                    project_facet_point(a, drop), project_facet_point(b, drop),
                    project_facet_point(c, drop), project_facet_point(p, drop));
            }
            if (beside) {
                near = to;
                return v;
            }
        }
    }
    return kNone;
}

void check_surface_self_intersection_3d(const Plc3& plc, const SurfaceTriangles3& surface) {
    const std::uint32_t count = surface.triangle_count();
    if (count < 2) return;
    // Bounding boxes, and the coordinates scaled by a power of two so that the grid arithmetic
    // neither overflows nor depends on the magnitude (the grid only selects pairs; every
    // decision is exact).
    std::vector<std::array<double, 6>> boxes(count);
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = std::numeric_limits<double>::infinity();
        hi[k] = -lo[k];
    }
    for (std::uint32_t t = 0; t < count; ++t) {
        auto& box = boxes[t];
        for (int k = 0; k < 3; ++k) {
            box[k] = std::numeric_limits<double>::infinity();
            box[3 + k] = -box[k];
        }
        for (int c = 0; c < 3; ++c) {
            const double* p = plc.point(surface.triangles[3 * std::size_t{t} + c]);
            for (int k = 0; k < 3; ++k) {
                box[k] = std::min(box[k], p[k]);
                box[3 + k] = std::max(box[3 + k], p[k]);
            }
        }
        // Grown by the rounding tolerance (corner_within_rounding), so that triangles within
        // rounding of each other are paired too.
        const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
        const double w = near_tolerance({plc.point(tv[0]), plc.point(tv[1]), plc.point(tv[2])});
        for (int k = 0; k < 3; ++k) {
            box[k] = std::nextafter(box[k] - w, -std::numeric_limits<double>::infinity());
            box[3 + k] = std::nextafter(box[3 + k] + w, std::numeric_limits<double>::infinity());
        }
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], box[k]);
            hi[k] = std::max(hi[k], box[3 + k]);
        }
    }
    double largest = 0;
    for (int k = 0; k < 3; ++k) largest = std::max({largest, std::fabs(lo[k]), std::fabs(hi[k])});
    const double scale =
        largest > 0 ? std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1000, 1000)) : 1.0;
    double range[3];
    double extent_sum = 0;
    for (int k = 0; k < 3; ++k) range[k] = hi[k] * scale - lo[k] * scale;
    for (const auto& box : boxes) {
        extent_sum += std::max({box[3] * scale - box[0] * scale, box[4] * scale - box[1] * scale,
                                box[5] * scale - box[2] * scale});
    }
    // Cells about twice the mean triangle extent, at most a few per triangle overall; coarser
    // when the triangles would fill too many cells (a few huge triangles).
    double cell =
        std::max(2.0 * extent_sum / count, std::max({range[0], range[1], range[2]}) * 0x1p-20);
    if (!(cell > 0)) cell = 1;
    std::vector<std::array<std::uint32_t, 6>> cells(count);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    std::uint64_t resolution[3];
    for (;;) {
        std::uint64_t total = 1;
        for (int k = 0; k < 3; ++k) {
            resolution[k] = static_cast<std::uint64_t>(std::min(std::ceil(range[k] / cell), 1e6));
            resolution[k] = std::max<std::uint64_t>(resolution[k], 1);
            total *= resolution[k];
        }
        if (total > 8 * std::uint64_t{count} + 64) {
            cell *= 2;
            continue;
        }
        // Monotone in the coordinate, so boxes that overlap get cell ranges that overlap.
        auto cell_of = [&](double x, int k) {
            const double g = std::floor((x * scale - lo[k] * scale) / cell);
            // (a NaN, which no finite input should give, lands in cell 0 rather than in UB)
            const double clamped =
                g >= 0 ? std::min(g, static_cast<double>(resolution[k] - 1)) : 0.0;
            return static_cast<std::uint32_t>(clamped);
        };
        std::uint64_t entry_count = 0;
        for (std::uint32_t t = 0; t < count; ++t) {
            std::uint64_t covered = 1;
            for (int k = 0; k < 3; ++k) {
                cells[t][k] = cell_of(boxes[t][k], k);
                cells[t][3 + k] = cell_of(boxes[t][3 + k], k);
                covered *= cells[t][3 + k] - cells[t][k] + 1;
            }
            entry_count += covered;
        }
        if (entry_count > 32 * std::uint64_t{count} + 4096 && total > 1) {
            cell *= 2;
            continue;
        }
        entries.clear();
        entries.reserve(entry_count);
        for (std::uint32_t t = 0; t < count; ++t) {
            const auto& c = cells[t];
            for (std::uint64_t x = c[0]; x <= c[3]; ++x) {
                for (std::uint64_t y = c[1]; y <= c[4]; ++y) {
                    for (std::uint64_t z = c[2]; z <= c[5]; ++z) {
                        entries.emplace_back((x * resolution[1] + y) * resolution[2] + z, t);
                    }
                }
            }
        }
        break;
    }
    std::sort(entries.begin(), entries.end());
    const Names names{plc};
    for (std::size_t begin = 0; begin < entries.size();) {
        std::size_t end = begin;
        while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
        const std::uint64_t key = entries[begin].first;
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t ta = entries[i].second;
            for (std::size_t j = i + 1; j < end; ++j) {
                const std::uint32_t tb = entries[j].second;
                if (surface.facets[ta] == surface.facets[tb]) continue;
                bool overlap = true;
                for (int k = 0; k < 3 && overlap; ++k) {
                    overlap = boxes[ta][k] <= boxes[tb][3 + k] && boxes[tb][k] <= boxes[ta][3 + k];
                }
                if (!overlap) continue;
                // Test each pair once: in the cell holding the corner of the boxes' overlap.
                const std::uint64_t x = std::max(cells[ta][0], cells[tb][0]);
                const std::uint64_t y = std::max(cells[ta][1], cells[tb][1]);
                const std::uint64_t z = std::max(cells[ta][2], cells[tb][2]);
                if ((x * resolution[1] + y) * resolution[2] + z != key) continue;
                const VertIdx* va = &surface.triangles[3 * std::size_t{ta}];
                const VertIdx* vb = &surface.triangles[3 * std::size_t{tb}];
                if (triangles_meet_improperly(plc, va, vb)) {
                    std::uint32_t fa = surface.facets[ta], fb = surface.facets[tb];
                    if (fa > fb) {
                        std::swap(fa, fb);
                        std::swap(va, vb);
                    }
                    fail("self-intersecting surface: " + names.facet(fa) + " and " +
                         names.facet(fb) + " intersect (triangle " + names.triangle(va) + " of " +
                         names.facet(fa) + " and triangle " + names.triangle(vb) + " of " +
                         names.facet(fb) + ")");
                }
                const VertIdx* near = nullptr;
                const VertIdx corner = corner_within_rounding(plc, va, vb, near);
                if (corner != kNone) {
                    const std::uint32_t f_corner =
                        near == vb ? surface.facets[ta] : surface.facets[tb];
                    const std::uint32_t f_near =
                        near == vb ? surface.facets[tb] : surface.facets[ta];
                    fail("self-touching surface: vertex " + names.vertex(corner) + " of " +
                         names.facet(f_corner) + " lies within rounding of triangle " +
                         names.triangle(near) + " of " + names.facet(f_near) +
                         " (closer than 2^-48 of the coordinates there) without being a corner of "
                         "it: "
                         "the facets touch or overlap as far as doubles tell");
                }
            }
        }
        begin = end;
    }
}

void check_surface_closed_3d(const Plc3& plc, const SurfaceTriangles3& surface) {
    struct EdgeUse {
        VertIdx lo, hi;
        std::uint32_t facet;
    };
    std::vector<EdgeUse> edges;
    edges.reserve(surface.triangles.size());
    for (std::uint32_t t = 0; t < surface.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const VertIdx a = surface.triangles[3 * std::size_t{t} + k];
            const VertIdx b = surface.triangles[3 * std::size_t{t} + (k + 1) % 3];
            edges.push_back({std::min(a, b), std::max(a, b), surface.facets[t]});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const EdgeUse& p, const EdgeUse& q) {
        return p.lo != q.lo ? p.lo < q.lo : p.hi < q.hi;
    });
    const Names names{plc};
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
        if (j - i == 1) {
            fail("surface not closed: edge " + names.edge(edges[i].lo, edges[i].hi) + " of " +
                 names.facet(edges[i].facet) + " lies in only one surface triangle");
        }
        i = j;
    }
}

FreeVertexEmbedding3 embed_free_vertices_3d(Plc3& plc) {
    return apply_placements(plc, free_vertices_on_surface(plc));
}

FreeVertexEmbedding3 attach_free_vertices_near_surface_3d(Plc3& plc) {
    FreeVertexEmbedding3 attached = apply_placements(plc, free_vertices_near_surface(plc));
    if (!attached.vertices.empty()) attached.split_warnings = split_nonplanar_facets_3d(plc);
    return attached;
}

bool facets_exactly_planar_3d(const Plc3& plc) {
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        std::array<VertIdx, 3> corners{};
        if (off_plane_corner(plc, f, checked_reference_corners(plc, f), corners, true) != kNone)
            return false;
    }
    return true;
}

std::vector<std::string> merge_duplicate_vertices_3d(Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    if (!plc.input_vertex.empty()) return {};
    // A coordinate that is not finite, or a corner out of range: validate_plc_3d_input names
    // it in the input's numbering.
    for (const double x : plc.xyz)
        if (!std::isfinite(x)) return {};
    for (const Facet3& facet : plc.facets)
        for (const std::vector<VertIdx>& polygon : facet.polygons)
            for (const VertIdx v : polygon)
                if (v >= n) return {};
    const std::vector<VertIdx> first = first_at_same_point(plc);
    std::vector<std::pair<VertIdx, VertIdx>> merged;  // (input vertex, the first at its point)
    for (VertIdx v = 0; v < n; ++v)
        if (first[v] != v) merged.emplace_back(v, first[v]);
    if (merged.empty()) return {};
    // The names in the warning are the input's: taken before the numbering changes.
    const Names names{plc};
    std::string list;
    for (std::size_t i = 0; i < merged.size() && i < 10; ++i)
        list += (i == 0 ? "" : ", ") + names.vertex(merged[i].first) + " into " +
                names.vertex(merged[i].second) + " " + format_point(plc.point(merged[i].first), 3);
    if (merged.size() > 10) list += " and " + std::to_string(merged.size() - 10) + " more";

    std::vector<double> xyz;
    xyz.reserve(3 * (std::size_t{n} - merged.size()));
    plc.merged_vertex.assign(n, kNone);
    for (VertIdx v = 0; v < n; ++v) {
        if (first[v] != v) continue;
        plc.merged_vertex[v] = static_cast<VertIdx>(plc.input_vertex.size());
        plc.input_vertex.push_back(v);
        xyz.insert(xyz.end(), plc.point(v), plc.point(v) + 3);
    }
    for (VertIdx v = 0; v < n; ++v) plc.merged_vertex[v] = plc.merged_vertex[first[v]];
    plc.xyz = std::move(xyz);
    for (Facet3& facet : plc.facets) {
        for (std::vector<VertIdx>& polygon : facet.polygons) {
            // Only the repeats the merge makes are dropped: the input's own (vertex 1 twice
            // in a row) are left for validate_plc_3d_input to refuse.
            const auto merged_here = [&](VertIdx a, VertIdx b) {
                return a != b && plc.merged_vertex[a] == plc.merged_vertex[b];
            };
            std::vector<VertIdx> corners, original;
            for (const VertIdx v : polygon) {
                if (!original.empty() && merged_here(original.back(), v)) continue;
                original.push_back(v);
                corners.push_back(plc.merged_vertex[v]);
            }
            // A closed loop: its last corner also comes before its first.
            while (polygon.size() >= 3 && original.size() > 1 &&
                   merged_here(original.back(), original.front())) {
                original.pop_back();
                corners.pop_back();
            }
            if (polygon.size() >= 3 && corners.size() < 3) {
                // A loop merged to fewer than three points keeps its corners, so that
                // drop_zero_area_facets_3d sees it for what it is.
                corners.clear();
                for (const VertIdx v : polygon) corners.push_back(plc.merged_vertex[v]);
            }
            polygon = std::move(corners);
        }
    }
    return {std::to_string(merged.size()) + (merged.size() == 1 ? " vertex" : " vertices") +
            " at the same point as an earlier one merged into it, as TetGen does (the output "
            "keeps them, unused): " +
            list};
}

namespace {

/// Leaves out the facets for which `why(f)` gives a reason (appended to the facet's name in
/// the warning), keeping facet_origin in step; one warning "N facets <what> left out: ...",
/// or nothing when none goes.
template <class Why>
std::vector<std::string> drop_facets(Plc3& plc, const char* what, Why&& why) {
    const Names names{plc};
    std::string list;
    std::size_t dropped = 0;
    std::vector<Facet3> kept;
    std::vector<std::uint64_t> kept_origin;
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        if (const std::optional<std::string> reason = why(f)) {
            if (++dropped <= 10) list += (dropped == 1 ? "" : ", ") + names.facet(f) + *reason;
            continue;
        }
        kept.push_back(plc.facets[f]);
        if (f < plc.facet_origin.size()) kept_origin.push_back(plc.facet_origin[f]);
    }
    if (dropped == 0) return {};
    if (dropped > 10) list += " and " + std::to_string(dropped - 10) + " more";
    plc.facets = std::move(kept);
    if (!plc.facet_origin.empty()) plc.facet_origin = std::move(kept_origin);
    return {std::to_string(dropped) + (dropped == 1 ? " facet " : " facets ") + what +
            " left out: " + list};
}

}  // namespace

std::vector<std::string> drop_zero_area_facets_3d(Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    const auto distinct = [](std::vector<VertIdx> corners) {
        std::sort(corners.begin(), corners.end());
        return static_cast<std::size_t>(std::unique(corners.begin(), corners.end()) -
                                        corners.begin());
    };
    return drop_facets(plc, "with no area (corners at fewer than three points)",
                       [&](std::uint32_t f) -> std::optional<std::string> {
                           bool collapsed = false, area = false, in_range = true;
                           for (const std::vector<VertIdx>& polygon : plc.facets[f].polygons) {
                               for (const VertIdx v : polygon) in_range = in_range && v < n;
                               if (polygon.size() < 3) continue;
                               if (distinct(polygon) < 3)
                                   collapsed = true;
                               else
                                   area = true;
                           }
                           if (collapsed && !area && in_range) return std::string();
                           return std::nullopt;
                       });
}

std::vector<std::string> drop_repeated_facets_3d(Plc3& plc) {
    const std::uint32_t n = plc.vertex_count();
    // A polygon as a key: rotated to start at its least corner, then read in the direction
    // whose second corner is the smaller.
    const auto canonical = [](const std::vector<VertIdx>& polygon) {
        const std::size_t k = polygon.size();
        const std::size_t start = static_cast<std::size_t>(
            std::min_element(polygon.begin(), polygon.end()) - polygon.begin());
        const bool forward = polygon[(start + 1) % k] <= polygon[(start + k - 1) % k];
        std::vector<VertIdx> key(k);
        for (std::size_t i = 0; i < k; ++i)
            key[i] = polygon[forward ? (start + i) % k : (start + k - i) % k];
        return key;
    };
    const Names names{plc};
    std::map<std::vector<VertIdx>, std::uint32_t> first;
    return drop_facets(
        plc, "repeating an earlier one", [&](std::uint32_t f) -> std::optional<std::string> {
            const Facet3& facet = plc.facets[f];
            if (facet.polygons.size() != 1 || !facet.holes.empty()) return std::nullopt;
            const std::vector<VertIdx>& polygon = facet.polygons[0];
            if (polygon.size() < 3 ||
                !std::all_of(polygon.begin(), polygon.end(), [n](VertIdx v) { return v < n; }))
                return std::nullopt;
            const auto [it, inserted] = first.emplace(canonical(polygon), f);
            if (inserted) return std::nullopt;
            return " repeats " + names.facet(it->second);
        });
}

std::vector<std::string> prepare_plc_for_meshing_3d(Plc3& plc) {
    // Vertices at one point become one, as TetGen makes them; facets left with no area go.
    std::vector<std::string> warnings = merge_duplicate_vertices_3d(plc);
    for (const auto& step : {drop_zero_area_facets_3d, drop_repeated_facets_3d}) {
        const std::vector<std::string> dropped = step(plc);
        warnings.insert(warnings.end(), dropped.begin(), dropped.end());
    }
    // A free vertex on a segment or a facet becomes part of it (as Triangle does in 2D).
    validate_plc_3d_input(plc);
    // A facet whose corners were rounded off their plane (a rotated box) becomes the
    // triangles of its projection, as TetGen meshes it; a warning names it.
    const std::vector<std::string> split = split_nonplanar_facets_3d(plc);
    warnings.insert(warnings.end(), split.begin(), split.end());
    // A free vertex within rounding of a segment or facet (a point of a rotated box's edge
    // or facet, rounded off it) becomes part of it, and the facets it joins are split.
    const FreeVertexEmbedding3 near = attach_free_vertices_near_surface_3d(plc);
    if (!near.vertices.empty()) {
        std::string names;
        for (const VertIdx v : near.vertices)
            names += (names.empty() ? "" : ", ") + std::to_string(plc.vertex_number(v));
        warnings.push_back(
            "free vertices within rounding of the surface (2^-48 of their coordinates) made "
            "part of it, as if on it: " +
            names);
        warnings.insert(warnings.end(), near.split_warnings.begin(), near.split_warnings.end());
    }
    embed_free_vertices_3d(plc);
    // A mesh generator's domain must enclose a volume: an open surface would leave the flood
    // fill nothing to keep (internal facets, edges in more than two triangles, are fine).
    check_surface_closed_3d(plc, validate_plc_3d(plc));
    return warnings;
}

std::vector<std::string> split_nonplanar_facets_3d(Plc3& plc, bool within_rounding_too) {
    std::vector<std::string> warnings;
    const auto facet_count = static_cast<std::uint32_t>(plc.facets.size());
    std::vector<Facet3> added;
    std::vector<std::uint64_t> added_origin;
    for (std::uint32_t f = 0; f < facet_count; ++f) {
        const auto ref = checked_reference_corners(plc, f);
        std::array<VertIdx, 3> corners{};
        const VertIdx off = off_plane_corner(plc, f, ref, corners, within_rounding_too);
        if (off == kNone) continue;
        const FacetPlane plane = facet_plane(plc, plc.facets[f]);
        const std::vector<VertIdx> triangles =
            projected_facet_triangles(plc, f, plane.drop, plane.flip);
        const Names names{plc};
        static constexpr const char* kPlanes[3] = {"yz", "zx", "xy"};
        warnings.push_back(names.facet(f) + " is not planar (vertex " + names.vertex(off) +
                           " is off the plane of vertices " + names.vertex(corners[0]) + ", " +
                           names.vertex(corners[1]) + ", " + names.vertex(corners[2]) +
                           "): split into the " + std::to_string(triangles.size() / 3) +
                           " triangles of its constrained Delaunay triangulation in the " +
                           kPlanes[plane.drop] + " plane, each a facet with its marker");
        const int marker = plc.facets[f].marker;
        const std::uint64_t origin = f < plc.facet_origin.size() ? plc.facet_origin[f] : 0;
        for (std::size_t t = 0; t < triangles.size(); t += 3) {
            Facet3 triangle;
            triangle.polygons.push_back({triangles[t], triangles[t + 1], triangles[t + 2]});
            triangle.marker = marker;
            if (t == 0) {
                plc.facets[f] = std::move(triangle);
            } else {
                added.push_back(std::move(triangle));
                added_origin.push_back(origin);
            }
        }
    }
    plc.facets.insert(plc.facets.end(), std::make_move_iterator(added.begin()),
                      std::make_move_iterator(added.end()));
    if (!plc.facet_origin.empty())
        plc.facet_origin.insert(plc.facet_origin.end(), added_origin.begin(), added_origin.end());
    return warnings;
}

SurfaceTriangles3 validate_plc_3d(const Plc3& plc) {
    validate_plc_3d_input(plc);
    const std::vector<SurfacePlacement3> stray = free_vertices_on_surface(plc);
    if (!stray.empty()) {
        const Names names{plc};
        const SurfacePlacement3& first = stray.front();
        fail("vertex " + names.vertex(first.vertex) + " " +
             format_point(plc.point(first.vertex), 3) + " lies " +
             (first.segment[0] != kNone
                  ? "inside segment " + names.edge(first.segment[0], first.segment[1])
                  : "in " + names.facet(first.facets.front())) +
             " but in no facet polygon: list it in the facet (a corner of the polygon edge, or "
             "a 1-corner polygon), or embed it with embed_free_vertices_3d (exactmesh tetmesh "
             "does)");
    }
    SurfaceTriangles3 surface = triangulate_facets_3d(plc);
    check_surface_self_intersection_3d(plc, surface);
    return surface;
}

PlcSegments3 plc_segments_3d(const Plc3& plc) {
    PlcSegments3 out;
    std::map<std::uint64_t, std::uint32_t> index;
    out.segments_of_facet.resize(plc.facets.size());
    const auto add_unique = [](std::vector<std::uint32_t>& list, std::uint32_t value) {
        if (std::find(list.begin(), list.end(), value) == list.end()) list.push_back(value);
    };
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        for (const auto& polygon : plc.facets[f].polygons) {
            const std::size_t n = polygon.size();
            if (n < 2) continue;
            for (std::size_t k = 0; k < (n == 2 ? 1 : n); ++k) {
                VertIdx a = polygon[k], b = polygon[(k + 1) % n];
                if (a > b) std::swap(a, b);
                const auto [it, added] = index.emplace((std::uint64_t{a} << 32) | b,
                                                       static_cast<std::uint32_t>(out.ends.size()));
                if (added) {
                    out.ends.push_back({a, b});
                    out.facets_of_segment.emplace_back();
                }
                add_unique(out.facets_of_segment[it->second], f);
                add_unique(out.segments_of_facet[f], it->second);
            }
        }
    }
    return out;
}

std::vector<std::array<VertIdx, 3>> facet_largest_triangles_3d(const Plc3& plc,
                                                               const SurfaceTriangles3& surface) {
    std::vector<std::array<VertIdx, 3>> largest_triangle(plc.facets.size(), {kNone, kNone, kNone});
    std::vector<std::pair<long, double>> largest_area(plc.facets.size(), {LONG_MIN, 0.0});
    for (std::uint32_t t = 0; t < surface.triangle_count(); ++t) {
        const VertIdx* c = &surface.triangles[3 * std::size_t{t}];
        const double *a = plc.point(c[0]), *b = plc.point(c[1]), *d = plc.point(c[2]);
        double u[3], w[3], largest = 0;
        for (int k = 0; k < 3; ++k) {
            u[k] = b[k] - a[k], w[k] = d[k] - a[k];
            largest = std::max({largest, std::fabs(u[k]), std::fabs(w[k])});
        }
        const int shift = predicates::unit_shift(largest);
        const predicates::PowerOfTwo unit(shift);
        for (int k = 0; k < 3; ++k) u[k] = unit(u[k]), w[k] = unit(w[k]);
        const double normal[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                                  u[0] * w[1] - u[1] * w[0]};
        const double scaled = std::fabs(normal[0]) + std::fabs(normal[1]) + std::fabs(normal[2]);
        int exponent = 0;
        const double mantissa = std::frexp(scaled, &exponent);
        const std::pair<long, double> area{scaled > 0 ? long{exponent} - 2L * shift : LONG_MIN,
                                           mantissa};
        const std::uint32_t f = surface.facets[t];
        if (largest_triangle[f][0] == kNone || area > largest_area[f]) {
            largest_area[f] = area;
            largest_triangle[f] = {c[0], c[1], c[2]};
        }
    }
    return largest_triangle;
}

}  // namespace exactmesh::triangulation
