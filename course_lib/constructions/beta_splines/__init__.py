"""Beta-splines of every degree, built in Bézier form.

* :mod:`~course_lib.constructions.beta_splines.quadratic_cubic` -- the quadratic G1 and cubic
  G2 Beta-splines of Barsky's construction, with shape parameters per joint, their basis
  functions and the design by interior vertices (seed 000 §10);
* :mod:`~course_lib.constructions.beta_splines.degree_n` -- the G^n Beta-splines of degree
  ``n + 1`` with global shape parameters, the quartic G3 among them (seed 001 Example 2.1).

For ``n = 1, 2`` the two coincide (a cross-check in the tests).
"""

from __future__ import annotations

from course_lib.constructions.beta_splines.degree_n import (
    BetaSplineBasis,
    beta_spline,
    gn_beta_spline_basis,
    quartic_beta_spline,
)
from course_lib.constructions.beta_splines.quadratic_cubic import (
    cubic_beta_spline,
    cubic_beta_spline_basis,
    design_beta_spline,
    quadratic_beta_spline,
    quadratic_beta_spline_basis,
)

__all__ = [
    "BetaSplineBasis",
    "beta_spline",
    "cubic_beta_spline",
    "cubic_beta_spline_basis",
    "design_beta_spline",
    "gn_beta_spline_basis",
    "quadratic_beta_spline",
    "quadratic_beta_spline_basis",
    "quartic_beta_spline",
]
