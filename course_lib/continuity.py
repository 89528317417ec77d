"""Continuity at a joint: parametric order C^n and geometric order G^n, three ways.

Two parametrizations ``q`` (ending at the joint) and ``r`` (starting there) meet with

* ``C^n`` (parametric continuity, seed 000 eq. (1)) if ``r^{(i)}(start) = q^{(i)}(end)``
  for ``i = 0..n``;
* ``G^n`` (geometric continuity) -- checked by all three characterizations of seed 000:

  1. **reparametrization** (§4, Definition 1): an orientation-preserving change of
     variables ``u`` with ``u(end) = end`` makes ``q o u`` and ``r`` meet ``C^n``.
     Here ``u`` is built explicitly (the Taylor polynomial with ``u^{(j)}(end) = β_j``,
     :meth:`~course_lib.reparametrization.ChangeOfVariables.from_betas`) and the
     composite's derivatives (Faà di Bruno) are compared with ``r``'s;
  2. **Beta-constraints** (§5, eq. (6)-(7)): shape parameters ``β_1 > 0, β_2, ...``
     solved order by order (:func:`~course_lib.beta_constraints.solve_shape_parameters`)
     leave zero residuals up to order ``n``;
  3. **arc length** (§6): the derivatives with respect to arc length of orders
     ``1..n`` (unit tangent, curvature vector, ...) agree on both sides.

The three must agree (tests: ``tests/unit/test_continuity.py``).

Orders are integers capped at ``max_order``: an order equal to ``max_order`` means
"at least ``max_order``".  A positional gap gives order ``-1`` for both (not even
``C^0``/``G^0``).  Comparisons are relative: derivatives of order ``k`` are compared
with ``rtol`` times ``max(|q^{(k)}|, |r^{(k)}|, v^k / l^{k-1})``, where ``v`` is the
speed at the joint and ``l`` a length scale of the two pieces (``|c'|`` times the
domain length), so the verdict does not depend on units or on how fast each piece
is traversed.

For a :class:`~course_lib.curve.PiecewiseBezier`, :func:`curve_continuity` uses the
*global* parameter (knots): the knots change the C-order but never the G-order.

Lesson: ``notebooks/02_beta_constraints.ipynb`` (the three characterizations agree).
"""

from __future__ import annotations

import html
from dataclasses import dataclass, field

import numpy as np

from ._bell import check_chain_rule_order
from ._validation import check_finite_scalar, check_integer
from .beta_constraints import solve_shape_parameters
from .differential_geometry import _arc_length_derivatives_from, _typical_speed
from .parametrization import as_parametrization
from .reparametrization import ChangeOfVariables, Reparametrized

__all__ = ["CHARACTERIZATIONS", "JointReport", "curve_continuity", "joint_continuity"]

#: Names of the three characterizations of G^n (seed 000 §4, §5, §6).
CHARACTERIZATIONS = ("reparametrization", "beta_constraints", "arc_length")


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
        title = "Joint" if self.index is None else f"Joint {self.index}"
        body = "".join(
            f"<tr><th style='text-align:left'>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
            for k, v in rows
        )
        return (
            f"<table class='cl-joint-report'><caption>{html.escape(title)}</caption>{body}</table>"
        )


class _GlobalSegment:
    """Segment ``i`` of a PiecewiseBezier in the *global* parameter ``t in [t_i, t_{i+1}]``."""

    __slots__ = ("curve", "dim", "domain", "h", "i")

    def __init__(self, curve, i: int) -> None:
        self.curve, self.i = curve, i
        k = curve.knots
        self.domain = (float(k[i]), float(k[i + 1]))
        self.h = self.domain[1] - self.domain[0]
        self.dim = curve.dim

    def evaluate(self, t, n: int = 0):
        u = (np.asarray(t, dtype=float) - self.domain[0]) / self.h
        return self.curve.evaluate_segment(self.i, np.clip(u, 0.0, 1.0), n) / self.h**n


def _cross_norm(x: np.ndarray, y: np.ndarray) -> float:
    if x.size == 2:
        return abs(float(x[0] * y[1] - x[1] * y[0]))
    return float(np.linalg.norm(np.cross(x, y)))


def _end_derivs(c, at: float, n: int) -> np.ndarray:
    return np.stack([np.asarray(c.evaluate(at, k), dtype=float) for k in range(n + 1)])


def _scales(dq: np.ndarray, dr: np.ndarray, ell: float) -> np.ndarray:
    """Reference magnitudes of the derivatives of orders 0..n (see the module docstring)."""
    n = dq.shape[0] - 1
    vq, vr = np.linalg.norm(dq[1]), np.linalg.norm(dr[1])
    out = np.empty(n + 1)
    out[0] = ell
    for k in range(1, n + 1):
        out[k] = max(
            np.linalg.norm(dq[k]),
            np.linalg.norm(dr[k]),
            vq**k / ell ** (k - 1),
            vr**k / ell ** (k - 1),
        )
    return out


def _matching_order(
    a: np.ndarray, b: np.ndarray, scale: np.ndarray, rtol: float, atol: float
) -> int:
    """Largest k with rows 1..k of a and b equal within tolerance (rows 0 assumed equal)."""
    k = 0
    for i in range(1, a.shape[0]):
        if np.linalg.norm(a[i] - b[i]) <= rtol * scale[i] + atol:
            k = i
        else:
            break
    return k


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
        Highest order checked (>= 1); reported orders are capped there.
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
        geometric continuity is defined for regular parametrizations only.
    """
    q = as_parametrization(q, "q")
    r = as_parametrization(r, "r")
    n = check_chain_rule_order(check_integer(max_order, "max_order", minimum=1), "max_order")
    rtol = check_finite_scalar(rtol, "rtol")
    atol = check_finite_scalar(atol, "atol")
    if rtol < 0 or atol < 0:
        raise ValueError(f"rtol and atol must be >= 0; got rtol={rtol}, atol={atol}")
    if q.dim != r.dim:
        raise ValueError(f"q and r must have the same dimension; got {q.dim} and {r.dim}")
    where = "" if index is None else f"at joint {index}: "
    a, b = float(q.domain[1]), float(r.domain[0])
    m = max(n, 2)
    dq = _end_derivs(q, a, m)
    dr = _end_derivs(r, b, m)
    vq, vr = float(np.linalg.norm(dq[1])), float(np.linalg.norm(dr[1]))
    for name, v, c in (("q", vq, q), ("r", vr, r)):
        if v <= 1e-10 * _typical_speed(c):
            raise ValueError(
                f"{where}the parametrization {name} is not regular at the joint: its first "
                f"derivative vanishes (|{name}'| = {v:.3g}); geometric continuity needs "
                "regular pieces"
            )
    ell = max(vq * (q.domain[1] - q.domain[0]), vr * (r.domain[1] - r.domain[0]))
    scale = _scales(dq, dr, ell)

    gap = float(np.linalg.norm(dr[0] - dq[0]))
    cosang = float(dq[1] @ dr[1]) / (vq * vr)
    sinang = _cross_norm(dq[1], dr[1]) / (vq * vr)
    angle = float(np.degrees(np.arctan2(sinang, cosang)))
    Kq = _arc_length_derivatives_from(dq[:3, None, :], np.array([vq]), 2)[1, 0]
    Kr = _arc_length_derivatives_from(dr[:3, None, :], np.array([vr]), 2)[1, 0]
    jump = float(np.linalg.norm(Kr - Kq))

    if gap > rtol * ell + atol:
        return JointReport(
            index,
            tuple(map(float, dq[0])),
            gap,
            angle,
            jump,
            -1,
            -1,
            (),
            (),
            dict.fromkeys(CHARACTERIZATIONS, -1),
            n,
        )

    dq, dr, scale = dq[: n + 1], dr[: n + 1], scale[: n + 1]
    c_order = _matching_order(dq, dr, scale, rtol, atol)

    # (2) Beta-constraints: β's solved order by order, residuals must vanish.
    fit = solve_shape_parameters(dq[1:], dr[1:])
    g_beta = 0
    if fit.betas[0] > 0:
        for i in range(1, n + 1):
            if fit.residual_norms[i - 1] <= rtol * scale[i] + atol:
                g_beta = i
            else:
                break

    # (1) Existence of a reparametrization: build u with u(a) = a, u^(j)(a) = β_j and
    #     check C^n of q o u against r.
    g_rep = 0
    if fit.betas[0] > 0:
        u = ChangeOfVariables.from_betas(
            fit.betas,
            end=a,
            image_end=a,
            max_width=q.domain[1] - q.domain[0],
            image_start_min=q.domain[0],
        )
        qbar = Reparametrized(q, u)
        dqbar = _end_derivs(qbar, a, n)
        g_rep = _matching_order(dqbar, dr, _scales(dqbar, dr, ell), rtol, atol)

    # (3) Arc length: derivatives with respect to arc length agree up to order n.
    Aq = _arc_length_derivatives_from(dq[:, None, :], np.array([vq]), n)[:, 0]
    Ar = _arc_length_derivatives_from(dr[:, None, :], np.array([vr]), n)[:, 0]
    sscale = np.array(
        [0.0]
        + [
            max(np.linalg.norm(Aq[k - 1]), np.linalg.norm(Ar[k - 1]), ell ** (1 - k))
            for k in range(1, n + 1)
        ]
    )
    g_arc = _matching_order(
        np.vstack([np.zeros((1, q.dim)), Aq]),
        np.vstack([np.zeros((1, q.dim)), Ar]),
        sscale,
        rtol,
        0.0,
    )

    return JointReport(
        index=index,
        point=tuple(map(float, dq[0])),
        gap=gap,
        tangent_angle=angle,
        curvature_jump=jump,
        c_order=c_order,
        g_order=g_beta,
        betas=tuple(map(float, fit.betas)),
        residuals=tuple(map(float, fit.residual_norms)),
        g_order_by={"reparametrization": g_rep, "beta_constraints": g_beta, "arc_length": g_arc},
        max_order=n,
    )


def curve_continuity(
    curve: object,
    max_order: int = 4,
    *,
    rtol: float = 1e-8,
    atol: float = 0.0,
) -> list[JointReport]:
    """One :class:`JointReport` per interior joint of a :class:`~course_lib.curve.PiecewiseBezier`.

    Derivatives are taken in the *global* parameter (segment ``i`` on
    ``[t_i, t_{i+1}]``, seed 004 §19.7), so the knots affect ``c_order`` but
    not ``g_order``.
    """
    from .curve import PiecewiseBezier

    if not isinstance(curve, PiecewiseBezier):
        raise TypeError(
            f"curve must be a PiecewiseBezier, got {type(curve).__name__}; "
            "use joint_continuity(q, r) for two parametrizations"
        )
    return [
        joint_continuity(
            _GlobalSegment(curve, i),
            _GlobalSegment(curve, i + 1),
            max_order,
            rtol=rtol,
            atol=atol,
            index=i,
        )
        for i in range(curve.n_joints)
    ]
