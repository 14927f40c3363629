// SPDX-License-Identifier: MIT
#include "generators/boundary/narrow_wedges_2d.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

std::vector<std::uint64_t> narrow_wedges_2d(
    std::span<const double> xy, std::span<const std::array<triangulation::VertIdx, 2>> ends) {
    using triangulation::kNone;
    using triangulation::VertIdx;
    constexpr double kTurn = 2 * 3.14159265358979323846;
    // Per end vertex, its segments' directions as angles in (-pi, pi].
    std::vector<std::pair<VertIdx, std::pair<double, std::uint32_t>>> at;
    for (std::uint32_t s = 0; s < ends.size(); ++s) {
        const auto [a, b] = ends[s];
        if (a == kNone || b == kNone || a == b) continue;
        for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
            double dx = xy[2 * std::size_t{to}] - xy[2 * std::size_t{from}];
            double dy = xy[2 * std::size_t{to} + 1] - xy[2 * std::size_t{from} + 1];
            const predicates::PowerOfTwo unit(
                predicates::unit_shift(std::max(std::fabs(dx), std::fabs(dy))));
            dx = unit(dx), dy = unit(dy);
            at.push_back({from, {std::atan2(dy, dx), s}});
        }
    }
    std::sort(at.begin(), at.end());
    std::vector<std::uint64_t> pairs;
    const auto add = [&](std::uint32_t s, std::uint32_t t) {
        if (s != t)
            pairs.push_back(s < t ? std::uint64_t{s} << 32 | t : std::uint64_t{t} << 32 | s);
    };
    for (std::size_t begin = 0; begin < at.size();) {
        std::size_t end = begin;
        while (end < at.size() && at[end].first == at[begin].first) ++end;
        const std::size_t n = end - begin;
        // Sorted by angle: the segments within the wedge angle of one are the next ones round
        // the circle (the last ones meet the first ones across pi).
        for (std::size_t i = 0; i < n; ++i) {
            for (std::size_t k = 1; k < n; ++k) {
                const auto& here = at[begin + i].second;
                const auto& next = at[begin + (i + k) % n].second;
                double gap = next.first - here.first;
                if (i + k >= n) gap += kTurn;
                if (!(gap < kNarrowWedgeRadians)) break;
                add(here.second, next.second);
            }
        }
        begin = end;
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

bool narrow_wedge_pair(const std::vector<std::uint64_t>& pairs, std::uint32_t a, std::uint32_t b) {
    if (a == b || pairs.empty()) return false;
    const std::uint64_t key = a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
    return std::binary_search(pairs.begin(), pairs.end(), key);
}

}  // namespace exactmesh::generators
