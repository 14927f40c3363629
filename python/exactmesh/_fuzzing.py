# SPDX-License-Identifier: MIT
"""exactmesh.fuzz: judging a Python triangulator on the project's degenerate inputs (issue 16),
the Python face of `exactmesh fuzz --command` (generators/fuzzing/fuzz_program.hpp does the work,
with the GIL released between calls of the program)."""
from dataclasses import dataclass, field

import numpy as np

from . import _exactmesh as _core
from ._exactmesh import InputError

_KINDS = {"points2d": 2, "pslg": 2, "points3d": 3}


@dataclass
class FuzzSummary:
    """What a fuzz() run saw: inputs run and each verdict's count (timed_out stays 0: a Python
    callable is never interrupted); per_distribution[name] = (inputs run, bad ones)."""

    run: int
    passed: int
    refused: int
    failed: int
    crashed: int
    timed_out: int
    first_seed: int
    last_seed: int
    seconds: float
    per_distribution: dict = field(default_factory=dict)

    @property
    def bad(self):
        return self.failed + self.crashed + self.timed_out


@dataclass
class FuzzFailure:
    """One bad input: as generated (points, and segments for a PSLG, else None) and minimized by ddmin with the program as
    the oracle (minimized_points, minimized_segments: the same verdict persists on them; for a
    crash, the same exception type). verdict is "failed" or "crashed"; judgement the exact
    check's first problem (vertices and cells numbered from 0) or the exception's text.
    minimized is False past max_minimized failures, complete False when the minimizer ran out of
    time before the input was 1-minimal."""

    seed: int
    distribution: str
    verdict: str
    judgement: str
    points: np.ndarray
    segments: np.ndarray
    minimized_points: np.ndarray
    minimized_segments: np.ndarray
    minimized_verdict: str
    minimized_judgement: str
    minimized: bool
    complete: bool
    evaluations: int


class _Unreadable(Exception):
    pass


def _returned_indices(a, columns, what):
    a = np.asarray(a)
    if a.size == 0:
        return np.zeros((0, columns), dtype=np.int64)
    if not np.issubdtype(a.dtype, np.integer):
        raise _Unreadable(f"{what}: expected integers, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != columns:
        raise _Unreadable(f"{what}: expected shape (N, {columns}), got {a.shape}")
    if (a < 0).any():
        raise _Unreadable(f"{what}: negative index {int(a.min())}")
    return np.ascontiguousarray(a, dtype=np.int64)


def _returned_points(a, dim):
    a = np.asarray(a)
    if not (np.issubdtype(a.dtype, np.floating) or np.issubdtype(a.dtype, np.integer)):
        raise _Unreadable(f"points: expected numbers, got dtype {a.dtype}")
    if a.ndim != 2 or a.shape[1] != dim:
        raise _Unreadable(f"points: expected shape (N, {dim}), got {a.shape}")
    return np.ascontiguousarray(a, dtype=np.float64)


def _program_answer(result, dim, pslg):
    """The program's result as ("ok", points or None, cells, pieces or None)."""
    points = pieces = None
    if isinstance(result, tuple):
        if len(result) == 2:
            points, cells = result
        elif len(result) == 3 and pslg:
            points, cells, pieces = result
        else:
            expected = "cells, (points, cells)" + (" or (points, cells, pieces)" if pslg else "")
            raise _Unreadable(f"the program returned a tuple of {len(result)}; expected {expected}")
    else:
        cells = result
    if cells is None:
        raise _Unreadable("the program returned no cells (None)")
    cells = _returned_indices(cells, dim + 1, "cells")
    if points is not None:
        points = _returned_points(points, dim)
    if pieces is not None:
        pieces = _returned_indices(pieces, 2, "pieces")
    return ("ok", points, cells, pieces)


def _fuzz_adapter(program, kind):
    """program as the driver calls it: (points, segments) -> one of ("ok", ...),
    ("crashed", "TypeName: message"), ("unreadable", why). Exceptions that are not Exceptions
    (KeyboardInterrupt, SystemExit) go through and end the run."""
    dim, pslg = _KINDS[kind], kind == "pslg"

    def run(points, segments):
        try:
            result = program(points, segments) if pslg else program(points)
        except Exception as error:  # noqa: BLE001  (every exception of the program is a crash)
            return ("crashed", f"{type(error).__name__}: {error}")
        try:
            return _program_answer(result, dim, pslg)
        except _Unreadable as why:
            return ("unreadable", str(why))

    return run


def fuzz(program, kind="points2d", count=100, seed=1, max_points=1000, conforming=False,
         convex_hull=False, oriented=True, minimize_seconds=60, max_minimized=20, quiet=True):
    """Judges program on count generated inputs of kind (case seeds seed, seed + 1, ...), as
    `exactmesh fuzz --command` does: the output is checked exactly and each bad input is
    minimized by ddmin (at most minimize_seconds per failure, the first max_minimized failures).

    program(points) for kind "points2d" ((n, 2) float64) and "points3d" ((n, 3)), or
    program(points, segments) for "pslg" (segments (m, 2) int64), returns the cells: an (k, 3)
    or (k, 4) integer array into points (triangles counter-clockwise, tetrahedra as
    exactmesh.tetrahedralize orients them; oriented=False orients each exactly first), or a
    tuple (points, cells) when it adds vertices (matched to the input's by exact coordinates),
    and for a PSLG optionally (points, cells, pieces) with the constrained edges (k, 2). The
    points2d and points3d outputs must be Delaunay; a PSLG's constrained Delaunay (Chew), or with
    conforming=True a valid mesh of the domain; convex_hull=True asks the whole convex hull to be
    covered. An exception the program raises is a crash (on an input without a triangulation,
    all collinear or coplanar, a refusal).

    Returns (FuzzSummary, [FuzzFailure]). Bad arguments raise ValueError (exactmesh.InputError)."""
    if not callable(program):
        raise InputError(f"program: expected a callable, got {type(program).__name__}")
    if kind not in _KINDS:
        raise InputError(f"kind: '{kind}' is not one of the known kinds: points2d, pslg, points3d")
    for name, value in (("count", count), ("seed", seed), ("max_points", max_points),
                        ("max_minimized", max_minimized)):
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
            raise InputError(f"{name}: expected a non-negative integer, got {value!r}")
    if max_points < 4 or max_points >= 2**31:
        raise InputError(f"max_points: expected an integer in [4, 2^31), got {max_points}")
    try:
        minimize_seconds = float(minimize_seconds)
    except (TypeError, ValueError):
        raise InputError(f"minimize_seconds: expected a number, got {minimize_seconds!r}") \
            from None
    if not 0 <= minimize_seconds <= 1e6:
        raise InputError(f"minimize_seconds: expected seconds in [0, 1e6], got {minimize_seconds}")
    d = _core._fuzz(_fuzz_adapter(program, kind), kind, int(count), int(seed), int(max_points),
                    bool(conforming), bool(convex_hull), bool(oriented), minimize_seconds,
                    int(max_minimized), bool(quiet))
    failures = [FuzzFailure(**f) for f in d.pop("failures")]
    if kind != "pslg":
        for f in failures:
            f.segments = f.minimized_segments = None
    return FuzzSummary(**d), failures
