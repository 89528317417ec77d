"""Every joint of an outline classified, vectorized: gap, tangent angle, signed curvature on
both sides, the strict G-order (the rule of :func:`~course_lib.geometry.continuity.joint_continuity`,
computed once by :func:`~course_lib.geometry.joint_kernel.joint_kernel`, seed 000 §6) and the
type designer's kind (corner / G1 / G2)."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from course_lib.constructions.outlines.contours import Outline
from course_lib.curves.bezier import end_derivative_matrix
from course_lib.geometry.joint_kernel import joint_kernel
from course_lib.homework import own_work
from course_lib.validation import check_finite_scalar

__all__ = ["KINDS", "RTOL", "JointTable", "classify_joints"]

#: Joint kinds of :func:`classify_joints`, in this order.
KINDS = ("gap", "singular", "corner", "G1", "G2")

#: Tolerance of the strict G-order, the default of :func:`~course_lib.geometry.continuity.joint_continuity`.
RTOL = 1e-8


@dataclass(frozen=True)
class JointTable:
    """Every joint of an outline, one entry per joint (arrays of equal length).

    Attributes
    ----------
    contour, joint : ndarray of int
        Contour index and joint index within it (the closing joint of a closed contour
        is its last joint).
    point : ndarray (m, 2)
        End point of the incoming segment.
    gap : ndarray
        Distance between the incoming segment's end and the outgoing segment's start.
    angle : ndarray
        Angle in degrees between the incoming and outgoing tangent directions (the
        geometric tangents: first non-vanishing control-point difference at each end).
    kappa_in, kappa_out : ndarray
        Signed curvature at the end of the incoming / the start of the outgoing segment
        (NaN where that side is singular).
    rel_jump : ndarray
        ``|kappa_out - kappa_in| / max(|kappa_in|, |kappa_out|, 1/l)``: the curvature
        jump relative to the local curvature (``l``: the larger end speed, a length scale
        of the two pieces).
    regular : ndarray of bool
        Both sides have a non-vanishing first derivative.
    implied : ndarray of bool
        The joint is an implied TrueType on-curve point.
    g_order : ndarray of int
        Strict G-order -1..2 (tolerance ``rtol``, the continuity report's rule).
    kind : ndarray of str
        One of :data:`KINDS` (``corner_angle``, ``curvature_rtol`` tolerances).
    """

    contour: np.ndarray
    joint: np.ndarray
    point: np.ndarray
    gap: np.ndarray
    angle: np.ndarray
    kappa_in: np.ndarray
    kappa_out: np.ndarray
    rel_jump: np.ndarray
    regular: np.ndarray
    implied: np.ndarray
    g_order: np.ndarray
    kind: np.ndarray
    settings: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(self.contour.size)

    def counts(self) -> dict[str, int]:
        """Number of joints of each kind (keys :data:`KINDS`)."""
        return {k: int(np.count_nonzero(self.kind == k)) for k in KINDS}


def _end_data(segs: list[np.ndarray]):
    """Per segment: start/end points, first and second derivatives, geometric tangents.

    Vectorized over the segments of each degree (seed 000 eq. (8): the end derivatives of
    a Bézier curve are differences of its end control points).
    """
    S = len(segs)
    out = {k: np.zeros((S, 2)) for k in ("p0", "p1", "a1", "a2", "b1", "b2", "ta", "tb")}
    scale = np.zeros(S)
    degrees = np.fromiter((s.shape[0] - 1 for s in segs), int, S)
    for d in np.unique(degrees):
        idx = np.flatnonzero(degrees == d)
        P = np.stack([segs[i] for i in idx])  # (m, d+1, 2)
        out["p0"][idx], out["p1"][idx] = P[:, 0], P[:, -1]
        at0 = end_derivative_matrix(int(d), 2, 0) @ P  # (m, 3, 2): orders 0..2 at u = 0
        at1 = end_derivative_matrix(int(d), 2, 1) @ P  # zero rows above the degree
        out["a1"][idx], out["a2"][idx] = at0[:, 1], at0[:, 2]
        out["b1"][idx], out["b2"][idx] = at1[:, 1], at1[:, 2]
        scale[idx] = d * np.ptp(P, axis=1).max(axis=1)
        # Geometric tangent: the first non-zero difference from each end.
        ta = P[:, 1:] - P[:, :1]
        tb = P[:, -1:] - P[:, -2::-1]
        for name, D in (("ta", ta), ("tb", tb)):
            nz = np.linalg.norm(D, axis=2) > 0
            first = np.argmax(nz, axis=1)
            out[name][idx] = D[np.arange(idx.size), first]
    return out, scale


def classify_joints(
    outline: Outline,
    *,
    corner_angle: float = 2.0,
    curvature_rtol: float = RTOL,
    rtol: float = RTOL,
) -> JointTable:
    """Classify every joint of an outline (vectorized).

    Parameters
    ----------
    outline : Outline
    corner_angle : float
        Tangent angle in degrees above which a joint is a corner (default 2°).  Font
        outlines live on an integer grid, so an explicit on-curve point a designer meant
        to be smooth turns by a little: in DejaVu Sans 'S' one turns by 1.0° (a
        quadratic meeting a line, directions (166, -31) and (122, -25) font units).
        Implied midpoints turn by 0 (up to rounding).
    curvature_rtol : float
        A smooth point is ``"G2"`` when its relative curvature jump is at most this.
    rtol : float
        Tolerance of the strict ``g_order`` (the continuity report's default).

    Returns
    -------
    JointTable

    Examples
    --------
    A right triangle from SVG path data: three corners.

    >>> from course_lib.constructions.outlines import svg_outline
    >>> table = classify_joints(svg_outline("M 0 0 L 2 0 L 2 2 Z"))
    >>> table.kind.tolist(), table.angle.tolist()
    (['corner', 'corner', 'corner'], [90.0, 135.0, 135.0])
    """
    own_work.require("course_lib.constructions.outlines.classification.classify_joints")
    if not isinstance(outline, Outline):
        raise TypeError(f"outline must be an Outline, got {type(outline).__name__}")
    corner_angle = check_finite_scalar(corner_angle, "corner_angle")
    curvature_rtol = check_finite_scalar(curvature_rtol, "curvature_rtol")
    rtol = check_finite_scalar(rtol, "rtol")
    if not 0 <= corner_angle < 180:
        raise ValueError(f"corner_angle must be in [0, 180) degrees; got {corner_angle}")
    if curvature_rtol < 0 or rtol < 0:
        raise ValueError("curvature_rtol and rtol must be >= 0")
    segs: list[np.ndarray] = []
    q_idx, r_idx, cont, jnt, impl = [], [], [], [], []
    for ci, c in enumerate(outline.contours):
        S, base = c.curve.n_segments, len(segs)
        segs.extend(c.curve.segments)
        J = c.n_joints
        q = base + np.arange(J)
        q_idx.append(q)
        r_idx.append(base + (np.arange(J) + 1) % S)
        cont.append(np.full(J, ci))
        jnt.append(np.arange(J))
        impl.append(np.asarray(c.implied, bool))
    if not segs or not sum(len(x) for x in q_idx):
        e, i, b = np.zeros(0), np.zeros(0, int), np.zeros(0, bool)
        return JointTable(i, i, np.zeros((0, 2)), e, e, e, e, e, b, b, i, e.astype(str))
    data, scale = _end_data(segs)
    qi, ri = np.concatenate(q_idx), np.concatenate(r_idx)
    # gap, tangent angle, signed curvature and the strict G-order: the joint kernel shared
    # with the continuity report (seed 000 §6).  Two outline settings, explicit: the angle
    # of the geometric tangents (a singular end still has one) and regularity relative to
    # each segment's control-point extent.
    dq = np.stack([data["p1"][qi], data["b1"][qi], data["b2"][qi]], axis=1)  # (m, 3, 2)
    dr = np.stack([data["p0"][ri], data["a1"][ri], data["a2"][ri]], axis=1)
    K = joint_kernel(
        dq,
        dr,
        2,
        rtol=rtol,
        speed_scales=(scale[qi], scale[ri]),
        directions=(data["tb"][qi], data["ta"][ri]),
    )
    gap, angle, regular, ell = K.gap, K.angle, K.regular, K.length
    kq, kr, rel, g = K.curvature_in, K.curvature_out, K.rel_jump, K.g_order
    kind = np.full(qi.size, "G1", dtype="<U8")
    kind[rel <= curvature_rtol] = "G2"
    kind[angle > corner_angle] = "corner"
    kind[~regular] = "singular"
    kind[gap > rtol * np.maximum(ell, scale[qi])] = "gap"
    return JointTable(
        np.concatenate(cont),
        np.concatenate(jnt),
        data["p1"][qi],
        gap,
        angle,
        kq,
        kr,
        rel,
        regular,
        np.concatenate(impl),
        g.astype(int),
        kind,
        {"corner_angle": corner_angle, "curvature_rtol": curvature_rtol, "rtol": rtol},
    )
