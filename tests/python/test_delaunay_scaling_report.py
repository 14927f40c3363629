# SPDX-License-Identifier: MIT
"""The strong-scaling section (scripts/delaunay_scaling.py) of scripts/delaunay3d_report.py and
scripts/delaunay_report.py on small hand-made benchmark JSON: the medians of the real time (raw
repetitions in 3D, median aggregates in 2D), speed-up T1/T_T, efficiency T1/(T*T_T), the ratio to
CGAL's Parallel_tag on as many threads (3D) or to CGAL sequential (2D), peak bytes per point, the
two plots; and that a JSON without the rows (an older file) gives no section and no failure."""
import json
import os
import subprocess
import sys

SCRIPTS = os.path.join(os.path.dirname(__file__), "..", "..", "scripts")
FIGURES = ("scaling_time.png", "scaling_efficiency.png")


def iteration(name, repetition, real_ms, cpu_ms=None, **counters):
    return dict(name=name, run_name=name, run_type="iteration", repetition_index=repetition,
                iterations=1, real_time=real_ms, cpu_time=real_ms if cpu_ms is None else cpu_ms,
                time_unit="ms", **counters)


def aggregate(name, kind, real_ms, **counters):
    return dict(name=f"{name}_{kind}", run_name=name, run_type="aggregate", aggregate_name=kind,
                repetitions=3, iterations=3, real_time=real_ms, cpu_time=2 * real_ms,
                time_unit="ms", **counters)


def run_report(tmp_path, script, benchmarks, markdown):
    path = tmp_path / "bench.json"
    path.write_text(json.dumps({"context": {"host_name": "test"}, "benchmarks": benchmarks}))
    done = subprocess.run([sys.executable, os.path.join(SCRIPTS, script), str(path),
                           "--out-dir", str(tmp_path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return (tmp_path / markdown).read_text()


def scaling_rows(text):
    """The strong-scaling table's rows by (n, threads), cells stripped."""
    rows = {}
    for line in text.split("## Strong scaling", 1)[1].splitlines():
        cells = [c.strip() for c in line.split("|")[1:-1]]
        if len(cells) == 9 and cells[2].isdigit():
            rows[(cells[1], int(cells[2]))] = cells
    return rows


def test_3d_scaling_against_cgal_parallel_at_the_same_thread_count(tmp_path):
    benchmarks = []
    # Medians of the real time (the CPU time, which adds up the threads, is not used): ours 100 ms
    # on 1 thread, 60 ms on 2; CGAL's Parallel_tag 150 ms and 80 ms.
    for rep, (one, two, cgal_one, cgal_two) in enumerate(
            [(110.0, 62.0, 150.0, 90.0), (90.0, 58.0, 140.0, 80.0), (100.0, 60.0, 160.0, 70.0)]):
        benchmarks.append(iteration("BM_bowyer_watson_1_threads/uniform/100000/real_time", rep,
                                    one, **{"peak_bytes/pt": 286.0}))
        benchmarks.append(iteration("BM_bowyer_watson_2_threads/uniform/100000/real_time", rep,
                                    two, cpu_ms=2 * two, **{"peak_bytes/pt": 287.4}))
        benchmarks.append(iteration("BM_cgal_parallel_1_threads/uniform/100000/real_time", rep,
                                    cgal_one))
        benchmarks.append(iteration("BM_cgal_parallel_2_threads/uniform/100000/real_time", rep,
                                    cgal_two))
        benchmarks.append(iteration("BM_bowyer_watson/uniform/100000", rep, 95.0))
        benchmarks.append(iteration("BM_cgal/uniform/100000", rep, 140.0))
    # An aggregate other than the median is not a time to use.
    benchmarks.append(aggregate("BM_bowyer_watson_2_threads/uniform/100000/real_time", "mean",
                                1000.0))
    # 10^7 on ours alone (no CGAL row): the ratio is left blank.
    benchmarks.append(iteration("BM_bowyer_watson_1_threads/uniform/10000000/real_time", 0,
                                30000.0, **{"peak_bytes/pt": 285.8}))
    benchmarks.append(iteration("BM_bowyer_watson_2_threads/uniform/10000000/real_time", 0,
                                24000.0, **{"peak_bytes/pt": 285.9}))
    text = run_report(tmp_path, "delaunay3d_report.py", benchmarks, "delaunay3d.md")
    rows = scaling_rows(text)
    # n, threads, median real s, speed-up, efficiency, CGAL s, ours / CGAL, peak B/pt.
    assert rows[("100,000", 1)][3:] == ["0.1", "1.00", "1.00", "0.15", "0.67", "286"]
    assert rows[("100,000", 2)][3:] == ["0.06", "1.67", "0.83", "0.08", "0.75", "287"]
    assert rows[("10,000,000", 2)][3:] == ["24", "1.25", "0.62", "–", "–", "286"]
    assert "CGAL Parallel_tag on the same number of threads" in text
    # The one-thread table above is unchanged by the new rows: CGAL time / ours = 140 / 95.
    assert "| 100,000 | 0.0950 | — | 0.1400 | 1.47 |" in text
    for figure in FIGURES:
        size = (tmp_path / f"delaunay3d_{figure}").stat().st_size
        assert 0 < size < 300_000


def test_2d_scaling_against_cgal_sequential(tmp_path):
    benchmarks = []
    for kind, scale in (("mean", 1.2), ("median", 1.0), ("stddev", 0.1), ("cv", 0.01)):
        # With --benchmark_report_aggregates_only only aggregates are written; the median counts.
        benchmarks.append(aggregate("BM_bowyer_watson_1_threads/gaussian/brio/1000000/real_time",
                                    kind, 400.0 * scale, **{"peak_bytes/pt": 96.0}))
        benchmarks.append(aggregate("BM_bowyer_watson_2_threads/gaussian/brio/1000000/real_time",
                                    kind, 250.0 * scale, **{"peak_bytes/pt": 97.0}))
        benchmarks.append(aggregate("BM_cgal_1_threads/gaussian/brio/1000000/real_time", kind,
                                    600.0 * scale, **{"peak_bytes/pt": 152.0}))
        benchmarks.append(aggregate("BM_cgal/gaussian/brio/1048576", kind, 620.0 * scale,
                                    **{"triangles/pt": 2.0}))
    text = run_report(tmp_path, "delaunay_report.py", benchmarks, "delaunay2d.md")
    rows = scaling_rows(text)
    # Both thread counts against CGAL's one sequential time: 400 / 600 and 250 / 600.
    assert rows[("1,000,000", 1)] == ["gaussian", "1,000,000", "1", "0.4", "1.00", "1.00", "0.6",
                                      "0.67", "96"]
    assert rows[("1,000,000", 2)][3:] == ["0.25", "1.60", "0.80", "0.6", "0.42", "97"]
    assert "CGAL on one thread (sequential) for every thread count" in text
    for figure in FIGURES:
        size = (tmp_path / f"delaunay2d_{figure}").stat().st_size
        assert 0 < size < 300_000


def floor_rows(text):
    """The memory floor table's rows by (distribution, n), cells stripped."""
    rows = {}
    for line in text.split("## Memory floor", 1)[1].splitlines():
        cells = [c.strip() for c in line.split("|")[1:-1]]
        if len(cells) == 9 and cells[1][:1].isdigit():
            rows[(cells[0], cells[1])] = cells
    return rows


def test_memory_floor_beside_our_one_thread_time(tmp_path):
    # 3D, raw repetitions: ours 2,400 ms on one thread; the floor 50 ms warm, 160 ms fresh,
    # 700 ms fresh on huge pages (medians of three), 264 MB written.
    benchmarks = []
    for rep, (ours, warm, fresh, huge) in enumerate(
            [(2400.0, 50.0, 150.0, 700.0), (2500.0, 40.0, 160.0, 690.0),
             (2300.0, 60.0, 170.0, 710.0)]):
        benchmarks.append(iteration("BM_bowyer_watson_1_threads/uniform/1000000/real_time", rep,
                                    ours))
        for memory, ms in (("warm", warm), ("fresh", fresh), ("fresh_huge_pages", huge)):
            benchmarks.append(iteration(f"BM_memory_floor_{memory}/uniform/1000000/real_time",
                                        rep, ms, MB_written=263.9))
    text = run_report(tmp_path, "delaunay3d_report.py", benchmarks, "delaunay3d.md")
    # n, warm, fresh, fresh huge pages, MB, ours, ours / warm, ours / fresh.
    assert floor_rows(text)[("uniform", "1,000,000")][2:] == [
        "0.05", "0.16", "0.7", "264", "2.4", "48.0", "15.0"]
    # 2D, median aggregates only, a floor without our row: the ratios are left blank.
    benchmarks = []
    for kind, scale in (("mean", 1.5), ("median", 1.0)):
        benchmarks.append(aggregate("BM_bowyer_watson_1_threads/uniform/brio/1000000/real_time",
                                    kind, 365.0 * scale))
        benchmarks.append(aggregate("BM_memory_floor_fresh/uniform/brio/1000000/real_time", kind,
                                    45.0 * scale, MB_written=64.0))
        benchmarks.append(aggregate("BM_memory_floor_warm/gaussian/brio/1000000/real_time", kind,
                                    15.0 * scale, MB_written=64.0))
    text = run_report(tmp_path, "delaunay_report.py", benchmarks, "delaunay2d.md")
    rows = floor_rows(text)
    assert rows[("uniform", "1,000,000")][2:] == ["–", "0.045", "–", "64", "0.365", "–", "8.1"]
    assert rows[("gaussian", "1,000,000")][2:] == ["0.015", "–", "–", "64", "–", "–", "–"]
    # Uniform first.
    assert text.index("| uniform | 1,000,000") < text.index("| gaussian | 1,000,000")


def test_older_json_without_scaling_rows(tmp_path):
    benchmarks = [iteration("BM_bowyer_watson/uniform/1000", 0, 1.0),
                  iteration("BM_cgal/uniform/1000", 0, 2.0)]
    text = run_report(tmp_path, "delaunay3d_report.py", benchmarks, "delaunay3d.md")
    assert "Strong scaling" not in text and "| 1,000 | 0.0010 |" in text
    benchmarks = [iteration("BM_bowyer_watson/uniform/brio/1024", 0, 1.0),
                  iteration("BM_cgal/uniform/brio/1024", 0, 2.0)]
    text = run_report(tmp_path, "delaunay_report.py", benchmarks, "delaunay2d.md")
    assert "Strong scaling" not in text and "time / CGAL" in text
    assert "Memory floor" not in text
    assert not any(name.endswith(FIGURES) for name in os.listdir(tmp_path))
