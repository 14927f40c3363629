// SPDX-License-Identifier: MIT
// The registry of 3D Delaunay algorithms shared by the CLI, benches and tests.
#include "triangulation/delaunay_3d.hpp"

#include <string>

#include "triangulation/bowyer_watson_3d.hpp"
#include "triangulation/green_sibson_3d.hpp"

namespace exactmesh::triangulation {

Delaunay3Function delaunay_3d_algorithm(std::string_view name) {
    if (name == "bowyer-watson") return &bowyer_watson_3d;
    if (name == "green-sibson") return &green_sibson_3d;
    throw InputError("unknown 3D Delaunay algorithm '" + std::string(name) +
                     "' (known: bowyer-watson, green-sibson)");
}

}  // namespace exactmesh::triangulation
