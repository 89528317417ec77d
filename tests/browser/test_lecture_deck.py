"""Lecture mode in a real browser: ``make present L=05`` at 1920×1080 (and 1366×768).

``tools/present.py`` builds the deck of lecture 05 and Voilà serves it with the course's
``course-deck`` template and a pre-heated kernel, exactly as ``make present`` does (here on
a free port, in a temporary folder).  Once the kernel has executed the deck, Chromium opens
the page at 1920×1080 and the test

1. times the page from ``goto`` until the first slide shows and every demo is live
   (goal: ≤ 10 s; recorded, asserted ≤ 30 s only, so a busy machine does not fail it);
2. measures from the DOM: body text ≥ 24 px, prose lines ≤ 85 characters, the first demo's
   canvas ≥ 60 % of the screen width;
3. presses PageDown (next slide) and moves a demo's slider: the canvas gets a new frame;
4. checks nothing was requested from another host and no console error occurred;
5. at 1366×768 checks that nothing scrolls horizontally;

and saves screenshots and ``lecture-deck.json`` to ``test-artifacts/``.
"""

from __future__ import annotations

import importlib.util
import json
import time
from pathlib import Path

import pytest
from browser_harness import WAIT_MS, WAIT_S, make_server, new_page

ROOT = Path(__file__).resolve().parents[2]
LECTURE = "05"
pytestmark = [pytest.mark.browser, pytest.mark.slow]


def _present():
    from tools import present

    return present


# prose metrics: font size, and characters per line estimated from each paragraph's height
METRICS_JS = """() => {
  const ps = Array.from(document.querySelectorAll('.jp-RenderedMarkdown p'))
    .filter(p => p.offsetParent !== null && p.textContent.trim().length > 0);
  const sizes = ps.map(p => parseFloat(getComputedStyle(p).fontSize));
  let maxChars = 0;
  for (const p of ps) {
    const lh = parseFloat(getComputedStyle(p).lineHeight);
    const lines = Math.round(p.getBoundingClientRect().height / lh);
    if (lines >= 3) maxChars = Math.max(maxChars, p.textContent.length / lines);
  }
  const canvas = document.querySelector('.cl-demo .jupyter-matplotlib-canvas-div canvas');
  return {
    paragraphs: ps.length, minFont: Math.min(...sizes), maxCharsPerLine: maxChars,
    canvasWidth: canvas ? canvas.getBoundingClientRect().width : 0,
    viewport: window.innerWidth,
    slides: document.querySelectorAll('section.deck-slide').length,
    horizontalOverflow: document.documentElement.scrollWidth - document.documentElement.clientWidth,
  };
}"""


@pytest.fixture(scope="module")
def deck_server(chromium_path, tmp_path_factory):
    if importlib.util.find_spec("voila") is None:
        pytest.skip("lecture mode untested: voila is not installed")
    present = _present()
    lecture = present.find_lecture(LECTURE)
    server = make_server("voila", tmp_path_factory, [])
    deck = present.build_deck(lecture, server.root)
    env = present.voila_env(server.env())
    cmd = present.voila_command(deck, server.port)
    t0 = time.monotonic()
    import subprocess

    server._log = server.log_path.open("wb")
    server.proc = subprocess.Popen(cmd, cwd=server.root, env=env, stdout=server._log,
                                   stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True)
    with server.serving("lecture-deck-voila.log", "the lecture-mode test"):
        ok = present.wait_preheated(server.root / present.READY, server.proc, timeout=WAIT_S)
        assert ok, f"the pre-heated kernel did not execute the deck:\n{server.log_tail()}"
        server.preheat_s = time.monotonic() - t0
        yield server


@pytest.mark.timeout(1800)  # a hang guard: waits are WAIT_S each
def test_lecture_deck_on_a_projector(deck_server, chromium_browser, artifacts):
    from playwright.sync_api import expect

    result = {"preheat (s)": round(deck_server.preheat_s, 1)}
    context, page, log = new_page(chromium_browser, width=1920, height=1080)
    try:
        page.add_init_script("""(() => {
          window.__clDraws = 0;
          const orig = CanvasRenderingContext2D.prototype.drawImage;
          CanvasRenderingContext2D.prototype.drawImage = function (...a) {
            if (this.canvas && this.canvas.isConnected) window.__clDraws++;
            return orig.apply(this, a);
          };
        })();""")
        t0 = time.monotonic()
        page.goto(f"{deck_server.url}/")
        expect(page.locator("section.deck-slide").first).to_be_visible(timeout=WAIT_MS)
        result["first slide visible (s)"] = round(time.monotonic() - t0, 2)
        expect(page.locator(".cl-demo").first).to_be_attached(timeout=WAIT_MS)
        n_demos = page.locator(".cl-demo").count()
        assert n_demos >= 1, "the deck shows no demo"
        expect(page.locator(".cl-demo .jupyter-matplotlib-canvas-div")).to_have_count(
            n_demos, timeout=WAIT_MS)
        page.wait_for_function("() => window.__clDraws > 0", timeout=WAIT_MS)
        result["every demo live (s)"] = round(time.monotonic() - t0, 2)
        page.screenshot(path=str(artifacts / "lecture-deck-1920-first-slide.png"))
        # WCAG 2.4.2: the tab names the lecture, not the file (the time above is recorded only)
        expect(page).to_have_title("5 · Curvature of plane curves", timeout=WAIT_MS)

        m = page.evaluate(METRICS_JS)
        result["1920x1080"] = m
        assert m["minFont"] >= 24, m
        assert 0 < m["maxCharsPerLine"] <= 85, m
        assert m["canvasWidth"] >= 0.6 * 1920, m
        assert m["slides"] >= 5, m
        assert m["horizontalOverflow"] <= 0, m

        # next slide with the keyboard, then the first demo's slide and its slider
        page.keyboard.press("PageDown")
        page.wait_for_timeout(300)
        top = page.evaluate(
            "() => document.querySelectorAll('section.deck-slide')[1].getBoundingClientRect().top")
        assert abs(top) < 5, f"PageDown: the second slide should be at the top, is at {top} px"
        demo = page.locator(".cl-demo").first
        slide = page.locator("section.deck-slide", has=demo).first
        slide.scroll_into_view_if_needed()
        page.evaluate("(e) => e.scrollIntoView({block: 'start'})", slide.element_handle())
        page.wait_for_timeout(500)
        handle = demo.locator(".noUi-handle").first
        report = demo.locator(".cl-report").first
        before = report.inner_text()
        draws = page.evaluate("() => window.__clDraws")
        handle.focus()
        for _ in range(3):
            page.keyboard.press("ArrowRight")
            page.wait_for_timeout(80)
        page.wait_for_function(f"() => window.__clDraws > {draws}", timeout=WAIT_MS)
        expect(report).not_to_have_text(before, timeout=WAIT_MS)
        page.wait_for_timeout(400)
        page.screenshot(path=str(artifacts / "lecture-deck-1920-demo.png"))
        assert not log.blocked, f"requests to other hosts: {log.blocked}"
        problems = log.problems()
        assert not problems, "\n".join(problems)

        # a laptop: nothing scrolls sideways
        page.set_viewport_size({"width": 1366, "height": 768})
        page.wait_for_timeout(500)
        m = page.evaluate(METRICS_JS)
        result["1366x768"] = m
        page.evaluate("(e) => e.scrollIntoView({block: 'start'})", slide.element_handle())
        page.wait_for_timeout(300)
        page.screenshot(path=str(artifacts / "lecture-deck-1366-demo.png"))
        assert m["horizontalOverflow"] <= 0, m
    finally:
        (artifacts / "lecture-deck.json").write_text(json.dumps(result, indent=1))
        context.close()
