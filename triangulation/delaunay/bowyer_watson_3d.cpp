// SPDX-License-Identifier: MIT
// Bowyer-Watson 3D (see bowyer_watson_3d.hpp).
#include "triangulation/delaunay/bowyer_watson_3d.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

#include "triangulation/delaunay/bowyer_watson_3d_cavity.hpp"
#include "triangulation/delaunay/delaunay_3d_core.hpp"
#include "triangulation/delaunay/parallel_bowyer_watson_3d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The whole mesh as the region of a CavityInserter3: the core's conflict test, counters and
/// free list; slots are added when the list runs short.
struct WholeMesh3 {
    static constexpr bool kPartitioned = false;
    detail::Delaunay3Core& core;
    TetIdx& last_tet;

    bool owns(TetIdx) const { return true; }
    detail::ConflictTest3 tests() { return core.tests(); }
    Delaunay3Counters& counters() { return core.counters; }
    std::vector<TetIdx>& free_tets() { return core.mesh.free_tets; }
    bool make_room(std::size_t faces) {
        while (core.mesh.free_tets.size() < faces) core.mesh.add_slots();
        return true;
    }
};

/// The sequential insertion of insert_incrementally: the cavity inserter on the whole mesh.
class CavityInserter {
  public:
    explicit CavityInserter(detail::Delaunay3Core& core)
        : region_{core, core.last_tet}, inserter_(region_, core.mesh) {}

    void insert(VertIdx p, const detail::Location3& where) { inserter_.insert(p, where.tet); }

  private:
    WholeMesh3 region_;
    detail::CavityInserter3<WholeMesh3> inserter_;
};

}  // namespace

Delaunay3Result bowyer_watson_3d(std::span<const double> xyz, const Delaunay3Options& options) {
    // The parallel construction partitions the BRIO rounds; other orders run sequentially.
    if (options.threads != 1 && options.order == InsertionOrder::Brio) {
        const unsigned threads = resolve_thread_count(options.threads);
        if (threads > 1) return parallel_bowyer_watson_3d(xyz, options, threads);
    }
    return detail::insert_incrementally<CavityInserter>(xyz, options);
}

}  // namespace exactmesh::triangulation
