// SPDX-License-Identifier: MIT
// Delaunay point-insertion adaptation in 3D (see insertion_adaptation_3d.hpp).
#include "generators/adaptation/insertion_adaptation_3d.hpp"

#include <algorithm>

#include "base/errors.hpp"
#include "generators/adaptation/field_transfer.hpp"
#include "generators/adaptation/laplacian_smoothing_3d.hpp"
#include "generators/adaptation/weighted_movement.hpp"
#include "generators/topology/mesh_edges.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::generators {

using predicates::Sign;
using triangulation::kNone;
using triangulation::VertIdx;

namespace {

// The hull faces of a mesh as vertex triples (each as kFaceVertex orders it).
std::vector<VertIdx> hull_faces(const triangulation::Tetrahedralization3& mesh) {
    std::vector<VertIdx> faces;
    for (std::size_t t = 0; t < mesh.tet_count(); ++t)
        for (unsigned k = 0; k < 4; ++k)
            if (mesh.neighbors[4 * t + k] == kNone)
                for (unsigned i = 0; i < 3; ++i)
                    faces.push_back(mesh.tets[4 * t + triangulation::kFaceVertex[k][i]]);
    return faces;
}

}  // namespace

AdaptiveMesh3 make_adaptive_mesh_3d(triangulation::Tetrahedralization3 mesh) {
    AdaptiveMesh3 state;
    for (const VertIdx v : hull_faces(mesh))
        state.hull_faces.insert(state.hull_faces.end(), mesh.point(v), mesh.point(v) + 3);
    state.fixed_vertices = mesh.vertex_count();
    state.mesh = std::move(mesh);
    return state;
}

bool insertion_cycle_3d(AdaptiveMesh3& state, const AdaptationOptions& options,
                        const FieldSource& field, InsertionCounters3& counters) {
    const triangulation::Tetrahedralization3& mesh = state.mesh;
    const detail::CycleFlags marked =
        detail::cycle_flags(options, mesh.xyz, 3, mesh.tets, state.values);
    if (marked.flagged == 0) return false;
    const std::vector<VertIdx>& edges = marked.edges;
    const std::vector<std::uint8_t>& flags = marked.flags;

    // The hull faces at each hull edge, to keep boundary midpoints in their faces' planes.
    const std::vector<VertIdx> hull = hull_faces(mesh);
    std::vector<std::uint32_t> hull_edge_faces;  // pairs (edge, face)
    for (std::size_t f = 0; f < hull.size() / 3; ++f)
        for (unsigned i = 0; i < 3; ++i) {
            const std::uint32_t e =
                find_mesh_edge(edges, hull[3 * f + i], hull[3 * f + (i + 1) % 3]);
            hull_edge_faces.insert(hull_edge_faces.end(), {e, static_cast<std::uint32_t>(f)});
        }
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_edge;
    for (std::size_t i = 0; i < hull_edge_faces.size(); i += 2)
        by_edge.emplace_back(hull_edge_faces[i], hull_edge_faces[i + 1]);
    std::sort(by_edge.begin(), by_edge.end());

    std::vector<double> xyz = mesh.xyz;
    std::vector<double> first_values = state.values;
    std::uint64_t inserted = 0, boundary = 0, skipped = 0;
    for (std::size_t e = 0; e < flags.size(); ++e) {
        if (!flags[e]) continue;
        const VertIdx a = edges[2 * e], b = edges[2 * e + 1];
        double m[3];
        bool same_a = true, same_b = true;
        for (unsigned c = 0; c < 3; ++c) {
            m[c] = 0.5 * mesh.xyz[3 * std::size_t{a} + c] + 0.5 * mesh.xyz[3 * std::size_t{b} + c];
            same_a = same_a && m[c] == mesh.xyz[3 * std::size_t{a} + c];
            same_b = same_b && m[c] == mesh.xyz[3 * std::size_t{b} + c];
        }
        if (same_a || same_b) continue;
        bool on_hull = false, in_planes = true;
        auto it = std::lower_bound(
            by_edge.begin(), by_edge.end(),
            std::pair<std::uint32_t, std::uint32_t>{static_cast<std::uint32_t>(e), 0});
        for (; it != by_edge.end() && it->first == e; ++it) {
            on_hull = true;
            const VertIdx* f = &hull[3 * std::size_t{it->second}];
            if (predicates::orient3d(mesh.point(f[0]), mesh.point(f[1]), mesh.point(f[2]), m) !=
                Sign::Zero)
                in_planes = false;
        }
        if (!in_planes) {
            ++skipped;
            continue;
        }
        xyz.insert(xyz.end(), m, m + 3);
        first_values.push_back(0.5 * state.values[a] + 0.5 * state.values[b]);
        ++inserted;
        boundary += on_hull ? 1 : 0;
    }
    if (inserted == 0) return false;
    triangulation::Delaunay3Result result = triangulation::delaunay_3d_algorithm("green-sibson")(
        xyz, triangulation::Delaunay3Options{});
    if (result.coplanar)
        throw GeometryError("insertion adaptation 3D: the points became coplanar (a bug)");
    if (result.counters.duplicates != 0) {
        // An input's repeated point stays unused, merged again; only a vertex the old mesh
        // used, or a new midpoint, may never be merged.
        std::vector<std::uint8_t> used(mesh.vertex_count(), 0);
        for (const VertIdx v : mesh.tets) used[v] = 1;
        for (std::size_t v = 0; v < result.merged_into.size(); ++v)
            if (result.merged_into[v] != v && (v >= used.size() || used[v] != 0))
                throw GeometryError(
                    "insertion adaptation 3D: a midpoint repeated a vertex (a bug)");
    }
    AdaptiveMesh3 next;
    next.mesh = std::move(result.mesh);
    next.fixed_vertices = state.fixed_vertices;
    next.hull_faces = std::move(state.hull_faces);
    const std::vector<double> before_smoothing = next.mesh.xyz;
    if (options.smoothing_sweeps > 0) {
        SmoothingOptions3 smoothing;
        smoothing.iterations = options.smoothing_sweeps;
        const SmoothingCounters3 c =
            laplacian_smoothing_3d(next.mesh, next.fixed_vertices, smoothing);
        counters.smoothing_moves += c.moves;
        counters.smoothing_undone += c.undone + c.undone_worse;
    }
    const auto set_field = [&] {
        if (field.analytic != nullptr) {
            next.values = sample_field(*field.analytic, next.mesh.xyz, 3, field.t);
            return;
        }
        next.values =
            transfer_field_3d(mesh.xyz, mesh.tets, mesh.neighbors, state.values, next.mesh.xyz);
        keep_values_of_unmoved(next.values, next.mesh.xyz, before_smoothing, 3, first_values);
    };
    set_field();
    if (options.movement_sweeps > 0) {
        WeightedMovementOptions movement;
        movement.sweeps = options.movement_sweeps;
        movement.strength = options.movement_strength;
        const WeightedMovementCounters c = weighted_movement_3d(
            next.mesh,
            mesh_vertex_indicator(options.indicator, next.mesh.xyz, 3, next.mesh.tets, next.values),
            next.fixed_vertices, movement);
        counters.movement_moves += c.moves;
        counters.movement_undone += c.undone + c.undone_worse;
        set_field();
    }
    ++counters.cycles;
    counters.flagged_edges += marked.flagged;
    counters.closure_edges += marked.closure;
    counters.inserted += inserted;
    counters.boundary_points += boundary;
    counters.off_plane_skipped += skipped;
    state = std::move(next);
    return true;
}

std::string check_adaptive_mesh_3d(const AdaptiveMesh3& state, std::span<const double> fixed_xyz) {
    const triangulation::Check3Report report = triangulation::check_tetrahedralization_3d(
        state.mesh.xyz, state.mesh.tets, state.mesh.neighbors);
    if (!report.ok) return report.problem;
    for (std::size_t i = 0; i < fixed_xyz.size(); ++i)
        if (state.mesh.xyz[i] != fixed_xyz[i])
            return "input vertex " + std::to_string(i / 3) + " moved";
    const std::vector<VertIdx> hull = hull_faces(state.mesh);
    const std::size_t planes = state.hull_faces.size() / 9;
    std::size_t last = 0;
    for (std::size_t f = 0; f < hull.size() / 3; ++f) {
        bool found = false;
        for (std::size_t j = 0; j < planes && !found; ++j) {
            const std::size_t p = (last + j) % planes;
            const double* q = &state.hull_faces[9 * p];
            bool coplanar = true;
            for (unsigned i = 0; i < 3 && coplanar; ++i)
                coplanar = predicates::orient3d(q, q + 3, q + 6,
                                                state.mesh.point(hull[3 * f + i])) == Sign::Zero;
            if (coplanar) {
                found = true;
                last = p;
            }
        }
        if (!found)
            return "hull face " + std::to_string(f) + " lies in no plane of the input's hull";
    }
    return "";
}

}  // namespace exactmesh::generators
