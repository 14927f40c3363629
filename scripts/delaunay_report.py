#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Markdown report and plots of 2D Delaunay construction from delaunay2d_bench's JSON.

Usage:
  delaunay2d_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \\
      --benchmark_out=bench.json --benchmark_out_format=json
  scripts/delaunay_report.py bench.json --out-dir report \\
      [--bench build/release/bench/delaunay2d_bench --cli build/release/cli/exactmesh]

Reads benchmarks named BM_<algo>/<distribution>/<order>/<n> (medians over the repetitions of
the CPU time, or medians computed here from raw runs), and writes into --out-dir:
  delaunay2d.md             tables: median seconds per algorithm and N with the ratio to CGAL,
                            least-squares exponents of time vs N, t/(n log2 n), per-point counters,
                            peak heap memory ours vs CGAL, the parabola adversary, a cross-check
                            of triangle counts;
  delaunay2d_time.png       log-log time vs N, every algorithm and CGAL;
  delaunay2d_ratio.png      time ours / CGAL vs N;
  delaunay2d_parabola.png   the parabola, given (sorted) vs random order;
  delaunay2d_scaling_time.png, delaunay2d_scaling_efficiency.png (with the rows
                            BM_bowyer_watson_<T>_threads): strong scaling on 1..T threads beside
                            CGAL's sequential construction, with its table (delaunay_scaling.py),
                            and with the rows BM_memory_floor_<memory> the memory floor of the
                            same result beside our one-thread time (floor_section);
  gaussian_200_green_sibson.svg (with --bench and --cli): 200 Gaussian points written as a .node
                            by the bench's helper mode, triangulated by `exactmesh triangulate`.
Exits 1 when a benchmark reported an error or the triangle counts disagree, after writing.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys

from matplotlib.ticker import FuncFormatter

from delaunay_scaling import floor_section, scaling_section  # scripts/, beside this one
from report_plots import finish_axes, plt, save_figure

DISTRIBUTIONS = ["uniform", "gaussian"]
# (algo, order) families in table order; cgal last.
FAMILIES = [("bowyer_watson", "brio"), ("bowyer_watson", "random"),
            ("green_sibson", "brio"), ("green_sibson", "random"),
            ("tanemura_merriam", "none"), ("cgal", "brio")]
OURS = [f for f in FAMILIES if f[0] != "cgal"]
PARABOLA = [("given", "parabola by decreasing t, inserted as given"),
            ("random", "the same points, random order"),
            ("ascending", "by increasing t (generate_points_2d's order), as given")]
COUNTERS = ["walk_steps/pt", "incircle_calls/pt", "orient_calls/pt", "flips/pt", "cavity/pt",
            "candidates/pt", "triangles/pt"]
SECONDS_PER_UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
STYLE = {  # colour per algorithm, line style per order
    "bowyer_watson": "tab:blue", "green_sibson": "tab:green",
    "tanemura_merriam": "tab:orange", "cgal": "black",
}
LINESTYLE = {"brio": "-", "none": "-", "random": "--", "given": "-", "ascending": ":"}


def family_label(algo, order):
    return algo if order in ("none",) or algo == "cgal" else f"{algo}/{order}"


class Results:
    """Medians per benchmark instance, keyed (algo, distribution, order, n)."""

    def __init__(self, data):
        self.context = data.get("context", {})
        self.time = {}       # key -> median CPU seconds
        self.cv = {}         # key -> coefficient of variation of the CPU time
        self.counters = {}   # key -> {counter: median value}
        self.bigo = {}       # (algo, dist, order) -> (big_o, cpu coefficient, time unit)
        self.rms = {}        # (algo, dist, order) -> rms
        self.errors = {}
        self.repetitions = 1
        raw = {}
        for entry in data.get("benchmarks", []):
            name = entry.get("run_name", entry.get("name", ""))
            self.repetitions = max(self.repetitions, int(entry.get("repetitions", 1) or 1))
            if entry.get("error_occurred"):
                self.errors[name] = entry.get("error_message", "error")
                continue
            parts = name.split("/")
            if not parts[0].startswith("BM_"):
                continue
            algo = parts[0][3:]
            aggregate = entry.get("aggregate_name")
            if aggregate in ("BigO", "RMS"):
                if len(parts) != 3:
                    continue
                family = (algo, parts[1], parts[2])
                if aggregate == "BigO":
                    self.bigo[family] = (entry.get("big_o", "?"), entry.get("cpu_coefficient"),
                                         entry.get("time_unit", "ns"))
                else:
                    self.rms[family] = entry.get("rms")
                continue
            if len(parts) != 4:
                continue
            key = (algo, parts[1], parts[2], int(parts[3]))
            seconds = float(entry["cpu_time"]) * SECONDS_PER_UNIT[entry.get("time_unit", "ns")]
            counters = {k: v for k, v in entry.items() if "/pt" in k or k.startswith("peak_")}
            if entry.get("run_type") == "aggregate":
                if aggregate == "median":
                    self.time[key] = seconds
                    self.counters[key] = counters
                elif aggregate == "cv":
                    self.cv[key] = float(entry["cpu_time"])
            else:
                raw.setdefault(key, []).append((seconds, counters))
        for key, runs in raw.items():
            if key in self.time:
                continue
            times = [t for t, _ in runs]
            self.time[key] = statistics.median(times)
            self.counters[key] = runs[0][1]
            if len(times) > 1 and statistics.mean(times) > 0:
                self.cv[key] = statistics.stdev(times) / statistics.mean(times)

    def sizes(self, algo, dist, order):
        return sorted(n for (a, d, o, n) in self.time if (a, d, o) == (algo, dist, order))

    def series(self, algo, dist, order):
        ns = self.sizes(algo, dist, order)
        return ns, [self.time[(algo, dist, order, n)] for n in ns]

    def counter(self, algo, dist, order, n, name):
        value = self.counters.get((algo, dist, order, n), {}).get(name)
        return None if value is None or (isinstance(value, float) and math.isnan(value)) else value


def slope(ns, ts, min_n=0):
    """Least-squares slope of log t against log n over the sizes >= min_n (None if < 3)."""
    pairs = [(math.log(n), math.log(t)) for n, t in zip(ns, ts) if n >= min_n and t > 0]
    if len(pairs) < 3:
        return None
    mx = sum(x for x, _ in pairs) / len(pairs)
    my = sum(y for _, y in pairs) / len(pairs)
    sxx = sum((x - mx) ** 2 for x, _ in pairs)
    return sum((x - mx) * (y - my) for x, y in pairs) / sxx if sxx > 0 else None


def fmt_seconds(s):
    if s is None:
        return "–"
    if s >= 10:
        return f"{s:.1f}"
    if s >= 0.1:
        return f"{s:.3f}"
    return f"{s:.2e}"


def fmt(value, digits=2):
    if value is None:
        return "–"
    return f"{value:.{digits}f}"


def fmt_n(n):
    log2 = round(math.log2(n))
    return f"2^{log2} ({n:,})" if 2 ** log2 == n else f"{n:,}"


def ratio(a, b):
    return None if a is None or b is None or b <= 0 else a / b


def table(header, rows, align=None):
    align = align or ["---"] + ["---:"] * (len(header) - 1)
    out = ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"]
    out += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return out


# ------------------------------------------------------------------------------------------
# Sections

def headline(res, out):
    out.append("## At the largest N")
    out.append("")
    for dist in DISTRIBUTIONS:
        cgal_ns = res.sizes("cgal", dist, "brio")
        ours_ns = set()
        for algo, order in OURS:
            ours_ns.update(res.sizes(algo, dist, order))
        common = sorted(set(cgal_ns) & ours_ns)
        if not common:
            continue
        n = common[-1]
        cgal_t = res.time.get(("cgal", dist, "brio", n))
        cgal_mem = res.counter("cgal", dist, "brio", n, "peak_bytes")
        rows = []
        best = None
        for algo, order in FAMILIES:
            t = res.time.get((algo, dist, order, n))
            if t is None:
                continue
            mem = res.counter(algo, dist, order, n, "peak_bytes")
            cv = res.cv.get((algo, dist, order, n))
            rows.append([family_label(algo, order), fmt_seconds(t),
                         fmt(ratio(t, cgal_t)) if algo != "cgal" else "1",
                         fmt(mem / 2**20 if mem else None, 1),
                         fmt(ratio(mem, n), 1), fmt(ratio(mem, cgal_mem)) if algo != "cgal" else "1",
                         "–" if cv is None else f"{100 * cv:.0f}%"])
            if algo != "cgal" and (best is None or t < best[1]):
                best = ((algo, order), t)
        out.append(f"### {dist}, N = {fmt_n(n)}")
        out.append("")
        out += table(["algorithm", "median s", "time / CGAL", "peak MiB", "peak B/pt",
                      "peak / CGAL", "CV"], rows)
        out.append("")
        if best and cgal_t:
            r = best[1] / cgal_t
            verdict = (f"{1 / r:.2f}x faster than CGAL" if r < 1 else f"{r:.2f}x slower than CGAL")
            out.append(f"**Fastest of ours at N = {n:,} ({dist}): {family_label(*best[0])}, "
                       f"{fmt_seconds(best[1])} s against CGAL's {fmt_seconds(cgal_t)} s: "
                       f"ratio {r:.2f}, {verdict}.**")
            tm = res.time.get(("tanemura_merriam", dist, "none", n))
            if tm is not None and best[0][0] != "tanemura_merriam":
                out.append(f"Tanemura-Merriam / our fastest: {tm / best[1]:.2f}; "
                           f"Tanemura-Merriam / CGAL: {tm / cgal_t:.2f}.")
            out.append("")


def time_tables(res, out):
    out.append("## Median CPU seconds by N, and time / CGAL")
    out.append("")
    for dist in DISTRIBUTIONS:
        families = [f for f in FAMILIES if res.sizes(f[0], dist, f[1])]
        if not families:
            continue
        ns = sorted({n for algo, order in families for n in res.sizes(algo, dist, order)})
        ours = [f for f in families if f[0] != "cgal"]
        has_cgal = ("cgal", "brio") in families
        header = ["N"] + [family_label(*f) for f in families]
        if has_cgal:
            header += [f"{family_label(*f)} / CGAL" for f in ours]
        rows = []
        for n in ns:
            row = [fmt_n(n)] + [fmt_seconds(res.time.get((a, dist, o, n))) for a, o in families]
            if has_cgal:
                cgal_t = res.time.get(("cgal", dist, "brio", n))
                row += [fmt(ratio(res.time.get((a, dist, o, n)), cgal_t)) for a, o in ours]
            rows.append(row)
        out.append(f"### {dist}")
        out.append("")
        out += table(header, rows)
        out.append("")


def exponent_tables(res, out):
    out.append("## Fitted exponents")
    out.append("")
    out.append("Slope of the least-squares line through (log n, log t) of the medians: 1 is "
               "linear, n log n over 2^10..2^20 shows as about 1.1. Also over n >= 2^14 only "
               "(past the caches), Google Benchmark's own fit of the named class (coefficient "
               "per n or n log2 n, and the RMS of its relative residuals), and t / (n log2 n), "
               "which stays flat for an n log n algorithm.")
    out.append("")
    rows = []
    for dist in DISTRIBUTIONS + ["parabola"]:
        fams = FAMILIES if dist != "parabola" else [("bowyer_watson", o) for o, _ in PARABOLA]
        for algo, order in fams:
            ns, ts = res.series(algo, dist, order)
            if len(ns) < 2:
                continue
            big_o, coefficient, unit = res.bigo.get((algo, dist, order), ("?", None, "ns"))
            rms = res.rms.get((algo, dist, order))
            per = [t / (n * math.log2(n)) * 1e9 for n, t in zip(ns, ts)]
            per_text = "–" if dist == "parabola" else f"{min(per):.1f}..{max(per):.1f}"
            rows.append([f"{dist}: {family_label(algo, order)}",
                         f"2^{round(math.log2(ns[0]))}..2^{round(math.log2(ns[-1]))}",
                         fmt(slope(ns, ts)), fmt(slope(ns, ts, 2**14)),
                         f"{coefficient:.3g} {unit} · {big_o}" if coefficient is not None else "–",
                         "–" if rms is None else f"{100 * rms:.0f}%", per_text])
    out += table(["family", "N", "exponent", "exponent n >= 2^14", "GB fit",
                  "GB RMS", "ns per n log2 n"], rows)
    out.append("")
    for dist in DISTRIBUTIONS:
        families = [f for f in FAMILIES if res.sizes(f[0], dist, f[1])]
        ns = sorted({n for algo, order in families for n in res.sizes(algo, dist, order)})
        if not ns:
            continue
        out.append(f"t / (n log2 n) in ns, {dist}:")
        out.append("")
        rows = []
        for n in ns:
            row = [fmt_n(n)]
            for algo, order in families:
                t = res.time.get((algo, dist, order, n))
                row.append(fmt(None if t is None else t / (n * math.log2(n)) * 1e9, 1))
            rows.append(row)
        out += table(["N"] + [family_label(*f) for f in families], rows)
        out.append("")


def counter_tables(res, out):
    out.append("## Work per point")
    out.append("")
    out.append("From one construction per benchmark (the counters are deterministic): "
               "triangles visited by the walk, incircle and orient2d evaluations, Lawson flips "
               "(Green-Sibson), cavity triangles (Bowyer-Watson), candidate points examined "
               "(Tanemura-Merriam), and finite triangles per point (a cross-check against CGAL).")
    out.append("")
    rows = []
    for dist in DISTRIBUTIONS:
        for algo, order in FAMILIES:
            ns = res.sizes(algo, dist, order)
            if not ns:
                continue
            n = ns[-1]
            rows.append([f"{dist}: {family_label(algo, order)}", fmt_n(n)] +
                        [fmt(res.counter(algo, dist, order, n, c)) for c in COUNTERS])
    out += table(["family", "N"] + COUNTERS, rows)
    out.append("")
    # The walk length shows the point-location cost that orders trade: BRIO keeps it O(1) per
    # point from the last insertion; a random order needs the grid jump-and-walk for that (the
    # plain walk would pay ~sqrt(n)).
    for dist in DISTRIBUTIONS:
        fams = [f for f in FAMILIES if f[0] != "cgal" and f[1] != "none" and
                res.sizes(f[0], dist, f[1])]
        ns = sorted({n for a, o in fams for n in res.sizes(a, dist, o)})
        if not ns:
            continue
        out.append(f"walk_steps/pt by N, {dist} (sqrt(n) shown for scale):")
        out.append("")
        rows = [[fmt_n(n)] + [fmt(res.counter(a, dist, o, n, "walk_steps/pt"), 1) for a, o in fams]
                + [f"{math.sqrt(n):.0f}"] for n in ns]
        out += table(["N"] + [family_label(*f) for f in fams] + ["sqrt(n)"], rows)
        out.append("")


def tanemura_merriam_table(res, out):
    """Tanemura-Merriam's search work by N: its uniform grid assumes evenly spread points."""
    ns = sorted({n for d in DISTRIBUTIONS for n in res.sizes("tanemura_merriam", d, "none")})
    if not ns:
        return
    out.append("Tanemura-Merriam's candidate search by N (candidates/pt and incircle_calls/pt): "
               "flat on uniform points; on Gaussian clusters its uniform grid, refined where "
               "the points crowd but to at most 4 cells per point, still holds many points per "
               "cell at small N (few, dense clusters in a large bounding box).")
    out.append("")
    rows = []
    for n in ns:
        row = [fmt_n(n)]
        for dist in DISTRIBUTIONS:
            row += [fmt(res.counter("tanemura_merriam", dist, "none", n, c), 1)
                    for c in ("candidates/pt", "incircle_calls/pt")]
        rows.append(row)
    out += table(["N"] + [f"{d} {c}" for d in DISTRIBUTIONS
                          for c in ("candidates/pt", "incircle_calls/pt")], rows)
    out.append("")


def memory_tables(res, out):
    out.append("## Peak memory, ours vs CGAL")
    out.append("")
    out.append("Peak live heap bytes during one construction above the level before it, the "
               "result still alive (every operator new/delete of the bench process counted via "
               "malloc_usable_size; see bench/delaunay2d_bench.cpp). The input points are not "
               "counted; CGAL's own copy of them (made for its spatial sort) is. Bytes per "
               "point, and ours / CGAL.")
    out.append("")
    verdicts = []
    for dist in DISTRIBUTIONS:
        fams = [f for f in FAMILIES if res.sizes(f[0], dist, f[1])]
        ours = [f for f in fams if f[0] != "cgal"]
        if ("cgal", "brio") not in fams:
            continue
        ns = sorted({n for a, o in fams for n in res.sizes(a, dist, o)})
        rows = []
        worst = {f: 0.0 for f in ours}
        for n in ns:
            cgal_mem = res.counter("cgal", dist, "brio", n, "peak_bytes")
            row = [fmt_n(n)]
            for a, o in fams:
                row.append(fmt(ratio(res.counter(a, dist, o, n, "peak_bytes"), n), 1))
            for f in ours:
                r = ratio(res.counter(f[0], dist, f[1], n, "peak_bytes"), cgal_mem)
                row.append(fmt(r))
                if r is not None:
                    worst[f] = max(worst[f], r)
            rows.append(row)
        out.append(f"### {dist}: peak bytes per point")
        out.append("")
        out += table(["N"] + [family_label(*f) for f in fams] +
                     [f"{family_label(*f)} / CGAL" for f in ours], rows)
        out.append("")
        for f, w in worst.items():
            verdicts.append(f"{dist} {family_label(*f)}: at most {w:.2f}x CGAL's peak "
                            f"({'no more than CGAL' if w <= 1.0 else 'MORE than CGAL'})")
    if verdicts:
        out.append("No more peak memory than CGAL, at every N:")
        out.append("")
        out += [f"- {v}" for v in verdicts]
        out.append("")


def parabola_section(res, out):
    fams = [(o, label) for o, label in PARABOLA if res.sizes("bowyer_watson", "parabola", o)]
    if not fams:
        return
    out.append("## The adversary: a parabola, Bowyer-Watson")
    out.append("")
    out.append("Points (t, t^2). The circle through three of them, at a < b < c, meets the "
               "parabola again at t = -(a + b + c) and contains the parabola exactly on "
               "(-(a + b + c), a) and (b, c). By decreasing t (all t >= 0), every new point "
               "lies in every circumcircle: the cavity is the whole triangulation, Theta(n^2). "
               "By increasing t (the order generate_points_2d lists them), no new point lies "
               "in any circumcircle: the cavity is one hull triangle, linear. Shuffled, the "
               "expected structural change is O(1) per point, but the walk from the last "
               "point crosses the fan around the leftmost point, O(n) per point without a "
               "location structure.")
    out.append("")
    ns = sorted({n for o, _ in fams for n in res.sizes("bowyer_watson", "parabola", o)})
    header = ["N"] + [f"{o} s" for o, _ in fams] + [f"{o} cavity/pt" for o, _ in fams] + \
        [f"{o} walk/pt" for o, _ in fams]
    rows = []
    for n in ns:
        row = [fmt_n(n)]
        row += [fmt_seconds(res.time.get(("bowyer_watson", "parabola", o, n))) for o, _ in fams]
        row += [fmt(res.counter("bowyer_watson", "parabola", o, n, "cavity/pt"), 1)
                for o, _ in fams]
        row += [fmt(res.counter("bowyer_watson", "parabola", o, n, "walk_steps/pt"), 1)
                for o, _ in fams]
        rows.append(row)
    out += table(header, rows)
    out.append("")
    for o, label in fams:
        ns_o, ts = res.series("bowyer_watson", "parabola", o)
        big_o, coefficient, unit = res.bigo.get(("bowyer_watson", "parabola", o), ("?", None, ""))
        rms = res.rms.get(("bowyer_watson", "parabola", o))
        fit = "" if coefficient is None else \
            f"; Google Benchmark's {big_o} fit: {coefficient:.3g} {unit} · {big_o}, RMS " \
            f"{100 * (rms or 0):.0f}%"
        out.append(f"- **{o}** ({label}): fitted exponent {fmt(slope(ns_o, ts))} "
                   f"(n >= 2^11: {fmt(slope(ns_o, ts, 2**11))}){fit}")
    out.append("")


def cross_check(res, out):
    """Triangle counts per (distribution, n) must agree across all algorithms and CGAL."""
    problems = []
    groups = {}
    for (algo, dist, order, n), counters in res.counters.items():
        value = counters.get("triangles/pt")
        if value is not None:
            groups.setdefault((dist, n), {})[family_label(algo, order)] = round(value * n)
    for (dist, n), counts in sorted(groups.items()):
        if len(set(counts.values())) > 1:
            problems.append(f"{dist} N={n}: {counts}")
    out.append("## Cross-check")
    out.append("")
    if problems:
        out.append("Triangle counts DISAGREE:")
        out += [f"- {p}" for p in problems]
    else:
        out.append(f"Every algorithm (and CGAL) returned the same number of triangles for each "
                   f"of the {len(groups)} (distribution, N) inputs.")
    out.append("")
    return problems


# ------------------------------------------------------------------------------------------
# Plots

def plot_time(res, path):
    fig, axes = plt.subplots(1, len(DISTRIBUTIONS), figsize=(13, 5.2), sharey=True)
    for ax, dist in zip(axes, DISTRIBUTIONS):
        for algo, order in FAMILIES:
            ns, ts = res.series(algo, dist, order)
            if not ns:
                continue
            e = slope(ns, ts)
            ax.loglog(ns, ts, marker="o", markersize=3.5, color=STYLE[algo],
                      linestyle=LINESTYLE[order], linewidth=2 if algo == "cgal" else 1.5,
                      label=f"{family_label(algo, order)} (exponent {fmt(e)})")
        ax.set_xscale("log", base=2)
        finish_axes(ax, f"{dist} points")
    axes[0].set_ylabel("median CPU seconds per construction")
    fig.suptitle("2D Delaunay construction time vs N (log-log)")
    save_figure(fig, path)


def plot_ratio(res, path):
    fig, axes = plt.subplots(1, len(DISTRIBUTIONS), figsize=(13, 5), sharey=True)
    for ax, dist in zip(axes, DISTRIBUTIONS):
        cgal_ns, cgal_ts = res.series("cgal", dist, "brio")
        cgal = dict(zip(cgal_ns, cgal_ts))
        for algo, order in OURS:
            ns, ts = res.series(algo, dist, order)
            pts = [(n, t / cgal[n]) for n, t in zip(ns, ts) if n in cgal]
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[1] for p in pts], marker="o", markersize=3.5,
                    color=STYLE[algo], linestyle=LINESTYLE[order],
                    label=family_label(algo, order))
        ax.axhline(1.0, color="black", linewidth=1.2, label="CGAL")
        ax.set_xscale("log", base=2)
        ax.set_yscale("log", base=2)
        ax.yaxis.set_major_formatter(FuncFormatter(lambda y, _: f"{y:g}"))
        finish_axes(ax, f"{dist} points")
    axes[0].set_ylabel("time ours / time CGAL (below 1: faster)")
    fig.suptitle("Construction time relative to CGAL Delaunay_triangulation_2<Epick>")
    save_figure(fig, path)


def plot_parabola(res, path):
    fig, ax = plt.subplots(figsize=(7.5, 5.5))
    colors = {"given": "tab:red", "random": "tab:purple", "ascending": "tab:gray"}
    for order, label in PARABOLA:
        ns, ts = res.series("bowyer_watson", "parabola", order)
        if not ns:
            continue
        ax.loglog(ns, ts, marker="o", markersize=4, color=colors[order],
                  label=f"{order}: {label} (exponent {fmt(slope(ns, ts))})")
    ns, ts = res.series("bowyer_watson", "parabola", "given")
    if ns:
        # Reference slopes through the first point of the given order.
        for power, style in ((2, "--"), (1, ":")):
            ax.loglog(ns, [ts[0] * (n / ns[0]) ** power for n in ns], color="black",
                      linestyle=style, linewidth=0.8, label=f"slope {power}")
    ax.set_xscale("log", base=2)
    ax.set_ylabel("median CPU seconds")
    finish_axes(ax, "Bowyer-Watson on (t, t²): sorted vs random insertion")
    save_figure(fig, path)


def make_picture(bench, cli, out_dir):
    """200 Gaussian points -> .node (bench helper) -> SVG (exactmesh triangulate)."""
    node = os.path.join(out_dir, "gaussian_200.node")
    svg = os.path.join(out_dir, "gaussian_200_green_sibson.svg")
    subprocess.run([bench, f"--write_node=gaussian,200,{node}"], check=True)
    subprocess.run([cli, "triangulate", node, "-o", svg, "--algorithm", "green-sibson"],
                   check=True, stdout=subprocess.DEVNULL)
    return os.path.basename(svg)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json_file", help="Google Benchmark JSON output of delaunay2d_bench")
    parser.add_argument("--out-dir", default="report")
    parser.add_argument("--bench", help="delaunay2d_bench binary (for the picture's .node)")
    parser.add_argument("--cli", help="exactmesh binary (renders the picture)")
    args = parser.parse_args()
    with open(args.json_file, encoding="utf-8") as handle:
        data = json.load(handle)
    res = Results(data)
    os.makedirs(args.out_dir, exist_ok=True)
    ctx = res.context

    out = ["# 2D Delaunay construction: exactmesh vs CGAL", ""]
    load = ctx.get("load_avg")
    out.append(
        f"Median CPU time of {res.repetitions} repetition{'s' if res.repetitions != 1 else ''} "
        f"per benchmark, all algorithms in one run of `delaunay2d_bench` "
        f"(inputs generated once, seed {ctx.get('exactmesh_input_seed', '?')}; only the "
        f"construction timed). Host `{ctx.get('host_name', '?')}`, {ctx.get('num_cpus', '?')} "
        f"CPUs at {ctx.get('mhz_per_cpu', '?')} MHz"
        f"{', load average ' + ', '.join(f'{x:.1f}' for x in load) if load else ''}, "
        f"{ctx.get('exactmesh_compiler', '?')}, {ctx.get('exactmesh_build_type', '?')} build, "
        f"CGAL {ctx.get('exactmesh_cgal', 'absent')}, {ctx.get('date', '?')}. N up to "
        f"2^{ctx.get('exactmesh_max_log2_points', '?')} (EXACTMESH_BENCH_MAX_LOG2); the random "
        f"order up to 2^{ctx.get('exactmesh_random_max_log2_points', '?')} "
        f"(EXACTMESH_BENCH_RANDOM_MAX_LOG2), located by the grid jump-and-walk "
        f"(see walk steps below). "
        f"Heap {ctx.get('exactmesh_heap', '?')} (warm: freed memory stays resident, so no "
        f"construction pays page faults; EXACTMESH_BENCH_COLD_HEAP=1 for cold); repetitions "
        f"{'randomly interleaved' if ctx.get('exactmesh_interleaved') == 'yes' else 'in sequence'}"
        f" across benchmarks.")
    out.append("")
    out.append("Orders: brio = our BRIO + Hilbert rounds; random = a uniform shuffle; "
               "tanemura_merriam orders nothing; cgal = `Delaunay_triangulation_2<Epick>` built "
               "from the point range (CGAL spatially sorts it). Ratios below 1: ours faster.")
    out.append("")
    out.append("![time vs N](delaunay2d_time.png)")
    out.append("")
    out.append("![ratio vs CGAL](delaunay2d_ratio.png)")
    out.append("")
    headline(res, out)
    time_tables(res, out)
    scaling_section(data.get("benchmarks", []), out, args.out_dir, "delaunay2d", "cgal", "CGAL",
                    same_threads=False)
    floor_section(data.get("benchmarks", []), out)
    exponent_tables(res, out)
    counter_tables(res, out)
    tanemura_merriam_table(res, out)
    memory_tables(res, out)
    parabola_section(res, out)
    out.append("![parabola](delaunay2d_parabola.png)")
    out.append("")
    problems = cross_check(res, out)

    plot_time(res, os.path.join(args.out_dir, "delaunay2d_time.png"))
    plot_ratio(res, os.path.join(args.out_dir, "delaunay2d_ratio.png"))
    plot_parabola(res, os.path.join(args.out_dir, "delaunay2d_parabola.png"))
    if args.bench and args.cli:
        svg = make_picture(args.bench, args.cli, args.out_dir)
        out.append("## Picture")
        out.append("")
        out.append(f"200 Gaussian points (`generate_points_2d(gaussian, 200, "
                   f"{ctx.get('exactmesh_input_seed', '?')})`), Green-Sibson, drawn by "
                   f"`exactmesh triangulate gaussian_200.node -o {svg} --algorithm green-sibson`:")
        out.append("")
        out.append(f"![200 Gaussian points]({svg})")
        out.append("")

    if res.errors:
        out.append("## Errors")
        out.append("")
        out += [f"- {name}: {message}" for name, message in sorted(res.errors.items())]
        out.append("")
    with open(os.path.join(args.out_dir, "delaunay2d.md"), "w", encoding="utf-8") as handle:
        handle.write("\n".join(out))
    for name, message in sorted(res.errors.items()):
        print(f"error: {name}: {message}", file=sys.stderr)
    for problem in problems:
        print(f"error: triangle counts disagree: {problem}", file=sys.stderr)
    return 1 if res.errors or problems else 0


if __name__ == "__main__":
    sys.exit(main())
