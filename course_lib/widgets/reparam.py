"""The reparametrization demo: one curve, two parametrizations, the same geometry.

``Q(u)`` is a cubic Bézier curve; ``Q~ = Q o f`` with the orientation-preserving change
of variables ``f(v) = v + a v (1 - v)`` of ``[0, 1]`` (``f' = 1 + a (1 - 2v) > 0`` for
``|a| < 1``; seed 000 §4, Example 2 in spirit).  Equally spaced parameter values land
on different points and the velocity vectors differ in length, but the unit tangent
and the curvature at a point do not (they are intrinsic).
"""

from __future__ import annotations

import html

import numpy as np

from course_lib.validation import as_points, check_finite_scalar
from course_lib.widgets.assembly import Demo, resolve_static
from course_lib.widgets.report import warning_paragraph
from course_lib.widgets.state import DrawnState, SliderSpec
from course_lib.widgets.view import BlitView, fit_equal_limits, make_figure

__all__ = ["ReparametrizationState", "reparametrization_demo"]

_DEFAULT = [[0.0, 0.0], [1.0, 2.2], [3.2, 2.4], [4.0, 0.4]]
#: ``a`` in [-0.9, 0.9] keeps ``f' = 1 + a (1 - 2v) >= 0.1 > 0``; ``v`` spans the domain.
A_SLIDER = SliderSpec("a", "a", -0.9, 0.9, 0.01, "cl-slider-shape", per_joint=False)
V_SLIDER = SliderSpec("v", "v", 0.0, 1.0, 0.0025, "cl-slider-t", per_joint=False)


class ReparametrizationState(DrawnState):
    """State of :func:`reparametrization_demo`: control points, ``a`` (shape of ``f``), ``v``.

    Raises
    ------
    ValueError
        If ``|a| >= 1`` (then ``f`` is not orientation preserving), from
        :class:`~course_lib.geometry.reparametrization.ChangeOfVariables`.
    """

    def __init__(self, points=None, a: float = 0.6, v: float = 0.3, samples: int = 11) -> None:
        from course_lib.curves.curve import PiecewiseBezier

        self.points = as_points(
            _DEFAULT if points is None else points, "points", min_points=2, dims=(2,)
        ).copy()
        self.curve = PiecewiseBezier([self.points])
        self.samples = samples
        self.v = check_finite_scalar(v, "v")
        self.a = check_finite_scalar(a, "a")
        self.f = self._change(self.a)
        self.warning = ""
        super().__init__()
        self.compute()

    @staticmethod
    def _change(a: float):
        from course_lib.geometry.reparametrization import ChangeOfVariables

        return ChangeOfVariables.polynomial([0.0, 1.0 + a, -a], (0.0, 1.0), (0.0, 1.0))

    def set_a(self, a: float) -> None:
        """Change the shape of ``f``; raises ValueError (keeping the old ``f``) if ``|a| >= 1``."""
        a = check_finite_scalar(a, "a")
        self.f = self._change(a)
        self.a = a
        self.update()

    def set_t(self, v: float) -> None:
        self.v = float(np.clip(check_finite_scalar(v, "v"), 0.0, 1.0))
        self.update()

    def drag(self, k: int, x: float, y: float) -> None:
        from course_lib.curves.curve import PiecewiseBezier

        self.points[k] = (x, y)
        self.curve = PiecewiseBezier([self.points])
        self.update()

    def compute(self) -> None:
        from course_lib.geometry import differential_geometry as dg
        from course_lib.geometry.reparametrization import Reparametrized

        self.reparametrized = Reparametrized(self.curve, self.f)
        u = float(self.f(self.v))
        self.u = u
        self.warning = ""
        try:
            self.facts = {
                "speed_q": dg.speed(self.curve, u),
                "speed_r": dg.speed(self.reparametrized, self.v),
                "fprime": float(self.f(self.v, 1)),
                "T_q": dg.unit_tangent(self.curve, u),
                "T_r": dg.unit_tangent(self.reparametrized, self.v),
                "kappa_q": dg.signed_curvature(self.curve, u),
                "kappa_r": dg.signed_curvature(self.reparametrized, self.v),
            }
        except ValueError as exc:
            self.facts = {}
            self.warning = str(exc)

    def report_html(self) -> str:
        if self.warning:
            return warning_paragraph(self.warning)
        F = self.facts

        def vec(x):
            return f"({x[0]:.4f}, {x[1]:.4f})"

        rows = [
            ("u = f(v)", f"{self.u:.4f}  (v = {self.v:.4f})"),
            ("speed of Q at u", f"{F['speed_q']:.4f}"),
            ("speed of Q∘f at v", f"{F['speed_r']:.4f}"),
            ("chain rule: f'(v) × speed of Q", f"{F['fprime'] * F['speed_q']:.4f}"),
            ("unit tangent of Q / of Q∘f", f"{vec(F['T_q'])} / {vec(F['T_r'])}"),
            ("curvature of Q / of Q∘f", f"{F['kappa_q']:.4f} / {F['kappa_r']:.4f}"),
        ]
        body = "".join(
            f"<tr><th style='text-align:left'>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
            for k, v in rows
        )
        return f"<table class='cl-reparam-report'>{body}</table>"


class ReparametrizationView(BlitView):
    """Left: the curve with the samples of both parametrizations and their velocity
    vectors at the moving point; right: the graph of ``f``.  On an interactive canvas only
    the moving artists are redrawn (blitted over a cached background, :class:`BlitView`)."""

    def __init__(self, state: ReparametrizationState, static: bool) -> None:
        from course_lib.plotting import plot_control_polygon, plot_curve, plot_vectors
        from course_lib.plotting.style import OKABE_ITO, course_style

        self.state = state
        self.fig = make_figure((10.0, 4.6), static)
        with course_style():
            self.ax = self.fig.add_axes((0.04, 0.08, 0.56, 0.84))
            self.fax = self.fig.add_axes((0.70, 0.14, 0.27, 0.74))
        self.curve_artists = plot_curve(
            self.ax, state.curve, points=False, joints=False, polygon=False
        )
        self.design = plot_control_polygon(
            self.ax, state.points, linestyle="--", color="#6E6E6E", markersize=6
        )
        blue, red = OKABE_ITO["blue"], OKABE_ITO["vermillion"]
        (self.dots_q,) = self.ax.plot([], [], "o", ms=7, color=blue, label="Q(u), u equally spaced")
        (self.dots_r,) = self.ax.plot(
            [], [], "s", ms=6, mfc="white", mec=red, mew=1.8, label="Q∘f(v), v equally spaced"
        )
        self._scale = 0.25
        # a wide arrow under a narrow one; draw() puts the shorter of the two on top
        self.vel_r = plot_vectors(
            self.ax, [0, 0], [0, 0], scale=self._scale, color=red, width=0.012,
            label="d(Q∘f)/dv (× 1/4)", zorder=6,
        )  # fmt: skip
        self.vel_q = plot_vectors(
            self.ax, [0, 0], [0, 0], scale=self._scale, color=blue, width=0.005,
            label="dQ/du (× 1/4)", zorder=7,
        )  # fmt: skip
        (self.point,) = self.ax.plot([], [], "o", color="black", ms=8, zorder=8)
        self.ax.set_title("one curve, two parametrizations", fontsize=13)
        v = np.linspace(0, 1, 101)
        (self.fline,) = self.fax.plot(v, v, color=red, lw=2.4)
        self.fax.plot([0, 1], [0, 1], color="#8B8B8B", lw=1, ls=":")
        (self.fpt,) = self.fax.plot([], [], "o", color="black", ms=7)
        self.fax.set_xlim(0, 1)
        self.fax.set_ylim(0, 1)
        self.fax.set_aspect("equal")
        self.fax.set_xlabel("v")
        self.fax.set_ylabel("u = f(v)")
        self.fax.set_title("change of variables f", fontsize=12)
        fit_equal_limits(self.ax, state.points, margin=0.08, top=0.3)
        self.ax.legend(loc="upper center", ncol=2, fontsize=10)
        self.setup_blit((self.ax, self.fax), live=not static)
        self.draw(state)
        state.view = self

    def draw(self, st: ReparametrizationState) -> None:
        self.curve_artists.update(st.curve)
        self.design.update(st.points)
        grid = np.linspace(0.0, 1.0, st.samples)
        pq = st.curve.evaluate(grid)
        pr = st.reparametrized.evaluate(grid)
        self.dots_q.set_data(pq[:, 0], pq[:, 1])
        self.dots_r.set_data(pr[:, 0], pr[:, 1])
        p = st.curve.evaluate(st.u)
        self.point.set_data([p[0]], [p[1]])
        dq = st.curve.evaluate(st.u, 1)
        dr = st.reparametrized.evaluate(st.v, 1)
        self.vel_q.update(p, dq)
        self.vel_r.update(p, dr)
        # both arrows start at the point: the shorter one on top, or the longer would hide it
        q_on_top = float(np.linalg.norm(dq)) <= float(np.linalg.norm(dr))
        self.vel_q.quiver.set_zorder(7 if q_on_top else 6)
        self.vel_r.quiver.set_zorder(6 if q_on_top else 7)
        v = np.linspace(0, 1, 101)
        self.fline.set_ydata(st.f(v))
        self.fpt.set_data([st.v], [st.u])
        self.render()


def reparametrization_demo(
    points=None, a: float = 0.6, v: float = 0.3, *, static: bool | None = None
) -> Demo:
    """Reparametrize a cubic Bézier curve by ``f(v) = v + a v(1 - v)`` and watch what changes.

    Sliders: ``a`` (shape of ``f``; the range ``[-0.9, 0.9]`` keeps ``f' > 0``) and
    ``v`` (the moving parameter, class ``cl-slider-t``); draggable control points.
    The report compares speeds (not intrinsic: chain rule ``|Q~'| = f' |Q'|``) with
    unit tangents and curvatures (intrinsic: equal).

    Raises
    ------
    ValueError
        If ``|a| >= 1`` or the points are bad; if ``a`` or ``v`` lies outside its
        slider's range (``[-0.9, 0.9]``, ``[0, 1]``).
    """
    static = resolve_static(static)
    state = ReparametrizationState(points, a, v)  # |a| >= 1 raises here
    A_SLIDER.check(state.a)  # no initial value outside its slider (never clamped)
    V_SLIDER.check(state.v)
    view = ReparametrizationView(state, static)
    demo = Demo(state, view, static=static)
    demo.name = "reparametrization"
    if static:
        return demo

    from course_lib.widgets.assembly import observe, slider, snap_to_step
    from course_lib.widgets.interactor import PointDragger

    sa = slider(A_SLIDER, state.a)
    sv = slider(V_SLIDER, state.v)
    demo.controls.update(a=sa, t=sv)
    observe(demo, sa, lambda ch: state.set_a(snap_to_step(A_SLIDER, ch["new"])))
    observe(demo, sv, lambda ch: state.set_t(snap_to_step(V_SLIDER, ch["new"])))
    from course_lib.widgets.access import point_controls

    demo.build_widgets([sa, sv, point_controls(demo)])
    demo.dragger = PointDragger(
        view.ax,
        lambda: state.points,
        demo.guard(state.drag),
        on_release=demo.guard(lambda k: view.end_interaction()),
    )
    return demo
