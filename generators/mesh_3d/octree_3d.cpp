// SPDX-License-Identifier: MIT
// The 2:1 balanced octree (see octree_3d.hpp).
#include "generators/mesh_3d/octree_3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"

namespace exactmesh::generators {

namespace {

constexpr std::uint64_t kAxisMask = (std::uint64_t{1} << 19) - 1;

OctreeCell3 decode(std::uint64_t key) {
    return {static_cast<std::uint32_t>(key >> 57),
            static_cast<std::uint32_t>((key >> 38) & kAxisMask),
            static_cast<std::uint32_t>((key >> 19) & kAxisMask),
            static_cast<std::uint32_t>(key & kAxisMask)};
}

}  // namespace

Octree3::Octree3(const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
    double extent = 0;
    for (std::size_t a = 0; a < 3; ++a) {
        if (!std::isfinite(lo[a]) || !std::isfinite(hi[a]) || !(lo[a] <= hi[a]))
            throw InputError("octree: the bounding box is empty or not finite");
        extent = std::max(extent, hi[a] - lo[a]);
    }
    if (!(extent > 0)) throw InputError("octree: the bounding box has no extent");
    int exponent = 0;
    std::frexp(extent, &exponent);  // extent < 2^exponent
    double edge = std::ldexp(1.0, exponent);
    if (std::ldexp(1.0, exponent - 1) >= extent) edge = std::ldexp(1.0, exponent - 1);
    // The smallest power-of-two cube aligned to half its edge: double the edge until the
    // aligned cube holding lo holds hi too on every axis (it does once the edge is twice the
    // extent). Aligned to the whole edge, no cube would hold a box straddling zero.
    for (bool fits = false; !fits;) {
        fits = true;
        for (std::size_t a = 0; a < 3; ++a) {
            const double half = edge / 2;
            corner_[a] = std::floor(lo[a] / half) * half;
            if (corner_[a] + edge < hi[a]) fits = false;
        }
        if (!fits) edge *= 2;
    }
    edge_ = edge;
    // Grid coordinates c + i * edge / 2^kMaxLevel are exact while |c| / edge * 2^kMaxLevel and
    // i stay below 2^52.
    for (std::size_t a = 0; a < 3; ++a) {
        if (std::fabs(corner_[a] / edge_) > std::ldexp(1.0, 52 - static_cast<int>(kMaxLevel) - 1))
            throw InputError(
                "octree: the domain lies too far from the origin for its size (corner " +
                format_number(corner_[a]) + ", edge " + format_number(edge_) +
                "): grid coordinates would not be exact; translate it");
    }
    leaf_keys_.insert(key(0, 0, 0, 0));
    finish();
}

std::uint64_t Octree3::key(std::uint32_t level, std::uint32_t i, std::uint32_t j, std::uint32_t k) {
    return (std::uint64_t{level} << 57) | (std::uint64_t{i} << 38) | (std::uint64_t{j} << 19) |
           std::uint64_t{k};
}

double Octree3::cell_edge(std::uint32_t level) const {
    return std::ldexp(edge_, -static_cast<int>(level));
}

double Octree3::cell_min(const OctreeCell3& cell, int axis) const {
    return corner_[static_cast<std::size_t>(axis)] + cell.index(axis) * cell_edge(cell.level);
}

double Octree3::cell_max(const OctreeCell3& cell, int axis) const {
    return corner_[static_cast<std::size_t>(axis)] +
           (cell.index(axis) + 1.0) * cell_edge(cell.level);
}

std::uint32_t Octree3::containing_level(std::uint32_t level, std::int64_t i, std::int64_t j,
                                        std::int64_t k) const {
    const std::int64_t n = std::int64_t{1} << level;
    if (i < 0 || j < 0 || k < 0 || i >= n || j >= n || k >= n) return kOutside;
    const auto ui = static_cast<std::uint32_t>(i), uj = static_cast<std::uint32_t>(j),
               uk = static_cast<std::uint32_t>(k);
    if (split_keys_.count(key(level, ui, uj, uk)) != 0) return kFiner;
    for (std::uint32_t l = level + 1; l-- > 0;) {
        const std::uint32_t shift = level - l;
        if (leaf_keys_.count(key(l, ui >> shift, uj >> shift, uk >> shift)) != 0) return l;
    }
    return kOutside;  // unreachable: the leaves partition the root
}

std::uint32_t Octree3::find_leaf(std::uint32_t level, std::int64_t i, std::int64_t j,
                                 std::int64_t k) const {
    const std::uint32_t l = containing_level(level, i, j, k);
    if (l == kOutside || l == kFiner) return l;
    const std::uint32_t shift = level - l;
    return leaf_index_.at(key(l, static_cast<std::uint32_t>(i) >> shift,
                              static_cast<std::uint32_t>(j) >> shift,
                              static_cast<std::uint32_t>(k) >> shift));
}

void Octree3::split_leaf(const OctreeCell3& cell, std::vector<OctreeCell3>& created) {
    if (cell.level >= kMaxLevel) {
        throw InputError("octree: refinement below level " + std::to_string(kMaxLevel) +
                         " (cells of edge " + format_number(cell_edge(kMaxLevel)) +
                         "): the size is too small for the domain's extent");
    }
    if (leaf_keys_.size() + 7 > max_leaves_) {
        throw InputError("octree: leaf budget of " + std::to_string(max_leaves_) +
                         " exceeded while refining; raise the size or the budget");
    }
    leaf_keys_.erase(key(cell.level, cell.i, cell.j, cell.k));
    split_keys_.insert(key(cell.level, cell.i, cell.j, cell.k));
    for (std::uint32_t c = 0; c < 8; ++c) {
        const OctreeCell3 child{cell.level + 1, 2 * cell.i + (c & 1), 2 * cell.j + ((c >> 1) & 1),
                                2 * cell.k + ((c >> 2) & 1)};
        leaf_keys_.insert(key(child.level, child.i, child.j, child.k));
        created.push_back(child);
    }
}

void Octree3::refine_and_balance(const std::function<bool(const OctreeCell3&)>& split,
                                 std::uint64_t max_leaves) {
    max_leaves_ = max_leaves;
    std::vector<OctreeCell3> work = leaves_;
    while (!work.empty()) {
        const OctreeCell3 cell = work.back();
        work.pop_back();
        if (split(cell)) split_leaf(cell, work);
    }
    // Balance: a leaf checks its 26 neighbours; a neighbour leaf more than one level coarser is
    // split (its children re-check theirs, the leaf re-checks itself).
    for (const std::uint64_t k : leaf_keys_) work.push_back(decode(k));
    std::sort(work.begin(), work.end(), [](const OctreeCell3& a, const OctreeCell3& b) {
        return key(a.level, a.i, a.j, a.k) < key(b.level, b.i, b.j, b.k);
    });
    while (!work.empty()) {
        const OctreeCell3 cell = work.back();
        work.pop_back();
        if (cell.level < 2 || leaf_keys_.count(key(cell.level, cell.i, cell.j, cell.k)) == 0)
            continue;
        bool again = false;
        for (int d = 0; d < 27 && !again; ++d) {
            if (d == 13) continue;  // the cell itself
            const std::int64_t ni = std::int64_t{cell.i} + d % 3 - 1,
                               nj = std::int64_t{cell.j} + (d / 3) % 3 - 1,
                               nk = std::int64_t{cell.k} + d / 9 - 1;
            const std::uint32_t l = containing_level(cell.level, ni, nj, nk);
            if (l == kOutside || l == kFiner || l + 1 >= cell.level) continue;
            const std::uint32_t shift = cell.level - l;
            split_leaf(
                {l, static_cast<std::uint32_t>(ni) >> shift,
                 static_cast<std::uint32_t>(nj) >> shift, static_cast<std::uint32_t>(nk) >> shift},
                work);
            ++balance_splits_;
            again = true;
        }
        if (again) work.push_back(cell);
    }
    finish();
}

void Octree3::finish() {
    std::vector<std::uint64_t> keys(leaf_keys_.begin(), leaf_keys_.end());
    std::sort(keys.begin(), keys.end());
    leaves_.clear();
    leaf_index_.clear();
    max_level_ = 0;
    for (const std::uint64_t k : keys) {
        leaf_index_.emplace(k, static_cast<std::uint32_t>(leaves_.size()));
        leaves_.push_back(decode(k));
        max_level_ = std::max(max_level_, leaves_.back().level);
    }
}

}  // namespace exactmesh::generators
