"""Tests of course_lib.curves.bezier against independent derivations.

References used here: the Bernstein definition evaluated with exact rationals
(fractions.Fraction), de Casteljau's algorithm (a different algorithm from the
Bernstein-matrix evaluation), sympy differentiation of the polynomial, and the
literal end-derivative formulas of seed 000 eq. (8.1)-(8.3).
"""

from __future__ import annotations

from fractions import Fraction
from math import comb

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.curves import bezier

# Dyadic data keeps every intermediate value exact in binary floating point.
V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]])


def exact_bernstein(d: int, u: Fraction) -> list[Fraction]:
    return [comb(d, i) * u**i * (1 - u) ** (d - i) for i in range(d + 1)]


@pytest.mark.parametrize("d", [0, 1, 2, 3, 5, 8])
@pytest.mark.parametrize("u", ["0", "1/4", "5/8", "1"])
def test_bernstein_matches_exact_rationals(d, u):
    uf = Fraction(u)
    expected = np.array([float(x) for x in exact_bernstein(d, uf)])
    np.testing.assert_allclose(bezier.bernstein(d, float(uf)), expected, rtol=0, atol=1e-15)


@settings(max_examples=60, deadline=None)
@given(d=st.integers(0, 12), u=st.lists(st.floats(0, 1), min_size=1, max_size=20))
def test_bernstein_partition_of_unity_and_nonnegativity(d, u):
    B = bezier.bernstein(d, np.array(u))
    np.testing.assert_allclose(B.sum(axis=1), 1.0, atol=1e-13)
    assert np.all(B >= 0)


def test_evaluate_matches_de_casteljau():
    u = np.linspace(0, 1, 17)
    pts = bezier.evaluate(V, u)
    ref = np.array([bezier.de_casteljau(V, x)[-1][0] for x in u])
    np.testing.assert_allclose(pts, ref, atol=1e-14)
    # endpoint interpolation, seed 000 eq. (8.1a), (8.1b)
    np.testing.assert_array_equal(bezier.evaluate(V, 0.0), V[0])
    np.testing.assert_array_equal(bezier.evaluate(V, 1.0), V[-1])


def test_derivatives_match_sympy():
    sp = pytest.importorskip("sympy")
    u = sp.symbols("u")
    d = V.shape[0] - 1
    poly = [
        sum(
            comb(d, i) * u**i * (1 - u) ** (d - i) * sp.Rational(V[i, c]).limit_denominator()
            for i in range(d + 1)
        )
        for c in range(2)
    ]
    for n in range(0, 5):
        for x in (0, sp.Rational(3, 8), 1):
            expected = [float(sp.diff(p, u, n).subs(u, x)) for p in poly]
            np.testing.assert_allclose(bezier.evaluate(V, float(x), n=n), expected, atol=1e-12)


def test_end_derivatives_are_seed_formulas_8_2_and_8_3():
    d = 3
    ends = bezier.end_derivatives(V, 2, end=1)
    np.testing.assert_array_equal(ends[0], V[3])
    np.testing.assert_allclose(ends[1], d * (V[3] - V[2]))  # (8.2b)
    np.testing.assert_allclose(ends[2], d * (d - 1) * (V[1] - 2 * V[2] + V[3]))  # (8.3b)
    starts = bezier.end_derivatives(V, 2, end=0)
    np.testing.assert_allclose(starts[1], d * (V[1] - V[0]))  # (8.2a)
    np.testing.assert_allclose(starts[2], d * (d - 1) * (V[0] - 2 * V[1] + V[2]))  # (8.3a)
    # derivatives beyond the degree vanish
    np.testing.assert_array_equal(bezier.end_derivatives(V, 5, end=0)[4:], 0.0)


def test_hodograph_degree_and_values():
    H = bezier.derivative_control_points(V, 1)
    assert H.shape == (3, 2)
    np.testing.assert_allclose(H, 3 * np.diff(V, axis=0))
    np.testing.assert_array_equal(bezier.derivative_control_points(V, 4), np.zeros((1, 2)))


@settings(max_examples=40, deadline=None)
@given(
    pts=st.lists(st.tuples(st.floats(-10, 10), st.floats(-10, 10)), min_size=2, max_size=7),
    times=st.integers(1, 3),
)
def test_degree_elevation_keeps_the_curve(pts, times):
    P = np.array(pts)
    W = bezier.elevate_degree(P, times)
    assert W.shape[0] == P.shape[0] + times
    u = np.linspace(0, 1, 11)
    np.testing.assert_allclose(bezier.evaluate(W, u), bezier.evaluate(P, u), atol=1e-11)


def test_degree_elevation_seed_formula_cubic_to_quartic():
    # seed 000, Fig. 5: W_i = i/(d+1) V_{i-1} + (1 - i/(d+1)) V_i with d = 3
    W = bezier.elevate_degree(V)
    expected = [V[0], V[0] / 4 + 3 * V[1] / 4, V[1] / 2 + V[2] / 2, 3 * V[2] / 4 + V[3] / 4, V[3]]
    np.testing.assert_allclose(W, np.array(expected))


@pytest.mark.parametrize("split", [0.25, 0.5, 0.9])
def test_subdivision_reparametrizes_the_two_halves(split):
    left, right = bezier.subdivide(V, split)
    s = np.linspace(0, 1, 9)
    np.testing.assert_allclose(bezier.evaluate(left, s), bezier.evaluate(V, split * s), atol=1e-14)
    np.testing.assert_allclose(
        bezier.evaluate(right, s), bezier.evaluate(V, split + (1 - split) * s), atol=1e-14
    )


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: bezier.evaluate(np.zeros((0, 2)), 0.5), ValueError, "at least 1 points"),
        (
            lambda: bezier.evaluate([[0, 0, 0, 0], [1, 1, 1, 1]], 0.5),
            ValueError,
            "dimension 2 or 3",
        ),
        (lambda: bezier.evaluate([[0, np.nan], [1, 1]], 0.5), ValueError, "finite"),
        (lambda: bezier.evaluate([0, 1, 2], 0.5), ValueError, "shape"),
        (lambda: bezier.evaluate("abc", 0.5), TypeError, "control_points"),
        (lambda: bezier.evaluate(V, np.inf), ValueError, "finite"),
        (lambda: bezier.evaluate(V, 0.5, n=-1), ValueError, "n must be >= 0"),
        (lambda: bezier.evaluate(V, 0.5, n=1.5), TypeError, "n must be an integer"),
        (lambda: bezier.subdivide(V, 1.0), ValueError, "0 < u < 1"),
        (lambda: bezier.end_derivatives(V, 2, end=2), ValueError, "end must be 0"),
        (lambda: bezier.bernstein(-1, 0.5), ValueError, "d must be >= 0"),
    ],
)
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call()


def test_hodographs_of_stacked_polygons_match_one_by_one():
    from course_lib.curves.bezier import derivative_points

    W = V[::-1] * 0.5 + 1.0
    stacked = np.stack([V, W])
    for k in range(5):
        expected = np.stack([bezier.derivative_control_points(P, k) for P in (V, W)])
        np.testing.assert_array_equal(derivative_points(stacked, k), expected)


@pytest.mark.parametrize("d", [1, 2, 3, 5])
@pytest.mark.parametrize("end", [0, 1])
def test_end_derivative_matrix_is_the_hodograph_at_the_end(d, end):
    """The one end-derivative matrix against the k-th hodograph written out by hand
    (k-th forward differences times d!/(d-k)!), exact on integer control points."""
    from math import factorial

    from course_lib.curves.bezier import end_derivative_matrix

    rng = np.random.default_rng(d)
    P = rng.integers(-9, 10, size=(d + 1, 2)).astype(float)
    M = end_derivative_matrix(d, d + 1, end)
    for k in range(d + 2):
        if k > d:
            expected = np.zeros(2)
        else:
            diffs = np.diff(P, n=k, axis=0) * (factorial(d) // factorial(d - k))
            expected = diffs[-1] if end == 1 else diffs[0]
        np.testing.assert_array_equal(M[k] @ P, expected)
    with pytest.raises(ValueError, match="end must be 0"):
        end_derivative_matrix(d, 1, 2)
