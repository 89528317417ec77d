"""The tools of lecture 09, *Higher order* (``notebooks/09_higher_order.ipynb``).

The lecture opens with ``from course_lib.lessons.l09 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from ..beta_constraints import beta_coefficients
from ..beta_splines import cubic_beta_spline
from ..checks.lectures import check_number, quiz
from ..continuity import curve_continuity
from ..higher_order import beta_spline, gn_beta_spline_basis, quartic_beta_spline
from ..plotting import new_figure, plot_control_polygon, plot_curve
from ..plotting.lecture_figures import quartic_conventions_figure
from ..seed_formulas import blending_basis, blending_system, inverse_betas
from ..widgets import quartic_beta_spline_demo

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
