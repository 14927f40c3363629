// SPDX-License-Identifier: MIT
// The constrained-edge flags of a triangulation read from outside (a file, a Python array):
// Triangulation2::constrained rebuilt from a list of edges, for the exact checks of constrained
// and conforming meshes (checks/check_constrained_2d, check_conforming_2d).
#pragma once

#include <span>

#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// Sets mesh.constrained (3·#T) to 1 on every side of every triangle whose two vertices are the
/// two ends of an edge of `edges` (2·#E vertex indices, either direction), 0 elsewhere.
void flag_constrained_edges_2d(Triangulation2& mesh, std::span<const VertIdx> edges);

}  // namespace exactmesh::triangulation
