"""Tests of the fast evaluation paths of PiecewiseBezier.evaluate and bezier.bernstein_matrix.

``PiecewiseBezier.evaluate`` uses a cached two-sided Taylor (power-basis) form with
Horner's rule for hodographs of degree <= ``TAYLOR_MAX_DEGREE`` and the Bernstein
form above.  Independent references here: exact rational de Casteljau on the exact
hodograph (``fractions.Fraction``), the Bernstein form (``Evaluator.eval_located``, and
``course_lib.curves.bezier.evaluate``), the chain rule written out by hand, and the
textbook Bernstein formula for ``bernstein_matrix``.
"""

from __future__ import annotations

from fractions import Fraction
from itertools import pairwise
from math import comb

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from course_lib import PiecewiseBezier
from course_lib.curves import bezier, evaluation
from course_lib.curves.bezier import bernstein_matrix

TOP = evaluation.TAYLOR_MAX_DEGREE


# ------------------------------------------------------------ exact reference
def exact_derivative(points, u: Fraction, n: int) -> list[Fraction]:
    """n-th derivative of the Bézier curve ``points`` at ``u``, in exact rationals."""
    Q = [[Fraction(x) for x in p] for p in points]
    d = len(Q) - 1
    if n > d:
        return [Fraction(0)] * len(Q[0])
    for r in range(n):  # hodograph: (d - r) * forward differences
        Q = [[(d - r) * (b - a) for a, b in zip(p, q, strict=True)] for p, q in pairwise(Q)]
    while len(Q) > 1:  # de Casteljau
        Q = [[(1 - u) * a + u * b for a, b in zip(p, q, strict=True)] for p, q in pairwise(Q)]
    return Q[0]


def hodograph_scale(points: np.ndarray, n: int) -> float:
    """max |control point| of the n-th hodograph: the size errors are measured against."""
    Q = bezier.derivative_control_points(points, n)
    return max(1.0, float(np.abs(Q).max()))


def random_curve(rng, degrees, dim=2, knots=None):
    segs = [rng.standard_normal((d + 1, dim)) * 10.0 ** rng.uniform(-1, 2) for d in degrees]
    return PiecewiseBezier(segs, knots)


# ------------------------------------------------------ accuracy of the Taylor form
@settings(max_examples=25, deadline=None)
@given(
    degree=st.integers(1, TOP),
    n=st.integers(0, 3),
    coords=st.lists(st.integers(-1000, 1000), min_size=2 * (TOP + 1), max_size=2 * (TOP + 1)),
    num=st.integers(0, 64),
)
@example(degree=TOP, n=0, coords=list(range(-9, 9)), num=64)  # the curve's end, u = 1
@example(degree=3, n=2, coords=list(range(18)), num=32)  # the split point u = 1/2
def test_taylor_form_matches_exact_rationals(degree, n, coords, num):
    pts = np.array(coords[: 2 * (degree + 1)], dtype=float).reshape(-1, 2) / 7.0
    # knots -1 < 0 < 0.75: a non-unit knot sequence (the search path); pts is the last
    # segment, so u = 1 (t = 0.75, the curve's end) belongs to it
    other = np.array([[3.0, 1.0], [4.0, 2.0]])
    c = PiecewiseBezier([other, pts], knots=[-1.0, 0.0, 0.75])
    u = Fraction(num, 64)
    t = float(Fraction(3, 4) * u)  # exact: a multiple of 3/256
    expected = np.array([float(x) for x in exact_derivative(pts.tolist(), u, n)]) / 0.75**n
    scale = hodograph_scale(pts, n) / 0.75**n
    np.testing.assert_allclose(c.evaluate(t, n), expected, rtol=0, atol=1e-13 * scale)


@pytest.mark.parametrize("degree", [1, 4, TOP])
def test_taylor_form_on_the_worst_case_polygon(degree):
    """Alternating control points maximize |Δ^k Q| = 2^k max|Q|: the bound's worst case."""
    P = np.array([[(-1.0) ** i, (-1.0) ** (i // 2)] for i in range(degree + 1)]) * 1000.0
    c = PiecewiseBezier([P])
    us = [Fraction(k, 64) for k in range(65)]  # exact in binary
    u = np.array([float(x) for x in us])
    for n in range(4):
        expected = np.array([[float(v) for v in exact_derivative(P.tolist(), x, n)] for x in us])
        err = np.abs(c.evaluate(u, n) - expected).max() / hodograph_scale(P, n)
        assert err < 1e-13


@pytest.mark.parametrize("degree", range(1, TOP + 1))
@pytest.mark.parametrize("n", [0, 1, 2, 3])
def test_taylor_form_matches_bernstein_form(degree, n):
    """The Horner path agrees with the Bernstein path to ~1e-13 of the control-point size."""
    rng = np.random.default_rng(100 * degree + n)
    knots = np.cumsum(rng.uniform(0.2, 3.0, 6))
    c = random_curve(rng, [degree] * 5, knots=knots)
    t = np.sort(rng.uniform(knots[0], knots[-1], 4000))
    t = np.concatenate([t, knots])  # joints and ends too
    idx, u = c.locate(t)
    h = np.diff(knots)[idx][:, None]
    bernstein_form = c.engine.eval_located(idx, u, n) / h**n
    scale = max(hodograph_scale(s, n) for s in c.segments) / np.diff(knots).min() ** n
    err = np.abs(c.evaluate(t, n) - bernstein_form).max() / scale
    assert err < 1e-13


def test_bernstein_fallback_above_the_taylor_degree():
    rng = np.random.default_rng(7)
    seg = rng.standard_normal((TOP + 4, 2))  # degree TOP + 3
    c = PiecewiseBezier([seg, seg[::-1]], knots=[0.0, 1.5, 2.0])
    assert c.engine.taylor(0) is None  # the Bernstein path is used
    assert c.engine.taylor(3) is not None  # the 3rd hodograph has degree TOP
    u = np.linspace(0.0, 1.0, 9)[:-1]
    for n in range(5):
        np.testing.assert_allclose(
            c.evaluate(1.5 * u, n), bezier.evaluate(seg, u, n) / 1.5**n, rtol=1e-12, atol=1e-10
        )


# ------------------------------------------------------------ structure and shapes
def test_mixed_degrees_match_each_segment():
    rng = np.random.default_rng(1)
    degrees = [1, 3, 2, TOP, 5]
    knots = [0.0, 0.3, 1.0, 1.1, 2.0, 4.0]
    c = random_curve(rng, degrees, dim=3, knots=knots)
    u = np.linspace(0.0, 1.0, 11)[:-1]
    for i, seg in enumerate(c.segments):
        h = knots[i + 1] - knots[i]
        for n in range(TOP + 2):
            got = c.evaluate(knots[i] + h * u, n)
            expected = bezier.evaluate(seg, u, n) / h**n
            scale = hodograph_scale(seg, n) / h**n
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-13 * scale)


def test_derivatives_of_order_above_the_degree_are_zero():
    seg_lin = np.array([[0.0, 0.0], [1.0, 2.0]])
    seg_cub = np.array([[1.0, 2.0], [2.0, 3.0], [4.0, 3.0], [5.0, 1.0]])
    c = PiecewiseBezier([seg_lin, seg_cub])
    t_lin = np.linspace(0.0, 0.99, 7)
    t_cub = np.linspace(1.0, 2.0, 7)
    np.testing.assert_array_equal(c.evaluate(t_lin, 2), np.zeros((7, 2)))
    np.testing.assert_array_equal(c.evaluate(t_cub, 4), np.zeros((7, 2)))
    np.testing.assert_array_equal(c.evaluate(t_lin, 7), np.zeros((7, 2)))
    # third derivative of a cubic is constant: 6 * Δ³V (hand formula)
    third = 6 * (seg_cub[3] - 3 * seg_cub[2] + 3 * seg_cub[1] - seg_cub[0])
    np.testing.assert_allclose(c.evaluate(t_cub, 3), np.tile(third, (7, 1)), rtol=1e-15)
    np.testing.assert_array_equal(c.evaluate(t_lin, 3), np.zeros((7, 2)))


@pytest.mark.parametrize("knots", [None, [0.0, 0.5, 2.0, 2.25]])
def test_scalar_and_array_agree(knots):
    rng = np.random.default_rng(2)
    c = random_curve(rng, [3, 2, 4], knots=knots)
    t0, t1 = c.domain
    ts = np.concatenate([np.linspace(t0, t1, 13), c.knots, rng.uniform(t0, t1, 50)])
    for n in range(4):
        many = c.evaluate(ts, n)  # the vectorized path
        for t, row in zip(ts, many, strict=True):
            one = c.evaluate(float(t), n)  # the one-parameter path: the same bits
            assert one.shape == (2,)
            np.testing.assert_array_equal(one, row)
            np.testing.assert_array_equal(c.evaluate(np.array([t]), n), row[None, :])
            np.testing.assert_array_equal(c.evaluate(np.float64(t), n), row)
    assert c.evaluate(np.array([], dtype=float)).shape == (0, 2)


def test_joints_and_ends_are_exact_and_one_sided():
    # a curve with a corner: the derivative jumps at the joint t = 1
    A = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
    B = np.array([[3.0, 0.0], [3.0, -1.0], [5.0, -1.0], [6.0, 0.5]])
    for knots in (None, [0.0, 1.0, 2.0], [0.0, 0.4, 1.7]):
        c = PiecewiseBezier([A, B], knots)
        k = c.knots
        np.testing.assert_array_equal(c.evaluate(k[0]), A[0])
        np.testing.assert_array_equal(c.evaluate(k[1]), B[0])  # starting segment, exactly
        np.testing.assert_array_equal(c.evaluate(k[2]), B[-1])  # curve end, exactly
        h1 = k[2] - k[1]
        np.testing.assert_allclose(c.evaluate(k[1], 1), 3 * (B[1] - B[0]) / h1, rtol=1e-15)
        np.testing.assert_allclose(c.evaluate(k[2], 1), 3 * (B[3] - B[2]) / h1, rtol=1e-14)


def test_parameters_just_outside_the_domain_are_clipped_and_far_ones_refused():
    A = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])
    for knots in (None, [0.0, 2.0]):
        c = PiecewiseBezier([A], knots)
        t1 = c.domain[1]
        np.testing.assert_array_equal(c.evaluate([-1e-14, t1 + 1e-14]), [A[0], A[-1]])
        np.testing.assert_array_equal(c.evaluate(-1e-14), A[0])
        np.testing.assert_array_equal(c.evaluate(t1 + 1e-14), A[-1])
        np.testing.assert_array_equal(c.evaluate([t1 + 1e-14]), [A[-1]])
        with pytest.raises(ValueError, match=r"t must lie in the domain"):
            c.evaluate(t1 + 1e-6)
        with pytest.raises(ValueError, match=r"t must lie in the domain"):
            c.evaluate([0.5, -1e-6])


def test_unit_knot_path_equals_search_path():
    """Default knots 0..S (index by floor(2t)) and a shifted copy (binary search) agree."""
    rng = np.random.default_rng(3)
    c = random_curve(rng, [3, 3, 4, 2, 3, 3])
    shifted = c.with_knots(c.knots + 0.25)  # same spacing, not the default knots
    assert c.engine.halves()[3] and not shifted.engine.halves()[3]
    t = rng.uniform(0.0, 6.0, 2000)
    t[:7] = np.arange(7)  # every joint and both ends
    for n in range(4):
        np.testing.assert_allclose(
            c.evaluate(t, n), shifted.evaluate(t + 0.25, n), rtol=1e-13, atol=1e-12
        )


def test_explicit_integer_knots_equal_default_knots_bitwise():
    rng = np.random.default_rng(4)
    c = random_curve(rng, [3, 2, 3])
    explicit = c.with_knots([0.0, 1.0, 2.0, 3.0])
    t = np.linspace(0.0, 3.0, 301)
    for n in range(3):
        np.testing.assert_array_equal(c.evaluate(t, n), explicit.evaluate(t, n))


def test_knot_scaling_follows_the_chain_rule():
    rng = np.random.default_rng(5)
    c = random_curve(rng, [3, 5, 2])
    scaled = c.with_knots(2.5 * c.knots - 1.0)  # t' = 2.5 t - 1, so d/dt' = (1/2.5) d/dt
    t = np.linspace(0.0, 3.0, 97)
    for n in range(4):
        np.testing.assert_allclose(
            scaled.evaluate(2.5 * t - 1.0, n), c.evaluate(t, n) / 2.5**n, rtol=1e-12, atol=1e-12
        )


def test_long_unsorted_input_crosses_chunks():
    rng = np.random.default_rng(6)
    c = random_curve(rng, [3] * 10, knots=np.cumsum(rng.uniform(0.5, 2.0, 11)))
    m = 2 * evaluation.CHUNK + 17
    t = rng.uniform(*c.domain, m)
    for n in (0, 2):
        whole = c.evaluate(t, n)
        idx, u = c.locate(t)
        h = np.diff(c.knots)[idx][:, None]
        np.testing.assert_allclose(whole, c.engine.eval_located(idx, u, n) / h**n, rtol=1e-12, atol=1e-9)
        # the pieces evaluated separately give the same numbers
        cut = evaluation.CHUNK + 3
        np.testing.assert_array_equal(
            whole, np.vstack([c.evaluate(t[:cut], n), c.evaluate(t[cut:], n)])
        )


def test_cache_does_not_leak_between_curves():
    A = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])
    c1 = PiecewiseBezier([A])
    c1.evaluate(0.5)
    c2 = c1.transformed(np.array([[2.0, 0.0], [0.0, 2.0]]))
    np.testing.assert_allclose(c2.evaluate(0.5), 2 * c1.evaluate(0.5))


# ------------------------------------------------------------------ bernstein_matrix
def textbook_bernstein(d: int, u: np.ndarray) -> np.ndarray:
    """comb(d, i) * u**i * (1 - u)**(d - i) with powers as repeated products."""
    out = np.empty((u.size, d + 1))
    for i in range(d + 1):
        up = np.ones_like(u)
        for _ in range(i):
            up = up * u
        vp = np.ones_like(u)
        for _ in range(d - i):
            vp = vp * (1.0 - u)
        out[:, i] = comb(d, i) * up * vp
    return out


@pytest.mark.parametrize("d", range(0, 13))
def test_fast_bernstein_is_the_textbook_formula_bit_for_bit(d):
    u = np.concatenate([np.random.default_rng(d).uniform(-0.5, 1.5, 500), [0.0, 0.5, 1.0]])
    np.testing.assert_array_equal(bernstein_matrix(d, u), textbook_bernstein(d, u))
    out = bezier.bernstein(d, u)
    assert out.shape == (u.size, d + 1) and out.flags.c_contiguous
