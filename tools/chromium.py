"""Where the course finds the browser it drives (browser tests, handouts): one rule for both."""

from __future__ import annotations

import os
import shutil

CHROMIUM_ENV = "COURSE_CHROMIUM"  # optional override of the browser executable


def find_chromium() -> str | None:
    """Path of a Chromium executable: ``$COURSE_CHROMIUM`` when set (and then only that),
    else /usr/bin/chromium (Debian) or ``chromium``/``chromium-browser`` on PATH."""
    override = os.environ.get(CHROMIUM_ENV)
    cands = (override,) if override else (
        "/usr/bin/chromium", shutil.which("chromium"), shutil.which("chromium-browser"))
    for cand in cands:
        if cand and os.path.isfile(cand) and os.access(cand, os.X_OK):
            return cand
    return None
