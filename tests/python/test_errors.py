# SPDX-License-Identifier: MIT
"""Every error path raises ValueError (exactmesh.InputError / GeometryError) with the command's
message; no input crashes the interpreter."""
import numpy as np
import pytest

import exactmesh

SQUARE = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
SIDES = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def test_errors_are_value_errors():
    assert issubclass(exactmesh.InputError, ValueError)
    assert issubclass(exactmesh.GeometryError, ValueError)


@pytest.mark.parametrize("points", [np.zeros((5, 3)), np.zeros(6), np.zeros((2, 2, 2))])
def test_wrong_shapes(points):
    with pytest.raises(exactmesh.InputError, match="shape"):
        exactmesh.triangulate(points)


@pytest.mark.parametrize("bad", [np.nan, np.inf])
def test_non_finite_points(bad):
    points = np.array([[0, 0], [1, 0], [0, 1], [bad, 0.5]])
    with pytest.raises(exactmesh.InputError):
        exactmesh.triangulate(points)
    with pytest.raises(exactmesh.InputError):
        exactmesh.tetrahedralize(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, bad]]))


def test_unknown_names():
    with pytest.raises(exactmesh.InputError, match="known"):
        exactmesh.triangulate(SQUARE, algorithm="qhull")
    with pytest.raises(exactmesh.InputError, match="known"):
        exactmesh.triangulate(SQUARE, order="sideways")
    with pytest.raises(exactmesh.InputError, match="known"):
        exactmesh.mesh(domain="teapot")
    with pytest.raises(exactmesh.InputError):
        exactmesh.mesh(SQUARE, SIDES, generator="magic")
    with pytest.raises(exactmesh.InputError):
        exactmesh.cdt(SQUARE, SIDES, recovery="glue")


@pytest.mark.parametrize("segments", [[[0, 4]], [[-1, 2]], [[0, 2**40]]])
def test_segment_indices_out_of_range(segments):
    with pytest.raises(exactmesh.InputError, match="outside"):
        exactmesh.cdt(SQUARE, segments)


def test_float_indices_are_refused():
    with pytest.raises(exactmesh.InputError, match="integer"):
        exactmesh.cdt(SQUARE, np.array([[0.0, 1.0]]))


def test_options_a_generator_does_not_honour():
    with pytest.raises(exactmesh.InputError, match="min_angle"):
        exactmesh.mesh(SQUARE, SIDES, generator="frontal", min_angle=30)
    with pytest.raises(exactmesh.InputError, match="layers"):
        exactmesh.mesh(SQUARE, SIDES, generator="frontal", layers=(1e-3, 1.2))
    with pytest.raises(exactmesh.InputError, match="needs layers"):
        exactmesh.mesh(domain="naca0012", generator="advancing-layers")
    with pytest.raises(exactmesh.InputError, match="not both"):
        exactmesh.mesh(SQUARE, SIDES, domain="key")


@pytest.mark.parametrize("size", [0.0, -1.0, np.nan, np.inf])
def test_bad_sizes(size):
    with pytest.raises(exactmesh.InputError):
        exactmesh.mesh(SQUARE, SIDES, generator="frontal", size=size)


def test_a_size_over_the_budget_fails_at_once_with_the_estimate():
    with pytest.raises(exactmesh.InputError, match="triangles"):
        exactmesh.mesh(domain="naca0012", generator="frontal", size=1e-7)


def test_a_size_that_is_not_a_size():
    with pytest.raises(TypeError):
        exactmesh.mesh(SQUARE, SIDES, size=True)
    with pytest.raises(exactmesh.InputError):
        exactmesh.mesh(SQUARE, SIDES, generator="frontal", size="point 1 2")


def test_an_open_boundary_is_an_input_error():
    # Three sides of the square enclose nothing: the exterior removal reaches every triangle.
    with pytest.raises(exactmesh.InputError, match="enclose no region"):
        exactmesh.mesh(SQUARE, SIDES[:3], generator="frontal", size=0.1)


def test_check_mesh_input_vertex_count_beyond_the_points():
    m = exactmesh.cdt(SQUARE, SIDES)
    m.input_vertex_count = 99
    with pytest.raises(exactmesh.InputError, match="exceeds"):
        exactmesh.check_mesh(m)
