// SPDX-License-Identifier: MIT
// Stretched Delaunay point insertion (see stretched_delaunay_2d.hpp for the steps and
// references).
#include "generators/stretched/stretched_delaunay_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/stretched/layer_mesh_2d.hpp"
#include "generators/stretched/metric_mesh_edits_2d.hpp"
#include "generators/stretched/metric_smoothing_2d.hpp"
#include "generators/stretched/wall_loops_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;
using predicates::scale_free_norm;
using predicates::Sign;

namespace {

using layer_mesh::unit_vector;

/// The point budget of the O-meshes and of the far field, each.
std::uint64_t point_budget(const StretchedDelaunayOptions2& o) {
    return o.max_points != 0 ? o.max_points : kStretchedPointBudget;
}

constexpr std::uint32_t kNoComponent = 0xFFFFFFFFu;

/// The size across of a staggered layer's metric over the spacing between layers: 2 / sqrt 3
/// (the height of an equilateral triangle is sqrt 3 / 2 of its side).
constexpr double kStaggeredAcross = 1.1547005383792515;

/// A far-field point's metric size over its quadtree leaf's side: (1 + sqrt 2) / 2.
constexpr double kFarFieldSizePerSide = 1.2071067811865475;

/// The length of wall side i (from vertex i to the next), scale-free.
double side_length(const tri::Triangulation2& mesh, const WallLoop2& wall, std::size_t i) {
    const double* p = mesh.point(wall.vertices[i]);
    const double* q = mesh.point(wall.vertices[(i + 1) % wall.vertices.size()]);
    return scale_free_norm(q[0] - p[0], q[1] - p[1]);
}

/// A point the mesher adds, and what step 3 needs of it.
struct AddedPoint {
    double x = 0, y = 0;
    std::uint32_t component = kNoComponent;  ///< its O-mesh, or kNoComponent (far field)
    int layer = 0;                           ///< O-mesh layer k >= 1
    double thickness = 0;                    ///< its layer's thickness (O-mesh)
    double across = 0;                       ///< its metric's size across the wall (O-mesh)
    double spacing = 0;                      ///< the wall's tangential spacing at its normal
    double tx = 1, ty = 0;                   ///< the wall's direction at its normal
    bool wake = false;                       ///< a wake point (of its component's wake)
};

/// True when (x, y) lies strictly inside the domain: in a triangle of its CDT (exact orient2d
/// through the locator), not on a boundary side or a segment, not at a vertex.
bool strictly_inside(const tri::Triangulation2& mesh, const DomainLocator2& locator, double x,
                     double y) {
    const tri::TriIdx t = locator.locate(mesh, x, y);
    if (t == tri::kNone) return false;
    const double p[2] = {x, y};
    for (unsigned k = 0; k < 3; ++k) {
        const double* a = mesh.point(mesh.triangles[3 * t + k]);
        if (a[0] == x && a[1] == y) return false;
        const double* b = mesh.point(mesh.triangles[3 * t + (k + 1) % 3]);
        if (predicates::orient2d(a, b, p) == Sign::Zero &&
            (mesh.neighbors[3 * t + k] == tri::kNone ||
             mesh.is_constrained(t, static_cast<int>(k))))
            return false;
    }
    return true;
}

/// Points sorted by x, for the neighbourhood scans of the filters (a window of x, then y).
class SortedPoints {
  public:
    void add(double x, double y, std::uint32_t tag) { items_.push_back({x, y, tag}); }
    void sort() {
        std::sort(items_.begin(), items_.end(), [](const Item& a, const Item& b) {
            return a.x < b.x || (a.x == b.x && (a.y < b.y || (a.y == b.y && a.tag < b.tag)));
        });
    }
    /// Calls f(x, y, tag) for the points with |x - px| < r and |y - py| < r until f returns
    /// true; returns whether it did.
    template <class F>
    bool any_near(double px, double py, double r, F&& f) const {
        auto it = std::lower_bound(items_.begin(), items_.end(), px - r,
                                   [](const Item& a, double x) { return a.x <= x; });
        for (; it != items_.end() && it->x < px + r; ++it) {
            if (std::fabs(it->y - py) < r && f(it->x, it->y, it->tag)) return true;
        }
        return false;
    }

  private:
    struct Item {
        double x, y;
        std::uint32_t tag;
    };
    std::vector<Item> items_;
};

void check_options(const StretchedDelaunayOptions2& o) {
    const auto fail = [](const std::string& what, double value) {
        throw InputError("stretched Delaunay: " + what + " " + format_number(value) +
                         " is out of range");
    };
    if (!(o.first_height > 0) || !std::isfinite(o.first_height))
        fail("first height", o.first_height);
    if (!(o.growth >= 1) || !std::isfinite(o.growth)) fail("growth", o.growth);
    if (o.max_layers < 0 || o.max_layers > 10000) fail("max layers", o.max_layers);
    if (o.normal_smoothing_passes < 0) fail("normal smoothing passes", o.normal_smoothing_passes);
    if (o.metric_smoothing_passes < 0) fail("metric smoothing passes", o.metric_smoothing_passes);
    if (o.point_smoothing_passes < 0) fail("point smoothing passes", o.point_smoothing_passes);
    if (!(o.point_move_limit >= 0 && o.point_move_limit <= 1))
        fail("point move limit", o.point_move_limit);
    if (!(o.far_field_spacing > 0 && o.far_field_spacing <= 1))
        fail("far-field spacing", o.far_field_spacing);
    if (!(o.wake_length >= 0) || !std::isfinite(o.wake_length)) fail("wake length", o.wake_length);
}

/// Step 1 and the first filter: every wall's O-mesh points strictly inside the domain.
std::vector<AddedPoint> omesh_points(const tri::Triangulation2& domain_mesh,
                                     const DomainLocator2& locator,
                                     std::span<const WallLoop2> walls,
                                     const StretchedDelaunayOptions2& o,
                                     StretchedDelaunayCounters2& counters) {
    // Scale-free factors: height_k = first_height * sum_{j<k} growth^j, thickness_k =
    // first_height * growth^(k-1); a first_height scaled by 2^k scales both exactly.
    std::vector<double> height_factor(static_cast<std::size_t>(o.max_layers) + 1, 0);
    std::vector<double> thickness_factor(height_factor.size(), 0);
    double power = 1;
    for (std::size_t k = 1; k < height_factor.size(); ++k) {
        thickness_factor[k] = power;
        height_factor[k] = height_factor[k - 1] + power;
        power *= o.growth;
    }
    // The budget before any work: the layers each normal would get (an upper bound: the
    // staggered layers stop sooner, at sqrt(3)/2 of the larger of the two spacings).
    std::uint64_t count = 0;
    for (const WallLoop2& wall : walls) {
        for (std::size_t i = 0; i < wall.vertices.size(); ++i) {
            const double spacing =
                o.staggered_layers ? std::max(wall.spacing[i], side_length(domain_mesh, wall, i))
                                   : wall.spacing[i];
            for (std::size_t k = 1; k < height_factor.size(); ++k) {
                if (!(o.first_height * thickness_factor[k] < spacing)) break;
                ++count;
            }
        }
    }
    if (count > point_budget(o)) {
        throw InputError("stretched Delaunay: the layers (first height " +
                         format_number(o.first_height) + ", growth " + format_number(o.growth) +
                         ") ask for " + std::to_string(count) + " points, more than " +
                         std::to_string(point_budget(o)));
    }
    std::vector<AddedPoint> points;
    points.reserve(count);
    // A layer point's neighbours on its normal lie t_k below and growth t_k above it: the
    // metric's size across is their geometric mean, so both edges measure about 1 (1 / sqrt g
    // and sqrt g; with t_k itself the upper one measured g, and the cells' diagonals sqrt(1 +
    // g^2), beyond sqrt 2: 70% of the edges were unit, 76% then on the NACA 0012). Staggered,
    // the layers' points are half a spacing apart along the wall from those of the layers
    // below and above, and the size across is 2 / sqrt 3 of that mean: a cell's two slanted
    // sides then measure sqrt(1/4 + 3/4) = 1, like its side along the layer, so the triangles
    // are equilateral in the point's metric (the unstaggered cells' diagonals measured sqrt 2
    // at best, sqrt(1 + g) with the geometric mean: 79% unit edges).
    const double across_factor =
        std::sqrt(o.growth) * (o.staggered_layers ? kStaggeredAcross : 1.0);
    // A layer is isotropic when its thickness reaches the spacing (unstaggered: square cells)
    // or sqrt 3 / 2 of it (staggered: equilateral triangles): the layers end there.
    const double stop_factor = o.staggered_layers ? 1 / kStaggeredAcross : 1.0;
    constexpr std::size_t kNoPoint = ~std::size_t{0};
    for (std::uint32_t c = 0; c < walls.size(); ++c) {
        const WallLoop2& wall = walls[c];
        // column[i][k - 1]: the point of normal i in layer k (the columns end where a normal
        // stopped).
        std::vector<std::vector<std::size_t>> column(wall.vertices.size());
        const std::size_t nw = wall.vertices.size();
        for (std::size_t i = 0; i < nw; ++i) {
            // The foot and direction of slot i's even layers (the wall vertex and its normal)
            // and, staggered, of its odd ones (the midpoint of the side to the next vertex and
            // the mean of the two normals; halving and adding are exact under power-of-two
            // scaling, so the point is still built scale-exactly).
            const double* p = domain_mesh.point(wall.vertices[i]);
            const double* q = domain_mesh.point(wall.vertices[(i + 1) % nw]);
            const std::array<double, 2> mid_foot = {0.5 * p[0] + 0.5 * q[0],
                                                    0.5 * p[1] + 0.5 * q[1]};
            const std::array<double, 2> mid_normal =
                unit_vector(wall.normals[i][0] + wall.normals[(i + 1) % nw][0],
                            wall.normals[i][1] + wall.normals[(i + 1) % nw][1]);
            const double mid_spacing = side_length(domain_mesh, wall, i);
            for (std::size_t k = 1; k < height_factor.size(); ++k) {
                const bool shifted = o.staggered_layers && k % 2 == 1;
                if (shifted && mid_normal[0] == 0 && mid_normal[1] == 0) break;  // a cusp
                const double* foot = shifted ? mid_foot.data() : p;
                const std::array<double, 2>& n = shifted ? mid_normal : wall.normals[i];
                const double spacing = shifted ? mid_spacing : wall.spacing[i];
                const double thickness = o.first_height * thickness_factor[k];
                // Aspect ratio about 1 reached: the layers end here.
                if (!(thickness < stop_factor * spacing)) break;
                const double height = o.first_height * height_factor[k];
                AddedPoint a;
                a.x = std::fma(height, n[0], foot[0]);
                a.y = std::fma(height, n[1], foot[1]);
                ++counters.omesh_points;
                if (!strictly_inside(domain_mesh, locator, a.x, a.y)) {
                    ++counters.outside_domain;
                    break;
                }
                a.component = c;
                a.layer = static_cast<int>(k);
                a.thickness = thickness;
                a.across = thickness * across_factor;
                a.spacing = spacing;
                a.tx = -n[1];
                a.ty = n[0];
                column[i].push_back(points.size());
                points.push_back(a);
            }
        }
        // The spacing along the wall of each point's own structured cell: the mean distance to
        // the points of the same layer on the neighbouring normals (wider than at the wall
        // about a convex nose, narrower in a concave part), the wall's where neither exists.
        for (std::size_t i = 0; i < nw; ++i) {
            for (std::size_t k = 0; k < column[i].size(); ++k) {
                AddedPoint& a = points[column[i][k]];
                double sum = 0;
                int found = 0;
                for (const std::size_t j : {(i + nw - 1) % nw, (i + 1) % nw}) {
                    const std::size_t q = k < column[j].size() ? column[j][k] : kNoPoint;
                    if (q == kNoPoint) continue;
                    sum += scale_free_norm(points[q].x - a.x, points[q].y - a.y);
                    ++found;
                }
                if (found > 0 && sum / found > a.across) a.spacing = sum / found;
            }
        }
    }
    return points;
}

/// The stretching of an O-mesh point: its wall's spacing along the wall, its layer's thickness
/// across.
Metric2 omesh_metric(const AddedPoint& p) {
    return metric_from_stretching(p.tx, p.ty, p.spacing, p.spacing / p.across);
}

/// The stretching of wall vertex i: the wall's spacing along it, the first height across (times
/// 2 / sqrt 3 when the layers are staggered: the first layer's cells equilateral).
Metric2 wall_metric(const WallLoop2& wall, std::size_t i, const StretchedDelaunayOptions2& o) {
    const std::array<double, 2>& n = wall.normals[i];
    const double across = o.first_height * (o.staggered_layers ? kStaggeredAcross : 1.0);
    const double aspect = wall.spacing[i] / across;
    return aspect > 1 ? metric_from_stretching(-n[1], n[0], wall.spacing[i], aspect)
                      : isotropic(wall.spacing[i]);
}

/// The second filter: an O-mesh point goes when a strictly finer point of another component's
/// O-mesh (its wall vertices the finest; finer: a thinner layer, then a lower component) lies
/// inside the unit ellipse of either point's stretching (closer than the local spacing in that
/// direction: along the wall, the spacing; across it, the thickness). The decision reads only
/// the unfiltered set, so it does not depend on the order.
std::vector<AddedPoint> drop_overlaps(const tri::Triangulation2& domain_mesh,
                                      std::span<const WallLoop2> walls,
                                      std::vector<AddedPoint> points,
                                      const StretchedDelaunayOptions2& o,
                                      StretchedDelaunayCounters2& counters) {
    if (walls.size() < 2) return points;
    // Tags: i < points.size() an O-mesh point, else a wall vertex.
    SortedPoints sorted;
    std::vector<Metric2> metric_of;
    std::vector<double> thickness_of;
    std::vector<std::uint32_t> component_of;
    double largest = 0;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        sorted.add(points[i].x, points[i].y, i);
        metric_of.push_back(omesh_metric(points[i]));
        thickness_of.push_back(points[i].thickness);
        component_of.push_back(points[i].component);
        largest = std::max(largest, points[i].spacing);
    }
    for (std::uint32_t c = 0; c < walls.size(); ++c) {
        for (std::size_t i = 0; i < walls[c].vertices.size(); ++i) {
            const double* p = domain_mesh.point(walls[c].vertices[i]);
            sorted.add(p[0], p[1], static_cast<std::uint32_t>(metric_of.size()));
            metric_of.push_back(wall_metric(walls[c], i, o));
            thickness_of.push_back(0);
            component_of.push_back(c);
            largest = std::max(largest, walls[c].spacing[i]);
        }
    }
    sorted.sort();
    std::vector<AddedPoint> kept;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const AddedPoint& p = points[i];
        const bool near_finer =
            sorted.any_near(p.x, p.y, largest, [&](double x, double y, std::uint32_t q) {
                const std::uint32_t component = component_of[q];
                if (component == p.component) return false;
                const bool finer = thickness_of[q] < p.thickness ||
                                   (thickness_of[q] == p.thickness && component < p.component);
                if (!finer) return false;
                const double dx = x - p.x, dy = y - p.y;
                return metric_length(metric_of[i], dx, dy) < 1 ||
                       metric_length(metric_of[q], dx, dy) < 1;
            });
        if (near_finer) {
            ++counters.overlap_dropped;
        } else {
            kept.push_back(p);
        }
    }
    return kept;
}

/// A wall's trailing edge: its rearmost vertex (largest x, then smallest y; the flow is taken
/// along +x, as in the built-in airfoil domains) when the wall turns there by a sharp convex
/// corner of the solid (exact orient2d: convex; exact compare_angles: the solid's angle below
/// 90 degrees), with the corner's outward bisector and the component's chord (the largest
/// distance from it to a vertex of the wall, scale-free).
struct TrailingEdge {
    std::size_t vertex = 0;  ///< index in the wall loop
    std::array<double, 2> direction{};
    double chord = 0;
};

std::optional<TrailingEdge> trailing_edge(const tri::Triangulation2& mesh, const WallLoop2& wall) {
    const std::size_t n = wall.vertices.size();
    if (n < 3) return std::nullopt;
    std::size_t rear = 0;
    for (std::size_t i = 1; i < n; ++i) {
        const double* p = mesh.point(wall.vertices[i]);
        const double* r = mesh.point(wall.vertices[rear]);
        if (p[0] > r[0] || (p[0] == r[0] && p[1] < r[1])) rear = i;
    }
    const double* a = mesh.point(wall.vertices[(rear + n - 1) % n]);
    const double* v = mesh.point(wall.vertices[rear]);
    const double* b = mesh.point(wall.vertices[(rear + 1) % n]);
    // The wall runs with the domain on its left, so a convex corner of the solid turns right.
    if (predicates::orient2d(a, v, b) != Sign::Negative) return std::nullopt;
    static constexpr double kOrigin[2] = {0, 0}, kRight[2] = {1, 0}, kUp[2] = {0, 1};
    const predicates::Corner right_angle{kOrigin, kRight, kUp};
    if (predicates::compare_angles(predicates::Corner{v, a, b}, right_angle) != Sign::Negative)
        return std::nullopt;
    const std::array<double, 2> to_a = unit_vector(a[0] - v[0], a[1] - v[1]);
    const std::array<double, 2> to_b = unit_vector(b[0] - v[0], b[1] - v[1]);
    const std::array<double, 2> direction = unit_vector(-(to_a[0] + to_b[0]), -(to_a[1] + to_b[1]));
    if (direction[0] == 0 && direction[1] == 0) return std::nullopt;
    TrailingEdge edge{rear, direction, 0};
    for (const tri::VertIdx w : wall.vertices) {
        const double* p = mesh.point(w);
        edge.chord = std::max(edge.chord, scale_free_norm(p[0] - v[0], p[1] - v[1]));
    }
    return edge;
}

/// The wake behind each wall's trailing edge [Mavriplis90 §3: a wake region of stretched
/// points behind each trailing edge]: stations along the corner's bisector from the trailing
/// edge, the first one wall spacing away, each `growth` times farther apart than the last (at
/// most the far-field size there), each with a centre point and staggered layers on both sides
/// like an O-mesh's (the odd layers half a station ahead), its first height growing by
/// growth^2 per station from first_height: the stretching along the wake decreases by a factor
/// growth per station, and the wake ends where it turns isotropic, after wake_length chords, or
/// where its centre leaves the domain. Points not strictly inside the domain go, as do points
/// with another component's O-mesh point, a wall vertex or a boundary point inside either one's
/// unit ellipse (the other components' O-meshes and the boundary win) and points with a finer point
/// of another wake inside either one's ellipse; then the O-mesh points of the wake's own component
/// with a kept wake point inside either one's ellipse go (the wake replaces the trailing edge's fan
/// of normals, whose cells are stretched across the wake).
std::vector<AddedPoint> wake_points(const tri::Triangulation2& domain_mesh,
                                    const DomainLocator2& locator, std::span<const WallLoop2> walls,
                                    std::span<const double> boundary_xy,
                                    std::vector<AddedPoint>& omesh, const SizeFunction& size,
                                    const StretchedDelaunayOptions2& o,
                                    StretchedDelaunayCounters2& counters) {
    std::vector<AddedPoint> points;
    std::vector<std::uint32_t> wake_of;
    const double across_factor =
        std::sqrt(o.growth) * (o.staggered_layers ? kStaggeredAcross : 1.0);
    const double stop_factor = o.staggered_layers ? 1 / kStaggeredAcross : 1.0;
    const double first_across = o.staggered_layers ? kStaggeredAcross : 1.0;
    std::uint32_t wakes = 0;
    for (const WallLoop2& wall : walls) {
        const std::optional<TrailingEdge> edge = trailing_edge(domain_mesh, wall);
        if (!edge) continue;
        ++counters.trailing_edges;
        const auto component = static_cast<std::uint32_t>(&wall - walls.data());
        const std::uint32_t wake = wakes++;
        const double* v = domain_mesh.point(wall.vertices[edge->vertex]);
        const std::array<double, 2>& d = edge->direction;
        const std::array<double, 2> normal = {-d[1], d[0]};
        const double length = o.wake_length * edge->chord;
        double distance = 0, station = wall.spacing[edge->vertex], first = o.first_height;
        while (true) {
            distance += station;
            if (!(distance <= length)) break;
            const double cx = std::fma(distance, d[0], v[0]);
            const double cy = std::fma(distance, d[1], v[1]);
            station = std::min(station, size(cx, cy));
            if (!(first < stop_factor * station)) break;  // isotropic: the far field's
            if (!strictly_inside(domain_mesh, locator, cx, cy)) break;
            // The centre (layer 0) and the layers on both sides; points of the odd layers half
            // a station ahead when staggered.
            double height = 0, thickness = first;
            for (int k = 0; k <= o.max_layers; ++k) {
                if (k > 0) {
                    if (!(thickness < stop_factor * station)) break;
                    height += thickness;
                }
                const double ahead = o.staggered_layers && k % 2 == 1 ? 0.5 * station : 0.0;
                for (const double side : {1.0, -1.0}) {
                    if (k == 0 && side < 0) continue;
                    AddedPoint a;
                    const double along = distance + ahead;
                    a.x = std::fma(side * height, normal[0], std::fma(along, d[0], v[0]));
                    a.y = std::fma(side * height, normal[1], std::fma(along, d[1], v[1]));
                    a.component = component;
                    a.wake = true;
                    a.layer = k;
                    a.thickness = k == 0 ? 0 : thickness;
                    a.across = k == 0 ? first * first_across : thickness * across_factor;
                    a.spacing = std::max(station, a.across);
                    a.tx = d[0];
                    a.ty = d[1];
                    ++counters.wake_points;
                    points.push_back(a);
                    wake_of.push_back(wake);
                    if (points.size() > point_budget(o)) {
                        throw InputError("stretched Delaunay: the wake (length " +
                                         format_number(o.wake_length) +
                                         " chords) asks for more than " +
                                         std::to_string(point_budget(o)) + " points");
                    }
                }
                if (k > 0) thickness *= o.growth;
            }
            station *= o.growth;
            first *= o.growth * o.growth;
        }
    }
    if (points.empty()) return points;
    // The filter: the O-meshes, the wall vertices and the boundary win; between wakes, the
    // finer point (a thinner layer, then a lower wake).
    SortedPoints sorted;
    std::vector<Metric2> metric_of;
    double largest = 0;
    for (const AddedPoint& p : omesh) {
        sorted.add(p.x, p.y, static_cast<std::uint32_t>(metric_of.size()));
        metric_of.push_back(omesh_metric(p));
        largest = std::max({largest, p.spacing, p.across});
    }
    for (std::size_t i = 0; i + 1 < boundary_xy.size(); i += 2) {
        const double h = size(boundary_xy[i], boundary_xy[i + 1]);
        sorted.add(boundary_xy[i], boundary_xy[i + 1],
                   static_cast<std::uint32_t>(metric_of.size()));
        metric_of.push_back(isotropic(h));
        largest = std::max(largest, h);
    }
    for (const WallLoop2& wall : walls) {
        for (std::size_t i = 0; i < wall.vertices.size(); ++i) {
            const double* p = domain_mesh.point(wall.vertices[i]);
            sorted.add(p[0], p[1], static_cast<std::uint32_t>(metric_of.size()));
            metric_of.push_back(wall_metric(wall, i, o));
            largest = std::max(largest, wall.spacing[i]);
        }
    }
    const auto others = static_cast<std::uint32_t>(metric_of.size());
    for (const AddedPoint& p : points) {
        sorted.add(p.x, p.y, static_cast<std::uint32_t>(metric_of.size()));
        metric_of.push_back(omesh_metric(p));
        largest = std::max({largest, p.spacing, p.across});
    }
    sorted.sort();
    std::vector<AddedPoint> kept;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
        const AddedPoint& p = points[i];
        const Metric2& own = metric_of[others + i];
        const bool drop =
            !strictly_inside(domain_mesh, locator, p.x, p.y) ||
            sorted.any_near(p.x, p.y, largest, [&](double x, double y, std::uint32_t q) {
                if (q < omesh.size() && omesh[q].component == p.component) return false;
                if (q >= others) {
                    const std::uint32_t j = q - others;
                    if (wake_of[j] == wake_of[i]) return false;
                    const bool finer =
                        points[j].thickness < p.thickness ||
                        (points[j].thickness == p.thickness && wake_of[j] < wake_of[i]);
                    if (!finer) return false;
                }
                const double dx = x - p.x, dy = y - p.y;
                return metric_length(own, dx, dy) < 1 || metric_length(metric_of[q], dx, dy) < 1;
            });
        if (drop) {
            ++counters.wake_dropped;
        } else {
            kept.push_back(p);
        }
    }
    // The trailing edges' fans give way to their wakes.
    SortedPoints kept_sorted;
    double largest_kept = 0;
    for (std::uint32_t i = 0; i < kept.size(); ++i) {
        kept_sorted.add(kept[i].x, kept[i].y, i);
        largest_kept = std::max({largest_kept, kept[i].spacing, kept[i].across});
    }
    kept_sorted.sort();
    std::vector<AddedPoint> omesh_kept;
    for (std::uint32_t i = 0; i < omesh.size(); ++i) {
        const AddedPoint& p = omesh[i];
        const double radius = std::max({largest_kept, p.spacing, p.across});
        const bool drop =
            kept_sorted.any_near(p.x, p.y, radius, [&](double x, double y, std::uint32_t q) {
                if (kept[q].component != p.component) return false;
                const double dx = x - p.x, dy = y - p.y;
                return metric_length(metric_of[i], dx, dy) < 1 ||
                       metric_length(omesh_metric(kept[q]), dx, dy) < 1;
            });
        if (drop) {
            ++counters.wake_omesh_dropped;
        } else {
            omesh_kept.push_back(p);
        }
    }
    omesh = std::move(omesh_kept);
    return kept;
}

/// The far field: the centres of the leaves of a quadtree over the domain's bounding square,
/// a cell split while it is wider than the size at its centre; kept strictly inside the domain
/// and at least far_field_spacing sizes from every point of `near`.
std::vector<AddedPoint> far_field_points(const tri::Triangulation2& domain_mesh,
                                         const DomainLocator2& locator,
                                         std::span<const double> boundary_xy,
                                         std::span<const AddedPoint> omesh,
                                         std::span<const AddedPoint> wake, const SizeFunction& size,
                                         const StretchedDelaunayOptions2& o,
                                         StretchedDelaunayCounters2& counters) {
    double lo_x = std::numeric_limits<double>::infinity(), lo_y = lo_x;
    double hi_x = -lo_x, hi_y = -lo_x;
    for (std::size_t i = 0; i + 1 < boundary_xy.size(); i += 2) {
        lo_x = std::min(lo_x, boundary_xy[i]);
        hi_x = std::max(hi_x, boundary_xy[i]);
        lo_y = std::min(lo_y, boundary_xy[i + 1]);
        hi_y = std::max(hi_y, boundary_xy[i + 1]);
    }
    if (!(hi_x > lo_x) && !(hi_y > lo_y)) return {};
    struct Cell {
        double x, y, side;
        int depth;
    };
    std::vector<Cell> stack{{lo_x, lo_y, std::max(hi_x - lo_x, hi_y - lo_y), 0}};
    std::vector<std::array<double, 3>> centres;  // x, y, the leaf's side
    while (!stack.empty()) {
        const Cell cell = stack.back();
        stack.pop_back();
        const double half = 0.5 * cell.side;
        const double cx = cell.x + half, cy = cell.y + half;
        if (cell.depth < 60 && cell.side > size(cx, cy)) {
            for (const auto& [dx, dy] : {std::pair{0.0, 0.0}, std::pair{half, 0.0},
                                         std::pair{0.0, half}, std::pair{half, half}})
                stack.push_back({cell.x + dx, cell.y + dy, half, cell.depth + 1});
            continue;
        }
        centres.push_back({cx, cy, cell.side});
        if (centres.size() > point_budget(o)) {
            throw InputError("stretched Delaunay: the far-field size (" + size.describe() +
                             ") asks for more than " +
                             format_approximate(static_cast<double>(point_budget(o))) + " points");
        }
    }
    counters.far_field_candidates = centres.size();
    SortedPoints near;
    for (std::size_t i = 0; i + 1 < boundary_xy.size(); i += 2)
        near.add(boundary_xy[i], boundary_xy[i + 1], 0);
    for (const AddedPoint& p : omesh) near.add(p.x, p.y, 0);
    for (const AddedPoint& p : wake) near.add(p.x, p.y, 0);
    near.sort();
    std::vector<AddedPoint> kept;
    for (const auto& centre : centres) {
        // Named copies, not structured bindings: a lambda may not capture those (clang 14).
        const double x = centre[0], y = centre[1];
        const double r = o.far_field_spacing * size(x, y);
        const bool drop = !strictly_inside(domain_mesh, locator, x, y) ||
                          near.any_near(x, y, r, [&](double qx, double qy, std::uint32_t) {
                              return scale_free_norm(qx - x, qy - y) < r;
                          });
        if (drop) {
            ++counters.far_field_dropped;
            continue;
        }
        AddedPoint a;
        a.x = x;
        a.y = y;
        // Its metric, like an O-mesh point's, from its own cell (step 3): isotropic, the leaf's
        // side times (1 + sqrt 2) / 2, so that a uniform patch's sides and diagonals (side and
        // side sqrt 2 long) measure 0.83 and 1.17, both unit; the size asked for would measure
        // sides from 0.5 (leaves are half to all of it wide) and miss the unit range.
        a.spacing = centre[2] * kFarFieldSizePerSide;
        kept.push_back(a);
    }
    return kept;
}

/// Lawson swapping by in-ellipse under the quadrilaterals' mean metrics.

/// Replaces the side k of triangle t (from v[k] to v[k+1]) by the other diagonal of its
/// quadrilateral with the neighbour across it, keeping the neighbours and the constraint flags
/// (neither of the two triangles' other sides changes): with p = v[k], q = v[k+1], r = v[k+2]
/// and s the neighbour's apex, t = (p, q, r) and u = (q, p, s) become t = (r, p, s) and
/// u = (s, q, r), the diagonal p-q replaced by r-s.
void flip_side(tri::Triangulation2& mesh, tri::TriIdx t, unsigned k, tri::TriIdx u, unsigned j) {
    const auto at = [](tri::TriIdx tri_index, unsigned local) {
        return 3 * std::size_t{tri_index} + local % 3;
    };
    const tri::VertIdx p = mesh.triangles[at(t, k)], q = mesh.triangles[at(t, k + 1)];
    const tri::VertIdx r = mesh.triangles[at(t, k + 2)], s = mesh.triangles[at(u, j + 2)];
    const tri::TriIdx n_qr = mesh.neighbors[at(t, k + 1)], n_rp = mesh.neighbors[at(t, k + 2)];
    const tri::TriIdx n_ps = mesh.neighbors[at(u, j + 1)], n_sq = mesh.neighbors[at(u, j + 2)];
    const bool flagged = !mesh.constrained.empty();
    const std::uint8_t c_qr = flagged ? mesh.constrained[at(t, k + 1)] : 0;
    const std::uint8_t c_rp = flagged ? mesh.constrained[at(t, k + 2)] : 0;
    const std::uint8_t c_ps = flagged ? mesh.constrained[at(u, j + 1)] : 0;
    const std::uint8_t c_sq = flagged ? mesh.constrained[at(u, j + 2)] : 0;
    const tri::VertIdx new_t[3] = {r, p, s}, new_u[3] = {s, q, r};
    const tri::TriIdx across_t[3] = {n_rp, n_ps, u}, across_u[3] = {n_sq, n_qr, t};
    const std::uint8_t flags_t[3] = {c_rp, c_ps, 0}, flags_u[3] = {c_sq, c_qr, 0};
    for (unsigned i = 0; i < 3; ++i) {
        mesh.triangles[at(t, i)] = new_t[i];
        mesh.triangles[at(u, i)] = new_u[i];
        mesh.neighbors[at(t, i)] = across_t[i];
        mesh.neighbors[at(u, i)] = across_u[i];
        if (flagged) {
            mesh.constrained[at(t, i)] = flags_t[i];
            mesh.constrained[at(u, i)] = flags_u[i];
        }
    }
    // The two outer neighbours that changed sides: p-s now faces t, q-r now faces u.
    const auto relink = [&](tri::TriIdx outer, tri::TriIdx from, tri::TriIdx to) {
        if (outer == tri::kNone) return;
        for (unsigned i = 0; i < 3; ++i) {
            if (mesh.neighbors[at(outer, i)] == from) mesh.neighbors[at(outer, i)] = to;
        }
    };
    relink(n_ps, u, t);
    relink(n_qr, t, u);
}

/// Below this mean ratio in its metric, a triangle is flat there (1: equilateral).
constexpr double kFlatMetricShape = 0.5;

/// The mean ratio 4 sqrt(3) area / sum of squared edge lengths of the triangle with corners
/// `corner` in the log-Euclidean mean of its corners' metrics, on the edges mapped to the
/// metric's unit frame and scaled by a power of two (no square overflows or underflows; the
/// same value for the mesh and metrics scaled by 2^k). A selection, not a sign: the swap it
/// allows is still decided exactly.
double metric_shape(const tri::Triangulation2& mesh, std::span<const Metric2> metrics,
                    const tri::VertIdx* corner) {
    const std::array<Metric2, 3> at = {metrics[corner[0]], metrics[corner[1]], metrics[corner[2]]};
    static constexpr double kThirds[3] = {1, 1, 1};
    const Metric2 mean = log_euclidean_mean(at, kThirds);
    double ex[3], ey[3];
    double largest = 0;
    for (unsigned k = 0; k < 3; ++k) {
        const double* a = mesh.point(corner[k]);
        const double* b = mesh.point(corner[(k + 1) % 3]);
        metric_map(mean, b[0] - a[0], b[1] - a[1], ex[k], ey[k]);
        largest = std::max({largest, std::fabs(ex[k]), std::fabs(ey[k])});
    }
    const predicates::PowerOfTwo scale(predicates::unit_shift(largest));
    double squares = 0;
    for (unsigned k = 0; k < 3; ++k) {
        ex[k] = scale(ex[k]);
        ey[k] = scale(ey[k]);
        squares += ex[k] * ex[k] + ey[k] * ey[k];
    }
    const double area = 0.5 * (ex[0] * ey[1] - ey[0] * ex[1]);
    return squares > 0 ? 4.0 * 1.7320508075688772 * area / squares : 0.0;
}

/// The larger of two corners (exact compare_angles).
predicates::Corner larger_corner(const predicates::Corner& a, const predicates::Corner& b) {
    return predicates::compare_angles(a, b) == Sign::Negative ? b : a;
}

/// A cleanup after the in-ellipse swaps: the mean of four vertex matrices, where the stretching
/// turns quickly between neighbouring wall normals (a trailing edge's fan), is much less
/// stretched than any of them, and the swaps under it can leave flat triangles along one
/// normal. A triangle whose largest angle exceeds the reference corner (atan2(1/2, -0.8660...),
/// 150 degrees to 1e-16) gets the side opposite it swapped when its quadrilateral is strictly
/// convex and the quadrilateral's largest angle strictly decreases: the min-max criterion
/// [Babuska-Aziz76; BarthJespersen "The design and application of upwind schemes on
/// unstructured meshes" 1989] applied only there. Every decision is exact (orient2d,
/// compare_angles); every swap decreases the largest angle of a pair, so passes end.
///
/// With staggered layers the triangles of a stretched cell are equilateral in their metric and
/// their Euclidean largest angle is near 180 degrees by design (an isosceles triangle of base s
/// and height sqrt(3)/2 s / aspect ratio): only the triangles flat in their metric as well
/// (metric_shape below kFlatMetricShape) are swapped then; `metrics` empty: every one.
std::uint64_t swap_out_flat_triangles(tri::Triangulation2& mesh, std::span<const Metric2> metrics) {
    static constexpr double kOrigin[2] = {0, 0}, kRight[2] = {1, 0};
    static constexpr double kAt150[2] = {-0.8660254037844386, 0.5};
    const predicates::Corner reference{kOrigin, kRight, kAt150};
    std::uint64_t swaps = 0;
    for (int pass = 0; pass < 16; ++pass) {
        std::uint64_t pass_swaps = 0;
        for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
            const double* corner_point[3];
            for (unsigned i = 0; i < 3; ++i)
                corner_point[i] = mesh.point(mesh.triangles[3 * t + i]);
            const predicates::Corner largest =
                predicates::largest_corner(corner_point[0], corner_point[1], corner_point[2]);
            if (predicates::compare_angles(largest, reference) != Sign::Positive) continue;
            if (!metrics.empty() &&
                !(metric_shape(mesh, metrics, &mesh.triangles[3 * std::size_t{t}]) <
                  kFlatMetricShape))
                continue;
            unsigned apex = 0;
            while (corner_point[apex] != largest.o) ++apex;
            const unsigned k = (apex + 1) % 3;  // the side opposite the largest angle
            const tri::TriIdx u = mesh.neighbors[3 * std::size_t{t} + k];
            if (u == tri::kNone || mesh.is_constrained(t, static_cast<int>(k))) continue;
            unsigned j = 0;
            while (j < 3 && mesh.neighbors[3 * std::size_t{u} + j] != t) ++j;
            if (j == 3) continue;
            const double* p = corner_point[k];
            const double* q = corner_point[(k + 1) % 3];
            const double* r = corner_point[apex];
            const double* s = mesh.point(mesh.triangles[3 * std::size_t{u} + (j + 2) % 3]);
            if (predicates::orient2d(r, p, s) != Sign::Positive ||
                predicates::orient2d(s, q, r) != Sign::Positive)
                continue;
            const predicates::Corner before =
                larger_corner(largest, predicates::largest_corner(q, p, s));
            const predicates::Corner after = larger_corner(predicates::largest_corner(r, p, s),
                                                           predicates::largest_corner(s, q, r));
            if (predicates::compare_angles(after, before) != Sign::Negative) continue;
            flip_side(mesh, t, k, u, j);
            ++pass_swaps;
        }
        swaps += pass_swaps;
        if (pass_swaps == 0) break;
    }
    return swaps;
}

}  // namespace

StretchedDelaunayResult2 stretched_delaunay_2d(const MeshDomain2& domain,
                                               const StretchedDelaunayOptions2& options) {
    check_options(options);
    StretchedDelaunayCounters2 counters;
    const tri::Cdt2Result& domain_cdt = domain.triangulation();
    const tri::Triangulation2& domain_mesh = domain_cdt.mesh;
    std::vector<WallLoop2> walls = wall_loops_2d(domain_mesh);
    for (WallLoop2& wall : walls) {
        wall_normals_2d(domain_mesh, wall, options.normal_smoothing_passes);
        ++counters.components;
        counters.wall_vertices += wall.vertices.size();
    }
    const SizeFunction size = options.far_field_size.bounded() ? options.far_field_size
                                                               : graded_size_from_boundary(domain);
    // The boundary split to the far-field size, except the walls: their vertices (the input's)
    // are the O-meshes' feet.
    DomainBoundary2 boundary = discretize_except_walls(domain, walls, size);
    const DomainLocator2& locator = boundary.locator;
    const tri::Triangulation2& located = boundary.cdt.mesh;

    // Steps 1 and 2.
    std::vector<AddedPoint> omesh = omesh_points(located, locator, walls, options, counters);
    if (!omesh.empty()) omesh = drop_overlaps(located, walls, std::move(omesh), options, counters);
    const std::vector<AddedPoint> wake =
        options.wake_length > 0
            ? wake_points(located, locator, walls, boundary.xy, omesh, size, options, counters)
            : std::vector<AddedPoint>{};
    const std::vector<AddedPoint> far =
        far_field_points(located, locator, boundary.xy, omesh, wake, size, options, counters);

    // Every point once, exactly: the boundary's, then the O-meshes', then the far field's.
    std::vector<double> xy = boundary.xy;
    const auto boundary_count = static_cast<tri::VertIdx>(xy.size() / 2);
    std::set<std::pair<double, double>> seen;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) seen.insert({xy[i], xy[i + 1]});
    std::vector<AddedPoint> added;
    for (const std::vector<AddedPoint>* list :
         std::array<const std::vector<AddedPoint>*, 3>{&omesh, &wake, &far}) {
        for (const AddedPoint& p : *list) {
            if (!seen.insert({p.x, p.y}).second) {
                ++counters.duplicates;
                continue;
            }
            xy.push_back(p.x);
            xy.push_back(p.y);
            added.push_back(p);
        }
    }

    // Step 3: a metric and a smoothing weight per point.
    std::vector<Metric2> metrics(xy.size() / 2);
    std::vector<double> weights(metrics.size(), 0.5);
    for (tri::VertIdx v = 0; v < boundary_count; ++v)
        metrics[v] = isotropic(size(xy[2 * std::size_t{v}], xy[2 * std::size_t{v} + 1]));
    for (const WallLoop2& wall : walls) {
        for (std::size_t i = 0; i < wall.vertices.size(); ++i) {
            // No layers (max_layers 0): the wall is boundary like any other, sized isotropically.
            metrics[wall.vertices[i]] =
                options.max_layers > 0 ? wall_metric(wall, i, options) : isotropic(wall.spacing[i]);
            weights[wall.vertices[i]] = 0;
        }
    }
    for (std::size_t i = 0; i < added.size(); ++i) {
        const AddedPoint& p = added[i];
        const std::size_t v = boundary_count + i;
        if (p.component == kNoComponent) {
            metrics[v] = isotropic(p.spacing);
        } else {
            metrics[v] = omesh_metric(p);
            weights[v] = 0.5 * p.layer / (p.layer + 4.0);
        }
    }

    // Step 4.
    const tri::Pslg& pslg = domain.pslg();
    // Each piece bends only where its input segment may (piece_lines: the chain rule measured
    // against the input segment, as frontal and metric Delaunay triangulate their pieces).
    const std::vector<tri::VertIdx> lines = piece_lines(boundary);
    tri::Cdt2Result out = tri::constrained_delaunay_2d(
        tri::Pslg{xy, boundary.pieces, pslg.holes, pslg.regions, lines}, domain.domain_options());
    restore_input_terms(boundary, out);
    tri::Triangulation2& mesh = out.mesh;
    counters.points = mesh.vertex_count();

    // Steps 5 to 7.
    if (mesh.triangle_count() > 0) {
        smooth_vertex_metrics(mesh, metrics, options.metric_smoothing_passes, 0, weights);
        tri::EdgeSwapCounters swapped = metric_swaps_2d(mesh, metrics);
        counters.swaps = swapped.swaps;
        counters.swap_budget_hits = swapped.budget_stops;
        for (int pass = 0; pass < options.point_smoothing_passes; ++pass) {
            const PointSmoothingCounters2 smoothed =
                smooth_metric_points_2d(mesh, metrics, weights, options.point_move_limit,
                                        MoveLimit::SmallestSize, boundary_count);
            counters.smoothing_moves += smoothed.moves;
            counters.smoothing_refused += smoothed.refused;
            swapped = metric_swaps_2d(mesh, metrics);
            counters.reswaps += swapped.swaps;
            counters.swap_budget_hits += swapped.budget_stops;
        }
        counters.flat_swaps = swap_out_flat_triangles(mesh, options.staggered_layers
                                                                ? std::span<const Metric2>(metrics)
                                                                : std::span<const Metric2>());
    }
    return {std::move(out), std::move(metrics), counters};
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const StretchedDelaunayCounters2& c) {
    return counters_by_name(kStretchedDelaunayCounterNames, c);
}

}  // namespace exactmesh::generators
