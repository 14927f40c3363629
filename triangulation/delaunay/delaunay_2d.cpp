// SPDX-License-Identifier: MIT
// The registry of 2D Delaunay algorithms shared by the CLI, benches and tests.
#include "triangulation/delaunay/delaunay_2d.hpp"

#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/delaunay/tanemura_merriam_2d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The registry: one line per algorithm.
constexpr Delaunay2Algorithm kAlgorithms[] = {
    {"bowyer-watson", &bowyer_watson_2d,
     "Bowyer-Watson: the cavity of triangles whose circumcircle holds the point, starred from it"},
    {"green-sibson", &green_sibson_2d,
     "Green-Sibson: the point splits its triangle (or edge), then Lawson flips"},
    {"tanemura-merriam", &tanemura_merriam_2d,
     "Tanemura-Merriam: a front over the points, each edge closed by the point of smallest "
     "circumcircle"},
};

}  // namespace

std::span<const Delaunay2Algorithm> delaunay_2d_algorithms() {
    return kAlgorithms;
}

Delaunay2Function delaunay_2d_algorithm(std::string_view name) {
    return find_delaunay_algorithm<Delaunay2Function>(kAlgorithms, name, "2D Delaunay algorithm");
}

}  // namespace exactmesh::triangulation
