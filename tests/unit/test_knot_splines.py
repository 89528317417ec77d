"""Tests of course_lib.constructions.knot_splines (seed 004 §19.5-19.7).

References: the midpoint rule of the C1 Bézier spline (uniform knots); the chain rule
in the global parameter (C1, seed 004 exercise 3) checked on the global derivatives
and by course_lib.geometry.continuity; the explicit Beta-constraint (7.1) with β1 from the knot
ratio; the barycentric identity of seed 004 §19.6 checked on the numbers t_i.
"""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import check_joint
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.knot_splines import (
    bezier_points_from_g1,
    g1_knot_spline,
    knot_ratio_beta1,
)
from course_lib.geometry.continuity import curve_continuity


def _knots(rng, L):
    return np.concatenate([[0.0], np.cumsum(rng.uniform(0.2, 3.0, L))])


def test_uniform_knots_midpoint_rule_and_c1():
    rng = np.random.default_rng(0)
    D = rng.normal(size=(8, 2))  # L = 3
    P = bezier_points_from_g1(D, [0.0, 1.0, 2.0, 3.0])
    np.testing.assert_allclose(P[3], (P[2] + P[4]) / 2)
    np.testing.assert_allclose(P[6], (P[5] + P[7]) / 2)
    # the non-joint points are the d's in order
    np.testing.assert_allclose(np.delete(P, [3, 6], axis=0), D)
    c = g1_knot_spline(D, [0.0, 1.0, 2.0, 3.0])
    assert [r.c_order for r in curve_continuity(c, max_order=2)] == [1, 1]


def test_finn_exercise_2_knots():
    """Seed 004 exercise 2 (a)-(c): joints divide p_{3i-1} p_{3i+1} like t_i divides."""
    D = np.array([[0, 0], [1, 2], [3, 3], [5, 3], [7, 2], [8, 0], [9, -2], [11, -1]], float)
    for knots in ([0, 1, 2, 5], [0, 2, 4, 6], [0, 1, 3, 4]):
        P = bezier_points_from_g1(D, knots)
        for i in (1, 2):
            lam = (knots[i] - knots[i - 1]) / (knots[i + 1] - knots[i - 1])
            np.testing.assert_allclose(P[3 * i], (1 - lam) * P[3 * i - 1] + lam * P[3 * i + 1])
    # (b) is uniform: midpoints
    P = bezier_points_from_g1(D, [0, 2, 4, 6])
    np.testing.assert_allclose(P[3], (D[2] + D[3]) / 2)


@settings(max_examples=25, deadline=None)
@given(L=st.integers(2, 6), seed=st.integers(0, 10**6))
def test_random_knots_c1_in_global_parameter(L, seed):
    rng = np.random.default_rng(seed)
    D = rng.normal(size=(2 * L + 2, 2))
    t = _knots(rng, L)
    c = g1_knot_spline(D, t)
    np.testing.assert_allclose(c.knots, t)
    h = np.diff(t)
    for j in range(c.n_joints):
        left = c.end_derivatives(j, 1, 1)[1] / h[j]  # chain rule: d/dt = (1/h) d/du
        right = c.end_derivatives(j + 1, 0, 1)[1] / h[j + 1]
        np.testing.assert_allclose(left, right, atol=1e-10 * (1 + np.abs(left).max()))
        check_joint(c, j, [h[j + 1] / h[j]])  # local parameters: G1 with the knot ratio
    np.testing.assert_allclose(knot_ratio_beta1(t), h[1:] / h[:-1])
    np.testing.assert_allclose(c.info["beta1"], h[1:] / h[:-1])


def test_exactly_c1_and_g1_for_generic_knots():
    rng = np.random.default_rng(4)
    c = g1_knot_spline(rng.normal(size=(10, 2)), [0.0, 0.7, 2.0, 2.4, 4.0])
    reps = curve_continuity(c, max_order=2, rtol=1e-7)
    assert [r.c_order for r in reps] == [1, 1, 1]
    assert [r.g_order for r in reps] == [1, 1, 1]
    # without the knots (unit global parameter) the same geometry is G1 but not C1
    reps = curve_continuity(c.with_knots(np.arange(5.0)), max_order=2, rtol=1e-7)
    assert [r.c_order for r in reps] == [0, 0, 0]
    assert [r.g_order for r in reps] == [1, 1, 1]


def test_barycentric_identity_of_knots():
    a, b, c = 0.3, 1.1, 2.9
    assert (c - b) / (c - a) * a + (b - a) / (c - a) * c == pytest.approx(b)


def test_one_segment():
    D = np.array([[0, 0], [1, 1], [2, 1], [3, 0]], float)
    c = g1_knot_spline(D, [2.0, 5.0])
    np.testing.assert_allclose(c.segments[0], D)
    assert c.domain == (2.0, 5.0)


D8 = np.arange(16, dtype=float).reshape(8, 2) ** 1.5


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ((D8, [0.0, 1.0, 1.0, 2.0]), r"strictly increasing; knots\[1\] = 1.0"),
        ((D8, [0.0, 2.0, 1.0, 3.0]), "strictly increasing"),
        ((D8, [0.0, 1.0, 2.0]), "knots must have L \\+ 1 = 4 values"),
        ((D8[:7], [0.0, 1.0, 2.0]), "even number"),
        ((D8[:2], [0.0, 1.0]), "at least 4 points"),
        ((D8, [0.0, 1.0, np.nan, 3.0]), "finite"),
        ((np.vstack([D8[:2], D8[1:2], D8[1:2], D8[4:]]), [0, 1, 2, 3]), "joint 0"),
    ],
)
def test_bad_input(args, match):
    with pytest.raises(ValueError, match=match):
        g1_knot_spline(*args)
