// SPDX-License-Identifier: MIT
// The registry of 2D Delaunay algorithms shared by the CLI, benches and tests.
#include "triangulation/delaunay_2d.hpp"

#include <string>

#include "predicates/errors.hpp"
#include "triangulation/bowyer_watson_2d.hpp"
#include "triangulation/green_sibson_2d.hpp"
#include "triangulation/tanemura_merriam_2d.hpp"

namespace exactmesh::triangulation {

Delaunay2Function delaunay_2d_algorithm(std::string_view name) {
    if (name == "bowyer-watson") return &bowyer_watson_2d;
    if (name == "green-sibson") return &green_sibson_2d;
    if (name == "tanemura-merriam") return &tanemura_merriam_2d;
    throw InputError("unknown 2D Delaunay algorithm '" + std::string(name) +
                     "' (known: bowyer-watson, green-sibson, tanemura-merriam)");
}

}  // namespace exactmesh::triangulation
