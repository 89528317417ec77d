"""The tools of lecture 02, *Beta-constraints* (``notebooks/02_beta_constraints.ipynb``).

The lecture opens with ``from course_lib.lessons.l02 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.constructions.stitching import g2_stitch
from course_lib.geometry.beta_constraints import beta_constraints, solve_shape_parameters
from course_lib.geometry.continuity import curve_continuity
from course_lib.geometry.differential_geometry import arc_length_derivatives
from course_lib.geometry.joint_reparametrization import onto_change_of_variables
from course_lib.geometry.reparametrization import ChangeOfVariables
from course_lib.homework.checks.lectures import check_number, check_vector, quiz
from course_lib.plotting import new_figure, plot_curvature_comb, plot_curvature_profile, plot_curve
from course_lib.plotting.lecture_figures import combs_figure, names_figure
from course_lib.sources.seed_formulas import inverse_betas
from course_lib.widgets import g2_stitch_demo

__all__ = [
    "ChangeOfVariables",
    "PiecewiseBezier",
    "arc_length_derivatives",
    "beta_constraints",
    "check_number",
    "check_vector",
    "combs_figure",
    "curve_continuity",
    "g2_stitch",
    "g2_stitch_demo",
    "inverse_betas",
    "names_figure",
    "new_figure",
    "onto_change_of_variables",
    "plot_curvature_comb",
    "plot_curvature_profile",
    "plot_curve",
    "quiz",
    "solve_shape_parameters",
]
