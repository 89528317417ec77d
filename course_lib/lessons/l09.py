"""The tools of lecture 09, *Higher order* (``notebooks/09_higher_order.ipynb``).

The lecture opens with ``from course_lib.lessons.l09 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib.constructions.beta_splines import (
    beta_spline,
    cubic_beta_spline,
    gn_beta_spline_basis,
    quartic_beta_spline,
)
from course_lib.geometry.beta_constraints import beta_coefficients
from course_lib.geometry.continuity import curve_continuity
from course_lib.homework.checks.lectures import check_number, quiz
from course_lib.plotting import new_figure, plot_control_polygon, plot_curve
from course_lib.plotting.lecture_figures import (
    quartic_conventions_figure,
)
from course_lib.sources.seed_formulas import blending_basis, blending_system, inverse_betas
from course_lib.widgets import quartic_beta_spline_demo

__all__ = [
    "beta_coefficients",
    "beta_spline",
    "blending_basis",
    "blending_system",
    "check_number",
    "cubic_beta_spline",
    "curve_continuity",
    "gn_beta_spline_basis",
    "inverse_betas",
    "new_figure",
    "plot_control_polygon",
    "plot_curve",
    "quartic_beta_spline",
    "quartic_beta_spline_demo",
    "quartic_conventions_figure",
    "quiz",
]
