"""course_lib: the companion package of the open course on geometric continuity.

Importing ``course_lib`` loads numpy only.  Symbolic work (sympy), plotting
(matplotlib) and widgets (ipywidgets, ipympl) live in submodules that import
their heavy dependencies lazily, inside the functions that need them.

The central type is :class:`~course_lib.curve.PiecewiseBezier`: every
construction returns one, every analysis, plot and widget consumes one.
"""

from __future__ import annotations

from .curve import PiecewiseBezier

__version__ = "0.1.0"

__all__ = ["PiecewiseBezier", "__version__"]
