"""The tools of lecture 04, *Arc length and Theorem 1*
(``notebooks/04_arc_length_and_theorem_1.ipynb``).

The lecture opens with ``from course_lib.lessons.l04 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.constructions.stitching import g2_stitch
from course_lib.geometry.continuity import curve_continuity
from course_lib.geometry.differential_geometry import arc_length_derivatives
from course_lib.homework.checks.lectures import check_number, check_vector, quiz
from course_lib.plotting import (
    new_figure,
    plot_curvature_comb,
    plot_curvature_profile,
    plot_curve,
)
from course_lib.plotting.lecture_figures import (
    combs_figure,
)
from course_lib.widgets import g2_stitch_demo

__all__ = [
    "PiecewiseBezier",
    "arc_length_derivatives",
    "check_number",
    "check_vector",
    "combs_figure",
    "curve_continuity",
    "g2_stitch",
    "g2_stitch_demo",
    "new_figure",
    "plot_curvature_comb",
    "plot_curvature_profile",
    "plot_curve",
    "quiz",
]
