// SPDX-License-Identifier: MIT
// The public face of 2D Delaunay construction: options, counters and the flat result shared by
// bowyer_watson_2d, green_sibson_2d and tanemura_merriam_2d. All three break ties with the same
// symbolic perturbation (predicates/sos.hpp, by input index), so for the same points they
// return the same triangulation, whatever the algorithm or insertion order.
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
#include "triangulation/mesh/mesh2.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

/// Where the visibility walk of each insertion starts. Walk: the last inserted point's triangle
/// (enough for BRIO and other spatially coherent orders). Grid: jump first to a triangle made
/// by a recent insertion nearby, found in a multi-level grid of the bounding box (a bucketing
/// equivalent of the Delaunay hierarchy: O(1) expected steps for random orders, where the
/// plain walk costs O(sqrt n) per point). Auto: Grid for InsertionOrder::Random, else Walk.
enum class PointLocation { Auto, Walk, Grid };

struct Delaunay2Options {
    InsertionOrder order = InsertionOrder::Brio;
    std::uint64_t seed = 1;
    PointLocation location = PointLocation::Auto;
    /// Called every 2^14 points inserted, with the point count as total (base/progress.hpp).
    Progress progress{};
    /// Threads of bowyer-watson (parallel_bowyer_watson_2d.hpp): 1 runs the sequential code,
    /// 0 every hardware thread. The output is the same triangulation for every count. Used only
    /// with the brio order and walk location; the other algorithms and orders run sequentially
    /// (their counters then report threads = 1).
    unsigned threads = 1;
    /// Parallel only: a BRIO round of fewer than this many points per thread is inserted
    /// sequentially (its ranges would be mostly border). Tests lower it to run the parallel
    /// rounds on small inputs; the triangles do not depend on it.
    std::uint32_t parallel_round_minimum = 2048;
};

/// Work counters of one construction (predicate stage counts come from predicates/stats.hpp).
struct Delaunay2Counters {
    std::uint64_t points = 0;             ///< input points
    std::uint64_t duplicates = 0;         ///< input points merged into an earlier identical one
    std::uint64_t orient_calls = 0;       ///< orient2d evaluations made by the algorithm
    std::uint64_t incircle_calls = 0;     ///< incircle evaluations made by the algorithm
    std::uint64_t walk_steps = 0;         ///< triangles visited by point location
    std::uint64_t cavity_triangles = 0;   ///< Bowyer-Watson: triangles removed, summed
    std::uint64_t flips = 0;              ///< Green-Sibson: Lawson flips
    std::uint64_t candidates = 0;         ///< Tanemura-Merriam: candidate points examined
    std::uint64_t threads = 1;            ///< threads of the construction
    std::uint64_t sequential_prefix = 0;  ///< parallel: points inserted before the parallel rounds
    std::uint64_t parallel_rounds = 0;    ///< parallel: passes of the threads over their partitions
    std::uint64_t parallel_points = 0;    ///< parallel: points inserted (or merged) by the threads
    std::uint64_t deferred_points = 0;  ///< parallel: insertions put off (a point may count twice)
    std::uint64_t sequential_tail = 0;  ///< parallel: deferred points inserted at the end
    // Wall-clock phases of bowyer-watson (sequential and parallel), in microseconds: measured,
    // not work, so they differ from run to run; the other algorithms leave them at 0.
    std::uint64_t order_microseconds = 0;  ///< validation, BRIO order (parallel: also mesh arrays)
    std::uint64_t keys_microseconds = 0;   ///< parallel: the curves' keys by mesh vertex
    std::uint64_t sequential_microseconds = 0;  ///< one-thread insertions (parallel: prefix, tail)
    std::uint64_t partition_microseconds = 0;   ///< parallel: merging, sorting, ranges, starts
    std::uint64_t parallel_microseconds = 0;    ///< parallel: the threads' passes
    std::uint64_t result_microseconds = 0;      ///< numbering and compaction of the result
};

/// The name table of Delaunay2Counters (base/counter_table.hpp): --stats prints it in this order.
inline constexpr std::array kDelaunay2CounterNames = EM_COUNTER_TABLE(
    Delaunay2Counters, points, duplicates, orient_calls, incircle_calls, walk_steps,
    cavity_triangles, flips, candidates, threads, sequential_prefix, parallel_rounds,
    parallel_points, deferred_points, sequential_tail, order_microseconds, keys_microseconds,
    sequential_microseconds, partition_microseconds, parallel_microseconds, result_microseconds);
static_assert(counter_table_complete(kDelaunay2CounterNames));

/// The Delaunay triangulation in the caller's vertex numbering.
struct Delaunay2Result {
    std::vector<VertIdx> triangles;  ///< 3·#T input indices, counter-clockwise
    std::vector<TriIdx>
        neighbors;  ///< 3·#T: triangle across edge (v[k], v[k+1]), kNone on the hull
    std::vector<VertIdx> merged_into;  ///< #V: the first input point with the same coordinates
    Delaunay2Counters counters;
};

/// Throws InputError (NonFiniteCoordinate) naming the first NaN or infinite coordinate, or when
/// there are more than kMaxPoints points or an odd number of coordinates.
void validate_points_2d(std::span<const double> xy);

using Delaunay2Function = Delaunay2Result (*)(std::span<const double>, const Delaunay2Options&);

/// One Delaunay algorithm of a registry (2D here, 3D in delaunay_3d.hpp): the name the CLI,
/// benches and tests use, the function, and one line for help texts.
template <class Function>
struct DelaunayAlgorithm {
    std::string_view name;
    Function build;
    std::string_view description;
};

/// The function of the algorithm named `name` in `algorithms`.
/// @throws InputError "unknown <what> '<name>' (known: <every name>)".
template <class Function>
Function find_delaunay_algorithm(std::span<const DelaunayAlgorithm<Function>> algorithms,
                                 std::string_view name, std::string_view what,
                                 SourceLocation where = SourceLocation::current()) {
    std::string known;
    for (const DelaunayAlgorithm<Function>& algorithm : algorithms) {
        if (algorithm.name == name) return algorithm.build;
        known += (known.empty() ? "" : ", ") + std::string(algorithm.name);
    }
    throw InputError(
        "unknown " + std::string(what) + " '" + std::string(name) + "' (known: " + known + ")",
        where);
}

using Delaunay2Algorithm = DelaunayAlgorithm<Delaunay2Function>;

/// Every 2D Delaunay algorithm (delaunay_2d.cpp; adding one is its file plus one line there):
/// "bowyer-watson", "green-sibson", "tanemura-merriam".
std::span<const Delaunay2Algorithm> delaunay_2d_algorithms();

/// The algorithm of that name. @throws InputError naming the known ones.
Delaunay2Function delaunay_2d_algorithm(std::string_view name);

}  // namespace exactmesh::triangulation
