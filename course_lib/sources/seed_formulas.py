"""The sources' formulas as printed, next to their corrected forms: evidence for the lectures.

Where a seed's formula is wrong, incomplete, or written in another convention, the
lectures show the difference by *running* both forms.  The printed forms live here, so
that a lecture cell is one line and each form is tested once
(``tests/unit/test_seed_formulas.py``).  Nothing here is used to build curves elsewhere.

Conventions
    Seed 000 (§5, eq. 7) writes the Beta-constraints forwards: the right piece's start
    derivatives from the left piece's end derivatives, ``r'(0) = β1 q'(1)``, ...  Seed 001
    (eq. 2.6) writes them backwards: its ``r`` *arrives* at the joint and its ``q`` leaves,
    and ``r^{(i)}(t_1) = CL_i(q^{(1)}(u_0), ...; β)``.  The same chain-rule polynomials
    then hold for the *inverse* change of variables, so 001's β's are
    ``inverse_betas`` of 000's (and vice versa: the map is an involution).

Lectures: ``notebooks/03_beta_constraints.ipynb`` (conventions),
``notebooks/08_beta_splines.ipynb`` (seed 000 §10), ``notebooks/09_higher_order.ipynb``
(seed 001 Ex. 2.1), ``notebooks/06_g1_knot_bezier_splines.ipynb`` (seed 004 §19.6).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from course_lib.curves.curve import PiecewiseBezier
from course_lib.validation import as_points, check_integer

__all__ = [
    "barycentric_weights",
    "blending_basis",
    "blending_system",
    "cubic_beta_spline_printed",
    "cubic_beta_spline_reciprocal",
    "gamma_printed",
    "inverse_betas",
]


# ------------------------------------------------------------------ conventions
def inverse_betas(betas: Sequence[object]) -> tuple:
    """Shape parameters of the inverse change of variables, up to order 4.

    If ``u(ū)`` has ``u^{(j)} = β_j`` at the joint, its inverse ``ū(u)`` has
    ``1/β1``, ``-β2/β1³``, ``(3β2² - β1β3)/β1⁵`` and
    ``(-15β2³ + 10β1β2β3 - β1²β4)/β1⁷``.  This converts between seed 000's and seed
    001's conventions (module docstring); applied twice it gives the β's back.
    Works for floats and for sympy symbols.

    Raises
    ------
    ValueError
        If not 1 to 4 values are given, or β1 is a number ``<= 0``.

    Examples
    --------
    >>> inverse_betas([2.0, 1.0])
    (0.5, -0.125)
    >>> inverse_betas(inverse_betas([2.0, 1.0]))
    (2.0, 1.0)
    """
    b = list(betas)
    if not 1 <= len(b) <= 4:
        raise ValueError(f"betas must hold 1 to 4 values (β1, ..., β4); got {len(b)}")
    if isinstance(b[0], (int, float, np.floating, np.integer)) and not b[0] > 0:
        raise ValueError(f"beta1 must be > 0; got {b[0]}")
    b = b + [0] * (4 - len(b))
    b1, b2, b3, b4 = b
    out = (
        1 / b1,
        -b2 / b1**3,
        (3 * b2**2 - b1 * b3) / b1**5,
        (-15 * b2**3 + 10 * b1 * b2 * b3 - b1**2 * b4) / b1**7,
    )
    return out[: len(list(betas))]


# ------------------------------------------------------- blending functions (001)
def blending_system(n: int, betas: Sequence[object], convention: str = "000", printed_range=False):
    """Linear equations for the blending functions of a G^n Beta-spline (seed 001 Ex. 2.1).

    The ``n + 2`` weights ``b_0 .. b_{n+1}`` of degree ``n + 1`` (seed 001 eq. 2.8 numbers
    them ``-2 .. 2`` for n = 3) must pass every joint with the Beta-constraints:
    vertex weight ``b_k`` at the end of one segment becomes ``b_{k-1}`` at the start of
    the next.  ``convention="000"`` writes the constraints forwards (start of the next
    segment from the end of the previous), ``"001"`` backwards as seed 001 eq. (2.10)
    prints them.  The full system also has the pairs with ``b_{-1} = b_{n+2} = 0`` and the
    normalization ``sum_k b_k(0) = 1``; ``printed_range=True`` keeps only what eqs.
    (2.9)-(2.10) print: the ``n + 1`` inner pairs and no normalization.

    Returns
    -------
    (equations, unknowns, weights)
        sympy expressions ``= 0``, the coefficient symbols, and the weights as polynomials
        in ``u`` with those coefficients.
    """
    import sympy as sp

    from course_lib.geometry.beta_constraints import beta_constraints

    n = check_integer(n, "n", minimum=1)
    if convention not in ("000", "001"):
        raise ValueError(f"convention must be '000' or '001'; got {convention!r}")
    if len(betas) != n:
        raise ValueError(f"betas must hold n = {n} values; got {len(betas)}")
    u = sp.Symbol("u")
    bc = beta_constraints(n)
    C = bc.coefficients.subs(dict(zip(bc.betas, betas, strict=True)))
    N = n + 2
    a = sp.symbols(f"a0:{N * N}")
    b = [sum(a[N * k + j] * u**j for j in range(N)) for k in range(N)]

    def weight(k):
        return b[k] if 0 <= k < N else sp.S(0)

    eqs = [] if printed_range else [sum(b).subs(u, 0) - 1]
    pairs = range(1, N) if printed_range else range(N + 1)
    for k in pairs:
        nxt, prv = (weight(k - 1), 0), (weight(k), 1)
        if convention == "001":
            nxt, prv = prv, nxt
        dn = [nxt[0].diff(u, i).subs(u, nxt[1]) for i in range(n + 1)]
        dp = [prv[0].diff(u, i).subs(u, prv[1]) for i in range(n + 1)]
        eqs.append(dn[0] - dp[0])
        for i in range(1, n + 1):
            eqs.append(dn[i] - sum(C[i - 1, j - 1] * dp[j] for j in range(1, i + 1)))
    return eqs, a, b


def blending_basis(n: int, betas: Sequence[object], convention: str = "000") -> list:
    """The weights ``b_0 .. b_{n+1}`` (sympy polynomials in ``u``) solving ``blending_system``.

    Raises
    ------
    ValueError
        If the system has no unique solution (e.g. where its determinant vanishes).
    """
    import sympy as sp

    eqs, a, b = blending_system(n, betas, convention)
    sol = sp.linsolve(eqs, a)
    if not sol or any(s.free_symbols & set(a) for s in next(iter(sol))):
        raise ValueError(f"no unique G^{n} Beta-spline basis for betas = {tuple(betas)}")
    (values,) = sol
    return [sp.expand(f.subs(dict(zip(a, values, strict=True)))) for f in b]


# -------------------------------------------------------------- seed 000 §10.2
def _gamma_reciprocal(b1: np.ndarray, b2: np.ndarray) -> np.ndarray:
    """1/γ = (β2 + 2β1(1 + β1)) / (2(1 + β1)): defined for every β1 > 0."""
    return (b2 + 2 * b1 * (1 + b1)) / (2 * (1 + b1))


def gamma_printed(beta1: object, beta2: object) -> np.ndarray:
    """γ of seed 000 §10.2 step (1a), ``2(1 + β1) / (β2 + 2β1(1 + β1))``; ``inf`` where undefined."""
    b1, b2 = np.asarray(beta1, dtype=float), np.asarray(beta2, dtype=float)
    with np.errstate(divide="ignore"):
        return 1 / _gamma_reciprocal(b1, b2)


def _per_vertex(value: object, m: int, name: str) -> np.ndarray:
    arr = np.broadcast_to(np.asarray(value, dtype=float), (m + 1,)).copy()
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite at every vertex")
    return arr


def _cubic_from(P, W1, W2, b1) -> PiecewiseBezier:
    J = (b1[1:-1, None] * W2[:-1] + W1[1:]) / (1 + b1[1:-1, None])  # step (2)
    segs = [[J[i], W1[i + 1], W2[i + 1], J[i + 1]] for i in range(len(J) - 1)]
    return PiecewiseBezier(segs)


def cubic_beta_spline_printed(V: np.ndarray, beta1: object, beta2: object) -> PiecewiseBezier:
    """Cubic Beta-spline by seed 000 §10.2 steps (1a), (1b), (2) exactly as printed.

    Step (1b) as printed uses ``β1_i² γ_{i+1}`` for the last piece of leg ``V_i V_{i+1}``
    (the correct factor is ``β1_{i+1}² γ_{i+1}``: ``course_lib.constructions.beta_splines``).  β's are
    one per vertex (``m + 1`` values) or scalars.  Segments ``1 .. m-2`` of the seed
    are the curve's segments ``0 .. m-3``.  Evidence only: the result is not G2 when β1
    varies from vertex to vertex.
    """
    P = as_points(V, "V", min_points=4)
    m = P.shape[0] - 1
    b1, b2 = _per_vertex(beta1, m, "beta1"), _per_vertex(beta2, m, "beta2")
    if np.any(b1 <= 0):
        raise ValueError("beta1 must be > 0 at every vertex")
    g = gamma_printed(b1, b2)  # (1a)
    if not np.all(np.isfinite(g)):
        j = int(np.argmax(~np.isfinite(g)))
        raise ValueError(f"step (1a) divides by zero at vertex V_{j}: gamma is undefined")
    far = b1[:-1] ** 2 * g[1:]  # (1b) as printed: β1_i² γ_{i+1}
    S = (1 + g[:-1] + far)[:, None]
    W1 = ((1 + far)[:, None] * P[:-1] + g[:-1, None] * P[1:]) / S
    W2 = (far[:, None] * P[:-1] + (1 + g[:-1])[:, None] * P[1:]) / S
    return _cubic_from(P, W1, W2, b1)


def cubic_beta_spline_reciprocal(V: np.ndarray, beta1: object, beta2: object) -> PiecewiseBezier:
    """Cubic Beta-spline by the corrected §10.2 construction, written with ``1/γ``.

    Multiplying the numerators and denominators of step (1b) by ``1/γ_i · 1/γ_{i+1}``
    removes every division by ``β2 + 2β1(1 + β1)``: the construction then stays defined
    where γ is not (``β2 = -2β1(1 + β1)``, where the interior vertices of a leg
    coincide).  Equal to ``course_lib.constructions.beta_splines.cubic_beta_spline`` wherever γ is defined.

    Raises
    ------
    ValueError
        β1 <= 0, or a leg whose three ratios sum to zero.
    """
    P = as_points(V, "V", min_points=4)
    m = P.shape[0] - 1
    b1, b2 = _per_vertex(beta1, m, "beta1"), _per_vertex(beta2, m, "beta2")
    if np.any(b1 <= 0):
        raise ValueError("beta1 must be > 0 at every vertex")
    h = _gamma_reciprocal(b1, b2)  # h_i = 1/γ_i
    h0, h1, sq = h[:-1], h[1:], b1[1:] ** 2
    # γ_i : 1 : β1_{i+1}² γ_{i+1} times h_i h_{i+1} is h_{i+1} : h_i h_{i+1} : β1² h_i; on a
    # leg with γ_i = γ_{i+1} times h only: 1 : h : β1² (also where both are undefined).
    same = np.isclose(h0, h1, rtol=1e-12, atol=1e-15)
    first = np.where(same, 1.0, h1)
    middle = np.where(same, h0, h0 * h1)
    last = np.where(same, sq, sq * h0)
    S = first + middle + last
    if np.any(np.abs(S) <= 1e-12):
        raise ValueError("a leg's ratios γ_i : 1 : β1_(i+1)² γ_(i+1) sum to zero")
    W1 = ((middle + last)[:, None] * P[:-1] + first[:, None] * P[1:]) / S[:, None]
    W2 = (last[:, None] * P[:-1] + (first + middle)[:, None] * P[1:]) / S[:, None]
    return _cubic_from(P, W1, W2, b1)


# ------------------------------------------------------------------ seed 004
def barycentric_weights(point: object, a: object, c: object) -> np.ndarray:
    """Weights ``(λ, μ)``, ``λ + μ = 1``, with ``λ a + μ c = point`` (least squares).

    For numbers or points.  Raises ValueError if ``a == c`` (no unique weights) or if
    the point is off the line through ``a`` and ``c``.
    """
    p, A, B = (np.atleast_1d(np.asarray(x, dtype=float)) for x in (point, a, c))
    d = B - A
    dd = float(d @ d)
    if dd == 0.0:
        raise ValueError("a and c coincide: barycentric weights are not unique")
    mu = float((p - A) @ d) / dd
    if not np.allclose(A + mu * d, p, atol=1e-9 * max(1.0, np.sqrt(dd))):
        raise ValueError("point is not on the line through a and c")
    return np.array([1 - mu, mu])
