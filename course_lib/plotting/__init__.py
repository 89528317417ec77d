"""Pictures of the course: every function takes an Axes and returns its artists.

Importing this package imports matplotlib (``import course_lib`` does not).  Nothing
changes matplotlib's global settings at import time; the course style is applied by
:func:`course_style` (a context manager) or :func:`new_figure`.

Modules: :mod:`.style` (palette, rcParams, ``new_figure``), :mod:`.curves` (curves and
control polygons), :mod:`.vectors` (arrows, velocities, tangent, normal, curvature
vector, osculating circle), :mod:`.curvature` (curvature comb, curvature against arc length),
:mod:`.constructions` (stitching, Farin-Boehm, Beta-spline and knot-spline
construction diagrams), :mod:`.blending` (blending functions), :mod:`.surfaces3d`
(Bézier patches and their normals).
"""

from __future__ import annotations

from course_lib.plotting.blending import (
    BlendingArtists,
    blending_functions,
    plot_blending_functions,
)
from course_lib.plotting.constructions import (
    Diagram,
    plot_beta_spline_construction,
    plot_farin_boehm,
    plot_g1_stitch,
    plot_knot_joint_construction,
    plot_stitching,
)
from course_lib.plotting.curvature import (
    CombArtists,
    CurvatureProfileArtists,
    curvature_profile,
    plot_curvature_comb,
    plot_curvature_profile,
)
from course_lib.plotting.curves import CurveArtists, PointsArtists, plot_control_polygon, plot_curve
from course_lib.plotting.outlines import OutlineArtists, plot_outline
from course_lib.plotting.style import (
    COURSE_RC,
    OKABE_ITO,
    ROLE_COLORS,
    course_style,
    new_figure,
    segment_color,
)
from course_lib.plotting.surfaces3d import PatchPairArtists, plot_patch, plot_patch_pair
from course_lib.plotting.vectors import (
    FrameArtists,
    OsculatingCircleArtists,
    VectorArtists,
    plot_frame,
    plot_osculating_circle,
    plot_vectors,
    plot_velocity,
)

__all__ = [
    "COURSE_RC",
    "OKABE_ITO",
    "ROLE_COLORS",
    "BlendingArtists",
    "CombArtists",
    "CurvatureProfileArtists",
    "CurveArtists",
    "Diagram",
    "FrameArtists",
    "OsculatingCircleArtists",
    "OutlineArtists",
    "PatchPairArtists",
    "PointsArtists",
    "VectorArtists",
    "blending_functions",
    "course_style",
    "curvature_profile",
    "new_figure",
    "plot_beta_spline_construction",
    "plot_blending_functions",
    "plot_control_polygon",
    "plot_curvature_comb",
    "plot_curvature_profile",
    "plot_curve",
    "plot_farin_boehm",
    "plot_frame",
    "plot_g1_stitch",
    "plot_knot_joint_construction",
    "plot_osculating_circle",
    "plot_outline",
    "plot_patch",
    "plot_patch_pair",
    "plot_stitching",
    "plot_vectors",
    "plot_velocity",
    "segment_color",
]
