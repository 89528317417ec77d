"""Benchmark: how long from the hand to the picture, for every lecture demo, in a real browser.

A private JupyterLab opens ``fixtures/all_demos.ipynb`` (each lecture demo as the lectures
call it, and lecture 10's rotatable 3D patch pair) in headless Chromium and runs it.  For
each demo the test then

* presses an arrow key on its first slider ``N`` times (alternating right/left),
* drags a design point in ``N`` small mouse moves (the 3D pair: turns it),
* moves it 15 times more, one move every 33 ms as a hand does, and releases it at once,
  without waiting: records the time from the release to the last new frame (events queued
  in the kernel show there) and how far the released point is from the mouse,

and measures, *inside the page*, the time from the input event (a capturing listener's
``performance.now()``) to the first new picture on that demo's canvas (a wrapper around
``CanvasRenderingContext2D.drawImage``: ipympl paints every frame it receives with it).
After each interaction it waits until the demo is quiet, so every sample is one input on an
idle demo.  The medians go to ``test-artifacts/demo-latency.json`` and ``.md``.

It is a benchmark, not a timed assertion: the only assertions are that every input produced a
new picture (waits are generous: how soon is measured, never asserted) and that a released point
lands under the mouse (within 1.5 px of where the mouseup happened on the canvas, whatever the
load; how far the canvas moved in the page during the drag is reported).
"""

from __future__ import annotations

import json
import os
import statistics
import time
from pathlib import Path

import pytest
from browser_harness import RUN_STATE_JS, WAIT_MS, WAIT_S, kernel, make_server, new_page

HERE = Path(__file__).resolve().parent
NOTEBOOK = HERE / "fixtures" / "all_demos.ipynb"
DEMOS = ("beta_spline", "reparametrization", "g2_stitch", "knot_spline", "catmull_rom", "quartic")
SLIDERS = (".cl-slider-beta1", ".cl-slider-shape", ".cl-slider-knot", ".cl-slider-beta2",
           ".cl-slider-t")
N = int(os.environ.get("COURSE_LATENCY_SAMPLES", "10"))
QUIET_MS = 80  # no new frame for this long (and the kernel idle): the demo has finished

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# Installed before any page script: timestamps of inputs and of every frame painted on a
# visible canvas.
INIT_JS = """(() => {
  window.__clDraws = [];
  const orig = CanvasRenderingContext2D.prototype.drawImage;
  CanvasRenderingContext2D.prototype.drawImage = function (...args) {
    const c = this.canvas;
    if (c && c.isConnected) window.__clDraws.push({t: performance.now(), c});
    return orig.apply(this, args);
  };
  window.__clInput = 0;
  for (const type of ['keydown', 'mousemove', 'mousedown', 'mouseup'])
    window.addEventListener(type, () => { window.__clInput = performance.now(); }, true);
  // where the mouse was released, relative to the canvas it was released on (CSS px), taken
  // at the event: what the demo must put the point under, even if the page moved meanwhile
  window.__clUp = null;
  window.addEventListener('mouseup', (e) => {
    const r = e.target.getBoundingClientRect();
    window.__clUp = {x: e.clientX - r.left, y: e.clientY - r.top, canvas: e.target.tagName,
                     t: performance.now()};
  }, true);
})();"""

# ms from input time t0 to the first frame painted inside `sel` after it (null: none yet)
FIRST_DRAW_JS = """([sel, t0]) => {
  const root = document.querySelector(sel);
  if (!root) return null;
  for (let i = window.__clDraws.length - 1; i >= 0 && window.__clDraws[i].t > t0; i--) {
    const d = window.__clDraws[i];
    if (!root.contains(d.c)) continue;
    let first = d;
    for (let j = i - 1; j >= 0 && window.__clDraws[j].t > t0; j--)
      if (root.contains(window.__clDraws[j].c)) first = window.__clDraws[j];
    return first.t - t0;
  }
  return null;
}"""

LAST_DRAW_JS = """(sel) => {
  const root = document.querySelector(sel);
  for (let i = window.__clDraws.length - 1; i >= 0; i--)
    if (root.contains(window.__clDraws[i].c)) return window.__clDraws[i].t;
  return 0;
}"""

GEO = r'''
def _cl_geo(name):
    import json
    d = BENCH[name]
    ax, fig = d.view.ax, d.view.fig
    r = float(getattr(fig.canvas, "device_pixel_ratio", 1.0) or 1.0)
    H = float(fig.bbox.height)
    pts = [[float(x / r), float((H - y) / r)] for x, y in ax.transData.transform(d.state.points)]
    b = ax.get_window_extent()
    return json.dumps({"points": pts, "axes": [b.x0 / r, (H - b.y1) / r, b.x1 / r, (H - b.y0) / r]})
'''

KERNEL_IDLE_JS = """() => window.jupyterapp.shell.currentWidget.sessionContext.session.kernel
  .status === 'idle'"""


def quiet(page, sel: str, timeout: float = 10.0) -> None:
    """Wait until the kernel is idle and ``sel``'s canvas got no frame for QUIET_MS."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        last = page.evaluate(LAST_DRAW_JS, sel)
        now = page.evaluate("() => performance.now()")
        if now - last >= QUIET_MS and page.evaluate(KERNEL_IDLE_JS):
            return
        page.wait_for_timeout(QUIET_MS // 2)


def latency(page, sel: str) -> float:
    """ms from the last input event to the first new frame on ``sel``'s canvas."""
    t0 = page.evaluate("() => window.__clInput")
    # generous: a frame must come (that is asserted), how soon is measured, not asserted
    ms = page.wait_for_function(FIRST_DRAW_JS, arg=[sel, t0], polling=10, timeout=WAIT_MS)
    return float(ms.json_value())


def fast_drag_and_release(page, sel: str, x: float, y: float, dx: float,
                          moves: int = 15, name: str | None = None) -> float:
    """Move the (held) mouse ``moves`` times, one move every 33 ms as a hand does, release at
    once, without waiting for pictures; return the ms from the release to the last new frame
    (what queued up in the kernel, and the final frame)."""
    for i in range(moves):
        page.mouse.move(x + dx * (i + 1), y)
        if i < moves - 1:  # the hand lets go right after its last move
            page.wait_for_timeout(33)
    page.evaluate("() => { window.__clUp = null; }")
    page.mouse.up()
    # On a busy machine the page may still be dispatching queued moves when mouse.up()
    # returns: wait for the mouseup itself, then (a demo) for the kernel to have handled it
    # (the kernel reads comm messages and our requests in no guaranteed order: a state read
    # too early sees a point the release has not reached yet).
    t_up = page.wait_for_function("() => window.__clUp && window.__clUp.t",
                                  timeout=WAIT_MS).json_value()
    if name is not None:
        released(page, name)
    # the release sends a complete picture: wait for it (behaviour), then for the quiet
    page.wait_for_function(FIRST_DRAW_JS, arg=[sel, t_up], polling=10, timeout=WAIT_MS)
    page.wait_for_timeout(QUIET_MS)
    quiet(page, sel, timeout=30)
    return round(page.evaluate(LAST_DRAW_JS, sel) - t_up, 1)


def released(page, name: str) -> None:
    """Wait until the kernel has handled the mouse release of demo ``name`` (its dragger
    holds no point).  A hang guard only (WAIT_S): how long it takes is not asserted."""
    deadline = time.monotonic() + WAIT_S
    while kernel(page, f"print(BENCH[{name!r}].dragger.active is None)").strip() != "True":
        if time.monotonic() > deadline:
            raise AssertionError(f"{name}: the kernel did not handle the mouse release "
                                 f"within {WAIT_S:.0f} s")
        page.wait_for_timeout(100)


def median(xs):
    return round(statistics.median(xs), 1) if xs else None


@pytest.fixture(scope="module")
def bench_page(chromium_path, tmp_path_factory, request):
    from playwright.sync_api import expect

    server = make_server("lab", tmp_path_factory, [NOTEBOOK])
    context = None
    try:
        server.launch(server.lab_command())
        browser = request.getfixturevalue("chromium_browser")
        server.wait_ready()
        server.start_kernel_for(NOTEBOOK.name)
        context, page, _log = new_page(browser, width=1400, height=1000)
        page.add_init_script(INIT_JS)
        page.goto(f"{server.url}/lab/tree/{NOTEBOOK.name}?reset&token={server.token}")
        expect(page.locator("#jp-main-statusbar")).to_contain_text("| Idle", timeout=WAIT_MS)
        page.locator(".lm-MenuBar-item", has_text="Run").click()
        page.locator('.lm-Menu-item[data-command="runmenu:run-all"]').click()
        state = page.wait_for_function(RUN_STATE_JS, polling=250, timeout=WAIT_MS).json_value()
        assert state is True, state
        kernel(page, GEO)
        yield page
    finally:
        if context is not None:
            context.close()
        server.stop()
        server.save_log("latency-server.log")


def make_slider(demo):
    for sel in SLIDERS:
        loc = demo.locator(f"{sel} .noUi-handle")
        if loc.count():
            return sel, loc.first
    raise AssertionError("no slider in the demo")


@pytest.mark.timeout(1800)  # a hang guard only: on a loaded machine this test is slow, not wrong
def test_input_to_canvas_latency(bench_page, artifacts):
    page = bench_page
    load0 = os.getloadavg()
    rows = {}
    for name in DEMOS:
        sel = f".cl-bench-{name}"
        demo = page.locator(sel)
        demo.scroll_into_view_if_needed()
        canvas = demo.locator(".jupyter-matplotlib-canvas-div canvas").first
        canvas.wait_for(state="visible", timeout=WAIT_MS)
        quiet(page, sel)
        # -- slider: arrow keys, alternating so the value stays in range
        ssel, handle = make_slider(demo)
        handle.focus()
        slider = []
        for i in range(N):
            page.keyboard.press("ArrowRight" if i % 2 == 0 else "ArrowLeft")
            slider.append(latency(page, sel))
            quiet(page, sel)
        # -- drag the design point nearest the axes' centre, in small moves
        geo = json.loads(kernel(page, f"print(_cl_geo({name!r}))"))
        box = demo.locator(".jupyter-matplotlib-canvas-div").first.bounding_box()
        x0, y0, x1, y1 = geo["axes"]
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        inside = [(x, y) for x, y in geo["points"] if x0 + 40 < x < x1 - 40 and y0 + 40 < y < y1 - 40]
        px, py = min(inside, key=lambda p: (p[0] - cx) ** 2 + (p[1] - cy) ** 2)
        k = geo["points"].index([px, py])
        page.mouse.move(box["x"] + px, box["y"] + py)
        page.mouse.down()
        page.wait_for_timeout(60)
        quiet(page, sel)
        drag = []
        for i in range(N):
            dx = 8 if i % 2 == 0 else -4  # drifts right: ends 20 px from the start for N = 10
            px += dx
            page.mouse.move(box["x"] + px, box["y"] + py)
            drag.append(latency(page, sel))
            quiet(page, sel)
        settle = fast_drag_and_release(page, sel, box["x"] + px, box["y"] + py, -2.0,
                                       name=name)
        px -= 30
        up = page.evaluate("() => window.__clUp")
        moves = kernel(page, f"m = BENCH[{name!r}].dragger.moves; print(m.calls, m.dropped)")
        calls, dropped = (int(v) for v in moves.split())
        page.wait_for_timeout(200)
        nx, ny = json.loads(kernel(page, f"print(_cl_geo({name!r}))"))["points"][k]
        # Behaviour, not timing: the point is under the mouse where it was released *on the
        # canvas* (the page may scroll or reflow during a drag on a busy machine: the box
        # measured before the drag would then be stale; its drift is reported, not asserted).
        assert up is not None and up["canvas"] == "CANVAS", up
        err = round(max(abs(nx - up["x"]), abs(ny - up["y"])), 1)
        assert err <= 1.5, (
            f"{name}: released at ({up['x']:.1f}, {up['y']:.1f}) px on the canvas, "
            f"the point is at ({nx:.1f}, {ny:.1f})")
        drift = round(max(abs(up["x"] - px), abs(up["y"] - py)), 1)
        rows[name] = {"slider": median(slider), "slider control": ssel, "drag": median(drag),
                      "fast drag: release to final frame": settle,
                      "released point: px from the mouse": err,
                      "canvas moved during the drag (px)": drift, "n": N,
                      "moves handled / dropped as stale (whole test)": [calls, dropped],
                      "slider samples": [round(x, 1) for x in slider],
                      "drag samples": [round(x, 1) for x in drag]}

    # -- the 3D patch pair of lecture 10: turn the left panel
    sel = ".cl-bench-patches"
    fig = page.locator(sel).first
    fig.scroll_into_view_if_needed()
    fig.locator("canvas").first.wait_for(state="visible", timeout=WAIT_MS)
    quiet(page, sel)
    box = fig.locator(".jupyter-matplotlib-canvas-div").first.bounding_box()
    x, y = box["x"] + box["width"] * 0.25, box["y"] + box["height"] * 0.5
    page.mouse.move(x, y)
    page.mouse.down()
    page.wait_for_timeout(60)
    quiet(page, sel)
    turn = []
    for i in range(N):
        x += 15 if i % 2 == 0 else -10
        page.mouse.move(x, y)
        turn.append(latency(page, sel))
        quiet(page, sel)
    settle = fast_drag_and_release(page, sel, x, y, 3.0)
    rows["patch pair (3D)"] = {"slider": None, "drag": median(turn),
                               "fast drag: release to final frame": settle,
                               "released point: px from the mouse": None, "n": N,
                               "drag samples": [round(x, 1) for x in turn]}
    page.screenshot(path=str(artifacts / "latency-patches.png"))
    load1 = os.getloadavg()

    result = {"load average at start": load0, "load average at end": load1,
              "cpus": os.cpu_count(), "demos": rows}
    (artifacts / "demo-latency.json").write_text(json.dumps(result, indent=1))
    lines = [
        "| demo | slider → canvas (median ms) | drag → canvas (median ms) "
        "| fast drag: release → final frame (ms) | released point: px from the mouse |",
        "|---|---:|---:|---:|---:|",
    ]
    for name, r in rows.items():
        lines.append(f"| {name} | {r['slider'] if r['slider'] is not None else '—'} | "
                     f"{r['drag']} | {r['fast drag: release to final frame']} | "
                     f"{r['released point: px from the mouse'] if r['released point: px from the mouse'] is not None else '—'} |")
    lines.append(f"\nN = {N} interactions each; load average {load0[0]:.1f} at the start, "
                 f"{load1[0]:.1f} at the end, {os.cpu_count()} CPUs.")
    (artifacts / "demo-latency.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))
