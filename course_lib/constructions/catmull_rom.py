"""Catmull-Rom splines with the shape parameter β1 (seed 000 §9, eq. (13)-(14)).

Segment ``i`` interpolates ``V_i`` and ``V_{i+1}`` and is a blend of
``V_{i-1} .. V_{i+2}`` (eq. (13))::

    q_i(u) = φ_{-1}(u) V_{i-1} + φ_0(u) V_i + φ_1(u) V_{i+1} + φ_2(u) V_{i+2}.

With one global β1 the weights are seed 000 eq. (14.1)-(14.4); the transcription is
correct (tests/unit/test_catmull_rom.py::test_eq_14_symbolic proves interpolation,
partition of unity and ``q_{i+1}'(0) = β1 q_i'(1)`` with sympy).

Local shape parameters (one β1 per interpolated vertex).  Differentiating eq. (14)
shows that the curve is the cubic Hermite interpolant with the derivative on the
right of vertex ``V_j``

.. math:: D_j^+ = \\frac{(V_{j+1} - V_j) + β_1^2 (V_j - V_{j-1})}{1 + β_1},
          \\qquad D_j^- = D_j^+ / β_1

on its left, so ``r'(0) = β1 q'(1)`` holds at each vertex by construction.  Both
derivatives involve only the β1 *of that vertex*, so β1 can vary from joint to
joint: segment ``i`` then depends on ``β1`` at its two ends ``V_i`` and ``V_{i+1}``
(its four blending functions carry both), and with equal values it reduces to
eq. (14) (test: ``::test_local_beta1_reduces_to_eq_14``).  The Bézier form of
segment ``i`` is ``V_i, V_i + D_i^+/3, V_{i+1} - D_{i+1}^-/3, V_{i+1}``.

The weights φ_{-1}, φ_2 are negative on ``(0, 1)``: Catmull-Rom curves do *not*
have the convex hull property (test: ``::test_convex_hull_fails``).

Lesson: ``notebooks/07_stitching_bezier_curves.ipynb``.
"""

from __future__ import annotations

import numpy as np

from course_lib.curves.curve import PiecewiseBezier
from course_lib.validation import (
    as_parameter_array,
    as_points,
    as_real_array,
    check_shape_parameters,
    scaled_norm,
)

__all__ = ["catmull_rom", "catmull_rom_blending"]


def catmull_rom_blending(
    u: float | np.ndarray, beta1: float = 1.0, beta1_end: float | None = None
) -> np.ndarray:
    """The weights ``φ_{-1}, φ_0, φ_1, φ_2`` of ``V_{i-1} .. V_{i+2}`` in segment ``i``.

    With one global β1 these are seed 000 eq. (14.1)-(14.4).  With local shape
    parameters, ``beta1`` is the value at the segment's start ``V_i`` (``a``) and
    ``beta1_end`` at its end ``V_{i+1}`` (``b``); in cubic Hermite form
    (``h00 = 2u³-3u²+1``, ``h10 = u³-2u²+u``, ``h01 = -2u³+3u²``, ``h11 = u³-u²``)::

        φ_{-1} = -a²/(1+a) h10,          φ_0 = h00 + (a-1) h10 - b/(1+b) h11,
        φ_1 = h01 + h10/(1+a) + (b-1)/b h11,   φ_2 = h11 / (b(1+b)),

    which for ``a = b`` is eq. (14) (test: ``test_catmull_rom.py::test_eq_14_symbolic``).

    Parameters
    ----------
    u : float or array_like of shape (m,)
    beta1 : float
        ``β1 > 0`` (global, or at the segment's start).
    beta1_end : float, optional
        ``β1 > 0`` at the segment's end (default: ``beta1``).

    Returns
    -------
    ndarray of shape (4,) or (m, 4)

    Examples
    --------
    At ``u = 0`` the curve is at ``V_i``; the weights always sum to 1:

    >>> catmull_rom_blending(0.0) + 0.0
    array([0., 1., 0., 0.])
    >>> round(float(catmull_rom_blending(0.3, beta1=2.0).sum()), 12)
    1.0
    """
    a = float(check_shape_parameters(beta1, "beta1", 1, positive=True)[0])
    b = (
        a
        if beta1_end is None
        else float(check_shape_parameters(beta1_end, "beta1_end", 1, positive=True)[0])
    )
    uu, scalar = as_parameter_array(u, "u")
    u2, u3 = uu**2, uu**3
    h00, h10 = 2 * u3 - 3 * u2 + 1, u3 - 2 * u2 + uu
    h01, h11 = -2 * u3 + 3 * u2, u3 - u2
    out = np.empty((uu.size, 4))
    out[:, 0] = -(a**2) / (1 + a) * h10
    out[:, 1] = h00 + (a - 1) * h10 - b / (1 + b) * h11
    out[:, 2] = h01 + h10 / (1 + a) + (b - 1) / b * h11
    out[:, 3] = h11 / (b * (1 + b))
    return out[0] if scalar else out


def _vertex_betas(beta1: object, n_vertices: int, n_joints: int) -> np.ndarray:
    """β1 at the interpolated vertices V_1 .. V_{m-1}: scalar, one per vertex, or per joint."""
    arr = as_real_array(beta1, "beta1", "a real number or an array of them")
    if arr is not None and arr.ndim == 1 and arr.size == n_joints and n_joints != n_vertices:
        b = check_shape_parameters(beta1, "beta1", n_joints, positive=True)
        return np.concatenate([[1.0], b, [1.0]])
    if arr is not None and arr.ndim == 1 and arr.size not in (n_vertices, n_joints):
        raise ValueError(
            f"beta1 must be a scalar, one value per interior joint ({n_joints}) or one per "
            f"interpolated vertex V_1..V_(m-1) ({n_vertices}); got {arr.size}"
        )
    b = check_shape_parameters(beta1, "beta1", n_vertices, positive=False)
    if np.any(b <= 0):
        j = int(np.argmax(b <= 0))
        raise ValueError(f"beta1 must be > 0 at every vertex; at V_{j + 1} it is {b[j]}")
    return b


def catmull_rom(V: np.ndarray, beta1: float | np.ndarray = 1.0) -> PiecewiseBezier:
    """Catmull-Rom spline with shape parameter(s) β1 as cubic Bézier segments (seed 000 §9).

    Parameters
    ----------
    V : array_like of shape (m + 1, dim), ``m >= 3``
        Control polygon.  The curve interpolates ``V_1 .. V_{m-1}``; ``V_0`` and
        ``V_m`` only steer the end tangents.  Segment ``i - 1`` (``i = 1..m-2``)
        runs from ``V_i`` to ``V_{i+1}`` and uses ``V_{i-1} .. V_{i+2}``.
    beta1 : float or array_like
        ``β1 > 0``: a scalar (global, seed eq. (14)), one value per interior joint
        ``V_2 .. V_{m-2}`` (``m - 3`` values; the curve ends use 1), or one value per
        interpolated vertex ``V_1 .. V_{m-1}`` (``m - 1`` values; at the two curve
        ends β1 only scales the end tangent).

    Returns
    -------
    PiecewiseBezier
        ``m - 2`` cubic segments.  ``info``: ``beta1`` (per interior joint),
        ``beta1_vertices`` (at ``V_1 .. V_{m-1}``), ``tangents_right`` (``D_j^+``).

    Raises
    ------
    ValueError
        Fewer than 4 control points; β1 <= 0 or wrong length (naming the joint); β1 so
        large or small that the tangents overflow (never an inf in the result);
        a vanishing tangent ``D_j^+ = 0`` at an interpolated vertex (e.g. coincident
        consecutive control points), naming the vertex.

    Examples
    --------
    Five points give two segments, interpolating ``V_1, V_2, V_3``:

    >>> import numpy as np
    >>> V = np.array([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]])
    >>> curve = catmull_rom(V, beta1=2.0)
    >>> curve.n_segments, curve.degrees
    (2, (3, 3))
    >>> curve.joint_points
    array([[2., 0.]])
    """
    P = as_points(V, "V", min_points=4)
    m = P.shape[0] - 1
    b = _vertex_betas(beta1, m - 1, m - 3)  # at V_1 .. V_{m-1}
    prev, here, nxt = P[:-2], P[1:-1], P[2:]
    w = 1.0 / (1.0 + b)  # D+ = (V_{j+1} - V_j)/(1 + β1) + β1/(1 + β1) β1 (V_j - V_{j-1}):
    with np.errstate(over="ignore", invalid="ignore"):  # no β1² (it overflows first)
        Dp = w[:, None] * (nxt - here) + (b * w)[:, None] * (b[:, None] * (here - prev))
        Dm = Dp / b[:, None]
    huge = ~np.all(np.isfinite(Dp) & np.isfinite(Dm), axis=1)
    if np.any(huge):
        j = int(np.argmax(huge)) + 1
        raise ValueError(
            f"beta1 = {b[j - 1]} at V_{j} makes the curve leave the float range: the tangents "
            f"D+ ~ beta1 |V_{j} - V_{j - 1}| and D- = D+ / beta1 overflow (the Catmull-Rom "
            "curve has no finite limit as beta1 -> 0 or infinity); choose a moderate beta1"
        )
    scale = float(np.max(np.abs(P)))
    bad = scaled_norm(Dp, axis=1) <= 1e-12 * scale
    if np.any(bad):
        j = int(np.argmax(bad)) + 1
        raise ValueError(
            f"the tangent at V_{j} vanishes (V_{j - 1}, V_{j}, V_{j + 1} with beta1 = "
            f"{b[j - 1]} give D = 0, e.g. coincident consecutive control points): the curve "
            f"would not be regular at V_{j}"
        )
    segs = np.empty((m - 2, 4, P.shape[1]))
    segs[:, 0] = P[1:-2]
    segs[:, 1] = P[1:-2] + Dp[:-1] / 3
    segs[:, 2] = P[2:-1] - Dm[1:] / 3
    segs[:, 3] = P[2:-1]
    info = {"beta1": b[1:-1].copy(), "beta1_vertices": b, "tangents_right": Dp}
    return PiecewiseBezier.from_trusted_segments(list(segs), info=info)
