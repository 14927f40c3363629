// SPDX-License-Identifier: MIT
// CGAL's 2D Delaunay refinement (Delaunay_mesher_2 on a Constrained_Delaunay_triangulation_2
// with Epick), as the peer of generators/delaunay_refinement_2d in the differential tests and
// in bench/mesh_bench: the same PSLG, the same angle bound (CGAL's shape bound is sin^2 of the
// smallest angle, i.e. B = 1 / (2 sin theta) squared and inverted: b = 1 / (4 B^2)) and the same
// size criterion (every edge of a triangle at most the size at its midpoint: CGAL's own
// Delaunay_mesh_size_criteria_2 when the size is uniform, else the same criteria class with the
// size function evaluated where ours evaluates it). Holes are CGAL seeds (mark = false); the
// unbounded component is outside, as ours. The result converts to a Triangulation2 (input
// vertices first, in input order) with its constrained edges as pieces, for the same checks.
// Test and bench support: CGAL appears only in tests/ and bench/.
#pragma once

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "generators/size_function.hpp"
#include "triangulation/triangulation_2d.hpp"

namespace exactmesh::testing {

namespace cgal_mesh {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using Fb = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using UniformCriteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

/// Delaunay_mesh_size_criteria_2 with a size function: the size ratio is the largest
/// |edge|^2 / s(midpoint)^2 over the triangle's edges (1 is the bound), the shape CGAL's.
class FieldCriteria {
public:
    using Quality = UniformCriteria::Quality;
    FieldCriteria() = default;
    FieldCriteria(double sine2_bound, const generators::SizeFunction* size) : bound_(sine2_bound), size_(size) {}

    class Is_bad {
    public:
        Is_bad(double bound, const generators::SizeFunction* size) : bound_(bound), size_(size) {}
        CGAL::Mesh_2::Face_badness operator()(const Quality q) const {
            if (q.size() > 1) return CGAL::Mesh_2::IMPERATIVELY_BAD;
            return q.sine() < bound_ ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
        }
        CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& fh, Quality& q) const {
            const Kernel::Point_2* p[3] = {&fh->vertex(0)->point(), &fh->vertex(1)->point(), &fh->vertex(2)->point()};
            double length2[3], ratio = 0;
            for (int k = 0; k < 3; ++k) {
                const Kernel::Point_2& a = *p[(k + 1) % 3];
                const Kernel::Point_2& b = *p[(k + 2) % 3];
                const double dx = b.x() - a.x(), dy = b.y() - a.y();
                length2[k] = dx * dx + dy * dy;
                if (size_ != nullptr && size_->bounded()) {
                    const double s = (*size_)(0.5 * (a.x() + b.x()), 0.5 * (a.y() + b.y()));
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
        double bound_;
        const generators::SizeFunction* size_;
    };
    Is_bad is_bad_object() const { return Is_bad(bound_, size_); }

private:
    double bound_ = 0.125;
    const generators::SizeFunction* size_ = nullptr;
};
}  // namespace cgal_mesh

struct CgalMesh {
    std::unique_ptr<cgal_mesh::Cdt> cdt;
    std::vector<cgal_mesh::Cdt::Vertex_handle> input;  ///< the input vertices, in input order
};

/// Meshes the PSLG with CGAL: insert the points, the constraints, then refine (the timed part
/// of the bench). min_angle in degrees; size uniform (CGAL's own criteria) or any (FieldCriteria).
inline CgalMesh cgal_delaunay_mesh_2d(std::span<const double> xy, std::span<const std::uint32_t> segments,
                                      std::span<const double> holes, double min_angle,
                                      const generators::SizeFunction& size) {
    using namespace cgal_mesh;
    CgalMesh out;
    out.cdt = std::make_unique<Cdt>();
    Cdt& cdt = *out.cdt;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) out.input.push_back(cdt.insert(Kernel::Point_2(xy[i], xy[i + 1])));
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
        if (out.input[segments[s]] != out.input[segments[s + 1]]) {
            cdt.insert_constraint(out.input[segments[s]], out.input[segments[s + 1]]);
        }
    }
    std::list<Kernel::Point_2> seeds;
    for (std::size_t h = 0; h + 1 < holes.size(); h += 2) seeds.emplace_back(holes[h], holes[h + 1]);
    const double sine = std::sin(min_angle * 3.14159265358979323846 / 180);
    const double b = sine * sine;  // = 1 / (4 B^2) with B = 1 / (2 sin theta)
    if (!size.bounded() || size.is_uniform()) {
        CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(),
                                     UniformCriteria(b, size.bounded() ? size(0, 0) : 0.0));
    } else {
        CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), FieldCriteria(b, &size));
    }
    return out;
}

/// The triangles in CGAL's domain as a Triangulation2 (input vertices first), and its
/// constrained edges as pieces (2·#P).
inline triangulation::Triangulation2 cgal_mesh_triangulation(const CgalMesh& mesh, std::vector<std::uint32_t>& pieces) {
    using namespace cgal_mesh;
    triangulation::Triangulation2 out;
    std::unordered_map<const void*, std::uint32_t> index;
    auto number = [&](Cdt::Vertex_handle v) {
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
            if (const auto it = face_index.find(&*n); it != face_index.end()) out.neighbors[3 * t + k] = it->second;
            out.constrained[3 * t + k] = mesh.cdt->is_constrained(Cdt::Edge(f, opposite)) ? 1 : 0;
        }
    }
    for (auto e = mesh.cdt->finite_edges_begin(); e != mesh.cdt->finite_edges_end(); ++e) {
        if (!mesh.cdt->is_constrained(*e)) continue;
        pieces.push_back(number(e->first->vertex(Cdt::ccw(e->second))));
        pieces.push_back(number(e->first->vertex(Cdt::cw(e->second))));
    }
    return out;
}

}  // namespace exactmesh::testing
