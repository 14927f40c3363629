# SPDX-License-Identifier: MIT
"""The strong-scaling section of the Delaunay reports (issue 17), shared by delaunay_report.py
(2D) and delaunay3d_report.py (3D).

Reads the rows named BM_<algo>_<T>_threads/<distribution>[/<order>]/<n>[/real_time] of the
benchmark JSON (raw repetitions, or the median aggregates of --benchmark_report_aggregates_only),
the median real (wall-clock) seconds of each, and writes a table (n, threads, median real seconds,
speed-up over our one thread T1/T_T, efficiency T1/(T*T_T), the peer's seconds and the ratio ours /
peer, peak heap bytes per point) and two plots: time vs threads per n, efficiency vs threads. The
peer is CGAL's Parallel_tag triangulation at the same thread count (3D), or CGAL's sequential
construction at every thread count (2D, where CGAL has no parallel triangulation). A JSON without
such rows (older files) gives no section and no plots.

The memory floor section (floor_section) reads the rows BM_memory_floor_<memory>/<distribution>
[/<order>]/<n>[/real_time] (bench/memory_floor.hpp: memory warm, fresh or fresh_huge_pages) and
writes, per distribution and n, the floor's median real seconds in each memory, the megabytes it
writes, our one-thread time and its ratio to the warm and the fresh floor.
"""

import os
import re
import statistics

from report_markdown import fmt, table
from report_plots import finish_axes, plt, save_figure

NAME = re.compile(r"^BM_(?P<algo>[a-z_]+?)_(?P<threads>\d+)_threads/(?P<dist>[a-z_]+)/"
                  r"(?:[a-z_]+/)?(?P<n>\d+)(?:/real_time)?$")
FLOOR_NAME = re.compile(r"^BM_memory_floor_(?P<memory>[a-z_]+)/(?P<dist>[a-z_]+)/"
                        r"(?:[a-z_]+/)?(?P<n>\d+)(?:/real_time)?$")
FLOOR_MEMORY = ("warm", "fresh", "fresh_huge_pages")
SECONDS_PER_UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
OURS = "bowyer_watson"


def median_real_seconds(benchmarks, pattern, key_of):
    """The median real seconds of the rows whose name matches `pattern`, keyed key_of(match)
    (the median of the raw repetitions, else the median aggregate), and each key's last entry."""
    raw, aggregated, entries = {}, {}, {}
    for entry in benchmarks:
        match = pattern.match(entry.get("run_name", entry.get("name", "")))
        if match is None or entry.get("error_occurred"):
            continue
        key = key_of(match)
        seconds = float(entry["real_time"]) * SECONDS_PER_UNIT[entry.get("time_unit", "ns")]
        if entry.get("run_type") == "aggregate":
            if entry.get("aggregate_name") != "median":
                continue
            aggregated[key] = seconds
        else:
            raw.setdefault(key, []).append(seconds)
        entries[key] = entry
    seconds = dict(aggregated)
    seconds.update({key: statistics.median(times) for key, times in raw.items()})
    return seconds, entries


class Scaling:
    """Median real seconds and peak heap bytes per point, keyed (algo, distribution, n, T)."""

    def __init__(self, benchmarks):
        self.seconds, entries = median_real_seconds(
            benchmarks, NAME,
            lambda m: (m["algo"], m["dist"], int(m["n"]), int(m["threads"])))
        self.peak_per_point = {key: entry["peak_bytes/pt"] for key, entry in entries.items()
                               if entry.get("peak_bytes/pt") is not None}

    def distributions(self):
        return sorted({d for a, d, _, _ in self.seconds if a == OURS},
                      key=lambda d: (d != "uniform", d))

    def sizes(self, dist):
        return sorted({n for a, d, n, _ in self.seconds if (a, d) == (OURS, dist)})

    def threads(self, algo, dist, n):
        return sorted(t for a, d, m, t in self.seconds if (a, d, m) == (algo, dist, n))

    def speedup(self, algo, dist, n, threads):
        """T1 / T_T of `algo` (None without both)."""
        one, many = self.seconds.get((algo, dist, n, 1)), self.seconds.get((algo, dist, n, threads))
        return None if one is None or not many else one / many


def peer_seconds(scaling, peer, same_threads, dist, n, threads):
    """The peer's time to compare ours on `threads` threads with."""
    return scaling.seconds.get((peer, dist, n, threads if same_threads else 1))


def scaling_table(scaling, peer, peer_label, same_threads):
    header = ["distribution", "n", "threads", "median real s", "speed-up", "efficiency",
              f"{peer_label} s", f"ours / {peer_label}", "peak B/pt"]
    rows = []
    for dist in scaling.distributions():
        for n in scaling.sizes(dist):
            for threads in scaling.threads(OURS, dist, n):
                seconds = scaling.seconds[(OURS, dist, n, threads)]
                speedup = scaling.speedup(OURS, dist, n, threads)
                other = peer_seconds(scaling, peer, same_threads, dist, n, threads)
                peak = scaling.peak_per_point.get((OURS, dist, n, threads))
                rows.append([dist, f"{n:,}", threads, fmt(seconds),
                             "–" if speedup is None else f"{speedup:.2f}",
                             "–" if speedup is None else f"{speedup / threads:.2f}",
                             fmt(other) if other else "–",
                             f"{seconds / other:.2f}" if other else "–",
                             "–" if peak is None else f"{peak:.0f}"])
    return table(header, rows)


def plot_scaling(scaling, peer, peer_label, same_threads, kind, path):
    """kind "time": median real seconds vs threads per n (log y), with the ideal T1/T; kind
    "efficiency": T1/(T*T_T) vs threads. Ours solid, the peer dashed (dotted when sequential)."""
    dists = scaling.distributions()
    fig, axes = plt.subplots(1, len(dists), figsize=(6.5 * len(dists), 5), sharey=True,
                             squeeze=False)
    max_threads = 1
    for ax, dist in zip(axes[0], dists):
        for index, n in enumerate(scaling.sizes(dist)):
            color = f"C{index}"
            for algo, label, style in ((OURS, "ours", "-"), (peer, peer_label, "--")):
                ts = scaling.threads(algo, dist, n)
                if kind == "time" and algo == peer and not same_threads and 1 in ts:
                    ax.axhline(scaling.seconds[(algo, dist, n, 1)], color=color, linestyle=":",
                               label=f"{label} sequential, n = {n:,}")
                    continue
                if algo == peer and not same_threads:
                    continue
                if kind == "time":
                    values = [scaling.seconds[(algo, dist, n, t)] for t in ts]
                else:
                    ts = [t for t in ts if scaling.speedup(algo, dist, n, t) is not None]
                    values = [scaling.speedup(algo, dist, n, t) / t for t in ts]
                if not ts:
                    continue
                max_threads = max(max_threads, ts[-1])
                ax.plot(ts, values, marker="o" if algo == OURS else "s", markersize=4,
                        color=color, linestyle=style, label=f"{label}, n = {n:,}")
            one = scaling.seconds.get((OURS, dist, n, 1))
            ts = scaling.threads(OURS, dist, n)
            if kind == "time" and one is not None and len(ts) > 1:
                ax.plot(ts, [one / t for t in ts], color=color, linestyle="-", linewidth=0.6,
                        alpha=0.5)
        if kind == "time":
            ax.set_yscale("log")
        else:
            ax.axhline(1.0, color="black", linewidth=1.0, label="ideal (1)")
            ax.set_ylim(0, 1.1)
        ax.set_xticks(range(1, max_threads + 1))
        finish_axes(ax, f"{dist} points", xlabel="threads",
                    legend_loc="best" if kind == "time" else "lower left")
    if kind == "time":
        axes[0][0].set_ylabel("median real seconds (thin lines: ours T1 / T, ideal)")
        fig.suptitle("Strong scaling: construction time vs threads")
    else:
        axes[0][0].set_ylabel("efficiency T1 / (T · T_T)")
        fig.suptitle("Strong scaling: per-thread efficiency vs threads")
    save_figure(fig, path)


def scaling_section(benchmarks, out, out_dir, prefix, peer, peer_label, same_threads):
    """Appends the section to the Markdown lines `out` and writes <prefix>_scaling_time.png and
    <prefix>_scaling_efficiency.png into out_dir; nothing without scaling rows of ours."""
    scaling = Scaling(benchmarks)
    if not scaling.distributions():
        return
    compared = (f"{peer_label} on the same number of threads" if same_threads else
                f"{peer_label} on one thread (sequential) for every thread count")
    out.append("## Strong scaling (issue 17)")
    out.append("")
    out.append("Rows `BM_bowyer_watson_<T>_threads`: median real (wall-clock) seconds of the "
               "repetitions; T = 1 runs the sequential code. Speed-up = T1 / T_T (our one "
               "thread over our T threads), efficiency = T1 / (T · T_T) (1 is ideal); ours / "
               f"{peer_label} = our time over that of {compared} (below 1: ours faster). "
               "Real time counts the waits of a thread preempted by other load: on a shared "
               "machine these figures are noisy.")
    out.append("")
    out.append(scaling_table(scaling, peer, peer_label, same_threads))
    out.append("")
    for kind in ("time", "efficiency"):
        name = f"{prefix}_scaling_{kind}.png"
        plot_scaling(scaling, peer, peer_label, same_threads, kind, os.path.join(out_dir, name))
        out.append(f"![strong scaling: {kind} vs threads]({name})")
        out.append("")


def floor_section(benchmarks, out):
    """Appends the memory floor section to the Markdown lines `out`; nothing without floor
    rows."""
    seconds, entries = median_real_seconds(
        benchmarks, FLOOR_NAME, lambda m: (m["memory"], m["dist"], int(m["n"])))
    if not seconds:
        return
    scaling = Scaling(benchmarks)
    header = ["distribution", "n"] + [f"floor {memory} s" for memory in FLOOR_MEMORY] + [
        "MB written", "ours, 1 thread s", "ours / warm floor", "ours / fresh floor"]
    rows = []
    for dist, n in sorted({(d, m) for _, d, m in seconds}, key=lambda k: (k[0] != "uniform", k)):
        floor = {memory: seconds.get((memory, dist, n)) for memory in FLOOR_MEMORY}
        written = next((entries[(memory, dist, n)].get("MB_written") for memory in FLOOR_MEMORY
                        if (memory, dist, n) in entries), None)
        ours = scaling.seconds.get((OURS, dist, n, 1))
        ratio = lambda f: f"{ours / f:.1f}" if ours and f else "–"  # noqa: E731
        rows.append([dist, f"{n:,}"] + [fmt(floor[m]) if floor[m] else "–" for m in FLOOR_MEMORY]
                    + ["–" if written is None else f"{written:.0f}",
                       fmt(ours) if ours else "–", ratio(floor["warm"]), ratio(floor["fresh"])])
    out.append("## Memory floor (issue 17)")
    out.append("")
    out.append("Rows `BM_memory_floor_<memory>` (bench/memory_floor.hpp): one pass that reads the "
               "points in BRIO order and writes what the result holds, nothing else, in memory "
               "that is warm, first touched in the pass, or first touched on 2 MiB pages (as our "
               "mesh arrays are). Median real seconds; ours / floor = how many times the floor "
               "our one-thread construction takes.")
    out.append("")
    out.append(table(header, rows))
    out.append("")
