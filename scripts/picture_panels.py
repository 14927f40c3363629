#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Mesh pictures a reader can read (issue 18): for each 2D sample domain, one figure with every
generator side by side (and Gmsh's Delaunay and Frontal-Delaunay when `gmsh` is installed) on the
same window and scale, triangles shaded by their smallest angle with a colour bar, the minimum
angle and the triangle count under each panel; and a zoomed figure per detail (the airfoils'
leading and trailing edges and the gaps between elements, the key's 10-degree tooth).

The meshes are made for the picture, not taken from the benchmark: one --size per domain (a
uniform size, or the domain's own line source with its strength scaled), calibrated so the
median count over the generators is about --target triangles, and the same for every generator. Each figure is
written as SVG and PNG (PNG at a dpi that keeps it small); pictures.md lists them.

Usage: picture_panels.py --cli build/release/cli/exactmesh --out-dir report [--target 3500]
       [--domains D ...] [--generators G ...] [--no-gmsh] [--markdown pictures.md]
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.colors import BoundaryNorm, ListedColormap  # noqa: E402

# The generators of `exactmesh mesh --help` that need nothing but a size (advancing-layers and
# stretched-delaunay need --layers: their pictures are in the stretched-mesh report).
GENERATORS = ["delaunay-refinement", "quadtree", "advancing-front", "advancing-front-delaunay",
              "frontal", "metric-delaunay", "min-max-front"]
GMSH = {"gmsh-delaunay": 5, "gmsh-frontal": 6}

# Per domain: the size ("uniform", H) or ("line", X0, Y0, X1, Y1, S, RBAR, GAMMA, CAP) with H or
# S the calibrated strength (the starting guess here); the overview window (None: the whole
# domain); the zoom windows, each (file suffix, caption, X0, Y0, X1, Y1).
DOMAINS = {
    "square-with-holes": {
        "size": ("uniform", 0.035),
        "overview": None,
        "zooms": [("diamond", "the diamond's corners and the small hole", 0.1, 0.36, 0.5, 0.86)],
    },
    "naca0012": {
        # The domain's own source along the chord (generators/boundary/sample_domains.cpp).
        "size": ("line", 0.0, 0.0, 1.0, 0.0, 0.015, 0.1, 1.5, 0.5),
        "overview": (-0.35, -0.45, 1.35, 0.45),
        "zooms": [("leading-edge", "leading edge", -0.04, -0.06, 0.10, 0.06),
                  ("trailing-edge", "trailing edge", 0.90, -0.06, 1.04, 0.06)],
    },
    "key": {
        "size": ("uniform", 0.035),
        "overview": None,
        "zooms": [("tooth", "the 10-degree tooth", 1.30, -0.37, 1.50, -0.07)],
    },
    "three-element": {
        # One source from the slat's nose to the flap's trailing edge, as the domain's own.
        "size": ("line", -0.106, -0.018, 1.202, -0.133, 0.012, 0.1, 1.5, 0.5),
        "overview": (-0.25, -0.5, 1.35, 0.35),
        "zooms": [("slat-gap", "the slat and its gap, the main element's leading edge",
                   -0.16, -0.10, 0.10, 0.10),
                  ("flap-gap", "the main element's trailing edge over the flap, the flap gap",
                   0.82, -0.16, 1.06, 0.04),
                  ("flap-trailing-edge", "the flap's trailing edge", 1.10, -0.21, 1.26, -0.07)],
    },
}

ANGLE_CLASSES = 12  # 5 degrees each, 0 to 60: the classes of io/svg_picture.cpp
# matplotlib's RdYlBu from 0 to 0.8 (the darkest blues left out so edges stay visible on good
# triangles), sampled at each class's middle: the same colours as `--shade min-angle`.
COLOURS = ["#a50026", "#c0272d", "#dc3d2d", "#f0633e", "#f88d52", "#fdb366",
           "#fed384", "#fff0a8", "#f4fad9", "#d9eff6", "#b4ddec", "#8ec2dd"]


def size_text(spec, strength):
    """The size file of `spec` with its strength (H or S) set to `strength`."""
    if spec[0] == "uniform":
        return f"uniform {strength!r}\n"
    _, x0, y0, x1, y1, _, rbar, gamma, cap = spec
    return f"uniform {cap!r}\nline {x0!r} {y0!r} {x1!r} {y1!r} {strength!r} {rbar!r} {gamma!r}\n"


def strip(line):
    return line.split("#", 1)[0].split()


def data_lines(path):
    with open(path) as f:
        for line in f:
            fields = strip(line)
            if fields:
                yield fields


def read_node(path, dimension=2):
    """Vertices of a Triangle (dimension 2) or TetGen (3) .node, and the first index."""
    lines = data_lines(path)
    count = int(next(lines)[0])
    xy = np.empty((count, dimension))
    first = None
    for k in range(count):
        fields = next(lines)
        if first is None:
            first = int(fields[0])
        xy[k] = [float(v) for v in fields[1:1 + dimension]]
    return xy, first


def read_ele(path, first):
    lines = data_lines(path)
    count = int(next(lines)[0])
    triangles = np.empty((count, 3), dtype=np.int64)
    for k in range(count):
        fields = next(lines)
        triangles[k] = [int(v) - first for v in fields[1:4]]
    return triangles


def read_poly_segments(path, first):
    lines = data_lines(path)
    header = next(lines)
    for _ in range(int(header[0])):  # vertices listed in the .poly itself
        next(lines)
    count = int(next(lines)[0])
    return [(int(f[1]) - first, int(f[2]) - first) for f in (next(lines) for _ in range(count))]


def min_angles(xy, triangles):
    """Smallest angle of each triangle in degrees. Drawing only, but scale-free like
    io::triangle_min_angle_degrees: corners scaled by a power of two to the unit range, then the
    edge vectors again, so nothing overflows or underflows at 2^+-600 coordinates."""
    if len(triangles) == 0:
        return np.zeros(0)
    p = xy[triangles]  # T x 3 x 2
    largest = np.abs(p).reshape(len(p), -1).max(axis=1)
    _, e = np.frexp(np.where(largest > 0, largest, 1.0))
    p = np.ldexp(p, -e[:, None, None])
    edges = np.roll(p, -1, axis=1) - p  # edge k from corner k to corner k+1
    longest = np.abs(edges).reshape(len(p), -1).max(axis=1)
    _, f = np.frexp(np.where(longest > 0, longest, 1.0))
    edges = np.ldexp(edges, -f[:, None, None])
    u = -np.roll(edges, 1, axis=1)  # at corner k: from k back to k-1 ...
    v = edges  # ... and from k on to k+1
    cross = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
    dot = u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]
    angles = np.degrees(np.arctan2(np.abs(cross), dot)).min(axis=1)
    return np.where((largest > 0) & (longest > 0), np.clip(angles, 0.0, 60.0), 0.0)


def run_exactmesh(cli, domain, generator, size_file, out):
    done = subprocess.run([cli, "mesh", "--domain", domain, "--generator", generator, "--size",
                           size_file, "-o", out], capture_output=True, text=True)
    if done.returncode != 0:
        return None, done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed"
    xy, first = read_node(out[:-4] + ".node")
    return (xy, read_ele(out, first), read_poly_segments(out[:-4] + ".poly", first)), None


def gmsh_geo(xy, segments, spec, strength, algorithm):
    """A .geo of the boundary pieces (their loops; the outer one has the largest box) with the
    picture's size: Mesh.MeshSize{Min,Max} for a uniform size, else the source formula as
    Distance + MathEval fields (bench/mesh_bench.cpp's formula mode)."""
    used = sorted({v for s in segments for v in s})
    number = {v: k + 1 for k, v in enumerate(used)}
    out = [f"Point({number[v]}) = {{{xy[v][0]!r}, {xy[v][1]!r}, 0}};" for v in used]
    out += [f"Line({k + 1}) = {{{number[a]}, {number[b]}}};" for k, (a, b) in enumerate(segments)]
    at = {}
    for k, (a, b) in enumerate(segments):
        at.setdefault(a, []).append(k)
        at.setdefault(b, []).append(k)
    seen, loops = set(), []
    for start in range(len(segments)):
        if start in seen:
            continue
        loop, s, came_from, box = [], start, segments[start][0], [math.inf, -math.inf] * 2
        while True:
            seen.add(s)
            a, b = segments[s]
            forward = a == came_from
            loop.append(s + 1 if forward else -(s + 1))
            to = b if forward else a
            box = [min(box[0], xy[to][0]), max(box[1], xy[to][0]),
                   min(box[2], xy[to][1]), max(box[3], xy[to][1])]
            following = [t for t in at[to] if t not in seen]
            if not following:
                break
            s, came_from = following[0], to
        loops.append(((box[1] - box[0]) * (box[3] - box[2]), loop))
    loops.sort(key=lambda item: -item[0])
    for k, (_, loop) in enumerate(loops):
        out.append(f"Curve Loop({k + 1}) = {{{', '.join(map(str, loop))}}};")
    out.append(f"Plane Surface(1) = {{{', '.join(str(k + 1) for k in range(len(loops)))}}};")
    if spec[0] == "uniform":
        out.append(f"Mesh.MeshSizeMin = {strength!r};\nMesh.MeshSizeMax = {strength!r};")
    else:
        _, x0, y0, x1, y1, _, rbar, gamma, cap = spec
        p = len(used) + 1
        line = len(segments) + 1
        out += [f"Point({p}) = {{{x0!r}, {y0!r}, 0}};", f"Point({p + 1}) = {{{x1!r}, {y1!r}, 0}};",
                f"Line({line}) = {{{p}, {p + 1}}};",
                f"Field[1] = Distance; Field[1].CurvesList = {{{line}}}; "
                "Field[1].NumPointsPerCurve = 4000;",
                f'Field[2] = MathEval; Field[2].F = "{strength!r}*(1+(F1/{rbar!r})^{gamma!r})";',
                f'Field[3] = MathEval; Field[3].F = "{cap!r}";',
                "Field[4] = Min; Field[4].FieldsList = {2, 3};", "Background Field = 4;"]
    out.append("Mesh.MeshSizeExtendFromBoundary = 0;\nMesh.MeshSizeFromPoints = 0;\n"
               f"Mesh.MeshSizeFromCurvature = 0;\nMesh.Algorithm = {algorithm};")
    return "\n".join(out) + "\n"


def read_msh2(path, curves):
    """Nodes, triangles and boundary lines (on curves 1..curves) of a Gmsh 2.2 file (element
    tags: physical, then elementary)."""
    nodes, triangles, lines_, index = [], [], [], {}
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line == "$Nodes":
            for _ in range(int(next(lines))):
                fields = next(lines).split()
                index[int(fields[0])] = len(nodes)
                nodes.append((float(fields[1]), float(fields[2])))
        elif line == "$Elements":
            for _ in range(int(next(lines))):
                fields = [int(x) for x in next(lines).split()]
                tags = fields[2]
                if fields[1] == 2:
                    triangles.append([index[v] for v in fields[3 + tags:6 + tags]])
                elif fields[1] == 1 and fields[4] <= curves:  # not the size's source line
                    lines_.append(tuple(index[v] for v in fields[3 + tags:5 + tags]))
    return np.array(nodes), np.array(triangles, dtype=np.int64).reshape(-1, 3), lines_


def run_gmsh(xy, segments, spec, strength, algorithm, work):
    geo = os.path.join(work, f"gmsh{algorithm}.geo")
    msh = os.path.join(work, f"gmsh{algorithm}.msh")
    with open(geo, "w") as f:
        f.write(gmsh_geo(xy, segments, spec, strength, algorithm))
    done = subprocess.run(["gmsh", geo, "-2", "-nt", "1", "-format", "msh2", "-o", msh],
                          capture_output=True, text=True)
    if done.returncode != 0 or not os.path.exists(msh):
        return None, "gmsh failed"
    nodes, triangles, boundary = read_msh2(msh, len(segments))
    return (nodes, triangles, boundary), None


def run_cgal(tool, domain, xy, segments, spec, strength, work):
    """CGAL's Delaunay_mesher_2 (bench/cgal_mesh_2d, mesh_bench's peer) on the same boundary
    pieces as Gmsh, the same size file and the angle bound of our Delaunay refinement (20.7
    degrees); hole points from the sample domain."""
    segments = np.asarray(segments)
    used = np.unique(segments)
    number = {int(v): k for k, v in enumerate(used)}
    poly = os.path.join(work, "cgal.poly")
    with open(poly, "w") as f:
        f.write(f"{len(used)} 2 0 0\n")
        for k, v in enumerate(used):
            f.write(f"{k} {xy[v][0]!r} {xy[v][1]!r}\n")
        f.write(f"{len(segments)} 0\n")
        for k, (a, b) in enumerate(segments):
            f.write(f"{k} {number[int(a)]} {number[int(b)]}\n")
        f.write("0\n")
    size_file = os.path.join(work, "cgal_size.txt")
    with open(size_file, "w") as f:
        f.write(size_text(spec, strength))
    out = os.path.join(work, "cgal")
    done = subprocess.run([tool, poly, size_file, "20.7", out, "--domain", domain],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None, (done.stderr.strip().splitlines() or ["cgal_mesh_2d failed"])[-1]
    nodes, first = read_node(out + ".node")
    triangles = read_ele(out + ".ele", first)
    boundary = [(number[int(a)], number[int(b)]) for a, b in segments]
    return (nodes, triangles, boundary), None


def mesh_all(cli, domain, generators, spec, strength, work):
    """Every generator on `domain` with the size file of `spec` at `strength`."""
    size_file = os.path.join(work, "size.txt")
    with open(size_file, "w") as f:
        f.write(size_text(spec, strength))
    meshes = []
    for g in generators:
        mesh, error = run_exactmesh(cli, domain, g, size_file, os.path.join(work, f"{g}.ele"))
        meshes.append({"name": g, "mesh": mesh, "error": error})
    return meshes


def calibrated_meshes(cli, domain, generators, spec, target, work):
    """The strength (and the meshes) giving a median of about `target` triangles over the
    generators: a second run at the strength rescaled by sqrt(count / target) when the first is
    more than 20% off (counts go as 1 / strength^2)."""
    strength = spec[1] if spec[0] == "uniform" else spec[5]
    for attempt in range(2):
        meshes = mesh_all(cli, domain, generators, spec, strength, work)
        counts = [len(m["mesh"][1]) for m in meshes if m["mesh"]]
        if not counts:
            raise RuntimeError(f"{domain}: every generator failed: {meshes[0]['error']}")
        median = float(np.median(counts))
        if attempt == 1 or abs(median - target) <= 0.2 * target:
            return strength, meshes
        strength = float(f"{strength * math.sqrt(median / target):.3g}")


def overlapping(xy, triangles, window):
    x0, y0, x1, y1 = window
    p = xy[triangles]
    return ~((p[..., 0] < x0).all(axis=1) | (p[..., 0] > x1).all(axis=1) |
             (p[..., 1] < y0).all(axis=1) | (p[..., 1] > y1).all(axis=1))


def layout(n, aspect, width=14.0):
    """Columns for n panels of height/width `aspect` in a figure `width` inches wide: the
    arrangement closest to a 3:2 page."""
    best = None
    for columns in range(1, n + 1):
        rows = math.ceil(n / columns)
        panel = width / columns
        ratio = width / (rows * (panel * aspect + 0.8) + 1.95)
        # Close to 3:2, and few empty places in the last row.
        score = abs(math.log(ratio / 1.5)) + 0.1 * (rows * columns - n)
        if best is None or score < best[0]:
            best = (score, columns)
    return best[1]


def save_png(fig, path, dpi):
    """The figure as a palette PNG (matplotlib's RGBA output quantized to 256 colours: the
    panels use 12 fills, black and grey), the dpi lowered until the file is under 300 kB."""
    from PIL import Image

    while True:
        fig.savefig(path, dpi=dpi)
        with Image.open(path) as image:
            image.convert("RGB").quantize(colors=256, method=Image.Quantize.FASTOCTREE).save(
                path, optimize=True)
        if os.path.getsize(path) <= 300_000 or dpi <= 50:
            return dpi
        dpi = int(dpi * 0.9)


def figure(panels, window, title, path_base, dpi=120):
    """One figure: a panel per mesh on `window`, same scale, shaded by smallest angle."""
    x0, y0, x1, y1 = window
    aspect = (y1 - y0) / (x1 - x0)
    n = len(panels)
    columns = layout(n, aspect)
    rows = math.ceil(n / columns)
    panel_width = 14.0 / columns
    panel_height = panel_width * aspect
    caption, header, footer = 0.8, 0.5, 1.45  # inches
    height = rows * (panel_height + caption) + header + footer
    fig = plt.figure(figsize=(14.0, height))
    cmap = ListedColormap(COLOURS)
    norm = BoundaryNorm(np.arange(0, 61, 5), cmap.N)
    # One line width for the whole figure, in points, from the median on-screen size of the
    # triangles in view (the square root of their median area): the same for every panel, so
    # dense and coarse meshes are compared at one stroke, and thin against the triangles.
    points_per_unit = panel_width * 72 / (x1 - x0)
    sizes = []
    for mesh in panels:
        if mesh["xy"] is None:
            continue
        p = mesh["xy"][mesh["triangles"][overlapping(mesh["xy"], mesh["triangles"], window)]]
        if len(p):
            area = 0.5 * np.abs((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1]) -
                                (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0]))
            sizes.append(math.sqrt(float(np.median(area))) * points_per_unit)
    typical = float(np.median(sizes)) if sizes else 10.0
    linewidth = min(0.8, max(0.05, 0.04 * typical))
    grid = fig.add_gridspec(rows, columns, left=0.005, right=0.995, top=1 - header / height,
                            bottom=footer / height,
                            hspace=caption / panel_height if panel_height > 0 else 0.2,
                            wspace=0.03)
    for k, mesh in enumerate(panels):
        ax = fig.add_subplot(grid[k // columns, k % columns])
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        for spine in ax.spines.values():
            spine.set_color("#999999")
        ax.set_title(mesh["name"], fontsize=11, pad=3)
        if mesh["xy"] is None:
            ax.text(0.5, 0.5, mesh["error"], ha="center", va="center", fontsize=8,
                    transform=ax.transAxes, wrap=True)
            continue
        xy, triangles, angles = mesh["xy"], mesh["triangles"], mesh["angles"]
        keep = overlapping(xy, triangles, window)  # triangles wholly outside: not drawn
        collection = PolyCollection(xy[triangles[keep]], array=angles[keep], cmap=cmap,
                                    norm=norm, edgecolors="#333333", linewidths=linewidth)
        ax.add_collection(collection)
        if mesh["segments"]:
            ends = np.array(mesh["segments"])
            seen = overlapping(xy, ends[:, [0, 1, 1]], window)
            from matplotlib.collections import LineCollection

            ax.add_collection(LineCollection(xy[ends[seen]], colors="#111111",
                                             linewidths=2.5 * linewidth, capstyle="round"))
        label = f"min angle {mesh['min_angle']:.1f}°\n{len(triangles):,} triangles"
        if keep.sum() < len(triangles):
            label += f", {int(keep.sum()):,} in view"
        ax.set_xlabel(label, fontsize=10, labelpad=3)
    fig.suptitle(title, fontsize=12.5, y=1 - 0.1 / height, va="top")
    bar = fig.add_axes([0.3, 0.3 / height, 0.4, 0.16 / height])
    colourbar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar,
                             orientation="horizontal", ticks=range(0, 61, 10))
    colourbar.ax.tick_params(labelsize=9)
    colourbar.ax.set_title("smallest angle of each triangle (degrees)", fontsize=10, pad=3)
    fig.savefig(path_base + ".svg")
    dpi = save_png(fig, path_base + ".png", dpi)
    plt.close(fig)
    return dpi


def domain_window(meshes):
    points = [m["xy"] for m in meshes if m["xy"] is not None]
    xy = np.vstack(points)
    x0, y0 = xy.min(axis=0)
    x1, y1 = xy.max(axis=0)
    pad = 0.02 * max(x1 - x0, y1 - y0)
    return (x0 - pad, y0 - pad, x1 + pad, y1 + pad)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="the exactmesh binary")
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--target", type=int, default=2500,
                        help="median triangle count over the generators (default 2500)")
    parser.add_argument("--domains", nargs="*", default=list(DOMAINS))
    parser.add_argument("--generators", nargs="*", default=GENERATORS)
    parser.add_argument("--no-gmsh", action="store_true", help="leave Gmsh out")
    parser.add_argument("--cgal", default=None,
                        help="bench/cgal_mesh_2d (CGAL's mesher as a command); none: no CGAL panel")
    parser.add_argument("--markdown", default="pictures.md",
                        help="the Markdown page listing the figures, in --out-dir")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    use_gmsh = not args.no_gmsh and shutil.which("gmsh") is not None
    page = ["# Mesh pictures", "",
            "Every generator on each sample domain, meshed for the picture: one size per domain "
            f"(calibrated so the generators' median count is about {args.target:,} triangles; the same "
            "size file for every generator), each panel on the same window and scale, triangles "
            "shaded by their smallest angle. Written by `scripts/picture_panels.py`.", ""]
    if use_gmsh:
        page += ["Gmsh (Delaunay, Frontal-Delaunay) meshes the boundary that advancing-front "
                 "keeps (the domain's curves discretized by the same size) with the same size "
                 "as Distance and MathEval fields.", ""]
    else:
        page += ["Gmsh is not installed here: its panels are left out.", ""]
    use_cgal = args.cgal is not None and os.path.exists(args.cgal)
    if use_cgal:
        page += ["CGAL's Delaunay_mesher_2 (`bench/cgal_mesh_2d`, the peer of `mesh_bench`) "
                 "meshes the same boundary with the same size file and a 20.7-degree bound.", ""]
    else:
        page += ["CGAL's panel is left out (bench/cgal_mesh_2d not built: no CGAL).", ""]
    for domain in args.domains:
        spec = DOMAINS[domain]["size"]
        with tempfile.TemporaryDirectory() as work:
            strength, meshes = calibrated_meshes(args.cli, domain, args.generators, spec,
                                                 args.target, work)
            size_line = " / ".join(size_text(spec, strength).strip().splitlines())
            boundary = next((m["mesh"] for m in meshes
                             if m["name"] == "advancing-front" and m["mesh"]), None)
            boundary = boundary or next((m["mesh"] for m in meshes if m["mesh"]), None)
            if use_cgal:
                mesh, error = (run_cgal(args.cgal, domain, boundary[0], boundary[2], spec,
                                        strength, work) if boundary else (None, "no boundary"))
                meshes.append({"name": "cgal", "mesh": mesh, "error": error})
            if use_gmsh:
                for name, algorithm in GMSH.items():
                    mesh, error = (run_gmsh(boundary[0], boundary[2], spec, strength, algorithm,
                                            work) if boundary else (None, "no boundary"))
                    meshes.append({"name": name, "mesh": mesh, "error": error})
        for m in meshes:
            if m["mesh"] is None:
                m.update(xy=None, triangles=None, segments=[], angles=None)
                continue
            xy, triangles, segments = m["mesh"]
            angles = min_angles(xy, triangles)
            m.update(xy=xy, triangles=triangles, segments=segments, angles=angles,
                     min_angle=float(angles.min()) if len(angles) else 0.0)
        overview = DOMAINS[domain]["overview"] or domain_window(meshes)
        base = f"panels_{domain}"
        figure(meshes, overview, f"{domain}: size file '{size_line}'",
               os.path.join(args.out_dir, base))
        page += [f"## {domain}", "", f"Size file: `{size_line}`.", "",
                 f"![{domain}, every generator]({base}.png)", "",
                 f"([SVG]({base}.svg))", ""]
        for suffix, caption, *window in DOMAINS[domain]["zooms"]:
            zoom = f"{base}_{suffix}"
            figure(meshes, tuple(window), f"{domain}, {caption} (zoom)",
                   os.path.join(args.out_dir, zoom))
            page += [f"![{domain}: {caption}]({zoom}.png)", "", f"([SVG]({zoom}.svg))", ""]
        print(f"picture_panels: {domain}: size {size_line}; " +
              ", ".join(f"{m['name']} {len(m['triangles']) if m['xy'] is not None else 'failed'}"
                        for m in meshes), file=sys.stderr)
    with open(os.path.join(args.out_dir, args.markdown), "w") as f:
        f.write("\n".join(page))


if __name__ == "__main__":
    main()
