"""The tools of lecture 02, *Reparametrization and geometric continuity*
(``notebooks/02_reparametrization.ipynb``).

The lecture opens with ``from course_lib.lessons.l02 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry.continuity import joint_continuity
from course_lib.geometry.differential_geometry import (
    curvature,
    signed_curvature,
    speed,
    unit_tangent,
)
from course_lib.geometry.joint_reparametrization import onto_change_of_variables
from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized, are_equivalent
from course_lib.homework.checks.lectures import check_number, check_vector, quiz
from course_lib.plotting import (
    new_figure,
    plot_curve,
    plot_frame,
    plot_vectors,
    plot_velocity,
)
from course_lib.plotting.lecture_figures import (
    models_figure,
    reparametrization_figure,
)
from course_lib.plotting.reparametrization_figure import plot_reparametrization
from course_lib.plotting.style import ROLE_COLORS
from course_lib.widgets import reparametrization_demo

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
