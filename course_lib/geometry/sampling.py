"""Sampling a curve for pictures: each segment on its own grid, joints from both sides.

A math module (it knows nothing of matplotlib): the plotting and widget layers draw what it
returns.  For a PiecewiseBezier whose segments share one degree, every frame of a widget
samples the same local parameters, so the Bernstein matrices of the grid are constant and
cached here; derivatives use the hodograph control points of :mod:`course_lib.curves.bezier`, and
tangents and curvature vectors the formulas of :mod:`course_lib.geometry.differential_geometry`.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from course_lib.curves.bezier import derivative_points
from course_lib.geometry import differential_geometry as dg
from course_lib.validation import check_integer

#: The last sample of a segment is taken this fraction of the segment before its end,
#: so that global evaluation (which gives a joint to the segment that *starts* there)
#: returns the one-sided limit of the segment that *ends* there.  Curvature and points
#: of a polynomial segment change by O(1e-10) relative over that distance: invisible,
#: and far below the tolerances of the tests (tests/unit/test_plotting.py).
ONE_SIDED_EPS = 1e-10


def segment_grid(curve, per_segment: int) -> np.ndarray:
    """Global parameters of shape ``(S, per_segment)``: row ``i`` spans segment ``i``.

    Row ``i`` runs from ``t_i`` to (just before) ``t_{i+1}``, so evaluating row ``i``
    gives segment ``i`` only, including its own limits at both joints.

    Examples
    --------
    Row 0 ends a hair before the joint ``t = 1`` (printed ``1.``), where row 1 starts:

    >>> from course_lib import PiecewiseBezier
    >>> tent = PiecewiseBezier([[[0, 0], [3, 4]], [[3, 4], [6, 0]]])
    >>> segment_grid(tent, 3)
    array([[0. , 0.5, 1. ],
           [1. , 1.5, 2. ]])
    """
    per_segment = check_integer(per_segment, "per_segment", minimum=2)
    k = np.asarray(curve.knots, dtype=float)
    u = np.linspace(0.0, 1.0, per_segment)
    h = np.diff(k)
    t = k[:-1, None] + h[:, None] * u[None, :]
    if t.shape[0] > 1:
        t[:-1, -1] = k[1:-1] - ONE_SIDED_EPS * h[:-1]
    return t


def segment_samples(curve, per_segment: int) -> tuple[np.ndarray, np.ndarray]:
    """``(t, points)`` with shapes ``(S, n)`` and ``(S, n, dim)``: each segment on its own."""
    t = segment_grid(curve, per_segment)
    (pts,) = segment_derivatives(curve, per_segment, (0,))
    return t, pts


@lru_cache(maxsize=32)
def _local_bernstein(degree: int, per_segment: int) -> np.ndarray:
    """Bernstein matrix ``B[j, r] = B_r^degree(u_j)`` of the fixed local grid
    ``u = linspace(0, 1, per_segment)`` (the same for every segment and every frame)."""
    from course_lib.curves.bezier import bernstein

    B = np.array(bernstein(degree, np.linspace(0.0, 1.0, per_segment)), dtype=float)
    B.setflags(write=False)
    return B


def segment_derivatives(curve, per_segment: int, orders=(0,)) -> list[np.ndarray]:
    """Points and derivatives (global parameter) on :func:`segment_grid`, each ``(S, n, dim)``.

    Entry ``k`` of the result is the ``orders[k]``-th derivative; row ``i`` spans segment
    ``i`` with its own one-sided limits at both ends (for a PiecewiseBezier whose segments
    share one degree: exactly at ``u = 0`` and ``u = 1``).

    For such a curve every frame of a widget samples the same local parameters, so the
    Bernstein matrices are constant (cached here) and each order is one matrix product
    with the hodograph control points of all segments at once, ``d!/(d-k)! Δ^k V``
    (seed 000 eq. (8); :func:`course_lib.curves.bezier.derivative_control_points`), divided by
    ``h_i^k`` for the global parameter.  Any other parametrization is evaluated on
    :func:`segment_grid` through its ``evaluate``.
    """
    per_segment = check_integer(per_segment, "per_segment", minimum=2)
    if not _single_degree(curve):
        t = segment_grid(curve, per_segment)
        flat = t.ravel()
        return [curve.evaluate(flat, k).reshape((*t.shape, curve.dim)) for k in orders]
    d = curve.degrees[0]
    V = np.stack(curve.segments)  # (S, d + 1, dim)
    h = np.diff(np.asarray(curve.knots, dtype=float))
    out = []
    for k in orders:
        k = check_integer(k, "order", minimum=0)
        if k > d:
            out.append(np.zeros((V.shape[0], per_segment, V.shape[2])))
            continue
        D = np.matmul(_local_bernstein(d - k, per_segment), derivative_points(V, k))  # (S, n, dim)
        if k:
            D *= (h ** -float(k))[:, None, None]  # d/dt = (1/h_i) d/du on segment i
        out.append(D)
    return out


def _single_degree(curve) -> bool:
    degrees = getattr(curve, "degrees", None)
    return degrees is not None and len(set(degrees)) == 1 and hasattr(curve, "segments")


def point_derivatives(curve, t: np.ndarray, orders=(0,)) -> list[np.ndarray]:
    """Derivatives of the given orders at global parameters ``t`` (1-d), each ``(m, dim)``.

    For a PiecewiseBezier of one degree: the segments located once, each order one
    Bernstein evaluation of the hodograph points (seed 000 eq. (8)); otherwise
    ``curve.evaluate``.  A joint parameter belongs to the segment that starts there
    (as in ``PiecewiseBezier.evaluate``).
    """
    t = np.asarray(t, dtype=float).ravel()
    if not _single_degree(curve):
        return [np.atleast_2d(curve.evaluate(t, k)) for k in orders]
    from course_lib.curves.bezier import bernstein

    idx, u = curve.locate(t)
    d = curve.degrees[0]
    V = np.stack(curve.segments)[idx]  # (m, d + 1, dim)
    h = np.diff(np.asarray(curve.knots, dtype=float))[idx]
    out = []
    for k in orders:
        if k > d:
            out.append(np.zeros((t.size, V.shape[2])))
            continue
        B = np.atleast_2d(bernstein(d - k, u))  # (m, d - k + 1)
        D = np.einsum("mr,mrd->md", B, derivative_points(V, k))
        if k:
            D *= (h ** -float(k))[:, None]
        out.append(D)
    return out


def tangent_and_curvature(
    curve, d1: np.ndarray, d2: np.ndarray, t
) -> tuple[np.ndarray, np.ndarray]:
    """Unit tangents ``T = c'/|c'|`` and curvature vectors ``K = (c'' - (c''.T) T)/|c'|^2``
    (seed 004 §19.2; the formulas of :mod:`course_lib.geometry.differential_geometry`, tested equal
    in tests/unit/test_plotting.py) from derivatives of any shape ``(..., dim)``.

    Raises
    ------
    ValueError
        Where ``|c'|`` vanishes relative to the curve's size (the regularity rule of
        :mod:`course_lib.geometry.differential_geometry`); ``t`` (same leading shape as the
        derivatives, or a callable returning it) names the place.
    """
    return dg.frame_from_derivatives(d1, d2, dg.check_regular(curve, t, d1))
