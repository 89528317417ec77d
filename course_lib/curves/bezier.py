"""Bézier curves: Bernstein basis, evaluation, hodographs, degree elevation, subdivision.

A Bézier curve of degree ``d`` with control polygon ``V_0, ..., V_d`` is

.. math:: q(u) = \\sum_{i=0}^{d} V_i B_i^d(u), \\qquad B_i^d(u) = \\binom{d}{i} u^i (1-u)^{d-i},

for ``u`` in ``[0, 1]`` (seed 000, §8).  Control points are always stored as an
array of shape ``(d + 1, dim)``, one point per row, ``dim`` in ``{2, 3}``.

Lesson: ``notebooks/07_stitching_bezier_curves.ipynb`` (Bézier facts used for stitching).
"""

from __future__ import annotations

from functools import lru_cache
from math import comb, factorial

import numpy as np

from course_lib.validation import as_parameter_array, as_points, check_finite_scalar, check_integer

__all__ = [
    "bernstein",
    "bernstein_matrix",
    "de_casteljau",
    "derivative_control_points",
    "derivative_points",
    "elevate_degree",
    "end_derivative_matrix",
    "end_derivative_points",
    "end_derivatives",
    "evaluate",
    "subdivide",
]


@lru_cache(maxsize=64)
def _binomials(d: int) -> np.ndarray:
    out = np.array([comb(d, i) for i in range(d + 1)], dtype=float)
    out.setflags(write=False)
    return out


def bernstein_matrix(d: int, u: np.ndarray) -> np.ndarray:
    """Bernstein values without checks (the fast path of :func:`bernstein`); ``u`` 1-d float,
    returns ``(len(u), d + 1)``.

    The result is a transposed view of a ``(d + 1, len(u))`` array: each basis
    function is built in one contiguous row, which is several times faster than
    filling strided columns for long ``u``.
    """
    if d == 0:
        return np.ones((u.size, 1))
    # Powers by cumulative products: no pow() calls, exact at u = 0 and u = 1.
    # Row i ends as (comb(d, i) * u**i) * (1 - u)**(d - i), the same products in the
    # same order as the textbook formula.
    out = np.empty((d + 1, u.size))
    out[0] = 1.0
    for k in range(1, d + 1):
        np.multiply(out[k - 1], u, out=out[k])
    out *= _binomials(d)[:, None]
    w = 1.0 - u
    vp = w.copy()
    for k in range(d - 1, -1, -1):
        out[k] *= vp
        if k:
            vp *= w
    return out.T


def bernstein(d: int, u: float | np.ndarray) -> np.ndarray:
    """Bernstein polynomials :math:`B_i^d(u)`, ``i = 0..d`` (seed 000, §8).

    Parameters
    ----------
    d : int
        Degree, ``d >= 0``.
    u : float or array_like of shape (m,)
        Parameter values (any real; the basis is a polynomial).

    Returns
    -------
    ndarray of shape (d + 1,) or (m, d + 1)
        ``B[..., i] = comb(d, i) * u**i * (1 - u)**(d - i)``.

    Examples
    --------
    >>> bernstein(2, 0.5)
    array([0.25, 0.5 , 0.25])
    """
    d = check_integer(d, "d", minimum=0)
    uu, scalar = as_parameter_array(u, "u")
    out = np.ascontiguousarray(bernstein_matrix(d, uu))
    return out[0] if scalar else out


def derivative_points(P: np.ndarray, k: int) -> np.ndarray:
    """k-th hodograph control points without checks.

    ``P`` has shape ``(d + 1, dim)`` or, for several polygons of one degree at once,
    ``(S, d + 1, dim)``; the result keeps the leading axes.
    """
    d = P.shape[-2] - 1
    if k > d:
        return np.zeros((*P.shape[:-2], 1, P.shape[-1]))
    return (factorial(d) / factorial(d - k)) * np.diff(P, n=k, axis=-2) if k else P


def derivative_control_points(control_points: np.ndarray, k: int = 1) -> np.ndarray:
    """Control points of the k-th derivative (the k-th hodograph).

    The k-th derivative of a degree-``d`` Bézier curve is a Bézier curve of degree
    ``d - k`` with control points ``d!/(d-k)! * Δ^k V_i``, ``i = 0..d-k``.
    For ``k > d`` the derivative is the zero polynomial (one zero point).

    Parameters
    ----------
    control_points : array_like of shape (d + 1, dim)
    k : int
        Order of the derivative, ``k >= 0``.

    Returns
    -------
    ndarray of shape (d - k + 1, dim), or (1, dim) of zeros if ``k > d``.

    Degree 0 (one control point, a constant curve) is allowed everywhere in this module:
    it evaluates to its point, its derivatives are zero, and it elevates to a polygon of
    repeated points.

    Examples
    --------
    The hodograph of a quadratic is the line through ``2 (P1 - P0)`` and ``2 (P2 - P1)``:

    >>> derivative_control_points([[0, 0], [1, 2], [2, 0]])
    array([[ 2.,  4.],
           [ 2., -4.]])
    """
    P = as_points(control_points, "control_points", min_points=1)
    k = check_integer(k, "k", minimum=0)
    return derivative_points(P, k)


def _evaluate(P: np.ndarray, u: np.ndarray, n: int = 0) -> np.ndarray:
    Q = derivative_points(P, n) if n else P
    return bernstein_matrix(Q.shape[0] - 1, u) @ Q


def evaluate(control_points: np.ndarray, u: float | np.ndarray, n: int = 0) -> np.ndarray:
    """Point (or n-th derivative) of a Bézier curve at parameters ``u``.

    Uses the Bernstein form of the n-th hodograph, vectorized over ``u``.

    Parameters
    ----------
    control_points : array_like of shape (d + 1, dim)
    u : float or array_like of shape (m,)
    n : int
        Derivative order (0 for points).

    Returns
    -------
    ndarray of shape (dim,) or (m, dim)

    Examples
    --------
    A quadratic's point and first derivative at its middle:

    >>> P = [[0, 0], [1, 2], [2, 0]]
    >>> evaluate(P, 0.5)
    array([1., 1.])
    >>> evaluate(P, 0.5, n=1)
    array([2., 0.])
    """
    P = as_points(control_points, "control_points", min_points=1)
    n = check_integer(n, "n", minimum=0)
    uu, scalar = as_parameter_array(u, "u")
    out = _evaluate(P, uu, n)
    return out[0] if scalar else out


def end_derivatives(control_points: np.ndarray, n: int, end: int = 1) -> np.ndarray:
    """Derivatives of orders ``0..n`` at ``u = 0`` (``end=0``) or ``u = 1`` (``end=1``).

    Generalizes seed 000 eq. (8.1)-(8.3): at ``u = 1`` the k-th derivative is
    ``d!/(d-k)! * Δ^k V_{d-k}``, e.g. ``q'(1) = d (V_d - V_{d-1})`` and
    ``q''(1) = d (d-1) (V_{d-2} - 2 V_{d-1} + V_d)``.

    Returns
    -------
    ndarray of shape (n + 1, dim)
        Row ``k`` is the k-th derivative (zero for ``k > d``).
    """
    P = as_points(control_points, "control_points", min_points=1)
    n = check_integer(n, "n", minimum=0)
    if end not in (0, 1):
        raise ValueError(f"end must be 0 (start, u = 0) or 1 (end, u = 1); got {end!r}")
    return end_derivative_points(P, n, end)


def end_derivative_points(P: np.ndarray, n: int, end: int) -> np.ndarray:
    """:func:`end_derivatives` without checks: ``P`` a float ``(d + 1, dim)`` array (or a stack
    ``(S, d + 1, dim)``), through :func:`end_derivative_matrix`."""
    return end_derivative_matrix(P.shape[-2] - 1, n, end) @ P


@lru_cache(maxsize=128)
def end_derivative_matrix(d: int, n: int, end: int) -> np.ndarray:
    """The matrix of end derivatives: ``M @ P`` holds the derivatives of orders ``0..n`` at
    ``u = end`` of the degree-``d`` Bézier curve with control points ``P`` (seed 000 eq.
    (8.1)-(8.3): ``d!/(d-k)! Δ^k P_0`` at ``u = 0``, ``d!/(d-k)! ∇^k P_d`` at ``u = 1``).

    Returns
    -------
    ndarray of shape (n + 1, d + 1), read-only (cached)
        Row ``k`` is zero for ``k > d``.  ``P`` may be a stack ``(S, d + 1, dim)``:
        ``M @ P`` is then ``(S, n + 1, dim)``.
    """
    if end not in (0, 1):
        raise ValueError(f"end must be 0 (start, u = 0) or 1 (end, u = 1); got {end!r}")
    E = np.zeros((n + 1, d + 1))
    fac = 1.0
    for k in range(min(n, d) + 1):
        for j in range(k + 1):
            E[k, j if end == 0 else d - k + j] = fac * (-1) ** (k - j) * comb(k, j)
        fac *= d - k
    E.setflags(write=False)
    return E


def elevate_degree(control_points: np.ndarray, times: int = 1) -> np.ndarray:
    """Raise the degree of a Bézier curve without changing the curve (seed 000, Fig. 5).

    ``W_i = i/(d+1) V_{i-1} + (1 - i/(d+1)) V_i``, ``i = 0..d+1`` (with the
    out-of-range terms ``V_{-1}``, ``V_{d+1}`` multiplied by zero), applied
    ``times`` times.

    Returns
    -------
    ndarray of shape (d + 1 + times, dim)

    Examples
    --------
    A segment as a quadratic: the new middle point is the segment's midpoint.

    >>> elevate_degree([[0, 0], [2, 2]])
    array([[0., 0.],
           [1., 1.],
           [2., 2.]])
    """
    P = as_points(control_points, "control_points", min_points=1)
    times = check_integer(times, "times", minimum=0)
    for _ in range(times):
        d = P.shape[0] - 1
        a = (np.arange(d + 2) / (d + 1))[:, None]
        W = np.empty((d + 2, P.shape[1]))
        W[0] = P[0]
        W[-1] = P[-1]
        W[1:-1] = a[1:-1] * P[:-1] + (1 - a[1:-1]) * P[1:]
        P = W
    return P


def de_casteljau(control_points: np.ndarray, u: float) -> list[np.ndarray]:
    """All levels of de Casteljau's algorithm at one parameter ``u``.

    Returns
    -------
    list of ndarray
        ``levels[r]`` has shape ``(d + 1 - r, dim)``; ``levels[0]`` is the control
        polygon and ``levels[d][0]`` is the point ``q(u)``.
    """
    P = as_points(control_points, "control_points", min_points=1)
    u = check_finite_scalar(u, "u")
    levels = [P]
    while levels[-1].shape[0] > 1:
        Q = levels[-1]
        levels.append((1 - u) * Q[:-1] + u * Q[1:])
    return levels


def subdivide(control_points: np.ndarray, u: float = 0.5) -> tuple[np.ndarray, np.ndarray]:
    """Split a Bézier curve at ``u`` into two Bézier curves of the same degree.

    The left piece reparametrizes ``[0, u]`` and the right piece ``[u, 1]`` onto
    ``[0, 1]``; their control points are the first and last points of the de
    Casteljau levels.

    Raises
    ------
    ValueError
        If ``u`` is not strictly between 0 and 1.

    Examples
    --------
    >>> left, right = subdivide([[0, 0], [1, 2], [2, 0]])
    >>> left
    array([[0. , 0. ],
           [0.5, 1. ],
           [1. , 1. ]])
    >>> right[0]  # both halves meet at the curve's midpoint
    array([1., 1.])
    """
    u = check_finite_scalar(u, "u")
    if not 0.0 < u < 1.0:
        raise ValueError(f"u must satisfy 0 < u < 1 to split a curve; got {u}")
    levels = de_casteljau(control_points, u)
    left = np.array([lv[0] for lv in levels])
    right = np.array([lv[-1] for lv in reversed(levels)])
    return left, right
