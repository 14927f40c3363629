// SPDX-License-Identifier: MIT
// Gmsh as a peer of the 2D benchmarks (mesh_bench, stretched_bench): a .geo of a PSLG, the `gmsh`
// program run on it with one thread, its "Done meshing 2D" CPU time read from its log (file
// reading, 1D meshing of the segments and writing excluded), and its triangles read back from
// the ASCII MSH 2.2 file it writes, oriented counter-clockwise. And of tetmesh_bench: a .geo of
// a 3D PLC (plane surfaces, surface loops, one volume), `gmsh -3`, the CPU times of its 2D
// meshing, its 3D meshing and its optimization read apart, and its tetrahedra read back,
// positively oriented by exactmesh's orient3d.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_support.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/mesh/mesh2.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::bench {

/// Points, Lines, one Curve Loop per closed chain of segments (the loop with the largest
/// bounding box the outer one, the others holes) and Plane Surface(1); no size and no options.
inline std::string gmsh_pslg_geo(const std::vector<double>& xy,
                                 const std::vector<triangulation::VertIdx>& seg) {
    const std::size_t n = xy.size() / 2, m = seg.size() / 2;
    std::ostringstream geo;
    geo.precision(17);
    for (std::size_t v = 0; v < n; ++v)
        geo << "Point(" << v + 1 << ") = {" << xy[2 * v] << ", " << xy[2 * v + 1] << ", 0};\n";
    for (std::size_t s = 0; s < m; ++s)
        geo << "Line(" << s + 1 << ") = {" << seg[2 * s] + 1 << ", " << seg[2 * s + 1] + 1
            << "};\n";
    std::vector<std::vector<std::size_t>> at(n);
    for (std::size_t s = 0; s < m; ++s) {
        at[seg[2 * s]].push_back(s);
        at[seg[2 * s + 1]].push_back(s);
    }
    std::vector<bool> used(m, false);
    std::vector<std::vector<long>> loops;
    std::vector<double> extents;
    for (std::size_t first = 0; first < m; ++first) {
        if (used[first]) continue;
        std::vector<long> loop;
        double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
        std::size_t s = first;
        std::uint32_t from = seg[2 * s];
        while (true) {
            used[s] = true;
            const bool forward = seg[2 * s] == from;
            loop.push_back(forward ? static_cast<long>(s + 1) : -static_cast<long>(s + 1));
            const std::uint32_t to = forward ? seg[2 * s + 1] : seg[2 * s];
            x0 = std::min(x0, xy[2 * to]), x1 = std::max(x1, xy[2 * to]);
            y0 = std::min(y0, xy[2 * to + 1]), y1 = std::max(y1, xy[2 * to + 1]);
            std::size_t next = m;
            for (const std::size_t t : at[to]) {
                if (!used[t]) next = t;
            }
            if (next == m) break;
            s = next;
            from = to;
        }
        loops.push_back(std::move(loop));
        extents.push_back((x1 - x0) * (y1 - y0));
    }
    std::size_t outer = 0;
    for (std::size_t k = 1; k < loops.size(); ++k) {
        if (extents[k] > extents[outer]) outer = k;
    }
    std::vector<std::size_t> order{outer};
    for (std::size_t k = 0; k < loops.size(); ++k) {
        if (k != outer) order.push_back(k);
    }
    for (std::size_t k = 0; k < order.size(); ++k) {
        geo << "Curve Loop(" << k + 1 << ") = {";
        for (std::size_t i = 0; i < loops[order[k]].size(); ++i)
            geo << (i ? ", " : "") << loops[order[k]][i];
        geo << "};\n";
    }
    geo << "Plane Surface(1) = {";
    for (std::size_t k = 0; k < order.size(); ++k) geo << (k ? ", " : "") << k + 1;
    geo << "};\n";
    return geo.str();
}

struct GmshMesh {
    double cpu_seconds = 0;
    std::vector<double> xy;
    std::vector<triangulation::VertIdx> triangles;
};

/// Reads an ASCII MSH 2.2 file: each node's coordinates to `node(x, y, z)` in file order (its
/// index is the number of nodes before it), then each element of `type` (2 triangle, 4
/// tetrahedron) to `element(v)`, v its `corners` node indices.
template <class Node, class Element>
void read_msh2_elements(const std::filesystem::path& file, long type, std::size_t corners,
                        Node node, Element element) {
    std::ifstream in(file);
    std::string line;
    std::map<long, triangulation::VertIdx> index;
    while (std::getline(in, line)) {
        if (line == "$Nodes") {
            std::size_t count = 0;
            in >> count;
            for (std::size_t i = 0; i < count; ++i) {
                long id;
                double x, y, z;
                in >> id >> x >> y >> z;
                index[id] = static_cast<triangulation::VertIdx>(i);
                node(x, y, z);
            }
        } else if (line == "$Elements") {
            std::size_t count = 0;
            in >> count;
            std::getline(in, line);
            std::vector<triangulation::VertIdx> v(corners);
            for (std::size_t i = 0; i < count; ++i) {
                std::getline(in, line);
                std::istringstream fields(line);
                long id, element_type, tags;
                fields >> id >> element_type >> tags;
                for (long k = 0; k < tags; ++k) fields >> id;
                if (element_type != type) continue;
                for (std::size_t k = 0; k < corners; ++k) {
                    long n;
                    fields >> n;
                    v[k] = index.at(n);
                }
                element(v);
            }
        }
    }
}

/// Reads the triangles (element type 2) of an ASCII MSH 2.2 file, oriented counter-clockwise.
inline void read_msh2(const std::filesystem::path& file, GmshMesh& mesh) {
    read_msh2_elements(
        file, 2, 3,
        [&mesh](double x, double y, double) {
            mesh.xy.push_back(x);
            mesh.xy.push_back(y);
        },
        [&mesh](const std::vector<triangulation::VertIdx>& v) {
            const double* p = &mesh.xy[2 * v[0]];
            const double* q = &mesh.xy[2 * v[1]];
            const double* r = &mesh.xy[2 * v[2]];
            const bool ccw = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0;
            mesh.triangles.insert(mesh.triangles.end(),
                                  {v[0], ccw ? v[1] : v[2], ccw ? v[2] : v[1]});
        });
}

/// Throws std::runtime_error with the error lines of gmsh's log (or its last line).
[[noreturn]] inline void throw_gmsh_failure(const std::filesystem::path& log) {
    std::ifstream text(log);
    std::string line, errors, last;
    while (std::getline(text, line)) {
        if (line.find("Error") != std::string::npos) errors += (errors.empty() ? "" : " | ") + line;
        if (!line.empty()) last = line;
    }
    // No error line (a crash): the log's last line says where it stopped.
    if (errors.empty()) errors = "no error line; the log ends with: " + last;
    throw std::runtime_error("gmsh failed: " + errors.substr(0, 600));
}

/// Runs `gmsh` on the .geo text in `dir` (2D, one thread, MSH 2.2); throws std::runtime_error
/// with the log's error lines (or its last line) when it fails.
inline GmshMesh run_gmsh_geo(const std::string& geo_text, const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path geo = dir / "domain.geo", msh = dir / "domain.msh", log = dir / "gmsh.log";
    std::ofstream(geo) << geo_text;
    const std::string command = "gmsh '" + geo.string() + "' -2 -nt 1 -format msh2 -o '" +
                                msh.string() + "' -v 4 > '" + log.string() + "' 2>&1";
    if (std::system(command.c_str()) != 0) throw_gmsh_failure(log);
    GmshMesh mesh;
    std::ifstream text(log);
    std::string line;
    bool timed = false;
    while (std::getline(text, line)) {
        const auto at = line.find("Done meshing 2D (Wall ");
        const auto cpu = line.find("CPU ");
        if (at != std::string::npos && cpu != std::string::npos) {
            mesh.cpu_seconds = std::stod(line.substr(cpu + 4));
            timed = true;
        }
    }
    if (!timed)
        throw std::runtime_error("no 'Done meshing 2D' line from gmsh (see " + log.string() + ")");
    read_msh2(msh, mesh);
    return mesh;
}

/// A 3D PLC as a .geo: Points, one Line per polygon edge (shared by the facets that hold it),
/// a Curve Loop per polygon and a Plane Surface per facet (its first polygon the outer loop, the
/// others holes: the form of the sample domains, whose facets with several polygons have facet
/// hole points; a facet with several polygons and no hole point is refused), then one Surface
/// Loop per connected set of facets (sharing a vertex), the one with the largest bounding box
/// first, and Volume(1) = those loops (the others cavities). No size and no options.
inline std::string gmsh_plc_geo(const triangulation::Plc3& plc) {
    std::ostringstream geo;
    geo.precision(17);
    const std::size_t n = plc.vertex_count();
    for (std::size_t v = 0; v < n; ++v)
        geo << "Point(" << v + 1 << ") = {" << plc.xyz[3 * v] << ", " << plc.xyz[3 * v + 1] << ", "
            << plc.xyz[3 * v + 2] << "};\n";
    std::map<std::pair<std::uint32_t, std::uint32_t>, long> lines;
    std::vector<std::size_t> component(n);
    for (std::size_t v = 0; v < n; ++v) component[v] = v;
    auto find = [&](std::size_t v) {
        while (component[v] != v) v = component[v] = component[component[v]];
        return v;
    };
    long loop_count = 0;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        const triangulation::Facet3& facet = plc.facets[f];
        if (facet.polygons.size() > 1 && facet.holes.empty())
            throw std::runtime_error("gmsh_plc_geo: facet " + std::to_string(f) +
                                     " has several polygons and no hole point");
        std::vector<long> loops;
        for (const auto& polygon : facet.polygons) {
            std::ostringstream loop;
            for (std::size_t k = 0; k < polygon.size(); ++k) {
                const std::uint32_t a = polygon[k], b = polygon[(k + 1) % polygon.size()];
                component[find(a)] = find(b);
                const auto key = std::minmax(a, b);
                auto [at, added] = lines.emplace(key, static_cast<long>(lines.size() + 1));
                if (added)
                    geo << "Line(" << at->second << ") = {" << key.first + 1 << ", "
                        << key.second + 1 << "};\n";
                loop << (k ? ", " : "") << (a < b ? at->second : -at->second);
            }
            geo << "Curve Loop(" << ++loop_count << ") = {" << loop.str() << "};\n";
            loops.push_back(loop_count);
        }
        geo << "Plane Surface(" << f + 1 << ") = {";
        for (std::size_t k = 0; k < loops.size(); ++k) geo << (k ? ", " : "") << loops[k];
        geo << "};\n";
    }
    std::map<std::size_t, std::vector<std::size_t>> shells;  // root vertex -> facets
    std::map<std::size_t, std::array<double, 6>> boxes;
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        const std::size_t root = find(plc.facets[f].polygons.front().front());
        shells[root].push_back(f);
        auto [box, added] = boxes.emplace(
            root,
            std::array<double, 6>{INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY});
        for (const auto& polygon : plc.facets[f].polygons) {
            for (const std::uint32_t v : polygon) {
                for (int c = 0; c < 3; ++c) {
                    box->second[c] = std::min(box->second[c], plc.xyz[3 * v + c]);
                    box->second[c + 3] = std::max(box->second[c + 3], plc.xyz[3 * v + c]);
                }
            }
        }
    }
    std::vector<std::size_t> order;
    for (const auto& [root, facets] : shells) order.push_back(root);
    auto extent = [&](std::size_t root) {
        const auto& b = boxes.at(root);
        return (b[3] - b[0]) + (b[4] - b[1]) + (b[5] - b[2]);
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return extent(a) > extent(b); });
    for (std::size_t k = 0; k < order.size(); ++k) {
        geo << "Surface Loop(" << k + 1 << ") = {";
        const auto& facets = shells.at(order[k]);
        for (std::size_t i = 0; i < facets.size(); ++i) geo << (i ? ", " : "") << facets[i] + 1;
        geo << "};\n";
    }
    geo << "Volume(1) = {";
    for (std::size_t k = 0; k < order.size(); ++k) geo << (k ? ", " : "") << k + 1;
    geo << "};\n";
    return geo.str();
}

struct GmshMesh3 {
    double max_rss_bytes = 0;         ///< gmsh's largest resident set (run_shell_command)
    double cpu_seconds_2d = 0;        ///< "Done meshing 2D": the surface mesh
    double cpu_seconds_3d = 0;        ///< "Done meshing 3D": Delaunay, recovery, refinement
    double cpu_seconds_optimize = 0;  ///< "Done optimizing mesh" (0 with Mesh.Optimize = 0)
    triangulation::Tetrahedralization3 mesh;
};

/// The CPU seconds of the log's last line containing `done` (the form "... (Wall w, CPU c)"),
/// or NaN.
inline double gmsh_log_cpu(const std::filesystem::path& log, const std::string& done) {
    std::ifstream text(log);
    std::string line;
    double seconds = std::nan("");
    while (std::getline(text, line)) {
        const auto at = line.find(done);
        const auto cpu = line.find("CPU ", at == std::string::npos ? 0 : at);
        if (at != std::string::npos && cpu != std::string::npos)
            seconds = std::stod(line.substr(cpu + 4));
    }
    return seconds;
}

/// Reads the tetrahedra (element type 4) of an ASCII MSH 2.2 file, each positive by orient3d
/// (a zero-volume one is kept as written).
inline triangulation::Tetrahedralization3 read_msh2_tets(const std::filesystem::path& file) {
    triangulation::Tetrahedralization3 mesh;
    read_msh2_elements(
        file, 4, 4,
        [&mesh](double x, double y, double z) {
            mesh.xyz.insert(mesh.xyz.end(), {x, y, z});
        },
        [&mesh](std::vector<triangulation::VertIdx> v) {
            if (predicates::orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                     mesh.point(v[3])) == predicates::Sign::Negative)
                std::swap(v[2], v[3]);
            mesh.tets.insert(mesh.tets.end(), v.begin(), v.end());
        });
    return mesh;
}

/// Runs `gmsh -3` (one thread, MSH 2.2) on the .geo text in `dir` (its options included);
/// throws std::runtime_error with the log's error lines when it fails or reports no 3D time.
inline GmshMesh3 run_gmsh_geo_3d(const std::string& geo_text, const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path geo = dir / "domain.geo", msh = dir / "domain.msh", log = dir / "gmsh.log";
    std::ofstream(geo) << geo_text;
    const std::string command = "gmsh '" + geo.string() + "' -3 -nt 1 -format msh2 -o '" +
                                msh.string() + "' -v 4 > '" + log.string() + "' 2>&1";
    const ProcessRun run = run_shell_command(command);
    if (!run.ok) throw_gmsh_failure(log);
    GmshMesh3 out;
    out.max_rss_bytes = run.max_rss_bytes;
    out.cpu_seconds_2d = gmsh_log_cpu(log, "Done meshing 2D (");
    out.cpu_seconds_3d = gmsh_log_cpu(log, "Done meshing 3D (");
    out.cpu_seconds_optimize = gmsh_log_cpu(log, "Done optimizing mesh (");
    if (std::isnan(out.cpu_seconds_optimize)) out.cpu_seconds_optimize = 0;
    if (std::isnan(out.cpu_seconds_3d)) throw_gmsh_failure(log);
    out.mesh = read_msh2_tets(msh);
    return out;
}

inline bool have_gmsh() {
    return std::system("gmsh --version > /dev/null 2>&1") == 0;
}

}  // namespace exactmesh::bench
