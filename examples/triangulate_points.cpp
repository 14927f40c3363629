// SPDX-License-Identifier: MIT
// Example: the Delaunay triangulation of a point array, checked exactly. Reads "x y" lines from
// standard input (or makes a 100 x 100 grid of exactly cocircular points when there is none),
// prints the triangle count and the result of the exact Delaunay check.
#include <exactmesh/base/errors.hpp>
#include <exactmesh/base/version.hpp>
#include <exactmesh/triangulation/checks/check_2d.hpp>
#include <exactmesh/triangulation/delaunay/delaunay_2d.hpp>

#include <iostream>
#include <vector>

int main(int argc, char** argv) {
    namespace tri = exactmesh::triangulation;
    std::vector<double> xy;
    if (argc > 1 && std::string(argv[1]) == "-") {
        double x = 0, y = 0;
        while (std::cin >> x >> y) xy.insert(xy.end(), {x, y});
    } else {
        for (int i = 0; i < 100; ++i)
            for (int j = 0; j < 100; ++j) xy.insert(xy.end(), {double(i), double(j)});
    }
    try {
        const tri::Delaunay2Function build = tri::delaunay_2d_algorithm("green-sibson");
        const tri::Delaunay2Result result = build(xy, tri::Delaunay2Options{});
        const tri::CheckReport check = tri::check_delaunay_2d(xy, result.triangles);
        std::cout << "exactmesh " << exactmesh::kVersion << ": " << xy.size() / 2 << " points, "
                  << result.triangles.size() / 3
                  << " triangles, Delaunay check: " << (check.ok ? "ok" : check.problem) << '\n';
        return check.ok ? 0 : 1;
    } catch (const exactmesh::InputError& error) {
        std::cerr << "bad input: " << error.what() << '\n';
        return 2;
    }
}
