"""The tools of lecture 05, *Beta-splines* (``notebooks/05_beta_splines.ipynb``).

The lecture opens with ``from course_lib.lessons.l05 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from .. import PiecewiseBezier, bezier
from ..beta_splines import cubic_beta_spline, design_beta_spline, quadratic_beta_spline
from ..catmull_rom import catmull_rom
from ..checks.lectures import check_number, quiz
from ..continuity import curve_continuity
from ..plotting import new_figure, plot_control_polygon, plot_curvature_profile, plot_curve
from ..plotting.constructions import plot_beta_spline_construction, plot_farin_boehm, plot_stitching
from ..plotting.lecture_figures import (
    bezier_figure,
    catmull_rom_figure,
    cubic_beta_spline_figure,
    curvature_profiles_figure,
    degree_raising_figure,
    farin_boehm_figure,
    g1_stitching_figure,
    quadratic_beta_spline_figure,
)
from ..seed_formulas import (
    blending_basis,
    blending_system,
    cubic_beta_spline_printed,
    cubic_beta_spline_reciprocal,
    gamma_printed,
)
from ..stitching import farin_boehm, g1_stitch, g2_stitch
from ..widgets import beta_spline_demo, catmull_rom_demo, g2_stitch_demo

__all__ = [
    "PiecewiseBezier",
    "beta_spline_demo",
    "bezier",
    "bezier_figure",
    "blending_basis",
    "blending_system",
    "catmull_rom",
    "catmull_rom_demo",
    "catmull_rom_figure",
    "check_number",
    "cubic_beta_spline",
    "cubic_beta_spline_figure",
    "cubic_beta_spline_printed",
    "cubic_beta_spline_reciprocal",
    "curvature_profiles_figure",
    "curve_continuity",
    "degree_raising_figure",
    "design_beta_spline",
    "farin_boehm",
    "farin_boehm_figure",
    "g1_stitch",
    "g1_stitching_figure",
    "g2_stitch",
    "g2_stitch_demo",
    "gamma_printed",
    "new_figure",
    "plot_beta_spline_construction",
    "plot_control_polygon",
    "plot_curvature_profile",
    "plot_curve",
    "plot_farin_boehm",
    "plot_stitching",
    "quadratic_beta_spline",
    "quadratic_beta_spline_figure",
    "quiz",
]
