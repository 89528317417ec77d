"""The evaluation engine behind :class:`~course_lib.curves.curve.PiecewiseBezier` (its "hazmat").

``PiecewiseBezier`` is the façade: it validates, owns the control points and knots, and
answers in the course's terms.  Each curve hands its data to one :class:`Evaluator`, made on
first use, which holds the fast paths of ``evaluate`` and their caches:

* the **two-sided Taylor form** (:meth:`Evaluator.taylor`): every segment split at ``u = 1/2``
  and expanded at its nearer end, evaluated by Horner's rule (:func:`horner_chunk`, in chunks
  of :data:`CHUNK` parameters; :meth:`Evaluator.horner_one` for one parameter on Python
  floats, the same bits) -- for hodographs of degree up to :data:`TAYLOR_MAX_DEGREE`;
* the **Bernstein form** of the located segments grouped by degree
  (:meth:`Evaluator.eval_located`), above that degree, and for curves of at least
  :data:`LAZY_MIN_SEGMENTS` segments evaluated at few parameters (building the whole Taylor
  table would cost more than it saves).

Nothing here checks its input: the façade has.
"""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable
from functools import lru_cache
from math import comb, factorial

import numpy as np

from course_lib.curves.bezier import bernstein_matrix, derivative_points

__all__ = ["CHUNK", "LAZY_MIN_SEGMENTS", "TAYLOR_MAX_DEGREE", "Evaluator", "horner_chunk", "taylor_matrix"]

#: Hodographs of degree up to this are evaluated from the two-sided Taylor form
# (Evaluator.taylor); above it, from the Bernstein form (stable for any degree).
TAYLOR_MAX_DEGREE = 8
#: Curves with at least this many segments, evaluated at fewer than 4 parameters per
#: segment before any table exists, are evaluated from the Bernstein form of the located
#: segments only (building the O(segments) Taylor table would cost more than it saves).
LAZY_MIN_SEGMENTS = 4096
#: Parameters are evaluated in chunks of this many so the temporaries stay in cache.
CHUNK = 1 << 15



def horner_chunk(t: np.ndarray, table: np.ndarray, halves: tuple, out: np.ndarray) -> None:
    """Evaluate the two-sided Taylor form at in-domain parameters ``t`` into ``out``."""
    bp, anchor, hh, unit = halves
    last = anchor.size - 1
    # j is within [0, last] by construction: mode="clip" skips take()'s bounds checks.
    if unit:
        # Knots 0, 1, ..., S and t >= 0: the half-segment index is floor(2 t), exactly,
        # and t - anchor is exact (Sterbenz), so no search and no division.
        j = (t * 2.0).astype(np.intp)
        np.minimum(j, last, out=j)
        w = t - anchor.take(j, mode="clip")
    else:
        j = np.searchsorted(bp, t, side="right")
        j -= 1
        np.clip(j, 0, last, out=j)
        w = t - anchor.take(j, mode="clip")
        w /= hh.take(j, mode="clip")
    # One coordinate at a time on contiguous 1-d arrays (the table is laid out
    # (level, coordinate, half) for that): an (m, dim) array times an (m, 1) column
    # runs an inner loop of length dim and costs several times more.
    top = table.shape[0] - 1
    for c in range(table.shape[1]):
        acc = table[top, c].take(j, mode="clip")
        if top == 0:
            out[:, c] = acc
            continue
        for k in range(top - 1, 0, -1):
            acc *= w
            acc += table[k, c].take(j, mode="clip")
        acc *= w
        np.add(acc, table[0, c].take(j, mode="clip"), out=out[:, c])


@lru_cache(maxsize=64)
def taylor_matrix(d: int, n: int) -> np.ndarray:
    """Integer matrix taking a degree-``d`` control polygon ``P`` to the two-sided Taylor
    coefficients of its n-th derivative (see :meth:`Evaluator.taylor`).

    With ``e = d - n`` and ``Δ^m P_i = sum_j (-1)^(m-j) C(m, j) P_(i+j)``, row ``k`` is
    ``C(e, k) d!/e! Δ^(n+k) P_0`` (expansion at ``u = 0``) and row ``e + 1 + k`` is
    ``C(e, k) d!/e! Δ^(n+k) P_(e-k)`` (expansion at ``u = 1``), ``k = 0..e``.
    Built in exact integer arithmetic.
    """
    e = d - n
    M = np.zeros((2 * (e + 1), d + 1))
    for k in range(e + 1):
        m = n + k
        c = comb(e, k) * (factorial(d) // factorial(e))
        for j in range(m + 1):
            w = c * comb(m, j) * (-1) ** (m - j)
            M[k, j] = w
            M[e + 1 + k, e - k + j] = w
    M.setflags(write=False)
    return M


class Evaluator:
    """The fast paths of one curve's evaluation, with their caches.

    Parameters
    ----------
    array : ndarray of shape (S, d + 1, dim) or None
        All control points when every segment has degree ``d`` (read-only).
    segments : tuple of ndarray or None
        The control polygons when the degrees differ (``array`` is then None).
    degrees : tuple of int
    knots : ndarray of shape (S + 1,)
    dim : int
    check_domain : callable
        The façade's domain check of a parameter array (raises outside the domain).

    Examples
    --------
    The engine is reached through the façade, :meth:`PiecewiseBezier.evaluate`:

    >>> from course_lib import PiecewiseBezier
    >>> PiecewiseBezier([[[0, 0], [1, 1], [2, 0]]]).evaluate(0.5)
    array([1. , 0.5])
    """

    __slots__ = ("array", "cache", "check_domain", "degrees", "dim", "knots", "segments")

    def __init__(
        self,
        array: np.ndarray | None,
        segments: tuple[np.ndarray, ...] | None,
        degrees: tuple[int, ...],
        knots: np.ndarray,
        dim: int,
        check_domain: Callable[[np.ndarray], bool],
    ) -> None:
        self.array, self.segments, self.degrees = array, segments, degrees
        self.knots, self.dim, self.check_domain = knots, dim, check_domain
        self.cache: dict = {}

    @property
    def n_segments(self) -> int:
        return len(self.degrees)

    def locate(self, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Segment index and local parameter of in-domain global parameters ``tt``."""
        k = self.knots
        self.check_domain(tt)
        idx = np.clip(np.searchsorted(k, tt, side="right") - 1, 0, self.n_segments - 1)
        u = (tt - k[idx]) / (k[idx + 1] - k[idx])
        return idx, np.clip(u, 0.0, 1.0)

    def evaluate(self, tt: np.ndarray, n: int, clip: bool) -> np.ndarray:
        """Points (``n = 0``) or n-th global derivatives at the checked parameters ``tt``
        (``clip``: some lie within rounding outside the domain), shape ``(m, dim)``."""
        few = (
            self.n_segments >= LAZY_MIN_SEGMENTS
            and tt.size < 4 * self.n_segments
            and ("taylor", n) not in self.cache
        )
        table = None if few else self.taylor(n)
        if table is None:
            idx, u = self.locate(tt)
            out = self.eval_located(idx, u, n)
            if n:
                h = np.diff(self.knots)
                out *= (h[idx] ** -float(n))[:, None]
        elif tt.size == 1:
            out = self.horner_one(float(tt[0]), n)[None, :]
        else:
            if clip:
                tt = np.clip(tt, self.knots[0], self.knots[-1])
            out = np.empty((tt.size, self.dim))
            halves = self.halves()
            for s in range(0, tt.size, CHUNK):
                horner_chunk(tt[s : s + CHUNK], table, halves, out[s : s + CHUNK])
        return out

    def segments_by_degree(self, n: int) -> list[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
        """See :meth:`~course_lib.curves.curve.PiecewiseBezier.segments_by_degree`."""
        key = ("stack", n)
        if key not in self.cache:
            if self.array is not None:
                S = self.n_segments
                stack = derivative_points(self.array, n)
                self.cache[key] = [(self.degrees[0], np.arange(S), np.arange(S), stack)]
                return self.cache[key]
            groups: dict[int, list[int]] = {}
            for i, d in enumerate(self.degrees):
                groups.setdefault(d, []).append(i)
            out = []
            for d, idx in groups.items():
                rows = np.full(self.n_segments, -1)
                rows[idx] = np.arange(len(idx))
                stack = np.stack([derivative_points(self.segments[i], n) for i in idx])
                out.append((d, np.array(idx), rows, stack))
            self.cache[key] = out
        return self.cache[key]

    def taylor(self, n: int) -> np.ndarray | None:
        """Two-sided Taylor coefficients of the n-th global derivative, or None.

        Segment ``i`` is split at ``u = 1/2``.  With ``Q`` the control points of its
        n-th hodograph (degree ``e``), the left half is expanded at ``u = 0`` and
        the right half at ``u = 1``:

        .. math:: q^{(n)}(u) = \\sum_k \\binom{e}{k} \\Delta^k Q_0\\, u^k
                 = \\sum_k \\binom{e}{k} \\Delta^k Q_{e-k}\\, (u - 1)^k,

        the Taylor coefficients being the end derivatives of seed 000
        eq. (8.1)-(8.3) divided by ``k!``.  Row ``2 i`` (left) and ``2 i + 1``
        (right) of ``table[k]`` hold the coefficients of ``w^k`` times
        ``h_i^{-n}`` (the chain rule), zero-padded to the largest degree (the table's
        shape is ``(levels, dim, 2 S)``: level ``k``, coordinate, half-segment).  As
        ``|Δ^k Q| <= 2^k max|Q|`` and ``|w| <= 1/2``, the terms sum to at most
        ``2^e max|Q|`` in absolute value, so Horner's rule loses a small multiple of
        ``2^e`` ulps of ``max|Q|`` -- below 1e-13 relative up to ``e = 8``
        (tests/unit/test_curve_fast_paths.py) -- and the segment ends (``w = 0``)
        are exact.  ``None`` when some ``e`` exceeds ``TAYLOR_MAX_DEGREE``.
        """
        key = ("taylor", n)
        if key not in self.cache:
            top = max(0, (self.degrees[0] if self.array is not None else max(self.degrees)) - n)
            self.cache[key] = None if top > TAYLOR_MAX_DEGREE else self.taylor_table(n, top)
        return self.cache[key]

    def taylor_table(self, n: int, top: int) -> np.ndarray:
        """Build the table of :meth:`taylor`: one matrix product per degree present
        (curves are rebuilt on every slider move, so this must be cheap too)."""
        h = np.diff(self.knots)
        scale = h ** -float(n) if n else np.ones_like(h)
        if self.array is not None:
            d = self.degrees[0]
            e = d - n
            table = np.empty((top + 1, self.dim, 2 * self.n_segments))
            if e < 0:
                table[:] = 0.0
            else:
                S, dim = self.n_segments, self.dim
                A = self.array.transpose(1, 2, 0).reshape(d + 1, dim * S)
                C = (taylor_matrix(d, n) @ A).reshape(2 * (e + 1), dim, S)  # one GEMM
                if n:
                    C *= scale
                table[: e + 1, :, 0::2] = C[: e + 1]
                table[: e + 1, :, 1::2] = C[e + 1 :]
            table.setflags(write=False)
            return table
        table = np.zeros((top + 1, self.dim, 2 * self.n_segments))
        for d, idx, _rows, Q in self.segments_by_degree(0):  # Q: (G, d + 1, dim)
            e = d - n
            if e < 0:  # derivative order above the degree: the zero polynomial
                continue
            C = np.matmul(taylor_matrix(d, n), Q) * scale[idx][:, None, None]
            table[: e + 1, :, 2 * idx] = C[:, : e + 1].transpose(1, 2, 0)
            table[: e + 1, :, 2 * idx + 1] = C[:, e + 1 :].transpose(1, 2, 0)
        table.setflags(write=False)
        return table

    def horner_one(self, x: float, n: int) -> np.ndarray:
        """One parameter: the same arithmetic as :func:`horner_chunk` on Python floats
        (same operations in the same order, so the same bits), without array overhead."""
        key = ("taylor-lists", n)
        if key not in self.cache:
            bp, anchor, hh, unit = self.halves()
            table = self.taylor(n).transpose(0, 2, 1)  # (level, half, coordinate)
            rows = [[tuple(p) for p in level] for level in table.tolist()]
            self.cache[key] = (bp.tolist(), anchor.tolist(), hh.tolist(), unit, rows)
        bp, anchor, hh, unit, rows = self.cache[key]
        if not bp[0] <= x <= bp[-1]:
            self.check_domain(np.array([x]))  # raises unless within rounding tolerance
            x = min(max(x, bp[0]), bp[-1])
        last = len(anchor) - 1
        if unit:
            j = min(int(2.0 * x), last)
            w = x - anchor[j]
        else:
            j = min(max(bisect_right(bp, x) - 1, 0), last)
            w = (x - anchor[j]) / hh[j]
        acc = rows[-1][j]
        for level in reversed(rows[:-1]):
            acc = [a * w + c for a, c in zip(acc, level[j], strict=True)]
        return np.array(acc, dtype=float)

    def halves(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
        """Half-segment breakpoints, anchors (the expansion points) and lengths.

        Half ``j`` of segment ``i = j // 2`` is ``[t_i, m_i]`` (``j`` even, anchor
        ``t_i``) or ``[m_i, t_{i+1}]`` (``j`` odd, anchor ``t_{i+1}``), ``m_i`` the
        midpoint; the last flag is True for the default knots ``0, 1, ..., S``.
        """
        if "halves" not in self.cache:
            k = self.knots
            S = self.n_segments
            bp = np.empty(2 * S + 1)
            bp[0::2] = k
            bp[1::2] = 0.5 * (k[:-1] + k[1:])
            anchor = np.empty(2 * S)
            anchor[0::2] = k[:-1]
            anchor[1::2] = k[1:]
            unit = bool(np.array_equal(k, np.arange(S + 1, dtype=float)))
            self.cache["halves"] = (bp, anchor, np.repeat(np.diff(k), 2), unit)
        return self.cache["halves"]

    def eval_located(self, idx: np.ndarray, u: np.ndarray, n: int) -> np.ndarray:
        stacks = self.segments_by_degree(n)
        if len(stacks) == 1:
            _, _, rows, stack = stacks[0]
            B = bernstein_matrix(stack.shape[1] - 1, u)
            return np.einsum("mk,mkd->md", B, stack[rows[idx]])
        out = np.empty((u.size, self.dim))
        for _, _, rows, stack in stacks:
            r = rows[idx]
            mask = r >= 0
            B = bernstein_matrix(stack.shape[1] - 1, u[mask])
            out[mask] = np.einsum("mk,mkd->md", B, stack[r[mask]])
        return out
