"""G^n Beta-splines of degree n + 1 with global shape parameters (seed 001 Example 2.1).

Segment ``j`` of the spline is ``q_j(u) = sum_{k=0}^{d} V_{j+k} b_k(u)``, ``d = n + 1``
(seed 001 eq. (2.8) writes ``k = -2..2`` for the quartic; here the offsets run
``0..d``, so ``b_k`` here is the seed's ``b_{k-2}``).  The control point ``V_{j+k}``
has weight ``b_k`` in segment ``j`` and ``b_{k-1}`` in segment ``j + 1``.  The joint
between them is G^n with shape parameters ``β_1 .. β_n`` (seed 000 eq. (6)) for every
control polygon iff, for every ``k = 0..d+1`` (with ``b_{-1} = b_{d+1} = 0``),

.. math:: b_{k-1}^{(i)}(0) = CR_i\\big(b_k^{(1)}(1), \\dots, b_k^{(i)}(1); β\\big),
          \\quad i = 0..n

(``CR_0`` is the identity: positional continuity).  These ``(d+2)(n+1)`` linear
equations in the ``(d+1)^2`` Bernstein coefficients of ``b_0..b_d`` leave one degree
of freedom, fixed by the normalization ``sum_k b_k(0) = 1``; the result is a
partition of unity (tested).  For ``n <= 4`` the system is solved by a float SVD
(exact to ~1e-15); above, in a chained form with ``n + 2`` unknowns in multiple
precision (``_solve_multiprecision``), so that the basis stays unique and exact (the
uniform B-spline to ~1e-16 up to ``n = MAX_BASIS_ORDER = 16``).

Seed 001 eq. (2.10) reads ``b_{k+1}^{(i)}(1) = CR_i(b_k^{(1)}(0), ..., b_k^{(i)}(0), β)``:
it applies the chain rule to the derivatives at ``u = 0`` and equates them to those at
``u = 1``, i.e. it swaps the roles of the two segments.  That system also produces a
G^n spline, but its joints satisfy seed 000 eq. (7) with the shape parameters of the
*inverse* change of variables (``1/β1``, ``-β2/β1³``, ...), not with the given ones
(tests: ``tests/unit/test_beta_splines_degree_n.py::test_seed_eq_2_10_gives_inverse_betas``).
The seed's eq. (2.9) for the C^3 B-spline is correct as printed.

With ``β1 = 1, β2 = ... = βn = 0`` the basis is the uniform B-spline of degree
``n + 1`` (test against scipy).  For ``n = 1, 2`` it coincides with the geometric
constructions of :mod:`course_lib.constructions.beta_splines` (independent cross-check).

Lesson: ``notebooks/09_higher_order.ipynb``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from math import comb, factorial

import numpy as np

from course_lib.curves.bezier import bernstein_matrix, derivative_points, end_derivative_matrix
from course_lib.curves.curve import PiecewiseBezier
from course_lib.geometry.beta_constraints import beta_coefficients
from course_lib.validation import (
    as_parameter_array,
    as_points,
    as_real_array,
    check_integer,
    scaled_norm,
)

__all__ = ["BetaSplineBasis", "beta_spline", "gn_beta_spline_basis", "quartic_beta_spline"]


def _check_betas(betas: object, n: int) -> tuple[float, ...]:
    arr, scalar = as_parameter_array(betas, "betas")
    if scalar or arr.size != n:
        raise ValueError(
            f"betas must be a sequence (beta1, ..., beta{n}) of {n} global shape parameters "
            f"for G^{n}; got {arr.size} value(s)"
        )
    if arr[0] <= 0:
        raise ValueError(f"beta1 must be > 0; got {arr[0]}")
    return tuple(float(x) for x in arr)


#: Largest order n of :func:`gn_beta_spline_basis` / :func:`beta_spline`.  Above
#: ``_FLOAT_MAX_ORDER`` the basis is solved in multiple precision (mpmath, a dependency of
#: sympy) at O(n^4) cost: n = 12 ~0.3 s, n = 16 ~0.5 s; above the cap a ValueError is raised
#: at once instead of an hours-long computation (n = 60 took 451 s in an SVD before).
MAX_BASIS_ORDER = 16
_FLOAT_MAX_ORDER = 4  # float SVD of the full system: exact to ~1e-15 for n <= 4


def _solve_multiprecision(n: int, betas: tuple) -> np.ndarray:
    """Bernstein coefficients of ``b_0..b_d`` from a chained system in multiple precision.

    The joint conditions chain the blending functions: ``b_d`` vanishes to order n at 0
    (only its top Taylor coefficient ``x_d`` is free), and the Taylor coefficients ``0..n``
    of ``b_{k-1}`` at 0 are the chain rule ``CR_i`` applied to those of ``b_k`` at 1; only
    its top coefficient ``x_{k-1}`` is new.  So every coefficient is a linear form in the
    ``n + 2`` unknowns ``x_d .. x_0``, and ``b_{-1} = 0`` (``b_0`` vanishes to order n at 1)
    gives ``n + 1`` homogeneous equations: the basis is unique iff their rank is ``n + 1``.
    The chain amplifies rounding by ~10^n, so it runs with ``30 + 4 n`` digits (the floats
    β are exact there); the rank is decided at half that precision.  Normalization:
    ``sum_k b_k(0) = 1``.
    """
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 30 + 4 * n
    d = n + 1
    N = n + 2
    pairs = betas if isinstance(betas[0], tuple) else (betas,) * (d + 2)

    def chain_matrix(bs):
        b = [ctx.mpf(x) for x in bs]
        B = [[ctx.mpf(0)] * (n + 1) for _ in range(n + 1)]
        B[0][0] = ctx.mpf(1)
        for i in range(1, n + 1):
            for k in range(1, i + 1):
                B[i][k] = ctx.fsum(
                    comb(i - 1, j - 1) * b[j - 1] * B[i - j][k - 1] for j in range(1, i - k + 2)
                )
        # the chain rule on Taylor coefficients: T[i][k] = B_{i,k} k! / i!
        return ctx.matrix(
            [
                [B[i][k] * factorial(k) / factorial(i) for k in range(1, n + 1)]
                for i in range(1, n + 1)
            ]
        )

    Ts = {}
    shift = ctx.matrix([[comb(j, i) for j in range(d + 1)] for i in range(n + 1)])  # u=0 -> u=1
    at0 = ctx.zeros(d + 1, N)
    at0[d, 0] = 1
    forms = [at0]  # Taylor coefficients (rows) of b_d, b_{d-1}, ..., b_0 as linear forms
    for c in range(1, d + 1):
        at1 = shift * at0
        pair = pairs[d - c + 1]  # b_{d-c} on the right of b_{d-c+1}: pair k = d - c + 1
        if pair not in Ts:
            Ts[pair] = chain_matrix(pair)
        chained = Ts[pair] * at1[1 : n + 1, :]
        new = ctx.zeros(d + 1, N)
        for u in range(N):
            new[0, u] = at1[0, u]
            for i in range(1, n + 1):
                new[i, u] = chained[i - 1, u]
        new[d, c] = 1
        at0 = new
        forms.append(at0)
    R = shift * at0
    square = ctx.zeros(N, N)
    for i in range(n + 1):
        norm = ctx.sqrt(ctx.fsum(R[i, u] ** 2 for u in range(N)))
        for u in range(N):
            square[i, u] = R[i, u] / norm
    _, S, V = ctx.svd_r(square)
    if S[n] <= ctx.mpf(10) ** (-(ctx.dps // 2)) * S[0]:
        raise ValueError(
            f"the shape parameters betas = {betas} admit more than one G^{n} basis of "
            f"degree {d} (singular system); choose other values"
        )
    x = [V[N - 1, u] for u in range(N)]
    taylor = [[ctx.fsum(f[i, u] * x[u] for u in range(N)) for i in range(d + 1)] for f in forms]
    total = ctx.fsum(t[0] for t in taylor)
    if abs(total) <= ctx.mpf(10) ** (-(ctx.dps // 2)) * max(abs(v) for t in taylor for v in t):
        raise ValueError(
            f"the shape parameters betas = {betas} make the normalization sum_k b_k(0) = 1 "
            "impossible (the blending functions would sum to zero)"
        )
    C = np.empty((N, d + 1))
    for idx, t in enumerate(taylor):  # forms[idx] is b_{d - idx}
        for j in range(d + 1):  # monomial -> Bernstein: c_j = sum_{i<=j} C(j,i)/C(d,i) a_i
            c = ctx.fsum(ctx.mpf(comb(j, i)) / comb(d, i) * t[i] for i in range(j + 1))
            C[d - idx, j] = float(c / total)
    return C


@lru_cache(maxsize=512)
def _solve(n: int, betas: tuple, seed_eq_2_10: bool = False) -> np.ndarray:
    """Bernstein coefficients of ``b_0..b_d`` (rows), normalized by ``sum_k b_k(0) = 1``.

    ``betas``: one tuple ``(β_1..β_n)`` for every joint (global), or a tuple of ``d + 2``
    such tuples, one per pair ``k`` (``b_{k-1}`` on the right of ``b_k``: the joints of one
    control point's support, for local shape parameters)."""
    if not seed_eq_2_10 and n > _FLOAT_MAX_ORDER:
        C = _solve_multiprecision(n, betas)
        C.setflags(write=False)
        return C
    d = n + 1
    pairs = betas if isinstance(betas[0], tuple) else (betas,) * (d + 2)
    Ms = {}
    for pb in set(pairs):
        M = np.zeros((n + 1, n + 1))
        M[0, 0] = 1.0
        M[1:, 1:] = beta_coefficients(np.array(pb))
        Ms[pb] = M
    E0, E1 = end_derivative_matrix(d, n, 0), end_derivative_matrix(d, n, 1)
    N = d + 1  # number of basis functions
    rows = []
    for k in range(d + 2):  # pair (b_{k-1} on the right segment, b_k on the left)
        M = Ms[pairs[k]]
        A = np.zeros((n + 1, N * N))
        if k - 1 >= 0:
            if seed_eq_2_10:  # b_k^{(i)}(1) = CR_i(b_{k-1}(0)): seed 001 eq. (2.10)
                A[:, (k - 1) * N : k * N] -= M @ E0
            else:
                A[:, (k - 1) * N : k * N] += E0
        if k <= d:
            if seed_eq_2_10:
                A[:, k * N : (k + 1) * N] += E1
            else:
                A[:, k * N : (k + 1) * N] -= M @ E1
        rows.append(A)
    A = np.vstack(rows)
    # Equilibrate the rows: the constraint of order i carries powers up to β1^i, so without
    # this the singular values spread over many decades for large or small β1.
    norms = np.linalg.norm(A, axis=1)
    A = A / np.where(norms > 0, norms, 1.0)[:, None]
    # A has one more column than rows ((n+2)^2 unknowns, (n+3)(n+1) equations), so it
    # always has a null vector; the basis is unique when the null space is exactly one
    # vector, i.e. when all (n+3)(n+1) singular values are nonzero.
    _, s, Vt = np.linalg.svd(A)
    tol = 1e-10 * s[0]
    if s[-1] <= tol:
        raise ValueError(
            f"the shape parameters betas = {betas} admit more than one G^{n} basis of "
            f"degree {d} (singular system); choose other values"
        )
    x = Vt[-1].reshape(N, N)
    total = x[:, 0].sum()
    if abs(total) <= 1e-10 * np.abs(x).max():
        raise ValueError(
            f"the shape parameters betas = {betas} make the normalization sum_k b_k(0) = 1 "
            "impossible (the blending functions would sum to zero)"
        )
    C = x / total
    C.setflags(write=False)
    return C


@dataclass(frozen=True)
class BetaSplineBasis:
    """The ``d + 1 = n + 2`` blending functions of a G^n Beta-spline of degree ``n + 1``.

    Attributes
    ----------
    n : int
        Order of geometric continuity.
    betas : tuple of float
        Global shape parameters ``β_1 .. β_n``.
    coefficients : ndarray of shape (n + 2, n + 2)
        Row ``k`` holds the Bernstein coefficients of ``b_k`` (offset ``k``; the seed's
        ``b_{k - (n+1)//2}`` for even degree, e.g. ``b_{-2}..b_2`` for the quartic).
    """

    n: int
    betas: tuple[float, ...]
    coefficients: np.ndarray

    @property
    def degree(self) -> int:
        return self.n + 1

    def evaluate(self, u: float | np.ndarray, order: int = 0) -> np.ndarray:
        """``b_k^{(order)}(u)`` for ``k = 0..d``: shape ``(d + 1,)`` or ``(m, d + 1)``."""
        order = check_integer(order, "order", minimum=0)
        uu, scalar = as_parameter_array(u, "u")
        Q = np.stack([derivative_points(c[:, None], order)[:, 0] for c in self.coefficients])
        out = bernstein_matrix(Q.shape[1] - 1, uu) @ Q.T
        return out[0] if scalar else out

    def bump(self, t: float | np.ndarray) -> np.ndarray:
        """The single blending function ``N(t)`` with support ``[0, d + 1]``.

        On ``[s, s + 1]`` it equals ``b_{d-s}(t - s)`` (the weight of one control
        vertex in the successive segments); zero outside.
        """
        tt, scalar = as_parameter_array(t, "t")
        d = self.degree
        s = np.clip(np.floor(tt).astype(np.intp), 0, d)
        B = bernstein_matrix(d, np.clip(tt - s, 0.0, 1.0))
        out = np.einsum("mr,mr->m", B, self.coefficients[d - s])
        out[(tt < 0) | (tt > d + 1)] = 0.0
        return out[0] if scalar else out


def gn_beta_spline_basis(n: int, betas: object) -> BetaSplineBasis:
    """Blending functions of the G^n Beta-spline of degree ``n + 1`` (seed 001 Ex. 2.1).

    Parameters
    ----------
    n : int
        ``n >= 1`` (``n = 3``: the quartic Beta-spline of seed 001).
    betas : sequence of n floats
        Global ``β_1 > 0, β_2, ..., β_n``.

    Raises
    ------
    ValueError
        Wrong number of betas, β1 <= 0, or betas for which the basis is not unique
        or cannot be normalized.
    """
    n = _check_order(n)
    b = _check_betas(betas, n)
    return BetaSplineBasis(n, b, _solve(n, b))


def _check_order(n: object) -> int:
    n = check_integer(n, "n", minimum=1)
    if n > MAX_BASIS_ORDER:
        raise ValueError(
            f"n must be <= {MAX_BASIS_ORDER} (MAX_BASIS_ORDER): the G^n basis is solved in "
            f"multiple precision at O(n^4) cost; got n = {n}"
        )
    return n


def beta_spline(V: np.ndarray, betas: object, n: int = 3) -> PiecewiseBezier:
    """G^n Beta-spline curve of degree ``n + 1``, global or per-joint shape parameters.

    Parameters
    ----------
    V : array_like of shape (N, dim), ``N >= n + 2``
        Control polygon; segment ``j`` uses ``V_j .. V_{j+n+1}`` (``N - n - 1`` segments).
    betas : sequence of n floats, or array_like of shape (N - n - 2, n)
        Global ``(β_1, ..., β_n)``, or one row ``(β_1, ..., β_n)`` per interior joint
        (joint ``j`` between segments ``j`` and ``j + 1``).  With per-joint values each
        control point's blending function is solved with the β's of the joints of its
        support (joints beyond the curve's ends use the nearest joint's β's), and the
        blending functions are scaled to a partition of unity; equal rows give exactly the
        global construction.
    n : int
        ``1 <= n <= MAX_BASIS_ORDER``.

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1 .. beta{n}`` (arrays, one value per interior joint), ``betas``
        (the global tuple, or the per-joint array).
    """
    n = _check_order(n)
    d = n + 1
    P = as_points(V, "V", min_points=d + 1)
    S = P.shape[0] - d
    arr = as_real_array(betas, "betas", "a sequence (beta1, ..., betan) or one row per joint")
    if arr.ndim == 2:
        jb = _check_joint_betas(arr, n, S - 1)
        if S > 1 and not np.all(jb == jb[0]):
            segs = _local_segments(P, jb, n)
            info = {f"beta{i + 1}": jb[:, i].copy() for i in range(n)}
            info["betas"] = jb
            _check_spline_tangents(segs, P, d)
            return PiecewiseBezier.from_trusted_segments(list(segs), info=info)
        betas = tuple(jb[0]) if S > 1 else (1.0,) + (0.0,) * (n - 1)
    basis = gn_beta_spline_basis(n, betas)
    win = np.lib.stride_tricks.sliding_window_view(P, d + 1, axis=0)  # (S, dim, d+1)
    segs = np.einsum("kr,sdk->srd", basis.coefficients, win)
    info: dict[str, object] = {f"beta{i + 1}": np.full(S - 1, b) for i, b in enumerate(basis.betas)}
    info["betas"] = basis.betas
    _check_spline_tangents(segs, P, d)
    return PiecewiseBezier.from_trusted_segments(list(segs), info=info)


def _check_joint_betas(arr: np.ndarray, n: int, joints: int) -> np.ndarray:
    if arr.shape != (joints, n):
        raise ValueError(
            f"betas per joint must have shape ({joints}, {n}): one row (beta1..beta{n}) for "
            f"each of the {joints} interior joints; got {arr.shape}"
        )
    if not np.all(np.isfinite(arr)):
        raise ValueError("betas must be finite")
    bad = arr[:, 0] <= 0 if joints else np.zeros(0, bool)
    if np.any(bad):
        j = int(np.argmax(bad))
        raise ValueError(f"beta1 must be > 0 at every joint; at joint {j} it is {arr[j, 0]}")
    return arr


def _local_segments(P: np.ndarray, jb: np.ndarray, n: int) -> np.ndarray:
    """Segments of the G^n Beta-spline with per-joint β's (rows of ``jb``)."""
    d = n + 1
    Mpts = P.shape[0]
    S = Mpts - d
    rows = [tuple(float(x) for x in r) for r in jb]
    C = []
    for i in range(Mpts):  # pair k of V_i: joint between segments i-k and i-k+1
        pairs = tuple(rows[min(max(i - k + 1, 1), S - 1) - 1] for k in range(d + 2))
        C.append(_solve(n, pairs))
    # weights: segment j, control point j + r, Bernstein coefficient l -> C[j+r][r, l];
    # scale each blending function (c_i) so that they sum to one on every segment
    A = np.zeros((S * (d + 1), Mpts))
    for j in range(S):
        for r in range(d + 1):
            A[j * (d + 1) : (j + 1) * (d + 1), j + r] = C[j + r][r]
    c, *_ = np.linalg.lstsq(A, np.ones(S * (d + 1)), rcond=None)
    if np.max(np.abs(A @ c - 1.0)) > 1e-9:
        raise ValueError(
            "these per-joint shape parameters give blending functions that cannot be scaled "
            "to a partition of unity (a singular configuration); choose other values"
        )
    W = (A * c[None, :]).reshape(S, d + 1, Mpts)  # W[j, l, i]
    return np.einsum("jli,id->jld", W, P)


def _check_spline_tangents(segs: np.ndarray, P: np.ndarray, d: int) -> None:
    scale = float(np.max(np.abs(P)))
    for j in range(segs.shape[0] - 1):
        if scaled_norm(segs[j, -1] - segs[j, -2]) <= 1e-12 * scale:
            raise ValueError(
                f"the tangent vanishes at joint {j} (control points V_{j}..V_{j + d + 1}, e.g. "
                "coincident consecutive ones): the curve would not be regular there"
            )


def quartic_beta_spline(
    V: np.ndarray,
    beta1: float | np.ndarray = 1.0,
    beta2: float | np.ndarray = 0.0,
    beta3: float | np.ndarray = 0.0,
) -> PiecewiseBezier:
    """The quartic G3 Beta-spline of seed 001 Example 2.1.

    ``beta1, beta2, beta3``: scalars (global), or one value per interior joint (arrays of
    ``N - 5`` values; scalars are broadcast), see :func:`beta_spline`.

    Examples
    --------
    >>> import numpy as np
    >>> V = np.array([[0, 0], [1, 2], [3, 2], [4, 0], [6, 1], [7, 3]])
    >>> curve = quartic_beta_spline(V, beta1=1.0, beta2=0.0, beta3=0.0)
    >>> curve.n_segments, curve.degrees
    (2, (4, 4))
    """
    parts = [
        np.asarray(as_real_array(b, f"beta{i + 1}")) for i, b in enumerate((beta1, beta2, beta3))
    ]
    if all(p.ndim == 0 for p in parts):
        return beta_spline(V, tuple(float(p) for p in parts), 3)
    P = as_points(V, "V", min_points=5)
    joints = P.shape[0] - 5
    for i, p in enumerate(parts):
        if p.ndim > 1 or (p.ndim == 1 and p.size != joints):
            raise ValueError(
                f"beta{i + 1} must be a scalar or one value per interior joint ({joints}); "
                f"got shape {p.shape}"
            )
    jb = np.stack([np.broadcast_to(p, (joints,)) for p in parts], axis=1)
    return beta_spline(P, jb, 3)
