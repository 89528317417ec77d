"""course_lib: the companion package of the open course on geometric continuity.

Importing ``course_lib`` loads numpy only.  Symbolic work (sympy), plotting
(matplotlib) and widgets (ipywidgets, ipympl) live in submodules that import
their heavy dependencies lazily, inside the functions that need them.

The central type is :class:`~course_lib.curves.curve.PiecewiseBezier`: every
construction returns one, every analysis, plot and widget consumes one.  The parts, one
subpackage each: ``curves`` (the curve type, Bézier tools), ``geometry`` (the mathematics of a
curve), ``constructions`` (what builds curves), ``sources`` (the sources' formulas as printed),
``plotting`` and ``widgets`` (the pictures), ``homework`` (checks, answers, the grader's
protocol, variants, submit), ``lessons`` (one module per lecture).

Imported in a Jupyter kernel, it registers :mod:`course_lib.figure_alt`'s hook: JupyterLab
then shows each figure's text alternative (cell metadata) as a line under the figure.
"""

from __future__ import annotations

from course_lib import figure_alt
from course_lib.curves.curve import PiecewiseBezier
from course_lib.curves.parametrization import CurveLike, ParametricCurve

# in a Jupyter kernel: a figure's alt text (cell metadata mystnb.image.alt) is shown under it
figure_alt.register_in_kernel()

__version__ = "0.1.0"

__all__ = ["CurveLike", "ParametricCurve", "PiecewiseBezier", "__version__"]
