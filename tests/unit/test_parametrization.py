"""Tests of course_lib.curves.parametrization.ParametricCurve.

References: closed-form derivatives of cos/sin and of polynomials, written by hand.
"""

from __future__ import annotations

import numpy as np
import pytest

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve, as_parametrization


def test_from_sympy_derivatives_of_any_order():
    import sympy as sp

    t = sp.Symbol("t")
    c = ParametricCurve.from_sympy([sp.cos(2 * t), sp.sin(2 * t), t], t, (0.0, 2.0), name="helix")
    assert c.dim == 3 and c.domain == (0.0, 2.0) and "helix" in repr(c)
    x = np.linspace(0, 2, 7)
    for n in range(6):
        # d^n/dt^n (cos 2t, sin 2t) = 2^n (cos(2t + n pi/2), sin(2t + n pi/2))
        ph = 2 * x + n * np.pi / 2
        z = {0: x, 1: np.ones_like(x)}.get(n, np.zeros_like(x))
        expected = np.stack([2**n * np.cos(ph), 2**n * np.sin(ph), z], -1)
        np.testing.assert_allclose(c.evaluate(x, n), expected, atol=1e-12)
    assert c.evaluate(1.0, 3).shape == (3,)  # constant third coordinate broadcast


def test_numpy_callables_and_protocol():
    funcs = [
        lambda t: np.stack([t, t**2], -1),
        lambda t: (np.ones_like(t), 2 * t),  # a tuple of coordinates is accepted too
        lambda t: (0.0, 2.0),  # constants broadcast
    ]
    p = ParametricCurve(funcs, (-1.0, 1.0))
    np.testing.assert_allclose(p.evaluate([-1.0, 0.5], 2), [[0, 2], [0, 2]])
    np.testing.assert_allclose(p.evaluate(0.5, 1), [1.0, 1.0])
    assert as_parametrization(p) is p
    bz = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 1.0]])])
    assert as_parametrization(bz) is bz


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: ParametricCurve([lambda t: np.stack([t, t], -1)], (1.0, 0.0)), ValueError,
         "start < end"),
        (lambda: ParametricCurve([lambda t: np.stack([t, t], -1)], (0.0, np.inf)), ValueError,
         "finite"),
        (lambda: ParametricCurve([], (0.0, 1.0)), ValueError, "at least the position"),
        (lambda: ParametricCurve([42], (0.0, 1.0)), TypeError, "callable"),
        (lambda: ParametricCurve([lambda t: np.stack([t] * 4, -1)], (0, 1)), ValueError,
         "R\\^2 or R\\^3"),
        (lambda: ParametricCurve([lambda t: np.stack([t, t], -1)], (0, 1)).evaluate(0.5, 1),
         ValueError, "up to order 0"),
        (lambda: ParametricCurve([lambda t: np.stack([t, t], -1)], (0, 1)).evaluate(1.5),
         ValueError, "domain"),
        (lambda: ParametricCurve([lambda t: np.stack([1 / (t - 1.5), t], -1)], (0, 2))
         .evaluate(1.5), ValueError, "not finite"),
        (lambda: as_parametrization(3.0), TypeError, "parametrization"),
    ],
)  # fmt: skip
def test_bad_input(call, exc, match):
    with np.errstate(all="ignore"), pytest.raises(exc, match=match):
        call()


def test_from_sympy_bad_input():
    import sympy as sp

    t, a = sp.symbols("t a")
    with pytest.raises(ValueError, match="depends on"):
        ParametricCurve.from_sympy([a * t, t], t, (0, 1))
    with pytest.raises(TypeError, match="Symbol"):
        ParametricCurve.from_sympy([t, t], "t", (0, 1))
    with pytest.raises(ValueError, match="2 or 3 coordinates"):
        ParametricCurve.from_sympy([t], t, (0, 1))
