"""Beta-constraints of any order: symbolic (derived by the chain rule) and numeric.

Two regular parametrizations ``q(u)`` and ``r(t)`` meeting at ``r(0) = q(1)`` are
``G^n`` iff there is an orientation-preserving change of variables ``u(ū)`` with
``u(1) = 1`` such that ``q o u`` and ``r`` are ``C^n`` at the joint (seed 000 §4-5).
Differentiating ``q(u(ū))`` ``i`` times by the chain rule and writing
``β_j = u^{(j)}(1)`` gives the *Beta-constraints* (seed 000 eq. (6))::

    r^{(i)}(0) = sum_{k=1}^{i} B_{i,k}(β_1, ..., β_{i-k+1}) q^{(k)}(1),   i = 1..n,  β_1 > 0,

where ``B_{i,k}`` are the partial Bell polynomials (Faà di Bruno's formula).

* :func:`beta_constraints` derives them *programmatically* with sympy: it
  differentiates ``q(u(t))`` with undefined functions ``q, u`` and substitutes
  ``u^{(j)}(1) = β_j`` -- nothing is typed in.  For ``n = 4`` it reproduces seed 000
  eq. (7.1)-(7.4) (test: ``tests/unit/test_beta_constraints.py::test_seed_000_eq_7``).
* Seed 001 eq. (2.7) (as transcribed) reads ``... + β_2 q'(u_0)`` in ``r'''`` and
  ``(4 β_1 β_2 + 3 β_2^2) q''`` in ``r''''``; the chain rule gives ``β_3 q'`` and
  ``(4 β_1 β_3 + 3 β_2^2) q''`` (test: ``::test_seed_001_eq_2_7_is_not_the_chain_rule``).
  Seed 001 also says "β_i > 0" after eq. (2.4); only ``β_1 > 0`` is required.
* :func:`apply_beta_constraints` and :func:`solve_shape_parameters` are the
  numeric form (pure numpy, Bell polynomials; sympy is not imported).

Lesson: ``notebooks/03_beta_constraints.ipynb``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from course_lib.geometry.chain_rule import bell_row, bell_table, check_chain_rule_order
from course_lib.homework import own_work
from course_lib.validation import as_real_array, check_integer

__all__ = [
    "BetaConstraints",
    "ShapeParameterFit",
    "apply_beta_constraints",
    "beta_coefficients",
    "beta_constraints",
    "solve_shape_parameters",
]


# ------------------------------------------------------------------ symbolic
class BetaConstraints:
    """The Beta-constraints of orders ``1..n`` as sympy objects.

    Attributes
    ----------
    n : int
    betas : tuple of sympy.Symbol
        ``β_1 .. β_n``.
    q : tuple of sympy.Symbol
        ``q^{(1)}(1) .. q^{(n)}(1)`` (derivatives of the left parametrization at its end).
    r : tuple of sympy.Symbol
        ``r^{(1)}(0) .. r^{(n)}(0)``.
    rhs : tuple of sympy expressions
        ``rhs[i-1]`` is the chain-rule expression for ``r^{(i)}(0)``.
    coefficients : sympy.Matrix, shape (n, n)
        Lower triangular; entry ``[i-1, k-1]`` is the coefficient of ``q^{(k)}(1)``
        in ``r^{(i)}(0)``, a polynomial in the β's (the Bell polynomial ``B_{i,k}``).
    equations : list of sympy.Eq
        ``Eq(r[i-1], rhs[i-1])``.
    """

    def __init__(self, n: int, betas, q, r, rhs, coefficients) -> None:
        self.n = n
        self.betas = betas
        self.q = q
        self.r = r
        self.rhs = rhs
        self.coefficients = coefficients

    @property
    def equations(self) -> list:
        import sympy as sp

        return [sp.Eq(ri, e) for ri, e in zip(self.r, self.rhs, strict=True)]

    def _terms(self, i: int, fmt_coef, fmt_q) -> str:
        parts = []
        for k in range(i, 0, -1):  # highest derivative first, as in seed 000 eq. (7)
            c = self.coefficients[i - 1, k - 1]
            if c == 0:
                continue
            parts.append(fmt_coef(c) + fmt_q(k))
        return " + ".join(parts)

    def _repr_latex_(self) -> str:
        import sympy as sp

        def coef(c):
            if c == 1:
                return ""
            s = sp.latex(c)
            return f"\\left({s}\\right) " if isinstance(c, sp.Add) else s + " "

        rows = [
            f"\\mathbf{{r}}^{{({i})}}(0) &= "
            + self._terms(i, coef, lambda k: f"\\mathbf{{q}}^{{({k})}}(1)")
            for i in range(1, self.n + 1)
        ]
        return "$\\begin{aligned}" + " \\\\ ".join(rows) + "\\end{aligned}$"

    def __str__(self) -> str:
        import sympy as sp

        def coef(c):
            if c == 1:
                return ""
            s = sp.sstr(c).replace("**", "^")
            return f"({s}) " if isinstance(c, sp.Add) else s + " "

        rows = [
            f"r^({i})(0) = " + self._terms(i, coef, lambda k: f"q^({k})(1)")
            for i in range(1, self.n + 1)
        ]
        return "\n".join(rows)

    def __repr__(self) -> str:
        return f"BetaConstraints(n={self.n})\n{self}"


@lru_cache(maxsize=1)
def _chain_rule_state():
    import sympy as sp

    t = sp.Symbol("t")
    u = sp.Function("u")(t)
    q = sp.Function("q")
    return sp, t, u, q


@lru_cache(maxsize=32)
def _raw_derivative(i: int):
    """``d^i/dt^i q(u(t))`` with undefined ``q, u`` (sympy's chain rule), cached by order."""
    sp, t, u, q = _chain_rule_state()
    if i == 0:
        return q(u)
    return sp.diff(_raw_derivative(i - 1), t)


#: Largest order of the symbolic :func:`beta_constraints` (sympy's cost grows fast: the
#: chain-rule derivation takes ~4 s at n = 12, the Bell-polynomial path ~1 s).
MAX_SYMBOLIC_ORDER = 12
#: Up to this order ``method="auto"`` derives by the chain rule, as the lecture shows.
_CHAIN_RULE_AUTO_MAX = 6


def beta_constraints(n: int, method: str = "auto") -> BetaConstraints:
    """Derive the Beta-constraints of orders ``1..n`` by the chain rule (seed 000 eq. (4)-(6)).

    ``method="chain_rule"``: ``q(u(t))`` is differentiated ``i`` times with sympy (``q`` and
    ``u`` undefined functions); then ``u^{(j)}(1)`` is replaced by ``β_j`` and
    ``q^{(k)}(u(1)) = q^{(k)}(1)`` by a symbol (~0.9 s at n = 8, ~2 s at n = 10, cold).
    ``method="bell"``: the same coefficients from sympy's partial Bell polynomials
    ``B_{i,k}(β_1, ..)`` (Faà di Bruno's formula; n = 10 in ~0.4 s; tested equal to the
    chain-rule derivation).  ``method="auto"`` (default) uses the chain rule up to
    ``n = 6`` and the Bell polynomials above.  Cached.

    Raises
    ------
    ValueError
        ``n > MAX_SYMBOLIC_ORDER`` (12), or an unknown ``method``.

    Examples
    --------
    >>> print(beta_constraints(2))
    r^(1)(0) = beta1 q^(1)(1)
    r^(2)(0) = beta1^2 q^(2)(1) + beta2 q^(1)(1)
    """
    own_work.require("course_lib.geometry.beta_constraints.beta_constraints")
    return _cached_constraints(n, method)


@lru_cache(maxsize=32)
def _cached_constraints(n: int, method: str) -> BetaConstraints:
    # the cache sits behind the guard: a cached result is not handed out during an exercise
    own_work.require("course_lib.geometry.beta_constraints.beta_constraints")
    n = check_integer(n, "n", minimum=1)
    if n > MAX_SYMBOLIC_ORDER:
        raise ValueError(
            f"n must be <= {MAX_SYMBOLIC_ORDER} (MAX_SYMBOLIC_ORDER) for the symbolic "
            f"Beta-constraints (sympy's cost grows steeply); got {n}; the numeric form "
            "(apply_beta_constraints) goes higher"
        )
    if method not in ("auto", "chain_rule", "bell"):
        raise ValueError(f"method must be 'auto', 'chain_rule' or 'bell'; got {method!r}")
    if method == "bell" or (method == "auto" and n > _CHAIN_RULE_AUTO_MAX):
        return _bell_constraints(n)
    return _chain_rule_constraints(n)


beta_constraints.cache_clear = _cached_constraints.cache_clear  # type: ignore[attr-defined]


def _bell_constraints(n: int) -> BetaConstraints:
    own_work.require("course_lib.geometry.beta_constraints._bell_constraints")
    import sympy as sp

    betas = sp.symbols(f"beta1:{n + 1}")
    Q = sp.symbols(f"q1:{n + 1}")
    R = sp.symbols(f"r1:{n + 1}")
    M = sp.zeros(n, n)
    for i in range(1, n + 1):
        for k in range(1, i + 1):
            M[i - 1, k - 1] = sp.expand(sp.bell(i, k, betas[: i - k + 1]))
    rhs = tuple(sp.expand(sum(M[i, k] * Q[k] for k in range(i + 1))) for i in range(n))
    return BetaConstraints(n, tuple(betas), tuple(Q), tuple(R), rhs, M)


def _chain_rule_constraints(n: int) -> BetaConstraints:
    own_work.require("course_lib.geometry.beta_constraints._chain_rule_constraints")
    sp, _t, u, q = _chain_rule_state()
    betas = sp.symbols(f"beta1:{n + 1}")
    Q = sp.symbols(f"q1:{n + 1}")
    R = sp.symbols(f"r1:{n + 1}")

    def is_q_derivative(e):
        return isinstance(e, sp.Derivative) and e.expr == q(u)

    def is_u_derivative(e):
        return isinstance(e, sp.Derivative) and e.expr == u

    rhs = []
    for i in range(1, n + 1):
        e = _raw_derivative(i)
        e = e.replace(is_q_derivative, lambda d: Q[d.derivative_count - 1])
        e = e.replace(is_u_derivative, lambda d: betas[d.derivative_count - 1])
        rhs.append(sp.expand(e))
    M = sp.zeros(n, n)
    for i, e in enumerate(rhs):
        poly = sp.Poly(e, *Q)
        for k in range(n):
            M[i, k] = poly.coeff_monomial(Q[k])
        assert sp.expand(e - sum(M[i, k] * Q[k] for k in range(n))) == 0  # linear in q
    return BetaConstraints(n, tuple(betas), tuple(Q), tuple(R), tuple(rhs), M)


# ------------------------------------------------------------------- numeric
def beta_coefficients(betas: np.ndarray | list[float]) -> np.ndarray:
    """Numeric coefficient table: ``C[i-1, k-1] = B_{i,k}(β_1, ..., β_{i-k+1})``.

    The numeric counterpart of :attr:`BetaConstraints.coefficients` (pure numpy).

    Returns
    -------
    ndarray of shape (n, n), lower triangular.
    """
    own_work.require("course_lib.geometry.beta_constraints.beta_coefficients")
    b = _as_betas(betas)
    n = b.size
    return bell_table(b, n)[1:, 1:]


def _as_betas(betas) -> np.ndarray:
    b = as_real_array(betas, "betas", "a sequence of real numbers")
    if b.ndim != 1 or b.size == 0:
        raise ValueError(
            f"betas must be a 1-d sequence (β_1, ..., β_n) with n >= 1; got shape {b.shape}"
        )
    if not np.all(np.isfinite(b)):
        raise ValueError("betas must be finite")
    check_chain_rule_order(b.size, "the number of betas")
    if b[0] <= 0:
        raise ValueError(
            f"beta1 must be > 0 (orientation-preserving change of variables); got {b[0]}"
        )
    return b


def _as_derivs(value, name: str, n: int | None = None) -> np.ndarray:
    d = as_real_array(value, name, "an array of derivative vectors")
    if d.ndim != 2 or d.shape[1] not in (2, 3) or d.shape[0] == 0:
        raise ValueError(
            f"{name} must have shape (n, dim), row k-1 the k-th derivative, dim 2 or 3; "
            f"got shape {d.shape}"
        )
    check_chain_rule_order(d.shape[0], f"the number of derivatives in {name}")
    if n is not None and d.shape[0] < n:
        raise ValueError(f"{name} must hold at least {n} derivatives; got {d.shape[0]}")
    if not np.all(np.isfinite(d)):
        raise ValueError(f"{name} must contain only finite values")
    return d


def apply_beta_constraints(q_derivs: np.ndarray, betas: np.ndarray | list[float]) -> np.ndarray:
    """Right-hand sides of the Beta-constraints: the ``r^{(i)}(0)`` they prescribe.

    Parameters
    ----------
    q_derivs : array_like of shape (n, dim)
        ``q^{(1)}(1), ..., q^{(n)}(1)`` (row ``k - 1`` is the k-th derivative).
    betas : array_like of shape (n,)
        ``β_1 > 0, β_2, ..., β_n``.

    Returns
    -------
    ndarray of shape (n, dim)
        ``r^{(i)}(0) = sum_k B_{i,k}(β) q^{(k)}(1)`` (seed 000 eq. (6), (7.1)-(7.4)).
    """
    own_work.require("course_lib.geometry.beta_constraints.apply_beta_constraints")
    b = _as_betas(betas)
    Q = _as_derivs(q_derivs, "q_derivs", b.size)[: b.size]
    return beta_coefficients(b) @ Q


@dataclass(frozen=True)
class ShapeParameterFit:
    """Result of :func:`solve_shape_parameters`.

    Attributes
    ----------
    betas : ndarray of shape (n,)
        ``β_1 .. β_n`` (``β_1`` may come out <= 0: then no orientation-preserving
        reparametrization exists and the joint is not even G1).
    residuals : ndarray of shape (n, dim)
        ``r^{(i)}(0) - sum_k B_{i,k}(β) q^{(k)}(1)``: what the best ``β_i`` cannot explain.
    residual_norms : ndarray of shape (n,)
    """

    betas: np.ndarray
    residuals: np.ndarray
    residual_norms: np.ndarray


def solve_shape_parameters(q_derivs: np.ndarray, r_derivs: np.ndarray) -> ShapeParameterFit:
    """Find ``β_1 .. β_n`` from the derivatives on both sides of a joint.

    Order by order: in constraint ``i`` only ``β_i`` is new and it multiplies
    ``q^{(1)}(1)`` (``B_{i,1} = β_i``), so ``β_i`` is the least-squares coefficient
    of the remainder ``r^{(i)}(0) - sum_{k>=2} B_{i,k} q^{(k)}(1)`` along ``q^{(1)}(1)``;
    the part perpendicular to ``q^{(1)}(1)`` is the residual.  The joint is
    ``G^n`` iff ``β_1 > 0`` and the residuals of orders ``1..n`` vanish.

    Parameters
    ----------
    q_derivs : array_like of shape (n, dim)
        ``q^{(1)}(1) .. q^{(n)}(1)``.
    r_derivs : array_like of shape (n, dim)
        ``r^{(1)}(0) .. r^{(n)}(0)``.

    Raises
    ------
    ValueError
        If ``q^{(1)}(1) = 0`` (``q`` not regular at the joint) or the shapes differ.
    """
    own_work.require("course_lib.geometry.beta_constraints.solve_shape_parameters")
    R = _as_derivs(r_derivs, "r_derivs")
    n = R.shape[0]
    Q = _as_derivs(q_derivs, "q_derivs", n)[:n]
    if Q.shape[1] != R.shape[1]:
        raise ValueError(
            f"q_derivs and r_derivs must have the same dimension; got {Q.shape[1]} and {R.shape[1]}"
        )
    q1 = Q[0]
    qq = float(q1 @ q1)
    if qq == 0.0:
        raise ValueError("q_derivs[0] = q'(1) must be nonzero: q is not regular at the joint")
    betas = np.zeros(n)
    residuals = np.zeros_like(R)
    B = np.zeros((n + 1, n + 1))  # Bell table of the β's, row by row (β_i enters only B_{i,1})
    B[0, 0] = 1.0
    for i in range(1, n + 1):
        bell_row(B, betas, i)
        rem = R[i - 1] - B[i, 2 : i + 1] @ Q[1:i]
        betas[i - 1] = float(rem @ q1) / qq
        B[i, 1] = betas[i - 1]
        residuals[i - 1] = rem - betas[i - 1] * q1
    return ShapeParameterFit(betas, residuals, np.linalg.norm(residuals, axis=-1))
