# SPDX-License-Identifier: MIT
"""bench/robustness_table.py (issue 16), briefly: every program row appears, exactmesh's own
commands get every input exactly right, the counts add up, and the crash grouping names the
causes the report groups by."""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "bench"))

import robustness_table  # noqa: E402


def test_table_on_a_few_inputs(command, tmp_path):
    out = tmp_path / "rows.json"
    r = subprocess.run([sys.executable, os.path.join(ROOT, "bench", "robustness_table.py"),
                        "--count", "3", "--max-points", "60", "--exactmesh", command, "--quiet",
                        "--json", str(out)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    assert r.stderr == ""
    assert "| program | kind | inputs | exactly right | wrong | crashed | timed out | refused |" \
        in r.stdout
    rows = json.loads(out.read_text())["rows"]
    assert len(rows) == 8
    for row in rows:
        if row.get("missing"):
            continue
        assert row["inputs"] == 3
        assert sum(row[k] for k in ("right", "wrong", "crashed", "timed_out", "refused")) == 3
        if row["program"].startswith("exactmesh"):
            assert row["right"] == 3, row


def test_grouping():
    assert robustness_table.problem_kind(
        "no triangles, but points 1, 2, 3 are not collinear") == "no cells at all"
    assert robustness_table.problem_kind(
        "tetrahedron 1 (4, 3, 1, 2): not positively oriented (orient3d <= 0)") == \
        "flat (or inverted) cell"
    assert robustness_table.crash_kind(
        "exit status 1: QhullError: QH6154 Qhull precision error: Initial simplex is flat "
        "(facet 1 is coplanar)") == \
        "exit status 1, QH6154 Qhull precision error: Initial simplex is flat"
    assert robustness_table.crash_kind(
        "exit status 134: tetgen: /build/tetgen-1.5.0/tetgen.cxx:11026: tetgenmesh::locate(): "
        "Assertion `0' failed. | Aborted") == "exit status 134, assertion at tetgen.cxx:11026"
    assert robustness_table.crash_kind("killed by signal 11 (Segmentation fault)") == \
        "killed by signal 11 (Segmentation fault)"
