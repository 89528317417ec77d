"""Honest limits (issue 14): work that grows like n^4 or worse has a documented cap, and
above it a ValueError naming the cap is answered at once (< 100 ms), never an hours-long
computation or an OverflowError.  Plus the G^n bases that stay exact up to n = 12."""

from __future__ import annotations

import time

import numpy as np
import pytest
from scipy.interpolate import BSpline

from course_lib.constructions.beta_splines import beta_spline, gn_beta_spline_basis
from course_lib.constructions.beta_splines.degree_n import MAX_BASIS_ORDER
from course_lib.curves.curve import PiecewiseBezier
from course_lib.geometry.beta_constraints import (
    MAX_SYMBOLIC_ORDER,
    apply_beta_constraints,
    beta_constraints,
    solve_shape_parameters,
)
from course_lib.geometry.chain_rule import MAX_CHAIN_RULE_ORDER
from course_lib.geometry.continuity import joint_continuity
from course_lib.geometry.differential_geometry import arc_length_derivatives
from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized, faa_di_bruno

V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]])
C = PiecewiseBezier([V, V + np.array([4.0, 0.0])])
Q, R = C.segment_curve(0), C.segment_curve(1)
REP = Reparametrized(Q, ChangeOfVariables.polynomial([0.0, 0.9, 0.1], (0.0, 1.0)))
P70 = np.random.default_rng(0).normal(size=(70, 2))

CAPPED = [
    ("beta_spline n=60", lambda: beta_spline(P70, (1.0,) + (0.0,) * 59, 60), "MAX_BASIS_ORDER"),
    ("basis n=17", lambda: gn_beta_spline_basis(17, (1.0,) + (0.0,) * 16), "MAX_BASIS_ORDER"),
    ("arc length n=40", lambda: arc_length_derivatives(C, np.linspace(0, 2, 50), 40), "MAX_CHAIN"),
    ("joint max_order=40", lambda: joint_continuity(Q, R, max_order=40), "MAX_CHAIN"),
    ("joint max_order=1000", lambda: joint_continuity(Q, R, max_order=1000), "MAX_CHAIN"),
    ("Reparametrized n=100", lambda: REP.evaluate(np.linspace(0, 1, 50), 100), "MAX_CHAIN"),
    ("faa_di_bruno n=30", lambda: faa_di_bruno(np.ones((30, 2)), np.ones(30)), "MAX_CHAIN"),
    ("apply n=30", lambda: apply_beta_constraints(np.ones((30, 2)), np.ones(30)), "MAX_CHAIN"),
    ("solve n=30", lambda: solve_shape_parameters(np.ones((30, 2)), np.ones((30, 2))), "MAX_CHAIN"),
    ("symbolic n=40", lambda: beta_constraints(40), "MAX_SYMBOLIC_ORDER"),
]


@pytest.mark.parametrize(("what", "call", "cap"), CAPPED, ids=[c[0] for c in CAPPED])
def test_capped_work_is_refused_at_once(what, call, cap):
    t0 = time.perf_counter()
    with pytest.raises(ValueError, match=cap):
        call()
    assert time.perf_counter() - t0 < 0.1


def test_caps_allow_what_they_promise():
    assert MAX_BASIS_ORDER >= 12 and MAX_CHAIN_RULE_ORDER >= 12 and MAX_SYMBOLIC_ORDER >= 10
    assert arc_length_derivatives(C, 0.5, MAX_CHAIN_RULE_ORDER).shape == (MAX_CHAIN_RULE_ORDER, 2)
    assert joint_continuity(Q, R, max_order=MAX_CHAIN_RULE_ORDER).g_order >= 0


@pytest.mark.parametrize("n", [5, 9, 10, 12])
def test_uniform_gn_basis_is_unique_and_matches_scipy(n):
    """β = (1, 0, ..., 0): the uniform B-spline of degree n + 1 (unique for every n)."""
    d = n + 1
    basis = gn_beta_spline_basis(n, (1.0,) + (0.0,) * (n - 1))
    u = np.linspace(0.0, 1.0, 41)[:-1]  # [0, 1): scipy's element is half-open
    N = BSpline.basis_element(np.arange(d + 2.0), extrapolate=False)
    ref = np.stack([N(u + d - k) for k in range(d + 1)], axis=1)  # weight of V_{j+k} on segment j
    np.testing.assert_allclose(basis.evaluate(u), ref, atol=1e-12, rtol=0)


def test_beta_spline_order_9_is_a_gn_spline_with_nonuniform_betas():
    n = 9
    betas = (1.3, 0.4, -0.2, 0.1, 0.0, 0.3, -0.1, 0.05, 0.2)
    c = beta_spline(np.random.default_rng(3).normal(size=(14, 2)), betas, n)
    for j in range(c.n_joints):
        q = c.end_derivatives(j, 1, n)[1:]
        r = c.end_derivatives(j + 1, 0, n)[1:]
        want = apply_beta_constraints(q, betas)
        scale = np.abs(q).max() * 10**n
        np.testing.assert_allclose(r, want, atol=1e-11 * scale)
