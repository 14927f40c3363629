// SPDX-License-Identifier: MIT
// The domain's discretized boundary and point-in-domain queries (see domain_boundary_2d.hpp).
#include "generators/domain_boundary_2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>

#include "predicates/errors.hpp"
#include "predicates/orient2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;
using Point = std::array<double, 2>;

namespace {

/// discretize_curve with a first sample count (doubled until there are 8 samples per piece).
std::vector<Point> spaced_points(const Curve2& curve, double u0, double u1,
                                 const SizeFunction& size, int min_pieces, int samples) {
    for (;;) {
        std::vector<double> u(static_cast<std::size_t>(samples) + 1), cumulative(u.size(), 0.0);
        Point previous = curve(u0);
        u[0] = u0;
        for (int i = 1; i <= samples; ++i) {
            const auto index = static_cast<std::size_t>(i);
            u[index] = u0 + (u1 - u0) * i / samples;
            const Point p = curve(u[index]);
            const double s = size(0.5 * (p[0] + previous[0]), 0.5 * (p[1] + previous[1]));
            const double ds = std::hypot(p[0] - previous[0], p[1] - previous[1]);
            cumulative[index] = cumulative[index - 1] + (std::isfinite(s) ? ds / s : 0.0);
            previous = p;
        }
        const double total = cumulative.back();
        if (!std::isfinite(total) || total > double{1 << 30}) {
            throw InputError(
                "boundary discretization: the size function asks for more than 2^30 pieces on one "
                "curve or segment (size " +
                std::to_string(size(curve(u0)[0], curve(u0)[1])) + " near (" +
                std::to_string(curve(u0)[0]) + ", " + std::to_string(curve(u0)[1]) + "))");
        }
        const int pieces = std::max(min_pieces, static_cast<int>(std::ceil(total - 1e-9)));
        if (pieces * 8 > samples && samples < (1 << 24)) {
            samples = std::min(1 << 24, pieces * 16);
            continue;
        }
        std::vector<Point> points{curve(u0)};
        std::size_t i = 0;
        for (int k = 1; k < pieces; ++k) {
            const double target = total > 0 ? total * k / pieces : 0.0;
            double parameter;
            if (total > 0) {
                while (i + 1 < cumulative.size() && cumulative[i + 1] < target) ++i;
                const double span = cumulative[i + 1] - cumulative[i];
                const double f = span > 0 ? (target - cumulative[i]) / span : 0.0;
                parameter = u[i] + f * (u[i + 1] - u[i]);
            } else {
                parameter = u0 + (u1 - u0) * k / pieces;
            }
            points.push_back(curve(parameter));
        }
        points.push_back(curve(u1));
        return points;
    }
}

std::uint64_t edge_key(tri::VertIdx a, tri::VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace

std::vector<Point> discretize_curve(const Curve2& curve, double u0, double u1,
                                    const SizeFunction& size, int min_pieces) {
    return spaced_points(curve, u0, u1, size, min_pieces, 4096);
}

DomainLocator2::DomainLocator2(const tri::Triangulation2& mesh) {
    const tri::TriIdx count = mesh.triangle_count();
    if (count == 0) return;
    double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
    x0_ = std::numeric_limits<double>::infinity();
    y0_ = x0_;
    for (const tri::VertIdx v : mesh.triangles) {
        x0_ = std::min(x0_, mesh.point(v)[0]);
        y0_ = std::min(y0_, mesh.point(v)[1]);
        x1 = std::max(x1, mesh.point(v)[0]);
        y1 = std::max(y1, mesh.point(v)[1]);
    }
    // About one triangle per cell; widths in long double so that extents near the largest
    // double do not overflow.
    const long double width = static_cast<long double>(x1) - x0_,
                      height = static_cast<long double>(y1) - y0_;
    const long double extent = std::max(width, height);
    const double cells = std::max(1.0, std::sqrt(static_cast<double>(count)));
    cell_ = static_cast<double>(extent / cells);
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = std::numeric_limits<double>::max();
    columns_ = static_cast<std::uint32_t>(std::clamp<long double>(width / cell_, 0, 4095)) + 1;
    rows_ = static_cast<std::uint32_t>(std::clamp<long double>(height / cell_, 0, 4095)) + 1;
    start_.assign(std::size_t{columns_} * rows_ + 1, 0);
    auto range = [&](tri::TriIdx t, std::uint32_t& c0, std::uint32_t& c1, std::uint32_t& r0,
                     std::uint32_t& r1) {
        c0 = r0 = std::numeric_limits<std::uint32_t>::max();
        c1 = r1 = 0;
        for (unsigned k = 0; k < 3; ++k) {
            std::uint32_t c, r;
            cell_of(mesh.point(mesh.triangles[3 * t + k])[0],
                    mesh.point(mesh.triangles[3 * t + k])[1], c, r);
            c0 = std::min(c0, c), c1 = std::max(c1, c), r0 = std::min(r0, r), r1 = std::max(r1, r);
        }
    };
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<std::uint32_t> fill;
        if (pass == 1) {
            for (std::size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
            triangles_.resize(start_.back());
            fill.assign(start_.begin(), start_.end() - 1);
        }
        for (tri::TriIdx t = 0; t < count; ++t) {
            std::uint32_t c0, c1, r0, r1;
            range(t, c0, c1, r0, r1);
            for (std::uint32_t r = r0; r <= r1; ++r) {
                for (std::uint32_t c = c0; c <= c1; ++c) {
                    const std::size_t cell = std::size_t{r} * columns_ + c;
                    if (pass == 0) {
                        ++start_[cell + 1];
                    } else {
                        triangles_[fill[cell]++] = t;
                    }
                }
            }
        }
    }
}

bool DomainLocator2::cell_of(double x, double y, std::uint32_t& column, std::uint32_t& row) const {
    const long double fx = (static_cast<long double>(x) - x0_) / cell_,
                      fy = (static_cast<long double>(y) - y0_) / cell_;
    if (!(fx >= -1e-9L) || !(fy >= -1e-9L) || !(fx < columns_ + 1e-9L) || !(fy < rows_ + 1e-9L))
        return false;
    column = static_cast<std::uint32_t>(std::clamp<long double>(fx, 0, columns_ - 1));
    row = static_cast<std::uint32_t>(std::clamp<long double>(fy, 0, rows_ - 1));
    return true;
}

tri::TriIdx DomainLocator2::locate(const tri::Triangulation2& mesh, double x, double y) const {
    if (columns_ == 0 || !std::isfinite(x) || !std::isfinite(y)) return tri::kNone;
    std::uint32_t column, row;
    if (!cell_of(x, y, column, row)) return tri::kNone;
    const double p[2] = {x, y};
    const auto search = [&](std::uint32_t c, std::uint32_t r) -> tri::TriIdx {
        const std::size_t cell = std::size_t{r} * columns_ + c;
        for (std::uint32_t i = start_[cell]; i < start_[cell + 1]; ++i) {
            const tri::TriIdx t = triangles_[i];
            bool inside = true;
            for (unsigned k = 0; k < 3 && inside; ++k) {
                inside = predicates::orient2d(mesh.point(mesh.triangles[3 * t + k]),
                                              mesh.point(mesh.triangles[3 * t + (k + 1) % 3]),
                                              p) != predicates::Sign::Negative;
            }
            if (inside) return t;
        }
        return tri::kNone;
    };
    // The point's own cell first: cell_of is monotone in x and in y, so a triangle containing
    // the point has its box's cells around the point's cell and is listed there. The cells
    // beside it only when that fails (a point outside, or on a border: kept as a safeguard).
    if (const tri::TriIdx t = search(column, row); t != tri::kNone) return t;
    for (std::uint32_t r = row > 0 ? row - 1 : 0; r <= std::min(row + 1, rows_ - 1); ++r) {
        for (std::uint32_t c = column > 0 ? column - 1 : 0; c <= std::min(column + 1, columns_ - 1);
             ++c) {
            if (c == column && r == row) continue;
            if (const tri::TriIdx t = search(c, r); t != tri::kNone) return t;
        }
    }
    return tri::kNone;
}

SizeFunction size_from_boundary(const tri::Pslg& pslg, const tri::Cdt2Options& cdt) {
    tri::Cdt2Options options = cdt;
    options.remove_exterior = true;
    const tri::Cdt2Result domain = tri::constrained_delaunay_2d(pslg, options);
    const tri::Triangulation2& mesh = domain.mesh;
    if (mesh.triangle_count() == 0) throw InputError("the segments enclose no region");
    // Per vertex: the summed length and count of the pieces at it, then of all its edges.
    const std::size_t n = mesh.vertex_count();
    std::vector<double> piece_sum(n, 0), edge_sum(n, 0);
    std::vector<std::uint32_t> piece_count(n, 0), edge_count(n, 0);
    auto length = [&](tri::VertIdx a, tri::VertIdx b) {
        return std::hypot(mesh.xy[2 * b] - mesh.xy[2 * a], mesh.xy[2 * b + 1] - mesh.xy[2 * a + 1]);
    };
    for (std::size_t p = 0; p + 1 < domain.pieces.size(); p += 2) {
        const double l = length(domain.pieces[p], domain.pieces[p + 1]);
        for (const tri::VertIdx v : {domain.pieces[p], domain.pieces[p + 1]}) {
            piece_sum[v] += l;
            ++piece_count[v];
        }
    }
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const tri::VertIdx a = mesh.triangles[e];
        const tri::VertIdx b = mesh.triangles[e % 3 == 2 ? e - 2 : e + 1];
        edge_sum[a] += length(a, b);
        ++edge_count[a];
    }
    // The background mesh holds the vertices some triangle uses (merged duplicates and points
    // outside the domain are left out), renumbered densely.
    std::vector<std::uint32_t> dense(n, tri::kNone);
    std::vector<double> xy, sizes;
    std::vector<std::uint32_t> triangles;
    triangles.reserve(mesh.triangles.size());
    for (const tri::VertIdx v : mesh.triangles) {
        if (dense[v] == tri::kNone) {
            dense[v] = static_cast<std::uint32_t>(sizes.size());
            xy.insert(xy.end(), {mesh.xy[2 * v], mesh.xy[2 * v + 1]});
            sizes.push_back(piece_count[v] > 0 ? piece_sum[v] / piece_count[v]
                                               : edge_sum[v] / edge_count[v]);
        }
        triangles.push_back(dense[v]);
    }
    return SizeFunction::background_mesh(std::move(xy), std::move(sizes), std::move(triangles));
}

bool in_domain(const DomainBoundary2& boundary, double x, double y) {
    return boundary.locator.locate(boundary.cdt.mesh, x, y) != tri::kNone;
}

DomainBoundary2 discretize_domain_boundary(const tri::Pslg& pslg, const SizeFunction& size,
                                           const tri::Cdt2Options& cdt_options) {
    tri::Cdt2Options options = cdt_options;
    options.remove_exterior = true;
    if (options.recovery == tri::SegmentRecovery::Conforming)
        options.recovery = tri::SegmentRecovery::Swap;
    DomainBoundary2 boundary;
    boundary.cdt = tri::constrained_delaunay_2d(pslg, options);
    const tri::Triangulation2& mesh = boundary.cdt.mesh;
    if (mesh.triangle_count() == 0) {
        throw InputError(
            "the segments enclose no region (every triangle is outside the segments or in a hole)");
    }
    boundary.xy = mesh.xy;
    boundary.input_vertex_count = boundary.cdt.input_vertex_count;
    std::unordered_set<std::uint64_t> directed;
    directed.reserve(mesh.triangles.size());
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k)
            directed.insert(
                edge_key(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]));
    }
    const auto& pieces = boundary.cdt.pieces;
    for (std::size_t p = 0; 2 * p + 1 < pieces.size(); ++p) {
        const tri::VertIdx a = pieces[2 * p], b = pieces[2 * p + 1];
        const std::uint32_t segment = boundary.cdt.piece_segment[p];
        const bool left = directed.count(edge_key(a, b)) != 0,
                   right = directed.count(edge_key(b, a)) != 0;
        std::vector<tri::VertIdx> chain{a};
        if (left || right) {
            // Split by the size function along the straight piece; the first sample count
            // estimated from the sizes at the ends and the middle.
            const Point pa{mesh.point(a)[0], mesh.point(a)[1]},
                pb{mesh.point(b)[0], mesh.point(b)[1]};
            const Curve2 line = [&](double u) {
                return u == 1.0 ? pb
                                : Point{pa[0] + u * (pb[0] - pa[0]), pa[1] + u * (pb[1] - pa[1])};
            };
            const double length = std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
            const double smallest = std::min({size(pa[0], pa[1]), size(pb[0], pb[1]),
                                              size(0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]))});
            const double estimate = std::isfinite(smallest) ? length / smallest : 0.0;
            if (!(estimate <= double{1 << 30})) {
                throw InputError(
                    "boundary discretization: the size function asks for more than 2^30 pieces on "
                    "segment " +
                    std::to_string(segment + options.first_index) + " (size " +
                    std::to_string(smallest) + " along a length " + std::to_string(length) + ")");
            }
            const int samples =
                static_cast<int>(std::clamp(16 * estimate + 16, 16.0, double{1 << 24}));
            const std::vector<Point> points = spaced_points(line, 0.0, 1.0, size, 1, samples);
            for (std::size_t k = 1; k + 1 < points.size(); ++k) {
                if ((points[k][0] == points[k - 1][0] && points[k][1] == points[k - 1][1]) ||
                    (points[k][0] == pb[0] && points[k][1] == pb[1])) {
                    continue;  // rounding merged two points: one piece fewer
                }
                chain.push_back(static_cast<tri::VertIdx>(boundary.xy.size() / 2));
                boundary.xy.push_back(points[k][0]);
                boundary.xy.push_back(points[k][1]);
            }
        }
        chain.push_back(b);
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
            boundary.pieces.insert(boundary.pieces.end(), {chain[k], chain[k + 1]});
            boundary.piece_segment.push_back(segment);
            if (left) {
                boundary.front.insert(boundary.front.end(), {chain[k], chain[k + 1]});
                boundary.front_segment.push_back(segment);
            }
            if (right) {
                boundary.front.insert(boundary.front.end(), {chain[k + 1], chain[k]});
                boundary.front_segment.push_back(segment);
            }
        }
    }
    if (boundary.xy.size() / 2 > std::uint64_t{tri::kNone} / 4) {
        throw InputError("boundary discretization: " + std::to_string(boundary.xy.size() / 2) +
                         " boundary points, too many for 32-bit vertex numbers");
    }
    boundary.locator = DomainLocator2(boundary.cdt.mesh);
    return boundary;
}

}  // namespace exactmesh::generators
