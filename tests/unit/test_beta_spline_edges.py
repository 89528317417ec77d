"""The cubic Beta-spline at the edges of its parameter space (issue 14).

References, all independent of the construction under test:

* Barsky's closed form of the uniformly shaped cubic Beta-spline (B. A. Barsky, *The
  Beta-spline*, 1981; Bartels-Beatty-Barsky 1987, ch. 13), typed in below and first
  checked *symbolically* with sympy (partition of unity, and the Beta-constraints of seed
  000 eq. (7.1)-(7.2) between consecutive segments), then compared numerically.
* The seed's own construction (leg ratio γ_i : 1 : β1² γ_{i+1}, γ from eq. (12.1)) in exact
  sympy arithmetic, with the *limit* taken where γ has its pole.
* The Beta-constraints typed in from seed 000 eq. (7.1)-(7.2) (``_spline_checks``).
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from _spline_checks import check_joint
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from course_lib.constructions.beta_splines import cubic_beta_spline, design_beta_spline
from course_lib.constructions.stitching import farin_boehm, g2_stitch_points

u, B1, B2 = sp.symbols("u beta1 beta2")
DELTA = 2 * B1**3 + 4 * B1**2 + 4 * B1 + B2 + 2
BARSKY = [  # b_{-2}, b_{-1}, b_0, b_1 (weights of V_k .. V_{k+3} on segment k)
    2 * B1**3 * (1 - u) ** 3 / DELTA,
    (
        2 * B1**3 * u * (u**2 - 3 * u + 3)
        + 2 * B1**2 * (u**3 - 3 * u**2 + 2)
        + 2 * B1 * (u**3 - 3 * u + 2)
        + B2 * (2 * u**3 - 3 * u**2 + 1)
    )
    / DELTA,
    (
        2 * B1**2 * u**2 * (-u + 3)
        + 2 * B1 * u * (-(u**2) + 3)
        + B2 * u**2 * (-2 * u + 3)
        + 2 * (-(u**3) + 1)
    )
    / DELTA,
    2 * u**3 / DELTA,
]
_BARSKY_NUM = sp.lambdify((u, B1, B2), BARSKY, "numpy")

V7 = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5], [6.0, 1.0], [7.0, 3.0], [9, 2]])


def test_barsky_closed_form_is_a_g2_partition_of_unity_symbolically():
    assert sp.simplify(sum(BARSKY) - 1) == 0
    # the weight of V_{k+s} on segment k is BARSKY[s + 2]; on segment k + 1 it is BARSKY[s + 1]
    padded = [sp.Integer(0), *BARSKY, sp.Integer(0)]
    for s in range(-2, 3):
        left, right = padded[s + 3], padded[s + 2]
        q = [sp.diff(left, u, k).subs(u, 1) for k in range(3)]
        r = [sp.diff(right, u, k).subs(u, 0) for k in range(3)]
        assert sp.simplify(r[0] - q[0]) == 0
        assert sp.simplify(r[1] - B1 * q[1]) == 0  # seed 000 eq. (7.1)
        assert sp.simplify(r[2] - (B1**2 * q[2] + B2 * q[1])) == 0  # eq. (7.2)


def _barsky_curve(V, b1, b2, uu):
    W = np.array([np.broadcast_to(w, uu.shape) for w in _BARSKY_NUM(uu, b1, b2)])  # (4, m)
    return np.stack([W.T @ V[k : k + 4] for k in range(V.shape[0] - 3)])


def _our_curve(c, uu):
    return np.stack([c.segment_curve(k).evaluate(uu) for k in range(c.n_segments)])


@pytest.mark.parametrize(("b1", "b2"), [(1.0, -4.0), (0.5, -1.5), (2.0, -12.0), (1.0, 0.0)])
def test_gamma_undefined_globally_matches_barsky(b1, b2):
    uu = np.linspace(0, 1, 9)
    c = cubic_beta_spline(V7, b1, b2)
    np.testing.assert_allclose(_our_curve(c, uu), _barsky_curve(V7, b1, b2, uu), atol=1e-12)
    assert np.all(np.isinf(c.info["gamma"])) == (b2 == -2 * b1 * (1 + b1))
    for j in range(c.n_joints):
        check_joint(c, j, [b1, b2])


@settings(max_examples=40, deadline=None)
@given(b1=st.floats(0.05, 20.0), b2=st.floats(-60.0, 60.0))
def test_global_parameters_match_barsky(b1, b2):
    delta = 2 * b1**3 + 4 * b1**2 + 4 * b1 + b2 + 2
    assume(abs(delta) > 1e-2 * (1 + b1**3 + abs(b2)))  # Barsky's own pole
    uu = np.linspace(0, 1, 7)
    ref = _barsky_curve(V7, b1, b2, uu)
    got = _our_curve(cubic_beta_spline(V7, b1, b2), uu)
    np.testing.assert_allclose(got, ref, atol=1e-9 * (1 + np.abs(ref).max()))


def _seed_limit_segments(V, b1, b2_sym_at, j):
    """Seed construction with exact rationals, β2 at vertex j -> its pole (sympy limit)."""
    n = len(b1)
    b2 = [sp.Rational(x) for x in b2_sym_at]
    b2[j] = B2
    g = [2 * (1 + b1[i]) / (b2[i] + 2 * b1[i] * (1 + b1[i])) for i in range(n)]
    P = [sp.Matrix([sp.Rational(x) for x in p]) for p in V]
    W1, W2 = [], []
    for i in range(n - 1):
        far = b1[i + 1] ** 2 * g[i + 1]
        S = 1 + g[i] + far
        W1.append(((1 + far) * P[i] + g[i] * P[i + 1]) / S)
        W2.append((far * P[i] + (1 + g[i]) * P[i + 1]) / S)
    pole = -2 * b1[j] * (1 + b1[j])
    W1 = [w.applyfunc(lambda e: sp.limit(e, B2, pole)) for w in W1]
    W2 = [w.applyfunc(lambda e: sp.limit(e, B2, pole)) for w in W2]
    J = [(b1[i] * W2[i - 1] + W1[i]) / (1 + b1[i]) for i in range(1, n - 1)]
    segs = [[J[k], W1[k + 1], W2[k + 1], J[k + 1]] for k in range(n - 3)]
    return np.array([[[float(x) for x in p] for p in s] for s in segs])


@pytest.mark.parametrize(("j", "b1j"), [(3, sp.Integer(1)), (2, sp.Rational(1, 2))])
def test_gamma_undefined_at_one_vertex_is_the_seed_limit(j, b1j):
    b1 = [sp.Integer(1), sp.Rational(3, 2), sp.Integer(1), sp.Rational(4, 5), 2, 1, 1]
    b1[j] = b1j
    b2 = [0, 1, 0, 2, -1, 0, 0]
    ref = _seed_limit_segments(V7, b1, b2, j)
    b1f = [float(x) for x in b1]
    b2f = [float(x) for x in b2]
    b2f[j] = -2 * b1f[j] * (1 + b1f[j])
    c = cubic_beta_spline(V7, b1f, b2f)
    np.testing.assert_allclose(np.array(c.segments), ref, atol=1e-12)
    assert np.isinf(c.info["gamma"][j])
    for k in range(c.n_joints):
        check_joint(c, k, [b1f[k + 2], b2f[k + 2]])
    # the slider crosses the value: both sides converge to it
    for h in (1e-7, -1e-7):
        near = list(b2f)
        near[j] += h
        d = np.array(cubic_beta_spline(V7, b1f, near).segments) - ref
        assert np.abs(d).max() < 1e-5


@pytest.mark.parametrize("b1", [1e-300, 1e-12, 1e8, 1e200, 1e300, 1.7e308])
@pytest.mark.parametrize("b2", [0.0, 3.0])
def test_extreme_beta1_is_finite_and_near_its_limit(b1, b2):
    c = cubic_beta_spline(V7, b1, b2)
    segs = np.array(c.segments)
    assert np.all(np.isfinite(segs))
    # limits: β1 -> 0 puts W_{i,1} = W_{i,2} = V_{i+1} and J_i = V_{i+1};
    # β1 -> inf puts W_{i,1} = W_{i,2} = V_i and J_i = V_{i-1}
    if b1 < 1:
        if b2 != 0.0:  # the limit β1 -> 0 depends on β2; finite is the promise
            return
        W = np.stack([V7[2:6], V7[2:6], V7[2:6], V7[3:7]], axis=1)
    else:
        W = np.stack([V7[0:4], V7[1:5], V7[1:5], V7[1:5]], axis=1)
    np.testing.assert_allclose(segs, W, atol=1e-5 if b1 in (1e-12, 1e8) else 1e-12)


def test_farin_boehm_reports_T_at_infinity():
    V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
    fb = farin_boehm(V[-3:], 1.0, -4.0, 3, at_infinity="report")
    assert fb.T_at_infinity and fb.T is None and fb.gamma == np.inf
    np.testing.assert_allclose(fb.W, g2_stitch_points(V, 1.0, -4.0), atol=1e-12)
    assert not farin_boehm(V[-3:], 1.0, -3.0, 3).T_at_infinity


def _params(draw_b1, inv_gamma):
    b1 = np.array(draw_b1)
    ig = np.array(inv_gamma)
    return b1, 2 * (1 + b1) * (ig - b1)  # β2 from 1/γ = D / N


@settings(max_examples=40, deadline=None)
@given(
    b1=st.lists(st.floats(0.2, 5.0), min_size=7, max_size=7),
    inv_gamma=st.lists(
        st.one_of(st.floats(-4.0, -0.05), st.floats(0.05, 4.0)), min_size=7, max_size=7
    ),
    scale=st.sampled_from([1.0, 1e-150, 1e150, 3e-200, 3e200]),
)
def test_design_inverts_every_spline_including_negative_gamma(b1, inv_gamma, scale):
    b1, b2 = _params(b1, inv_gamma)
    try:
        c = cubic_beta_spline(V7 * scale, b1, b2)
    except ValueError as exc:  # Barsky's delta = 0 on a leg: no spline to invert
        assert "sum to zero" in str(exc)
        assume(False)
    d = design_beta_spline(V7 * scale, c.info["interior_points"])
    np.testing.assert_allclose(d.info["beta1_vertices"], b1[1:-1], rtol=1e-6)
    np.testing.assert_allclose(d.info["beta2_vertices"], b2[1:-1], rtol=1e-6, atol=1e-6)
    for x, y in zip(c.segments, d.segments, strict=True):
        np.testing.assert_allclose(x / scale, y / scale, atol=1e-7)


def test_design_negative_gamma_example_swaps_the_interior_vertices():
    c = cubic_beta_spline(V7, 1.0, -10.0)  # γ = 4 / (-10 + 4) < 0
    W = c.info["interior_points"]
    legs = V7[1:] - V7[:-1]
    s = (
        np.einsum("ikd,id->ik", W - V7[:-1, None], legs)
        / np.einsum("id,id->i", legs, legs)[:, None]
    )
    assert np.all(s[:, 0] > s[:, 1])  # W_{i,1} after W_{i,2}: the other order
    d = design_beta_spline(V7, W)
    np.testing.assert_allclose(d.info["beta2_vertices"], -10.0, rtol=1e-12)
    for j in range(d.n_joints):
        check_joint(d, j, [1.0, -10.0])


def test_design_at_gamma_infinite_says_why():
    c = cubic_beta_spline(V7, 1.0, -4.0)
    with pytest.raises(ValueError, match="gamma is infinite"):
        design_beta_spline(V7, c.info["interior_points"])


@pytest.mark.parametrize("b1", [1e-300, 1e-100, 1e100, 1e300])
def test_catmull_rom_extreme_beta1_is_finite_or_refused(b1):
    from course_lib.constructions.catmull_rom import catmull_rom

    c = catmull_rom(V7, b1)
    assert np.all(np.isfinite(np.array(c.segments)))
    if b1 == 1e300:
        with pytest.raises(ValueError, match="float range"):
            catmull_rom(V7 * 1e10, b1)


@settings(max_examples=40, deadline=None)
@given(
    e1=st.floats(-300.0, 300.0),
    b2=st.one_of(st.floats(-1e6, 1e6), st.sampled_from([0.0, -4.0, -1.5])),
    local=st.booleans(),
)
def test_any_beta1_gives_finite_points_or_a_named_error(e1, b2, local):
    """β1 = 10^e1 anywhere in the float range: finite control points, or the one named
    ValueError of a true pole (Barsky's delta = 0) -- never NaN or inf."""
    b1 = 10.0**e1
    b1v = np.array([1.0, 1.0, b1, b1, b1, 1.0, 1.0]) if local else b1
    b2v = np.array([0.0, 0.0, b2, b2, b2, 0.0, 0.0]) if local else b2
    try:
        c = cubic_beta_spline(V7, b1v, b2v)
    except ValueError as exc:
        assert "sum to zero" in str(exc) or "no limit" in str(exc)
        return
    assert np.all(np.isfinite(np.array(c.segments)))
