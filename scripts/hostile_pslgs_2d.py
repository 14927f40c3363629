#!/usr/bin/env python3
"""Hostile 2D PSLGs and a campaign over them (issue 11's hostile inputs; the figures in the
README's known gaps, "Narrow wedges").

  scripts/hostile_pslgs_2d.py DIR SEEDS [KINDS]
      writes DIR/<kind>_<seed>_s<e>.poly for the kinds cross (long segments crossing at generic
      points, some 1e-2 to 1e-15 rad from parallel), fan (segments from one vertex 1e-1 to
      1e-10 rad apart), near (free vertices 1e-3 to 1e-15 from a segment and from each other),
      ring (near-cocircular free vertices, a chord) and mix (cross and near together), in a
      box, each at 2^0, 2^600 and 2^-600 (the same bits scaled), and each also renumbered
      (<kind>p_<seed>_s<e>.poly: the vertices in a shuffled order, the segments shuffled and
      some reversed; the same domain). Seeded by kind and seed. More kinds: touch (vertices
      exactly on segments on a dyadic lattice, collinear overlapping segments, T-junctions on
      the box's sides), hole (a square hole turned by a Pythagorean angle, segments across it,
      vertices on and a hair off its sides, a hole point), thin (a comb of fingers 1e-2 to
      1e-9 wide with free vertices in them) and odd (free vertices outside the box, a hair and
      1e6 away, in a hole, on its hole point, on a segment's line beyond its ends, on the box's
      corners and sides, duplicated, at -0.0). SEEDS: a count N (seeds 0..N-1) or a range
      FIRST-LAST; KINDS: a comma-separated list (default: all).
  scripts/hostile_pslgs_2d.py --run DIR GENERATORS [REGEX] [EXACTMESH]
      meshes every DIR/*.poly (matching REGEX) with each of the comma-separated generators
      (`exactmesh mesh --generator G`), checks each mesh with `exactmesh check` (--conforming
      for all but delaunay-refinement), prints a line per run, a SCALE MISMATCH line when
      one input's triangle counts (or exit codes) differ between its scales, and a NUMBERING
      MISMATCH line when an input and its renumbered copy end differently (one meshed, one
      refused; triangle counts may differ), and an AREA MISMATCH line when the generators'
      meshes of one input at 2^0 cover different areas (beyond 1e-9 relative). Exit 1 when a
      check fails, a run exits with neither 0 nor 2 (a clear refusal), or a scale, numbering or
      area mismatches.
"""
import collections
import glob
import math
import os
import random
import re
import subprocess
import sys
import time


def box(pts, segs, lo=-1.0, hi=1.0):
    b = len(pts)
    pts += [(lo, lo), (hi, lo), (hi, hi), (lo, hi)]
    segs += [(b, b+1), (b+1, b+2), (b+2, b+3), (b+3, b)]

def kind_cross(r):
    # long segments crossing at generic points, some nearly parallel
    pts, segs = [], []
    box(pts, segs)
    n = r.randint(2, 12)
    for i in range(n):
        a = r.uniform(0, math.pi)
        if i > 0 and r.random() < 0.6:
            a = base + r.choice([1, -1]) * 10 ** -r.uniform(2, 15)
        base = a
        cx, cy = r.uniform(-0.3, 0.3), r.uniform(-0.3, 0.3)
        L = r.uniform(0.8, 0.99)
        p = (cx - L*math.cos(a), cy - L*math.sin(a)); q = (cx + L*math.cos(a), cy + L*math.sin(a))
        if max(abs(p[0]), abs(p[1]), abs(q[0]), abs(q[1])) >= 1: continue
        k = len(pts); pts += [p, q]; segs.append((k, k+1))
    return pts, segs

def kind_fan(r):
    pts, segs = [], []
    box(pts, segs)
    n = r.randint(2, 5)
    o = (r.uniform(-0.5, 0.5), r.uniform(-0.5, 0.5)); k0 = len(pts); pts.append(o)
    a = r.uniform(0, 2*math.pi)
    for i in range(n):
        L = r.uniform(0.2, 0.45)
        pts.append((o[0] + L*math.cos(a), o[1] + L*math.sin(a))); segs.append((k0, len(pts)-1))
        a += 10 ** -r.uniform(1, 10)
    return pts, segs

def kind_near(r):
    # free vertices a hair from segments and from each other
    pts, segs = [], []
    box(pts, segs)
    k = len(pts); a = (r.uniform(-0.9, -0.2), r.uniform(-0.9, 0.9)); b = (r.uniform(0.2, 0.9), r.uniform(-0.9, 0.9))
    pts += [a, b]; segs.append((k, k+1))
    for i in range(r.randint(1, 6)):
        t = r.random(); d = 10 ** -r.uniform(3, 15) * r.choice([1, -1])
        nx, ny = -(b[1]-a[1]), b[0]-a[0]; ln = math.hypot(nx, ny)
        pts.append((a[0] + t*(b[0]-a[0]) + d*nx/ln, a[1] + t*(b[1]-a[1]) + d*ny/ln))
    for i in range(r.randint(0, 3)):
        p = (r.uniform(-0.9, 0.9), r.uniform(-0.9, 0.9)); pts.append(p)
        pts.append((p[0] + 10 ** -r.uniform(4, 14), p[1] + 10 ** -r.uniform(4, 14)))
    return pts, segs

def kind_ring(r):
    # near-cocircular ring of free vertices, plus a chord segment
    pts, segs = [], []
    box(pts, segs)
    c = (r.uniform(-0.2, 0.2), r.uniform(-0.2, 0.2)); R = r.uniform(0.3, 0.7)
    n = r.randint(5, 40)
    for i in range(n):
        a = 2*math.pi*i/n + r.uniform(0, 10 ** -r.uniform(3, 14))
        pts.append((c[0] + R*math.cos(a), c[1] + R*math.sin(a)))
    if r.random() < 0.5:
        segs.append((4, 4 + n//2))
    return pts, segs

def lattice_line(r, pts, segs, lo=-0.9, hi=0.9, steps=(2, 9)):
    """Adds a segment between two points of a dyadic lattice and some lattice points exactly on
    it (free vertices); returns its endpoints' indices and the lattice points along it, or None
    (nothing added) when they would leave the box."""
    m = 2 ** r.randint(3, 12)
    k = r.randint(*steps)
    dx, dy = r.randint(-5, 5), r.randint(-5, 5)
    if dx == 0 and dy == 0:
        dx = 1
    span = max(abs(dx), abs(dy)) * k / m
    if span >= hi - lo:
        m *= 2 ** math.ceil(math.log2(span / (hi - lo)) + 1)
    x0 = r.randint(math.ceil(lo * m), math.floor(hi * m))
    y0 = r.randint(math.ceil(lo * m), math.floor(hi * m))
    line = [((x0 + j * dx) / m, (y0 + j * dy) / m) for j in range(k + 1)]
    if any(abs(c) >= 1 for q in line for c in q):
        return None
    a = len(pts)
    pts.append(line[0])
    pts.append(line[-1])
    segs.append((a, a + 1))
    for q in line[1:-1]:
        if r.random() < 0.5:
            pts.append(q)  # a free vertex exactly on the segment
    return a, a + 1, line


def kind_touch(r):
    # exact touching: vertices exactly on segments, segments through vertices, collinear
    # overlapping segments, T-junctions on the box's sides, a free vertex on a side, the
    # box's diagonal through lattice vertices
    pts, segs = [], []
    box(pts, segs)
    lines = [lattice_line(r, pts, segs) for _ in range(r.randint(1, 5))]
    for made in lines:
        if made is None or r.random() < 0.4:
            continue
        a, b, line = made
        # a collinear segment overlapping this one, or one continuing it through a vertex
        i, j = sorted(r.sample(range(len(line)), 2))
        if (i, j) != (0, len(line) - 1):
            k = len(pts)
            pts += [line[i], line[j]]
            segs.append((k, k + 1))
    for _ in range(r.randint(0, 3)):
        # a T-junction: a segment ending on a side of the box (no vertex there)
        side = r.randrange(4)
        t = r.randint(-15, 15) / 16
        end = [(t, -1.0), (1.0, t), (t, 1.0), (-1.0, t)][side]
        inner = [(t, -0.5), (0.5, t), (t, 0.5), (-0.5, t)][side]
        if r.random() < 0.5:
            inner = (inner[0] + r.uniform(-0.3, 0.3), inner[1] + r.uniform(-0.3, 0.3))
        k = len(pts)
        pts += [end, inner]
        segs.append((k, k + 1))
    if r.random() < 0.5:
        pts.append((r.randint(-7, 7) / 8, 1.0))  # a free vertex on the top side
    if r.random() < 0.3:
        segs.append((0, 2))  # the diagonal, corner to corner
        for j in range(1, r.randint(2, 6)):
            pts.append((-1 + j / 4, -1 + j / 4))
    return pts, segs


def kind_hole(r):
    # a hole (a square turned by a Pythagorean angle, exact corners) with segments running
    # into and across it, free vertices inside it, on its sides and a hair outside
    pts, segs = [], []
    box(pts, segs)
    c, s_ = r.choice([(1.0, 0.0), (0.6, 0.8), (0.8, 0.6), (5 / 13, 12 / 13), (12 / 13, 5 / 13)])
    h = r.choice([0.125, 0.25, 0.375])
    cx, cy = r.randint(-4, 4) / 16, r.randint(-4, 4) / 16
    corners = [(cx + h * (x * c - y * s_), cy + h * (x * s_ + y * c))
               for x, y in [(-1, -1), (1, -1), (1, 1), (-1, 1)]]
    k = len(pts)
    pts += corners
    segs += [(k, k + 1), (k + 1, k + 2), (k + 2, k + 3), (k + 3, k)]
    # the marker off the centre, which the segments below cross
    holes = [(cx + r.uniform(-0.5, 0.5) * h, cy + r.uniform(-0.5, 0.5) * h)]
    for _ in range(r.randint(0, 3)):
        a = r.uniform(0, math.pi)
        L = r.uniform(0.5, 0.9)
        p = (cx - L * math.cos(a), cy - L * math.sin(a))
        q = (cx + L * math.cos(a), cy + L * math.sin(a))
        if max(abs(p[0]), abs(p[1]), abs(q[0]), abs(q[1])) < 1:
            m = len(pts)
            pts += [p, q]
            segs.append((m, m + 1))
    for _ in range(r.randint(0, 3)):
        pts.append((cx + r.uniform(-0.5, 0.5) * h, cy + r.uniform(-0.5, 0.5) * h))  # inside
    for _ in range(r.randint(0, 3)):
        i = r.randrange(4)
        t = r.randint(1, 7) / 8
        a, b = corners[i], corners[(i + 1) % 4]
        d = r.choice([0.0, 10 ** -r.uniform(6, 15)])
        pts.append((a[0] + t * (b[0] - a[0]) + d * (cx - a[0]), a[1] + t * (b[1] - a[1]) + d * (cy - a[1])))
    return pts, segs, holes


def kind_thin(r):
    # a comb: teeth of width 1e-2 to 1e-9 cut into the top of a rectangle, free vertices in
    # the teeth and a hair from their sides
    teeth = r.randint(1, 5)
    width = [10 ** -r.uniform(2, 9) for _ in range(teeth)]
    outline = [(-1.0, -1.0), (1.0, -1.0), (1.0, 0.0)]
    free = []
    xs = sorted(r.uniform(-0.9, 0.9) for _ in range(teeth))
    for x, w in zip(reversed(xs), reversed(width)):
        depth = r.uniform(0.1, 0.9)
        outline += [(x + w, 0.0), (x + w, depth), (x, depth), (x, 0.0)]
        for _ in range(r.randint(0, 2)):
            free.append((x + w * r.uniform(0.1, 0.9), depth * r.uniform(0.1, 0.95)))
    outline += [(-1.0, 0.0)]
    clean = [outline[0]]
    for q in outline[1:]:
        if q != clean[-1]:
            clean.append(q)
    pts = clean + free
    segs = [(i, (i + 1) % len(clean)) for i in range(len(clean))]
    return pts, segs


def kind_odd(r):
    # free vertices in odd places: outside the box (a hair and far), in a hole, on a hole
    # point, on a segment's line beyond its end, on the box's corners and sides (duplicates),
    # duplicated among themselves, at the origin as -0.0
    pts, segs = [], []
    box(pts, segs)
    holes = []
    if r.random() < 0.5:
        k = len(pts)
        pts += [(-0.5, -0.5), (0.0, -0.5), (0.0, 0.0), (-0.5, 0.0)]
        segs += [(k, k + 1), (k + 1, k + 2), (k + 2, k + 3), (k + 3, k)]
        holes.append((-0.3, -0.2))
        pts.append((-0.3, -0.2))  # on the hole point
        pts.append((-0.25, -0.25))  # inside the hole
        pts.append((-0.5, -0.25 + 10 ** -r.uniform(6, 15)))  # a hair off the hole's side
    a = (r.uniform(-0.8, 0.8), r.uniform(0.1, 0.8))
    b = (r.uniform(-0.8, 0.8), r.uniform(0.1, 0.8))
    k = len(pts)
    pts += [a, b]
    segs.append((k, k + 1))
    for t in (2.0, -1.0, 1.5):  # on the segment's line, beyond its ends (rounded)
        q = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
        if max(abs(q[0]), abs(q[1])) < 1:
            pts.append(q)
    pts.append((1.0 + 10 ** -r.uniform(6, 15), r.uniform(-0.9, 0.9)))  # a hair outside
    pts.append((r.choice([-1, 1]) * 1e6, r.uniform(-1e6, 1e6)))  # far outside
    pts.append(r.choice([(-1.0, -1.0), (1.0, 1.0)]))  # a corner again
    pts.append((r.randint(-3, 3) / 4, -1.0))  # on the bottom side
    q = (r.uniform(-0.9, 0.9), r.uniform(-0.9, 0.0))
    pts += [q, q]  # duplicated free vertices
    pts.append((-0.0, -0.0))
    return pts, segs, holes


def kind_mix(r):
    p1, s1 = kind_cross(r)
    p2, s2 = kind_near(r)
    off = len(p1)
    return p1 + p2[4:], s1 + [(a + off - 4, b + off - 4) for a, b in s2[4:]]

def write(path, pts, segs, e, holes=()):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n")
        for i, (x, y) in enumerate(pts):
            f.write(f"{i+1} {math.ldexp(x, e)!r} {math.ldexp(y, e)!r}\n")
        f.write(f"{len(segs)} 0\n")
        for i, (a, b) in enumerate(segs):
            f.write(f"{i+1} {a+1} {b+1}\n")
        f.write(f"{len(holes)}\n")
        for i, (x, y) in enumerate(holes):
            f.write(f"{i+1} {math.ldexp(x, e)!r} {math.ldexp(y, e)!r}\n")


def generate(out, seeds, only=()):
    kinds = dict(cross=kind_cross, fan=kind_fan, near=kind_near, ring=kind_ring, mix=kind_mix,
                 touch=kind_touch, hole=kind_hole, thin=kind_thin, odd=kind_odd)
    os.makedirs(out, exist_ok=True)
    for name, fn in kinds.items():
        if only and name not in only:
            continue
        for s in seeds:
            made = fn(random.Random(f"{name}{s}"))
            pts, segs, holes = made if len(made) == 3 else (*made, [])
            shuffled, renumbered = renumber(pts, segs, random.Random(f"{name}{s}p"))
            for e in (0, 600, -600):
                write(f"{out}/{name}_{s}_s{e}.poly", pts, segs, e, holes)
                write(f"{out}/{name}p_{s}_s{e}.poly", shuffled, renumbered, e, holes)


def renumber(pts, segs, r):
    """The same domain with its vertices in a shuffled order, its segments shuffled and about
    half of them reversed."""
    order = list(range(len(pts)))
    r.shuffle(order)
    new_index = [0] * len(pts)
    for new, old in enumerate(order):
        new_index[old] = new
    renumbered = [(new_index[a], new_index[b]) if r.random() < 0.5 else (new_index[b], new_index[a])
                  for a, b in segs]
    r.shuffle(renumbered)
    return [pts[old] for old in order], renumbered


def mesh_area(ele):
    """The area of a mesh written as ELE and the .node beside it (doubles: for the inputs at
    2^0, whose areas cannot overflow)."""
    with open(ele[:-4] + ".node") as handle:
        rows = [line.split() for line in handle if line.strip() and not line.startswith("#")]
    xy = {int(r[0]): (float(r[1]), float(r[2])) for r in rows[1:1 + int(rows[0][0])]}
    total = 0.0
    with open(ele) as handle:
        rows = [line.split() for line in handle if line.strip() and not line.startswith("#")]
    for r in rows[1:1 + int(rows[0][0])]:
        (ax, ay), (bx, by), (cx, cy) = (xy[int(v)] for v in r[1:4])
        total += 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))
    return total


def run(directory, generators, pattern, exe):
    files = sorted(glob.glob(directory + "/*.poly"))
    if pattern:
        files = [f for f in files if re.search(pattern, f)]
    out = os.path.join(directory, "out")
    os.makedirs(out, exist_ok=True)
    outcome = collections.defaultdict(dict)
    areas = collections.defaultdict(dict)  # input at 2^0 -> generator -> meshed area
    failed = False
    for f in files:
        stem = os.path.basename(f)[:-5]
        base, scale = stem.rsplit("_s", 1)
        for g in generators:
            o = f"{out}/{stem}.{g}.ele"
            t0 = time.time()
            try:
                p = subprocess.run([exe, "mesh", f, "-o", o, "--generator", g],
                                   capture_output=True, text=True, timeout=120)
                rc, err = p.returncode, (p.stderr.strip().splitlines() or [""])[-1][:150]
            except subprocess.TimeoutExpired:
                rc, err = "TIMEOUT", ""
            dt = time.time() - t0
            triangles, check = None, ""
            if rc == 0:
                with open(o) as handle:
                    triangles = int(handle.readline().split()[0])
                extra = [] if g == "delaunay-refinement" else ["--conforming"]
                c = subprocess.run([exe, "check", f, o] + extra, capture_output=True, text=True,
                                   timeout=300)
                check = "ok" if c.returncode == 0 else "CHECK FAILED " + (c.stdout + c.stderr).strip()[:150]
            outcome[(base, g)][scale] = (rc, triangles)
            if rc == 0 and check == "ok" and scale == "0":
                areas[base][g] = mesh_area(o)
            bad = not ((rc == 0 and check == "ok") or rc == 2)
            failed |= bad
            print(f"{stem:24s} {g:26s} rc={rc} t={dt:6.2f} triangles={triangles} {check} "
                  f"{err if rc else ''}{' <<<' if bad else ''}", flush=True)
    for (base, g), by_scale in sorted(outcome.items()):
        if len(set(by_scale.values())) > 1:
            failed = True
            print("SCALE MISMATCH", base, g, by_scale, flush=True)
        kind, seed = base.rsplit("_", 1)
        twin = outcome.get((f"{kind}p_{seed}", g)) if not kind.endswith("p") else None
        if twin is not None:
            for scale, (rc, _) in by_scale.items():
                if scale in twin and twin[scale][0] != rc:
                    failed = True
                    print("NUMBERING MISMATCH", base, g, scale, "exit", rc, "renumbered exit",
                          twin[scale][0], flush=True)
    # Every generator meshes the same domain: areas equal up to rounding (a hole point decided
    # differently by two generators removed a wedge in one and nothing in the other).
    for base, by_generator in sorted(areas.items()):
        values = list(by_generator.values())
        if max(values) - min(values) > 1e-9 * max(abs(v) for v in values):
            failed = True
            print("AREA MISMATCH", base, {g: round(a, 12) for g, a in by_generator.items()},
                  flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "--run":
        here = os.path.dirname(os.path.abspath(__file__))
        exe = sys.argv[5] if len(sys.argv) > 5 else os.path.join(here, "..", "build", "release",
                                                                   "cli", "exactmesh")
        sys.exit(run(sys.argv[2], sys.argv[3].split(","), sys.argv[4] if len(sys.argv) > 4 else "",
                     exe))
    if len(sys.argv) in (3, 4):
        # SEEDS: a count (0..N-1) or a range FIRST-LAST; KINDS: comma-separated, default all
        first, _, last = sys.argv[2].partition("-")
        seeds = range(int(first), int(last) + 1) if last else range(int(first))
        generate(sys.argv[1], seeds, sys.argv[3].split(",") if len(sys.argv) == 4 else ())
        sys.exit(0)
    sys.exit(__doc__)
