// SPDX-License-Identifier: MIT
// Octree tetrahedral mesh generation (see octree_mesh_3d.hpp).
//
// Data: the octree's leaves (octree_3d) with a core flag; the pieces of every core leaf's faces
// (a piece is the leaf's face, or a finer neighbour's face when the neighbour across is finer);
// exact axis lines (every vertex filed under the three axis-parallel lines through it) to find
// the vertices on a piece's perimeter; vertex tables keyed by exact coordinates.
#include "generators/mesh_3d/octree_mesh_3d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/mesh_3d/gap_estimate_3d.hpp"
#include "generators/mesh_3d/region_volumes_3d.hpp"
#include "generators/mesh_3d/restricted_delaunay_3d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/recovery_3d/region_flood_3d.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
using Point = std::array<double, 3>;
using predicates::Sign;
using tri::kNone;
using tri::VertIdx;

constexpr std::uint64_t kDefaultMaxLeaves = 1000000;
/// A leaf splits while its edge exceeds this many sizes at its centre, so leaves end with
/// edges in (0.9 h, 1.8 h]. The cone template's edges (leaf edges, half and whole face and cube
/// diagonals) average 0.78 leaf edges (measured on box-with-hole), so the mesh's edges average
/// between 0.7 h and 1.4 h, centred on h in ratio. With 1 (split while the edge exceeds h) the
/// edges averaged 0.5-0.56 h: at size 0.05, 6% of them in [0.7, 1.4] h against 85% now.
constexpr double kLeafEdgePerSize = 1.8;

struct PointHash {
    std::size_t operator()(const Point& p) const {
        std::uint64_t h = 0;
        for (const double x : p) h = (h ^ std::bit_cast<std::uint64_t>(x)) * 0x9E3779B97F4A7C15ull;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

/// +0 for -0, so that equal coordinates hash alike.
Point normalized(Point p) {
    for (double& x : p) x += 0.0;
    return p;
}

/// Vertices of a flat coordinate array, found by their exact coordinates.
class VertexTable {
  public:
    explicit VertexTable(std::vector<double>& xyz) : xyz_(xyz) {
        for (std::size_t v = 0; 3 * v < xyz_.size(); ++v)
            ids_.emplace(normalized({xyz_[3 * v], xyz_[3 * v + 1], xyz_[3 * v + 2]}),
                         static_cast<VertIdx>(v));
    }
    VertIdx add(const Point& p) {
        const auto [it, added] = ids_.emplace(normalized(p), static_cast<VertIdx>(xyz_.size() / 3));
        if (added) xyz_.insert(xyz_.end(), p.begin(), p.end());
        return it->second;
    }
    VertIdx find(const Point& p) const {
        const auto it = ids_.find(normalized(p));
        return it == ids_.end() ? kNone : it->second;
    }

  private:
    std::vector<double>& xyz_;
    std::unordered_map<Point, VertIdx, PointHash> ids_;
};

/// Points filed under the three axis-parallel lines through them (exact coordinates).
class AxisLines {
  public:
    void add(const Point& p, VertIdx v) {
        for (int a = 0; a < 3; ++a) lines_[line_key(a, p)].push_back({p[axis(a)], v});
    }
    void finish() {
        for (auto& [line, entries] : lines_) {
            std::sort(entries.begin(), entries.end());
            entries.erase(
                std::unique(entries.begin(), entries.end(),
                            [](const auto& x, const auto& y) { return x.first == y.first; }),
                entries.end());
        }
    }
    /// The points strictly between `from` and `to` on the line through p along `a`, in order
    /// from `from` to `to`.
    void between(int a, const Point& p, double from, double to, std::vector<VertIdx>& out) const {
        const auto it = lines_.find(line_key(a, p));
        if (it == lines_.end()) return;
        const auto& entries = it->second;
        const double lo = std::min(from, to), hi = std::max(from, to);
        auto first = std::upper_bound(entries.begin(), entries.end(), lo,
                                      [](double x, const auto& e) { return x < e.first; });
        auto last = std::lower_bound(entries.begin(), entries.end(), hi,
                                     [](const auto& e, double x) { return e.first < x; });
        if (first >= last) return;
        if (from < to) {
            for (auto e = first; e != last; ++e) out.push_back(e->second);
        } else {
            for (auto e = last; e != first;) out.push_back((--e)->second);
        }
    }

  private:
    static std::size_t axis(int a) { return static_cast<std::size_t>(a); }
    static std::tuple<int, double, double> line_key(int a, const Point& p) {
        return {a, p[axis((a + 1) % 3)] + 0.0, p[axis((a + 2) % 3)] + 0.0};
    }
    std::map<std::tuple<int, double, double>, std::vector<std::pair<double, VertIdx>>> lines_;
};

/// One square piece of a core leaf's face: in the plane x_axis = plane, [u0, u0 + edge] x
/// [v0, v0 + edge] on the axes (axis + 1) % 3 and (axis + 2) % 3.
struct Piece {
    std::uint32_t leaf = 0;       ///< the core leaf whose face holds it
    std::uint32_t neighbour = 0;  ///< the leaf across
    int axis = 0;
    double plane = 0, u0 = 0, v0 = 0, edge = 0;
    bool core_core = false;
    std::uint32_t facet = kNone;  ///< the band PLC's facet (core-band pieces)

    Point corner(int q) const {
        Point p{};
        p[static_cast<std::size_t>(axis)] = plane;
        p[static_cast<std::size_t>((axis + 1) % 3)] = u0 + ((q == 1 || q == 2) ? edge : 0.0);
        p[static_cast<std::size_t>((axis + 2) % 3)] = v0 + (q >= 2 ? edge : 0.0);
        return p;
    }
    Point centre() const {
        Point p{};
        p[static_cast<std::size_t>(axis)] = plane;
        p[static_cast<std::size_t>((axis + 1) % 3)] = u0 + edge / 2;
        p[static_cast<std::size_t>((axis + 2) % 3)] = v0 + edge / 2;
        return p;
    }
};

/// The vertices around a piece, counter-clockwise in (u, v): each corner (found by `corner_id`)
/// then the points strictly inside the edge to the next corner.
template <class CornerId>
std::vector<VertIdx> perimeter(const Piece& piece, const AxisLines& lines, CornerId corner_id) {
    std::vector<VertIdx> ids;
    for (int q = 0; q < 4; ++q) {
        const Point p = piece.corner(q), next = piece.corner((q + 1) % 4);
        ids.push_back(corner_id(p));
        const int along = q % 2 == 0 ? (piece.axis + 1) % 3 : (piece.axis + 2) % 3;
        const auto a = static_cast<std::size_t>(along);
        lines.between(along, p, p[a], next[a], ids);
    }
    return ids;
}

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) {
        std::iota(parent.begin(), parent.end(), std::uint32_t{0});
    }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

class OctreeMesher {
  public:
    OctreeMesher(const tri::Plc3& plc, const tri::ConformingMesh3& recovered,
                 const OctreeMesh3Options& options)
        : plc_(plc), recovered_(recovered), options_(options) {}

    OctreeMesh3Result run() {
        build_octree();
        classify_leaves();
        collect_pieces();
        mesh_band();
        merge();
        result_.counters.leaves = result_.octree.leaves().size();
        result_.counters.balance_splits = result_.octree.balance_splits();
        result_.counters.max_level = result_.octree.max_level();
        return std::move(result_);
    }

  private:
    const Octree3& octree() const { return result_.octree; }
    const OctreeCell3& leaf(std::uint32_t l) const { return result_.octree.leaves()[l]; }

    Point leaf_min(std::uint32_t l) const {
        return {octree().cell_min(leaf(l), 0), octree().cell_min(leaf(l), 1),
                octree().cell_min(leaf(l), 2)};
    }
    Point leaf_centre(std::uint32_t l) const {
        const double half = octree().cell_edge(leaf(l).level) / 2;
        const Point lo = leaf_min(l);
        return {lo[0] + half, lo[1] + half, lo[2] + half};
    }

    void build_octree() {
        // The box of the facets' corners: the domain lies inside it, and a free vertex outside
        // it is outside the domain (the other generators leave it out too). The box of every
        // vertex made one free vertex 1e6 above a unit cube ask for 6.4e7 leaves at size 0.25.
        const double inf = std::numeric_limits<double>::infinity();
        Point lo = {inf, inf, inf}, hi = {-inf, -inf, -inf};
        const auto extend = [&](VertIdx v) {
            for (std::size_t a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], plc_.point(v)[a]);
                hi[a] = std::max(hi[a], plc_.point(v)[a]);
            }
        };
        for (const tri::Facet3& facet : plc_.facets)
            for (const std::vector<VertIdx>& polygon : facet.polygons)
                for (const VertIdx v : polygon) extend(v);
        result_.octree = Octree3(lo, hi);
        const std::uint64_t budget = options_.max_leaves ? options_.max_leaves : kDefaultMaxLeaves;
        // The estimate: the box's volume over h^3 (every leaf meeting the box has an edge of at
        // most h), summed over 8^3 samples; each factor a ratio of lengths, so scale-free.
        constexpr int kSamples = 8;
        double estimate = 0;
        for (int s = 0; s < kSamples * kSamples * kSamples; ++s) {
            const int index[3] = {s % kSamples, (s / kSamples) % kSamples,
                                  s / (kSamples * kSamples)};
            Point centre{};
            double step[3];
            for (std::size_t a = 0; a < 3; ++a) {
                step[a] = (hi[a] - lo[a]) / kSamples;
                centre[a] = lo[a] + (index[a] + 0.5) * step[a];
            }
            const double h = options_.size(centre[0], centre[1], centre[2]);
            estimate += (step[0] / h) * (step[1] / h) * (step[2] / h);
        }
        // Capped like the other 3D estimates, so that a domain at 2^600 with an unscaled size
        // reads "about 1e+300", not "infinity" (and a NaN from a flat box counts as huge).
        if (!(estimate <= 1e300)) estimate = 1e300;
        result_.counters.estimated_leaves = static_cast<std::uint64_t>(std::min(estimate, 1.8e19));
        if (estimate > static_cast<double>(budget)) {
            throw InputError("octree mesh 3d: leaf budget of " + std::to_string(budget) +
                             " exceeded at once: the size (" + options_.size.describe() +
                             ") asks for about " + format_approximate(estimate, 3) +
                             " leaves; raise the size or the budget");
        }
        result_.octree.refine_and_balance(
            [&](const OctreeCell3& cell) {
                Point centre{};
                for (int a = 0; a < 3; ++a) {
                    const double cmin = octree().cell_min(cell, a),
                                 cmax = octree().cell_max(cell, a);
                    const auto ua = static_cast<std::size_t>(a);
                    if (cmin > hi[ua] || cmax < lo[ua]) return false;
                    centre[ua] = (cmin + cmax) / 2;
                }
                return octree().cell_edge(cell.level) >
                       kLeafEdgePerSize * options_.size(centre[0], centre[1], centre[2]);
            },
            budget);
    }

    /// The leaves across face d (axis d / 2, the + side when d is odd) of leaf l, with the
    /// piece each shares: {neighbour, the cell whose face is the piece}. Empty outside the root.
    std::vector<std::pair<std::uint32_t, OctreeCell3>> face_neighbours(std::uint32_t l,
                                                                       int d) const {
        const OctreeCell3& cell = leaf(l);
        const int axis = d / 2, side = d % 2;
        std::int64_t n[3] = {cell.i, cell.j, cell.k};
        n[axis] += side ? 1 : -1;
        const std::uint32_t found = octree().find_leaf(cell.level, n[0], n[1], n[2]);
        if (found == Octree3::kOutside) return {};
        if (found != Octree3::kFiner) return {{found, cell}};
        std::vector<std::pair<std::uint32_t, OctreeCell3>> out;
        for (std::uint32_t c = 0; c < 4; ++c) {
            std::int64_t m[3];
            m[axis] = 2 * n[axis] + (side ? 0 : 1);
            m[(axis + 1) % 3] = 2 * n[(axis + 1) % 3] + (c & 1);
            m[(axis + 2) % 3] = 2 * n[(axis + 2) % 3] + (c >> 1);
            const std::uint32_t child = octree().find_leaf(cell.level + 1, m[0], m[1], m[2]);
            // 2:1 balance: the cells across a finer face are leaves.
            if (child == Octree3::kOutside || child == Octree3::kFiner ||
                leaf(child).level != cell.level + 1)
                throw InternalError("octree mesh 3d: the octree is not 2:1 balanced");
            out.push_back({child, leaf(child)});
        }
        return out;
    }

    void classify_leaves() {
        const std::uint32_t leaf_count = static_cast<std::uint32_t>(octree().leaves().size());
        // Facet bounding boxes, filed in a uniform grid of buckets over the root (conservative:
        // the bucket of a coordinate is monotone in it, so boxes that meet share a bucket).
        const std::size_t facets = plc_.facets.size();
        std::vector<std::array<Point, 2>> boxes(facets);
        for (std::size_t f = 0; f < facets; ++f) {
            bool first = true;
            for (const auto& polygon : plc_.facets[f].polygons) {
                for (const VertIdx v : polygon) {
                    const double* p = plc_.point(v);
                    for (std::size_t a = 0; a < 3; ++a) {
                        boxes[f][0][a] = first ? p[a] : std::min(boxes[f][0][a], p[a]);
                        boxes[f][1][a] = first ? p[a] : std::max(boxes[f][1][a], p[a]);
                    }
                    first = false;
                }
            }
        }
        // Free vertices (in no facet polygon) inside the domain must be band vertices too: a
        // core leaf's templates would leave one out (or, on an interface square, make the
        // band's PLC refuse it). Each is a point box.
        std::vector<std::uint8_t> in_facet(plc_.vertex_count(), 0);
        for (const auto& facet : plc_.facets)
            for (const auto& polygon : facet.polygons)
                for (const VertIdx v : polygon) in_facet[v] = 1;
        for (VertIdx v = 0; v < plc_.vertex_count(); ++v) {
            if (in_facet[v]) continue;
            const double* p = plc_.point(v);
            boxes.push_back({Point{p[0], p[1], p[2]}, Point{p[0], p[1], p[2]}});
        }
        const std::size_t items = boxes.size();  // facets, then free vertices
        const int levels = std::clamp(
            static_cast<int>(std::ceil(std::log2(std::cbrt(static_cast<double>(items))))), 0, 6);
        const std::int64_t buckets = std::int64_t{1} << levels;
        const double root = octree().root_edge();
        auto bucket = [&](double x, std::size_t a) {
            const double t =
                std::floor((x - octree().corner()[a]) / root * static_cast<double>(buckets));
            return static_cast<std::int64_t>(std::clamp(t, 0.0, static_cast<double>(buckets - 1)));
        };
        std::unordered_map<std::int64_t, std::vector<std::uint32_t>> grid;
        auto bucket_key = [&](std::int64_t x, std::int64_t y, std::int64_t z) {
            return (x * buckets + y) * buckets + z;
        };
        for (std::size_t f = 0; f < items; ++f) {
            for (std::int64_t x = bucket(boxes[f][0][0], 0); x <= bucket(boxes[f][1][0], 0); ++x)
                for (std::int64_t y = bucket(boxes[f][0][1], 1); y <= bucket(boxes[f][1][1], 1);
                     ++y)
                    for (std::int64_t z = bucket(boxes[f][0][2], 2); z <= bucket(boxes[f][1][2], 2);
                         ++z)
                        grid[bucket_key(x, y, z)].push_back(static_cast<std::uint32_t>(f));
        }
        std::vector<std::uint8_t> candidate(leaf_count, 0);
        std::vector<std::uint32_t> seen_stamp(items, kNone);
        for (std::uint32_t l = 0; l < leaf_count; ++l) {
            const double e = octree().cell_edge(leaf(l).level);
            const Point lo = leaf_min(l);
            Point grown_lo{}, grown_hi{};
            for (std::size_t a = 0; a < 3; ++a) {
                grown_lo[a] = lo[a] - e;
                grown_hi[a] = lo[a] + 2 * e;
            }
            bool free = true;
            for (std::int64_t x = bucket(grown_lo[0], 0); free && x <= bucket(grown_hi[0], 0); ++x)
                for (std::int64_t y = bucket(grown_lo[1], 1); free && y <= bucket(grown_hi[1], 1);
                     ++y)
                    for (std::int64_t z = bucket(grown_lo[2], 2);
                         free && z <= bucket(grown_hi[2], 2); ++z) {
                        const auto it = grid.find(bucket_key(x, y, z));
                        if (it == grid.end()) continue;
                        for (const std::uint32_t f : it->second) {
                            if (seen_stamp[f] == l) continue;
                            seen_stamp[f] = l;
                            bool meets = true;
                            for (std::size_t a = 0; a < 3 && meets; ++a)
                                meets =
                                    boxes[f][1][a] > grown_lo[a] && boxes[f][0][a] < grown_hi[a];
                            if (meets) {
                                free = false;
                                break;
                            }
                        }
                    }
            candidate[l] = free ? 1 : 0;
        }
        // Face-connected components of candidates; one located centre classifies each.
        UnionFind components(leaf_count);
        for (std::uint32_t l = 0; l < leaf_count; ++l) {
            if (!candidate[l]) continue;
            for (int d = 1; d < 6; d += 2)
                for (const auto& [n, piece] : face_neighbours(l, d))
                    if (candidate[n]) components.unite(l, n);
        }
        std::unordered_map<std::uint32_t, bool> inside;
        result_.core.assign(leaf_count, 0);
        for (std::uint32_t l = 0; l < leaf_count; ++l) {
            if (!candidate[l]) continue;
            const std::uint32_t root_leaf = components.find(l);
            auto it = inside.find(root_leaf);
            if (it == inside.end())
                it = inside.emplace(root_leaf, locate(leaf_centre(root_leaf))).first;
            if (it->second) {
                result_.core[l] = 1;
                ++result_.counters.core_leaves;
            }
        }
    }

    /// Whether p lies in a (closed) tetrahedron of the recovered domain mesh (exact orient3d).
    bool locate(const Point& p) const {
        const tri::Tetrahedralization3& mesh = recovered_.mesh;
        for (std::size_t t = 0; t < mesh.tets.size(); t += 4) {
            const double* v[4];
            for (std::size_t k = 0; k < 4; ++k) v[k] = mesh.point(mesh.tets[t + k]);
            bool in = true;
            for (std::size_t k = 0; k < 4 && in; ++k) {
                const double* w[4] = {v[0], v[1], v[2], v[3]};
                w[k] = p.data();
                in = predicates::orient3d(w[0], w[1], w[2], w[3]) != Sign::Negative;
            }
            if (in) return true;
        }
        return false;
    }

    void collect_pieces() {
        const std::uint32_t leaf_count = static_cast<std::uint32_t>(octree().leaves().size());
        UnionFind components(leaf_count);
        for (std::uint32_t l = 0; l < leaf_count; ++l) {
            if (!result_.core[l]) continue;
            first_piece_.push_back(static_cast<std::uint32_t>(pieces_.size()));
            core_leaves_.push_back(l);
            for (int d = 0; d < 6; ++d) {
                const auto neighbours = face_neighbours(l, d);
                if (neighbours.empty())
                    throw InternalError("octree mesh 3d: a core leaf touches the root's side");
                const int axis = d / 2;
                for (const auto& [n, cell] : neighbours) {
                    Piece piece;
                    piece.leaf = l;
                    piece.neighbour = n;
                    piece.axis = axis;
                    const OctreeCell3& own = leaf(l);
                    piece.plane =
                        d % 2 ? octree().cell_max(own, axis) : octree().cell_min(own, axis);
                    piece.u0 = octree().cell_min(cell, (axis + 1) % 3);
                    piece.v0 = octree().cell_min(cell, (axis + 2) % 3);
                    piece.edge = octree().cell_edge(cell.level);
                    piece.core_core = result_.core[n] != 0;
                    if (piece.core_core) components.unite(l, n);
                    pieces_.push_back(piece);
                }
            }
        }
        first_piece_.push_back(static_cast<std::uint32_t>(pieces_.size()));
        for (const std::uint32_t l : core_leaves_) {
            if (components.find(l) != l) continue;
            const Point c = leaf_centre(l);
            hole_points_.insert(hole_points_.end(), c.begin(), c.end());
            ++result_.counters.core_components;
        }
    }

    void mesh_band() {
        band_plc_ = plc_;
        // Regions are assigned on the merged mesh (merge); in the band's PLC a region point on
        // an interface square would be refused as naming neither side of a facet.
        band_plc_.regions.clear();
        // Phase A: the corners of every core leaf and piece, on exact axis lines, so each
        // interface square lists every such corner on its perimeter (hanging corners).
        VertexTable corner_table(corner_xyz_);
        for (const std::uint32_t l : core_leaves_) {
            const Point lo = leaf_min(l);
            const double e = octree().cell_edge(leaf(l).level);
            for (int c = 0; c < 8; ++c)
                corner_table.add(
                    {lo[0] + (c & 1) * e, lo[1] + ((c >> 1) & 1) * e, lo[2] + ((c >> 2) & 1) * e});
        }
        for (const Piece& piece : pieces_)
            for (int q = 0; q < 4; ++q) corner_table.add(piece.corner(q));
        AxisLines corner_lines;
        for (std::size_t v = 0; 3 * v < corner_xyz_.size(); ++v)
            corner_lines.add({corner_xyz_[3 * v], corner_xyz_[3 * v + 1], corner_xyz_[3 * v + 2]},
                             static_cast<VertIdx>(v));
        corner_lines.finish();

        VertexTable band_table(band_plc_.xyz);
        for (Piece& piece : pieces_) {
            if (piece.core_core) continue;
            std::vector<VertIdx> polygon = perimeter(
                piece, corner_lines, [&](const Point& p) { return corner_table.find(p); });
            for (VertIdx& v : polygon)
                v = band_table.add({corner_xyz_[3 * std::size_t{v}],
                                    corner_xyz_[3 * std::size_t{v} + 1],
                                    corner_xyz_[3 * std::size_t{v} + 2]});
            piece.facet = static_cast<std::uint32_t>(band_plc_.facets.size());
            band_plc_.facets.push_back({{polygon}, {}, 0});
            piece_of_facet_.push_back(static_cast<std::uint32_t>(&piece - pieces_.data()));
        }
        result_.counters.interface_facets = piece_of_facet_.size();
        band_plc_.holes.insert(band_plc_.holes.end(), hole_points_.begin(), hole_points_.end());

        tri::BoundaryRecovery3Options recovery_options;
        recovery_options.max_steiner_points = options_.max_steiner_points;
        tri::BoundaryRecovery3Result recovered =
            tri::boundary_recovery_3d(band_plc_, recovery_options);
        result_.band_recovery = recovered.counters;
        FrontalDelaunay3Options frontal_options;
        frontal_options.size = options_.size;
        frontal_options.max_steiner_points = options_.max_steiner_points;
        frontal_options.estimate_gaps = false;  // octree_mesh_3d asked it of the input
        frontal_options.feature_gradation = options_.feature_gradation;
        FrontalDelaunay3Result frontal =
            frontal_delaunay_3d(band_plc_, std::move(recovered.mesh), frontal_options);
        result_.band_frontal = frontal.counters;
        band_ = std::move(frontal.mesh);
        result_.counters.band_vertices = band_.mesh.vertex_count();
        result_.counters.band_tets = band_.mesh.tet_count();
        check_band_planes();
    }

    /// Every band Steiner point on an interface square lies exactly in its plane, and on an
    /// interface segment exactly on its line (the constructions round once; see the header).
    void check_band_planes() const {
        const std::size_t input_facets = plc_.facets.size();
        for (VertIdx v = band_.input_vertex_count; v < band_.mesh.vertex_count(); ++v) {
            const double* p = band_.mesh.point(v);
            const std::uint32_t index = band_.feature_index[v];
            if (band_.vertex_feature[v] == tri::VertexFeature3::Facet && index >= input_facets) {
                const Piece& piece = pieces_[piece_of_facet_[index - input_facets]];
                if (p[piece.axis] != piece.plane)
                    throw InternalError("octree mesh 3d: band point " + format_point(p, 3) +
                                        " is off its interface square's plane");
            } else if (band_.vertex_feature[v] == tri::VertexFeature3::Segment &&
                       is_interface_segment(index)) {
                const double* a = band_.mesh.point(band_.segments[2 * std::size_t{index}]);
                const double* b = band_.mesh.point(band_.segments[2 * std::size_t{index} + 1]);
                for (int k = 0; k < 3; ++k)
                    if (a[k] == b[k] && p[k] != a[k])
                        throw InternalError("octree mesh 3d: band point " + format_point(p, 3) +
                                            " is off its interface segment's line");
            }
        }
    }

    bool is_interface_segment(std::uint32_t s) const {
        return band_.segments[2 * std::size_t{s}] >= plc_.vertex_count();
    }

    void merge() {
        tri::ConformingMesh3& out = result_.mesh;
        tri::Tetrahedralization3& mesh = out.mesh;
        mesh.xyz = band_.mesh.xyz;
        mesh.tets = band_.mesh.tets;
        const VertIdx band_count = band_.mesh.vertex_count();
        VertexTable table(mesh.xyz);
        for (std::size_t v = 0; 3 * v < corner_xyz_.size(); ++v)
            table.add({corner_xyz_[3 * v], corner_xyz_[3 * v + 1], corner_xyz_[3 * v + 2]});
        // Phase B: every vertex so far (band and corners) on exact axis lines.
        AxisLines lines;
        for (VertIdx v = 0; v < mesh.vertex_count(); ++v) {
            const double* p = mesh.point(v);
            lines.add({p[0], p[1], p[2]}, v);
        }
        lines.finish();
        const std::size_t input_facets = plc_.facets.size();
        std::vector<std::vector<VertIdx>> facet_triangles(piece_of_facet_.size());
        for (std::size_t s = 0; s < band_.subface_facet.size(); ++s) {
            const std::uint32_t f = band_.subface_facet[s];
            if (f < input_facets) continue;
            auto& list = facet_triangles[f - input_facets];
            list.insert(list.end(), band_.subfaces.begin() + static_cast<std::ptrdiff_t>(3 * s),
                        band_.subfaces.begin() + static_cast<std::ptrdiff_t>(3 * s + 3));
        }
        auto add_tet = [&](VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
            const Sign s =
                predicates::orient3d(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
            if (s == Sign::Zero) throw InternalError("octree mesh 3d: a flat template tetrahedron");
            if (s == Sign::Negative) std::swap(c, d);
            mesh.tets.insert(mesh.tets.end(), {a, b, c, d});
            ++result_.counters.template_tets;
        };
        for (std::size_t i = 0; i < core_leaves_.size(); ++i) {
            const VertIdx centre = table.add(leaf_centre(core_leaves_[i]));
            for (std::uint32_t p = first_piece_[i]; p < first_piece_[i + 1]; ++p) {
                const Piece& piece = pieces_[p];
                if (!piece.core_core) {
                    const auto& triangles = facet_triangles[piece.facet - input_facets];
                    if (triangles.empty())
                        throw InternalError("octree mesh 3d: an interface square has no band face");
                    for (std::size_t t = 0; t < triangles.size(); t += 3)
                        add_tet(centre, triangles[t], triangles[t + 1], triangles[t + 2]);
                    continue;
                }
                const std::vector<VertIdx> ring = perimeter(piece, lines, [&](const Point& q) {
                    const VertIdx v = table.find(q);
                    EM_ASSERT(v != kNone);
                    return v;
                });
                const VertIdx middle = table.add(piece.centre());
                for (std::size_t k = 0; k < ring.size(); ++k)
                    add_tet(centre, middle, ring[k], ring[(k + 1) % ring.size()]);
            }
        }
        result_.counters.template_vertices = mesh.vertex_count() - band_count;
        // Neighbours by shared faces; link_neighbors_3d also checks every tetrahedron positive
        // and every face in at most two (exact): a failure here is a bug, not the input's.
        mesh.neighbors.clear();
        try {
            tri::link_neighbors_3d(mesh);
        } catch (const InputError& error) {
            throw InternalError(std::string("octree mesh 3d: the merged mesh is not valid: ") +
                                error.what());
        }
        fill_features(out, band_count);
        // Regions on the merged mesh: its subfaces are the PLC's (interface squares dropped),
        // so a flood from each region point covers its whole region, core and band alike. The
        // domain is the recovered one, so a region point outside it was already named in
        // boundary recovery's warnings: these are the same and are not repeated.
        tri::assign_regions_3d(plc_, out);
    }

    /// The PLC's features from the band's: interface corners, segments and facets are not
    /// the PLC's, so their vertices become Volume and their pieces are dropped.
    void fill_features(tri::ConformingMesh3& out, VertIdx band_count) const {
        const VertIdx input = plc_.vertex_count();
        const std::size_t input_facets = plc_.facets.size();
        std::size_t input_segments = 0;
        while (2 * input_segments < band_.segments.size() &&
               band_.segments[2 * input_segments] < input)
            ++input_segments;
        for (std::size_t s = input_segments; 2 * s < band_.segments.size(); ++s)
            EM_ASSERT(band_.segments[2 * s] >= input && band_.segments[2 * s + 1] >= input);
        out.input_vertex_count = input;
        out.segments.assign(
            band_.segments.begin(),
            band_.segments.begin() + static_cast<std::ptrdiff_t>(2 * input_segments));
        for (std::size_t i = 0; i < band_.subsegment_segment.size(); ++i) {
            if (band_.subsegment_segment[i] >= input_segments) continue;
            out.subsegments.insert(out.subsegments.end(),
                                   {band_.subsegments[2 * i], band_.subsegments[2 * i + 1]});
            out.subsegment_segment.push_back(band_.subsegment_segment[i]);
        }
        for (std::size_t i = 0; i < band_.subface_facet.size(); ++i) {
            if (band_.subface_facet[i] >= input_facets) continue;
            out.subfaces.insert(out.subfaces.end(),
                                band_.subfaces.begin() + static_cast<std::ptrdiff_t>(3 * i),
                                band_.subfaces.begin() + static_cast<std::ptrdiff_t>(3 * i + 3));
            out.subface_facet.push_back(band_.subface_facet[i]);
        }
        const VertIdx n = out.mesh.vertex_count();
        out.vertex_feature.assign(n, tri::VertexFeature3::Volume);
        out.feature_index.assign(n, kNone);
        for (VertIdx v = 0; v < band_count; ++v) {
            const tri::VertexFeature3 feature = band_.vertex_feature[v];
            const std::uint32_t index = band_.feature_index[v];
            const bool own = (feature == tri::VertexFeature3::Input && v < input) ||
                             (feature == tri::VertexFeature3::Segment && index < input_segments) ||
                             (feature == tri::VertexFeature3::Facet && index < input_facets);
            if (!own) continue;
            out.vertex_feature[v] = feature;
            out.feature_index[v] = index;
        }
    }

    const tri::Plc3& plc_;
    const tri::ConformingMesh3& recovered_;
    const OctreeMesh3Options& options_;
    OctreeMesh3Result result_;
    std::vector<std::uint32_t> core_leaves_;
    std::vector<std::uint32_t> first_piece_;  ///< per core leaf (and one past the last)
    std::vector<Piece> pieces_;
    std::vector<double> hole_points_;
    std::vector<double> corner_xyz_;
    std::vector<std::uint32_t> piece_of_facet_;  ///< per interface facet (band facet - #input)
    tri::Plc3 band_plc_;
    tri::ConformingMesh3 band_;
};

}  // namespace

OctreeMesh3Result octree_mesh_3d(const tri::Plc3& plc, const tri::ConformingMesh3& recovered,
                                 const OctreeMesh3Options& options) {
    if (!options.size.defined())
        throw InputError("octree mesh 3d: no size given (the target edge length h)");
    if (plc.xyz.empty()) throw InputError("octree mesh 3d: the PLC has no vertex");
    refuse_gaps_far_over_budget_3d(
        plc, recovered, restricted_3d::steiner_budget_3d(recovered, options.max_steiner_points),
        "octree mesh 3d");
    // Region volume bounds (Region3::max_volume, flooded into the recovered tetrahedra) cap
    // the size in their regions: the leaves, the band's frontal insertion and the estimate
    // all follow the capped size.
    OctreeMesh3Options capped = options;
    capped.size = size_with_region_volumes_3d(options.size, recovered);
    OctreeMesher mesher(plc, recovered, capped);
    OctreeMesh3Result result = mesher.run();
    result.size = capped.size;
    return result;
}

}  // namespace exactmesh::generators
