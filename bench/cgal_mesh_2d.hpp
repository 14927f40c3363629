// SPDX-License-Identifier: MIT
// CGAL's 2D Delaunay refinement (Delaunay_mesher_2 on a Constrained_Delaunay_triangulation_2
// with Epick), as the peer of generators/mesh_2d/delaunay_refinement_2d in the differential tests
// and in bench/mesh_bench: the same PSLG, the same angle bound (CGAL's shape bound is sin^2 of the
// smallest angle, i.e. B = 1 / (2 sin theta) squared and inverted: b = 1 / (4 B^2)) and the same
// size criterion (every edge of a triangle at most the size at its midpoint: CGAL's own
// Delaunay_mesh_size_criteria_2 when the size is uniform, else the same criteria class with the
// size function evaluated where ours evaluates it). With a size that is not uniform, the size at
// an edge's midpoint is memoized in the faces on both sides of the edge (SizeMemoFaceBase), as
// ours keeps it per half-edge: CGAL's criteria test a face three edges at a time and test
// every face around each new vertex, so without the memo it evaluates the size function about
// three times per edge where ours evaluates it once (issue 11; SizeCache::None keeps the plain
// criteria, for the test that the memo changes no decision). Holes are CGAL seeds (mark =
// false); the unbounded component is outside, as ours. The result converts to a Triangulation2
// (input vertices first, in input order) with its constrained edges as pieces, for the same
// checks. Test and bench support: CGAL appears only in tests/ and bench/.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "generators/sizing/size_function.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::testing {

namespace cgal_mesh {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using Fb = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using UniformCriteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

/// Delaunay_mesh_face_base_2 with a memo per edge (edge k opposite vertex k): the addresses of
/// the edge's two vertices when its size was found, and that size. A memo is valid while the
/// face's edge k still joins those two vertices (faces are rewritten in place by insertions and
/// flips; vertices never move, and Delaunay_mesher_2 removes none, so an address names one point).
template <class Gt, class FbBase = CGAL::Delaunay_mesh_face_base_2<Gt>>
class SizeMemoFaceBase : public FbBase {
  public:
    template <typename Tds2>
    struct Rebind_TDS {
        using Fb2 = typename FbBase::template Rebind_TDS<Tds2>::Other;
        using Other = SizeMemoFaceBase<Gt, Fb2>;
    };
    using FbBase::FbBase;
    // User-provided, unlike `= default`: CGAL's Compact_container value-initializes faces, which
    // would zero an implicit constructor's whole object, time stamp included (the base's stamp
    // must stay as the container set it, or handles compare equal and edge iteration breaks).
    SizeMemoFaceBase() : FbBase() {}

    struct Memo {
        const void* a = nullptr;
        const void* b = nullptr;
        double size = 0;
    };
    mutable std::array<Memo, 3> memo{};
};

using MemoFb = SizeMemoFaceBase<Kernel>;
using MemoTds = CGAL::Triangulation_data_structure_2<Vb, MemoFb>;
using MemoCdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, MemoTds>;

/// Delaunay_mesh_size_criteria_2 with a size function: the size ratio is the largest
/// |edge|^2 / s(midpoint)^2 over the triangle's edges (1 is the bound), the shape CGAL's. With
/// kMemo (Tr = MemoCdt) the size at an edge's midpoint comes from the face's memo or its
/// neighbour's across the edge when valid, and is stored in the face's memo when evaluated.
template <class Tr, bool kMemo>
class FieldCriteria {
  public:
    using Quality = typename CGAL::Delaunay_mesh_size_criteria_2<Tr>::Quality;
    using Face_handle = typename Tr::Face_handle;
    FieldCriteria() = default;
    FieldCriteria(double sine2_bound, const generators::SizeFunction* size)
        : bound_(sine2_bound), size_(size) {}

    class Is_bad {
      public:
        Is_bad(double bound, const generators::SizeFunction* size) : bound_(bound), size_(size) {}
        CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
            if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }
        CGAL::Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const {
            const typename Kernel::Point_2* p[3] = {
                &fh->vertex(0)->point(), &fh->vertex(1)->point(), &fh->vertex(2)->point()};
            double length2[3], ratio = 0;
            for (int k = 0; k < 3; ++k) {
                const typename Kernel::Point_2& a = *p[(k + 1) % 3];
                const typename Kernel::Point_2& b = *p[(k + 2) % 3];
                const double dx = b.x() - a.x(), dy = b.y() - a.y();
                length2[k] = dx * dx + dy * dy;
                if (size_ != nullptr && size_->bounded()) {
                    const double s = size_at(fh, k, a, b);
                    ratio = std::max(ratio, length2[k] / (s * s));
                }
            }
            q.second = ratio;
            if (q.size() > 1) {
                q.first = 1;
                return CGAL::Mesh_2::IMPERATIVELY_BAD;
            }
            std::sort(length2, length2 + 3);
            const double area2 = 2 * CGAL::to_double(CGAL::area(*p[0], *p[1], *p[2]));
            q.first = area2 * area2 / (length2[2] * length2[1]);
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }

      private:
        double size_at(const Face_handle& fh, int k, const typename Kernel::Point_2& a,
                       const typename Kernel::Point_2& b) const {
            if constexpr (kMemo) {
                const void* va = &*fh->vertex((k + 1) % 3);
                const void* vb = &*fh->vertex((k + 2) % 3);
                auto& own = fh->memo[static_cast<std::size_t>(k)];
                if (own.size > 0 && own.a == va && own.b == vb) return own.size;
                // The neighbour across edge k sees it the other way round.
                const Face_handle n = fh->neighbor(k);
                for (std::size_t j = 0; j < 3; ++j) {
                    const auto& other = n->memo[j];
                    if (other.size > 0 && other.a == vb && other.b == va) {
                        own = other;
                        std::swap(own.a, own.b);
                        return own.size;
                    }
                }
                own = {va, vb, evaluate(a, b)};
                return own.size;
            } else {
                (void)fh;
                (void)k;
                return evaluate(a, b);
            }
        }
        double evaluate(const typename Kernel::Point_2& a,
                        const typename Kernel::Point_2& b) const {
            return (*size_)(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()));
        }

        double bound_;
        const generators::SizeFunction* size_;
    };
    Is_bad is_bad_object() const { return Is_bad(bound_, size_); }

  private:
    double bound_ = 0.125;
    const generators::SizeFunction* size_ = nullptr;
};

template <class Tr>
struct MeshOf {
    std::unique_ptr<Tr> cdt;
    std::vector<typename Tr::Vertex_handle> input;  ///< the input vertices, in input order
};
}  // namespace cgal_mesh

/// How the CGAL peer pays for a size function that is not uniform: Memo (the default; the size
/// at an edge's midpoint found once per edge, as ours) or None (CGAL's criteria as they come:
/// every face test evaluates its three edges).
enum class SizeCache { Memo, None };

/// The mesh: exactly one of `plain` (uniform or no size, or SizeCache::None) and `memo` holds it.
struct CgalMesh {
    cgal_mesh::MeshOf<cgal_mesh::Cdt> plain;
    cgal_mesh::MeshOf<cgal_mesh::MemoCdt> memo;
};

namespace cgal_mesh {
template <class Tr, class Criteria>
void mesh_into(MeshOf<Tr>& out, std::span<const double> xy, std::span<const std::uint32_t> segments,
               std::span<const double> holes, const Criteria& criteria) {
    out.cdt = std::make_unique<Tr>();
    Tr& cdt = *out.cdt;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
        out.input.push_back(cdt.insert(Kernel::Point_2(xy[i], xy[i + 1])));
    }
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
        if (out.input[segments[s]] != out.input[segments[s + 1]]) {
            cdt.insert_constraint(out.input[segments[s]], out.input[segments[s + 1]]);
        }
    }
    std::list<Kernel::Point_2> seeds;
    for (std::size_t h = 0; h + 1 < holes.size(); h += 2)
        seeds.emplace_back(holes[h], holes[h + 1]);
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), criteria);
}
}  // namespace cgal_mesh

/// Meshes the PSLG with CGAL: insert the points, the constraints, then refine (the timed part
/// of the bench). min_angle in degrees; size uniform (CGAL's own criteria) or any (FieldCriteria,
/// memoized unless cache is SizeCache::None).
inline CgalMesh cgal_delaunay_mesh_2d(std::span<const double> xy,
                                      std::span<const std::uint32_t> segments,
                                      std::span<const double> holes, double min_angle,
                                      const generators::SizeFunction& size,
                                      SizeCache cache = SizeCache::Memo) {
    using namespace cgal_mesh;
    CgalMesh out;
    const double sine = std::sin(min_angle * 3.14159265358979323846 / 180);
    const double b = sine * sine;  // = 1 / (4 B^2) with B = 1 / (2 sin theta)
    if (!size.bounded() || size.is_uniform()) {
        mesh_into(out.plain, xy, segments, holes,
                  UniformCriteria(b, size.bounded() ? size(0, 0) : 0.0));
    } else if (cache == SizeCache::None) {
        mesh_into(out.plain, xy, segments, holes, FieldCriteria<Cdt, false>(b, &size));
    } else {
        mesh_into(out.memo, xy, segments, holes, FieldCriteria<MemoCdt, true>(b, &size));
    }
    return out;
}

namespace cgal_mesh {
template <class Tr>
triangulation::Triangulation2 mesh_triangulation(const MeshOf<Tr>& mesh,
                                                 std::vector<std::uint32_t>& pieces) {
    triangulation::Triangulation2 out;
    std::unordered_map<const void*, std::uint32_t> index;
    auto number = [&](typename Tr::Vertex_handle v) {
        const auto [it, added] = index.emplace(&*v, static_cast<std::uint32_t>(out.xy.size() / 2));
        if (added) {
            out.xy.push_back(v->point().x());
            out.xy.push_back(v->point().y());
        }
        return it->second;
    };
    for (const auto v : mesh.input) number(v);
    std::unordered_map<const void*, std::uint32_t> face_index;
    for (auto f = mesh.cdt->finite_faces_begin(); f != mesh.cdt->finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        face_index.emplace(&*f, static_cast<std::uint32_t>(out.triangles.size() / 3));
        for (int k = 0; k < 3; ++k) out.triangles.push_back(number(f->vertex(k)));
    }
    out.neighbors.assign(out.triangles.size(), triangulation::kNone);
    out.constrained.assign(out.triangles.size(), 0);
    for (auto f = mesh.cdt->finite_faces_begin(); f != mesh.cdt->finite_faces_end(); ++f) {
        if (!f->is_in_domain()) continue;
        const std::uint32_t t = face_index.at(&*f);
        for (int k = 0; k < 3; ++k) {
            // Our edge k runs v[k] -> v[k+1]: CGAL's edge (f, k+2), opposite v[k+2].
            const int opposite = (k + 2) % 3;
            const auto n = f->neighbor(opposite);
            if (const auto it = face_index.find(&*n); it != face_index.end())
                out.neighbors[3 * t + k] = it->second;
            out.constrained[3 * t + k] =
                mesh.cdt->is_constrained(typename Tr::Edge(f, opposite)) ? 1 : 0;
        }
    }
    for (auto e = mesh.cdt->finite_edges_begin(); e != mesh.cdt->finite_edges_end(); ++e) {
        if (!mesh.cdt->is_constrained(*e)) continue;
        pieces.push_back(number(e->first->vertex(Tr::ccw(e->second))));
        pieces.push_back(number(e->first->vertex(Tr::cw(e->second))));
    }
    return out;
}
}  // namespace cgal_mesh

/// The triangles in CGAL's domain as a Triangulation2 (input vertices first), and its
/// constrained edges as pieces (2·#P).
inline triangulation::Triangulation2 cgal_mesh_triangulation(const CgalMesh& mesh,
                                                             std::vector<std::uint32_t>& pieces) {
    return mesh.memo.cdt ? cgal_mesh::mesh_triangulation(mesh.memo, pieces)
                         : cgal_mesh::mesh_triangulation(mesh.plain, pieces);
}

}  // namespace exactmesh::testing
