"""The tools of lecture 05, *Curvature of plane curves* (``notebooks/05_curvature_of_plane_curves.ipynb``).

The lecture opens with ``from course_lib.lessons.l05 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from scipy.spatial.distance import pdist

from course_lib import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry import differential_geometry as dg
from course_lib.geometry.closeness import closeness, rippled_circle
from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized
from course_lib.homework.checks.lectures import check_number, quiz
from course_lib.plotting import (
    new_figure,
    plot_curve,
    plot_frame,
    plot_osculating_circle,
)
from course_lib.plotting.closeness_figure import plot_closeness
from course_lib.plotting.lecture_figures import (
    closeness_figure,
    frame_figure,
    rebuilt_figure,
)
from course_lib.widgets import curvature_comb_demo

__all__ = [
    "ChangeOfVariables",
    "ParametricCurve",
    "PiecewiseBezier",
    "Reparametrized",
    "check_number",
    "closeness",
    "closeness_figure",
    "curvature_comb_demo",
    "dg",
    "frame_figure",
    "new_figure",
    "pdist",
    "plot_closeness",
    "plot_curve",
    "plot_frame",
    "plot_osculating_circle",
    "quiz",
    "rebuilt_figure",
    "rippled_circle",
]
