"""The tools of lecture 08, *Beta-splines* (``notebooks/08_beta_splines.ipynb``).

The lecture opens with ``from course_lib.lessons.l08 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.constructions.beta_splines import (
    cubic_beta_spline,
    design_beta_spline,
    quadratic_beta_spline,
)
from course_lib.geometry.continuity import curve_continuity
from course_lib.homework.checks.lectures import check_number
from course_lib.plotting import new_figure, plot_control_polygon, plot_curvature_profile, plot_curve
from course_lib.plotting.constructions import plot_beta_spline_construction
from course_lib.plotting.lecture_figures import (
    cubic_beta_spline_figure,
    curvature_profiles_figure,
    quadratic_beta_spline_figure,
)
from course_lib.sources.seed_formulas import (
    blending_basis,
    blending_system,
    cubic_beta_spline_printed,
    cubic_beta_spline_reciprocal,
    gamma_printed,
)
from course_lib.widgets import beta_spline_demo

__all__ = [
    "PiecewiseBezier",
    "beta_spline_demo",
    "blending_basis",
    "blending_system",
    "check_number",
    "cubic_beta_spline",
    "cubic_beta_spline_figure",
    "cubic_beta_spline_printed",
    "cubic_beta_spline_reciprocal",
    "curvature_profiles_figure",
    "curve_continuity",
    "design_beta_spline",
    "gamma_printed",
    "new_figure",
    "plot_beta_spline_construction",
    "plot_control_polygon",
    "plot_curvature_profile",
    "plot_curve",
    "quadratic_beta_spline",
    "quadratic_beta_spline_figure",
]
