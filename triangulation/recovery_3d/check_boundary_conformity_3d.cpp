// SPDX-License-Identifier: MIT
// Exact check of a conforming tetrahedralization of a PLC (see check_boundary_conformity_3d.hpp).
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <unordered_set>
#include <vector>

#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::triangulation {

using predicates::Sign;

namespace {

using Face = std::array<VertIdx, 3>;

Face sorted3(VertIdx a, VertIdx b, VertIdx c) {
    if (a > b) std::swap(a, b);
    if (b > c) std::swap(b, c);
    if (a > b) std::swap(a, b);
    return {a, b, c};
}

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

/// Lexicographic order of three words, as std::array's operator< but by integer comparisons
/// (std::array's goes through memcmp, which made the searches below cost twice as much).
struct Less3 {
    bool operator()(const std::array<std::uint32_t, 3>& a,
                    const std::array<std::uint32_t, 3>& b) const noexcept {
        if (a[0] != b[0]) return a[0] < b[0];
        if (a[1] != b[1]) return a[1] < b[1];
        return a[2] < b[2];
    }
};

std::string name(VertIdx v) {
    return std::to_string(v);
}

/// The tetrahedra at each vertex of a tetrahedron list, as one array sliced per vertex.
class VertexTets {
  public:
    VertexTets(const std::vector<VertIdx>& tets, std::uint32_t vertex_count)
        : begin_(std::size_t{vertex_count} + 1, 0), tets_(tets.size()) {
        for (const VertIdx v : tets) ++begin_[std::size_t{v} + 1];
        for (std::size_t v = 1; v < begin_.size(); ++v) begin_[v] += begin_[v - 1];
        std::vector<std::uint32_t> cursor(begin_.begin(), begin_.end() - 1);
        for (std::size_t i = 0; i < tets.size(); ++i)
            tets_[cursor[tets[i]]++] = static_cast<TetIdx>(i / 4);
    }
    std::span<const TetIdx> at(VertIdx v) const {
        return {tets_.data() + begin_[v], tets_.data() + begin_[std::size_t{v} + 1]};
    }

  private:
    std::vector<std::uint32_t> begin_;
    std::vector<TetIdx> tets_;
};

std::string check(const Plc3& plc, const ConformingMesh3& cm) {
    const Tetrahedralization3& mesh = cm.mesh;
    const TopologyReport3 topology = check_topology_3d(mesh);
    if (!topology.ok) return "topology: " + topology.problem;
    const std::uint32_t n = mesh.vertex_count();
    if (cm.input_vertex_count != plc.vertex_count() || cm.vertex_feature.size() != n ||
        cm.feature_index.size() != n)
        return "vertex features: sizes do not match the mesh";
    for (std::size_t i = 0; i < plc.xyz.size(); ++i)
        if (mesh.xyz[i] != plc.xyz[i]) return "input vertex " + name(VertIdx(i / 3)) + " moved";

    // The tetrahedra at each vertex (a counting sort): a face or edge of the mesh is one of a
    // tetrahedron at its first vertex. (A map of every face and a hash set of every edge were
    // a third of this check's instructions.)
    const VertexTets stars(mesh.tets, n);
    const auto is_edge = [&](VertIdx a, VertIdx b) {
        if (a >= n || b >= n || a == b) return false;
        for (const TetIdx t : stars.at(a))
            for (unsigned k = 0; k < 4; ++k)
                if (mesh.tets[4 * std::size_t{t} + k] == b) return true;
        return false;
    };
    const auto is_face = [&](VertIdx a, VertIdx b, VertIdx c) {
        if (a >= n || b >= n || c >= n || a == b || b == c || a == c) return false;
        for (const TetIdx t : stars.at(a)) {
            bool has_b = false, has_c = false;
            for (unsigned k = 0; k < 4; ++k) {
                has_b = has_b || mesh.tets[4 * std::size_t{t} + k] == b;
                has_c = has_c || mesh.tets[4 * std::size_t{t} + k] == c;
            }
            if (has_b && has_c) return true;
        }
        return false;
    };
    std::vector<bool> used(n, false);
    for (const VertIdx v : mesh.tets) used[v] = true;
    for (const Facet3& facet : plc.facets)
        for (const auto& polygon : facet.polygons)
            for (const VertIdx v : polygon)
                if (!used[v]) return "facet corner " + name(v) + " is not a mesh vertex";

    // Subsegments: edges, chained along their segment.
    const std::size_t segment_count = cm.segments.size() / 2;
    std::vector<std::vector<std::array<VertIdx, 2>>> chains(segment_count);
    for (std::size_t i = 0; i < cm.subsegment_segment.size(); ++i) {
        const VertIdx a = cm.subsegments[2 * i], b = cm.subsegments[2 * i + 1];
        if (!is_edge(a, b))
            return "subsegment (" + name(a) + ", " + name(b) + ") is not a mesh edge";
        const std::uint32_t s = cm.subsegment_segment[i];
        if (s >= segment_count) return "subsegment with an unknown segment";
        chains[s].push_back({a, b});
    }
    for (std::size_t s = 0; s < segment_count; ++s) {
        // A path from the first end to the second through every piece once: every inner
        // vertex in exactly two pieces, the ends in one.
        std::map<VertIdx, int> degree;
        for (const auto& piece : chains[s]) {
            ++degree[piece[0]];
            ++degree[piece[1]];
        }
        const VertIdx s0 = cm.segments[2 * s], s1 = cm.segments[2 * s + 1];
        for (const auto& [v, d] : degree) {
            const bool end = v == s0 || v == s1;
            if (d != (end ? 1 : 2))
                return "segment " + std::to_string(s) +
                       ": its subsegments do not form a chain at " + name(v);
            if (!end &&
                (cm.vertex_feature[v] != VertexFeature3::Segment || cm.feature_index[v] != s))
                return "vertex " + name(v) + " inside segment " + std::to_string(s) +
                       "'s chain is not recorded on it";
        }
        if (degree.count(s0) == 0 || degree.count(s1) == 0)
            return "segment " + std::to_string(s) + " is not covered by subsegments";
    }

    // Steiner vertices within rounding of their features.
    const SurfaceTriangles3 input_triangles = triangulate_facets_3d(plc);
    std::vector<FacetPlane> planes;
    for (const Facet3& facet : plc.facets) planes.push_back(facet_plane(plc, facet));
    for (VertIdx v = cm.input_vertex_count; v < n; ++v) {
        const std::uint32_t index = cm.feature_index[v];
        if (cm.vertex_feature[v] == VertexFeature3::Segment) {
            if (index >= segment_count) return "vertex " + name(v) + ": unknown segment";
            if (!predicates::within_rounding_of_segment_3d(mesh.point(v),
                                                           mesh.point(cm.segments[2 * index]),
                                                           mesh.point(cm.segments[2 * index + 1])))
                return "segment vertex " + name(v) + " is not within rounding of its segment";
        } else if (cm.vertex_feature[v] == VertexFeature3::Facet) {
            if (index >= plc.facets.size()) return "vertex " + name(v) + ": unknown facet";
            const int drop = planes[index].drop;
            const VertIdx* holder = nullptr;
            for (std::uint32_t t = 0; t < input_triangles.triangle_count() && !holder; ++t) {
                if (input_triangles.facets[t] != index) continue;
                const VertIdx* tri = &input_triangles.triangles[3 * std::size_t{t}];
                if (in_projected_triangle(mesh.point(v), plc.point(tri[0]), plc.point(tri[1]),
                                          plc.point(tri[2]), drop))
                    holder = tri;
            }
            if (holder == nullptr)
                return "facet vertex " + name(v) + "'s projection lies outside facet " +
                       std::to_string(index);
            if (beyond_rounding_of_plane(mesh.point(v), plc.point(holder[0]), plc.point(holder[1]),
                                         plc.point(holder[2])))
                return "facet vertex " + name(v) + " lies off facet " + std::to_string(index) +
                       "'s plane beyond rounding";
        } else if (cm.vertex_feature[v] != VertexFeature3::Volume) {
            return "vertex " + name(v) + " beyond the input has no feature";
        }
    }

    // Subfaces: faces of the mesh, oriented like their facet, paired along inner edges.
    std::vector<Face> subface_keys;
    // Directed subface edges as (facet, from, to), sorted below: the order of a map per facet.
    std::vector<std::array<std::uint32_t, 3>> directed;
    std::unordered_set<std::uint64_t> subsegment_edges;
    for (std::size_t i = 0; i < cm.subsegment_segment.size(); ++i)
        subsegment_edges.insert(edge_key(cm.subsegments[2 * i], cm.subsegments[2 * i + 1]));
    for (std::size_t t = 0; t < cm.subface_facet.size(); ++t) {
        const VertIdx* f = &cm.subfaces[3 * t];
        const std::uint32_t facet = cm.subface_facet[t];
        if (facet >= plc.facets.size()) return "subface with an unknown facet";
        if (!is_face(f[0], f[1], f[2]))
            return "subface (" + name(f[0]) + ", " + name(f[1]) + ", " + name(f[2]) +
                   ") of facet " + std::to_string(facet) + " is not a mesh face";
        subface_keys.push_back(sorted3(f[0], f[1], f[2]));
        const Sign expected = planes[facet].flip ? Sign::Negative : Sign::Positive;
        if (projected_orient(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]),
                             planes[facet].drop) != expected)
            return "subface (" + name(f[0]) + ", " + name(f[1]) + ", " + name(f[2]) +
                   ") is not oriented like facet " + std::to_string(facet);
        for (unsigned k = 0; k < 3; ++k) directed.push_back({facet, f[k], f[(k + 1) % 3]});
    }
    std::sort(subface_keys.begin(), subface_keys.end(), Less3{});
    std::sort(directed.begin(), directed.end(), Less3{});
    const auto has_directed = [&](std::uint32_t facet, VertIdx a, VertIdx b) {
        return std::binary_search(directed.begin(), directed.end(),
                                  std::array<std::uint32_t, 3>{facet, a, b}, Less3{});
    };
    for (std::size_t i = 0; i < directed.size();) {
        std::size_t j = i + 1;
        while (j < directed.size() && directed[j] == directed[i]) ++j;
        const auto [facet, from, to] = directed[i];
        if (j - i != 1)
            return "facet " + std::to_string(facet) + ": directed edge (" + name(from) + ", " +
                   name(to) + ") in " + std::to_string(j - i) + " subfaces";
        if (!has_directed(facet, to, from) && subsegment_edges.count(edge_key(from, to)) == 0)
            return "facet " + std::to_string(facet) + ": edge (" + name(from) + ", " + name(to) +
                   ") bounds one subface and is no subsegment";
        i = j;
    }
    // The boundary of each facet's subfaces, as a chain of directed edges, is the boundary of
    // its input triangles (triangulate_facets_3d, the same reference orientation) with every
    // input edge (p, q) replaced by its chain of subsegments walked from p to q. With every
    // subface positively oriented in the projection, the winding-number argument then makes the
    // subfaces tile the facet exactly once, up to the slivers between each segment and its
    // chain of rounded Steiner points.
    {
        std::map<std::uint64_t, std::uint32_t> segment_of;
        for (std::size_t s = 0; s < segment_count; ++s)
            segment_of[edge_key(cm.segments[2 * s], cm.segments[2 * s + 1])] =
                static_cast<std::uint32_t>(s);
        // The chain of segment s as vertices from `from` to its other end.
        auto walk = [&](std::uint32_t s, VertIdx from) {
            std::map<VertIdx, std::vector<VertIdx>> next;
            for (const auto& piece : chains[s]) {
                next[piece[0]].push_back(piece[1]);
                next[piece[1]].push_back(piece[0]);
            }
            std::vector<VertIdx> path{from};
            VertIdx previous = kNone, at = from;
            while (path.size() <= chains[s].size()) {
                const auto& options = next[at];
                VertIdx step = kNone;
                for (const VertIdx w : options)
                    if (w != previous) step = w;
                if (step == kNone) break;
                previous = at;
                at = step;
                path.push_back(at);
            }
            return path;
        };
        std::vector<std::map<std::pair<VertIdx, VertIdx>, int>> input_directed(plc.facets.size());
        for (std::uint32_t t = 0; t < input_triangles.triangle_count(); ++t) {
            const VertIdx* tri = &input_triangles.triangles[3 * std::size_t{t}];
            for (unsigned k = 0; k < 3; ++k)
                ++input_directed[input_triangles.facets[t]][{tri[k], tri[(k + 1) % 3]}];
        }
        for (std::uint32_t f = 0; f < plc.facets.size(); ++f) {
            std::set<std::pair<VertIdx, VertIdx>> expected;
            for (const auto& [edge, count] : input_directed[f]) {
                if (input_directed[f].count({edge.second, edge.first}) != 0) continue;
                const auto s = segment_of.find(edge_key(edge.first, edge.second));
                if (s == segment_of.end())
                    return "facet " + std::to_string(f) + ": boundary edge (" + name(edge.first) +
                           ", " + name(edge.second) + ") of its input triangles is no segment";
                const std::vector<VertIdx> path = walk(s->second, edge.first);
                if (path.back() != edge.second || path.size() != chains[s->second].size() + 1)
                    return "segment " + std::to_string(s->second) +
                           ": its subsegments do not lead from one end to the other";
                for (std::size_t k = 0; k + 1 < path.size(); ++k)
                    expected.insert({path[k], path[k + 1]});
            }
            std::set<std::pair<VertIdx, VertIdx>> boundary;
            const auto first = std::lower_bound(directed.begin(), directed.end(),
                                                std::array<std::uint32_t, 3>{f, 0, 0}, Less3{});
            for (auto it = first; it != directed.end() && (*it)[0] == f; ++it)
                if (!has_directed(f, (*it)[2], (*it)[1])) boundary.insert({(*it)[1], (*it)[2]});
            if (boundary != expected)
                return "facet " + std::to_string(f) +
                       ": the boundary of its subfaces is not its boundary (split by its "
                       "subsegments)";
        }
    }
    // Boundary faces (no neighbour: check_topology_3d matched the neighbours with the shared
    // faces) that are no subface; the smallest is reported, as a walk over sorted faces would.
    std::optional<Face> stray;
    for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
        if (mesh.neighbors[f] != kNone) continue;
        const std::size_t t = f / 4;
        const unsigned* lf = kFaceVertex[f % 4];
        const Face face =
            sorted3(mesh.tets[4 * t + lf[0]], mesh.tets[4 * t + lf[1]], mesh.tets[4 * t + lf[2]]);
        if (!std::binary_search(subface_keys.begin(), subface_keys.end(), face, Less3{}) &&
            (!stray || Less3{}(face, *stray)))
            stray = face;
    }
    if (stray)
        return "boundary face (" + name((*stray)[0]) + ", " + name((*stray)[1]) + ", " +
               name((*stray)[2]) + ") is no subface";
    return "";
}

}  // namespace

BoundaryConformityReport3 check_boundary_conformity_3d(const Plc3& plc,
                                                       const ConformingMesh3& mesh) {
    BoundaryConformityReport3 report;
    report.problem = check(plc, mesh);
    report.ok = report.problem.empty();
    return report;
}

}  // namespace exactmesh::triangulation
