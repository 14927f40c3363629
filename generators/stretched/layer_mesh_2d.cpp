// SPDX-License-Identifier: MIT
// The shared last phase of the layered generators (see layer_mesh_2d.hpp).
#include "generators/stretched/layer_mesh_2d.hpp"

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators::layer_mesh {

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;

namespace {

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

/// Whether the closed segments (a, b) and (c, d), collinear, overlap (coordinates compared
/// exactly: on a line, overlapping boxes mean overlapping segments).
bool collinear_overlap(const double* a, const double* b, const double* c, const double* d) {
    for (int axis = 0; axis < 2; ++axis) {
        if (std::max(a[axis], b[axis]) < std::min(c[axis], d[axis]) ||
            std::max(c[axis], d[axis]) < std::min(a[axis], b[axis]))
            return false;
    }
    return true;
}

/// The triangles' neighbours across their edges (kNone on the boundary and beside a quad).
std::vector<tri::TriIdx> triangle_neighbors(const std::vector<VertIdx>& triangles) {
    std::unordered_map<std::uint64_t, std::uint32_t> half;
    half.reserve(triangles.size());
    std::vector<tri::TriIdx> neighbors(triangles.size(), kNone);
    for (std::uint32_t e = 0; e < triangles.size(); ++e) {
        const VertIdx a = triangles[e], b = triangles[e - e % 3 + (e % 3 + 1) % 3];
        const auto found = half.find((static_cast<std::uint64_t>(b) << 32) | a);
        if (found != half.end()) {
            neighbors[e] = found->second / 3;
            neighbors[found->second] = e / 3;
        } else {
            half[(static_cast<std::uint64_t>(a) << 32) | b] = e;
        }
    }
    return neighbors;
}

}  // namespace

/// Whether segments (a, b) and (c, d), given with their vertex ids, meet anywhere but at a
/// shared end: a crossing, a touch, or an overlap from a shared end. Exact.
bool segments_conflict(VertIdx ia, VertIdx ib, VertIdx ic, VertIdx id, const double* a,
                       const double* b, const double* c, const double* d) {
    const bool shares_a = ia == ic || ia == id, shares_b = ib == ic || ib == id;
    if (shares_a && shares_b) return false;  // the same segment
    if (shares_a || shares_b) {
        // Only an overlap along a common line from the shared end.
        const double* s = shares_a ? a : b;
        const double* own = shares_a ? b : a;
        const double* other = (shares_a ? ia : ib) == ic ? d : c;
        return pred::orient2d(s, own, other) == pred::Sign::Zero &&
               pred::direction_dot_sign(s, own, s, other) == pred::Sign::Positive;
    }
    const int o1 = static_cast<int>(pred::orient2d(a, b, c));
    const int o2 = static_cast<int>(pred::orient2d(a, b, d));
    if (o1 * o2 > 0) return false;
    const int o3 = static_cast<int>(pred::orient2d(c, d, a));
    const int o4 = static_cast<int>(pred::orient2d(c, d, b));
    if (o3 * o4 > 0) return false;
    if (o1 == 0 && o2 == 0) return collinear_overlap(a, b, c, d);
    return true;
}

/// Splits the strictly convex quadrilateral (v0, v1, v2, v3) by the diagonal whose two
/// triangles have the smaller largest angle (exact; ties to the diagonal v0-v2).
void split_quad(const std::array<VertIdx, 4>& v, const std::vector<double>& xy,
                std::vector<VertIdx>& triangles) {
    const auto at = [&](int k) { return &xy[2 * static_cast<std::size_t>(v[k])]; };
    // Diagonal v0-v2: (v0 v1 v2), (v0 v2 v3); diagonal v1-v3: (v0 v1 v3), (v1 v2 v3).
    const auto worst = [&](int a0, int a1, int a2, int b0, int b1, int b2) {
        const pred::Corner first = pred::largest_corner(at(a0), at(a1), at(a2));
        const pred::Corner second = pred::largest_corner(at(b0), at(b1), at(b2));
        return pred::compare_angles(first, second) == pred::Sign::Negative ? second : first;
    };
    const pred::Corner along02 = worst(0, 1, 2, 0, 2, 3);
    const pred::Corner along13 = worst(0, 1, 3, 1, 2, 3);
    if (pred::compare_angles(along13, along02) == pred::Sign::Negative) {
        triangles.insert(triangles.end(), {v[0], v[1], v[3], v[1], v[2], v[3]});
    } else {
        triangles.insert(triangles.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
    }
}

bool LayeredRegion2::is_wall_piece(VertIdx a, VertIdx b) const {
    return wall_edges_.count(edge_key(a, b)) != 0;
}

void LayeredRegion2::add_wall_loop(std::vector<VertIdx> loop) {
    for (std::size_t k = 0; k < loop.size(); ++k)
        wall_edges_.insert({edge_key(loop[k], loop[(k + 1) % loop.size()]), 1});
    wall_loops.push_back(std::move(loop));
}

void finish_layered_mesh_2d(const MeshDomain2& domain, const AdvancingLayersOptions2& options,
                            LayeredRegion2& region, AdvancingLayersResult2& result) {
    AdvancingLayersCounters2& counters = result.counters;
    const tri::Cdt2Result& cdt = domain.triangulation();
    const bool layered = options.layers.first_height != 0;
    const std::vector<double>& xy = region.xy;
    std::vector<VertIdx> fill_segments;
    std::vector<std::uint32_t> fill_segment_origin;  // input segment, or kNone for the front
    for (std::size_t p = 0; p < cdt.pieces.size() / 2; ++p) {
        const VertIdx a = cdt.pieces[2 * p], b = cdt.pieces[2 * p + 1];
        if (region.is_wall_piece(a, b)) continue;
        fill_segments.insert(fill_segments.end(), {a, b});
        fill_segment_origin.push_back(cdt.piece_segment[p]);
    }
    std::vector<VertIdx> front;
    // Where a stack stopped at the wall the front runs along a wall piece; the fill may split
    // it (at a vertex within rounding of it that the domain's triangulation did not put on
    // the input segment), so the output takes the wall's pieces from the fill there.
    std::unordered_map<std::uint64_t, std::uint32_t> wall_piece_segment;
    for (std::size_t p = 0; p < cdt.pieces.size() / 2; ++p) {
        const VertIdx a = cdt.pieces[2 * p], b = cdt.pieces[2 * p + 1];
        if (region.is_wall_piece(a, b))
            wall_piece_segment.emplace(edge_key(a, b), cdt.piece_segment[p]);
    }
    std::vector<std::uint32_t> front_wall_origin;  // per fill segment: the wall's input segment
    front_wall_origin.assign(fill_segment_origin.size(), kNone);
    for (const std::vector<VertIdx>& loop : region.fronts) {
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const VertIdx a = loop[k], b = loop[(k + 1) % loop.size()];
            front.insert(front.end(), {a, b});
            fill_segments.insert(fill_segments.end(), {a, b});
            fill_segment_origin.push_back(kNone);
            const auto wall = wall_piece_segment.find(edge_key(a, b));
            front_wall_origin.push_back(wall == wall_piece_segment.end() ? kNone : wall->second);
        }
    }

    // The fill's domain: the outer boundary and the front (the layers and the walls a hole).
    // Without layers (no first height, or no wall), the domain itself.
    const tri::Pslg pslg = domain.pslg();
    const tri::Pslg fill_pslg{xy, fill_segments, pslg.holes, {}};
    const MeshDomain2 fill_domain(fill_pslg, options.cdt);
    const MeshDomain2& filled = front.empty() ? domain : fill_domain;
    const SizeFunction base =
        options.size.bounded() ? options.size : graded_size_from_boundary(filled);
    // The fill's size near the front: at least 1.5 times the length of the front edges near
    // it, so the frontal generator keeps every front edge whole (its boundary split puts
    // ceil(integral of ds / s) pieces on an edge); the user's size or the graded spacing
    // elsewhere.
    SizeFunction fill_size = base;
    if (!front.empty()) {
        std::vector<double> lengths;
        for (std::size_t e = 0; e < front.size() / 2; ++e)
            lengths.push_back(distance(&xy[2 * front[2 * e]], &xy[2 * front[2 * e + 1]]));
        std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
        const double median = lengths[lengths.size() / 2];
        auto front_grid = std::make_shared<BucketGrid>(xy[0], xy[1], median);
        auto front_reach = std::make_shared<std::vector<std::array<double, 5>>>();
        for (std::size_t e = 0; e < front.size() / 2; ++e) {
            const double *a = &xy[2 * front[2 * e]], *b = &xy[2 * front[2 * e + 1]];
            const double length = distance(a, b);
            const double lo[2] = {std::min(a[0], b[0]) - length, std::min(a[1], b[1]) - length};
            const double hi[2] = {std::max(a[0], b[0]) + length, std::max(a[1], b[1]) + length};
            front_reach->push_back({lo[0], lo[1], hi[0], hi[1], 1.5 * length});
            front_grid->insert(static_cast<std::uint32_t>(e), lo, hi);
        }
        fill_size = SizeFunction::analytic(
            [base, front_grid, front_reach](double x, double y) {
                double s = base(x, y);
                const double p[2] = {x, y};
                front_grid->query(p, p, [&](std::uint32_t e) {
                    const auto& r = (*front_reach)[e];
                    if (x >= r[0] && y >= r[1] && x <= r[2] && y <= r[3]) s = std::max(s, r[4]);
                });
                return s;
            },
            "the larger of " + base.describe() + " and 1.5 times the last layer's edges");
    }
    tri::Cdt2Result fill_mesh = options.fill(filled, fill_size, options.max_steiner_points);
    if (front.empty()) {
        // No layers: the frontal mesh of the domain as it is.
        result.mesh = std::move(fill_mesh);
        counters.fill_triangles = counters.triangles = result.mesh.mesh.triangle_count();
        if (layered) {
            result.mesh.warnings.push_back(
                "advancing layers: the domain has no wall (no hole loop; the layers grow from "
                "the closed inner boundaries): no layers, the domain meshed by the fill alone");
        }
        return;
    }
    // Every stack stopped before its first layer: the walls are meshed by the fill alone, and
    // the user asked for layers (given with the mesh's warnings below).
    std::string no_layer_warning;
    if (layered && counters.stacks > 0 && counters.layer_points == 0 &&
        options.layers.method == LayerMethod2::TruncatedOMesh) {
        no_layer_warning =
            ("truncated O-mesh: no layer was built (of " + std::to_string(counters.stacks) +
             " columns, " + std::to_string(counters.stopped_unresolvable) +
             " cut where a layer point lay within rounding of the front, " +
             std::to_string(counters.omesh_removed_fold + counters.omesh_removed_overlap +
                            counters.omesh_removed_step) +
             " cells removed at folds, overlaps and steps; first height " +
             format_number(options.layers.first_height) + ")");
    } else if (layered && counters.stacks > 0 && counters.layer_points == 0) {
        no_layer_warning =
            ("advancing layers: no layer was built (of " + std::to_string(counters.stacks) +
             " stacks, " + std::to_string(counters.stopped_unresolvable) +
             " stopped as the first layer is thinner than 2^-44 of the walls' largest "
             "coordinate, " +
             std::to_string(counters.stopped_collision) + " by a collision, " +
             std::to_string(counters.stopped_size) + " by the size, " +
             std::to_string(counters.stopped_aspect_ratio) + " by the aspect ratio; first height " +
             format_number(options.layers.first_height) + ")");
    }
    if (fill_mesh.counters.intersections > 0 || fill_mesh.counters.vertices_on_segments > 0) {
        throw GeometryError(
            "advancing layers: the last layer's front crosses itself or the "
            "boundary (a bug)");
    }
    // Where stacks stop at different heights the front has steps, and the fill's constrained
    // Delaunay triangles beside them can be flat (up to 166 degrees on the three-element
    // airfoil): min-max swaps of the fill's unconstrained edges (exact compare_angles; the front
    // and the boundary are constrained, so they stay).
    counters.fill_min_max_swaps = tri::swap_edges_2d(fill_mesh.mesh, tri::MinMaxAngle{}).swaps;

    // Merge: the fill keeps every vertex of its input at its index, so the layers' vertices are
    // the same in both meshes.
    tri::Cdt2Result& mesh = result.mesh;
    mesh.mesh.xy = std::move(fill_mesh.mesh.xy);
    std::vector<VertIdx>& triangles = mesh.mesh.triangles;
    for (const Cell& c : region.cells) {
        if (c.is_quad()) ++counters.layer_quads;
        if (!c.is_quad()) {
            triangles.insert(triangles.end(), {c.v[0], c.v[1], c.v[2]});
        } else if (options.layers.quads) {
            result.quads.insert(result.quads.end(), c.v.begin(), c.v.end());
        } else {
            split_quad(c.v, mesh.mesh.xy, triangles);
        }
    }
    counters.layer_triangles = triangles.size() / 3;
    counters.fill_triangles = fill_mesh.mesh.triangle_count();
    triangles.insert(triangles.end(), fill_mesh.mesh.triangles.begin(),
                     fill_mesh.mesh.triangles.end());
    counters.triangles = triangles.size() / 3;
    counters.quads = result.quads.size() / 4;
    mesh.mesh.neighbors = triangle_neighbors(triangles);
    // The pieces: the fill's (the front left out: it lies inside), then the walls.
    std::unordered_set<std::uint64_t> walls_from_fill;
    for (std::size_t p = 0; p < fill_mesh.pieces.size() / 2; ++p) {
        const std::uint32_t segment = fill_mesh.piece_segment[p];
        std::uint32_t origin = fill_segment_origin[segment];
        if (origin == kNone && front_wall_origin[segment] != kNone) {
            origin = front_wall_origin[segment];
            walls_from_fill.insert(
                edge_key(fill_segments[2 * segment], fill_segments[2 * segment + 1]));
        }
        if (origin == kNone) continue;
        mesh.pieces.insert(mesh.pieces.end(),
                           {fill_mesh.pieces[2 * p], fill_mesh.pieces[2 * p + 1]});
        mesh.piece_segment.push_back(origin);
    }
    for (std::size_t p = 0; p < cdt.pieces.size() / 2; ++p) {
        const VertIdx a = cdt.pieces[2 * p], b = cdt.pieces[2 * p + 1];
        if (!region.is_wall_piece(a, b) || walls_from_fill.count(edge_key(a, b)) != 0) continue;
        mesh.pieces.insert(mesh.pieces.end(), {a, b});
        mesh.piece_segment.push_back(cdt.piece_segment[p]);
    }
    {
        std::unordered_map<std::uint64_t, std::uint8_t> piece_set;
        for (std::size_t p = 0; p < mesh.pieces.size() / 2; ++p) {
            const VertIdx a = mesh.pieces[2 * p], b = mesh.pieces[2 * p + 1];
            piece_set[(static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)] = 1;
        }
        mesh.mesh.constrained.assign(triangles.size(), 0);
        for (std::size_t e = 0; e < triangles.size(); ++e) {
            const VertIdx a = triangles[e], b = triangles[e - e % 3 + (e % 3 + 1) % 3];
            if (piece_set.count((static_cast<std::uint64_t>(std::min(a, b)) << 32) |
                                std::max(a, b)))
                mesh.mesh.constrained[e] = 1;
        }
    }
    mesh.input_vertex_count = cdt.input_vertex_count;
    mesh.merged_into = cdt.merged_into;
    mesh.warnings = cdt.warnings;
    if (!no_layer_warning.empty()) mesh.warnings.push_back(std::move(no_layer_warning));
    mesh.counters = cdt.counters;

    // The aspect ratio reached at the wall: a wall piece over the first height, where both of
    // its stacks have a layer.
    std::vector<std::uint32_t> layers_at(mesh.mesh.vertex_count(), 0);
    for (const auto& [wall_vertex, layers] : region.stack_layers)
        layers_at[wall_vertex] = std::max(layers_at[wall_vertex], layers);
    result.stack_layers = std::move(region.stack_layers);
    double best = 0;
    for (const std::vector<VertIdx>& loop : region.wall_loops) {
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const VertIdx a = loop[k], b = loop[(k + 1) % loop.size()];
            if (layers_at[a] == 0 || layers_at[b] == 0) continue;
            best = std::max(best, distance(&mesh.mesh.xy[2 * a], &mesh.mesh.xy[2 * b]) /
                                      options.layers.first_height);
        }
    }
    // Capped at 2^63: a first height of 1e-300 beside wall pieces of 0.01 would not convert.
    counters.max_wall_aspect_ratio = static_cast<std::uint64_t>(std::min(std::floor(best), 0x1p63));

    MixedMeshCheck2 check = check_mixed_mesh_2d(mesh.mesh.xy, triangles, result.quads, mesh.pieces);
    // A segment sticking into a hole stays a piece, in no cell.
    exempt_pieces_in_holes_2d(check, cdt, mesh.mesh.xy, mesh.pieces, mesh.piece_segment);
    if (!check.ok())
        throw GeometryError("advancing layers: the mixed mesh fails its check: " + check.summary());
}

}  // namespace exactmesh::generators::layer_mesh
