"""The tools of lecture 06, *G1 Bézier splines with knots* (``notebooks/06_g1_knot_bezier_splines.ipynb``).

The lecture opens with ``from course_lib.lessons.l06 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.constructions.knot_splines import g1_knot_spline
from course_lib.geometry.continuity import curve_continuity
from course_lib.homework.checks.lectures import check_number, quiz
from course_lib.plotting import new_figure, plot_control_polygon, plot_curve
from course_lib.plotting.constructions import (
    plot_knot_joint_construction,
)
from course_lib.plotting.lecture_figures import (
    g1_joint_figure,
    knot_joint_figure,
    splines_figure,
)
from course_lib.sources.seed_formulas import (
    barycentric_weights,
)
from course_lib.widgets import knot_spline_demo

__all__ = [
    "PiecewiseBezier",
    "barycentric_weights",
    "check_number",
    "curve_continuity",
    "g1_joint_figure",
    "g1_knot_spline",
    "knot_joint_figure",
    "knot_spline_demo",
    "new_figure",
    "plot_control_polygon",
    "plot_curve",
    "plot_knot_joint_construction",
    "quiz",
    "splines_figure",
]
