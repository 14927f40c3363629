// SPDX-License-Identifier: MIT
// What the multicore Bowyer-Watson constructions share (see parallel_rounds.hpp).
#include "triangulation/delaunay/parallel_rounds.hpp"

#include <algorithm>

#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

unsigned resolve_thread_count(unsigned threads) {
    if (threads != 0) return threads;
    return std::max(1u, static_cast<unsigned>(tbb::this_task_arena::max_concurrency()));
}

namespace detail {

BrioRounds brio_rounds(std::uint32_t n, unsigned threads, std::uint32_t round_minimum) {
    BrioRounds rounds;
    // The rounds after the first (random, at most 64 points): the first is the prefix's.
    const std::vector<std::uint32_t> begin = brio_round_begins(n);
    rounds.begin.assign(begin.begin() + 1, begin.end());
    std::size_t& first = rounds.first_parallel;
    while (first + 1 < rounds.begin.size() &&
           rounds.begin[first + 1] - rounds.begin[first] < std::uint64_t{round_minimum} * threads) {
        ++first;
    }
    rounds.prefix_end = first + 1 < rounds.begin.size() ? rounds.begin[first] : n;
    return rounds;
}

std::vector<VertIdx> unskipped_vertices(const std::vector<bool>& skip, std::uint32_t begin,
                                        std::uint32_t end) {
    std::vector<VertIdx> out;
    for (VertIdx p = begin; p < end; ++p) {
        if (!skip[p]) out.push_back(p);
    }
    return out;
}

std::vector<std::uint64_t> key_range_bounds(std::span<const std::uint32_t> keys,
                                            std::span<const VertIdx> points, std::size_t count,
                                            bool shifted) {
    std::vector<std::uint32_t> sorted(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) sorted[k] = keys[points[k]];
    // The key at the fraction (2 i + shifted) / (2 count) of the points (0 without points).
    auto key_at = [&](std::size_t i) -> std::uint64_t {
        if (points.empty()) return 0;
        const auto at =
            std::min(points.size() * (2 * i + shifted) / (2 * count), points.size() - 1);
        std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(at),
                         sorted.end());
        return sorted[at];
    };
    std::vector<std::uint64_t> out{shifted ? key_at(0) : 0};
    for (std::size_t i = 1; i < count; ++i) out.push_back(key_at(i));
    out.push_back(out.front() + (std::uint64_t{1} << 32));
    return out;
}

std::vector<std::span<const VertIdx>> split_by_bounds(std::span<const std::uint32_t> keys,
                                                      std::span<const VertIdx> points,
                                                      std::span<const std::uint64_t> bounds) {
    std::vector<std::span<const VertIdx>> out;
    // Keys below the first range's low come after the others (the wrapped range).
    auto position = [&](VertIdx p) {
        const std::uint64_t key = keys[p];
        return key < bounds.front() ? key + (std::uint64_t{1} << 32) : key;
    };
    std::size_t begin = 0;
    for (std::size_t w = 0; w + 1 < bounds.size(); ++w) {
        std::size_t end = begin;
        while (end < points.size() && position(points[end]) < bounds[w + 1]) ++end;
        out.push_back(points.subspan(begin, end - begin));
        begin = end;
    }
    return out;
}

void rotate_to_bound(std::span<const std::uint32_t> keys, std::vector<VertIdx>& points,
                     std::uint64_t low) {
    const auto first = std::partition_point(points.begin(), points.end(),
                                            [&](VertIdx p) { return keys[p] < low; });
    std::rotate(points.begin(), first, points.end());
}

void sort_by_key(std::span<const std::uint32_t> keys, std::vector<VertIdx>& points) {
    std::sort(points.begin(), points.end(), [keys](VertIdx u, VertIdx v) {
        return keys[u] < keys[v] || (keys[u] == keys[v] && u < v);
    });
}

std::vector<VertIdx> merge_by_key(std::span<const std::uint32_t> keys, std::span<const VertIdx> a,
                                  std::span<const VertIdx> b) {
    std::vector<VertIdx> out(a.size() + b.size());
    std::merge(a.begin(), a.end(), b.begin(), b.end(), out.begin(), [keys](VertIdx u, VertIdx v) {
        return keys[u] < keys[v] || (keys[u] == keys[v] && u < v);
    });
    return out;
}

}  // namespace detail
}  // namespace exactmesh::triangulation
