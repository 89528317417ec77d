"""The tools of lecture 03, *Curvature and G1 knot splines* (``notebooks/03_g1_knot_bezier_splines.ipynb``).

The lecture opens with ``from course_lib.lessons.l03 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from scipy.spatial.distance import pdist

from .. import PiecewiseBezier
from .. import differential_geometry as dg
from ..checks.lectures import check_number, quiz
from ..closeness import closeness, rippled_circle
from ..continuity import curve_continuity
from ..knot_splines import g1_knot_spline
from ..parametrization import ParametricCurve
from ..plotting import (
    new_figure,
    plot_control_polygon,
    plot_curve,
    plot_frame,
    plot_osculating_circle,
)
from ..plotting.closeness_figure import plot_closeness
from ..plotting.constructions import plot_knot_joint_construction
from ..plotting.lecture_figures import (
    closeness_figure,
    frame_figure,
    g1_joint_figure,
    knot_joint_figure,
    rebuilt_figure,
    splines_figure,
)
from ..reparametrization import ChangeOfVariables, Reparametrized
from ..seed_formulas import barycentric_weights
from ..widgets import knot_spline_demo

__all__ = [
    "ChangeOfVariables",
    "ParametricCurve",
    "PiecewiseBezier",
    "Reparametrized",
    "barycentric_weights",
    "check_number",
    "closeness",
    "closeness_figure",
    "curve_continuity",
    "dg",
    "frame_figure",
    "g1_joint_figure",
    "g1_knot_spline",
    "knot_joint_figure",
    "knot_spline_demo",
    "new_figure",
    "pdist",
    "plot_closeness",
    "plot_control_polygon",
    "plot_curve",
    "plot_frame",
    "plot_knot_joint_construction",
    "plot_osculating_circle",
    "quiz",
    "rebuilt_figure",
    "rippled_circle",
    "splines_figure",
]
