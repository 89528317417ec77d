"""The tools of lecture 07, *Stitching Bézier curves* (``notebooks/07_stitching_bezier_curves.ipynb``).

The lecture opens with ``from course_lib.lessons.l07 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.constructions.catmull_rom import catmull_rom
from course_lib.constructions.stitching import farin_boehm, g1_stitch, g2_stitch
from course_lib.curves import bezier
from course_lib.geometry.continuity import curve_continuity
from course_lib.homework.checks.lectures import check_number, quiz
from course_lib.plotting import new_figure, plot_control_polygon, plot_curve
from course_lib.plotting.constructions import plot_farin_boehm, plot_stitching
from course_lib.plotting.lecture_figures import (
    bezier_figure,
    catmull_rom_figure,
    degree_raising_figure,
    farin_boehm_figure,
    g1_stitching_figure,
)
from course_lib.widgets import catmull_rom_demo, g2_stitch_demo

__all__ = [
    "PiecewiseBezier",
    "bezier",
    "bezier_figure",
    "catmull_rom",
    "catmull_rom_demo",
    "catmull_rom_figure",
    "check_number",
    "curve_continuity",
    "degree_raising_figure",
    "farin_boehm",
    "farin_boehm_figure",
    "g1_stitch",
    "g1_stitching_figure",
    "g2_stitch",
    "g2_stitch_demo",
    "new_figure",
    "plot_control_polygon",
    "plot_curve",
    "plot_farin_boehm",
    "plot_stitching",
    "quiz",
]
