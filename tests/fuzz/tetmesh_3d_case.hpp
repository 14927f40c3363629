// SPDX-License-Identifier: MIT
// One case of fuzz_tetmesh_3d, decoded and run once for the libFuzzer target and for the
// release-build test that replays its seeds and saved findings
// (tests/unit/generators/tetmesh_3d_fuzz_cases_test.cpp): a small PLC of one of four forms
// (a box, a prism over a convex 3-6-gon, a box with a box-shaped hole at a gap of 2^-2..2^-45 of
// its side, a star-shaped polyhedron: a subdivided octahedron with random vertex radii), with up
// to 6 free vertices inside, on facets, on edges, or 1e-12..1e-300 off a facet, an edge or a
// corner, every coordinate times 2^k (k in [-600, 600]); then the pipeline of `exactmesh
// tetmesh`: validate_plc_3d_input, split_nonplanar_facets_3d, attach_free_vertices_near_surface_3d
// (then split_nonplanar_facets_3d again), embed_free_vertices_3d,
// validate_plc_3d,
// check_surface_closed_3d, boundary_recovery_3d, one generator (delaunay_refinement_3d with B in
// [1, 3], frontal_delaunay_3d or octree_mesh_3d with a size of 1/1..1/4 of the box's largest
// side), then sliver_removal_3d, all with small budgets. Every mesh (recovered, generated,
// improved) must pass check_boundary_conformity_3d and keep every input vertex at its input
// coordinates; a refined mesh must meet the radius-edge bound as the command requires (a
// tetrahedron over it is allowed only when refinement rejected points). InputError and
// GeometryError are accepted outcomes; any other exception is a failure.
//
// Byte layout (bytes past the end read as 0): 0 form (% 5), 1 generator (% 3), 2 generator
// parameter, 3-4 the scale exponent (little endian, % 1201 - 600), then the form's bytes, then
// the free vertex count (% 7) and 7 bytes per free vertex (kind, facet, 3 weights or edge
// position, offset exponent and signs).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_mesh_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::fuzz {

enum class TetmeshForm : std::uint8_t { Box, Prism, BoxWithHole, Star, TouchingBoxes, Count };
enum class TetmeshGenerator : std::uint8_t { Refinement, Frontal, Octree, Count };

inline const char* tetmesh_form_name(TetmeshForm form) {
    switch (form) {
        case TetmeshForm::Box:
            return "box";
        case TetmeshForm::Prism:
            return "prism";
        case TetmeshForm::BoxWithHole:
            return "box-with-hole";
        case TetmeshForm::TouchingBoxes:
            return "touching-boxes";
        default:
            return "star";
    }
}

inline const char* tetmesh_generator_name(TetmeshGenerator generator) {
    switch (generator) {
        case TetmeshGenerator::Refinement:
            return "delaunay-refinement";
        case TetmeshGenerator::Frontal:
            return "frontal";
        default:
            return "octree";
    }
}

/// Budgets that keep a case to a fraction of a second under the sanitizers.
inline constexpr std::uint64_t kTetmeshRecoverySteiner = 400;
inline constexpr std::uint64_t kTetmeshGeneratorSteiner = 400;
inline constexpr std::uint64_t kTetmeshOctreeLeaves = 4096;

struct TetmeshCase {
    TetmeshForm form = TetmeshForm::Box;
    TetmeshGenerator generator = TetmeshGenerator::Refinement;
    int scale_exponent = 0;        ///< every coordinate times 2^scale_exponent
    double radius_edge_bound = 2;  ///< refinement's B
    double size = 0;               ///< frontal and octree: the uniform size (scaled)
    std::uint32_t free_vertices = 0;
    triangulation::Plc3 plc;  ///< as decoded (before embedding)
};

struct TetmeshOutcome {
    bool meshed = false;  ///< every stage ran and every check passed
    std::string stage;    ///< the last stage started
    std::string error;    ///< the InputError or GeometryError, when not meshed
    std::string failure;  ///< a failed check or an unexpected exception (a bug); else empty
};

namespace tetmesh_detail {

class ByteReader {
  public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    std::uint8_t byte() { return position_ < size_ ? data_[position_++] : 0; }
    /// In (0, 1): (1 + byte) / 257.
    double unit() { return (1.0 + byte()) / 257.0; }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t position_ = 0;
};

inline std::uint32_t add_vertex(triangulation::Plc3& plc, double x, double y, double z) {
    plc.xyz.insert(plc.xyz.end(), {x, y, z});
    return plc.vertex_count() - 1;
}

inline void add_facet(triangulation::Plc3& plc, std::vector<triangulation::VertIdx> corners) {
    triangulation::Facet3 facet;
    facet.polygons.push_back(std::move(corners));
    plc.facets.push_back(std::move(facet));
}

/// The 6 quadrilateral facets of the box [x0, x1] x [y0, y1] x [z0, z1].
inline void add_box(triangulation::Plc3& plc, std::array<double, 3> lo, std::array<double, 3> hi) {
    std::array<std::uint32_t, 8> v{};
    for (unsigned i = 0; i < 8; ++i)
        v[i] = add_vertex(plc, (i & 1) ? hi[0] : lo[0], (i & 2) ? hi[1] : lo[1],
                          (i & 4) ? hi[2] : lo[2]);
    add_facet(plc, {v[0], v[2], v[3], v[1]});
    add_facet(plc, {v[4], v[5], v[7], v[6]});
    add_facet(plc, {v[0], v[1], v[5], v[4]});
    add_facet(plc, {v[2], v[6], v[7], v[3]});
    add_facet(plc, {v[0], v[4], v[6], v[2]});
    add_facet(plc, {v[1], v[3], v[7], v[5]});
}

/// A side in [1, 5): 1 + byte / 64, exact.
inline double side(ByteReader& in) {
    return 1.0 + in.byte() / 64.0;
}

inline void decode_box(ByteReader& in, triangulation::Plc3& plc) {
    add_box(plc, {0, 0, 0}, {side(in), side(in), side(in)});
}

/// A prism over a convex n-gon (n in 3..6, corners on a circle at jittered angles), height in
/// [1, 5); every side is exactly planar (vertical).
inline void decode_prism(ByteReader& in, triangulation::Plc3& plc) {
    const unsigned n = 3 + in.byte() % 4;
    const double radius = side(in), height = side(in);
    constexpr double kPi = 3.141592653589793;
    std::vector<std::uint32_t> bottom, top;
    for (unsigned i = 0; i < n; ++i) {
        const double angle = 2 * kPi * (i + 0.45 * (in.unit() - 0.5)) / n;
        bottom.push_back(add_vertex(plc, radius * std::cos(angle), radius * std::sin(angle), 0));
    }
    for (unsigned i = 0; i < n; ++i) {
        const double* p = plc.point(bottom[i]);
        top.push_back(add_vertex(plc, p[0], p[1], height));
    }
    add_facet(plc, bottom);
    add_facet(plc, top);
    for (unsigned i = 0; i < n; ++i) {
        const unsigned j = (i + 1) % n;
        add_facet(plc, {bottom[i], bottom[j], top[j], top[i]});
    }
}

/// Two boxes that touch only along an edge (byte even) or only at a corner (odd): [0, a] x
/// [0, b] x [0, c] and, from its corner (a, b, 0) or (a, b, c), a second box of its own sides.
/// The domain's boundary is not a manifold there (the stars of the shared vertices, and of
/// points later put on the shared edge, fall in two pieces); shared corners are one vertex.
inline void decode_touching_boxes(ByteReader& in, triangulation::Plc3& plc) {
    const bool along_an_edge = in.byte() % 2 == 0;
    const double a = side(in), b = side(in), c = side(in);
    add_box(plc, {0, 0, 0}, {a, b, c});
    const std::array<double, 3> lo{a, b, along_an_edge ? 0.0 : c};
    const std::array<double, 3> hi{a + side(in), b + side(in), along_an_edge ? c : c + side(in)};
    const std::uint32_t first = plc.vertex_count();
    add_box(plc, lo, hi);
    // The second box's corners that coincide with the first's are renumbered to them and their
    // copies dropped (a PLC may not repeat a point).
    std::vector<std::uint32_t> remap(8);
    std::vector<double> kept(plc.xyz.begin(),
                             plc.xyz.begin() + 3 * static_cast<std::ptrdiff_t>(first));
    for (std::uint32_t i = 0; i < 8; ++i) {
        const double* p = plc.point(first + i);
        remap[i] = triangulation::kNone;
        for (std::uint32_t v = 0; v < first; ++v) {
            const double* q = plc.point(v);
            if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) remap[i] = v;
        }
        if (remap[i] == triangulation::kNone) {
            remap[i] = static_cast<std::uint32_t>(kept.size() / 3);
            kept.insert(kept.end(), p, p + 3);
        }
    }
    plc.xyz = std::move(kept);
    for (std::size_t f = plc.facets.size() - 6; f < plc.facets.size(); ++f)
        for (auto& polygon : plc.facets[f].polygons)
            for (auto& v : polygon) v = remap[v - first];
}

/// An outer box and a box-shaped hole whose low x side lies a gap of side * 2^-(2 + byte % 44)
/// from the outer box's (so gaps reach far below what refinement can resolve in its budget); its
/// high x side at the middle (so at most a quarter of the side from the gap).
inline void decode_box_with_hole(ByteReader& in, triangulation::Plc3& plc) {
    const double a = side(in), b = side(in), c = side(in);
    const double gap = std::ldexp(a, -(2 + in.byte() % 44));
    add_box(plc, {0, 0, 0}, {a, b, c});
    const double x1 = a / 2;
    add_box(plc, {gap, b / 4, c / 4}, {x1, 3 * b / 4, 3 * c / 4});
    plc.holes = {(gap + x1) / 2, b / 2, c / 2};
}

/// A star-shaped polyhedron about the origin: the octahedron's faces subdivided n times (n in
/// 1..3), the vertex at integer direction d (|d|_1 = n) placed at d * r / n, r in [1/4, 1)
/// per vertex; every face is a triangle facet. Radial projection from the origin maps it onto
/// the subdivided octahedron, so it never self-intersects.
inline void decode_star(ByteReader& in, triangulation::Plc3& plc) {
    const int n = 1 + in.byte() % 3;
    std::map<std::array<int, 3>, std::uint32_t> vertex_of;
    auto vertex = [&](int x, int y, int z) {
        const std::array<int, 3> key{x, y, z};
        const auto found = vertex_of.find(key);
        if (found != vertex_of.end()) return found->second;
        const double r = (0.25 + 0.75 * in.byte() / 256.0) / n;
        const std::uint32_t v = add_vertex(plc, r * x, r * y, r * z);
        vertex_of.emplace(key, v);
        return v;
    };
    for (int octant = 0; octant < 8; ++octant) {
        const int sx = (octant & 1) ? -1 : 1, sy = (octant & 2) ? -1 : 1,
                  sz = (octant & 4) ? -1 : 1;
        auto at = [&](int i, int j) { return vertex(sx * i, sy * j, sz * (n - i - j)); };
        for (int i = 0; i < n; ++i) {
            for (int j = 0; i + j < n; ++j) {
                add_facet(plc, {at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j <= n - 2) add_facet(plc, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    }
}

/// Free vertices on, near and off the surface: kind % 5 is 0 inside (between the centroid of
/// the PLC's vertices and a facet point), 1 on a facet (a positive combination of its corners,
/// coordinates shared by every corner kept exactly), 2 on a facet edge, 3 off a facet point by
/// 10^-(12..300) along the facet's constant coordinate (or every coordinate), 4 off a facet
/// corner or a point on an edge by the same.
inline void decode_free_vertex(ByteReader& in, triangulation::Plc3& plc) {
    const unsigned kind = in.byte() % 5;
    const triangulation::Facet3& facet = plc.facets[in.byte() % plc.facets.size()];
    const std::vector<triangulation::VertIdx>& corners = facet.polygons.front();
    std::array<double, 3> p{};
    std::array<bool, 3> constant{true, true, true};
    for (unsigned k = 0; k < 3; ++k) {
        for (const triangulation::VertIdx v : corners)
            constant[k] = constant[k] && plc.point(v)[k] == plc.point(corners.front())[k];
    }
    const std::uint8_t w0 = in.byte(), w1 = in.byte(), w2 = in.byte();
    if (kind == 2 || (kind == 4 && w2 % 2 == 0)) {
        // On edge (w0 % n, next), at (1 + w1) / 257 along it; or (kind 4) at its first corner.
        const std::size_t i = w0 % corners.size(), j = (i + 1) % corners.size();
        const double t = kind == 2 || w2 % 4 == 0 ? (1.0 + w1) / 257.0 : 0.0;
        for (unsigned k = 0; k < 3; ++k) {
            const double a = plc.point(corners[i])[k], b = plc.point(corners[j])[k];
            p[k] = a == b ? a : a + t * (b - a);
            constant[k] = constant[k] || a == b;
        }
    } else {
        const std::array<double, 3> weights{1.0 + w0, 1.0 + w1, 1.0 + w2};
        double total = 0;
        for (std::size_t i = 0; i < corners.size(); ++i) {
            const double w = weights[i % 3];
            total += w;
            for (unsigned k = 0; k < 3; ++k) p[k] += w * plc.point(corners[i])[k];
        }
        for (unsigned k = 0; k < 3; ++k)
            p[k] = constant[k] ? plc.point(corners.front())[k] : p[k] / total;
    }
    const std::uint8_t exponent = in.byte(), signs = in.byte();
    if (kind == 0) {
        std::array<double, 3> centroid{};
        for (std::uint32_t v = 0; v < plc.vertex_count(); ++v)
            for (unsigned k = 0; k < 3; ++k) centroid[k] += plc.point(v)[k] / plc.vertex_count();
        const double t = (1.0 + exponent) / 257.0;
        for (unsigned k = 0; k < 3; ++k) p[k] = centroid[k] + t * (p[k] - centroid[k]);
    } else if (kind >= 3) {
        const double offset = std::pow(10.0, -(12 + exponent * 288 / 255));
        const bool along_constant = constant[0] || constant[1] || constant[2];
        for (unsigned k = 0; k < 3; ++k) {
            if (along_constant && !constant[k]) continue;
            p[k] += (signs >> k) & 1 ? offset : -offset;
        }
    }
    add_vertex(plc, p[0], p[1], p[2]);
}

inline void scale(triangulation::Plc3& plc, int exponent) {
    for (double& x : plc.xyz) x = std::ldexp(x, exponent);
    for (double& x : plc.holes) x = std::ldexp(x, exponent);
}

/// The first problem of `mesh` for `plc` at `stage`, or empty.
inline std::string check_mesh(const triangulation::Plc3& plc, const std::vector<double>& input_xyz,
                              const triangulation::ConformingMesh3& mesh, const char* stage) {
    const std::string where = std::string(stage) + ": ";
    const triangulation::BoundaryConformityReport3 report =
        triangulation::check_boundary_conformity_3d(plc, mesh);
    if (!report.ok) return where + "check_boundary_conformity_3d: " + report.problem;
    if (mesh.input_vertex_count != plc.vertex_count())
        return where + "input_vertex_count " + std::to_string(mesh.input_vertex_count) + " for " +
               std::to_string(plc.vertex_count()) + " PLC vertices";
    if (mesh.mesh.xyz.size() < input_xyz.size()) return where + "input vertices were dropped";
    for (std::size_t i = 0; i < input_xyz.size(); ++i) {
        if (!(mesh.mesh.xyz[i] == input_xyz[i])) {
            char text[160];
            std::snprintf(text, sizeof text, "input vertex %zu moved: coordinate %zu is %a, was %a",
                          i / 3, i % 3, mesh.mesh.xyz[i], input_xyz[i]);
            return where + text;
        }
    }
    return {};
}

}  // namespace tetmesh_detail

/// The case in data (every byte string decodes to one).
inline TetmeshCase decode_tetmesh_case(const std::uint8_t* data, std::size_t size) {
    tetmesh_detail::ByteReader in(data, size);
    TetmeshCase c;
    c.form = static_cast<TetmeshForm>(in.byte() % static_cast<unsigned>(TetmeshForm::Count));
    c.generator =
        static_cast<TetmeshGenerator>(in.byte() % static_cast<unsigned>(TetmeshGenerator::Count));
    const std::uint8_t parameter = in.byte();
    const unsigned low = in.byte(), high = in.byte();
    c.scale_exponent = static_cast<int>((low | (high << 8)) % 1201) - 600;
    switch (c.form) {
        case TetmeshForm::Box:
            tetmesh_detail::decode_box(in, c.plc);
            break;
        case TetmeshForm::Prism:
            tetmesh_detail::decode_prism(in, c.plc);
            break;
        case TetmeshForm::BoxWithHole:
            tetmesh_detail::decode_box_with_hole(in, c.plc);
            break;
        case TetmeshForm::TouchingBoxes:
            tetmesh_detail::decode_touching_boxes(in, c.plc);
            break;
        default:
            tetmesh_detail::decode_star(in, c.plc);
            break;
    }
    // The size from the surface's box before the free vertices (which may lie outside it).
    std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (std::uint32_t v = 0; v < c.plc.vertex_count(); ++v) {
        for (unsigned k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], c.plc.point(v)[k]);
            hi[k] = std::max(hi[k], c.plc.point(v)[k]);
        }
    }
    const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    c.free_vertices = in.byte() % 7;
    for (std::uint32_t i = 0; i < c.free_vertices; ++i)
        tetmesh_detail::decode_free_vertex(in, c.plc);
    c.radius_edge_bound = 1.0 + 2.0 * parameter / 255.0;
    c.size = std::ldexp(extent / (1 + parameter % 4), c.scale_exponent);
    tetmesh_detail::scale(c.plc, c.scale_exponent);
    return c;
}

/// A description of the case that reproduces it: the form, the generator and its parameter,
/// the scale, every vertex (%a) and facet.
inline std::string describe_tetmesh_case(const TetmeshCase& c) {
    std::string out = "form ";
    out += tetmesh_form_name(c.form);
    out += ", generator ";
    out += tetmesh_generator_name(c.generator);
    char text[200];
    if (c.generator == TetmeshGenerator::Refinement)
        std::snprintf(text, sizeof text, ", radius-edge bound %.17g", c.radius_edge_bound);
    else
        std::snprintf(text, sizeof text, ", size %a", c.size);
    out += text;
    out += ", scale 2^" + std::to_string(c.scale_exponent) + ", " +
           std::to_string(c.free_vertices) + " free vertices (the last ones)\nvertices (" +
           std::to_string(c.plc.vertex_count()) + "):\n";
    for (std::uint32_t v = 0; v < c.plc.vertex_count(); ++v) {
        const double* p = c.plc.point(v);
        std::snprintf(text, sizeof text, "  %u: %a %a %a  (%.17g %.17g %.17g)\n", v, p[0], p[1],
                      p[2], p[0], p[1], p[2]);
        out += text;
    }
    out += "facets (" + std::to_string(c.plc.facets.size()) + "):";
    for (const triangulation::Facet3& facet : c.plc.facets) {
        out += " [";
        for (std::size_t i = 0; i < facet.polygons.front().size(); ++i) {
            if (i != 0) out += ' ';
            out += std::to_string(facet.polygons.front()[i]);
        }
        out += "]";
    }
    out += "\n";
    for (std::size_t i = 0; i + 2 < c.plc.holes.size(); i += 3) {
        std::snprintf(text, sizeof text, "hole point: %a %a %a\n", c.plc.holes[i],
                      c.plc.holes[i + 1], c.plc.holes[i + 2]);
        out += text;
    }
    return out;
}

/// Runs the case's pipeline (see the top of this file) and checks every mesh it makes.
inline TetmeshOutcome run_tetmesh_case(const TetmeshCase& c) {
    namespace gen = exactmesh::generators;
    namespace tri = exactmesh::triangulation;
    TetmeshOutcome out;
    tri::Plc3 plc = c.plc;
    const std::vector<double> input_xyz = plc.xyz;
    try {
        out.stage = "validate_plc_3d_input";
        tri::validate_plc_3d_input(plc);
        out.stage = "split_nonplanar_facets_3d";
        (void)tri::split_nonplanar_facets_3d(plc);
        out.stage = "attach_free_vertices_near_surface_3d";
        (void)tri::attach_free_vertices_near_surface_3d(plc);
        out.stage = "embed_free_vertices_3d";
        tri::embed_free_vertices_3d(plc);
        if (plc.xyz != input_xyz) {
            out.failure = "embed_free_vertices_3d changed the coordinates";
            return out;
        }
        out.stage = "validate_plc_3d";
        tri::SurfaceTriangles3 surface;
        try {
            surface = tri::validate_plc_3d(plc);
        } catch (const InputError& e) {
            // Embedded, no free vertex is left on the surface (as fuzz_plc_3d checks).
            if (std::string(e.what()).find("in no facet polygon") != std::string::npos) {
                out.failure = "a free vertex was left on the surface: ";
                out.failure += e.what();
                return out;
            }
            throw;
        }
        out.stage = "check_surface_closed_3d";
        tri::check_surface_closed_3d(plc, surface);

        out.stage = "boundary_recovery_3d";
        tri::BoundaryRecovery3Options recovery_options;
        recovery_options.max_steiner_points = kTetmeshRecoverySteiner;
        std::vector<std::string> recovery_warnings;
        tri::BoundaryRecovery3Result recovered =
            tri::boundary_recovery_3d_whole_facets(plc, recovery_options, recovery_warnings);
        out.failure = tetmesh_detail::check_mesh(plc, input_xyz, recovered.mesh, "recovered mesh");
        if (!out.failure.empty()) return out;

        tri::ConformingMesh3 mesh;
        gen::DelaunayRefinement3Options refinement;
        refinement.radius_edge_bound = c.radius_edge_bound;
        refinement.max_steiner_points = kTetmeshGeneratorSteiner;
        std::uint64_t rejected_points = 0;
        switch (c.generator) {
            case TetmeshGenerator::Refinement: {
                out.stage = "delaunay_refinement_3d";
                gen::DelaunayRefinement3Result refined =
                    gen::delaunay_refinement_3d(plc, std::move(recovered.mesh), refinement);
                mesh = std::move(refined.mesh);
                rejected_points = refined.counters.rejected_points;
                break;
            }
            case TetmeshGenerator::Frontal: {
                out.stage = "frontal_delaunay_3d";
                gen::FrontalDelaunay3Options options;
                options.size = gen::SizeFunction3::uniform(c.size);
                options.max_steiner_points = kTetmeshGeneratorSteiner;
                mesh = gen::frontal_delaunay_3d(plc, std::move(recovered.mesh), options).mesh;
                break;
            }
            default: {
                out.stage = "octree_mesh_3d";
                gen::OctreeMesh3Options options;
                options.size = gen::SizeFunction3::uniform(c.size);
                options.max_leaves = kTetmeshOctreeLeaves;
                options.max_steiner_points = kTetmeshGeneratorSteiner;
                mesh = gen::octree_mesh_3d(plc, recovered.mesh, options).mesh;
                break;
            }
        }
        // The command's rule (cli/tetmesh_command.cpp): after refinement a tetrahedron over the
        // bound is a bug unless refinement rejected splitting points.
        auto refinement_problem = [&](const char* stage) -> std::string {
            if (c.generator != TetmeshGenerator::Refinement) return {};
            const gen::RefinementQuality3 quality =
                gen::check_refinement_quality_3d(mesh, refinement);
            if (quality.over_bound + quality.over_volume == 0 || rejected_points != 0) return {};
            return std::string(stage) + ": " + std::to_string(quality.over_bound) +
                   " tetrahedra over the radius-edge bound with no rejected point";
        };
        out.failure = tetmesh_detail::check_mesh(plc, input_xyz, mesh, out.stage.c_str());
        if (out.failure.empty()) out.failure = refinement_problem(out.stage.c_str());
        if (!out.failure.empty()) return out;

        out.stage = "sliver_removal_3d";
        gen::SliverRemoval3Options slivers;
        // The command's bound for sliver removal: B after refinement, else its default 2.
        if (c.generator == TetmeshGenerator::Refinement)
            slivers.radius_edge_bound = refinement.radius_edge_bound;
        mesh = gen::sliver_removal_3d(std::move(mesh), slivers).mesh;
        out.failure = tetmesh_detail::check_mesh(plc, input_xyz, mesh, "sliver_removal_3d");
        if (out.failure.empty()) out.failure = refinement_problem("sliver_removal_3d");
        if (!out.failure.empty()) return out;
        out.meshed = true;
    } catch (const InternalError& e) {
        out.failure = out.stage + " threw InternalError: " + e.what();
    } catch (const InputError& e) {
        out.error = e.what();
    } catch (const GeometryError& e) {
        out.error = e.what();
    } catch (const std::exception& e) {
        out.failure = out.stage + " threw: " + e.what();
    }
    return out;
}

}  // namespace exactmesh::fuzz
