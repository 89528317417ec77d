"""Tests of course_lib.constructions.beta_splines (seed 001 Example 2.1, G^n Beta-splines).

References: the explicit Beta-constraints of seed 000 eq. (7.1)-(7.4) at every joint;
scipy.interpolate.BSpline for β1 = 1, β_{>1} = 0; an exact sympy solve of the same
linear system at rational β's; the inverse-function derivatives (1/β1, -β2/β1³,
(3β2² - β1β3)/β1⁵) for the seed's eq. (2.10); course_lib.geometry.continuity for "exactly G^n".
"""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import assert_g_order, check_joint
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline

from course_lib.constructions.beta_splines import (
    BetaSplineBasis,
    beta_spline,
    gn_beta_spline_basis,
    quartic_beta_spline,
)
from course_lib.constructions.beta_splines.degree_n import _solve


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_uniform_bspline_reduction(n):
    d = n + 1
    basis = gn_beta_spline_basis(n, (1.0,) + (0.0,) * (n - 1))
    t = np.linspace(0, d + 1, 4 * (d + 1) + 1)
    ref = BSpline.basis_element(np.arange(d + 2, dtype=float), extrapolate=False)(t)
    np.testing.assert_allclose(basis.bump(t), np.nan_to_num(ref), atol=1e-12)
    rng = np.random.default_rng(n)
    V = rng.normal(size=(d + 4, 2))
    c = beta_spline(V, (1.0,) + (0.0,) * (n - 1), n)
    tt = np.linspace(0, c.n_segments, 31)
    want = BSpline(np.arange(V.shape[0] + d + 1, dtype=float), V, d)(tt + d)
    np.testing.assert_allclose(c.evaluate(tt), want, atol=1e-11)


betas3 = st.tuples(st.floats(0.3, 3.0), st.floats(-2.0, 20.0), st.floats(-5.0, 5.0))


@settings(max_examples=20, deadline=None)
@given(b=betas3, seed=st.integers(0, 10**6))
def test_quartic_g3_beta_constraints_at_every_joint(b, seed):
    V = np.random.default_rng(seed).normal(size=(9, 2))
    c = quartic_beta_spline(V, *b)
    assert c.degrees == (4,) * 5
    for j in range(c.n_joints):
        check_joint(c, j, list(b), rtol=1e-8)


@settings(max_examples=20, deadline=None)
@given(b=betas3, u=st.floats(0.0, 1.0))
def test_partition_of_unity(b, u):
    assert gn_beta_spline_basis(3, b).evaluate(u).sum() == pytest.approx(1.0, abs=1e-10)


@settings(max_examples=20, deadline=None)
@given(b=betas3, seed=st.integers(0, 10**6))
def test_affine_invariance(b, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(7, 3))
    A, s = rng.normal(size=(3, 3)), rng.normal(size=3)
    c1 = beta_spline(V @ A.T + s, b, 3)
    c2 = beta_spline(V, b, 3).transformed(A, s)
    for x, y in zip(c1.segments, c2.segments, strict=True):
        np.testing.assert_allclose(x, y, atol=1e-9)


def test_local_support():
    """Moving V_k changes only the d + 1 segments that use it."""
    rng = np.random.default_rng(3)
    V = rng.normal(size=(10, 2))
    c0 = beta_spline(V, (1.3, 2.0, -0.5), 3)
    V2 = V.copy()
    V2[5] += 1.0
    c1 = beta_spline(V2, (1.3, 2.0, -0.5), 3)
    changed = [not np.allclose(a, b) for a, b in zip(c0.segments, c1.segments, strict=True)]
    assert changed == [False, True, True, True, True, True]  # segments 1..5 use V_5


def test_matches_exact_sympy_solution():
    """Same linear system set up independently (sympy diff, eq. (7.1)-(7.3) typed in)."""
    sp = pytest.importorskip("sympy")
    b1, b2, b3 = sp.Rational(3, 2), sp.Rational(5, 1), sp.Rational(-1, 3)
    u = sp.Symbol("u")
    cs = sp.symbols("c0:25")
    polys = [
        sum(cs[5 * k + r] * sp.binomial(4, r) * u**r * (1 - u) ** (4 - r) for r in range(5))
        for k in range(5)
    ]
    zero = sp.Integer(0)

    def derivs(p, at):
        out = []
        for _ in range(4):
            out.append(p.subs(u, at))
            p = sp.diff(p, u)
        return out

    D0 = [derivs(p, 0) for p in polys]
    D1 = [derivs(p, 1) for p in polys]
    eqs = []
    for k in range(6):  # V_{j+k}: weight polys[k] on segment j, polys[k-1] on segment j+1
        right = D0[k - 1] if k >= 1 else [zero] * 4
        left = D1[k] if k <= 4 else [zero] * 4
        cr = [
            left[0],
            b1 * left[1],
            b1**2 * left[2] + b2 * left[1],
            b1**3 * left[3] + 3 * b1 * b2 * left[2] + b3 * left[1],
        ]
        eqs += [sp.expand(r - c) for r, c in zip(right, cr, strict=True)]
    eqs.append(sum(p.subs(u, 0) for p in polys) - 1)
    sol = list(sp.linsolve(sp.linear_eq_to_matrix(eqs, cs), cs))
    assert len(sol) == 1 and not any(x.free_symbols for x in sol[0])  # unique
    exact = np.array([[float(sol[0][5 * k + r]) for r in range(5)] for k in range(5)])
    num = gn_beta_spline_basis(3, (1.5, 5.0, -1 / 3)).coefficients
    np.testing.assert_allclose(num, exact, atol=1e-11)


@pytest.mark.parametrize("b", [(1.0, 0.0, 0.0), (1.3, 0.7, -0.4), (0.6, 3.0, 1.0)])
def test_exactly_g3_not_g4(b):
    V = np.random.default_rng(7).normal(size=(9, 2))
    assert_g_order(quartic_beta_spline(V, *b), 3)


def test_gn_general_n4():
    b = (1.2, 0.5, -0.3, 2.0)
    V = np.random.default_rng(8).normal(size=(9, 3))
    c = beta_spline(V, b, 4)
    for j in range(c.n_joints):
        check_joint(c, j, list(b), rtol=1e-7)
    assert_g_order(c, 4)


def test_seed_eq_2_10_gives_inverse_betas():
    """Seed 001 eq. (2.10) as printed = the constraints with the inverse map's betas."""
    b1, b2, b3 = 1.6, 0.8, -0.5
    inv = (1 / b1, -b2 / b1**3, (3 * b2**2 - b1 * b3) / b1**5)
    seed_version = _solve(3, (b1, b2, b3), True)
    np.testing.assert_allclose(seed_version, _solve(3, inv), atol=1e-10)
    assert not np.allclose(seed_version, _solve(3, (b1, b2, b3)), atol=1e-3)


@pytest.mark.parametrize("b2", [0.0, 20.0, 100.0])
def test_seed_001_figure_5_parameters(b2):
    """beta1 = 1, beta3 = 0, beta2 in {0, 20, 100}: well defined, G3, convex weights."""
    basis = gn_beta_spline_basis(3, (1.0, b2, 0.0))
    t = np.linspace(0, 5, 101)
    assert basis.bump(t).min() >= -1e-12
    V = np.array([[0, 0], [1, 3], [3, 4], [5, 1], [7, 3], [8, 0], [10, 2]], float)
    c = quartic_beta_spline(V, 1.0, b2, 0.0)
    for j in range(c.n_joints):
        check_joint(c, j, [1.0, b2, 0.0], rtol=1e-8)
    assert isinstance(basis, BetaSplineBasis)


def test_figure_5_curves_differ_only_through_beta2():
    V = np.array([[0, 0], [1, 3], [3, 4], [5, 1], [7, 3], [8, 0], [10, 2]], float)
    t = np.linspace(0, 2, 21)
    pts = [quartic_beta_spline(V, 1.0, b2, 0.0).evaluate(t) for b2 in (0.0, 20.0, 100.0)]
    assert np.abs(pts[0] - pts[1]).max() > 0.1 and np.abs(pts[1] - pts[2]).max() > 0.05


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: gn_beta_spline_basis(3, (1.0, 0.0)), r"sequence \(beta1, ..., beta3\) of 3"),
        (lambda: gn_beta_spline_basis(3, (0.0, 0.0, 0.0)), "beta1 must be > 0"),
        (lambda: gn_beta_spline_basis(3, (-1.0, 0.0, 0.0)), "beta1 must be > 0"),
        (lambda: gn_beta_spline_basis(3, (1.0, np.nan, 0.0)), "finite"),
        (lambda: gn_beta_spline_basis(0, (1.0,)), "n must be >= 1"),
        (lambda: beta_spline(np.zeros((4, 2)), (1.0, 0.0, 0.0), 3), "at least 5 points"),
        (
            lambda: beta_spline(
                [[0, 0], [1, 0], [1, 0], [1, 0], [1, 0], [1, 0], [2, 1]], (1.0, 0.0, 0.0), 3
            ),
            "tangent vanishes at joint",
        ),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("betas", [(1.0, -4.0, 0.0), (0.5, 0.0, -39.375)])
def test_singular_quartic_shape_parameters_are_refused(betas):
    # Independent derivation (sympy, notebook 07's blending equations): the quartic basis is
    # unique unless δ = 6β1⁶ + 18β1⁵ + 30β1⁴ + 36β1³ + 30β1² + 18β1 + 6
    #                   + 6(1 + β1)³β2 + 3β1β2² + (1 − β1²)β3 vanishes.
    # (1, -4, 0): δ = 144 - 192 + 48 = 0;  (1/2, 0, -39.375): δ = 29.53125 - 0.75 * 39.375 = 0.
    b1, b2, b3 = betas
    delta = (
        6 * b1**6
        + 18 * b1**5
        + 30 * b1**4
        + 36 * b1**3
        + 30 * b1**2
        + 18 * b1
        + 6
        + 6 * (1 + b1) ** 3 * b2
        + 3 * b1 * b2**2
        + (1 - b1**2) * b3
    )
    assert abs(delta) < 1e-12
    with pytest.raises(ValueError, match="more than one G\\^3 basis"):
        gn_beta_spline_basis(3, betas)
    gn_beta_spline_basis(3, (b1, b2 + 0.5, b3))  # nearby values are fine
