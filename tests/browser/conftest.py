"""Fixtures of the browser tests; the harness itself is in browser_harness.py."""

from __future__ import annotations

from pathlib import Path

import pytest
from browser_harness import ARTIFACTS, CHROMIUM_ENV, find_chromium

# nbval (``--nbval-lax`` in addopts) would otherwise collect the fixture notebooks as tests.
collect_ignore_glob = ["fixtures/*"]


@pytest.fixture(scope="session")
def chromium_path() -> str:
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError as exc:
        pytest.skip(f"browser test skipped: Playwright is not installed ({exc}); "
                    "install the test extras: pip install -e '.[test]'")
    path = find_chromium()
    if path is None:
        pytest.skip(f"browser test skipped: no Chromium found (${CHROMIUM_ENV}, /usr/bin/chromium "
                    "or PATH); install it with `bash tools/ensure-browser` (Debian, root) "
                    "or `apt-get install chromium`")
    return path


@pytest.fixture(scope="session")
def chromium_browser(chromium_path):
    """One headless Chromium for the session, closed at the end."""
    from playwright.sync_api import sync_playwright

    pw = sync_playwright().start()
    try:
        b = pw.chromium.launch(
            executable_path=chromium_path, headless=True, args=["--no-sandbox", "--disable-gpu"]
        )
        try:
            yield b
        finally:
            b.close()
    finally:
        pw.stop()


@pytest.fixture(scope="session")
def artifacts() -> Path:
    """test-artifacts/ (gitignored): screenshots, server logs, timings."""
    ARTIFACTS.mkdir(exist_ok=True)
    return ARTIFACTS


