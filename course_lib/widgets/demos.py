"""One-line demos of the course.  Each returns a :class:`~course_lib.widgets.assembly.Demo`.

In a notebook the demo displays as a figure (ipympl canvas) with sliders, switches, a
live continuity report and draggable points.  With ``static=True`` -- or automatically
when ipywidgets/ipympl are missing -- it is a plain figure (Agg).  Every demo is driven
by its ``state`` object, so a test (or a notebook cell) can change it without a browser::

    demo = beta_spline_demo()
    demo.controls["beta1"].value = 2.0          # as if the slider moved
    demo.state.curve, demo.state.report         # the new curve and joint report
    demo.state.drag(3, 1.0, 2.0)                # as if vertex 3 were dragged to (1, 2)

Bad initial data fails at construction with the math layer's own ``ValueError``, and
an initial value outside its slider's range with a ``ValueError`` naming the range
(never silently clamped); slider ranges never allow an invalid value (β1 > 0, knots
kept in order); a degenerate configuration reached by dragging shows a warning in the
report instead of raising.

Why this module is long: one function per demo, each wiring its sliders to one construction
through the shared demo assembly.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from course_lib.validation import as_points
from course_lib.widgets._controls import assemble_curve_demo
from course_lib.widgets.assembly import Demo, resolve_static
from course_lib.widgets.reparam import reparametrization_demo
from course_lib.widgets.state import CurveDemoState, SliderSpec
from course_lib.widgets.view import CurveDemoView

__all__ = [
    "BETA1",
    "BETA2",
    "BETA2_STITCH",
    "QUARTIC_BETA2",
    "QUARTIC_BETA3",
    "beta_spline_demo",
    "catmull_rom_demo",
    "curvature_comb_demo",
    "g2_stitch_demo",
    "knot_spline_demo",
    "quartic_beta_spline_demo",
    "reparametrization_demo",
]

#: β1 slider: logarithmic, so it is strictly positive (0.05 .. 20) and 1 sits in the middle.
BETA1 = SliderSpec("beta1", "β₁", 0.05, 20.0, 0.01, "cl-slider-beta1", log=True)
#: β2 slider of the Beta-spline demos: 0 .. 50.  The construction accepts β2 < 0 as long
#: as γ = 2(1 + β1) / (β2 + 2β1(1 + β1)) is defined (seed 000 eq. (12.1), d = 3), but with
#: β1 down to 0.05 the pole β2 = -2β1(1 + β1) comes as close as -0.105, and β2 >= 0 keeps
#: the curve in the convex hull of its control polygon.
BETA2 = SliderSpec("beta2", "β₂", 0.0, 50.0, 0.1, "cl-slider-beta2")
#: β2 slider of the stitching demo: -10 .. 50.  G2 stitching is defined for every real β2
#: (seed 000 eq. (11)); only Farin-Boehm's point T needs γ, which the diagram then hides.
BETA2_STITCH = SliderSpec("beta2", "β₂", -10.0, 50.0, 0.1, "cl-slider-beta2", per_joint=False)
#: β2 slider of the quartic G3 Beta-spline: 0 .. 100, global (seed 001 Fig. 5 goes up to
#: β2 = 100).  With β3 = 0 and β2 >= 0 every blending weight is positive (convex hull); for
#: β2 < 0 the basis breaks down already at β1 = 1, β2 = -4, β3 = 0 (the normalizing
#: denominator sum_k b_k(0) of the unnormalized weights vanishes there).
QUARTIC_BETA2 = replace(BETA2, max=100.0, per_joint=False)
#: β3 slider of the quartic G3 Beta-spline: -50 .. 50, global.  Any real β3 is a valid
#: shape parameter; for β1 != 1 and |β3| large the weights may leave [0, 1] or, near a
#: singular configuration, grow large (the curve then leaves the picture).
QUARTIC_BETA3 = SliderSpec("beta3", "β₃", -50.0, 50.0, 0.1, "cl-slider-beta3", per_joint=False)


def _finish(
    state: CurveDemoState,
    *,
    static: bool | None,
    name: str,
    sliders=(),
    knots: bool = False,
    design_labels: str | None = None,
    extras=(),
    title: str | None = None,
    design_polygon: bool = True,
    order: int | None = None,
) -> Demo:
    if order is not None:  # the continuity order the demo is about: shown first in the report
        state.order = min(int(order), state.max_order)
    for spec in sliders:  # an initial value the slider cannot show is an error, not clamped
        spec.check(state.params[spec.name])
    static = resolve_static(static)
    view = CurveDemoView(
        state,
        static=static,
        design_labels=design_labels,
        extras=extras,
        title=title,
        design_polygon=design_polygon,
    )
    demo = Demo(state, view, static=static)
    demo.name = name
    if not static:
        assemble_curve_demo(demo, sliders, knots=knots)
    return demo


# ------------------------------------------------------------ curvature comb
def _default_g1_curve():
    from course_lib.curves.curve import PiecewiseBezier

    V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])
    W1 = V[3] + (V[3] - V[2])  # on the ray: G1 (and C1); W2 free: not G2
    return PiecewiseBezier([V, [V[3], W1, [6.5, 0.5], [8.0, 2.0]]])


def curvature_comb_demo(curve=None, *, static: bool | None = None) -> Demo:
    """Drag the Bézier control points of any plane PiecewiseBezier; watch the curvature comb.

    Default: two cubic segments meeting G1 but not G2 -- the comb and the κ(s) plot
    jump at the joint.  Shared joint points move together.

    Raises
    ------
    TypeError, ValueError
        If ``curve`` is not a plane PiecewiseBezier.
    """
    from course_lib.curves.curve import PiecewiseBezier

    curve = _default_g1_curve() if curve is None else curve
    if not isinstance(curve, PiecewiseBezier):
        raise TypeError(f"curve must be a PiecewiseBezier, got {type(curve).__name__}")
    if curve.dim != 2:
        raise ValueError(f"curve must be a plane curve (dim 2); got dim {curve.dim}")
    # index of every control point in one shared list (a joint shared by two segments once)
    index, points = [], []
    for i, seg in enumerate(curve.segments):
        rows = []
        for r, p in enumerate(seg):
            if r == 0 and i > 0 and np.array_equal(p, curve.segments[i - 1][-1]):
                rows.append(index[-1][-1])
            else:
                points.append(p)
                rows.append(len(points) - 1)
        index.append(rows)
    knots = curve.knots if curve.has_knots else None

    def build(P, params):
        return PiecewiseBezier([P[rows] for rows in index], knots, info=curve.info)

    state = CurveDemoState(build, np.array(points), {}, show_circle=True)
    return _finish(
        state,
        static=static,
        name="curvature comb",
        order=2,
        design_polygon=False,
        title="drag the control points",
    )


# ------------------------------------------------------- constructions (H2)
def _per_joint(value, n: int) -> np.ndarray:
    a = np.asarray(value, dtype=float)
    return np.full(n, float(a)) if a.ndim == 0 else a.copy()


_CR_DEFAULT = [[0, 0], [1, 2], [3, 2.5], [4.5, 0.5], [6.5, 1], [7.5, 3], [9, 2.5]]
_BETA_DEFAULT = [
    [0, 0],
    [0.5, 2.5],
    [2.5, 3.2],
    [4, 0.8],
    [6, 0.4],
    [7.5, 2.8],
    [9.5, 3.0],
    [10.5, 0.8],
]


def catmull_rom_demo(points=None, beta1=1.0, *, static: bool | None = None) -> Demo:
    """Catmull-Rom spline with shape parameter β1 (seed 000 §9, eq. (13)-(14)).

    Drag the control points (the curve interpolates ``V_1 .. V_{m-1}``); β1 slider
    (log scale, always > 0; global or per joint); moving point, comb, κ(s) plot and
    the report of the selected joint (G1 for every β1 > 0, C1 only for β1 = 1).

    Raises
    ------
    ValueError
        From :func:`course_lib.constructions.catmull_rom.catmull_rom` for bad initial data (β1 <= 0,
        fewer than 4 points, ...).
    """
    from course_lib.constructions.catmull_rom import catmull_rom

    P = as_points(_CR_DEFAULT if points is None else points, "points", min_points=1, dims=(2,))
    c0 = catmull_rom(P, beta1=beta1)  # bad data raises here, with the math layer's message
    b = _joint_values(beta1, c0.info.get("beta1"), c0.n_joints)

    def build(P, params):
        return catmull_rom(P, beta1=_uniform(params["beta1"]))

    state = CurveDemoState(build, P, {"beta1": b}, min_points=4)
    return _finish(
        state,
        static=static,
        name="Catmull-Rom",
        order=1,
        sliders=[BETA1],
        design_labels="$V_{{{i}}}$",
        title="Catmull-Rom spline with β₁",
    )


def _uniform(values):
    """Equal values at every joint are passed as one global value (the seed's global
    shape parameter, which also applies at the curve's ends)."""
    a = np.asarray(values, dtype=float)
    return float(a.ravel()[0]) if a.size and np.all(a == a.ravel()[0]) else a


def _joint_values(value, recorded, n_joints: int):
    """Per-joint values of a shape parameter (from the curve's ``info`` when recorded)."""
    if n_joints == 0:
        return float(np.asarray(value, dtype=float).ravel()[0])
    if recorded is not None and np.size(recorded) == n_joints:
        return np.array(recorded, dtype=float)
    return _per_joint(value, n_joints)


def beta_spline_demo(
    points=None, beta1=1.0, beta2=0.0, *, degree: int = 3, static: bool | None = None
) -> Demo:
    """Quadratic G1 (``degree=2``) or cubic G2 (``degree=3``) Beta-spline (seed 000 §10).

    Sliders β1 (log scale: always > 0) and β2 (cubic only), global or per joint;
    draggable control vertices; construction shown (junction and interior Bézier
    vertices, seed 000 Fig. 10/11); comb, κ(s) plot, report of the selected joint.

    Raises
    ------
    ValueError
        From :mod:`course_lib.constructions.beta_splines` for bad initial data (β1 <= 0, too few points).
    """
    from course_lib.constructions.beta_splines import cubic_beta_spline, quadratic_beta_spline

    if degree not in (2, 3):
        raise ValueError(f"degree must be 2 (quadratic G1) or 3 (cubic G2); got {degree!r}")
    P = as_points(_BETA_DEFAULT if points is None else points, "points", min_points=1, dims=(2,))
    if degree == 2:
        c0 = quadratic_beta_spline(P, beta1=beta1)  # bad data raises here

        def build(P, params):
            return quadratic_beta_spline(P, beta1=_uniform(params["beta1"]))

        params = {"beta1": _joint_values(beta1, c0.info.get("beta1"), c0.n_joints)}
        sliders = [BETA1]
    else:
        c0 = cubic_beta_spline(P, beta1=beta1, beta2=beta2)

        def build(P, params):
            return cubic_beta_spline(
                P, beta1=_uniform(params["beta1"]), beta2=_uniform(params["beta2"])
            )

        params = {
            "beta1": _joint_values(beta1, c0.info.get("beta1"), c0.n_joints),
            "beta2": _joint_values(beta2, c0.info.get("beta2"), c0.n_joints),
        }
        sliders = [BETA1, BETA2]
    state = CurveDemoState(build, P, params, min_points=degree + 1)
    return _finish(
        state,
        static=static,
        name="Beta-spline",
        order=1 if degree == 2 else 2,
        sliders=sliders,
        design_labels="$V_{{{i}}}$",
        extras=[_junction_marks],
        title=f"{'quadratic G1' if degree == 2 else 'cubic G2'} Beta-spline",
    )


#: Default control polygon of the quartic demo: the polygon of seed 001 Fig. 5 as drawn in
#: notebook 07 (eight vertices, four quartic segments, three joints).
_QUARTIC_DEFAULT = [[0, 0], [1, 2.4], [3, 3], [4, 0.6], [6, 0.2], [7, 2.6], [9, 3], [10, 0.4]]


def quartic_beta_spline_demo(
    points=None,
    beta1=1.0,
    beta2=0.0,
    beta3=0.0,
    *,
    static: bool | None = None,
) -> Demo:
    """The quartic G3 Beta-spline of seed 001 Example 2.1 with global β1, β2, β3.

    Sliders β1 (log scale: always > 0), β2 (0 .. 100, the range of seed 001 Fig. 5) and
    β3 (-50 .. 50), one value for the whole curve; draggable control vertices ``V_i``
    (each segment blends five of them); comb, κ(s) plot and the report of the selected
    joint, which reads G3 for every setting (and C1 only when β1 = 1, β2 != 0).  A
    setting the construction rejects shows a warning and keeps the last valid curve.

    Raises
    ------
    TypeError
        If a shape parameter is not a real number (global values only).
    ValueError
        From :func:`course_lib.constructions.beta_splines.quartic_beta_spline` for bad initial data
        (β1 <= 0, fewer than 5 points, a basis that is not unique); for an initial value
        outside its slider's range.
    """
    from course_lib.constructions.beta_splines import quartic_beta_spline
    from course_lib.validation import check_finite_scalar

    P = as_points(_QUARTIC_DEFAULT if points is None else points, "points", min_points=1, dims=(2,))
    params = {
        name: check_finite_scalar(value, name)
        for name, value in (("beta1", beta1), ("beta2", beta2), ("beta3", beta3))
    }

    def build(P, params):
        return quartic_beta_spline(P, params["beta1"], params["beta2"], params["beta3"])

    state = CurveDemoState(build, P, params, min_points=5)  # bad data raises here
    return _finish(
        state,
        static=static,
        name="quartic Beta-spline",
        order=3,
        sliders=[replace(BETA1, per_joint=False), QUARTIC_BETA2, QUARTIC_BETA3],
        design_labels="$V_{{{i}}}$",
        title="quartic G3 Beta-spline",
    )


def _junction_marks(view):
    """Interior Bézier vertices (squares) of the Beta-spline, kept up to date."""
    from course_lib.plotting.style import OKABE_ITO

    (art,) = view.ax.plot(
        [], [], ls="none", marker="s", ms=6, mfc=OKABE_ITO["bluish_green"], mec="black", zorder=6
    )

    def update(state):
        inner = np.vstack([s[1:-1] for s in state.curve.segments])
        art.set_data(inner[:, 0], inner[:, 1])

    return update


def g2_stitch_demo(V=None, beta1=1.0, beta2=0.0, W3=None, *, static: bool | None = None) -> Demo:
    """Stitch a cubic Bézier curve ``r`` to ``q`` with G2 continuity (seed 000 §8, Fig. 8).

    Draggable: ``V_0 .. V_3`` (the curve ``q``) and ``W_3``; ``W_0, W_1, W_2`` follow
    from β1, β2 (eq. (9), (11)); the Farin-Boehm construction with its point ``T`` is
    drawn.  The report confirms G2 at the joint with exactly these β1, β2.

    Raises
    ------
    ValueError
        From :func:`course_lib.constructions.stitching.g2_stitch` for bad data (β1 <= 0, ``V_2 = V_3``).
    """
    from course_lib.constructions.stitching import g2_stitch

    V = as_points(
        [[0, 0], [1, 1.5], [2.5, 2], [4, 1.6]] if V is None else V, "V", min_points=4, dims=(2,)
    )
    if V.shape[0] != 4:
        raise ValueError(f"V must hold the 4 control points of a cubic; got {V.shape[0]}")
    W3 = as_points(np.atleast_2d([8.5, 1.0] if W3 is None else W3), "W3", min_points=1, dims=(2,))
    P = np.vstack([V, W3[:1]])

    def build(P, params):
        return g2_stitch(P[:4], params["beta1"], params["beta2"], P[4:])

    state = CurveDemoState(build, P, {"beta1": float(beta1), "beta2": float(beta2)})
    return _finish(
        state,
        static=static,
        name="G2 stitching",
        order=2,
        sliders=[replace(BETA1, per_joint=False), BETA2_STITCH],
        design_polygon=False,
        extras=[_farin_boehm_overlay],  # the diagram labels the points
        title="G2 stitching (Farin-Boehm)",
    )


def _farin_boehm_overlay(view):
    """Farin-Boehm's diagram (seed 000 Fig. 8), kept up to date.  Where γ is undefined
    (β2 = -2β1(1 + β1), T at infinity) the parts built on T are hidden; the stitch itself
    stays valid (the report still shows G2)."""
    from course_lib.plotting.constructions import plot_farin_boehm

    V, W = view.state.curve.segments
    diagram = plot_farin_boehm(view.ax, V, W, V[-2], labels=True)  # T placed by update()
    texts = [diagram.artists[k] for k in diagram.artists if k.startswith("ratio:")]
    on_T = [diagram.artists[k] for k in ("line:leg", "line:fan", "label:T")] + texts[1:]

    def update(state):
        from course_lib.constructions.stitching import farin_boehm

        c = state.curve
        V, W = c.segments
        pts = {f"V{i}": V[i] for i in range(len(V))}
        pts.update({f"W{j}": W[j] for j in range(len(W))})
        try:
            fb = farin_boehm(V[-3:], state.params["beta1"], state.params["beta2"], V.shape[0] - 1)
        except ValueError:  # γ undefined: no point T
            diagram.update(pts, curve=c)
            for a in on_T:
                a.set_visible(False)
            return
        pts["T"] = fb.T
        diagram.update(pts, curve=c)
        texts[1].set_text(f"β₁²γ={state.params['beta1'] ** 2 * fb.gamma:.3g}")
        texts[2].set_text(f"γ={fb.gamma:.3g}")
        for a in on_T:
            a.set_visible(True)

    return update


def knot_spline_demo(d_points=None, knots=None, *, static: bool | None = None) -> Demo:
    """Finn's G1 Bézier spline from control points ``d_{-1} .. d_{2L}`` and knots (seed 004 §19.6).

    The course's answer to Finn's "G1 Bézier spline applet" (exercise 19.8.1): drag
    the control points, move an interior knot (its slider stays between its
    neighbours, so the knots stay strictly increasing) and watch the joint point slide
    along ``p_{3i-1} p_{3i+1}`` in the ratio of the knot intervals.  The report shows
    G1 always and C1 in the global parameter (exercise 19.8.3).

    Raises
    ------
    ValueError
        From :mod:`course_lib.constructions.knot_splines` for bad data (knots not increasing, wrong count).
    """
    from course_lib.constructions import knot_splines as ks

    D = as_points(
        [[0, 0], [0.8, 2.2], [2.5, 3], [4.5, 2.6], [5.5, 0.4], [7.5, 0.2], [9, 2.5], [10, 0.5]]
        if d_points is None
        else d_points,
        "d_points",
        min_points=1,
        dims=(2,),
    )
    L = (D.shape[0] - 2) // 2
    k = np.arange(L + 1, dtype=float) if knots is None else np.asarray(knots, dtype=float)

    def build(P, params):
        return ks.g1_knot_spline(P, params["knots"])

    state = CurveDemoState(build, D, {"knots": k})
    labels = [f"$d_{{{i - 1}}}$" for i in range(D.shape[0])]
    return _finish(
        state,
        static=static,
        name="G1 knot spline",
        order=1,
        knots=True,
        design_labels=labels,
        extras=[_knot_overlay],
        title="Finn's G1 Bézier spline",
    )


def _knot_overlay(view):
    """Joint points ``p_{3i}`` on the segments ``p_{3i-1} p_{3i+1}`` (dashed)."""
    from course_lib.plotting.style import OKABE_ITO

    (art,) = view.ax.plot([], [], color=OKABE_ITO["bluish_green"], lw=1.4, ls="--", zorder=4)

    def update(state):
        segs = state.curve.segments
        rows = []
        for i in range(1, len(segs)):
            rows += [segs[i - 1][2], segs[i][1], [np.nan, np.nan]]
        P = np.array(rows) if rows else np.zeros((0, 2))
        art.set_data(P[:, 0], P[:, 1]) if P.size else art.set_data([], [])

    return update
