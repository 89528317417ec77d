"""The tools of lecture 02, *Beta-constraints* (``notebooks/02_beta_constraints.ipynb``).

The lecture opens with ``from course_lib.lessons.l02 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from .. import PiecewiseBezier
from ..beta_constraints import beta_constraints, solve_shape_parameters
from ..checks.lectures import check_number, check_vector, quiz
from ..continuity import curve_continuity
from ..differential_geometry import arc_length_derivatives
from ..joint_reparametrization import onto_change_of_variables
from ..plotting import new_figure, plot_curvature_comb, plot_curvature_profile, plot_curve
from ..plotting.lecture_figures import combs_figure, names_figure
from ..reparametrization import ChangeOfVariables
from ..seed_formulas import inverse_betas
from ..stitching import g2_stitch
from ..widgets import g2_stitch_demo

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
