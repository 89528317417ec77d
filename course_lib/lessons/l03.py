"""The tools of lecture 03, *Beta-constraints* (``notebooks/03_beta_constraints.ipynb``).

The lecture opens with ``from course_lib.lessons.l03 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.geometry.beta_constraints import beta_constraints, solve_shape_parameters
from course_lib.geometry.joint_reparametrization import onto_change_of_variables
from course_lib.geometry.reparametrization import ChangeOfVariables
from course_lib.homework.checks.lectures import check_number, check_vector, quiz
from course_lib.plotting import new_figure, plot_curve
from course_lib.plotting.lecture_figures import (
    names_figure,
)
from course_lib.sources.seed_formulas import inverse_betas

__all__ = [
    "ChangeOfVariables",
    "PiecewiseBezier",
    "beta_constraints",
    "check_number",
    "check_vector",
    "inverse_betas",
    "names_figure",
    "new_figure",
    "onto_change_of_variables",
    "plot_curve",
    "quiz",
    "solve_shape_parameters",
]
