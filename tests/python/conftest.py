# SPDX-License-Identifier: BSD-3-Clause
"""Fixtures of the Python package's tests (run by CTest as python_package,
which sets PROJCURVE_LIBRARY, PYTHONPATH and the paths below)."""
import os

import pytest

# The standalone ctypes test of the installed library runs on its own
# (CTest python_ctypes); it has no pytest tests.
collect_ignore = ["test_ctypes.py"]

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.environ.get("PROJCURVE_SOURCE_DIR", os.path.dirname(os.path.dirname(HERE)))
DATA = os.environ.get("PROJCURVE_TEST_DATA", os.path.join(SOURCE_DIR, "tests", "data"))


def data(*parts):
    return os.path.join(DATA, *parts)


@pytest.fixture
def pc():
    import projcurve
    return projcurve


@pytest.fixture
def bilinear(pc):
    """The bilinear patch z = u v over [0, 1]^2 (x = u, y = v)."""
    return pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                                 control_points=[[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]],
                                 knots=([0, 0, 1, 1], [0, 0, 1, 1]))


@pytest.fixture
def segment(pc):
    """The segment (0.1, 0.2, 2) -> (0.9, 0.7, 2) above it."""
    return pc.Curve.from_nurbs(degree=1, control_points=[[0.1, 0.2, 2], [0.9, 0.7, 2]],
                               knots=[0, 0, 1, 1])
