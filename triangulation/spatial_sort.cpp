// SPDX-License-Identifier: MIT
// BRIO rounds [AmentaChoiRote03] and a Hilbert-curve sort over a 2^16 x 2^16 grid. The grid
// only orders points; no geometric decision depends on it, so quantisation is harmless.
#include "triangulation/spatial_sort.hpp"

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>

namespace exactmesh::triangulation {

namespace {

/// Position of grid cell (x, y) along the Hilbert curve of order 16.
std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) {
    std::uint32_t key = 0;
    for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
        const std::uint32_t rx = (x & s) ? 1u : 0u;
        const std::uint32_t ry = (y & s) ? 1u : 0u;
        key += s * s * ((3u * rx) ^ ry);
        if (ry == 0) {  // rotate the quadrant so the curve stays continuous
            if (rx == 1) {
                x = 65535u - x;
                y = 65535u - y;
            }
            std::swap(x, y);
        }
    }
    return key;
}

}  // namespace

void hilbert_sort_2d(std::span<const double> xy, std::span<std::uint32_t> indices) {
    if (indices.size() < 2) return;
    double min_x = xy[2 * indices[0]], max_x = min_x;
    double min_y = xy[2 * indices[0] + 1], max_y = min_y;
    for (const std::uint32_t i : indices) {
        min_x = std::min(min_x, xy[2 * i]);
        max_x = std::max(max_x, xy[2 * i]);
        min_y = std::min(min_y, xy[2 * i + 1]);
        max_y = std::max(max_y, xy[2 * i + 1]);
    }
    // Scale by halves so that huge extents (up to the double range) do not overflow.
    const double span_x = max_x / 2 - min_x / 2, span_y = max_y / 2 - min_y / 2;
    auto cell = [](double v, double lo, double half_span) -> std::uint32_t {
        if (!(half_span > 0)) return 0;
        const double t = (v / 2 - lo / 2) / half_span;
        return static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 65535.0);
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> keyed(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        const std::uint32_t i = indices[k];
        keyed[k] = {hilbert_key(cell(xy[2 * i], min_x, span_x), cell(xy[2 * i + 1], min_y, span_y)),
                    i};
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = keyed[k].second;
}

std::vector<std::uint32_t> insertion_order_2d(std::span<const double> xy, InsertionOrder order,
                                              std::uint64_t seed) {
    std::vector<std::uint32_t> perm(xy.size() / 2);
    std::iota(perm.begin(), perm.end(), 0u);
    if (order == InsertionOrder::Given) return perm;
    std::mt19937_64 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    if (order == InsertionOrder::Random) return perm;
    // BRIO: rounds [0, n/2^k) ... [n/4, n/2), [n/2, n), each Hilbert-sorted; the first round
    // stays small (at most 64 points) and random.
    std::size_t end = perm.size();
    while (end > 64) {
        const std::size_t begin = end / 2;
        hilbert_sort_2d(xy, std::span<std::uint32_t>(perm).subspan(begin, end - begin));
        end = begin;
    }
    return perm;
}

}  // namespace exactmesh::triangulation
