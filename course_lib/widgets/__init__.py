"""Interactive demos of the course (ipywidgets 8 + ipympl), each a one-liner.

>>> from course_lib.widgets import beta_spline_demo
>>> beta_spline_demo()            # doctest: +SKIP

Every demo keeps its state in one object (``demo.state``) that tests and notebooks can
drive without a browser, updates its figure in place, and falls back to a static
figure when widgets are unavailable (or with ``static=True``).  Widgets carry the CSS
classes of CONTRIBUTING.md (``cl-demo``, ``cl-slider-beta1``, ``cl-slider-beta2``,
``cl-slider-t``, ``cl-slider-knot``, ``cl-report``, ``cl-canvas``, ``cl-warning``).
"""

from __future__ import annotations

from ._core import CurveDemoState, CurveDemoView, Demo, SliderSpec, joint_report
from .demos import (
    beta_spline_demo,
    catmull_rom_demo,
    curvature_comb_demo,
    g2_stitch_demo,
    knot_spline_demo,
    reparametrization_demo,
)
from .interactor import PointDragger
from .reparam import ReparametrizationState

__all__ = [
    "CurveDemoState",
    "CurveDemoView",
    "Demo",
    "PointDragger",
    "ReparametrizationState",
    "SliderSpec",
    "beta_spline_demo",
    "catmull_rom_demo",
    "curvature_comb_demo",
    "g2_stitch_demo",
    "joint_report",
    "knot_spline_demo",
    "reparametrization_demo",
]
