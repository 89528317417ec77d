"""Constructions: functions that build a :class:`~course_lib.curves.curve.PiecewiseBezier`.

* :mod:`~course_lib.constructions.stitching` -- G1, G2 and G^n stitching, Farin-Boehm;
* :mod:`~course_lib.constructions.catmull_rom` -- Catmull-Rom with shape parameter β1;
* :mod:`~course_lib.constructions.beta_splines` -- Beta-splines of every degree;
* :mod:`~course_lib.constructions.knot_splines` -- Finn's G1 Bézier splines from knots;
* :mod:`~course_lib.constructions.surfaces` -- tensor-product Bézier patches, G1 along a
  boundary;
* :mod:`~course_lib.constructions.outlines` -- real outlines (TrueType glyphs, SVG path
  data) read as curves, and their joints classified.
"""
