"""The tools of lecture 05, *Higher order and surfaces* (``notebooks/05_higher_order_and_surfaces.ipynb``).

The lecture opens with ``from course_lib.lessons.l05 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from ..beta_constraints import beta_coefficients
from ..beta_splines import cubic_beta_spline
from ..checks.lectures import check_number, quiz
from ..continuity import curve_continuity
from ..higher_order import beta_spline, gn_beta_spline_basis, quartic_beta_spline
from ..plotting import new_figure, plot_control_polygon, plot_curve
from ..plotting.lecture_figures import (
    domain_and_patch_figure,
    parameter_lines_figure,
    patch_pairs_figure,
    quartic_conventions_figure,
)
from ..plotting.surface_figures import plot_domain_and_patch, plot_parameter_lines
from ..plotting.surfaces3d import plot_patch_pair
from ..seed_formulas import blending_basis, blending_system, inverse_betas
from ..surfaces import BezierPatch, g1_neighbour_patch, tangent_plane_continuity
from ..widgets import quartic_beta_spline_demo

__all__ = [
    "BezierPatch",
    "beta_coefficients",
    "beta_spline",
    "blending_basis",
    "blending_system",
    "check_number",
    "cubic_beta_spline",
    "curve_continuity",
    "domain_and_patch_figure",
    "g1_neighbour_patch",
    "gn_beta_spline_basis",
    "inverse_betas",
    "new_figure",
    "parameter_lines_figure",
    "patch_pairs_figure",
    "plot_control_polygon",
    "plot_curve",
    "plot_domain_and_patch",
    "plot_parameter_lines",
    "plot_patch_pair",
    "quartic_beta_spline",
    "quartic_beta_spline_demo",
    "quartic_conventions_figure",
    "quiz",
    "tangent_plane_continuity",
]
