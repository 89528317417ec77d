"""Tests of course_lib.geometry.differential_geometry (seed 004 §19.2-19.3).

Independent references: closed forms (circle, parabola, helix, clothoid via
scipy.special.fresnel), scipy.integrate.quad for arc length, central finite
differences for curvature, and a round trip through the fundamental theorem.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy import integrate, special

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry import differential_geometry as dg


def circle(R=2.0, center=(1.0, -1.0), orientation=1.0, domain=(0.0, 5.0)):
    cx, cy = center
    w = orientation

    def f(k):
        def g(t):
            # d^k/dt^k of (cos wt, sin wt) = w^k (cos(wt + k pi/2), sin(wt + k pi/2))
            ph = w * t + k * np.pi / 2
            off = (cx, cy) if k == 0 else (0.0, 0.0)
            return np.stack([off[0] + R * w**k * np.cos(ph), off[1] + R * w**k * np.sin(ph)], -1)

        return g

    return ParametricCurve([f(k) for k in range(6)], domain)


# The parabola y = x^2, x in [-1, 1], as one quadratic Bézier segment:
# V0 = (-1, 1), V1 = (0, -1), V2 = (1, 1) gives x = 2u - 1, y = (2u - 1)^2.
PARABOLA = PiecewiseBezier([np.array([[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]])])

MIXED = PiecewiseBezier(
    [
        np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]]),
        np.array([[3.0, 0.0], [4.0, -1.0], [5.0, 0.5]]),
        np.array([[5.0, 0.5], [6.0, 1.5], [6.5, 3.0], [7.0, 3.5], [8.0, 3.0]]),
    ],
    knots=[0.0, 0.3, 1.7, 2.0],
)


@pytest.mark.parametrize("orientation", [1.0, -1.0])
def test_circle_curvature_tangent_normal(orientation):
    R, center = 2.0, np.array([1.0, -1.0])
    c = circle(R, center, orientation)
    t = np.linspace(0.0, 5.0, 11)
    np.testing.assert_allclose(dg.signed_curvature(c, t), orientation / R, rtol=1e-14)
    np.testing.assert_allclose(dg.curvature(c, t), 1 / R, rtol=1e-14)
    radial = (c.evaluate(t) - center) / R
    # counter-clockwise: N = (-T2, T1) points to the centre; clockwise: away from it
    np.testing.assert_allclose(dg.unit_normal(c, t), -orientation * radial, atol=1e-14)
    np.testing.assert_allclose(dg.curvature_vector(c, t), -radial / R, atol=1e-14)
    T = dg.unit_tangent(c, t)
    np.testing.assert_allclose(np.sum(T * radial, axis=1), 0.0, atol=1e-14)
    np.testing.assert_allclose(dg.speed(c, t), R, rtol=1e-14)
    centre, radius = dg.osculating_circle(c, 1.3)
    np.testing.assert_allclose(centre, center, atol=1e-13)
    assert radius == pytest.approx(R, rel=1e-14)


def test_parabola_curvature_closed_form():
    # y = x^2: kappa(x) = 2 / (1 + 4 x^2)^(3/2), positive (turns left) for increasing x
    u = np.linspace(0.0, 1.0, 9)
    x = 2 * u - 1
    np.testing.assert_allclose(
        dg.signed_curvature(PARABOLA, u), 2 / (1 + 4 * x**2) ** 1.5, rtol=1e-13
    )
    np.testing.assert_allclose(
        dg.unit_tangent(PARABOLA, u), np.stack([1 + 0 * x, 2 * x], -1) / np.hypot(1, 2 * x)[:, None]
    )
    centre, radius = dg.osculating_circle(PARABOLA, 0.5)  # vertex: radius 1/2, centre (0, 1/2)
    np.testing.assert_allclose(centre, [0.0, 0.5], atol=1e-14)
    assert radius == pytest.approx(0.5)


def test_parabola_arc_length_closed_form():
    # L = int_{-1}^{1} sqrt(1 + 4x^2) dx. With 2x = sinh(w): int sqrt(1+4x^2) dx
    # = x sqrt(1+4x^2)/2 + asinh(2x)/4, so L = 2 (sqrt(5)/2 + asinh(2)/4) = sqrt(5) + asinh(2)/2.
    exact = np.sqrt(5.0) + np.arcsinh(2.0) / 2
    assert dg.arc_length(PARABOLA) == pytest.approx(exact, rel=1e-13, abs=0)
    half = np.sqrt(5.0) / 2 + np.arcsinh(2.0) / 4
    assert dg.arc_length(PARABOLA, 0.5, 1.0) == pytest.approx(half, rel=1e-13, abs=0)
    assert dg.arc_length(PARABOLA, 1.0, 0.5) == pytest.approx(-half, rel=1e-13, abs=0)


def test_arc_length_matches_scipy_quad_on_piecewise_curve_with_knots():
    def v(t):
        return np.linalg.norm(MIXED.evaluate(t, 1))

    ref = sum(
        integrate.quad(v, a, b, epsabs=0, epsrel=1e-13, limit=200)[0]
        for a, b in zip(MIXED.knots[:-1], MIXED.knots[1:], strict=True)
    )
    assert dg.arc_length(MIXED) == pytest.approx(ref, rel=1e-12, abs=0)
    t = np.array([0.1, 0.3, 1.0, 2.0])
    s = dg.cumulative_arc_length(MIXED, t)
    for ti, si in zip(t, s, strict=True):
        assert si == pytest.approx(dg.arc_length(MIXED, 0.0, ti), rel=1e-12)
    assert np.all(np.diff(dg.cumulative_arc_length(MIXED, np.linspace(0, 2, 50))) > 0)


def test_curvature_matches_finite_differences():
    t = np.linspace(0.05, 1.95, 13)
    h = 1e-4
    tt = np.concatenate([t - h, t, t + h])
    P = MIXED.evaluate(tt).reshape(3, t.size, 2)
    d1 = (P[2] - P[0]) / (2 * h)
    d2 = (P[2] - 2 * P[1] + P[0]) / h**2
    k_fd = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / np.linalg.norm(d1, axis=1) ** 3
    np.testing.assert_allclose(dg.signed_curvature(MIXED, t), k_fd, rtol=1e-5, atol=1e-6)


def test_helix_curvature_3d():
    a, b = 2.0, 0.5  # (a cos t, a sin t, b t): kappa = a / (a^2 + b^2)
    funcs = [
        lambda t: np.stack([a * np.cos(t), a * np.sin(t), b * t], -1),
        lambda t: np.stack([-a * np.sin(t), a * np.cos(t), b + 0 * t], -1),
        lambda t: np.stack([-a * np.cos(t), -a * np.sin(t), 0 * t], -1),
    ]
    h = ParametricCurve(funcs, (0.0, 6.0))
    np.testing.assert_allclose(dg.curvature(h, [0.0, 2.0]), a / (a * a + b * b), rtol=1e-14)
    assert dg.arc_length(h) == pytest.approx(6.0 * np.hypot(a, b), rel=1e-13)
    with pytest.raises(ValueError, match="plane curves"):
        dg.signed_curvature(h, 0.0)


def test_parameter_at_arc_length():
    c = circle(R=2.0, domain=(0.0, 3.0))
    s = np.linspace(0.0, 6.0, 7)
    np.testing.assert_allclose(dg.parameter_at_arc_length(c, s), s / 2.0, atol=1e-13)
    s = np.linspace(0.0, dg.arc_length(MIXED), 33)
    t = dg.parameter_at_arc_length(MIXED, s)
    np.testing.assert_allclose(dg.cumulative_arc_length(MIXED, t), s, rtol=1e-12, atol=1e-12)
    assert isinstance(dg.parameter_at_arc_length(MIXED, 1.0), float)
    np.testing.assert_allclose(dg.point_at_arc_length(MIXED, s[-1]), [8.0, 3.0], atol=1e-12)


def test_arc_length_derivatives_closed_form():
    import sympy as sp

    x = sp.Symbol("x")
    R = 1.5
    phase = x**2 + x  # a non-uniform circle parametrization
    c = ParametricCurve.from_sympy([R * sp.cos(phase), R * sp.sin(phase)], x, (0.0, 1.0))
    t0 = 0.4
    ph = t0**2 + t0
    D = dg.arc_length_derivatives(c, t0, 5)
    # arc-length parametrization R (cos(s/R), sin(s/R)):
    # k-th derivative R^(1-k) (cos, sin)(. + k pi/2)
    expected = [R ** (1 - k) * np.array([np.cos(ph + k * np.pi / 2), np.sin(ph + k * np.pi / 2)])
                for k in range(1, 6)]  # fmt: skip
    np.testing.assert_allclose(D, expected, atol=1e-12)
    np.testing.assert_allclose(D[0], dg.unit_tangent(c, t0))
    np.testing.assert_allclose(D[1], dg.curvature_vector(c, t0), atol=1e-14)


def test_curve_from_curvature_circle_and_clothoid():
    R = 2.0
    res = dg.curve_from_curvature(1 / R, np.pi * R, start_point=(1.0, 0.0), start_angle=np.pi / 2)
    # start (1, 0) heading up, turning left: the circle of radius R centred at (1 - R, 0)
    expected = np.stack([1 - R + R * np.cos(res.s / R), R * np.sin(res.s / R)], -1)
    np.testing.assert_allclose(res.points, expected, atol=1e-13)
    # clothoid kappa(s) = s: theta = s^2/2, x = sqrt(pi) C(s/sqrt(pi)), y = sqrt(pi) S(s/sqrt(pi))
    res = dg.curve_from_curvature(lambda s: s, 3.0, num=61)
    S, C = special.fresnel(res.s / np.sqrt(np.pi))
    np.testing.assert_allclose(res.points, np.sqrt(np.pi) * np.stack([C, S], -1), atol=1e-13)
    np.testing.assert_allclose(res.angle, res.s**2 / 2, atol=1e-14)


def test_fundamental_theorem_round_trip():
    """kappa(s) of a cubic Bézier -> rebuilt curve = the original (same start point and tangent)."""
    cubic = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 2.0], [3.0, -1.0], [4.0, 1.0]])])
    L = dg.arc_length(cubic)

    def kappa(s):
        return dg.signed_curvature(cubic, dg.parameter_at_arc_length(cubic, s))

    T0 = dg.unit_tangent(cubic, 0.0)
    res = dg.curve_from_curvature(kappa, L, start_point=(0.0, 0.0), start_tangent=T0, num=41)
    np.testing.assert_allclose(res.points, dg.point_at_arc_length(cubic, res.s), atol=1e-10)
    # rigid motion: rotating the start tangent rotates the whole curve
    res2 = dg.curve_from_curvature(kappa, L, start_point=(5.0, 1.0),
                                   start_angle=np.arctan2(T0[1], T0[0]) + 1.0, num=41)  # fmt: skip
    Rm = np.array([[np.cos(1.0), -np.sin(1.0)], [np.sin(1.0), np.cos(1.0)]])
    np.testing.assert_allclose(res2.points, res.points @ Rm.T + [5.0, 1.0], atol=1e-12)


def test_reparametrized_curve_accepted():
    from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized

    f = ChangeOfVariables.polynomial([0.0, 0.5, 0.0, 0.5], (0.0, 1.0))  # f(x) = (x + x^3)/2
    rp = Reparametrized(PARABOLA, f)
    x = np.linspace(0, 1, 5)
    np.testing.assert_allclose(dg.signed_curvature(rp, x), dg.signed_curvature(PARABOLA, f(x)))
    assert dg.arc_length(rp) == pytest.approx(dg.arc_length(PARABOLA), rel=1e-13)


CUSP = PiecewiseBezier([np.array([[0.0, 0.0], [0.0, 0.0], [1.0, 1.0], [2.0, 0.0]])])
LINE = PiecewiseBezier([np.array([[0.0, 0.0], [1.0, 1.0]])])


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: dg.unit_tangent(CUSP, 0.0), ValueError, "not regular at t=0"),
        (lambda: dg.signed_curvature(CUSP, [0.5, 0.0]), ValueError, "first derivative vanishes"),
        (lambda: dg.unit_tangent(MIXED, 2.5), ValueError, "domain"),
        (lambda: dg.unit_tangent("curve", 0.0), TypeError, "parametrization"),
        (lambda: dg.unit_tangent(MIXED, np.nan), ValueError, "finite"),
        (lambda: dg.osculating_circle(LINE, 0.5), ValueError, "curvature vanishes"),
        (lambda: dg.arc_length(MIXED, 0.0, 3.0), ValueError, "t1 must lie in the domain"),
        (lambda: dg.parameter_at_arc_length(LINE, 2.0), ValueError, r"s must lie in \[0, L\]"),
        (lambda: dg.curve_from_curvature(1.0, 0.0), ValueError, "length must be > 0"),
        (lambda: dg.curve_from_curvature(1.0, 1.0, num=1), ValueError, "num must be >= 2"),
        (lambda: dg.curve_from_curvature(1.0, 1.0, start_angle=0.0, start_tangent=(1, 0)),
         ValueError, "not both"),
        (lambda: dg.curve_from_curvature(lambda s: s / 0.0 * 0.0, 1.0), ValueError, "finite"),
        (lambda: dg.curve_from_curvature(1.0, 1.0, start_tangent=(0, 0)), ValueError,
         "start_tangent"),
        (lambda: dg.curve_from_curvature(1.0, 1.0, start_point=(0, 0, 0)), ValueError,
         "start_point"),
        (lambda: dg.arc_length_derivatives(MIXED, 0.5, 0), ValueError, "n must be >= 1"),
    ],
)  # fmt: skip
def test_bad_input(call, exc, match):
    with np.errstate(all="ignore"), pytest.raises(exc, match=match):
        call()


def test_frame_from_derivatives_on_a_circle_of_radius_2():
    # c(t) = 2 (cos t, sin t): c' = 2 (-sin, cos), c'' = -2 (cos, sin); T = (-sin, cos), K = -(cos, sin)/2
    t = np.linspace(0.0, 6.0, 7)
    d1 = 2 * np.stack([-np.sin(t), np.cos(t)], axis=-1)
    d2 = -2 * np.stack([np.cos(t), np.sin(t)], axis=-1)
    T, K = dg.frame_from_derivatives(d1.reshape(7, 1, 2), d2.reshape(7, 1, 2))  # any leading shape
    np.testing.assert_allclose(T[:, 0], np.stack([-np.sin(t), np.cos(t)], axis=-1), atol=1e-15)
    np.testing.assert_allclose(
        K[:, 0], -0.5 * np.stack([np.cos(t), np.sin(t)], axis=-1), atol=1e-15
    )


def test_check_regular_names_the_parameter_of_a_cusp():
    cusp = PiecewiseBezier([[[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]])  # c'(1/2) = 0
    t = np.array([[0.25, 0.5]])
    d1 = cusp.evaluate(t.ravel(), 1).reshape(1, 2, 2)
    with pytest.raises(ValueError, match=r"not regular at t=0\.5"):
        dg.check_regular(cusp, t, d1)
    np.testing.assert_allclose(
        dg.check_regular(cusp, t[:, :1], d1[:, :1]), [[np.linalg.norm(d1[0, 0])]]
    )
