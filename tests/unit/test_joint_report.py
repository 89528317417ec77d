"""``continuity.joint_report``: one joint of a curve alone, as the demos' live report asks it."""

from __future__ import annotations

import numpy as np
import pytest

from course_lib import PiecewiseBezier
from course_lib.geometry.continuity import curve_continuity, joint_report


def _curve() -> PiecewiseBezier:
    """Three cubics with knots 0, 1, 3, 4: joint 0 is C1 in the local parameters but, with
    these knots, only G1 (β1 = 1/2); joint 1 has a corner."""
    a = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
    b = np.array([[3.0, 0.0], [4.0, -1.0], [5.0, 0.5], [6.0, 0.0]])
    c = np.array([[6.0, 0.0], [6.0, 2.0], [7.0, 2.0], [8.0, 1.0]])
    return PiecewiseBezier([a, b, c], knots=[0.0, 1.0, 3.0, 4.0])


@pytest.mark.parametrize("j", [0, 1])
def test_one_joint_alone_is_that_joint_of_the_whole_curve(j):
    curve = _curve()
    whole = curve_continuity(curve, max_order=3)[j]
    alone = joint_report(curve, j, max_order=3)
    assert alone.index == j
    assert (alone.g_order, alone.c_order) == (whole.g_order, whole.c_order)
    np.testing.assert_allclose(alone.betas, whole.betas, rtol=1e-12, atol=1e-12)


def test_the_knots_count():
    """β1 = 1/2 at joint 0: a C1 pair in the local parameters, with knot spans 1 and 2, has
    ``r'(t_1) = Q_b'(0) / 2 = Q_a'(1) / 2`` in the global parameter (seed 004 §19.7)."""
    report = joint_report(_curve(), 0, max_order=2)
    assert report.g_order >= 1 and report.c_order == 0
    assert report.betas[0] == pytest.approx(0.5)


@pytest.mark.parametrize(
    ("curve", "j", "error", "match"),
    [
        (_curve(), 2, ValueError, "j must be < 2"),
        (_curve(), -1, ValueError, "j"),
        (PiecewiseBezier([[[0, 0], [1, 1]]]), 0, ValueError, "j must be < 0"),
        ("a curve", 0, TypeError, "curve must be a PiecewiseBezier"),
    ],
)
def test_bad_input_is_named(curve, j, error, match):
    with pytest.raises(error, match=match):
        joint_report(curve, j)
