"""The tools of lecture 11, *Are letters smooth?* (``notebooks/11_are_letters_smooth.ipynb``).

The lecture opens with ``from course_lib.lessons.l11 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib.constructions.beta_splines import cubic_beta_spline, quadratic_beta_spline
from course_lib.constructions.outlines import (
    Contour,
    Outline,
    classify_joints,
    font_summary,
    glyph_outline,
    glyph_summary,
    svg_outline,
)
from course_lib.geometry.continuity import curve_continuity, joint_continuity
from course_lib.homework.checks.lectures import check_number, quiz
from course_lib.plotting import new_figure, plot_outline
from course_lib.plotting.lecture_figures import glyph_points_figure, glyphs_figure, outlines_figure
from course_lib.widgets import glyph_demo

__all__ = [
    "Contour",
    "Outline",
    "check_number",
    "classify_joints",
    "cubic_beta_spline",
    "curve_continuity",
    "font_summary",
    "glyph_demo",
    "glyph_outline",
    "glyph_points_figure",
    "glyph_summary",
    "glyphs_figure",
    "joint_continuity",
    "new_figure",
    "outlines_figure",
    "plot_outline",
    "quadratic_beta_spline",
    "quiz",
    "svg_outline",
]
