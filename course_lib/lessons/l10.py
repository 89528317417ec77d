"""The tools of lecture 10, *Geometric continuity of surfaces* (``notebooks/10_surfaces.ipynb``).

The lecture opens with ``from course_lib.lessons.l10 import *``; every name below is
defined and documented in the module it is imported from.
"""

from __future__ import annotations

from course_lib.constructions.surfaces import (
    BezierPatch,
    g1_neighbour_patch,
    tangent_plane_continuity,
)
from course_lib.homework.checks.lectures import check_number
from course_lib.plotting.lecture_figures import (
    domain_and_patch_figure,
    parameter_lines_figure,
    patch_pairs_figure,
)
from course_lib.plotting.surface_figures import plot_domain_and_patch, plot_parameter_lines
from course_lib.plotting.surfaces3d import plot_patch_pair
from course_lib.widgets.patches import tangent_plane_demo

__all__ = [
    "BezierPatch",
    "check_number",
    "domain_and_patch_figure",
    "g1_neighbour_patch",
    "parameter_lines_figure",
    "patch_pairs_figure",
    "plot_domain_and_patch",
    "plot_parameter_lines",
    "plot_patch_pair",
    "tangent_plane_continuity",
    "tangent_plane_demo",
]
