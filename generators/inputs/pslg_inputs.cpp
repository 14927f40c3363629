// SPDX-License-Identifier: MIT
// PSLG generators (see pslg_inputs.hpp).
#include "generators/inputs/pslg_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "generators/inputs/inputs.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"

namespace exactmesh::generators {

namespace {

using Rng = std::mt19937_64;

Rng make_rng(PslgDistribution d, std::uint64_t seed) {
    return Rng(seed * 0xD1B54A32D192ED03ull + 0x9E37u * (static_cast<std::uint64_t>(d) + 1));
}

std::uint32_t below(Rng& rng, std::uint32_t n) {
    return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(rng);
}

/// Random walks along unused edges of the Delaunay triangulation of the first m points.
void add_chains(PslgInput& out, std::uint32_t m, std::uint32_t segments, Rng& rng) {
    const std::span<const double> subset(out.xy.data(), 2 * std::size_t{m});
    const triangulation::Delaunay2Result dt = triangulation::green_sibson_2d(subset);
    // Undirected edges once each (hull edges have no neighbour; interior ones are listed from
    // the triangle with the smaller index), then per-vertex adjacency (CSR).
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    const std::size_t triangles = dt.triangles.size() / 3;
    for (std::size_t t = 0; t < triangles; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t u = dt.neighbors[3 * t + k];
            if (u != triangulation::kNone && u < t) continue;
            edges.emplace_back(dt.triangles[3 * t + k], dt.triangles[3 * t + (k + 1) % 3]);
        }
    }
    std::vector<std::uint32_t> first(m + 1, 0), adjacent(2 * edges.size());
    for (const auto& [a, b] : edges) {
        ++first[a + 1];
        ++first[b + 1];
    }
    for (std::uint32_t v = 0; v < m; ++v) first[v + 1] += first[v];
    std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
    for (std::uint32_t e = 0; e < edges.size(); ++e) {
        adjacent[fill[edges[e].first]++] = e;
        adjacent[fill[edges[e].second]++] = e;
    }
    std::vector<std::uint8_t> used(edges.size(), 0);
    const std::uint32_t target =
        std::min<std::uint32_t>(segments, static_cast<std::uint32_t>(edges.size()));
    std::uint32_t made = 0;
    for (std::uint64_t attempts = 0; made < target && attempts < 64ull * target + 64; ++attempts) {
        std::uint32_t v = below(rng, m);
        const std::uint32_t length = 1 + below(rng, 64);
        for (std::uint32_t step = 0; step < length && made < target; ++step) {
            const std::uint32_t degree = first[v + 1] - first[v];
            if (degree == 0) break;
            const std::uint32_t start = below(rng, degree);
            std::uint32_t chosen = triangulation::kNone;
            for (std::uint32_t i = 0; i < degree && chosen == triangulation::kNone; ++i) {
                const std::uint32_t e = adjacent[first[v] + (start + i) % degree];
                if (!used[e]) chosen = e;
            }
            if (chosen == triangulation::kNone) break;
            used[chosen] = 1;
            const std::uint32_t w =
                edges[chosen].first == v ? edges[chosen].second : edges[chosen].first;
            out.segments.insert(out.segments.end(), {v, w});
            ++made;
            v = w;
        }
    }
}

/// A star-shaped polygon of k vertices about (cx, cy), radii in [0.55, 1]·radius, appended to
/// out.xy with its k segments; vertices whose exact angular order would not increase are left
/// out (never seen: the angular gaps are at least 0.4π/k, far above rounding).
void add_star_polygon(PslgInput& out, double cx, double cy, double radius, std::uint32_t k,
                      Rng& rng) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> polygon;
    for (std::uint32_t i = 0; i < k; ++i) {
        const double angle = 2 * std::numbers::pi * (i + 0.1 + 0.8 * unit(rng)) / k;
        const double r = radius * (0.55 + 0.45 * unit(rng));
        polygon.push_back(cx + r * std::cos(angle));
        polygon.push_back(cy + r * std::sin(angle));
    }
    const double centre[2] = {cx, cy};
    std::vector<double> kept;
    for (std::size_t i = 0; i < polygon.size(); i += 2) {
        if (kept.size() >= 2 &&
            predicates::orient2d(centre, kept.data() + kept.size() - 2, polygon.data() + i) !=
                predicates::Sign::Positive) {
            continue;
        }
        kept.insert(kept.end(), {polygon[i], polygon[i + 1]});
    }
    while (kept.size() >= 6 && predicates::orient2d(centre, kept.data() + kept.size() - 2,
                                                    kept.data()) != predicates::Sign::Positive) {
        kept.resize(kept.size() - 2);
    }
    const auto base = static_cast<std::uint32_t>(out.xy.size() / 2);
    const auto count = static_cast<std::uint32_t>(kept.size() / 2);
    out.xy.insert(out.xy.end(), kept.begin(), kept.end());
    for (std::uint32_t i = 0; i < count; ++i)
        out.segments.insert(out.segments.end(), {base + i, base + (i + 1) % count});
}

}  // namespace

std::string_view pslg_distribution_name(PslgDistribution d) {
    switch (d) {
        case PslgDistribution::Chains:
            return "chains";
        case PslgDistribution::Polygon:
            return "polygon";
        case PslgDistribution::PolygonWithHoles:
            return "holes";
        case PslgDistribution::GridLines:
            return "grid-lines";
        case PslgDistribution::Crossing:
            return "crossing";
        case PslgDistribution::NearCollinear:
            return "near-collinear";
        case PslgDistribution::Duplicates:
            return "duplicates";
    }
    return "unknown";
}

PslgInput generate_pslg(PslgDistribution d, std::uint32_t n, std::uint32_t segments,
                        std::uint64_t seed) {
    Rng rng = make_rng(d, seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PslgInput out;
    n = std::max<std::uint32_t>(n, 3);
    switch (d) {
        case PslgDistribution::Chains:
        case PslgDistribution::Duplicates: {
            out.xy = generate_points_2d(Distribution::Uniform, n, seed);
            add_chains(out, std::min(n, segments + 3), segments, rng);
            if (d == PslgDistribution::Duplicates) {
                // Copies of a third of the vertices appended (the geometry does not change, so
                // no crossing appears); a third of the segment ends moved to a copy.
                const std::uint32_t copies = n / 3;
                std::vector<std::uint32_t> copy_of(n, triangulation::kNone);
                for (std::uint32_t k = 0; k < copies; ++k) {
                    const std::uint32_t j = below(rng, n);
                    copy_of[j] = static_cast<std::uint32_t>(out.xy.size() / 2);
                    out.xy.insert(out.xy.end(), {out.xy[2 * j], out.xy[2 * j + 1]});
                }
                for (std::uint32_t& v : out.segments) {
                    if (copy_of[v] != triangulation::kNone && unit(rng) < 0.5) v = copy_of[v];
                }
                // And a few repeated and reversed segments.
                const std::size_t count = out.segments.size() / 2;
                for (std::size_t k = 0; k < count / 8; ++k) {
                    const std::size_t s = below(rng, static_cast<std::uint32_t>(count));
                    out.segments.insert(out.segments.end(),
                                        {out.segments[2 * s + 1], out.segments[2 * s]});
                }
            }
            break;
        }
        case PslgDistribution::Polygon: {
            const std::uint32_t k = std::clamp<std::uint32_t>(segments, 8, n);
            add_star_polygon(out, 0.5, 0.5, 0.5, k, rng);
            const auto corners = static_cast<std::uint32_t>(out.xy.size() / 2);
            const std::vector<double> polygon = out.xy;
            const double centre[2] = {0.5, 0.5};
            for (std::uint32_t i = corners; i < n; ++i) {
                // A point of the fan triangle (centre, p_j, p_j+1), strictly inside the polygon.
                const std::uint32_t j = below(rng, corners), j1 = (j + 1) % corners;
                const double s = 0.999 * std::sqrt(unit(rng)), w = unit(rng);
                for (int c = 0; c < 2; ++c) {
                    const double edge_point =
                        polygon[2 * j + c] * (1 - w) + polygon[2 * j1 + c] * w;
                    out.xy.push_back(centre[c] + s * (edge_point - centre[c]));
                }
            }
            break;
        }
        case PslgDistribution::PolygonWithHoles: {
            const std::uint32_t per_side = std::max<std::uint32_t>(1, segments / 8);
            for (std::uint32_t side = 0; side < 4; ++side) {
                for (std::uint32_t i = 0; i < per_side; ++i) {
                    const double t = static_cast<double>(i) / per_side;
                    const double x[4] = {t, 1, 1 - t, 0}, y[4] = {0, t, 1, 1 - t};
                    out.xy.insert(out.xy.end(), {x[side], y[side]});
                }
            }
            const std::uint32_t boundary = 4 * per_side;
            for (std::uint32_t i = 0; i < boundary; ++i)
                out.segments.insert(out.segments.end(), {i, (i + 1) % boundary});
            const std::uint32_t holes = std::max<std::uint32_t>(1, (segments / 2) / 12);
            const auto grid =
                static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(holes))));
            const double cell = 1.0 / grid;
            for (std::uint32_t h = 0; h < holes; ++h) {
                const double cx = (h % grid + 0.5) * cell, cy = (h / grid + 0.5) * cell;
                add_star_polygon(out, cx, cy, 0.35 * cell, 12, rng);
                out.holes.insert(out.holes.end(), {cx, cy});
            }
            while (out.xy.size() < 2 * std::size_t{n}) out.xy.push_back(0.001 + 0.998 * unit(rng));
            break;
        }
        case PslgDistribution::GridLines: {
            const auto side = std::max<std::uint32_t>(
                2, static_cast<std::uint32_t>(std::sqrt(static_cast<double>(n))));
            for (std::uint32_t i = 0; i < side * side; ++i) {
                out.xy.push_back(static_cast<double>(i % side));
                out.xy.push_back(static_cast<double>(i / side));
            }
            auto id = [side](std::uint32_t x, std::uint32_t y) { return y * side + x; };
            for (std::uint32_t s = 0; s < segments; ++s) {
                const std::uint32_t kind = below(rng, 10);
                std::uint32_t a = below(rng, side), b = below(rng, side), fixed = below(rng, side);
                if (a == b) b = (a + 1) % side;
                if (kind < 4) {
                    out.segments.insert(out.segments.end(),
                                        {id(a, fixed), id(b, fixed)});  // horizontal
                } else if (kind < 8) {
                    out.segments.insert(out.segments.end(),
                                        {id(fixed, a), id(fixed, b)});  // vertical
                } else {
                    // Diagonal of slope +-1 (through lattice points) or a knight's move (slope 2).
                    const std::uint32_t lo = std::min(a, b), span = std::max(a, b) - lo;
                    const std::uint32_t y0 = below(rng, side - span);
                    const bool up = kind == 8;
                    out.segments.insert(out.segments.end(), {id(lo, up ? y0 : y0 + span),
                                                             id(lo + span, up ? y0 + span : y0)});
                    if (side > 3 && s + 1 < segments) {
                        const std::uint32_t x = below(rng, side - 1), y = below(rng, side - 2);
                        out.segments.insert(out.segments.end(), {id(x, y), id(x + 1, y + 2)});
                        ++s;
                    }
                }
            }
            break;
        }
        case PslgDistribution::Crossing: {
            out.xy = generate_points_2d(Distribution::Uniform, n, seed);
            for (std::uint32_t s = 0; s < segments; ++s) {
                const std::uint32_t a = below(rng, n);
                std::uint32_t b = below(rng, n - 1);
                if (b >= a) ++b;
                out.segments.insert(out.segments.end(), {a, b});
            }
            break;
        }
        case PslgDistribution::NearCollinear: {
            // Two chains along y = x, sorted by x: one moved 1..4 ulps down in y, one 1..4 up.
            // A segment between two points strictly below the line y = x stays below it (a
            // half-plane is convex), so the chains never cross each other; within a chain the
            // segments occupy disjoint x-ranges. Then a few points well off the line.
            const std::uint32_t per_chain =
                std::max<std::uint32_t>(2, std::min(segments + 1, (n - 3) / 2));
            for (int side : {-1, 1}) {
                std::vector<double> t(per_chain);
                for (double& v : t) v = 0.5 + unit(rng);
                std::sort(t.begin(), t.end());
                t.erase(std::unique(t.begin(), t.end()), t.end());
                const auto base = static_cast<std::uint32_t>(out.xy.size() / 2);
                for (std::size_t i = 0; i < t.size(); ++i) {
                    double y = t[i];
                    for (std::uint32_t k = 1 + below(rng, 4); k > 0; --k)
                        y = std::nextafter(y, side > 0 ? 2.0 : 0.0);
                    out.xy.insert(out.xy.end(), {t[i], y});
                    if (i > 0)
                        out.segments.insert(out.segments.end(),
                                            {base + static_cast<std::uint32_t>(i) - 1,
                                             base + static_cast<std::uint32_t>(i)});
                }
            }
            out.xy.insert(out.xy.end(), {0.5, 1.5, 1.0, 1.25, 1.5, 0.5});
            break;
        }
    }
    return out;
}

std::uint64_t tiny_pslg_count(std::uint32_t vertices) {
    vertices = std::clamp<std::uint32_t>(vertices, 3, 8);
    return std::uint64_t{1} << (vertices * (vertices - 1) / 2);
}

PslgInput tiny_pslg(std::uint32_t vertices, std::uint64_t index) {
    static constexpr double kPoints[] = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 1, 0, 3, 1, 0, 1};
    vertices = std::clamp<std::uint32_t>(vertices, 3, 8);
    PslgInput out;
    out.xy.assign(kPoints, kPoints + 2 * vertices);
    std::uint32_t bit = 0;
    for (std::uint32_t i = 0; i < vertices; ++i) {
        for (std::uint32_t j = i + 1; j < vertices; ++j, ++bit) {
            if ((index >> bit) & 1u) out.segments.insert(out.segments.end(), {i, j});
        }
    }
    return out;
}

}  // namespace exactmesh::generators
