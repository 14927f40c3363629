// SPDX-License-Identifier: MIT
// The registry of 3D Delaunay algorithms shared by the CLI, benches and tests.
#include "triangulation/delaunay/delaunay_3d.hpp"

#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/green_sibson_3d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The registry: one line per algorithm.
constexpr Delaunay3Algorithm kAlgorithms[] = {
    {"bowyer-watson", &bowyer_watson_3d,
     "Bowyer-Watson: the cavity of tetrahedra whose circumsphere holds the point, starred from it"},
    {"green-sibson", &green_sibson_3d,
     "Green-Sibson (Joe): the point splits its tetrahedron, face or edge, then 2-3, 3-2 and 4-4 "
     "flips"},
};

}  // namespace

std::span<const Delaunay3Algorithm> delaunay_3d_algorithms() {
    return kAlgorithms;
}

Delaunay3Function delaunay_3d_algorithm(std::string_view name) {
    return find_delaunay_algorithm<Delaunay3Function>(kAlgorithms, name, "3D Delaunay algorithm");
}

}  // namespace exactmesh::triangulation
