"""Tests of course_lib.geometry.reparametrization (seed 000 §4, seed 001 §2).

Independent references: sympy differentiation of explicit compositions (Faà di
Bruno, orders 1..6), the closed forms of seed 000 Examples 1-2, and invariance
properties (hypothesis) checked against the un-reparametrized curve.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry import differential_geometry as dg
from course_lib.geometry.reparametrization import (
    ChangeOfVariables,
    Reparametrized,
    are_equivalent,
    faa_di_bruno,
)

# Seed 000 Example 1 and 2, as degree-1 PiecewiseBezier curves:
Q = PiecewiseBezier([np.array([[0.0, 0.0], [2.0, 1.0]])])  # q(u) = (2u, u), u in [0, 1]
Q_TILDE = PiecewiseBezier([np.array([[0.0, 0.0], [2.0, 1.0]])], knots=[0.0, 0.5])  # (4ũ, 2ũ)
R = PiecewiseBezier([np.array([[2.0, 1.0], [4.0, 2.0]])], knots=[0.0, 0.5])  # (4t+2, 2t+1)


def test_seed_000_examples_1_and_2_closed_forms():
    u = np.linspace(0, 0.5, 5)
    np.testing.assert_allclose(Q_TILDE.evaluate(u), np.stack([4 * u, 2 * u], -1))
    np.testing.assert_allclose(R.evaluate(u), np.stack([4 * u + 2, 2 * u + 1], -1))
    np.testing.assert_allclose(Q.evaluate(1.0, 1), [2.0, 1.0])  # q'(1)
    np.testing.assert_allclose(R.evaluate(0.0, 1), [4.0, 2.0])  # r'(0): differs (not C1)
    np.testing.assert_allclose(Q_TILDE.evaluate(0.5, 1), [4.0, 2.0])  # = r'(0): C1 after reparam.


def test_example_2_is_q_composed_with_2u():
    f = ChangeOfVariables.affine((0.0, 0.5), (0.0, 1.0))  # f(ũ) = 2ũ
    assert f(0.25) == pytest.approx(0.5)
    rq = Reparametrized(Q, f)
    u = np.linspace(0, 0.5, 7)
    for n in range(3):
        np.testing.assert_allclose(rq.evaluate(u, n), Q_TILDE.evaluate(u, n), atol=1e-15)
    res = are_equivalent(Q, Q_TILDE)
    assert res and res.equivalent
    np.testing.assert_allclose(res.f_of_u, 2 * res.u, atol=1e-12)
    assert np.all(np.diff(res.f_of_u) > 0)


def test_unit_tangent_is_intrinsic_and_seed_000_errata():
    # Derivative vectors are not intrinsic ...
    assert not np.allclose(Q.evaluate(1.0, 1), Q_TILDE.evaluate(0.5, 1))
    # ... the unit tangent is: all three give (2, 1)/sqrt(5).
    expected = np.array([2.0, 1.0]) / np.sqrt(5.0)
    for c, t in ((Q, 1.0), (Q_TILDE, 0.5), (R, 0.0)):
        np.testing.assert_allclose(dg.unit_tangent(c, t), expected, rtol=1e-15)
    # Seed 000 Example 1 prints the unit tangent as (4/5, 3/5); that is wrong:
    # (4/5, 3/5) is not even parallel to q'(1) = (2, 1) (cross product 4/5 - 6/5 != 0).
    printed = np.array([0.8, 0.6])
    assert not np.allclose(dg.unit_tangent(Q, 1.0), printed, atol=1e-3)
    assert abs(2.0 * printed[1] - 1.0 * printed[0]) > 0.1


def _sympy_composite_derivatives(n, t0):
    import sympy as sp

    x, t = sp.symbols("x t")
    g = [sp.sin(x) + x**2, sp.exp(x / 3) * x]
    f = t + t**3 / 3 + t**4 / 7
    comp = [gi.subs(x, f) for gi in g]

    def table(exprs, var, at):
        rows, cur = [], list(exprs)
        for _ in range(n):
            cur = [sp.diff(e, var) for e in cur]
            rows.append([float(e.evalf(subs={var: at})) for e in cur])
        return np.array(rows)

    direct = table(comp, t, t0)
    outer = table(g, x, float(f.subs(t, t0)))
    inner = table([f], t, t0)[:, 0]
    return direct, outer, inner, g, f, x, t


def test_faa_di_bruno_matches_sympy_orders_1_to_6():
    direct, outer, inner, *_ = _sympy_composite_derivatives(6, 0.7)
    got = faa_di_bruno(outer, inner)
    np.testing.assert_allclose(got, direct, rtol=1e-12)
    # scalar outer function and vectorized over m parameters
    got_scalar = faa_di_bruno(outer[:, 0], inner)
    np.testing.assert_allclose(got_scalar, direct[:, 0], rtol=1e-12)
    m_outer = np.stack([outer, 2 * outer], axis=1)  # (n, m=2, dim)
    m_inner = np.stack([inner, inner], axis=1)  # (n, m=2)
    np.testing.assert_allclose(faa_di_bruno(m_outer, m_inner)[:, 1], 2 * direct, rtol=1e-12)


def test_reparametrized_derivatives_match_sympy():
    direct, _, _, g, f, x, t = _sympy_composite_derivatives(5, 0.3)
    curve = ParametricCurve.from_sympy(g, x, (0.0, 3.0))
    cv = ChangeOfVariables.from_sympy(f, t, (0.0, 1.0))
    assert cv.image[1] == pytest.approx(float(f.subs(t, 1)))
    rp = Reparametrized(curve, cv)
    got = np.array([rp.evaluate(0.3, n) for n in range(1, 6)])
    np.testing.assert_allclose(got, direct, rtol=1e-12)
    np.testing.assert_allclose(rp.evaluate([0.3, 0.6], 4)[0], direct[3], rtol=1e-12)


def test_polynomial_and_inverse():
    f = ChangeOfVariables.polynomial([1.0, 2.0, 0.0, 1.0], (0.0, 1.0), image=(1.0, 4.0))
    x = np.linspace(0, 1, 9)
    np.testing.assert_allclose(f(x), 1 + 2 * x + x**3)
    np.testing.assert_allclose(f(x, 1), 2 + 3 * x**2)
    np.testing.assert_allclose(f(x, 3), 6.0)
    np.testing.assert_allclose(f.inverse(f(x)), x, atol=1e-14)
    np.testing.assert_allclose(f.derivatives(0.5, 2), [2.75, 3.0])
    P = np.polynomial.Polynomial([0.0, 1.0, 1.0])
    assert ChangeOfVariables.polynomial(P, (0.0, 1.0)).image == (0.0, 2.0)


def test_from_betas_taylor_polynomial():
    betas = [2.0, -3.0, 5.0, 1.0]
    f = ChangeOfVariables.from_betas(betas, end=1.0, image_end=1.0, image_start_min=0.0)
    assert f.domain[1] == 1.0 and f(1.0) == pytest.approx(1.0)
    np.testing.assert_allclose(f.derivatives(1.0, 4), betas, rtol=1e-12)
    assert f.image[0] >= 0.0


def _bernstein_cubic(b1, b2):
    # f(x) = 3 b1 x (1-x)^2 + 3 b2 x^2 (1-x) + x^3: increasing when 0 < b1 < b2 < 1
    return [0.0, 3 * b1, -6 * b1 + 3 * b2, 3 * b1 - 3 * b2 + 1]


CUBIC = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 2.0], [3.0, -1.0], [4.0, 1.0]])])


@settings(max_examples=25, deadline=None)
@given(
    b=st.lists(st.floats(0.05, 0.95), min_size=2, max_size=2, unique=True).map(sorted),
    L=st.floats(0.2, 5.0),
)
def test_tangent_and_curvature_invariant_under_reparametrization(b, L):
    if b[1] - b[0] < 1e-3:
        return
    # random orientation-preserving cubic change of variables [0, L] -> [0, 1]
    c = np.array(_bernstein_cubic(*b)) / np.array([1.0, L, L**2, L**3])
    f = ChangeOfVariables.polynomial(c, (0.0, L), image=(0.0, 1.0))
    rp = Reparametrized(CUBIC, f)
    x = np.linspace(0.0, L, 9)
    u = f(x)
    np.testing.assert_allclose(dg.unit_tangent(rp, x), dg.unit_tangent(CUBIC, u), atol=1e-12)
    np.testing.assert_allclose(
        dg.signed_curvature(rp, x), dg.signed_curvature(CUBIC, u), rtol=1e-9, atol=1e-12
    )
    np.testing.assert_allclose(
        dg.arc_length_derivatives(rp, L / 3, 3), dg.arc_length_derivatives(CUBIC, f(L / 3), 3),
        rtol=1e-8, atol=1e-10,
    )  # fmt: skip
    assert dg.arc_length(rp) == pytest.approx(dg.arc_length(CUBIC), rel=1e-12)
    # derivative vectors are not intrinsic: they scale with f'
    np.testing.assert_allclose(rp.evaluate(x, 1), CUBIC.evaluate(u, 1) * f(x, 1)[:, None])
    assert are_equivalent(CUBIC, rp)


def test_are_equivalent_negative_cases():
    reversed_q = PiecewiseBezier([np.array([[2.0, 1.0], [0.0, 0.0]])])
    res = are_equivalent(Q, reversed_q)
    assert not res and "opposite direction" in res.reason
    other = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 2.0]])])  # same length, other line
    res = are_equivalent(Q, other)
    assert not res and "different curves" in res.reason
    longer = PiecewiseBezier([np.array([[0.0, 0.0], [4.0, 2.0]])])
    assert "different lengths" in are_equivalent(Q, longer).reason
    q3 = PiecewiseBezier([np.array([[0.0, 0.0, 0.0], [2.0, 1.0, 0.0]])])
    assert "dimensions" in are_equivalent(Q, q3).reason


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: ChangeOfVariables.affine((0, 1), (1, 0)), ValueError, "start < end"),
        (lambda: ChangeOfVariables.affine((1, 1), (0, 1)), ValueError, "start < end"),
        (lambda: ChangeOfVariables.polynomial([0, 1], (0, 1), image=(0, 2)), ValueError,
         "must equal the end of the image"),
        (lambda: ChangeOfVariables.polynomial([0, 1, -3], (0, 1)), ValueError,
         "orientation preserving"),
        (lambda: ChangeOfVariables.polynomial([1, -1], (0, 1)), ValueError,
         "orientation preserving"),
        (lambda: ChangeOfVariables.polynomial([0, 0, 1], (-1, 1)), ValueError,
         "orientation preserving"),  # f' = 2x vanishes at 0 and is negative before
        (lambda: ChangeOfVariables.polynomial([np.nan, 1], (0, 1)), ValueError, "finite"),
        (lambda: ChangeOfVariables.from_betas([0.0, 1.0]), ValueError, "beta1 must be > 0"),
        (lambda: ChangeOfVariables(42, (0, 1)), TypeError, "callable"),
        (lambda: Reparametrized(Q, ChangeOfVariables.affine((0, 1), (0, 2))), ValueError,
         "must lie in the domain of param"),
        (lambda: Reparametrized(Q, lambda x: x), TypeError, "ChangeOfVariables"),
        (lambda: Reparametrized("q", ChangeOfVariables.affine((0, 1), (0, 1))), TypeError,
         "parametrization"),
        (lambda: ChangeOfVariables.affine((0, 1), (0, 1))(2.0), ValueError, "domain"),
        (lambda: faa_di_bruno(np.ones((3, 2)), np.ones(2)), ValueError, "same number"),
        (lambda: faa_di_bruno(np.ones((2, 2)), np.array([1.0, np.inf])), ValueError, "finite"),
    ],
)  # fmt: skip
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call()


def test_reparametrized_piecewise_curve_keeps_breakpoints_and_length():
    curve = PiecewiseBezier(
        [CUBIC.segments[0], np.array([[4.0, 1.0], [5.0, 2.0], [6.0, 0.0]])], knots=[0.0, 0.4, 1.0]
    )
    f = ChangeOfVariables.polynomial(_bernstein_cubic(0.2, 0.9), (0.0, 1.0), image=(0.0, 1.0))
    rp = Reparametrized(curve, f)
    np.testing.assert_allclose(f(rp.breakpoints), [0.0, 0.4, 1.0], atol=1e-14)
    assert dg.arc_length(rp) == pytest.approx(dg.arc_length(curve), rel=1e-12)
    s = np.linspace(0.0, dg.arc_length(curve), 9)
    np.testing.assert_allclose(
        dg.point_at_arc_length(rp, s), dg.point_at_arc_length(curve, s), atol=1e-11
    )
