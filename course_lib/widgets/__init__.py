"""Interactive demos of the course (ipywidgets 8 + ipympl), each a one-liner.

>>> from course_lib.widgets import beta_spline_demo
>>> beta_spline_demo()            # doctest: +SKIP

Every demo keeps its state in one object (``demo.state``) that tests and notebooks can
drive without a browser, updates its figure in place, and falls back to a static
figure when widgets are unavailable (or with ``static=True``).  Widgets carry the CSS
classes of CONTRIBUTING.md (``cl-demo``, ``cl-slider-beta1``, ``cl-slider-beta2``,
``cl-slider-beta3``, ``cl-slider-t``, ``cl-slider-knot``, ``cl-report``, ``cl-canvas``,
``cl-warning``).

Lecture mode (a projector, no code on screen): Voilà renders a notebook's outputs
with live widgets, e.g. ``.venv/bin/voila notebooks/04_beta_splines.ipynb`` (add
``--no-browser --port=8866`` on a server).  JupyterLab also works; the RISE slide view
does not render ipywidgets or ipympl (jupyterlab-contrib/rise #119).  Offline, Voilà's
default template asks a CDN for FontAwesome: two harmless console errors.
"""

from __future__ import annotations

from ._core import CurveDemoState, CurveDemoView, Demo, SliderSpec, joint_report
from .demos import (
    beta_spline_demo,
    catmull_rom_demo,
    curvature_comb_demo,
    g2_stitch_demo,
    knot_spline_demo,
    quartic_beta_spline_demo,
    reparametrization_demo,
)
from .interactor import PointDragger
from .outlines import GlyphDemoState, glyph_demo
from .reparam import ReparametrizationState

__all__ = [
    "CurveDemoState",
    "CurveDemoView",
    "Demo",
    "GlyphDemoState",
    "PointDragger",
    "ReparametrizationState",
    "SliderSpec",
    "beta_spline_demo",
    "catmull_rom_demo",
    "curvature_comb_demo",
    "g2_stitch_demo",
    "glyph_demo",
    "joint_report",
    "knot_spline_demo",
    "quartic_beta_spline_demo",
    "reparametrization_demo",
]
