# SPDX-License-Identifier: MIT
"""The size= argument of mesh() and quality(), in the form the extension takes."""
import numbers

import numpy as np

#: Grid points per side on which a callable size is sampled (linear in between).
SIZE_GRID = 129


def _grid(bounds, f):
    """f sampled on a SIZE_GRID x SIZE_GRID grid over bounds (x0, y0, x1, y1), 2% margin."""
    x0, y0, x1, y1 = bounds
    mx, my = 0.02 * (x1 - x0) or 1.0, 0.02 * (y1 - y0) or 1.0
    xs = np.linspace(x0 - mx, x1 + mx, SIZE_GRID)
    ys = np.linspace(y0 - my, y1 + my, SIZE_GRID)
    gx, gy = np.meshgrid(xs, ys, indexing="xy")
    x, y = gx.ravel(), gy.ravel()
    try:
        values = np.asarray(f(x, y), dtype=np.float64)
        values = np.broadcast_to(values, x.shape).copy()
    except (TypeError, ValueError):  # a scalar function: one call per point
        values = np.array([float(f(a, b)) for a, b in zip(x, y)])
    n = SIZE_GRID
    i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1), indexing="xy")
    v = (j * n + i).ravel()
    triangles = np.concatenate(
        [np.stack([v, v + 1, v + n + 1], axis=1), np.stack([v, v + n + 1, v + n], axis=1)]
    )
    return np.stack([x, y], axis=1), values.reshape(-1, 1), triangles.astype(np.int64)


def size_arguments(size, bounds):
    """The extension's (size_uniform, size_sources, grid points, grid values, grid triangles).

    size: None; a number (uniform); a string (a number, or size-file lines: 'uniform H',
    'point X Y S RBAR GAMMA', 'line X0 Y0 X1 Y1 S RBAR GAMMA'); or a callable f(x, y) -> size,
    vectorized over numpy arrays or not, sampled on a grid over `bounds`.
    """
    if size is None:
        return None, "", None, None, None
    if isinstance(size, bool):
        raise TypeError("size: expected a number, a string or a callable, got a bool")
    if isinstance(size, numbers.Real):
        return float(size), "", None, None, None
    if isinstance(size, str):
        try:
            return float(size), "", None, None, None
        except ValueError:
            return None, size, None, None, None
    if callable(size):
        if bounds is None:
            raise ValueError("size: a callable needs the domain's bounds")
        points, values, triangles = _grid(bounds, size)
        return None, "", points, values, triangles
    raise TypeError(f"size: expected a number, a string or a callable, got {type(size).__name__}")
