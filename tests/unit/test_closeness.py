"""closeness: three measures against closed forms for circles."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry.closeness import closeness

t = sp.Symbol("t")
TT = np.linspace(0, np.pi, 401)


def circle(radius):
    return ParametricCurve.from_sympy([radius * sp.cos(t), radius * sp.sin(t)], t, (0, np.pi))


def test_a_curve_is_close_to_itself():
    c = closeness(circle(1), circle(1), TT)
    assert c.distance == 0 and c.angle < 1e-6 and c.curvature_gap < 1e-12


def test_concentric_circles_closed_form():
    eps = 0.1
    c = closeness(circle(1), circle(1 + eps), TT)
    assert np.isclose(c.distance, eps) and c.angle < 1e-6  # parallel tangents
    assert np.isclose(c.curvature_gap, 1 - 1 / (1 + eps))  # κ = 1 / radius


def test_ripples_close_in_distance_not_in_tangent():
    r = 1 + sp.Rational(3, 100) * sp.sin(40 * t)
    ripple = ParametricCurve.from_sympy([r * sp.cos(t), r * sp.sin(t)], t, (0, np.pi))
    c = closeness(ripple, circle(1), np.linspace(0, np.pi, 4001))
    # tangent angle of r(t)(cos t, sin t) against the circle: atan(r'/r), r' up to 1.2
    assert c.distance <= 0.03 + 1e-12 and np.isclose(
        c.angle, np.degrees(np.arctan(1.2 / 1)), atol=1.0
    )
    assert str(c).startswith("distance ≤ 0.030")


def test_empty_parameters_raise():
    with pytest.raises(ValueError, match="t must"):
        closeness(circle(1), circle(1), [])


def test_rippled_circle_is_the_formula():
    from course_lib.geometry.closeness import rippled_circle

    c = rippled_circle(0.03, 40)
    tt = np.linspace(0, np.pi, 7)
    r = 1 + 0.03 * np.sin(40 * tt)
    np.testing.assert_allclose(c.evaluate(tt), np.column_stack([r * np.cos(tt), r * np.sin(tt)]))
    assert closeness(rippled_circle(0, 1), circle(1), TT).distance < 1e-15
