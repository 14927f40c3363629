// SPDX-License-Identifier: MIT
// The adaptive state of a 2D mesh and its exact check (see adaptive_mesh_2d.hpp).
#include "generators/adaptation/adaptive_mesh_2d.hpp"

#include <cmath>

#include "base/number_text.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace exactmesh::generators {

using triangulation::VertIdx;

namespace {

// The fraction of the way from a to b at p, by the longer axis of a - b.
double chord_fraction(const double* a, const double* b, const double* p) {
    const int axis = std::fabs(b[0] - a[0]) >= std::fabs(b[1] - a[1]) ? 0 : 1;
    if (b[axis] == a[axis]) return 0;
    return (p[axis] - a[axis]) / (b[axis] - a[axis]);
}

}  // namespace

AdaptiveMesh2 make_adaptive_mesh_2d(triangulation::Cdt2Result result,
                                    std::span<const double> segment_xy,
                                    std::span<const VertIdx> segments,
                                    std::span<const double> holes, std::vector<Curve2> curves,
                                    std::span<const SegmentCurve> segment_curves) {
    AdaptiveMesh2 state;
    state.fixed_vertices = result.input_vertex_count;
    state.holes.assign(holes.begin(), holes.end());
    state.curves = std::move(curves);
    const std::size_t piece_count = result.pieces.size() / 2;
    state.pieces.reserve(piece_count);
    for (std::size_t p = 0; p < piece_count; ++p) {
        CurvedPiece2 piece{result.pieces[2 * p], result.pieces[2 * p + 1]};
        const std::uint32_t s = result.piece_segment[p];
        if (s < segment_curves.size() && segment_curves[s].curve != kStraightSide) {
            const SegmentCurve& c = segment_curves[s];
            const double* sa = &segment_xy[2 * std::size_t{segments[2 * s]}];
            const double* sb = &segment_xy[2 * std::size_t{segments[2 * s + 1]}];
            const auto parameter = [&](VertIdx v) {
                if (v == segments[2 * s]) return c.u0;
                if (v == segments[2 * s + 1]) return c.u1;
                return c.u0 + chord_fraction(sa, sb, result.mesh.point(v)) * (c.u1 - c.u0);
            };
            piece.curve = c.curve;
            piece.ua = parameter(piece.a);
            piece.ub = parameter(piece.b);
        }
        state.pieces.push_back(piece);
    }
    state.mesh = std::move(result.mesh);
    state.on_curve.assign(state.mesh.vertex_count(), 0);
    return state;
}

std::string check_adaptive_mesh_2d(const AdaptiveMesh2& state, std::span<const double> fixed_xy,
                                   bool delaunay) {
    std::vector<VertIdx> pieces;
    pieces.reserve(2 * state.pieces.size());
    for (const CurvedPiece2& p : state.pieces) pieces.insert(pieces.end(), {p.a, p.b});
    const triangulation::CheckReport report = triangulation::detail::check_constrained_mesh_2d(
        state.mesh, state.mesh.vertex_count(), pieces, pieces, {}, delaunay);
    if (!report.ok) return report.problem;
    for (std::size_t i = 0; i < fixed_xy.size(); ++i)
        if (state.mesh.xy[i] != fixed_xy[i])
            return "input vertex " + std::to_string(i / 2) + " moved";
    for (const CurvedPiece2& p : state.pieces) {
        if (p.curve == kStraightSide) continue;
        for (const auto& [v, u] : {std::pair{p.a, p.ua}, std::pair{p.b, p.ub}}) {
            if (v >= state.on_curve.size() || state.on_curve[v] == 0) continue;
            const std::array<double, 2> c = state.curves[p.curve](u);
            if (c[0] != state.mesh.xy[2 * v] || c[1] != state.mesh.xy[2 * v + 1])
                return "boundary vertex " + std::to_string(v) + " " +
                       format_point(state.mesh.point(v)) + " is not on its curve at parameter " +
                       format_number(u) + " " + format_point(c.data());
        }
    }
    return "";
}

}  // namespace exactmesh::generators
