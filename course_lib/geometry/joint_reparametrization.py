"""A change of variables *onto* a whole piece with prescribed derivatives at the joint.

The Beta-constraints need a change of variables ``u(ū)`` with ``u(1) = 1`` and
``u^{(j)}(1) = β_j`` (seed 000 §5).  Its Taylor polynomial has these derivatives but is
increasing only near ``ū = 1`` and does not map any interval onto ``[0, 1]`` in general,
while Definition 1 reparametrizes the *whole* piece ``q(u)``, ``u ∈ [0, 1]``.  The step
that closes the gap: blend the Taylor polynomial into the straight line
``1 + β1 (ū - 1)`` with a smoothstep, over a width ``h`` small enough that ``u' > 0``::

    u(ū) = 1 + β1 (ū - 1) + φ((ū - 1 + h) / h) · R(ū),   R = Taylor rest of order ≥ 2,

where ``φ`` is the smoothstep of order ``n`` (``φ = 0`` left of ``1 - h``, ``φ = 1`` at
``1`` with its first ``n`` derivatives zero at both ends).  Then ``u`` is ``C^n``, has the
prescribed derivatives at 1, is the line for ``ū <= 1 - h`` and maps
``[1 - 1/β1, 1]`` onto ``[0, 1]``.

Lecture: ``notebooks/03_beta_constraints.ipynb`` §5.
"""

from __future__ import annotations

from collections.abc import Sequence
from math import comb, factorial

import numpy as np

from course_lib.geometry.reparametrization import ChangeOfVariables

__all__ = ["onto_change_of_variables", "smoothstep"]


def smoothstep(n: int) -> np.polynomial.Polynomial:
    """The polynomial ``S_n`` of degree ``2n + 1``: ``S(0) = 0``, ``S(1) = 1``, derivatives
    ``1..n`` zero at 0 and 1 (``S_1 = 3s² - 2s³``).

    Examples
    --------
    >>> print(smoothstep(1))
    0.0 + 0.0·x + 3.0·x² - 2.0·x³
    """
    coef = np.zeros(2 * n + 2)
    for k in range(n + 1):
        coef[n + 1 + k] = (-1) ** k * comb(n + k, k) * comb(2 * n + 1, n - k)
    return np.polynomial.Polynomial(coef)


def onto_change_of_variables(
    betas: Sequence[float], width: float | None = None
) -> ChangeOfVariables:
    """``u: [1 - 1/β1, 1] -> [0, 1]``, increasing, ``C^n``, with ``u^{(j)}(1) = β_j``.

    ``width`` is ``h`` of the module docstring; by default the largest of
    ``1/β1, 1/(2β1), ...`` for which ``u' > β1 / 2`` at 1025 samples.

    Raises
    ------
    ValueError
        If β1 <= 0, the betas are not finite, or the given width is not in ``(0, 1/β1]``
        or leaves ``u'`` non-positive somewhere.
    """
    b = np.asarray(betas, dtype=float)
    if b.ndim != 1 or b.size == 0 or not np.all(np.isfinite(b)):
        raise ValueError("betas must be a finite 1-d sequence (β1, ..., βn)")
    if b[0] <= 0:
        raise ValueError(f"beta1 must be > 0; got {b[0]}")
    n = b.size
    rest = np.polynomial.Polynomial(
        np.concatenate([[0.0, 0.0], b[1:] / [factorial(j) for j in range(2, n + 1)]])
    )  # in x = ū - 1
    step = smoothstep(max(n, 1))
    a = 1 - 1 / b[0]

    def make(h: float):
        def deriv(x, k):
            x = np.asarray(x, dtype=float)
            line = [1 + b[0] * (x - 1), np.full_like(x, b[0])][k] if k < 2 else 0 * x
            s = (x - 1 + h) / h
            inside = s > 0
            blend = np.zeros_like(x)
            for j in range(k + 1):  # Leibniz: (φ R)^{(k)}
                phi = step.deriv(j)(s) / h**j if j else step(s)
                blend += comb(k, j) * phi * rest.deriv(k - j)(x - 1)
            return line + np.where(inside, blend, 0.0)

        return deriv

    if width is not None:
        h = float(width)
        if not 0 < h <= 1 / b[0]:
            raise ValueError(f"width must be in (0, 1/beta1] = (0, {1 / b[0]:.6g}]; got {width}")
        return ChangeOfVariables(make(h), (a, 1.0), (0.0, 1.0), name="u")
    h = 1 / b[0]
    xs = np.linspace(a, 1.0, 1025)
    while make(h)(xs, 1).min() <= b[0] / 2:
        h /= 2
    return ChangeOfVariables(make(h), (a, 1.0), (0.0, 1.0), name="u")
