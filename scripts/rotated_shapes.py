#!/usr/bin/python3
"""Rotated polyhedra with 0-4 free vertices inside, on facets and on edges before the rotation
(rounded to doubles after it: an ulp off them): an L-shaped prism (a reflex edge), a wedge prism
(a 45-degree dihedral angle), a regular hexagonal prism (cocircular facet corners), two unit
boxes sharing a facet (an internal facet); the issue 15 campaign of README (Known gaps).
Usage: scripts/rotated_shapes.py KIND SEED SCALE_EXPONENT OUT.poly, KIND one of L, wedge, hex,
twobox (numpy: /usr/bin/python3)."""
import os
import sys

import numpy as np
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rotated_cubes import random_rotation

def prism(poly2d, h=1.0):
    n = len(poly2d)
    pts = [(x, y, 0.0) for x, y in poly2d] + [(x, y, h) for x, y in poly2d]
    facets = [list(range(n, 0, -1)), list(range(n + 1, 2 * n + 1))]
    for i in range(n):
        j = (i + 1) % n
        facets.append([i + 1, j + 1, j + 1 + n, i + 1 + n])
    return pts, facets

def shape(kind):
    if kind == 'L':
        return prism([(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)])
    if kind == 'wedge':
        return prism([(0, 0), (1, 0), (1, 1)])
    if kind == 'hex':
        return prism([(np.cos(a), np.sin(a)) for a in np.arange(6) * np.pi / 3])
    if kind == 'twobox':
        pts = [(x, y, z) for z in (0, 1, 2) for y in (0, 1) for x in (0, 1)]
        idx = lambda x, y, z: 1 + x + 2 * y + 4 * z
        facets = []
        for z in (0, 1, 2):
            facets.append([idx(0,0,z), idx(1,0,z), idx(1,1,z), idx(0,1,z)])
        for z in (0, 1):
            facets.append([idx(0,0,z), idx(1,0,z), idx(1,0,z+1), idx(0,0,z+1)])
            facets.append([idx(1,0,z), idx(1,1,z), idx(1,1,z+1), idx(1,0,z+1)])
            facets.append([idx(1,1,z), idx(0,1,z), idx(0,1,z+1), idx(1,1,z+1)])
            facets.append([idx(0,1,z), idx(0,0,z), idx(0,0,z+1), idx(0,1,z+1)])
        return pts, facets

def free_point(rng, pts, facets, kind):
    pts = np.array(pts, float)
    if kind == 'inside':  # the centroid, jittered (inside each of the four shapes)
        c = pts.mean(axis=0)
        return c + rng.uniform(-0.1, 0.1, 3)
    f = facets[rng.integers(len(facets))]
    if kind == 'facet':
        rng.dirichlet(np.ones(len(f)) * 2)  # an unused draw, kept: the campaign's seeds
        # a point of the triangle of the facet's first three corners (inside the facet for
        # these shapes, the L's non-convex ends included)
        a, b, c = pts[f[0]-1], pts[f[1]-1], pts[f[2]-1]
        u, v = sorted(rng.uniform(0.05, 0.95, 2))
        return a * u + b * (v - u) + c * (1 - v)
    i = rng.integers(len(f)); a, b = pts[f[i]-1], pts[f[(i+1) % len(f)]-1]
    t = rng.uniform(0.03, 0.97)
    return a * (1 - t) + b * t

def make(kind, seed, e):
    rng = np.random.default_rng(seed)
    pts, facets = shape(kind)
    frees = [free_point(rng, pts, facets, str(rng.choice(['inside', 'facet', 'edge']))) for _ in range(int(rng.integers(0, 5)))]
    r = random_rotation(rng)
    allp = [np.array(p, float) for p in pts] + frees
    out = [f"{len(allp)} 3 0 0"]
    for i, p in enumerate(allp):
        q = (r @ p) * 2.0 ** e
        out.append(f"{i+1} " + " ".join(repr(float(x)) for x in q))
    out.append(f"{len(facets)} 0")
    for f in facets:
        out += ["1", f"{len(f)} " + " ".join(map(str, f))]
    out += ["0", "0"]
    return "\n".join(out) + "\n"

if __name__ == '__main__':
    kind, seed, e, path = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    open(path, 'w').write(make(kind, seed, e))
