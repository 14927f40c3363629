#!/usr/bin/env python3
"""Hostile 2D PSLGs and a campaign over them (issue 11's hostile inputs; the figures in the
README's known gaps, "Narrow wedges").

  scripts/hostile_pslgs_2d.py DIR SEEDS
      writes DIR/<kind>_<seed>_s<e>.poly for the kinds cross (long segments crossing at generic
      points, some 1e-2 to 1e-15 rad from parallel), fan (segments from one vertex 1e-1 to
      1e-10 rad apart), near (free vertices 1e-3 to 1e-15 from a segment and from each other),
      ring (near-cocircular free vertices, a chord) and mix (cross and near together), in a
      box, each at 2^0, 2^600 and 2^-600 (the same bits scaled), and each also renumbered
      (<kind>p_<seed>_s<e>.poly: the vertices in a shuffled order, the segments shuffled and
      some reversed; the same domain). Seeded by kind and seed.
  scripts/hostile_pslgs_2d.py --run DIR GENERATORS [REGEX] [EXACTMESH]
      meshes every DIR/*.poly (matching REGEX) with each of the comma-separated generators
      (`exactmesh mesh --generator G`), checks each mesh with `exactmesh check` (--conforming
      for all but delaunay-refinement), prints a line per run, a SCALE MISMATCH line when
      one input's triangle counts (or exit codes) differ between its scales, and a NUMBERING
      MISMATCH line when an input and its renumbered copy end differently (one meshed, one
      refused; triangle counts may differ). Exit 1 when a check fails, a run exits with
      neither 0 nor 2 (a clear refusal), or a scale or numbering mismatches.
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

def kind_mix(r):
    p1, s1 = kind_cross(r)
    p2, s2 = kind_near(r)
    off = len(p1)
    return p1 + p2[4:], s1 + [(a + off - 4, b + off - 4) for a, b in s2[4:]]

def write(path, pts, segs, e):
    with open(path, "w") as f:
        f.write(f"{len(pts)} 2 0 0\n")
        for i, (x, y) in enumerate(pts):
            f.write(f"{i+1} {math.ldexp(x, e)!r} {math.ldexp(y, e)!r}\n")
        f.write(f"{len(segs)} 0\n")
        for i, (a, b) in enumerate(segs):
            f.write(f"{i+1} {a+1} {b+1}\n")
        f.write("0\n")


def generate(out, seeds):
    kinds = dict(cross=kind_cross, fan=kind_fan, near=kind_near, ring=kind_ring, mix=kind_mix)
    os.makedirs(out, exist_ok=True)
    for name, fn in kinds.items():
        for s in range(seeds):
            pts, segs = fn(random.Random(f"{name}{s}"))
            shuffled, renumbered = renumber(pts, segs, random.Random(f"{name}{s}p"))
            for e in (0, 600, -600):
                write(f"{out}/{name}_{s}_s{e}.poly", pts, segs, e)
                write(f"{out}/{name}p_{s}_s{e}.poly", shuffled, renumbered, e)


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


def run(directory, generators, pattern, exe):
    files = sorted(glob.glob(directory + "/*.poly"))
    if pattern:
        files = [f for f in files if re.search(pattern, f)]
    out = os.path.join(directory, "out")
    os.makedirs(out, exist_ok=True)
    outcome = collections.defaultdict(dict)
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
    return 1 if failed else 0


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "--run":
        here = os.path.dirname(os.path.abspath(__file__))
        exe = sys.argv[5] if len(sys.argv) > 5 else os.path.join(here, "..", "build", "release",
                                                                   "cli", "exactmesh")
        sys.exit(run(sys.argv[2], sys.argv[3].split(","), sys.argv[4] if len(sys.argv) > 4 else "",
                     exe))
    if len(sys.argv) == 3:
        generate(sys.argv[1], int(sys.argv[2]))
        sys.exit(0)
    sys.exit(__doc__)
