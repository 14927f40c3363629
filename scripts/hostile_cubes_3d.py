#!/usr/bin/env python3
"""Axis-aligned unit cubes with free vertices in exact and odd places, and a campaign over them
(stop 46's 3D campaign; README Known gaps).

  scripts/hostile_cubes_3d.py DIR SEEDS
      writes DIR/cube_<seed>_s<e>.poly (seeds 0..SEEDS-1) at e = 0, 300 and -300 (the same bits
      scaled): the unit cube's six facets and free vertices exactly on facets and edges at
      multiples of 1/16, inside, a hair (1e-6 to 1e-15) outside a facet and inside another, and
      1e6 away, some twice, and half the time a corner again as a later vertex that one of
      its facets names instead (vertices at one point are merged, as TetGen merges them).
  scripts/hostile_cubes_3d.py --run DIR [EXACTMESH]
      meshes every DIR/*.poly with `exactmesh tetmesh` (Delaunay refinement --radius-edge 2,
      frontal and octree at size 0.25 x 2^e), checks each mesh with `exactmesh check`, prints
      a line per input, a SCALE MISMATCH line when an input's exit codes differ between its
      scales and a VOLUME MISMATCH line when the three meshes of an input at 2^0 hold
      different volumes (beyond 1e-9 relative). Exit 1 when a check fails, a run exits with
      neither 0 nor 2 (a clear refusal), or a mismatch is found.
"""
import collections
import glob
import math
import os
import random
import subprocess
import sys


def write(path, pts, facets, e):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 3 0 0\n")
        for i, p in enumerate(pts):
            f.write(f"{i + 1} " + " ".join(repr(math.ldexp(c, e)) for c in p) + "\n")
        f.write(f"{len(facets)} 0\n")
        for facet in facets:
            f.write(f"1\n{len(facet)} " + " ".join(str(v + 1) for v in facet) + "\n")
        f.write("0\n0\n")


def cube(r):
    pts = [(x, y, z) for z in (0.0, 1.0) for y in (0.0, 1.0) for x in (0.0, 1.0)]
    idx = lambda x, y, z: x + 2 * y + 4 * z
    facets = [[idx(0, 0, 0), idx(0, 1, 0), idx(1, 1, 0), idx(1, 0, 0)],
              [idx(0, 0, 1), idx(1, 0, 1), idx(1, 1, 1), idx(0, 1, 1)],
              [idx(0, 0, 0), idx(1, 0, 0), idx(1, 0, 1), idx(0, 0, 1)],
              [idx(0, 1, 0), idx(0, 1, 1), idx(1, 1, 1), idx(1, 1, 0)],
              [idx(0, 0, 0), idx(0, 0, 1), idx(0, 1, 1), idx(0, 1, 0)],
              [idx(1, 0, 0), idx(1, 1, 0), idx(1, 1, 1), idx(1, 0, 1)]]
    d = lambda: r.randint(1, 15) / 16
    free = []
    free += [(d(), d(), r.choice([0.0, 1.0])) for _ in range(r.randint(0, 3))]  # on a facet
    free += [(d(), r.choice([0.0, 1.0]), r.choice([0.0, 1.0])) for _ in range(r.randint(0, 2))]
    free += [(d(), d(), d()) for _ in range(r.randint(0, 2))]  # inside
    if r.random() < 0.5:
        free.append((1.0 + 10 ** -r.uniform(6, 15), d(), d()))  # a hair outside
    if r.random() < 0.5:
        free.append((d(), d(), 1e6))  # far outside
    if r.random() < 0.5:
        free.append((0.5, 0.5, 10 ** -r.uniform(6, 15)))  # a hair inside the bottom facet
    # Free vertices at one point are kept (merged by tetmesh with a warning, as TetGen does).
    pts += free
    if r.random() < 0.5:
        # A corner again, as a later vertex, named by one of its facets instead of it.
        k = r.randrange(8)
        pts.append(pts[k])
        facet = r.choice([f for f in facets if k in f])
        facet[facet.index(k)] = len(pts) - 1
    return pts, facets


def generate(out, seeds):
    os.makedirs(out, exist_ok=True)
    for s in range(seeds):
        pts, facets = cube(random.Random(f"cube3d{s}"))
        for e in (0, 300, -300):
            write(f"{out}/cube_{s}_s{e}.poly", pts, facets, e)


def volume(ele):
    """The volume of a mesh written as ELE and the .node beside it (doubles, inputs at 2^0)."""
    with open(ele[:-4] + ".node") as handle:
        rows = [line.split() for line in handle if line.strip() and not line.startswith("#")]
    xyz = {int(r[0]): tuple(map(float, r[1:4])) for r in rows[1:1 + int(rows[0][0])]}
    with open(ele) as handle:
        rows = [line.split() for line in handle if line.strip() and not line.startswith("#")]
    total = 0.0
    for r in rows[1:1 + int(rows[0][0])]:
        a, b, c, d = (xyz[int(v)] for v in r[1:5])
        u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, c, d))
        total += (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                  u[2] * (v[0] * w[1] - v[1] * w[0])) / 6
    return abs(total)


def run(directory, exe):
    out = os.path.join(directory, "out")
    os.makedirs(out, exist_ok=True)
    codes = collections.defaultdict(dict)
    volumes = collections.defaultdict(dict)
    failed = False
    for f in sorted(glob.glob(directory + "/*.poly")):
        stem = os.path.basename(f)[:-5]
        base, scale = stem.rsplit("_s", 1)
        size = repr(math.ldexp(0.25, int(scale)))
        line = stem
        for name, args in (("refinement", ["--radius-edge", "2"]),
                           ("frontal", ["--generator", "frontal", "--size", size]),
                           ("octree", ["--generator", "octree", "--size", size])):
            o = f"{out}/{stem}.{name}.ele"
            try:
                rc = subprocess.run([exe, "tetmesh", f, "-o", o] + args, capture_output=True,
                                    timeout=300).returncode
            except subprocess.TimeoutExpired:
                rc = "TIMEOUT"
            check = ""
            if rc == 0:
                c = subprocess.run([exe, "check", f, o], capture_output=True, text=True,
                                   timeout=300)
                check = "ok" if c.returncode == 0 else "CHECK FAILED " + c.stdout.strip()[-150:]
                if check == "ok" and scale == "0":
                    volumes[base][name] = volume(o)
            bad = not ((rc == 0 and check == "ok") or rc == 2)
            failed |= bad
            codes[(base, name)][scale] = rc
            line += f" | {name} rc={rc} {check}{' <<<' if bad else ''}"
        print(line, flush=True)
    for (base, name), by_scale in sorted(codes.items()):
        if len(set(by_scale.values())) > 1:
            failed = True
            print("SCALE MISMATCH", base, name, by_scale, flush=True)
    for base, by_generator in sorted(volumes.items()):
        values = list(by_generator.values())
        if max(values) - min(values) > 1e-9 * max(values):
            failed = True
            print("VOLUME MISMATCH", base, by_generator, flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "--run":
        here = os.path.dirname(os.path.abspath(__file__))
        exe = sys.argv[3] if len(sys.argv) > 3 else os.path.join(here, "..", "build", "release",
                                                                   "cli", "exactmesh")
        sys.exit(run(sys.argv[2], exe))
    if len(sys.argv) == 3:
        generate(sys.argv[1], int(sys.argv[2]))
        sys.exit(0)
    sys.exit(__doc__)
