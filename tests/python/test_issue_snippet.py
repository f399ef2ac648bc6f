# SPDX-License-Identifier: BSD-3-Clause
"""The snippet of the issue that asked for the package, exactly as written."""
import pytest


def test_snippet_as_written():
    import projcurve as pc
    s = pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                              control_points=[[0,0,0], [1,0,0], [0,1,0], [1,1,1]],
                              knots=([0,0,1,1], [0,0,1,1]))
    c = pc.Curve.from_nurbs(degree=1, control_points=[[0.1,0.2,2], [0.9,0.7,2]],
                            knots=[0,0,1,1])
    res = pc.project_directional(s, c, (0, 0, -1))
    assert len(res.branches) == 1
    with pytest.raises(pc.Error) as info:
        pc.project_directional(s, c, (0, 0, 0))   # raises pc.Error naming the direction
    assert "direction" in str(info.value)
    assert info.value.status == pc.Status.ERR_ZERO_DIRECTION
    assert isinstance(info.value, pc.ZeroDirectionError)
