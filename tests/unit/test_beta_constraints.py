"""Tests of course_lib.geometry.beta_constraints (seed 000 §5 eq. (7.1)-(7.4), seed 001 eq. (2.7)).

Independent references: the printed equations of seed 000 (typed in here, in the
test only, and compared with ``(a - b).expand() == 0``); a direct sympy
differentiation of ``q(u(t))`` with concrete polynomial ``q`` and ``u``; and the
reduction to C^n for β = (1, 0, ..., 0).
"""

from __future__ import annotations

import numpy as np
import pytest

from course_lib.geometry.beta_constraints import (
    _raw_derivative,
    apply_beta_constraints,
    beta_coefficients,
    beta_constraints,
    solve_shape_parameters,
)


def _printed(sp, bc, seed):
    b1, b2, b3, b4 = bc.betas[:4]
    q1, q2, q3, q4 = bc.q[:4]
    if seed == "000":  # seed 000 eq. (7.1)-(7.4)
        return [
            b1 * q1,
            b1**2 * q2 + b2 * q1,
            b1**3 * q3 + 3 * b1 * b2 * q2 + b3 * q1,
            b1**4 * q4 + 6 * b1**2 * b2 * q3 + (4 * b1 * b3 + 3 * b2**2) * q2 + b4 * q1,
        ]
    # seed 001 eq. (2.7) as transcribed
    return [
        b1 * q1,
        b1**2 * q2 + b2 * q1,
        b1**3 * q3 + 3 * b1 * b2 * q2 + b2 * q1,
        b1**4 * q4 + 6 * b1**2 * b2 * q3 + (4 * b1 * b2 + 3 * b2**2) * q2 + b4 * q1,
    ]


def test_seed_000_eq_7():
    import sympy as sp

    bc = beta_constraints(4)
    for derived, printed in zip(bc.rhs, _printed(sp, bc, "000"), strict=True):
        assert (derived - printed).expand() == 0


def test_seed_001_eq_2_7_is_not_the_chain_rule():
    """Seed 001 eq. (2.7) (transcription) has β2 q' in r''' and 4β1β2 q'' in r''''.

    The chain rule gives β3 q' and 4β1β3 q'': the first two lines agree, the last two do not.
    """
    import sympy as sp

    bc = beta_constraints(4)
    printed = _printed(sp, bc, "001")
    diffs = [(d - p).expand() for d, p in zip(bc.rhs, printed, strict=True)]
    assert diffs[0] == 0 and diffs[1] == 0
    b1, b2, b3, _ = bc.betas
    q1, q2 = bc.q[:2]
    assert (diffs[2] - (b3 - b2) * q1).expand() == 0
    assert (diffs[3] - 4 * b1 * (b3 - b2) * q2).expand() == 0


def test_chain_rule_against_taylor_composition():
    """Independent derivation by composing Taylor series (no differentiation of q(u(t))).

    With h = t - 1 and u(t) = 1 + w(h), w = sum_j β_j h^j / j!, the Taylor series
    q(u(t)) = sum_k q^(k)(1) w^k / k! gives r^(i) = i! [h^i] sum_k q^(k)(1) w^k / k!.
    """
    import sympy as sp

    n = 6
    bc = beta_constraints(n)
    h = sp.Symbol("h")
    w = sp.Poly(sum(b * h**j / sp.factorial(j) for j, b in enumerate(bc.betas, 1)), h)
    series = sp.Poly(0, h)
    power = sp.Poly(1, h)
    for k in range(1, n + 1):
        power = sp.Poly(sum(c * h**m for (m,), c in (power * w).terms() if m <= n), h)
        series += power * (bc.q[k - 1] / sp.factorial(k))
    for i in range(1, n + 1):
        taylor = sp.factorial(i) * series.coeff_monomial(h**i)
        assert (taylor - bc.rhs[i - 1]).expand() == 0


def test_order_8_derives_and_is_cached():
    # Its speed (goal: under 1 s cold) is measured by benchmarks/run.py, not asserted here:
    # the test suite holds no timed assertions (shared, noisy machine).
    beta_constraints.cache_clear()
    _raw_derivative.cache_clear()
    bc = beta_constraints(8)
    assert beta_constraints(8) is bc
    # lower triangular, diagonal β1^i, first column β_i (B_{i,i} = x1^i, B_{i,1} = x_i)
    for i in range(8):
        assert bc.coefficients[i, i] == bc.betas[0] ** (i + 1)
        assert bc.coefficients[i, 0] == bc.betas[i]
        for k in range(i + 1, 8):
            assert bc.coefficients[i, k] == 0


def test_text_and_latex_forms():
    bc = beta_constraints(4)
    text = str(bc)
    assert "r^(4)(0) = beta1^4 q^(4)(1)" in text
    assert "(4*beta1*beta3 + 3*beta2^2) q^(2)(1)" in text
    latex = bc._repr_latex_()
    assert latex.startswith("$\\begin{aligned}") and "\\beta_{4} \\mathbf{q}^{(1)}(1)" in latex
    assert len(bc.equations) == 4


def test_numeric_coefficients_equal_symbolic():
    import sympy as sp

    n = 6
    bc = beta_constraints(n)
    betas = np.array([1.7, -0.4, 2.5, 0.3, -1.1, 0.8])
    sub = dict(zip(bc.betas, betas, strict=True))
    sym = np.array(bc.coefficients.subs(sub).evalf(), dtype=float)
    np.testing.assert_allclose(beta_coefficients(betas), sym, rtol=1e-13, atol=1e-13)
    rng = np.random.default_rng(1)
    q = rng.normal(size=(n, 3))
    expected = np.array(
        [[float(bc.rhs[i].subs(sub).subs(dict(zip(bc.q, q[:, c], strict=True)))) for c in range(3)]
         for i in range(n)]
    )  # fmt: skip
    np.testing.assert_allclose(apply_beta_constraints(q, betas), expected, rtol=1e-12)
    assert isinstance(sp, object)


def test_beta_1_and_zeros_reduce_to_c_n():
    q = np.random.default_rng(2).normal(size=(5, 2))
    np.testing.assert_allclose(apply_beta_constraints(q, [1.0, 0, 0, 0, 0]), q, rtol=1e-15)
    fit = solve_shape_parameters(q, q)
    np.testing.assert_allclose(fit.betas, [1, 0, 0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(fit.residual_norms, 0.0, atol=1e-12)


def test_solve_recovers_betas_and_reports_residuals():
    rng = np.random.default_rng(3)
    q = rng.normal(size=(4, 2))
    betas = np.array([0.6, 2.0, -1.5, 4.0])
    r = apply_beta_constraints(q, betas)
    fit = solve_shape_parameters(q, r)
    np.testing.assert_allclose(fit.betas, betas, rtol=1e-10)
    np.testing.assert_allclose(fit.residual_norms, 0.0, atol=1e-10)
    # spoil r''' by a vector perpendicular to q': order 3 residual is exactly that vector
    perp = np.array([-q[0, 1], q[0, 0]])
    r_bad = r.copy()
    r_bad[2] += 0.5 * perp
    fit = solve_shape_parameters(q, r_bad)
    np.testing.assert_allclose(fit.residuals[2], 0.5 * perp, atol=1e-12)
    np.testing.assert_allclose(fit.residual_norms[:2], 0.0, atol=1e-12)
    np.testing.assert_allclose(fit.betas[:3], betas[:3], rtol=1e-12)


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: beta_constraints(0), ValueError, "n must be >= 1"),
        (lambda: beta_constraints(2.0), TypeError, "n must be an integer"),
        (lambda: apply_beta_constraints(np.ones((2, 2)), [0.0, 1.0]), ValueError,
         "beta1 must be > 0"),
        (lambda: apply_beta_constraints(np.ones((1, 2)), [1.0, 1.0]), ValueError,
         "at least 2 derivatives"),
        (lambda: apply_beta_constraints(np.ones((2, 4)), [1.0, 1.0]), ValueError, "dim 2 or 3"),
        (lambda: apply_beta_constraints(np.ones((2, 2)), [1.0, np.nan]), ValueError, "finite"),
        (lambda: solve_shape_parameters(np.zeros((2, 2)), np.ones((2, 2))), ValueError,
         "not regular"),
        (lambda: solve_shape_parameters(np.ones((2, 2)), np.ones((2, 3))), ValueError,
         "same dimension"),
        (lambda: solve_shape_parameters(np.ones((2, 2)), np.ones((3, 2))), ValueError,
         "at least 3"),
    ],
)  # fmt: skip
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call()
