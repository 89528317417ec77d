"""The course's one curve type: a piecewise Bézier curve with an optional knot sequence.

Every construction of the course (stitching, Catmull-Rom, Beta-splines, Finn's
knot-based G1 splines, ...) returns a :class:`PiecewiseBezier`; every analysis,
plot and widget consumes one.  Data flows one way::

    construct  ->  PiecewiseBezier  ->  evaluate / analyse  ->  plot

Parametrization
---------------
Segment ``i`` is a Bézier curve ``q_i(u)``, ``u`` in ``[0, 1]`` (its *local*
parameter), of any degree ``>= 1``.  A knot sequence ``t_0 < t_1 < ... < t_S``
(``S`` segments) gives a *global* parameter ``t`` in ``[t_0, t_S]``: on
``[t_i, t_{i+1}]`` the curve is ``q_i((t - t_i) / (t_{i+1} - t_i))`` (seed 004,
§19.7).  Without knots the curve uses ``t_i = i``.  Derivatives in the global
parameter carry the chain-rule factor ``(t_{i+1} - t_i)^{-n}``.

Lesson: ``notebooks/01_parametric_continuity.ipynb`` (piecewise curves and joints),
``notebooks/06_g1_knot_bezier_splines.ipynb`` (the global parameter).

Why this module is long: it is the façade of the one curve type -- construction and
validation, the accessors every other module reads, the local and global parameters -- and
its methods are documented where they are; the evaluation engine is already apart
(:mod:`course_lib.curves.evaluation`).
"""

from __future__ import annotations

import warnings
from collections.abc import Mapping, Sequence
from itertools import pairwise
from types import MappingProxyType

import numpy as np

from course_lib.curves.bezier import bernstein_matrix, derivative_points, end_derivative_points
from course_lib.curves.evaluation import Evaluator
from course_lib.validation import (
    as_parameter_array,
    as_points,
    as_real_array,
    check_integer,
    check_knots,
)

__all__ = ["PiecewiseBezier"]

def _uniform_array(segments: object) -> np.ndarray | None:
    """``segments`` as one validated float array (S, d + 1, dim) when it is one (an
    ndarray or a sequence of equally shaped polygons), else None (then each segment is
    validated on its own, which names the offending one)."""
    if isinstance(segments, (str, bytes)) or segments is None:
        return None
    if not isinstance(segments, np.ndarray):
        try:
            first = segments[0]  # type: ignore[index]
            if not isinstance(first, np.ndarray):
                return None  # nested Python lists: the per-segment path is fast enough
        except (TypeError, IndexError, KeyError):
            return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            arr = np.asarray(segments)
    except (TypeError, ValueError, Warning):
        return None
    if arr.ndim != 3 or arr.dtype.kind not in "biuf" or arr.shape[0] == 0:
        return None
    if arr.shape[1] < 2 or arr.shape[2] not in (2, 3) or not np.isfinite(arr).all():
        return None  # let the per-segment checks name the segment and the rule
    out = arr.astype(float)  # always a copy: the curve owns its data
    out.setflags(write=False)
    return out


def _readonly(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


class PiecewiseBezier:
    """A curve made of Bézier segments, optionally parametrized by a knot sequence.

    Parameters
    ----------
    segments : sequence of array_like, each of shape (d_i + 1, dim)
        The Bézier control polygon of each segment, in order.  Degrees may differ
        from segment to segment (``d_i >= 1``); all segments share ``dim`` (2 or 3).
        Consecutive segments are *not* required to meet: a gap is a fact the
        continuity analysis reports, not an input error.
    knots : array_like of shape (len(segments) + 1,), optional
        Strictly increasing global parameter values of the segment ends.  Default:
        ``0, 1, ..., len(segments)``.
    info : mapping, optional
        Read-only facts about how the curve was built (shape parameters per joint,
        construction points such as Farin-Boehm's ``T``), for plots and reports.

    Raises
    ------
    ValueError
        If there is no segment, a segment has fewer than 2 control points, points
        are not finite, dimensions differ, or knots are not strictly increasing.
    TypeError
        If a segment is not an array of real numbers.

    Examples
    --------
    Two quadratic segments meeting at (2, 0):

    >>> c = PiecewiseBezier([[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]]])
    >>> c.n_segments, c.degrees, c.domain
    (2, (2, 2), (0.0, 2.0))
    >>> c.evaluate(1.0)
    array([2., 0.])
    """

    __slots__ = ("_array", "_degrees", "_engine", "_info", "_knots", "_segments", "has_knots")

    def __init__(
        self,
        segments: Sequence[np.ndarray],
        knots: Sequence[float] | np.ndarray | None = None,
        *,
        info: Mapping[str, object] | None = None,
    ) -> None:
        if isinstance(segments, np.ndarray) and segments.ndim == 2:
            raise ValueError(
                "segments must be a sequence of control polygons; to build a curve from one "
                "polygon use PiecewiseBezier([points]) or PiecewiseBezier.from_control_points"
            )
        arr = _uniform_array(segments)
        if arr is not None:  # one degree: validated and stored as one (S, d + 1, dim) array
            has_knots = knots is not None
            k = (
                check_knots(knots, "knots", count=arr.shape[0] + 1)
                if has_knots
                else np.arange(arr.shape[0] + 1, dtype=float)
            )
            self._init_array(arr, k, has_knots, info)
            return
        try:
            seg_list = list(segments)
        except TypeError:
            raise TypeError(
                f"segments must be a sequence of control polygons, got {type(segments).__name__}"
            ) from None
        if not seg_list:
            raise ValueError("segments must contain at least one Bézier segment")
        segs = [as_points(s, f"segments[{i}]", min_points=2) for i, s in enumerate(seg_list)]
        dim = segs[0].shape[1]
        for i, s in enumerate(segs):
            if s.shape[1] != dim:
                raise ValueError(
                    f"segments[{i}] has dimension {s.shape[1]} but segments[0] has dimension "
                    f"{dim}; all segments must live in the same space"
                )
        has_knots = knots is not None
        k = (
            check_knots(knots, "knots", count=len(segs) + 1)
            if has_knots
            else np.arange(len(segs) + 1, dtype=float)
        )
        self._init(segs, k, has_knots, info)

    def _init(self, segs, knots, has_knots, info) -> None:
        shapes = {s.shape for s in segs}
        if len(shapes) == 1 and len(segs) > 1:
            self._init_array(np.stack(segs), knots, has_knots, info)
            return
        self._segments = tuple(_readonly(s) for s in segs)
        self._array = None
        self._degrees = tuple(s.shape[0] - 1 for s in self._segments)
        self._knots = _readonly(knots)
        self.has_knots = bool(has_knots)
        self._info = MappingProxyType(dict(info or {}))
        self._engine: Evaluator | None = None

    def _init_array(self, arr, knots, has_knots, info) -> None:
        """Uniform degree: the segments are one read-only (S, d + 1, dim) array (no
        per-segment copies; the evaluation tables are built from it in one product)."""
        self._array = arr if not arr.flags.writeable and arr.dtype == float else _readonly(arr)
        self._segments = None  # views, made on first access of ``segments``
        self._degrees = (arr.shape[1] - 1,) * arr.shape[0]
        self._knots = _readonly(knots)
        self.has_knots = bool(has_knots)
        self._info = MappingProxyType(dict(info or {}))
        self._engine: Evaluator | None = None

    @classmethod
    def from_trusted_segments(cls, segments, knots=None, info=None) -> PiecewiseBezier:
        """Construct without validation: for constructions whose segments are finite float arrays
        of shape ``(d + 1, dim)`` by construction (a list, or one ``(S, d + 1, dim)`` array)."""
        obj = cls.__new__(cls)
        has = knots is not None
        k = np.asarray(knots, float) if has else np.arange(len(segments) + 1, dtype=float)
        if isinstance(segments, np.ndarray) and segments.ndim == 3:
            arr = np.array(segments, dtype=float)
            arr.setflags(write=False)
            obj._init_array(arr, k, has, info)
        else:
            obj._init([np.asarray(s, float) for s in segments], k, has, info)
        return obj

    @classmethod
    def from_control_points(
        cls,
        points: np.ndarray,
        degree: int,
        knots: Sequence[float] | np.ndarray | None = None,
    ) -> PiecewiseBezier:
        """Build a C0 composite curve from one list of points ``p_0 .. p_{dS}``.

        Segment ``i`` uses ``p_{di} .. p_{d(i+1)}`` (consecutive segments share
        their joint point), as in seed 004 §19.6.

        Raises
        ------
        ValueError
            If ``len(points) - 1`` is not a positive multiple of ``degree``.
        """
        degree = check_integer(degree, "degree", minimum=1)
        P = as_points(points, "points", min_points=degree + 1)
        if (P.shape[0] - 1) % degree:
            raise ValueError(
                f"points must have degree * n_segments + 1 rows; {P.shape[0]} points do not "
                f"split into segments of degree {degree}"
            )
        S = (P.shape[0] - 1) // degree
        return cls([P[degree * i : degree * (i + 1) + 1] for i in range(S)], knots)

    # ------------------------------------------------------------------ facts
    @property
    def segments(self) -> tuple[np.ndarray, ...]:
        """Control polygons, one read-only ``(d_i + 1, dim)`` array per segment."""
        if self._segments is None:
            self._segments = tuple(self._array)
        return self._segments

    @property
    def knots(self) -> np.ndarray:
        """Global parameter values ``t_0 < ... < t_S`` of the segment ends."""
        return self._knots

    @property
    def info(self) -> Mapping[str, object]:
        """Read-only facts recorded by the construction that built the curve."""
        return self._info

    @property
    def n_segments(self) -> int:
        return self._knots.size - 1

    @property
    def n_joints(self) -> int:
        """Number of interior joints (``n_segments - 1``)."""
        return self._knots.size - 2

    @property
    def degrees(self) -> tuple[int, ...]:
        return self._degrees

    @property
    def dim(self) -> int:
        return self._array.shape[2] if self._array is not None else self._segments[0].shape[1]

    @property
    def domain(self) -> tuple[float, float]:
        """The global parameter interval ``(t_0, t_S)``."""
        return float(self._knots[0]), float(self._knots[-1])

    @property
    def joint_points(self) -> np.ndarray:
        """End points ``q_i(1)`` of segments ``0 .. S-2``: the joints, shape ``(S-1, dim)``."""
        if self.n_joints == 0:
            return np.zeros((0, self.dim))
        if self._array is not None:
            return self._array[:-1, -1].copy()
        return np.array([s[-1] for s in self._segments[:-1]])

    @property
    def joint_parameters(self) -> np.ndarray:
        """Global parameters ``t_1 .. t_{S-1}`` of the interior joints."""
        return self._knots[1:-1].copy()

    @property
    def control_points(self) -> np.ndarray:
        """All control points, segment after segment, a shared joint point listed once.

        Where consecutive segments do not share their joint point, both are listed.
        """
        segs = self.segments
        rows = [segs[0]]
        for prev, s in pairwise(segs):
            rows.append(s[1:] if np.array_equal(prev[-1], s[0]) else s)
        return np.vstack(rows)

    def __len__(self) -> int:
        return self.n_segments

    def __repr__(self) -> str:
        deg = set(self.degrees)
        d = deg.pop() if len(deg) == 1 else sorted(set(self.degrees))
        kn = f", knots={np.array2string(self._knots, precision=4)}" if self.has_knots else ""
        return f"PiecewiseBezier({self.n_segments} segments, degree {d}, dim {self.dim}{kn})"

    # ------------------------------------------------------------ evaluation
    def _check_segment(self, i: int) -> int:
        i = check_integer(i, "segment", minimum=0)
        if i >= self.n_segments:
            raise ValueError(f"segment must be < n_segments = {self.n_segments}; got {i}")
        return i

    def evaluate_segment(self, i: int, u: float | np.ndarray, n: int = 0) -> np.ndarray:
        """n-th derivative of segment ``i`` with respect to its *local* parameter ``u``.

        Parameters
        ----------
        i : int
            Segment index.
        u : float or array_like of shape (m,)
            Local parameters, normally in ``[0, 1]``.
        n : int
            Derivative order.

        Returns
        -------
        ndarray of shape (dim,) or (m, dim)
        """
        i = self._check_segment(i)
        n = check_integer(n, "n", minimum=0)
        uu, scalar = as_parameter_array(u, "u")
        Q = derivative_points(self.segments[i], n)
        out = bernstein_matrix(Q.shape[0] - 1, uu) @ Q
        return out[0] if scalar else out

    def end_derivatives(self, i: int, end: int, n: int) -> np.ndarray:
        """Local derivatives of orders ``0..n`` of segment ``i`` at ``u = end`` (0 or 1).

        Returns
        -------
        ndarray of shape (n + 1, dim)
            Seed 000 eq. (8.1)-(8.3) and their higher-order analogues.
        """
        i = self._check_segment(i)
        n = check_integer(n, "n", minimum=0)
        if end not in (0, 1):
            raise ValueError(f"end must be 0 (u = 0) or 1 (u = 1); got {end!r}")
        return end_derivative_points(self.segments[i], n, end)

    @property
    def engine(self) -> Evaluator:
        """The evaluation engine of this curve (:mod:`course_lib.curves.evaluation`), made on
        first use: the fast paths behind :meth:`evaluate` and their caches."""
        if self._engine is None:
            segments = self._segments if self._array is None else None
            self._engine = Evaluator(
                self._array, segments, self._degrees, self._knots, self.dim, self.check_domain
            )
        return self._engine

    @property
    def uniform_array(self) -> np.ndarray | None:
        """All control points as one read-only ``(S, d + 1, dim)`` array when every segment has
        the same degree ``d``, else None (the fast paths of the analysis use it)."""
        return self._array

    def segments_by_degree(self, n: int = 0) -> list[tuple[int, np.ndarray, np.ndarray, np.ndarray]]:
        """The segments grouped by degree, with the control points of their ``n``-th hodographs.

        Returns
        -------
        list of (degree, indices, rows, points)
            One entry per degree present: the segment ``indices`` of that degree, ``rows``
            (length ``n_segments``: the row of each segment in ``points``, -1 for segments of
            other degrees) and ``points`` of shape ``(len(indices), degree - n + 1, dim)``
            (seed 000 eq. (8)).  Cached per ``n``; the arrays must not be modified.
        """
        return self.engine.segments_by_degree(n)

    def locate(self, t: float | np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Segment index and local parameter of global parameters ``t``.

        A joint parameter ``t_i`` belongs to the segment that *starts* there
        (except ``t_S``, which belongs to the last segment).

        Raises
        ------
        ValueError
            If some ``t`` lies outside the domain ``[t_0, t_S]``.
        """
        tt, _ = as_parameter_array(t, "t")
        return self._locate(tt)

    def check_domain(self, tt: np.ndarray) -> bool:
        """Raise if some ``t`` is outside the domain; True if some lie just outside (within
        the rounding tolerance) and must be clipped onto it."""
        if not tt.size:
            return False
        t0, t1 = self.domain
        if t0 <= float(tt.min()) and float(tt.max()) <= t1:
            return False
        k = self._knots
        lo, hi = tt.min(), tt.max()
        span = k[-1] - k[0]
        tol = 1e-12 * max(1.0, abs(k[0]), abs(k[-1]), span)
        if lo < k[0] - tol or hi > k[-1] + tol:
            bad = tt[(tt < k[0] - tol) | (tt > k[-1] + tol)][0]
            raise ValueError(f"t must lie in the domain [{k[0]}, {k[-1]}]; got {bad}")
        return True

    def _parameters(self, t: object) -> tuple[np.ndarray, bool, bool]:
        """``t`` checked as :func:`~course_lib.validation.as_parameter_array` and
        :meth:`check_domain` do, with the same errors, in two passes over the array when
        all is well: ``t_0 <= min(t)`` and ``max(t) <= t_S`` also prove every ``t`` finite
        (a NaN makes the minimum NaN, an infinity lies outside the domain).

        Returns
        -------
        tt : 1-d float array
        scalar : bool
            ``t`` was a scalar.
        clip : bool
            Some ``t`` lie just outside the domain (within the rounding tolerance).
        """
        arr = as_real_array(t, "t", "a real number or an array of them")
        if arr.ndim > 1:
            raise ValueError(f"t must be a scalar or a 1-d array; got shape {arr.shape}")
        scalar = arr.ndim == 0
        tt = arr.reshape(1) if scalar else arr
        if tt.size and self._knots[0] <= tt.min() and tt.max() <= self._knots[-1]:
            return tt, scalar, False
        if not np.isfinite(tt).all():
            raise ValueError("t must contain only finite values")
        return tt, scalar, self.check_domain(tt)

    def _locate(self, tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return self.engine.locate(tt)

    def evaluate(self, t: float | np.ndarray, n: int = 0) -> np.ndarray:
        """Points (``n = 0``) or n-th derivatives in the *global* parameter ``t``.

        Vectorized, no per-point Python loop: each segment's n-th derivative is
        evaluated from a cached two-sided Taylor form (Horner's rule on
        ``|w| <= 1/2``), or, for hodographs of degree above ``TAYLOR_MAX_DEGREE``, from
        the Bernstein form grouped by degree -- the fast paths of
        :mod:`course_lib.curves.evaluation`, behind this façade.

        Parameters
        ----------
        t : float or array_like of shape (m,)
            Global parameters in ``[t_0, t_S]``.
        n : int
            Derivative order with respect to ``t``: the local derivative times
            ``(t_{i+1} - t_i)^{-n}``.

        Returns
        -------
        ndarray of shape (dim,) or (m, dim)
        """
        n = check_integer(n, "n", minimum=0)
        tt, scalar, clip = self._parameters(t)
        out = self.engine.evaluate(tt, n, clip)
        return out[0] if scalar else out

    def sample(self, per_segment: int = 64) -> tuple[np.ndarray, np.ndarray]:
        """Global parameters and points for drawing: ``per_segment`` samples per segment.

        Joints are included once each; the result runs from ``t_0`` to ``t_S``.

        Returns
        -------
        t : ndarray of shape (m,)
        points : ndarray of shape (m, dim)
        """
        per_segment = check_integer(per_segment, "per_segment", minimum=2)
        t = self.parameter_grid(per_segment)
        return t, self.evaluate(t)

    def parameter_grid(self, per_segment: int = 64) -> np.ndarray:
        """Global parameters, ``per_segment`` equally spaced per segment, joints once."""
        per_segment = check_integer(per_segment, "per_segment", minimum=2)
        k = self._knots
        s = np.linspace(0.0, 1.0, per_segment)[:-1]
        t = (k[:-1, None] + np.diff(k)[:, None] * s[None, :]).ravel()
        return np.append(t, k[-1])

    # -------------------------------------------------------------- new curves
    def with_knots(self, knots: Sequence[float] | np.ndarray) -> PiecewiseBezier:
        """The same segments with a new knot sequence (a new global parametrization)."""
        src = self._array if self._array is not None else self._segments
        return PiecewiseBezier(src, knots, info=self._info)

    def transformed(self, matrix: np.ndarray, offset: np.ndarray | None = None) -> PiecewiseBezier:
        """The affine image ``x -> matrix @ x + offset`` (control points mapped the same way).

        Bézier curves are affinely invariant, so this is the exact image curve.
        """
        A = as_real_array(matrix, "matrix", f"a real ({self.dim}, {self.dim}) array")
        if A.shape != (self.dim, self.dim) or not np.all(np.isfinite(A)):
            raise ValueError(
                f"matrix must be a finite ({self.dim}, {self.dim}) array; got shape {A.shape}"
            )
        b = (
            np.zeros(self.dim)
            if offset is None
            else as_real_array(offset, "offset", "a real vector")
        )
        if b.shape != (self.dim,) or not np.all(np.isfinite(b)):
            raise ValueError(
                f"offset must be a finite vector of length {self.dim}; got shape {b.shape}"
            )
        if self._array is not None:
            return PiecewiseBezier.from_trusted_segments(
                self._array @ A.T + b, self._knots if self.has_knots else None, self._info
            )
        segs = [s @ A.T + b for s in self._segments]
        return PiecewiseBezier.from_trusted_segments(segs, self._knots if self.has_knots else None, self._info)

    def segment_curve(self, i: int) -> PiecewiseBezier:
        """Segment ``i`` alone, as a one-segment curve.

        Examples
        --------
        With knots ``0, 1, 3`` the second segment spans ``[1, 3]``; on its own it runs on ``[0, 1]``:

        >>> c = PiecewiseBezier([[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]]], knots=[0, 1, 3])
        >>> c.domain, c.evaluate(2.0)
        ((0.0, 3.0), array([ 3. , -0.5]))
        >>> c.segment_curve(1).evaluate(0.5)
        array([ 3. , -0.5])
        """
        i = self._check_segment(i)
        return PiecewiseBezier.from_trusted_segments([self.segments[i]])
