// SPDX-License-Identifier: MIT
// The small-input-angle rule of 3D Delaunay refinement (see small_angle_rule_3d.hpp).
#include "generators/mesh_3d/small_angle_rule_3d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <utility>

#include "generators/mesh_3d/scaled_differences_3d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using predicates::Sign;

namespace {
constexpr unsigned kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// Lattice tetrahedra whose dihedral angle at edge (0, 1) is exactly 60 and 90 degrees: the
// normals e x u of the first, (-3, 3, 0) and (0, 3, -3), have cosine 9 / 18 = 1/2.
constexpr double kRef60[4][3] = {{0, 0, 0}, {1, 1, 1}, {1, 1, -2}, {2, -1, -1}};
constexpr double kRef90[4][3] = {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}};

/// Sign of angle - reference, the angle between the half-planes bounded by line a b through c
/// and through d (c, d off the line; the tetrahedron may be flat: the terms stay defined).
Sign compare_half_planes(const double* a, const double* b, const double* c, const double* d,
                         const double (&reference)[4][3]) {
    const predicates::Dihedral angle{{a, b, c, d}, 0, 1};
    const predicates::Dihedral bound{
        {reference[0], reference[1], reference[2], reference[3]}, 0, 1};
    return predicates::compare_dihedral(angle, bound);
}

std::uint64_t pair_key(std::uint32_t f, std::uint32_t g) {
    if (f > g) std::swap(f, g);
    return (std::uint64_t{f} << 32) | g;
}

/// The squared distance of c from line ab over |ab|^2, in doubles on scaled differences (the
/// same at 2^+-600): a choice between candidates, never a decision.
double scaled_distance_to_line(const double* a, const double* b, const double* c) {
    const double* const p[3] = {a, b, c};
    std::array<double, 3> d[2];
    if (scaled_differences(p, 3, d) == kCoincident) return 0;
    const auto& u = d[0];
    const auto& v = d[1];
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2],
                 z = u[0] * v[1] - u[1] * v[0];
    const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    return uu > 0 ? (x * x + y * y + z * z) / uu : 0;
}

void sort_unique(std::vector<std::uint32_t>& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
}
}  // namespace

SharpFacets3::SharpFacets3(const tri::ConformingMesh3& mesh, const std::vector<double>& xyz) {
    const auto point = [&](tri::VertIdx v) { return xyz.data() + 3 * std::size_t{v}; };
    const std::uint32_t segment_count = static_cast<std::uint32_t>(mesh.segments.size() / 2);
    const tri::VertIdx inputs = mesh.input_vertex_count;
    segment_facets_.resize(segment_count);
    sharp_at_.resize(segment_count);
    input_facets_.resize(inputs);
    std::unordered_map<std::uint64_t, std::uint32_t> segment_by_ends;
    for (std::uint32_t s = 0; s < segment_count; ++s)
        segment_by_ends.emplace(pair_key(mesh.segments[2 * s], mesh.segments[2 * s + 1]), s);
    std::vector<std::vector<tri::VertIdx>> facet_inputs;
    for (std::size_t i = 0; 3 * i + 2 < mesh.subfaces.size(); ++i) {
        const std::uint32_t f = mesh.subface_facet[i];
        if (f >= facet_inputs.size()) facet_inputs.resize(std::size_t{f} + 1);
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx v = mesh.subfaces[3 * i + k];
            if (v >= inputs) continue;
            input_facets_[v].push_back(f);
            facet_inputs[f].push_back(v);
        }
    }
    for (auto& facets : input_facets_) sort_unique(facets);
    for (auto& vertices : facet_inputs) sort_unique(vertices);
    const auto on_segment = [&](tri::VertIdx x, std::uint32_t s) {
        if (x == mesh.segments[2 * s] || x == mesh.segments[2 * s + 1]) return true;
        return x >= inputs && mesh.vertex_feature[x] == tri::VertexFeature3::Segment &&
               mesh.feature_index[x] == s;
    };
    const auto segment_of_edge = [&](tri::VertIdx x, tri::VertIdx y) -> std::uint32_t {
        for (const tri::VertIdx v : {x, y}) {
            if (v >= inputs && mesh.vertex_feature[v] == tri::VertexFeature3::Segment) {
                const std::uint32_t s = mesh.feature_index[v];
                return on_segment(x, s) && on_segment(y, s) ? s : tri::kNone;
            }
        }
        if (x >= inputs || y >= inputs) return tri::kNone;
        const auto found = segment_by_ends.find(pair_key(x, y));
        return found == segment_by_ends.end() ? tri::kNone : found->second;
    };
    // Per (segment, facet): an input vertex of the facet on each side of the segment's line
    // the facet occupies next to it (one side, both for a segment inside the facet).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<tri::VertIdx>> sides;
    for (std::size_t i = 0; 3 * i + 2 < mesh.subfaces.size(); ++i) {
        const std::uint32_t f = mesh.subface_facet[i];
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx x = mesh.subfaces[3 * i + k];
            const tri::VertIdx y = mesh.subfaces[3 * i + (k + 1) % 3];
            const tri::VertIdx z = mesh.subfaces[3 * i + (k + 2) % 3];
            const std::uint32_t s = segment_of_edge(x, y);
            if (s == tri::kNone) continue;
            const double* a = point(mesh.segments[2 * s]);
            const double* b = point(mesh.segments[2 * s + 1]);
            auto& found = sides[{s, f}];
            const auto same_side = [&](tri::VertIdx c) {
                return compare_half_planes(a, b, point(c), point(z), kRef90) == Sign::Negative;
            };
            if (std::any_of(found.begin(), found.end(), same_side)) continue;
            // The input vertex of the facet on that side farthest from the segment's line (a
            // choice in doubles; the decisions are exact): a vertex within rounding of the line
            // (a free vertex attached to the segment's neighbour on the same cube edge, an ulp
            // off it) would give a half-plane rounding turns anywhere.
            tri::VertIdx best = tri::kNone;
            double best_distance = -1;
            for (const tri::VertIdx c : facet_inputs[f]) {
                if (tri::collinear_3d(a, b, point(c)) || !same_side(c)) continue;
                const double distance = scaled_distance_to_line(a, b, point(c));
                if (distance > best_distance) {
                    best_distance = distance;
                    best = c;
                }
            }
            if (best != tri::kNone) found.push_back(best);
        }
    }
    for (const auto& [key, reps] : sides) segment_facets_[key.first].push_back(key.second);
    for (std::uint32_t s = 0; s < segment_count; ++s) {
        const auto& facets = segment_facets_[s];
        const double* a = point(mesh.segments[2 * s]);
        const double* b = point(mesh.segments[2 * s + 1]);
        for (std::size_t i = 0; i < facets.size(); ++i) {
            for (std::size_t j = i + 1; j < facets.size(); ++j) {
                bool below = false;
                for (const tri::VertIdx c : sides.at({s, facets[i]})) {
                    for (const tri::VertIdx d : sides.at({s, facets[j]})) {
                        below = below || compare_half_planes(a, b, point(c), point(d), kRef60) ==
                                             Sign::Negative;
                    }
                }
                if (!below) continue;
                pairs_.push_back(pair_key(facets[i], facets[j]));
                sharp_at_[s].push_back(facets[i]);
                sharp_at_[s].push_back(facets[j]);
            }
        }
    }
    add_segments_near_facets(mesh, xyz);
    for (auto& facets : sharp_at_) sort_unique(facets);
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
}

void SharpFacets3::add_segments_near_facets(const tri::ConformingMesh3& mesh,
                                            const std::vector<double>& xyz) {
    const auto point = [&](tri::VertIdx v) { return xyz.data() + 3 * std::size_t{v}; };
    const tri::VertIdx inputs = mesh.input_vertex_count;
    const std::uint32_t segment_count = static_cast<std::uint32_t>(mesh.segments.size() / 2);
    // The subfaces at each input vertex (their facet's sector there).
    std::vector<std::vector<std::size_t>> subfaces_at(inputs);
    for (std::size_t i = 0; 3 * i + 2 < mesh.subfaces.size(); ++i)
        for (unsigned k = 0; k < 3; ++k)
            if (mesh.subfaces[3 * i + k] < inputs)
                subfaces_at[mesh.subfaces[3 * i + k]].push_back(i);
    // sin^2 of kSegmentFacetDegrees.
    const double sine = std::sin(kSegmentFacetDegrees * 3.14159265358979323846 / 180);
    const double sine2 = sine * sine;
    for (std::uint32_t s = 0; s < segment_count; ++s) {
        const auto& own = segment_facets_[s];
        for (unsigned end = 0; end < 2; ++end) {
            const tri::VertIdx apex = mesh.segments[2 * s + end];
            const tri::VertIdx other = mesh.segments[2 * s + 1 - end];
            if (apex >= inputs) continue;
            for (const std::size_t i : subfaces_at[apex]) {
                const std::uint32_t f = mesh.subface_facet[i];
                if (std::find(own.begin(), own.end(), f) != own.end()) continue;
                unsigned at = 0;
                while (mesh.subfaces[3 * i + at] != apex) ++at;
                const double* const p[4] = {point(apex), point(mesh.subfaces[3 * i + (at + 1) % 3]),
                                            point(mesh.subfaces[3 * i + (at + 2) % 3]),
                                            point(other)};
                std::array<double, 3> d[3];
                if (scaled_differences(p, 4, d) == kCoincident) continue;
                using vec3::cross;
                using vec3::dot;
                const std::array<double, 3> n = cross(d[0], d[1]);
                // The segment's direction over the subface's sector (seen along n), at less
                // than the angle from its plane. (Beside the sector, within the angle of one of
                // its sides, is not counted: that is a segment at a small angle to the side,
                // whose encroachment narrow_angle_pair already spares, and counting it changed
                // the wing's trailing edge, sparing more tetrahedra there.)
                // Open sectors: a direction on a side (a segment beside the facet's edge, seen
                // from above: the wing's trailing edge) is left to narrow_angle_pair. A direction
                // exactly on a ray to a Steiner point refinement put at the apex would count
                // before refinement and not after; no such input is known.
                if (!(dot(cross(d[0], d[2]), n) > 0 && dot(cross(d[2], d[1]), n) > 0)) continue;
                const double along = dot(d[2], n);
                if (!(along * along < sine2 * dot(d[2], d[2]) * dot(n, n))) continue;
                sharp_at_[s].push_back(f);
                for (const std::uint32_t g : own) pairs_.push_back(pair_key(f, g));
            }
        }
    }
}

bool SharpFacets3::sharp(std::uint32_t f, std::uint32_t g) const {
    return f != g && std::binary_search(pairs_.begin(), pairs_.end(), pair_key(f, g));
}

std::span<const std::uint32_t> SharpFacets3::facets_of(const tri::ConformingMesh3& mesh,
                                                       tri::VertIdx v) const {
    if (v < mesh.input_vertex_count) return input_facets_[v];
    switch (mesh.vertex_feature[v]) {
        case tri::VertexFeature3::Segment:
            return segment_facets_[mesh.feature_index[v]];
        case tri::VertexFeature3::Facet:
            return {&mesh.feature_index[v], 1};
        default:
            return {};
    }
}

bool SharpFacets3::shields_subface(const tri::ConformingMesh3& mesh, tri::VertIdx v,
                                   std::uint32_t facet) const {
    if (pairs_.empty()) return false;
    bool partner = false;
    for (const std::uint32_t g : facets_of(mesh, v)) {
        if (g == facet) return false;
        partner = partner || sharp(facet, g);
    }
    return partner;
}

bool SharpFacets3::shields_segment(std::uint32_t s, std::uint32_t facet) const {
    return !pairs_.empty() && std::binary_search(sharp_at_[s].begin(), sharp_at_[s].end(), facet);
}

bool SharpFacets3::shields_segment(const tri::ConformingMesh3& mesh, tri::VertIdx v,
                                   std::uint32_t s) const {
    if (pairs_.empty()) return false;
    for (const std::uint32_t g : facets_of(mesh, v))
        if (shields_segment(s, g)) return true;
    return false;
}

bool SharpFacets3::sharp_pair(const tri::ConformingMesh3& mesh, tri::VertIdx u,
                              tri::VertIdx w) const {
    if (pairs_.empty()) return false;
    for (const std::uint32_t f : facets_of(mesh, u))
        for (const std::uint32_t g : facets_of(mesh, w))
            if (sharp(f, g)) return true;
    return false;
}

SmallInputAngleRule3::SmallInputAngleRule3(const tri::ConformingMesh3& mesh,
                                           const std::vector<double>& xyz)
    : SmallInputAngleRule3(mesh, xyz, SharpFacets3(mesh, xyz)) {}

SmallInputAngleRule3::SmallInputAngleRule3(const tri::ConformingMesh3& mesh,
                                           const std::vector<double>& xyz, SharpFacets3 sharp)
    : mesh_(mesh), xyz_(xyz), sharp_(std::move(sharp)) {
    at_input_.resize(mesh.input_vertex_count);
    for (std::uint32_t s = 0; 2 * s + 1 < mesh.segments.size(); ++s) {
        at_input_[mesh.segments[2 * s]].push_back(s);
        at_input_[mesh.segments[2 * s + 1]].push_back(s);
    }
}

std::span<const std::uint32_t> SmallInputAngleRule3::segments_of(tri::VertIdx v) const {
    if (v < mesh_.input_vertex_count) return at_input_[v];
    if (mesh_.vertex_feature[v] == tri::VertexFeature3::Segment)
        return {&mesh_.feature_index[v], 1};  // no copy: this is asked per bad tetrahedron
    return {};
}

template <class AngleTest>
bool SmallInputAngleRule3::meet_at_apex(tri::VertIdx u, tri::VertIdx w, AngleTest&& below) const {
    for (const std::uint32_t s1 : segments_of(u)) {
        for (const std::uint32_t s2 : segments_of(w)) {
            if (s1 == s2) continue;
            for (unsigned i = 0; i < 2; ++i) {
                const tri::VertIdx apex = mesh_.segments[2 * s1 + i];
                const tri::VertIdx far1 = mesh_.segments[2 * s1 + 1 - i];
                tri::VertIdx far2 = tri::kNone;
                if (mesh_.segments[2 * s2] == apex) far2 = mesh_.segments[2 * s2 + 1];
                if (mesh_.segments[2 * s2 + 1] == apex) far2 = mesh_.segments[2 * s2];
                if (far2 == tri::kNone || apex == u || apex == w) continue;
                if (below(point(apex), point(far1), point(far2))) return true;
            }
        }
    }
    return false;
}

bool SmallInputAngleRule3::small_angle_pair(tri::VertIdx u, tri::VertIdx w) const {
    if (u < mesh_.input_vertex_count && w < mesh_.input_vertex_count) return false;
    if (sharp_.sharp_pair(mesh_, u, w)) return true;
    return meet_at_apex(u, w, [](const double* o, const double* a, const double* b) {
        return predicates::compare_angle_60_3d(o, a, b) == Sign::Positive;
    });
}

bool SmallInputAngleRule3::narrow_angle_pair(tri::VertIdx u, tri::VertIdx w) const {
    if (u < mesh_.input_vertex_count && w < mesh_.input_vertex_count) return false;
    return meet_at_apex(u, w, [](const double* o, const double* a, const double* b) {
        const double* const p[3] = {o, a, b};
        std::array<double, 3> d[2];
        if (scaled_differences(p, 3, d) == kCoincident) return false;
        const auto& v = d[0];
        const auto& x = d[1];
        const double dot = v[0] * x[0] + v[1] * x[1] + v[2] * x[2];
        const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        const double xx = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        return dot > 0 && 4 * dot * dot > 3 * vv * xx;  // cos^2 > 3/4: below 30 degrees
    });
}

bool SmallInputAngleRule3::spares(const std::array<tri::VertIdx, 4>& p) const {
    return spares(p, {point(p[0]), point(p[1]), point(p[2]), point(p[3])});
}

bool SmallInputAngleRule3::spares(const std::array<tri::VertIdx, 4>& p,
                                  const std::array<const double*, 4>& at) const {
    const auto length_sign = [&](unsigned e, unsigned f) {
        return predicates::compare_lengths_3d(at[kTetEdges[e][0]], at[kTetEdges[e][1]],
                                              at[kTetEdges[f][0]], at[kTetEdges[f][1]]);
    };
    unsigned shortest = 0;
    for (unsigned e = 1; e < 6; ++e) {
        if (length_sign(e, shortest) == Sign::Negative) shortest = e;
    }
    for (unsigned e = 0; e < 6; ++e) {
        if (e != shortest && length_sign(e, shortest) != Sign::Zero) continue;
        if (small_angle_pair(p[kTetEdges[e][0]], p[kTetEdges[e][1]])) return true;
    }
    return false;
}

}  // namespace exactmesh::generators
