// SPDX-License-Identifier: MIT
// The truncated structured O-mesh (see truncated_omesh_2d.hpp): the rings and their points
// (OMeshBuilder::make_rings), the cuts (cut_folds, cut_overlaps, cut_steps, cut_unresolvable),
// then the region for the shared fill and merge (region).
#include "generators/stretched/truncated_omesh_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/stretched/layer_mesh_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"

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

/// A point of a ring by its normal line (stack) and layer (0: the wall vertex).
using LinePoint = std::array<std::uint32_t, 2>;

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
}

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
        grid_frame();
        cut_folds();
        cut_overlaps();
        cut_steps();
        cut_unresolvable();
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
                r.stack_layers.emplace_back(id(s, 0),
                                            std::max(height_[previous_stack(s)], height_[s]));
            }
            for (const auto& [s, k] : front_of(ring)) front.push_back(id(s, k));
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
    std::uint32_t previous_stack(std::uint32_t s) const {
        const Ring& ring = rings_[ring_of_[s]];
        return s == ring.first_stack ? ring.first_stack + ring.size() - 1 : s - 1;
    }
    /// The ring's front: along each normal line from the top of the column on its left to the
    /// top of the column on its right, then to the next line along the right column's top.
    std::vector<LinePoint> front_of(const Ring& ring) const {
        std::vector<LinePoint> front;
        for (std::uint32_t s = ring.first_stack; s < ring.first_stack + ring.size(); ++s) {
            const std::uint32_t left = height_[previous_stack(s)], right = height_[s];
            for (std::uint32_t k = left;; k = left < right ? k + 1 : k - 1) {
                front.push_back({s, k});
                if (k == right) break;
            }
        }
        return front;
    }
    /// The layer of point v (0 for the domain's vertices).
    std::uint32_t layer_of(VertIdx v) const { return v < base_ ? 0 : point_layer_[v - base_]; }
    /// Whether point v is in the fill's domain: a domain vertex, or a layer point of a kept
    /// cell (guards never are).
    bool in_use(VertIdx v) const {
        if (v < base_) return true;
        const std::uint32_t s = point_stack_[v - base_];
        return s != kNone &&
               point_layer_[v - base_] <= std::max(height_[previous_stack(s)], height_[s]);
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
                    point_stack_.push_back(ring.first_stack + i);
                    point_layer_.push_back(k);
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
                        point_stack_.push_back(kNone);
                        point_layer_.push_back(0);
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

    /// The bucket grids' origin and bucket size: the median wall spacing, at most 2048 buckets
    /// across the domain.
    void grid_frame() {
        std::vector<double> spacings;
        for (const Ring& ring : rings_)
            spacings.insert(spacings.end(), ring.wall.spacing.begin(), ring.wall.spacing.end());
        std::nth_element(spacings.begin(), spacings.begin() + spacings.size() / 2, spacings.end());
        const std::vector<double>& xy = domain_.mesh.xy;
        double extent = 0;
        x0_ = xy[0];
        y0_ = xy[1];
        for (std::size_t v = 0; v < xy.size() / 2; ++v) {
            x0_ = std::min(x0_, xy[2 * v]);
            y0_ = std::min(y0_, xy[2 * v + 1]);
        }
        for (std::size_t v = 0; v < xy.size() / 2; ++v)
            extent = std::max({extent, xy[2 * v] - x0_, xy[2 * v + 1] - y0_});
        bucket_ = std::max(spacings[spacings.size() / 2], extent / 2048);
        if (!(bucket_ > 0)) bucket_ = 1;
    }

    /// Removes every kept cell whose guard or self meets the boundary, and
    /// the coarser of every two kept cells (different rings, or columns not side by side) where
    /// the guard of one or the cell meets the other.
    void cut_overlaps() {
        const double x0 = x0_, y0 = y0_, bucket = bucket_;
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

    /// Whether the fill's constrained triangulation may bend segment a - b through vertex w (the
    /// chain rule bend_candidate of triangulation/constrained/cdt_conforming_2d.cpp, for a
    /// segment that is its own piece): w within rounding of the segment
    /// (predicates::within_rounding_of_segment, 2^-40 of w's largest coordinate) and strictly
    /// between a and b along it. Exact.
    bool bends(VertIdx w, VertIdx a, VertIdx b) {
        ++counters_.crossing_tests;
        const double *pa = point(a), *pb = point(b), *pw = point(w);
        if (!pred::within_rounding_of_segment(pw, pa, pb)) return false;
        const pred::Sign from_a = pred::direction_dot_sign(pa, pw, pa, pb);
        return from_a != pred::Sign::Zero && from_a == pred::direction_dot_sign(pw, pb, pa, pb);
    }

    /// Lowers columns until no vertex of the fill's domain (the domain's vertices and the layer
    /// points in use) lies within rounding of a segment of the fill (the fronts' edges and the
    /// domain's pieces off the walls) strictly between its ends (bends): the fill's constrained
    /// triangulation would bend that segment through the vertex and cut the front short. With a
    /// first height h of about 2^-40 of the coordinates or less (1e-12 beside x = 0.99 on the
    /// NACA 0012: the allowance is 9.1e-13), the first layer point of a normal line that tilts
    /// over the wall piece beside it, where the front runs along that piece (its column cut to
    /// the wall at a sharp trailing edge), lies within rounding of the piece. Of the vertex and
    /// the segment's ends, the layer point on the highest layer goes (the vertex on a tie):
    /// both columns beside its normal line are cut below it; pairs of domain vertices only are
    /// the domain's own and left to the fill (as without layers). Repeated with the steps
    /// evened again until no pair is left; heights only fall, so it ends.
    void cut_unresolvable() {
        std::unordered_set<std::uint64_t> wall_pieces;
        for (const Ring& ring : rings_) {
            const std::vector<VertIdx>& wall = ring.wall.vertices;
            for (std::size_t k = 0; k < wall.size(); ++k)
                wall_pieces.insert(edge_key(wall[k], wall[(k + 1) % wall.size()]));
        }
        std::vector<std::array<VertIdx, 2>> boundary;
        for (std::size_t p = 0; p < domain_.pieces.size() / 2; ++p) {
            const VertIdx a = domain_.pieces[2 * p], b = domain_.pieces[2 * p + 1];
            if (wall_pieces.count(edge_key(a, b)) == 0) boundary.push_back({a, b});
        }
        BucketGrid vertices(x0_, y0_, bucket_);
        for (VertIdx v = 0; v < base_; ++v) vertices.insert(v, point(v), point(v));
        for (std::uint32_t c = 0; c < point_stack_.size(); ++c) {
            const VertIdx v = base_ + c;
            if (point_stack_[c] != kNone) vertices.insert(v, point(v), point(v));
        }
        std::vector<std::uint8_t> cut_here(height_.size(), 0);
        for (;;) {
            std::vector<std::array<VertIdx, 2>> segments = boundary;
            for (const Ring& ring : rings_) {
                const std::vector<LinePoint> front = front_of(ring);
                for (std::size_t k = 0; k < front.size(); ++k) {
                    const LinePoint& p = front[k];
                    const LinePoint& q = front[(k + 1) % front.size()];
                    segments.push_back({point_id(p[0], p[1]), point_id(q[0], q[1])});
                }
            }
            std::vector<std::uint32_t> cut_at = height_;
            bool found = false;
            for (const auto& segment : segments) {
                // Named copies, not structured bindings: a lambda below uses them (clang 14
                // refuses to capture a binding).
                const VertIdx a = segment[0], b = segment[1];
                const double *pa = point(a), *pb = point(b);
                // A vertex within rounding of the segment lies within 2^-40 (1 + 2^-40) of the
                // ends' largest coordinate of its box: the box widened by 2^-38 of it (its
                // rounding included) holds it.
                const double largest = std::max(
                    {std::fabs(pa[0]), std::fabs(pa[1]), std::fabs(pb[0]), std::fabs(pb[1])});
                const double margin = std::max(std::ldexp(largest, -38), 0x1p-1060);
                const double lo[2] = {std::min(pa[0], pb[0]) - margin,
                                      std::min(pa[1], pb[1]) - margin};
                const double hi[2] = {std::max(pa[0], pb[0]) + margin,
                                      std::max(pa[1], pb[1]) + margin};
                vertices.query(lo, hi, [&](std::uint32_t w) {
                    if (w == a || w == b || !in_use(w)) return;
                    VertIdx highest = w;
                    for (const VertIdx end : {a, b})
                        if (layer_of(end) > layer_of(highest)) highest = end;
                    const std::uint32_t k = layer_of(highest);
                    if (k == 0 || !bends(w, a, b)) return;
                    const std::uint32_t s = point_stack_[highest - base_];
                    for (const std::uint32_t column : {previous_stack(s), s}) {
                        if (cut_at[column] >= k) {
                            cut_at[column] = k - 1;
                            found = true;
                        }
                    }
                });
            }
            if (!found) break;
            for (std::uint32_t j = 0; j < height_.size(); ++j) {
                if (cut_at[j] < height_[j]) {
                    cut(j, cut_at[j], counters_.omesh_removed_unresolvable);
                    if (!cut_here[j]) ++counters_.stopped_unresolvable;
                    cut_here[j] = 1;
                }
            }
            cut_steps();
        }
    }

    const tri::Cdt2Result& domain_;
    const LayerParameters2& parameters_;
    AdvancingLayersCounters2& counters_;
    const VertIdx base_;
    std::vector<Ring> rings_;
    std::vector<std::uint32_t> ring_of_;      ///< per stack (and column): its ring
    std::vector<double> candidates_;          ///< layer points, then guard points (ids from base_)
    std::vector<std::uint32_t> point_stack_;  ///< per candidate: its normal line (kNone: a guard)
    std::vector<std::uint32_t> point_layer_;  ///< per candidate: its layer
    std::vector<std::uint32_t> height_;       ///< per column: the layers kept
    double x0_ = 0, y0_ = 0, bucket_ = 1;     ///< the bucket grids' origin and bucket size
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
    if (counters.omesh_removed_unresolvable > 0) {
        result.mesh.warnings.push_back(
            "truncated O-mesh: " + std::to_string(counters.omesh_removed_unresolvable) +
            " cells of " + std::to_string(counters.stopped_unresolvable) +
            " columns removed where a layer point lay within rounding (2^-40 of its "
            "coordinates) of the front, beside which the fill would bend the front; first "
            "height " +
            format_number(options.layers.first_height) +
            " is about as thin as doubles resolve beside the wall");
    }
    return result;
}

}  // namespace exactmesh::generators
