# SPDX-License-Identifier: MIT
"""pytest setup: the module under test is the build tree's (PYTHONPATH set by CTest, see
tests/CMakeLists.txt); EXACTMESH_COMMAND names the same build's `exactmesh` command."""
import os
import shutil

import numpy as np
import pytest


@pytest.fixture
def rng():
    return np.random.default_rng(20261203)


@pytest.fixture
def command():
    path = os.environ.get("EXACTMESH_COMMAND") or shutil.which("exactmesh")
    if not path:
        pytest.skip("EXACTMESH_COMMAND not set")
    return path


def scale():
    """EXACTMESH_TEST_SCALE, as the C++ tests read it (case counts and sizes)."""
    return float(os.environ.get("EXACTMESH_TEST_SCALE", "1"))
