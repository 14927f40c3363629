#!/usr/bin/python3
"""Rotated unit cubes with 1-5 free vertices inside, on facets and on edges before the rotation
(rounded to doubles after it: an ulp off them), in TetGen .poly form as tests/data/rotated/
cube_*.poly; the issue 15 campaign of README (Known gaps).
Usage: scripts/rotated_cubes.py SEED SCALE_EXPONENT OUT.poly (numpy: /usr/bin/python3)."""
import sys
import numpy as np

CORNERS = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 0, 1), (1, 0, 1), (0, 1, 1), (1, 1, 1)]
FACETS = [(1, 2, 4, 3), (5, 7, 8, 6), (1, 5, 6, 2), (3, 4, 8, 7), (1, 3, 7, 5), (2, 6, 8, 4)]


def random_rotation(rng):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def free_vertex(rng, kind):
    p = rng.uniform(0.05, 0.95, size=3)
    if kind == "facet":
        p[rng.integers(3)] = float(rng.integers(2))
    elif kind == "edge":
        axes = rng.permutation(3)[:2]
        for a in axes:
            p[a] = float(rng.integers(2))
    return p


def cube(seed, scale_exponent, kinds=None):
    rng = np.random.default_rng(seed)
    r = random_rotation(rng)
    if kinds is None:
        n = int(rng.integers(1, 6))
        kinds = [str(rng.choice(["inside", "facet", "edge"])) for _ in range(n)]
    pts = [np.array(c, dtype=float) for c in CORNERS] + [free_vertex(rng, k) for k in kinds]
    scale = 2.0 ** scale_exponent
    out = [f"{len(pts)} 3 0 0"]
    for i, p in enumerate(pts):
        q = (r @ p) * scale  # rounded to doubles: an ulp off the facets and edges
        out.append(f"{i + 1} " + " ".join(repr(float(x)) for x in q))
    out.append(f"{len(FACETS)} 0")
    for f in FACETS:
        out += ["1", "4 " + " ".join(map(str, f))]
    out += ["0", "0"]
    return "\n".join(out) + "\n", kinds


if __name__ == "__main__":
    seed, exponent, path = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    text, kinds = cube(seed, exponent)
    open(path, "w").write(text)
    print(path, " ".join(kinds))
