"""How close are two curves?  Three measures (seed 004 §19.3, "closeness of approximations").

Two parametrizations ``a`` and ``b`` are compared at the same parameter values ``t``:
the largest distance between corresponding points, the largest angle between their unit
tangents, and the largest difference of their signed curvatures.  Close in curvature
forces close in tangent and distance (for curves that start together, by integrating
``κ`` twice); the converse fails.

Lecture: ``notebooks/05_curvature_of_plane_curves.ipynb`` §4.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course_lib.geometry import differential_geometry as dg

__all__ = ["Closeness", "closeness", "rippled_circle"]


@dataclass(frozen=True)
class Closeness:
    """``distance`` (max |a - b|), ``angle`` (max angle between unit tangents, degrees),
    ``curvature_gap`` (max |κ_a - κ_b|)."""

    distance: float
    angle: float
    curvature_gap: float

    def __str__(self) -> str:
        return (
            f"distance ≤ {self.distance:.3f}, tangent angle ≤ {self.angle:.1f}°, "
            f"curvature gap ≤ {self.curvature_gap:.2f}"
        )


def closeness(a, b, t: np.ndarray) -> Closeness:
    """The three closeness measures of two plane parametrizations at the parameters ``t``.

    Raises
    ------
    ValueError
        If ``t`` is empty or leaves a domain (from the evaluation).

    Examples
    --------
    A circle with small, fast ripples is close in distance, less so in curvature:

    >>> import numpy as np
    >>> t = np.linspace(0, np.pi, 201)
    >>> print(closeness(rippled_circle(0.0, 5), rippled_circle(0.01, 5), t))
    distance ≤ 0.010, tangent angle ≤ 2.9°, curvature gap ≤ 0.24
    """
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.size == 0:
        raise ValueError("t must contain at least one parameter value")
    gap = np.linalg.norm(a.evaluate(t) - b.evaluate(t), axis=1)
    cos = np.sum(dg.unit_tangent(a, t) * dg.unit_tangent(b, t), axis=1)
    angle = np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))
    dk = np.abs(dg.signed_curvature(a, t) - dg.signed_curvature(b, t))
    return Closeness(float(gap.max()), float(angle.max()), float(dk.max()))


def rippled_circle(eps: float, k: int, domain: tuple[float, float] = (0.0, np.pi)):
    """The unit circle with radial ripples: ``r(t) = 1 + eps sin(k t)``, ``t`` in ``domain``.

    A :class:`~course_lib.curves.parametrization.ParametricCurve` (``eps = 0``: the unit circle).
    Close to the circle in distance (``|eps|``); in tangent only if ``eps k`` is small; in
    curvature only if ``eps k²`` is small.
    """
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve

    t = sp.Symbol("t")
    r = 1 + sp.nsimplify(eps) * sp.sin(int(k) * t)
    return ParametricCurve.from_sympy([r * sp.cos(t), r * sp.sin(t)], t, domain)
