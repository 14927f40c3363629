#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Robustness table (issue 16): the same degenerate inputs (case seeds 1..N of each kind, from
generators/inputs) through every triangulator at hand, each output checked exactly by
`exactmesh fuzz --command`: scipy.spatial.Delaunay (Qhull), TetGen, Gmsh's point-set Delaunay
and exactmesh's own commands.

Usage: bench/robustness_table.py [--quick] [--count N] [--exactmesh PATH] [--json OUT.json]
                                [--save DIR] [--quiet]
Prints Markdown: per program and kind, inputs run and how many were exactly right, wrong (the
output is missing, malformed or fails the exact check), crashed (nonzero exit or a signal),
timed out (--timeout) or refused (a nonzero exit on an input that has no triangulation: all
collinear or coplanar); then the kinds of wrong answers and the bad inputs per distribution.
Not a timing: each input is one process run (scripts/run writes report/robustness.md).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from collections import Counter

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PROGRAMS_DIR = os.path.join(ROOT, "tests", "data", "fuzz_programs")
PYTHON = "/usr/bin/python3"  # Debian's, with python3-scipy and python3-gmsh

SUMMARY = re.compile(r"^fuzz: (\d+) inputs \(.*\), (\d+) passed, (\d+) failed, (\d+) crashed, "
                     r"(\d+) timed out, (\d+) refused in ([0-9.]+) s$")
FAILURE = re.compile(r"^FAILURE: case seed (\d+) \(([^,]+), (\d+) points\): ([a-z ]+): (.*)$")

# What a wrong answer's first problem says, grouped (triangulation/checks' wording).
PROBLEM_KINDS = [
    (r"no (triangles|tetrahedra), but", "no cells at all"),
    (r"not counter-clockwise|not positively oriented", "flat (or inverted) cell"),
    (r"not the convex hull|boundary is not convex|not closed|hull", "convex hull not covered"),
    (r"not a vertex of any", "input point left out"),
    (r"not Delaunay", "not Delaunay"),
    (r"coincide|duplicate", "duplicate points used"),
    (r"wrote no|names vertex|expected", "unreadable output"),
]


def problem_kind(text):
    for pattern, name in PROBLEM_KINDS:
        if re.search(pattern, text):
            return name
    return "other: " + text[:60]


def crash_kind(text):
    """A crash report ("exit status N: the program's last stderr lines") grouped by its cause."""
    m = re.match(r"(exit status \d+|killed by signal \d+[^:]*)", text)
    how = m.group(1) if m else text[:40]
    said = text.split(": ", 1)[1] if ": " in text else ""
    qhull = re.search(r"(QH\d+ [^(|]*)", said)
    if qhull:
        return f"{how}, {qhull.group(1).strip()}"
    assertion = re.search(r"([A-Za-z0-9_]+\.c(?:xx|pp)?:\d+):.*Assertion", said)
    if assertion:
        return f"{how}, assertion at {assertion.group(1)}"
    terminate = re.search(r"(terminate called [^|]*)", said)
    if terminate:
        return f"{how}, {terminate.group(1).strip()}"
    return how


def programs(exactmesh):
    """(name, kind, command, extra options, available?) for every program of the table."""
    em = f"'{exactmesh}'"
    scipy_wrapper = os.path.join(PROGRAMS_DIR, "scipy_delaunay.py")
    gmsh_wrapper = os.path.join(PROGRAMS_DIR, "gmsh_delaunay.py")
    have_scipy = subprocess.run([PYTHON, "-c", "import scipy.spatial"],
                                capture_output=True).returncode == 0
    have_gmsh = subprocess.run([PYTHON, "-c", "import gmsh"], capture_output=True).returncode == 0
    have_tetgen = shutil.which("tetgen") is not None
    return [
        ("exactmesh triangulate", "points2d", f"{em} triangulate {{in}} -o {{out}}", [], True),
        ("scipy.spatial.Delaunay", "points2d", f"{PYTHON} '{scipy_wrapper}' {{in}} {{out}}", [],
         have_scipy),
        ("Gmsh triangulate", "points2d", f"{PYTHON} '{gmsh_wrapper}' {{in}} {{out}}",
         ["--orient"], have_gmsh),
        ("exactmesh cdt", "pslg", f"{em} cdt {{in}} -o {{out}}", [], True),
        ("exactmesh tetrahedralize", "points3d", f"{em} tetrahedralize {{in}} -o {{out}}", [],
         True),
        ("scipy.spatial.Delaunay", "points3d", f"{PYTHON} '{scipy_wrapper}' {{in}} {{out}}", [],
         have_scipy),
        ("TetGen -Q", "points3d", "tetgen -Q {in}", ["--output", "{stem}.1.ele"], have_tetgen),
        ("Gmsh tetrahedralize", "points3d", f"{PYTHON} '{gmsh_wrapper}' {{in}} {{out}}",
         ["--orient"], have_gmsh),
    ]


def versions(exactmesh):
    out = {}

    def run(args):
        r = subprocess.run(args, capture_output=True, text=True)
        return (r.stdout + r.stderr).strip().splitlines()[0] if r.returncode == 0 else "?"

    out["exactmesh"] = run([exactmesh, "--version"])
    out["scipy"] = run([PYTHON, "-c", "import scipy; print(scipy.__version__)"])
    out["gmsh"] = run(["dpkg-query", "-W", "-f=${Version}", "python3-gmsh"])
    out["tetgen"] = run(["dpkg-query", "-W", "-f=${Version}", "tetgen"])
    return out


def fuzz(exactmesh, kind, command, extra, args, save):
    argv = [exactmesh, "fuzz", "--quiet", "--kind", kind, "--count", str(args.count), "--seed",
            str(args.seed), "--max-points", str(args.max_points), "--timeout", str(args.timeout),
            "--minimize-seconds", "0", "--save", save, "--command", command] + extra
    r = subprocess.run(argv, capture_output=True, text=True)
    if r.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(argv)}: exit {r.returncode}: {r.stdout}{r.stderr}")
    row = None
    problems, crashes, per_distribution = Counter(), Counter(), {}
    for line in r.stdout.splitlines():
        m = SUMMARY.match(line)
        if m:
            run, passed, failed, crashed, timed_out, refused = map(int, m.groups()[:6])
            row = {"inputs": run, "right": passed, "wrong": failed, "crashed": crashed,
                   "timed_out": timed_out, "refused": refused, "seconds": float(m.group(7))}
        m = FAILURE.match(line)
        if m:
            verdict, text = m.group(4), m.group(5)
            if verdict == "failed":
                problems[problem_kind(text)] += 1
            else:
                crashes[crash_kind(text) if verdict == "crashed" else "timed out"] += 1
        if line.startswith("fuzz: failed of run per distribution:"):
            for name, bad, run in re.findall(r"(\S+) (\d+)/(\d+)", line.split(":", 2)[2]):
                per_distribution[name] = (int(bad), int(run))
    if row is None:
        raise RuntimeError(f"{' '.join(argv)}: no summary line in: {r.stdout}")
    row.update(problems=dict(problems), crashes=dict(crashes), per_distribution=per_distribution)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="20 inputs per kind, up to 300 points")
    parser.add_argument("--count", type=int, help="inputs per kind (default 100, --quick 20)")
    parser.add_argument("--seed", type=int, default=1, help="first case seed")
    parser.add_argument("--max-points", type=int, help="largest input (default 1000, --quick 300)")
    parser.add_argument("--timeout", type=float, default=20, help="seconds per run")
    parser.add_argument("--exactmesh", default=os.path.join(ROOT, "build/release/cli/exactmesh"))
    parser.add_argument("--save", help="keep each program's failing inputs and reproducers here")
    parser.add_argument("--json", help="write the rows as JSON here")
    parser.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
    args = parser.parse_args()
    args.count = args.count or (20 if args.quick else 100)
    args.max_points = args.max_points or (300 if args.quick else 1000)
    exactmesh = os.path.abspath(args.exactmesh)

    rows = []
    scratch = tempfile.mkdtemp(prefix="exactmesh-robustness-")
    try:
        for name, kind, command, extra, available in programs(exactmesh):
            row = {"program": name, "kind": kind}
            if not available:
                row["missing"] = True
                rows.append(row)
                continue
            slug = re.sub(r"[^a-z0-9]+", "-", f"{name} {kind}".lower()).strip("-")
            save = os.path.join(args.save or scratch, slug)
            if not args.quiet:
                print(f"robustness: {name} on {args.count} {kind} inputs...", file=sys.stderr)
            row.update(fuzz(exactmesh, kind, command, extra, args, save))
            rows.append(row)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)

    v = versions(exactmesh)
    print("# Robustness: the same degenerate inputs through every triangulator\n")
    print(f"Case seeds {args.seed}..{args.seed + args.count - 1} of each kind (the distributions "
          f"of `generators/inputs`: uniform, grids, cocircular/cospherical, near-collinear/"
          f"near-coplanar by a few ulps, duplicates, huge and tiny magnitudes, ...; at most "
          f"{args.max_points} points), each output checked exactly by `exactmesh fuzz "
          f"--command` (`bench/robustness_table.py`{' --quick' if args.quick else ''}). "
          f"Versions: {v['exactmesh']}; SciPy {v['scipy']} (Qhull); TetGen {v['tetgen']}; "
          f"Gmsh {v['gmsh']} (Python API). *Exactly right*: the exact Delaunay check passes "
          f"(points: a triangulation of the whole convex hull using every distinct point, "
          f"every edge or face locally Delaunay; PSLG: Chew's constrained Delaunay with every "
          f"segment); *wrong*: no, malformed or failing output; *refused*: a nonzero exit on an "
          f"input without any triangulation (all collinear or coplanar). scipy's and Gmsh's "
          f"cells are oriented exactly before the check (`--orient`, or in the wrapper), so "
          f"only their choice of cells is judged.\n")
    print("| program | kind | inputs | exactly right | wrong | crashed | timed out | refused |")
    print("|---|---|---:|---:|---:|---:|---:|---:|")
    for r in rows:
        if r.get("missing"):
            print(f"| {r['program']} | {r['kind']} | not installed | | | | | |")
            continue
        print(f"| {r['program']} | {r['kind']} | {r['inputs']} | {r['right']} | {r['wrong']} | "
              f"{r['crashed']} | {r['timed_out']} | {r['refused']} |")
    print("\nWhat went wrong (first problem of each bad input, grouped):\n")
    print("| program | kind | wrong answers | crashes |")
    print("|---|---|---|---|")
    for r in rows:
        if r.get("missing") or not (r["problems"] or r["crashes"]):
            continue
        wrong = "; ".join(f"{n} × {k}" for k, n in sorted(r["problems"].items(), key=lambda x: -x[1]))
        crashed = "; ".join(f"{n} × {k}" for k, n in sorted(r["crashes"].items(), key=lambda x: -x[1]))
        print(f"| {r['program']} | {r['kind']} | {wrong or '-'} | {crashed or '-'} |")
    print("\nBad inputs (wrong, crashed or timed out) of inputs run, per distribution:\n")
    print("| program | kind | per distribution |")
    print("|---|---|---|")
    for r in rows:
        if r.get("missing"):
            continue
        text = " ".join(f"{name} {bad}/{run}" for name, (bad, run) in
                        sorted(r["per_distribution"].items()))
        print(f"| {r['program']} | {r['kind']} | {text} |")
    if args.json:
        with open(args.json, "w", encoding="utf-8") as out:
            json.dump({"count": args.count, "seed": args.seed, "max_points": args.max_points,
                       "versions": v, "rows": rows}, out, indent=1)


if __name__ == "__main__":
    main()
