// SPDX-License-Identifier: MIT
// Constrained (and conforming) Delaunay triangulation of a planar straight-line graph: the
// vertices are triangulated (Green-Sibson, BRIO order), then every segment is recovered.
//  - Swap recovery [Sloan93: "A fast algorithm for generating constrained Delaunay
//    triangulations", Computers & Structures 47(3)]: the edges crossing the segment are swapped
//    out (a convex quadrilateral always exists among them), then Lawson flips that never cross
//    a constraint restore the constrained Delaunay property.
//  - Cavity recovery [Anglada97: "An improved incremental algorithm for constructing
//    restricted Delaunay triangulations", Computers & Graphics 21(2); Shewchuk-Brown 2015 §2]:
//    the crossed triangles are removed and the two pseudo-polygons on either side of the
//    segment are retriangulated, each by its own constrained Delaunay triangulation.
//  - Conforming: a missing piece, or a present one a later vertex makes not locally Delaunay
//    (encroached), is split (on a concentric shell about a corner [Ruppert95 §4], else at its
//    rounded midpoint) until the plain Delaunay triangulation contains every piece.
// Every incircle decision uses the same symbolic perturbation as delaunay_2d (predicates/sos),
// so the constrained Delaunay triangulation is unique and the swap and cavity recoveries return
// the same triangles. Segments that cross are split at their intersection, correctly rounded
// (predicates/constructions); a segment through a vertex is split there. Both add a warning.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "base/counter_table.hpp"
#include "base/errors.hpp"
#include "base/progress.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// A planar straight-line graph (Triangle's .poly content), 0-based indices.
struct Pslg {
    std::span<const double> xy;         ///< 2·#V vertex coordinates
    std::span<const VertIdx> segments;  ///< 2·#S endpoint indices into xy
    std::span<const double> holes;      ///< 2·#H points inside holes
    std::span<const double> regions;    ///< 4·#R: x, y, attribute, maximum area (unused here)
    /// Empty, or 2·#S indices into xy: per segment, the two vertices whose line its chain rule
    /// measures against (the vertices a segment may bend through: within rounding of that line,
    /// strictly between the piece's ends along it). Empty: the segment's own ends. A triangulation
    /// of a split boundary, whose segments are the pieces of input segments, gives each piece its
    /// input segment's ends, so that its bends are bends the input segment's check accepts.
    std::span<const VertIdx> segment_lines = {};
};

enum class SegmentRecovery { Swap, Cavity, Conforming };

/// "swap", "cavity", "conforming"; throws InputError for anything else.
SegmentRecovery segment_recovery_from_name(std::string_view name);
const char* segment_recovery_name(SegmentRecovery recovery);

struct Cdt2Options {
    SegmentRecovery recovery = SegmentRecovery::Swap;
    /// Remove the triangles outside the segments (reached from the convex hull without crossing
    /// a segment), as Triangle does with -p; false keeps the convex hull (Triangle's -c).
    bool remove_exterior = true;
    InsertionOrder order = InsertionOrder::Brio;
    std::uint64_t seed = 1;
    /// Number of the first vertex, segment, hole and region in warnings (1 for 1-based files).
    std::uint32_t first_index = 0;
    /// Called every 2^14 vertices inserted into the Delaunay triangulation, then (delaunay
    /// refinement) every 2^14 Steiner points (base/progress.hpp).
    Progress progress{};
};

struct Cdt2Counters {
    std::uint64_t points = 0;                ///< input vertices
    std::uint64_t duplicates = 0;            ///< input vertices merged into an equal earlier one
    std::uint64_t segments = 0;              ///< input segments
    std::uint64_t dropped_segments = 0;      ///< zero-length or repeated segments, ignored
    std::uint64_t crossed_edges = 0;         ///< triangulation edges crossed by segments, summed
    std::uint64_t recovery_flips = 0;        ///< swap recovery: flips removing crossed edges
    std::uint64_t delaunay_flips = 0;        ///< Lawson flips (insertions and restoration)
    std::uint64_t cavity_triangles = 0;      ///< cavity recovery: triangles retriangulated
    std::uint64_t vertices_on_segments = 0;  ///< segments split at an input vertex they contain
    std::uint64_t intersections = 0;         ///< vertices added where segments cross
    std::uint64_t bent_crossings = 0;        ///< pieces crossing where their input segments do not
    std::uint64_t conforming_splits =
        0;  ///< conforming: vertices added on pieces (shell or midpoint)
    std::uint64_t conforming_bends =
        0;  ///< conforming: pieces split at a vertex within rounding of the segment
    std::uint64_t conforming_passes = 0;  ///< conforming: final checks of every edge (normally 1)
    std::uint64_t removed_triangles = 0;  ///< exterior and hole triangles removed
    std::uint64_t orient_calls = 0;
    std::uint64_t incircle_calls = 0;
    std::uint64_t walk_steps = 0;
};

/// The name table of Cdt2Counters (base/counter_table.hpp): --stats prints it in this order.
inline constexpr std::array kCdt2CounterNames = EM_COUNTER_TABLE(
    Cdt2Counters, points, duplicates, segments, dropped_segments, vertices_on_segments,
    intersections, bent_crossings, conforming_splits, conforming_bends, conforming_passes,
    crossed_edges, recovery_flips, cavity_triangles, delaunay_flips, removed_triangles,
    orient_calls, incircle_calls, walk_steps);
static_assert(counter_table_complete(kCdt2CounterNames));

struct Cdt2Result {
    /// The triangulation: input vertices keep their index, added vertices follow them; merged
    /// duplicates stay in xy but no triangle uses them. Constrained edges are flagged.
    Triangulation2 mesh;
    std::uint32_t input_vertex_count = 0;
    std::vector<VertIdx> merged_into;  ///< #V input: the first input vertex with equal point
    /// 2·#P: every constrained edge (a segment or a piece of one), and piece_segment[p], the
    /// input segment it comes from (the first one when overlapping segments share it).
    std::vector<VertIdx> pieces;
    std::vector<std::uint32_t> piece_segment;
    /// #T regional attribute of each triangle (0 outside every region); empty without regions.
    std::vector<double> triangle_attributes;
    std::vector<std::string> warnings;  ///< one line per split, drop or unused hole
    Cdt2Counters counters;
};

/// A hole or region point that lies exactly on a segment or on a vertex (exact orient2d): the
/// side it names is ambiguous (a hole there would remove either side, often the whole domain),
/// so it is an input error, the same for `cdt` and every mesh generator (they all mark their
/// domain through constrained_delaunay_2d). what() names the point (in the input's numbering,
/// Cdt2Options::first_index) and the segment or vertex; kind() and index() (0-based) let a
/// caller add the file and line.
class AmbiguousMarkPoint : public InputError {
  public:
    enum class Kind { Hole, Region };
    AmbiguousMarkPoint(const std::string& what, Kind kind, std::size_t index)
        : InputError(what), kind_(kind), index_(index) {}
    Kind kind() const noexcept { return kind_; }
    std::size_t index() const noexcept { return index_; }

  private:
    Kind kind_;
    std::size_t index_;
};

/// Validates a PSLG as constrained_delaunay_2d does before any work.
/// @throws InputError naming the offending item: a non-finite coordinate (vertex, hole or
///         region), a segment index out of range, more than kMaxPoints vertices.
void validate_pslg(const Pslg& pslg);

/// @throws InputError naming the offending item: a non-finite coordinate (vertex, hole or
///         region), a segment index out of range, more than kMaxPoints vertices;
///         AmbiguousMarkPoint for a hole or region point on a segment or a vertex.
/// @throws GeometryError if segment recovery fails to converge (a bug: reported, never a hang).
Cdt2Result constrained_delaunay_2d(const Pslg& pslg, const Cdt2Options& options = {});

}  // namespace exactmesh::triangulation
