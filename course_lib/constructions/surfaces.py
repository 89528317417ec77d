"""Tensor-product Bézier patches and geometric continuity of surfaces (seed 001 §3).

A patch of degree ``(m, n)`` with control net ``P_{ij}`` (shape ``(m+1, n+1, 3)``) is
``F(u, v) = sum_ij P_ij B_i^m(u) B_j^n(v)`` on ``[0, 1]^2``.

Two patches ``F`` and ``G`` sharing the boundary ``F(1, v) = G(0, v)`` meet with G1
(tangent-plane continuity) iff their unit normals agree along it (seed 001 §3: the G1
bivariate Beta-constraints are equivalent to a common tangent plane with the same
orientation).  :func:`g1_neighbour_patch` builds such a ``G`` with the polynomial
shape-function scheme

.. math:: G_u(0, v) = α\\, F_u(1, v) + β(v)\\, F_v(1, v),
          \\qquad α > 0 \\text{ constant}, \\quad β(v) = β_0 (1 - v) + β_1 v,

which is the first-order bivariate Beta-constraint along the boundary with the
shape functions ``α`` and ``β``.  A constant ``α`` and linear ``β`` keep ``G`` of the
same degree ``n`` in ``v`` as ``F`` (``F_u(1, v)`` has degree ``n`` and
``F_v(1, v)`` degree ``n - 1``); then ``G_u × G_v = α F_u × F_v`` on the boundary, so
the normals agree and keep their orientation.

:func:`count_shape_functions` counts, with sympy's bivariate chain rule, the distinct
partial derivatives ``u^{(h,l)}, v^{(h,l)}`` (``1 <= h + l <= n``) that appear in the
partials of ``G(u(s, t), v(s, t))`` of orders ``1..n``: seed 001 §3 states there are
``n(n + 3)`` shape functions for G^n.

Lesson: ``notebooks/10_surfaces.ipynb``.
"""

from __future__ import annotations

from dataclasses import dataclass
from math import factorial

import numpy as np

from course_lib.curves.bezier import bernstein_matrix
from course_lib.validation import (
    as_parameter_array,
    check_finite_scalar,
    check_integer,
    check_positive,
)

__all__ = [
    "BezierPatch",
    "TangentPlaneReport",
    "count_shape_functions",
    "g1_neighbour_patch",
    "tangent_plane_continuity",
]


def _as_net(P: object, name: str = "control_net") -> np.ndarray:
    if isinstance(P, (str, bytes)) or P is None:
        raise TypeError(f"{name} must be an array of shape (m+1, n+1, 3)")
    try:
        N = np.asarray(P, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be an array of real numbers, shape (m+1, n+1, 3)") from None
    if N.ndim != 3 or N.shape[2] != 3 or N.shape[0] < 2 or N.shape[1] < 2:
        raise ValueError(
            f"{name} must have shape (m+1, n+1, 3) with m, n >= 1; got shape {N.shape}"
        )
    if not np.all(np.isfinite(N)):
        raise ValueError(f"{name} must contain only finite values")
    return N


def _diff_net(N: np.ndarray, k: int, axis: int) -> np.ndarray:
    d = N.shape[axis] - 1
    if k > d:
        shape = list(N.shape)
        shape[axis] = 1
        return np.zeros(shape)
    out = np.diff(N, n=k, axis=axis) if k else N
    return out * (factorial(d) / factorial(d - k))


class BezierPatch:
    """A tensor-product Bézier patch ``F(u, v)`` on ``[0, 1]^2``.

    Parameters
    ----------
    control_net : array_like of shape (m + 1, n + 1, 3)
    """

    __slots__ = ("_net",)

    def __init__(self, control_net: np.ndarray) -> None:
        N = _as_net(control_net)
        N.setflags(write=False)
        self._net = N

    @property
    def control_net(self) -> np.ndarray:
        return self._net

    @property
    def degree(self) -> tuple[int, int]:
        return self._net.shape[0] - 1, self._net.shape[1] - 1

    def __repr__(self) -> str:
        return f"BezierPatch(degree {self.degree})"

    def derivative_net(self, nu: int = 0, nv: int = 0) -> np.ndarray:
        """Control net of the partial derivative ``F^{(nu, nv)}`` (a Bézier patch itself)."""
        nu = check_integer(nu, "nu", minimum=0)
        nv = check_integer(nv, "nv", minimum=0)
        return _diff_net(_diff_net(self._net, nu, 0), nv, 1)

    def evaluate(
        self,
        u: float | np.ndarray,
        v: float | np.ndarray,
        nu: int = 0,
        nv: int = 0,
        *,
        grid: bool = True,
    ) -> np.ndarray:
        """Points or partial derivatives ``F^{(nu, nv)}(u, v)``.

        Parameters
        ----------
        u, v : float or 1-d array_like
        nu, nv : int
            Orders of differentiation in ``u`` and ``v``.
        grid : bool
            True: all pairs, result ``(len(u), len(v), 3)``; False: pointwise pairs
            (equal lengths), result ``(len(u), 3)``.  Scalars drop their axis.
        """
        Q = self.derivative_net(nu, nv)
        uu, su = as_parameter_array(u, "u")
        vv, sv = as_parameter_array(v, "v")
        Bu = bernstein_matrix(Q.shape[0] - 1, uu)
        Bv = bernstein_matrix(Q.shape[1] - 1, vv)
        if grid:
            out = np.einsum("ai,ijd,bj->abd", Bu, Q, Bv)
            if su:
                out = out[0]
            if sv:
                out = out[..., 0, :] if not su else out[0]
            return out
        if uu.size != vv.size:
            raise ValueError(
                f"with grid=False, u and v must have the same length; got {uu.size} and {vv.size}"
            )
        out = np.einsum("ai,ijd,aj->ad", Bu, Q, Bv)
        return out[0] if (su and sv) else out

    def normal(self, u: float | np.ndarray, v: float | np.ndarray, *, grid: bool = True):
        """Unit normals ``F_u × F_v / |F_u × F_v|``.

        Raises
        ------
        ValueError
            Where the patch is not regular (``F_u × F_v = 0``), naming the (u, v).
        """
        Fu = self.evaluate(u, v, 1, 0, grid=grid)
        Fv = self.evaluate(u, v, 0, 1, grid=grid)
        Nn = np.cross(Fu, Fv)
        L = np.linalg.norm(Nn, axis=-1)
        scale = np.linalg.norm(Fu, axis=-1) * np.linalg.norm(Fv, axis=-1)
        bad = L <= 1e-12 * np.maximum(scale, 1e-300)
        if np.any(bad):
            raise ValueError(
                "the patch is not regular (F_u x F_v = 0) at some (u, v): no normal there"
            )
        return Nn / L[..., None]


@dataclass(frozen=True)
class TangentPlaneReport:
    """Tangent-plane continuity along ``F(1, v) = G(0, v)`` sampled at ``v``.

    Attributes
    ----------
    gap : float
        Largest ``|F(1, v) - G(0, v)|``.
    max_angle : float
        Largest angle between the unit normals, in degrees (180 = opposite orientation).
    same_orientation : bool
        All normals point to the same side (``n_F · n_G > 0``).
    g1 : bool
        ``gap`` and ``max_angle`` within tolerance.
    """

    gap: float
    max_angle: float
    same_orientation: bool
    g1: bool


def tangent_plane_continuity(
    F: BezierPatch, G: BezierPatch, samples: int = 33, *, rtol: float = 1e-9
) -> TangentPlaneReport:
    """Check G1 (common tangent plane, same orientation) along ``F(1, v) = G(0, v)``.

    Parameters
    ----------
    F, G : BezierPatch
        ``F`` is used along its boundary ``u = 1``, ``G`` along ``u = 0``.
    samples : int
        Number of ``v`` values in ``[0, 1]``.
    rtol : float
        Relative tolerance for the gap (times the patches' size) and the angle (radians).

    Examples
    --------
    A flat patch and its G1 neighbour (``α = 1``, ``β = 0``), bent up beyond the first row:

    >>> import numpy as np
    >>> F = BezierPatch(np.array([[[i, j, 0.0] for j in range(3)] for i in range(3)]))
    >>> G = g1_neighbour_patch(F, np.array([[[3.0, j, 1.0] for j in range(3)]]))
    >>> tangent_plane_continuity(F, G).g1
    True
    """
    for name, X in (("F", F), ("G", G)):
        if not isinstance(X, BezierPatch):
            raise TypeError(f"{name} must be a BezierPatch, got {type(X).__name__}")
    samples = check_integer(samples, "samples", minimum=2)
    rtol = check_positive(rtol, "rtol")
    v = np.linspace(0.0, 1.0, samples)
    gap = float(np.max(np.linalg.norm(F.evaluate(1.0, v) - G.evaluate(0.0, v), axis=-1)))
    nF, nG = F.normal(1.0, v), G.normal(0.0, v)
    cosang = np.clip(np.einsum("vd,vd->v", nF, nG), -1.0, 1.0)
    sinang = np.linalg.norm(np.cross(nF, nG), axis=-1)
    ang = float(np.degrees(np.max(np.arctan2(sinang, cosang))))
    size = max(float(np.ptp(F.control_net.reshape(-1, 3), axis=0).max()), 1e-300)
    same = bool(np.all(cosang > 0))
    ok = gap <= rtol * size and np.radians(ang) <= rtol * 10 and same
    return TangentPlaneReport(gap, ang, same, bool(ok))


def g1_neighbour_patch(
    F: BezierPatch,
    rest: np.ndarray,
    alpha: float = 1.0,
    beta: tuple[float, float] | float = (0.0, 0.0),
) -> BezierPatch:
    """A patch ``G`` meeting ``F`` with G1 along ``G(0, v) = F(1, v)`` (seed 001 §3).

    ``G``'s first column of control points is ``F``'s last one, and its second is fixed by
    ``G_u(0, v) = α F_u(1, v) + β(v) F_v(1, v)`` with ``β(v) = β_0 (1-v) + β_1 v``
    (degree-raised product in Bernstein form, so ``G`` keeps ``F``'s degree in ``v``).

    Parameters
    ----------
    F : BezierPatch
        Degree ``(m, n)``.
    rest : array_like of shape (k - 1, n + 1, 3)
        The free rows ``G_{2..k}`` of ``G`` (degree ``k >= 2`` in ``u``); may be empty
        (then ``k = 1``).
    alpha : float
        Shape function ``α > 0`` (constant): ``α <= 0`` would flip or collapse the
        tangent plane.
    beta : float or (float, float)
        Values ``β(0), β(1)`` of the linear shape function (a scalar: constant).

    Returns
    -------
    BezierPatch
    """
    if not isinstance(F, BezierPatch):
        raise TypeError(f"F must be a BezierPatch, got {type(F).__name__}")
    a = check_positive(alpha, "alpha")
    bb, scalar = as_parameter_array(beta, "beta")
    if scalar:
        bb = np.array([bb[0], bb[0]])
    if bb.size != 2:
        raise ValueError(
            f"beta must be a scalar or the two values (beta(0), beta(1)); got {bb.size}"
        )
    b0, b1 = (check_finite_scalar(x, "beta") for x in bb)
    P = F.control_net
    m, n = F.degree
    R = np.asarray(rest, dtype=float)
    if R.size == 0:
        R = np.zeros((0, n + 1, 3))
    if R.ndim != 3 or R.shape[1:] != (n + 1, 3):
        raise ValueError(
            f"rest must have shape (k - 1, {n + 1}, 3): the free rows of G; got {R.shape}"
        )
    if not np.all(np.isfinite(R)):
        raise ValueError("rest must contain only finite values")
    k = R.shape[0] + 1
    Fu = m * (P[m] - P[m - 1])  # F_u(1, v): Bernstein coefficients of degree n
    Fv = n * np.diff(P[m], axis=0)  # F_v(1, v): degree n - 1
    j = np.arange(n + 1)[:, None]
    c = np.zeros((n + 1, 3))  # β(v) F_v(1, v) raised to degree n
    c[:n] += b0 * (n - j[:n]) / n * Fv
    c[1:] += b1 * j[1:] / n * Fv
    row0 = P[m]
    row1 = row0 + (a * Fu + c) / k
    return BezierPatch(np.concatenate([row0[None], row1[None], R], axis=0))


def count_shape_functions(n: int) -> int:
    """Number of shape functions for G^n surfaces, counted with sympy (seed 001 §3).

    Differentiates ``G(u(s, t), v(s, t))`` (undefined ``G, u, v``) in every way of
    total order ``1..n`` and counts the distinct partial derivatives
    ``u^{(h,l)}, v^{(h,l)}`` that occur.  The seed states ``n(n + 3)``.

    Examples
    --------
    >>> [count_shape_functions(n) for n in (1, 2, 3)]
    [4, 10, 18]
    """
    import sympy as sp

    n = check_integer(n, "n", minimum=1)
    # Every quantity is a symbol: G^{(a,b)} evaluated at (u, v), and the partials
    # u^{(h,l)}, v^{(h,l)} of the change of variables.  Differentiation in s (or t) is
    # the derivation with d/ds u^{(h,l)} = u^{(h+1,l)} and the bivariate chain rule
    #   d/ds G^{(a,b)}(u, v) = G^{(a+1,b)} u^{(1,0)} + G^{(a,b+1)} v^{(1,0)}.
    idx = [(a, b) for a in range(n + 2) for b in range(n + 2 - a)]
    syms = {(k, a, b): sp.Symbol(f"{k}_{a}_{b}") for k in "Guv" for a, b in idx}
    key = {sym: k for k, sym in syms.items()}

    def deriv(expr, ds: int, dt: int):
        out = sp.Integer(0)
        for sym in expr.free_symbols:
            k, a, b = key[sym]
            if k == "G":
                d = (
                    syms["G", a + 1, b] * syms["u", ds, dt]
                    + syms["G", a, b + 1] * syms["v", ds, dt]
                )
            else:
                d = syms[k, a + ds, b + dt]
            out += sp.diff(expr, sym) * d
        return sp.expand(out)

    found: set = set()
    D = {(0, 0): syms["G", 0, 0]}
    for order in range(1, n + 1):
        for i in range(order + 1):
            j = order - i
            D[(i, j)] = deriv(D[(i - 1, j)], 1, 0) if i else deriv(D[(i, j - 1)], 0, 1)
            found |= {key[x] for x in D[(i, j)].free_symbols if key[x][0] in "uv"}
    return len(found)
