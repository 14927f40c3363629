// SPDX-License-Identifier: MIT
// The graded default size from the boundary (see graded_boundary_size_2d.hpp): per-vertex sizes
// from the domain's CDT, and a kd-tree answering min over v of (h_v + g |x - v|) within 1.6%.
#include "generators/boundary/graded_boundary_size_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/narrow_wedges_2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// A node is skipped when its lower bound times 1 + 2^-6 reaches the best value found.
constexpr double kSlack = 1.0 + 0x1p-6;
constexpr std::uint32_t kLeafSize = 8;

/// |(dx, dy)| in a frame scaled by the power of two that brings the larger component to [1, 2):
/// no square overflows or underflows, and the result scales exactly with the input by 2^k.
using predicates::scale_free_norm;

/// min over the sites of (h_v + g |x - v|), approximately (within the slack).
class GradedSites {
  public:
    GradedSites(std::vector<double> xy, std::vector<double> sizes, double gradation)
        : gradation_(gradation) {
        const auto n = static_cast<std::uint32_t>(sizes.size());
        order_.resize(n);
        std::iota(order_.begin(), order_.end(), 0u);
        xy_ = std::move(xy);
        sizes_ = std::move(sizes);
        nodes_.reserve(4 * (n / kLeafSize + 1));
        nodes_.push_back(make_node(0, n));
        split(0);
        // Store the sites in tree order, so a leaf reads contiguous memory.
        std::vector<double> xy_sorted(2 * std::size_t{n}), sizes_sorted(n);
        for (std::uint32_t i = 0; i < n; ++i) {
            xy_sorted[2 * i] = xy_[2 * order_[i]];
            xy_sorted[2 * i + 1] = xy_[2 * order_[i] + 1];
            sizes_sorted[i] = sizes_[order_[i]];
        }
        xy_ = std::move(xy_sorted);
        sizes_ = std::move(sizes_sorted);
    }

    double operator()(double x, double y) const {
        double best = kInfinity;
        // Depth-first, the nearer child first; the stack holds (node, lower bound).
        std::pair<std::uint32_t, double> stack[64];
        int top = 0;
        stack[top++] = {0, lower_bound(nodes_[0], x, y)};
        while (top > 0) {
            const auto [index, bound] = stack[--top];
            if (bound * kSlack >= best) continue;
            const Node& node = nodes_[index];
            if (node.left == kLeaf) {
                for (std::uint32_t i = node.begin; i < node.end; ++i) {
                    const double value =
                        sizes_[i] +
                        gradation_ * scale_free_norm(x - xy_[2 * i], y - xy_[2 * i + 1]);
                    best = std::min(best, value);
                }
                continue;
            }
            const std::uint32_t a = node.left, b = node.left + 1;
            const double bound_a = lower_bound(nodes_[a], x, y);
            const double bound_b = lower_bound(nodes_[b], x, y);
            // The depth is at most about log2(n / 8) + 1 < 32, two entries per level.
            if (bound_a <= bound_b) {
                stack[top++] = {b, bound_b};
                stack[top++] = {a, bound_a};
            } else {
                stack[top++] = {a, bound_a};
                stack[top++] = {b, bound_b};
            }
        }
        return best;
    }

    /// At most the value operator() returns anywhere in the box [x0, x1] x [y0, y1] (the
    /// exact minimum over the sites of h_v + g·(distance from v to the box), no slack in the
    /// pruning), but for a few units in the last place of rounding: the size criterion settled
    /// for a whole box (SizeFunction::lower_bound_in_box).
    double lower_bound_in_box(double x0, double y0, double x1, double y1) const {
        double best = kInfinity;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (box_bound(node.x0, node.y0, node.x1, node.y1, node.smallest, x0, y0, x1, y1) >=
                best)
                continue;
            if (node.left == kLeaf) {
                for (std::uint32_t i = node.begin; i < node.end; ++i) {
                    const double x = xy_[2 * i], y = xy_[2 * i + 1];
                    best = std::min(best, box_bound(x, y, x, y, sizes_[i], x0, y0, x1, y1));
                }
                continue;
            }
            stack[top++] = node.left + 1;
            stack[top++] = node.left;
        }
        return best;
    }

  private:
    static constexpr std::uint32_t kLeaf = std::numeric_limits<std::uint32_t>::max();
    /// smallest + g·(distance between the boxes [a] and [b]).
    double box_bound(double ax0, double ay0, double ax1, double ay1, double smallest, double bx0,
                     double by0, double bx1, double by1) const {
        const double dx = bx1 < ax0 ? ax0 - bx1 : bx0 > ax1 ? bx0 - ax1 : 0;
        const double dy = by1 < ay0 ? ay0 - by1 : by0 > ay1 ? by0 - ay1 : 0;
        return smallest + gradation_ * scale_free_norm(dx, dy);
    }
    struct Node {
        double x0, y0, x1, y1;           ///< the bounding box of its sites
        double smallest;                 ///< the smallest h_v of its sites
        std::uint32_t begin, end, left;  ///< sites [begin, end) of order_; children left, left + 1
    };

    double lower_bound(const Node& node, double x, double y) const {
        return box_bound(node.x0, node.y0, node.x1, node.y1, node.smallest, x, y, x, y);
    }

    /// The node of sites order_[begin, end), a leaf until split.
    Node make_node(std::uint32_t begin, std::uint32_t end) const {
        Node node{kInfinity, kInfinity, -kInfinity, -kInfinity, kInfinity, begin, end, kLeaf};
        for (std::uint32_t i = begin; i < end; ++i) {
            const std::uint32_t v = order_[i];
            node.x0 = std::min(node.x0, xy_[2 * v]);
            node.x1 = std::max(node.x1, xy_[2 * v]);
            node.y0 = std::min(node.y0, xy_[2 * v + 1]);
            node.y1 = std::max(node.y1, xy_[2 * v + 1]);
            node.smallest = std::min(node.smallest, sizes_[v]);
        }
        return node;
    }

    /// Splits nodes_[slot] at the median of its wider side, recursively, into children stored
    /// as a pair (left, left + 1); the depth stays about log2(n / kLeafSize).
    void split(std::uint32_t slot) {
        const Node node = nodes_[slot];
        if (node.end - node.begin <= kLeafSize) return;
        const int axis = node.x1 - node.x0 >= node.y1 - node.y0 ? 0 : 1;
        const std::uint32_t middle = node.begin + (node.end - node.begin) / 2;
        std::nth_element(order_.begin() + node.begin, order_.begin() + middle,
                         order_.begin() + node.end, [&](std::uint32_t p, std::uint32_t q) {
                             return xy_[2 * p + axis] < xy_[2 * q + axis];
                         });
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_[slot].left = left;
        nodes_.push_back(make_node(node.begin, middle));
        nodes_.push_back(make_node(middle, node.end));
        split(left);
        split(left + 1);
    }

    double gradation_;
    std::vector<double> xy_, sizes_;
    std::vector<std::uint32_t> order_;
    std::vector<Node> nodes_;
};

/// @throws InputError unless g is finite and > 0.
void check_gradation(double gradation) {
    if (!(std::isfinite(gradation) && gradation > 0)) {
        std::ostringstream text;
        text.precision(17);
        text << "the gradation of the default size must be finite and > 0, not " << gradation;
        throw InputError(text.str());
    }
}

/// The distance from p to the closed segment qr, in a frame scaled by the power of two of the
/// largest coordinate difference (no square overflows or underflows; exact scaling by 2^k).
double point_segment_distance(const double* p, const double* q, const double* r) {
    const double ux = p[0] - q[0], uy = p[1] - q[1], dx = r[0] - q[0], dy = r[1] - q[1];
    const double largest = std::max({std::fabs(ux), std::fabs(uy), std::fabs(dx), std::fabs(dy)});
    if (!(largest > 0)) return 0;
    const int e = predicates::binary_exponent(largest);
    const predicates::PowerOfTwo down(-e);
    const double a = down(ux), b = down(uy), c = down(dx), d = down(dy);
    const double length2 = c * c + d * d;
    const double t = length2 > 0 ? std::clamp((a * c + b * d) / length2, 0.0, 1.0) : 0.0;
    return predicates::PowerOfTwo(e)(std::hypot(a - t * c, b - t * d));
}

/// A free vertex lowers the size when its feature is below this fraction of the size there,
/// any vertex below kFar of it (graded_to_fine_features).
constexpr double kFiner = 0.7071067811865476;
constexpr double kFar = 0x1p-10;

}  // namespace

SizeFunction graded_to_fine_features(const MeshDomain2& domain_of, const SizeFunction& size,
                                     double gradation) {
    check_gradation(gradation);
    if (!size.bounded()) return size;
    const tri::Cdt2Result& domain = domain_of.triangulation();
    const tri::Triangulation2& mesh = domain.mesh;
    const std::size_t n = mesh.vertex_count();
    // f_v: the shortest CDT edge at v, and the distance to each segment piece opposite v in a
    // triangle of the domain (a vertex 1e-12 off a segment sits in the triangle over it).
    const BoundarySpacing spacing = boundary_spacing(domain);
    std::vector<double> feature = spacing.shortest;
    std::vector<std::uint8_t> on_segment(n, 0);
    for (const tri::VertIdx v : domain.pieces) on_segment[v] = 1;
    // A piece across a narrow wedge from v (narrow_wedges_2d: v on the wedge's other segment) is
    // no feature of v: the generators leave such wedges unresolved, and a fan's segments 1e-9
    // radians apart graded the size to 1e-9 at their ends (10^7 triangles asked for).
    std::vector<std::array<tri::VertIdx, 2>> ends(domain_of.pslg().segments.size() / 2);
    for (std::size_t s = 0; s < ends.size(); ++s)
        ends[s] = {domain_of.pslg().segments[2 * s], domain_of.pslg().segments[2 * s + 1]};
    const std::vector<std::uint64_t> narrow = narrow_wedges_2d(domain_of.pslg().xy, ends);
    std::unordered_map<std::uint64_t, std::uint32_t> segment_of_piece;
    std::vector<std::vector<std::uint32_t>> segments_at(narrow.empty() ? 0 : n);
    const auto edge_key = [](tri::VertIdx a, tri::VertIdx b) {
        return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
    };
    for (std::size_t p = 0; !narrow.empty() && 2 * p + 1 < domain.pieces.size(); ++p) {
        const tri::VertIdx a = domain.pieces[2 * p], b = domain.pieces[2 * p + 1];
        const std::uint32_t segment = domain.piece_segment[p];
        segment_of_piece.emplace(edge_key(a, b), segment);
        for (const tri::VertIdx v : {a, b}) segments_at[v].push_back(segment);
    }
    const auto across_narrow_wedge = [&](tri::VertIdx v, tri::VertIdx q, tri::VertIdx r) {
        if (narrow.empty()) return false;
        const auto piece = segment_of_piece.find(edge_key(q, r));
        if (piece == segment_of_piece.end()) return false;
        for (const std::uint32_t s : segments_at[v])
            if (narrow_wedge_pair(narrow, s, piece->second)) return true;
        return false;
    };
    const bool flagged = !mesh.constrained.empty();
    for (std::size_t t = 0; flagged && 3 * t < mesh.triangles.size(); ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            // Edge k joins corners k and k + 1; corner k + 2 is opposite it.
            if (mesh.constrained[3 * t + k] == 0) continue;
            const tri::VertIdx q = mesh.triangles[3 * t + k];
            const tri::VertIdx r = mesh.triangles[3 * t + (k + 1) % 3];
            const tri::VertIdx v = mesh.triangles[3 * t + (k + 2) % 3];
            if (across_narrow_wedge(v, q, r)) continue;
            feature[v] = std::min(
                feature[v], point_segment_distance(mesh.point(v), mesh.point(q), mesh.point(r)));
        }
    }
    std::vector<double> xy, sizes;
    std::vector<std::uint8_t> seen(n, 0);
    for (const tri::VertIdx v : mesh.triangles) {
        if (seen[v] != 0) continue;
        seen[v] = 1;
        const double* p = mesh.point(v);
        // No feature below 2^-44 of the vertex's own coordinates counts (about 2^8 units in the
        // last place: the generators leave such triangles as they are), nor below 2^8 times the
        // least normal double (subnormal sizes are not chased).
        const double floor =
            std::max(std::ldexp(std::max(std::fabs(p[0]), std::fabs(p[1])), -44), 0x1p-1014);
        const double f = std::max(feature[v], floor);
        const double h = size(p[0], p[1]);
        if (on_segment[v] == 0 ? f < kFiner * h : f < kFar * h) {
            xy.insert(xy.end(), {p[0], p[1]});
            sizes.push_back(f);
        }
    }
    if (sizes.empty()) return size;
    const std::size_t sites = sizes.size();
    auto field = std::make_shared<const GradedSites>(std::move(xy), std::move(sizes), gradation);
    std::ostringstream description;
    description << size.describe() << ", graded to " << sites
                << " vertices' fine features (gradation " << gradation << ")";
    return SizeFunction::analytic(
               [field, size](double x, double y) { return std::min(size(x, y), (*field)(x, y)); },
               description.str(),
               [field, size](double x0, double y0, double x1, double y1) {
                   return std::min(size.lower_bound_in_box(x0, y0, x1, y1),
                                   field->lower_bound_in_box(x0, y0, x1, y1));
               })
        .marked_steep();
}

SizeFunction graded_size_from_boundary(const tri::Pslg& pslg, const tri::Cdt2Options& cdt,
                                       double gradation) {
    check_gradation(gradation);
    return graded_size_from_boundary(MeshDomain2(pslg, cdt), gradation);
}

SizeFunction graded_size_from_boundary(const MeshDomain2& domain_of, double gradation) {
    check_gradation(gradation);
    const tri::Cdt2Result& domain = domain_of.triangulation();
    const tri::Triangulation2& mesh = domain.mesh;
    if (mesh.triangle_count() == 0) throw InputError("the segments enclose no region");
    const std::size_t n = mesh.vertex_count();
    const BoundarySpacing spacing = boundary_spacing(domain);
    std::vector<double> xy, sizes;
    std::vector<std::uint8_t> used(n, 0);
    for (const tri::VertIdx v : mesh.triangles) {
        if (used[v] != 0) continue;
        used[v] = 1;
        xy.insert(xy.end(), {mesh.xy[2 * v], mesh.xy[2 * v + 1]});
        sizes.push_back(std::min(spacing.mean[v], spacing.shortest[v]));
    }
    const std::size_t sites = sizes.size();
    // Sites 1024 times finer than others (a free vertex 1e-15 from a vertex on a segment):
    // the size dips steeply there, and a boundary piece beside such a site is sampled
    // adaptively, its elements estimated by their own sizes (SizeFunction::is_steep); counted
    // by the smallest size, a piece 0.09 long beside a site 6e-15 fine asked for more than
    // 2^30 pieces (min-max front), a domain for 1.7e9 triangles (advancing front Delaunay).
    const auto [finest, coarsest] = std::minmax_element(sizes.begin(), sizes.end());
    const bool steep = *finest < kFar * *coarsest;
    auto field = std::make_shared<const GradedSites>(std::move(xy), std::move(sizes), gradation);
    std::ostringstream description;
    description << "graded from the boundary: " << sites << " vertices, gradation " << gradation;
    SizeFunction graded = SizeFunction::analytic(
        [field](double x, double y) { return (*field)(x, y); }, description.str(),
        [field](double x0, double y0, double x1, double y1) {
            return field->lower_bound_in_box(x0, y0, x1, y1);
        });
    return steep ? graded.marked_steep() : graded;
}

}  // namespace exactmesh::generators
