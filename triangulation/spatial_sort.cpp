// SPDX-License-Identifier: MIT
// BRIO rounds [AmentaChoiRote03] and a Hilbert-curve sort over a 2^16 x 2^16 grid. The grid
// only orders points; no geometric decision depends on it, so quantisation is harmless.
#include "triangulation/spatial_sort.hpp"

#include <algorithm>
#include <numeric>
#include <random>

namespace exactmesh::triangulation {

namespace {

/// Hilbert-curve state machine: for state s and quadrant q = 2*xbit + ybit, the digit along
/// the curve and the next state (the four orientations of the basic U shape).
struct HilbertStep {
    std::uint8_t digit, next;
};
constexpr HilbertStep kHilbert[4][4] = {
    {{0, 1}, {1, 0}, {3, 2}, {2, 0}},  // identity
    {{0, 0}, {3, 3}, {1, 1}, {2, 1}},  // x and y exchanged
    {{2, 2}, {1, 2}, {3, 0}, {0, 3}},  // both complemented, then exchanged
    {{2, 3}, {3, 1}, {1, 3}, {0, 2}},  // both complemented
};

/// Position of grid cell (x, y) along the Hilbert curve of order 16.
std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) {
    std::uint32_t key = 0;
    std::uint8_t state = 0;
    for (int bit = 15; bit >= 0; --bit) {
        const unsigned quadrant = (((x >> bit) & 1u) << 1) | ((y >> bit) & 1u);
        const HilbertStep step = kHilbert[state][quadrant];
        key = (key << 2) | step.digit;
        state = step.next;
    }
    return key;
}

/// LSD radix sort of (key, index) pairs by key: 4 passes of 8 bits, linear time.
void radix_sort_by_key(std::vector<std::uint64_t>& items, std::vector<std::uint64_t>& scratch) {
    scratch.resize(items.size());
    for (unsigned shift = 32; shift < 64; shift += 8) {
        std::size_t count[257] = {};
        for (const std::uint64_t item : items) ++count[((item >> shift) & 0xFFu) + 1];
        for (int b = 0; b < 256; ++b) count[b + 1] += count[b];
        for (const std::uint64_t item : items) scratch[count[(item >> shift) & 0xFFu]++] = item;
        items.swap(scratch);
    }
}

}  // namespace

namespace {

/// Hilbert keys of all points on a 2^16 grid over their bounding box, computed in input order
/// (sequential reads) so that the shuffled rounds only gather 4-byte keys.
std::vector<std::uint32_t> hilbert_keys(std::span<const double> xy) {
    const std::size_t n = xy.size() / 2;
    std::vector<std::uint32_t> keys(n);
    if (n == 0) return keys;
    double min_x = xy[0], max_x = xy[0], min_y = xy[1], max_y = xy[1];
    for (std::size_t i = 1; i < n; ++i) {
        min_x = std::min(min_x, xy[2 * i]);
        max_x = std::max(max_x, xy[2 * i]);
        min_y = std::min(min_y, xy[2 * i + 1]);
        max_y = std::max(max_y, xy[2 * i + 1]);
    }
    // Halves keep huge extents (up to the double range) from overflowing.
    const double half_x = max_x / 2 - min_x / 2, half_y = max_y / 2 - min_y / 2;
    auto cell = [](double v, double lo, double half_span) -> std::uint32_t {
        if (!(half_span > 0)) return 0;
        const double t = (v / 2 - lo / 2) / half_span;
        return static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 65535.0);
    };
    for (std::size_t i = 0; i < n; ++i) {
        keys[i] = hilbert_key(cell(xy[2 * i], min_x, half_x), cell(xy[2 * i + 1], min_y, half_y));
    }
    return keys;
}

void sort_by_keys(std::span<const std::uint32_t> keys, std::span<std::uint32_t> indices,
                  std::vector<std::uint64_t>& keyed, std::vector<std::uint64_t>& scratch) {
    keyed.resize(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        keyed[k] = (std::uint64_t{keys[indices[k]]} << 32) | indices[k];
    }
    radix_sort_by_key(keyed, scratch);
    for (std::size_t k = 0; k < indices.size(); ++k) {
        indices[k] = static_cast<std::uint32_t>(keyed[k] & 0xFFFFFFFFu);
    }
}

}  // namespace

void hilbert_sort_2d(std::span<const double> xy, std::span<std::uint32_t> indices) {
    if (indices.size() < 2) return;
    std::vector<double> subset(2 * indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        subset[2 * k] = xy[2 * indices[k]];
        subset[2 * k + 1] = xy[2 * indices[k] + 1];
    }
    const std::vector<std::uint32_t> keys = hilbert_keys(subset);
    std::vector<std::uint32_t> local(indices.size());
    std::iota(local.begin(), local.end(), 0u);
    std::vector<std::uint64_t> keyed, scratch;
    sort_by_keys(keys, local, keyed, scratch);
    std::vector<std::uint32_t> sorted(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) sorted[k] = indices[local[k]];
    std::copy(sorted.begin(), sorted.end(), indices.begin());
}

std::vector<std::uint32_t> insertion_order_2d(std::span<const double> xy, InsertionOrder order,
                                              std::uint64_t seed) {
    std::vector<std::uint32_t> perm(xy.size() / 2);
    std::iota(perm.begin(), perm.end(), 0u);
    if (order == InsertionOrder::Given) return perm;
    std::mt19937_64 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    if (order == InsertionOrder::Random) return perm;
    // BRIO: rounds [0, n/2^k) ... [n/4, n/2), [n/2, n), each sorted along the Hilbert curve;
    // the first round stays small (at most 64 points) and random.
    const std::vector<std::uint32_t> keys = hilbert_keys(xy);
    std::vector<std::uint64_t> keyed, scratch;
    std::size_t end = perm.size();
    while (end > 64) {
        const std::size_t begin = end / 2;
        sort_by_keys(keys, std::span<std::uint32_t>(perm).subspan(begin, end - begin), keyed,
                     scratch);
        end = begin;
    }
    return perm;
}

}  // namespace exactmesh::triangulation
