"""The figure of a demo: canvas, limits, blitting, and the picture of a curve demo.

* :func:`make_figure` -- a bare Figure on an Agg canvas (static) or an ipympl canvas widget
  ``canvas_width_px()`` wide; :func:`fit_equal_limits`, :func:`ring_marker`.
* :class:`BlitView` -- redraw only what moves (blitting over a cached background).
* :class:`CurveDemoView` -- the picture of a curve demo's state: curve, design polygon,
  curvature comb, tangent and curvature vectors at the moving point, curvature against arc
  length.  It only updates artists in place (``set_data``/``set_segments``, then
  ``draw_idle``); nothing is re-created.

No math here: every curve, comb and κ(s) sample comes from the state and from
:mod:`course_lib.plotting`.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from course_lib.widgets.state import CurveDemoState

__all__ = [
    "CANVAS_WIDTH_ENV",
    "CANVAS_WIDTH_PX",
    "BlitView",
    "CurveDemoView",
    "canvas_width_px",
    "fit_equal_limits",
    "make_figure",
    "ring_marker",
]


#: Width in CSS pixels of an interactive demo's canvas.  JupyterLab's notebook column is
#: about 970 px wide in a 1400 px browser window with the file browser open (measured
#: with headless Chromium); a wider canvas is clipped on the right.
CANVAS_WIDTH_PX = 880
#: Environment variable that overrides ``CANVAS_WIDTH_PX`` (``make present`` sets it: on a
#: 1920 px projector the demo canvas is 1280 px wide).
CANVAS_WIDTH_ENV = "COURSE_CANVAS_PX"


def canvas_width_px() -> int:
    """Width of an interactive canvas: ``$COURSE_CANVAS_PX`` (400 .. 3000) or ``CANVAS_WIDTH_PX``."""
    import os

    raw = os.environ.get(CANVAS_WIDTH_ENV, "")
    try:
        px = int(raw)
    except ValueError:
        return CANVAS_WIDTH_PX
    return px if 400 <= px <= 3000 else CANVAS_WIDTH_PX


def _ipympl_canvas_classes():
    """ipympl's Canvas and FigureManager, imported without changing pyplot's backend.

    Importing ipympl switches matplotlib to the ipympl backend when matplotlib is already
    loaded; a demo must not turn every later ``new_figure`` of the notebook into a widget,
    so the backend in use before (inline, in a plain notebook) is put back.
    """
    import sys

    import matplotlib

    from course_lib.plotting.style import resolve_pyplot_backend

    resolve_pyplot_backend()
    before = matplotlib.get_backend() if "matplotlib.pyplot" in sys.modules else None
    from ipympl.backend_nbagg import Canvas, FigureManager

    if before is not None and matplotlib.get_backend() != before:
        matplotlib.use(before)
    return Canvas, FigureManager


def make_figure(figsize: tuple[float, float], static: bool):
    """A bare Figure on an Agg canvas (``static``, 100 dpi) or on an ipympl canvas widget
    (``canvas_width_px()`` wide: the dpi is chosen for it, the layout stays the same)."""
    from matplotlib.figure import Figure

    from course_lib.plotting.style import course_style

    dpi = 100.0 if static else canvas_width_px() / float(figsize[0])
    with course_style():
        fig = Figure(figsize=figsize, dpi=dpi)
    if static:
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        FigureCanvasAgg(fig)
    else:
        import warnings

        Canvas, FigureManager = _ipympl_canvas_classes()
        canvas = Canvas(fig)
        with warnings.catch_warnings():
            # ipympl 0.10's Toolbar passes an argument traitlets deprecates; harmless
            warnings.filterwarnings("ignore", category=DeprecationWarning, module="traitlets")
            FigureManager(canvas, 0)
        canvas.header_visible = False
        canvas.toolbar_visible = False
        canvas.footer_visible = False
        canvas.resizable = False
        canvas.capture_scroll = False
        canvas.add_class("cl-canvas")
    return fig


def ring_marker(ax, colour, *, ms: float, mew: float, zorder: float, label: str | None = None):
    """An empty ring marker (no data yet) that marks a selected point or joint."""
    kwargs = {} if label is None else {"label": label}
    (ring,) = ax.plot(
        [], [], ls="none", marker="o", ms=ms, mfc="none", mec=colour, mew=mew, zorder=zorder,
        **kwargs,
    )  # fmt: skip
    return ring


def fit_equal_limits(ax, P: np.ndarray, margin: float = 0.2, top: float = 0.0) -> None:
    """Fixed limits showing the points ``P`` with equal scales on both axes.

    The limits are computed from the Axes box (so the box keeps its size and the
    pixel-to-data map is fixed while dragging): the data span plus ``margin`` on every
    side and ``top`` (a fraction of the height) extra above, for a legend.
    """
    lo, hi = P.min(axis=0), P.max(axis=0)
    span = float(max(hi - lo)) or 1.0
    lo = lo - margin * span
    hi = hi + margin * span
    hi[1] += top * (hi[1] - lo[1])
    pos = ax.get_position()
    fw, fh = ax.figure.get_size_inches()
    box = (pos.height * fh) / (pos.width * fw)  # height / width of the Axes box
    w, h = hi[0] - lo[0], hi[1] - lo[1]
    if h / w > box:
        w = h / box
    else:
        h = w * box
    mid = 0.5 * (lo + hi)
    ax.set_xlim(mid[0] - 0.5 * w, mid[0] + 0.5 * w)
    ax.set_ylim(mid[1] - 0.5 * h, mid[1] + 0.5 * h)
    ax.set_aspect("equal", adjustable="box")
    ax.set_autoscale_on(False)


class BlitView:
    """Redraw only what moves: the artists of some Axes are "animated" and blitted over a
    cached background (frames, ticks, labels, legend); the rest is drawn on a full frame only.

    A subclass calls :meth:`setup_blit` once its artists exist and :meth:`render` after
    changing them; :meth:`full_redraw` (on mouse release) sends a complete picture, which
    also heals a partial (diff) frame the browser may have lost.
    """

    fig = None
    #: True while the mouse holds a point: axis limits may grow but do not shrink (a
    #: rescale redraws everything); the release redraws with limits fitted again
    interacting = False

    def setup_blit(self, axes, live: bool) -> None:
        self.blit = bool(live)
        self.background = None
        self._full = True
        self.dynamic = [
            a
            for ax in axes
            for a in (*ax.lines, *ax.collections, *ax.patches, *ax.texts, *ax.artists)
        ]
        if self.blit:
            # the figure must then be redrawn through render() (savefig omits animated artists)
            for a in self.dynamic:
                a.set_animated(True)
            self._cid = self.fig.canvas.mpl_connect("draw_event", self._on_draw)

    def add_dynamic(self, artist) -> None:
        """Draw ``artist`` with the moving ones (an artist added after :meth:`setup_blit`,
        e.g. the keyboard's selection ring of ``access.py``)."""
        if getattr(self, "blit", False):
            artist.set_animated(True)
            self.dynamic.append(artist)

    def _on_draw(self, event) -> None:
        canvas = self.fig.canvas
        self.background = canvas.copy_from_bbox(self.fig.bbox)
        self._draw_dynamic()

    def _draw_dynamic(self) -> None:
        for a in self.dynamic:
            if a.get_visible() and a.axes.get_visible():
                self.fig.draw_artist(a)

    def render(self) -> str:
        """Redraw the canvas: blit over the cached background when nothing static changed,
        else ask for a full draw.  Returns ``"blit"``, ``"full"`` or ``"idle"``."""
        canvas = self.fig.canvas
        if self.blit and self.background is not None and not self._full:
            canvas.restore_region(self.background)
            self._draw_dynamic()
            canvas.blit(self.fig.bbox)
            return "blit"
        self._full = False
        if self.blit:
            self.background = None
        canvas.draw_idle()
        return "full" if not self.blit else "idle"

    def refit(self) -> None:
        """Fit limits that were left alone while interacting (subclasses)."""

    def end_interaction(self) -> str:
        """The mouse let go: limits may shrink again, and one complete frame is sent."""
        self.interacting = False
        self.refit()
        return self.full_redraw()

    def full_redraw(self) -> str:
        """A complete frame: background redrawn and, on ipympl, a full image instead of a
        diff against the browser's last picture (heals a lost partial frame)."""
        self._full = True
        if hasattr(self.fig.canvas, "_force_full"):
            self.fig.canvas._force_full = True
        return self.render()


class CurveDemoView(BlitView):
    """The picture of a :class:`~course_lib.widgets.state.CurveDemoState`; updates its
    artists in place.

    Parameters
    ----------
    state : CurveDemoState
    static : bool
        Agg canvas (True) or ipympl widget canvas (False).
    design_labels : str, optional
        Format of the design points' labels, e.g. ``"$V_{{{i}}}$"``.
    extras : sequence of callables ``(view) -> updater``
        Extra drawings (construction diagrams); each returns a function
        ``(state) -> None`` called on every redraw.
    profile_samples : int, optional
        Samples per segment of the κ(s) plot.  Default 16 on a blitted (interactive)
        canvas, where its arc lengths are the costliest data of a frame, and 48 on a
        static figure.
    blit : bool, optional
        Redraw by blitting over a cached background (default: on for the interactive
        canvas, off for a static figure, whose ``savefig`` must show every artist).
    """

    def __init__(
        self,
        state: CurveDemoState,
        *,
        static: bool = False,
        design_labels: str | None = None,
        design_polygon: bool = True,
        extras: Sequence[Callable] = (),
        figsize: tuple[float, float] = (10.0, 4.6),
        title: str | None = None,
        blit: bool | None = None,
        profile_samples: int | None = None,
    ) -> None:
        from course_lib.plotting import (
            plot_control_polygon,
            plot_curvature_comb,
            plot_curvature_profile,
            plot_curve,
            plot_frame,
            plot_osculating_circle,
        )
        from course_lib.plotting.style import OKABE_ITO, course_style

        self.state = state
        self._done: dict = {}  # what was last computed for which curve (see _once)
        self.fig = make_figure(figsize, static)
        with course_style():
            self.ax = self.fig.add_axes((0.04, 0.08, 0.56, 0.84))
            self.kax = self.fig.add_axes((0.69, 0.14, 0.29, 0.74))
        c = state.curve
        self.comb = plot_curvature_comb(self.ax, c, samples=state.samples)
        self.curve_artists = plot_curve(self.ax, c, points=False, per_segment=48)
        self.design = plot_control_polygon(
            self.ax, state.points, labels=design_labels, linestyle="-" if design_polygon else "none"
        )
        self.frame = plot_frame(self.ax, c, state.t, labels=False)
        self.circle = plot_osculating_circle(self.ax, c, state.t)
        live = (not static) if blit is None else bool(blit)  # redrawn many times a second
        if profile_samples is None:
            profile_samples = 16 if live else 48
        self.profile = plot_curvature_profile(
            self.kax, c, per_segment=profile_samples, arc_length_every=3 if live else 1
        )
        self.kax.set_xlim(0.0, 1.06 * self.kax.get_xlim()[1])  # room for the end dots
        (self.profile_point,) = self.kax.plot([], [], "o", color="black", ms=7, zorder=6)
        self.selected = ring_marker(self.ax, OKABE_ITO["orange"], ms=18, mew=2.5, zorder=7)
        self.kax.set_title("curvature along the curve", fontsize=12)
        if title:
            self.ax.set_title(title, fontsize=13)
        self._fit_limits()
        self.extras = [f(self) for f in extras]
        # Blitting (interactive canvases only; a static figure must keep every artist for
        # savefig): everything drawn on the two Axes is "animated", the rest (frames,
        # ticks, labels) is a cached background restored before the artists are redrawn.
        self._flags = None
        self.setup_blit((self.ax, self.kax), live)
        self.draw(state)
        state.view = self

    def refit(self) -> None:
        if self.state.show_curvature:
            self._profile_limits()

    def _profile_limits(self) -> None:
        """Rescale the curvature Axes only when the data leaves it or shrinks a lot
        (a rescale redraws the ticks: a full draw instead of a blit)."""
        segs = self.profile.lines.get_segments()
        X = np.concatenate([s[:, 0] for s in segs])
        K = np.concatenate([s[:, 1] for s in segs])
        _x0, x1 = self.kax.get_xlim()
        y0, y1 = self.kax.get_ylim()
        lo, hi = min(float(K.min()), 0.0), max(float(K.max()), 0.0)
        span = (hi - lo) or 1.0
        L = float(X.max())
        shrink = not self.interacting
        bad_x = L > x1 or (shrink and L < 0.7 * x1)
        bad_y = lo < y0 or hi > y1 or (shrink and span < 0.45 * (y1 - y0))
        if bad_x:
            self.kax.set_xlim(0.0, 1.1 * L if L > 0 else 1.0)
        if bad_y:
            self.kax.set_ylim(lo - 0.25 * span, hi + 0.25 * span)
        if bad_x or bad_y:
            self._full = True

    def _fit_limits(self) -> None:
        P = np.vstack([self.state.points, *self.state.curve.segments])
        fit_equal_limits(self.ax, P, margin=0.22)

    def _hide(self, artists) -> None:
        for a in artists:
            a.set_visible(False)

    def draw(self, state: CurveDemoState) -> list[str]:
        """Put the state's data into the artists and ask the canvas to redraw.

        Returns the problems met (also appended to ``state.warning``).
        """
        c = state.curve
        problems = []
        self._once("curve", c, lambda: self.curve_artists.update(c))
        self.design.update(state.points)
        jp = c.joint_points
        if c.n_joints:
            p = jp[state.joint]
            self.selected.set_data([p[0]], [p[1]])
        else:
            self.selected.set_data([], [])
        # each picture of derivatives may fail for a degenerate (irregular) curve
        for name, flag, arts, fn in (
            (
                "curvature comb",
                state.show_comb,
                self.comb.artists,
                lambda: self._once("comb", c, lambda: self._comb(c)),
            ),
            (
                "tangent and curvature vectors",
                state.show_tangents,
                self.frame.artists,
                lambda: self.frame.update(c, state.t),
            ),
            (
                "curvature plot",
                state.show_curvature,
                [*self.profile.artists, self.profile_point],
                lambda: self._profile(c, state),
            ),
        ):
            if not flag:
                self._hide(arts)
                continue
            try:
                fn()
                for a in arts:
                    a.set_visible(True)
            except ValueError as exc:
                self._hide(arts)
                problems.append(f"No {name}: {exc}")
        self.kax.set_visible(state.show_curvature)
        flags = (state.show_comb, state.show_tangents, state.show_curvature, state.show_circle)
        if flags != self._flags:
            self._flags = flags
            self._full = True
        if state.show_circle and state.show_tangents:
            try:
                self.circle.update(c, state.t)
            except ValueError:
                self._hide(self.circle.artists)
        else:
            self._hide(self.circle.artists)
        for f in self.extras:
            f(state)
        if problems:
            extra = " ".join(problems)
            state.warning = f"{state.warning} {extra}".strip()
        self.render()
        return problems

    def _comb(self, c) -> None:
        """Update the comb; rescale it only when its longest tooth leaves a wide band
        (the scale stays fixed while the curvature changes moderately, so the eye can
        compare; a tooth longer than the picture would hide everything else)."""
        self.comb.update(c)
        x0, x1 = self.ax.get_xlim()
        size = x1 - x0
        teeth = self.comb.tooth_array()
        longest = float(np.nanmax(np.linalg.norm(teeth[:, 1] - teeth[:, 0], axis=1)))
        if longest > 0.45 * size or 0 < longest < 0.03 * size:
            self.comb.scale *= 0.15 * size / longest
            self.comb.update(c)

    def _once(self, key: str, curve, fn: Callable[[], None]) -> None:
        """Run ``fn`` unless it already ran for this very curve object (a moving point, a
        switch or a new joint leave the curve unchanged: its comb, samples and κ(s) data
        are not recomputed).  A ValueError it raised is raised again for the same curve."""
        last = self._done.get(key)
        if last is not None and last[0] is curve:
            if last[1] is not None:
                raise last[1]
            return
        try:
            fn()
        except ValueError as exc:
            self._done[key] = (curve, exc)
            raise
        self._done[key] = (curve, None)

    def _profile(self, c, state) -> None:
        def data():
            self.profile.update(c, rescale=False)
            self._profile_limits()

        self._once("profile", c, data)
        # the moving point on the κ(s) plot: s(t) read off the plotted samples
        segs = self.profile.lines.get_segments()
        i = min(int(np.searchsorted(c.knots, state.t, side="right")) - 1, c.n_segments - 1)
        ti = np.linspace(c.knots[i], c.knots[i + 1], len(segs[i]))
        s = float(np.interp(state.t, ti, segs[i][:, 0]))
        k = float(np.interp(state.t, ti, segs[i][:, 1]))
        self.profile_point.set_data([s], [k])
