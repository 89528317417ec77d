"""Tests of course_lib.geometry.continuity (seed 000 §3-6).

Joints are built by hand from Bézier end-derivative formulas (seed 000 eq. (8.2)-(8.3),
and the cubic third derivative 6 (W3 - 3 W2 + 3 W1 - W0)) so that their continuity
order is known exactly; curvature vectors are cross-checked with
course_lib.geometry.differential_geometry on each side separately.  The three
characterizations must agree, and the G-order must survive random
orientation-preserving reparametrization (hypothesis).
"""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry import differential_geometry as dg
from course_lib.geometry.continuity import CHARACTERIZATIONS, curve_continuity, joint_continuity
from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized

V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])


def cubic_pair(betas, w3=None, V=V):
    """Left cubic V; right cubic W meeting it with the Beta-constraints up to len(betas) <= 3.

    Seed 000 eq. (7.1)-(7.3) with q^(k)(1) from the control points; W3 free if not fixed.
    """
    q1 = 3 * (V[3] - V[2])
    q2 = 6 * (V[3] - 2 * V[2] + V[1])
    q3 = 6 * (V[3] - 3 * V[2] + 3 * V[1] - V[0])
    b = list(betas) + [0.0] * (3 - len(betas))
    r1 = b[0] * q1
    r2 = b[0] ** 2 * q2 + b[1] * q1
    r3 = b[0] ** 3 * q3 + 3 * b[0] * b[1] * q2 + b[2] * q1
    W0 = V[3]
    W1 = W0 + r1 / 3
    if len(betas) >= 2:
        W2 = r2 / 6 - W0 + 2 * W1
    else:
        W2 = W1 + np.array([1.3, -0.7])
    if len(betas) >= 3:
        W3 = r3 / 6 + 3 * W2 - 3 * W1 + W0
    else:
        W3 = W2 + np.array([1.0, 1.7]) if w3 is None else w3
    return PiecewiseBezier([V]), PiecewiseBezier([np.array([W0, W1, W2, W3])])


def check_agree(rep, g):
    assert rep.g_order == g
    assert dict(rep.g_order_by) == dict.fromkeys(CHARACTERIZATIONS, g)
    assert rep.characterizations_agree


def test_seed_000_example_1_is_g_not_c():
    q = PiecewiseBezier([np.array([[0.0, 0.0], [2.0, 1.0]])])  # (2u, u)
    r = PiecewiseBezier([np.array([[2.0, 1.0], [4.0, 2.0]])], knots=[0.0, 0.5])  # (4t+2, 2t+1)
    rep = joint_continuity(q, r, max_order=3)
    assert rep.c_order == 0 and rep.gap == 0.0
    check_agree(rep, 3)  # lines: G^n for every n (capped at max_order)
    assert rep.betas[0] == pytest.approx(2.0)  # r'(0) = 2 q'(1)
    assert rep.tangent_angle == pytest.approx(0.0, abs=1e-12)
    q_tilde = PiecewiseBezier([np.array([[0.0, 0.0], [2.0, 1.0]])], knots=[0.0, 0.5])
    assert joint_continuity(q_tilde, r, max_order=3).c_order == 3  # Example 2: C1 (and more)


@pytest.mark.parametrize("max_order", [2, 3, 4])
def test_g2_not_g3_cubics(max_order):
    q, r = cubic_pair([1.5, 0.7])
    rep = joint_continuity(q, r, max_order=max_order)
    check_agree(rep, 2)
    assert rep.c_order == 0  # β1 != 1
    np.testing.assert_allclose(rep.betas[:2], [1.5, 0.7], rtol=1e-12)
    # independent check of G2 (seed 000 Theorem 1): same unit tangent and curvature vector
    np.testing.assert_allclose(dg.unit_tangent(q, 1.0), dg.unit_tangent(r, 0.0), atol=1e-14)
    np.testing.assert_allclose(dg.curvature_vector(q, 1.0), dg.curvature_vector(r, 0.0), atol=1e-13)
    assert rep.curvature_jump == pytest.approx(0.0, abs=1e-12)
    if max_order >= 3:
        assert rep.residuals[2] > 0.1


def test_g3_not_g4_cubics():
    q, r = cubic_pair([0.8, -1.2, 2.5])
    rep = joint_continuity(q, r, max_order=4)
    check_agree(rep, 3)
    np.testing.assert_allclose(rep.betas[:3], [0.8, -1.2, 2.5], rtol=1e-10)


def test_g1_not_g2_and_g0_not_g1():
    q, r = cubic_pair([2.0])
    rep = joint_continuity(q, r)
    check_agree(rep, 1)
    assert rep.curvature_jump > 0.01
    kink = PiecewiseBezier([np.array([V[3], V[3] + [1.0, 1.0], [6.0, 0.0], [7.0, 1.0]])])
    rep = joint_continuity(q, kink)
    check_agree(rep, 0)
    assert rep.c_order == 0
    q1 = V[3] - V[2]
    expected = np.degrees(np.arccos(q1 @ [1.0, 1.0] / (np.linalg.norm(q1) * np.sqrt(2))))
    assert rep.tangent_angle == pytest.approx(expected)
    # a cusp-like reversal: r' = -q' (β1 = -1 would be needed): not G1
    back = PiecewiseBezier([np.array([V[3], V[3] - (V[3] - V[2]), [3.0, 3.0], [2.0, 5.0]])])
    rep = joint_continuity(q, back)
    check_agree(rep, 0)
    assert rep.betas[0] < 0 and rep.tangent_angle == pytest.approx(180.0)


def test_gap_gives_minus_one():
    q, r = cubic_pair([1.0, 0.0])
    moved = PiecewiseBezier([r.segments[0] + [0.0, 0.1]])
    rep = joint_continuity(q, moved)
    assert rep.c_order == -1 and rep.g_order == -1 and rep.betas == ()
    assert set(rep.g_order_by.values()) == {-1}
    assert rep.gap == pytest.approx(0.1)
    assert "do not meet" in str(rep)


def test_knots_change_c_order_not_g_order():
    """C1 with uniform knots; unequal knots destroy C1 but not G1 (seed 004 §19.7)."""
    W1 = 2 * V[3] - V[2]  # C1 in the uniform global parameter
    seg2 = np.array([V[3], W1, [7.0, 3.0], [8.0, 0.0]])
    uniform = PiecewiseBezier([V, seg2])
    (rep,) = curve_continuity(uniform)
    assert rep.c_order == 1 and rep.index == 0
    check_agree(rep, 1)
    (rep,) = curve_continuity(uniform.with_knots([0.0, 1.0, 3.0]))
    assert rep.c_order == 0
    check_agree(rep, 1)
    # with knots [0, 1, 3] the C1 joint needs W1 = V3 + (h1/h0)(V3 - V2) (global derivatives)
    seg2b = np.array([V[3], V[3] + 2.0 * (V[3] - V[2]), [9.0, 3.0], [10.0, 0.0]])
    (rep,) = curve_continuity(PiecewiseBezier([V, seg2b], knots=[0.0, 1.0, 3.0]))
    assert rep.c_order == 1


def test_circle_arcs_at_different_speeds_are_g_infinity():
    def arc(w, phase, dom):
        return ParametricCurve(
            [lambda t, k=k: np.stack([w**k * np.cos(w * t + phase + k * np.pi / 2),
                                      w**k * np.sin(w * t + phase + k * np.pi / 2)], -1)
             for k in range(6)], dom)  # fmt: skip

    q = arc(1.0, 0.0, (0.0, 1.0))
    r = arc(3.0, 1.0, (0.0, 0.5))  # starts at angle 1 = where q ends, three times as fast
    rep = joint_continuity(q, r, max_order=5)
    assert rep.c_order == 0
    check_agree(rep, 5)
    np.testing.assert_allclose(rep.betas[:2], [3.0, 0.0], atol=1e-12)


def test_space_curves():
    V3 = np.column_stack([V, [0.0, 1.0, -1.0, 0.5]])
    q = PiecewiseBezier([V3])
    d = np.array([1.0, -0.5, 0.3])
    r = PiecewiseBezier(
        [np.array([V3[3], V3[3] + 0.5 * (V3[3] - V3[2]), V3[3] + d, V3[3] + 2 * d])]
    )
    rep = joint_continuity(q, r)
    check_agree(rep, 1)


def _random_change(b1, b2):
    # Bernstein cubic with 0 < b1 < b2 < 1: orientation preserving [0, 1] -> [0, 1]
    return ChangeOfVariables.polynomial(
        [0.0, 3 * b1, -6 * b1 + 3 * b2, 3 * b1 - 3 * b2 + 1], (0.0, 1.0), image=(0.0, 1.0)
    )


pairs = (
    st.lists(st.floats(0.05, 0.95), min_size=2, max_size=2)
    .map(sorted)
    .filter(lambda b: b[1] - b[0] > 0.02)
)


@settings(max_examples=30, deadline=None)
@given(fq=pairs, fr=pairs, which=st.sampled_from([(1.5, 0.7), (0.8, -1.2, 2.5), (2.0,)]))
def test_g_order_invariant_under_reparametrization(fq, fr, which):
    q, r = cubic_pair(list(which))
    expected = len(which)
    rep0 = joint_continuity(q, r, max_order=4)
    check_agree(rep0, expected)
    rq = Reparametrized(q, _random_change(*fq))
    rr = Reparametrized(r, _random_change(*fr))
    for a, b in ((rq, r), (q, rr), (rq, rr)):
        check_agree(joint_continuity(a, b, max_order=4), expected)


def test_report_text_html_and_frozen():
    q, r = cubic_pair([1.5, 0.7])
    (rep,) = curve_continuity(PiecewiseBezier([q.segments[0], r.segments[0]]), max_order=3)
    text = str(rep)
    assert text.startswith("Joint 0 at (4, 1): G2, C0")
    assert "β1 = 1.5" in text and "β2 = 0.7" in text
    assert "tangent angle 0°" in text
    html = rep._repr_html_()
    assert "<table" in html and "G2" in html and "Joint 0" in html
    with pytest.raises(dataclasses.FrozenInstanceError):
        rep.g_order = 5


def test_max_order_cap_is_reported():
    line = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 0.0]]), np.array([[1.0, 0.0], [3.0, 0.0]])])
    (rep,) = curve_continuity(line, max_order=2)
    assert rep.g_order == 2 and rep.c_order == 0
    assert "G2 (or higher)" in str(rep)


CUSP_R = PiecewiseBezier([np.array([V[3], V[3], [6.0, 0.0], [7.0, 1.0]])])


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: joint_continuity(PiecewiseBezier([V]), CUSP_R), ValueError,
         "r is not regular at the joint"),
        (lambda: curve_continuity(PiecewiseBezier([V, CUSP_R.segments[0]])), ValueError,
         "at joint 0: .*not regular"),
        (lambda: joint_continuity(PiecewiseBezier([V]), PiecewiseBezier([V]), max_order=0),
         ValueError, "max_order must be >= 1"),
        (lambda: joint_continuity(PiecewiseBezier([V]), PiecewiseBezier([V]), rtol=-1.0),
         ValueError, "rtol and atol must be >= 0"),
        (lambda: joint_continuity(PiecewiseBezier([V]), "r"), TypeError, "parametrization"),
        (lambda: joint_continuity(PiecewiseBezier([V]),
                                  PiecewiseBezier([np.column_stack([V, V[:, 0]])])),
         ValueError, "same dimension"),
        (lambda: curve_continuity([V, V]), TypeError, "PiecewiseBezier"),
    ],
)  # fmt: skip
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call()


@pytest.mark.parametrize("scale", [1e-6, 1.0, 1e6])
@pytest.mark.parametrize("knots", [None, [0.0, 1e-3, 3e-3], [0.0, 100.0, 101.0]])
def test_verdict_independent_of_units_and_knots(scale, knots):
    q, r = cubic_pair([1.5, 0.7])
    (rep,) = curve_continuity(
        PiecewiseBezier([q.segments[0] * scale, r.segments[0] * scale], knots)
    )
    check_agree(rep, 2)


def test_knot_ratio_equal_to_beta1_gives_c1():
    # local r'(0) = β1 q'(1); in the global parameter the derivatives are divided by the
    # interval lengths h0, h1, so the joint is C1 exactly when h1 / h0 = β1 (seed 004 §19.7)
    q, r = cubic_pair([2.0])
    (rep,) = curve_continuity(PiecewiseBezier([q.segments[0], r.segments[0]], [0.0, 1.0, 3.0]))
    assert rep.c_order == 1
    check_agree(rep, 1)


def test_report_prints_rounding_noise_as_zero_but_keeps_real_values():
    from course_lib.geometry.continuity import DISPLAY_ZERO, JointReport

    rep = JointReport(
        index=0,
        point=(1.0, 2e-16),
        gap=3e-17,
        tangent_angle=4.577e-14,
        curvature_jump=0.25,
        c_order=1,
        g_order=2,
        betas=(1.5, 1.599e-15),
        residuals=(1e-16, 2e-3),
        g_order_by={"reparametrization": 2, "beta_constraints": 2, "arc_length": 2},
        max_order=4,
    )
    text, html = str(rep), rep._repr_html_()
    for noise in ("e-14", "e-15", "e-16", "e-17"):
        assert noise not in text and noise not in html
    assert "tangent angle 0°" in text and "β2 = 0" in text
    assert "curvature jump 0.25" in text and "0.002" in text and "β1 = 1.5" in text
    assert DISPLAY_ZERO <= 1e-9
