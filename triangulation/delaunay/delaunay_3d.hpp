// SPDX-License-Identifier: MIT
// The public face of 3D Delaunay construction: options, counters and the result shared by
// bowyer_watson_3d and green_sibson_3d. Both break ties with the same symbolic perturbation
// (predicates/sos.hpp, insphere_sos by input index: the regular triangulation of weights
// -eps^index), so for the same points and the same insertion order they return the same
// tetrahedralization; without duplicate points, the same one for every insertion order.
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
#include "triangulation/delaunay/delaunay_2d.hpp"  // InsertionOrder
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

struct Delaunay3Options {
    InsertionOrder order = InsertionOrder::Brio;
    std::uint64_t seed = 1;
    /// Called every 2^14 points inserted, with the point count as total (base/progress.hpp).
    Progress progress{};
    /// Threads of bowyer-watson (parallel_bowyer_watson_3d.hpp): 1 runs the sequential code,
    /// 0 every hardware thread. The output is the same tetrahedralization for every count. Used
    /// only with the brio order; green-sibson and the other orders run sequentially (their
    /// counters then report threads = 1).
    unsigned threads = 1;
    /// Parallel only: a BRIO round of fewer than this many points per thread is inserted
    /// sequentially (its ranges would be mostly border). Tests lower it to run the parallel
    /// rounds on small inputs; the tetrahedra do not depend on it.
    std::uint32_t parallel_round_minimum = 2048;
};

/// Work counters of one construction (predicate stage counts come from predicates/stats.hpp).
struct Delaunay3Counters {
    std::uint64_t points = 0;          ///< input points
    std::uint64_t duplicates = 0;      ///< input points merged into an earlier identical one
    std::uint64_t orient_calls = 0;    ///< orient3d evaluations made by the algorithm
    std::uint64_t insphere_calls = 0;  ///< insphere evaluations made by the algorithm
    std::uint64_t walk_steps = 0;      ///< tetrahedra visited by point location
    std::uint64_t cavity_tets = 0;     ///< Bowyer-Watson: tetrahedra removed, summed
    std::uint64_t outside_hull = 0;    ///< Green-Sibson: point outside the hull (joined to the
                                       ///< hull faces it sees)
    std::uint64_t splits_1_4 = 0;      ///< Green-Sibson: point inside a tetrahedron
    std::uint64_t splits_2_6 = 0;      ///< Green-Sibson: point inside a face
    std::uint64_t splits_edge = 0;     ///< Green-Sibson: point inside an edge (n-2n)
    std::uint64_t flips_2_3 = 0;       ///< Green-Sibson flips
    std::uint64_t flips_3_2 = 0;
    std::uint64_t flips_4_4 = 0;
    std::uint64_t unflippable = 0;  ///< Green-Sibson: non-Delaunay link faces not flippable when
                                    ///< met, tried again later (counted each time)
    std::uint64_t threads = 1;      ///< threads of the construction
    std::uint64_t sequential_prefix = 0;  ///< parallel: points inserted before the parallel rounds
    std::uint64_t parallel_rounds = 0;    ///< parallel: passes of the threads over their partitions
    std::uint64_t parallel_points = 0;    ///< parallel: points inserted (or merged) by the threads
    std::uint64_t deferred_points = 0;  ///< parallel: insertions put off (a point may count twice)
    std::uint64_t sequential_tail = 0;  ///< parallel: deferred points inserted at the end
    // Wall-clock phases (sequential and parallel bowyer-watson; green-sibson: order, sequential
    // and result), in microseconds: measured, not work, they differ from run to run.
    std::uint64_t order_microseconds = 0;  ///< validation, BRIO order (parallel: also mesh arrays)
    std::uint64_t keys_microseconds = 0;   ///< parallel: the curves' keys by mesh vertex
    std::uint64_t sequential_microseconds = 0;  ///< one-thread insertions (parallel: prefix, tail)
    std::uint64_t partition_microseconds = 0;   ///< parallel: merging, sorting, ranges, starts
    std::uint64_t parallel_microseconds = 0;    ///< parallel: the threads' passes
    std::uint64_t result_microseconds = 0;      ///< numbering and compaction of the result
};

/// The name table of Delaunay3Counters (base/counter_table.hpp): --stats prints it in this order.
inline constexpr std::array kDelaunay3CounterNames = EM_COUNTER_TABLE(
    Delaunay3Counters, points, duplicates, orient_calls, insphere_calls, walk_steps, cavity_tets,
    outside_hull, splits_1_4, splits_2_6, splits_edge, flips_2_3, flips_3_2, flips_4_4, unflippable,
    threads, sequential_prefix, parallel_rounds, parallel_points, deferred_points, sequential_tail,
    order_microseconds, keys_microseconds, sequential_microseconds, partition_microseconds,
    parallel_microseconds, result_microseconds);
static_assert(counter_table_complete(kDelaunay3CounterNames));

/// The Delaunay tetrahedralization in the caller's vertex numbering. When fewer than four
/// distinct points are not coplanar, there is no tetrahedron: `mesh.tets` is empty and
/// `coplanar` is true (duplicates are still merged).
struct Delaunay3Result {
    Tetrahedralization3 mesh;          ///< xyz = the input points, tets and neighbors (finite)
    std::vector<VertIdx> merged_into;  ///< #V: the first input point with the same coordinates
    bool coplanar = false;             ///< all points coplanar: no tetrahedron
    Delaunay3Counters counters;
};

/// Thrown by callers that need a tetrahedralization (the CLI) when Delaunay3Result::coplanar.
class CoplanarPoints : public InputError {
  public:
    using InputError::InputError;
};

/// Throws InputError (NonFiniteCoordinate) naming the first NaN or infinite coordinate, or when
/// there are more than kMaxPoints3 points or a number of coordinates that is not a multiple of 3.
void validate_points_3d(std::span<const double> xyz);

using Delaunay3Function = Delaunay3Result (*)(std::span<const double>, const Delaunay3Options&);

/// One 3D Delaunay algorithm of the registry (DelaunayAlgorithm, delaunay_2d.hpp).
using Delaunay3Algorithm = DelaunayAlgorithm<Delaunay3Function>;

/// Every 3D Delaunay algorithm (delaunay_3d.cpp; adding one is its file plus one line there):
/// "bowyer-watson", "green-sibson".
std::span<const Delaunay3Algorithm> delaunay_3d_algorithms();

/// The algorithm of that name. @throws InputError naming the known ones.
Delaunay3Function delaunay_3d_algorithm(std::string_view name);

}  // namespace exactmesh::triangulation
