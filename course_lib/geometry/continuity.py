"""Continuity at a joint: parametric order C^n and geometric order G^n, three ways.

Two parametrizations ``q`` (ending at the joint) and ``r`` (starting there) meet with

* ``C^n`` (parametric continuity, seed 000 eq. (1)) if ``r^{(i)}(start) = q^{(i)}(end)``
  for ``i = 0..n``;
* ``G^n`` (geometric continuity) -- checked by all three characterizations of seed 000:

  1. **reparametrization** (§4, Definition 1): an orientation-preserving change of
     variables ``u`` with ``u(end) = end`` makes ``q o u`` and ``r`` meet ``C^n``.
     Here ``u`` is the Taylor polynomial with ``u^{(j)}(end) = β_j``
     (:meth:`~course_lib.geometry.reparametrization.ChangeOfVariables.from_betas` builds it);
     at the joint the composite's derivatives are Faà di Bruno's formula with the
     β's, and they are compared with ``r``'s;
  2. **Beta-constraints** (§5, eq. (6)-(7)): shape parameters ``β_1 > 0, β_2, ...``
     solved order by order (:func:`~course_lib.geometry.beta_constraints.solve_shape_parameters`)
     leave zero residuals up to order ``n``;
  3. **arc length** (§6): the derivatives with respect to arc length of orders
     ``1..n`` (unit tangent, curvature vector, ...) agree on both sides.

The three must agree (tests: ``tests/unit/test_continuity.py``).

Orders are integers capped at ``max_order``: an order equal to ``max_order`` means
"at least ``max_order``".  A positional gap gives order ``-1`` for both (not even
``C^0``/``G^0``).  Comparisons are relative.  ``C^n``: derivatives of order ``k`` are
compared with ``rtol`` times ``max(|q^{(k)}|, |r^{(k)}|, v^k / l^{k-1})``, where ``v`` is
the speed at the joint and ``l = max(|q'| h_q, |r'| h_r)`` a length scale of the two
pieces (``h`` the domain lengths).  ``G^n``: one scale-free measure for all three
characterizations, the discrepancy of order ``k`` as a derivative with respect to arc
length times ``l^{k-1}`` (dimensionless) -- ``|e_k| l^{k-1} / v_r^k`` for the Beta
residual ``e_k`` and for ``q o u - r`` (the same vector), ``|d^k r/ds^k - d^k q/ds^k|
l^{k-1}`` for arc length (equal to the former once the lower orders agree, because
``e_k`` is perpendicular to the tangent) -- compared with ``rtol`` times
``max(1, l^{k-1} max|d^k/ds^k|)`` (the same tolerance for the three: rounding grows
with the size of the derivatives of high order).  So the verdict does
not depend on units or on how fast each piece is traversed, and the three agree except
near the threshold (there the arc-length measure of order ``k`` also carries the lower
orders' tolerated discrepancies times the curvature scale); where a measure lies within
a factor 10 of ``rtol``, or the three disagree, the report says the joint is
``borderline`` (test: ``tests/unit/test_continuity_fast.py::test_characterizations_agree_near_the_threshold``).

The per-joint quantities (gap, tangent angle, arc-length derivatives, curvature jump) and
the arc-length characterization with the tolerance of order ``k`` come from
:func:`~course_lib.geometry.joint_kernel.joint_kernel`, the kernel the outline classifier
calls too: the G-order rule is written once, there.

For a :class:`~course_lib.curves.curve.PiecewiseBezier`, :func:`curve_continuity` uses the
*global* parameter (knots): the knots change the C-order but never the G-order.

Lesson: ``notebooks/04_arc_length_and_theorem_1.ipynb`` (the three characterizations agree).

Why this module is long: the report type (text and HTML), the three characterizations of
G-order and the vectorised report of a whole curve share one tolerance rule and are read
together.
"""

from __future__ import annotations

import html
from dataclasses import dataclass, field, replace

import numpy as np

from course_lib.curves.bezier import end_derivative_matrix
from course_lib.curves.curve import PiecewiseBezier
from course_lib.curves.parametrization import as_parametrization
from course_lib.geometry.chain_rule import bell_row, check_chain_rule_order
from course_lib.geometry.differential_geometry import typical_speed
from course_lib.geometry.joint_kernel import joint_kernel, leading_order
from course_lib.homework import own_work
from course_lib.validation import check_finite_scalar, check_integer, scaled_norm

__all__ = [
    "CHARACTERIZATIONS",
    "JointReport",
    "curve_continuity",
    "joint_continuity",
    "joint_report",
]

#: Names of the three characterizations of G^n (seed 000 §4, §5, §6).
CHARACTERIZATIONS = ("reparametrization", "beta_constraints", "arc_length")


#: A joint is *borderline* when a G measure lies within this factor of the tolerance.
BORDERLINE_FACTOR = 10.0

#: Values smaller than this are shown as 0 in reports: they are rounding noise of the
#: floating-point evaluation (about 1e-15 relative), not a property of the joint.
DISPLAY_ZERO = 1e-10


def _num(x: float, spec: str) -> str:
    """Format ``x`` for a report, printing rounding noise (|x| < DISPLAY_ZERO) as 0."""
    return "0" if abs(x) < DISPLAY_ZERO else format(x, spec)


@dataclass(frozen=True)
class JointReport:
    """How smoothly two parametrizations meet at one joint.

    Attributes
    ----------
    index : int or None
        Joint index (joint ``i`` joins segments ``i`` and ``i + 1``), None for a pair.
    point : tuple of float
        The joint ``q(end)``.
    gap : float
        ``|r(start) - q(end)|``.
    tangent_angle : float
        Angle in degrees between ``q'(end)`` and ``r'(start)`` (0 for G1).
    curvature_jump : float
        ``|K_r - K_q|``, the jump of the curvature vector (0 for G2 if G1).
    c_order : int
        Parametric continuity order, ``-1..max_order`` (``-1``: gap).
    g_order : int
        Geometric continuity order, ``-1..max_order``, from the Beta-constraints.
    betas : tuple of float
        ``β_1 .. β_max_order`` solved order by order (empty if there is a gap).
    residuals : tuple of float
        Norms of the Beta-constraint residuals, orders ``1..max_order``.
    g_order_by : dict
        The G-order by each characterization, keys :data:`CHARACTERIZATIONS`.
    max_order : int
    borderline : bool
        True when the verdict depends on the tolerance: a G measure of an order that
        decided lies within a factor :data:`BORDERLINE_FACTOR` (10) of ``rtol``, or the
        three characterizations disagree (which happens only near the threshold).
        ``g_order`` is then the Beta-constraints' verdict.
    """

    index: int | None
    point: tuple[float, ...]
    gap: float
    tangent_angle: float
    curvature_jump: float
    c_order: int
    g_order: int
    betas: tuple[float, ...]
    residuals: tuple[float, ...]
    g_order_by: dict = field(compare=False)
    max_order: int
    borderline: bool = False

    @property
    def characterizations_agree(self) -> bool:
        """True when the three characterizations found the same G-order."""
        return len(set(self.g_order_by.values())) == 1

    @staticmethod
    def _order_text(kind: str, k: int, cap: int) -> str:
        if k < 0:
            return f"not {kind}0 (the pieces do not meet)"
        return f"{kind}{k}" + (" (or higher)" if k == cap else "")

    def _lines(self) -> list[str]:
        where = "Joint" if self.index is None else f"Joint {self.index}"
        pt = ", ".join(_num(x, ".6g") for x in self.point)
        lines = [
            f"{where} at ({pt}): {self._order_text('G', self.g_order, self.max_order)}, "
            f"{self._order_text('C', self.c_order, self.max_order)}"
            f"  [orders checked up to {self.max_order}]",
            f"  gap {_num(self.gap, '.3g')}, tangent angle {_num(self.tangent_angle, '.4g')}°, "
            f"curvature jump {_num(self.curvature_jump, '.3g')}",
        ]
        if self.betas:
            b = ", ".join(f"β{i + 1} = {_num(v, '.6g')}" for i, v in enumerate(self.betas))
            r = ", ".join(_num(v, ".2g") for v in self.residuals)
            lines.append(f"  shape parameters {b}; residuals {r}")
        by = " / ".join(str(self.g_order_by[k]) for k in CHARACTERIZATIONS)
        lines.append(f"  G-order by reparametrization / Beta-constraints / arc length: {by}")
        if self.borderline:
            lines.append(
                "  borderline: a discrepancy is within a factor 10 of the tolerance rtol; "
                "the verdict depends on it"
            )
        return lines

    def __str__(self) -> str:
        return "\n".join(self._lines())

    def _repr_html_(self) -> str:
        rows = [
            ("geometric continuity", self._order_text("G", self.g_order, self.max_order)),
            ("parametric continuity", self._order_text("C", self.c_order, self.max_order)),
            ("gap", _num(self.gap, ".3g")),
            ("tangent angle", f"{_num(self.tangent_angle, '.4g')}°"),
            ("curvature jump", _num(self.curvature_jump, ".3g")),
        ]
        if self.betas:
            rows.append(
                (
                    "shape parameters",
                    ", ".join(f"β{i + 1} = {_num(v, '.4g')}" for i, v in enumerate(self.betas)),
                )
            )
            rows.append(("Beta residuals", ", ".join(_num(v, ".2g") for v in self.residuals)))
        rows.append(
            (
                "G-order: reparametrization / Beta / arc length",
                " / ".join(str(self.g_order_by[k]) for k in CHARACTERIZATIONS),
            )
        )
        if self.borderline:
            rows.append(("borderline", "yes: the verdict is within a factor 10 of rtol"))
        title = "Joint" if self.index is None else f"Joint {self.index}"
        body = "".join(
            f"<tr><th style='text-align:left'>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
            for k, v in rows
        )
        return (
            f"<table class='cl-joint-report'><caption>{html.escape(title)}</caption>{body}</table>"
        )


def _end_derivs(c, at: float, n: int) -> np.ndarray:
    return np.stack([np.asarray(c.evaluate(at, k), dtype=float) for k in range(n + 1)])


def _norms(x: np.ndarray) -> np.ndarray:
    """Plain norms: used on joints already scaled to a unit length scale (see _reports)."""
    return np.sqrt(np.einsum("...d,...d->...", x, x))


def _solve_betas(Q: np.ndarray, R: np.ndarray):
    """:func:`~course_lib.geometry.beta_constraints.solve_shape_parameters` for J joints at once.

    Q, R: (n, J, dim) derivatives of orders 1..n.  Returns betas (n, J), the residual
    vectors (n, J, dim) and the Bell table ``B[i, k] = B_{i,k}(β)`` (n+1, n+1, J), built
    order by order (``bell_row``)."""
    own_work.require("course_lib.geometry.continuity._solve_betas")
    n, J = Q.shape[0], Q.shape[1]
    q1 = Q[0]
    qq = np.einsum("jd,jd->j", q1, q1)
    betas = np.zeros((n, J))
    res = np.empty_like(R)
    B = np.zeros((n + 1, n + 1, J))
    B[0, 0] = 1.0
    for i in range(1, n + 1):
        bell_row(B, betas, i)
        rem = R[i - 1] - np.einsum("kj,kjd->jd", B[i, 2 : i + 1], Q[1:i]) if i > 1 else R[0]
        betas[i - 1] = np.einsum("jd,jd->j", rem, q1) / qq
        B[i, 1] = betas[i - 1]
        res[i - 1] = rem - betas[i - 1][:, None] * q1
    return betas, res, B


def _reports(
    dq: np.ndarray,
    dr: np.ndarray,
    hq: np.ndarray,
    hr: np.ndarray,
    speed_q: np.ndarray,
    speed_r: np.ndarray,
    n: int,
    rtol: float,
    atol: float,
    indices: list,
) -> list[JointReport]:
    """Reports of J joints from the end derivatives ``dq`` (of q at its end) and ``dr``
    (of r at its start), shape (max(n, 2) + 1, J, dim), the domain lengths ``hq``, ``hr``
    and typical speeds (for the regularity rule).  Vectorized over the joints, with the
    norms of all compared quantities taken in one call (the report runs on every widget
    frame)."""
    J = dq.shape[1]
    vq, vr, gap = scaled_norm(np.stack([dq[1], dr[1], dr[0] - dq[0]]), axis=-1)
    for name, v, ts in (("q", vq, speed_q), ("r", vr, speed_r)):
        bad = v <= 1e-10 * ts
        if bad.any():
            j = int(np.argmax(bad))
            where = "" if indices[j] is None else f"at joint {indices[j]}: "
            raise ValueError(
                f"{where}the parametrization {name} is not regular at the joint: its first "
                f"derivative vanishes (|{name}'| = {v[j]:.3g}); geometric continuity needs "
                "regular pieces"
            )
    ell = np.maximum(vq * hq, vr * hr)
    point = dq[0].copy()
    # work on the joint scaled by a power of two near 1/ell (exact): every measure is
    # scale-free, and nothing overflows or underflows over the whole float range
    _, e = np.frexp(ell)
    dq, dr = np.ldexp(dq, -e[None, :, None]), np.ldexp(dr, -e[None, :, None])
    atol_n = np.ldexp(atol, -e)  # atol in the rescaled units
    # gap, angle, arc-length derivatives and the G-order rule by arc length (§6): the
    # joint kernel shared with the outline classifier
    K = joint_kernel(
        np.moveaxis(dq, 0, 1), np.moveaxis(dr, 0, 1), n, lengths=(hq, hr), rtol=rtol, atol=atol_n
    )
    gapped, angle = K.gapped, K.angle
    vq, vr, ell = K.speed_in, K.speed_out, K.length
    Q, R = dq[1 : n + 1], dr[1 : n + 1]
    # (2) Beta-constraints: β's solved order by order, residuals must vanish
    betas, res, B = _solve_betas(Q, R)
    positive = betas[0] > 0
    # (1) Reparametrization: u(ū) = a + sum_j β_j (ū - a)^j / j! (ChangeOfVariables.from_betas)
    #     has u(a) = a and u^(j)(a) = β_j, so (q o u)^(i)(a) = sum_k B_{i,k}(β) q^(k)(a)
    #     (Faà di Bruno); q o u must meet r with C^n.
    Qbar = np.einsum("ikj,kjd->ijd", B[1:, 1:], Q)
    N = _norms(np.stack([Q, R, Q - R, Qbar - R, res]))
    jump = np.ldexp(K.curvature_jump, -e)  # back to the curve's units
    k = np.arange(1, n + 1)[:, None]
    lk = ell ** (k - 1.0)
    # C^n: derivatives compared with the magnitudes of order k (parametrization-dependent)
    scale = np.maximum(np.maximum(N[0], N[1]), np.maximum(vq, vr) ** k / lk)
    # G^n, one scale-free measure for all three characterizations: the discrepancy of
    # order k as a derivative with respect to arc length, made dimensionless with the
    # length scale ell.  The Beta residual e_k = r^(k) - (q o u)^(k) is perpendicular to
    # q' and, once the lower orders agree, equals v_r^k (d^k r/ds^k - d^k q/ds^k): the
    # three measures are one number computed three ways, compared with the kernel's
    # tolerance of order k (the same for the three)
    delta = np.stack(
        [
            N[4] * lk / vr**k,  # Beta-constraints residual
            N[3] * lk / vr**k,  # reparametrization: q o u against r
            K.measure.T,  # arc length (the kernel's measure)
        ]
    )
    tol = K.tolerance.T
    ok = np.concatenate([(N[2] <= rtol * scale + atol_n)[None], delta <= tol])
    c_order, g_beta, g_rep, g_arc = leading_order(np.moveaxis(ok, 1, 0))
    g_beta = np.where(positive, g_beta, 0)
    g_rep = np.where(positive, g_rep, 0)
    # borderline: a measure of an order that decided (the passing ones and the first
    # failing one) lies within a factor BORDERLINE_FACTOR of the tolerance, or the three
    # disagree (possible only near the threshold: the arc-length measure of order k also
    # carries the lower orders' tolerated discrepancies times the curvature scale)
    decided = k <= np.minimum(np.maximum.reduce([g_beta, g_rep, g_arc]) + 1, n)
    near = (delta > tol / BORDERLINE_FACTOR) & (delta <= tol * BORDERLINE_FACTOR)
    disagree = (g_beta != g_rep) | (g_beta != g_arc)
    borderline = (np.any(near & decided[None], axis=(0, 1)) & positive) | disagree
    res = np.ldexp(N[4], e[None, :])

    out = []
    for j in range(J):
        base = (indices[j], tuple(map(float, point[j])), float(gap[j]), float(angle[j]))
        if gapped[j]:
            out.append(
                JointReport(
                    *base, float(jump[j]), -1, -1, (), (), dict.fromkeys(CHARACTERIZATIONS, -1), n
                )
            )
            continue
        out.append(
            JointReport(
                *base,
                curvature_jump=float(jump[j]),
                c_order=int(c_order[j]),
                g_order=int(g_beta[j]),
                betas=tuple(map(float, betas[:, j])),
                residuals=tuple(map(float, res[:, j])),
                g_order_by={
                    "reparametrization": int(g_rep[j]),
                    "beta_constraints": int(g_beta[j]),
                    "arc_length": int(g_arc[j]),
                },
                max_order=n,
                borderline=bool(borderline[j]),
            )
        )
    return out


def _check_options(max_order, rtol, atol) -> tuple[int, float, float]:
    n = check_chain_rule_order(check_integer(max_order, "max_order", minimum=1), "max_order")
    rtol = check_finite_scalar(rtol, "rtol")
    atol = check_finite_scalar(atol, "atol")
    if rtol < 0 or atol < 0:
        raise ValueError(f"rtol and atol must be >= 0; got rtol={rtol}, atol={atol}")
    return n, rtol, atol


def joint_continuity(
    q: object,
    r: object,
    max_order: int = 4,
    *,
    rtol: float = 1e-8,
    atol: float = 0.0,
    index: int | None = None,
) -> JointReport:
    """Continuity of two parametrizations at ``q(q.domain[1]) = r(r.domain[0])`` (seed 000 §3-6).

    Parameters
    ----------
    q, r : parametrizations
        Protocol objects; ``q`` is used at the end of its domain, ``r`` at the start.
    max_order : int
        Highest order checked (``1 .. MAX_CHAIN_RULE_ORDER = 24``); reported orders are
        capped there.
    rtol : float
        Relative tolerance of every comparison (see the module docstring for the scales).
    atol : float
        Absolute floor added to every tolerance (default 0).
    index : int, optional
        Joint index to report (used by :func:`curve_continuity`).

    Returns
    -------
    JointReport

    Raises
    ------
    ValueError
        If ``q`` or ``r`` is not regular at the joint (first derivative vanishes):
        geometric continuity is defined for regular parametrizations only; or
        ``max_order`` above the cap.

    Examples
    --------
    Two quadratics meeting at ``(2, 1)`` with parallel end tangents of lengths 2 and 4:
    G1 with ``β1 = 2``, but not C1.

    >>> from course_lib import PiecewiseBezier
    >>> q = PiecewiseBezier([[[0, 0], [1, 1], [2, 1]]])
    >>> r = PiecewiseBezier([[[2, 1], [4, 1], [5, 0]]])
    >>> report = joint_continuity(q, r, max_order=2)
    >>> report.g_order, report.c_order, report.betas[0]
    (1, 0, 2.0)
    """
    own_work.require("course_lib.geometry.continuity.joint_continuity")
    q = as_parametrization(q, "q")
    r = as_parametrization(r, "r")
    n, rtol, atol = _check_options(max_order, rtol, atol)
    if q.dim != r.dim:
        raise ValueError(f"q and r must have the same dimension; got {q.dim} and {r.dim}")
    a, b = float(q.domain[1]), float(r.domain[0])
    m = max(n, 2)
    dq = _end_derivs(q, a, m)[:, None, :]
    dr = _end_derivs(r, b, m)[:, None, :]
    hq = np.array([q.domain[1] - q.domain[0]], dtype=float)
    hr = np.array([r.domain[1] - r.domain[0]], dtype=float)
    (rep,) = _reports(
        dq,
        dr,
        hq,
        hr,
        np.array([typical_speed(q)]),
        np.array([typical_speed(r)]),
        n,
        rtol,
        atol,
        [index],
    )
    return rep


def _bezier_end_derivatives(curve, m: int):
    """Derivatives of orders 0..m in the global parameter of every segment at both ends:
    (m+1, S, dim) at u = 0 and at u = 1, from the control points (seed 000 eq. (8)); the
    domain lengths ``h``; and each segment's typical speed (its control-point box diagonal
    over ``h``, the regularity scale)."""
    h = np.diff(curve.knots)
    S, dim = curve.n_segments, curve.dim
    at01 = np.zeros((2, m + 1, S, dim))
    diag = np.empty(S)
    for d, idx, _rows, D in curve.segments_by_degree(0):
        top = min(m, d)
        E = _end_difference_rows(d, top)  # (2, top+1, d+1): orders 0..top at u = 0, 1
        at01[:, : top + 1, idx] = np.einsum("ekr,srd->eksd", E, D)
        box = D.max(axis=1) - D.min(axis=1)
        diag[idx] = np.sqrt(np.einsum("sd,sd->s", box, box))
    scale = (1.0 / h) ** np.arange(m + 1)[:, None]
    at01 *= scale[None, :, :, None]
    speed = np.where(diag > 0, diag / h, 1.0)
    return at01[0], at01[1], h, speed


def _end_difference_rows(d: int, n: int) -> np.ndarray:
    """Rows mapping Bézier control points to derivatives 0..n at u = 0 and u = 1, stacked
    ``(2, n + 1, d + 1)`` (:func:`course_lib.curves.bezier.end_derivative_matrix`)."""
    return np.stack([end_derivative_matrix(d, n, 0), end_derivative_matrix(d, n, 1)])


def curve_continuity(
    curve: object,
    max_order: int = 4,
    *,
    rtol: float = 1e-8,
    atol: float = 0.0,
) -> list[JointReport]:
    """One :class:`JointReport` per interior joint of a :class:`~course_lib.curves.curve.PiecewiseBezier`.

    Derivatives are taken in the *global* parameter (segment ``i`` on
    ``[t_i, t_{i+1}]``, seed 004 §19.7), so the knots affect ``c_order`` but
    not ``g_order``.

    Examples
    --------
    >>> from course_lib import PiecewiseBezier
    >>> wave = PiecewiseBezier([[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]]])
    >>> [(j.g_order, j.c_order) for j in curve_continuity(wave, max_order=2)]
    [(1, 1)]
    """
    own_work.require("course_lib.geometry.continuity.curve_continuity")
    if not isinstance(curve, PiecewiseBezier):
        raise TypeError(
            f"curve must be a PiecewiseBezier, got {type(curve).__name__}; "
            "use joint_continuity(q, r) for two parametrizations"
        )
    n, rtol, atol = _check_options(max_order, rtol, atol)
    if curve.n_joints == 0:
        return []
    at0, at1, h, speed = _bezier_end_derivatives(curve, max(n, 2))
    return _reports(
        at1[:, :-1],
        at0[:, 1:],
        h[:-1],
        h[1:],
        speed[:-1],
        speed[1:],
        n,
        rtol,
        atol,
        list(range(curve.n_joints)),
    )


def joint_report(curve: object, j: int, max_order: int = 3) -> JointReport:
    """The :class:`JointReport` of joint ``j`` of a PiecewiseBezier alone.

    Only segments ``j`` and ``j + 1`` are analysed (with their knots, so in the global
    parameter, as :func:`curve_continuity` does); a live demo asks this on every frame.

    Parameters
    ----------
    curve : PiecewiseBezier
    j : int
        The joint, ``0 <= j < curve.n_joints``.
    max_order : int
        Highest order examined.

    Raises
    ------
    TypeError
        If ``curve`` is not a PiecewiseBezier.
    ValueError
        If ``j`` is not a joint of ``curve``.

    Examples
    --------
    >>> from course_lib import PiecewiseBezier
    >>> wave = PiecewiseBezier([[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]]])
    >>> report = joint_report(wave, 0, max_order=2)
    >>> report.index, report.g_order
    (0, 1)
    """
    from course_lib.curves.curve import PiecewiseBezier

    if not isinstance(curve, PiecewiseBezier):
        raise TypeError(f"curve must be a PiecewiseBezier, got {type(curve).__name__}")
    j = check_integer(j, "j", minimum=0)
    if j >= curve.n_joints:
        raise ValueError(f"j must be < {curve.n_joints} (the curve's joints); got {j}")
    k = curve.knots
    pair = PiecewiseBezier(curve.segments[j : j + 2], k[j : j + 3] if curve.has_knots else None)
    (rep,) = curve_continuity(pair, max_order=max_order)
    return replace(rep, index=j)
