"""Interactive demos of the course (ipywidgets 8 + ipympl), each a one-liner.

>>> from course_lib.widgets import beta_spline_demo
>>> beta_spline_demo()            # doctest: +SKIP

Every demo keeps its state in one object (``demo.state``) that tests and notebooks can
drive without a browser, updates its figure in place, and falls back to a static
figure when widgets are unavailable (or with ``static=True``).  Widgets carry the CSS
classes of CONTRIBUTING.md (``cl-demo``, ``cl-slider-beta1``, ``cl-slider-beta2``,
``cl-slider-beta3``, ``cl-slider-t``, ``cl-slider-knot``, ``cl-report``, ``cl-canvas``,
``cl-warning``).

Lecture mode (a projector, no code on screen): ``make present L=04`` serves a deck generated
from the lecture with Voilà, the course's ``course-deck`` template and a pre-heated kernel
(``tools/present.py``); there ``$COURSE_CANVAS_PX`` makes every demo canvas 1280 px wide.
The RISE slide view does not render ipywidgets or ipympl (jupyterlab-contrib/rise #119).

Layout: ``state`` (what a demo is: :class:`CurveDemoState`), ``view`` (how it is drawn:
:class:`CurveDemoView`, :class:`BlitView`), ``assembly`` (the widgets around them:
:class:`Demo`, sliders, selectors), ``_controls`` (a curve demo's standard controls),
``access`` (keyboard and screen readers), ``demos``, ``reparam``, ``outlines``, ``patches``
(the demos; ``patches``: two Bézier patches and their tangent plane, lecture 10).
No widget module computes: the numbers come from the math modules
(:func:`course_lib.geometry.continuity.joint_report` for the live report).

Demos follow the hand: only moving artists are redrawn (:class:`BlitView`), queued input is
coalesced (``_coalesce``), a released point lands under the mouse and the release sends a
full frame; ``cl-check-details`` shows the report's higher orders and residuals.
"""

from __future__ import annotations

from course_lib.geometry.continuity import (
    joint_report,  # kept here for callers of the demos' report
)
from course_lib.widgets.assembly import Demo
from course_lib.widgets.demos import (
    beta_spline_demo,
    catmull_rom_demo,
    curvature_comb_demo,
    g2_stitch_demo,
    knot_spline_demo,
    quartic_beta_spline_demo,
    reparametrization_demo,
)
from course_lib.widgets.interactor import PointDragger
from course_lib.widgets.outlines import GlyphDemoState, glyph_demo
from course_lib.widgets.patches import TangentPlaneState, tangent_plane_demo
from course_lib.widgets.reparam import ReparametrizationState
from course_lib.widgets.state import CurveDemoState, SliderSpec
from course_lib.widgets.view import BlitView, CurveDemoView

__all__ = [
    "BlitView",
    "CurveDemoState",
    "CurveDemoView",
    "Demo",
    "GlyphDemoState",
    "PointDragger",
    "ReparametrizationState",
    "SliderSpec",
    "TangentPlaneState",
    "beta_spline_demo",
    "catmull_rom_demo",
    "curvature_comb_demo",
    "g2_stitch_demo",
    "glyph_demo",
    "joint_report",
    "knot_spline_demo",
    "quartic_beta_spline_demo",
    "reparametrization_demo",
    "tangent_plane_demo",
]
