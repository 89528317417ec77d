"""A real browser test: a lecture notebook's demo, live in JupyterLab and in Voilà.

JupyterLab (class ``TestJupyterLab``): a private server opens ``NOTEBOOK`` in headless
Chromium and runs all cells; then

1. no cell has an error output, no widget failed to render (``.jupyter-widgets-error-widget``);
2. a slider of the demo moved with the keyboard changes the live report (``.cl-report``) and
   the picture on the ipympl canvas (``.cl-canvas``; pixels compared before/after);
3. a design point dragged with the mouse moves *in the kernel* to where the mouse went, and the
   curve and the report change;
4. a screenshot after the interaction is kept in ``test-artifacts/``;
5. stopping the server leaves no process behind.

Voilà (class ``TestVoila``): the same notebook as an app; the slider changes the report and the
picture, and nothing is left running.

The kernel is asked where the demo's points are (``window.jupyterapp`` is exposed; the probe
looks for an object with ``state.points`` and ``view.ax``/``view.fig``, as
``course_lib.widgets.Demo`` has) and tags that demo's box with ``cl-test-target``, so a
notebook with several demos is fine.  Run alone: ``.venv/bin/python -m pytest tests/browser``
(screenshots, server logs and timings land in test-artifacts/).
"""

from __future__ import annotations

import importlib.util
import io
import json
import time
from pathlib import Path

import pytest
from browser_harness import (
    ARTIFACTS,
    RUN_STATE_JS,
    WAIT_MS,
    WAIT_S,
    kernel,
    make_server,
    new_page,
)

ROOT = Path(__file__).resolve().parents[2]

# The notebook the browser tests open (the only place to change it): the welcome lecture,
# whose "widget sanity check" displays course_lib.widgets.beta_spline_demo().  It must show a
# course_lib.widgets demo (test_notebook_shows_a_course_demo).  Alternatives in fixtures/:
# course_demo.ipynb (the same demo alone: the fallback if the lecture stops showing one) and
# widget_mechanics.ipynb (plain ipywidgets + ipympl, no course_lib: proves the harness alone
# when a failure has to be located; test_notebook_shows_a_course_demo then fails on purpose).
NOTEBOOK = ROOT / "notebooks" / "00_welcome.ipynb"

pytestmark = [pytest.mark.browser, pytest.mark.slow]

# Sliders tried in this order inside the demo (CONTRIBUTING.md, "Widget hooks").
SLIDERS = (".cl-slider-beta1", ".cl-slider-knot", ".cl-slider-beta2", ".cl-slider-t")
CANVAS = ".cl-canvas .jupyter-matplotlib-canvas-div"
TARGET = ".cl-test-target"
# console messages that are not the notebook's fault: requests we aborted on purpose
IGNORED_CONSOLE = ("net::ERR_FAILED",)
KERNEL_TIMEOUT_MS = WAIT_MS
RUN_ALL_TIMEOUT_MS = WAIT_MS


# ----------------------------------------------------------------------------- helpers
def pixels(png: bytes):
    import numpy as np
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def changed_pixels(a: bytes, b: bytes) -> int:
    """Number of pixels that differ between two screenshots of the same element."""
    import numpy as np

    pa, pb = pixels(a), pixels(b)
    if pa.shape != pb.shape:
        return max(pa.size, pb.size)
    return int(np.count_nonzero(np.any(pa != pb, axis=-1)))


def wait_for_new_picture(locator, before: bytes, *, timeout: float = WAIT_S,
                         min_pixels: int = 30) -> int:
    """Screenshot ``locator`` until it differs from ``before`` in >= ``min_pixels`` pixels."""
    deadline = time.monotonic() + timeout
    n = 0
    while time.monotonic() < deadline:
        locator.page.wait_for_timeout(150)
        n = changed_pixels(before, locator.screenshot())
        if n >= min_pixels:
            locator.page.wait_for_timeout(300)  # let the last redraw arrive
            return n
    raise AssertionError(f"the canvas did not change ({n} pixels differ after {timeout} s)")


def settle(canvas, report, *, quiet_ms: int = 500, timeout: float = WAIT_S) -> bytes:
    """Wait until the picture and the report stop changing (the kernel may still be working
    through queued events); return the final screenshot."""
    png, text = canvas.screenshot(), report.inner_text()
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        canvas.page.wait_for_timeout(quiet_ms)
        png2, text2 = canvas.screenshot(), report.inner_text()
        if png2 == png and text2 == text:
            return png
        png, text = png2, text2
    raise AssertionError(f"the demo kept changing for {timeout} s")


def find_slider(demo):
    for sel in SLIDERS:
        loc = demo.locator(f"{sel} .noUi-handle")
        if loc.count():
            return sel, loc.first
    raise AssertionError(f"the demo shows none of the sliders {SLIDERS}")


def move_slider(page, demo, steps: int = 3) -> tuple[str, str, int]:
    """Press ArrowRight ``steps`` times on the demo's first slider; return (selector, report
    before, changed canvas pixels) after checking that report and canvas changed."""
    from playwright.sync_api import expect

    report, canvas = demo.locator(".cl-report").first, demo.locator(CANVAS).first
    expect(report).not_to_be_empty()
    sel, handle = find_slider(demo)
    handle.scroll_into_view_if_needed()
    before_png = settle(canvas, report)
    before_text = report.inner_text()
    readout = demo.locator(f"{sel} .widget-readout").first
    before_value = readout.inner_text() if readout.count() else None
    handle.focus()
    for _ in range(steps):
        page.keyboard.press("ArrowRight")
        page.wait_for_timeout(60)
    if before_value is not None:
        expect(readout).not_to_have_text(before_value, timeout=WAIT_MS)
    expect(report).not_to_have_text(before_text, timeout=WAIT_MS)
    n = wait_for_new_picture(canvas, before_png)
    settle(canvas, report)
    return sel, before_text, n


def drag(page, x0: float, y0: float, x1: float, y1: float, steps: int = 8) -> None:
    """Mouse drag respecting ipympl's 33 ms trailing-edge throttle of mousemove (recipe)."""
    page.mouse.move(x0, y0)
    page.wait_for_timeout(60)
    page.mouse.down()
    page.wait_for_timeout(60)
    for i in range(1, steps + 1):
        page.mouse.move(x0 + (x1 - x0) * i / steps, y0 + (y1 - y0) * i / steps)
        page.wait_for_timeout(60)
    page.wait_for_timeout(150)
    page.mouse.up()


# Kernel side of the probe: find the first demo, tag its box, report its geometry in CSS
# pixels relative to the canvas' top-left corner.  Runs with store_history=False.
PROBE = r'''
def _cl_browser_probe(tag=False):
    import json

    import numpy as np

    ns = globals()
    out = ns.get("Out", {})
    pool = [out[k] for k in sorted(out)] + list(ns.values())

    def is_demo(v):
        try:
            return (not isinstance(v, type) and hasattr(v.view, "ax") and hasattr(v.view, "fig")
                    and hasattr(v.state, "points") and hasattr(v, "widget"))
        except Exception:
            return False

    demo = next((v for v in pool if is_demo(v)), None)
    if demo is None:
        return json.dumps(None)
    if tag:
        demo.widget.add_class("cl-test-target")
    ax, fig = demo.view.ax, demo.view.fig
    r = float(getattr(fig.canvas, "device_pixel_ratio", 1.0) or 1.0)
    H = float(fig.bbox.height)

    def css(xy):
        xy = np.atleast_2d(np.asarray(xy, dtype=float))
        return [[float(x / r), float((H - y) / r)] for x, y in ax.transData.transform(xy)]

    box = ax.get_window_extent()
    joint = None
    try:
        joint = css(demo.state.curve.joint_points[demo.state.joint])[0]
    except Exception:
        pass
    return json.dumps({
        "points": css(demo.state.points),
        "axes": [box.x0 / r, (H - box.y1) / r, box.x1 / r, (H - box.y0) / r],
        "figure": [float(fig.bbox.width / r), H / r],
        "joint": joint,
    })
'''

def probe(page, tag: bool = False) -> dict:
    kernel(page, PROBE)
    res = json.loads(kernel(page, f"print(_cl_browser_probe({tag}))").strip())
    assert res is not None, (
        f"{NOTEBOOK.name}: no demo found in the kernel (an object with .state.points, "
        ".view.ax, .view.fig and .widget, like course_lib.widgets.Demo)"
    )
    return res


def test_notebook_shows_a_course_demo():
    """The browser tests must exercise the real widgets, not a stand-in."""
    cells = json.loads(NOTEBOOK.read_text())["cells"]
    code = "\n".join("".join(c["source"]) for c in cells if c["cell_type"] == "code")
    assert "course_lib.widgets" in code and "_demo(" in code, (
        f"{NOTEBOOK.name} displays no course_lib.widgets demo"
    )


# ----------------------------------------------------------------------------- JupyterLab
class Session:
    """A server, the page showing the notebook, the page's log, what the run-all gave."""

    def __init__(self, server, page, log, timings, run_result=True):
        self.server, self.page, self.log, self.timings = server, page, log, timings
        self.run_result = run_result


@pytest.fixture(scope="module")
def voila_server(chromium_path, tmp_path_factory):
    """Voilà serving ``NOTEBOOK``, launched without waiting so that its start-up overlaps
    the JupyterLab tests (2 cores); ``None`` when voila is not installed."""
    if importlib.util.find_spec("voila") is None:
        yield None
        return
    server = make_server("voila", tmp_path_factory, [NOTEBOOK])
    with server.serving("voila-server.log", "the Voilà test"):
        server.launch(server.voila_command(NOTEBOOK.name))
        yield server


@pytest.fixture(scope="class")
def lab(request, chromium_path, voila_server, tmp_path_factory):
    """JupyterLab with ``NOTEBOOK`` opened and all its cells run; stopped afterwards."""
    from playwright.sync_api import expect

    assert NOTEBOOK.exists(), f"missing {NOTEBOOK}"
    server = make_server("lab", tmp_path_factory, [NOTEBOOK])
    context = None
    timings: dict[str, float] = {}
    t0 = time.monotonic()
    with server.serving("jupyterlab-server.log", "the JupyterLab test"):
        try:
            server.launch(server.lab_command())
            browser = request.getfixturevalue("chromium_browser")  # starts while the server does
            server.wait_ready()
            timings["server start"] = time.monotonic() - t0
            t = time.monotonic()
            server.start_kernel_for(NOTEBOOK.name)  # boots while the page loads
            timings["session created"] = time.monotonic() - t
            context, page, log = new_page(browser)
            t = time.monotonic()
            # no ?reset: the course's default layout (make lab's), table of contents open
            page.goto(f"{server.url}/lab/tree/{NOTEBOOK.name}?token={server.token}")
            # the status bar, not the execution indicator, tells when the kernel is really up
            expect(page.locator("#jp-main-statusbar")).to_contain_text(
                "| Idle", timeout=KERNEL_TIMEOUT_MS
            )
            timings["open until kernel idle"] = time.monotonic() - t
            t = time.monotonic()
            page.locator(".lm-MenuBar-item", has_text="Run").click()
            page.locator('.lm-Menu-item[data-command="runmenu:run-all"]').click()
            state = page.wait_for_function(RUN_STATE_JS, polling=250, timeout=RUN_ALL_TIMEOUT_MS)
            timings["run all cells"] = time.monotonic() - t
            yield Session(server, page, log, timings, state.json_value())
        finally:
            if context is not None:
                context.close()


@pytest.mark.timeout(1800)
class TestJupyterLab:
    def test_all_cells_run_without_errors(self, lab):
        from playwright.sync_api import expect

        page = lab.page
        # in the notebook model: every code cell ran, none has an error output
        assert lab.run_result is True, f"{NOTEBOOK.name}: {lab.run_result}"
        # the page agrees:
        tracebacks = page.locator(
            '.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]',
            has_text="Traceback",
        )
        assert tracebacks.count() == 0, tracebacks.first.inner_text()
        demo = page.locator(".cl-demo").first
        expect(demo).to_be_attached(timeout=WAIT_MS)
        demo.scroll_into_view_if_needed()
        expect(demo.locator(CANVAS).first).to_be_visible(timeout=WAIT_MS)
        expect(page.locator(".jupyter-widgets-error-widget")).to_have_count(0)
        problems = lab.log.problems(IGNORED_CONSOLE)
        assert not problems, "\n".join(problems)
        # the random token is really required
        assert lab.server.status_without_token("/api/kernels") == 403

    def test_slider_changes_report_and_curve(self, lab):
        page = lab.page
        probe(page, tag=True)
        demo = page.locator(TARGET)
        demo.scroll_into_view_if_needed()
        sel, _, n = move_slider(page, demo)
        assert n >= 30, f"{sel}: only {n} canvas pixels changed"

    def test_drag_moves_point_curve_and_report(self, lab, artifacts):
        from playwright.sync_api import expect

        page = lab.page
        geo = probe(page, tag=True)
        demo = page.locator(TARGET)
        canvas = demo.locator(CANVAS).first
        canvas.scroll_into_view_if_needed()
        box = canvas.bounding_box()
        assert abs(box["width"] - geo["figure"][0]) < 2 and abs(
            box["height"] - geo["figure"][1]
        ) < 2, f"canvas {box} is not the figure's size {geo['figure']}"
        # the point to drag: the one nearest the selected joint (or the first), inside the axes
        x0, y0, x1, y1 = geo["axes"]
        inside = [
            i for i, (x, y) in enumerate(geo["points"])
            if x0 + 25 < x < x1 - 25 and y0 + 25 < y < y1 - 25
        ]
        assert inside, f"no design point well inside the axes: {geo}"
        ref = geo["joint"] or geo["points"][inside[0]]
        k = min(inside, key=lambda i: (geo["points"][i][0] - ref[0]) ** 2
                + (geo["points"][i][1] - ref[1]) ** 2)
        px, py = geo["points"][k]
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2  # move 30 px towards the axes' centre
        d = max(((cx - px) ** 2 + (cy - py) ** 2) ** 0.5, 1e-9)
        tx, ty = (px + 30 * (cx - px) / d, py + 30 * (cy - py) / d) if d > 30 else (px + 30, py)

        report = demo.locator(".cl-report").first
        before_png = settle(canvas, report)
        before_text = report.inner_text()
        drag(page, box["x"] + px, box["y"] + py, box["x"] + tx, box["y"] + ty)
        # The kernel handles each motion event in turn (a redraw each, ~0.2 s on a busy
        # machine) and may still be at it: wait until the point has arrived (mouse events
        # carry whole pixels, hence the 2.5 px tolerance).
        deadline = time.monotonic() + 15
        while True:
            nx, ny = probe(page)["points"][k]
            if (abs(nx - tx) < 2.5 and abs(ny - ty) < 2.5) or time.monotonic() > deadline:
                break
            page.wait_for_timeout(250)
        assert abs(nx - tx) < 2.5 and abs(ny - ty) < 2.5, (
            f"point {k} should be at ({tx:.1f}, {ty:.1f}) px after the drag, "
            f"the kernel has it at ({nx:.1f}, {ny:.1f})"
        )
        n = wait_for_new_picture(canvas, before_png)
        assert n >= 30
        expect(report).not_to_have_text(before_text, timeout=WAIT_MS)
        settle(canvas, report)
        # no callback failed during the interaction
        errors = demo.locator(".cl-output").all_inner_texts()
        assert not "".join(errors).strip(), errors
        expect(page.locator(".jupyter-widgets-error-widget")).to_have_count(0)
        demo.screenshot(path=str(artifacts / "jupyterlab-demo-after-interaction.png"))
        page.screenshot(path=str(artifacts / "jupyterlab-notebook-after-interaction.png"))
        assert (artifacts / "jupyterlab-demo-after-interaction.png").stat().st_size > 0

    def test_course_settings_and_no_dead_widgets_after_saving(self, lab):
        """``make lab``'s configuration (.jupyter-course/): readable font, no news popup, the
        table of contents open, and a saved notebook holds no widget view that would be dead on reopening."""
        from playwright.sync_api import expect

        page = lab.page
        font = page.evaluate(
            "() => getComputedStyle(document.body).getPropertyValue('--jp-content-font-size1')")
        assert font.strip() == "16px", font
        expect(page.locator(".jp-toast-message", has_text="news")).to_have_count(0)
        # the course's layout opens with the table of contents in the left sidebar, listing
        # the open notebook's headings
        toc = page.locator("#table-of-contents")
        expect(toc).to_be_visible()
        expect(toc.locator(".jp-tocItem-content").first).to_be_visible()
        # a student's 1366×768 laptop: the demo fits the notebook column, nothing scrolls sideways
        page.set_viewport_size({"width": 1366, "height": 768})
        page.wait_for_timeout(500)
        demo = page.locator(".cl-demo").first
        demo.scroll_into_view_if_needed()
        overflow = page.evaluate("""() => {
          const el = document.querySelector('.jp-NotebookPanel .jp-WindowedPanel-outer')
            || document.querySelector('.jp-NotebookPanel .jp-Notebook');
          return el.scrollWidth - el.clientWidth;
        }""")
        page.screenshot(path=str(ARTIFACTS / "jupyterlab-1366x768.png"))
        assert overflow <= 0, f"the notebook scrolls sideways by {overflow} px at 1366×768"
        page.set_viewport_size({"width": 1400, "height": 1000})
        saved = lab.server.root / NOTEBOOK.name
        before = saved.stat().st_mtime_ns
        page.locator(".jp-NotebookPanel").first.click()
        page.keyboard.press("Escape")
        page.keyboard.press("Control+s")
        deadline = time.monotonic() + 20
        while saved.stat().st_mtime_ns == before and time.monotonic() < deadline:
            page.wait_for_timeout(200)
        nb = json.loads(saved.read_text())
        outputs = [o for c in nb["cells"] for o in c.get("outputs", [])]
        assert outputs, "the notebook was saved without its outputs"
        mimes = {k for o in outputs for k in o.get("data", {})}
        assert "application/vnd.jupyter.widget-view+json" not in mimes
        assert "widgets" not in nb["metadata"]
        from course_lib.widgets.saving import WIDGET_PLACEHOLDER

        assert any(WIDGET_PLACEHOLDER in "".join(o.get("data", {}).get("text/plain", ""))
                   for o in outputs)

    def test_stop_leaves_no_process(self, lab):
        lab.page.context.close()
        lab.server.stop()
        assert lab.server.returncode == 0, lab.server.log_tail()
        assert lab.server.leftovers == []
        (ARTIFACTS / "jupyterlab-timings.json").write_text(json.dumps(lab.timings, indent=1))


# ----------------------------------------------------------------------------- Voilà
@pytest.fixture(scope="class")
def voila_page(request, voila_server):
    """The Voilà app of ``NOTEBOOK`` in the browser, its demo rendered."""
    from playwright.sync_api import expect

    if voila_server is None:
        pytest.skip("browser test of the lecture mode skipped: voila is not installed")
    browser = request.getfixturevalue("chromium_browser")
    voila_server.wait_ready()
    context, page, log = new_page(browser)
    try:
        page.goto(f"{voila_server.url}/?token={voila_server.token}")
        demo = page.locator(".cl-demo").first
        expect(demo.locator(".cl-report")).not_to_be_empty(timeout=KERNEL_TIMEOUT_MS)
        expect(demo.locator(CANVAS).first).to_be_visible(timeout=WAIT_MS)
        yield Session(voila_server, page, log, {})
    finally:
        context.close()


@pytest.mark.timeout(1800)
class TestVoila:
    def test_slider_changes_report_and_curve(self, voila_page, artifacts):
        from playwright.sync_api import expect

        page = voila_page.page
        tracebacks = page.locator(".jp-OutputArea-output", has_text="Traceback")
        assert tracebacks.count() == 0, tracebacks.first.inner_text()
        expect(page.locator(".jupyter-widgets-error-widget")).to_have_count(0)
        # the random token is really required (no token: redirected to the login page)
        assert voila_page.server.status_without_token("/") in (302, 401, 403)
        demo = page.locator(".cl-demo").first
        sel, _, n = move_slider(page, demo)
        assert n >= 30, f"{sel}: only {n} canvas pixels changed"
        demo.screenshot(path=str(artifacts / "voila-demo-after-interaction.png"))
        # offline the lab template's CDN stylesheet is aborted by the route: not an error
        problems = voila_page.log.problems(IGNORED_CONSOLE)
        assert not problems, "\n".join(problems)

    def test_stop_leaves_no_process(self, voila_page):
        voila_page.page.context.close()
        voila_page.server.stop()
        assert voila_page.server.returncode == 0, voila_page.server.log_tail()
        assert voila_page.server.leftovers == []
