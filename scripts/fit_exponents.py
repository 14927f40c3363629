#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# Least-squares slope of log(time) on log(n) per benchmark family of a Google Benchmark JSON
# (names <family>/<n>): the fitted exponent k of time ~ n^k, on CPU time (robust to a shared
# machine) and on real time. Usage: scripts/fit_exponents.py bench.json
import json
import math
import sys
from collections import defaultdict

runs = defaultdict(list)
for b in json.load(open(sys.argv[1]))["benchmarks"]:
    if b.get("run_type") != "iteration":
        continue
    family, _, n = b["name"].rpartition("/")
    runs[family].append((int(n), b["cpu_time"], b["real_time"]))


def slope(points):
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


print(f"{'family':48} {'n range':>14} {'k (cpu)':>8} {'k (real)':>8}")
for family, points in sorted(runs.items()):
    if len(points) < 2:
        continue
    points.sort()
    cpu = slope([(n, c) for n, c, _ in points])
    real = slope([(n, r) for n, _, r in points])
    print(f"{family:48} {points[0][0]:>6}-{points[-1][0]:<7} {cpu:8.2f} {real:8.2f}")
