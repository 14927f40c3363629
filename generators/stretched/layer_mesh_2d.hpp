// SPDX-License-Identifier: MIT
// What the two layered generators share (advancing layers and the truncated O-mesh, see
// advancing_layers_2d.hpp and truncated_omesh_2d.hpp): the bucket grid that picks the pairs for
// the exact crossing tests, the exact segment conflict test, the layer cells, and the last
// phase: the front (the outer edges of the layers), the fill from it, the merge of the two
// meshes and their exact check (finish_layered_mesh_2d). Internal to generators/stretched.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "generators/stretched/advancing_layers_2d.hpp"
#include "generators/stretched/wall_loops_2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators::layer_mesh {

using triangulation::kNone;
using triangulation::VertIdx;

/// (x, y) over its scale-free length; (0, 0) for the zero vector.
inline std::array<double, 2> unit_vector(double x, double y) {
    const double n = predicates::scale_free_norm(x, y);
    if (!(n > 0)) return {0, 0};
    return {x / n, y / n};
}

/// The id of a probe's far end (segments_conflict): no vertex has it.
constexpr VertIdx kProbe = kNone - 1;

struct Vec {
    double x = 0, y = 0;
};

/// The unit vector of (x, y), computed on the vector scaled by a power of two (exact under
/// 2^k scaling of the input; no overflow or underflow at 2^+-600).
inline Vec unit(double x, double y) {
    const double length = predicates::scale_free_norm(x, y);
    if (length == 0) return {0, 0};
    return {x / length, y / length};
}

inline double distance(const double* a, const double* b) {
    return predicates::scale_free_norm(b[0] - a[0], b[1] - a[1]);
}

/// A bucket grid over the plane for the crossing tests: items (segments, points) are kept in
/// every cell their bounding box meets, so two items whose boxes meet share a cell. It only
/// chooses which pairs are tested; every decision is exact.
class BucketGrid {
  public:
    BucketGrid(double x0, double y0, double cell) : x0_(x0), y0_(y0), cell_(cell) {}

    void insert(std::uint32_t item, const double* a, const double* b) {
        const Box box = box_of(a, b);
        if (box.cells() > kLargeBox) {
            large_.push_back(item);
            return;
        }
        for (std::int64_t i = box.i0; i <= box.i1; ++i)
            for (std::int64_t j = box.j0; j <= box.j1; ++j) cells_[key(i, j)].push_back(item);
    }

    /// Calls visit(item) for every item whose cells meet the box of (a, b), possibly twice.
    template <class Visit>
    void query(const double* a, const double* b, Visit&& visit) const {
        for (const std::uint32_t item : large_) visit(item);
        const Box box = box_of(a, b);
        if (box.cells() > kLargeBox) {
            for (const auto& [k, items] : cells_)
                for (const std::uint32_t item : items) visit(item);
            return;
        }
        for (std::int64_t i = box.i0; i <= box.i1; ++i) {
            for (std::int64_t j = box.j0; j <= box.j1; ++j) {
                const auto found = cells_.find(key(i, j));
                if (found == cells_.end()) continue;
                for (const std::uint32_t item : found->second) visit(item);
            }
        }
    }

    void clear() {
        cells_.clear();
        large_.clear();
    }

  private:
    static constexpr std::int64_t kLargeBox = 4096;
    struct Box {
        std::int64_t i0, i1, j0, j1;
        std::int64_t cells() const { return (i1 - i0 + 1) * (j1 - j0 + 1); }
    };
    std::int64_t index(double value, double origin) const {
        // Monotone in value, so overlapping boxes give overlapping cell ranges.
        const double t = std::floor((value - origin) / cell_);
        return static_cast<std::int64_t>(std::clamp(t, -1e9, 1e9));
    }
    Box box_of(const double* a, const double* b) const {
        return {index(std::min(a[0], b[0]), x0_), index(std::max(a[0], b[0]), x0_),
                index(std::min(a[1], b[1]), y0_), index(std::max(a[1], b[1]), y0_)};
    }
    static std::uint64_t key(std::int64_t i, std::int64_t j) {
        return (static_cast<std::uint64_t>(i + (1ll << 31)) << 32) ^
               static_cast<std::uint64_t>(j + (1ll << 31));
    }
    double x0_, y0_, cell_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> large_;
};

/// Whether segments (a, b) and (c, d), given with their vertex ids, meet anywhere but at a
/// shared end: a crossing, a touch, or an overlap from a shared end. Exact.
bool segments_conflict(VertIdx ia, VertIdx ib, VertIdx ic, VertIdx id, const double* a,
                       const double* b, const double* c, const double* d);

/// A cell of the layers: a triangle (v[3] == kNone) or a quadrilateral, counter-clockwise.
struct Cell {
    std::array<VertIdx, 4> v{kNone, kNone, kNone, kNone};
    bool is_quad() const { return v[3] != kNone; }
};

/// A segment of the layers or of the domain, by its end vertices.
struct Segment {
    VertIdx a, b;
};

/// Splits the strictly convex quadrilateral (v0, v1, v2, v3) by the diagonal whose two
/// triangles have the smaller largest angle (exact; ties to the diagonal v0-v2).
void split_quad(const std::array<VertIdx, 4>& v, const std::vector<double>& xy,
                std::vector<VertIdx>& triangles);

/// What a layered generator built before the fill: the points (the domain's first, every
/// input vertex at its index), the cells, and per wall loop its front (the loop of outer
/// edges that the fill starts from; repeats removed).
struct LayeredRegion2 {
    std::vector<double> xy;
    std::vector<Cell> cells;
    std::vector<std::vector<VertIdx>> fronts;
    std::vector<std::vector<VertIdx>> wall_loops;  ///< the walls (domain on the left)
    /// Per stack (normal line): its wall vertex and the layers it reached.
    std::vector<std::pair<VertIdx, std::uint32_t>> stack_layers;
    bool is_wall_piece(VertIdx a, VertIdx b) const;
    void add_wall_loop(std::vector<VertIdx> loop);

  private:
    std::unordered_map<std::uint64_t, std::uint8_t> wall_edges_;
};

/// The front, the fill from it, the merge and the exact check, into result (whose counters
/// the layers have filled in already): the fill meshes the domain minus the walls and the
/// cells, its size kept at least 1.5 times the front's edges near them so that the front is
/// never split. Without fronts, the fill meshes the domain alone (a warning when layered).
/// @throws GeometryError when the fill breaks the front or the final check fails (a bug).
void finish_layered_mesh_2d(const MeshDomain2& domain, const AdvancingLayersOptions2& options,
                            LayeredRegion2& region, AdvancingLayersResult2& result);

}  // namespace exactmesh::generators::layer_mesh
