// SPDX-License-Identifier: MIT
// The truncated structured O-mesh (see truncated_omesh_2d.hpp): the rings and their points
// (OMeshBuilder::make_rings), the cuts (cut_folds, cut_overlaps, cut_steps), then the region
// for the shared fill and merge (region).
#include "generators/stretched/truncated_omesh_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/stretched/layer_mesh_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;
using layer_mesh::BucketGrid;
using layer_mesh::distance;
using layer_mesh::segments_conflict;
using tri::kNone;
using tri::VertIdx;

namespace {

/// The widest corner a kept cell may have: 160 degrees, as the corner at (0, 0) from (1, 0)
/// to (cos 160, sin 160) rounded to doubles.
const double kWideCorner[3][2] = {{0, 0}, {1, 0}, {-0.93969262078590838, 0.34202014332566871}};

/// A ring: the O-mesh of one wall loop.
struct Ring {
    WallLoop2 wall;
    std::uint32_t layers = 0;       ///< K: its truncation layer
    std::uint32_t first_stack = 0;  ///< its stacks (normal lines) and columns, consecutive
    std::uint32_t first_point = 0;  ///< its points: stack s, layer k >= 1 at first_point +
                                    ///< (s - first_stack) K + k - 1
    std::uint32_t first_guard = 0;  ///< guard points: two per cell
    std::uint32_t first_cell = 0;   ///< cell (column j, layer k) at first_cell + (j -
                                    ///< first_stack) K + k
    std::vector<double> heights;    ///< heights[k]: layer k's height, h (1 + ... + g^(k-1))
    std::uint32_t size() const { return static_cast<std::uint32_t>(wall.vertices.size()); }
};

/// A cell or a guard: four corners, counter-clockwise, with their ids.
using Quad = std::array<VertIdx, 4>;

class OMeshBuilder {
  public:
    OMeshBuilder(const tri::Cdt2Result& domain, const LayerParameters2& parameters,
                 AdvancingLayersCounters2& counters)
        : domain_(domain),
          parameters_(parameters),
          counters_(counters),
          base_(static_cast<VertIdx>(domain.mesh.xy.size() / 2)) {}

    void build() {
        make_rings();
        if (cells_ == 0) return;
        cut_folds();
        cut_overlaps();
        cut_steps();
    }

    /// The points used, the cells kept, the fronts and the stacks' layers.
    layer_mesh::LayeredRegion2 region() const {
        layer_mesh::LayeredRegion2 r;
        r.xy = domain_.mesh.xy;
        std::vector<VertIdx> real(candidates_.size() / 2, kNone);
        const auto id = [&](std::uint32_t s, std::uint32_t k) {
            const Ring& ring = rings_[ring_of_[s]];
            if (k == 0) return ring.wall.vertices[s - ring.first_stack];
            const std::uint32_t c = ring.first_point + (s - ring.first_stack) * ring.layers + k - 1;
            if (real[c] == kNone) {
                real[c] = static_cast<VertIdx>(r.xy.size() / 2);
                r.xy.push_back(candidates_[2 * c]);
                r.xy.push_back(candidates_[2 * c + 1]);
            }
            return real[c];
        };
        for (const Ring& ring : rings_) {
            const std::uint32_t n = ring.size();
            r.add_wall_loop(ring.wall.vertices);
            std::vector<VertIdx> front;
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t s = ring.first_stack + i;
                const std::uint32_t left = height_[ring.first_stack + (i + n - 1) % n];
                const std::uint32_t right = height_[s];
                r.stack_layers.emplace_back(id(s, 0), std::max(left, right));
                // Along the normal line from the left column's top to the right column's.
                for (std::uint32_t k = left;; k = left < right ? k + 1 : k - 1) {
                    front.push_back(id(s, k));
                    if (k == right) break;
                }
            }
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t s = ring.first_stack + i, t = ring.first_stack + (i + 1) % n;
                for (std::uint32_t k = 0; k < height_[s]; ++k) {
                    layer_mesh::Cell c;
                    c.v = {id(s, k), id(t, k), id(t, k + 1), id(s, k + 1)};
                    r.cells.push_back(c);
                }
            }
            r.fronts.push_back(std::move(front));
        }
        counters_.layer_points = r.xy.size() / 2 - base_;
        return r;
    }

  private:
    const double* point(VertIdx v) const {
        return v < base_ ? &domain_.mesh.xy[2 * static_cast<std::size_t>(v)]
                         : &candidates_[2 * static_cast<std::size_t>(v - base_)];
    }
    std::uint32_t next_stack(std::uint32_t s) const {
        const Ring& ring = rings_[ring_of_[s]];
        return s + 1 == ring.first_stack + ring.size() ? ring.first_stack : s + 1;
    }
    VertIdx point_id(std::uint32_t s, std::uint32_t k) const {
        const Ring& ring = rings_[ring_of_[s]];
        if (k == 0) return ring.wall.vertices[s - ring.first_stack];
        return base_ + ring.first_point + (s - ring.first_stack) * ring.layers + k - 1;
    }
    std::uint32_t cell_index(std::uint32_t j, std::uint32_t k) const {
        const Ring& ring = rings_[ring_of_[j]];
        return ring.first_cell + (j - ring.first_stack) * ring.layers + k;
    }
    /// Cell (column j, layer k): its corners counter-clockwise (the domain on the wall's left).
    Quad cell(std::uint32_t j, std::uint32_t k) const {
        const std::uint32_t t = next_stack(j);
        return {point_id(j, k), point_id(t, k), point_id(t, k + 1), point_id(j, k + 1)};
    }
    Quad guard(std::uint32_t j, std::uint32_t k) const {
        const VertIdx g = base_ + rings_[ring_of_[j]].first_guard +
                          2 * (cell_index(j, k) - rings_[ring_of_[j]].first_cell);
        return {point_id(j, k), point_id(next_stack(j), k), g + 1, g};
    }

    void make_rings() {
        const double h = parameters_.first_height, g = parameters_.growth;
        std::uint64_t points = 0;
        for (WallLoop2& wall : wall_loops_2d(domain_.mesh)) {
            wall_normals_2d(domain_.mesh, wall, 2);
            Ring ring;
            std::vector<double> spacing = wall.spacing;
            std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
            const double median = spacing[spacing.size() / 2];
            for (double thickness = h; thickness < median && ring.layers < parameters_.max_layers;
                 thickness *= g)
                ++ring.layers;
            ring.first_stack = static_cast<std::uint32_t>(ring_of_.size());
            ring_of_.resize(ring_of_.size() + wall.vertices.size(),
                            static_cast<std::uint32_t>(rings_.size()));
            ring.wall = std::move(wall);
            points += std::uint64_t{ring.size()} * (3 * ring.layers);
            rings_.push_back(std::move(ring));
        }
        counters_.wall_loops = counters_.omesh_rings = rings_.size();
        counters_.stacks = counters_.wall_vertices = ring_of_.size();
        if (points + base_ > tri::kMaxPoints) {
            throw InputError("truncated O-mesh: " + std::to_string(ring_of_.size()) +
                             " normal lines of up to " + std::to_string(parameters_.max_layers) +
                             " layers exceed the vertex limit; give fewer layers");
        }
        height_.assign(ring_of_.size(), 0);
        counters_.omesh_min_ring_layers = rings_.empty() ? 0 : kMaxLayers;
        for (Ring& ring : rings_) {
            counters_.omesh_min_ring_layers =
                std::min<std::uint64_t>(counters_.omesh_min_ring_layers, ring.layers);
            counters_.omesh_max_ring_layers =
                std::max<std::uint64_t>(counters_.omesh_max_ring_layers, ring.layers);
            const std::uint32_t n = ring.size(), K = ring.layers;
            ring.first_point = static_cast<std::uint32_t>(candidates_.size() / 2);
            // Layer k at height h (1 + g + ... + g^(k-1)) along the normal, rounded once.
            std::vector<double>& heights = ring.heights;
            heights.resize(K + 2);
            std::vector<double> thickness(K + 2);
            double sum = 0, power = 1;
            for (std::uint32_t k = 0; k <= K + 1; ++k) {
                heights[k] = h * sum;
                thickness[k] = h * power;  // of layer k + 1
                sum += power;
                power *= g;
            }
            for (std::uint32_t i = 0; i < n; ++i) {
                const double* p = point(ring.wall.vertices[i]);
                const std::array<double, 2>& d = ring.wall.normals[i];
                for (std::uint32_t k = 1; k <= K; ++k) {
                    candidates_.push_back(std::fma(heights[k], d[0], p[0]));
                    candidates_.push_back(std::fma(heights[k], d[1], p[1]));
                }
                height_[ring.first_stack + i] = K;
            }
            // The guards: over cell (j, k), one layer up plus the larger of the next layer's
            // thickness and the cell's width at its top.
            ring.first_guard = static_cast<std::uint32_t>(candidates_.size() / 2);
            ring.first_cell = cells_;
            for (std::uint32_t i = 0; i < n; ++i) {
                const std::uint32_t j = ring.first_stack + i, t = next_stack(j);
                for (std::uint32_t k = 0; k < K; ++k) {
                    const double width =
                        distance(point(point_id(j, k + 1)), point(point_id(t, k + 1)));
                    const double reach = heights[k + 1] + std::max(thickness[k + 1], width);
                    for (const std::uint32_t s : {j, t}) {
                        const double* p = point(point_id(s, 0));
                        const std::array<double, 2>& d = ring.wall.normals[s - ring.first_stack];
                        candidates_.push_back(std::fma(reach, d[0], p[0]));
                        candidates_.push_back(std::fma(reach, d[1], p[1]));
                    }
                }
            }
            cells_ += n * K;
        }
    }

    bool convex(const Quad& q) const {
        for (int k = 0; k < 4; ++k) {
            if (pred::orient2d(point(q[k]), point(q[(k + 1) % 4]), point(q[(k + 2) % 4])) !=
                pred::Sign::Positive)
                return false;
        }
        return true;
    }

    /// Whether the strictly convex quad has a corner wider than the reference kWideCorner
    /// (exact compare_angles).
    bool has_wide_corner(const Quad& q) const {
        const pred::Corner reference{kWideCorner[0], kWideCorner[1], kWideCorner[2]};
        for (int k = 0; k < 4; ++k) {
            const pred::Corner corner{point(q[k]), point(q[(k + 1) % 4]), point(q[(k + 3) % 4])};
            if (pred::compare_angles(corner, reference) == pred::Sign::Positive) return true;
        }
        return false;
    }

    /// Cuts column j to at most k layers; counts the cells removed under `removed`.
    void cut(std::uint32_t j, std::uint32_t k, std::uint64_t& removed) {
        if (height_[j] <= k) return;
        removed += height_[j] - k;
        height_[j] = k;
    }

    /// Each column up to its first cell (or guard) that is not strictly convex, or whose cell
    /// has a corner wider than kWideCorner (at a sharp convex corner of the wall, where the
    /// normals of a structured ring splay without a fan, the cells' corner at the wall is
    /// about 90 degrees plus half the turn: the fill meshes the corner instead).
    void cut_folds() {
        for (std::uint32_t j = 0; j < height_.size(); ++j) {
            for (std::uint32_t k = 0; k < height_[j]; ++k) {
                const Quad c = cell(j, k);
                if (!convex(c) || !convex(guard(j, k)) || has_wide_corner(c)) {
                    cut(j, k, counters_.omesh_removed_fold);
                    break;
                }
            }
        }
    }

    /// Whether point v lies in the closed strictly convex quad q and is none of its corners.
    bool contains(const Quad& q, VertIdx v) {
        if (std::find(q.begin(), q.end(), v) != q.end()) return false;
        ++counters_.crossing_tests;
        for (int k = 0; k < 4; ++k) {
            if (pred::orient2d(point(q[k]), point(q[(k + 1) % 4]), point(v)) ==
                pred::Sign::Negative)
                return false;
        }
        return true;
    }

    /// Whether two closed strictly convex quads meet anywhere but at shared corners (and
    /// along shared edges): an edge conflict, or a corner of one in the other.
    bool meet(const Quad& a, const Quad& b) {
        for (int i = 0; i < 4; ++i) {
            for (int k = 0; k < 4; ++k) {
                ++counters_.crossing_tests;
                if (segments_conflict(a[i], a[(i + 1) % 4], b[k], b[(k + 1) % 4], point(a[i]),
                                      point(a[(i + 1) % 4]), point(b[k]), point(b[(k + 1) % 4])))
                    return true;
            }
        }
        for (int i = 0; i < 4; ++i)
            if (contains(a, b[i]) || contains(b, a[i])) return true;
        return false;
    }

    /// Whether the quad meets a boundary segment or a vertex of the domain (on a segment or
    /// free).
    bool meets_boundary(const Quad& q) {
        const auto [lo, hi] = box(q);
        bool found = false;
        piece_grid_->query(lo.data(), hi.data(), [&](std::uint32_t p) {
            if (found) return;
            const VertIdx a = domain_.pieces[2 * p], b = domain_.pieces[2 * p + 1];
            for (int k = 0; k < 4 && !found; ++k) {
                ++counters_.crossing_tests;
                found = segments_conflict(q[k], q[(k + 1) % 4], a, b, point(q[k]),
                                          point(q[(k + 1) % 4]), point(a), point(b));
            }
            found = found || contains(q, a) || contains(q, b);
        });
        // A vertex on no segment (a free input vertex) inside the cell would be left out.
        free_vertex_grid_->query(lo.data(), hi.data(), [&](std::uint32_t v) {
            if (!found && contains(q, v)) found = true;
        });
        return found;
    }

    std::array<std::array<double, 2>, 2> box(const Quad& q) const {
        std::array<double, 2> lo{point(q[0])[0], point(q[0])[1]}, hi = lo;
        for (const VertIdx v : q) {
            for (int axis = 0; axis < 2; ++axis) {
                lo[axis] = std::min(lo[axis], point(v)[axis]);
                hi[axis] = std::max(hi[axis], point(v)[axis]);
            }
        }
        return {lo, hi};
    }

    /// Whether columns i and j lie on one ring side by side (or are the same).
    bool neighbours(std::uint32_t i, std::uint32_t j) const {
        return i == j || next_stack(i) == j || next_stack(j) == i;
    }

    /// Removes every kept cell whose guard or self meets the boundary, and
    /// the coarser of every two kept cells (different rings, or columns not side by side) where
    /// the guard of one or the cell meets the other.
    void cut_overlaps() {
        // The bucket size: the median wall spacing, at most 2048 buckets across the domain.
        std::vector<double> spacings;
        for (const Ring& ring : rings_)
            spacings.insert(spacings.end(), ring.wall.spacing.begin(), ring.wall.spacing.end());
        std::nth_element(spacings.begin(), spacings.begin() + spacings.size() / 2, spacings.end());
        const std::vector<double>& xy = domain_.mesh.xy;
        double x0 = xy[0], y0 = xy[1], extent = 0;
        for (std::size_t v = 0; v < xy.size() / 2; ++v) {
            x0 = std::min(x0, xy[2 * v]);
            y0 = std::min(y0, xy[2 * v + 1]);
        }
        for (std::size_t v = 0; v < xy.size() / 2; ++v)
            extent = std::max({extent, xy[2 * v] - x0, xy[2 * v + 1] - y0});
        double bucket = std::max(spacings[spacings.size() / 2], extent / 2048);
        if (!(bucket > 0)) bucket = 1;
        piece_grid_ = std::make_unique<BucketGrid>(x0, y0, bucket);
        for (std::uint32_t p = 0; p < domain_.pieces.size() / 2; ++p)
            piece_grid_->insert(p, point(domain_.pieces[2 * p]), point(domain_.pieces[2 * p + 1]));
        std::vector<std::uint8_t> on_piece(base_, 0);
        for (const VertIdx v : domain_.pieces) on_piece[v] = 1;
        free_vertex_grid_ = std::make_unique<BucketGrid>(x0, y0, bucket);
        for (VertIdx v = 0; v < base_; ++v)
            if (!on_piece[v]) free_vertex_grid_->insert(v, point(v), point(v));
        BucketGrid cells(x0, y0, bucket);
        std::vector<std::array<std::uint32_t, 2>> cell_at(cells_);
        for (std::uint32_t j = 0; j < height_.size(); ++j) {
            for (std::uint32_t k = 0; k < height_[j]; ++k) {
                const auto [lo, hi] = box(cell(j, k));
                cells.insert(cell_index(j, k), lo.data(), hi.data());
                cell_at[cell_index(j, k)] = {j, k};
            }
        }
        // One pass suffices: the cells do not move, so a pair that does not meet now never
        // will, and every pair that meets loses at least one of its cells (and the cells above
        // it) here; the kept cells are then pairwise clear (the tests assert it through the
        // exact check and the areas).
        {
            std::vector<std::uint32_t> cut_at = height_;
            for (std::uint32_t j = 0; j < height_.size(); ++j) {
                for (std::uint32_t k = 0; k < height_[j]; ++k) {
                    const Quad a = cell(j, k), ga = guard(j, k);
                    if (meets_boundary(ga) || meets_boundary(a)) {
                        cut_at[j] = std::min(cut_at[j], k);
                        break;
                    }
                    const auto [lo, hi] = box(ga);
                    cells.query(lo.data(), hi.data(), [&](std::uint32_t other) {
                        const auto [i, m] = cell_at[other];
                        if (m >= height_[i] || i == j) return;
                        const Quad b = cell(i, m);
                        const bool side_by_side = neighbours(i, j);
                        // Side by side on a ring: only the cells themselves, never the guards
                        // (they reach over the neighbour's cells by design).
                        if (!(side_by_side ? meet(a, b) : meet(ga, b) || meet(a, b))) return;
                        if (k >= m) cut_at[j] = std::min(cut_at[j], k);
                        if (m >= k) cut_at[i] = std::min(cut_at[i], m);
                    });
                }
            }
            for (std::uint32_t j = 0; j < height_.size(); ++j)
                cut(j, cut_at[j], counters_.omesh_removed_overlap);
        }
    }

    /// Whether column `high` may stand above its neighbour `low` (sharing the normal line
    /// `line`): by at most two layers, or by a height at most the wall spacing there (so the
    /// fill closes the step with triangles about as tall as wide; near the wall, where the
    /// layers are thin, a step may span many layers).
    bool step_allowed(std::uint32_t high, std::uint32_t low, std::uint32_t line) const {
        const Ring& ring = rings_[ring_of_[line]];
        const std::uint32_t a = height_[high], b = height_[low];
        return a <= b + 2 ||
               ring.heights[a] - ring.heights[b] <= ring.wall.spacing[line - ring.first_stack];
    }

    /// Lowers columns until every step between neighbours on a ring is allowed.
    void cut_steps() {
        for (bool changed = true; changed;) {
            changed = false;
            for (std::uint32_t j = 0; j < height_.size(); ++j) {
                const std::uint32_t t = next_stack(j);
                for (const auto& [high, low] : {std::pair{j, t}, std::pair{t, j}}) {
                    while (!step_allowed(high, low, t)) {
                        cut(high, height_[high] - 1, counters_.omesh_removed_step);
                        changed = true;
                    }
                }
            }
        }
    }

    const tri::Cdt2Result& domain_;
    const LayerParameters2& parameters_;
    AdvancingLayersCounters2& counters_;
    const VertIdx base_;
    std::vector<Ring> rings_;
    std::vector<std::uint32_t> ring_of_;  ///< per stack (and column): its ring
    std::vector<double> candidates_;      ///< layer points, then guard points (ids from base_)
    std::vector<std::uint32_t> height_;   ///< per column: the layers kept
    std::uint32_t cells_ = 0;
    std::unique_ptr<BucketGrid> piece_grid_;
    std::unique_ptr<BucketGrid> free_vertex_grid_;  ///< domain vertices on no segment
};

}  // namespace

AdvancingLayersResult2 truncated_omesh_2d(const MeshDomain2& domain,
                                          const AdvancingLayersOptions2& options) {
    EM_ASSERT(options.fill != nullptr);
    validate_layer_parameters(options.layers);
    AdvancingLayersResult2 result;
    AdvancingLayersCounters2& counters = result.counters;
    OMeshBuilder builder(domain.triangulation(), options.layers, counters);
    builder.build();
    layer_mesh::LayeredRegion2 region = builder.region();
    counters.omesh_cells = region.cells.size();
    for (const auto& [base, layers] : region.stack_layers)
        counters.layers = std::max<std::uint64_t>(counters.layers, layers);
    layer_mesh::finish_layered_mesh_2d(domain, options, region, result);
    return result;
}

}  // namespace exactmesh::generators
