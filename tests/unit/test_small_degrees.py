"""Small degrees (issue 14): a degree-0 Bézier curve (one point) and G1 stitching of a
degree-1 left segment.  References: the definitions (a constant curve; seed 000 eq. (9)-(10)
use only V_{d-1}, V_d) and the explicit Beta-constraints of ``_spline_checks``."""

from __future__ import annotations

import numpy as np
from _spline_checks import check_joint

from course_lib.constructions.stitching import g1_stitch, g1_stitch_points
from course_lib.curves import bezier
from course_lib.geometry.continuity import curve_continuity

P0 = np.array([[1.5, -2.0]])


def test_degree_zero_evaluates_differentiates_and_elevates():
    u = np.linspace(0.0, 1.0, 5)
    np.testing.assert_array_equal(bezier.evaluate(P0, u), np.repeat(P0, 5, axis=0))
    np.testing.assert_array_equal(bezier.evaluate(P0, 0.3), P0[0])
    np.testing.assert_array_equal(bezier.evaluate(P0, u, 1), np.zeros((5, 2)))
    np.testing.assert_array_equal(bezier.derivative_control_points(P0, 2), np.zeros((1, 2)))
    np.testing.assert_array_equal(bezier.end_derivatives(P0, 2, 0), [P0[0], [0, 0], [0, 0]])
    np.testing.assert_array_equal(bezier.elevate_degree(P0, 3), np.repeat(P0, 4, axis=0))
    left, right = bezier.subdivide(P0, 0.4)
    np.testing.assert_array_equal(left, P0)
    np.testing.assert_array_equal(right, P0)
    assert len(bezier.de_casteljau(P0, 0.7)) == 1


def test_g1_stitch_of_a_degree_one_left_segment():
    V = np.array([[0.0, 0.0], [2.0, 1.0]])
    W = g1_stitch_points(V, 1.5)
    np.testing.assert_allclose(W, [[2.0, 1.0], [5.0, 2.5]])  # W1 = V1 + 1.5 (V1 - V0)
    c = g1_stitch(V, 1.5, None)
    assert c.degrees == (1, 1)
    check_joint(c, 0, [1.5])
    assert curve_continuity(c, 1)[0].g_order == 1
    c = g1_stitch(V, 0.5, np.zeros((0, 2)))
    check_joint(c, 0, [0.5])
