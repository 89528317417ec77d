"""The course website (``make site``) and the handouts (``make handouts``).

Built once per module (``site`` and ``handouts`` fixtures: the whole site into a temporary
folder, execution cached in ``build/site-cache/``, then one PDF per lecture), then:

* every lecture and blank homework has a page; no solution notebook, no hidden test;
* a link checker over the built HTML: every internal link and anchor resolves, and no script,
  style sheet, font or image is loaded from another host (no CDN);
* headless Chromium (Debian's, through Playwright; every request to another host aborted)
  opens the index and a lecture page: MathJax has typeset the math and no raw ``$…$`` or
  ``\\(…\\)`` is left in the text, every image has loaded (``naturalWidth > 0``), nothing was
  asked of the network; screenshots go to ``test-artifacts/site/``;
* each PDF has a plausible number of pages for its lecture and contains the caption (the
  prose around the picture, read from the lecture's markdown) of every seed figure that
  the figure table (``site/figures.md``) places in that lecture;
* no solution marker, solution line, hidden-test name or hidden-test message anywhere in the
  site or the PDFs.

The fast tests at the end check the page preparation on small synthetic notebooks.
"""

from __future__ import annotations

import ast
import concurrent.futures as cf
import functools
import html
import json
import math
import re
import subprocess
import sys
import time
import unicodedata
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest
from _homework_support import load

from tools import build_handouts, build_site

ROOT = Path(__file__).resolve().parents[1]
ARTIFACTS = ROOT / "test-artifacts" / "site"
LECTURE = "01_parametric_continuity"  # the lecture page screenshot in the browser
# the pages opened in the browser (3 s each): name -> path in the site.  Every page is
# checked for raw TeX without a browser (test_no_raw_tex_on_any_page).
PAGES = {"index": "index.html", "course": "course.html", LECTURE: f"lectures/{LECTURE}.html"}
PAGES |= {p.stem: f"homework/{p.stem}.html" for p in sorted((ROOT / "exercises").glob("hw*.ipynb"))[:1]}




# ----------------------------------------------------------------------------- fixtures
@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    pytest.importorskip("sphinx")
    pytest.importorskip("myst_nb")
    out = tmp_path_factory.mktemp("site") / "html"
    t0 = time.perf_counter()
    build_site.build(None, out, 2, True)
    _timing("site", time.perf_counter() - t0)
    return out


@pytest.fixture(scope="module")
def chromium() -> str:
    pytest.importorskip("playwright.sync_api", reason="Playwright is not installed")
    path = build_handouts.find_chromium()
    if path is None:
        pytest.skip("no Chromium (/usr/bin/chromium or $COURSE_CHROMIUM): bash tools/ensure-browser")
    return path


@pytest.fixture(scope="module")
def handouts(site, chromium, tmp_path_factory) -> dict[str, Path]:
    out = tmp_path_factory.mktemp("handouts")
    t0 = time.perf_counter()
    # a subprocess, as `make handouts` runs it (and Playwright's sync API cannot be nested in a
    # thread that already runs one, as the browser tests' session fixture may)
    subprocess.run(
        [sys.executable, str(ROOT / "tools" / "build_handouts.py"), "--site", str(site),
         "--out", str(out)],
        check=True, cwd=ROOT, timeout=300,
    )
    _timing("handouts", time.perf_counter() - t0)
    return {p.stem: p for p in sorted(out.glob("*.pdf"))}


def _timing(what: str, seconds: float) -> None:
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    path = ARTIFACTS / "timings.json"
    data = json.loads(path.read_text()) if path.exists() else {}
    data[what] = round(seconds, 1)
    path.write_text(json.dumps(data, indent=1))


def _in_thread(fn, *args):
    """Run ``fn`` in a fresh thread (its own Playwright, whatever this thread runs)."""
    with cf.ThreadPoolExecutor(1) as pool:
        return pool.submit(fn, *args).result()


# ------------------------------------------------------------------------ HTML parsing
_VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
         "track", "wbr"}


class _Links(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.prose: list[str] = []  # text outside code, math and outputs
        self.ids: set[str] = set()
        self.refs: list[tuple[str, str, str]] = []  # (tag, attribute, url)
        self.text: list[str] = []
        self._skip = 0
        self._stack: list[bool] = []  # per open element: is it (inside) code or math?

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if a.get("id"):
            self.ids.add(a["id"])
        if tag == "a" and a.get("name"):
            self.ids.add(a["name"])
        for attr in ("href", "src"):
            if a.get(attr):
                rel = a.get("rel") or ""
                self.refs.append((f"{tag}:{rel}" if tag == "link" else tag, attr, a[attr]))
        if tag in ("script", "style"):
            self._skip += 1
        if tag not in _VOID:
            cls = a.get("class") or ""
            code = tag in ("pre", "code", "script", "style", "kbd", "samp", "title") or bool(
                re.search(r"\bmath\b|highlight|output_text|output_stream|text_html", cls))
            self._stack.append(code or (bool(self._stack) and self._stack[-1]))

    def handle_endtag(self, tag):
        if tag in ("script", "style") and self._skip:
            self._skip -= 1
        if tag not in _VOID and self._stack:
            self._stack.pop()

    def handle_data(self, data):
        if not self._skip:
            self.text.append(data)
        if not (self._stack and self._stack[-1]):
            self.prose.append(data)


def _parse(path: Path) -> _Links:
    p = _Links()
    p.feed(path.read_text(errors="replace"))
    return p


def _html_files(site: Path) -> list[Path]:
    return sorted(site.rglob("*.html"))


def _site_text(site: Path, guides: bool = True) -> str:
    """Everything a reader (or a search engine) can get from the site; with
    ``guides=False`` without the guides (``site/*.md``) and the search index that holds
    their words: they name the instructors' folders (``solutions/hidden_tests/``) on purpose."""
    names = {f"{g}.html" for _, gs in build_site.GUIDES for g in gs}
    parts = [html.unescape(p.read_text(errors="replace")) for p in _html_files(site)
             if guides or p.relative_to(site).as_posix() not in names]  # fmt: skip
    parts += [p.read_text(errors="replace") for p in site.rglob("*.js") if "mathjax" not in p.parts
              and (guides or p.name != "searchindex.js")]  # fmt: skip
    parts += [p.read_text(errors="replace") for p in site.rglob("*.txt")]
    return "\n".join(parts)


@functools.cache
def _pdf_text(pdf: Path) -> str:
    """The PDF's text (pypdf; 1-3 s per handout, so read once per session)."""
    from pypdf import PdfReader

    return "\n".join(page.extract_text() or "" for page in PdfReader(str(pdf)).pages)


MATH_GLYPHS = re.compile("[\U0001D400-\U0001D7FF]")
FOOTER = re.compile(r"^.* — Geometric continuity — \d+/\d+$")


def _prose(pdf_text: str) -> str:
    """The PDF's text without the page footers and the lines of typeset math (text
    extraction puts a page's math glyphs at its end, in the middle of a sentence that runs
    over to the next page)."""
    return "\n".join(
        line for line in pdf_text.splitlines()
        if not FOOTER.match(line) and not MATH_GLYPHS.search(line)
    )


def _squash(text: str) -> str:
    """Letters and digits only, lower case, ligatures (ﬁ, ﬀ) undone: robust against PDF line
    breaks and spacing."""
    return re.sub(r"[^0-9a-z]", "", unicodedata.normalize("NFKC", text).lower())


# ------------------------------------------------------------------------------ tests


@pytest.mark.slow
def test_every_lecture_and_homework_has_a_page_and_no_solution_is_there(site):
    lectures = sorted(p.stem for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
    homework = sorted(p.stem for p in (ROOT / "exercises").glob("hw*.ipynb"))
    assert lectures and homework
    for stem in lectures:
        assert (site / "lectures" / f"{stem}.html").is_file(), stem
    for stem in homework:
        assert (site / "homework" / f"{stem}.html").is_file(), stem
    for name in ("index.html", "course.html", "search.html", "searchindex.js"):
        assert (site / name).is_file(), name
    for _, guides in build_site.GUIDES:  # the guides the README links
        for name in guides:
            assert (site / f"{name}.html").is_file(), name
    names = {p.relative_to(site).as_posix() for p in site.rglob("*")}
    assert not [n for n in names if re.search(r"solution|hidden_test|homework_src", n, re.I)]
    # the live-demo note is on the page of every lecture that shows a demo
    def live_demo(cell):
        src = "".join(cell["source"])
        return cell["cell_type"] == "code" and build_site.DEMO_CALL.search(src) and not re.search(
            r"static\s*=\s*True", src)

    demo_pages = [s for s in lectures if any(
        live_demo(c) for c in json.loads((ROOT / "notebooks" / f"{s}.ipynb").read_text())["cells"])]
    assert demo_pages
    for stem in lectures:  # static pictures, never a widget view without a kernel behind it
        page = (site / "lectures" / f"{stem}.html").read_text()
        assert "widget-view+json" not in page and "<img" in page, stem
    for stem in demo_pages:
        assert "live-demo" in (site / "lectures" / f"{stem}.html").read_text(), stem


@pytest.mark.slow
def test_internal_links_resolve_and_nothing_comes_from_another_host(site):
    parsed = {p: _parse(p) for p in _html_files(site)}
    broken, external = [], []
    for page, links in parsed.items():
        for tag, attr, url in links.refs:
            parts = urlsplit(url)
            if parts.scheme in ("http", "https") or url.startswith("//"):
                # a hyperlink to a paper or a project page is fine; a resource is not
                if tag != "a":
                    external.append(f"{page.relative_to(site)}: <{tag} {attr}={url}>")
                continue
            if parts.scheme in ("mailto", "data", "javascript") or not (parts.path or parts.fragment):
                continue
            target = (page.parent / unquote(parts.path)).resolve() if parts.path else page
            if target.is_dir():
                target = target / "index.html"
            if not target.exists():
                broken.append(f"{page.relative_to(site)}: {url}")
                continue
            if parts.fragment and target.suffix == ".html":
                ids = parsed[target].ids if target in parsed else _parse(target).ids
                if unquote(parts.fragment) not in ids:
                    broken.append(f"{page.relative_to(site)}: {url} (no such anchor)")
    assert not broken, "broken internal links:\n" + "\n".join(broken[:40])
    assert not external, "resources from another host:\n" + "\n".join(external[:40])
    # style sheets must not pull fonts or imports from the network either
    for css in site.rglob("*.css"):
        hits = re.findall(r"(?:url\(|@import)\s*['\"]?(?:https?:)?//[^)'\"]+", css.read_text(errors="replace"))
        assert not hits, f"{css.relative_to(site)}: {hits[:3]}"
    # the figure table links into the lecture pages, at the cells it names
    figures = parsed[site / "figures.html"]
    cell_links = [u for _, _, u in figures.refs if "#cell-" in u]
    assert len(cell_links) >= 20, cell_links
    # the course map links every lecture's page
    course = parsed[site / "course.html"]
    lectures = {Path(urlsplit(u).path).stem for _, _, u in course.refs if "lectures/" in u}
    assert lectures == {p.stem for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb")}


def _browse(site: Path, chromium: str) -> dict:
    """Open the index and a lecture page; returns what the tests assert on."""
    from playwright.sync_api import sync_playwright

    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    result = {}
    with build_handouts.serve(site) as base, sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium, headless=True,
                                     args=["--no-sandbox", "--disable-gpu"])
        try:
            blocked: list[str] = []
            page = build_handouts.offline_page(browser, base, blocked)
            errors: list[str] = []
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.on("response", lambda r: r.status >= 400 and errors.append(f"{r.status} {r.url}"))
            for name, rel in PAGES.items():
                build_handouts.open_ready(page, f"{base}/{rel}")
                page.screenshot(path=str(ARTIFACTS / f"{name}.png"))
                result[name] = page.evaluate(
                    """() => {
                      const art = document.querySelector('article') || document.body;
                      const clone = art.cloneNode(true);
                      clone.querySelectorAll('pre, code, script, style, .MathJax, .MathJax_Display, '
                        + '.MathJax_Preview, .MJX_Assistive_MathML, .output.text_html')
                        .forEach(e => e.remove());
                      const imgs = Array.from(document.images);
                      return {
                        text: clone.textContent,
                        math: document.querySelectorAll('.MathJax, .MathJax_Display').length,
                        mathSources: document.querySelectorAll('.math.notranslate').length,
                        mathErrors: document.querySelectorAll('.MathJax .merror, .mjx-merror').length,
                        images: imgs.map(i => [i.getAttribute('src'), i.complete, i.naturalWidth]),
                        title: document.title,
                        hiddenInputs: document.querySelectorAll('.tag_hide-input details, details.hide.above-input').length,
                      };
                    }"""
                )
            # a screenshot at a figure, further down the lecture
            build_handouts.open_ready(page, f"{base}/{PAGES[LECTURE]}")
            figure = page.locator("div.cell_output img").nth(1)
            figure.scroll_into_view_if_needed()
            page.screenshot(path=str(ARTIFACTS / "lecture-figure.png"))
            # full-text search works offline (Sphinx's search index, no server)
            page.goto(f"{base}/search.html?q=curvature", wait_until="load")
            page.wait_for_selector("#search-results ul.search li", timeout=30_000)
            result["search"] = page.eval_on_selector_all(
                "#search-results ul.search li a", "els => els.map(e => e.getAttribute('href'))")
            page.screenshot(path=str(ARTIFACTS / "search.png"))
            result["blocked"], result["errors"] = blocked, errors
        finally:
            browser.close()
    return result


@pytest.fixture(scope="module")
def browsed(site, chromium) -> dict:
    t0 = time.perf_counter()
    out = _in_thread(_browse, site, chromium)
    _timing("browser", time.perf_counter() - t0)
    return out


@pytest.mark.slow
def test_no_raw_tex_on_any_page(site):
    """MyST turned every $…$ of the prose into math: none is left as text (the browser test
    then sees MathJax typeset it).  The tab title (``<title>``) is plain text, checked by
    test_tab_titles_are_plain_text_and_headings_keep_their_math."""
    found = []
    for page in _html_files(site):
        prose = " ".join(_parse(page).prose)
        found += [f"{page.relative_to(site)}: {m!r}" for m in RAW_TEX.findall(prose)]
    assert not found, "\n".join(found[:20])


class _Title(HTMLParser):
    """The text of ``<title>``, of the heading printed on paper (sphinx-book-theme's
    ``#jb-print-docs-body h1``) and of the page's own first ``<h1>``."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.title, self.print_h1, self.h1, self._in, self._print = "", "", "", None, False

    def handle_starttag(self, tag, attrs):
        if dict(attrs).get("id") == "jb-print-docs-body":
            self._print = True
        if tag == "title":
            self._in = "title"
        elif tag == "h1" and self._print and not self.print_h1:
            self._in = "print_h1"
        elif tag == "h1" and not self._print and not self.h1:
            self._in = "h1"

    def handle_endtag(self, tag):
        if tag == self._in or (tag == "h1" and self._in):
            self._in, self._print = None, self._print and self._in != "print_h1"

    def handle_data(self, data):
        if self._in:
            setattr(self, self._in, getattr(self, self._in) + data)


@pytest.mark.slow
def test_tab_titles_are_plain_text_and_headings_keep_their_math(site):
    """Browser tabs and printed pages (the handouts) show readable titles (``Gⁿ``, not
    ``\\(G^n\\)`` or ``G^n``); the page's own heading keeps its math for MathJax."""
    bad = []
    for page in _html_files(site):
        p = _Title()
        p.feed(page.read_text(errors="replace"))
        for text in (p.title, p.print_h1):
            if RAW_TEX.search(text) or "\\" in text or "$" in text or "^" in text:
                bad.append(f"{page.relative_to(site)}: {text!r}")
    assert not bad, "\n".join(bad)
    lecture9 = next(site.glob("lectures/09_*.html"))
    p = _Title()
    p.feed(lecture9.read_text(errors="replace"))
    plain = "9 · Higher order: the quartic G3 Beta-spline and Gⁿ"
    assert p.title.startswith(plain)
    assert p.print_h1.strip() == plain, "the heading of the printed page (handouts)"
    assert "\\(G^n\\)" in p.h1, f"the heading keeps its math: {p.h1!r}"


def test_tab_title_text_from_tex():
    conf = _load_conf()
    assert conf.tex_to_text("G^n") == "Gⁿ"
    assert conf.tex_to_text("\\beta_1 > 0") == "β₁ > 0"
    assert conf.tex_to_text("G^{n+1}") == "Gⁿ⁺¹"
    assert conf.tex_to_text("x^{ab}") == "x^(ab)"  # no superscript letters a, b: spelled out
    title = '7 · Higher order, <span class="math">\\(G^n\\)</span>, and $C^2$'
    assert conf.plain_title(title) == '7 · Higher order, <span class="math">Gⁿ</span>, and C²'
    assert conf.plain_title("no math here") == "no math here"


def _load_conf():
    return load("site_conf", ROOT / "site" / "conf.py")


@pytest.mark.slow
@pytest.mark.browser
def test_search_finds_the_lectures_offline(browsed):
    hits = browsed["search"]
    assert any(h.startswith("lectures/03_") for h in hits), hits
    assert not browsed["blocked"]


RAW_TEX = re.compile(r"\$[^$\n]{1,200}\$|\\\(|\\\)|\\\[|\\\]|\\begin\{|\\frac|\\mathbf")


@pytest.mark.slow
@pytest.mark.browser
@pytest.mark.parametrize("name", list(PAGES))
def test_pages_render_math_and_images_offline(browsed, name):
    r = browsed[name]
    assert not browsed["blocked"], f"asked the network for {browsed['blocked']}"
    assert not browsed["errors"], browsed["errors"]
    raw = RAW_TEX.findall(r["text"])
    assert not raw, f"{name}: raw TeX left in the text: {raw[:5]}"
    if r["mathSources"]:
        assert r["math"] >= r["mathSources"] * 0.9, r
    assert r["mathErrors"] == 0, r
    assert all(complete and width > 0 for _, complete, width in r["images"]), [
        i for i in r["images"] if not (i[1] and i[2] > 0)]
    if name == LECTURE:
        assert r["math"] >= 20 and len(r["images"]) >= 3, r
    assert (ARTIFACTS / f"{name}.png").stat().st_size > 10_000


# ----------------------------------------------------------------------------- handouts
def _figure_rows() -> list[tuple[str, str, list[str]]]:
    """(figure, notebook number, cell ids) of the figure table (``site/figures.md``)."""
    rows = []
    for line in (ROOT / "site" / "figures.md").read_text().splitlines():
        if re.match(r"\| (000|001|004) Figs?\.", line):
            cols = [c.strip() for c in line.strip().strip("|").split("|")]
            rows.append((cols[0], cols[1], re.findall(r"`([\w-]+)`", cols[2])))
    return rows


def _plain(markdown: str) -> str:
    """Markdown prose without math, markup or links: what a reader sees of it as words."""
    text = re.sub(r"\$\$.*?\$\$|\$[^$]*\$", " | ", markdown, flags=re.S)  # math: a gap
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", text)
    text = re.sub(r"`[^`]*`", " | ", text)
    text = re.sub(r"<[^>]+>", " ", text)
    text = re.sub(r"^#+ |[*_]{1,2}", "", text, flags=re.M)
    return text


def figure_captions(stem: str) -> dict[str, list[str]]:
    """For each seed figure the figure table places in lecture ``stem``: its caption, i.e. the
    sentence of the lecture's markdown that names the figure (in the listed cell or the
    nearest markdown cell before it), as the word runs between math and code."""
    nb = json.loads((ROOT / "notebooks" / f"{stem}.ipynb").read_text())
    cells = nb["cells"]
    index = {c.get("id"): i for i, c in enumerate(cells)}
    out = {}
    for fig, number, ids in _figure_rows():
        if not stem.startswith(number):
            continue
        nums = re.findall(r"\d+", fig.split("Fig", 1)[1].split("—")[0])
        sentence = None
        for cid in ids:
            i = index[cid]
            for j in range(i, max(-1, i - 8), -1):
                c = cells[j]
                if c["cell_type"] != "markdown":
                    continue
                src = "".join(c["source"])
                sents = re.split(r"(?<=[.!?:])\s+(?=[A-Z(*])", src.replace("\n", " "))
                hits = [s for s in sents if re.search(r"Figs?\.\s*(\d+\s*(,|and|–|-)\s*)*("
                                                        + "|".join(nums) + r")\b", s)]
                if hits:
                    sentence = hits[0]
                    break
            if sentence:
                break
        if sentence is None:  # no sentence names it: the prose just before the first cell
            i = index[ids[0]]
            j = next(k for k in range(i, -1, -1) if cells[k]["cell_type"] == "markdown")
            sentence = "".join(cells[j]["source"]).strip().split("\n\n")[-1]
        runs = [r.strip() for r in re.split(r"\|", _plain(sentence))]
        out[fig] = [r for r in runs if len(r.split()) >= 3] or [_plain(sentence)]
    return out


@pytest.mark.slow
@pytest.mark.browser
def test_one_handout_per_lecture_with_its_pages_and_figure_captions(site, handouts):
    from pypdf import PdfReader

    lectures = sorted(p.stem for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
    assert sorted(handouts) == lectures
    problems = []
    for stem, pdf in handouts.items():
        page_html = (site / "lectures" / f"{stem}.html").read_text()
        n_img = page_html.count("<img")
        words = len(re.sub(r"<[^>]+>", " ", page_html.split('<article', 1)[-1]).split())
        n_pages = len(PdfReader(str(pdf)).pages)
        # A4 holds at most ~3 figures or ~700 words; a page is never emptier than ~150 words
        # plus one figure
        low = max(1, math.ceil(max(n_img / 3, words / 700)))
        high = math.ceil(words / 150 + n_img) + 2
        if not low <= n_pages <= high:
            problems.append(f"{stem}: {n_pages} pages, expected {low}..{high} "
                            f"({words} words, {n_img} images)")
        raw = _pdf_text(pdf)
        tex = re.findall(r".{0,40}(?:\\\(|\\\)|\$\$).{0,40}", raw)
        if tex:
            problems.append(f"{stem}: raw TeX in the PDF: {tex[:3]}")
        text = _squash(_prose(raw))
        for fig, runs in figure_captions(stem).items():
            missing = [r for r in runs if _squash(r) not in text]
            if missing:
                problems.append(f"{stem}: caption of {fig} missing: {missing}")
    assert not problems, "\n".join(problems)
    # every figure of the table was found in some lecture
    found = {fig for s in lectures for fig in figure_captions(s)}
    assert found == {r[0] for r in _figure_rows()}


# ------------------------------------------------------------------- nothing secret
def _solution_lines() -> set[str]:
    lines = set()
    for src in (ROOT / "tools" / "homework_src").glob("hw*.py"):
        inside = False
        for line in src.read_text().splitlines():
            s = line.strip()
            if s.startswith("### BEGIN SOLUTION"):
                inside = True
            elif s.startswith("### END SOLUTION"):
                inside = False
            elif inside and len(s) >= 25 and not s.startswith("#"):
                lines.add(s)
    return lines


def _public_text() -> str:
    """Everything the site may show anyway: lectures, blank homework, course_lib's sources."""
    paths = [*(ROOT / "notebooks").glob("*.ipynb"), *(ROOT / "exercises").glob("*.ipynb"),
             *(ROOT / "course_lib").rglob("*.py")]  # fmt: skip
    return re.sub(r"\s+", " ", "\n".join(p.read_text(encoding="utf-8") for p in paths))


def _hidden_test_strings() -> set[str]:
    """Text only the hidden tests hold (a phrase they share with the homework is public)."""
    public = _public_text()
    return {s for s in _hidden_test_literals() if re.sub(r"\s+", " ", s) not in public}


def _hidden_test_literals() -> set[str]:
    out = set()
    for path in (ROOT / "solutions" / "hidden_tests").glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                if len(node.value) >= 20 and " " in node.value.strip():
                    out.add(node.value.strip())
            if isinstance(node, ast.JoinedStr):  # f-strings: their literal parts
                for v in node.values:
                    if isinstance(v, ast.Constant) and len(v.value.strip()) >= 20:
                        out.add(v.value.strip())
    return out


@pytest.mark.slow
@pytest.mark.browser
def test_no_solution_or_hidden_test_in_site_or_handouts(site, handouts):
    texts = {"site": _site_text(site)}
    texts.update({f"{k}.pdf": _pdf_text(p) for k, p in handouts.items()})
    markers = ["BEGIN SOLUTION", "END SOLUTION", "hidden_tests", "homework_src"]
    markers += [p.name for p in (ROOT / "solutions" / "hidden_tests").glob("*.py")]
    solution = _solution_lines()
    hidden = _hidden_test_strings()
    assert solution and hidden
    found = []
    # the guides (grading, semester, developing) name the hidden tests' folder and files: the
    # markers are looked for everywhere else; solution lines and hidden-test text everywhere
    marked = {"site": _site_text(site, guides=False)}
    for where, text in texts.items():
        flat = re.sub(r"\s+", " ", text)
        found += [f"{where}: marker {m!r}" for m in markers if m in marked.get(where, text)]
        found += [f"{where}: solution line {s!r}" for s in solution if re.sub(r"\s+", " ", s) in flat]
        found += [f"{where}: hidden-test text {s!r}" for s in hidden if re.sub(r"\s+", " ", s) in flat]
    assert not found, "\n".join(found[:30])


# -------------------------------------------------------------------- evidence cells
def _collapsed_cells(page: Path) -> dict[str, bool]:
    """cell id -> is its source collapsed behind a toggle (with its outputs outside)?"""
    text = page.read_text()
    out = {}
    for m in re.finditer(r'<div class="cell ([^"]*)docutils container" id="cell-([\w-]+)">', text):
        body = text[m.end(): m.end() + 400]
        out[m.group(2)] = "tag_hide-input" in m.group(1) and body.lstrip().startswith(
            '<details class="admonition hide above-input">')
    return out


def _hidden_in_lab(cell: dict) -> bool:
    meta = cell.get("metadata", {})
    return "evidence" in meta.get("tags", []) or bool(meta.get("jupyter", {}).get("source_hidden"))


@pytest.mark.slow
def test_evidence_cells_are_collapsed_on_the_lecture_pages(site):
    """Whatever the lectures tag as evidence (or JupyterLab hides) is collapsed on the page,
    and nothing else is."""
    for nb in sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb")):
        cells = [c for c in json.loads(nb.read_text())["cells"] if c["cell_type"] == "code"]
        collapsed = _collapsed_cells(site / "lectures" / f"{nb.stem}.html")
        for c in cells:
            if c.get("id") in collapsed:
                assert collapsed[c["id"]] == _hidden_in_lab(c), (nb.stem, c["id"])


@pytest.mark.slow
def test_a_tagged_evidence_cell_is_collapsed_with_its_output_visible(tmp_path):
    """The same on a small notebook of our own, whatever the lectures contain today."""
    import nbformat
    from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

    nb = new_notebook(metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                               "language": "python"}})
    nb.cells = [
        new_markdown_cell("# Evidence\n\nA claim about $x^2$."),
        new_code_cell("print('evidence output')\nassert 1 + 1 == 2", id="ev",
                      metadata={"tags": ["evidence"], "jupyter": {"source_hidden": True}}),
        new_code_cell("print('hidden in lab')", id="lab", metadata={"jupyter": {"source_hidden": True}}),
        new_code_cell("print('plain cell')", id="plain"),
    ]
    src = tmp_path / "99_evidence.ipynb"
    nbformat.write(nb, src)
    out = build_site.build(None, tmp_path / "html", 1, True, items=[(src, "lectures/99_evidence")])
    page = out / "lectures" / "99_evidence.html"
    assert _collapsed_cells(page) == {"ev": True, "lab": True, "plain": False}
    text = page.read_text()
    assert text.index("</span>evidence output\n") > text.index("</details>"), "the output stays visible"
    assert "Show code cell source" in text
    for stale in build_site.CACHE.glob("99_evidence-*.ipynb"):
        stale.unlink()


# ------------------------------------------------------------- fast: page preparation
def _nb(*cells):
    return {"cells": list(cells), "metadata": {}, "nbformat": 4, "nbformat_minor": 5}


def _code(src, cid, **meta):
    return {"cell_type": "code", "id": cid, "metadata": meta, "source": src, "outputs": [],
            "execution_count": None}


def test_evidence_cells_are_collapsed_like_in_jupyterlab():
    nb = _nb(
        _code("assert 1 + 1 == 2", "a", tags=["evidence"]),
        _code("assert True", "b", jupyter={"source_hidden": True}),
        _code("x = 1", "c", jupyter={"outputs_hidden": True}),
        _code("y = 2", "d"),
    )
    page = build_site.prepare(nb, "notebooks/99_x.ipynb")
    by_id = {c["id"]: c for c in page["cells"]}
    assert "hide-input" in by_id["a"]["metadata"]["tags"]
    assert "evidence" in by_id["a"]["metadata"]["tags"]
    assert "hide-input" in by_id["b"]["metadata"]["tags"]
    assert by_id["c"]["metadata"]["tags"] == ["hide-output"]
    assert "tags" not in by_id["d"]["metadata"]
    assert nb["cells"][0]["metadata"]["tags"] == ["evidence"], "the input notebook is untouched"
    # every cell id is an anchor
    targets = [c["source"] for c in page["cells"] if c["cell_type"] == "markdown"]
    assert targets == ["(cell-a)=\n", "(cell-b)=\n", "(cell-c)=\n", "(cell-d)=\n"]


def test_demos_get_a_note_on_running_live_and_links_point_at_pages():
    nb = _nb(
        {"cell_type": "markdown", "id": "m", "metadata": {}, "source":
         "See [lecture 2](02_b.ipynb#sec), [hw](../exercises/hw01_a.ipynb), "
         "[the answers](../solutions/hw01_a.ipynb), [a paper](https://example.org) "
         "and ![pic](fig.png)."},
        _code("%matplotlib widget\nfrom course_lib.widgets import knot_spline_demo", "i"),
        _code("knot_spline_demo()", "k"),
        _code("knot_spline_demo(static=True)", "s"),
        _code("%matplotlib widget", "w"),
        _code("x = 1", "x"),
        {**_code("plot()", "p"), "outputs": [{"output_type": "display_data", "metadata": {},
                                             "data": {"image/png": "iVBOR", "text/plain": "F"}}]},
        _code("plot()", "q"),
    )
    docs = {"notebooks/01_a.ipynb": "lectures/01_a", "notebooks/02_b.ipynb": "lectures/02_b",
            "exercises/hw01_a.ipynb": "homework/hw01_a"}
    page = build_site.prepare(nb, "notebooks/01_a.ipynb", docs)
    md = page["cells"][0]["source"]
    assert "[lecture 2](02_b.ipynb#sec)" in md
    assert "[hw](../homework/hw01_a.ipynb)" in md
    assert "the answers" in md and "solutions" not in md
    assert "[a paper](https://example.org)" in md and "![pic](fig.png)" in md
    notes = [i for i, c in enumerate(page["cells"]) if "Live demo" in "".join(c["source"])]
    after = [page["cells"][i - 1]["id"] for i in notes]
    assert after == ["k", "p"], "after each demo, and after the figure `%matplotlib widget` makes live"
    assert all("voila notebooks/01_a.ipynb" in page["cells"][i]["source"] for i in notes)
    assert len({c["id"] for c in page["cells"]}) == len(page["cells"]), "cell ids are unique"


def test_the_build_never_reads_solutions():
    items = build_site.source_notebooks()
    assert items
    for path, doc in items:
        rel = path.relative_to(ROOT).parts
        assert rel[0] in ("notebooks", "exercises"), path
        assert doc.split("/")[0] in ("lectures", "homework")


def test_the_figure_table_links_into_the_lectures():
    items = build_site.source_notebooks()
    docs = {p.stem: d for p, d in items}
    ids = {p.stem: {c.get("id") for c in json.loads(p.read_text())["cells"]} for p, _ in items}
    text = (ROOT / "site" / "figures.md").read_text()
    page = build_site.guide_page("figures", text, docs, ids)
    rows = [x for x in page.splitlines() if re.match(r"\| (000|001|004) Fig", x)]
    assert len(rows) == len(_figure_rows())
    for row in rows:
        assert "{doc}`" in row and "{ref}`" in row and "<cell-" in row, row
    course = build_site.course_page(docs)
    assert "](notebooks/" not in course and "](exercises/" not in course
    assert all(f"</{d}>`" in course for d in docs.values()), "every lecture and homework linked"
