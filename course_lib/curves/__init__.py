"""The curve type and the Bézier tools.

* :mod:`~course_lib.curves.curve` -- :class:`PiecewiseBezier`, the one curve type: segments of
  any degree, optional knots, global and local evaluation (the façade);
* :mod:`~course_lib.curves.evaluation` -- the engine behind it: the fast paths of
  ``PiecewiseBezier.evaluate`` (power-basis Taylor tables and Horner, lazy chunks);
* :mod:`~course_lib.curves.bezier` -- Bernstein basis, evaluation, hodographs, end
  derivatives, degree elevation, de Casteljau;
* :mod:`~course_lib.curves.parametrization` -- :class:`ParametricCurve` (any smooth
  parametrization from sympy or numpy functions) and the :class:`CurveLike` protocol every
  analysis function accepts.
"""

from __future__ import annotations

from course_lib.curves.curve import PiecewiseBezier
from course_lib.curves.parametrization import CurveLike, ParametricCurve

__all__ = ["CurveLike", "ParametricCurve", "PiecewiseBezier"]
