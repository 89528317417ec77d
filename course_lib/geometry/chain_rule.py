"""Partial Bell polynomials, the bookkeeping of the chain rule (Faà di Bruno's formula).

For ``h = g o f``::

    h^{(i)} = sum_{k=1}^{i} g^{(k)}(f) * B_{i,k}(f', f'', ..., f^{(i-k+1)})

where ``B_{i,k}`` are the partial (exponential) Bell polynomials, computed here by
the recurrence ``B_{0,0} = 1`` and

    B_{i,k} = sum_{j=1}^{i-k+1} binom(i-1, j-1) x_j B_{i-j,k-1}.

Pure numpy/python, vectorized over any trailing shape of the ``x_j``.  Used by
:mod:`course_lib.geometry.reparametrization` (derivatives of ``q o f``),
:mod:`course_lib.geometry.beta_constraints` (numeric Beta-constraints, seed 000 eq. (6))
and :mod:`course_lib.geometry.differential_geometry` (derivatives with respect to arc length).
"""

from __future__ import annotations

from functools import lru_cache
from math import comb

import numpy as np

from course_lib.homework import own_work

__all__ = ["MAX_CHAIN_RULE_ORDER", "bell_table", "check_chain_rule_order", "compose_derivatives"]

#: Highest derivative order pushed through the chain rule (Faà di Bruno, arc-length
#: derivatives, Beta-constraints, continuity reports).  The Bell table has O(n^3) entries
#: and the derivatives of the parts grow like n!; above this a ValueError is raised at once
#: (before, n = 40 took seconds and n = 1000 overflowed).
MAX_CHAIN_RULE_ORDER = 24


def check_chain_rule_order(n: int, name: str) -> int:
    """Raise a ValueError naming ``name`` if ``n`` exceeds :data:`MAX_CHAIN_RULE_ORDER`.

    Examples
    --------
    >>> check_chain_rule_order(3, "n")
    3
    """
    if n > MAX_CHAIN_RULE_ORDER:
        raise ValueError(
            f"{name} must be <= {MAX_CHAIN_RULE_ORDER} (MAX_CHAIN_RULE_ORDER, the cap of the "
            f"chain rule's cost, which grows like n^3 and its values like n!); got {n}"
        )
    return n


def bell_table(x: np.ndarray, n: int) -> np.ndarray:
    """Partial Bell polynomials ``B[i, k] = B_{i,k}(x_1, ..., x_{i-k+1})``, ``0 <= k <= i <= n``.

    Computed from the exponential generating function ``sum_i B_{i,k} t^i / i! =
    X(t)^k / k!`` with ``X(t) = sum_j x_j t^j / j!``: ``n`` truncated power-series products,
    each one vectorized over ``i`` and over the trailing shape of ``x`` (equal to the
    recurrence of the module docstring; test: ``tests/unit/test_continuity_fast.py``).

    Parameters
    ----------
    x : ndarray of shape (>= n, ...)
        ``x[j - 1]`` is ``x_j`` (e.g. the j-th derivative of the inner function).
    n : int

    Returns
    -------
    ndarray of shape (n + 1, n + 1, ...)
        Zero where ``k > i``.
    """
    x = np.asarray(x, dtype=float)
    shape = x.shape[1:]
    pad = (1,) * len(shape)
    fact, diff, below = _egf_tables(n)
    a = np.zeros((n + 1, *shape))
    a[1:] = x[:n] / fact[1:].reshape((n, *pad))
    T = a[diff] * below.reshape(below.shape + pad)  # T[i, l] = a_{i-l} (i > l)
    P = np.zeros((n + 1, n + 1, *shape))  # P[k, i] = [t^i] X(t)^k / k!
    P[0, 0] = 1.0
    for k in range(1, n + 1):
        P[k] = np.einsum("il...,l...->i...", T, P[k - 1]) / k
    return np.swapaxes(P, 0, 1) * fact.reshape((n + 1, 1, *pad))


@lru_cache(maxsize=64)
def _egf_tables(n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    from math import factorial

    fact = np.array([float(factorial(i)) for i in range(n + 1)])
    i, l = np.indices((n + 1, n + 1))
    for arr in (fact,):
        arr.setflags(write=False)
    return fact, np.clip(i - l, 0, n), (i > l).astype(float)


def bell_row(B: np.ndarray, x: np.ndarray, i: int) -> None:
    """Fill ``B[i, 2..i]`` in place from ``x_1 .. x_{i-1}`` and the rows ``< i`` (the
    recurrence of the module docstring).  For quantities found order by order, where
    ``x_i`` becomes known only after row ``i``'s other entries: the caller then sets
    ``B[i, 1] = x_i``."""
    for k in range(2, i + 1):
        acc = x[0] * B[i - 1, k - 1]
        for j in range(2, i - k + 2):
            acc = acc + comb(i - 1, j - 1) * x[j - 1] * B[i - j, k - 1]
        B[i, k] = acc


def compose_derivatives(outer: np.ndarray, inner: np.ndarray) -> np.ndarray:
    """Derivatives of orders ``1..n`` of ``g o f`` from those of ``g`` (at ``f``) and ``f``.

    Parameters
    ----------
    outer : ndarray of shape (n, *S, *V)
        ``outer[k - 1] = g^{(k)}(f(t))``; ``V`` is the value shape of ``g`` (e.g. ``(dim,)``).
    inner : ndarray of shape (n, *S)
        ``inner[j - 1] = f^{(j)}(t)`` (scalars).

    Returns
    -------
    ndarray of shape (n, *S, *V)
        Row ``i - 1`` is ``(g o f)^{(i)}(t)``.
    """
    own_work.require("course_lib.geometry.chain_rule.compose_derivatives")
    outer = np.asarray(outer, dtype=float)
    inner = np.asarray(inner, dtype=float)
    n = inner.shape[0]
    B = bell_table(inner, n)
    extra = outer.ndim - inner.ndim
    Bs = B[1:, 1:].reshape(B[1:, 1:].shape + (1,) * extra)
    out = Bs[:, 0] * outer[0]
    for k in range(1, n):
        out = out + Bs[:, k] * outer[k]
    return out
