#!/usr/bin/python3
"""A unit cube with one thin box-shaped hole (sides from 0.8 down to 1e-4), its corners at
midpoint-like coordinates (so that the hole's facet planes pass through the points refinement
puts on the cube's edges and facets), turned by a random rotation (one seed in ten unturned),
scaled by 2^E; TetGen .poly form as tests/data/rotated/needle_hole_1.poly; the issue 15 campaign
of README. Usage: scripts/rotated_holes.py SEED SCALE_EXPONENT OUT.poly (numpy: /usr/bin/python3)."""
import os
import sys

import numpy as np
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rotated_cubes import random_rotation


def box_facets(base):
    corner = lambda x, y, z: base + 1 + x + 2 * y + 4 * z
    return [[corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0)],
            [corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)],
            [corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)],
            [corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)],
            [corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0)],
            [corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)]]


def make(seed, exponent):
    rng = np.random.default_rng(seed)
    length = rng.choice([0.8, 0.5, 0.25, 0.75])
    width = rng.choice([1e-3, 1e-2, 0.0625, 2.0**-10])
    height = rng.choice([1e-3, 1e-2, 2.0**-10, 1e-4])
    origin = np.array([rng.choice([0.1, 0.125, 0.25, 0.5 - length / 2]),
                       rng.choice([0.5, 0.25, 0.375, 0.5 - width / 2]),
                       rng.choice([0.5, 0.25, 0.5 - height / 2])])
    sides = np.array([length, width, height])
    order = rng.permutation(3)
    sides, origin = sides[order], np.minimum(origin[order], 1 - sides[order] - 0.05)
    unit = [np.array((x, y, z), dtype=float) for z in (0, 1) for y in (0, 1) for x in (0, 1)]
    rotation = random_rotation(rng) if rng.random() < 0.9 else np.eye(3)
    scale = 2.0**exponent
    points = [scale * (rotation @ p) for p in unit] + \
             [scale * (rotation @ (origin + sides * p)) for p in unit]
    hole = scale * (rotation @ (origin + sides / 2))
    lines = [f"# scripts/rotated_holes.py {seed} {exponent}: hole sides {sides.tolist()} at "
             f"{origin.tolist()}", "16 3 0 0"]
    lines += [f"{k + 1} {p[0]!r} {p[1]!r} {p[2]!r}" for k, p in enumerate(points)]
    facets = [(f, 1) for f in box_facets(0)] + [(f, 2) for f in box_facets(8)]
    lines.append(f"{len(facets)} 1")
    for facet, marker in facets:
        lines += [f"1 0 {marker}", f"4 {' '.join(map(str, facet))}"]
    lines += ["1", f"1 {hole[0]!r} {hole[1]!r} {hole[2]!r}", "0"]
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    with open(sys.argv[3], "w") as out:
        out.write(make(int(sys.argv[1]), int(sys.argv[2])))
