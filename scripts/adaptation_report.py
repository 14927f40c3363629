#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Markdown report and plots of solution-adaptive meshing (issue 13).

Usage:
  adaptation_convergence report/adaptation_convergence.json
  adaptation_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
      --benchmark_format=json --benchmark_out=report/adaptation_bench.json
  scripts/adaptation_report.py report/adaptation_convergence.json report/adaptation_bench.json \
      --out-dir report [--cli build/release/cli/exactmesh]

Writes into --out-dir:
  adaptation.md                 the set-up, the goals of issue 13 (met / not met, with the
                                figures), per field the final error of every indicator x method
                                against the uniform mesh at the same vertex count and the fitted
                                slope of error vs N over the cycles, the transient run's
                                statistics, the time of one cycle against regeneration;
  adaptation_<field>.png        max and L2 error vs vertices, log-log, one panel per indicator:
                                every method's cycles, the uniform baseline, an N^-1 slope;
  adaptation_transient.png      vertex count and max error per step of the transient run;
  adaptation_front_<m>.svg      (with --cli) the front field's mesh after insertion and steiner
                                cycles from the coarse initial mesh, drawn by `exactmesh adapt`.
Exits 1 when a run reported a problem (an exception or a failed exact check), after writing.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from report_markdown import fmt, table  # noqa: E402  (scripts/, beside this one)

METHODS = ["insertion", "h-refinement", "steiner", "remesh", "local-remesh"]
INDICATORS = ["first-difference", "second-difference", "loehner", "length-weighted"]
COLORS = {"insertion": "tab:blue", "h-refinement": "tab:orange", "steiner": "tab:green",
          "remesh": "tab:red", "local-remesh": "tab:purple"}
SECONDS_PER_UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
TRANSIENT_BAND = 0.15
ERROR_RATIO_GOAL = 0.1
SLOPE_GOAL = -1.0
TIME_RATIO_GOAL = 0.2


def fit_slope(points):
    """Least-squares slope of log(err) vs log(N) over (N, err) points (None with < 2)."""
    pts = [(math.log(n), math.log(e)) for n, e in points if n > 0 and e and e > 0]
    if len(pts) < 2:
        return None
    mx = sum(p[0] for p in pts) / len(pts)
    my = sum(p[1] for p in pts) / len(pts)
    sxx = sum((p[0] - mx) ** 2 for p in pts)
    if sxx == 0:
        return None
    return sum((p[0] - mx) * (p[1] - my) for p in pts) / sxx


def uniform_at(uniform, field, n, key):
    """The uniform baseline's error at n vertices, log-log interpolated (or extrapolated from the
    nearest two meshes)."""
    pts = sorted((u["vertices"], u[key]) for u in uniform if u["field"] == field)
    if len(pts) < 2:
        return None
    for i in range(len(pts) - 1):
        if pts[i][0] <= n <= pts[i + 1][0] or i == len(pts) - 2 or n < pts[0][0]:
            (n0, e0), (n1, e1) = pts[i], pts[i + 1]
            if n < pts[0][0]:
                (n0, e0), (n1, e1) = pts[0], pts[1]
            s = math.log(e1 / e0) / math.log(n1 / n0)
            return e0 * (n / n0) ** s
    return None


def final(run):
    return run["cycles"][-1]


def run_rows(conv, field):
    rows = []
    for run in conv["runs"]:
        if run["field"] != field or not run["cycles"]:
            continue
        last = final(run)
        u_max = uniform_at(conv["uniform"], field, last["vertices"], "max_error")
        u_l2 = uniform_at(conv["uniform"], field, last["vertices"], "l2_error")
        rows.append({
            "run": run, "vertices": last["vertices"], "max": last["max_error"],
            "l2": last["l2_error"], "u_max": u_max, "u_l2": u_l2,
            "ratio_max": last["max_error"] / u_max if u_max else None,
            "ratio_l2": last["l2_error"] / u_l2 if u_l2 else None,
            "slope_max": fit_slope([(c["vertices"], c["max_error"]) for c in run["cycles"]]),
            "slope_l2": fit_slope([(c["vertices"], c["l2_error"]) for c in run["cycles"]]),
            "cycles": len(run["cycles"]) - 1, "seconds": last["seconds"],
        })
    return rows


def best_row(rows):
    """The run with the smallest max error relative to the uniform mesh at its vertex count, of
    those that at least doubled the vertex count (a slope over a narrower range means nothing)."""
    rows = [r for r in rows if r["ratio_max"] is not None and r["cycles"] > 0
            and r["vertices"] >= 2 * r["run"]["cycles"][0]["vertices"]]
    return min(rows, key=lambda r: r["ratio_max"]) if rows else None


def plot_field(conv, field, path):
    fig, axes = plt.subplots(2, 4, figsize=(18, 8), sharex=True)
    uni = sorted((u["vertices"], u["max_error"], u["l2_error"]) for u in conv["uniform"]
                 if u["field"] == field)
    for col, indicator in enumerate(INDICATORS):
        for row, key in enumerate(["max_error", "l2_error"]):
            ax = axes[row][col]
            for run in conv["runs"]:
                if run["field"] != field or run["indicator"] != indicator:
                    continue
                xs = [c["vertices"] for c in run["cycles"]]
                ys = [c[key] for c in run["cycles"]]
                ax.loglog(xs, ys, "o-", ms=3, color=COLORS[run["method"]], label=run["method"])
            ax.loglog([u[0] for u in uni], [u[1 + row] for u in uni], "k--", lw=1.5,
                      label="uniform")
            if uni:
                n0, e0 = uni[0][0], uni[0][1 + row]
                n1 = uni[-1][0]
                ax.loglog([n0, n1], [e0, e0 * (n1 / n0) ** -1], color="gray", lw=1, ls=":",
                          label="N^-1")
            ax.set_title(f"{indicator}: {'max' if row == 0 else 'L2'} error", fontsize=10)
            if row == 1:
                ax.set_xlabel("vertices")
            ax.grid(True, which="both", alpha=0.3)
    axes[0][0].legend(fontsize=8)
    fig.suptitle(f"{field}: interpolation error vs vertices (every cycle), uniform baseline dashed")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def transient_stats(run, skip=0, budget=0):
    counts = [s["vertices"] for s in run["steps"] if s["step"] >= 1 + skip]
    if not counts:
        return None
    mean = statistics.mean(counts)
    return {"mean": mean, "min": min(counts), "max": max(counts),
            "at_budget": sum(1 for c in counts if budget and c >= 0.95 * budget),
            "dev": max(abs(c / mean - 1) for c in counts), "steps": len(counts),
            "max_error_median": statistics.median(
                s["max_error"] for s in run["steps"] if s["step"] >= 1 + skip),
            "max_error_max": max(s["max_error"] for s in run["steps"] if s["step"] >= 1 + skip),
            "seconds": statistics.median(
                s["seconds"] for s in run["steps"] if s["step"] >= 1 + skip)}


def plot_transient(conv, path):
    fig, axes = plt.subplots(1, 2, figsize=(13, 4.5))
    for run in conv["transient"]:
        steps = [s["step"] for s in run["steps"]]
        color = COLORS.get(run["method"], "black")
        axes[0].plot(steps, [s["vertices"] for s in run["steps"]], color=color,
                     label=run["method"])
        st = transient_stats(run)
        if st:
            axes[0].axhspan(st["mean"] * (1 - TRANSIENT_BAND), st["mean"] * (1 + TRANSIENT_BAND),
                            color=color, alpha=0.1)
        axes[1].semilogy(steps, [s["max_error"] for s in run["steps"]], color=color,
                         label=f"{run['method']} max")
        axes[1].semilogy(steps, [s["l2_error"] for s in run["steps"]], color=color, ls="--",
                         label=f"{run['method']} L2")
    axes[0].set_title("vertices per step (band: mean ± 15%)")
    axes[1].set_title("interpolation error per step")
    for ax in axes:
        ax.set_xlabel("step")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def bench_times(bench):
    """name -> (median seconds, counters) from the aggregates (or raw repetitions)."""
    raw = defaultdict(list)
    counters = {}
    medians = {}
    for b in bench.get("benchmarks", []):
        name = b.get("run_name", b["name"]).replace("/manual_time", "")
        if b.get("error_occurred"):
            raise SystemExit(f"benchmark {name} failed: {b.get('error_message')}")
        seconds = b["real_time"] * SECONDS_PER_UNIT[b.get("time_unit", "ns")]
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                medians[name] = seconds
                counters[name] = b
        else:
            raw[name].append(seconds)
            counters.setdefault(name, b)
    for name, values in raw.items():
        medians.setdefault(name, statistics.median(values))
    return medians, counters


def time_section(bench, out):
    medians, counters = bench_times(bench)
    rows, ratios = [], {}
    init = medians.get("BM_generate_initial")
    for m in METHODS:
        cycle, regen = medians.get(f"BM_adapt_cycle/{m}"), medians.get(f"BM_regenerate/{m}")
        if cycle is None or regen is None:
            continue
        c, r = counters[f"BM_adapt_cycle/{m}"], counters[f"BM_regenerate/{m}"]
        ratios[m] = cycle / regen
        rows.append([m, f"{int(c['vertices_before'])}", f"{int(c['vertices'])} / {int(c['triangles'])}",
                     f"{cycle * 1e3:.1f}", f"{int(r['vertices'])} / {int(r['triangles'])}",
                     f"{regen * 1e3:.1f}", f"{cycle / regen:.2f}",
                     "yes" if cycle / regen <= TIME_RATIO_GOAL else "no",
                     f"{cycle / init:.2f}" if init else "n/a"])
    out.append("## Time of one cycle against regeneration from scratch\n")
    out.append(
        "`adaptation_bench`, one run, medians of the repetitions (manual wall time, one thread). "
        "Start: the NACA 0012 domain meshed by Delaunay refinement at the uniform size h0 = "
        f"{fmt(counters.get('BM_generate_initial', {}).get('h0'))} "
        f"({int(counters['BM_generate_initial']['vertices']) if 'BM_generate_initial' in counters else 0} "
        f"vertices, {int(counters['BM_generate_initial']['triangles']) if 'BM_generate_initial' in counters else 0} "
        f"triangles, generated in {fmt(init * 1e3 if init else None)} ms), the front field, "
        "second-difference indicator, threshold 1. *Cycle*: one cycle of the method, everything "
        "it does including sampling the field at the new vertices. *From scratch*: Delaunay "
        "refinement of the same domain PSLG with a background size (linear over the adapted "
        "mesh; vertex values its local spacing, scaled by one factor calibrated outside the "
        "clock so that the vertex count matches), timed from building the size function to "
        "the field sampled on the new mesh.\n")
    out.append(table(["method", "vertices before", "after cycle (V / T)", "cycle ms",
                      "from scratch (V / T)", "from scratch ms", "cycle / scratch", "<= 1/5",
                      "cycle / uniform initial"], rows))
    out.append(
        "\n*cycle / uniform initial*: the cycle against generating the initial mesh (uniform "
        "size, no background mesh), for scale: most of *from scratch* is the graded size "
        "(a background-mesh query per size evaluation) and the larger, graded mesh; the "
        "uniform initial mesh is the cheapest mesh of that vertex count the generator makes. "
        "The spread of the repetitions is in the JSON (cv aggregates).\n")
    return ratios


def pictures(cli, conv, out_dir, out):
    made = []
    for method in ["insertion", "steiner"]:
        name = f"adaptation_front_{method}.svg"
        done = subprocess.run(
            [cli, "adapt", "--domain", "naca0012", "--size", str(conv["h0"]), "--field",
             "tanh(50 * (x * cos(_pi / 6) + y * sin(_pi / 6) - 0.5))", "--method", method,
             "--cycles", "6", "--max-vertices", "20000", "-o", os.path.join(out_dir, name)],
            capture_output=True, text=True)
        if done.returncode == 0:
            made.append(f"![front, {method}]({name})")
        else:
            print(f"picture {name}: {done.stderr.strip()}", file=sys.stderr)
    if made:
        out.append("## Pictures\n")
        out.append("The front field after up to 6 cycles (budget 20000 vertices) from the "
                   "initial mesh, drawn by `exactmesh adapt ... -o X.svg`.\n")
        out.extend(m + "\n" for m in made)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("convergence")
    parser.add_argument("bench")
    parser.add_argument("--out-dir", default="report")
    parser.add_argument("--cli")
    args = parser.parse_args()
    with open(args.convergence) as f:
        conv = json.load(f)
    with open(args.bench) as f:
        bench = json.load(f)
    os.makedirs(args.out_dir, exist_ok=True)
    problems = [f"{r['field']} {r['indicator']} {r['method']}: {r['problem']}"
                for r in conv["runs"] if r.get("problem")]
    problems += [f"transient {r['method']}: {r['problem']}" for r in conv["transient"]
                 if r.get("problem")]

    fields = [f["name"] for f in conv["fields"]]
    per_field = {f: run_rows(conv, f) for f in fields}
    for f in fields:
        plot_field(conv, f, os.path.join(args.out_dir, f"adaptation_{f}.png"))
    plot_transient(conv, os.path.join(args.out_dir, "adaptation_transient.png"))

    body = []
    ratios = time_section(bench, body)
    budget = conv["budget"]
    transient = {r["method"]: (transient_stats(r, 0, r.get("budget", budget)),
                               transient_stats(r, 10, r.get("budget", budget)))
                 for r in conv["transient"]}
    transient_budget = conv["transient"][0].get("budget", budget) if conv["transient"] else budget

    # The goals.
    goal_rows = []
    front_best = best_row(per_field.get("front", []))
    if front_best:
        r = front_best
        goal_rows.append([
            "front: best max error <= 1/10 of uniform at equal N",
            f"{r['run']['method']} + {r['run']['indicator']}: {fmt(r['max'])} at N = "
            f"{r['vertices']}, uniform {fmt(r['u_max'])} (ratio {fmt(r['ratio_max'], 2)})",
            "met" if r["ratio_max"] <= ERROR_RATIO_GOAL else "not met"])
    for f in fields:
        b = best_row(per_field[f])
        if not b:
            continue
        steep = [r for r in per_field[f] if r["slope_max"] is not None and r["slope_max"] <= SLOPE_GOAL]
        goal_rows.append([
            f"{f}: max error falls at least like N^-1 over the cycles",
            f"best ({b['run']['method']} + {b['run']['indicator']}): slope {fmt(b['slope_max'], 2)} "
            f"(L2 {fmt(b['slope_l2'], 2)}) over {b['cycles']} cycles, N {b['run']['cycles'][0]['vertices']}"
            f" -> {b['vertices']}; {len(steep)} of {len(per_field[f])} runs at or below -1",
            "met" if b["slope_max"] is not None and b["slope_max"] <= SLOPE_GOAL else "not met"])
    for m, (all_steps, settled) in transient.items():
        if not all_steps:
            continue
        goal_rows.append([
            f"transient {m}: vertices within ±15% of their mean over {all_steps['steps']} steps",
            f"mean {all_steps['mean']:.0f}, min {all_steps['min']}, max {all_steps['max']}: "
            f"largest deviation {100 * all_steps['dev']:.1f}%"
            + (f" (steps 11-{10 + settled['steps']}: {100 * settled['dev']:.1f}%)" if settled else "")
            + f"; {all_steps['at_budget']} of {all_steps['steps']} steps at >= 95% of the vertex "
            f"budget {transient_budget}" + (" (the budget, not the method, holds the count there)"
                                  if all_steps["at_budget"] > all_steps["steps"] // 2 else ""),
            "met" if all_steps["dev"] <= TRANSIENT_BAND else "not met"])
    for m, ratio in ratios.items():
        goal_rows.append([f"{m}: one cycle <= 1/5 of regenerating from scratch",
                          f"ratio {ratio:.2f}", "met" if ratio <= TIME_RATIO_GOAL else "not met"])

    out = ["# Solution-adaptive meshing (issue 13)\n"]
    out.append(
        f"Domain: the built-in NACA 0012 (chord (0, 0)-(1, 0), far-field box [-1.5, 2.5] x [-2, 2]). "
        f"Initial mesh: {conv['generator']} at the uniform size h0 = {conv['h0']} "
        f"({conv['runs'][0]['cycles'][0]['vertices']} vertices), the boundary discretized at h0. "
        f"Every run: up to {conv['max_cycles']} cycles, threshold {conv['threshold']} x the mean "
        f"indicator, vertex budget {conv['budget']}; a run stops when a cycle changes nothing or "
        "the mesh is within 5% of the budget. Error: the piecewise-linear interpolant of the "
        "field's vertex values against the field at every triangle's centroid and every edge's "
        "midpoint (max, and the area-weighted RMS as L2; generators/adaptation/"
        "interpolation_error.hpp). Uniform baseline: the same generator at uniform sizes h0 / "
        "2^(k/4), k = 0..12, each its own boundary discretization. Fields:\n")
    for f in conv["fields"]:
        out.append(f"- **{f['name']}**: {f['formula']}")
    out.append(
        "\nThe boundary layer's d is an approximation: with xc = clamp(x, 0, 1), d = hypot(x - xc, "
        "max(|y| - y_t(xc), 0)), the vertical distance above the surface over the chord (exact "
        "only where the surface is flat; continuous). The singularity omits the angular factor "
        "sin(2θ/3): its branch cut would cross the domain ahead of the leading edge.\n")
    out.append("## Goals\n")
    out.append(table(["goal", "measured", "verdict"], goal_rows))
    out.append("")
    if problems:
        out.append("**Problems reported by runs:**\n")
        out.extend(f"- {p}" for p in problems)
        out.append("")
    for f in fields:
        out.append(f"## Field {f}\n")
        out.append(f"![{f}](adaptation_{f}.png)\n")
        out.append("Last cycle of each run; *uniform* is the baseline's error at the same vertex "
                   "count (log-log interpolation); *slope* the least-squares slope of log error "
                   "vs log N over the run's cycles (cycle 0 included).\n")
        rows = []
        for r in sorted(per_field[f], key=lambda r: (r["ratio_max"] is None, r["ratio_max"] or 0)):
            rows.append([r["run"]["method"], r["run"]["indicator"], r["cycles"], r["vertices"],
                         fmt(r["max"]), fmt(r["u_max"]), fmt(r["ratio_max"], 2), fmt(r["l2"]),
                         fmt(r["u_l2"]), fmt(r["ratio_l2"], 2), fmt(r["slope_max"], 2),
                         fmt(r["slope_l2"], 2), fmt(r["seconds"], 2)])
        out.append(table(["method", "indicator", "cycles", "vertices", "max err", "uniform max",
                          "ratio", "L2 err", "uniform L2", "ratio", "slope max", "slope L2",
                          "cycles s"], rows))
        out.append("")
    out.append("## Transient: the front moving\n")
    out.append(
        "The front tanh(50 (x cos 30° + y sin 30° - c)), c = -0.5 + t, t = k dt, dt = "
        f"{conv['transient'][0]['dt'] if conv['transient'] else '?'}, from the mesh adapted at t = 0 "
        f"(up to {conv['transient'][0].get('initial_cycles', 0) if conv['transient'] else '?'} cycles); "
        "each step as `exactmesh adapt --steps` (`--derefine` for insertion and h-refinement): the "
        "field resampled; insertion and h-refinement then derefine (passes until one removes "
        "nothing) where every edge is below 0.1 x the refinement threshold, Steiner restart and "
        "remeshing coarsen through their size field; then up to "
        f"{conv['transient'][0]['cycles_per_step'] if conv['transient'] else '?'} refinement "
        "cycles. Thresholds and size targets are fixed to the first mesh's mean second-difference "
        f"indicator; the vertex budget is {transient_budget} (a safety net).\n")
    out.append("![transient](adaptation_transient.png)\n")
    rows = []
    for m, (a, s) in transient.items():
        if a:
            rows.append([m, f"{a['mean']:.0f}", a["min"], a["max"], a["at_budget"],
                         f"{100 * a['dev']:.1f}%",
                         f"{100 * s['dev']:.1f}%" if s else "n/a", fmt(a["max_error_median"]),
                         fmt(a["max_error_max"]), f"{a['seconds'] * 1e3:.1f}"])
    out.append(table(["method", "mean vertices", "min", "max", "steps at >= 95% budget",
                      "largest deviation",
                      "deviation, steps 11-100", "median max error", "largest max error",
                      "median ms per step"], rows))
    out.append("")
    out.extend(body)
    if args.cli:
        pictures(args.cli, conv, args.out_dir, out)
    path = os.path.join(args.out_dir, "adaptation.md")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")
    print(f"wrote {path}", file=sys.stderr)
    for p in problems:
        print(f"problem: {p}", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
