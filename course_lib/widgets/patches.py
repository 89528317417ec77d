"""The tangent-plane demo of lecture 10: two bicubic Bézier patches meeting along a boundary.

>>> from course_lib.widgets import tangent_plane_demo
>>> tangent_plane_demo()                 # doctest: +SKIP

``F`` is the lecture's hill; ``G`` is its G1 neighbour built by
:func:`~course_lib.constructions.surfaces.g1_neighbour_patch` from the shape function
``α`` and the two values ``β(0)``, ``β(1)`` of the linear ``β(v)``.  A fourth slider,
"lift", moves one control point of ``G``'s second row (the row the construction fixes)
straight up: at 0 the construction holds; anything else takes that point off the tangent
plane, and the normals along the boundary split.  The verdict comes from
:func:`~course_lib.constructions.surfaces.tangent_plane_continuity` (the math layer); this
module only moves control points and shows the result.

The state (:class:`TangentPlaneState`) needs no browser: ``demo.state.set_param("lift",
0.3)``, then ``demo.state.verdict()``.
"""

from __future__ import annotations

import html

import numpy as np

from course_lib.constructions.surfaces import (
    BezierPatch,
    g1_neighbour_patch,
    tangent_plane_continuity,
)
from course_lib.widgets.assembly import Demo, resolve_static
from course_lib.widgets.report import NOISE, live_html, warning_paragraph
from course_lib.widgets.state import DrawnState, SliderSpec
from course_lib.widgets.view import make_figure

__all__ = ["PATCH_SLIDERS", "TangentPlaneState", "TangentPlaneView", "tangent_plane_demo"]

#: The lecture's hill (``nb10-025b``) and the free rows of its neighbour (``nb10-041``).
_HILL = [[0, 0.5, 0.5, 0], [0.3, 1.6, 1.3, 0.2], [0.2, 1.3, 1.8, 0.4], [0, 0.4, 0.7, 0.2]]
_SHIFT = [[[1.5, 0, 0.3]], [[3.0, 0, -0.2]]]

#: The initial view (the viewer may turn it; a redraw keeps the turn).
ELEV, AZIM = 18.0, -35.0

#: The sliders, in the order they are shown.  ``α`` stays > 0 (the construction's rule).
PATCH_SLIDERS = {
    "alpha": SliderSpec("alpha", "α", 0.2, 3.0, 0.1, "cl-slider-alpha", per_joint=False),
    "beta0": SliderSpec("beta0", "β(0)", -1.0, 1.0, 0.05, "cl-slider-beta0", per_joint=False),
    "beta1": SliderSpec("beta1", "β(1)", -1.0, 1.0, 0.05, "cl-slider-beta1", per_joint=False),
    "lift": SliderSpec("lift", "lift", -1.0, 1.0, 0.05, "cl-slider-lift", per_joint=False),
}


def _hill() -> tuple[BezierPatch, np.ndarray]:
    xy = np.stack(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"), axis=-1)
    F = BezierPatch(np.concatenate([xy, np.array(_HILL)[..., None]], axis=-1))
    return F, F.control_net[3] + np.array(_SHIFT)


class TangentPlaneState(DrawnState):
    """Two patches ``F``, ``G`` along ``F(1, v) = G(0, v)`` and their tangent-plane report.

    Parameters
    ----------
    alpha, beta0, beta1 : float
        Shape functions of :func:`~course_lib.constructions.surfaces.g1_neighbour_patch`
        (``β(v) = β0 (1 - v) + β1 v``).
    lift : float
        Height added to control point ``(1, lifted)`` of ``G`` after the construction.
    lifted : int
        Which control point of ``G``'s second row is lifted (0..3; default the middle-ish 2).

    Raises
    ------
    ValueError
        The construction's own error (``alpha <= 0``), or a value outside its slider.
    """

    def __init__(
        self,
        alpha: float = 1.2,
        beta0: float = 0.4,
        beta1: float = -0.3,
        lift: float = 0.0,
        *,
        lifted: int = 2,
    ) -> None:
        self.F, self.rest = _hill()
        n = self.F.degree[1]
        if not (isinstance(lifted, (int, np.integer)) and 0 <= lifted <= n):
            raise ValueError(f"lifted must be an integer in 0..{n} (a column of G); got {lifted!r}")
        self.lifted = int(lifted)
        self.params = {"alpha": alpha, "beta0": beta0, "beta1": beta1, "lift": lift}
        for name, spec in PATCH_SLIDERS.items():
            spec.check(self.params[name])  # never clamped by a slider
            self.params[name] = float(self.params[name])
        self.warning = ""
        super().__init__()
        self.compute()

    # ---------------------------------------------------------------- changes
    def set_param(self, name: str, value: float) -> None:
        """Set ``alpha``, ``beta0``, ``beta1`` or ``lift``; rebuild ``G``; redraw; notify.

        Raises
        ------
        KeyError
            An unknown name.
        ValueError
            A value outside the slider (the old value is kept).
        """
        if name not in PATCH_SLIDERS:
            raise KeyError(f"unknown parameter {name!r}; known: {sorted(PATCH_SLIDERS)}")
        PATCH_SLIDERS[name].check(value)
        self.params[name] = float(value)
        self.update()

    # ---------------------------------------------------------------- results
    def compute(self) -> None:
        """``G`` from the construction, its lifted point moved, and the report."""
        p = self.params
        built = g1_neighbour_patch(self.F, self.rest, p["alpha"], (p["beta0"], p["beta1"]))
        net = built.control_net.copy()
        net[1, self.lifted, 2] += p["lift"]  # a moved control point, as a drag would move it
        self.G = BezierPatch(net)
        self.warning = ""
        try:
            self.report = tangent_plane_continuity(self.F, self.G)
        except ValueError as exc:  # G not regular on the boundary: no normal there
            self.report = None
            self.warning = str(exc)

    @property
    def g1(self) -> bool:
        return self.report is not None and self.report.g1

    def verdict(self) -> str:
        """One sentence: G1 or not, and the largest angle between the normals."""
        if self.report is None:
            return f"Warning: {self.warning}"
        ang = self.report.max_angle if self.report.max_angle >= NOISE else 0.0
        if self.report.g1:
            return f"G1: one tangent plane along the boundary (largest normal angle {ang:.2g}°)."
        return f"Not G1: the normals split by up to {ang:.3g}° along the boundary (a crease)."

    def report_html(self) -> str:
        """The live report: verdict, angle, gap, the shape functions and the lift."""
        if self.report is None:
            return warning_paragraph(self.warning)
        r, p = self.report, self.params
        rows = [
            ("tangent plane", "G1 ✓ one plane" if r.g1 else "not G1: a crease"),
            ("largest normal angle", f"{r.max_angle if r.max_angle >= NOISE else 0.0:.3g}°"),
            ("gap", f"{r.gap if r.gap >= NOISE else 0.0:.2g}"),
            ("shape functions", f"α = {p['alpha']:.2f}, β(0) = {p['beta0']:.2f}, "
                                f"β(1) = {p['beta1']:.2f}"),
            ("lift of G's point", f"{p['lift']:.2f}"),
        ]  # fmt: skip
        body = "".join(
            f"<tr><th style='text-align:left;padding-right:0.8em'>{html.escape(k)}</th>"
            f"<td>{html.escape(v)}</td></tr>"
            for k, v in rows
        )
        return (
            "<table class='cl-joint-report cl-patch-report'><caption style='text-align:left;"
            f"font-weight:bold'>Boundary F(1, v) = G(0, v)</caption>{body}</table>"
        )


class TangentPlaneView:
    """The two patches, their boundary and normals (redrawn coarse), the verdict as title.

    A 3D picture changes everywhere when ``G`` changes, so there is nothing to blit: the
    Axes is cleared and redrawn with coarse meshes and without its axes (panes, ticks),
    keeping the viewer's rotation.
    """

    #: samples per direction of each surface: coarse, so that a redraw stays quick
    RESOLUTION = 9

    def __init__(self, state: TangentPlaneState, static: bool) -> None:
        self.fig = make_figure((8.0, 5.6), static)
        self.ax = self.fig.add_axes((0.0, 0.04, 1.0, 0.88), projection="3d")
        self.ax.view_init(elev=ELEV, azim=AZIM)
        self.artists = None
        self.draw(state)
        state.view = self

    def draw(self, st: TangentPlaneState) -> None:
        from course_lib.plotting.style import OKABE_ITO
        from course_lib.plotting.surfaces3d import plot_patch_pair

        ax = self.ax
        elev, azim = ax.elev, ax.azim
        if self.artists is not None and self.artists.motion is not None:
            self.artists.motion.disconnect()
        ax.clear()
        self.artists = plot_patch_pair(
            ax, st.F, st.G, net=False, length=1.0, zoom=1.5, resolution=self.RESOLUTION,
            normals=st.report is not None,
        )  # fmt: skip
        # the control points the construction fixes: G's first two rows, joined across
        N = st.G.control_net[:2]
        red = OKABE_ITO["vermillion"]
        for a, b in zip(N[0], N[1], strict=True):
            ax.plot(*np.transpose([a, b]), color=red, lw=1.0, ls="--")
        ax.plot(*N[1].T, color=red, lw=1.0, ls="--", marker="o", ms=4)
        P = N[1, st.lifted]
        ax.plot([P[0]], [P[1]], [P[2]], "o", ms=10, mfc="none", mec=OKABE_ITO["black"], mew=2,
                label="the point “lift” moves")  # fmt: skip
        ax.view_init(elev=elev, azim=azim)
        # no panes, ticks or numbers: they are not the point, and they cost half of a frame
        # (measured 225 -> 100 ms per draw at 880 px on the course's busy 2-core machine)
        ax.set_axis_off()
        ax.legend(loc="upper left", fontsize=9)
        colour = OKABE_ITO["black"] if st.g1 else OKABE_ITO["vermillion"]
        ax.set_title(st.verdict(), fontsize=11, color=colour)
        self.fig.canvas.draw_idle()


def tangent_plane_demo(
    alpha: float = 1.2,
    beta0: float = 0.4,
    beta1: float = -0.3,
    lift: float = 0.0,
    *,
    static: bool | None = None,
) -> Demo:
    """Two bicubic patches along a boundary: move the shape functions, then lift a point.

    Sliders ``α``, ``β(0)``, ``β(1)`` (classes ``cl-slider-alpha``, ``cl-slider-beta0``,
    ``cl-slider-beta1``) change ``G`` inside the G1 construction: the verdict stays G1.
    The slider "lift" (``cl-slider-lift``) moves one control point of ``G``'s second row up
    or down: at any value but 0 the normals split.  The report (``cl-report``) and a live
    region (``cl-live``, ``role="status"``) say the verdict.

    Raises
    ------
    ValueError
        An initial value outside its slider (``α`` in [0.2, 3], the others in [-1, 1]).
    """
    static = resolve_static(static)
    state = TangentPlaneState(alpha, beta0, beta1, lift)
    view = TangentPlaneView(state, static)
    demo = Demo(state, view, static=static)
    demo.name = "tangent_plane"
    if static:
        return demo
    import ipywidgets as w

    from course_lib.widgets.assembly import observe, slider, snap_to_step

    rows = []
    for name, spec in PATCH_SLIDERS.items():
        s = slider(spec, state.params[name])
        demo.controls[name] = s

        def moved(change, name=name, spec=spec) -> None:
            state.set_param(name, snap_to_step(spec, change["new"]))

        observe(demo, s, moved)
        rows.append(s)
    live = w.HTML(layout=w.Layout(width="auto", min_height="1.5em"))
    live.add_class("cl-live")
    demo.controls["live"] = live

    def say(st) -> None:
        value = live_html(st.verdict())
        if live.value != value:
            live.value = value

    state.listeners.append(say)
    say(state)
    demo.build_widgets([*rows, live])
    return demo
