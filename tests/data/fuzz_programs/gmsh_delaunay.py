#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Gmsh's point-set Delaunay (gmsh.model.mesh.triangulate in 2D, gmsh.model.mesh.tetrahedralize in
# 3D; Debian 12's python3-gmsh, Gmsh 4.8.4) as a program for `exactmesh fuzz --command` (issue
# 16): reads a Triangle .node (2D) or TetGen .node (3D), writes Gmsh's cells as a Triangle or
# TetGen .ele in the input's numbering (Gmsh returns node tags numbered from 1 in the input's
# order, so no matching is needed). Gmsh does not orient its triangles consistently: run with
# --orient, which orients each cell exactly before the check (what is judged is Gmsh's choice of
# cells, never this wrapper's).
#   exactmesh fuzz --kind points2d --orient --command '/usr/bin/python3 gmsh_delaunay.py {in} {out}'
"""Usage: gmsh_delaunay.py IN.node OUT.ele"""
import sys

import gmsh

import node_file


def read_node(path):
    points, dimension, first = node_file.read_node(path)
    return [v for point in points for v in point], dimension, first


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    coordinates, dimension, first = read_node(argv[1])
    gmsh.initialize(readConfigFiles=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("General.Verbosity", 0)
        if dimension == 2:
            tags = gmsh.model.mesh.triangulate(coordinates)
        else:
            tags = gmsh.model.mesh.tetrahedralize(coordinates)
    finally:
        gmsh.finalize()
    corners = dimension + 1
    tags = [int(t) for t in tags]
    if len(tags) % corners:
        sys.exit(f"gmsh returned {len(tags)} node tags, not a multiple of {corners}")
    with open(argv[2], "w", encoding="ascii") as ele:
        ele.write(f"{len(tags) // corners} {corners} 0\n")
        for number in range(len(tags) // corners):
            cell = tags[corners * number:corners * (number + 1)]
            ele.write(f"{number + first} " + " ".join(str(t - 1 + first) for t in cell) + "\n")


if __name__ == "__main__":
    main(sys.argv)
