"""The joint kernel: the per-joint quantities of many joints at once, and the G-order rule.

One vectorised function, :func:`joint_kernel`, shared by the continuity report
(:func:`~course_lib.geometry.continuity.curve_continuity`) and the outline classifier
(:func:`~course_lib.constructions.outlines.classification.classify_joints`).  From the end
derivatives of the incoming piece ``q`` (at its end) and of the outgoing piece ``r`` (at its
start) it computes the gap, the speeds, the unit tangents and the angle between them, the
derivatives with respect to arc length (unit tangent, curvature vector, ...), the signed
curvature of plane curves, and the G-order by arc length (Barsky & DeRose 1988 §6, seed 000):
``q`` and ``r`` meet ``G^n`` when ``d^k q/ds^k = d^k r/ds^k`` for ``k = 1..n``.

The rule, written once here: the discrepancy of order ``k``, made dimensionless with the
length scale ``l = max(|q'| h_q, |r'| h_r)``, is

    ``delta_k = |d^k r/ds^k - d^k q/ds^k| l^(k-1)``

and order ``k`` passes when ``delta_k <= rtol max(1, l^(k-1) max|d^k/ds^k|) + atol l^(k-1) / |r'|^k``;
the G-order is the number of leading orders that pass (:func:`leading_order`), ``-1`` where
the gap exceeds ``rtol l + atol`` and ``0`` at a singular (non-regular) joint.  The
continuity report compares its two other characterizations (reparametrization and
Beta-constraints) with the same :attr:`JointQuantities.tolerance`.

Math only: no plotting, no curve types.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course_lib.geometry.differential_geometry import arc_length_derivatives_unscaled
from course_lib.homework import own_work

__all__ = ["REGULAR_RTOL", "JointQuantities", "joint_kernel", "leading_order"]

#: A side is regular when its speed exceeds this times its speed scale.
REGULAR_RTOL = 1e-10


@dataclass(frozen=True)
class JointQuantities:
    """What :func:`joint_kernel` computes for ``m`` joints (seed 000 §6).

    Attributes
    ----------
    gap : ndarray (m,)
        ``|r(start) - q(end)|``.
    speed_in, speed_out : ndarray (m,)
        ``|q'(end)|``, ``|r'(start)|``.
    length : ndarray (m,)
        The length scale ``l = max(|q'| h_q, |r'| h_r)``.
    regular : ndarray of bool (m,)
        Both speeds exceed :data:`REGULAR_RTOL` times their speed scales.
    gapped : ndarray of bool (m,)
        ``gap > rtol l + atol``.
    tangent_in, tangent_out : ndarray (m, dim)
        Unit tangents (of the ``directions`` when given; NaN where a direction vanishes).
    angle : ndarray (m,)
        Angle in degrees between the two tangent directions.
    arc_in, arc_out : ndarray (m, n, dim)
        ``d^k q/ds^k`` and ``d^k r/ds^k``, ``k = 1..n`` (``n = max(max_order, 2)``).
    curvature_in, curvature_out : ndarray (m,)
        Signed curvature ``(c' x c'') / |c'|^3`` for plane curves, ``|d^2 c/ds^2|``
        otherwise; NaN on a singular side.
    curvature_jump : ndarray (m,)
        ``|K_r - K_q|``, the jump of the curvature vector.
    rel_jump : ndarray (m,)
        ``|kappa_out - kappa_in| / max(|kappa_in|, |kappa_out|, 1/l)`` (plane: signed
        curvatures; otherwise the curvature vectors).
    measure, tolerance : ndarray (m, max_order)
        ``delta_k`` and its tolerance, orders ``1..max_order`` (module docstring).
    g_order : ndarray of int (m,)
        G-order by arc length, ``-1..max_order`` (capped: ``max_order`` means at least).
    """

    gap: np.ndarray
    speed_in: np.ndarray
    speed_out: np.ndarray
    length: np.ndarray
    regular: np.ndarray
    gapped: np.ndarray
    tangent_in: np.ndarray
    tangent_out: np.ndarray
    angle: np.ndarray
    arc_in: np.ndarray
    arc_out: np.ndarray
    curvature_in: np.ndarray
    curvature_out: np.ndarray
    curvature_jump: np.ndarray
    rel_jump: np.ndarray
    measure: np.ndarray
    tolerance: np.ndarray
    g_order: np.ndarray


def _norms(x: np.ndarray) -> np.ndarray:
    return np.sqrt(np.einsum("...d,...d->...", x, x))


def leading_order(ok: np.ndarray) -> np.ndarray:
    """The number of leading orders that pass: ``ok`` of shape ``(n, ...)`` (order ``k`` in
    row ``k - 1``) gives, per column, the first ``k`` whose row fails, or ``n`` if none.

    Examples
    --------
    >>> leading_order(np.array([[True, True, False], [True, False, True]])).tolist()
    [2, 1, 0]
    """
    ok = np.asarray(ok, dtype=bool)
    pad = np.zeros((1, *ok.shape[1:]), bool)
    return np.argmin(np.concatenate([ok, pad], axis=0), axis=0)


def _arc_length_orders(arc_in, arc_out, speed_out, length, max_order, rtol, atol):
    """The G-order rule by arc length (seed 000 §6): measures, tolerances, orders, all (n, m)."""
    own_work.require("course_lib.geometry.joint_kernel._arc_length_orders")
    n = max_order
    k = np.arange(1, n + 1)[:, None]
    lk = length ** (k - 1.0)
    Aq, Ar = arc_in[:n], arc_out[:n]
    measure = _norms(Aq - Ar) * lk
    size = np.maximum(_norms(Aq), _norms(Ar))
    tol = rtol * np.maximum(1.0, size * lk) + atol * lk / speed_out**k
    return measure, tol, leading_order(measure <= tol)


def joint_kernel(
    dq: object,
    dr: object,
    max_order: int = 2,
    *,
    lengths: tuple | None = None,
    rtol: float = 1e-8,
    atol: float = 0.0,
    speed_scales: tuple | None = None,
    directions: tuple | None = None,
) -> JointQuantities:
    """Gap, tangents, curvature and G-order of ``m`` joints at once (seed 000 §6).

    Parameters
    ----------
    dq, dr : array_like (m, k, dim)
        Derivatives of orders ``0 .. k - 1`` of the incoming piece at its end and of the
        outgoing piece at its start (``k >= max(max_order, 2) + 1``), e.g. from
        :func:`course_lib.curves.bezier.end_derivative_matrix`.
    max_order : int
        Highest order of the G-order rule.
    lengths : (array_like, array_like), optional
        Domain lengths ``h_q``, ``h_r`` of the pieces (default 1): the length scale is
        ``l = max(|q'| h_q, |r'| h_r)``.
    rtol, atol : float
        Tolerances of the rule (module docstring).  The continuity report passes its
        ``rtol``/``atol``; the outline classifier its ``rtol`` and ``atol = 0``.
    speed_scales : (array_like, array_like), optional
        Speed scales of the two sides for the regularity test (default: regular when the
        speed is positive).
    directions : (array_like, array_like), optional
        Tangent directions to use for ``tangent_*`` and ``angle`` instead of the first
        derivatives.  The outline classifier passes the *geometric* tangents (first
        non-vanishing control-point difference), so a singular end still has an angle;
        the G-order always uses the derivatives.

    Returns
    -------
    JointQuantities

    Examples
    --------
    A line into a parabola along the same tangent: G1, not G2 (curvature 0, then 1/2).

    >>> import numpy as np
    >>> dq = np.array([[[1.0, 0.0], [1.0, 0.0], [0.0, 0.0]]])   # q(1), q'(1), q''(1)
    >>> dr = np.array([[[1.0, 0.0], [2.0, 0.0], [-2.0, 2.0]]])  # r(0), r'(0), r''(0)
    >>> jq = joint_kernel(dq, dr)
    >>> jq.g_order.tolist(), float(jq.curvature_out[0])
    ([1], 0.5)
    """
    dq = np.asarray(dq, dtype=float)
    dr = np.asarray(dr, dtype=float)
    n = max(int(max_order), 2)
    if dq.ndim != 3 or dq.shape != dr.shape or dq.shape[1] < n + 1:
        raise ValueError(
            f"dq and dr must have the same shape (m, k, dim) with k >= {n + 1}; "
            f"got {dq.shape} and {dr.shape}"
        )
    m, _, dim = dq.shape
    D = np.concatenate([np.moveaxis(dq, 1, 0), np.moveaxis(dr, 1, 0)], axis=1)  # (k, 2m, dim)
    hq, hr = (1.0, 1.0) if lengths is None else lengths
    vq, vr = _norms(D[1, :m]), _norms(D[1, m:])
    gap = _norms(D[0, m:] - D[0, :m])
    if speed_scales is None:
        regular = (vq > 0) & (vr > 0)
    else:
        sq, sr = speed_scales
        regular = (vq > REGULAR_RTOL * np.asarray(sq)) & (vr > REGULAR_RTOL * np.asarray(sr))
    length = np.maximum(vq * hq, vr * hr)
    gapped = gap > rtol * length + atol
    tq, tr = (D[1, :m], D[1, m:]) if directions is None else map(np.asarray, directions)
    nq, nr = _norms(tq), _norms(tr)
    with np.errstate(invalid="ignore", divide="ignore"):
        cosang = np.einsum("jd,jd->j", tq, tr) / (nq * nr)
        if dim == 2:
            cross = np.abs(tq[:, 0] * tr[:, 1] - tq[:, 1] * tr[:, 0])
        else:
            cross = _norms(np.cross(tq, tr))
        angle = np.degrees(np.arctan2(cross / (nq * nr), cosang))
        A = arc_length_derivatives_unscaled(D[: n + 1], np.concatenate([vq, vr]), n)
        Aq, Ar = A[:, :m], A[:, m:]
        if dim == 2:
            d1, d2, v = D[1], D[2], np.concatenate([vq, vr])
            kappa = (d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]) / v**3
            kq, kr = kappa[:m], kappa[m:]
            jump_signed = np.abs(kr - kq)
        else:
            kq, kr = _norms(Aq[1]), _norms(Ar[1])
            jump_signed = _norms(Ar[1] - Aq[1])
        kq, kr = np.where(regular, kq, np.nan), np.where(regular, kr, np.nan)
        rel = jump_signed / np.maximum.reduce([np.abs(kq), np.abs(kr), 1.0 / length])
        measure, tol, order = _arc_length_orders(Aq, Ar, vr, length, int(max_order), rtol, atol)
        tangent_in, tangent_out = tq / nq[:, None], tr / nr[:, None]
    g = np.where(gapped, -1, np.where(regular, order, 0))
    return JointQuantities(
        gap=gap,
        speed_in=vq,
        speed_out=vr,
        length=length,
        regular=regular,
        gapped=gapped,
        tangent_in=tangent_in,
        tangent_out=tangent_out,
        angle=angle,
        arc_in=np.moveaxis(Aq, 0, 1),
        arc_out=np.moveaxis(Ar, 0, 1),
        curvature_in=kq,
        curvature_out=kr,
        curvature_jump=_norms(Ar[1] - Aq[1]),
        rel_jump=rel,
        measure=measure.T,
        tolerance=tol.T,
        g_order=g.astype(int),
    )
