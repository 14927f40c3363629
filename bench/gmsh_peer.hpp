// SPDX-License-Identifier: MIT
// Gmsh as a peer of the 2D benchmarks (mesh_bench, stretched_bench): a .geo of a PSLG, the `gmsh`
// program run on it with one thread, its "Done meshing 2D" CPU time read from its log (file
// reading, 1D meshing of the segments and writing excluded), and its triangles read back from
// the ASCII MSH 2.2 file it writes, oriented counter-clockwise.
#pragma once

#include <algorithm>
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

#include "triangulation/mesh/mesh2.hpp"

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

/// Reads the triangles (element type 2) of an ASCII MSH 2.2 file, oriented counter-clockwise.
inline void read_msh2(const std::filesystem::path& file, GmshMesh& mesh) {
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
                index[id] = static_cast<triangulation::VertIdx>(mesh.xy.size() / 2);
                mesh.xy.push_back(x);
                mesh.xy.push_back(y);
            }
        } else if (line == "$Elements") {
            std::size_t count = 0;
            in >> count;
            std::getline(in, line);
            for (std::size_t i = 0; i < count; ++i) {
                std::getline(in, line);
                std::istringstream fields(line);
                long id, type, tags;
                fields >> id >> type >> tags;
                for (long k = 0; k < tags; ++k) fields >> id;
                if (type != 2) continue;
                long a, b, c;
                fields >> a >> b >> c;
                const triangulation::VertIdx v[3] = {index.at(a), index.at(b), index.at(c)};
                const double* p = &mesh.xy[2 * v[0]];
                const double* q = &mesh.xy[2 * v[1]];
                const double* r = &mesh.xy[2 * v[2]];
                const bool ccw = (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]) > 0;
                mesh.triangles.insert(mesh.triangles.end(),
                                      {v[0], ccw ? v[1] : v[2], ccw ? v[2] : v[1]});
            }
        }
    }
}

/// Runs `gmsh` on the .geo text in `dir` (2D, one thread, MSH 2.2); throws std::runtime_error
/// with the log's error lines (or its last line) when it fails.
inline GmshMesh run_gmsh_geo(const std::string& geo_text, const std::filesystem::path& dir) {
    namespace fs = std::filesystem;
    const fs::path geo = dir / "domain.geo", msh = dir / "domain.msh", log = dir / "gmsh.log";
    std::ofstream(geo) << geo_text;
    const std::string command = "gmsh '" + geo.string() + "' -2 -nt 1 -format msh2 -o '" +
                                msh.string() + "' -v 4 > '" + log.string() + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
        std::ifstream text(log);
        std::string line, errors, last;
        while (std::getline(text, line)) {
            if (line.find("Error") != std::string::npos)
                errors += (errors.empty() ? "" : " | ") + line;
            if (!line.empty()) last = line;
        }
        // No error line (a crash): the log's last line says where it stopped.
        if (errors.empty()) errors = "no error line; the log ends with: " + last;
        throw std::runtime_error("gmsh failed: " + errors.substr(0, 600));
    }
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

inline bool have_gmsh() {
    return std::system("gmsh --version > /dev/null 2>&1") == 0;
}

}  // namespace exactmesh::bench
