// SPDX-License-Identifier: MIT
// Degenerate PSLGs in the unit square that several 2D generator tests mesh: input vertices on
// the sides, duplicate vertices and segments, a tiny square hole, a vertex a few ulps off a skew
// segment. Test support (depends on pslg_fixtures_2d.hpp only).
#pragma once

#include <cmath>
#include <vector>

#include "tests/support/pslg_fixtures_2d.hpp"

namespace exactmesh::testing {

/// The unit square with collinear input vertices on its sides (4-6 on the bottom side at 0.25,
/// 0.5, 0.75; 7 at (1, 0.3) on the right side): segments are split there.
inline Input square_with_points_on_sides() {
    Input in = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    in.xy.insert(in.xy.end(), {0.25, 0, 0.5, 0, 0.75, 0, 1, 0.3});
    return in;
}

/// The unit square with duplicate vertices (4, 5 repeat 1, 2), a duplicated segment (4-5, the
/// side 1-2 through the copies) and a repeated one (0-1).
inline Input square_with_duplicates() {
    Input in = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    in.xy.insert(in.xy.end(), {1, 0, 1, 1});
    in.segments.insert(in.segments.end(), {4, 5, 0, 1});
    return in;
}

/// The unit square with a tiny square hole of side 1e-4 at (0.3, 0.3): vertices 4-7.
inline Input square_with_tiny_hole() {
    Input in = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    const double a = 0.3, w = 1e-4;
    in.xy.insert(in.xy.end(), {a, a, a + w, a, a + w, a + w, a, a + w});
    in.segments.insert(in.segments.end(), {4, 5, 5, 6, 6, 7, 7, 4});
    in.holes = {a + w / 2, a + w / 2};
    return in;
}

/// A quadrilateral with a free vertex a few ulps off its skew side (0, 0) - (1, 0.3).
inline Input vertex_ulps_off_a_segment() {
    Input in = polygon({0, 0, 1, 0.3, 1, 1, 0, 1});
    in.xy.insert(in.xy.end(), {0.5, std::nextafter(0.15, 1.0)});
    return in;
}

/// A named input of degenerate_pslgs().
struct NamedInput {
    const char* name;
    Input in;
};

/// The four above by name, the tiny hole with a free vertex 1e-6 above the bottom side.
inline std::vector<NamedInput> degenerate_pslgs() {
    std::vector<NamedInput> cases;
    // Collinear points on the boundary (input vertices on the square's sides: split there).
    cases.push_back({"points on segments", square_with_points_on_sides()});
    // Duplicate vertices, a duplicated segment and one given through the copies.
    cases.push_back({"duplicates", square_with_duplicates()});
    // A tiny square hole (1e-4) next to a big domain, and a free vertex 1e-6 above a segment.
    {
        Input in = square_with_tiny_hole();
        in.xy.insert(in.xy.end(), {0.6, 1e-6});
        cases.push_back({"tiny features", in});
    }
    // A vertex a few ulps off a skew segment's line (0, 0) - (1, 0.3).
    cases.push_back({"vertex ulps off a segment", vertex_ulps_off_a_segment()});
    return cases;
}

}  // namespace exactmesh::testing
