"""Quadratic G1 and cubic G2 Beta-splines built in Bézier form (seed 000 §10).

Both constructions follow Farin and Boehm: every segment is a Bézier curve whose
control points are placed on the legs of the Beta-spline control polygon
``V_0 .. V_m`` so that consecutive segments satisfy the Beta-constraints of seed
000 eq. (7.1) (and (7.2)) with the shape parameters *of that joint*.

Quadratic G1 (seed 000 §10.1, eq. (15)-(19))
    One β1 per *leg* ``V_i V_{i+1}``, ``i = 0..m-1``.  The junction vertex
    ``J_i = (β1_i V_i + V_{i+1}) / (1 + β1_i)`` divides leg ``i`` in the ratio
    ``1 : β1_i``; segment ``i - 1`` (``i = 1..m-1``) is ``J_{i-1}, V_i, J_i``.
    ``m - 1`` segments; the interior joints are ``J_1 .. J_{m-2}`` (joint ``k`` is
    on leg ``k + 1``); β1 on the end legs 0 and ``m - 1`` places the curve's end points.

Cubic G2 (seed 000 §10.2, steps 1a, 1b, 2)
    One pair ``(β1_j, β2_j)`` per *vertex* ``V_j``, ``j = 0..m``, with
    ``γ_j = 2 (1 + β1_j) / (β2_j + 2 β1_j (1 + β1_j))`` (eq. (12.1) with ``d = 3``).
    Leg ``i`` carries the interior Bézier vertices ``W_{i,1}, W_{i,2}`` splitting it
    in the ratio ``γ_i : 1 : β1_{i+1}² γ_{i+1}``, and the junction vertex
    ``J_j = (β1_j W_{j-1,2} + W_{j,1}) / (1 + β1_j)`` sits near ``V_j``.  Segment
    ``i - 1`` (``i = 1..m-2``) is ``J_i, W_{i,1}, W_{i,2}, J_{i+1}``: ``m - 2``
    segments; the interior joints are ``J_2 .. J_{m-2}`` (joint ``k`` at vertex
    ``V_{k+2}``).  The parameters at ``V_0, V_1, V_{m-1}, V_m`` only shape the ends.

    Seed 000 §10.2 step (1b) reads ``γ_i : 1 : β1_i² γ_{i+1}``; the correct ratio is
    ``γ_i : 1 : β1_{i+1}² γ_{i+1}``.  The vertex ``V_{i+1}`` plays the role of
    Farin-Boehm's point ``T`` (eq. (12.4)) for the joint at ``V_{i+1}``, where
    ``|W_{i,2} T| = β1² γ |W_{i,1} W_{i,2}|`` with *that* joint's β1 and γ.  With one
    global β1 the two readings coincide; with β1 varying from joint to joint the
    seed's indices break G2 (test:
    ``tests/unit/test_beta_splines.py::test_seed_leg_ratio_index_breaks_g2``).

With β1 = 1 (and β2 = 0) both reduce to the uniform quadratic / cubic B-spline
(test against scipy.interpolate.BSpline).

Lesson: ``notebooks/08_beta_splines.ipynb``.

Why this module is long: the quadratic and the cubic constructions share their per-site
shape parameters, leg weights and junction vertices, and their basis functions are read off
the constructions themselves.
"""

from __future__ import annotations

import numpy as np

from course_lib.curves.bezier import bernstein_matrix
from course_lib.curves.curve import PiecewiseBezier
from course_lib.homework import own_work
from course_lib.validation import as_parameter_array, as_points, check_shape_parameters, scaled_norm

__all__ = [
    "cubic_beta_spline",
    "cubic_beta_spline_basis",
    "design_beta_spline",
    "quadratic_beta_spline",
    "quadratic_beta_spline_basis",
]


# ------------------------------------------------------------------ parameters
def _per_site(
    value: object, name: str, n_sites: int, n_joints: int, site: str, default: float, positive: bool
) -> np.ndarray:
    """Shape parameter as a scalar, one per site (leg or vertex), or one per interior joint."""
    arr = None
    if not isinstance(value, (str, bytes)) and value is not None:
        try:
            arr = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            arr = None
    if arr is not None and arr.ndim == 1 and arr.size == n_joints and n_joints != n_sites:
        b = check_shape_parameters(value, name, n_joints, positive=positive)
        pad = (n_sites - n_joints) // 2
        return np.concatenate([np.full(pad, default), b, np.full(pad, default)])
    if arr is not None and arr.ndim == 1 and arr.size not in (n_sites, n_joints):
        raise ValueError(
            f"{name} must be a scalar, one value per interior joint ({n_joints}) or one per "
            f"{site} ({n_sites}); got {arr.size}"
        )
    out = check_shape_parameters(value, name, n_sites, positive=False)
    if positive and np.any(out <= 0):
        j = int(np.argmax(out <= 0))
        where = f"leg {j}" if site.startswith("leg") else f"vertex V_{j}"
        raise ValueError(f"{name} must be > 0 at every {site}; at {where} it is {out[j]}")
    return out


def _frexp(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    m, e = np.frexp(x)
    return m, e.astype(np.int64)


def _vertex_terms(b1: np.ndarray, b2: np.ndarray):
    """``γ_j = N_j / D_j`` with ``N = 2 (1 + β1)``, ``D = β2 + 2 β1 (1 + β1)`` (seed 000
    eq. (12.1), d = 3), each as (mantissa, exponent) so that no β1 up to the float limit
    overflows.  Scaling by powers of two is exact: for moderate β's the mantissas carry the
    same rounding as the direct formulas."""
    _, k = _frexp(np.maximum(b1, 1.0))  # β1 < 2**k
    s = np.ldexp(b1, -k)
    one = np.ldexp(1.0, -k)
    nm, ne = _frexp(2.0 * (one + s))  # N = nm 2**(ne + k)
    dm, de = _frexp(np.ldexp(b2, -2 * k) + 2.0 * s * (one + s))  # D = dm 2**(de + 2k)
    bm, be = _frexp(b1)
    return (nm, ne + k), (dm, de + 2 * k), (bm * bm, 2 * be)


def _mul(*factors: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    m = np.ones_like(factors[0][0])
    e = np.zeros_like(factors[0][1])
    for fm, fe in factors:
        m = m * fm
        e = e + fe
    return m, e


def _gammas(b1: np.ndarray, b2: np.ndarray) -> np.ndarray:
    """γ_j of seed 000 eq. (12.1) with d = 3; ``inf`` where it is undefined
    (``β2 = -2 β1 (1 + β1)``: Farin-Boehm's point T is at infinity there)."""
    (nm, ne), (dm, de), _ = _vertex_terms(b1, b2)
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        g = np.ldexp(nm / dm, ne - de)
    return np.where(dm == 0.0, np.inf, g)


def _gamma_inverse(b1: np.ndarray, b2: np.ndarray) -> np.ndarray:
    """``1/γ_j`` (pole-free; 0 where T is at infinity)."""
    (nm, ne), (dm, de), _ = _vertex_terms(b1, b2)
    return np.ldexp(dm / nm, de - ne)


def _leg_weights(b1: np.ndarray, b2: np.ndarray, seed_indexing: bool = False):
    """Barycentric weights of ``W_{i,1}``, ``W_{i,2}`` on every leg, without the pole of γ.

    The leg ratio ``γ_i : 1 : β1_{i+1}² γ_{i+1}`` (seed 000 §10.2 step (1b), corrected
    index) times ``D_i D_{i+1}`` is ``N_i D_{i+1} : D_i D_{i+1} : β1_{i+1}² N_{i+1} D_i``,
    finite for every β; where both ends of a leg carry the same (β1, β2) the common
    factor ``D`` cancels, ``N : D : β1² N`` (this keeps the limit at ``D = 0``, where
    Barsky's closed form is finite).  Returns ``(A, B, C)`` normalised by their sum.
    """
    Nv, Dv, B2v = _vertex_terms(b1, b2)
    i, j = slice(None, -1), slice(1, None)

    def at(t, s):
        return t[0][s], t[1][s]

    bsel = at(B2v, i) if seed_indexing else at(B2v, j)
    general = (
        _mul(at(Nv, i), at(Dv, j)),
        _mul(at(Dv, i), at(Dv, j)),
        _mul(bsel, at(Nv, j), at(Dv, i)),
    )
    cancelled = (at(Nv, i), at(Dv, i), _mul(bsel, at(Nv, j)))
    same = (b1[:-1] == b1[1:]) & (b2[:-1] == b2[1:])
    both = (Dv[0][:-1] == 0.0) & (Dv[0][1:] == 0.0) & ~same
    if np.any(both):
        k = int(np.argmax(both))
        raise ValueError(
            f"beta2 makes gamma undefined at both V_{k} and V_{k + 1} (beta2 = -2 beta1 "
            f"(1 + beta1)) with different beta1 there: the interior Bézier vertices of leg {k} "
            "have no limit (they depend on how each vertex approaches it)"
        )
    terms = [
        (np.where(same, c[0], g[0]), np.where(same, c[1], g[1]))
        for g, c in zip(general, cancelled, strict=True)
    ]
    lowest = np.iinfo(np.int64).min // 4
    E = np.max([np.where(m == 0.0, lowest, e) for m, e in terms], axis=0)
    A, B, C = (np.ldexp(m, np.maximum(e - E, -2000)) for m, e in terms)
    S = A + B + C
    bad = np.abs(S) <= 1e-12 * (np.abs(A) + np.abs(B) + np.abs(C))
    if np.any(bad):
        k = int(np.argmax(bad))
        raise ValueError(
            f"beta2 at V_{k} or V_{k + 1} makes the leg ratio gamma_{k} : 1 : "
            f"beta1_{k + 1}^2 gamma_{k + 1} sum to zero on leg {k} (Barsky's "
            "delta = 0: the spline has a pole there); the interior Bézier vertices are undefined"
        )
    return A / S, B / S, C / S


# ------------------------------------------------------------- constructions
def _quadratic_polygons(V: np.ndarray, b1: np.ndarray) -> np.ndarray:
    """Segments (m-1, 3, D) of the quadratic G1 Beta-spline; b1 one per leg (m values)."""
    own_work.require("course_lib.constructions.beta_splines.quadratic_cubic._quadratic_polygons")
    w = 1.0 / (1.0 + b1[:, None])
    J = (b1[:, None] * w) * V[:-1] + w * V[1:]  # J_i on leg i (no overflow for huge β1)
    S = V.shape[0] - 2
    out = np.empty((S, 3, V.shape[1]))
    out[:, 0] = J[:-1]
    out[:, 1] = V[1:-1]
    out[:, 2] = J[1:]
    return out


def _cubic_points(V: np.ndarray, b1: np.ndarray, b2: np.ndarray, seed_indexing: bool = False):
    """Interior vertices W1, W2 (m, D) per leg and junctions J (m-1, D) at V_1..V_{m-1}.

    ``seed_indexing=True`` uses the transcribed ratio γ_i : 1 : β1_i² γ_{i+1} (wrong).
    """
    own_work.require("course_lib.constructions.beta_splines.quadratic_cubic._cubic_points")
    a, b, c = _leg_weights(b1, b2, seed_indexing)
    W1 = (b + c)[:, None] * V[:-1] + a[:, None] * V[1:]
    W2 = c[:, None] * V[:-1] + (a + b)[:, None] * V[1:]
    J = _junctions(W1, W2, b1[1:-1])
    g = _gammas(b1, b2)
    return W1, W2, J, g


def _junctions(W1: np.ndarray, W2: np.ndarray, b1: np.ndarray) -> np.ndarray:
    """``J_j = (β1_j W_{j-1,2} + W_{j,1}) / (1 + β1_j)`` (step (2)), without overflow for
    huge β1 or coordinates."""
    own_work.require("course_lib.constructions.beta_splines.quadratic_cubic._junctions")
    w = 1.0 / (1.0 + b1[:, None])
    return (b1[:, None] * w) * W2[:-1] + w * W1[1:]


def _cubic_polygons_from(W1: np.ndarray, W2: np.ndarray, J: np.ndarray) -> np.ndarray:
    S = J.shape[0] - 1
    out = np.empty((S, 4, J.shape[1]))
    out[:, 0] = J[:-1]
    out[:, 1] = W1[1:-1]
    out[:, 2] = W2[1:-1]
    out[:, 3] = J[1:]
    return out


def _cubic_curve(W1, W2, J, b1, b2, g, joints: slice) -> PiecewiseBezier:
    """The cubic Beta-spline from its interior and junction vertices, with the shape
    parameters per site (``b1``, ``b2``, ``g``) and, in ``info``, per joint (``joints``)."""
    info = {
        "beta1": b1[joints].copy(),
        "beta2": b2[joints].copy(),
        "beta1_vertices": b1,
        "beta2_vertices": b2,
        "gamma": g,
        "gamma_inverse": _gamma_inverse(b1, b2) if g.size == b1.size else 1.0 / g,
        "junction_points": J,
        "interior_points": np.stack([W1, W2], axis=1),
    }
    return PiecewiseBezier.from_trusted_segments(list(_cubic_polygons_from(W1, W2, J)), info=info)


def _check_joint_tangents(A: np.ndarray, B: np.ndarray, P: np.ndarray, where, what: str):
    """Raise if A_k = B_k (zero tangent at a junction); ``where(k)`` names the place."""
    scale = float(np.max(np.abs(P)))
    bad = scaled_norm(B - A, axis=1) <= 1e-12 * scale
    if np.any(bad):
        k = int(np.argmax(bad))
        raise ValueError(
            f"the tangent vanishes at the junction vertex on {where(k)} ({what}, "
            "e.g. coincident consecutive control points): the curve would not be regular there"
        )


def quadratic_beta_spline(V: np.ndarray, beta1: float | np.ndarray = 1.0) -> PiecewiseBezier:
    """Quadratic G1 Beta-spline with one β1 per joint (seed 000 §10.1, eq. (17)-(19)).

    Parameters
    ----------
    V : array_like of shape (m + 1, dim), ``m >= 2``
        Control polygon; the curve has ``m - 1`` quadratic segments, segment ``i - 1``
        using ``V_{i-1}, V_i, V_{i+1}``.
    beta1 : float or array_like
        ``β1 > 0``: a scalar (global); one value per leg ``V_i V_{i+1}`` (``m``
        values, the seed's ``β1_0 .. β1_{m-1}``; legs 0 and ``m - 1`` carry the curve's
        end points); or one per interior joint (``m - 2`` values, the end legs use 1).

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1`` (per interior joint), ``beta1_legs``, ``junction_points``
        (``J_0 .. J_{m-1}``), ``interior_points`` (``V_1 .. V_{m-1}``).

    Raises
    ------
    ValueError
        Fewer than 3 points, β1 <= 0 or wrong length (naming the joint), coincident
        consecutive control points (zero tangent at a junction).

    Examples
    --------
    >>> import numpy as np
    >>> curve = quadratic_beta_spline(np.array([[0, 0], [1, 2], [3, 2], [4, 0]]), beta1=2.0)
    >>> curve.n_segments, curve.degrees
    (2, (2, 2))
    """
    own_work.require("course_lib.constructions.beta_splines.quadratic_cubic.quadratic_beta_spline")
    P = as_points(V, "V", min_points=3)
    m = P.shape[0] - 1
    b1 = _per_site(beta1, "beta1", m, m - 2, "leg V_i V_(i+1)", 1.0, True)
    _check_joint_tangents(P[:-1], P[1:], P, lambda k: f"leg {k}", "V_k = V_(k+1)")
    segs = _quadratic_polygons(P, b1)
    J = np.vstack([segs[:, 0], segs[-1:, 2]])
    info = {
        "beta1": b1[1:-1].copy(),
        "beta1_legs": b1,
        "junction_points": J,
        "interior_points": P[1:-1].copy(),
    }
    return PiecewiseBezier.from_trusted_segments(list(segs), info=info)


def cubic_beta_spline(
    V: np.ndarray, beta1: float | np.ndarray = 1.0, beta2: float | np.ndarray = 0.0
) -> PiecewiseBezier:
    """Cubic G2 Beta-spline with one (β1, β2) per joint (seed 000 §10.2, steps 1a, 1b, 2).

    Parameters
    ----------
    V : array_like of shape (m + 1, dim), ``m >= 3``
        Control polygon; ``m - 2`` cubic segments, segment ``i - 1`` using
        ``V_{i-1} .. V_{i+2}``.
    beta1, beta2 : float or array_like
        A scalar (global); one value per control vertex (``m + 1`` values, the seed's
        ``β_{·0} .. β_{·m}``); or one per interior joint (``m - 3`` values, at
        ``V_2 .. V_{m-2}``; the four end vertices use β1 = 1, β2 = 0).  ``β1 > 0``, any
        β2.  Where ``β2 = -2 β1 (1 + β1)`` γ has a pole (Farin-Boehm's T is at infinity)
        but the curve is finite: the leg ratios are computed without the pole (see
        ``_leg_weights``), so a slider crosses that value and the result is the limit
        (Barsky's closed form).  Any β1 up to the float limit gives finite control points
        (β1 -> 0 and β1 -> inf approach finite, degenerate limits).

    Returns
    -------
    PiecewiseBezier
        ``info``: ``beta1``, ``beta2`` (per interior joint), ``beta1_vertices``,
        ``beta2_vertices``, ``gamma`` (per vertex; ``inf`` where T is at infinity),
        ``gamma_inverse`` (``1/γ``, pole-free), ``junction_points``
        (``J_1 .. J_{m-1}``), ``interior_points`` (``(m, 2, dim)``: ``W_{i,1}, W_{i,2}``
        on every leg).

    Raises
    ------
    ValueError
        Fewer than 4 points; β1 <= 0 or wrong lengths (naming the vertex/joint); a leg
        whose ratio sums to zero (Barsky's ``δ = 0``, a true pole); γ undefined at both
        ends of a leg with different β1 (no limit); a zero tangent at a junction vertex.

    Examples
    --------
    >>> import numpy as np
    >>> V = np.array([[0, 0], [1, 2], [3, 2], [4, 0], [6, 1]])
    >>> curve = cubic_beta_spline(V, beta1=1.5, beta2=2.0)
    >>> curve.n_segments, curve.degrees
    (2, (3, 3))
    """
    own_work.require("course_lib.constructions.beta_splines.quadratic_cubic.cubic_beta_spline")
    P = as_points(V, "V", min_points=4)
    m = P.shape[0] - 1
    b1 = _per_site(beta1, "beta1", m + 1, m - 3, "control vertex", 1.0, True)
    b2 = _per_site(beta2, "beta2", m + 1, m - 3, "control vertex", 0.0, False)
    W1, W2, J, g = _cubic_points(P, b1, b2)
    _check_joint_tangents(W2[:-1], W1[1:], P, lambda k: f"vertex V_{k + 1}", "W_(j-1),2 = W_j,1")
    return _cubic_curve(W1, W2, J, b1, b2, g, slice(2, -2))


# ------------------------------------------------------------------ bases
def _basis(segs: np.ndarray, t: object) -> np.ndarray:
    """Evaluate linear-map segments (S, d+1, n) at global parameters t in [0, S]."""
    tt, scalar = as_parameter_array(t, "t")
    S = segs.shape[0]
    if np.any((tt < 0) | (tt > S)):
        bad = tt[(tt < 0) | (tt > S)][0]
        raise ValueError(f"t must lie in the domain [0, {S}]; got {bad}")
    idx = np.minimum(np.floor(tt).astype(np.intp), S - 1)
    u = tt - idx
    B = bernstein_matrix(segs.shape[1] - 1, u)
    out = np.einsum("md,mdk->mk", B, segs[idx])
    return out[0] if scalar else out


def _check_n_points(n_points: object, minimum: int) -> int:
    from course_lib.validation import check_integer

    return check_integer(n_points, "n_points", minimum=minimum)


def quadratic_beta_spline_basis(
    n_points: int, beta1: float | np.ndarray, t: float | np.ndarray
) -> np.ndarray:
    """The G1 quadratic Beta-spline blending functions ``b_k(t)``, ``k = 0..n_points-1``.

    Built by applying :func:`quadratic_beta_spline` to unit control vectors (the
    construction is linear in ``V``), evaluated in the global parameter
    ``t in [0, n_points - 2]`` (segment ``s`` on ``[s, s+1]``).

    Returns
    -------
    ndarray of shape (n_points,) or (len(t), n_points)
    """
    n = _check_n_points(n_points, 3)
    m = n - 1
    b1 = _per_site(beta1, "beta1", m, m - 2, "leg V_i V_(i+1)", 1.0, True)
    return _basis(_quadratic_polygons(np.eye(n), b1), t)


def cubic_beta_spline_basis(
    n_points: int,
    beta1: float | np.ndarray,
    beta2: float | np.ndarray,
    t: float | np.ndarray,
) -> np.ndarray:
    """The G2 cubic Beta-spline blending functions, ``t in [0, n_points - 3]``.

    Returns
    -------
    ndarray of shape (n_points,) or (len(t), n_points)
    """
    n = _check_n_points(n_points, 4)
    m = n - 1
    b1 = _per_site(beta1, "beta1", m + 1, m - 3, "control vertex", 1.0, True)
    b2 = _per_site(beta2, "beta2", m + 1, m - 3, "control vertex", 0.0, False)
    W1, W2, J, _ = _cubic_points(np.eye(n), b1, b2)
    return _basis(_cubic_polygons_from(W1, W2, J), t)


# ------------------------------------------------------------------ design
def design_beta_spline(V: np.ndarray, interior: np.ndarray) -> PiecewiseBezier:
    """Cubic G2 Beta-spline from its polygon and the interior Bézier vertices (seed 000 §10.3).

    The designer places ``W_{i,1}, W_{i,2}`` on the line of each leg ``V_i V_{i+1}``.
    With the signed positions ``W_{i,k} = V_i + s_{i,k} (V_{i+1} - V_i)``,
    ``a_i = s_{i,1} / (s_{i,2} - s_{i,1})`` and ``c_i = (1 - s_{i,2}) / (s_{i,2} - s_{i,1})``,
    the leg ratios ``γ_i : 1 : β1_{i+1}² γ_{i+1}`` of :func:`cubic_beta_spline` give, at each
    vertex ``V_j``, ``j = 1..m-1``::

        γ_j = a_j,   β1_j = sqrt(c_{j-1} / a_j),   β2_j = 2 (1 + β1_j) (1/γ_j - β1_j),

    and the junction vertices follow from step (2).  This inverts every spline
    :func:`cubic_beta_spline` produces with γ finite: for ``γ > 0`` the interior vertices
    lie inside the leg in the order ``V_i, W_{i,1}, W_{i,2}, V_{i+1}``; for ``γ < 0``
    (``β2 < -2 β1 (1 + β1)``) ``W_{i,1}`` and ``W_{i,2}`` swap order or leave the leg.
    Where γ is infinite (``W_{i,1} = W_{i,2}`` on both legs at a vertex) β1 is not
    determined by the interior vertices alone: a ValueError says so.  Scale-free: the
    positions are computed from coordinates scaled by a power of two.

    Parameters
    ----------
    V : array_like of shape (m + 1, dim), ``m >= 3``
    interior : array_like of shape (m, 2, dim)
        ``interior[i] = (W_{i,1}, W_{i,2})`` on (the line of) leg ``i``.

    Returns
    -------
    PiecewiseBezier
        The same curve as ``cubic_beta_spline`` with the recovered parameters.
        ``info``: ``beta1``, ``beta2`` (interior joints), ``beta1_vertices``,
        ``beta2_vertices``, ``gamma`` (at ``V_1 .. V_{m-1}``), ``junction_points``,
        ``interior_points``.

    Raises
    ------
    ValueError
        Wrong shapes; an interior vertex off the line of its leg; ``W_{i,1} = W_{i,2}``;
        ``W_{j,1} = V_j`` (γ = 0); or positions giving ``β1_j² = c_{j-1} / a_j <= 0``
        (naming the legs).
    """
    P = as_points(V, "V", min_points=4)
    m = P.shape[0] - 1
    if isinstance(interior, (str, bytes)):
        raise TypeError("interior must be an array of points of shape (m, 2, dim), got str")
    Wi = _real_array(interior, "interior", "an array of points of shape (m, 2, dim)")
    if Wi.shape != (m, 2, P.shape[1]):
        raise ValueError(
            f"interior must have shape ({m}, 2, {P.shape[1]}): two points on each of the {m} "
            f"legs; got {Wi.shape}"
        )
    if not np.all(np.isfinite(Wi)):
        raise ValueError("interior must contain only finite values")
    # exact power-of-two scaling: positions are scale-free and nothing over/underflows
    big = max(float(np.max(np.abs(P))), float(np.max(np.abs(Wi))))
    _, e = np.frexp(big if big > 0 else 1.0)
    Ps, Ws = np.ldexp(P, -e), np.ldexp(Wi, -e)
    leg = Ps[1:] - Ps[:-1]
    L2 = np.einsum("id,id->i", leg, leg)
    for i in range(m):
        if L2[i] <= (1e-12 * max(float(np.max(np.abs(Ps))), 1e-300)) ** 2:
            raise ValueError(f"leg {i} has zero length (V_{i} = V_{i + 1}); no direction")
    s = np.einsum("ikd,id->ik", Ws - Ps[:-1, None], leg) / L2[:, None]
    off = scaled_norm(Ws - (Ps[:-1, None] + s[..., None] * leg[:, None]), axis=2)
    for i in range(m):
        if np.max(off[i]) > 1e-9 * np.sqrt(L2[i]):
            raise ValueError(
                f"interior[{i}] must lie on leg {i} (the line V_{i} V_{i + 1}); it is off it"
            )
    mid = s[:, 1] - s[:, 0]
    for i in range(m):
        if abs(mid[i]) <= 1e-12:
            raise ValueError(
                f"interior[{i}] must satisfy W_{i},1 != W_{i},2: coincident interior vertices "
                "mean gamma is infinite there (Farin-Boehm's T at infinity), and beta1 is then "
                "not determined by the interior vertices alone"
            )
    for j in range(1, m):
        if abs(s[j, 0]) <= 1e-12:
            raise ValueError(
                f"interior[{j}] must satisfy W_{j},1 != V_{j} (gamma_{j} = 0 is not a "
                "Beta-spline with finite beta2)"
            )
    a = s[:, 0] / mid
    c = (1 - s[:, 1]) / mid
    g = a[1:]  # γ at V_1 .. V_{m-1}
    ratio = c[:-1] / g
    if np.any(ratio <= 0):
        j = int(np.argmax(ratio <= 0)) + 1
        raise ValueError(
            f"interior[{j - 1}] and interior[{j}] must satisfy beta1_{j}^2 = c_{j - 1} / a_{j} > 0 "
            f"at V_{j}; got {ratio[j - 1]:.3g} (W_{j - 1},2 and W_{j},1 must lie on the same side "
            "of their legs' common order, as cubic_beta_spline places them)"
        )
    b1 = np.sqrt(ratio)
    b2 = 2 * (1 + b1) * (1 / g - b1)
    W1, W2 = Wi[:, 0], Wi[:, 1]
    J = _junctions(W1, W2, b1)
    return _cubic_curve(W1, W2, J, b1, b2, g, slice(1, -1))


def _real_array(value: object, name: str, what: str) -> np.ndarray:
    from course_lib.validation import as_real_array

    return as_real_array(value, name, what)
