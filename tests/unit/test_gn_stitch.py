"""G^n stitching of any order (issue 14): reduces to eq. (10), (11a) for n = 1, 2; satisfies
the Beta-constraints typed in from seed 000 eq. (7.1)-(7.4) for n <= 4 and, above, the
chain rule as a power-series composition q(u(t)) (numpy polynomials, no Bell tables)."""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import check_joint
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.stitching import (
    g1_stitch_points,
    g2_stitch_points,
    gn_stitch,
    gn_stitch_points,
)
from course_lib.geometry.continuity import curve_continuity


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10**6), b1=st.floats(0.2, 5.0), b2=st.floats(-5.0, 5.0))
def test_reduces_to_eq_10_and_11a(seed, b1, b2):
    V = np.random.default_rng(seed).normal(size=(5, 2))
    np.testing.assert_allclose(gn_stitch_points(V, [b1]), g1_stitch_points(V, b1), atol=1e-12)
    np.testing.assert_allclose(
        gn_stitch_points(V, [b1, b2]), g2_stitch_points(V, b1, b2), atol=1e-10
    )


@settings(max_examples=20, deadline=None)
@given(
    seed=st.integers(0, 10**6),
    n=st.integers(1, 4),
    extra=st.integers(0, 2),
    b=st.lists(st.floats(-2.0, 2.0), min_size=3, max_size=3),
    b1=st.floats(0.3, 3.0),
)
def test_satisfies_the_typed_in_constraints(seed, n, extra, b, b1):
    rng = np.random.default_rng(seed)
    d = n + extra
    V = rng.normal(size=(d + 1, 2))
    betas = [b1, *b[: n - 1]]
    c = gn_stitch(V, betas, rng.normal(size=(d - n, 2)))
    check_joint(c, 0, betas)


def _composition(n: int, betas, qd):
    """r^(i)(0), i = 1..n, as i! [t^i] q(u(t)) with the polynomials u(t) = sum β_j t^j / j!
    and q(x) = sum q^(k) x^k / k! (power-series composition, independent of Bell tables)."""
    from math import factorial

    from numpy.polynomial import polynomial as Pn

    u = np.array([0.0] + [betas[j - 1] / factorial(j) for j in range(1, n + 1)])
    out = np.zeros((n, qd.shape[1]))
    for k in range(1, n + 1):
        uk = Pn.polypow(u, k)[: n + 1]
        uk = np.pad(uk, (0, n + 1 - uk.size))
        out += np.outer(uk[1:] * [factorial(i) for i in range(1, n + 1)], qd[k - 1] / factorial(k))
    return out


@pytest.mark.parametrize("n", [5, 6, 8])
def test_high_orders_against_power_series_composition(n):
    betas = [1.25, -0.5, 0.75, 0.25, -1.0, 0.5, 0.3, -0.2][:n]
    V = np.random.default_rng(n).normal(size=(n + 2, 2))
    c = gn_stitch(V[: n + 2], betas, V[:1] + 9.0)
    q = c.end_derivatives(0, 1, n)[1:]
    r = c.end_derivatives(1, 0, n)[1:]
    np.testing.assert_allclose(r, _composition(n, betas, q), rtol=1e-9, atol=1e-9 * np.abs(r).max())
    rep = curve_continuity(c, n, rtol=1e-6)[0]  # rounding grows with the order
    assert rep.g_order == n and rep.characterizations_agree
    tol = 10.0 ** (n - 12)  # the β's of high orders carry amplified rounding
    np.testing.assert_allclose(rep.betas, betas, rtol=tol, atol=tol)


def test_bad_input():
    V = np.random.default_rng(0).normal(size=(4, 2))
    with pytest.raises(ValueError, match="degree d >= n = 4"):
        gn_stitch_points(V, [1, 0, 0, 0])
    with pytest.raises(ValueError, match="beta1 must be > 0"):
        gn_stitch_points(V, [-1.0, 0])
    with pytest.raises(TypeError, match="betas"):
        gn_stitch_points(V, ["1", "0"])
    with pytest.raises(ValueError, match="W_rest"):
        gn_stitch(V, [1.0, 0.0], None)
