"""The arc-length engine: exact lengths of Bézier segments, quadrature of any curve's speed.

The length of a segment ``q(u)``, ``u`` in ``[0, 1]``, is ``L = int_0^1 |q'(u)| du``
(seed 004 §19.2); it does not depend on the global parametrization, so the knot
spacing of a :class:`~course_lib.curves.curve.PiecewiseBezier` never enters.

**Fast path** (:func:`segment_lengths`, all segments of one degree at once, a handful of
numpy calls).  The hodograph ``q'(u) = d sum_i B^{d-1}_i(u) (P_{i+1} - P_i)`` is evaluated
from the control-point *differences* (exact for nearby points, so a curve far from the
origin loses nothing to translation) at the nodes of two composite Gauss-Legendre rules
-- :data:`ORDER` nodes on :data:`PIECES` equal subintervals (*coarse*) and on twice as
many (*fine*) -- with one precomputed matrix.  A segment's fine value is accepted when

1. the two rules agree to :data:`RTOL` (relative), and
2. the speed is bounded away from zero at the resolution of the nodes: with ``reach`` the
   largest distance from a point of ``[0, 1]`` to the nearest node and ``M`` the sum of
   the norms of the second-hodograph control points (``|q''| <= M``: convex hull), the
   smallest speed at the nodes is at least ``SEPARATION * reach * M``.  So ``|q'| >= (SEPARATION - 1)
   reach M > 0`` on the whole segment and the branch points of ``sqrt(q'.q')`` stay at
   least about a node spacing away from ``[0, 1]``: the nodes see every feature of the
   speed, and condition 1 is a meaningful error estimate.  (Without condition 2 both
   rules agree to 1e-16 on a speed dip narrower than the node spacing and are both
   wrong by up to 1e-11: ``tests/unit/test_arc_length.py``.)

**Second stage**: the segments the first stage does not certify (out of the safe range
after a power-of-two scaling, or with a strongly varying speed) are tried on a grid of
:data:`FINER_PIECES` subintervals with the same certificate.

**Robust path** (:func:`robust_length`), for every segment neither stage certifies: the
segment is scaled by powers of two (exact), split at the critical points of its speed in
``(0, 1)`` -- a near-cusp is a minimum of the speed, so it sits at the end of a piece --
and each piece is integrated on a mesh graded geometrically towards its ends, down to a
few times below the distance ``v / max|q''|`` of the speed's nearest complex zero; the
mesh and the mesh halved must agree to :data:`RTOL`.  If they do not, adaptive
Gauss-Legendre bisection (:func:`integrate_speed`, to
:data:`ROBUST_RTOL`) on the same pieces decides.  On 400 random near-cusps
(``eps`` from 1e-12 to 1e-1, anywhere in ``[0, 1]`` and just outside) the robust path is
within 5e-16 of mpmath.

**Any curve** (:func:`integrate_speed`): adaptive Gauss-Legendre of ``|c'|`` on intervals
(bisection until two levels agree), with the Bézier pieces of a ``PiecewiseBezier`` sent to
the certified rules above.  **Live pictures** (:func:`segment_arc_lengths`): fixed rules on
every segment's sampling grid, Bernstein matrices cached.  Every rule comes from one cache,
:func:`gauss_legendre`.

Why this module is long: it is the one arc-length engine of the course (the certified
fast path, the robust path, the adaptive quadrature for any curve and the fixed rules of the
pictures share their rules, constants and certificate); the public functions of
:mod:`course_lib.geometry.differential_geometry` call it.
"""

from __future__ import annotations

import math
from functools import lru_cache
from math import comb

import numpy as np

from course_lib.curves.bezier import bernstein_matrix, derivative_points
from course_lib.curves.curve import PiecewiseBezier
from course_lib.homework import own_work
from course_lib.validation import scaled_norm

__all__ = [
    "FINER_PIECES",
    "GRADED_ORDER",
    "ORDER",
    "PIECES",
    "ROBUST_RTOL",
    "RTOL",
    "SEPARATION",
    "bezier_curve_length",
    "bezier_piece_lengths",
    "breakpoints",
    "gauss_legendre",
    "hodograph_lengths",
    "integrate_speed",
    "piece_lengths",
    "robust_hodograph_length",
    "robust_length",
    "segment_arc_lengths",
    "segment_lengths",
    "speed_integrals",
]

#: Gauss-Legendre nodes per subinterval of both rules.
ORDER = 16
#: Subintervals of ``[0, 1]`` of the coarse rule; the fine rule has twice as many.
PIECES = 4
#: Subintervals of the coarse rule of the second stage, for the segments the first does
#: not certify (strongly varying speed; 93 % of random cubics pass one of the two stages).
FINER_PIECES = 32
#: Relative agreement of the coarse and fine rules required to accept the fine value.
RTOL = 1e-13
#: Smallest speed at the nodes, in units of ``reach * max|q''|`` (see the module notes).
SEPARATION = 4.0
#: Agreement of successive bisection levels required by the robust path.  Near a cusp the
#: level-to-level difference underestimates the error (1e-13 leaves up to 8e-13 on the
#: near-cusps of ``tests/unit/test_arc_length.py``); 1e-15 leaves about 2e-16.
ROBUST_RTOL = 1e-15
#: Gauss-Legendre nodes per subinterval of the robust path's graded mesh (on it every
#: singularity of the speed is at least about one subinterval away: ``rho >= 5.8``).
GRADED_ORDER = 10
# Most halvings of the graded mesh towards one end of a piece (2^-60 ~ 1e-18).
_MAX_LEVELS = 60
# The fast path sums plain squares: a length in this range proves that no square
# overflowed (|q'| <= C L for a polynomial, C far below 1e50) and that an underflow
# changed no speed by more than 1e-154, relative 1e-54.  Other segments are scaled by
# powers of two (exact) and tried again.
_RANGE = (1e-100, 1e100)


@lru_cache(maxsize=8)
def gauss_legendre(order: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss-Legendre nodes and weights on ``[-1, 1]`` (read-only, cached): the one rule of the
    course's quadratures.

    Examples
    --------
    The two-point rule integrates cubics exactly; its weights add up to the length of the
    interval:

    >>> nodes, weights = gauss_legendre(2)
    >>> float(weights.sum())
    2.0
    """
    x, w = np.polynomial.legendre.leggauss(order)
    x.setflags(write=False)
    w.setflags(write=False)
    return x, w


@lru_cache(maxsize=32)
def _rule(d: int, pieces: int = PIECES) -> tuple[np.ndarray, np.ndarray, float]:
    """Matrix, weights and reach of the fast path for degree ``d >= 2`` (coarse rule on
    ``pieces`` subintervals, fine rule on ``2 * pieces``).

    Returns
    -------
    G : ndarray of shape (d, M + d - 1)
        ``H.T @ G`` (``H`` the ``(d, dim)`` control-point differences) holds ``q'`` at the
        ``M`` nodes of both rules (coarse first), then the ``d - 1`` control points
        ``d (d - 1) (H_{i+1} - H_i)`` of the second hodograph.
    W : ndarray of shape (M + d - 1, 3)
        Column 0 the coarse weights, column 1 the fine ones, column 2 ones on the second
        hodograph (zero elsewhere): ``|X| @ W`` gives both rules and ``M`` in one product.
    reach : float
        Largest distance from a point of ``[0, 1]`` to the nearest node.
    """
    x, w = gauss_legendre(ORDER)
    nodes, weights = [], []
    for k in (pieces, 2 * pieces):
        h = 0.5 / k
        centres = (np.arange(k) + 0.5) / k
        nodes.append((centres[:, None] + h * x[None, :]).ravel())
        weights.append(np.broadcast_to(h * w, (k, ORDER)).ravel())
    u = np.concatenate(nodes)
    m = u.size
    W = np.zeros((m + d - 1, 3))
    W[: nodes[0].size, 0] = weights[0]
    W[nodes[0].size : m, 1] = weights[1]
    W[m:, 2] = 1.0
    G = np.zeros((d, m + d - 1))
    G[:, :m] = d * bernstein_matrix(d - 1, u).T
    for i in range(d - 1):
        G[i, m + i] = -d * (d - 1)
        G[i + 1, m + i] = d * (d - 1)
    s = np.concatenate([[0.0], np.sort(u), [1.0]])
    gaps = np.diff(s)
    reach = float(max(gaps[0], gaps[-1], 0.5 * gaps[1:-1].max()))
    G.setflags(write=False)
    W.setflags(write=False)
    return G, W, reach


def _fixed_grid(H: np.ndarray, pieces: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fine-rule lengths of the segments with control-point differences ``H`` (``(S, d,
    dim)``, ``d >= 2``) on ``pieces`` and ``2 * pieces`` subintervals, which of them the
    certificate accepts, and which lie in the safe range (plain sums of squares: no
    overflow or underflow can spoil them; see ``_RANGE``)."""
    d = H.shape[1]
    G, W, reach = _rule(d, pieces)
    m = W.shape[0] - d + 1
    with np.errstate(over="ignore", invalid="ignore"):
        X = np.matmul(H.transpose(0, 2, 1), G)  # (S, dim, m + d - 1)
        v = np.sqrt(np.einsum("sdm,sdm->sm", X, X))
        coarse, fine, bound = (v @ W).T
        in_range = (fine > _RANGE[0]) & (fine < _RANGE[1])
        ok = in_range & (np.abs(fine - coarse) <= RTOL * fine)
        ok &= v[:, :m].min(axis=1) >= SEPARATION * reach * bound
    return fine, ok, in_range


def _scaled_differences(arr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Control-point differences of each segment scaled by a power of two (exact) to a
    largest entry in ``[0.5, 1)``, and the exponents that undo it (no overflow even for
    coordinates near the float maximum: the points are scaled first)."""
    big = np.abs(arr).max(axis=(1, 2))
    e1 = np.frexp(np.where(big > 0, big, 1.0))[1]
    H = np.diff(np.ldexp(arr, -e1[:, None, None]), axis=1)
    Hs, e2 = _scaled(H)
    return Hs, e1 + e2


def _scaled(H: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Finite hodographs ``H`` (``(S, d, dim)``) scaled by powers of two to a largest entry
    in ``[0.5, 1)`` (zero stays zero), and the exponents that undo it."""
    small = np.abs(H).max(axis=(1, 2))
    e = np.frexp(np.where(small > 0, small, 1.0))[1]
    return np.ldexp(H, -e[:, None, None]), e


def _finish(
    H: np.ndarray,
    out: np.ndarray,
    ok: np.ndarray,
    in_range: np.ndarray,
    arr: np.ndarray | None = None,
) -> np.ndarray:
    """Complete ``out`` where ``ok`` is False: the segments out of range again after
    scaling, then the finer grid, then the robust path.  ``arr`` (the control points)
    is needed only where ``H`` overflowed."""
    out = np.where(ok, out, 0.0)
    bad = np.flatnonzero(~ok)
    Hb = H[bad]
    finite = np.isfinite(Hb).all(axis=(1, 2))
    Hs, e = _scaled(np.where(finite[:, None, None], Hb, 0.0))
    if not finite.all():
        Hs[~finite], e[~finite] = _scaled_differences(arr[bad[~finite]])
    if H.shape[1] == 1:  # lines: the length is the norm of the one difference
        out[bad] = np.ldexp(_norms_1(Hs[:, 0].T), e)
        return out
    again = ~in_range[bad]
    if again.any():
        fine, ok1, _ = _fixed_grid(Hs[again], PIECES)
        idx = np.flatnonzero(again)[ok1]
        out[bad[idx]] = np.ldexp(fine[ok1], e[idx])
        keep = np.ones(bad.size, dtype=bool)
        keep[idx] = False
        bad, Hs, e = bad[keep], Hs[keep], e[keep]
    fine, ok2, _ = _fixed_grid(Hs, FINER_PIECES)
    out[bad[ok2]] = np.ldexp(fine[ok2], e[ok2])
    for i in np.flatnonzero(~ok2):
        out[bad[i]] = np.ldexp(robust_hodograph_length(Hs[i]), e[i])
    return out


def hodograph_lengths(H: np.ndarray, arr: np.ndarray | None = None) -> np.ndarray:
    """Lengths ``int_0^1 |d sum_i B^{d-1}_i(u) H_i| du`` of Bézier segments given by their
    control-point differences ``H`` (``(S, d, dim)``, ``d >= 1``); ``arr``, the points,
    only if ``H`` may have overflowed."""
    own_work.require("course_lib.geometry.arc_length.hodograph_lengths")
    if H.shape[1] == 1:
        none = np.zeros(H.shape[0], dtype=bool)
        return _finish(H, np.zeros(H.shape[0]), none, none, arr)
    out, ok, in_range = _fixed_grid(H, PIECES)
    return out if ok.all() else _finish(H, out, ok, in_range, arr)


def segment_lengths(arr: np.ndarray) -> np.ndarray:
    """Lengths of Bézier segments of one degree, ``arr`` of shape ``(S, d + 1, dim)``.

    ``arr`` must be finite (a :class:`~course_lib.curves.curve.PiecewiseBezier` guarantees it);
    no other checks.  Relative accuracy about 1e-13 or better (see the module notes).
    """
    own_work.require("course_lib.geometry.arc_length.segment_lengths")
    if arr.shape[1] < 2:  # a point
        return np.zeros(arr.shape[0])
    with np.errstate(over="ignore", invalid="ignore"):
        H = arr[:, 1:] - arr[:, :-1]
    return hodograph_lengths(H, arr)


def piece_lengths(arr: np.ndarray, u0: np.ndarray, u1: np.ndarray) -> np.ndarray:
    """Lengths of the pieces ``u0_i <= u <= u1_i`` of Bézier segments ``arr[i]``
    (``(n, d + 1, dim)``, one degree, ``0 <= u0 <= u1 <= 1``).

    The piece is a Bézier curve whose control-point differences are ``(u1 - u0)`` times
    the blossom of the hodograph at ``(u0, ..., u0, u1, ..., u1)`` (de Casteljau on the
    differences, never on the points: nothing is lost to the curve's distance from the
    origin).  A whole segment (``u0 = 0``, ``u1 = 1``) gets its differences exactly, so
    its length is bit for bit the one :func:`segment_lengths` gives.
    """
    own_work.require("course_lib.geometry.arc_length.piece_lengths")
    n, p, _ = arr.shape
    if p < 2:
        return np.zeros(n)
    H, e = _scaled_differences(arr)
    k = p - 2  # degree of the hodograph
    a, b = u0[:, None, None], u1[:, None, None]
    R = np.empty_like(H)
    for j in range(k + 1):  # j arguments u1, k - j arguments u0
        B = H
        for step in range(k):
            t = b if step < j else a
            B = (1.0 - t) * B[:, :-1] + t * B[:, 1:]
        R[:, j] = B[:, 0]
    R *= (u1 - u0)[:, None, None]
    return np.ldexp(hodograph_lengths(R), e)


def segment_length(P: np.ndarray) -> float:
    """Length of one Bézier segment ``P`` of shape ``(d + 1, dim)``, ``d >= 2``, finite: the
    first stage of :func:`segment_lengths` on Python floats (one call's fixed cost matters
    here: a widget asks for one curve's length on every frame).

    ``P.P < 1e280`` (one BLAS call, which never warns) bounds every coordinate by 1e140, so
    no product below can overflow and no ``np.errstate`` (about 1.5 µs) is needed;
    ``hypot`` keeps the norms exact at every scale.  Larger curves take the guarded path.

    Examples
    --------
    A straight quadratic from (0, 0) to (3, 4) is 5 long:

    >>> import numpy as np
    >>> round(segment_length(np.array([[0.0, 0.0], [1.5, 2.0], [3.0, 4.0]])), 12)
    5.0
    """
    own_work.require("course_lib.geometry.arc_length.segment_length")
    d = P.shape[0] - 1
    if not np.vdot(P, P) < 1e280:
        return float(segment_lengths(P[None])[0])
    G, W, reach = _rule(d)
    X = (P[1:] - P[:-1]).T @ G
    v = np.hypot(X[0], X[1]) if X.shape[0] == 2 else np.hypot(np.hypot(X[0], X[1]), X[2])
    coarse, fine, bound = (v @ W).tolist()
    in_range = _RANGE[0] < fine < _RANGE[1]
    if (
        in_range
        and abs(fine - coarse) <= RTOL * fine
        and v[: 1 - d].min() >= SEPARATION * reach * bound
    ):
        return fine
    H = (P[1:] - P[:-1])[None]
    return float(_finish(H, np.zeros(1), np.zeros(1, dtype=bool), np.array([in_range]), P[None])[0])


def _norms_1(X: np.ndarray) -> np.ndarray:
    """Euclidean norms of the columns of ``X`` (``dim`` 2 or 3 rows) by ``hypot``."""
    v = np.hypot(X[0], X[1])
    return np.hypot(v, X[2]) if X.shape[0] == 3 else v


# ------------------------------------------------------------------ robust path
@lru_cache(maxsize=32)
def _bernstein_to_power(k: int) -> np.ndarray:
    """(k + 1, k + 1) matrix: power-basis coefficients (rows: u^0..u^k) of B^k_0..B^k_k."""
    M = np.zeros((k + 1, k + 1))
    for i in range(k + 1):
        for j in range(i, k + 1):
            M[j, i] = comb(k, j) * comb(j, i) * (-1) ** (j - i)
    M.setflags(write=False)
    return M


def _critical_points(H: np.ndarray) -> np.ndarray:
    """Parameters in ``(0, 1)`` where the speed ``|sum_i B^{d-1}_i(u) H_i|`` is stationary:
    real roots of ``(q'.q')' = 2 q'.q''`` (power basis, used only to split the interval)."""
    k = H.shape[0] - 1
    if k < 1:
        return np.zeros(0)
    C = _bernstein_to_power(k) @ H  # (k + 1, dim): q'(u) = sum_j C_j u^j
    der = C[1:] * np.arange(1, k + 1)[:, None]  # q''(u) = sum_j der_j u^j
    g = sum(np.convolve(C[:, c], der[:, c]) for c in range(H.shape[1]))  # degree 2k - 1
    nz = np.flatnonzero(g)
    if nz.size == 0 or nz[-1] == 0 or not np.all(np.isfinite(g)):
        return np.zeros(0)
    g = g[: nz[-1] + 1]
    n = g.size - 1  # roots: eigenvalues of the companion matrix of the monic polynomial
    companion = np.diag(np.ones(n - 1), -1)
    companion[:, -1] = -g[:-1] / g[-1]
    r = np.linalg.eigvals(companion)
    tol = 1e-7 * max(1.0, float(np.abs(r).max()))
    real = r.real[(np.abs(r.imag) <= tol) & (r.real > 0.0) & (r.real < 1.0)]
    return np.sort(real)


def robust_length(P: np.ndarray) -> float:
    """Length of one Bézier segment ``P`` (``(d + 1, dim)``, finite, any degree and scale)
    by the robust path alone (see :func:`robust_hodograph_length`)."""
    own_work.require("course_lib.geometry.arc_length.robust_length")
    if P.shape[0] < 2:
        return 0.0
    H, e = _scaled_differences(P[None])
    if H.shape[1] == 1:
        return float(np.ldexp(_norms_1(H[0, 0][:, None])[0], e[0]))
    return float(np.ldexp(robust_hodograph_length(H[0]), e[0]))


def robust_hodograph_length(H: np.ndarray) -> float:
    """``int_0^1 |d sum_i B^{d-1}_i(u) H_i| du`` for one segment's control-point
    differences ``H`` (``(d, dim)``, ``d >= 2``, scaled: largest entry in ``[0.5, 1)``).

    Split at the critical points of the speed, then the graded mesh of :func:`_graded`,
    and adaptive Gauss-Legendre bisection to :data:`ROBUST_RTOL` where that mesh is not
    certified.
    """
    own_work.require("course_lib.geometry.arc_length.robust_hodograph_length")
    d = H.shape[0]
    if not np.any(H):
        return 0.0
    grid = np.concatenate([[0.0], _critical_points(H), [1.0]])
    total = _graded(H, grid)
    if total is None:

        def speed(u: np.ndarray) -> np.ndarray:
            return _norms_1((bernstein_matrix(d - 1, u) @ H).T)

        total = float(integrate_speed(None, grid[:-1], grid[1:], ROBUST_RTOL, speed).sum())
    return d * total


def _levels(width: float, v: float, M: float) -> int:
    """Halvings of a piece of ``width`` towards an end where the speed is ``v`` and
    ``|q''| <= M``: the speed cannot vanish within ``v / M`` of the end, so the nearest
    singularity of the speed is about that far; grade down to a few times below it."""
    if M <= 0.0 or v >= M * width:
        return 2
    if v <= 0.0:
        return _MAX_LEVELS
    return min(_MAX_LEVELS, max(2, math.ceil(math.log2(M * width / v)) + 4))


def _graded(H: np.ndarray, grid: np.ndarray) -> float | None:
    """``int_0^1 |sum_i B_i(u) H_i| du`` (``H`` scaled, largest entry in ``[0.5, 1)``) on a
    mesh graded geometrically towards both ends of every piece ``[grid_j, grid_j+1]``
    (the pieces end at the critical points of the speed, so a near-cusp sits at an end,
    where the mesh resolves it down to a few times below the distance of the speed's
    nearest complex zero); Gauss-Legendre on the mesh and on the mesh halved, in one
    evaluation.  None when the two disagree by more than :data:`RTOL`."""
    k = H.shape[0] - 1
    speeds = np.sqrt(np.einsum("md,md->m", *(2 * [bernstein_matrix(k, grid) @ H])))
    M = k * float(np.sqrt(np.einsum("md,md->m", *(2 * [np.diff(H, axis=0)]))).sum()) if k else 0.0
    edges = []
    g, sp = grid.tolist(), speeds.tolist()
    for a, b, va, vb in zip(g[:-1], g[1:], sp[:-1], sp[1:], strict=True):
        w = b - a
        left = a + w * 2.0 ** -np.arange(_levels(w, va, M), 1, -1)
        right = b - w * 2.0 ** -np.arange(2, _levels(w, vb, M) + 1)
        edges.append(np.concatenate([[a], left, [a + 0.5 * w], right]))
    e = np.concatenate([*edges, [1.0]])
    lo, hi = e[:-1], e[1:]
    mid = 0.5 * (lo + hi)
    A = np.concatenate([lo, lo, mid])
    B = np.concatenate([hi, mid, hi])
    x, wts = gauss_legendre(GRADED_ORDER)
    half = 0.5 * (B - A)
    nodes = (0.5 * (A + B))[:, None] + half[:, None] * x
    X = bernstein_matrix(k, nodes.ravel()) @ H
    v = np.sqrt(np.einsum("md,md->m", X, X)).reshape(nodes.shape)
    vals = half * (v @ wts)
    n = lo.size
    coarse, fine = float(vals[:n].sum()), float(vals[n:].sum())
    return fine if abs(fine - coarse) <= RTOL * fine else None


# ------------------------------------------------- any curve: adaptive quadrature of the speed
def breakpoints(curve) -> np.ndarray:
    """Parameters where the curve may fail to be smooth: knots (if any) and the domain ends."""
    a, b = curve.domain
    bp = getattr(curve, "breakpoints", None)
    if bp is None:
        bp = getattr(curve, "knots", None)
    if bp is None:
        return np.array([a, b], dtype=float)
    bp = np.asarray(bp, dtype=float)
    return np.unique(np.concatenate([[a, b], bp[(bp > a) & (bp < b)]]))


def speed_integrals(curve, a: np.ndarray, b: np.ndarray, order: int = 20, speed=None) -> np.ndarray:
    """Gauss-Legendre approximation of int_a^b |c'| on each interval (vectorized).

    ``speed``, if given, replaces ``|c'|``: a function of a 1-d parameter array."""
    x, w = gauss_legendre(order)
    half = 0.5 * (b - a)
    nodes = (0.5 * (a + b))[:, None] + half[:, None] * x[None, :]
    if speed is not None:
        v = speed(nodes.ravel()).reshape(nodes.shape)
    else:
        v = scaled_norm(curve.evaluate(nodes.ravel(), 1), axis=-1).reshape(nodes.shape)
    return half * (v @ w)


def integrate_speed(
    curve, a: np.ndarray, b: np.ndarray, rtol: float = 1e-13, speed=None
) -> np.ndarray:
    """Adaptive Gauss-Legendre (20 nodes, bisection) of |c'| on each ``[a_i, b_i]``.

    An interval is accepted when its 20-node value and the sum of the values on
    its two halves agree to ``rtol`` (relative; the finer value is kept) -- for the
    smooth speeds of polynomial and analytic curves after zero or one bisection.
    ``speed`` (optional) replaces ``|c'|``, as in :func:`speed_integrals`.

    For a :class:`~course_lib.curves.curve.PiecewiseBezier` and intervals that each lie in one
    segment (the callers split at the knots), every interval is a Bézier
    piece measured by :func:`piece_lengths` instead: the same
    certified rules as :func:`bezier_curve_length`, accurate near cusps too.
    """
    own_work.require("course_lib.geometry.arc_length.integrate_speed")
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    if speed is None and type(curve) is PiecewiseBezier and a.size:
        pieces = bezier_piece_lengths(curve, a, b)
        if pieces is not None:
            return pieces
    total = np.zeros(a.size)
    if a.size == 0:
        return total
    owner = np.arange(a.size)
    k = a.size
    mid = 0.5 * (a + b)
    # one vectorized evaluation per level: the whole intervals (first level only) and halves
    first = speed_integrals(curve, np.concatenate([a, a, mid]), np.concatenate([b, mid, b]), speed=speed)
    whole, left, right = first[:k], first[k : 2 * k], first[2 * k :]
    scale = max(float(np.abs(whole).sum()), 1e-300)
    for depth in range(60):
        if depth:
            k = a.size
            mid = 0.5 * (a + b)
            halves = speed_integrals(curve, np.concatenate([a, mid]), np.concatenate([mid, b]), speed=speed)
            left, right = halves[:k], halves[k:]
        both = left + right
        err = np.abs(both - whole)
        ok = (err <= rtol * np.abs(both)) | (err <= 1e-15 * scale)
        if depth == 59 or a.size > 20000:  # give up refining (e.g. a cusp): keep the best value
            ok[:] = True
        np.add.at(total, owner[ok], both[ok])
        if np.all(ok):
            break
        bad = ~ok
        a = np.concatenate([a[bad], mid[bad]])
        b = np.concatenate([mid[bad], b[bad]])
        whole = np.concatenate([left[bad], right[bad]])
        owner = np.concatenate([owner[bad], owner[bad]])
    return total


def bezier_piece_lengths(curve: PiecewiseBezier, a: np.ndarray, b: np.ndarray) -> np.ndarray | None:
    """Lengths of ``curve`` on ``[a_i, b_i]`` as Bézier pieces, or None unless each interval
    lies in one segment."""
    k = curve.knots
    last = k.size - 2
    seg = np.clip(np.searchsorted(k, a, side="right") - 1, 0, last)
    if np.any(np.clip(np.searchsorted(k, b, side="left") - 1, 0, last) > seg):
        return None
    h = k[seg + 1] - k[seg]
    u0 = np.clip((a - k[seg]) / h, 0.0, 1.0)
    u1 = np.clip((b - k[seg]) / h, 0.0, 1.0)
    u0[a <= k[seg]] = 0.0  # exact ends: a whole segment is measured exactly as arc_length does
    u1[b >= k[seg + 1]] = 1.0
    if curve.uniform_array is not None:
        return piece_lengths(curve.uniform_array[seg], u0, u1)
    out = np.empty(a.size)
    for _d, _idx, rows, points in curve.segments_by_degree(0):  # one call per degree present
        r = rows[seg]
        m = r >= 0
        if m.any():
            out[m] = piece_lengths(points[r[m]], u0[m], u1[m])
    return out


# ------------------------------------------------------- whole curves and live pictures
def bezier_curve_length(curve: PiecewiseBezier) -> float:
    """Length of a whole :class:`~course_lib.curves.curve.PiecewiseBezier`: the sum of its segment
    lengths (each independent of the knots), one vectorized call per degree."""
    arr = curve.uniform_array
    if arr is not None:
        if arr.shape[0] == 1 and arr.shape[1] > 2:
            return segment_length(arr[0])
        return float(segment_lengths(arr).sum())
    return float(sum(segment_lengths(stack).sum() for _, _, _, stack in curve.segments_by_degree(0)))


@lru_cache(maxsize=32)
def _gauss_bernstein(degree: int, breaks: tuple, order: int) -> tuple[np.ndarray, np.ndarray]:
    """Bernstein matrix at the Gauss-Legendre nodes of every ``[breaks[j], breaks[j+1]]``
    and the matching weights (``half-length * w``), both flattened interval by interval."""
    x, w = gauss_legendre(order)
    br = np.asarray(breaks)
    half = 0.5 * np.diff(br)
    nodes = (0.5 * (br[:-1] + br[1:]))[:, None] + half[:, None] * x[None, :]
    B = np.array(bernstein_matrix(degree, nodes.ravel()), dtype=float)
    W = (half[:, None] * w[None, :]).ravel()
    B.setflags(write=False)
    W.setflags(write=False)
    return B, W


def segment_arc_lengths(curve, per_segment: int, idx: np.ndarray, order: int = 16):
    """Arc length from the start of the curve at the local samples ``idx`` of every
    segment's grid, shape ``(S, len(idx))``, or None if the curve is not a PiecewiseBezier
    of one degree (then use :func:`course_lib.geometry.differential_geometry.cumulative_arc_length`).
    For live pictures: the segments' local grids of :mod:`course_lib.geometry.sampling`.

    ``idx`` must start with 0 and end with ``per_segment - 1``.  Each piece between
    consecutive samples is a fixed ``order``-node Gauss-Legendre sum of the speed
    ``|dq/du|`` (``ds = |dq/du| du``), with the Bernstein matrix at the nodes cached: the
    nodes are the same local parameters on every frame.  On the smooth speeds of regular
    polynomial pieces this agrees with the adaptive quadrature of ``cumulative_arc_length``
    to about 1e-12 relative (tests/unit/test_plotting.py); meant for live pictures.
    """
    if curve.uniform_array is None:
        return None
    d = curve.degrees[0]
    u = np.linspace(0.0, 1.0, per_segment)[np.asarray(idx)]
    B, W = _gauss_bernstein(d - 1, tuple(u.tolist()), order)
    Q = derivative_points(curve.uniform_array, 1)  # hodograph points (S, d, dim)
    speed = np.linalg.norm(np.matmul(B, Q), axis=-1)  # (S, J * order)
    pieces = (speed * W).reshape(speed.shape[0], -1, order).sum(axis=-1)  # (S, J)
    within = np.concatenate([np.zeros((pieces.shape[0], 1)), np.cumsum(pieces, axis=1)], axis=1)
    start = np.concatenate([[0.0], np.cumsum(within[:-1, -1])])
    return within + start[:, None]
