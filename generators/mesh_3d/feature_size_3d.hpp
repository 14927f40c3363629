// SPDX-License-Identifier: MIT
// Local feature sizes of a PLC's vertices, and a size graded down to them (issue 15).
// Frontal insertion places points at the size h only: a feature far finer than h (free
// vertices 1e-9 apart, a free vertex 1e-12 off an edge, two facets 1e-6 apart) keeps the flat
// tetrahedra the boundary recovery made beside it (1e-6 degrees in a unit cube at h = 0.1).
// As Gmsh grades its sizes from the boundary's points (Mesh.MeshSizeFromPoints and
// MeshSizeExtendFromBoundary), the size is lowered near each such feature:
//     h'(x) = min(h(x), min over the sources v of f_v + g |x - v|),
// f_v the vertex's local feature size: the distance to the nearest other vertex of the PLC
// (free vertices included) and to the nearest triangle of a facet that does not contain v
// (triangulate_facets_3d), at least 2^-44 of the coordinates' magnitude (the generators spare
// tetrahedra with edges below that fraction: no finer feature is chased); g the gradation
// (0.5, as the 2D graded_size_from_boundary). The sources: free vertices (on no facet) with
// f_v < h(v) / sqrt 2, and facet vertices with f_v < h(v) / 1024. A facet vertex's nearest
// feature on a tessellated curved surface is its neighbouring facets, the surface's own
// spacing, which boundary fitting follows already: grading from every vertex made frontal
// insertion on the wing at h = 0.1 2x slower with a smallest dihedral angle of 0.02 degrees
// instead of 4.0, and the ellipsoid 3.2x slower. A choice of where to put points, not a
// decision of geometry: computed in doubles on coordinates scaled by one power of two (exact),
// so the PLC scaled by 2^k gives the same feature sizes times 2^k, bit for bit.
// Cost: one nearest-vertex and one nearest-triangle query per vertex in bounding-box trees
// (triangle_tree_3d.hpp); each h'(x) one branch-and-bound query over the sources.
// Known limit: a vertex near an edge of its own facet (a slit in a facet) is not seen, since
// its own facets' triangles are left out (their interior distances are no feature).
#pragma once

#include <vector>

#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::generators {

/// f_v for every vertex of `plc` (validated: validate_plc_3d), in the input's units.
std::vector<double> local_feature_sizes_3d(const triangulation::Plc3& plc);

/// h' above. `gradation` > 0 and finite; `size` defined. The description names both.
/// With no source, the result is `size` itself.
/// @throws InputError for a bad gradation or an undefined size.
SizeFunction3 feature_graded_size_3d(const triangulation::Plc3& plc, const SizeFunction3& size,
                                     double gradation = 0.5);

}  // namespace exactmesh::generators
