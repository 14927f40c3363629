// SPDX-License-Identifier: MIT
// BRIO rounds [AmentaChoiRote03] and a Hilbert-curve sort over a 2^16 x 2^16 grid (2D) or a
// 2^10 x 2^10 x 2^10 grid (3D, Skilling's transpose algorithm [Skilling04]). The grid only
// orders points; no geometric decision depends on it, so quantisation is harmless.
#include "triangulation/mesh/spatial_sort.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <bit>
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

/// kHilbert four levels at a time: for a state and the next four bits of x and y (index
/// 16 x + y), the curve's eight bits of digits (low byte) and the state after them (above).
struct HilbertNibbleSteps {
    std::uint16_t step[4][256];
};
constexpr HilbertNibbleSteps hilbert_nibble_steps() {
    HilbertNibbleSteps table{};
    for (unsigned first = 0; first < 4; ++first) {
        for (unsigned x = 0; x < 16; ++x) {
            for (unsigned y = 0; y < 16; ++y) {
                unsigned state = first, digits = 0;
                for (int bit = 3; bit >= 0; --bit) {
                    const unsigned quadrant = (((x >> bit) & 1u) << 1) | ((y >> bit) & 1u);
                    digits = (digits << 2) | kHilbert[state][quadrant].digit;
                    state = kHilbert[state][quadrant].next;
                }
                table.step[first][16 * x + y] = static_cast<std::uint16_t>(digits | state << 8);
            }
        }
    }
    return table;
}
constexpr HilbertNibbleSteps kHilbertNibbles = hilbert_nibble_steps();

/// Position of grid cell (x, y) along the Hilbert curve of order 16: four table steps of four
/// levels each (a chain of 16 one-level steps took 22 ns a point; the keys are the same).
std::uint32_t hilbert_key(std::uint32_t x, std::uint32_t y) {
    std::uint32_t key = 0;
    unsigned state = 0;
    for (int shift = 12; shift >= 0; shift -= 4) {
        const unsigned index = (((x >> shift) & 15u) << 4) | ((y >> shift) & 15u);
        const unsigned step = kHilbertNibbles.step[state][index];
        key = (key << 8) | (step & 0xFFu);
        state = step >> 8;
    }
    return key;
}

/// Stable LSD radix sort of (key << 32 | index) items by key: passes of 8 bits, the four
/// histograms counted in one read, a pass skipped when all items share its digit.
void radix_sort_by_key(std::span<std::uint64_t> items, std::vector<std::uint64_t>& scratch) {
    if (items.empty()) return;
    scratch.resize(items.size());
    std::size_t count[4][256] = {};
    for (const std::uint64_t item : items) {
        for (unsigned d = 0; d < 4; ++d) ++count[d][(item >> (32 + 8 * d)) & 0xFFu];
    }
    std::span<std::uint64_t> from = items, to(scratch.data(), scratch.size());
    for (unsigned d = 0; d < 4; ++d) {
        const unsigned shift = 32 + 8 * d;
        if (count[d][(items[0] >> shift) & 0xFFu] == items.size()) continue;
        std::size_t offset[256];
        for (std::size_t b = 0, sum = 0; b < 256; ++b) {
            offset[b] = sum;
            sum += count[d][b];
        }
        for (const std::uint64_t item : from) to[offset[(item >> shift) & 0xFFu]++] = item;
        std::swap(from, to);
    }
    if (from.data() != items.data()) std::copy(from.begin(), from.end(), items.begin());
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

std::vector<std::uint32_t> random_permutation(std::size_t n, std::uint64_t seed) {
    std::vector<std::uint32_t> perm(n);
    std::iota(perm.begin(), perm.end(), 0u);
    std::mt19937_64 rng(seed);
    std::shuffle(perm.begin(), perm.end(), rng);
    return perm;
}

std::vector<std::uint32_t> inverse_permutation(std::span<const std::uint32_t> perm, bool parallel) {
    std::vector<std::uint32_t> inverse(perm.size());
    auto compute = [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k) inverse[perm[k]] = static_cast<std::uint32_t>(k);
    };
    compute_in_chunks(perm.size(), parallel, compute);
    return inverse;
}

std::vector<std::uint32_t> brio_round_begins(std::uint32_t n) {
    std::vector<std::uint32_t> ends;
    for (std::uint32_t end = n; end > 64; end >>= kBrioRoundShift) ends.push_back(end);
    std::vector<std::uint32_t> begin{0};
    for (auto end = ends.rbegin(); end != ends.rend(); ++end)
        begin.push_back(*end >> kBrioRoundShift);
    begin.push_back(n);
    return begin;
}

// The points are dealt to their rounds by position in input order (reading the keys in order,
// where gathering them by the shuffled index missed the cache at every point), sorted by key
// (stable: equal keys in input order), then each run of equal keys, and the first round, by
// position: the order of sorting the shuffled points' rounds by key, with a stable sort,
// exactly (frontal_delaunay_3d on the wing at size 0.08 did not finish in minutes when equal
// keys, or the rounds, came in another order: an order-sensitive fault there, not fixed here).
// Each item is (key << 32 | point), the first round's key its position; with `parallel`, the
// points are dealt in chunks (each chunk's count per round first) and the rounds sorted on the
// arena.
std::vector<std::uint32_t> brio_order(std::span<const std::uint32_t> keys,
                                      std::span<const std::uint32_t> position, bool parallel) {
    const std::size_t n = keys.size();
    EM_ASSERT(position.size() == n);
    EM_ASSERT(n <= 0xFFFFFFFFu);
    // begin[r] .. begin[r + 1]: round r's positions.
    const std::vector<std::uint32_t> begin = brio_round_begins(static_cast<std::uint32_t>(n));
    const std::size_t rounds = begin.size() - 1;
    // Round r >= 1 holds the positions [n >> 3j, n >> 3(j - 1)) for j = rounds - r, round 0
    // those below n >> 3(rounds - 1). The smallest j with n >> 3j <= at (at < n): with d the
    // difference of the bit widths of n and at, n >> 3j is above at when 3j < d and below when
    // 3j > d, so j is d / 3 rounded up, or d / 3 + 1 when 3 divides d and n >> d is above at
    // (no loop: the rounds are random, and a loop's exits were mispredicted at about every
    // point).
    static_assert(kBrioRoundShift == 3);
    const std::size_t last_j = rounds - 1;
    auto round_of = [n, last_j](std::size_t at) -> std::size_t {
        const auto d = static_cast<std::size_t>(std::bit_width(n) - std::bit_width(at));
        const std::size_t j = d / 3 + (d % 3 != 0 || (n >> d) > at ? 1 : 0);
        return j > last_j ? 0 : last_j + 1 - j;
    };
    auto item = [&](std::size_t i, std::size_t r) {
        const std::uint64_t key = r == 0 ? position[i] : keys[i];
        return key << 32 | i;
    };
    std::vector<std::uint64_t> items(n);
    // Chunks of points dealt in order: chunk c's points of round r go after those of the
    // chunks before it (every chunk's count of each round first).
    const std::size_t chunk = parallel ? std::size_t{1} << 16 : std::max<std::size_t>(n, 1);
    const std::size_t chunks = (n + chunk - 1) / chunk;
    std::vector<std::size_t> cursor(chunks * rounds, 0);
    auto for_chunks = [&](auto&& body) {
        if (parallel) {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  for (std::size_t c = r.begin(); c != r.end(); ++c) body(c);
                              });
        } else {
            for (std::size_t c = 0; c < chunks; ++c) body(c);
        }
    };
    if (chunks == 1) {
        for (std::size_t r = 0; r < rounds; ++r) cursor[r] = begin[r];
    } else {
        for_chunks([&](std::size_t c) {
            for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i)
                ++cursor[c * rounds + round_of(position[i])];
        });
        for (std::size_t r = 0; r < rounds; ++r) {
            std::size_t at = begin[r];
            for (std::size_t c = 0; c < chunks; ++c) {
                const std::size_t count = cursor[c * rounds + r];
                cursor[c * rounds + r] = at;
                at += count;
            }
        }
    }
    for_chunks([&](std::size_t c) {
        std::size_t* next = &cursor[c * rounds];
        for (std::size_t i = c * chunk; i < std::min(n, (c + 1) * chunk); ++i) {
            const std::size_t r = round_of(position[i]);
            items[next[r]++] = item(i, r);
        }
    });
    auto sort_round = [&](std::size_t r, std::vector<std::uint64_t>& scratch) {
        const std::span<std::uint64_t> round =
            std::span<std::uint64_t>(items).subspan(begin[r], begin[r + 1] - begin[r]);
        radix_sort_by_key(round, scratch);
        for (std::size_t k = 0; k + 1 < round.size();) {
            std::size_t end = k + 1;
            while (end < round.size() && round[end] >> 32 == round[k] >> 32) ++end;
            if (end - k > 1) {
                std::sort(round.begin() + static_cast<std::ptrdiff_t>(k),
                          round.begin() + static_cast<std::ptrdiff_t>(end),
                          [&](std::uint64_t a, std::uint64_t b) {
                              return position[a & 0xFFFFFFFFu] < position[b & 0xFFFFFFFFu];
                          });
            }
            k = end;
        }
    };
    if (parallel) {
        // The rounds are disjoint: the largest (7/8 of the points) on one thread, the others
        // beside it.
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rounds, 1),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              std::vector<std::uint64_t> scratch;
                              for (std::size_t k = r.begin(); k != r.end(); ++k)
                                  sort_round(k, scratch);
                          });
    } else {
        std::vector<std::uint64_t> scratch;
        for (std::size_t r = 0; r < rounds; ++r) sort_round(r, scratch);
    }
    std::vector<std::uint32_t> order(n);
    for (std::size_t k = 0; k < n; ++k)
        order[k] = static_cast<std::uint32_t>(items[k] & 0xFFFFFFFFu);
    return order;
}

namespace {

/// The order of n points: the identity, a random permutation, or the BRIO order of the points'
/// Hilbert keys (`keys()`, computed only then; with `parallel`, beside the random stream).
template <class Keys>
std::vector<std::uint32_t> insertion_order(std::size_t n, InsertionOrder order, std::uint64_t seed,
                                           Keys keys, bool parallel) {
    if (order == InsertionOrder::Random) return random_permutation(n, seed);
    if (order == InsertionOrder::Given) {
        std::vector<std::uint32_t> identity(n);
        std::iota(identity.begin(), identity.end(), 0u);
        return identity;
    }
    std::vector<std::uint32_t> position;
    std::vector<std::uint32_t> point_keys;
    if (parallel) {
        tbb::parallel_invoke(
            [&] { position = inverse_permutation(random_permutation(n, seed), true); },
            [&] { point_keys = keys(); });
    } else {
        position = inverse_permutation(random_permutation(n, seed));
        point_keys = keys();
    }
    return brio_order(point_keys, position, parallel);
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
                                              std::uint64_t seed, bool parallel) {
    return insertion_order(
        xy.size() / 2, order, seed, [xy, parallel] { return hilbert_keys_2d(xy, 0, parallel); },
        parallel);
}

std::vector<std::uint32_t> insertion_order_3d(std::span<const double> xyz, InsertionOrder order,
                                              std::uint64_t seed, bool parallel) {
    return insertion_order(
        xyz.size() / 3, order, seed, [xyz, parallel] { return hilbert_keys_3d(xyz, 0, parallel); },
        parallel);
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
