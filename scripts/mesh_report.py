#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Markdown report and plots of 2D mesh generation from mesh_bench's JSON.

Usage:
  mesh_bench --benchmark_out=mesh_bench.json --benchmark_out_format=json
  scripts/mesh_report.py mesh_bench.json --out-dir report

Reads benchmarks named BM_mesh/<mesher>/<domain>/<angle>/<target>[/...] (raw repetitions; the
medians are computed here: CPU time for ours and CGAL, the manual time for Gmsh, which is Gmsh's
own CPU time of its 2D meshing) and writes into --out-dir:
  mesh.md                 per domain and target: triangles, median time, triangles per second,
                          throughput relative to CGAL, minimum and mean minimum angle, size
                          conformity; the fitted exponent of time vs triangles per mesher;
                          the goals of issue 6 (Delaunay refinement >= 2x CGAL's throughput with
                          an equal or better minimum angle; frontal generators' mean quality
                          above Delaunay refinement's);
  mesh_histograms.png     the corner-angle histograms of every mesher, one panel per domain, at
                          the target nearest 10^5;
  mesh_throughput.png     triangles per second vs triangles, one panel per domain;
  mesh.md links the figures of scripts/picture_panels.py (panels_<domain>.png, pictures.md),
                          which scripts/run writes after it.
Exits 1 when a benchmark reported an error, after writing.
"""

import argparse
import json
import math
import os
import statistics
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)

SECONDS_PER_UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
PEERS = ["cgal", "gmsh-delaunay", "gmsh-frontal"]
FRONTAL = ["advancing-front", "advancing-front-delaunay", "frontal"]


def parse_angle(text):
    """'20.7' -> (20.7, None); '20.7p30.7' -> (20.7, 30.7) (bound, polish); 'none' -> (None, None)."""
    if text == "none":
        return None, None
    bound, _, polish = text.partition("p")
    return float(bound), float(polish) if polish else None


def angle_label(mesher, angle):
    bound, polish = parse_angle(angle)
    if bound is None:
        return mesher
    if polish is None:
        return f"{mesher} {angle}" + (" (no polish)" if mesher == "delaunay-refinement" else "")
    return f"{mesher} {bound:g}, polish {polish:g}"


class Results:
    def __init__(self, data):
        self.runs = defaultdict(list)  # (mesher, domain, angle, target) -> [benchmark dicts]
        self.plain = defaultdict(list)  # (mesher, input) -> [benchmark dicts], default sizes
        self.errors = []
        for b in data["benchmarks"]:
            if b.get("run_type") == "aggregate":
                continue
            parts = b["name"].split("/")
            if len(parts) < 5 or parts[0] != "BM_mesh":
                continue
            if not parts[4].isdigit():
                # BM_mesh/<mesher>/near-circle-10000/default: the plain input of issue 11,
                # each generator with the size `exactmesh mesh` takes without --size.
                if not b.get("error_occurred"):
                    self.plain[(parts[1], parts[2])].append(b)
                else:
                    self.errors.append(f"{b['name']}: {b.get('error_message', '')}")
                continue
            key = (parts[1], parts[2], parts[3], int(parts[4]))
            if b.get("error_occurred"):
                self.errors.append(f"{b['name']}: {b.get('error_message', '')}")
                continue
            self.runs[key].append(b)

    def keys(self):
        return sorted(self.runs)

    def meshers(self):
        names = sorted({k[0] for k in self.runs})
        ours = [n for n in names if n not in PEERS]
        return ours + [p for p in PEERS if p in names]

    def series(self):
        """(mesher, angle) pairs measured at every target of their domain (the 30-degree pairs,
        measured at 10^5 only, are left to the tables), in mesher order."""
        found = defaultdict(set)
        for mesher, domain, angle, target in self.runs:
            found[(mesher, angle)].add((domain, target))
        all_cells = {(k[1], k[3]) for k in self.runs}
        pairs = [p for p, cells in found.items() if len(cells) * 2 > len(all_cells) or len(all_cells) <= 4]
        return sorted(pairs, key=lambda p: (self.meshers().index(p[0]), p[1]))

    def domains(self):
        order = ["square-with-holes", "naca0012", "key", "three-element"]
        found = {k[1] for k in self.runs}
        return [d for d in order if d in found] + sorted(found - set(order))

    def times(self, key):
        """Seconds per iteration of each repetition: CPU time for ours and CGAL, the manual time
        (Gmsh's own CPU time of its 2D meshing) for Gmsh."""
        field = "real_time" if key[0].startswith("gmsh") else "cpu_time"
        return [r[field] * SECONDS_PER_UNIT[r["time_unit"]] for r in self.runs[key]]

    def seconds(self, key):
        return statistics.median(self.times(key))

    def cv(self, key):
        t = self.times(key)
        return statistics.stdev(t) / statistics.mean(t) if len(t) >= 2 else None

    def counter(self, key, name):
        return self.runs[key][0].get(name)

    def label(self, key):
        return self.runs[key][0].get("label", "")

    def find(self, mesher, domain, target, angle=None):
        for k in self.runs:
            if k[0] == mesher and k[1] == domain and k[3] == target and (angle is None or k[2] == angle):
                return k
        return None

    def cgal_peer(self, key):
        """CGAL like for like: at the same bound for a bound, at the polish angle for a polished
        run, at 20.7 degrees for meshers without an angle criterion."""
        mesher, domain, angle, target = key
        bound, polish = parse_angle(angle)
        if bound is None:
            return self.find("cgal", domain, target, "20.7")
        return self.find("cgal", domain, target, f"{polish if polish is not None else bound:g}")


def fmt(value, digits=2):
    if value is None:
        return "—"
    return f"{value:.{digits}f}"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---" if i == 0 else "---:" for i in range(len(header))) + "|"]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def throughput(res, key):
    return res.counter(key, "triangles") / res.seconds(key)


def throughput_ratio(res, key, peer):
    """Median triangles per second of key over peer's, and the range over the repetitions
    (slowest of key against fastest of peer .. fastest against slowest)."""
    n, m = res.counter(key, "triangles"), res.counter(peer, "triangles")
    mid = throughput(res, key) / throughput(res, peer)
    low = (n / max(res.times(key))) / (m / min(res.times(peer)))
    high = (n / min(res.times(key))) / (m / max(res.times(peer)))
    return mid, low, high


def fmt_ratio(ratio):
    mid, low, high = ratio
    return f"{mid:.2f} ({low:.2f}–{high:.2f})"


def fmt_ms(res, key):
    t = [x * 1e3 for x in res.times(key)]
    return f"{statistics.median(t):.1f} ({min(t):.1f}–{max(t):.1f})"


def domain_tables(res, out):
    out.append("Per domain: time per mesh in ms, median of the repetitions (min–max) and their coefficient "
               "of variation; throughput / CGAL against CGAL like for like (ours polished against CGAL at "
               "the polish angle, ours unpolished and the other generators against CGAL at the bound, "
               "20.7 for those without one).\n")
    for domain in res.domains():
        out.append(f"### {domain}\n")
        rows = []
        for key in [k for k in res.keys() if k[1] == domain]:
            mesher, _, angle, target = key
            cgal = res.cgal_peer(key)
            rel = fmt(throughput(res, key) / throughput(res, cgal)) if cgal else "—"
            cv = res.cv(key)
            rows.append([mesher, angle, f"{target:,}", f"{int(res.counter(key, 'triangles')):,}",
                         fmt_ms(res, key), f"{100 * cv:.1f}%" if cv is not None else "—",
                         f"{throughput(res, key) / 1e3:,.0f}k", rel, fmt(res.counter(key, "min_angle")),
                         fmt(res.counter(key, "mean_min_angle")), fmt(res.counter(key, "median_size_ratio")),
                         fmt(res.counter(key, "max_size_ratio"))])
        rows.sort(key=lambda r: (int(r[2].replace(",", "")), res.meshers().index(r[0]), r[1]))
        out.append(table(["mesher", "angle bound", "target", "triangles", "ms median (min–max)", "cv",
                          "triangles/s", "throughput / CGAL", "min angle", "mean min angle",
                          "size ratio median", "size ratio max"], rows))
        out.append("")


def slope(points):
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    den = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / den if den > 0 else None


def exponent_table(res, out):
    out.append("### Fitted complexity: time ~ triangles^k (least squares over the targets)\n")
    rows = []
    for mesher, angle in res.series():
        row = [angle_label(mesher, angle)]
        for domain in res.domains():
            pts = [(res.counter(k, "triangles"), res.seconds(k)) for k in res.keys()
                   if k[0] == mesher and k[1] == domain and k[2] == angle]
            row.append(fmt(slope(pts)) if len(pts) >= 2 else "—")
        rows.append(row)
    out.append(table(["mesher"] + res.domains(), rows))
    out.append("")


def goal_rows(res, polished):
    rows, met = [], 0
    for key in res.keys():
        mesher, domain, angle, target = key
        bound, polish = parse_angle(angle)
        if mesher != "delaunay-refinement" or bound is None or (polish is not None) != polished:
            continue
        cgal = res.cgal_peer(key)
        if not cgal:
            continue
        ratio = throughput_ratio(res, key, cgal)
        ours_angle, cgal_angle = res.counter(key, "min_angle"), res.counter(cgal, "min_angle")
        ok = ratio[0] >= 2 and ours_angle >= cgal_angle - 1e-9
        met += ok
        verdict = "yes" if ok else ("speed only" if ratio[0] >= 2 else ("angle only" if ours_angle >= cgal_angle - 1e-9 else "no"))
        rows.append([domain, f"{bound:g}" if not polished else f"{bound:g} → {polish:g}", cgal[2], f"{target:,}",
                     f"{int(res.counter(key, 'triangles')):,} / {int(res.counter(cgal, 'triangles')):,}",
                     fmt_ratio(ratio), fmt(ours_angle), fmt(cgal_angle), verdict])
    return rows, met


def goals(res, out):
    out.append("### Delaunay refinement against CGAL, like for like\n")
    out.append("The goal (issue 6): at least 2x CGAL's throughput (triangles per second) with an equal or "
               "better minimum angle, same PSLG and size function. Throughput ratio: ratio of the medians, "
               "in parentheses its range over the repetitions (ours slowest against CGAL fastest .. ours "
               "fastest against CGAL slowest).\n")
    header = ["domain", "ours: bound", "CGAL: bound", "target", "triangles ours / CGAL",
              "throughput ours / CGAL", "min angle ours", "min angle CGAL", ">= 2x and angle >= CGAL's"]
    rows, met = goal_rows(res, polished=False)
    out.append(f"**Without the polish** (ours with `--polish-angle 0`) against CGAL at the same bound: "
               f"goal met in {met} of {len(rows)} cells.\n")
    out.append(table(header, rows))
    out.append("")
    rows, met = goal_rows(res, polished=True)
    out.append(f"**With the polish** (ours at the bound, then polished toward min(bound + 10, 32), the default) "
               f"against CGAL given the polish angle as its bound: goal met in {met} of {len(rows)} cells.\n")
    out.append(table(header, rows))
    out.append("")
    rows = []
    for key in res.keys():
        mesher, domain, angle, target = key
        if mesher not in FRONTAL:
            continue
        refinement = res.find("delaunay-refinement", domain, target, "20.7p30.7") or \
            res.find("delaunay-refinement", domain, target, "20.7")
        if not refinement:
            continue
        ours, dr = res.counter(key, "mean_min_angle"), res.counter(refinement, "mean_min_angle")
        rows.append([mesher, domain, f"{target:,}", fmt(ours), fmt(dr), "yes" if ours > dr else "no"])
    out.append("Frontal generators against Delaunay refinement (20.7 degrees, polished: the default) on the same "
               "size function: mean of the triangles' smallest angles.\n")
    out.append(table(["generator", "domain", "target", "mean min angle", "Delaunay refinement", "better"], rows))
    out.append("")


def gmsh_sizes(res, out):
    rows = []
    for key in res.keys():
        mesher, domain, angle, target = key
        if mesher != "gmsh-delaunay" and not (mesher == "gmsh-frontal" and not res.find("gmsh-delaunay", domain, target)):
            continue
        rows.append([domain, f"{target:,}", res.label(key).removeprefix("size: ")])
    if not rows:
        return
    out.append("### How Gmsh is given the size\n")
    out.append("Prepared outside Gmsh's timed region: a uniform size through Mesh.MeshSizeMin = "
               "Mesh.MeshSizeMax (no size field at all); a graded one as a background mesh, a .pos view of the "
               "size at the vertices of a Delaunay refinement of the domain's bounding box at the size itself, "
               "as a PostView background field, looked up (compiled code, an octree search) at every size query "
               "(the error is linear interpolation's, largest at the kink where the sources meet the cap); or, "
               "with EXACTMESH_MESH_BENCH_GMSH_SIZE=formula, as MathEval of the source formula over sampled "
               "Distance fields, interpreted at every query. MeshSizeFromPoints, MeshSizeFromCurvature and "
               "MeshSizeExtendFromBoundary are off. The table says which each domain got; on a graded domain "
               "Gmsh's time includes its size lookups either way, where ours evaluates the compiled formula.\n")
    out.append(table(["domain", "target", "size input (both Gmsh algorithms)"], rows))
    out.append("")


def style(index, mesher, angle):
    """One colour per series (tab20 has enough for every mesher and angle); dashed for CGAL and
    Gmsh, so the peers stand apart from ours."""
    return {"color": plt.cm.tab20(index % 20), "linestyle": "--" if mesher in PEERS else "-"}


def plot_histograms(res, path):
    domains = res.domains()
    fig, axes = plt.subplots(1, len(domains), figsize=(4.2 * len(domains), 3.6), squeeze=False)
    for ax, domain in zip(axes[0], domains):
        targets = sorted({k[3] for k in res.keys() if k[1] == domain})
        target = min(targets, key=lambda t: abs(math.log(t / 1e5)))
        for i, (mesher, angle) in enumerate(res.series()):
            key = res.find(mesher, domain, target, angle)
            if not key:
                continue
            hist = [res.counter(key, f"angle_hist_{k}") or 0 for k in range(18)]
            ax.plot([10 * k + 5 for k in range(18)], hist, marker=".", label=angle_label(mesher, angle),
                    **style(i, mesher, angle))
        ax.set_title(f"{domain}, ~{target:,} triangles")
        ax.set_xlabel("corner angle (degrees)")
        ax.set_xlim(0, 130)
    axes[0][0].set_ylabel("fraction of corners")
    axes[0][-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_throughput(res, path):
    domains = res.domains()
    fig, axes = plt.subplots(1, len(domains), figsize=(4.2 * len(domains), 3.6), squeeze=False)
    for ax, domain in zip(axes[0], domains):
        for i, (mesher, angle) in enumerate(res.series()):
            pts = sorted((res.counter(k, "triangles"), throughput(res, k)) for k in res.keys()
                         if k[0] == mesher and k[1] == domain and k[2] == angle)
            if pts:
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker="o", label=angle_label(mesher, angle),
                          **style(i, mesher, angle))
        ax.set_title(domain)
        ax.set_xlabel("triangles")
    axes[0][0].set_ylabel("triangles per second")
    axes[0][-1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def pictures(res, out):
    """Links to scripts/picture_panels.py's figures (scripts/run writes them next): each domain
    meshed for the picture, every generator side by side, shaded by smallest angle."""
    out.append("### Pictures\n")
    out.append("Each domain meshed for the picture (about 2,500 triangles, one size for every "
               "generator), every generator and Gmsh side by side on one window and scale, "
               "triangles shaded by their smallest angle, zooms where the detail is: "
               "[pictures.md](pictures.md) (`scripts/picture_panels.py`).\n")
    for domain in res.domains():
        out.append(f"[![{domain}](panels_{domain}.png)](pictures.md#{domain})\n")


def plain_inputs(res, out):
    """Each generator on the plain inputs with the size it takes when given none."""
    if not res.plain:
        return
    out.append("### Plain inputs, default size\n")
    out.append("Each generator with the size `exactmesh mesh` takes without `--size` (Delaunay "
               "refinement: none; the others: the boundary spacing graded away from it), the size "
               "built inside the timed region as the command does.\n")
    rows = []
    for (mesher, name), runs in sorted(res.plain.items()):
        times = [r["cpu_time"] * SECONDS_PER_UNIT[r["time_unit"]] for r in runs]
        median = statistics.median(times)
        triangles = runs[0].get("triangles", 0)
        rows.append([name, mesher, f"{triangles:,.0f}", f"{median * 1e3:.1f} ({min(times) * 1e3:.1f}-{max(times) * 1e3:.1f})",
                     f"{triangles / median / 1e3:,.0f}k", fmt(runs[0].get("min_angle")), fmt(runs[0].get("mean_min_angle"))])
    out.append(table(["input", "mesher", "triangles", "ms median (range)", "triangles/s", "min angle", "mean min angle"], rows))
    out.append("")


def repetitions(res):
    counts = sorted({len(v) for v in res.runs.values()})
    return "/".join(str(c) for c in counts) if counts else "0"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("json")
    parser.add_argument("--out-dir", default="report")
    args = parser.parse_args()
    with open(args.json) as f:
        data = json.load(f)
    res = Results(data)
    os.makedirs(args.out_dir, exist_ok=True)
    out = ["# 2D mesh generation\n",
           f"From `{os.path.basename(args.json)}` (host {data['context'].get('host_name', '?')}, "
           f"{data['context'].get('num_cpus', '?')} CPUs, {data['context'].get('date', '')}, load average "
           f"{', '.join(f'{x:.1f}' for x in data['context'].get('load_avg', [])) or '?'} at the start). "
           f"{repetitions(res)} repetitions of each case, each running iterations for at least its minimum time, "
           "interleaved at random when run by `scripts/run`; times are per mesh, medians of the repetitions with "
           "their spread: CPU time for ours and CGAL, Gmsh's own CPU time of its 2D meshing for Gmsh "
           "(1D meshing, file reading and writing excluded). Every mesher gets the same PSLG and size "
           "function; ours and CGAL's Delaunay refinement also the angle bound, and both find the size at "
           "an edge's midpoint once per edge (ours per half-edge, CGAL memoized in its faces).\n"]
    goals(res, out)
    gmsh_sizes(res, out)
    exponent_table(res, out)
    out.append("![angle histograms](mesh_histograms.png)\n")
    out.append("![throughput](mesh_throughput.png)\n")
    domain_tables(res, out)
    plain_inputs(res, out)
    pictures(res, out)
    if res.errors:
        out.append("### Errors\n")
        out += [f"- {e}" for e in res.errors]
    plot_histograms(res, os.path.join(args.out_dir, "mesh_histograms.png"))
    plot_throughput(res, os.path.join(args.out_dir, "mesh_throughput.png"))
    with open(os.path.join(args.out_dir, "mesh.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    for e in res.errors:
        print(f"mesh_report: {e}", file=sys.stderr)
    return 1 if res.errors else 0


if __name__ == "__main__":
    sys.exit(main())
