#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A triangulator writing another format than .ele, for the tests of `exactmesh fuzz --command
# ... --output {dir}/output.vtu` (tests/cli): runs `EXACTMESH SUBCOMMAND IN -o OUT.ele
# [OPTIONS...]` (triangulate, cdt or tetrahedralize) and writes its mesh to OUT by meshio in the
# format OUT's extension names (.vtu, .msh, ...): the points of OUT.node (or IN), the triangles
# or tetrahedra in meshio's corner order, and for cdt the constrained pieces of OUT.poly as line
# cells. With --drop-last the last cell is left out, so every input with a cell fails the exact
# check and minimizes to one cell, as with drop_last_cell.py.
"""Usage: meshio_output.py [--drop-last] EXACTMESH SUBCOMMAND IN OUT [OPTIONS...]"""
import os
import subprocess
import sys

import meshio
import numpy


def records(path):
    """The lines of a Triangle/TetGen file as lists of words, comments and blanks left out."""
    with open(path, encoding="ascii") as text:
        lines = (line.split("#", 1)[0].split() for line in text)
        return [words for words in lines if words]


def main(argv):
    drop_last = len(argv) > 1 and argv[1] == "--drop-last"
    if drop_last:
        argv = argv[:1] + argv[2:]
    if len(argv) < 5:
        sys.exit(__doc__)
    exactmesh, subcommand, path_in, path_out = argv[1:5]
    stem = os.path.splitext(path_out)[0] + ".exactmesh"
    subprocess.run([exactmesh, subcommand, path_in, "-o", stem + ".ele"] + argv[5:], check=True,
                   stdout=subprocess.DEVNULL)
    node = records(stem + ".node" if os.path.exists(stem + ".node") else path_in)
    count, dimension, first = int(node[0][0]), int(node[0][1]), int(node[1][0])
    points = numpy.zeros((count, 3))
    for k in range(count):
        points[k, :dimension] = [float(x) for x in node[1 + k][1:1 + dimension]]
    ele = records(stem + ".ele")
    corners = int(ele[0][1])
    cells = [[int(v) - first for v in line[1:1 + corners]] for line in ele[1:1 + int(ele[0][0])]]
    if corners == 4:
        # TetGen's corners (0, 1, 2, 3) are VTK's and Gmsh's (1, 0, 3, 2): the same orientation.
        cells = [[c[1], c[0], c[3], c[2]] for c in cells]
    if drop_last:
        cells = cells[:-1]
    blocks = []
    if cells:
        blocks.append(("tetra" if corners == 4 else "triangle", numpy.array(cells)))
    if os.path.exists(stem + ".poly"):
        poly = records(stem + ".poly")
        at = 1 + int(poly[0][0])
        pieces = [[int(line[1]) - first, int(line[2]) - first]
                  for line in poly[at + 1:at + 1 + int(poly[at][0])]]
        if pieces:
            blocks.append(("line", numpy.array(pieces)))
    meshio.write(path_out, meshio.Mesh(points, blocks))


if __name__ == "__main__":
    main(sys.argv)
