#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Slices through tetrahedral meshes (issue 18, 3D): for each 3D sample domain, a mesh made for
the picture by `exactmesh tetmesh` (radius-edge 2 and a volume bound per domain, a few thousand
tetrahedra) and, when `tetgen` is installed, TetGen's mesh (`tetgen -pq2a<V>`, the same bounds)
of the same boundary; one figure per domain with 2-3 axis-aligned planar slices of each: the
polygon where the plane cuts each tetrahedron (a triangle or a quadrilateral), filled by that
tetrahedron's smallest dihedral angle, one colour bar in degrees; the tetrahedron count, the
count cut and the smallest dihedral angle in the slice under each panel.

TetGen is given the boundary exactmesh recovers without refinement (its .face: the domain's
facets triangulated, any Steiner points of the recovery on them) as a .poly with the domain's
hole points, so both meshers start from the same surface triangles.

Each figure is written as SVG and PNG (under 300 kB); a section "Slices through tetrahedral
meshes" is put at the end of --markdown in --out-dir (replacing an earlier one).

Usage: slice_pictures.py --cli build/release/cli/exactmesh --out-dir report [--quick]
       [--domains D ...] [--no-tetgen] [--markdown pictures.md]
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import picture_panels  # noqa: E402  (the shared .node/.ele readers)

# Per domain: the tetmesh options (besides --radius-edge 2), TetGen's hole points, the slices
# (axis 0/1/2 = x/y/z, the plane's coordinate, a caption) and, per slice, the window drawn
# (None: the whole cut).
DOMAINS = {
    "box-with-hole": {
        "options": ["--max-volume", "0.0005"],
        "quick": ["--max-volume", "0.01"],
        "holes": [(0.5, 0.5, 0.5)],
        # Off the refinement's dyadic lattice, so no vertex lies on a plane.
        "slices": [(2, 0.47, "z = 0.47, through the hole", None),
                   (0, 0.31, "x = 0.31, the hole's side", None),
                   (2, 0.11, "z = 0.11, under the hole", None)],
    },
    "ellipsoid": {
        "options": ["--domain-size", "0.2", "--max-volume", "0.001"],
        "quick": ["--domain-size", "0.4", "--max-volume", "0.02"],
        "holes": [],
        # Just off the axial planes, where the surface's lattice has vertices.
        "slices": [(2, 0.01, "z = 0.01, by the x-y axial plane", None),
                   (1, 0.01, "y = 0.01, by the x-z axial plane", None),
                   (0, 0.01, "x = 0.01, by the y-z axial plane", None)],
    },
    "wing": {
        "options": ["--domain-size", "0.05", "--max-volume", "0.3"],
        "quick": ["--domain-size", "0.2", "--max-volume", "2"],
        # Inside the NACA 0012 section (chord 0..1 along x, half thickness 0.06 at x = 0.3).
        "holes": [(0.3, 0.0, 0.5)],
        "slices": [(2, 0.49, "z = 0.49, mid-span", None),
                   (2, 0.49, "z = 0.49, the airfoil", (-0.15, -0.3, 1.15, 0.3)),
                   (1, 0.01, "y = 0.01, by the chord plane", None)],
    },
}

AXES = "xyz"
CLASSES = 14  # 5 degrees each, 0 to 70 (a regular tetrahedron: 70.53)
# matplotlib's RdYlBu from 0 to 0.8 sampled at each class's middle (red for small angles), as
# picture_panels.py does for the 2D smallest angle.


def read_node(path):
    """Vertices of a TetGen .node (N x 3) and the first index."""
    return picture_panels.read_node(path, 3)


def read_cells(path, first, corners):
    """The first `corners` vertex numbers of each element of a TetGen .ele or .face, and the
    .face's markers (the column after them, 0 when absent)."""
    lines = picture_panels.data_lines(path)
    header = next(lines)
    count = int(header[0])
    cells = np.empty((count, corners), dtype=np.int64)
    markers = np.zeros(count, dtype=np.int64)
    for k in range(count):
        fields = next(lines)
        cells[k] = [int(v) - first for v in fields[1:1 + corners]]
        if len(fields) > 1 + corners:
            markers[k] = int(fields[1 + corners])
    return cells, markers


def min_dihedral_angles(xyz, tets):
    """Smallest dihedral angle of each tetrahedron in degrees. Drawing only, but scale-free
    like picture_panels.min_angles: corners scaled by a power of two to the unit range, then the
    edge vectors again, so nothing overflows or underflows at 2^+-600 coordinates."""
    if len(tets) == 0:
        return np.zeros(0)
    p = xyz[tets]  # T x 4 x 3
    largest = np.abs(p).reshape(len(p), -1).max(axis=1)
    _, e = np.frexp(np.where(largest > 0, largest, 1.0))
    p = np.ldexp(p, -e[:, None, None])
    edges = p[:, 1:, :] - p[:, :1, :]  # from corner 0 to corners 1, 2, 3
    longest = np.abs(edges).reshape(len(p), -1).max(axis=1)
    _, f = np.frexp(np.where(longest > 0, longest, 1.0))
    q = np.concatenate([np.zeros((len(p), 1, 3)), np.ldexp(edges, -f[:, None, None])], axis=1)
    # Normal of the face opposite corner k, pointing away from corner k.
    normals = []
    for k in range(4):
        a, b, c = [q[:, i] for i in range(4) if i != k]
        n = np.cross(b - a, c - a)
        away = np.einsum("ij,ij->i", n, q[:, k] - a) > 0
        normals.append(np.where(away[:, None], -n, n))
    angles = []
    for k in range(4):
        for m in range(k + 1, 4):  # the faces opposite k and m meet at the other two corners
            cross = np.linalg.norm(np.cross(normals[k], normals[m]), axis=1)
            dot = np.einsum("ij,ij->i", normals[k], normals[m])
            angles.append(180.0 - np.degrees(np.arctan2(cross, dot)))
    smallest = np.min(angles, axis=0)
    return np.where((largest > 0) & (longest > 0), smallest, 0.0)


def slice_polygons(xyz, tets, axis, value):
    """The polygon where the plane {coordinate `axis` = value} cuts each tetrahedron, in the
    plane's coordinates (the other two axes in order): a list of (tetrahedron index, k x 2
    array), k = 3 or 4, corners in cyclic order. A vertex on the plane counts as below it (the
    plane moved up by an infinitesimal), so a face in the plane is cut once, by the tetrahedron
    above it, and every point of the plane inside the mesh is in exactly one polygon (up to the
    rounding of the cut points)."""
    other = [a for a in range(3) if a != axis]
    distance = xyz[:, axis] - value
    above = distance[tets] > 0  # T x 4
    count = above.sum(axis=1)
    polygons = []

    def cut(t, i, j):  # the point where edge (i above, j below) meets the plane
        a, b = tets[t, i], tets[t, j]
        da, db = distance[a], distance[b]
        if db == 0:
            return xyz[b, other]
        s = da / (da - db)
        return xyz[a, other] + s * (xyz[b, other] - xyz[a, other])

    for t in np.nonzero((count > 0) & (count < 4))[0]:
        up = [k for k in range(4) if above[t, k]]
        down = [k for k in range(4) if not above[t, k]]
        if len(up) == 1:
            corners = [cut(t, up[0], j) for j in down]
        elif len(down) == 1:
            corners = [cut(t, i, down[0]) for i in up]
        else:  # edges i-k, i-l, j-l, j-k: consecutive ones share a corner
            (i, j), (k, m) = up, down
            corners = [cut(t, i, k), cut(t, i, m), cut(t, j, m), cut(t, j, k)]
        polygons.append((int(t), np.array(corners)))
    return polygons


def polygon_area(corners):
    """Unsigned area of a simple polygon given in cyclic order (shoelace)."""
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * abs(float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def run_exactmesh(cli, domain, options, out):
    done = subprocess.run([cli, "tetmesh", "--domain", domain, *options, "-o", out],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None, (done.stderr.strip().splitlines() or ["exactmesh failed"])[-1]
    xyz, first = read_node(out[:-4] + ".node")
    tets, _ = read_cells(out, first, 4)
    return (xyz, tets), None


def poly_from_face(node, face, holes, path):
    """A TetGen .poly with the vertices of `node`, the triangles of `face` as facets (their
    markers kept) and `holes`."""
    xyz, first = read_node(node)
    triangles, markers = read_cells(face, first, 3)
    with open(path, "w") as f:
        f.write(f"{len(xyz)} 3 0 0\n")
        for k, (x, y, z) in enumerate(xyz):
            f.write(f"{k} {x!r} {y!r} {z!r}\n")
        f.write(f"{len(triangles)} 1\n")
        for (a, b, c), marker in zip(triangles, markers):
            f.write(f"1 0 {marker}\n3 {a} {b} {c}\n")
        f.write(f"{len(holes)}\n")
        for k, (x, y, z) in enumerate(holes):
            f.write(f"{k} {x!r} {y!r} {z!r}\n")
        f.write("0\n")


def run_tetgen(cli, domain, options, holes, work):
    """TetGen (-pq2a<V>) on the boundary exactmesh recovers for `domain` without refinement."""
    recovered = os.path.join(work, "recovered.ele")
    surface = []  # the built-in domain's own surface size, when given
    if "--domain-size" in options:
        k = options.index("--domain-size")
        surface = options[k:k + 2]
    done = subprocess.run([cli, "tetmesh", "--domain", domain, *surface, "-o", recovered],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return None, "exactmesh's recovery failed"
    poly = os.path.join(work, "tetgen.poly")
    poly_from_face(recovered[:-4] + ".node", recovered[:-4] + ".face", holes, poly)
    volume = options[options.index("--max-volume") + 1]
    try:
        done = subprocess.run(["tetgen", f"-pq2a{volume}Q", poly], capture_output=True,
                              text=True, timeout=600)
    except subprocess.TimeoutExpired:
        return None, "tetgen timed out"
    base = os.path.join(work, "tetgen.1")
    if done.returncode != 0 or not os.path.exists(base + ".ele"):
        return None, "tetgen failed"
    xyz, first = read_node(base + ".node")
    tets, _ = read_cells(base + ".ele", first, 4)
    return (xyz, tets), None


def colours():
    import matplotlib.pyplot as plt

    ramp = plt.get_cmap("RdYlBu")
    return [ramp(0.8 * (k + 0.5) / CLASSES) for k in range(CLASSES)]


save_png = picture_panels.save_png  # palette PNG under 300 kB, as the 2D panels


def figure(rows, slices, title, path_base, dpi=120):
    """One figure: a row per mesher (name, mesh or None, error), a column per slice."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import BoundaryNorm, ListedColormap

    cmap = ListedColormap(colours())
    norm = BoundaryNorm(np.arange(0, 5 * CLASSES + 1, 5), cmap.N)
    # Each column's window: the given one, or the cut of the meshes with a margin.
    cuts = [[None] * len(slices) for _ in rows]
    windows = []
    for c, (axis, value, _, window) in enumerate(slices):
        points = []
        for r, (name, mesh, _) in enumerate(rows):
            if mesh is None:
                continue
            xyz, tets, angles = mesh
            polygons = slice_polygons(xyz, tets, axis, value)
            cuts[r][c] = polygons
            on_plane = int(np.count_nonzero(xyz[:, axis] == value))
            if on_plane:  # drawn right (see slice_polygons), but some polygons are degenerate
                print(f"slice_pictures: {title}: {name}: {on_plane} vertices on {AXES[axis]} = "
                      f"{value}", file=sys.stderr)
            points += [p for _, p in polygons]
        if window is None and points:
            p = np.vstack(points)
            lo, hi = p.min(axis=0), p.max(axis=0)
            pad = 0.03 * float((hi - lo).max())
            window = (lo[0] - pad, lo[1] - pad, hi[0] + pad, hi[1] + pad)
        windows.append(window or (0, 0, 1, 1))
    width = 14.0
    panel_width = width / len(slices)
    aspects = [(w[3] - w[1]) / (w[2] - w[0]) for w in windows]
    panel_height = panel_width * max(aspects)
    caption, header, footer = 0.85, 0.55, 1.0
    height = len(rows) * (panel_height + caption) + header + footer
    fig = plt.figure(figsize=(width, height))
    grid = fig.add_gridspec(len(rows), len(slices), left=0.01, right=0.99,
                            top=1 - header / height, bottom=footer / height,
                            hspace=caption / panel_height, wspace=0.04)
    for r, (name, mesh, error) in enumerate(rows):
        for c, (axis, value, label, _) in enumerate(slices):
            ax = fig.add_subplot(grid[r, c])
            x0, y0, x1, y1 = windows[c]
            ax.set_xlim(x0, x1)
            ax.set_ylim(y0, y1)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            for spine in ax.spines.values():
                spine.set_color("#999999")
            right, up = [AXES[a] for a in range(3) if a != axis]
            ax.set_title(f"{name}: {label} ({right} right, {up} up)", fontsize=10.5, pad=3)
            if mesh is None:
                ax.text(0.5, 0.5, error, ha="center", va="center", fontsize=9,
                        transform=ax.transAxes, wrap=True)
                continue
            xyz, tets, angles = mesh
            polygons = cuts[r][c]
            if not polygons:
                ax.text(0.5, 0.5, "the plane misses the mesh", ha="center", va="center",
                        transform=ax.transAxes)
                continue
            cut = np.array([t for t, _ in polygons])
            # Line width from the median on-screen size of the polygons in the window.
            points_per_unit = panel_width * 72 / (x1 - x0)
            typical = math.sqrt(float(np.median([polygon_area(p) for _, p in polygons])))
            linewidth = min(0.6, max(0.08, 0.03 * typical * points_per_unit))
            ax.add_collection(PolyCollection([p for _, p in polygons],
                                             array=np.minimum(angles[cut], 5 * CLASSES - 1e-9),
                                             cmap=cmap, norm=norm, edgecolors="#333333",
                                             linewidths=linewidth))
            ax.set_xlabel(f"{len(tets):,} tetrahedra, {len(cut):,} cut\nmin dihedral "
                          f"{angles[cut].min():.1f}° in the slice, "
                          f"{angles.min():.1f}° in the mesh", fontsize=10, labelpad=3)
    fig.suptitle(title, fontsize=12.5, y=1 - 0.1 / height, va="top")
    bar = fig.add_axes([0.3, 0.3 / height, 0.4, 0.16 / height])
    colourbar = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), cax=bar,
                             orientation="horizontal", ticks=range(0, 5 * CLASSES + 1, 10))
    colourbar.ax.tick_params(labelsize=9)
    colourbar.ax.set_title("smallest dihedral angle of the tetrahedron cut (degrees)",
                           fontsize=10, pad=3)
    fig.savefig(path_base + ".svg")
    dpi = save_png(fig, path_base + ".png", dpi)
    plt.close(fig)
    return dpi


SECTION = "## Slices through tetrahedral meshes"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", required=True, help="the exactmesh binary")
    parser.add_argument("--out-dir", required=True)
    parser.add_argument("--domains", nargs="*", default=list(DOMAINS))
    parser.add_argument("--quick", action="store_true",
                        help="coarse meshes (a few hundred tetrahedra), for a smoke run")
    parser.add_argument("--no-tetgen", action="store_true", help="leave TetGen out")
    parser.add_argument("--markdown", default="pictures.md",
                        help="the Markdown page the section goes at the end of, in --out-dir")
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    use_tetgen = not args.no_tetgen and shutil.which("tetgen") is not None
    page = [SECTION, "",
            "Each 3D sample domain meshed for the picture by `exactmesh tetmesh --radius-edge 2` "
            "with a volume bound per domain" +
            (" and by TetGen (`tetgen -pq2a<V>`, the same bounds)" if use_tetgen else "") +
            ", cut by axis-aligned planes: the polygon where the plane cuts each tetrahedron, "
            "filled by that tetrahedron's smallest dihedral angle (red for small). Written by "
            "`scripts/slice_pictures.py`.", ""]
    if use_tetgen:
        page += ["TetGen is given the boundary exactmesh recovers before refinement (its .face "
                 "as a .poly, with the domain's hole points): the same surface triangles to "
                 "start from.", ""]
    else:
        page += ["TetGen is not installed here (or --no-tetgen): its rows are left out.", ""]
    for domain in args.domains:
        spec = DOMAINS[domain]
        options = ["--radius-edge", "2", *(spec["quick"] if args.quick else spec["options"])]
        with tempfile.TemporaryDirectory() as work:
            rows = []
            mesh, error = run_exactmesh(args.cli, domain, options, os.path.join(work, "m.ele"))
            rows.append(("exactmesh", mesh, error))
            if use_tetgen:
                mesh, error = run_tetgen(args.cli, domain, options[2:], spec["holes"], work)
                rows.append(("TetGen", mesh, error))
        rows = [(name, None if mesh is None else (*mesh, min_dihedral_angles(*mesh)), error)
                for name, mesh, error in rows]
        option_text = " ".join(options)
        base = f"slices_{domain}"
        figure(rows, spec["slices"], f"{domain}: tetmesh {option_text}",
               os.path.join(args.out_dir, base))
        counts = ", ".join(f"{name} {len(mesh[1]) if mesh else 'failed'}"
                           for name, mesh, _ in rows)
        page += [f"### {domain}", "", f"Options: `{option_text}`; tetrahedra: {counts}.", "",
                 f"![{domain}, slices]({base}.png)", "", f"([SVG]({base}.svg))", ""]
        print(f"slice_pictures: {domain}: {option_text}; {counts}", file=sys.stderr)
    path = os.path.join(args.out_dir, args.markdown)
    before = ""
    if os.path.exists(path):
        with open(path) as f:
            before = f.read().split(SECTION, 1)[0].rstrip("\n")
    with open(path, "w") as f:
        f.write((before + "\n\n" if before else "") + "\n".join(page))


if __name__ == "__main__":
    main()
