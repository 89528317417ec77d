"""Finn's G1 cubic Bézier splines from control points and a knot sequence (seed 004 §19.5-19.7).

Given ``2L + 2`` control points ``d_{-1}, d_0, ..., d_{2L}`` and knots
``t_0 < t_1 < ... < t_L``, the piecewise cubic Bézier control points are
(seed 004 §19.6)::

    p_0 = d_{-1},  p_{3i+1} = d_{2i},  p_{3i+2} = d_{2i+1}  (i = 0..L-1),  p_{3L} = d_{2L},
    p_{3i} = ((t_{i+1} - t_i) p_{3i-1} + (t_i - t_{i-1}) p_{3i+1}) / (t_{i+1} - t_{i-1})
             (i = 1..L-1),

so the joint ``p_{3i}`` divides ``p_{3i-1} p_{3i+1}`` as ``t_i`` divides
``[t_{i-1}, t_{i+1}]``.  Segment ``i`` (``p_{3i} .. p_{3i+3}``) lives on
``[t_i, t_{i+1}]`` of the global parameter (seed 004 §19.7).

Derived here (and tested): with local parameters the joint ``i`` satisfies the
Beta-constraint (7.1) with ``β1_i = (t_{i+1} - t_i) / (t_i - t_{i-1})``, and in the
global parameter the chain-rule factors ``1/(t_{i+1} - t_i)`` cancel that ratio, so
the spline is C1 in ``t`` (seed 004 exercise 3).  Uniform knots give the midpoint rule
of the C1 Bézier spline.

Lesson: ``notebooks/06_g1_knot_bezier_splines.ipynb``.
"""

from __future__ import annotations

import numpy as np

from course_lib.curves.curve import PiecewiseBezier
from course_lib.homework import own_work
from course_lib.validation import as_points, check_knots

__all__ = ["bezier_points_from_g1", "g1_knot_spline", "knot_ratio_beta1"]


def knot_ratio_beta1(knots: np.ndarray) -> np.ndarray:
    """β1 at each interior joint: ``(t_{i+1} - t_i) / (t_i - t_{i-1})``, ``i = 1..L-1``.

    Returns
    -------
    ndarray of shape (L - 1,)
        Entry ``k`` belongs to joint ``k`` of the curve (the knot ``t_{k+1}``).

    Examples
    --------
    >>> import numpy as np
    >>> knot_ratio_beta1(np.array([0.0, 1.0, 3.0, 4.0]))
    array([2. , 0.5])
    """
    own_work.require("course_lib.constructions.knot_splines.knot_ratio_beta1")
    t = check_knots(knots, "knots")
    h = np.diff(t)
    return h[1:] / h[:-1]


def _inputs(d_points: object, knots: object) -> tuple[np.ndarray, np.ndarray, int]:
    D = as_points(d_points, "d_points", min_points=4)
    if D.shape[0] % 2:
        raise ValueError(
            f"d_points must hold 2L + 2 points d_(-1) .. d_(2L) (an even number); got {D.shape[0]}"
        )
    L = (D.shape[0] - 2) // 2
    t = check_knots(knots, "knots")
    if t.size != L + 1:
        raise ValueError(
            f"knots must have L + 1 = {L + 1} values t_0 < ... < t_L for {D.shape[0]} control "
            f"points (2L + 2 with L = {L}); got {t.size}"
        )
    return D, t, L


def _joint_points(D: np.ndarray, t: np.ndarray, L: int) -> np.ndarray:
    own_work.require("course_lib.constructions.knot_splines._joint_points")
    P = np.empty((3 * L + 1, D.shape[1]))
    P[0] = D[0]
    P[3 * L] = D[-1]
    P[1::3] = D[1:-1:2]  # p_{3i+1} = d_{2i}   (D[k] = d_{k-1})
    P[2::3] = D[2:-1:2]  # p_{3i+2} = d_{2i+1}
    if L > 1:
        left, right = P[2 : 3 * L - 1 : 3], P[4 : 3 * L + 1 : 3]  # p_{3i-1}, p_{3i+1}
        scale = max(float(np.max(np.abs(D))), 1.0)
        bad = np.linalg.norm(right - left, axis=1) <= 1e-12 * scale
        if np.any(bad):
            i = int(np.argmax(bad)) + 1
            raise ValueError(
                f"d_points: p_{3 * i - 1} = d_{2 * i - 1} and p_{3 * i + 1} = d_{2 * i} coincide, "
                f"so joint {i - 1} (knot t_{i}) has no tangent direction"
            )
        h = np.diff(t)
        w_left = (h[1:] / (h[1:] + h[:-1]))[:, None]  # (t_{i+1} - t_i) / (t_{i+1} - t_{i-1})
        P[3 : 3 * L : 3] = w_left * left + (1 - w_left) * right
    return P


def bezier_points_from_g1(d_points: np.ndarray, knots: np.ndarray) -> np.ndarray:
    """The C0 Bézier control points ``p_0 .. p_{3L}`` of Finn's G1 spline (seed 004 §19.6).

    Parameters
    ----------
    d_points : array_like of shape (2L + 2, dim)
        ``d_{-1}, d_0, ..., d_{2L}``, ``L >= 1``.
    knots : array_like of shape (L + 1,)
        Strictly increasing ``t_0 < ... < t_L``.

    Returns
    -------
    ndarray of shape (3L + 1, dim)

    Raises
    ------
    ValueError
        Odd number of points, fewer than 4, knots not strictly increasing or of the
        wrong length, coincident ``p_{3i-1} = p_{3i+1}`` (no tangent at a joint).
    """
    own_work.require("course_lib.constructions.knot_splines.bezier_points_from_g1")
    return _joint_points(*_inputs(d_points, knots))


def g1_knot_spline(d_points: np.ndarray, knots: np.ndarray) -> PiecewiseBezier:
    """Finn's G1 cubic Bézier spline, parametrized by the knots (seed 004 §19.6-19.7).

    Returns
    -------
    PiecewiseBezier
        ``L`` cubic segments with ``knots`` as global parameter (C1 in ``t``).
        ``info``: ``beta1`` (knot ratios per joint), ``junction_points``
        (``p_3 .. p_{3L-3}``), ``d_points``.

    Examples
    --------
    Two segments (knots 0, 1, 3) from ``2L + 2 = 6`` points:

    >>> import numpy as np
    >>> d = np.array([[0, 0], [1, 2], [3, 2], [4, 0], [6, 1], [7, 3]])
    >>> curve = g1_knot_spline(d, np.array([0.0, 1.0, 3.0]))
    >>> curve.n_segments, curve.degrees, curve.knots
    (2, (3, 3), array([0., 1., 3.]))
    """
    own_work.require("course_lib.constructions.knot_splines.g1_knot_spline")
    D, t, L = _inputs(d_points, knots)
    P = _joint_points(D, t, L)
    segs = [P[3 * i : 3 * i + 4] for i in range(L)]
    h = np.diff(t)
    info = {"beta1": h[1:] / h[:-1], "junction_points": P[3 : 3 * L : 3].copy(), "d_points": D}
    return PiecewiseBezier.from_trusted_segments(segs, t, info)
