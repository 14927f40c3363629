// SPDX-License-Identifier: MIT
// Reading a conforming mesh back from its files (see conforming_mesh_from_faces_3d.hpp).
#include "triangulation/recovery_3d/conforming_mesh_from_faces_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// Whether w lies on the line through a and b up to its own rounding and the rounding of the
/// test (a reading of which segment a point is on, not a decision of the check). In doubles on
/// differences scaled by a power of two: a point rounded once from the line is within
/// 0.87 ulp(|w|) <= 2^-52 |w|_max sqrt 3 of it; the computed distance errs by a few units of
/// |w - a| (the differences' and the cross product's rounding). Accepted: 2^-50 |w|_max +
/// 2^-48 |w - a|_max. The former bound, 2^-46 |w|_max, took a facet point 1.03e-14 off a unit
/// cube's edge for a point of it (cube_free_vertices_1e-14_off_an_edge.poly) and could miss a
/// point near the origin on a long segment.
bool on_segment_line(const double* w, const double* a, const double* b) {
    double d[3], u[3], largest = 0, reach = 0, magnitude = 0;
    for (int k = 0; k < 3; ++k) {
        d[k] = b[k] - a[k];
        u[k] = w[k] - a[k];
        largest = std::max({largest, std::fabs(d[k]), std::fabs(u[k])});
        reach = std::max(reach, std::fabs(u[k]));
        magnitude = std::max(magnitude, std::fabs(w[k]));
    }
    if (!(largest > 0)) return true;
    const int e = std::ilogb(largest);
    for (int k = 0; k < 3; ++k) {
        d[k] = std::ldexp(d[k], -e);
        u[k] = std::ldexp(u[k], -e);
    }
    const double c[3] = {u[1] * d[2] - u[2] * d[1], u[2] * d[0] - u[0] * d[2],
                         u[0] * d[1] - u[1] * d[0]};
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double distance = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / length;
    // In units of 2^e: the bound's terms scaled alike (no underflow of the small one matters:
    // it only loosens the test by the smallest subnormal).
    const double bound = std::ldexp(magnitude, -50 - e) + std::ldexp(reach, -48 - e);
    return distance <= bound;
}

std::string face_text(const VertIdx* f) {
    std::string text = "(";
    for (unsigned k = 0; k < 3; ++k) {
        if (k > 0) text += ", ";
        text += std::to_string(f[k]);
    }
    text += ')';
    return text;
}

}  // namespace

ConformingMeshReading3 conforming_mesh_from_faces_3d(const Plc3& plc, Tetrahedralization3 mesh,
                                                     std::span<const VertIdx> faces) {
    ConformingMeshReading3 reading;
    ConformingMesh3& cm = reading.mesh;
    const std::uint32_t n = mesh.vertex_count();
    const std::uint32_t inputs = plc.vertex_count();
    cm.input_vertex_count = inputs;
    cm.vertex_feature.assign(n, VertexFeature3::Volume);
    cm.feature_index.assign(n, kNone);
    for (VertIdx v = 0; v < std::min(n, inputs); ++v) cm.vertex_feature[v] = VertexFeature3::Input;

    // Segments as boundary recovery numbers them (plc_segments_3d), the facets holding each
    // segment and each input vertex.
    PlcSegments3 segments = plc_segments_3d(plc);
    for (const auto& [a, b] : segments.ends) cm.segments.insert(cm.segments.end(), {a, b});
    const std::vector<std::vector<std::uint32_t>>& facets_of_segment = segments.facets_of_segment;
    std::vector<std::vector<std::uint32_t>> facets_of_vertex(inputs);
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        for (const auto& polygon : plc.facets[f].polygons) {
            for (const VertIdx v : polygon) {
                if (std::find(facets_of_vertex[v].begin(), facets_of_vertex[v].end(), f) ==
                    facets_of_vertex[v].end())
                    facets_of_vertex[v].push_back(f);
            }
        }
    }
    const std::size_t segment_count = cm.segments.size() / 2;

    // Steiner vertices of the faces: on a segment (within rounding) or in a facet.
    std::vector<std::uint8_t> on_face(n, 0);
    for (const VertIdx v : faces) {
        if (v >= n) {
            reading.problem = "face vertex " + std::to_string(v) + " is not a mesh vertex";
            return reading;
        }
        on_face[v] = 1;
    }
    struct Box {
        std::array<double, 3> lo, hi;
    };
    std::vector<Box> boxes(segment_count);
    for (std::size_t s = 0; s < segment_count; ++s) {
        const double* a = plc.point(cm.segments[2 * s]);
        const double* b = plc.point(cm.segments[2 * s + 1]);
        for (int k = 0; k < 3; ++k) {
            boxes[s].lo[k] = std::min(a[k], b[k]);
            boxes[s].hi[k] = std::max(a[k], b[k]);
        }
    }
    std::vector<std::vector<VertIdx>> near_segments(segment_count);
    for (VertIdx v = inputs; v < n; ++v) {
        if (on_face[v] == 0) continue;
        const double* w = mesh.point(v);
        // The rounding square's half-width is 2^-40 of w's largest coordinate: the box test
        // with 2^-39 of it keeps every candidate.
        const double slack =
            std::ldexp(std::max({std::fabs(w[0]), std::fabs(w[1]), std::fabs(w[2])}), -39) +
            0x1p-1074;
        cm.vertex_feature[v] = VertexFeature3::Facet;
        for (std::size_t s = 0; s < segment_count; ++s) {
            bool near = true;
            for (int k = 0; k < 3 && near; ++k)
                near = w[k] >= boxes[s].lo[k] - slack && w[k] <= boxes[s].hi[k] + slack;
            if (near && predicates::within_rounding_of_segment_3d(
                            w, plc.point(cm.segments[2 * s]), plc.point(cm.segments[2 * s + 1])))
                near_segments[s].push_back(v);
        }
    }
    // Each segment's chain: its ends and the vertices within rounding of it that lie on its
    // line up to their rounding (on_segment_line: rounded points of the segment), in order along
    // its largest coordinate. A facet point merely within rounding of a segment beside it
    // (refinement near a small angle puts some there, farther from the line than that) stays a
    // facet vertex.
    std::vector<std::vector<VertIdx>> chains(segment_count);
    for (std::size_t s = 0; s < segment_count; ++s) {
        const VertIdx first = cm.segments[2 * s], last = cm.segments[2 * s + 1];
        const double* pa = plc.point(first);
        const double* pb = plc.point(last);
        std::vector<VertIdx>& chain = chains[s];
        for (const VertIdx v : near_segments[s]) {
            const double* w = mesh.point(v);
            if (on_segment_line(w, pa, pb)) chain.push_back(v);
        }
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::fabs(pb[k] - pa[k]) > std::fabs(pb[axis] - pa[axis])) axis = k;
        const bool rising = pb[axis] >= pa[axis];
        std::sort(chain.begin(), chain.end(), [&](VertIdx p, VertIdx q) {
            return rising ? mesh.point(p)[axis] < mesh.point(q)[axis]
                          : mesh.point(p)[axis] > mesh.point(q)[axis];
        });
        for (const VertIdx v : chain) {
            cm.vertex_feature[v] = VertexFeature3::Segment;
            cm.feature_index[v] = static_cast<std::uint32_t>(s);
        }
        chain.insert(chain.begin(), first);
        chain.push_back(last);
    }

    // Each face's facet: candidates from its input and segment vertices, then the projections
    // of its facet vertices; faces of facet vertices only wait for a neighbour.
    const SurfaceTriangles3 triangles = triangulate_facets_3d(plc);
    std::vector<std::vector<std::uint32_t>> triangles_of(plc.facets.size());
    for (std::uint32_t t = 0; t < triangles.triangle_count(); ++t)
        triangles_of[triangles.facets[t]].push_back(t);
    std::vector<FacetPlane> planes;
    for (const Facet3& facet : plc.facets) planes.push_back(facet_plane(plc, facet));
    // A facet vertex lies within rounding of its facet's plane: the projection test alone
    // would take (1, 0.5, 0.5) for a point of the facet y = 0. In doubles, on differences
    // scaled by a power of two; a reading, not a decision the check rests on.
    // The plane of each facet from its largest input triangle (facet_largest_triangles_3d, as
    // Delaunay refinement's): the first three non-collinear corners can be within rounding of
    // collinear (a free vertex attached to an edge), where their cross product is rounding noise.
    const std::vector<std::array<VertIdx, 3>> largest_triangle =
        facet_largest_triangles_3d(plc, triangles);
    std::vector<std::array<double, 6>> plane_of(plc.facets.size());  // unit normal, a point
    for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
        const VertIdx* c = largest_triangle[f].data();
        if (c[0] == kNone) continue;
        const double* a = plc.point(c[0]);
        const double* b = plc.point(c[1]);
        const double* d = plc.point(c[2]);
        double u[3], w[3], largest = 0;
        for (int k = 0; k < 3; ++k) {
            u[k] = b[k] - a[k];
            w[k] = d[k] - a[k];
            largest = std::max({largest, std::fabs(u[k]), std::fabs(w[k])});
        }
        if (!(largest > 0)) continue;
        const int e = std::ilogb(largest);
        for (int k = 0; k < 3; ++k) {
            u[k] = std::ldexp(u[k], -e);
            w[k] = std::ldexp(w[k], -e);
        }
        const double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                               u[0] * w[1] - u[1] * w[0]};
        const double length = std::sqrt(nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2]);
        if (!(length > 0)) continue;
        plane_of[f] = {nrm[0] / length, nrm[1] / length, nrm[2] / length, a[0], a[1], a[2]};
    }
    // The distance of v from facet f's plane over the magnitude of the coordinates involved.
    const auto plane_distance = [&](std::uint32_t f, VertIdx v) {
        const auto& pl = plane_of[f];
        const double* p = mesh.point(v);
        double largest = 0;
        for (int k = 0; k < 3; ++k)
            largest = std::max(
                {largest, std::fabs(p[k]), std::fabs(pl[3 + static_cast<std::size_t>(k)])});
        const double distance =
            std::fabs(pl[0] * (p[0] - pl[3]) + pl[1] * (p[1] - pl[4]) + pl[2] * (p[2] - pl[5]));
        return largest > 0 ? distance / largest : distance;
    };
    const auto near_plane = [&](std::uint32_t f, VertIdx v) {
        return plane_distance(f, v) <= 0x1p-30;
    };
    const auto holds = [&](std::uint32_t f, VertIdx v) {
        if (!near_plane(f, v)) return false;
        for (const std::uint32_t t : triangles_of[f]) {
            const VertIdx* c = &triangles.triangles[3 * std::size_t{t}];
            if (in_projected_triangle(mesh.point(v), plc.point(c[0]), plc.point(c[1]),
                                      plc.point(c[2]), planes[f].drop))
                return true;
        }
        return false;
    };
    const std::size_t face_count = faces.size() / 3;
    std::vector<std::uint32_t> face_facet(face_count, kNone);
    std::vector<std::vector<std::uint32_t>> faces_of_vertex(n);
    for (std::size_t i = 0; i < face_count; ++i)
        for (unsigned k = 0; k < 3; ++k)
            faces_of_vertex[faces[3 * i + k]].push_back(static_cast<std::uint32_t>(i));
    // The facets that may hold face i, from its vertices whose facets are known; `known` false
    // when none is.
    const auto candidates = [&](std::size_t i, bool& known) {
        std::vector<std::uint32_t> out;
        known = false;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = faces[3 * i + k];
            std::vector<std::uint32_t> own;
            if (v < inputs) {
                own = facets_of_vertex[v];
            } else if (cm.vertex_feature[v] == VertexFeature3::Segment) {
                own = facets_of_segment[cm.feature_index[v]];
            } else if (cm.feature_index[v] != kNone) {
                own = {cm.feature_index[v]};
            } else {
                continue;
            }
            if (!known) {
                out = own;
                known = true;
            } else {
                std::vector<std::uint32_t> both;
                for (const std::uint32_t f : out)
                    if (std::find(own.begin(), own.end(), f) != own.end()) both.push_back(f);
                out = std::move(both);
            }
        }
        return out;
    };
    const auto assign = [&](std::size_t i, std::uint32_t f, std::vector<std::size_t>& queue) {
        face_facet[i] = f;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = faces[3 * i + k];
            if (v < inputs || cm.vertex_feature[v] != VertexFeature3::Facet ||
                cm.feature_index[v] != kNone)
                continue;
            cm.feature_index[v] = f;
            for (const std::uint32_t j : faces_of_vertex[v])
                if (face_facet[j] == kNone) queue.push_back(j);
        }
    };
    // The first candidate that holds the face's facet vertices (all of them when none is known).
    // Of the candidates that hold the face's facet vertices (all of them when none is known),
    // the one whose plane they lie nearest: facets meeting at a small dihedral angle both pass
    // the tolerance near their common edge.
    const auto place = [&](std::size_t i, const std::vector<std::uint32_t>& from) {
        std::uint32_t best = kNone;
        double best_distance = INFINITY;
        for (const std::uint32_t f : from) {
            bool ok = true;
            double distance = 0;
            for (unsigned k = 0; k < 3 && ok; ++k) {
                const VertIdx v = faces[3 * i + k];
                if (v >= inputs && cm.vertex_feature[v] == VertexFeature3::Facet &&
                    (cm.feature_index[v] == kNone || cm.feature_index[v] == f)) {
                    ok = holds(f, v);
                    distance = std::max(distance, plane_distance(f, v));
                } else if (v >= inputs && cm.vertex_feature[v] == VertexFeature3::Segment) {
                    // A segment vertex counts too: read within rounding of a segment, it may
                    // lie 1e-14 off it on one of the segment's facets, and a face of three such
                    // vertices (a strip along a cube's edge beside a free vertex as close to it,
                    // cube_free_vertices_1e-14_off_an_edge.poly) took the first facet.
                    distance = std::max(distance, plane_distance(f, v));
                }
            }
            if (ok && distance < best_distance) {
                best = f;
                best_distance = distance;
            }
        }
        return best;
    };
    std::vector<std::size_t> queue;
    for (std::size_t i = 0; i < face_count; ++i) queue.push_back(i);
    std::vector<std::uint32_t> all(plc.facets.size());
    for (std::uint32_t f = 0; f < all.size(); ++f) all[f] = f;
    for (int pass = 0; pass < 2; ++pass) {
        // Pass 0: faces with a known vertex, propagating; pass 1: the rest, against every facet.
        while (!queue.empty()) {
            const std::size_t i = queue.back();
            queue.pop_back();
            if (face_facet[i] != kNone) continue;
            bool known = false;
            const std::vector<std::uint32_t> from = candidates(i, known);
            if (!known && pass == 0) continue;
            const std::uint32_t f = place(i, known ? from : all);
            if (f == kNone) {
                if (known || pass == 1) {
                    reading.problem = "face " + face_text(&faces[3 * i]) + " lies on no facet";
                    return reading;
                }
                continue;
            }
            assign(i, f, queue);
        }
        for (std::size_t i = 0; i < face_count; ++i)
            if (face_facet[i] == kNone) queue.push_back(i);
    }

    // Subfaces, oriented as their facets; subsegments, each segment's vertices in order.
    for (std::size_t i = 0; i < face_count; ++i) {
        std::array<VertIdx, 3> f{faces[3 * i], faces[3 * i + 1], faces[3 * i + 2]};
        const FacetPlane& plane = planes[face_facet[i]];
        const Sign opposite = plane.flip ? Sign::Positive : Sign::Negative;
        if (projected_orient(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), plane.drop) ==
            opposite)
            std::swap(f[1], f[2]);
        cm.subfaces.insert(cm.subfaces.end(), f.begin(), f.end());
        cm.subface_facet.push_back(face_facet[i]);
    }
    for (std::size_t s = 0; s < segment_count; ++s) {
        for (std::size_t k = 0; k + 1 < chains[s].size(); ++k) {
            cm.subsegments.insert(cm.subsegments.end(), {chains[s][k], chains[s][k + 1]});
            cm.subsegment_segment.push_back(static_cast<std::uint32_t>(s));
        }
    }
    // Facet vertices that no face placed, and Steiner vertices on no face, stay as read: a
    // facet vertex without a facet is reported.
    for (VertIdx v = inputs; v < n; ++v) {
        if (cm.vertex_feature[v] == VertexFeature3::Facet && cm.feature_index[v] == kNone) {
            reading.problem = "vertex " + std::to_string(v) + " lies on no facet";
            return reading;
        }
    }
    cm.mesh = std::move(mesh);
    return reading;
}

}  // namespace exactmesh::triangulation
