// SPDX-License-Identifier: MIT
// The small-input-angle rule of 3D Delaunay refinement (see small_angle_rule_3d.hpp).
#include "generators/mesh_3d/small_angle_rule_3d.hpp"

#include "predicates/tet_quality_3d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using predicates::Sign;

namespace {
constexpr unsigned kTetEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
}  // namespace

SmallInputAngleRule3::SmallInputAngleRule3(const tri::ConformingMesh3& mesh,
                                           const std::vector<double>& xyz)
    : mesh_(mesh), xyz_(xyz) {
    at_input_.resize(mesh.input_vertex_count);
    for (std::uint32_t s = 0; 2 * s + 1 < mesh.segments.size(); ++s) {
        at_input_[mesh.segments[2 * s]].push_back(s);
        at_input_[mesh.segments[2 * s + 1]].push_back(s);
    }
}

std::vector<std::uint32_t> SmallInputAngleRule3::segments_of(tri::VertIdx v) const {
    if (v < mesh_.input_vertex_count) return at_input_[v];
    if (mesh_.vertex_feature[v] == tri::VertexFeature3::Segment) return {mesh_.feature_index[v]};
    return {};
}

bool SmallInputAngleRule3::small_angle_pair(tri::VertIdx u, tri::VertIdx w) const {
    if (u < mesh_.input_vertex_count && w < mesh_.input_vertex_count) return false;
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
                if (predicates::compare_angle_60_3d(point(apex), point(far1), point(far2)) ==
                    Sign::Positive)
                    return true;
            }
        }
    }
    return false;
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
