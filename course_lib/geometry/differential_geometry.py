"""Differential geometry of parametrized curves: tangent, normal, curvature, arc length.

Seed 004 §19.2-19.3 (Finn): for a regular parametrization ``c(t)`` (``c'(t) != 0``)

* unit tangent ``T = c' / |c'|`` -- the derivative with respect to arc length ``dc/ds``;
* unit normal (plane curves) ``N = (-T_2, T_1)``, so that ``[T, N]`` is right-handed;
* signed curvature ``kappa`` defined by ``dT/ds = T'(t) / |c'(t)| = kappa N``; in
  coordinates ``kappa = (x' y'' - y' x'') / |c'|^3``; positive when the curve turns
  towards ``N`` (to the left);
* curvature vector ``dT/ds = d^2 c / ds^2 = (c'' - (c''.T) T) / |c'|^2`` (plane or space);
* arc length ``s(t) = int_{t0}^{t} |c'(tau)| dtau``;
* fundamental theorem of plane curves: ``kappa(s)`` determines the curve up to a rigid
  motion, through ``theta(s) = theta_0 + int kappa`` and
  ``c(s) = c_0 + int (cos theta, sin theta)``.

Every function accepts any object of the parametrization protocol (``CONTRIBUTING.md``):
:class:`~course_lib.curves.curve.PiecewiseBezier`,
:class:`~course_lib.curves.parametrization.ParametricCurve`,
:class:`~course_lib.geometry.reparametrization.Reparametrized`.  A scalar ``t`` gives a
``(dim,)`` vector or a float, a 1-d ``t`` gives ``(m, dim)`` or ``(m,)``.
Where a formula divides by ``|c'|`` and ``c'`` vanishes, a ``ValueError`` says so.

Lesson: ``notebooks/05_curvature_of_plane_curves.ipynb`` (unit tangent, signed curvature, fundamental theorem).

Why this module is long: the formulas of seed 004 §19.2-19.3 (frame, curvature, arc-length
derivatives, the curve from its curvature) share one regularity rule and one parameter
check; the quadrature engine is already apart (:mod:`course_lib.geometry.arc_length`).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from course_lib.curves.curve import PiecewiseBezier
from course_lib.curves.parametrization import as_parametrization, check_in_domain
from course_lib.geometry.arc_length import (
    bezier_curve_length,
    breakpoints,
    gauss_legendre,
    integrate_speed,
    speed_integrals,
)
from course_lib.geometry.chain_rule import bell_row, check_chain_rule_order
from course_lib.homework import own_work
from course_lib.validation import (
    as_parameter_array,
    as_real_array,
    check_finite_scalar,
    check_integer,
    check_positive,
    scaled_norm,
)

__all__ = [
    "CurveFromCurvature",
    "arc_length",
    "arc_length_derivatives",
    "check_regular",
    "cumulative_arc_length",
    "curvature",
    "curvature_vector",
    "curve_from_curvature",
    "frame_from_derivatives",
    "osculating_circle",
    "parameter_at_arc_length",
    "point_at_arc_length",
    "signed_curvature",
    "speed",
    "unit_normal",
    "unit_tangent",
]

#: |c'| below this fraction of the curve's typical speed counts as "vanishing".
REGULARITY_RTOL = 1e-10


# ------------------------------------------------------------------ helpers
def _params(curve: object, t: object) -> tuple[np.ndarray, bool]:
    tt, scalar = as_parameter_array(t, "t")
    return check_in_domain(tt, tuple(curve.domain)), scalar  # type: ignore[attr-defined]


def typical_speed(curve) -> float:
    """A speed scale of the curve: the diagonal of its bounding box over the domain length.

    For a Bézier curve the box of the control points is used (it contains the curve);
    otherwise the box of 17 sample points.
    """
    a, b = curve.domain
    segments = getattr(curve, "segments", None)
    pts = np.vstack(segments) if segments is not None else curve.evaluate(np.linspace(a, b, 17))
    diag = float(scaled_norm(pts.max(axis=0) - pts.min(axis=0)))
    return diag / (b - a) if diag > 0 else 1.0


def check_regular(curve, t: np.ndarray, d1: np.ndarray) -> np.ndarray:
    """Speeds ``|c'|`` of first derivatives ``d1`` (shape ``(..., dim)``) taken at ``t``.

    Raises
    ------
    ValueError
        Where ``|c'|`` vanishes relative to the curve's typical speed
        (``REGULARITY_RTOL``): the unit tangent and curvature are undefined there.
        ``t`` has the leading shape of ``d1`` (or is a callable returning it, called only
        to name the place in the message).
    """
    v = scaled_norm(d1, axis=-1)
    bad = v <= REGULARITY_RTOL * typical_speed(curve)
    if np.any(bad):
        i = np.unravel_index(int(np.argmax(bad)), bad.shape)
        tt = np.asarray(t() if callable(t) else t, dtype=float)
        raise ValueError(
            f"the parametrization is not regular at t={float(tt[i]):.12g}: the first derivative "
            f"vanishes (|c'(t)| = {float(v[i]):.3g}), so the unit tangent and curvature are "
            "undefined there"
        )
    return v


def frame_from_derivatives(d1: np.ndarray, d2: np.ndarray, speed: np.ndarray | None = None):
    """Unit tangent ``T = c'/|c'|`` and curvature vector ``K = (c'' - (c''.T) T)/|c'|^2``.

    The formulas of seed 004 §19.2 applied to derivative vectors already computed, of any
    shape ``(..., dim)`` (no regularity check: see :func:`check_regular`).  Every tangent
    and curvature of the course goes through this function.

    Returns
    -------
    T, K : ndarray, each of the shape of ``d1``
    """
    own_work.require("course_lib.geometry.differential_geometry.frame_from_derivatives")
    v = np.sqrt(np.einsum("...d,...d->...", d1, d1)) if speed is None else speed
    T = d1 / v[..., None]
    K = (d2 - np.einsum("...d,...d->...", d2, T)[..., None] * T) / (v * v)[..., None]
    return T, K


# --------------------------------------------------------------- first order
def speed(curve, t: float | np.ndarray) -> float | np.ndarray:
    """Speed ``|c'(t)|`` (seed 004 §19.2: ``ds/dt``).  Zero is allowed here."""
    curve = as_parametrization(curve)
    tt, scalar = _params(curve, t)
    v = scaled_norm(curve.evaluate(tt, 1), axis=-1)
    return float(v[0]) if scalar else v


def unit_tangent(curve, t: float | np.ndarray) -> np.ndarray:
    """Unit tangent ``T = c'/|c'|`` (seed 004 §19.2; seed 000 §4, intrinsic).

    Raises
    ------
    ValueError
        If the parametrization is not regular at some ``t``.
    """
    own_work.require("course_lib.geometry.differential_geometry.unit_tangent")
    curve = as_parametrization(curve)
    tt, scalar = _params(curve, t)
    d1 = curve.evaluate(tt, 1)
    v = check_regular(curve, tt, d1)
    T = d1 / v[:, None]
    return T[0] if scalar else T


def unit_normal(curve, t: float | np.ndarray) -> np.ndarray:
    """Unit normal of a plane curve, ``N = (-T_2, T_1)`` (seed 004 §19.2): ``T`` turned by +90°."""
    curve = as_parametrization(curve)
    _require_plane(curve, "unit_normal")
    T = np.atleast_2d(unit_tangent(curve, t))
    N = np.stack([-T[:, 1], T[:, 0]], axis=-1)
    return N[0] if np.ndim(t) == 0 else N


def _require_plane(curve, what: str) -> None:
    if curve.dim != 2:
        raise ValueError(
            f"{what} is defined for plane curves (dim 2); this curve has dim {curve.dim}. "
            "Use curvature_vector or curvature for space curves"
        )


# -------------------------------------------------------------- second order
def curvature_vector(curve, t: float | np.ndarray) -> np.ndarray:
    """Curvature vector ``dT/ds = d^2c/ds^2 = (c'' - (c''.T) T) / |c'|^2`` (seed 004 §19.2).

    It points to the centre of the osculating circle and has length ``|kappa|``;
    in the plane it equals ``kappa N`` (seed 000 §6, Theorem 1: G2 = common
    unit tangent and curvature vector).
    """
    own_work.require("course_lib.geometry.differential_geometry.curvature_vector")
    curve = as_parametrization(curve)
    tt, scalar = _params(curve, t)
    d1 = curve.evaluate(tt, 1)
    d2 = curve.evaluate(tt, 2)
    _, K = frame_from_derivatives(d1, d2, check_regular(curve, tt, d1))
    return K[0] if scalar else K


def signed_curvature(curve, t: float | np.ndarray) -> float | np.ndarray:
    """Signed curvature of a plane curve, ``kappa = (x'y'' - y'x'') / |c'|^3`` (seed 004 §19.2).

    Positive where the curve turns left (towards ``N = (-T_2, T_1)``), negative
    where it turns right; ``|kappa| = 1/R`` for a circle of radius ``R``.
    """
    own_work.require("course_lib.geometry.differential_geometry.signed_curvature")
    curve = as_parametrization(curve)
    _require_plane(curve, "signed_curvature")
    tt, scalar = _params(curve, t)
    d1 = curve.evaluate(tt, 1)
    d2 = curve.evaluate(tt, 2)
    v = check_regular(curve, tt, d1)
    k = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / v**3
    return float(k[0]) if scalar else k


def curvature(curve, t: float | np.ndarray) -> float | np.ndarray:
    """Unsigned curvature ``|c' x c''| / |c'|^3`` = length of the curvature vector (2D or 3D).

    Examples
    --------
    The parabola ``y = x²`` (a quadratic Bézier curve) has curvature 2 at its vertex
    ``Q(1/2) = (0, 0)``:

    >>> from course_lib import PiecewiseBezier
    >>> parabola = PiecewiseBezier([[[-1, 1], [0, -1], [1, 1]]])
    >>> float(curvature(parabola, 0.5))
    2.0
    >>> float(curvature(PiecewiseBezier([[[0, 0], [1, 0], [2, 0]]]), 0.5))  # a straight line
    0.0
    """
    own_work.require("course_lib.geometry.differential_geometry.curvature")
    K = curvature_vector(curve, t)
    k = np.linalg.norm(np.atleast_2d(K), axis=-1)
    return float(k[0]) if np.ndim(t) == 0 else k


def osculating_circle(curve, t: float | np.ndarray) -> tuple[np.ndarray, float | np.ndarray]:
    """Centre and radius of the osculating (best-fitting) circle at ``t``.

    ``radius = 1/|kappa|`` and ``centre = c + K / |K|^2`` with ``K`` the curvature
    vector (seed 004 §19.2: ``|kappa|`` is the reciprocal of the radius of the
    best-fit circle).

    Returns
    -------
    centre : ndarray of shape (dim,) or (m, dim)
    radius : float or ndarray of shape (m,)

    Raises
    ------
    ValueError
        Where the curvature vanishes (the circle degenerates into the tangent line).
    """
    own_work.require("course_lib.geometry.differential_geometry.osculating_circle")
    curve = as_parametrization(curve)
    tt, scalar = _params(curve, t)
    K = np.atleast_2d(curvature_vector(curve, tt))
    k2 = np.sum(K * K, axis=-1)
    k_scale = 1.0 / (typical_speed(curve) * (curve.domain[1] - curve.domain[0]))
    flat = np.sqrt(k2) <= 1e-12 * k_scale
    if np.any(flat):
        bad = float(tt[np.argmax(flat)])
        raise ValueError(
            f"the curvature vanishes at t={bad:.12g}: the osculating circle degenerates "
            "into the tangent line (infinite radius)"
        )
    centre = curve.evaluate(tt) + K / k2[:, None]
    radius = 1.0 / np.sqrt(k2)
    return (centre[0], float(radius[0])) if scalar else (centre, radius)


# -------------------------------------------------------------- arc length
def cumulative_arc_length(curve, t: float | np.ndarray) -> float | np.ndarray:
    """Arc length ``s(t) = int_{t_0}^{t} |c'|`` from the start of the domain (seed 004 §19.2).

    Adaptive Gauss-Legendre quadrature on the intervals between consecutive
    requested parameters and the knots (the speed of a piecewise curve is only
    piecewise smooth), relative accuracy about 1e-13 or better.
    """
    own_work.require("course_lib.geometry.differential_geometry.cumulative_arc_length")
    curve = as_parametrization(curve)
    tt, scalar = _params(curve, t)
    a = curve.domain[0]
    grid = np.unique(np.concatenate([[a], tt, breakpoints(curve)]))
    grid = grid[grid <= max(tt.max(), a)]
    pieces = integrate_speed(curve, grid[:-1], grid[1:])
    cum = np.concatenate([[0.0], np.cumsum(pieces)])
    s = cum[np.searchsorted(grid, tt)]
    return float(s[0]) if scalar else s


def arc_length(curve, t0: float | None = None, t1: float | None = None) -> float:
    """Length ``int_{t0}^{t1} |c'(t)| dt`` of the curve between two parameters (seed 004 §19.2).

    Parameters
    ----------
    t0, t1 : float, optional
        Default to the ends of the domain.  ``t1 < t0`` gives a negative value.

    Notes
    -----
    The whole of a :class:`~course_lib.curves.curve.PiecewiseBezier` (the common case, e.g. a
    widget frame): the sum of its segment lengths, each from two fixed composite
    Gauss-Legendre rules in one vectorized evaluation, accepted when they agree to 1e-13
    and the speed stays away from zero (:mod:`course_lib.geometry.arc_length`); otherwise, and
    for any other curve or sub-interval, Gauss-Legendre with 20 nodes per interval,
    bisected until two successive levels agree to 1e-13 (relative), on each smooth piece
    (split at the knots of a :class:`~course_lib.curves.curve.PiecewiseBezier`).

    Examples
    --------
    >>> from course_lib import PiecewiseBezier
    >>> arc_length(PiecewiseBezier([[[0, 0], [3, 4]]]))
    5.0
    >>> tent = PiecewiseBezier([[[0, 0], [3, 4]], [[3, 4], [6, 0]]])
    >>> arc_length(tent, 0.0, 1.0), arc_length(tent)
    (5.0, 10.0)
    """
    own_work.require("course_lib.geometry.differential_geometry.arc_length")
    if t0 is None and t1 is None and type(curve) is PiecewiseBezier:
        return bezier_curve_length(curve)  # the hot path: nothing to validate
    curve = as_parametrization(curve)
    a, b = curve.domain
    t0 = a if t0 is None else check_finite_scalar(t0, "t0")
    t1 = b if t1 is None else check_finite_scalar(t1, "t1")
    check_in_domain(np.array([t0]), (a, b), "t0")
    check_in_domain(np.array([t1]), (a, b), "t1")
    lo, hi, sign = (t0, t1, 1.0) if t0 <= t1 else (t1, t0, -1.0)
    lo, hi = max(lo, a), min(hi, b)
    if hi <= lo:
        return 0.0
    if lo == a and hi == b and isinstance(curve, PiecewiseBezier):
        return sign * bezier_curve_length(curve)
    bp = breakpoints(curve)
    grid = np.unique(np.concatenate([[lo, hi], bp[(bp > lo) & (bp < hi)]]))
    return sign * float(integrate_speed(curve, grid[:-1], grid[1:]).sum())


def parameter_at_arc_length(curve, s: float | np.ndarray) -> float | np.ndarray:
    """Parameter ``t`` with ``s(t) = s``: the inverse of the arc-length function.

    Vectorized safeguarded Newton iteration (``dt/ds = 1/|c'|``, falling back to
    bisection in a bracketing table cell), converged to about 1e-14 of the length.

    Parameters
    ----------
    s : float or array_like
        Arc lengths in ``[0, L]``, ``L = arc_length(curve)``.

    Raises
    ------
    ValueError
        If some ``s`` lies outside ``[0, L]``.
    """
    own_work.require("course_lib.geometry.differential_geometry.parameter_at_arc_length")
    curve = as_parametrization(curve)
    ss, scalar = as_parameter_array(s, "s")
    bp = breakpoints(curve)
    per = max(8, int(np.ceil(64 / (bp.size - 1))))
    frac = np.linspace(0.0, 1.0, per + 1)[:-1]
    grid = np.append((bp[:-1, None] + np.diff(bp)[:, None] * frac).ravel(), bp[-1])
    S = np.concatenate([[0.0], np.cumsum(integrate_speed(curve, grid[:-1], grid[1:]))])
    L = S[-1]
    if not np.isfinite(L):
        raise ValueError(
            f"the arc length of the curve overflows the float range (L = {L}); rescale the curve"
        )
    tol = 1e-12 * max(L, 1e-300)
    if ss.min() < -tol or ss.max() > L + tol:
        bad = ss[(ss < -tol) | (ss > L + tol)][0]
        raise ValueError(f"s must lie in [0, L] with L = arc length = {L:.15g}; got {bad}")
    ss = np.clip(ss, 0.0, L)
    i = np.clip(np.searchsorted(S, ss, side="right") - 1, 0, grid.size - 2)
    lo, hi = grid[i].copy(), grid[i + 1].copy()
    s_lo = S[i]
    width = S[i + 1] - s_lo
    t = np.where(width > 0, lo + (ss - s_lo) / np.where(width > 0, width, 1.0) * (hi - lo), lo)
    base = grid[i]
    for _ in range(60):
        F = s_lo + speed_integrals(curve, base, t) - ss
        if np.all(np.abs(F) <= 1e-15 * L + 4e-16 * np.abs(ss)):  # relative: scale-free
            break
        lo = np.where(F < 0, t, lo)
        hi = np.where(F > 0, t, hi)
        v = scaled_norm(curve.evaluate(t, 1), axis=-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = t - F / v
        inside = (v > 0) & (newton > lo) & (newton < hi)
        t_new = np.where(inside, newton, 0.5 * (lo + hi))
        if np.all(t_new == t):
            break
        t = t_new
    return float(t[0]) if scalar else t


def point_at_arc_length(curve, s: float | np.ndarray) -> np.ndarray:
    """The point at arc length ``s`` from the start: ``c(t(s))``."""
    return as_parametrization(curve).evaluate(parameter_at_arc_length(curve, s))


# ------------------------------------------------------ arc-length derivatives
def arc_length_derivatives(curve, t: float | np.ndarray, n: int) -> np.ndarray:
    """Derivatives ``d^k c / ds^k``, ``k = 1..n``, with respect to arc length at ``t``.

    ``k = 1`` is the unit tangent, ``k = 2`` the curvature vector (seed 000 §6).
    Computed exactly from the parametric derivatives ``c', ..., c^{(n)}``: the
    derivatives of the speed ``s'(t) = sqrt(c'.c')``, then of the inverse function
    ``t(s)`` (``t' = 1/s'`` and, for ``m >= 2``, ``sum_k s^{(k)} B_{m,k}(t', ...) = 0``),
    then Faà di Bruno for ``c(t(s))``.

    Returns
    -------
    ndarray of shape (n, dim) for a scalar ``t``, or (n, m, dim)
        Row ``k - 1`` is ``d^k c/ds^k``.
    """
    own_work.require("course_lib.geometry.differential_geometry.arc_length_derivatives")
    curve = as_parametrization(curve)
    n = check_chain_rule_order(check_integer(n, "n", minimum=1), "n")
    tt, scalar = _params(curve, t)
    d = np.stack([curve.evaluate(tt, k) for k in range(n + 1)])  # (n+1, m, dim)
    v = check_regular(curve, tt, d[1])
    out = _arc_length_derivatives_from(d, v, n)
    return out[:, 0] if scalar else out


@lru_cache(maxsize=64)
def _leibniz_matrix(n: int) -> np.ndarray:
    """(n, n*n): row j holds C(j, i) at column i*n + (j - i) (Leibniz's rule for a product)."""
    from math import comb

    L = np.zeros((n, n * n))
    for j in range(n):
        for i in range(j + 1):
            L[j, i * n + (j - i)] = comb(j, i)
    L.setflags(write=False)
    return L


def _arc_length_derivatives_from(d: np.ndarray, v: np.ndarray, n: int) -> np.ndarray:
    """``d[k]`` = k-th parametric derivative (shape (n+1, m, dim)), ``v = |d[1]|``.

    Computed for the curve scaled by a power of two near ``1/v`` (exact), then scaled back
    (``d^k c/ds^k`` is homogeneous of degree ``1 - k``): no intermediate over/underflow."""
    _, e = np.frexp(v)
    d = np.ldexp(d[: n + 1], -e[None, :, None])
    A = arc_length_derivatives_unscaled(d, np.ldexp(v, -e), n)
    k = np.arange(1, n + 1)[:, None, None]
    return np.ldexp(A, (1 - k) * e[None, :, None])


def arc_length_derivatives_unscaled(d: np.ndarray, v: np.ndarray, n: int) -> np.ndarray:
    """``d^k c/ds^k``, ``k = 1..n`` (shape ``(n, m, dim)``), from the parametric derivatives ``d``
    (``(n + 1, m, dim)``) and speeds ``v = |d[1]|``, without the power-of-two scaling that
    :func:`arc_length_derivatives` applies first (callers whose joints are already scaled)."""
    from math import comb

    m = d.shape[1]
    # g = c'.c' and its derivatives g^(j) = sum_i C(j, i) c^(i+1).c^(j-i+1), j = 0..n-1
    G = np.einsum("imd,kmd->ikm", d[1 : n + 1], d[1 : n + 1]).reshape(n * n, m)
    g = _leibniz_matrix(n) @ G
    # s^(j), j = 1..n, from s'^2 = g (Leibniz): 2 s' s^(j+1) = g^(j) - sum_{i=1}^{j-1}
    # C(j, i) s^(i+1) s^(j-i+1) -- no Bell table needed
    sd = np.zeros((n + 1, m))
    sd[1] = v
    for j in range(1, n):
        acc = g[j]
        for i in range(1, j):
            acc = acc - comb(j, i) * sd[i + 1] * sd[j - i + 1]
        sd[j + 1] = acc / (2.0 * v)
    # t^(j)(s), j = 1..n, from s(t(s)) = s; B is the Bell table of t', t'', ... built row by
    # row, and at the end it composes c(t(s)) (Faà di Bruno)
    td = np.zeros((n, m))
    td[0] = 1.0 / v
    B = np.zeros((n + 1, n + 1, m))
    B[0, 0] = 1.0
    B[1, 1] = td[0]
    for j in range(2, n + 1):
        bell_row(B, td, j)
        acc = sd[2] * B[j, 2]
        for k in range(3, j + 1):
            acc = acc + sd[k] * B[j, k]
        td[j - 1] = -acc / v
        B[j, 1] = td[j - 1]
    return np.einsum("ikm,kmd->imd", B[1:, 1:], d[1 : n + 1])


# -------------------------------------------------------- fundamental theorem
class CurveFromCurvature(NamedTuple):
    """Result of :func:`curve_from_curvature`: samples of an arc-length parametrized curve."""

    s: np.ndarray
    """Arc-length samples, shape (num,), from 0 to ``length``."""
    points: np.ndarray
    """Points ``c(s)``, shape (num, 2)."""
    angle: np.ndarray
    """Tangent angle ``theta(s)`` (radians), shape (num,): ``T = (cos theta, sin theta)``."""


def _as_curvature_function(kappa: object) -> Callable[[np.ndarray], np.ndarray]:
    if callable(kappa):

        def f(s: np.ndarray) -> np.ndarray:
            flat = s.ravel()  # kappa is called with a 1-d array of arc lengths
            out = np.broadcast_to(np.asarray(kappa(flat), dtype=float), flat.shape)
            if not np.all(np.isfinite(out)):
                raise ValueError("kappa(s) must be finite on [0, length]")
            return out.reshape(s.shape)

        return f
    k0 = check_finite_scalar(kappa, "kappa")
    return lambda s: np.full(s.shape, k0)


def curve_from_curvature(
    kappa: Callable[[np.ndarray], np.ndarray] | float,
    length: float,
    start_point: tuple[float, float] | np.ndarray = (0.0, 0.0),
    start_angle: float | None = None,
    start_tangent: tuple[float, float] | np.ndarray | None = None,
    num: int = 201,
) -> CurveFromCurvature:
    """Rebuild a plane curve from its signed curvature ``kappa(s)`` (seed 004 §19.3).

    Solves ``c' = T``, ``T' = kappa N`` with ``c(0) = start_point`` and
    ``T(0) = (cos theta_0, sin theta_0)`` through the tangent angle
    ``theta(s) = theta_0 + int_0^s kappa``: then ``c(s) = c(0) + int_0^s (cos theta, sin theta)``.
    Both integrals are Gauss-Legendre quadratures (16 nodes) on each of the
    ``num - 1`` sample intervals, the inner one nested, so the samples are
    accurate to near rounding for smooth ``kappa``.

    Parameters
    ----------
    kappa : callable or float
        Signed curvature as a function of arc length, called with a 1-d array
        ``s`` and returning an array of the same length (or a constant).
    length : float
        Total arc length, > 0.
    start_point : (x, y)
    start_angle : float, optional
        Initial tangent angle in radians (default 0 unless ``start_tangent`` is given).
    start_tangent : (x, y), optional
        Initial tangent direction (normalized here); exclusive with ``start_angle``.
    num : int
        Number of samples, >= 2.

    Returns
    -------
    CurveFromCurvature
        Named tuple ``(s, points, angle)``.
    """
    f = _as_curvature_function(kappa)
    length = check_positive(length, "length")
    num = check_integer(num, "num", minimum=2)
    p0 = as_real_array(start_point, "start_point", "a real 2-d point")
    if p0.shape != (2,) or not np.all(np.isfinite(p0)):
        raise ValueError(f"start_point must be a finite 2-d point; got {start_point!r}")
    if start_angle is not None and start_tangent is not None:
        raise ValueError("give start_angle or start_tangent, not both")
    if start_tangent is not None:
        v = as_real_array(start_tangent, "start_tangent", "a real 2-d vector")
        if v.shape != (2,) or not np.all(np.isfinite(v)) or np.hypot(*v) == 0:
            raise ValueError(
                f"start_tangent must be a finite nonzero 2-d vector; got {start_tangent!r}"
            )
        theta0 = float(np.arctan2(v[1], v[0]))
    else:
        theta0 = 0.0 if start_angle is None else check_finite_scalar(start_angle, "start_angle")

    x, w = gauss_legendre(16)
    s = np.linspace(0.0, length, num)
    a, b = s[:-1], s[1:]
    h = 0.5 * (b - a)
    # theta at the samples: theta_i = theta_0 + sum of int kappa over previous intervals
    nodes = (0.5 * (a + b))[:, None] + h[:, None] * x[None, :]  # (num-1, 16)
    dtheta = h * (f(nodes) @ w)
    theta = theta0 + np.concatenate([[0.0], np.cumsum(dtheta)])
    # theta at the GL nodes of each interval: theta_i + int_{a_i}^{node} kappa (nested GL)
    hn = 0.5 * (nodes - a[:, None])  # (num-1, 16)
    inner = (0.5 * (nodes + a[:, None]))[..., None] + hn[..., None] * x  # (num-1, 16, 16)
    theta_nodes = theta[:-1, None] + hn * (f(inner) @ w)
    dx = h * (np.cos(theta_nodes) @ w)
    dy = h * (np.sin(theta_nodes) @ w)
    pts = np.empty((num, 2))
    pts[0] = p0
    pts[1:] = p0 + np.cumsum(np.stack([dx, dy], axis=-1), axis=0)
    return CurveFromCurvature(s, pts, theta)
