// SPDX-License-Identifier: MIT
// Conforming Delaunay boundary recovery in 3D (see boundary_recovery_3d.hpp).
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/constructions.hpp"
#include "predicates/dot_sign_3d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"
#include "triangulation/recovery_3d/region_flood_3d.hpp"

namespace exactmesh::triangulation {

using predicates::Sign;

namespace {

using FaceSet = FaceSet3;

/// Exact coordinates as a key (bit patterns; +0 and -0 merged).
struct PointKey {
    std::array<std::uint64_t, 3> bits;
    bool operator==(const PointKey&) const = default;
};
struct PointKeyHash {
    std::size_t operator()(const PointKey& k) const noexcept {
        return static_cast<std::size_t>((k.bits[0] * 0x9E3779B97F4A7C15ull) ^
                                        (k.bits[1] * 0xC2B2AE3D27D4EB4Full) ^ k.bits[2]);
    }
};
PointKey point_key(const double* p) {
    PointKey k{};
    for (unsigned i = 0; i < 3; ++i) {
        const double x = p[i] == 0 ? 0.0 : p[i];
        std::memcpy(&k.bits[i], &x, sizeof x);
    }
    return k;
}

/// Whether p and q differ in every coordinate by at most 2^-44 of `magnitude` (the largest
/// coordinate magnitude of the points they were constructed from: their rounding noise scales
/// with it, not with their own size; a hexagon's centre at the origin is a circumcentre of
/// about 1e-16 computed from corners of about 1). A choice of which points to add, not a
/// validity decision: the differences are taken in doubles (their rounding scales with the
/// input: the same answer at 2^+-600; an overflow to infinity answers false, as it should).
bool within_rounding_3d(const double* p, const double* q, double magnitude) {
    if (!(magnitude > 0)) return true;
    const double threshold = std::ldexp(1.0, std::ilogb(magnitude) - 44);
    for (int k = 0; k < 3; ++k)
        if (std::max(p[k], q[k]) - std::min(p[k], q[k]) > threshold) return false;
    return true;
}

struct Subsegment {
    VertIdx a, b;
    std::uint32_t segment;
};

/// The triangulation of one facet in the current round.
struct FacetTriangulation {
    std::vector<VertIdx> vertices;   ///< global indices (sorted)
    std::vector<double> xy;          ///< their projections
    std::vector<VertIdx> triangles;  ///< 3·#T global indices, counter-clockwise in projection
};

class Recovery {
  public:
    Recovery(const Plc3& plc, const BoundaryRecovery3Options& options) : plc_(plc) {
        xyz_ = plc.xyz;
        const std::uint32_t n = plc.vertex_count();
        feature_.assign(n, VertexFeature3::Input);
        feature_index_.assign(n, kNone);
        parameter_.assign(n, 0.0);
        for (VertIdx v = 0; v < n; ++v) points_.emplace(point_key(plc.point(v)), v);
        budget_ = options.max_steiner_points != 0 ? options.max_steiner_points
                                                  : 100 * std::uint64_t{n} + 100000;
        seed_ = options.seed;
        collect_segments();
        reject_corners_on_segments();
        planes_.reserve(plc.facets.size());
        for (const Facet3& facet : plc.facets) planes_.push_back(facet_plane(plc, facet));
        facet_interior_.resize(plc.facets.size());
    }

    BoundaryRecovery3Result run();

  private:
    const Plc3& plc_;
    std::vector<double> xyz_;
    std::vector<VertexFeature3> feature_;
    std::vector<std::uint32_t> feature_index_;
    std::vector<double> parameter_;  ///< position along the segment, for segment vertices
    std::unordered_map<PointKey, VertIdx, PointKeyHash> points_;
    std::vector<std::array<VertIdx, 2>> segments_;
    std::vector<std::vector<std::uint32_t>> facet_segments_;
    std::vector<std::vector<std::uint32_t>> vertex_segments_;  ///< per input vertex
    std::vector<Subsegment> subs_;
    std::vector<std::vector<VertIdx>> facet_interior_;
    std::vector<FacetPlane> planes_;
    std::uint64_t budget_ = 0;
    std::uint64_t seed_ = 1;  ///< the Delaunay tetrahedralizations' insertion-order seed
    BoundaryRecovery3Counters counters_;
    std::vector<std::string> warnings_;  ///< carve's: input points the domain leaves unused

    Delaunay3Result mesh_;
    std::unordered_set<std::uint64_t> edges_;
    FaceSet faces_;

    std::string vertex_name(VertIdx v) const { return std::to_string(plc_.vertex_number(v)); }
    std::string segment_name(std::uint32_t s) const {
        return "segment (" + vertex_name(segments_[s][0]) + ", " + vertex_name(segments_[s][1]) +
               ")";
    }
    std::string facet_name(std::uint32_t f) const {
        return "facet " + std::to_string(std::uint64_t{f} + plc_.first_index);
    }
    const double* point(VertIdx v) const { return xyz_.data() + 3 * std::size_t{v}; }
    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz_.size() / 3); }

    void collect_segments() {
        PlcSegments3 segments = plc_segments_3d(plc_);
        segments_ = std::move(segments.ends);
        facet_segments_ = std::move(segments.segments_of_facet);
        vertex_segments_.resize(plc_.vertex_count());
        for (std::uint32_t s = 0; s < segments_.size(); ++s) {
            const auto [a, b] = segments_[s];
            subs_.push_back({a, b, s});
            vertex_segments_[a].push_back(s);
            vertex_segments_[b].push_back(s);
        }
        counters_.segments = segments_.size();
    }

    /// A facet corner inside one of the facet's segments (exact: collinear in every coordinate
    /// projection and strictly inside the segment's diametral sphere) passes the facet checks
    /// (the planar triangulation splits the segment there) but no tetrahedralization can keep
    /// the segment as one chain: refuse it, naming both.
    void reject_corners_on_segments() const {
        for (std::uint32_t f = 0; f < plc_.facets.size(); ++f) {
            std::vector<VertIdx> corners;
            for (const auto& polygon : plc_.facets[f].polygons)
                corners.insert(corners.end(), polygon.begin(), polygon.end());
            std::sort(corners.begin(), corners.end());
            corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
            for (const std::uint32_t s : facet_segments_[f]) {
                const VertIdx a = segments_[s][0], b = segments_[s][1];
                for (const VertIdx v : corners) {
                    if (v == a || v == b) continue;
                    if (predicates::dot_sign_3d(point(v), point(a), point(b)) != Sign::Negative)
                        continue;
                    bool collinear = true;
                    for (int k = 0; k < 3 && collinear; ++k)
                        collinear = projected_orient(point(a), point(b), point(v), k) == Sign::Zero;
                    if (collinear) {
                        throw InputError("boundary recovery: vertex " + vertex_name(v) + " of " +
                                         facet_name(f) + " lies inside its " + segment_name(s) +
                                         " (make it a corner of the polygon there)");
                    }
                }
            }
        }
    }

    std::string feature_text(VertIdx v) const {
        if (feature_[v] == VertexFeature3::Input) return "an input vertex";
        if (feature_[v] == VertexFeature3::Segment)
            return "on " + segment_name(feature_index_[v]) + " at " + std::to_string(parameter_[v]);
        return "in " + facet_name(feature_index_[v]);
    }

    /// Adds a Steiner vertex (the caller checked it is new).
    VertIdx add_vertex(const std::array<double, 3>& p, VertexFeature3 feature, std::uint32_t index,
                       double parameter, const std::string& what) {
        if (counters_.insertions >= budget_) {
            throw InputError("boundary recovery: Steiner point budget of " +
                             std::to_string(budget_) + " exceeded while recovering " + what);
        }
        const VertIdx v = vertex_count();
        xyz_.insert(xyz_.end(), p.begin(), p.end());
        feature_.push_back(feature);
        feature_index_.push_back(index);
        parameter_.push_back(parameter);
        points_.emplace(point_key(p.data()), v);
        ++counters_.insertions;
        return v;
    }

    double parameter_of(VertIdx v, std::uint32_t s) const {
        if (v == segments_[s][0]) return 0.0;
        if (v == segments_[s][1]) return 1.0;
        return parameter_[v];
    }

    /// Whether input vertex `apex` (an end of segment s) meets another segment at an acute
    /// angle (exact: (far - apex) . (other - apex) > 0).
    bool acute_apex(VertIdx apex, std::uint32_t s) const {
        const VertIdx far = segments_[s][0] == apex ? segments_[s][1] : segments_[s][0];
        for (const std::uint32_t other : vertex_segments_[apex]) {
            if (other == s) continue;
            const VertIdx end =
                segments_[other][0] == apex ? segments_[other][1] : segments_[other][0];
            if (predicates::dot_sign_3d(point(apex), point(far), point(end)) == Sign::Positive)
                return true;
        }
        return false;
    }

    double shell_parameter(std::uint32_t s, double t_apex, double t_far) const {
        return concentric_shell_parameter(point(segments_[s][0]), point(segments_[s][1]), t_apex,
                                          t_far);
    }

    void split_subsegment(std::size_t i, bool encroached) {
        const Subsegment sub = subs_[i];
        const std::uint32_t s = sub.segment;
        const double ta = parameter_of(sub.a, s), tb = parameter_of(sub.b, s);
        const bool apex_a = sub.a < plc_.vertex_count() && acute_apex(sub.a, s);
        const bool apex_b = sub.b < plc_.vertex_count() && acute_apex(sub.b, s);
        double t = std::nan("");
        if (apex_a != apex_b) t = apex_a ? shell_parameter(s, ta, tb) : shell_parameter(s, tb, ta);
        const bool shell = !std::isnan(t);
        if (!shell) t = 0.5 * ta + 0.5 * tb;
        const std::array<double, 3> m =
            predicates::point_on_segment_3d(point(segments_[s][0]), point(segments_[s][1]), t);
        const auto found = points_.find(point_key(m.data()));
        if (found != points_.end()) {
            // Refinement has cascaded down to adjacent doubles: at a vertex where facets or
            // segments meet at small angles, conforming refinement need not terminate
            // [Shewchuk97 §3.5; Cohen-Steiner et al. 2002 protect such vertices with balls],
            // and the budget would not stop it first: one chain halves about 1,000 times.
            throw InputError("boundary recovery: " + segment_name(s) +
                             " needs a split point closer than doubles resolve (its split "
                             "point is vertex " +
                             vertex_name(found->second) + ", " + feature_text(found->second) +
                             "): refinement cascades at small input angles");
        }
        const VertIdx v = add_vertex(m, VertexFeature3::Segment, s, t, segment_name(s));
        if (encroached) {
            ++counters_.encroachment_splits;
        } else if (shell) {
            ++counters_.shell_splits;
        } else {
            ++counters_.segment_splits;
        }
        subs_[i] = {sub.a, v, s};
        subs_.push_back({v, sub.b, s});
    }

    void build_mesh() {
        ++counters_.rounds;
        mesh_ = delaunay_3d_algorithm("green-sibson")(xyz_, Delaunay3Options{.seed = seed_});
        if (mesh_.coplanar) throw InputError("boundary recovery: the PLC's vertices are coplanar");
        EM_ASSERT(mesh_.counters.duplicates == 0);
        edges_.clear();
        faces_.clear();
        const auto& tets = mesh_.mesh.tets;
        for (std::size_t t = 0; t < tets.size(); t += 4) {
            for (unsigned i = 0; i < 4; ++i) {
                for (unsigned j = i + 1; j < 4; ++j)
                    edges_.insert(edge_key(tets[t + i], tets[t + j]));
                const unsigned* lf = kFaceVertex[i];
                faces_.insert(sorted3(tets[t + lf[0]], tets[t + lf[1]], tets[t + lf[2]]));
            }
        }
    }

    bool recover_segments() {
        bool split = false;
        const std::size_t count = subs_.size();
        for (std::size_t i = 0; i < count; ++i) {
            if (edges_.count(edge_key(subs_[i].a, subs_[i].b)) == 0) {
                split_subsegment(i, false);
                split = true;
            }
        }
        return split;
    }

    FacetTriangulation triangulate_facet(std::uint32_t f,
                                         const std::vector<std::vector<std::size_t>>& by_segment,
                                         std::vector<std::size_t>& facet_subs) const {
        const Facet3& facet = plc_.facets[f];
        const int drop = planes_[f].drop;
        FacetTriangulation out;
        facet_subs.clear();
        for (const auto& polygon : facet.polygons)
            out.vertices.insert(out.vertices.end(), polygon.begin(), polygon.end());
        for (const std::uint32_t s : facet_segments_[f]) {
            for (const std::size_t i : by_segment[s]) {
                facet_subs.push_back(i);
                out.vertices.push_back(subs_[i].a);
                out.vertices.push_back(subs_[i].b);
            }
        }
        out.vertices.insert(out.vertices.end(), facet_interior_[f].begin(),
                            facet_interior_[f].end());
        std::sort(out.vertices.begin(), out.vertices.end());
        out.vertices.erase(std::unique(out.vertices.begin(), out.vertices.end()),
                           out.vertices.end());
        auto local = [&](VertIdx v) {
            return static_cast<VertIdx>(
                std::lower_bound(out.vertices.begin(), out.vertices.end(), v) -
                out.vertices.begin());
        };
        for (const VertIdx v : out.vertices) {
            const auto p = project_facet_point(point(v), drop);
            out.xy.insert(out.xy.end(), p.begin(), p.end());
        }
        std::vector<VertIdx> constraints;
        for (const std::size_t i : facet_subs) {
            constraints.push_back(local(subs_[i].a));
            constraints.push_back(local(subs_[i].b));
        }
        std::vector<double> holes;
        for (std::size_t h = 0; h + 2 < facet.holes.size(); h += 3) {
            const auto p = project_facet_point(&facet.holes[h], drop);
            holes.insert(holes.end(), p.begin(), p.end());
        }
        Pslg pslg;
        pslg.xy = out.xy;
        pslg.segments = constraints;
        pslg.holes = holes;
        const Cdt2Result cdt = constrained_delaunay_2d(pslg);
        if (cdt.counters.duplicates != 0) {
            for (std::size_t v = 0; v < cdt.merged_into.size(); ++v) {
                if (cdt.merged_into[v] == v) continue;
                const VertIdx p = out.vertices[v], q = out.vertices[cdt.merged_into[v]];
                throw GeometryError("boundary recovery: vertices " + vertex_name(p) + " and " +
                                    vertex_name(q) + " of " + facet_name(f) +
                                    " have the same projection into its plane (" + feature_text(p) +
                                    ", " + feature_text(q) + ")");
            }
        }
        if (cdt.mesh.vertex_count() > out.vertices.size()) {
            throw GeometryError(
                "boundary recovery: the subsegments of " + facet_name(f) +
                " cross or overlap in its plane's projection (rounded split points finer than "
                "doubles resolve): " +
                std::to_string(cdt.counters.intersections) + " crossings, " +
                std::to_string(cdt.counters.duplicates) + " repeated points, " +
                std::to_string(cdt.counters.vertices_on_segments) + " vertices on pieces");
        }
        out.triangles.reserve(cdt.mesh.triangles.size());
        for (const VertIdx v : cdt.mesh.triangles) out.triangles.push_back(out.vertices[v]);
        return out;
    }

    /// Whether the projection of p lies in a triangle of the facet (closed), exactly.
    bool inside(const FacetTriangulation& facet, const double* p, int drop,
                std::size_t first) const {
        const auto q = project_facet_point(p, drop);
        // The subface's own triangle first (where a well-shaped subface's circumcenter lies),
        // then all of them.
        for (std::size_t i = 0; i <= facet.triangles.size(); i += 3) {
            const std::size_t t = i == 0 ? first : i - 3;
            if (i != 0 && t == first) continue;
            bool in = true;
            for (unsigned k = 0; k < 3 && in; ++k) {
                const auto a = project_facet_point(point(facet.triangles[t + k]), drop);
                const auto b = project_facet_point(point(facet.triangles[t + (k + 1) % 3]), drop);
                in = predicates::orient2d(a.data(), b.data(), q.data()) != Sign::Negative;
            }
            if (in) return true;
        }
        return false;
    }

    /// Flips unconstrained edges of the facet's triangulation whose two triangles are not both
    /// mesh faces to the other diagonal when its two triangles are mesh faces (and the
    /// quadrilateral is strictly convex in the projection, exact orient2d). The projection's
    /// Delaunay triangulation is Delaunay in the projected metric, not in the facet's plane:
    /// without this, the facet's triangulation and the tetrahedralization's faces could choose
    /// different diagonals of nearly cocircular quadrilaterals at every scale, and inserting
    /// circumcenters there never ends (random star PLC 17: facet 47 grew past 10^5 points).
    void match_mesh_faces(FacetTriangulation& facet, const std::vector<std::size_t>& facet_subs,
                          int drop) const {
        std::unordered_set<std::uint64_t> constrained;
        for (const std::size_t i : facet_subs) constrained.insert(edge_key(subs_[i].a, subs_[i].b));
        std::vector<VertIdx>& tri = facet.triangles;
        const std::size_t count = tri.size() / 3;
        auto positive = [&](VertIdx a, VertIdx b, VertIdx c) {
            return projected_orient(point(a), point(b), point(c), drop) == Sign::Positive;
        };
        for (std::size_t pass = 0; pass < count + 1; ++pass) {
            std::unordered_map<std::uint64_t, std::array<std::size_t, 2>> edge_triangles;
            for (std::size_t t = 0; t < count; ++t) {
                for (unsigned k = 0; k < 3; ++k) {
                    const auto [it, added] =
                        edge_triangles.emplace(edge_key(tri[3 * t + k], tri[3 * t + (k + 1) % 3]),
                                               std::array<std::size_t, 2>{t, kNone});
                    if (!added) it->second[1] = t;
                }
            }
            std::vector<std::uint8_t> touched(count, 0);
            bool flipped = false;
            for (std::size_t t = 0; t < count; ++t) {
                if (touched[t] || faces_.count(sorted3(tri[3 * t], tri[3 * t + 1], tri[3 * t + 2])))
                    continue;
                for (unsigned k = 0; k < 3; ++k) {
                    const VertIdx a = tri[3 * t + k], b = tri[3 * t + (k + 1) % 3],
                                  c = tri[3 * t + (k + 2) % 3];
                    if (constrained.count(edge_key(a, b)) != 0) continue;
                    const auto& pair = edge_triangles.at(edge_key(a, b));
                    const std::size_t u = pair[0] == t ? pair[1] : pair[0];
                    if (u == kNone || touched[u]) continue;
                    VertIdx d = kNone;
                    for (unsigned j = 0; j < 3; ++j) {
                        const VertIdx w = tri[3 * u + j];
                        if (w != a && w != b) d = w;
                    }
                    if (faces_.count(sorted3(a, c, d)) == 0 || faces_.count(sorted3(b, c, d)) == 0)
                        continue;
                    if (!positive(a, d, c) || !positive(d, b, c)) continue;
                    tri[3 * t] = a, tri[3 * t + 1] = d, tri[3 * t + 2] = c;
                    tri[3 * u] = d, tri[3 * u + 1] = b, tri[3 * u + 2] = c;
                    touched[t] = touched[u] = 1;
                    flipped = true;
                    break;
                }
            }
            if (!flipped) return;
        }
    }

    /// Appends the facet's subsegments whose diametral sphere strictly contains the apex of a
    /// subface on them (exact dot_sign_3d).
    void sweep_encroached(const FacetTriangulation& facet,
                          const std::vector<std::size_t>& facet_subs,
                          std::vector<std::size_t>& to_split) const {
        std::unordered_map<std::uint64_t, std::size_t> sub_of;
        for (const std::size_t i : facet_subs) sub_of.emplace(edge_key(subs_[i].a, subs_[i].b), i);
        for (std::size_t t = 0; t < facet.triangles.size(); t += 3) {
            for (unsigned k = 0; k < 3; ++k) {
                const VertIdx a = facet.triangles[t + k], b = facet.triangles[t + (k + 1) % 3],
                              apex = facet.triangles[t + (k + 2) % 3];
                const auto it = sub_of.find(edge_key(a, b));
                if (it == sub_of.end()) continue;
                if (predicates::dot_sign_3d(point(apex), point(a), point(b)) == Sign::Negative)
                    to_split.push_back(it->second);
            }
        }
    }

    /// One pass over the facets: returns false when every subface is a face (then `subfaces`
    /// holds them all), true when points were added.
    bool recover_facets(std::vector<VertIdx>& subfaces, std::vector<std::uint32_t>& owners) {
        std::vector<std::vector<std::size_t>> by_segment(segments_.size());
        for (std::size_t i = 0; i < subs_.size(); ++i) by_segment[subs_[i].segment].push_back(i);
        subfaces.clear();
        owners.clear();
        std::vector<std::size_t> to_split;
        struct Pending {
            std::array<double, 3> p;
            std::uint32_t facet;
            bool fallback;
        };
        std::vector<Pending> pending;
        std::unordered_set<PointKey, PointKeyHash> pending_keys;
        std::vector<std::size_t> facet_subs;
        for (std::uint32_t f = 0; f < plc_.facets.size(); ++f) {
            FacetTriangulation facet = triangulate_facet(f, by_segment, facet_subs);
            const int drop = planes_[f].drop;
            const std::size_t facet_pending = pending.size();
            match_mesh_faces(facet, facet_subs, drop);
            bool swept = false, vertex_encroached = false;
            std::set<std::pair<double, double>> projections;
            for (std::size_t k = 0; k + 1 < facet.xy.size(); k += 2)
                projections.insert({facet.xy[k], facet.xy[k + 1]});
            for (std::size_t t = 0; t < facet.triangles.size(); t += 3) {
                const VertIdx a = facet.triangles[t], b = facet.triangles[t + 1],
                              c = facet.triangles[t + 2];
                if (planes_[f].flip) {
                    subfaces.insert(subfaces.end(), {a, c, b});
                } else {
                    subfaces.insert(subfaces.end(), {a, b, c});
                }
                owners.push_back(f);
                if (faces_.count(sorted3(a, b, c)) != 0) continue;
                const std::array<double, 3> center =
                    predicates::triangle_circumcenter_3d(point(a), point(b), point(c));
                bool encroaches = false;
                for (const std::size_t i : facet_subs) {
                    if (predicates::dot_sign_3d(center.data(), point(subs_[i].a),
                                                point(subs_[i].b)) != Sign::Positive) {
                        to_split.push_back(i);
                        encroaches = true;
                    }
                }
                if (encroaches) continue;
                Pending next{center, f, false};
                if (!inside(facet, center.data(), drop, t)) {
                    // Ruppert's lemma: with no subsegment encroached by a vertex, every
                    // circumcenter lies in the domain. So split the facet's subsegments that
                    // the apex of a subface on them encroaches (in a constrained Delaunay
                    // triangulation an encroached subsegment is encroached by such an apex
                    // [Shewchuk97 §3.4]), strictly inside the diametral sphere.
                    if (!swept) {
                        swept = true;
                        const std::size_t before = to_split.size();
                        sweep_encroached(facet, facet_subs, to_split);
                        vertex_encroached = to_split.size() > before;
                    }
                    if (vertex_encroached) continue;
                    // The projection's triangulation is Delaunay in the projected metric, not
                    // in the facet's own: a circumcenter may then fall outside the facet with
                    // no subsegment encroached. The centroid lies inside the subface.
                    for (unsigned k = 0; k < 3; ++k)
                        next.p[k] = point(a)[k] / 3 + point(b)[k] / 3 + point(c)[k] / 3;
                    next.fallback = true;
                }
                // Vertices of a facet must have distinct projections (its triangulation is
                // planar there), but a circumcenter of cocircular subfaces may land, in
                // projection, on a vertex of the facet, possibly one that differs from it only
                // by the rounding of the dropped coordinate (random star 53, facet 62): then
                // nothing is added for this subface this round (other points change it).
                auto projected_taken = [&](const std::array<double, 3>& q) {
                    const auto pq = project_facet_point(q.data(), drop);
                    return projections.count({pq[0], pq[1]}) != 0;
                };
                if (projected_taken(next.p)) continue;
                // Cocircular subfaces (a regular polygon's triangles, a square's) share their
                // circumcentre, rounded differently for each: one point for them this round,
                // not several an ulp apart (a rotated hexagonal prism got two Steiner points
                // 4e-16 apart, an edge no refinement can improve).
                double magnitude = 0;
                for (const VertIdx corner : {a, b, c})
                    for (int k = 0; k < 3; ++k)
                        magnitude = std::max(magnitude, std::fabs(point(corner)[k]));
                const auto near_pending = [&](const Pending& other) {  // this facet's
                    return within_rounding_3d(next.p.data(), other.p.data(), magnitude);
                };
                if (std::any_of(pending.begin() + static_cast<std::ptrdiff_t>(facet_pending),
                                pending.end(), near_pending))
                    continue;
                const PointKey key = point_key(next.p.data());
                if (points_.count(key) != 0 || !pending_keys.insert(key).second) continue;
                const auto pq = project_facet_point(next.p.data(), drop);
                projections.insert({pq[0], pq[1]});
                pending.push_back(next);
            }
        }
        std::sort(to_split.begin(), to_split.end());
        to_split.erase(std::unique(to_split.begin(), to_split.end()), to_split.end());
        for (const std::size_t i : to_split) split_subsegment(i, true);
        for (const Pending& p : pending) {
            if (points_.count(point_key(p.p.data())) != 0) continue;
            const VertIdx v =
                add_vertex(p.p, VertexFeature3::Facet, p.facet, 0.0, facet_name(p.facet));
            facet_interior_[p.facet].push_back(v);
            ++(p.fallback ? counters_.fallback_points : counters_.facet_splits);
        }
        if (to_split.empty() && pending.empty()) {
            for (std::size_t t = 0; t < subfaces.size(); t += 3) {
                if (faces_.count(sorted3(subfaces[t], subfaces[t + 1], subfaces[t + 2])) == 0) {
                    throw GeometryError("boundary recovery: a subface of " +
                                        facet_name(owners[t / 3]) +
                                        " is missing and no point can be added to recover it");
                }
            }
            return false;
        }
        return true;
    }

    /// Whether p lies in the closed subface (a, b, c), exactly: coplanar (orient3d zero) and
    /// inside it in a coordinate projection where it is not flat (drop_axis).
    bool on_subface(const double* p, VertIdx a, VertIdx b, VertIdx c) const {
        const auto& m = mesh_.mesh;
        const double *pa = m.point(a), *pb = m.point(b), *pc = m.point(c);
        return predicates::orient3d(pa, pb, pc, p) == Sign::Zero &&
               in_projected_triangle(p, pa, pb, pc, drop_axis(pa, pb, pc));
    }

    /// A volume hole or region point on a subface names neither side of its facet (a hole there
    /// removed both, or nothing): an InputError naming the point and the facet, as the 2D
    /// generators refuse a hole on a segment.
    void refuse_points_on_facets(const std::vector<VertIdx>& subfaces,
                                 const std::vector<std::uint32_t>& owners) const {
        const auto check = [&](const double* p, const std::string& what) {
            for (std::size_t t = 0; t + 2 < subfaces.size(); t += 3) {
                if (!on_subface(p, subfaces[t], subfaces[t + 1], subfaces[t + 2])) continue;
                throw InputError("boundary recovery: " + what + " " + format_point(p, 3) +
                                 " lies on " + facet_name(owners[t / 3]) +
                                 ", so it names neither side of it; move it into the region "
                                 "it is meant for");
            }
        };
        for (std::size_t h = 0; h + 2 < plc_.holes.size(); h += 3)
            check(&plc_.holes[h], "volume hole point " + std::to_string(h / 3 + plc_.first_index));
        for (std::size_t r = 0; r < plc_.regions.size(); ++r) {
            const double p[3] = {plc_.regions[r].x, plc_.regions[r].y, plc_.regions[r].z};
            check(p, "region point " + std::to_string(r + plc_.first_index));
        }
    }

    ConformingMesh3 carve(std::vector<VertIdx> subfaces, std::vector<std::uint32_t> owners) {
        refuse_points_on_facets(subfaces, owners);
        const FaceSet subface_set = face_set_3d(subfaces);
        const auto& m = mesh_.mesh;
        const TetIdx count = m.tet_count();
        std::vector<std::uint8_t> removed(count, 0);
        std::vector<TetIdx> seeds;
        for (TetIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                if (m.neighbors[4 * t + k] != kNone) continue;
                const unsigned* lf = kFaceVertex[k];
                if (subface_set.count(sorted3(m.tets[4 * t + lf[0]], m.tets[4 * t + lf[1]],
                                              m.tets[4 * t + lf[2]])) == 0)
                    seeds.push_back(t);
            }
        }
        flood_tetrahedra_3d(m, subface_set, seeds, removed, 1);
        // Hole points after the outside: one there (or beyond the hull) changes nothing and is
        // named in a warning, as TetGen ignores it.
        seeds.clear();
        for (std::size_t h = 0; h + 2 < plc_.holes.size(); h += 3) {
            const TetIdx t = locate_closed_tetrahedron_3d(m, &plc_.holes[h]);
            if (t != kNone && removed[t] == 0) {
                seeds.push_back(t);
            } else {
                warnings_.push_back(
                    "volume hole point " + std::to_string(h / 3 + plc_.first_index) + " " +
                    format_point(&plc_.holes[h], 3) + " lies outside the domain: ignored");
            }
        }
        flood_tetrahedra_3d(m, subface_set, seeds, removed, 1);
        // Region attributes and volume bounds by the same flood (a later region point in the
        // same region overrides an earlier one, as TetGen does).
        RegionAssignment3 regions = assign_regions_3d(plc_, m, subface_set, removed);
        warnings_.insert(warnings_.end(), regions.warnings.begin(), regions.warnings.end());
        const std::vector<double>& attributes = regions.attributes;
        const std::vector<double>& max_volumes = regions.max_volumes;
        ConformingMesh3 out;
        std::vector<TetIdx> new_index(count, kNone);
        TetIdx kept = 0;
        for (TetIdx t = 0; t < count; ++t)
            if (!removed[t]) new_index[t] = kept++;
        counters_.removed_tets = count - kept;
        if (kept == 0) {
            throw InputError(
                "boundary recovery: the domain is empty: " +
                (plc_.holes.empty()
                     ? std::string("the facets enclose no volume")
                     : std::string("the volume hole points remove every region the facets "
                                   "enclose")));
        }
        out.mesh.xyz = xyz_;
        out.mesh.tets.reserve(4 * std::size_t{kept});
        out.mesh.neighbors.reserve(4 * std::size_t{kept});
        for (TetIdx t = 0; t < count; ++t) {
            if (removed[t]) continue;
            for (unsigned k = 0; k < 4; ++k) {
                out.mesh.tets.push_back(m.tets[4 * t + k]);
                const TetIdx n = m.neighbors[4 * t + k];
                out.mesh.neighbors.push_back(n == kNone ? kNone : new_index[n]);
            }
            if (!attributes.empty()) out.tet_attributes.push_back(attributes[t]);
            if (!max_volumes.empty()) out.tet_max_volume.push_back(max_volumes[t]);
        }
        // Input vertices in no kept tetrahedron: free vertices outside the domain or in a hole.
        std::vector<std::uint8_t> used(plc_.vertex_count(), 0);
        for (const VertIdx v : out.mesh.tets)
            if (v < used.size()) used[v] = 1;
        std::string unused;
        std::size_t unused_count = 0;
        for (VertIdx v = 0; v < used.size(); ++v) {
            if (used[v] != 0) continue;
            if (++unused_count <= 10)
                unused += (unused.empty() ? "" : ", ") + std::to_string(plc_.vertex_number(v));
        }
        if (unused_count != 0) {
            warnings_.push_back(
                "input vertices outside the domain or in a hole, left out of the mesh (kept in "
                "its vertex list): " +
                unused +
                (unused_count > 10 ? ", ... (" + std::to_string(unused_count) + " in all)" : ""));
        }
        out.input_vertex_count = plc_.vertex_count();
        out.vertex_feature = feature_;
        out.feature_index = feature_index_;
        for (const auto& s : segments_) out.segments.insert(out.segments.end(), s.begin(), s.end());
        for (const Subsegment& sub : subs_) {
            out.subsegments.insert(out.subsegments.end(), {sub.a, sub.b});
            out.subsegment_segment.push_back(sub.segment);
        }
        out.subfaces = std::move(subfaces);
        out.subface_facet = std::move(owners);
        return out;
    }
};

BoundaryRecovery3Result Recovery::run() {
    std::vector<VertIdx> subfaces;
    std::vector<std::uint32_t> owners;
    while (true) {
        build_mesh();
        if (recover_segments()) continue;
        if (!recover_facets(subfaces, owners)) break;
    }
    BoundaryRecovery3Result result;
    result.mesh = carve(std::move(subfaces), std::move(owners));
    result.counters = counters_;
    result.warnings = std::move(warnings_);
    return result;
}

}  // namespace

double concentric_shell_parameter(const double* p, const double* q, double t_apex, double t_far) {
    double d[3], largest = 0;
    for (int k = 0; k < 3; ++k) {
        d[k] = q[k] - p[k];
        if (!std::isfinite(d[k])) return std::nan("");
        largest = std::max(largest, std::fabs(d[k]));
    }
    const int e = std::ilogb(largest);
    double norm2 = 0;
    for (int k = 0; k < 3; ++k) {
        const double x = std::ldexp(d[k], -e);
        norm2 += x * x;
    }
    const double length = std::sqrt(norm2);  // in [1, 2 sqrt(3)): the segment over 2^e
    const double piece = std::fabs(t_far - t_apex) * length;
    if (!(piece > 0x1p-900)) return std::nan("");
    const double offset =
        std::ldexp(1.0, static_cast<int>(std::lround(std::log2(piece / 2)))) / length;
    const double t = t_far > t_apex ? t_apex + offset : t_apex - offset;
    const bool between = t_far > t_apex ? (t > t_apex && t < t_far) : (t < t_apex && t > t_far);
    return between ? t : std::nan("");
}

BoundaryRecovery3Result boundary_recovery_3d(const Plc3& plc,
                                             const BoundaryRecovery3Options& options) {
    validate_plc_3d(plc);
    Recovery recovery(plc, options);
    return recovery.run();
}

BoundaryRecovery3Result boundary_recovery_3d_whole_facets(Plc3& plc,
                                                          const BoundaryRecovery3Options& options,
                                                          std::vector<std::string>& warnings) {
    if (facets_exactly_planar_3d(plc)) return boundary_recovery_3d(plc, options);
    const std::uint64_t cap = 4096 + 64 * std::uint64_t{plc.vertex_count()};
    BoundaryRecovery3Options capped = options;
    capped.max_steiner_points =
        options.max_steiner_points != 0 ? std::min(options.max_steiner_points, cap) : cap;
    std::string why;
    try {
        BoundaryRecovery3Result whole = boundary_recovery_3d(plc, capped);
        // A free vertex attached to a whole facet 2e-88 beside its corner (at 2^493, a fuzzed
        // PLC) left the facet's subfaces not tiling it: checked exactly, else split.
        const BoundaryConformityReport3 report = check_boundary_conformity_3d(plc, whole.mesh);
        if (report.ok) return whole;
        why = "did not conform (" + report.problem + ")";
    } catch (const InputError&) {
        // Also a budget the caller set: the split PLC then runs into it again, with its message.
        why = "ran past " + std::to_string(capped.max_steiner_points) + " Steiner points";
    }
    std::vector<std::string> split_warnings = split_nonplanar_facets_3d(plc, true);
    warnings.push_back(
        "boundary recovery with the facets within rounding of a plane kept "
        "whole " +
        why + ": those facets are split into their triangles");
    warnings.insert(warnings.end(), split_warnings.begin(), split_warnings.end());
    return boundary_recovery_3d(plc, options);
}

}  // namespace exactmesh::triangulation
