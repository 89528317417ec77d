"""Real outlines as course curves: TrueType glyphs and SVG path data, and their joints.

Everything else in the course was drawn for the course.  This module reads outlines that
nobody here drew -- the letters of the fonts matplotlib ships, and SVG path data such as
matplotlib's toolbar icons -- into the course's one curve type, one
:class:`~course_lib.curves.curve.PiecewiseBezier` per contour, and classifies every joint.

Reading
-------
* :func:`glyph_outline` -- a TrueType glyph (by character or by glyph name) from a font
  file, read with fontTools from the raw ``glyf`` points.  TrueType contours are
  quadratic: between two consecutive off-curve points lies an *implied* on-curve point,
  their midpoint, which is made explicit here.  Units are kept (font units) or
  normalised to the em (``em=True``, default).  One-point contours (anchors that draw
  nothing) are skipped and counted; zero-length segments (repeated points) are dropped.
* :func:`svg_outline` -- SVG path data (``d`` strings: ``M L H V C S Q T A Z``, absolute
  and relative), parsed by a strict scanner of the SVG 1.1 path grammar that names the
  offending token and its position, and read as a browser draws them: subpaths of one
  point and closing lines within rounding of the path's size are dropped (they draw
  nothing), no point is ever infinite.  Elliptical arcs ``A`` are converted to cubics whose
  distance from the true ellipse is at most ``arc_tolerance`` times its larger radius,
  or refused (``arcs="refuse"``).

Analysis
--------
:func:`classify_joints` computes, for every joint of an outline (the closing joint of a
closed contour included, as the last joint of that contour), the gap, the tangent
angle, the signed curvature on both sides and the curvature jump relative to the local
curvature, all vectorized.  Two verdicts:

* ``g_order`` (-1, 0, 1, 2): the strict G-order with the rule and tolerance of
  :func:`~course_lib.geometry.continuity.joint_continuity` (``rtol = 1e-8``; arc-length
  characterization, seed 000 §6: unit tangents agree to ``rtol``, curvature vectors to
  ``rtol`` times ``max(|K_q|, |K_r|, 1/l)``).  Tests check it against the continuity
  report joint by joint on samples of real glyphs.
* ``kind`` -- the type designer's view: ``"corner"`` where the tangent turns by more
  than ``corner_angle`` degrees; otherwise a smooth point, ``"G2"`` if the curvature
  jump relative to the local curvature is at most ``curvature_rtol``, else ``"G1"``.
  ``"singular"`` where a side has a vanishing derivative, ``"gap"`` where the pieces do
  not meet.

:func:`glyph_summary` and :func:`font_summary` count joints, corners, G1 and G2 smooth
points per glyph and per font.

Lesson: ``notebooks/11_are_letters_smooth.ipynb``.

Modules
-------
``contours`` (the types :class:`Contour`, :class:`Outline`), ``fonts`` (TrueType glyphs),
``svg`` and ``svg_path`` (SVG path data), ``classification`` (:func:`classify_joints`),
``summaries`` (per glyph, per font).
"""

from __future__ import annotations

from course_lib.constructions.outlines.classification import KINDS, JointTable, classify_joints
from course_lib.constructions.outlines.contours import Contour, Outline
from course_lib.constructions.outlines.fonts import (
    bundled_fonts,
    font_glyph_names,
    glyph_outline,
    truetype_contour,
    truetype_outline,
)
from course_lib.constructions.outlines.summaries import (
    FontSummary,
    GlyphSummary,
    font_summary,
    glyph_summary,
)
from course_lib.constructions.outlines.svg import svg_file_outlines, svg_outline

__all__ = [
    "KINDS",
    "Contour",
    "FontSummary",
    "GlyphSummary",
    "JointTable",
    "Outline",
    "bundled_fonts",
    "classify_joints",
    "font_glyph_names",
    "font_summary",
    "glyph_outline",
    "glyph_summary",
    "svg_file_outlines",
    "svg_outline",
    "truetype_contour",
    "truetype_outline",
]

