"""Keyboard only, in the lecture deck served by Voilà (``make present``; WCAG 2.1.1, 4.1.2, 4.1.3).

test_accessibility.py drives a demo with the keyboard in JupyterLab; this test does the same
in the projector deck (tools/present.py, template ``.jupyter-course/voila/templates/
course-deck``), which has a key handler of its own (PageDown and the arrow keys change the
slide).  The deck server is test_lecture_deck.py's fixture (lecture 05, pre-heated kernel).
With Tab, the arrow keys, Enter and Space only (no mouse, no ``element.click()``, no
``focus()``) the test

1. tabs from the top of the page to the first demo's point selector and selects P1 with
   ArrowDown: the live region (``role="status"``, ``aria-live``) says so;
2. tabs on to the point's ``y`` field and presses ArrowUp: the field's value and the live
   region change;
3. tabs on to the "→ right" nudge button and presses Space, then Enter: the ``x`` field and the
   live region change;
4. after every key, checks that the deck did not take the key (the page did not scroll to
   another slide);
5. checks that every slider handle in the demos has an ``aria-label`` (its label) and an
   ``aria-valuetext`` (its readout): the naming script (course_lib/widgets/slider_names.py)
   runs in Voilà too;
6. runs axe-core (WCAG 2.0/2.1 A and AA) on the deck page and inside the demo: no violation of
   the course's own inside the demo; the whole page's report is saved.

The same steps run in plain Voilà (``voila notebooks/07_stitching_bezier_curves.ipynb``, as
site/teaching.md prints it; Voilà's stock template, whose FontAwesome CDN requests are blocked
here and recorded).  Step 1 found a keyboard trap (WCAG 2.1.2): ipympl's canvas is a tab stop
whose keydown handler prevents every key, Tab included; slider_names.py now lets Tab through.

Times and axe's page-wide report are recorded in ``test-artifacts/a11y/deck-keyboard.json``
and ``voila-keyboard.json`` (never asserted).
"""

from __future__ import annotations

import importlib.util
import json
import os
import time
from pathlib import Path

import pytest
from browser_harness import WAIT_MS, make_server, new_page
from test_accessibility import AXE_DEFAULT, AXE_ENV, AXE_VERSION, OUT, own_violations, run_axe
from test_lecture_deck import deck_server  # noqa: F401  (the fixture: lecture 05's deck)

pytestmark = [pytest.mark.browser, pytest.mark.slow]
ROOT = Path(__file__).resolve().parents[2]

#: where the focus is: the classes of the closest course widget around document.activeElement
FOCUS_JS = """() => {
  const a = document.activeElement;
  if (!a || a === document.body) return {tag: 'BODY', where: ''};
  const box = a.closest('.cl-point-select, .cl-point-x, .cl-point-y, .cl-point-step, '
    + '[class*="cl-nudge-"], .widget-slider, .cl-demo');
  const where = box ? Array.from(box.classList).filter(c => c.startsWith('cl-')
    || c === 'widget-slider').join(' ') : '';
  return {tag: a.tagName, where, text: (a.textContent || '').trim().slice(0, 30),
          inDemo: !!a.closest('.cl-demo')};
}"""

SLIDES_JS = """() => ({y: Math.round(window.scrollY),
  nav: (document.getElementById('deck-nav') || {}).textContent || ''})"""


def _tab_to(page, css: str, limit: int = 400, key: str = "Tab") -> int:
    """Press ``key`` (Tab, or Shift+Tab) until the focused element matches ``css``;
    returns the number of presses."""
    for n in range(1, limit + 1):
        page.keyboard.press(key)
        if page.evaluate("(css) => !!document.activeElement?.matches(css)", css):
            return n
    f = page.evaluate(FOCUS_JS)
    raise AssertionError(f"{limit} presses of {key} never reached {css!r}; focus is on {f}")


def _press_in_place(page, key: str) -> None:
    """Press ``key`` and check the deck did not take it (no scroll to another slide)."""
    before = page.evaluate(SLIDES_JS)
    page.keyboard.press(key)
    page.wait_for_timeout(250)  # the deck's go() scrolls at once; give it the chance
    after = page.evaluate(SLIDES_JS)
    assert abs(after["y"] - before["y"]) <= 2, (
        f"{key} with the focus on {page.evaluate(FOCUS_JS)} moved the deck: {before} -> {after}")


def drive_by_keyboard(chromium_browser, url: str, name: str, result: dict, artifacts,
                      ignore: tuple[str, ...] = ()) -> None:
    """Steps 1-6 of the module docstring on the page at ``url``; records into ``result``
    and saves ``test-artifacts/a11y/<name>-*.json``."""
    from playwright.sync_api import expect

    context, page, log = new_page(chromium_browser, width=1920, height=1080)
    try:
        t0 = time.monotonic()
        page.goto(url)
        demo = page.locator(".cl-demo").filter(has=page.locator(".cl-point-select")).first
        live = demo.locator(".cl-live [role=status]").first
        expect(live).to_be_attached(timeout=WAIT_MS)
        expect(demo.locator(".jupyter-matplotlib-canvas-div")).to_be_visible(timeout=WAIT_MS)
        result["demo live (s)"] = round(time.monotonic() - t0, 2)
        expect(live).to_have_attribute("aria-live", "polite")

        # (5) the naming script ran in Voilà: every slider handle is named and reads its value
        sliders = page.locator(".cl-demo .widget-slider")
        n_sliders = sliders.count()
        assert n_sliders >= 1, "the deck's demos have no slider"
        for i in range(n_sliders):
            box = sliders.nth(i)
            handle = box.locator(".noUi-handle").first
            label = box.locator(".widget-label").first.inner_text().strip()
            readout = box.locator(".widget-readout").first.inner_text().strip()
            expect(handle).to_have_attribute("aria-label", label, timeout=WAIT_MS)
            expect(handle).to_have_attribute("aria-valuetext", readout)
        result["sliders named"] = n_sliders

        # (1) keyboard only from the top of the page: Tab to the point selector, ArrowDown
        t1 = time.monotonic()
        result["Tab presses to the point selector"] = _tab_to(page, ".cl-demo .cl-point-select select")
        result["tabbing (s)"] = round(time.monotonic() - t1, 2)
        f = page.evaluate(FOCUS_JS)
        assert f["tag"] == "SELECT" and f["inDemo"], f
        page.wait_for_timeout(500)  # focus may scroll the control into view: let it settle
        _press_in_place(page, "ArrowDown")
        expect(live).to_contain_text("P1 selected", timeout=WAIT_MS)
        text0 = live.inner_text()

        # (2) Tab to the y field, nudge it with the arrow keys
        y_field = demo.locator(".cl-point-y input").first
        x_field = demo.locator(".cl-point-x input").first
        y0, x0 = float(y_field.input_value()), float(x_field.input_value())
        result["Tab presses select -> y"] = _tab_to(page, ".cl-demo .cl-point-y input", limit=10)
        for _ in range(3):
            _press_in_place(page, "ArrowUp")
        expect(live).to_contain_text("P1 moved to", timeout=WAIT_MS)
        expect(live).not_to_have_text(text0, timeout=WAIT_MS)
        y1 = float(y_field.input_value())
        assert y1 > y0, f"ArrowUp in the y field: y stayed {y0} -> {y1}"
        assert float(x_field.input_value()) == x0

        # (3) Tab to the "right" nudge button; Space, then Enter
        result["Tab presses y -> nudge right"] = _tab_to(
            page, ".cl-demo .cl-nudge-right button, .cl-demo button.cl-nudge-right", limit=20)
        for key in (" ", "Enter"):
            text1, shown = live.inner_text(), x_field.input_value()
            x1 = float(shown)
            _press_in_place(page, key)
            expect(live).not_to_have_text(text1, timeout=WAIT_MS)
            # wait for the field's own text to change: it shows "1", and a wait for a change
            # from str(1.0) == "1.0" passed at once (a busy machine's late update then failed)
            expect(x_field).not_to_have_value(shown, timeout=WAIT_MS)
            assert float(x_field.input_value()) > x1, (key, x1, x_field.input_value())
        result["live region at the end"] = live.inner_text()
        page.screenshot(path=str(artifacts / f"{name}-demo.png"))

        # a focused slider handle keeps the arrow keys too (Shift+Tab back to the last slider)
        result["Shift+Tab presses back to a slider"] = _tab_to(
            page, ".cl-demo .widget-slider .noUi-handle", limit=60, key="Shift+Tab")
        slider = demo.locator(".widget-slider", has=page.locator(".noUi-handle:focus")).first
        readout = slider.locator(".widget-readout").first
        handle = slider.locator(".noUi-handle").first
        report = demo.locator(".cl-report").first
        r0, rep0 = readout.inner_text(), report.inner_text()
        at_max = handle.get_attribute("aria-valuenow") == handle.get_attribute("aria-valuemax")
        # the slider's step is finer than its readout: several presses, and the report shows it;
        # PageUp/PageDown are the deck's slide keys and must stay with the slider too
        keys = ["ArrowLeft"] * 3 + ["PageDown"] * 2 if at_max else ["ArrowRight"] * 3 + ["PageUp"] * 2
        for k in keys:
            _press_in_place(page, k)
        expect(report).not_to_have_text(rep0, timeout=WAIT_MS)
        result["slider readout before, after"] = [r0, readout.inner_text()]
        expect(handle).to_have_attribute(
            "aria-valuetext", readout.inner_text().strip(), timeout=WAIT_MS)
        result["blocked outside requests"] = log.blocked
        problems = log.problems(ignore)
        assert not problems, "\n".join(problems)

        # (6) axe-core on the deck page (saved) and inside the demo (asserted)
        axe = os.environ.get(AXE_ENV) or str(AXE_DEFAULT)
        if not os.path.isfile(axe):
            result["axe"] = f"skipped: no axe-core {AXE_VERSION} at {axe}"
            return
        page_violations = run_axe(page, Path(axe))
        demo_violations = run_axe(page, Path(axe), ".cl-demo")
        OUT.mkdir(parents=True, exist_ok=True)
        (OUT / f"{name}-axe.json").write_text(json.dumps(
            {"page": page_violations, "demo": demo_violations}, indent=1, ensure_ascii=False))
        result["axe page violations"] = own_violations(page_violations)
        if name == "deck-keyboard":  # the course's deck: every figure has its text alternative
            assert not [v for v in page_violations if v["id"] == "image-alt"], page_violations
        own = own_violations(demo_violations)
        assert not own, "\n".join(own)
    finally:
        OUT.mkdir(parents=True, exist_ok=True)
        (OUT / f"{name}.json").write_text(json.dumps(result, indent=1, ensure_ascii=False))
        context.close()


@pytest.mark.timeout(1800)  # a hang guard: waits are WAIT_S each
def test_deck_demo_by_keyboard_only(deck_server, chromium_browser, artifacts):  # noqa: F811
    result: dict = {"preheat (s)": round(deck_server.preheat_s, 1)}
    drive_by_keyboard(chromium_browser, f"{deck_server.url}/", "deck-keyboard", result, artifacts)
    assert not result["blocked outside requests"], result["blocked outside requests"]


PLAIN = ROOT / "notebooks" / "07_stitching_bezier_curves.ipynb"


@pytest.fixture(scope="module")
def plain_voila(chromium_path, tmp_path_factory):
    """``voila notebooks/07_stitching_bezier_curves.ipynb`` (site/teaching.md), on a free port."""
    if importlib.util.find_spec("voila") is None:
        pytest.skip("plain Voilà untested: voila is not installed")
    server = make_server("voila", tmp_path_factory, [PLAIN])
    with server.serving("voila-keyboard-server.log", "the plain Voilà test"):
        server.launch(server.voila_command(PLAIN.name))
        server.wait_ready()
        yield server


@pytest.mark.timeout(1800)
def test_plain_voila_demo_by_keyboard_only(plain_voila, chromium_browser, artifacts):
    # Voilà's stock lab template loads FontAwesome from a CDN: blocked here (no network),
    # which gives console errors that are not the course's
    result: dict = {}
    drive_by_keyboard(chromium_browser, f"{plain_voila.url}/?token={plain_voila.token}",
                      "voila-keyboard", result, artifacts, ignore=("ERR_FAILED", "net::"))
