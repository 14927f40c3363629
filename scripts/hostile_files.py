#!/usr/bin/env python3
"""Hostile files through every command that reads files (the hostile-file campaign of
2026-12-06; the figures in the README's "Correctness campaigns").

  scripts/hostile_files.py DIR
      writes DIR/cases/<id>/ (the files of one run: .node/.ele/.poly/.smesh/.off/.stl, size and
      metric files, links to /dev/zero and /dev/null, directories where files belong) and
      DIR/manifest.jsonl (per run: the command and what is expected: reject = exit 2, accept =
      exit 0, either). Generic text mutations of every format (empty, truncated, CRLF, CR only,
      tabs, byte order marks, comments and blank lines anywhere, trailing garbage, NUL bytes,
      over-long lines, binary garbage, UTF-16, header counts of 0, -1, 2^31, 2^32, 2^63, 2^64,
      1e3, +-1, missing, extra fields), numbers (NaN, inf, 1e309, subnormals, -0, 1e+-300, hex,
      commas, ...), indices (0 in 1-based files, negative, past the end, 2^32), degenerate
      geometry (duplicates, collinear, coplanar, huge, tiny, mixed magnitudes, open and
      self-intersecting surfaces, facets of 0/1/2 corners, repeated corners), binary STLs whose
      count disagrees with the size both ways (2^32-1), size files, size and metric expressions,
      metric files, sizes asking for 10^12 elements, missing companions.
  scripts/hostile_files.py --run DIR [EXACTMESH] [JOBS]
      runs every case (20 s timeout, `ulimit -v` 4 GB, peak RSS by GNU time), classifies each run
      (good: exit 2 with one 'exactmesh: error:' line, or the expected exit 0; else CRASH,
      TIMEOUT, INTERNAL (exit 3), ACCEPTED_GARBAGE, REFUSED_VALID, NOT_ONE_ERROR_LINE, NO_FILE
      (the message names no file of the run), RSS (over 1 GB), SLOW (over 5 s)), re-checks every
      mesh written with `exactmesh check`, prints the counts and each non-good run. Exit 1 on a
      crash, a time-out, an internal error, an RSS or SLOW refusal, or a written mesh that fails
      its check. ACCEPTED_GARBAGE and REFUSED_VALID need reading: the expectations are the
      generator's guesses (a truncation may leave a valid number).
"""
import concurrent.futures as cf
import json
import os
import random
import re
import shlex
import struct
import subprocess
import sys
import time


def generate(out):
    cases = []
    os.makedirs(out, exist_ok=True)
    cases = []
    os.makedirs(out, exist_ok=True)

    def case(name, files, cmd, expect):
        cid = f"{len(cases):04d}_" + re.sub(r"[^A-Za-z0-9_.+-]", "_", name)
        d = os.path.join(out, "cases", cid)
        os.makedirs(d, exist_ok=True)
        for fname, content in files.items():
            p = os.path.join(d, fname)
            if content is None:
                continue
            if isinstance(content, tuple) and content[0] == "symlink":
                if os.path.lexists(p): os.remove(p)
                os.symlink(content[1], p)
            elif isinstance(content, tuple) and content[0] == "dir":
                os.makedirs(p, exist_ok=True)
            else:
                data = content.encode() if isinstance(content, str) else content
                with open(p, "wb") as f:
                    f.write(data)
        cases.append({"id": cid, "cmd": cmd, "expect": expect})

    # ---------- base inputs ----------
    NODE2 = "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.5 0.4\n"
    ELE2 = "4 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n"
    NODE2_ATTR = "5 2 1 0\n1 0 0 0.1\n2 1 0 0.2\n3 1 1 0.3\n4 0 1 0.4\n5 0.5 0.4 0.5\n"
    POLY2 = ("8 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n5 0.4 0.4 2\n6 0.6 0.4 2\n7 0.6 0.6 2\n8 0.4 0.6 2\n"
             "8 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
             "1\n1 0.5 0.5\n1\n1 0.2 0.2 3 0.05\n")
    NODE3 = "9 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n9 0.5 0.5 0.5\n"
    CUBE_PTS = "8 3 0 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n"
    CUBE_FACETS = [(1,2,3,4),(5,6,7,8),(1,2,6,5),(2,3,7,6),(3,4,8,7),(4,1,5,8)]
    POLY3 = CUBE_PTS + "6 1\n" + "".join(f"1 0 {i+1}\n4 {' '.join(map(str,f))}\n" for i,f in enumerate(CUBE_FACETS)) + "0\n0\n"
    SMESH = CUBE_PTS + "6 0\n" + "".join(f"4 {' '.join(map(str,f))}\n" for f in CUBE_FACETS) + "0\n0\n"
    OFF = "OFF\n8 6 12\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(
        f"4 {' '.join(str(v-1) for v in f)}\n" for f in CUBE_FACETS)
    P = [(0,0,0),(1,0,0),(1,1,0),(0,1,0),(0,0,1),(1,0,1),(1,1,1),(0,1,1)]
    TRIS = []
    for f in [(1,4,3,2),(5,6,7,8),(1,2,6,5),(2,3,7,6),(3,4,8,7),(4,1,5,8)]:
        a,b,c,d = [x-1 for x in f]
        TRIS += [(a,b,c),(a,c,d)]
    def stl_ascii(tris, pts=P):
        s = "solid cube\n"
        for t in tris:
            s += " facet normal 0 0 0\n  outer loop\n"
            for v in t:
                s += "   vertex %r %r %r\n" % pts[v]
            s += "  endloop\n endfacet\n"
        return s + "endsolid cube\n"
    def stl_binary(tris, pts=P, count=None, header=b"binary cube".ljust(80, b" "), extra=b""):
        b = header[:80].ljust(80, b" ") + struct.pack("<I", len(tris) if count is None else count)
        for t in tris:
            b += struct.pack("<3f", 0, 0, 0)
            for v in t:
                b += struct.pack("<3f", *pts[v])
            b += b"\0\0"
        return b + extra
    STL_A = stl_ascii(TRIS)
    STL_B = stl_binary(TRIS)
    TETELE = None  # made from tetrahedralize in the runner's base step; use a hand-made one:
    NODE3_TET = "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n"
    ELE3_TET = "2 4 0\n1 1 2 3 4\n2 2 3 4 5\n"

    # ---------- commands per kind ----------
    def cmds_node2(f):
        return [["triangulate", f, "-o", "{d}/o.ele"],
                ["triangulate", f, "-o", "{d}/o.ele", "--algorithm", "tanemura-merriam"],
                ["triangulate", f, "-o", "{d}/o.ele", "--algorithm", "green-sibson", "--order", "random"],
                ["min-max", f, "-o", "{d}/o.ele"]]
    GEN2 = ["delaunay-refinement", "quadtree", "advancing-front", "advancing-front-delaunay", "frontal",
            "metric-delaunay", "min-max-front"]
    def cmds_poly2(f, full=False):
        c = [["cdt", f, "-o", "{d}/o.ele"], ["cdt", f, "-o", "{d}/o.ele", "--recovery", "conforming"],
             ["cdt", f, "-o", "{d}/o.ele", "--recovery", "cavity", "--convex-hull"]]
        gens = GEN2 if full else ["delaunay-refinement", "quadtree", "frontal"]
        for g in gens:
            c.append(["mesh", f, "-o", "{d}/o.ele", "--generator", g, "--size", "0.2"])
        if full:
            c.append(["mesh", f, "-o", "{d}/o.ele"])
            c.append(["mesh", f, "-o", "{d}/o.ele", "--generator", "stretched-delaunay", "--layers", "0.01,1.2,5"])
            c.append(["mesh", f, "-o", "{d}/o.ele", "--generator", "advancing-layers", "--layers", "0.01,1.2,5"])
            c.append(["adapt", f, "--field", "tanh(20*(x+y-1))", "-o", "{d}/o.ele", "--cycles", "1"])
        return c
    GEN3 = [[], ["--radius-edge", "2"], ["--generator", "frontal", "--size", "0.3"], ["--generator", "octree", "--size", "0.3"]]
    def cmds_plc(f):
        return [["tetmesh", f, "-o", "{d}/o.ele"] + g for g in GEN3]
    def cmds_node3(f):
        return [["tetrahedralize", f, "-o", "{d}/o.ele"],
                ["tetrahedralize", f, "-o", "{d}/o.ele", "--algorithm", "green-sibson"]]

    # ---------- text mutators ----------
    def lines_of(t): return t.split("\n")
    def mutate_text(base, kind):
        """Yield (name, text, expect) for generic text mutations of a line-based format."""
        L = lines_of(base)
        body = [i for i, l in enumerate(L) if l.strip()]
        yield "empty", "", "reject"
        yield "only_comments", "# nothing\n#\n\n", "reject"
        yield "only_blank", "\n\n  \n\t\n", "reject"
        yield "crlf", base.replace("\n", "\r\n"), "accept"
        yield "cr_only", base.replace("\n", "\r"), "reject"
        yield "tabs", base.replace(" ", "\t"), "accept"
        yield "bom", "\ufeff" + base, "accept"
        yield "double_bom", "\ufeff\ufeff" + base, "reject"
        yield "comments_everywhere", "\n".join((l + "  # c " if l.strip() else "# x") for l in L), "accept"
        yield "blank_lines_between", "\n\n".join(L), "accept"
        yield "no_final_newline", base.rstrip("\n"), "accept"
        yield "trailing_garbage", base + "garbage here\n", "reject"
        yield "trailing_numbers", base + "1 2 3\n", "reject"
        yield "trailing_nul", base + "\0\0\0", "reject"
        yield "nul_in_middle", base[: len(base)//2] + "\0" + base[len(base)//2:], "reject"
        yield "long_line", base + "#" + "x" * (3 << 20) + "\n", "either"
        yield "long_data_line", L[0] + " " + "1" * (2 << 20) + "\n" + "\n".join(L[1:]), "reject"
        yield "binary_garbage", bytes(random.Random(7).randrange(256) for _ in range(5000)), "reject"
        yield "utf16", base.encode("utf-16"), "reject"
        yield "latin1_in_comment", (base + "# caf\xe9\n").encode("latin-1"), "accept"
        for frac in (0.25, 0.5, 0.75, 0.97):
            yield f"truncated_{int(frac*100)}", base[: int(len(base) * frac)], "reject"
        yield "drop_last_line", "\n".join(L[: body[-1]]) + "\n", "reject"
        yield "only_header", L[0] + "\n", "either"
        # header count mutations
        h = L[body[0]].split()
        for v in ["0", "-1", "2147483648", "4294967295", "4294967296", "9223372036854775808",
                  "18446744073709551616", "1e3", "abc", "0x10", "+5", "3.0", ""]:
            hh = [v] + h[1:] if v else h[1:]
            LL = list(L); LL[body[0]] = " ".join(hh)
            yield f"count_{v or 'missing'}", "\n".join(LL), "either" if v in ("+5",) else "reject"
        try:
            n = int(h[0])
            for dv in (1, -1):
                LL = list(L); LL[body[0]] = " ".join([str(n + dv)] + h[1:])
                yield f"count_{'plus' if dv > 0 else 'minus'}1", "\n".join(LL), "reject"
        except ValueError:
            pass
        # extra header fields
        LL = list(L); LL[body[0]] = L[body[0]] + " 0 0 0 0"
        yield "header_extra_fields", "\n".join(LL), "reject"

    NUMS = ["nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e309", "-1e309", "1e-320", "4.9e-324",
            "1e-400", "-0", "-0.0", "1e300", "-1e300", "1e-300", "0x1p3", "1,5", "1.5.5", "1e", "--1",
            "+-1", "1_000", "١", "0.5f", "1d0", "NAN", "nan(0x1)", ".", "-", "e5", "  ", "1e999999999999999999999"]

    def field_mutations(base, line_idx, field_idx, values):
        L = lines_of(base)
        for v in values:
            f = L[line_idx].split()
            if field_idx < len(f):
                f[field_idx] = v if v.strip() else ""
                LL = list(L); LL[line_idx] = " ".join(x for x in f if x != "" ) if not v.strip() else " ".join(f)
                yield v, "\n".join(LL)

    def add(name, files, cmds, expect):
        for k, cmd in enumerate(cmds):
            case(f"{name}_c{k}", files, cmd, expect)

    # ================= 2D .node =================
    for n, t, e in mutate_text(NODE2, "node"):
        add(f"node2_{n}", {"in.node": t}, cmds_node2("{d}/in.node")[:2], e)
    for v, t in field_mutations(NODE2, 3, 1, NUMS):
        exp = "either" if v in ("-0", "-0.0", "1e300", "-1e300", "1e-300", "1e-320", "4.9e-324", "+-1") else "reject"
        add(f"node2_x_{v.strip() or 'blank'}", {"in.node": t}, cmds_node2("{d}/in.node")[:1] + cmds_node2("{d}/in.node")[3:], exp)
    # vertex numbering
    for name, t in [
        ("number_2_first", NODE2.replace("\n1 0 0\n", "\n2 0 0\n", 1)),
        ("number_gap", NODE2.replace("\n3 1 1\n", "\n7 1 1\n")),
        ("number_negative", NODE2.replace("\n1 0 0\n", "\n-1 0 0\n")),
        ("number_repeat", NODE2.replace("\n3 1 1\n", "\n2 1 1\n")),
        ("number_huge", NODE2.replace("\n1 0 0\n", "\n4294967295 0 0\n")),
        ("fields_missing_y", NODE2.replace("\n3 1 1\n", "\n3 1\n")),
        ("fields_extra", NODE2.replace("\n3 1 1\n", "\n3 1 1 7\n")),
        ("attr_missing", NODE2_ATTR.replace("\n3 1 1 0.3\n", "\n3 1 1\n")),
        ("attr_nan", NODE2_ATTR.replace("0.3", "nan")),
        ("attr_count_huge", "5 2 4294967287 0\n1 0 0\n"),
        ("attr_count_big_lines", "2 2 100000 0\n1 0 0 " + " ".join(["1"] * 100000) + "\n2 1 1 " + " ".join(["1"] * 99999) + "\n"),
        ("marker_flag_2", "5 2 0 2\n" + "\n".join(NODE2.split("\n")[1:])),
        ("marker_huge", "5 2 0 1\n1 0 0 99999999999\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.5 0.4 0\n"),
        ("dimension_3", NODE2.replace("5 2 0 0", "5 3 0 0")),
        ("dimension_1", NODE2.replace("5 2 0 0", "5 1 0 0")),
        ("dimension_huge", NODE2.replace("5 2 0 0", "5 99999999999999999999 0 0")),
    ]:
        exp = "either" if name in ("number_2_first",) else "reject"
        add(f"node2_{name}", {"in.node": t}, cmds_node2("{d}/in.node")[:1], exp)
    # degenerate geometry (valid parse)
    def node2(pts, base1=True):
        return f"{len(pts)} 2 0 0\n" + "".join(f"{i+1} {x!r} {y!r}\n" for i, (x, y) in enumerate(pts))
    geo2 = {
        "one_point": [(0, 0)], "two_points": [(0, 0), (1, 1)], "zero_points": [],
        "collinear": [(i, 2 * i) for i in range(10)], "all_same": [(1, 1)] * 10,
        "duplicates": [(0, 0), (1, 0), (0, 1), (0, 0), (1, 0), (1, 1), (1, 1)],
        "huge": [(1e300, 1e300), (-1e300, 1e300), (1e300, -1e300), (-1e300, -1e300), (0, 0)],
        "max_double": [(1.7976931348623157e308, 0), (-1.7976931348623157e308, 0), (0, 1.7976931348623157e308), (0, -1.7976931348623157e308)],
        "tiny": [(1e-300, 0), (0, 1e-300), (-1e-300, 0), (0, -1e-300), (0, 0)],
        "denormal": [(5e-324, 0), (0, 5e-324), (1e-320, 1e-320), (0, 0)],
        "mixed_scale": [(1e300, 0), (0, 1e-300), (-1e-300, 1e-300), (0, 1e300), (1, 1)],
        "neg_zero": [(-0.0, -0.0), (0.0, 0.0), (1, 0), (0, 1)],
        "near_collinear": [(0.5 + i * 2**-53, 0.5 + i * 2**-53 * (1 if i % 2 else 1.0000001)) for i in range(20)],
    }
    for name, pts in geo2.items():
        add(f"node2geo_{name}", {"in.node": node2(pts)}, cmds_node2("{d}/in.node"), "either")
        if len(pts) >= 3:
            add(f"node2geo_{name}_tet", {"in.node": node2(pts)}, [["tetrahedralize", "{d}/in.node", "-o", "{d}/o.ele"]], "reject")

    # ================= 2D .ele with node (check, swap, adapt) =================
    def cmds_ele2():
        return [["check", "{d}/in.node", "{d}/in.ele"],
                ["swap", "{d}/in.node", "{d}/in.ele", "-o", "{d}/o.ele", "--criterion", "delaunay"],
                ["swap", "{d}/in.node", "{d}/in.ele", "-o", "{d}/o.ele", "--criterion", "data-dependent"],
                ["adapt", "{d}/in.node", "{d}/in.ele", "--field", "x*y", "-o", "{d}/o.ele", "--cycles", "1"]]
    for n, t, e in mutate_text(ELE2, "ele"):
        add(f"ele2_{n}", {"in.node": NODE2_ATTR, "in.ele": t}, cmds_ele2()[:2] + cmds_ele2()[3:], e)
    for name, t in [
        ("index_zero_in_one_based", ELE2.replace("\n1 1 2 5", "\n1 0 2 5")),
        ("index_negative", ELE2.replace("\n1 1 2 5", "\n1 -1 2 5")),
        ("index_past_end", ELE2.replace("\n1 1 2 5", "\n1 6 2 5")),
        ("index_2p32", ELE2.replace("\n1 1 2 5", "\n1 4294967296 2 5")),
        ("index_2p32m1", ELE2.replace("\n1 1 2 5", "\n1 4294967295 2 5")),
        ("index_float", ELE2.replace("\n1 1 2 5", "\n1 1.0 2 5")),
        ("repeated_corner", ELE2.replace("\n1 1 2 5", "\n1 1 1 5")),
        ("all_same_corner", ELE2.replace("\n1 1 2 5", "\n1 5 5 5")),
        ("clockwise", ELE2.replace("\n1 1 2 5", "\n1 2 1 5")),
        ("duplicate_triangle", "5 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n5 1 2 5\n"),
        ("missing_triangle", "3 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n"),
        ("zero_triangles", "0 3 0\n"),
        ("zero_based_mixed", "4 3 0\n0 0 1 4\n1 1 2 4\n2 2 3 4\n3 3 0 4\n"),
        ("six_nodes", "4 6 0\n1 1 2 5 1 2 5\n2 2 3 5 2 3 5\n3 3 4 5 3 4 5\n4 4 1 5 4 1 5\n"),
        ("four_nodes", "4 4 0\n1 1 2 5 3\n2 2 3 5 1\n3 3 4 5 1\n4 4 1 5 1\n"),
        ("attr_declared_missing", "4 3 1\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n"),
        ("overlapping", "5 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n5 1 3 4\n"),
    ]:
        exp = "either" if name in ("six_nodes",) else "reject"
        add(f"ele2_{name}", {"in.node": NODE2_ATTR, "in.ele": t}, cmds_ele2(), exp)
    # node bad, ele good; missing companion; directory; /dev/zero
    add("ele2_node_missing", {"in.ele": ELE2}, cmds_ele2(), "reject")
    add("ele2_ele_missing", {"in.node": NODE2}, cmds_ele2(), "reject")
    add("ele2_ele_is_dir", {"in.node": NODE2, "in.ele": ("dir",)}, cmds_ele2(), "reject")
    add("ele2_ele_devzero", {"in.node": NODE2, "in.ele": ("symlink", "/dev/zero")}, cmds_ele2(), "reject")
    add("ele2_node_devzero", {"in.node": ("symlink", "/dev/zero"), "in.ele": ELE2}, cmds_ele2(), "reject")
    add("ele2_node_devnull", {"in.node": ("symlink", "/dev/null"), "in.ele": ELE2}, cmds_ele2(), "reject")
    add("ele2_ele_devnull", {"in.node": NODE2, "in.ele": ("symlink", "/dev/null")}, cmds_ele2(), "reject")
    add("ele2_node_3d", {"in.node": NODE3_TET, "in.ele": ELE2}, cmds_ele2(), "reject")
    add("ele2_node_dangling_link", {"in.node": ("symlink", "/nonexistent/x.node"), "in.ele": ELE2}, cmds_ele2(), "reject")
    # duplicate vertices in the node used by an ele
    add("ele2_dup_vertices", {"in.node": "5 2 1 0\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 0\n", "in.ele": "2 3 0\n1 1 2 3\n2 5 3 4\n"}, cmds_ele2(), "reject")
    add("ele2_unused_vertex", {"in.node": NODE2_ATTR, "in.ele": "2 3 0\n1 1 2 3\n2 1 3 4\n"}, cmds_ele2(), "either")
    add("ele2_data_nan_attr", {"in.node": NODE2_ATTR.replace("0.3", "nan"), "in.ele": ELE2}, cmds_ele2(), "reject")
    add("ele2_data_huge_attr", {"in.node": NODE2_ATTR.replace("0.3", "1e308").replace("0.2", "-1e308"), "in.ele": ELE2}, cmds_ele2(), "either")
    add("ele2_huge_coords", {"in.node": "5 2 1 0\n1 0 0 0\n2 1e300 0 1\n3 1e300 1e300 0\n4 0 1e300 1\n5 5e299 4e299 0\n", "in.ele": ELE2}, cmds_ele2(), "either")
    add("ele2_tiny_coords", {"in.node": "5 2 1 0\n1 0 0 0\n2 1e-300 0 1\n3 1e-300 1e-300 0\n4 0 1e-300 1\n5 5e-301 4e-301 0\n", "in.ele": ELE2}, cmds_ele2(), "either")
    add("ele2_denormal_coords", {"in.node": "5 2 1 0\n1 0 0 0\n2 1e-322 0 1\n3 1e-322 1e-322 0\n4 0 1e-322 1\n5 5e-323 4e-323 0\n", "in.ele": ELE2}, cmds_ele2(), "either")
    # adapt field file
    FIELD = "5 2 1 0\n1 0 0 0\n2 1 0 1\n3 1 1 2\n4 0 1 1\n5 0.5 0.4 0.9\n"
    for name, t in [("ok", FIELD), ("nan", FIELD.replace(" 2\n", " nan\n")), ("no_attr", NODE2),
                    ("moved_point", FIELD.replace("0.5 0.4", "0.5 0.41")), ("fewer", "4 2 1 0\n1 0 0 0\n2 1 0 1\n3 1 1 2\n4 0 1 1\n"),
                    ("huge", FIELD.replace(" 2\n", " 1e308\n").replace(" 0.9\n", " -1e308\n"))]:
        add(f"adapt_fieldfile_{name}", {"in.node": NODE2, "in.ele": ELE2, "f.node": t},
            [["adapt", "{d}/in.node", "{d}/in.ele", "--field-file", "{d}/f.node", "-o", "{d}/o.ele", "--cycles", "1"]],
            "accept" if name == "ok" else "either" if name == "huge" else "reject")
    # adapt expressions
    for expr in ["1/0", "sqrt(-1)", "0/0", "log(0)", "1e308*10", "x/(x-x)", "", "x+", "q", "_nan", "1e400"]:
        add(f"adapt_field_expr", {"in.node": NODE2, "in.ele": ELE2},
            [["adapt", "{d}/in.node", "{d}/in.ele", "--field", expr, "-o", "{d}/o.ele", "--cycles", "1"],
             ["adapt", "--domain", "cube", "--field", expr, "-o", "{d}/o.ele", "--cycles", "1"]], "either")

    # ================= 2D .poly =================
    for n, t, e in mutate_text(POLY2, "poly"):
        add(f"poly2_{n}", {"in.poly": t}, cmds_poly2("{d}/in.poly")[:1] + cmds_poly2("{d}/in.poly")[3:4], e)
    PL = lines_of(POLY2)
    seg_hdr = 9; hole_hdr = 18; reg_hdr = 20
    def poly_replace(i, new):
        L = list(PL); L[i] = new; return "\n".join(L)
    for name, t, exp in [
        ("seg_count_big", poly_replace(seg_hdr, "9 1"), "reject"),
        ("seg_count_small", poly_replace(seg_hdr, "7 1"), "reject"),
        ("seg_count_2p63", poly_replace(seg_hdr, "9223372036854775807 1"), "reject"),
        ("seg_endpoint_zero", poly_replace(10, "1 0 2 1"), "reject"),
        ("seg_endpoint_past", poly_replace(10, "1 9 2 1"), "reject"),
        ("seg_endpoint_neg", poly_replace(10, "1 -1 2 1"), "reject"),
        ("seg_zero_length", poly_replace(10, "1 1 1 1"), "either"),
        ("seg_duplicate", poly_replace(11, "2 1 2 1"), "either"),
        ("seg_missing_field", poly_replace(10, "1 1 2"), "reject"),
        ("seg_marker_nan", poly_replace(10, "1 1 2 nan"), "reject"),
        ("hole_count_big", poly_replace(hole_hdr, "2"), "reject"),
        ("hole_outside", poly_replace(hole_hdr + 1, "1 5 5"), "either"),
        ("hole_far_outside", poly_replace(hole_hdr + 1, "1 1e300 -1e300"), "either"),
        ("hole_nan", poly_replace(hole_hdr + 1, "1 nan 0.5"), "reject"),
        ("hole_on_vertex", poly_replace(hole_hdr + 1, "1 0.4 0.4"), "reject"),
        ("hole_in_domain_not_hole", poly_replace(hole_hdr + 1, "1 0.1 0.1"), "either"),
        ("hole_missing_coord", poly_replace(hole_hdr + 1, "1 0.5"), "reject"),
        ("region_outside", poly_replace(reg_hdr + 1, "1 5 5 3 0.05"), "either"),
        ("region_in_hole", poly_replace(reg_hdr + 1, "1 0.5 0.5 3 0.05"), "either"),
        ("region_area_zero", poly_replace(reg_hdr + 1, "1 0.2 0.2 3 0"), "either"),
        ("region_area_negative", poly_replace(reg_hdr + 1, "1 0.2 0.2 3 -5"), "either"),
        ("region_area_tiny", poly_replace(reg_hdr + 1, "1 0.2 0.2 3 1e-300"), "reject"),
        ("region_area_denormal", poly_replace(reg_hdr + 1, "1 0.2 0.2 3 5e-324"), "reject"),
        ("region_area_huge", poly_replace(reg_hdr + 1, "1 0.2 0.2 3 1e308"), "accept"),
        ("region_attr_nan", poly_replace(reg_hdr + 1, "1 0.2 0.2 nan 0.05"), "reject"),
        ("region_three_fields", poly_replace(reg_hdr + 1, "1 0.2 0.2"), "reject"),
        ("region_count_big", poly_replace(reg_hdr, "3"), "reject"),
        ("no_holes_section", "\n".join(PL[:hole_hdr]) + "\n", "reject"),
        ("no_regions_section", "\n".join(PL[:reg_hdr]) + "\n", "accept"),
        ("vertices_from_node_missing", "0 2 0 0\n" + "\n".join(PL[9:]), "reject"),
        ("crossing_segments", "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n2 0\n1 1 2\n2 3 4\n0\n", "either"),
        ("open_polyline", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n3 0\n1 1 2\n2 2 3\n3 3 4\n0\n", "either"),
        ("no_segments", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n0 0\n0\n", "either"),
        ("collinear_all", "4 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 3 0\n3 0\n1 1 2\n2 2 3\n3 3 4\n0\n", "either"),
        ("dup_vertices", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1 1\n4 0\n1 1 2\n2 2 5\n3 3 4\n4 4 1\n0\n", "either"),
        ("segment_through_vertex", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.5 0.5\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n0\n", "either"),
        ("huge_square", "4 2 0 0\n1 -1e300 -1e300\n2 1e300 -1e300\n3 1e300 1e300\n4 -1e300 1e300\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "either"),
        ("max_square", "4 2 0 0\n1 -1.7976931348623157e308 -1.7976931348623157e308\n2 1.7976931348623157e308 -1.7976931348623157e308\n3 1.7976931348623157e308 1.7976931348623157e308\n4 -1.7976931348623157e308 1.7976931348623157e308\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "either"),
        ("tiny_square", "4 2 0 0\n1 0 0\n2 1e-300 0\n3 1e-300 1e-300\n4 0 1e-300\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "either"),
        ("denormal_square", "4 2 0 0\n1 0 0\n2 1e-320 0\n3 1e-320 1e-320\n4 0 1e-320\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "either"),
        ("sliver_triangle", "3 2 0 0\n1 0 0\n2 1 0\n3 0.5 1e-300\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n", "either"),
        ("one_vertex", "1 2 0 0\n1 0 0\n0 0\n0\n", "either"),
        ("two_vertices_seg", "2 2 0 0\n1 0 0\n2 1 0\n1 0\n1 1 2\n0\n", "either"),
        ("mixed_scale", "4 2 0 0\n1 0 0\n2 1e300 0\n3 1e300 1e-300\n4 0 1e-300\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "either"),
    ]:
        add(f"poly2_{name}", {"in.poly": t}, cmds_poly2("{d}/in.poly", full=True), exp)
    # node companion problems
    add("poly2_node_companion_dir", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": ("dir",)}, cmds_poly2("{d}/in.poly")[:2], "reject")
    add("poly2_node_companion_zero", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": ("symlink", "/dev/zero")}, cmds_poly2("{d}/in.poly")[:2], "reject")
    add("poly2_node_companion_3d", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": NODE3}, cmds_poly2("{d}/in.poly")[:2], "reject")
    add("poly2_node_companion_zero_count", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": "0 2 0 0\n"}, cmds_poly2("{d}/in.poly")[:2], "reject")
    add("poly2_node_companion_ok", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n"}, cmds_poly2("{d}/in.poly")[:2], "accept")
    add("poly2_node_companion_0based", {"in.poly": "0 2 0 0\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n", "in.node": "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n"}, cmds_poly2("{d}/in.poly")[:2], "reject")
    add("poly2_devzero", {"in.poly": ("symlink", "/dev/zero")}, cmds_poly2("{d}/in.poly")[:4], "reject")
    add("poly2_isdir", {"in.poly": ("dir",)}, cmds_poly2("{d}/in.poly")[:4], "reject")
    add("poly2_fifo_like_devnull", {"in.poly": ("symlink", "/dev/null")}, cmds_poly2("{d}/in.poly")[:4], "reject")
    add("poly2_check_mismatch", {"in.poly": POLY2, "in.ele": ELE2, "in.node": NODE2}, [["check", "{d}/in.poly", "{d}/in.ele"], ["check", "{d}/in.poly", "{d}/in.ele", "--conforming"]], "either")
    add("poly2_3d_given_to_cdt", {"in.poly": POLY3}, [["cdt", "{d}/in.poly", "-o", "{d}/o.ele"], ["mesh", "{d}/in.poly", "-o", "{d}/o.ele"]], "reject")

    # ================= size files / expressions / metric =================
    SQ = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n"
    size_files = {
        "uniform_ok": ("uniform 0.1\n", "accept"),
        "uniform_zero": ("uniform 0\n", "reject"), "uniform_neg": ("uniform -1\n", "reject"),
        "uniform_nan": ("uniform nan\n", "reject"), "uniform_inf": ("uniform inf\n", "reject"),
        "uniform_tiny": ("uniform 1e-12\n", "reject"), "uniform_denormal": ("uniform 5e-324\n", "reject"),
        "uniform_huge": ("uniform 1e308\n", "accept"), "uniform_missing": ("uniform\n", "reject"),
        "uniform_extra": ("uniform 0.1 0.2\n", "reject"), "unknown_kind": ("blob 1 2\n", "reject"),
        "point_ok": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 1.2\n", "accept"),
        "point_neg_size": ("uniform 0.2\npoint 0.5 0.5 -0.01 0.1 1.2\n", "reject"),
        "point_zero_size": ("uniform 0.2\npoint 0.5 0.5 0 0.1 1.2\n", "reject"),
        "point_nan": ("uniform 0.2\npoint nan 0.5 0.01 0.1 1.2\n", "reject"),
        "point_gamma_neg": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 -1\n", "reject"),
        "point_gamma_zero": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 0\n", "either"),
        "point_gamma_huge": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 1e308\n", "either"),
        "point_rbar_neg": ("uniform 0.2\npoint 0.5 0.5 0.01 -0.1 1.2\n", "reject"),
        "point_fields_short": ("uniform 0.2\npoint 0.5 0.5 0.01\n", "reject"),
        "point_tiny_size": ("uniform 0.2\npoint 0.5 0.5 1e-15 0.1 1.2\n", "reject"),
        "line_zero_len": ("uniform 0.2\nline 0.5 0.5 0.5 0.5 0.01 0.1 1.2\n", "either"),
        "line_ok": ("uniform 0.2\nline 0 0 1 1 0.01 0.1 1.2\n", "accept"),
        "empty": ("", "reject"), "comments": ("# only\n", "reject"),
        "bg_mesh_ok": ("vertex 0 0 0.1\nvertex 1 0 0.1\nvertex 1 1 0.2\nvertex 0 1 0.2\ntriangle 0 1 2\ntriangle 0 2 3\n", "either"),
        "bg_mesh_bad_index": ("vertex 0 0 0.1\nvertex 1 0 0.1\nvertex 1 1 0.2\ntriangle 0 1 7\n", "reject"),
        "bg_mesh_neg_index": ("vertex 0 0 0.1\nvertex 1 0 0.1\nvertex 1 1 0.2\ntriangle 0 1 -1\n", "reject"),
        "bg_mesh_neg_size": ("vertex 0 0 -0.1\nvertex 1 0 0.1\nvertex 1 1 0.2\ntriangle 0 1 2\n", "reject"),
        "bg_mesh_zero_size": ("vertex 0 0 0\nvertex 1 0 0.1\nvertex 1 1 0.2\ntriangle 0 1 2\n", "reject"),
        "bg_mesh_degenerate": ("vertex 0 0 0.1\nvertex 1 0 0.1\nvertex 2 0 0.2\ntriangle 0 1 2\n", "either"),
        "bg_mesh_no_triangles": ("vertex 0 0 0.1\nvertex 1 0 0.1\n", "either"),
        "bg_mesh_repeated": ("vertex 0 0 0.1\nvertex 1 0 0.1\nvertex 1 1 0.2\ntriangle 0 0 2\n", "either"),
        "box_quadtree": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 1.2\nbox 0 0 1 1\nquadtree\n", "either"),
        "box_inverted": ("uniform 0.2\nbox 1 1 0 0\nquadtree\n", "reject"),
        "box_zero": ("uniform 0.2\nbox 0 0 0 0\nquadtree\n", "reject"),
        "box_nan": ("uniform 0.2\nbox 0 0 nan 1\nquadtree\n", "reject"),
        "quadtree_no_box": ("uniform 0.2\nquadtree\n", "reject"),
        "quadtree_tol_neg": ("uniform 0.2\nbox 0 0 1 1\nquadtree -1\n", "reject"),
        "quadtree_tol_zero": ("uniform 0.2\npoint 0.5 0.5 0.01 0.1 1.2\nbox 0 0 1 1\nquadtree 0 2\n", "either"),
        "quadtree_factor_huge": ("uniform 0.2\nbox 0 0 1 1\nquadtree 0.1 1e308\n", "either"),
        "smooth_huge": ("uniform 0.2\nbox 0 0 1 1\nsmooth 100000 100000\n", "reject"),
        "smooth_2p32": ("uniform 0.2\nbox 0 0 1 1\nsmooth 4294967296 2\n", "reject"),
        "smooth_zero": ("uniform 0.2\nbox 0 0 1 1\nsmooth 0 0\n", "reject"),
        "smooth_one": ("uniform 0.2\nbox 0 0 1 1\nsmooth 1 1\n", "either"),
        "smooth_grade_neg": ("uniform 0.2\nbox 0 0 1 1\nsmooth 10 10 -1\n", "reject"),
        "smooth_grade_nan": ("uniform 0.2\nbox 0 0 1 1\nsmooth 10 10 nan\n", "reject"),
        "smooth_length_zero": ("uniform 0.2\nbox 0 0 1 1\nsmooth 10 10 0.3 0\n", "either"),
        "box_far": ("uniform 0.2\nbox 1e300 1e300 1.1e300 1.1e300\nsmooth 10 10\n", "either"),
        "crlf": ("uniform 0.2\r\npoint 0.5 0.5 0.01 0.1 1.2\r\n", "accept"),
        "bom": ("\ufeffuniform 0.2\n", "accept"),
        "binary": (bytes(range(256)) * 10, "reject"),
        "point_1e12": ("uniform 0.2\npoint 0.5 0.5 1e-9 1e-9 1.0001\n", "reject"),
    }
    for name, (text, exp) in size_files.items():
        cmds = [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", "{d}/size.txt"],
                ["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", "{d}/size.txt", "--generator", "frontal"],
                ["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", "{d}/size.txt", "--generator", "quadtree"]]
        add(f"size_{name}", {"in.poly": SQ, "size.txt": text}, cmds, exp)
    add("size_devzero", {"in.poly": SQ, "size.txt": ("symlink", "/dev/zero")}, [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", "{d}/size.txt"]], "reject")
    add("size_dir", {"in.poly": SQ, "size.txt": ("dir",)}, [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", "{d}/size.txt"]], "reject")
    add("size_is_output", {"in.poly": SQ, "size.txt": "uniform 0.2\n"}, [["mesh", "{d}/in.poly", "-o", "{d}/size.txt"]], "reject")
    for expr in ["1/0", "0/0", "sqrt(-1)", "-0.1", "0", "x-0.5", "1e-12", "1e-300", "1e308", "1e400", "log(x)", "1/x",
                 "x<0.5?0.1:-1", "abs(sin(1/(x-0.5)))", "0.1*(x>2)", "_pi*1e-9", "rnd()", "sum()", "", "  ", "x y", "z", "t",
                 "0.1+x*1e-320", "5e-324", "(((((((((((((((((((((((((((((((0.1)))))))))))))))))))))))))))))))", "0.1" + "+0" * 20000]:
        cmds = [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", expr, "--generator", g] for g in ["delaunay-refinement", "quadtree", "advancing-front", "frontal", "metric-delaunay"]]
        cmds.append(["mesh", "--domain", "key", "-o", "{d}/o.ele", "--size", expr])
        cmds.append(["tetmesh", "{d}/cube.poly", "-o", "{d}/o.ele", "--generator", "frontal", "--size", expr])
        cmds.append(["tetmesh", "{d}/cube.poly", "-o", "{d}/o.ele", "--generator", "octree", "--size", expr])
        add("size_expr", {"in.poly": SQ, "cube.poly": POLY3}, cmds, "either")
    # numeric sizes asking for 10^12 elements
    for s in ["1e-6", "1e-9", "1e-150", "5e-324", "1e-320"]:
        cmds = [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", s, "--generator", g] for g in GEN2]
        cmds += [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--size", s, "--generator", "stretched-delaunay", "--layers", "0.01,1.2"],
                 ["tetmesh", "{d}/cube.poly", "-o", "{d}/o.ele", "--max-volume", s],
                 ["tetmesh", "{d}/cube.poly", "-o", "{d}/o.ele", "--generator", "frontal", "--size", s],
                 ["tetmesh", "{d}/cube.poly", "-o", "{d}/o.ele", "--generator", "octree", "--size", s],
                 ["adapt", "{d}/in.poly", "--field", "x", "-o", "{d}/o.ele", "--size", s, "--cycles", "1"],
                 ["adapt", "{d}/in.poly", "--field", "x", "-o", "{d}/o.ele", "--size", s, "--method", "remesh", "--cycles", "1"]]
        add(f"budget_{s}", {"in.poly": SQ, "cube.poly": POLY3}, cmds, "reject")
    for lay in ["1e-300,1.2", "0.01,1", "0.01,0.5", "0.01,1e308", "0,1.2", "-1,1.2", "nan,1.2", "0.01,1.2,4294967296", "0.01,1.2,0", "1e-12,1.0000001,1000000", "0.01", "a,b"]:
        add("layers", {"in.poly": POLY2}, [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--generator", g, "--layers", lay] for g in ["stretched-delaunay", "advancing-layers"]], "either")
    # metric files
    MNODE = "4 2 3 0\n1 0 0 100 0 100\n2 1 0 100 0 100\n3 1 1 100 0 100\n4 0 1 100 0 100\n"
    MELE = "2 3 0\n1 1 2 3\n2 1 3 4\n"
    for name, (nt, et, exp) in {
        "ok": (MNODE, MELE, "accept"),
        "neg_def": (MNODE.replace("100 0 100\n4", "-100 0 100\n4"), MELE, "reject"),
        "indefinite": (MNODE.replace("100 0 100\n4", "1 5 1\n4"), MELE, "reject"),
        "zero": (MNODE.replace("100 0 100\n4", "0 0 0\n4"), MELE, "reject"),
        "nan": (MNODE.replace("100 0 100\n4", "nan 0 100\n4"), MELE, "reject"),
        "huge": (MNODE.replace("100 0 100", "1e300 0 1e300"), MELE, "reject"),
        "tiny": (MNODE.replace("100 0 100", "1e-300 0 1e-300"), MELE, "reject"),
        "two_attr": ("4 2 2 0\n1 0 0 1 1\n2 1 0 1 1\n3 1 1 1 1\n4 0 1 1 1\n", MELE, "reject"),
        "stretch_ok": ("4 2 4 0\n1 0 0 1 0 0.1 10\n2 1 0 1 0 0.1 10\n3 1 1 1 0 0.1 10\n4 0 1 1 0 0.1 10\n", MELE, "accept"),
        "stretch_zero_dir": ("4 2 4 0\n1 0 0 0 0 0.1 10\n2 1 0 1 0 0.1 10\n3 1 1 1 0 0.1 10\n4 0 1 1 0 0.1 10\n", MELE, "reject"),
        "stretch_neg_size": ("4 2 4 0\n1 0 0 1 0 -0.1 10\n2 1 0 1 0 0.1 10\n3 1 1 1 0 0.1 10\n4 0 1 1 0 0.1 10\n", MELE, "reject"),
        "stretch_aspect_huge": ("4 2 4 0\n1 0 0 1 0 0.1 1e300\n2 1 0 1 0 0.1 10\n3 1 1 1 0 0.1 10\n4 0 1 1 0 0.1 10\n", MELE, "reject"),
        "stretch_aspect_lt1": ("4 2 4 0\n1 0 0 1 0 0.1 0.5\n2 1 0 1 0 0.1 10\n3 1 1 1 0 0.1 10\n4 0 1 1 0 0.1 10\n", MELE, "either"),
        "ele_missing": (MNODE, None, "reject"),
        "ele_bad_index": (MNODE, "2 3 0\n1 1 2 3\n2 1 3 9\n", "reject"),
        "ele_degenerate": ("4 2 3 0\n1 0 0 100 0 100\n2 1 0 100 0 100\n3 2 0 100 0 100\n4 0 1 100 0 100\n", "1 3 0\n1 1 2 3\n", "reject"),
        "ele_overlap": (MNODE, "3 3 0\n1 1 2 3\n2 1 3 4\n3 1 2 4\n", "reject"),
        "ele_not_covering": ("4 2 3 0\n1 0 0 100 0 100\n2 0.1 0 100 0 100\n3 0.1 0.1 100 0 100\n4 0 0.1 100 0 100\n", MELE, "either"),
        "ele_empty": (MNODE, "0 3 0\n", "reject"),
        "ele_dir": (MNODE, ("dir",), "reject"),
        "dup_vertices": ("4 2 3 0\n1 0 0 100 0 100\n2 0 0 100 0 100\n3 1 1 100 0 100\n4 0 1 100 0 100\n", MELE, "reject"),
        "fine_1e12": (MNODE.replace("100 0 100", "1e12 0 1e12"), MELE, "reject"),
    }.items():
        files = {"in.poly": SQ, "m.node": nt, "m.ele": et}
        cmds = [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--generator", "metric-delaunay", "--metric", "{d}/m.node"],
                ["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--metric", "{d}/m.node", "--quality", "--size", "0.2"],
                ["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--generator", "metric-delaunay", "--metric", "{d}/m.node", "--metric-gradation", "0.3", "--metric-smoothing", "2"]]
        add(f"metric_{name}", files, cmds, exp)
    for expr in ["1;0;1", "1/0;0;1", "0/0;0;1", "-1;0;1", "1;2;1", "0;0;0", "1e300;0;1e300", "1e-300;0;1e-300", "1;0", "1;0;1;1;1",
                 "1;0;0.1;1e300", "0;0;0.1;10", "1;0;-0.1;10", "1;0;0.1;0.5", "1;0;0.1;nan", "x;0;1", "1e12;0;1e12", "1e16;0;1e16",
                 "1;0;1e-8;1", ";;", "1;;1"]:
        add("metric_expr", {"in.poly": SQ}, [["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--generator", "metric-delaunay", "--metric", expr],
                                             ["mesh", "{d}/in.poly", "-o", "{d}/o.ele", "--metric", expr, "--quality"]], "either")

    # ================= 3D node / tetrahedralize / swap3d / check =================
    for n, t, e in mutate_text(NODE3, "node3"):
        add(f"node3_{n}", {"in.node": t}, cmds_node3("{d}/in.node")[:1], e)
    for v, t in field_mutations(NODE3, 3, 3, NUMS):
        exp = "either" if v in ("-0", "-0.0", "1e300", "-1e300", "1e-300", "1e-320", "4.9e-324") else "reject"
        add(f"node3_z_{v.strip() or 'blank'}", {"in.node": t}, cmds_node3("{d}/in.node")[:1], exp)
    def node3(pts):
        return f"{len(pts)} 3 0 0\n" + "".join(f"{i+1} {x!r} {y!r} {z!r}\n" for i, (x, y, z) in enumerate(pts))
    geo3 = {
        "four_coplanar": [(0,0,0),(1,0,0),(0,1,0),(1,1,0)], "collinear": [(i,i,i) for i in range(6)], "one": [(0,0,0)],
        "zero": [], "all_same": [(1,2,3)] * 6, "dups": [(0,0,0),(1,0,0),(0,1,0),(0,0,1),(0,0,0),(0,0,1)],
        "huge": [(s1*1e300, s2*1e300, s3*1e300) for s1 in (-1,1) for s2 in (-1,1) for s3 in (-1,1)],
        "max": [(s1*1.7976931348623157e308, s2*1.7976931348623157e308, s3*1.7976931348623157e308) for s1 in (-1,1) for s2 in (-1,1) for s3 in (-1,1)],
        "tiny": [(s1*1e-300, s2*1e-300, s3*1e-300) for s1 in (-1,1) for s2 in (-1,1) for s3 in (-1,1)],
        "denormal": [(s1*5e-324, s2*5e-324, s3*5e-324) for s1 in (-1,1) for s2 in (-1,1) for s3 in (-1,1)],
        "mixed": [(1e300,0,0),(0,1e-300,0),(0,0,1),(1,1,1),(-1e-300,0,1e300)],
        "cospherical": [(1,0,0),(-1,0,0),(0,1,0),(0,-1,0),(0,0,1),(0,0,-1)] * 1,
    }
    for name, pts in geo3.items():
        add(f"node3geo_{name}", {"in.node": node3(pts)}, cmds_node3("{d}/in.node") + [["check", "{d}/in.node", "{d}/in.ele"]], "either")
    def cmds_ele3():
        return [["check", "{d}/in.node", "{d}/in.ele"],
                ["swap3d", "{d}/in.node", "{d}/in.ele", "-o", "{d}/o.ele", "--criterion", "delaunay"],
                ["swap3d", "{d}/in.node", "{d}/in.ele", "-o", "{d}/o.ele", "--criterion", "min-max-dihedral", "--edge-removal"],
                ["adapt", "{d}/in.node", "{d}/in.ele", "--field", "x*y*z", "-o", "{d}/o.ele", "--cycles", "1"]]
    for n, t, e in mutate_text(ELE3_TET, "ele3"):
        add(f"ele3_{n}", {"in.node": NODE3_TET, "in.ele": t}, cmds_ele3()[:2], e)
    for name, t in [
        ("repeated", "2 4 0\n1 1 2 3 3\n2 2 3 4 5\n"), ("negative", "2 4 0\n1 1 2 3 -4\n2 2 3 4 5\n"),
        ("past", "2 4 0\n1 1 2 3 6\n2 2 3 4 5\n"), ("zero", "2 4 0\n1 0 2 3 4\n2 2 3 4 5\n"),
        ("inverted", "2 4 0\n1 2 1 3 4\n2 2 3 4 5\n"), ("flat", "1 4 0\n1 1 2 3 3\n"),
        ("ten_nodes", "2 10 0\n1 1 2 3 4 1 1 1 1 1 1\n2 2 3 4 5 1 1 1 1 1 1\n"), ("three_nodes", "2 3 0\n1 1 2 3\n2 2 3 4\n"),
        ("dup_tet", "3 4 0\n1 1 2 3 4\n2 2 3 4 5\n3 1 2 3 4\n"), ("overlap", "3 4 0\n1 1 2 3 4\n2 2 3 4 5\n3 1 2 3 5\n"),
        ("region_attr", "2 4 1\n1 1 2 3 4 1\n2 2 3 4 5 2\n"), ("region_attr_nan", "2 4 1\n1 1 2 3 4 nan\n2 2 3 4 5 2\n"),
        ("count_2p31", "2147483648 4 0\n1 1 2 3 4\n"),
    ]:
        add(f"ele3_{name}", {"in.node": NODE3_TET, "in.ele": t}, cmds_ele3(), "either" if name in ("ten_nodes", "region_attr") else "reject")
    add("ele3_node_missing", {"in.ele": ELE3_TET}, cmds_ele3(), "reject")
    add("ele3_node_2d", {"in.node": NODE2, "in.ele": ELE3_TET}, cmds_ele3(), "reject")
    add("ele3_degenerate_coplanar_nodes", {"in.node": "5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n5 2 2 0\n", "in.ele": ELE3_TET}, cmds_ele3(), "reject")
    add("ele3_huge_coords", {"in.node": "5 3 0 0\n1 0 0 0\n2 1e300 0 0\n3 0 1e300 0\n4 0 0 1e300\n5 1e300 1e300 1e300\n", "in.ele": ELE3_TET}, cmds_ele3(), "either")
    add("ele3_tiny_coords", {"in.node": "5 3 0 0\n1 0 0 0\n2 1e-300 0 0\n3 0 1e-300 0\n4 0 0 1e-300\n5 1e-300 1e-300 1e-300\n", "in.ele": ELE3_TET}, cmds_ele3(), "either")
    add("ele3_denormal_coords", {"in.node": "5 3 0 0\n1 0 0 0\n2 1e-322 0 0\n3 0 1e-322 0\n4 0 0 1e-322\n5 1e-322 1e-322 1e-322\n", "in.ele": ELE3_TET}, cmds_ele3(), "either")
    add("ele3_max_coords", {"in.node": "5 3 0 0\n1 0 0 0\n2 1.7976931348623157e308 0 0\n3 0 1.7976931348623157e308 0\n4 0 0 1.7976931348623157e308\n5 1.7976931348623157e308 1.7976931348623157e308 1.7976931348623157e308\n", "in.ele": ELE3_TET}, cmds_ele3(), "either")
    add("ele3_unused", {"in.node": NODE3_TET, "in.ele": "1 4 0\n1 1 2 3 4\n"}, cmds_ele3(), "either")

    # ================= PLC files (tetmesh, check) =================
    for fmt, base, fname in [("poly3", POLY3, "in.poly"), ("smesh", SMESH, "in.smesh"), ("off", OFF, "in.off"), ("stla", STL_A, "in.stl")]:
        for n, t, e in mutate_text(base, fmt):
            if fmt == "stla" and n.startswith("count_"):
                continue
            if fmt == "off" and n in ("count_0x10",):
                pass
            add(f"{fmt}_{n}", {fname: t}, cmds_plc("{d}/" + fname)[:1], e)
    PL3 = lines_of(POLY3)
    # index 9 is the facet header "6 1"
    facet_line = 11  # "4 1 2 3 4"
    def p3(i, new):
        L = list(PL3); L[i] = new; return "\n".join(L)
    for name, t, exp in [
        ("facet_0_corners", p3(facet_line, "0"), "reject"),
        ("facet_1_corner", p3(facet_line, "1 1"), "reject"),
        ("facet_2_corners", p3(facet_line, "2 1 2"), "reject"),
        ("facet_repeated_corner", p3(facet_line, "4 1 2 2 4"), "either"),
        ("facet_all_same", p3(facet_line, "4 1 1 1 1"), "reject"),
        ("facet_corner_count_big", p3(facet_line, "5 1 2 3 4"), "reject"),
        ("facet_corner_count_2p32", p3(facet_line, "4294967296 1 2 3 4"), "reject"),
        ("facet_corner_zero", p3(facet_line, "4 0 2 3 4"), "reject"),
        ("facet_corner_past", p3(facet_line, "4 1 2 3 9"), "reject"),
        ("facet_corner_neg", p3(facet_line, "4 1 2 3 -4"), "reject"),
        ("facet_collinear", p3(facet_line, "3 1 2 2"), "reject"),
        ("facet_bowtie", p3(facet_line, "4 1 3 2 4"), "reject"),
        ("facet_nonplanar", p3(facet_line, "4 1 2 3 8"), "reject"),
        ("facet_polygons_0", p3(facet_line - 1, "0 0 1"), "reject"),
        ("facet_polygons_2p40", p3(facet_line - 1, "1099511627776 0 1"), "reject"),
        ("facet_holes_big", p3(facet_line - 1, "1 5 1"), "reject"),
        ("facet_marker_nan", p3(facet_line - 1, "1 0 nan"), "reject"),
        ("facet_header_big", p3(9, "7 1"), "reject"),
        ("facet_header_small", p3(9, "5 1"), "reject"),
        ("facet_missing", "\n".join(PL3[:9] + ["5 1"] + PL3[12:]), "reject"),
        ("facet_duplicated", "\n".join(PL3[:9] + ["7 1"] + PL3[10:22] + PL3[10:12] + PL3[22:]), "reject"),
        ("facet_flipped", p3(facet_line, "4 4 3 2 1"), "accept"),
        ("hole_outside", "\n".join(PL3[:-3] + ["1", "1 5 5 5", "0", ""]), "either"),
        ("hole_inside_all", "\n".join(PL3[:-3] + ["1", "1 0.5 0.5 0.5", "0", ""]), "reject"),
        ("hole_on_facet", "\n".join(PL3[:-3] + ["1", "1 0.5 0.5 0", "0", ""]), "reject"),
        ("hole_nan", "\n".join(PL3[:-3] + ["1", "1 nan 0.5 0.5", "0", ""]), "reject"),
        ("region_outside", "\n".join(PL3[:-3] + ["0", "1", "1 5 5 5 1 0.1", ""]), "either"),
        ("region_vol_zero", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 0.5 1 0", ""]), "either"),
        ("region_vol_neg", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 0.5 1 -1", ""]), "either"),
        ("region_vol_tiny", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 0.5 1 1e-300", ""]), "reject"),
        ("region_vol_denormal", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 0.5 1 5e-324", ""]), "reject"),
        ("region_attr_missing", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 0.5", ""]), "reject"),
        ("region_on_facet", "\n".join(PL3[:-3] + ["0", "1", "1 0.5 0.5 1 7 0.1", ""]), "reject"),
        ("open_box", "\n".join(PL3[:9] + ["5 1"] + PL3[12:]).replace("5 1\n1 0 2", "5 1\n1 0 2"), "reject"),
        ("points_from_node_missing", "0 3 0 0\n" + "\n".join(PL3[9:]), "reject"),
        ("dim2", POLY3.replace("8 3 0 0", "8 2 0 0", 1), "reject"),
        ("huge", POLY3.replace(" 1", " 1e300").replace("\n1e300 ", "\n1 "), "either"),
        ("tiny", POLY3.replace(" 1 ", " 1e-300 ").replace(" 1\n", " 1e-300\n"), "either"),
        ("dup_points", POLY3.replace("8 3 0 0", "9 3 0 0").replace("8 0 1 1\n", "8 0 1 1\n9 0 1 1\n"), "either"),
        ("free_dup_point", POLY3.replace("8 3 0 0", "9 3 0 0").replace("8 0 1 1\n", "8 0 1 1\n9 0.5 0.5 0.5\n"), "either"),
        ("free_outside_point", POLY3.replace("8 3 0 0", "9 3 0 0").replace("8 0 1 1\n", "8 0 1 1\n9 5 5 5\n"), "either"),
        ("nested_same_cube", None, "reject"),
    ]:
        if t is None:
            # two identical cubes: overlapping facets
            t = POLY3.replace("6 1\n", "12 1\n", 1).replace("\n0\n0\n", "\n" + "".join(f"1 0 {i+7}\n4 {' '.join(map(str,f))}\n" for i, f in enumerate(CUBE_FACETS)) + "0\n0\n")
        add(f"poly3_{name}", {"in.poly": t}, cmds_plc("{d}/in.poly"), exp)
    # smesh specifics
    for name, t, exp in [
        ("smesh_tri_facet_degenerate", SMESH.replace("4 1 2 3 4\n", "3 1 1 2\n3 1 2 3\n"), "reject"),
        ("smesh_marker_declared_missing", SMESH.replace("6 0\n", "6 1\n"), "reject"),
    ]:
        add(name, {"in.smesh": t}, cmds_plc("{d}/in.smesh"), exp)
    # OFF specifics
    for name, t, exp in [
        ("off_counts_same_line", OFF.replace("OFF\n8 6 12", "OFF 8 6 12"), "accept"),
        ("off_coff", OFF.replace("OFF", "COFF"), "reject"),
        ("off_colour", OFF.replace("4 0 1 2 3\n", "4 0 1 2 3 1 0 0\n"), "accept"),
        ("off_colour_nan", OFF.replace("4 0 1 2 3\n", "4 0 1 2 3 nan 0 0\n"), "reject"),
        ("off_colour_2", OFF.replace("4 0 1 2 3\n", "4 0 1 2 3 1 0\n"), "reject"),
        ("off_face_1", OFF.replace("4 0 1 2 3\n", "1 0\n"), "reject"),
        ("off_face_2", OFF.replace("4 0 1 2 3\n", "2 0 1\n"), "reject"),
        ("off_face_index_8", OFF.replace("4 0 1 2 3\n", "4 0 1 2 8\n"), "reject"),
        ("off_vcount_2p30", OFF.replace("8 6 12", "1073741824 6 12"), "reject"),
        ("off_vcount_2p32", OFF.replace("8 6 12", "4294967296 6 12"), "reject"),
        ("off_fcount_big", OFF.replace("8 6 12", "8 7 12"), "reject"),
        ("off_edges_wrong", OFF.replace("8 6 12", "8 6 99"), "either"),
        ("off_4d_vertex", OFF.replace("\n1 1 1\n", "\n1 1 1 1\n"), "reject"),
        ("off_tri_faces", "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIS), "accept"),
        ("off_inconsistent_orientation", "OFF\n8 12 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(f"3 {a} {c} {b}\n" if i == 0 else f"3 {a} {b} {c}\n" for i, (a, b, c) in enumerate(TRIS)), "either"),
        ("off_open", "OFF\n8 11 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIS[1:]), "reject"),
        ("off_dup_face", "OFF\n8 13 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIS + [TRIS[0]]), "reject"),
        ("off_unused_vertex", OFF.replace("8 6 12", "9 6 12").replace("0 1 1\n4", "0 1 1\n0.5 0.5 0.5\n4"), "either"),
        ("off_dup_vertex", OFF.replace("8 6 12", "9 6 12").replace("0 1 1\n4", "0 1 1\n0 1 1\n4").replace("4 3 0 4 7", "4 3 0 4 8"), "either"),
        ("off_zero_area_face", "OFF\n8 13 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n" + "".join(f"3 {a} {b} {c}\n" for a, b, c in TRIS) + "3 0 1 1\n", "reject"),
    ]:
        add(name, {"in.off": t}, cmds_plc("{d}/in.off"), exp)
    # STL specifics
    degenerate_pts = P + [(0.5, 0, 0)]
    for name, data, exp in [
        ("stl_bin_ok", STL_B, "accept"),
        ("stl_bin_count_plus1", stl_binary(TRIS, count=13), "reject"),
        ("stl_bin_count_minus1", stl_binary(TRIS, count=11), "reject"),
        ("stl_bin_count_max", stl_binary(TRIS, count=0xFFFFFFFF), "reject"),
        ("stl_bin_count_2p31", stl_binary(TRIS, count=0x80000000), "reject"),
        ("stl_bin_count_zero_empty", stl_binary([], count=0), "reject"),
        ("stl_bin_count_zero_with_data", stl_binary(TRIS, count=0), "reject"),
        ("stl_bin_header_solid", stl_binary(TRIS, header=b"solid cube binary"), "accept"),
        ("stl_bin_header_solid_bad_count", stl_binary(TRIS, header=b"solid cube binary", count=5), "reject"),
        ("stl_bin_trailing_byte", stl_binary(TRIS, extra=b"\0"), "reject"),
        ("stl_bin_truncated", stl_binary(TRIS)[:-10], "reject"),
        ("stl_bin_nan", stl_binary(TRIS, pts=[(float("nan"), 0, 0)] + P[1:]), "reject"),
        ("stl_bin_inf", stl_binary(TRIS, pts=[(float("inf"), 0, 0)] + P[1:]), "reject"),
        ("stl_bin_denormal", stl_binary(TRIS, pts=[(x * 1e-44, y * 1e-44, z * 1e-44) for x, y, z in P]), "either"),
        ("stl_bin_huge", stl_binary(TRIS, pts=[(x * 3e38, y * 3e38, z * 3e38) for x, y, z in P]), "either"),
        ("stl_bin_degenerate_tri", stl_binary(TRIS + [(0, 1, 1)]), "reject"),
        ("stl_bin_collinear_tri", stl_binary(TRIS + [(0, 8, 1)], pts=degenerate_pts), "reject"),
        ("stl_bin_open", stl_binary(TRIS[1:]), "reject"),
        ("stl_bin_dup", stl_binary(TRIS + TRIS[:1]), "reject"),
        ("stl_bin_flipped_one", stl_binary([(a, c, b) if i == 3 else (a, b, c) for i, (a, b, c) in enumerate(TRIS)]), "either"),
        ("stl_bin_all_flipped", stl_binary([(a, c, b) for a, b, c in TRIS]), "either"),
        ("stl_bin_84_bytes_junk", b"\xff" * 84, "reject"),
        ("stl_bin_83_bytes", b"\x00" * 83, "reject"),
        ("stl_bin_random", bytes(random.Random(3).randrange(256) for _ in range(84 + 50 * 12)), "reject"),
        ("stl_ascii_5_vertices", STL_A.replace("  endloop\n", "   vertex 0 0 0\n  endloop\n", 1), "reject"),
        ("stl_ascii_2_vertices", STL_A.replace("   vertex 0 0 0\n", "", 1), "reject"),
        ("stl_ascii_no_endsolid", STL_A.replace("endsolid cube\n", ""), "reject"),
        ("stl_ascii_two_solids", STL_A + STL_A, "reject"),
        ("stl_ascii_normal_nan", STL_A.replace("facet normal 0 0 0", "facet normal nan nan nan", 1), "either"),
        ("stl_ascii_normal_garbage", STL_A.replace("facet normal 0 0 0", "facet normal a b c", 1), "either"),
        ("stl_ascii_uppercase", STL_A.upper(), "either"),
        ("stl_ascii_degenerate", STL_A.replace("endsolid", " facet normal 0 0 0\n  outer loop\n   vertex 0 0 0\n   vertex 0 0 0\n   vertex 1 0 0\n  endloop\n endfacet\nendsolid"), "reject"),
        ("stl_ascii_empty_solid", "solid x\nendsolid x\n", "reject"),
        ("stl_ascii_solid_only", "solid", "reject"),
        ("stl_devzero", ("symlink", "/dev/zero"), "reject"),
        ("stl_dir", ("dir",), "reject"),
    ]:
        add(name, {"in.stl": data}, cmds_plc("{d}/in.stl")[:2], exp)
    # check with a PLC
    add("plc_check_bad_ele", {"in.poly": POLY3, "m.ele": ELE3_TET, "m.node": NODE3_TET}, [["check", "{d}/in.poly", "{d}/m.ele"]], "either")
    add("plc_check_no_node", {"in.poly": POLY3, "m.ele": ELE3_TET}, [["check", "{d}/in.poly", "{d}/m.ele"]], "reject")
    add("plc_check_off_no_node", {"in.off": OFF, "m.ele": ELE3_TET}, [["check", "{d}/in.off", "{d}/m.ele"]], "reject")
    add("plc_check_face_bad", {"in.poly": POLY3, "m.ele": ELE3_TET, "m.node": NODE3_TET, "m.face": "1 1\n1 1 2 99 1\n"}, [["check", "{d}/in.poly", "{d}/m.ele"]], "reject")
    add("plc_check_face_garbage", {"in.poly": POLY3, "m.ele": ELE3_TET, "m.node": NODE3_TET, "m.face": "\0\0\0"}, [["check", "{d}/in.poly", "{d}/m.ele"]], "reject")
    # inputs named oddly / extension issues
    add("ext_unknown", {"in.xyz": NODE2}, [["triangulate", "{d}/in.xyz", "-o", "{d}/o.ele"], ["tetmesh", "{d}/in.xyz", "-o", "{d}/o.ele"], ["cdt", "{d}/in.xyz", "-o", "{d}/o.ele"], ["mesh", "{d}/in.xyz", "-o", "{d}/o.ele"]], "either")
    add("ext_none", {"in": NODE2}, [["triangulate", "{d}/in", "-o", "{d}/o.ele"], ["cdt", "{d}/in", "-o", "{d}/o.ele"]], "either")
    add("output_dir", {"in.node": NODE2, "o.ele": ("dir",)}, [["triangulate", "{d}/in.node", "-o", "{d}/o.ele"]], "reject")
    add("output_ext_bad", {"in.node": NODE2}, [["triangulate", "{d}/in.node", "-o", "{d}/o.xyz"], ["triangulate", "{d}/in.node", "-o", "{d}/o"]], "reject")
    add("input_devzero_all", {"z.node": ("symlink", "/dev/zero"), "z.poly": ("symlink", "/dev/zero"), "z.off": ("symlink", "/dev/zero"), "z.smesh": ("symlink", "/dev/zero"), "z.stl": ("symlink", "/dev/zero")},
        [["tetrahedralize", "{d}/z.node", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.poly", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.off", "-o", "{d}/o.ele"],
         ["tetmesh", "{d}/z.smesh", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.stl", "-o", "{d}/o.ele"], ["min-max", "{d}/z.node", "-o", "{d}/o.ele"],
         ["adapt", "{d}/z.poly", "--field", "x", "-o", "{d}/o.ele"], ["mesh", "{d}/z.poly", "-o", "{d}/o.ele"],
         ["check", "{d}/z.node", "{d}/z.node"], ["check", "{d}/z.stl", "{d}/z.node"], ["check", "{d}/z.off", "{d}/z.node"]], "reject")
    add("input_dir_all", {"z.node": ("dir",), "z.poly": ("dir",), "z.off": ("dir",), "z.stl": ("dir",)},
        [["tetrahedralize", "{d}/z.node", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.poly", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.off", "-o", "{d}/o.ele"],
         ["tetmesh", "{d}/z.stl", "-o", "{d}/o.ele"], ["adapt", "{d}/z.poly", "--field", "x", "-o", "{d}/o.ele"], ["check", "{d}/z.stl", "{d}/z.node"]], "reject")
    add("input_missing_all", {},
        [["tetrahedralize", "{d}/z.node", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.poly", "-o", "{d}/o.ele"], ["tetmesh", "{d}/z.stl", "-o", "{d}/o.ele"],
         ["adapt", "{d}/z.poly", "--field", "x", "-o", "{d}/o.ele"], ["mesh", "{d}/z.poly", "-o", "{d}/o.ele"], ["swap3d", "{d}/z.node", "{d}/z.ele", "-o", "{d}/o.ele"]], "reject")

    with open(os.path.join(out, "manifest.jsonl"), "w") as f:
        for c in cases:
            f.write(json.dumps(c) + "\n")
    print(len(cases), "runs written to", out)


def run_case(d, exe, c):
    cd = os.path.join(d, "cases", c["id"])
    cmd = [a.replace("{d}", cd) for a in c["cmd"]]
    for f in os.listdir(cd):
        p = os.path.join(cd, f)
        if f.startswith("o.") and os.path.isfile(p) and not os.path.islink(p):
            os.remove(p)
    tf = os.path.join(cd, ".time")
    sh = f'ulimit -v 4000000; exec /usr/bin/time -o {shlex.quote(tf)} -f "%M %e" timeout -s KILL 20 "$@"'
    t0 = time.time()
    p = subprocess.run(["bash", "-c", sh, "x", exe] + cmd, capture_output=True, timeout=60)
    wall = time.time() - t0
    rss, sig = 0, None
    try:
        txt = open(tf).read()
        for line in txt.split("\n"):
            m = re.match(r"^(\d+) ([\d.]+)$", line.strip())
            if m:
                rss = int(m.group(1))
        m = re.search(r"terminated by signal (\d+)", txt)
        if m:
            sig = int(m.group(1))
    except OSError:
        pass
    return {**c, "rc": p.returncode, "sig": sig, "wall": round(wall, 3), "rss_kb": rss,
            "stderr": p.stderr.decode(errors="replace")[-3000:]}


def classify(r):
    rc, e = r["rc"], r["expect"]
    lines = [l for l in r["stderr"].splitlines() if l.strip()]
    errors = [l for l in lines if l.startswith("exactmesh: error:")]
    files = [os.path.basename(a) for a in r["cmd"] if "{d}" in a]
    cls = []
    if r["sig"] is not None or rc < 0 or rc >= 128:
        cls.append("CRASH" if r["wall"] < 19.5 else "TIMEOUT")
    elif rc == 3:
        cls.append("INTERNAL")
    elif rc == 0 and e == "reject":
        cls.append("ACCEPTED_GARBAGE")
    elif rc == 2:
        if e == "accept":
            cls.append("REFUSED_VALID")
        if len(errors) != 1:
            cls.append("NOT_ONE_ERROR_LINE")
        elif files and r["id"] not in errors[0] and "--" not in errors[0] \
                and "field '" not in errors[0]:  # a file of the run (or its companion), an option
            cls.append("NO_FILE")
    elif rc == 1 and r["cmd"][0] != "check":
        cls.append("EXIT1")
    elif rc not in (0, 1, 2):
        cls.append(f"EXIT{rc}")
    if r["rss_kb"] > 1_000_000:
        cls.append("RSS")
    if r["wall"] > 5 and "TIMEOUT" not in cls and rc != 0:
        cls.append("SLOW")
    return cls or ["good"]


def recheck(d, exe, r):
    """`exactmesh check` of the mesh an exit-0 run wrote, or None when there is none to check."""
    c = r["cmd"]
    cd = os.path.join(d, "cases", r["id"])
    out = os.path.join(cd, "o.ele")
    if r["rc"] != 0 or not os.path.exists(out) or "-o" not in c or not c[c.index("-o") + 1].endswith("o.ele"):
        return None
    sub = lambda a: a.replace("{d}", cd)
    if c[0] in ("triangulate", "tetrahedralize", "swap", "swap3d"):
        chk = ["check", sub(c[1]), out]
    elif c[0] == "cdt":
        chk = ["check", sub(c[1]), out] + (["--convex-hull"] if "--convex-hull" in c else [])
    elif c[0] == "mesh" and c[1].startswith("{d}"):
        g = c[c.index("--generator") + 1] if "--generator" in c else "delaunay-refinement"
        chk = ["check", sub(c[1]), out] + ([] if g == "delaunay-refinement" else ["--conforming"])
    elif c[0] == "tetmesh" and c[1].startswith("{d}"):
        chk = ["check", sub(c[1]), out]
    else:
        return None
    p = subprocess.run([exe] + chk, capture_output=True, timeout=120)
    if p.returncode == 2 and b"--convex-hull is checked only" in p.stderr:
        # The hull check's refusal with hole points: the constrained Delaunay check instead.
        p = subprocess.run([exe] + chk[:-1], capture_output=True, timeout=120)
    return p.returncode, (p.stdout + p.stderr).decode(errors="replace").strip()[:300]


def run(d, exe, jobs):
    cases = [json.loads(l) for l in open(os.path.join(d, "manifest.jsonl"))]
    with cf.ThreadPoolExecutor(jobs) as ex:
        results = list(ex.map(lambda c: run_case(d, exe, c), cases))
    with open(os.path.join(d, "results.jsonl"), "w") as f:
        for r in results:
            f.write(json.dumps(r) + "\n")
    counts, bad = {}, False
    for r in results:
        for k in classify(r):
            counts[k] = counts.get(k, 0) + 1
            if k != "good":
                bad |= k in ("CRASH", "TIMEOUT", "INTERNAL", "RSS", "SLOW")
                print(f"{k}: {r['id']} exit {r['rc']} {r['wall']} s {r['rss_kb'] // 1024} MB: "
                      f"exactmesh {' '.join(r['cmd']).replace('{d}/', '')[:160]}\n    "
                      f"{r['stderr'].strip()[:240]!r}")
    checked = failed = 0
    for r in results:
        verdict = recheck(d, exe, r)
        if verdict is None:
            continue
        checked += 1
        if verdict[0] != 0:
            failed += 1
            print(f"CHECK FAILED: {r['id']}: exactmesh {' '.join(r['cmd']).replace('{d}/', '')[:160]}: {verdict[1]}")
    print(f"{len(results)} runs: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    print(f"meshes written and re-checked: {checked}, failed: {failed}")
    return 1 if bad or failed else 0


if __name__ == "__main__":
    if len(sys.argv) >= 3 and sys.argv[1] == "--run":
        exe = sys.argv[3] if len(sys.argv) > 3 else "build/release/cli/exactmesh"
        sys.exit(run(sys.argv[2], os.path.abspath(exe), int(sys.argv[4]) if len(sys.argv) > 4 else 2))
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    generate(sys.argv[1])
