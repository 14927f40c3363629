# SPDX-License-Identifier: MIT
"""exactmesh: robust triangulations and mesh generators on exact predicates.

Every function takes and returns numpy arrays (float64 coordinates of shape (N, 2) or (N, 3),
int32 indices), reading C-contiguous float64 input in place and handing results over without a
copy. Bad input raises ValueError (exactmesh.InputError or exactmesh.GeometryError) with the
message the `exactmesh` command prints; the GIL is released during every construction.

    >>> import numpy as np, exactmesh
    >>> t = exactmesh.triangulate(np.random.default_rng(1).random((1000, 2)))
    >>> exactmesh.check_delaunay(t.points, t.triangles).ok
    True
"""
from dataclasses import dataclass, field

import numpy as np

from . import _exactmesh as _core
from ._exactmesh import (  # noqa: F401  (re-exported)
    Error,
    GeometryError,
    InputError,
    InternalError,
    __version__,
    distributions_2d,
    distributions_3d,
    domains,
    generators,
    in_ellipse,
    incircle,
    insphere,
    orient2d,
    points_2d,
    points_3d,
    orient3d,
)
from ._fuzzing import FuzzFailure, FuzzSummary, fuzz  # noqa: F401  (re-exported)
from ._meshio import from_meshio as _from_meshio
from ._meshio import to_meshio as _to_meshio
from ._sizes import size_arguments as _size_arguments

__all__ = [
    "CheckResult", "Error", "FuzzFailure", "FuzzSummary", "GeometryError", "InputError",
    "InternalError", "Mesh", "Tetrahedralization", "Triangulation", "cdt", "check_delaunay",
    "check_mesh", "check_tetrahedralization", "check_triangulation", "distributions_2d",
    "distributions_3d", "domain", "domains", "from_meshio", "fuzz",
    "generators", "in_ellipse", "incircle", "insphere", "mesh", "orient2d", "orient3d",
    "points_2d", "points_3d", "quality", "tetrahedralize", "triangulate",
]

_EMPTY2 = np.zeros((0, 2))
_NO_INDICES = np.zeros((0, 2), dtype=np.int64)


def _points(points, dim, what="points"):
    """float64 C-contiguous (no copy when it is one already); None stays empty."""
    if points is None:
        return np.zeros((0, dim))
    return np.ascontiguousarray(points, dtype=np.float64)


def _index_array(a, columns):
    if a is None:
        return np.zeros((0, columns), dtype=np.int64)
    a = np.asarray(a)
    if a.size and not np.issubdtype(a.dtype, np.integer):
        raise InputError(f"expected an integer index array, got dtype {a.dtype}")
    return np.ascontiguousarray(a, dtype=np.int64)


@dataclass
class CheckResult:
    """An exact check's verdict: ok, the first problem in words, and what it names."""

    ok: bool
    problem: str
    vertices: list
    cell: int = -1

    def __bool__(self):
        return self.ok


def _check_result(d, cell_key):
    return CheckResult(d["ok"], d["problem"], list(d["vertices"]), d[cell_key])


@dataclass
class Triangulation:
    """A 2D Delaunay triangulation: triangles (M, 3) counter-clockwise into points;
    neighbors[t, k] the triangle across edge (k, k+1) of t, -1 on the hull; merged_into[v] the
    first point with v's coordinates (duplicates are used by no triangle)."""

    points: np.ndarray
    triangles: np.ndarray
    neighbors: np.ndarray
    merged_into: np.ndarray
    counters: dict = field(default_factory=dict)
    construct_seconds: float = 0.0  #: the C++ construction alone (GIL released)

    def to_meshio(self):
        return _to_meshio(self.points, [("triangle", self.triangles)])


@dataclass
class Tetrahedralization:
    """A 3D Delaunay tetrahedralization: tetrahedra (T, 4) with orient3d > 0 in Shewchuk's
    convention (to_meshio writes VTK's right-handed order); neighbors[t, k] the tetrahedron
    across the face opposite corner k, -1 on the hull; coplanar when no tetrahedron exists."""

    points: np.ndarray
    tetrahedra: np.ndarray
    neighbors: np.ndarray
    merged_into: np.ndarray
    coplanar: bool
    counters: dict = field(default_factory=dict)
    construct_seconds: float = 0.0  #: the C++ construction alone (GIL released)

    def to_meshio(self):
        return _to_meshio(self.points, [("tetra", self.tetrahedra[:, [0, 1, 3, 2]])])


@dataclass
class Mesh:
    """A mesh of a planar straight-line graph (cdt(), mesh()): every input vertex first and at
    its index (input_vertex_count of them), added vertices after; triangles (M, 3)
    counter-clockwise, quads (Q, 4) for mixed meshes; segments (S, 2) the input segments and
    pieces (P, 2) the constrained edges covering them, piece_segment[p] the segment of piece p."""

    points: np.ndarray
    triangles: np.ndarray
    neighbors: np.ndarray
    input_vertex_count: int
    segments: np.ndarray
    pieces: np.ndarray
    piece_segment: np.ndarray
    merged_into: np.ndarray
    quads: np.ndarray
    holes: np.ndarray
    warnings: list
    counters: dict
    construct_seconds: float = 0.0
    delaunay: bool = True

    def to_meshio(self):
        cells = [("triangle", self.triangles), ("quad", self.quads), ("line", self.pieces)]
        return _to_meshio(self.points, cells)

    def quality(self, size=None):
        return quality(self.points, self.triangles, size)

    def check(self):
        return check_mesh(self)


def triangulate(points, algorithm="bowyer-watson", order="brio", seed=1, threads=1):
    """The Delaunay triangulation of points (N, 2), exact (symbolic perturbation on ties).
    algorithm: bowyer-watson, green-sibson or tanemura-merriam; order: given, random, brio;
    threads (bowyer-watson with brio; 0: every core): the same triangles for every count."""
    p = _points(points, 2)
    d = _core._triangulate(p, algorithm, order, seed, int(threads))
    return Triangulation(p, d["triangles"], d["neighbors"], d["merged_into"].ravel(),
                         d["counters"], d["construct_seconds"])


def tetrahedralize(points, algorithm="bowyer-watson", order="brio", seed=1, threads=1):
    """The Delaunay tetrahedralization of points (N, 3). algorithm: bowyer-watson or
    green-sibson; threads (bowyer-watson with brio; 0: every core): the same tetrahedra for
    every count."""
    p = _points(points, 3)
    d = _core._tetrahedralize(p, algorithm, order, seed, int(threads))
    return Tetrahedralization(p, d["tetrahedra"], d["neighbors"], d["merged_into"].ravel(),
                              d["coplanar"], d["counters"], d["construct_seconds"])


def _mesh_from(d, segments, delaunay):
    return Mesh(d["points"], d["triangles"], d["neighbors"], d["input_vertex_count"],
                segments, d["pieces"], d["piece_segment"].ravel(), d["merged_into"].ravel(),
                d["quads"], d.get("holes", _EMPTY2), list(d["warnings"]), d["counters"],
                d.get("construct_seconds", 0.0), delaunay)


def cdt(points, segments, holes=None, recovery="swap", remove_exterior=True, order="brio",
        seed=1):
    """The constrained Delaunay triangulation of points (N, 2) and segments (S, 2), crossing
    segments split at their correctly rounded crossing; holes (H, 2) points inside holes.
    recovery: swap, cavity or conforming (Steiner points on segments, conforming Delaunay);
    remove_exterior=False keeps the convex hull."""
    p = _points(points, 2)
    s = _index_array(segments, 2)
    d = _core._cdt(p, s, _points(holes, 2), recovery, remove_exterior, order, seed)
    return _mesh_from(d, s.astype(np.int32), True)


def domain(name):
    """A built-in domain's PSLG, discretized by its own size: (points, segments, holes)."""
    d = _core._domain(name)
    return d["points"], d["segments"], d["holes"]


def _bounds(points):
    p = np.asarray(points, dtype=np.float64)
    if p.size == 0:
        return None
    return (*p.min(axis=0), *p.max(axis=0))


def mesh(points=None, segments=None, holes=None, *, domain=None, generator="delaunay-refinement",
         size=None, min_angle=None, polish_angle=None, max_steiner=0, layers=None, quads=False,
         o_mesh=False, threads=1, refine_order=None):
    """A quality mesh of a PSLG (points, segments, holes) or of a built-in domain
    (domain="naca0012", "square-with-holes", "key", "three-element"), as `exactmesh mesh`.

    generator: one of exactmesh.generators; size: a number, size-file lines, or a callable
    f(x, y) sampled on a 129 x 129 grid over the domain; min_angle / polish_angle (degrees,
    delaunay-refinement only); layers=(first_height, growth[, max_layers]) for the layered
    generators, quads=True keeps layer quadrilaterals, o_mesh=True the truncated O-mesh;
    threads (delaunay-refinement; 0: every core): more than one refines in rounds
    (refine_order="rounds", whose mesh is the same for every thread count; "worst-first", the
    default on one thread, is sequential)."""
    if domain is not None and (points is not None or segments is not None or holes is not None):
        raise InputError("give either points and segments, or domain= (not both)")
    if domain is None and points is None:
        raise InputError("give either points and segments, or domain=")
    p = _points(points, 2)
    bounds = _bounds(p) if domain is None else _bounds(_core._domain(domain)["points"])
    sizes = _size_arguments(size, bounds)
    layer_text = "" if layers is None else ",".join(repr(float(v)) if i < 2 else str(int(v))
                                                      for i, v in enumerate(layers))
    d = _core._mesh(p, _index_array(segments, 2), _points(holes, 2), domain or "", generator,
                    *sizes, None if min_angle is None else float(min_angle),
                    None if polish_angle is None else float(polish_angle), int(max_steiner),
                    layer_text, bool(quads), bool(o_mesh), int(threads), refine_order or "")
    return _mesh_from(d, d["segments"], d["delaunay"])


def quality(points, triangles, size=None):
    """The quality report of a triangle mesh as a dict: angles (degrees) and their histogram
    (10-degree bins), radius-edge ratios, and size conformity (edge length over size at its
    midpoint) when size is given (as in mesh())."""
    p = _points(points, 2)
    return _core._quality(p, _index_array(triangles, 3), *_size_arguments(size, _bounds(p)))


def check_triangulation(points, triangles):
    """Exact topology and convex-hull check of a 2D triangulation of points."""
    return _check_result(_core._check_triangulation(_points(points, 2), _index_array(triangles, 3)),
                         "triangle")


def check_delaunay(points, triangles):
    """check_triangulation, then every interior edge locally Delaunay, exactly."""
    return _check_result(_core._check_delaunay(_points(points, 2), _index_array(triangles, 3)),
                         "triangle")


def check_tetrahedralization(points, tetrahedra, delaunay=True):
    """Exact topology and convex-hull check of a tetrahedralization (Shewchuk's orientation, as
    tetrahedralize() returns), and with delaunay=True every interior face locally Delaunay."""
    d = _core._check_tetrahedralization(_points(points, 3), _index_array(tetrahedra, 4),
                                        bool(delaunay))
    return _check_result(d, "tetrahedron")


def check_mesh(mesh, delaunay=None):
    """Exact check of a Mesh against its own input: constrained Delaunay (Chew's definition)
    when delaunay (default: as the generator promises), else a valid conforming mesh; every
    input segment covered by pieces, every input vertex kept."""
    delaunay = mesh.delaunay if delaunay is None else delaunay
    d = _core._check_constrained(mesh.points, mesh.triangles, int(mesh.input_vertex_count),
                                 _index_array(mesh.segments, 2), _index_array(mesh.pieces, 2),
                                 bool(delaunay))
    return _check_result(d, "triangle")


def from_meshio(m):
    """A Triangulation-free conversion from a meshio.Mesh: (points, cells) where cells maps
    "triangle", "quad", "tetra", "line" to index arrays (tetra back in exactmesh's
    orientation)."""
    points, cells = _from_meshio(m)
    if "tetra" in cells:
        cells["tetra"] = np.ascontiguousarray(cells["tetra"][:, [0, 1, 3, 2]])
    return points, cells
