"""Tests of course_lib.sources.seed_formulas: the printed forms fail where the lectures say, the
corrected forms hold, each against an independent derivation."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from course_lib.constructions.beta_splines import (
    beta_spline,
    cubic_beta_spline,
    gn_beta_spline_basis,
)
from course_lib.geometry.continuity import curve_continuity
from course_lib.sources import seed_formulas as sf

P = np.array(
    [[0, 0], [0.5, 2.5], [2.5, 3.2], [4, 0.8], [6, 0.4], [7.5, 2.8], [9.5, 3.0], [10.5, 0.8]]
)
B1 = np.array([1.0, 1.0, 0.6, 1.6, 1.0, 1.4, 1.0, 1.0])
B2 = np.array([0.0, 0.0, 2.0, 0.0, 4.0, 1.0, 0.0, 0.0])
u = sp.Symbol("u")


def test_inverse_betas_are_the_derivatives_of_the_inverse_function():
    # independent: invert a concrete polynomial change of variables by a power series
    x, y = sp.symbols("x y")
    betas = [sp.Rational(3, 2), sp.Rational(1, 2), -2, 3]
    forward = sum(b * x**j / sp.factorial(j) for j, b in enumerate(betas, start=1))
    inv = sp.S(0)
    for _ in range(4):  # fixed-point iteration of y = x / β1 - (forward(x) - β1 x)/β1
        inv = sp.series(y / betas[0] - (forward.subs(x, inv) - betas[0] * inv) / betas[0], y, 0, 5)
        inv = inv.removeO()
    expected = [sp.diff(inv, y, j).subs(y, 0) for j in range(1, 5)]
    assert [sp.nsimplify(v) for v in sf.inverse_betas(betas)] == expected


@given(st.floats(0.1, 10), st.floats(-10, 10), st.floats(-10, 10), st.floats(-10, 10))
def test_inverse_betas_is_an_involution(b1, b2, b3, b4):
    back = sf.inverse_betas(sf.inverse_betas((b1, b2, b3, b4)))
    assert np.allclose(back, (b1, b2, b3, b4), rtol=1e-9, atol=1e-9)


def test_inverse_betas_example_of_the_lectures():
    assert sf.inverse_betas((1, 20, 0)) == (1, -20, 1200)


@pytest.mark.parametrize("bad", [(), (1, 2, 3, 4, 5), (0.0, 1.0), (-1.0,)])
def test_inverse_betas_rejects_bad_input(bad):
    with pytest.raises(ValueError, match="beta"):
        sf.inverse_betas(bad)


def test_uniform_quartic_b_spline_weights_at_a_joint():
    # classical table (Farin, CAGD): 1/24, 11/24, 11/24, 1/24
    w = [b.subs(u, 0) for b in sf.blending_basis(3, [1, 0, 0])]
    assert w == [
        sp.Rational(1, 24),
        sp.Rational(11, 24),
        sp.Rational(11, 24),
        sp.Rational(1, 24),
        0,
    ]


def test_printed_ranges_of_seed_001_eqs_2_9_2_10_leave_the_basis_undetermined():
    eqs, a, _ = sf.blending_system(3, [1, 0, 0], printed_range=True)
    (sol,) = sp.linsolve(eqs, a)
    free = set().union(*(s.free_symbols for s in sol)) & set(a)
    assert len(eqs) == 16 and len(a) == 25 and len(free) == 9


def test_seed_001_convention_gives_the_inverse_betas():
    seed_form = sf.blending_basis(3, [1, 20, 0], convention="001")
    ours = sf.blending_basis(3, list(sf.inverse_betas((sp.Integer(1), 20, 0))))
    assert all(sp.expand(s - o) == 0 for s, o in zip(seed_form, ours, strict=True))
    # and the numerical basis of course_lib agrees at a joint
    num = gn_beta_spline_basis(3, (1, -20, 1200)).evaluate(0.0)
    assert np.allclose(num, [float(w.subs(u, 0)) for w in seed_form])


@pytest.mark.parametrize("b1", [sp.Rational(1, 2), sp.Integer(1), sp.Integer(2)])
def test_cubic_system_is_singular_exactly_where_gamma_is_undefined(b1):
    # γ's denominator β2 + 2 β1 (1 + β1) vanishes: the 16 x 16 system loses rank there only
    b2_star = -2 * b1 * (1 + b1)
    for b2, deficit in ((b2_star, 1), (b2_star + 1, 0), (sp.Integer(0), 0)):
        eqs, a, _ = sf.blending_system(2, [b1, b2])
        M = np.array(sp.linear_eq_to_matrix(eqs, a)[0], dtype=float)
        assert M.shape[1] - np.linalg.matrix_rank(M) == deficit
    with pytest.raises(ValueError, match="unique"):
        sf.blending_basis(2, [b1, b2_star])


def test_quartic_basis_fails_for_admissible_positive_betas():
    b1, b2, b3 = sp.symbols("beta1 beta2 beta3")
    w0 = sf.blending_basis(3, [b1, b2, b3])[0].subs(u, 0)
    den = sp.denom(sp.together(w0))
    assert den.subs({b1: 2, b2: 0, b3: 630}) == 0
    with pytest.raises(ValueError):
        sf.blending_basis(3, [2, 0, 630])
    with pytest.raises(ValueError):
        gn_beta_spline_basis(3, (2, 0, 630))


def test_printed_cubic_construction_breaks_g2_only_with_varying_beta1():
    same = sf.cubic_beta_spline_printed(P, 1.3, B2)
    assert np.allclose(np.array(same.segments), np.array(cubic_beta_spline(P, 1.3, B2).segments))
    varying = sf.cubic_beta_spline_printed(P, B1, B2)
    assert any(r.g_order < 2 for r in curve_continuity(varying, max_order=2))
    with pytest.raises(ValueError, match="gamma"):
        sf.cubic_beta_spline_printed(P, 1.0, -4.0)


def test_gamma_printed_is_infinite_where_undefined():
    assert np.isinf(sf.gamma_printed(1.0, -4.0)) and np.isclose(sf.gamma_printed(1.0, 0.0), 1.0)


def test_reciprocal_construction_equals_the_course_and_the_basis_route():
    rec = sf.cubic_beta_spline_reciprocal(P, B1, B2)
    assert np.allclose(np.array(rec.segments), np.array(cubic_beta_spline(P, B1, B2).segments))
    uni = sf.cubic_beta_spline_reciprocal(P, 1.3, 2.0)
    assert np.allclose(np.array(uni.segments), np.array(beta_spline(P, (1.3, 2.0), n=2).segments))


def test_reciprocal_construction_is_g2_where_gamma_is_undefined():
    rec = sf.cubic_beta_spline_reciprocal(P, 1.0, -4.0)
    reps = curve_continuity(rec, max_order=2)
    assert all(r.g_order >= 2 and np.allclose(r.betas[:2], (1, -4), atol=1e-6) for r in reps)


def test_cubic_constructions_reject_bad_beta1():
    for f in (sf.cubic_beta_spline_printed, sf.cubic_beta_spline_reciprocal):
        with pytest.raises(ValueError, match="beta1"):
            f(P, 0.0, 0.0)


def test_barycentric_weights_of_numbers_and_points():
    assert np.allclose(sf.barycentric_weights(1.0, 0.0, 3.0), [2 / 3, 1 / 3])
    a, c = np.array([0.0, 0.0]), np.array([3.0, 6.0])
    assert np.allclose(sf.barycentric_weights(a + (c - a) / 3, a, c), [2 / 3, 1 / 3])
    with pytest.raises(ValueError, match="coincide"):
        sf.barycentric_weights(a, a, a)
    with pytest.raises(ValueError, match="line"):
        sf.barycentric_weights([1.0, 0.0], a, c)


@pytest.mark.parametrize(
    "kwargs, match",
    [({"convention": "002"}, "convention"), ({"betas": [1]}, "betas")],
)
def test_blending_system_rejects_bad_input(kwargs, match):
    args = {"n": 2, "betas": [1, 0], **kwargs}
    with pytest.raises(ValueError, match=match):
        sf.blending_system(**args)
