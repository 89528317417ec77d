"""Handouts: one PDF per lecture, ``python tools/build_handouts.py`` (``make handouts``).

Each lecture page of the website (``build/site/``, built first by ``tools/build_site.py``
when missing) is printed to ``build/handouts/NN_name.pdf`` by headless Debian Chromium
(``/usr/bin/chromium``, or ``$COURSE_CHROMIUM``) driven by Playwright; no browser is
downloaded.  The PDFs are also copied into the site (``build/site/handouts/``), so they are
published with it.  Printing the site rather than converting the notebooks again means the PDF is
exactly the page: the same executed outputs and static demo figures, the same MathJax
(local), the same collapsed evidence cells; the site's print style (``site/_static/
course.css``) drops the navigation.  A4, page numbers in the footer.  Tagged PDFs: a
structure tree with the figures' alt text, bookmarks from the headings, title and language.

The site is served on 127.0.0.1 (a random free port) while printing: MathJax loads its
fonts by XHR, which Chromium refuses for ``file://`` pages.  Every request to another host
is aborted, so a PDF can never depend on the network.
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import html
import http.server
import re
import shutil
import sys
import threading
import time
from pathlib import Path
from urllib.parse import urlparse

from tools.chromium import CHROMIUM_ENV, find_chromium

ROOT = Path(__file__).resolve().parents[1]

SITE = ROOT / "build" / "site"
OUT = ROOT / "build" / "handouts"
FOOTER = (
    '<div style="font-size:8px;width:100%;text-align:center;color:#555">'
    '{title} — Geometric continuity — <span class="pageNumber"></span>/'
    '<span class="totalPages"></span></div>'
)
#: a page is ready when MathJax has typeset it and every image has loaded
READY_JS = """() => {
  const imgs = Array.from(document.images);
  return window.__courseMathDone === true && imgs.every(i => i.complete);
}"""
MATH_HOOK_JS = """() => {
  window.__courseMathDone = false;
  if (!document.querySelector('script[src*="MathJax.js"]')) {  // a page without math
    window.__courseMathDone = true;
    return;
  }
  const wait = () => {
    if (window.MathJax && window.MathJax.Hub && window.MathJax.Hub.Register) {
      // "End": after the start-up typesetting of the whole page (replayed if already past)
      window.MathJax.Hub.Register.StartupHook("End", () => {
        window.MathJax.Hub.Queue(() => { window.__courseMathDone = true; });
      });
    } else { setTimeout(wait, 50); }
  };
  wait();
}"""


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, *args) -> None:  # keep the build log readable
        pass


@contextlib.contextmanager
def serve(directory: Path):
    """Serve ``directory`` on 127.0.0.1 at a free port; yields the base URL."""
    handler = functools.partial(_QuietHandler, directory=str(directory))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=server.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}"
    finally:
        server.shutdown()
        server.server_close()
        thread.join(timeout=5)


@contextlib.contextmanager
def chromium():
    """A headless Debian Chromium through Playwright (never a downloaded browser)."""
    from playwright.sync_api import sync_playwright

    exe = find_chromium()
    if exe is None:
        raise RuntimeError(
            "no Chromium: install Debian's (apt-get install chromium, or bash "
            f"tools/ensure-browser) or set {CHROMIUM_ENV}"
        )
    with sync_playwright() as p:
        browser = p.chromium.launch(
            executable_path=exe, headless=True, args=["--no-sandbox", "--disable-gpu"]
        )
        try:
            yield browser
        finally:
            browser.close()


def offline_page(browser, base: str, blocked: list[str] | None = None):
    """A page that may only talk to ``base``: every other request is aborted (and listed)."""
    page = browser.new_page(viewport={"width": 1280, "height": 1000})
    host = urlparse(base).netloc

    def route(r):
        url = r.request.url
        if urlparse(url).netloc == host or url.startswith(("data:", "blob:", "about:")):
            r.continue_()
        else:
            if blocked is not None:
                blocked.append(url)
            r.abort()

    page.route("**/*", route)
    return page


def open_ready(page, url: str, timeout_ms: int = 60_000) -> None:
    """Go to ``url`` and wait until MathJax has finished and every image has loaded."""
    page.goto(url, wait_until="load")
    page.evaluate(MATH_HOOK_JS)
    page.wait_for_function(READY_JS, timeout=timeout_ms)


def _title(page) -> str:
    """The lecture's title as a reader sees it (TeX delimiters of its math dropped)."""
    title = page.evaluate("() => document.title").split(" — ")[0]
    return re.sub(r"\\[()]", "", title)


def lecture_pages(site: Path) -> list[Path]:
    return sorted((site / "lectures").glob("[0-9][0-9]_*.html"))


def build(site: Path = SITE, out: Path = OUT, only: list[str] | None = None) -> list[Path]:
    t0 = time.perf_counter()
    if not (site / "index.html").exists():
        from tools import build_site

        build_site.build(only, site, 2, True)
    pages = [p for p in lecture_pages(site) if not only or p.stem in only]
    if not pages:
        raise SystemExit(f"no lecture page in {site}/lectures")
    out.mkdir(parents=True, exist_ok=True)
    written = []
    blocked: list[str] = []
    with serve(site) as base, chromium() as browser:
        page = offline_page(browser, base, blocked)
        for page_file in pages:
            rel = page_file.relative_to(site).as_posix()
            open_ready(page, f"{base}/{rel}")
            page.emulate_media(media="print")
            pdf = out / f"{page_file.stem}.pdf"
            page.pdf(
                path=str(pdf),
                format="A4",
                print_background=True,
                margin={"top": "14mm", "bottom": "16mm", "left": "12mm", "right": "12mm"},
                display_header_footer=True,
                header_template="<span></span>",
                footer_template=FOOTER.format(title=html.escape(_title(page))),
                # accessible PDF (WCAG 1.3.1, 2.4.5): a structure tree from the HTML (headings,
                # lists, tables, figures with their alt text), bookmarks from the headings;
                # its title and language come from the page (<title>, <html lang="en">)
                tagged=True,
                outline=True,
            )
            page.emulate_media(media="screen")
            written.append(pdf)
            print(f"  {pdf.relative_to(ROOT) if pdf.is_relative_to(ROOT) else pdf}")
    if blocked:
        raise RuntimeError(f"the pages asked for outside resources: {sorted(set(blocked))}")
    # published with the site too: <site>/handouts/NN_name.pdf
    (site / "handouts").mkdir(exist_ok=True)
    for pdf in written:
        shutil.copy2(pdf, site / "handouts" / pdf.name)
    print(f"{len(written)} handouts in {time.perf_counter() - t0:.0f} s")
    return written


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", type=Path, default=SITE)
    ap.add_argument("--out", type=Path, default=OUT)
    ap.add_argument("--only", action="append", help="lecture stem (repeatable)")
    args = ap.parse_args(argv)
    build(args.site.resolve(), args.out.resolve(), args.only)
    return 0


if __name__ == "__main__":
    sys.exit(main())
