// SPDX-License-Identifier: MIT
// The domain's boundary as the frontal and quadtree generators start from it (issue 6):
//  - the constrained Delaunay triangulation of the input PSLG (duplicates merged, crossing
//    segments split, exterior and holes removed as Triangle's -p does): the domain itself, kept
//    for exact point-in-domain queries;
//  - its boundary pieces split so that each is about as long as the size function wants: the
//    integral of ds / s over each piece is equal along a piece of the input and at most 1 (whole
//    pieces), new points by linear interpolation, rounded, then kept exactly on the piece or
//    strictly inside a domain triangle beside it (moved by up to 3 units in the last place when
//    they rounded outside), so that the pieces always form a valid PSLG: two pieces meet only at
//    a shared end, whatever features at the resolution of doubles the input has. Beside a sliver
//    (a vertex within 3 units in the last place of a piece) the piece bends at that vertex, the
//    sliver left out; a point that has no place is left out (a longer piece there);
//  - the directed front: every piece with the domain on its left (both directions for a slit:
//    a segment with the domain on both sides); every new point lies in the domain.
// Also discretize_curve, the same spacing rule along any parametric curve (sample domains).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/locate_2d.hpp"

namespace exactmesh::generators {

/// Exact point-in-domain queries over a triangulation of the domain: the shared bucket-grid
/// locator (triangulation/mesh/locate_2d.hpp); locate(mesh, x, y) is a triangle containing (x, y)
/// (closed), the lowest-numbered one, or kNone.
using DomainLocator2 = triangulation::TriangleLocator2;

struct DomainBoundary2 {
    /// The constrained Delaunay triangulation of the input PSLG (constrained_delaunay_2d:
    /// duplicates merged, crossings split, exterior and holes removed): the domain.
    triangulation::Cdt2Result cdt;
    /// 2·#V: cdt.mesh.xy (input vertices keep their numbers, crossings after them), then the
    /// points added on the boundary so that each boundary edge is about the size's length.
    std::vector<double> xy;
    std::uint32_t input_vertex_count = 0;
    /// 2·#E directed boundary edges with the domain on their left (a slit gives both
    /// directions); the initial front of the frontal generators.
    std::vector<triangulation::VertIdx> front;
    std::vector<std::uint32_t> front_segment;  ///< #E: the input segment of each front edge
    /// 2·#P: the boundary pieces (each once, undirected) and their input segment: each piece
    /// a - b of cdt is a chain of them from a to b through new points (and, bent around a
    /// sliver, through the sliver's third vertex); pieces meet only at shared ends (exact).
    std::vector<triangulation::VertIdx> pieces;
    std::vector<std::uint32_t> piece_segment;
    /// 2·#S: the input's segments (its vertex numbers, 0-based), which piece_segment names, and
    /// the input's first index (messages).
    std::vector<triangulation::VertIdx> input_segments;
    std::uint32_t first_index = 0;
    /// The vertices of the domain on no front edge (ascending): input vertices strictly inside
    /// the domain with no segment at them. Every generator keeps them; the advancing fronts
    /// treat them as front vertices without edges (candidates, and points no triangle may
    /// cover) until a triangle takes them in.
    std::vector<triangulation::VertIdx> free_vertices;
    /// Over cdt.mesh (built last: the boundary must not move afterwards).
    DomainLocator2 locator;
};

/// The discretization's refusal of a size asking for too many boundary pieces: more than 2^30
/// on one curve or segment, more than 2^24 samples to integrate, or more new points than the
/// generator's budget. An InputError naming the densest place; a caller that made the size
/// itself (global remeshing under a vertex budget) ends at its budget on it instead of passing
/// it on as the user's bad input.
class BoundaryBudgetError : public InputError {
  public:
    using InputError::InputError;
};

/// @param size the target edge length (unbounded: the pieces of the CDT are kept as they are).
/// @throws InputError as constrained_delaunay_2d; InputError when the segments enclose no region.
DomainBoundary2 discretize_domain_boundary(const triangulation::Pslg& pslg,
                                           const SizeFunction& size,
                                           const triangulation::Cdt2Options& cdt = {});
/// The same from the domain's triangulation, built once (MeshDomain2::triangulation, copied).
/// @param max_points the generator's Steiner budget (0: none but the 2^30 pieces and 2^24
///        samples per segment): a size asking for more new boundary points is refused with a
///        BoundaryBudgetError as soon as the sampling's integral passes it.
DomainBoundary2 discretize_domain_boundary(const MeshDomain2& domain, const SizeFunction& size,
                                           std::uint64_t max_points = 0);

/// A mesh built over the boundary's points and pieces (a new PSLG: the frontal and metric
/// generators) put back into the input's terms: its pieces' input segments, its vertex count, its
/// merged duplicates and warnings, and its constrained triangulation's counters (the mesh's own
/// Delaunay flips added to them).
/// @throws GeometryError when a piece's end lies off its input segment by more than its own
///         rounding (within_rounding_of_segment): the triangulation of the boundary's pieces
///         bent one at a vertex that doubles cannot place on the segment, and the exact checks
///         would reject the segment's chain.
void restore_input_terms(const DomainBoundary2& boundary, triangulation::Cdt2Result& mesh);

/// The size along one piece a - b of the domain's boundary: a size that depends on the
/// direction as well as the position (a metric field's length along the piece, issue 14).
using PieceSizeFunction = std::function<SizeFunction(const double* a, const double* b)>;
/// The same discretization with the size of each piece given by piece_size(a, b) (a and b its
/// ends' coordinates); the isotropic overload passes the same size for every piece.
DomainBoundary2 discretize_domain_boundary(const MeshDomain2& domain,
                                           const PieceSizeFunction& piece_size,
                                           std::uint64_t max_points = 0);

/// Per vertex of a domain's CDT (constrained_delaunay_2d with the exterior removed): the mean
/// length of the boundary pieces at it (of all its edges where no piece ends there; 0 for a
/// vertex no triangle uses), and its shortest edge (infinity when it has none). Lengths are
/// scale-free (predicates::scale_free_norm): exact under 2^k scaling, no overflow at 2^600.
struct BoundarySpacing {
    std::vector<double> mean;
    std::vector<double> shortest;
};
BoundarySpacing boundary_spacing(const triangulation::Cdt2Result& domain);

/// The input's own spacing, ungraded (Gmsh's "extend from the boundary"; the generators' default
/// is graded_size_from_boundary, generators/boundary/graded_boundary_size_2d.hpp):
/// the domain's constrained Delaunay triangulation as a background mesh
/// (SizeFunction::background_mesh), each vertex sized by the mean length of the pieces at it (of
/// its edges when no piece ends there), linear in between, so the input's own spacing sets the
/// mesh's.
/// @throws InputError as constrained_delaunay_2d; InputError when the segments enclose no region.
SizeFunction size_from_boundary(const triangulation::Pslg& pslg,
                                const triangulation::Cdt2Options& cdt = {});

/// The number of triangles the size function asks for on the domain (the generators' automatic
/// budgets): over the triangles of boundary.cdt, area / (area of an equilateral triangle at the
/// smallest size sampled at the corners and the centroid), a triangle split in four while it is
/// wider than 8 such sizes and holds more than 16 (at most 8 levels), so that a small size inside
/// a large triangle of the CDT is not missed, and none split further after 2^18 size
/// evaluations. A rough estimate (double precision), 0 for an unbounded size.
double expected_triangle_count(const DomainBoundary2& boundary, const SizeFunction& size);

/// A split point of the input segment s0 - s1 that the exact checks accept on its chain
/// (predicates::within_rounding_of_segment: 2^-40 of the point's own magnitude): p itself when it
/// is; else the point of the line s0 - s1 at p's coordinate along the segment's longer axis, the
/// other coordinate correctly rounded (predicates::segment_intersection with the axis-parallel
/// segment there), when that one is; else nothing. An interpolated point near a coordinate's
/// zero is the case: (2.0e-15, -4.0e-15) for the middle (0, 0) of (2, -3) - (-2, 3), off the
/// line by far more than its own rounding, becomes (2.0e-15, -3.0e-15).
std::optional<std::array<double, 2>> chain_point(const std::array<double, 2>& p, const double* s0,
                                                 const double* s1);

/// 2·#P: each boundary piece's input segment's two input vertices (numbers in boundary.xy): the
/// lines a triangulation whose segments are the pieces measures its chain rule against
/// (triangulation::Pslg::segment_lines), so that it bends a piece only where the input
/// segment's check accepts the bend.
std::vector<triangulation::VertIdx> piece_lines(const DomainBoundary2& boundary);

/// True when (x, y) lies in the domain (closed), by exact orient2d tests on the CDT.
bool in_domain(const DomainBoundary2& boundary, double x, double y);

/// Points of curve(u), u in [u0, u1], both ends included, spaced so that the integral of
/// ds / size between neighbours is equal and at most 1 (at least min_pieces pieces); the
/// integral is taken over a polyline of at least 8 samples per piece. An unbounded size gives
/// min_pieces pieces equal in u.
std::vector<std::array<double, 2>> discretize_curve(const Curve2& curve, double u0, double u1,
                                                    const SizeFunction& size, int min_pieces);
/// The parameters of discretize_curve's points (its points are curve(u) for these u, bit for bit).
std::vector<double> discretize_curve_parameters(const Curve2& curve, double u0, double u1,
                                                const SizeFunction& size, int min_pieces);

}  // namespace exactmesh::generators
