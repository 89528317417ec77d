"""Stitching two Bézier curves with G1 or G2 continuity (seed 000 §8, eq. (9)-(12)).

The left curve ``q`` has the control polygon ``V_0 .. V_d``; the right curve ``r``
has ``W_0 .. W_d`` (same degree ``d >= 2``).  Putting the Bézier end derivatives
(seed 000 eq. (8.1)-(8.3)) into the Beta-constraints (eq. (7.1)-(7.2)) fixes

* ``W_0 = V_d`` (G0) and ``W_1 = V_d + β1 (V_d - V_{d-1})`` (G1, eq. (9), (10)),
* ``W_2 = 2 W_1 - W_0 + β1² (V_{d-2} - 2 V_{d-1} + V_d) + β2 (V_d - V_{d-1}) / (d - 1)``
  (G2, eq. (11a); expanded in eq. (11b)),

and leaves ``W_2 .. W_d`` (G1) or ``W_3 .. W_d`` (G2) free.  Farin and Boehm's
construction (eq. (12.1)-(12.5)) produces the same ``W_2`` through an auxiliary
point ``T`` on the line ``V_{d-2} V_{d-1}``:
``T = V_{d-1} + β1² γ (V_{d-1} - V_{d-2})`` and ``W_2 = W_1 + (W_1 - T) / γ`` with
``γ = (d-1)(1+β1) / (β2 + β1 (d-1)(1+β1))``.  The transcription of eq. (12.1)-(12.5)
is correct: expanding it gives eq. (11b) exactly (sympy proof:
``tests/unit/test_stitching.py::test_farin_boehm_factorizes_eq_11b_symbolically``).

Any order: :func:`gn_stitch_points` fixes ``W_0 .. W_n`` from the Beta-constraints of
orders ``0..n`` (seed 000 eq. (6)) with the Bézier end derivatives, one point per order:
``W_i = (d-i)!/d! r^{(i)}(0) - sum_{j<i} (-1)^{i-j} C(i, j) W_j``; for ``n = 1, 2`` it is
eq. (10) and (11a).

Lesson: ``notebooks/07_stitching_bezier_curves.ipynb``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from course_lib.curves.curve import PiecewiseBezier
from course_lib.homework import own_work
from course_lib.validation import (
    as_points,
    as_real_array,
    check_finite_scalar,
    check_integer,
    check_positive,
)

__all__ = [
    "FarinBoehm",
    "farin_boehm",
    "farin_boehm_gamma",
    "g1_stitch",
    "g1_stitch_points",
    "g2_stitch",
    "g2_stitch_points",
    "gn_stitch",
    "gn_stitch_points",
]


def _check_regular_end(V: np.ndarray, name: str) -> None:
    """The direction V_{d-1} -> V_d is needed: reject coincident last two points."""
    scale = max(float(np.max(np.abs(V))), 1.0)
    if np.linalg.norm(V[-1] - V[-2]) <= 1e-12 * scale:
        raise ValueError(
            f"{name}[-2] and {name}[-1] coincide: the end tangent q'(1) = d (V_d - V_(d-1)) "
            "vanishes, so the joint has no tangent direction to continue (G1 needs a regular q)"
        )


def _polygon(V: object, name: str = "V", min_points: int = 3) -> np.ndarray:
    P = as_points(V, name, min_points=min_points)
    _check_regular_end(P, name)
    return P


def g1_stitch_points(V: np.ndarray, beta1: float) -> np.ndarray:
    """``W_0, W_1`` that make ``r`` continue ``q`` with G1 for shape parameter ``beta1``.

    Seed 000 eq. (10.1)-(10.2): ``W_0 = V_d``, ``W_1 = W_0 + β1 (V_d - V_{d-1})``.

    Parameters
    ----------
    V : array_like of shape (d + 1, dim)
        Control polygon of the left curve ``q``, ``d >= 1``.
    beta1 : float
        ``β1 > 0``.

    Returns
    -------
    ndarray of shape (2, dim)
    """
    own_work.require("course_lib.constructions.stitching.g1_stitch_points")
    P = _polygon(V, min_points=2)  # eq. (9)-(10) use only V_(d-1), V_d: d = 1 works
    b1 = check_positive(beta1, "beta1")
    return np.array([P[-1], P[-1] + b1 * (P[-1] - P[-2])])


def g2_stitch_points(V: np.ndarray, beta1: float, beta2: float) -> np.ndarray:
    """``W_0, W_1, W_2`` for G2 continuity with ``β1, β2`` (seed 000 eq. (9), (11a)).

    Defined for every real ``β2`` (eq. (11a) has no denominator besides ``d - 1``).

    Returns
    -------
    ndarray of shape (3, dim)
    """
    own_work.require("course_lib.constructions.stitching.g2_stitch_points")
    P = _polygon(V)
    b1 = check_positive(beta1, "beta1")
    b2 = check_finite_scalar(beta2, "beta2")
    return _g2_points(P, b1, b2)


def _g2_points(P: np.ndarray, b1: float, b2: float) -> np.ndarray:
    own_work.require("course_lib.constructions.stitching._g2_points")
    d = P.shape[0] - 1
    W0 = P[-1]
    W1 = W0 + b1 * (P[-1] - P[-2])
    W2 = 2 * W1 - W0 + b1**2 * (P[-3] - 2 * P[-2] + P[-1]) + b2 * (P[-1] - P[-2]) / (d - 1)
    return np.array([W0, W1, W2])


def _rest(W_rest: object, count: int, dim: int, what: str) -> np.ndarray:
    if W_rest is None:
        if count:
            raise ValueError(
                f"W_rest must give the {count} free control point(s) of r left by {what}; got None"
            )
        return np.zeros((0, dim))
    R = as_real_array(W_rest, "W_rest", "an array of points (real numbers)")
    if R.size == 0 and count == 0:
        return np.zeros((0, dim))
    R = as_points(W_rest, "W_rest", min_points=1)
    if R.shape[0] != count or R.shape[1] != dim:
        raise ValueError(
            f"W_rest must have shape ({count}, {dim}) (the free points of r after {what}, "
            f"same degree and dimension as V); got {R.shape}"
        )
    return R


def g1_stitch(V: np.ndarray, beta1: float, W_rest: np.ndarray) -> PiecewiseBezier:
    """Two-segment curve ``q, r`` meeting with G1 (seed 000 eq. (9)-(10)).

    Parameters
    ----------
    V : array_like of shape (d + 1, dim)
        Control polygon of ``q``, ``d >= 1`` (eq. (9)-(10) use only ``V_{d-1}, V_d``).
    beta1 : float
        ``β1 > 0``.
    W_rest : array_like of shape (d - 1, dim)
        The free control points ``W_2 .. W_d`` of ``r`` (``None`` or empty for ``d = 1``).

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1`` (one value), ``W01`` (the constructed ``W_0, W_1``).

    Examples
    --------
    ``W_1`` goes on the ray from ``V_2`` through ``V_3``, ``β1`` times as far:

    >>> import numpy as np
    >>> V = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
    >>> curve = g1_stitch(V, 2.0, np.array([[7.0, 3.0], [8.0, 0.0]]))
    >>> curve.segments[1][1]
    array([ 5., -2.])
    """
    own_work.require("course_lib.constructions.stitching.g1_stitch")
    P = _polygon(V, min_points=2)
    W = g1_stitch_points(P, beta1)
    R = _rest(W_rest, P.shape[0] - 2, P.shape[1], "G1 fixed W_0, W_1")
    info = {"beta1": np.array([float(beta1)]), "W01": W}
    return PiecewiseBezier.from_trusted_segments([P, np.vstack([W, R])], info=info)


def g2_stitch(
    V: np.ndarray, beta1: float, beta2: float, W_rest: np.ndarray | None = None
) -> PiecewiseBezier:
    """Two-segment curve ``q, r`` meeting with G2 (seed 000 eq. (9), (11a)).

    Parameters
    ----------
    W_rest : array_like of shape (d - 2, dim)
        The free points ``W_3 .. W_d`` (``None`` or empty for ``d = 2``).

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1``, ``beta2`` (one value each), ``W012``, and Farin-Boehm's
        ``T`` and ``gamma`` when γ is defined.

    Examples
    --------
    With ``β1 = 1`` and ``β2 = 0`` G2 stitching is C2 stitching (the last point is free):

    >>> import numpy as np
    >>> V = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
    >>> g2_stitch(V, 1.0, 0.0, np.array([[6.0, 0.0]])).segments[1]
    array([[ 3.,  0.],
           [ 4., -1.],
           [ 5., -3.],
           [ 6.,  0.]])
    """
    own_work.require("course_lib.constructions.stitching.g2_stitch")
    P = _polygon(V)
    W = g2_stitch_points(P, beta1, beta2)
    R = _rest(W_rest, P.shape[0] - 3, P.shape[1], "G2 fixed W_0, W_1, W_2")
    info = {"beta1": np.array([float(beta1)]), "beta2": np.array([float(beta2)]), "W012": W}
    d = P.shape[0] - 1
    den = float(beta2) + float(beta1) * (d - 1) * (1 + float(beta1))
    if den != 0.0:  # Farin-Boehm's T and gamma (eq. (12.1), (12.4)) when defined
        g = (d - 1) * (1 + float(beta1)) / den
        info["gamma"] = g
        info["T"] = P[-2] + float(beta1) ** 2 * g * (P[-2] - P[-3])
    return PiecewiseBezier.from_trusted_segments([P, np.vstack([W, R])], info=info)


def farin_boehm_gamma(beta1: float, beta2: float, d: int = 3, *, joint: int | None = None) -> float:
    """``γ = (d-1)(1+β1) / (β2 + β1 (d-1)(1+β1))`` (seed 000 eq. (12.1)).

    Raises
    ------
    ValueError
        If ``β1 <= 0``, or ``β2 = -β1 (d-1)(1+β1)`` (denominator zero: γ undefined;
        the message names ``beta2`` and, if given, the joint).
    """
    own_work.require("course_lib.constructions.stitching.farin_boehm_gamma")
    at = "" if joint is None else f" at joint {joint}"
    b1 = check_finite_scalar(beta1, "beta1")
    if b1 <= 0:
        raise ValueError(f"beta1 must be > 0{at}; got {b1}")
    b2 = check_finite_scalar(beta2, "beta2")
    d = check_integer(d, "d", minimum=2)
    den = b2 + b1 * (d - 1) * (1 + b1)
    if abs(den) <= 1e-12 * max(1.0, abs(b2), b1 * (d - 1) * (1 + b1)):
        raise ValueError(
            f"beta2 = {b2}{at} makes gamma undefined: beta2 + beta1 (d-1)(1+beta1) = 0 "
            f"(seed 000 eq. (12.1)); choose beta2 != {-b1 * (d - 1) * (1 + b1)}"
        )
    return (d - 1) * (1 + b1) / den


@dataclass(frozen=True)
class FarinBoehm:
    """Result of :func:`farin_boehm`: ``W`` = ``(W_0, W_1, W_2)``, the point ``T``, ``gamma``.

    Where γ is undefined (``β2 = -β1 (d-1)(1+β1)``) ``T`` is at infinity: ``gamma`` is
    ``inf``, ``T`` is ``None`` and ``T_at_infinity`` is True (``W`` is still finite).
    """

    W: np.ndarray
    T: np.ndarray | None
    gamma: float

    @property
    def T_at_infinity(self) -> bool:
        return self.T is None


def farin_boehm(
    V_last3: np.ndarray, beta1: float, beta2: float, d: int, *, at_infinity: str = "raise"
) -> FarinBoehm:
    """Farin-Boehm construction of ``W_0, W_1, W_2`` (seed 000 eq. (12.1)-(12.5)).

    Parameters
    ----------
    V_last3 : array_like of shape (3, dim)
        ``V_{d-2}, V_{d-1}, V_d`` of the left curve.
    beta1, beta2 : float
        Shape parameters, ``β1 > 0``.
    d : int
        Degree of both curves (``>= 2``).
    at_infinity : {"raise", "report"}
        Where γ is undefined (``β2 = -β1 (d-1)(1+β1)``), T is at infinity but ``W`` is
        finite: ``"report"`` returns it with ``T = None``, ``gamma = inf``,
        ``T_at_infinity = True``; ``"raise"`` (default, the historical behaviour that
        the widgets rely on) raises the ValueError of :func:`farin_boehm_gamma`.

    Returns
    -------
    FarinBoehm
        ``T = V_{d-1} + β1² γ (V_{d-1} - V_{d-2})``, ``W_2 = W_1 + (W_1 - T)/γ``, computed
        without the pole of γ as ``W_2 = W_1 + (W_1 - V_{d-1})/γ - β1² (V_{d-1} - V_{d-2})``
        (the same point, eq. (11a)).  Where γ is undefined, ``T`` is at infinity: the
        result has ``gamma = inf``, ``T = None``, ``T_at_infinity = True``.

    Raises
    ------
    ValueError
        If ``β1 <= 0``, ``V_{d-1} = V_d``, or γ is undefined and ``at_infinity="raise"``.
    """
    own_work.require("course_lib.constructions.stitching.farin_boehm")
    P = as_points(V_last3, "V_last3", min_points=3)
    if P.shape[0] != 3:
        raise ValueError(
            f"V_last3 must hold exactly 3 points V_(d-2), V_(d-1), V_d; got {P.shape[0]}"
        )
    _check_regular_end(P, "V_last3")
    b1 = check_positive(beta1, "beta1")
    b2 = check_finite_scalar(beta2, "beta2")
    d = check_integer(d, "d", minimum=2)
    den = b2 + b1 * (d - 1) * (1 + b1)
    inv_g = den / ((d - 1) * (1 + b1))  # 1/γ, no pole
    W0 = P[2]
    W1 = W0 + b1 * (P[2] - P[1])
    W2 = W1 + inv_g * (W1 - P[1]) - b1**2 * (P[1] - P[0])
    if at_infinity not in ("raise", "report"):
        raise ValueError(f"at_infinity must be 'raise' or 'report'; got {at_infinity!r}")
    if abs(den) <= 1e-12 * max(1.0, abs(b2), b1 * (d - 1) * (1 + b1)):
        if at_infinity == "raise":
            farin_boehm_gamma(b1, b2, d)  # raises, naming beta2
        return FarinBoehm(np.array([W0, W1, W2]), None, math.inf)
    g = (d - 1) * (1 + b1) / den
    T = P[1] + b1**2 * g * (P[1] - P[0])
    return FarinBoehm(np.array([W0, W1, W2]), T, g)


def gn_stitch_points(V: np.ndarray, betas: object) -> np.ndarray:
    """``W_0 .. W_n`` that make ``r`` continue ``q`` with G^n for ``β_1 .. β_n``.

    The Beta-constraints ``r^{(i)}(0) = sum_k B_{i,k}(β) q^{(k)}(1)`` (seed 000 eq. (6))
    with the Bézier end derivatives ``q^{(k)}(1) = d!/(d-k)! ∇^k V_d`` and ``r^{(i)}(0) =
    d!/(d-i)! Δ^i W_0`` (eq. (8)) fix one new point per order.  ``n = 1, 2`` give eq. (10)
    and (11a) (tested equal to :func:`g1_stitch_points`, :func:`g2_stitch_points`).

    Parameters
    ----------
    V : array_like of shape (d + 1, dim)
        Control polygon of the left curve ``q``, ``d >= n`` (``r`` has the same degree).
    betas : sequence of n floats
        ``β_1 > 0, β_2, ..., β_n`` (``n <= MAX_CHAIN_RULE_ORDER``).

    Returns
    -------
    ndarray of shape (n + 1, dim)
    """
    own_work.require("course_lib.constructions.stitching.gn_stitch_points")
    from math import comb, factorial

    from course_lib.geometry.beta_constraints import apply_beta_constraints

    b = as_real_array(betas, "betas", "a sequence (beta1, ..., betan) of real numbers")
    if b.ndim != 1 or b.size == 0:
        raise ValueError(
            f"betas must be a sequence (beta1, ..., betan), n >= 1; got shape {b.shape}"
        )
    n = b.size
    P = _polygon(V, min_points=2)
    d = P.shape[0] - 1
    if n > d:
        raise ValueError(f"G^{n} stitching needs degree d >= n = {n}; V has degree {d}")
    if not b[0] > 0:
        raise ValueError(f"beta1 must be > 0; got {b[0]}")
    q = np.stack([_backward(P, k) * (factorial(d) / factorial(d - k)) for k in range(1, n + 1)])
    r = apply_beta_constraints(q, b)  # r^(1..n)(0)
    W = [P[-1]]
    for i in range(1, n + 1):
        acc = r[i - 1] * (factorial(d - i) / factorial(d))
        for j in range(i):
            acc = acc - (-1) ** (i - j) * comb(i, j) * W[j]
        W.append(acc)
    return np.array(W)


def _backward(P: np.ndarray, k: int) -> np.ndarray:
    """``∇^k V_d = sum_j (-1)^j C(k, j) V_{d-j}``."""
    from math import comb

    return sum((-1) ** j * comb(k, j) * P[-1 - j] for j in range(k + 1))


def gn_stitch(V: np.ndarray, betas: object, W_rest: np.ndarray | None = None) -> PiecewiseBezier:
    """Two-segment curve ``q, r`` meeting with G^n for ``β_1 .. β_n`` (seed 000 eq. (6), (8)).

    Parameters
    ----------
    W_rest : array_like of shape (d - n, dim)
        The free points ``W_{n+1} .. W_d`` (``None`` or empty for ``d = n``).

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1 .. beta{n}`` (one value each), ``betas``, ``W_fixed``.
    """
    own_work.require("course_lib.constructions.stitching.gn_stitch")
    P = _polygon(V, min_points=2)
    W = gn_stitch_points(P, betas)
    n = W.shape[0] - 1
    R = _rest(W_rest, P.shape[0] - 1 - n, P.shape[1], f"G{n} fixed W_0 .. W_{n}")
    b = tuple(float(x) for x in np.asarray(betas, dtype=float))
    info: dict[str, object] = {f"beta{i + 1}": np.array([x]) for i, x in enumerate(b)}
    info["betas"] = b
    info["W_fixed"] = W
    return PiecewiseBezier.from_trusted_segments([P, np.vstack([W, R])], info=info)
