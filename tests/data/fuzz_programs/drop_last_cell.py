#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# A deliberately wrong triangulator for the tests of `exactmesh fuzz --command` (tests/cli):
# runs `EXACTMESH SUBCOMMAND IN -o OUT [OPTIONS...]` (triangulate, cdt or tetrahedralize), then removes the
# last triangle or tetrahedron from OUT (a Triangle or TetGen .ele). Every input with at least
# one cell then fails the exact check; the smallest such input is one triangle (3 points) or one
# tetrahedron (4 points), which is what minimization must reach.
"""Usage: drop_last_cell.py EXACTMESH SUBCOMMAND IN OUT [OPTIONS...]"""
import subprocess
import sys


def main(argv):
    if len(argv) < 5:
        sys.exit(__doc__)
    exactmesh, subcommand, path_in, path_out = argv[1:5]
    subprocess.run([exactmesh, subcommand, path_in, "-o", path_out] + argv[5:], check=True,
                   stdout=subprocess.DEVNULL)
    with open(path_out, encoding="ascii") as ele:
        lines = [line for line in ele.read().splitlines()
                 if line.strip() and not line.lstrip().startswith("#")]
    header = lines[0].split()
    cells = lines[1:]
    if cells:
        cells = cells[:-1]
    header[0] = str(len(cells))
    with open(path_out, "w", encoding="ascii") as ele:
        ele.write(" ".join(header) + "\n")
        for line in cells:
            ele.write(line + "\n")


if __name__ == "__main__":
    main(sys.argv)
