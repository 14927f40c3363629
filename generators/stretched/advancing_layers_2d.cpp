// SPDX-License-Identifier: MIT
// Advancing layers (see advancing_layers_2d.hpp): the walls and their stacks (LayerBuilder::
// find_walls), the layers one after another with exact conflict resolution (advance,
// resolve_conflicts, commit), then the front, the fill and the merge (advancing_layers_2d).
#include "generators/stretched/advancing_layers_2d.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/stretched/layer_mesh_2d.hpp"
#include "generators/stretched/truncated_omesh_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;
using tri::kNone;
using tri::VertIdx;

void validate_layer_parameters(const LayerParameters2& layers) {
    if (!(layers.first_height > 0) || !std::isfinite(layers.first_height)) {
        throw InputError("--layers: the first height must be a finite number > 0 (got " +
                         format_number(layers.first_height) + ")");
    }
    if (!(layers.growth >= 1 && layers.growth <= 10)) {
        throw InputError("--layers: the growth ratio must be in [1, 10] (got " +
                         format_number(layers.growth) + ")");
    }
    if (layers.max_layers < 1 || layers.max_layers > kMaxLayers) {
        throw InputError("--layers: the number of layers must be in [1, " +
                         std::to_string(kMaxLayers) + "] (got " +
                         std::to_string(layers.max_layers) + ")");
    }
}

LayerParameters2 parse_layer_parameters(std::string_view text) {
    LayerParameters2 layers;
    std::vector<std::string_view> fields;
    for (std::size_t start = 0;;) {
        const std::size_t comma = text.find(',', start);
        fields.push_back(text.substr(start, comma - start));
        if (comma == std::string_view::npos) break;
        start = comma + 1;
    }
    const std::string quoted = "--layers '" + std::string(text) + "'";
    if (fields.size() < 2 || fields.size() > 3) {
        throw InputError(quoted + ": expected FIRST_HEIGHT,GROWTH[,MAX_LAYERS]");
    }
    const auto number = [&](std::string_view field, const char* what) {
        double value = 0;
        const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
        if (error != std::errc{} || end != field.data() + field.size() || field.empty())
            throw InputError(quoted + ": the " + what + " '" + std::string(field) +
                             "' is not a number");
        return value;
    };
    layers.first_height = number(fields[0], "first height");
    layers.growth = number(fields[1], "growth");
    if (fields.size() == 3) {
        const double count = number(fields[2], "number of layers");
        if (!(count >= 1 && count <= kMaxLayers) || count != std::floor(count)) {
            throw InputError(quoted + ": the number of layers must be a whole number in [1, " +
                             std::to_string(kMaxLayers) + "]");
        }
        layers.max_layers = static_cast<std::uint32_t>(count);
    }
    validate_layer_parameters(layers);
    return layers;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const AdvancingLayersCounters2& counters) {
    return counters_by_name(kAdvancingLayersCounterNames, counters);
}

namespace {

using layer_mesh::BucketGrid;
using layer_mesh::Cell;
using layer_mesh::distance;
using layer_mesh::kProbe;
using layer_mesh::Segment;
using layer_mesh::segments_conflict;
using layer_mesh::unit;
using layer_mesh::Vec;

/// A boundary loop of the domain with the domain on its left.
using Loop = std::vector<VertIdx>;

/// The boundary loops of the domain's triangulation (edges with no neighbour), each with the
/// domain on its left; loops through a vertex where the boundary pinches (two outgoing
/// boundary edges) are left out (they are not simple).
std::vector<Loop> boundary_loops(const tri::Triangulation2& mesh) {
    std::vector<VertIdx> next(mesh.vertex_count(), kNone);
    std::vector<std::uint8_t> pinched(mesh.vertex_count(), 0);
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
        for (std::uint32_t k = 0; k < 3; ++k) {
            if (mesh.neighbors[3 * t + k] != kNone) continue;
            const VertIdx a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
            if (next[a] != kNone) pinched[a] = 1;
            next[a] = b;
        }
    }
    std::vector<Loop> loops;
    std::vector<std::uint8_t> seen(next.size(), 0);
    for (VertIdx v = 0; v < next.size(); ++v) {
        if (next[v] == kNone || seen[v] || pinched[v]) continue;
        Loop loop;
        bool simple = true;
        for (VertIdx u = v; !seen[u]; u = next[u]) {
            seen[u] = 1;
            if (pinched[u]) simple = false;
            loop.push_back(u);
            if (pinched[u]) break;
        }
        if (simple) loops.push_back(std::move(loop));
    }
    return loops;
}

/// Whether a simple loop runs clockwise: the turn at its lowest-then-leftmost vertex (a convex
/// corner of its hull) decides it, exactly.
bool clockwise(const Loop& loop, const std::vector<double>& xy) {
    std::size_t lowest = 0;
    for (std::size_t k = 1; k < loop.size(); ++k) {
        const double* p = &xy[2 * loop[k]];
        const double* q = &xy[2 * loop[lowest]];
        if (p[1] < q[1] || (p[1] == q[1] && p[0] < q[0])) lowest = k;
    }
    const std::size_t n = loop.size();
    return pred::orient2d(&xy[2 * loop[(lowest + n - 1) % n]], &xy[2 * loop[lowest]],
                          &xy[2 * loop[(lowest + 1) % n]]) == pred::Sign::Negative;
}

enum class Stop : std::uint8_t {
    Active,
    AspectRatio,
    Size,
    Collision,
    Neighbour,
    MaxLayers,
    Unresolvable
};

/// No layer is built when the first is thinner than 2^-kUnresolvableExponent of the walls'
/// largest coordinate (the 3D generators spare tetrahedra below the same fraction).
constexpr int kUnresolvableExponent = 44;

struct Stack {
    VertIdx base = kNone;
    Vec direction;
    double wall_spacing = 0;
    std::uint32_t prev = 0, next = 0;  ///< neighbouring stacks on the same loop
    std::vector<VertIdx> points;       ///< points[k]: layer k (points[0] = base)
    Stop stop = Stop::Active;
    VertIdx top() const { return points.back(); }
    std::uint32_t layers() const { return static_cast<std::uint32_t>(points.size() - 1); }
};

class LayerBuilder {
  public:
    LayerBuilder(const tri::Cdt2Result& domain, const LayerParameters2& parameters,
                 const SizeFunction& size, AdvancingLayersCounters2& counters)
        : domain_(domain),
          parameters_(parameters),
          size_(size),
          counters_(counters),
          xy_(domain.mesh.xy) {}

    void build() {
        find_walls();
        if (stacks_.empty()) return;
        make_grids();
        advance();
    }

    std::vector<double>& xy() { return xy_; }
    const std::vector<Stack>& stacks() const { return stacks_; }
    const std::vector<Cell>& cells() const { return cells_; }
    const std::vector<Loop>& wall_loops() const { return walls_; }
    const std::vector<std::vector<std::uint32_t>>& loop_stacks() const { return loop_stacks_; }
    bool is_wall_piece(VertIdx a, VertIdx b) const {
        return wall_edges_.count(edge_key(a, b)) != 0;
    }

  private:
    static std::uint64_t edge_key(VertIdx a, VertIdx b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    }
    const double* point(VertIdx v) const {
        return v >= provisional_base_ ? &candidate_xy_[2 * (v - provisional_base_)]
                                      : &xy_[2 * static_cast<std::size_t>(v)];
    }

    void find_walls() {
        const tri::Triangulation2& mesh = domain_.mesh;
        for (Loop& loop : boundary_loops(mesh)) {
            if (loop.size() < 3 || !clockwise(loop, xy_)) continue;
            for (std::size_t k = 0; k < loop.size(); ++k)
                wall_edges_.insert({edge_key(loop[k], loop[(k + 1) % loop.size()]), 1});
            walls_.push_back(std::move(loop));
        }
        counters_.wall_loops = walls_.size();
        constexpr double kCornerAngle = std::numbers::pi / 4;  // beyond it: a fan or a merge
        constexpr double kFanStep = std::numbers::pi / 6;      // the angle between fan stacks
        for (const Loop& loop : walls_) {
            const std::size_t n = loop.size();
            counters_.wall_vertices += n;
            const auto first = static_cast<std::uint32_t>(stacks_.size());
            for (std::size_t k = 0; k < n; ++k) {
                const double* p = &xy_[2 * loop[(k + n - 1) % n]];
                const double* v = &xy_[2 * loop[k]];
                const double* q = &xy_[2 * loop[(k + 1) % n]];
                // The left normals of the two pieces (the domain is on the left).
                const Vec n1{-(v[1] - p[1]), v[0] - p[0]}, n2{-(q[1] - v[1]), q[0] - v[0]};
                const Vec u1 = unit(n1.x, n1.y), u2 = unit(n2.x, n2.y);
                const double turn =
                    std::atan2(u1.x * u2.y - u1.y * u2.x, u1.x * u2.x + u1.y * u2.y);
                const pred::Sign side = pred::orient2d(p, v, q);
                const double spacing = 0.5 * distance(p, v) + 0.5 * distance(v, q);
                std::vector<Vec> directions;
                if (side == pred::Sign::Negative && std::fabs(turn) > kCornerAngle) {
                    // A convex corner of the wall: the domain's angle exceeds 180 degrees; a
                    // fan of normals turning from the first piece's to the second's.
                    ++counters_.fan_corners;
                    const int pieces = static_cast<int>(std::ceil(std::fabs(turn) / kFanStep));
                    for (int j = 0; j <= pieces; ++j) {
                        const double angle = turn * j / pieces;
                        const double c = std::cos(angle), s = std::sin(angle);
                        directions.push_back(unit(c * u1.x - s * u1.y, s * u1.x + c * u1.y));
                    }
                } else if (side == pred::Sign::Positive && std::fabs(turn) > kCornerAngle) {
                    // A concave corner: one stack along the bisector of the unit normals.
                    ++counters_.merged_corners;
                    directions.push_back(unit(u1.x + u2.x, u1.y + u2.y));
                } else {
                    // The length (area) weighted mean of the two normals.
                    directions.push_back(unit(n1.x + n2.x, n1.y + n2.y));
                }
                for (const Vec& d : directions) {
                    Stack stack;
                    stack.base = loop[k];
                    stack.direction = d;
                    stack.wall_spacing = spacing;
                    stack.points.push_back(loop[k]);
                    stacks_.push_back(std::move(stack));
                }
            }
            const auto last = static_cast<std::uint32_t>(stacks_.size());
            std::vector<std::uint32_t> members;
            for (std::uint32_t s = first; s < last; ++s) {
                stacks_[s].next = s + 1 == last ? first : s + 1;
                stacks_[s].prev = s == first ? last - 1 : s - 1;
                members.push_back(s);
            }
            loop_stacks_.push_back(std::move(members));
        }
        counters_.stacks = stacks_.size();
        const double budget = static_cast<double>(stacks_.size()) * parameters_.max_layers;
        if (budget + static_cast<double>(xy_.size() / 2) > static_cast<double>(tri::kMaxPoints)) {
            throw InputError("advancing layers: " + std::to_string(stacks_.size()) +
                             " stacks of up to " + std::to_string(parameters_.max_layers) +
                             " layers exceed the vertex limit; give fewer layers");
        }
    }

    void make_grids() {
        // Cells about the median wall spacing: the layers near the wall fill a few of them.
        std::vector<double> spacings;
        for (const Stack& s : stacks_) spacings.push_back(s.wall_spacing);
        std::nth_element(spacings.begin(), spacings.begin() + spacings.size() / 2, spacings.end());
        double cell = spacings[spacings.size() / 2];
        double x0 = xy_[0], y0 = xy_[1], x1 = x0, y1 = y0;
        for (std::size_t v = 0; v < xy_.size() / 2; ++v) {
            x0 = std::min(x0, xy_[2 * v]);
            x1 = std::max(x1, xy_[2 * v]);
            y0 = std::min(y0, xy_[2 * v + 1]);
            y1 = std::max(y1, xy_[2 * v + 1]);
        }
        // At most about 2^22 cells over the domain's box.
        const double extent = std::max(x1 - x0, y1 - y0);
        if (!(cell > 0) || extent / cell > 2048) cell = extent / 2048;
        if (!(cell > 0)) cell = 1;
        segment_grid_ = std::make_unique<BucketGrid>(x0, y0, cell);
        point_grid_ = std::make_unique<BucketGrid>(x0, y0, cell);
        new_segment_grid_ = std::make_unique<BucketGrid>(x0, y0, cell);
        new_point_grid_ = std::make_unique<BucketGrid>(x0, y0, cell);
        cell_grid_ = std::make_unique<BucketGrid>(x0, y0, cell);
        // Obstacles: every constrained edge of the domain and every vertex in use.
        const tri::Triangulation2& mesh = domain_.mesh;
        for (std::size_t p = 0; p < domain_.pieces.size() / 2; ++p)
            add_segment({domain_.pieces[2 * p], domain_.pieces[2 * p + 1]});
        std::vector<std::uint8_t> used(mesh.vertex_count(), 0);
        for (const VertIdx v : mesh.triangles) used[v] = 1;
        for (VertIdx v = 0; v < used.size(); ++v) {
            if (used[v]) point_grid_->insert(v, point(v), point(v));
        }
    }

    void add_segment(Segment s) {
        segments_.push_back(s);
        segment_grid_->insert(static_cast<std::uint32_t>(segments_.size() - 1), point(s.a),
                              point(s.b));
    }

    /// One layer after another until every stack has stopped.
    void advance() {
        const double h = parameters_.first_height, g = parameters_.growth;
        double sum = 0, power = 1;  // 1 + g + ... + g^(k-1) and g^k
        std::vector<Vec> smoothed(stacks_.size());
        for (std::uint32_t k = 0;; ++k) {
            const double thickness = h * power;  // of layer k + 1, from layer k
            sum += power;
            power *= g;
            const double height = h * sum;
            // Directions: none smoothed for the first layer, then each averaged with its
            // neighbours' a little more at each layer (up to half and half).
            if (k > 0) {
                const double w = std::min(0.5, 0.05 * k);
                for (std::size_t s = 0; s < stacks_.size(); ++s) {
                    const Vec a = stacks_[stacks_[s].prev].direction,
                              b = stacks_[stacks_[s].next].direction, d = stacks_[s].direction;
                    smoothed[s] = unit((1 - w) * d.x + 0.5 * w * (a.x + b.x),
                                       (1 - w) * d.y + 0.5 * w * (a.y + b.y));
                }
                for (std::size_t s = 0; s < stacks_.size(); ++s) stacks_[s].direction = smoothed[s];
            }
            // The candidate points, each from its wall vertex, rounded once.
            provisional_base_ = static_cast<VertIdx>(xy_.size() / 2);
            candidate_xy_.assign(2 * stacks_.size(), 0);
            probe_xy_.assign(2 * stacks_.size(), 0);
            for (std::size_t s = 0; s < stacks_.size(); ++s) {
                const double* p = &xy_[2 * static_cast<std::size_t>(stacks_[s].base)];
                candidate_xy_[2 * s] = std::fma(height, stacks_[s].direction.x, p[0]);
                candidate_xy_[2 * s + 1] = std::fma(height, stacks_[s].direction.y, p[1]);
            }
            // The probe: the normal continued beyond the candidate by the larger of the new
            // thickness and half the tangential spacing, so that a stack stops short of an
            // opposing front or boundary ("near", not on it) and leaves the fill room for
            // triangles about as wide as the layer's cells.
            for (std::size_t s = 0; s < stacks_.size(); ++s) {
                const double* p = &xy_[2 * static_cast<std::size_t>(stacks_[s].base)];
                const double probe =
                    height +
                    std::max(thickness, 0.5 * tangential_spacing(static_cast<std::uint32_t>(s)));
                probe_xy_[2 * s] = std::fma(probe, stacks_[s].direction.x, p[0]);
                probe_xy_[2 * s + 1] = std::fma(probe, stacks_[s].direction.y, p[1]);
            }
            // A first layer thinner than 2^-44 of the walls' largest coordinate is a few ulps
            // thick somewhere: no stack is built (at 1e-14 to 1e-16 on the NACA 0012 the fill
            // then overlapped the thin cells and steps). All or none, so that no thin steps
            // are left. Scale-invariant: both sides scale.
            if (k == 0 && h < std::ldexp(largest_wall_coordinate(), -kUnresolvableExponent)) {
                for (std::uint32_t s = 0; s < stacks_.size(); ++s) stop(s, Stop::Unresolvable);
                break;
            }
            std::vector<std::uint8_t> candidate(stacks_.size(), 0);
            bool any = false;
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                Stack& stack = stacks_[s];
                if (stack.stop != Stop::Active) continue;
                if (k >= parameters_.max_layers) {
                    stop(s, Stop::MaxLayers);
                    continue;
                }
                // Tangential spacing: the larger of the wall's and the new layer's (the mean
                // distance to the neighbours' candidates); the cell's aspect ratio is that over
                // the new layer's thickness.
                const double* q = &candidate_xy_[2 * s];
                if (tangential_spacing(s) <= thickness) {
                    stop(s, Stop::AspectRatio);
                    continue;
                }
                // Where the stacks diverge (convex walls, fans) the width grows with the height
                // and the aspect ratio may never fall to 1: a given size ends them where the
                // new layer would be thicker than it (the fill's cells take over there).
                if (size_.bounded() && thickness >= size_(q[0], q[1])) {
                    stop(s, Stop::Size);
                    continue;
                }
                candidate[s] = 1;
                any = true;
            }
            if (!any) break;
            // A stack may not rise more than two layers above a stopped neighbour.
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                if (!candidate[s]) continue;
                for (const std::uint32_t j : {stacks_[s].prev, stacks_[s].next}) {
                    if (!candidate[j] && stacks_[j].layers() + 2 < k + 1) {
                        candidate[s] = 0;
                        stop(s, Stop::Neighbour);
                        break;
                    }
                }
            }
            resolve_conflicts(candidate, k == 0);
            commit(candidate);
        }
    }

    /// The largest coordinate magnitude of a stack's wall vertex.
    double largest_wall_coordinate() const {
        double largest = 0;
        for (const Stack& stack : stacks_) {
            const double* p = &xy_[2 * static_cast<std::size_t>(stack.base)];
            largest = std::max({largest, std::abs(p[0]), std::abs(p[1])});
        }
        return largest;
    }

    /// In a fan (stacks sharing a wall vertex, consecutive), the stacks that stay at the wall
    /// must be consecutive: a stack rising between two that stay would make the front pass
    /// twice through the wall vertex and cut the cells between off the layers' hole. Drops
    /// every candidate between the fan's first and last stack that stays.
    void drop_pinching_fan_stacks(const std::vector<std::uint8_t>& candidate,
                                  std::vector<std::uint8_t>& drop) const {
        for (std::uint32_t first = 0; first < stacks_.size();) {
            std::uint32_t end = first + 1;
            while (end < stacks_.size() && stacks_[end].base == stacks_[first].base) ++end;
            std::uint32_t low = kNone, high = kNone;
            for (std::uint32_t s = first; s < end; ++s) {
                if (candidate[s] && !drop[s]) continue;
                if (low == kNone) low = s;
                high = s;
            }
            if (low != kNone)
                for (std::uint32_t s = low + 1; s < high; ++s) drop[s] = 1;
            first = end;
        }
    }

    /// The tangential spacing at stack s's candidate: the larger of the wall's and the mean
    /// distance to its neighbours' candidates.
    double tangential_spacing(std::uint32_t s) const {
        const Stack& stack = stacks_[s];
        const double* q = &candidate_xy_[2 * s];
        const double width = 0.5 * distance(q, &candidate_xy_[2 * stack.prev]) +
                             0.5 * distance(q, &candidate_xy_[2 * stack.next]);
        return std::max(width, stack.wall_spacing);
    }

    void stop(std::uint32_t s, Stop why) {
        stacks_[s].stop = why;
        switch (why) {
            case Stop::AspectRatio:
                ++counters_.stopped_aspect_ratio;
                break;
            case Stop::Size:
                ++counters_.stopped_size;
                break;
            case Stop::Collision:
                ++counters_.stopped_collision;
                break;
            case Stop::Neighbour:
                ++counters_.stopped_neighbour;
                break;
            case Stop::MaxLayers:
                ++counters_.stopped_max_layers;
                break;
            case Stop::Unresolvable:
                ++counters_.stopped_unresolvable;
                break;
            case Stop::Active:
                break;
        }
    }

    VertIdx candidate_id(std::uint32_t s) const { return provisional_base_ + s; }

    /// The new segments and cells of the candidates, with their owners.
    struct Proposal {
        std::vector<Segment> segments;
        std::vector<std::array<std::uint32_t, 2>> segment_owners;
        std::vector<Cell> cells;
        std::vector<std::array<std::uint32_t, 2>> cell_owners;
        std::vector<std::uint32_t> blocked;  ///< candidates that cannot rise at all
    };

    Proposal propose(const std::vector<std::uint8_t>& candidate) const {
        Proposal p;
        for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
            const Stack& stack = stacks_[s];
            const std::uint32_t j = stack.next;
            if (candidate[s]) {
                p.segments.push_back({stack.top(), candidate_id(s)});
                p.segment_owners.push_back({s, kNone});
            }
            // The cell between s and its next stack j, and the outer edge over it.
            if (candidate[s] && candidate[j]) {
                p.segments.push_back({candidate_id(s), candidate_id(j)});
                p.segment_owners.push_back({s, j});
                Cell c;
                if (stack.top() == stacks_[j].top()) {  // the first layer of a fan
                    c.v = {stack.top(), candidate_id(j), candidate_id(s), kNone};
                } else {
                    c.v = {stack.top(), stacks_[j].top(), candidate_id(j), candidate_id(s)};
                }
                p.cells.push_back(c);
                p.cell_owners.push_back({s, j});
            } else if (candidate[s] || candidate[j]) {
                const std::uint32_t riser = candidate[s] ? s : j;
                const VertIdx low = stacks_[riser].top(), high = candidate_id(riser);
                const VertIdx other = stacks_[candidate[s] ? j : s].top();
                if (other == low) continue;  // a fan's wall vertex: nothing to close
                if (other == stacks_[riser].base) {
                    // A fan neighbour left at the shared wall vertex: the step triangle would
                    // have its three corners on the riser's own normal line.
                    p.blocked.push_back(riser);
                    continue;
                }
                if (candidate[s]) {
                    p.segments.push_back({high, other});
                    p.cells.push_back({{low, other, high, kNone}});
                } else {
                    p.segments.push_back({other, high});
                    p.cells.push_back({{other, low, high, kNone}});
                }
                p.segment_owners.push_back({riser, kNone});
                p.cell_owners.push_back({riser, kNone});
            }
        }
        return p;
    }

    /// Whether point v lies in the closed cell (and is none of its corners).
    bool cell_contains(const Cell& c, VertIdx v) {
        const int corners = c.is_quad() ? 4 : 3;
        for (int k = 0; k < corners; ++k)
            if (c.v[k] == v) return false;
        ++counters_.crossing_tests;
        for (int k = 0; k < corners; ++k) {
            if (pred::orient2d(point(c.v[k]), point(c.v[(k + 1) % corners]), point(v)) ==
                pred::Sign::Negative)
                return false;
        }
        return true;
    }

    bool cell_valid(const Cell& c) const {
        const int corners = c.is_quad() ? 4 : 3;
        for (int k = 0; k < corners; ++k) {
            if (pred::orient2d(point(c.v[k]), point(c.v[(k + 1) % corners]),
                               point(c.v[(k + 2) % corners])) != pred::Sign::Positive)
                return false;
        }
        return true;
    }

    /// Removes candidates until their segments and cells conflict with nothing: each round
    /// tests every proposal against what is there and against each other, and drops the
    /// owners of every failure at once (so the outcome does not depend on the order).
    void resolve_conflicts(std::vector<std::uint8_t>& candidate, bool first_layer) {
        for (;;) {
            const Proposal p = propose(candidate);
            std::vector<std::uint8_t> drop(stacks_.size(), 0);
            const auto drop_owners = [&](const std::array<std::uint32_t, 2>& owners) {
                for (const std::uint32_t s : owners)
                    if (s != kNone) drop[s] = 1;
            };
            new_segment_grid_->clear();
            new_point_grid_->clear();
            for (std::uint32_t i = 0; i < p.segments.size(); ++i)
                new_segment_grid_->insert(i, point(p.segments[i].a), point(p.segments[i].b));
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                if (candidate[s])
                    new_point_grid_->insert(candidate_id(s), point(candidate_id(s)),
                                            point(candidate_id(s)));
            }
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                if (!candidate[s]) continue;
                const VertIdx top = stacks_[s].top();
                const double *a = point(top), *b = &probe_xy_[2 * s];
                segment_grid_->query(a, b, [&](std::uint32_t other) {
                    if (drop[s]) return;
                    const Segment& o = segments_[other];
                    ++counters_.crossing_tests;
                    if (segments_conflict(top, kProbe, o.a, o.b, a, b, point(o.a), point(o.b)))
                        drop[s] = 1;
                });
            }
            for (std::uint32_t i = 0; i < p.segments.size(); ++i) {
                const Segment& s = p.segments[i];
                const double *a = point(s.a), *b = point(s.b);
                bool conflict = false;
                segment_grid_->query(a, b, [&](std::uint32_t other) {
                    if (conflict) return;
                    const Segment& o = segments_[other];
                    ++counters_.crossing_tests;
                    conflict = segments_conflict(s.a, s.b, o.a, o.b, a, b, point(o.a), point(o.b));
                });
                new_segment_grid_->query(a, b, [&](std::uint32_t other) {
                    if (other == i) return;
                    const Segment& o = p.segments[other];
                    ++counters_.crossing_tests;
                    if (segments_conflict(s.a, s.b, o.a, o.b, a, b, point(o.a), point(o.b))) {
                        conflict = true;
                        drop_owners(p.segment_owners[other]);
                    }
                });
                if (conflict) drop_owners(p.segment_owners[i]);
            }
            // A candidate with no cell on either side (its neighbours both stopped at its own
            // wall vertex: inside a fan) would leave a bare spike in the front.
            std::vector<std::uint8_t> has_cell(stacks_.size(), 0);
            for (const auto& owners : p.cell_owners)
                for (const std::uint32_t s : owners)
                    if (s != kNone) has_cell[s] = 1;
            for (std::uint32_t s = 0; s < stacks_.size(); ++s)
                if (candidate[s] && !has_cell[s]) drop[s] = 1;
            for (const std::uint32_t s : p.blocked) drop[s] = 1;
            if (first_layer) drop_pinching_fan_stacks(candidate, drop);
            for (std::size_t i = 0; i < p.cells.size(); ++i) {
                const Cell& c = p.cells[i];
                bool conflict = !cell_valid(c);
                const int corners = c.is_quad() ? 4 : 3;
                double lo[2] = {point(c.v[0])[0], point(c.v[0])[1]}, hi[2] = {lo[0], lo[1]};
                for (int q = 1; q < corners; ++q) {
                    for (int axis = 0; axis < 2; ++axis) {
                        lo[axis] = std::min(lo[axis], point(c.v[q])[axis]);
                        hi[axis] = std::max(hi[axis], point(c.v[q])[axis]);
                    }
                }
                const auto test = [&](std::uint32_t v) {
                    if (!conflict && cell_contains(c, v)) conflict = true;
                };
                if (!conflict) point_grid_->query(lo, hi, test);
                if (!conflict) new_point_grid_->query(lo, hi, test);
                if (conflict) drop_owners(p.cell_owners[i]);
            }
            // A candidate inside a committed cell (its new edges could start at a corner of
            // that cell and stay inside it, crossing nothing).
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                if (!candidate[s] || drop[s]) continue;
                const double* q = point(candidate_id(s));
                cell_grid_->query(q, q, [&](std::uint32_t c) {
                    if (!drop[s] && cell_contains(cells_[c], candidate_id(s))) drop[s] = 1;
                });
            }
            bool dropped = false;
            for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
                if (drop[s] && candidate[s]) {
                    candidate[s] = 0;
                    stop(s, Stop::Collision);
                    dropped = true;
                }
            }
            if (!dropped) return;
        }
    }

    void commit(const std::vector<std::uint8_t>& candidate) {
        const Proposal p = propose(candidate);
        // Real ids for the candidates, in stack order.
        std::vector<VertIdx> id(stacks_.size(), kNone);
        for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
            if (!candidate[s]) continue;
            id[s] = static_cast<VertIdx>(xy_.size() / 2);
            xy_.push_back(candidate_xy_[2 * s]);
            xy_.push_back(candidate_xy_[2 * s + 1]);
            ++counters_.layer_points;
        }
        const VertIdx provisional = provisional_base_;
        const auto real = [&](VertIdx v) { return v >= provisional ? id[v - provisional] : v; };
        provisional_base_ = kNone;
        for (const Segment& s : p.segments) add_segment({real(s.a), real(s.b)});
        for (Cell c : p.cells) {
            for (VertIdx& v : c.v)
                if (v != kNone) v = real(v);
            cells_.push_back(c);
            double lo[2] = {point(c.v[0])[0], point(c.v[0])[1]}, hi[2] = {lo[0], lo[1]};
            for (const VertIdx v : c.v) {
                if (v == kNone) continue;
                for (int axis = 0; axis < 2; ++axis) {
                    lo[axis] = std::min(lo[axis], point(v)[axis]);
                    hi[axis] = std::max(hi[axis], point(v)[axis]);
                }
            }
            cell_grid_->insert(static_cast<std::uint32_t>(cells_.size() - 1), lo, hi);
        }
        for (std::uint32_t s = 0; s < stacks_.size(); ++s) {
            if (!candidate[s]) continue;
            stacks_[s].points.push_back(id[s]);
            point_grid_->insert(id[s], point(id[s]), point(id[s]));
            counters_.layers = std::max<std::uint64_t>(counters_.layers, stacks_[s].layers());
        }
    }

    const tri::Cdt2Result& domain_;
    const LayerParameters2& parameters_;
    const SizeFunction& size_;
    AdvancingLayersCounters2& counters_;
    std::vector<double> xy_;
    std::vector<Loop> walls_;
    std::unordered_map<std::uint64_t, std::uint8_t> wall_edges_;
    std::vector<Stack> stacks_;
    std::vector<std::vector<std::uint32_t>> loop_stacks_;
    std::vector<Segment> segments_;
    std::vector<Cell> cells_;
    std::unique_ptr<BucketGrid> segment_grid_, point_grid_, new_segment_grid_, new_point_grid_,
        cell_grid_;
    std::vector<double> candidate_xy_, probe_xy_;
    VertIdx provisional_base_ = kNone;
};

}  // namespace

QuadQuality2 quad_quality_2d(std::span<const double> xy, std::span<const VertIdx> quads) {
    QuadQuality2 q;
    q.quads = quads.size() / 4;
    if (q.quads == 0) return q;
    q.min_angle = 180;
    double sum = 0;
    for (std::size_t c = 0; c < q.quads; ++c) {
        double shortest = std::numeric_limits<double>::infinity(), longest = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            const double* o = &xy[2 * static_cast<std::size_t>(quads[4 * c + k])];
            const double* p = &xy[2 * static_cast<std::size_t>(quads[4 * c + (k + 1) % 4])];
            const double* r = &xy[2 * static_cast<std::size_t>(quads[4 * c + (k + 3) % 4])];
            const Vec u = unit(p[0] - o[0], p[1] - o[1]), v = unit(r[0] - o[0], r[1] - o[1]);
            const double angle =
                std::atan2(std::fabs(u.x * v.y - u.y * v.x), u.x * v.x + u.y * v.y) * 180 /
                std::numbers::pi;
            q.min_angle = std::min(q.min_angle, angle);
            q.max_angle = std::max(q.max_angle, angle);
            const double side = distance(o, p);
            shortest = std::min(shortest, side);
            longest = std::max(longest, side);
        }
        const double ratio = longest / shortest;
        q.max_aspect_ratio = std::max(q.max_aspect_ratio, ratio);
        sum += ratio;
    }
    q.mean_aspect_ratio = sum / static_cast<double>(q.quads);
    return q;
}

std::string MixedMeshCheck2::summary() const {
    if (ok()) return "ok";
    return std::to_string(inverted_triangles.size()) + " inverted triangles, " +
           std::to_string(nonconvex_quads.size()) + " non-convex quadrilaterals, " +
           std::to_string(overused_edges.size() / 2) + " edges in more than two cells, " +
           std::to_string(open_edges.size() / 2) + " open edges off the boundary, " +
           std::to_string(missing_pieces.size() / 2) + " missing boundary pieces";
}

void exempt_pieces_in_holes_2d(MixedMeshCheck2& check, const tri::Cdt2Result& domain,
                               std::span<const double> xy, std::span<const VertIdx> pieces,
                               std::span<const std::uint32_t> piece_segment) {
    if (check.missing_pieces.empty()) return;
    const auto key = [](VertIdx a, VertIdx b) {
        return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
    };
    std::unordered_set<std::uint64_t> domain_edges;
    const std::vector<VertIdx>& triangles = domain.mesh.triangles;
    for (std::size_t e = 0; e < triangles.size(); ++e)
        domain_edges.insert(key(triangles[e], triangles[e - e % 3 + (e % 3 + 1) % 3]));
    std::unordered_map<std::uint64_t, std::uint32_t> segment_of;
    for (std::size_t p = 0; p < pieces.size() / 2 && p < piece_segment.size(); ++p)
        segment_of.emplace(key(pieces[2 * p], pieces[2 * p + 1]), piece_segment[p]);
    const auto in_box = [&](VertIdx v, VertIdx c, VertIdx d) {
        const double *q = &xy[2 * std::size_t{v}], *a = &xy[2 * std::size_t{c}],
                     *b = &xy[2 * std::size_t{d}];
        return std::min(a[0], b[0]) <= q[0] && q[0] <= std::max(a[0], b[0]) &&
               std::min(a[1], b[1]) <= q[1] && q[1] <= std::max(a[1], b[1]);
    };
    std::vector<VertIdx> missing;
    for (std::size_t i = 0; i + 1 < check.missing_pieces.size(); i += 2) {
        const VertIdx a = check.missing_pieces[i], b = check.missing_pieces[i + 1];
        const auto origin = segment_of.find(key(a, b));
        bool in_hole = false;
        for (std::size_t p = 0; p < domain.pieces.size() / 2 && !in_hole; ++p) {
            const VertIdx c = domain.pieces[2 * p], d = domain.pieces[2 * p + 1];
            in_hole = origin != segment_of.end() && domain.piece_segment[p] == origin->second &&
                      domain_edges.count(key(c, d)) == 0 && in_box(a, c, d) && in_box(b, c, d);
        }
        if (!in_hole) missing.insert(missing.end(), {a, b});
    }
    check.missing_pieces = std::move(missing);
}

MixedMeshCheck2 check_mixed_mesh_2d(std::span<const double> xy, std::span<const VertIdx> triangles,
                                    std::span<const VertIdx> quads,
                                    std::span<const VertIdx> pieces) {
    MixedMeshCheck2 check;
    const auto at = [&](VertIdx v) { return &xy[2 * static_cast<std::size_t>(v)]; };
    // Directed edges: each may appear once; an undirected edge once each way at most.
    std::unordered_map<std::uint64_t, std::uint32_t> directed;
    const auto add_cell = [&](std::span<const VertIdx> c) {
        for (std::size_t k = 0; k < c.size(); ++k) {
            const VertIdx a = c[k], b = c[(k + 1) % c.size()];
            if (++directed[(static_cast<std::uint64_t>(a) << 32) | b] == 2)
                check.overused_edges.insert(check.overused_edges.end(), {a, b});
        }
    };
    for (std::uint32_t t = 0; t < triangles.size() / 3; ++t) {
        const std::span<const VertIdx> c = triangles.subspan(3 * t, 3);
        if (pred::orient2d(at(c[0]), at(c[1]), at(c[2])) != pred::Sign::Positive)
            check.inverted_triangles.push_back(t);
        add_cell(c);
    }
    for (std::uint32_t q = 0; q < quads.size() / 4; ++q) {
        const std::span<const VertIdx> c = quads.subspan(4 * q, 4);
        for (int k = 0; k < 4; ++k) {
            if (pred::orient2d(at(c[k]), at(c[(k + 1) % 4]), at(c[(k + 2) % 4])) !=
                pred::Sign::Positive) {
                check.nonconvex_quads.push_back(q);
                break;
            }
        }
        add_cell(c);
    }
    std::unordered_map<std::uint64_t, std::uint8_t> piece_set;
    for (std::size_t p = 0; p < pieces.size() / 2; ++p) {
        const VertIdx a = pieces[2 * p], b = pieces[2 * p + 1];
        piece_set[(static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)] = 1;
        if (!directed.count((static_cast<std::uint64_t>(a) << 32) | b) &&
            !directed.count((static_cast<std::uint64_t>(b) << 32) | a))
            check.missing_pieces.insert(check.missing_pieces.end(), {a, b});
    }
    for (const auto& [key, count] : directed) {
        (void)count;
        const auto a = static_cast<VertIdx>(key >> 32), b = static_cast<VertIdx>(key);
        if (directed.count((static_cast<std::uint64_t>(b) << 32) | a)) continue;
        if (!piece_set.count((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)))
            check.open_edges.insert(check.open_edges.end(), {a, b});
    }
    return check;
}

AdvancingLayersResult2 advancing_layers_2d(const MeshDomain2& domain,
                                           const AdvancingLayersOptions2& options) {
    EM_ASSERT(options.fill != nullptr);
    AdvancingLayersResult2 result;
    const tri::Cdt2Result& cdt = domain.triangulation();
    const bool layered = options.layers.first_height != 0;
    if (layered) validate_layer_parameters(options.layers);
    if (layered && options.layers.method == LayerMethod2::TruncatedOMesh)
        return truncated_omesh_2d(domain, options);
    LayerBuilder builder(cdt, options.layers, options.size, result.counters);
    if (layered) builder.build();
    layer_mesh::LayeredRegion2 region;
    region.xy = std::move(builder.xy());
    for (const Loop& loop : builder.wall_loops()) region.add_wall_loop(loop);
    // The front: per wall loop, the top of every stack in order (repeats removed).
    for (const std::vector<std::uint32_t>& members : builder.loop_stacks()) {
        std::vector<VertIdx> tops;
        for (const std::uint32_t s : members) {
            const VertIdx v = builder.stacks()[s].top();
            if (tops.empty() || tops.back() != v) tops.push_back(v);
        }
        while (tops.size() > 1 && tops.back() == tops.front()) tops.pop_back();
        region.fronts.push_back(std::move(tops));
    }
    region.cells = builder.cells();
    for (const Stack& s : builder.stacks()) region.stack_layers.emplace_back(s.base, s.layers());
    layer_mesh::finish_layered_mesh_2d(domain, options, region, result);
    return result;
}

}  // namespace exactmesh::generators
