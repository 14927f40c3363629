// SPDX-License-Identifier: MIT
// PSLG fixtures shared by the 2D triangulation and generator tests: an owning Input (vertices,
// segments, hole points, regions) that views as a triangulation::Pslg, built from a sample
// domain, from a closed polygon or by appending closed loops, and the unit square with a square
// hole and a slit. Test support; depends on triangulation/ only (from_domain takes any
// generators::DomainPslg-like value, so the triangulation tests need no generator header).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::testing {

/// An owning PSLG: 2·#V coordinates, 2·#S endpoint indices, 2·#H hole points and 4·#R regions
/// (x, y, attribute, maximum area); pslg() views it (valid while the Input lives).
struct Input {
    std::vector<double> xy;
    std::vector<std::uint32_t> segments;
    std::vector<double> holes;
    std::vector<double> regions;
    triangulation::Pslg pslg() const { return {xy, segments, holes, regions}; }
};

/// The input of a generators::DomainPslg (sample_domains.hpp): its vertices, segments and
/// holes, no regions.
template <class Domain>
Input from_domain(const Domain& d) {
    return {d.xy, d.segments, d.holes, {}};
}

/// A closed polygon (vertices in order) appended to `in`: its vertices after in's, segments
/// from each to the next and from the last to the first.
inline void add_loop(Input& in, const std::vector<double>& xy) {
    const auto first = static_cast<std::uint32_t>(in.xy.size() / 2);
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    in.xy.insert(in.xy.end(), xy.begin(), xy.end());
    for (std::uint32_t k = 0; k < n; ++k)
        in.segments.insert(in.segments.end(), {first + k, first + (k + 1) % n});
}

/// A closed polygon's input (vertices in order).
inline Input polygon(const std::vector<double>& xy) {
    Input in;
    add_loop(in, xy);
    return in;
}

/// The unit square with a square hole [0.4, 0.6]^2 and a slit from (0.1, 0.5) to (0.3, 0.5):
/// vertices 0-3 the square, 4-7 the hole, 8-9 the slit; hole point (0.5, 0.5).
inline Input square_with_hole_and_slit() {
    Input in;
    add_loop(in, {0, 0, 1, 0, 1, 1, 0, 1});
    add_loop(in, {0.4, 0.4, 0.6, 0.4, 0.6, 0.6, 0.4, 0.6});
    in.xy.insert(in.xy.end(), {0.1, 0.5, 0.3, 0.5});
    in.segments.insert(in.segments.end(), {8, 9});
    in.holes = {0.5, 0.5};
    return in;
}

}  // namespace exactmesh::testing
