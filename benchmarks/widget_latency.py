"""Widget update latency: one slider change of a demo, from new value to redrawn canvas.

Scenario (the goal of the widgets' issue): a cubic Beta-spline of 12 segments with a
400-tooth curvature comb, the κ(s) plot and the tangent/curvature vectors shown; the
β1 slider moves (global β1, so every segment changes).  Medians over ``repeats``
changes, each to a new β1 value.  Goals: total (compute + Agg redraw) ≤ 25 ms median,
computation alone ≤ 2 ms.

Measured parts (seconds):

* ``compute_curve_and_artists``: the construction (cubic_beta_spline) plus every
  artist's new data (comb teeth, samples, vectors, κ(s) with its arc lengths) put
  into the artists -- ``CurveDemoView.draw`` without the canvas redraw;
* ``math_only``: the math calls of a frame alone (construction, comb, samples,
  vectors, κ(s)), without matplotlib's ``set_data`` bookkeeping;
* ``report``: the continuity report of the selected joint (HTML widget, not an artist);
* ``redraw_blit``: the Agg redraw as the widget does it (restore the cached background,
  draw the changed artists, blit);
* ``redraw_full``: a full Agg ``canvas.draw()`` (what a non-blitting widget would pay);
* ``total``: ``state.set_param("beta1", ...)`` until the canvas is redrawn:
  construction, artists, blit redraw (the goal's measure);
* ``total_with_report``: the same plus the continuity report, which the state
  computes *after* the redraw;
* ``ipympl_total`` (optional): the same through the real ipympl canvas and slider
  widget (no browser attached), which adds ipympl's PNG encoding of the changed
  pixels for the browser -- the kernel-side latency a student sees.

Usage::

    .venv/bin/python benchmarks/widget_latency.py [--repeats 60] [--no-ipympl] [--cpu]
"""

from __future__ import annotations

import argparse
import gc
import statistics
import time
from dataclasses import asdict, dataclass

import numpy as np

GOAL_TOTAL = 0.025
GOAL_COMPUTE = 0.002


@dataclass
class Latency:
    segments: int
    comb_samples: int
    repeats: int
    compute_curve_and_artists: float
    math_only: float
    report: float
    redraw_blit: float
    redraw_full: float
    total: float
    total_with_report: float
    ipympl_total: float | None
    redraw_mode_counts: dict

    @property
    def met(self) -> bool:
        return self.total <= GOAL_TOTAL and self.math_only <= GOAL_COMPUTE


def control_polygon(segments: int = 12) -> np.ndarray:
    """A wavy control polygon with ``segments + 3`` vertices (cubic Beta-spline: m - 2 segments)."""
    n = segments + 3
    x = np.linspace(0.0, 12.0, n)
    y = 1.5 * np.sin(1.3 * x) + 0.3 * np.cos(3.1 * x)
    return np.column_stack([x, y])


#: CPU time of this process (``time.process_time``) instead of wall time: on a loaded
#: machine (other jobs on the same cores) it is the better estimate of the idle-machine
#: latency.  Set by ``--cpu``.
CLOCK = time.perf_counter


def _median(fn, values, warmup: int = 3) -> float:
    for v in values[:warmup]:
        fn(v)
    gc_was = gc.isenabled()
    gc.disable()
    try:
        ts = []
        for v in values:
            t0 = CLOCK()
            fn(v)
            ts.append(CLOCK() - t0)
    finally:
        if gc_was:
            gc.enable()
    return statistics.median(ts)


def measure(
    repeats: int = 60, segments: int = 12, samples: int = 400, ipympl: bool = True
) -> Latency:
    import matplotlib

    matplotlib.use("Agg")
    from course_lib.constructions.beta_splines import cubic_beta_spline
    from course_lib.geometry.sampling import (
        point_derivatives,
        segment_samples,
        tangent_and_curvature,
    )
    from course_lib.plotting.curvature import comb_teeth, curvature_profile
    from course_lib.widgets import CurveDemoView, beta_spline_demo, joint_report

    P = control_polygon(segments)
    values = list(np.geomspace(0.4, 3.0, repeats))

    # the demo's state with an Agg canvas and blitting, as in the browser minus PNG encoding
    demo = beta_spline_demo(P, static=True)
    st = demo.state
    assert st.curve.n_segments == segments
    st.samples = samples
    view = CurveDemoView(st, static=True, blit=True)
    view.fig.canvas.draw()  # first full draw: caches the background
    modes: dict = {}

    render = view.render

    def counted_render():
        m = render()
        modes[m] = modes.get(m, 0) + 1
        return m

    view.render = counted_render
    with_report = _median(lambda b: st.set_param("beta1", b), values)
    # the canvas is redrawn before the report is computed (CurveDemoState.update): the
    # latency the user sees on the canvas stops there
    compute_report = st.compute_report
    st.compute_report = lambda: None
    total = _median(lambda b: st.set_param("beta1", b), values)
    st.compute_report = compute_report

    view.render = lambda: "none"

    def compute(b):
        st.params["beta1"][:] = b
        st.curve = st.build(st.points, st.params)
        view.draw(st)

    compute_t = _median(compute, values)
    view.render = render

    n_comb = view.comb.per_segment
    n_prof = view.profile.per_segment

    def math_only(b):
        c = cubic_beta_spline(P, beta1=b, beta2=0.0)
        segment_samples(c, view.curve_artists.per_segment)
        comb_teeth(c, n_comb, 1.0)
        # the moving point with T and dT/ds, as FrameArtists.update computes them
        tangent_and_curvature(c, *point_derivatives(c, [st.t], (0, 1, 2))[1:], [st.t])
        curvature_profile(c, n_prof, arc_length_every=view.profile.arc_length_every)

    math_t = _median(math_only, values)
    report_t = _median(lambda b: joint_report(st.curve, st.joint), values)
    blit_t = _median(lambda b: view.render(), values)
    full_t = _median(lambda b: view.fig.canvas.draw(), values[: max(10, repeats // 3)])

    ipympl_t = None
    if ipympl:
        try:
            live = beta_spline_demo(P, static=False)
            live.state.samples = samples
            # as once a browser has connected: ipympl then sends only the diff PNG (no
            # full-frame data URL for the saved notebook)
            live.figure.canvas.syncing_data_url = False
            live.figure.canvas.draw()
            slider = live.controls["beta1"]
            ipympl_t = _median(lambda b: setattr(slider, "value", float(b)), values)
        except ImportError:
            ipympl_t = None

    return Latency(
        segments,
        samples,
        repeats,
        compute_t,
        math_t,
        report_t,
        blit_t,
        full_t,
        total,
        with_report,
        ipympl_t,
        modes,
    )


def main(argv: list[str] | None = None) -> Latency:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=60)
    ap.add_argument("--no-ipympl", action="store_true")
    ap.add_argument(
        "--cpu",
        action="store_true",
        help="time with process CPU time (for a machine busy with other jobs)",
    )
    args = ap.parse_args(argv)
    global CLOCK
    CLOCK = time.process_time if args.cpu else time.perf_counter
    r = measure(repeats=args.repeats, ipympl=not args.no_ipympl)
    for k, v in asdict(r).items():
        if isinstance(v, float):
            print(f"{k:28s} {v * 1e3:8.2f} ms")
        else:
            print(f"{k:28s} {v}")
    print(
        f"goal: total <= {GOAL_TOTAL * 1e3:.0f} ms and math <= {GOAL_COMPUTE * 1e3:.0f} ms:"
        f" {'met' if r.met else 'NOT met'}"
    )
    return r


if __name__ == "__main__":
    main()
