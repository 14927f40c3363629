// SPDX-License-Identifier: MIT
// Advancing layers: a boundary-layer mesh of thin cells along the walls (issue 14, "hybrid and
// semi-structured meshes; advancing layers") [Pirzadeh96: "Three-dimensional unstructured
// viscous grids by the advancing-layers method", AIAA J. 34(1); Garimella-Shephard00: "Boundary
// layer mesh generation for viscous flow simulations", IJNME 49].
//  - Walls: every hole loop of the domain (a boundary loop of its constrained triangulation
//    that runs clockwise with the domain on its left: the closed inner boundaries); the outer
//    boundary and interior segments are obstacles, never walls. The built-in airfoil domains
//    carry no markers: their walls are their elements.
//  - One stack per wall vertex along the area (length) weighted mean of its segments' normals;
//    at a convex corner (the domain's angle above 180 degrees, normals turning by more than 45
//    degrees) a fan of stacks spreads over the exterior angle; at a concave one the unit
//    normals are merged into their bisector. Layer k + 1 lies at height h (1 + g + ... + g^k)
//    from the wall vertex p, the point p + t d rounded once (fma); the directions d are
//    smoothed from layer to layer with their neighbours, none at the wall, more away from it.
//  - A stack stops when its cell's aspect ratio (tangential spacing over the next layer's
//    thickness) reaches 1, where the next layer would be thicker than a given size, after
//    max_layers, when a neighbour stopped more than two layers below (the step stays at most
//    two triangles), or when its new segments or cells would cross or touch anything already
//    there, or its normal, extended by one more layer, would (exact orient2d on every pair:
//    layer, normal and boundary segments; cells strictly convex and empty of other vertices).
//  - The layer cells are kept as quadrilaterals or split by the diagonal with the smaller
//    largest angle (exact compare_angles); steps between stacks are closed by triangles.
//  - The rest of the domain is meshed by the fill generator (frontal) from the last layer:
//    the outer edges of the layers enclose a new hole, their length the size along them, so
//    that the front is never split and the two meshes share its vertices; then min-max swaps
//    of the fill's unconstrained edges (exact compare_angles) remove the flat triangles the
//    fill's constrained Delaunay triangles make beside steps of the front (three-element
//    airfoil, bench size: 29 triangles above 150 degrees before, none after).
// Invariants: check_mixed_mesh_2d holds on the result (checked before returning). Cost: O(S L)
// for S stacks and L layers (a bucket grid keeps the crossing tests local), plus the fill.
// Predicates: orient2d, direction_dot_sign, compare_angles, compare_lengths.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// How the layers are built: advancing layers (stacks stopped one by one), or the truncated
/// structured O-mesh (truncated_omesh_2d.hpp: a ring of normal lines per wall, truncated
/// where its cells turn isotropic, the overlaps between rings removed).
enum class LayerMethod2 : std::uint8_t { AdvancingLayers, TruncatedOMesh };

/// `--layers FIRST_HEIGHT,GROWTH[,MAX_LAYERS]`, `--quads` and `--o-mesh`.
struct LayerParameters2 {
    double first_height = 0;        ///< thickness of the first layer; finite and > 0 (0: no layers)
    double growth = 1.2;            ///< ratio of consecutive thicknesses; finite, in [1, 10]
    std::uint32_t max_layers = 60;  ///< in [1, kMaxLayers]
    bool quads = false;  ///< keep the layer quadrilaterals (else each split in two triangles)
    LayerMethod2 method = LayerMethod2::AdvancingLayers;
};

inline constexpr std::uint32_t kMaxLayers = 1000;

/// @throws InputError naming the bad value: a height not finite and > 0, a growth below 1 (or
///         above 10, or not finite), a layer count outside [1, kMaxLayers].
void validate_layer_parameters(const LayerParameters2& layers);

/// Parses "FIRST_HEIGHT,GROWTH[,MAX_LAYERS]" (max_layers keeps its default when omitted) and
/// validates it. @throws InputError naming the text and what is wrong with it.
LayerParameters2 parse_layer_parameters(std::string_view text);

/// The generator that meshes the rest of the domain from the last layer (the frontal Delaunay
/// generator in the registry; the advancing-front Delaunay one would do): given the fill's
/// domain (the outer boundary and the front; the layers a hole), its size and a Steiner point
/// budget (0: automatic), the mesh with every input vertex at its index and the pieces carrying
/// their input segment. Passed in, so that the layers depend on no generator (generators/
/// families: stretched comes before mesh_2d, whose registry wires the two).
using LayerFill2 = triangulation::Cdt2Result (*)(const MeshDomain2& domain,
                                                 const SizeFunction& size,
                                                 std::uint64_t max_steiner_points);

struct AdvancingLayersOptions2 {
    LayerParameters2 layers;
    LayerFill2 fill = nullptr;  ///< required
    /// The size of the fill (bounded: the user's --size); everywhere at least the length of the
    /// last layer's edges near them, so that the front is kept as it is. Unbounded: the fill's
    /// boundary spacing graded away from it (graded_size_from_boundary).
    SizeFunction size;
    triangulation::Cdt2Options cdt;
    std::uint64_t max_steiner_points = 0;  ///< the fill's budget (FrontalDelaunayOptions2)
};

struct AdvancingLayersCounters2 {
    std::uint64_t wall_loops = 0;
    std::uint64_t wall_vertices = 0;
    std::uint64_t stacks = 0;          ///< wall vertices plus the extra stacks of the fans
    std::uint64_t fan_corners = 0;     ///< convex corners given a fan
    std::uint64_t merged_corners = 0;  ///< concave corners given the bisector of their normals
    std::uint64_t layers = 0;          ///< the most layers any stack reached
    std::uint64_t layer_points = 0;    ///< points added by the layers
    std::uint64_t stopped_aspect_ratio = 0;
    std::uint64_t stopped_size = 0;  ///< the next layer thicker than the given size
    std::uint64_t stopped_collision = 0;
    std::uint64_t stopped_neighbour = 0;  ///< a neighbour stopped more than two layers below
    std::uint64_t stopped_max_layers = 0;
    /// Advancing layers: all stacks, when the first layer is under 2^-44 of the walls'
    /// coordinates. Truncated O-mesh: the columns cut because a layer point lay within rounding
    /// of the front (omesh_removed_unresolvable).
    std::uint64_t stopped_unresolvable = 0;
    std::uint64_t crossing_tests = 0;   ///< segment pairs and point-in-cell tests decided exactly
    std::uint64_t layer_quads = 0;      ///< layer cells (quadrilaterals, split or kept)
    std::uint64_t layer_triangles = 0;  ///< triangles of the layers (steps, fans, split quads)
    std::uint64_t fill_triangles = 0;
    std::uint64_t fill_min_max_swaps = 0;     ///< min-max swaps of the fill's flat triangles
    std::uint64_t quads = 0;                  ///< quadrilaterals in the output
    std::uint64_t triangles = 0;              ///< triangles in the output
    std::uint64_t max_wall_aspect_ratio = 0;  ///< wall piece length / first height, the largest
    // The truncated O-mesh (LayerMethod2::TruncatedOMesh; zero otherwise).
    std::uint64_t omesh_rings = 0;            ///< O-meshes built (one per wall loop)
    std::uint64_t omesh_cells = 0;            ///< their cells kept
    std::uint64_t omesh_min_ring_layers = 0;  ///< the truncation layer, the least over the rings
    std::uint64_t omesh_max_ring_layers = 0;  ///< the truncation layer, the most over the rings
    std::uint64_t omesh_removed_overlap = 0;  ///< cells removed where O-meshes overlap or meet
                                              ///< the boundary (gap under the local spacing)
    std::uint64_t omesh_removed_fold = 0;  ///< cells removed where normal lines fold (non-convex)
    std::uint64_t omesh_removed_step = 0;  ///< cells removed to keep steps of at most 2 layers
    /// Cells removed where a point of the front (or a vertex) lay within rounding of a front
    /// edge (or boundary piece) strictly between its ends, which the fill's constrained
    /// triangulation would bend through it (first heights near 2^-40 of the coordinates).
    std::uint64_t omesh_removed_unresolvable = 0;
};

inline constexpr std::array kAdvancingLayersCounterNames = EM_COUNTER_TABLE(
    AdvancingLayersCounters2, wall_loops, wall_vertices, stacks, fan_corners, merged_corners,
    layers, layer_points, stopped_aspect_ratio, stopped_size, stopped_collision, stopped_neighbour,
    stopped_max_layers, stopped_unresolvable, crossing_tests, layer_quads, layer_triangles,
    fill_triangles, fill_min_max_swaps, quads, triangles, max_wall_aspect_ratio, omesh_rings,
    omesh_cells, omesh_min_ring_layers, omesh_max_ring_layers, omesh_removed_overlap,
    omesh_removed_fold, omesh_removed_step, omesh_removed_unresolvable);
static_assert(counter_table_complete(kAdvancingLayersCounterNames));

struct AdvancingLayersResult2 {
    /// The triangles (the layers' first: [0, counters.layer_triangles)), input vertices first
    /// in xy, then the domain's added vertices, the layer points, the fill's points; pieces:
    /// the input segments (split by the fill where they bound it); neighbors across a
    /// quadrilateral are kNone.
    triangulation::Cdt2Result mesh;
    /// 4·#Q quadrilaterals, counter-clockwise, strictly convex (empty unless layers.quads).
    std::vector<triangulation::VertIdx> quads;
    /// Per stack: its wall vertex and the layers it reached (tests, pictures).
    std::vector<std::pair<triangulation::VertIdx, std::uint32_t>> stack_layers;
    AdvancingLayersCounters2 counters;
};

/// With layers.first_height == 0 (the registry's default), or on a domain without a hole loop
/// (a warning then), no layers: the domain is meshed by the fill alone.
/// A hole loop through a vertex where the boundary pinches is no wall.
/// @throws InputError on bad input (as constrained_delaunay_2d), bad layer parameters; as the
///         fill generator.
/// @pre options.fill is set (InternalError otherwise).
/// @throws GeometryError when the fill breaks the front or the final check fails (a bug).
AdvancingLayersResult2 advancing_layers_2d(const MeshDomain2& domain,
                                           const AdvancingLayersOptions2& options);

/// What check_mixed_mesh_2d found; ok() when every list is empty.
struct MixedMeshCheck2 {
    std::vector<std::uint32_t> inverted_triangles;  ///< orient2d <= 0
    std::vector<std::uint32_t> nonconvex_quads;     ///< some corner with orient2d <= 0
    /// Edges (2 vertices each) used by more than two cells, or twice in the same direction.
    std::vector<triangulation::VertIdx> overused_edges;
    /// Edges of one cell only that lie on no piece (a hole in the mesh or a hanging vertex).
    std::vector<triangulation::VertIdx> open_edges;
    /// Pieces that are no cell's edge.
    std::vector<triangulation::VertIdx> missing_pieces;
    bool ok() const {
        return inverted_triangles.empty() && nonconvex_quads.empty() && overused_edges.empty() &&
               open_edges.empty() && missing_pieces.empty();
    }
    std::string summary() const;
};

/// Exact conformity check of a mixed mesh: every cell positively oriented (quads strictly
/// convex), every edge in at most two cells and in opposite directions, every edge of one cell
/// on a piece (the boundary), every piece an edge of a cell (one cell on the boundary, two
/// inside).
MixedMeshCheck2 check_mixed_mesh_2d(std::span<const double> xy,
                                    std::span<const triangulation::VertIdx> triangles,
                                    std::span<const triangulation::VertIdx> quads,
                                    std::span<const triangulation::VertIdx> pieces);

/// Removes from check.missing_pieces the pieces that lie in a hole of the domain: a segment
/// sticking into a hole stays a piece of every generator's output but is in no cell. Such a
/// piece (pieces[2p], pieces[2p + 1], from input segment piece_segment[p]) comes from the same
/// input segment as a piece of `domain` (the domain's constrained triangulation, holes removed)
/// with no domain triangle on either side, and lies in that piece's bounding box (a fill may
/// split it at a vertex within rounding of it; the chain is collinear within rounding, so the
/// box orders it; exact comparisons of coordinates).
void exempt_pieces_in_holes_2d(MixedMeshCheck2& check, const triangulation::Cdt2Result& domain,
                               std::span<const double> xy,
                               std::span<const triangulation::VertIdx> pieces,
                               std::span<const std::uint32_t> piece_segment);

/// Measures of quadrilaterals for the quality report (the shared report measures triangles):
/// their corner angles (degrees) and aspect ratios (longest side over shortest), in doubles on
/// vectors scaled by a power of two (no overflow at 2^600); a report, not a decision.
struct QuadQuality2 {
    std::uint64_t quads = 0;
    double min_angle = 0, max_angle = 0;
    double max_aspect_ratio = 0, mean_aspect_ratio = 0;
};
QuadQuality2 quad_quality_2d(std::span<const double> xy,
                             std::span<const triangulation::VertIdx> quads);

/// The counters as (name, value) pairs, in declaration order (the CLI's --stats).
std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const AdvancingLayersCounters2& counters);

}  // namespace exactmesh::generators
