# SPDX-License-Identifier: MIT
"""scripts/tetmesh_report.py on a small hand-made tetmesh_bench JSON: medians and spreads of the
repetitions (CPU time for ours, the manual time for a peer), the ratio to TetGen's tetrahedra per
second from the same case, the quality shares, the goals, the skipped rows, and the two figures
(PNG, under 300 kB)."""
import json
import os
import subprocess
import sys

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "tetmesh_report.py")


def entry(name, repetition, cpu_ms, real_ms, tets, **counters):
    histogram = {f"dihedral_bin_{k}": (tets if k == 7 else 0) for k in range(18)}
    histogram.update({f"radius_edge_bin_{k}": (tets if k == 4 else 0) for k in range(21)})
    values = {"tets": tets, "target_tets": 1000.0, "tets_over_target": tets / 1000.0,
              "min_dihedral_degrees": 12.0, "dihedrals_below_10_share": 0.0,
              "dihedrals_below_20_share": 0.01, "slivers": 0.0, "radius_edge_over_2": 0.0,
              "radius_edge_over_2_share": 0.0, "max_radius_edge": 1.5}
    values.update(histogram)
    values.update(counters)
    return dict(name=name, run_name=name, run_type="iteration", repetition_index=repetition,
                iterations=1, cpu_time=cpu_ms, real_time=real_ms, time_unit="ms", **values)


def test_report(tmp_path):
    benchmarks = []
    for rep, (ours_cpu, tetgen_manual) in enumerate([(10.0, 40.0), (12.0, 40.0), (11.0, 44.0)]):
        benchmarks.append(entry("BM_exactmesh/box-with-hole/0.001", rep, ours_cpu - 1, 99.0,
                                1000.0, peak_heap_bytes=2.0 * 2**20))
        benchmarks.append(entry("BM_exactmesh_slivers/box-with-hole/0.001", rep, ours_cpu, 99.0,
                                1000.0, peak_heap_bytes=2.0 * 2**20, min_dihedral_degrees=15.0))
        benchmarks.append(entry("BM_tetgen/box-with-hole/0.001/manual_time", rep, 1.0,
                                tetgen_manual, 2000.0, peak_rss_bytes=8.0 * 2**20,
                                min_dihedral_degrees=5.0))
    benchmarks.append(dict(name="BM_gmsh/box-with-hole/0.001/manual_time", run_type="iteration",
                           error_occurred=True, error_message="gmsh not found on PATH"))
    path = tmp_path / "tetmesh_bench.json"
    path.write_text(json.dumps({"context": {"host_name": "test"}, "benchmarks": benchmarks}))
    done = subprocess.run([sys.executable, SCRIPT, str(path), "--out-dir", str(tmp_path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "gmsh not found on PATH" in done.stderr
    text = (tmp_path / "tetmesh.md").read_text()
    rows = {line.split("|")[1].strip(): [c.strip() for c in line.split("|")[1:-1]]
            for line in text.splitlines() if line.startswith("| exactmesh") or
            line.startswith("| tetgen")}
    # Ours: the median CPU time 11 ms, 1000 tets: 9.09e4 tets/s; TetGen: the median manual time
    # 40 ms, 2000 tets: 5e4 tets/s; the ratio 1.82; spread (12 - 10) / 11 = 18%.
    slivers = rows["exactmesh_slivers"]
    assert slivers[3] == "11" and slivers[4] == "18%" and slivers[5] == "9.09e+04"
    assert slivers[6] == "1.8"
    assert slivers[-1] == "2 MiB heap"
    assert rows["tetgen"][3] == "40" and rows["tetgen"][-1] == "8 MiB RSS"
    assert "1.8 (not met)" in text and "15 vs 5 (met)" in text
    assert "- BM_gmsh/box-with-hole/0.001/manual_time: gmsh not found on PATH" in text
    for figure in ("tetmesh_histograms.png", "tetmesh_throughput.png"):
        size = (tmp_path / figure).stat().st_size
        assert 0 < size < 300_000
