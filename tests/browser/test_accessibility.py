"""Accessibility (WCAG 2.1 AA) of the website, the handouts and a live demo, in Chromium.

* **Site**: a small build (the welcome lecture and one homework, ``tools/build_site.py
  --only``; executions cached) served on 127.0.0.1; axe-core (npm ``axe-core``, pinned in
  ``tools/ensure-browser``, which installs it into ``build/a11y/``; or ``$COURSE_AXE`` = the
  path of ``axe.min.js``) is injected into each page after MathJax has typeset it, with the
  rules tagged ``wcag2a``, ``wcag2aa``, ``wcag21a``, ``wcag21aa``: no violation that is the
  course's own (the toolchain's are listed in ``UPSTREAM`` with their issue, and in the
  accessibility statement, ``site/accessibility.md``).  Every ``<img>`` has an ``alt`` that is a sentence,
  never empty or a file name.
* **Handouts**: the welcome lecture's PDF is tagged (a structure tree, ``/MarkInfo``), has
  ``/Lang``, a title and bookmarks, and its figure carries the cell's alt text.
* **JupyterLab, keyboard only**: the welcome notebook's demo; the slider handles have a name
  and a value text that is what the readout shows; a control point is selected with the
  point selector and moved with the arrow keys in its ``y`` field and with a nudge button —
  the point moves in the kernel and the live region (``role="status"``) says so; axe finds no
  violation of the course's own inside the demo.

Reports (JSON) land in ``test-artifacts/a11y/``.  Skipped with the reason when Playwright,
Chromium or axe-core is missing.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path

import pytest
from browser_harness import ARTIFACTS, RUN_STATE_JS, kernel, make_server, new_page

ROOT = Path(__file__).resolve().parents[2]

pytestmark = [pytest.mark.browser, pytest.mark.slow]

OUT = ARTIFACTS / "a11y"
AXE_ENV = "COURSE_AXE"
AXE_DEFAULT = ROOT / "build" / "a11y" / "node_modules" / "axe-core" / "axe.min.js"
AXE_VERSION = "4.14.1"
WCAG_TAGS = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]
LECTURE, HOMEWORK = "00_welcome", "hw02_beta_constraints"
PAGES = ["index.html", "course.html", f"lectures/{LECTURE}.html", f"homework/{HOMEWORK}.html"]
NOTEBOOK = ROOT / "notebooks" / f"{LECTURE}.ipynb"

#: Violations that are the toolchain's, not the course's: (rule id, a CSS-selector fragment
#: of the offending node, why, upstream issue).  The accessibility statement lists them.
UPSTREAM: list[tuple[str, str, str, str]] = []


def _axe_path() -> Path:
    path = Path(os.environ.get(AXE_ENV) or AXE_DEFAULT)
    if not path.is_file():
        pytest.skip(
            f"no axe-core at {path}: run `bash tools/ensure-browser` (npm install axe-core@"
            f"{AXE_VERSION} into build/a11y/) or set {AXE_ENV} to axe.min.js"
        )
    return path


def _upstream(rule: str, target: str) -> bool:
    return any(rule == r and frag in target for r, frag, _why, _url in UPSTREAM)


def run_axe(page, axe: Path, context: str = "document") -> list[dict]:
    """axe-core's violations of the WCAG 2.0/2.1 A and AA rules on ``page`` (within the
    element ``context`` selects); each as ``{"id", "impact", "help", "targets"}``."""
    if not page.evaluate("() => typeof window.axe !== 'undefined'"):
        page.add_script_tag(path=str(axe))
    assert page.evaluate("() => window.axe.version") == AXE_VERSION
    ctx = "document" if context == "document" else json.dumps(context)
    res = page.evaluate(
        f"""async () => {{
          const r = await window.axe.run({ctx}, {{runOnly: {{type: 'tag',
              values: {json.dumps(WCAG_TAGS)}}}, resultTypes: ['violations']}});
          return r.violations.map(v => ({{id: v.id, impact: v.impact, help: v.help,
              targets: v.nodes.map(n => n.target.join(' '))}}));
        }}"""
    )
    return res


def own_violations(violations: list[dict]) -> list[str]:
    out = []
    for v in violations:
        targets = [t for t in v["targets"] if not _upstream(v["id"], t)]
        if targets:
            out.append(f"{v['id']} ({v['impact']}: {v['help']}): {targets[:5]}")
    return out


# ----------------------------------------------------------------------------- the site
@pytest.fixture(scope="module")
def small_site(tmp_path_factory) -> Path:
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_nb")
    from tools import build_site

    out = tmp_path_factory.mktemp("a11y-site") / "html"
    build_site.build([LECTURE, HOMEWORK], out, 2, True)
    return out


@pytest.fixture(scope="module")
def handout(small_site, chromium_path, tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("a11y-handouts")
    subprocess.run(
        [sys.executable, str(ROOT / "tools" / "build_handouts.py"), "--site", str(small_site),
         "--out", str(out), "--only", LECTURE],
        check=True, cwd=ROOT, timeout=300,
    )  # fmt: skip
    return out / f"{LECTURE}.pdf"


class _Images(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.alts: list[tuple[str, str | None]] = []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            a = dict(attrs)
            self.alts.append((a.get("src", ""), a.get("alt")))


BAD_ALT = re.compile(r"^\S+\.(png|jpe?g|svg|gif)$|_images/|^\.\./", re.I)


def test_every_image_has_a_sentence_for_alt(small_site):
    problems = []
    n = 0
    for page in [*PAGES[2:]]:
        parser = _Images()
        parser.feed((small_site / page).read_text(encoding="utf-8"))
        for src, alt in parser.alts:
            if "_images/" not in src:  # figures (theme logos have their own alt)
                continue
            n += 1
            if not alt or BAD_ALT.search(alt) or len(alt.split()) < 5:
                problems.append(f"{page}: {src} has alt {alt!r}")
    assert n >= 1, "no figure found on the pages"
    assert not problems, "\n".join(problems)


def test_site_pages_have_no_wcag_violations_of_our_own(small_site, chromium_browser):
    from tools import build_handouts

    axe = _axe_path()
    OUT.mkdir(parents=True, exist_ok=True)
    report, problems = {}, []
    with build_handouts.serve(small_site) as base:
        context, page, _log = new_page(chromium_browser, width=1280, height=900)
        try:
            for rel in PAGES:
                build_handouts.open_ready(page, f"{base}/{rel}")
                lang = page.evaluate("() => document.documentElement.lang")
                if not lang.startswith("en"):
                    problems.append(f"{rel}: <html lang={lang!r}>")
                # MathJax: the formulas are no tab stops (no dead stops, WCAG 2.4.3)
                stops = page.evaluate(
                    "() => document.querySelectorAll('.MathJax[tabindex=\"0\"]').length"
                )
                if stops:
                    problems.append(f"{rel}: {stops} formulas are tab stops")
                violations = run_axe(page, axe)
                report[rel] = violations
                problems += [f"{rel}: {p}" for p in own_violations(violations)]
        finally:
            context.close()
    (OUT / "site-axe.json").write_text(json.dumps(report, indent=1, ensure_ascii=False))
    assert not problems, "\n".join(problems)


def test_handout_is_tagged_with_language_title_outline_and_alt_text(handout):
    from pypdf import PdfReader
    from pypdf.generic import IndirectObject

    reader = PdfReader(str(handout))
    root = reader.trailer["/Root"]
    assert "/StructTreeRoot" in root, "untagged PDF: no structure tree"
    assert bool(root.get("/MarkInfo", {}).get("/Marked")), "/MarkInfo /Marked is not true"
    assert str(root.get("/Lang", "")).startswith("en"), f"/Lang is {root.get('/Lang')!r}"
    assert "/Outlines" in root and reader.outline, "no bookmarks"
    assert reader.metadata and reader.metadata.title, "no document title"

    alts: list[str] = []

    def walk(node, depth=0):
        if isinstance(node, IndirectObject):
            node = node.get_object()
        if depth > 60:
            return
        if hasattr(node, "get"):
            if "/Alt" in node:
                alts.append(str(node["/Alt"]))
            kids = node.get("/K")
            if kids is not None:
                for k in kids if isinstance(kids, list) else [kids]:
                    walk(k, depth + 1)

    walk(root["/StructTreeRoot"])
    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    want = [
        " ".join(c["metadata"]["mystnb"]["image"]["alt"].split())
        for c in cells
        if c.get("metadata", {}).get("mystnb", {}).get("image", {}).get("alt")
    ]
    assert want, f"{NOTEBOOK.name} has no figure with alt text"
    got = {" ".join(a.split()) for a in alts}
    assert set(want) <= got, f"figure alt text missing from the structure tree: {want} vs {got}"


# ----------------------------------------------------------------------------- JupyterLab
KERNEL_TIMEOUT_MS = 90_000
RUN_ALL_TIMEOUT_MS = 120_000
POINTS_JS = r"""
def _cl_a11y_points():
    import json
    ns = globals()
    out = ns.get("Out", {})
    pool = [out[k] for k in sorted(out)] + list(ns.values())
    demo = next(v for v in pool if hasattr(v, "controls") and "points" in getattr(v, "controls", {}))
    return json.dumps(demo.state.points.tolist())
"""


@pytest.fixture(scope="module")
def lab(chromium_browser, tmp_path_factory):
    from playwright.sync_api import expect

    server = make_server("lab", tmp_path_factory, [NOTEBOOK])
    context = None
    try:
        server.launch(server.lab_command())
        server.wait_ready()
        server.start_kernel_for(NOTEBOOK.name)
        context, page, _log = new_page(chromium_browser)
        page.goto(f"{server.url}/lab/tree/{NOTEBOOK.name}?token={server.token}")
        expect(page.locator("#jp-main-statusbar")).to_contain_text(
            "| Idle", timeout=KERNEL_TIMEOUT_MS
        )
        page.locator(".lm-MenuBar-item", has_text="Run").click()
        page.locator('.lm-Menu-item[data-command="runmenu:run-all"]').click()
        state = page.wait_for_function(RUN_STATE_JS, polling=250, timeout=RUN_ALL_TIMEOUT_MS)
        assert state.json_value() is True, state.json_value()
        expect(page.locator(".cl-demo .cl-live").first).to_be_attached(timeout=30_000)
        yield page
    finally:
        if context is not None:
            context.close()
        server.stop()
        server.save_log("a11y-jupyterlab-server.log")


def _points(page) -> list[list[float]]:
    kernel(page, POINTS_JS)
    return json.loads(kernel(page, "print(_cl_a11y_points())").strip())


@pytest.mark.timeout(300)
def test_keyboard_only_moves_a_point_and_the_live_region_says_so(lab):
    from playwright.sync_api import expect

    page = lab
    demo = page.locator(".cl-demo").first
    live = demo.locator(".cl-live [role=status]").first
    expect(live).to_have_attribute("aria-live", "polite")
    expect(live).to_contain_text("Joint 0:")
    before_points = _points(page)

    # select P1 with the keyboard: focus the selector, arrow down
    select = demo.locator(".cl-point-select select").first
    select.focus()
    page.keyboard.press("ArrowDown")
    expect(live).to_contain_text("P1 selected", timeout=10_000)
    text0 = live.inner_text()

    # nudge it up with the arrow keys in its labelled y field
    y = demo.locator(".cl-point-y input").first
    label_for = demo.locator(".cl-point-y label").first.get_attribute("for")
    assert label_for and label_for == y.get_attribute("id"), "the y field's label is not linked"
    y.focus()
    for _ in range(3):
        page.keyboard.press("ArrowUp")
        page.wait_for_timeout(100)
    expect(live).not_to_have_text(text0, timeout=10_000)
    expect(live).to_contain_text("P1 moved to", timeout=10_000)
    after = _points(page)
    assert after[1][1] > before_points[1][1], (before_points[1], after[1])
    assert after[0] == before_points[0]

    # a nudge button, pressed with the keyboard
    text1 = live.inner_text()
    right = demo.locator(".cl-nudge-right button, button.cl-nudge-right").first
    right.focus()
    page.keyboard.press("Enter")
    expect(live).not_to_have_text(text1, timeout=10_000)
    assert _points(page)[1][0] > after[1][0]


def test_slider_handles_are_named_and_read_their_value(lab):
    from playwright.sync_api import expect

    demo = lab.locator(".cl-demo").first
    for css in (".cl-slider-beta1", ".cl-slider-beta2", ".cl-slider-t"):
        handle = demo.locator(f"{css} .noUi-handle").first
        label = demo.locator(f"{css} .widget-label").first.inner_text().strip()
        readout = demo.locator(f"{css} .widget-readout").first
        expect(handle).to_have_attribute("aria-label", label, timeout=10_000)
        expect(handle).to_have_attribute("aria-valuetext", readout.inner_text().strip())
    # β1 is a log slider: its value text is β1 itself (1), not the exponent (0)
    b1 = demo.locator(".cl-slider-beta1 .noUi-handle").first
    assert float(b1.get_attribute("aria-valuetext")) == pytest.approx(1.0)


def test_demo_has_no_wcag_violations_of_our_own(lab):
    axe = _axe_path()
    violations = run_axe(lab, axe, ".cl-demo")
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / "demo-axe.json").write_text(json.dumps(violations, indent=1, ensure_ascii=False))
    problems = own_violations(violations)
    assert not problems, "\n".join(problems)


def test_figure_alt_text_is_shown_under_the_demo(lab):
    from playwright.sync_api import expect

    cells = json.loads(NOTEBOOK.read_text(encoding="utf-8"))["cells"]
    (alt,) = [
        c["metadata"]["mystnb"]["image"]["alt"]
        for c in cells
        if c.get("metadata", {}).get("mystnb", {}).get("image", {}).get("alt")
    ]
    caption = lab.locator(".jp-RenderedMarkdown", has_text="Figure:").first
    expect(caption).to_contain_text(alt[:60], timeout=10_000)
