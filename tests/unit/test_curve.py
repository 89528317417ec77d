"""Tests of the central curve type, course_lib.curves.curve.PiecewiseBezier.

Independent references: per-segment Bézier evaluation (course_lib.curves.bezier, tested
separately against exact rationals), central finite differences for global
derivatives, and the chain rule d/dt = (1/h) d/du written out by hand.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import PiecewiseBezier
from course_lib.curves import bezier

SEG_A = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
SEG_B = np.array([[3.0, 0.0], [4.0, -1.0], [5.0, 0.5]])  # quadratic: mixed degrees
SEG_C = np.array([[5.0, 0.5], [6.0, 1.5], [6.5, 3.0], [7.0, 3.5], [8.0, 3.0]])  # quartic


def mixed(knots=None):
    return PiecewiseBezier([SEG_A, SEG_B, SEG_C], knots)


def test_facts():
    c = mixed([0.0, 0.5, 2.0, 2.25])
    assert c.n_segments == 3 and c.n_joints == 2
    assert c.degrees == (3, 2, 4)
    assert c.dim == 2 and c.domain == (0.0, 2.25) and c.has_knots
    np.testing.assert_array_equal(c.joint_points, [SEG_A[-1], SEG_B[-1]])
    np.testing.assert_array_equal(c.joint_parameters, [0.5, 2.0])
    assert c.control_points.shape == (4 + 2 + 4, 2)  # shared joints listed once
    assert not mixed().has_knots and mixed().domain == (0.0, 3.0)
    assert "3 segments" in repr(c)


def test_segments_are_read_only_copies():
    src = SEG_A.copy()
    c = PiecewiseBezier([src])
    src[0] = 99.0
    assert c.segments[0][0, 0] == 0.0
    with pytest.raises(ValueError):
        c.segments[0][0, 0] = 1.0


@pytest.mark.parametrize("knots", [None, [0.0, 0.5, 2.0, 2.25], [-3.0, -1.0, 4.0, 10.0]])
def test_global_evaluation_matches_segments(knots):
    c = mixed(knots)
    k = c.knots
    for i, seg in enumerate((SEG_A, SEG_B, SEG_C)):
        u = np.linspace(0.0, 1.0, 7)[:-1]  # the end belongs to the next segment
        t = k[i] + (k[i + 1] - k[i]) * u
        for n in range(4):
            expected = bezier.evaluate(seg, u, n) / (k[i + 1] - k[i]) ** n
            np.testing.assert_allclose(c.evaluate(t, n), expected, rtol=1e-13, atol=1e-12)
    np.testing.assert_allclose(c.evaluate(k[-1]), SEG_C[-1])


def test_global_derivative_matches_finite_differences():
    c = mixed([0.0, 0.5, 2.0, 2.25])
    t = np.array([0.1, 0.3, 0.9, 1.7, 2.1])  # away from joints
    h = 1e-6
    fd = (c.evaluate(t + h) - c.evaluate(t - h)) / (2 * h)
    np.testing.assert_allclose(c.evaluate(t, 1), fd, rtol=1e-7, atol=1e-7)
    fd2 = (c.evaluate(t + 1e-4) - 2 * c.evaluate(t) + c.evaluate(t - 1e-4)) / 1e-8
    np.testing.assert_allclose(c.evaluate(t, 2), fd2, rtol=1e-4, atol=1e-4)


def test_joint_parameter_belongs_to_the_starting_segment():
    c = mixed([0.0, 0.5, 2.0, 2.25])
    idx, u = c.locate([0.0, 0.5, 2.0, 2.25])
    np.testing.assert_array_equal(idx, [0, 1, 2, 2])
    np.testing.assert_array_equal(u, [0.0, 0.0, 0.0, 1.0])
    # first derivative at t = 0.5 is the right-hand one: 2 (B1 - B0) / h, h = 1.5
    np.testing.assert_allclose(c.evaluate(0.5, 1), 2 * (SEG_B[1] - SEG_B[0]) / 1.5)


def test_scalar_and_array_shapes():
    c = mixed()
    assert c.evaluate(0.3).shape == (2,)
    assert c.evaluate([0.3]).shape == (1, 2)
    assert c.evaluate(np.array([], dtype=float)).shape == (0, 2)
    assert c.evaluate_segment(1, 0.5).shape == (2,)
    t, p = c.sample(10)
    assert t.shape == (28,) and p.shape == (28, 2)
    assert t[0] == 0.0 and t[-1] == 3.0 and np.all(np.diff(t) > 0)


def test_end_derivatives_of_segments():
    c = mixed()
    np.testing.assert_allclose(c.end_derivatives(0, 1, 1)[1], 3 * (SEG_A[3] - SEG_A[2]))
    np.testing.assert_allclose(c.end_derivatives(1, 0, 1)[1], 2 * (SEG_B[1] - SEG_B[0]))


def test_from_control_points_and_with_knots():
    pts = np.vstack([SEG_A, [[4.0, -1.0], [6.0, 0.0], [7.0, 1.0]]])  # 7 points = 2 cubics
    c = PiecewiseBezier.from_control_points(pts, 3)
    assert c.n_segments == 2
    np.testing.assert_array_equal(c.segments[1][0], c.segments[0][-1])
    c2 = c.with_knots([0.0, 1.0, 4.0])
    np.testing.assert_allclose(c2.evaluate(4.0), c.evaluate(2.0))
    with pytest.raises(ValueError, match="degree"):
        PiecewiseBezier.from_control_points(pts[:-1], 3)


@settings(max_examples=40, deadline=None)
@given(
    a=st.floats(-3, 3),
    b=st.floats(-3, 3),
    c_=st.floats(-3, 3),
    d=st.floats(-3, 3),
    off=st.tuples(st.floats(-5, 5), st.floats(-5, 5)),
)
def test_affine_invariance(a, b, c_, d, off):
    A = np.array([[a, b], [c_, d]])
    curve = mixed([0.0, 1.0, 1.5, 4.0])
    image = curve.transformed(A, off)
    t = np.linspace(0, 4, 23)
    np.testing.assert_allclose(image.evaluate(t), curve.evaluate(t) @ A.T + off, atol=1e-9)


@pytest.mark.parametrize(
    ("args", "kwargs", "exc", "match"),
    [
        (([],), {}, ValueError, "at least one Bézier segment"),
        (([[[0, 0]]],), {}, ValueError, r"segments\[0\] must have at least 2 points"),
        (([SEG_A, [[0, 0, 0], [1, 1, 1]]],), {}, ValueError, "same space"),
        (([SEG_A, [[0, np.inf], [1, 1]]],), {}, ValueError, "finite"),
        (([SEG_A],), {"knots": [0.0, 0.0]}, ValueError, "strictly increasing"),
        (([SEG_A, SEG_B],), {"knots": [0.0, 2.0, 1.0]}, ValueError, "strictly increasing"),
        (([SEG_A, SEG_B],), {"knots": [0.0, 1.0]}, ValueError, "3 values"),
        (([SEG_A],), {"knots": [0.0, np.nan]}, ValueError, "finite"),
        ((SEG_A,), {}, ValueError, "sequence of control polygons"),
        ((5,), {}, TypeError, "sequence of control polygons"),
        ((["ab"],), {}, TypeError, "segments"),
    ],
)
def test_bad_construction(args, kwargs, exc, match):
    with pytest.raises(exc, match=match):
        PiecewiseBezier(*args, **kwargs)


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda c: c.evaluate(3.5), ValueError, "domain"),
        (lambda c: c.evaluate(-0.1), ValueError, "domain"),
        (lambda c: c.evaluate(np.nan), ValueError, "finite"),
        (lambda c: c.evaluate([[0.1]]), ValueError, "1-d"),
        (lambda c: c.evaluate(0.1, n=-2), ValueError, "n must be >= 0"),
        (lambda c: c.evaluate_segment(3, 0.5), ValueError, "segment must be < n_segments"),
        (lambda c: c.end_derivatives(0, 0.5, 1), ValueError, "end must be 0"),
        (lambda c: c.transformed(np.eye(3)), ValueError, "matrix"),
        (lambda c: c.sample(1), ValueError, "per_segment must be >= 2"),
    ],
)
def test_bad_calls(call, exc, match):
    with pytest.raises(exc, match=match):
        call(mixed())


def test_segments_by_degree_groups_mixed_degrees_with_their_hodographs():
    line, quad, cubic = ([[0, 0], [1, 0]], [[1, 0], [2, 1], [3, 0]], [[3, 0], [4, 1], [5, 1], [6, 0]])
    c = PiecewiseBezier([quad, line, cubic, quad])
    groups = {d: (idx.tolist(), rows.tolist(), pts) for d, idx, rows, pts in c.segments_by_degree(1)}
    assert sorted(groups) == [1, 2, 3]
    assert groups[2][0] == [0, 3] and groups[2][1] == [0, -1, -1, 1]
    np.testing.assert_array_equal(groups[2][2][0], 2 * np.diff(np.array(quad, float), axis=0))
    np.testing.assert_array_equal(groups[3][2][0], 3 * np.diff(np.array(cubic, float), axis=0))
    assert c.uniform_array is None
    assert PiecewiseBezier([quad, quad]).uniform_array.shape == (2, 3, 2)
