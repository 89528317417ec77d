"""The tools of lecture 02, *Reparametrization and geometric continuity*
(``notebooks/02_reparametrization.ipynb``).

The lecture opens with ``from course_lib.lessons.l02 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from .. import PiecewiseBezier
from ..checks.lectures import check_number, check_vector, quiz
from ..continuity import joint_continuity
from ..differential_geometry import curvature, signed_curvature, speed, unit_tangent
from ..joint_reparametrization import onto_change_of_variables
from ..parametrization import ParametricCurve
from ..plotting import new_figure, plot_curve, plot_frame, plot_vectors, plot_velocity
from ..plotting.lecture_figures import models_figure, reparametrization_figure
from ..plotting.reparametrization_figure import plot_reparametrization
from ..plotting.style import ROLE_COLORS
from ..reparametrization import ChangeOfVariables, Reparametrized, are_equivalent
from ..widgets import reparametrization_demo

__all__ = [
    "ROLE_COLORS",
    "ChangeOfVariables",
    "ParametricCurve",
    "PiecewiseBezier",
    "Reparametrized",
    "are_equivalent",
    "check_number",
    "check_vector",
    "curvature",
    "joint_continuity",
    "models_figure",
    "new_figure",
    "onto_change_of_variables",
    "plot_curve",
    "plot_frame",
    "plot_reparametrization",
    "plot_vectors",
    "plot_velocity",
    "quiz",
    "reparametrization_demo",
    "reparametrization_figure",
    "signed_curvature",
    "speed",
    "unit_tangent",
]
