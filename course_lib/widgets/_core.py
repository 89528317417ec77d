"""The machinery shared by every demo: state object, figure view, widget assembly.

* :class:`CurveDemoState` -- the whole state of a demo (design points, shape
  parameters, selected joint, moving parameter, display switches) and the results
  derived from it (the curve, the continuity report of the selected joint, a warning).
  ``update()`` recomputes and redraws; ``set_param``/``drag`` change it.  No widget
  and no pixel is needed to drive it, so tests can use it directly.
* :class:`CurveDemoView` -- the figure: curve, design polygon, curvature comb,
  tangent and curvature vectors at the moving point, curvature against arc length.
  It only updates artists in place (``set_data``/``set_segments``, then
  ``draw_idle``); nothing is re-created.
* :class:`Demo` -- the widgets around them (sliders, checkboxes, report, warning,
  error output), or, with ``static=True`` or without ipywidgets/ipympl, just the figure.

The math is called, never written here: every curve comes from the construction the
demo was given, every number from :mod:`course_lib.geometry.continuity` and
:mod:`course_lib.geometry.differential_geometry`.

Why this module is long: state, figure and widget assembly still live together here (they
are split apart in the 'tools' helper's branch of session 30).
"""

from __future__ import annotations

import html
import traceback
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np

from course_lib.validation import as_points, check_finite_scalar, check_integer

__all__ = [
    "CANVAS_WIDTH_PX",
    "BlitView",
    "CurveDemoState",
    "CurveDemoView",
    "Demo",
    "SliderSpec",
    "fit_equal_limits",
    "joint_report",
    "make_figure",
]


# --------------------------------------------------------------------- math calls
def joint_report(curve, j: int, max_order: int = 3):
    """The continuity report of joint ``j`` only (segments ``j`` and ``j + 1``, global parameter)."""
    from course_lib.curves.curve import PiecewiseBezier
    from course_lib.geometry.continuity import curve_continuity

    k = curve.knots
    pair = PiecewiseBezier(curve.segments[j : j + 2], k[j : j + 3] if curve.has_knots else None)
    (rep,) = curve_continuity(pair, max_order=max_order)
    return replace(rep, index=j)


# -------------------------------------------------------------------- parameters
@dataclass(frozen=True)
class SliderSpec:
    """How a shape parameter is offered to the user.

    ``log=True`` gives a FloatLogSlider over ``[min, max]`` (both > 0): the slider can
    never produce a value <= 0 (the rule for β1).
    """

    name: str
    description: str
    min: float
    max: float
    step: float
    css: str
    log: bool = False
    per_joint: bool = True

    def check(self, value) -> None:
        """Raise ``ValueError`` if ``value`` (a scalar or one value per joint) leaves
        ``[min, max]``: a demo must not start from a value its slider cannot show (the
        slider would silently clamp it while the state keeps the true value)."""
        a = np.atleast_1d(np.asarray(value, dtype=float))
        bad = ~((a >= self.min) & (a <= self.max))
        if np.any(bad):
            j = int(np.argmax(bad))
            at = f" at joint {j}" if a.size > 1 else ""
            raise ValueError(
                f"{self.name} must lie in [{self.min:g}, {self.max:g}] (the range of this "
                f"demo's {self.description} slider); got {a[j]:g}{at}"
            )


class CurveDemoState:
    """The state of a curve demo and what follows from it.

    Parameters
    ----------
    build : callable ``(points, params) -> PiecewiseBezier``
        The construction (a call into the math layer).  Raises ``ValueError`` on
        bad data.
    points : array_like of shape (n, 2)
        The draggable design points.
    params : mapping of name -> float or array
        Shape parameters (arrays: one value per joint), knots, ...
    joint_of_param : callable ``(name, joint) -> index``, optional
        Which entry of a per-joint parameter array belongs to curve joint ``joint``
        (default: the same index).
    t : float, optional
        Global parameter of the moving point (default: middle of the domain).
    order : int, optional
        The continuity order the demo is about (default ``max_order``): the report shows
        orders up to it; higher orders, residuals and all β's only with ``show_details``.

    Raises
    ------
    ValueError
        If the initial data is invalid: the construction's own error, unchanged; if
        ``t`` lies outside the curve's domain.
    """

    def __init__(
        self,
        build: Callable[[np.ndarray, dict], object],
        points,
        params: Mapping[str, object] | None = None,
        *,
        joint_of_param: Callable[[str, int], int] | None = None,
        t: float | None = None,
        joint: int = 0,
        show_comb: bool = True,
        show_tangents: bool = True,
        show_curvature: bool = True,
        show_circle: bool = False,
        samples: int = 400,
        max_order: int = 3,
        min_points: int = 2,
        order: int | None = None,
        show_details: bool = False,
    ) -> None:
        self.build = build
        self.points = as_points(points, "points", min_points=min_points, dims=(2,)).copy()
        self.params = {
            k: (np.array(v, dtype=float) if np.ndim(v) else float(v))
            for k, v in (params or {}).items()
        }
        self.joint_of_param = joint_of_param or (lambda name, j: j)
        self.show_comb = bool(show_comb)
        self.show_tangents = bool(show_tangents)
        self.show_curvature = bool(show_curvature)
        self.show_circle = bool(show_circle)
        self.samples = check_integer(samples, "samples", minimum=2)
        self.max_order = check_integer(max_order, "max_order", minimum=1)
        #: the continuity order the demo is about (the report shows it first)
        self.order = self.max_order if order is None else check_integer(order, "order", minimum=0)
        if self.order > self.max_order:
            raise ValueError(f"order must be <= max_order = {self.max_order}; got {self.order}")
        self.show_details = bool(show_details)
        self.curve = build(self.points.copy(), self._params_copy())  # bad data raises here
        self.joint = self._check_joint(joint)
        a, b = self.curve.domain
        self.t = 0.5 * (a + b) if t is None else check_finite_scalar(t, "t")
        if not a <= self.t <= b:  # the t slider spans the domain: no silent clamping
            raise ValueError(f"t must lie in the curve's domain [{a:g}, {b:g}]; got {self.t:g}")
        self.report = None
        self.warning = ""
        self.view: CurveDemoView | None = None
        self.listeners: list[Callable[[CurveDemoState], None]] = []
        self.compute()

    # ---------------------------------------------------------------- helpers
    def _params_copy(self) -> dict:
        return {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in self.params.items()}

    def _check_joint(self, j: int) -> int:
        j = check_integer(j, "joint", minimum=0)
        n = self.curve.n_joints
        if n and j >= n:
            raise ValueError(f"joint must be < {n} (the curve has {n} joints); got {j}")
        return j

    @property
    def n_joints(self) -> int:
        return self.curve.n_joints

    # ---------------------------------------------------------------- changes
    def set_param(self, name: str, value, joint: int | None = None) -> None:
        """Set a parameter (for all joints when ``joint`` is None), rebuild, redraw.

        Raises
        ------
        ValueError
            If the construction rejects the new value; the old value is kept.
        KeyError
            For an unknown parameter name.
        """
        if name not in self.params:
            raise KeyError(f"unknown parameter {name!r}; known: {sorted(self.params)}")
        old = self.params[name]
        new = old.copy() if isinstance(old, np.ndarray) else old
        if isinstance(new, np.ndarray):
            if joint is None and np.ndim(value) == 0:
                new[:] = float(value)
            elif joint is None:
                new = np.array(value, dtype=float)
            else:
                new[self.joint_of_param(name, joint)] = float(value)
        else:
            new = float(value)
        params = self._params_copy()
        params[name] = new
        self.curve = self.build(self.points.copy(), params)  # raises -> old state kept
        self.params = params
        self.update()

    def get_param(self, name: str, joint: int | None = None) -> float:
        """Value of a parameter at a joint (the first entry when ``joint`` is None)."""
        v = self.params[name]
        if isinstance(v, np.ndarray):
            return float(v[self.joint_of_param(name, 0 if joint is None else joint)])
        return float(v)

    def select_joint(self, j: int) -> None:
        self.joint = self._check_joint(j)
        self.update()

    def set_t(self, t: float) -> None:
        a, b = self.curve.domain
        self.t = float(np.clip(check_finite_scalar(t, "t"), a, b))
        self.update()

    def set_flag(self, name: str, value: bool) -> None:
        if name not in ("show_comb", "show_tangents", "show_curvature", "show_circle"):
            raise KeyError(f"unknown switch {name!r}")
        setattr(self, name, bool(value))
        self.update()

    def set_details(self, value: bool) -> None:
        """Show or hide the report's details (no recomputation, no redraw)."""
        self.show_details = bool(value)
        for f in self.listeners:
            f(self)

    def drag(self, k: int, x: float, y: float) -> None:
        """Move design point ``k`` to ``(x, y)`` and update.  Never raises on geometry:
        a degenerate configuration (e.g. two coincident points) becomes ``warning``."""
        k = check_integer(k, "k", minimum=0)
        if k >= len(self.points):
            raise ValueError(f"k must be < {len(self.points)} (number of points); got {k}")
        self.points[k] = (check_finite_scalar(x, "x"), check_finite_scalar(y, "y"))
        self.update(rebuild=True)

    # ----------------------------------------------------------------- results
    def compute(self, rebuild: bool = False, report: bool = True) -> None:
        """Rebuild the curve (if asked) and the report; problems become ``warning``."""
        warnings = []
        if rebuild:
            try:
                self.curve = self.build(self.points.copy(), self._params_copy())
            except ValueError as exc:
                warnings.append(f"The construction failed for these points: {exc}")
        a, b = self.curve.domain
        self.t = float(np.clip(self.t, a, b))
        if self.curve.n_joints:
            self.joint = min(self.joint, self.curve.n_joints - 1)
        self.warning = " ".join(warnings)
        if report:
            self.compute_report()

    def compute_report(self) -> None:
        """The continuity report of the selected joint (a failure becomes ``warning``)."""
        self.report = None
        if self.curve.n_joints:
            try:
                self.report = joint_report(self.curve, self.joint, self.max_order)
            except ValueError as exc:
                msg = f"Joint {self.joint} cannot be analysed: {exc}"
                self.warning = f"{self.warning} {msg}".strip()

    def update(self, rebuild: bool = False) -> None:
        """Recompute and redraw the view (if any), then the report, then notify listeners.

        The picture comes first: the canvas is redrawn before the (slower) continuity
        report is computed.
        """
        self.compute(rebuild=rebuild, report=False)
        if self.view is not None:
            self.view.draw(self)
        self.compute_report()
        for f in self.listeners:
            f(self)

    def report_html(self) -> str:
        """The live report: the selected joint's continuity, then any warning."""
        parts = []
        if self.warning:
            parts.append(
                "<p class='cl-warning-text' style='color:#934100;font-weight:bold'>⚠ "
                f"{html.escape(self.warning)}</p>"
            )
        if self.report is not None:
            from course_lib.widgets.report import demo_report_html

            parts.append(demo_report_html(self.report, self.order, self.show_details))
        elif not self.warning:
            parts.append("<p>This curve has a single segment: no joint to report.</p>")
        return "".join(parts)


# ------------------------------------------------------------------------ figure
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
    """The picture of a :class:`CurveDemoState`; updates its artists in place.

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
        (self.selected,) = self.ax.plot(
            [],
            [],
            ls="none",
            marker="o",
            ms=18,
            mfc="none",
            mec=OKABE_ITO["orange"],
            mew=2.5,
            zorder=7,
        )
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


# ----------------------------------------------------------------------- widgets
def widgets_available() -> bool:
    # find_spec, not import: importing ipympl would switch pyplot's backend
    from importlib.util import find_spec

    return find_spec("ipympl") is not None and find_spec("ipywidgets") is not None


class Demo:
    """A demo: its state, its figure and (unless static) its widgets.

    Attributes
    ----------
    state : CurveDemoState (or the demo's own state object)
    view : the figure's view object; ``figure`` is its matplotlib Figure
    controls : dict of name -> widget (sliders ``"beta1"``, ``"beta2"``, ``"t"``,
        ``"knot"``, selectors ``"joint"``, checkboxes ``"comb"``, ``"tangents"``, ...)
    report, warning : ipywidgets.HTML (classes ``cl-report``, ``cl-warning``)
    output : ipywidgets.Output, where errors raised in callbacks are written
    widget : the outer ``VBox`` (class ``cl-demo``), None when static
    """

    def __init__(self, state, view, *, static: bool) -> None:
        self.state = state
        self.view = view
        self.static = static
        self.controls: dict = {}
        self.report = self.warning = self.output = self.widget = None
        self._busy = False

    @property
    def figure(self):
        return self.view.fig

    # ----------------------------------------------------------- callbacks
    def guard(self, fn: Callable) -> Callable:
        """Wrap a widget callback: any exception is shown in the warning and the output."""

        def wrapped(*args, **kwargs):
            if self._busy:
                return None
            try:
                return fn(*args, **kwargs)
            except Exception as exc:  # a callback must never fail silently
                self.show_error(exc)
                return None

        return wrapped

    def show_error(self, exc: BaseException) -> None:
        msg = f"⚠ {type(exc).__name__}: {exc}"
        if self.warning is not None:
            self.warning.value = (
                f"<span style='color:#934100;font-weight:bold'>{html.escape(msg)}</span>"
            )
            self.warning.layout.display = None
        if self.output is not None:
            self.output.append_stderr("".join(traceback.format_exception(exc)))
        if self.widget is None:
            raise exc

    def refresh(self, state=None) -> None:
        """Copy the state's report and warning into the widgets."""
        if self.report is None:
            return
        st = self.state
        self.report.value = st.report_html()
        if st.warning:
            self.warning.value = (
                f"<span style='color:#934100;font-weight:bold'>⚠ {html.escape(st.warning)}</span>"
            )
            self.warning.layout.display = None
        else:
            self.warning.value = ""
            self.warning.layout.display = "none"

    def _sync(self, fn: Callable) -> None:
        """Change widget values without triggering their callbacks."""
        self._busy = True
        try:
            fn()
        finally:
            self._busy = False

    # ----------------------------------------------------------- assembly
    def build_widgets(self, rows: Sequence) -> None:
        import ipywidgets as w

        self.report = w.HTML(layout=w.Layout(width="auto"))
        self.report.add_class("cl-report")
        self.warning = w.HTML(layout=w.Layout(display="none"))
        self.warning.add_class("cl-warning")
        self.output = w.Output(layout=w.Layout(max_height="12em", overflow="auto"))
        self.output.add_class("cl-output")
        controls = w.VBox([r for r in rows if r is not None])
        side = w.VBox([self.warning, self.report], layout=w.Layout(margin="0 0 0 1em"))
        self.widget = w.VBox([self.view.fig.canvas, w.HBox([controls, side]), self.output])
        self.widget.add_class("cl-demo")
        if hasattr(self.state, "listeners"):
            self.state.listeners.append(self.refresh)
        self.refresh()

    # ----------------------------------------------------------- display
    def _repr_mimebundle_(self, **kwargs):
        if self.widget is not None:
            from course_lib.widgets.access import publish_slider_names

            publish_slider_names()  # names the slider handles (ipywidgets leaves them unnamed)
            return self.widget._repr_mimebundle_(**kwargs)
        import io

        buf = io.BytesIO()
        self.view.fig.savefig(buf, format="png", dpi=100)
        import base64

        return {
            "image/png": base64.b64encode(buf.getvalue()).decode("ascii"),
            "text/plain": repr(self),
        }

    def __repr__(self) -> str:
        kind = "static figure" if self.widget is None else "interactive"
        return f"<{type(self).__name__} {getattr(self, 'name', '')} ({kind})>"
