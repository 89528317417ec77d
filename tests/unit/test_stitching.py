"""Tests of course_lib.constructions.stitching (seed 000 §8, eq. (9)-(12)).

References: the Beta-constraints typed in from seed 000 eq. (7.1)-(7.2) applied to
Bézier end derivatives; a sympy expansion of eq. (12.1)-(12.5) against eq. (11b);
course_lib.geometry.continuity for "exactly G1 / G2".
"""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import assert_g_order, check_joint
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.stitching import (
    farin_boehm,
    farin_boehm_gamma,
    g1_stitch,
    g1_stitch_points,
    g2_stitch,
    g2_stitch_points,
)

pos = st.floats(0.1, 5.0)
real = st.floats(-5.0, 5.0)


def test_farin_boehm_factorizes_eq_11b_symbolically():
    """Eq. (12.1)-(12.5) as transcribed expand to eq. (11b), and (11b) to (11a)."""
    sp = pytest.importorskip("sympy")
    b1, b2, d = sp.symbols("beta1 beta2 d", positive=True)
    Vm2, Vm1, Vd = sp.symbols("V_dm2 V_dm1 V_d")  # one coordinate suffices (affine)
    g = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))
    W0 = Vd
    W1 = W0 + b1 * (Vd - Vm1)
    T = Vm1 + b1**2 * g * (Vm1 - Vm2)
    W2 = W1 + (W1 - T) / g
    eq11b = (
        b1**2 * Vm2
        - (2 * b1**2 + 2 * b1 + b2 / (d - 1)) * Vm1
        + (b1**2 + 2 * b1 + b2 / (d - 1) + 1) * Vd
    )
    eq11a = 2 * W1 - W0 + b1**2 * (Vm2 - 2 * Vm1 + Vd) + b2 * (Vd - Vm1) / (d - 1)
    assert sp.cancel(W2 - eq11b) == 0
    assert sp.cancel(eq11a - eq11b) == 0
    # and a wrong variant one might read from the OCR, W2 = W1 + gamma (W1 - T), is not it
    assert sp.cancel(W1 + g * (W1 - T) - eq11b) != 0


@settings(max_examples=25, deadline=None)
@given(d=st.integers(2, 6), b1=pos, b2=real, seed=st.integers(0, 10**6))
def test_g2_stitch_satisfies_beta_constraints(d, b1, b2, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(d + 1, 2))
    rest = rng.normal(size=(d - 2, 2))
    c = g2_stitch(V, b1, b2, rest)
    check_joint(c, 0, [b1, b2])
    np.testing.assert_allclose(c.info["W012"], g2_stitch_points(V, b1, b2))
    if "T" in c.info and abs(c.info["gamma"]) < 1e6:  # W2 = W1 + (W1 - T) / gamma
        W = c.info["W012"]
        np.testing.assert_allclose(
            W[2], W[1] + (W[1] - c.info["T"]) / c.info["gamma"], atol=1e-8 * (1 + abs(W).max())
        )


@settings(max_examples=25, deadline=None)
@given(d=st.integers(2, 6), b1=pos, b2=real, seed=st.integers(0, 10**6))
def test_farin_boehm_equals_eq_11a(d, b1, b2, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(d + 1, 3))
    den = b2 + b1 * (d - 1) * (1 + b1)
    if abs(den) < 1e-3:
        return
    fb = farin_boehm(V[-3:], b1, b2, d)
    np.testing.assert_allclose(fb.W, g2_stitch_points(V, b1, b2), atol=1e-8 * (1 + abs(1 / den)))
    # T lies on the line V_{d-2} V_{d-1}, and T, W1, W2 are collinear (Figure 8)
    cross = np.cross(fb.T - V[-2], V[-2] - V[-3])
    assert np.linalg.norm(cross) <= 1e-8 * (1 + np.linalg.norm(fb.T))
    assert np.linalg.norm(np.cross(fb.W[1] - fb.T, fb.W[2] - fb.W[1])) <= 1e-7 * (
        1 + np.linalg.norm(fb.T) ** 2
    )


@settings(max_examples=25, deadline=None)
@given(d=st.integers(2, 5), b1=pos, seed=st.integers(0, 10**6))
def test_g1_stitch(d, b1, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(d + 1, 2))
    c = g1_stitch(V, b1, rng.normal(size=(d - 1, 2)))
    check_joint(c, 0, [b1])
    W = g1_stitch_points(V, b1)
    # eq. (9) geometrically: |W0 W1| = beta1 |V_{d-1} V_d|, same direction
    np.testing.assert_allclose(W[1] - W[0], b1 * (V[-1] - V[-2]))


def test_exact_orders_with_continuity_module():
    V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])
    rest = np.array([[7.0, 3.0], [8.0, -1.0]])
    assert_g_order(g1_stitch(V, 1.7, rest), 1)
    assert_g_order(g2_stitch(V, 0.6, -1.3, rest[1:]), 2)


def test_g2_is_c2_for_beta_1_0():
    V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])
    c = g2_stitch(V, 1.0, 0.0, [[5.0, 5.0]])
    q, r = c.end_derivatives(0, 1, 2), c.end_derivatives(1, 0, 2)
    np.testing.assert_allclose(r, q, atol=1e-12)


def test_gamma_closed_form():
    # d = 3, beta1 = 1, beta2 = 0: gamma = 2*2 / (0 + 1*2*2) = 1 (uniform B-spline thirds)
    assert farin_boehm_gamma(1.0, 0.0, 3) == pytest.approx(1.0)
    assert farin_boehm_gamma(2.0, 1.0, 4) == pytest.approx(3 * 3 / (1 + 2 * 3 * 3))


V3 = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: g1_stitch_points(V3, 0.0), "beta1 must be > 0"),
        (lambda: g1_stitch_points(V3, -1.0), "beta1 must be > 0"),
        (lambda: g2_stitch_points(V3, np.nan, 0.0), "beta1 must be finite"),
        (lambda: g2_stitch_points(V3, 1.0, np.inf), "beta2 must be finite"),
        (lambda: farin_boehm(V3[-3:], 1.0, -4.0, 3), "beta2 = -4.0 makes gamma undefined"),
        (lambda: farin_boehm_gamma(1.0, -4.0, 3, joint=2), "at joint 2"),
        (lambda: farin_boehm(V3[-3:], -1.0, 0.0, 3), "beta1 must be > 0"),
        (lambda: farin_boehm(V3, 1.0, 0.0, 3), "exactly 3 points"),
        (lambda: g1_stitch_points(V3[:1], 1.0), "at least 2 points"),
        (lambda: g1_stitch_points([[0, 0], [1, 1], [1, 1]], 1.0), "coincide"),
        (lambda: g1_stitch(V3, 1.0, [[1.0, 1.0]]), r"W_rest must have shape \(2, 2\)"),
        (lambda: g2_stitch(V3, 1.0, 0.0), "W_rest must give the 1 free"),
        (lambda: g2_stitch(V3, 1.0, 0.0, [[np.nan, 0.0]]), "finite"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_quadratic_g2_needs_no_free_points():
    V = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])
    c = g2_stitch(V, 0.8, 0.5)
    check_joint(c, 0, [0.8, 0.5])
    assert c.degrees == (2, 2)
