// SPDX-License-Identifier: MIT
// BRIO rounds [AmentaChoiRote03] and a Hilbert-curve sort over a 2^16 x 2^16 grid (2D) or a
// 2^10 x 2^10 x 2^10 grid (3D, Skilling's transpose algorithm [Skilling04]). The grid only
// orders points; no geometric decision depends on it, so quantisation is harmless.
#include "triangulation/mesh/spatial_sort.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <string>

#include "base/errors.hpp"

namespace exactmesh::triangulation {

InsertionOrder insertion_order_from_name(std::string_view name) {
    if (name == "given") return InsertionOrder::Given;
    if (name == "random") return InsertionOrder::Random;
    if (name == "brio") return InsertionOrder::Brio;
    throw InputError("unknown insertion order '" + std::string(name) +
                     "' (known: given, random, brio)");
}

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

/// compute(begin, end) over [0, n): on every thread of the current oneTBB arena with
/// `parallel` (each point's key alone: any split gives the same keys), else in one call.
template <class Compute>
void compute_in_chunks(std::size_t n, bool parallel, Compute& compute) {
    if (!parallel) {
        compute(0, n);
        return;
    }
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, 1 << 14),
        [&](const tbb::blocked_range<std::size_t>& r) { compute(r.begin(), r.end()); });
}

}  // namespace

/// Hilbert keys of all points on a 2^16 grid over their bounding box, computed in input order
/// (sequential reads) so that the shuffled rounds only gather 4-byte keys.
std::vector<std::uint32_t> hilbert_keys_2d(std::span<const double> xy, std::uint32_t cell_shift,
                                           bool parallel) {
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
    auto compute = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            keys[i] = hilbert_key((cell(xy[2 * i], min_x, half_x) + cell_shift) & 0xFFFFu,
                                  (cell(xy[2 * i + 1], min_y, half_y) + cell_shift) & 0xFFFFu);
        }
    };
    compute_in_chunks(n, parallel, compute);
    return keys;
}

namespace {

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

/// Spreads the 10 low bits of x to every third bit (bit b to bit 3b).
std::uint32_t spread_3(std::uint32_t x) {
    x &= 0x3FFu;
    x = (x | x << 16) & 0x030000FFu;
    x = (x | x << 8) & 0x0300F00Fu;
    x = (x | x << 4) & 0x030C30C3u;
    x = (x | x << 2) & 0x09249249u;
    return x;
}

/// Hilbert index of cell (x, y, z) of a 2^bits grid per axis: Skilling's transpose algorithm
/// ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004), then the bits interleaved
/// (x's bit highest at each level). Branch-free: the choice between inverting and exchanging
/// depends on coordinate bits, a coin toss for the branch predictor.
std::uint32_t hilbert_key_3d(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    constexpr int kBits = 10;
    std::uint32_t axes[3] = {x, y, z};
    // Inverse undo of the excess work, from the top bit down: invert the low bits of axis 0
    // when bit q of axis i is set, else exchange them with those of axis i (a no-op for i = 0).
    for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) {
        const std::uint32_t p = q - 1;
        for (int i = 0; i < 3; ++i) {
            const std::uint32_t set = 0u - ((axes[i] & q) != 0 ? 1u : 0u);
            const std::uint32_t t = (axes[0] ^ axes[i]) & p & ~set;
            axes[0] ^= (p & set) | t;
            axes[i] ^= t;
        }
    }
    // Gray encode.
    axes[1] ^= axes[0];
    axes[2] ^= axes[1];
    std::uint32_t t = 0;
    for (std::uint32_t q = 1u << (kBits - 1); q > 1; q >>= 1) {
        t ^= (q - 1) & (0u - ((axes[2] & q) != 0 ? 1u : 0u));
    }
    for (std::uint32_t& a : axes) a ^= t;
    return spread_3(axes[0]) << 2 | spread_3(axes[1]) << 1 | spread_3(axes[2]);
}

}  // namespace

/// 3D Hilbert keys of all points on a 2^10 grid per axis over their bounding box.
std::vector<std::uint32_t> hilbert_keys_3d(std::span<const double> xyz, std::uint32_t cell_shift,
                                           bool parallel) {
    const std::size_t n = xyz.size() / 3;
    std::vector<std::uint32_t> keys(n);
    if (n == 0) return keys;
    double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
    for (std::size_t i = 1; i < n; ++i) {
        for (std::size_t c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], xyz[3 * i + c]);
            hi[c] = std::max(hi[c], xyz[3 * i + c]);
        }
    }
    // Halves keep huge extents (up to the double range) from overflowing.
    double half[3];
    for (std::size_t c = 0; c < 3; ++c) half[c] = hi[c] / 2 - lo[c] / 2;
    auto cell = [](double v, double low, double half_span) -> std::uint32_t {
        if (!(half_span > 0)) return 0;
        const double t = (v / 2 - low / 2) / half_span;
        return static_cast<std::uint32_t>(std::clamp(t, 0.0, 1.0) * 1023.0);
    };
    auto compute = [&](std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            keys[i] = hilbert_key_3d((cell(xyz[3 * i], lo[0], half[0]) + cell_shift) & 0x3FFu,
                                     (cell(xyz[3 * i + 1], lo[1], half[1]) + cell_shift) & 0x3FFu,
                                     (cell(xyz[3 * i + 2], lo[2], half[2]) + cell_shift) & 0x3FFu);
        }
    };
    compute_in_chunks(n, parallel, compute);
    return keys;
}

namespace {

/// A random permutation of 0..n-1, or the identity for the given order.
std::vector<std::uint32_t> shuffled(std::size_t n, InsertionOrder order, std::uint64_t seed) {
    std::vector<std::uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    if (order == InsertionOrder::Given) return perm;
    std::mt19937_64 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    return perm;
}

/// BRIO: rounds [0, n/2^k) ... [n/4, n/2), [n/2, n) of the shuffled `perm`, each sorted by key;
/// the first round stays small (at most 64 points) and random.
void sort_brio_rounds(std::span<const std::uint32_t> keys, std::vector<std::uint32_t>& perm,
                      bool parallel) {
    std::vector<std::size_t> ends;
    for (std::size_t end = perm.size(); end > 64; end /= 2) ends.push_back(end);
    auto sort_round = [&](std::size_t r, std::vector<std::uint64_t>& keyed,
                          std::vector<std::uint64_t>& scratch) {
        const std::size_t begin = ends[r] / 2;
        sort_by_keys(keys, std::span<std::uint32_t>(perm).subspan(begin, ends[r] - begin), keyed,
                     scratch);
    };
    if (parallel) {
        // The rounds are disjoint: the largest (half the points) on one thread, the others
        // (the other half) beside it.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, ends.size(), 1),
                          [&](const tbb::blocked_range<std::size_t>& rounds) {
                              std::vector<std::uint64_t> keyed, scratch;
                              for (std::size_t r = rounds.begin(); r != rounds.end(); ++r)
                                  sort_round(r, keyed, scratch);
                          });
        return;
    }
    std::vector<std::uint64_t> keyed, scratch;
    for (std::size_t r = 0; r < ends.size(); ++r) sort_round(r, keyed, scratch);
}

/// The order of n points: shuffled() for Given and Random; for Brio, sort_brio_rounds with the
/// points' Hilbert keys (`keys()`, computed only then).
template <class Keys>
std::vector<std::uint32_t> insertion_order(std::size_t n, InsertionOrder order, std::uint64_t seed,
                                           Keys keys, bool parallel = false,
                                           std::vector<std::uint32_t>* keys_out = nullptr) {
    if (parallel && order == InsertionOrder::Brio) {
        // The shuffle (one random stream: sequential) beside the keys.
        std::vector<std::uint32_t> perm;
        std::vector<std::uint32_t> point_keys;
        tbb::parallel_invoke([&] { perm = shuffled(n, order, seed); },
                             [&] { point_keys = keys(); });
        sort_brio_rounds(point_keys, perm, true);
        if (keys_out != nullptr) *keys_out = std::move(point_keys);
        return perm;
    }
    std::vector<std::uint32_t> perm = shuffled(n, order, seed);
    if (order != InsertionOrder::Brio) return perm;
    sort_brio_rounds(keys(), perm, false);
    return perm;
}

/// Sorts `indices` by `keys` (keys[k] the key of indices[k]), in sort_by_keys's order.
void reorder_by_keys(std::span<const std::uint32_t> keys, std::span<std::uint32_t> indices) {
    std::vector<std::uint32_t> local(indices.size());
    std::iota(local.begin(), local.end(), 0u);
    std::vector<std::uint64_t> keyed, scratch;
    sort_by_keys(keys, local, keyed, scratch);
    std::vector<std::uint32_t> sorted(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) sorted[k] = indices[local[k]];
    std::copy(sorted.begin(), sorted.end(), indices.begin());
}

}  // namespace

void hilbert_sort_2d(std::span<const double> xy, std::span<std::uint32_t> indices) {
    if (indices.size() < 2) return;
    std::vector<double> subset(2 * indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        subset[2 * k] = xy[2 * indices[k]];
        subset[2 * k + 1] = xy[2 * indices[k] + 1];
    }
    reorder_by_keys(hilbert_keys_2d(subset), indices);
}

std::vector<std::uint32_t> insertion_order_2d(std::span<const double> xy, InsertionOrder order,
                                              std::uint64_t seed, bool parallel,
                                              std::vector<std::uint32_t>* keys) {
    EM_ASSERT(keys == nullptr || (parallel && order == InsertionOrder::Brio));
    return insertion_order(
        xy.size() / 2, order, seed, [xy, parallel] { return hilbert_keys_2d(xy, 0, parallel); },
        parallel, keys);
}

std::vector<std::uint32_t> insertion_order_3d(std::span<const double> xyz, InsertionOrder order,
                                              std::uint64_t seed, bool parallel,
                                              std::vector<std::uint32_t>* keys) {
    EM_ASSERT(keys == nullptr || (parallel && order == InsertionOrder::Brio));
    return insertion_order(
        xyz.size() / 3, order, seed, [xyz, parallel] { return hilbert_keys_3d(xyz, 0, parallel); },
        parallel, keys);
}

void hilbert_sort_3d(std::span<const double> xyz, std::span<std::uint32_t> indices) {
    if (indices.size() < 2) return;
    std::vector<double> subset(3 * indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k) {
        for (std::size_t c = 0; c < 3; ++c)
            subset[3 * k + c] = xyz[3 * std::size_t{indices[k]} + c];
    }
    reorder_by_keys(hilbert_keys_3d(subset), indices);
}

}  // namespace exactmesh::triangulation
