"""The tools of lecture 01, *Parametrizations, joints and parametric continuity*
(``notebooks/01_parametric_continuity.ipynb``).

The lecture opens with ``from course_lib.lessons.l01 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib import PiecewiseBezier
from course_lib.geometry.differential_geometry import (
    speed,
    unit_tangent,
)
from course_lib.homework.checks.lectures import check_number, check_vector, quiz
from course_lib.plotting.lecture_figures import (
    deformation_figure,
    example1_figure,
    joint_figure,
)

__all__ = [
    "PiecewiseBezier",
    "check_number",
    "check_vector",
    "deformation_figure",
    "example1_figure",
    "joint_figure",
    "quiz",
    "speed",
    "unit_tangent",
]
