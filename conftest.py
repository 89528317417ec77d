"""Repository-wide pytest configuration.

One `pytest` run covers the unit tests (tests/) and nbval over notebooks/, exercises/ and
solutions/ (options in pyproject.toml).  Notebooks under tests/fixtures/ are data for other tests
(submissions to grade, some broken on purpose), never executed by nbval.
"""

from __future__ import annotations

import base64
import struct
from pathlib import Path

import pytest

#: Widest static figure of a lecture or homework, in pixels as shown inline: the notebook column of
#: JupyterLab on a 1366×768 laptop screen with the file browser open is about 880–900 px;
#: a wider PNG is scaled down and its text, drawn at the course style's sizes, becomes tiny.
MAX_FIGURE_WIDTH_PX = 900


def pytest_ignore_collect(collection_path: Path, config) -> bool | None:
    if collection_path.suffix == ".ipynb" and "fixtures" in collection_path.parts:
        return True
    return None


COURSE_LIB = Path(__file__).resolve().parent / "course_lib"


def wants_doctests(path: Path) -> bool:
    """Doctests run for the modules of ``course_lib`` that have an example (``>>>``) only:
    no other file is imported for them (tests, hidden tests, fixtures, tools), and a module
    without examples is not imported just to find none."""
    path = Path(path).resolve()
    if path.suffix != ".py" or COURSE_LIB not in path.parents:
        return False
    return ">>> " in path.read_text(encoding="utf-8")


@pytest.hookimpl(wrapper=True)
def pytest_collect_file(file_path: Path, parent):
    """``--doctest-modules`` (pyproject.toml) restricted to :func:`wants_doctests`."""
    collectors = yield
    if file_path.suffix == ".py" and not wants_doctests(file_path):
        collectors = [c for c in collectors if type(c).__name__ != "DoctestModule"]
    return collectors


def _hypothesis_profiles() -> None:
    """In CI (CI=true) property tests draw the same examples every run (derandomized), so a
    landing never depends on luck; locally they explore new examples each run."""
    import os

    try:
        from hypothesis import settings
    except ImportError:  # pragma: no cover - hypothesis is a test dependency
        return
    settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
    if os.environ.get("CI"):
        settings.load_profile("ci")


_hypothesis_profiles()


def png_width(data: str | bytes, metadata: dict | None = None) -> int:
    """Displayed width in pixels of a base64 PNG output: ``metadata["width"]`` when the
    kernel sent one (retina figures are shown at half their pixel width), else the width
    in the PNG's IHDR header."""
    if metadata and "width" in metadata:
        return int(metadata["width"])
    if isinstance(data, bytes):
        data = data.decode("ascii")
    raw = base64.b64decode("".join(data.split())[:64])
    if raw[:8] != b"\x89PNG\r\n\x1a\n" or raw[12:16] != b"IHDR":
        raise ValueError("data must be a base64-encoded PNG image")
    return struct.unpack(">I", raw[16:20])[0]


def too_wide_figures(outputs, limit: int = MAX_FIGURE_WIDTH_PX) -> list[int]:
    """Widths of the PNG images among a cell's ``outputs`` that are wider than ``limit``."""
    widths = []
    for out in outputs or ():
        png = out.get("data", {}).get("image/png")
        if png:
            widths.append(png_width(png, out.get("metadata", {}).get("image/png")))
    return [w for w in widths if w > limit]


@pytest.hookimpl(wrapper=True)
def pytest_runtest_call(item):
    """Under nbval, a cell of a lecture or homework (notebooks/, exercises/, solutions/) fails
    when it shows a figure wider than :data:`MAX_FIGURE_WIDTH_PX`.  Costs nothing extra: nbval
    keeps each cell's outputs (``item.test_outputs``) and only the PNG headers are read."""
    result = yield
    path = Path(str(getattr(item, "path", item.fspath)))
    if path.suffix == ".ipynb" and path.parent.name in {"notebooks", "exercises", "solutions"}:
        wide = too_wide_figures(getattr(item, "test_outputs", None))
        if wide:
            pytest.fail(
                f"figure {wide[0]} px wide; a figure of the course may be at most "
                f"{MAX_FIGURE_WIDTH_PX} px (figsize width ≤ 8.8 in at the course's 100 dpi: "
                "fewer inches or panels per row, never a lower dpi)",
                pytrace=False,
            )
    return result


# ------------------------------------------------------------------ two workers (make test)
# `make test` runs pytest on two workers (pytest-xdist: `-n 2 --dist loadfile
# --no-loadscope-reorder`).  The unit of work a worker gets is a whole test file -- a notebook's
# cells run in order in one kernel, and a module's fixtures (the site build, the student
# edition, a grading batch) are built once -- and the folders of SHARED_WORKER are one unit
# each: all browser tests run on one worker (one Chromium for the session, one notebook server
# at a time).  pytest-xdist's own `xdist_group` mark cannot do this here: xdist 3.8 renames the
# test (`item._nodeid`), which pytest 9 no longer reads.  Files holding a `slow` test are handed
# out first, so that the two workers finish together instead of one waiting on a long file at
# the end.  Without xdist (`pytest tests/test_x.py`) none of this applies.

#: test folders whose files one worker runs, one after the other
SHARED_WORKER = {"tests/browser/": "tests/browser (one worker)"}


def work_unit(nodeid: str) -> str:
    """What one worker runs together: the test's file, or its folder in :data:`SHARED_WORKER`."""
    path = nodeid.split("::", 1)[0]
    return next((unit for top, unit in SHARED_WORKER.items() if path.startswith(top)), path)


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config, log):
    """``--dist loadfile``, with the folders of :data:`SHARED_WORKER` one unit each."""
    if config.getoption("dist") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class CourseScheduling(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return work_unit(nodeid)

    return CourseScheduling(config, log)


def pytest_collection_modifyitems(config, items) -> None:
    """On an xdist worker: the files holding a ``slow`` test come first."""
    if not hasattr(config, "workerinput"):
        return
    heavy = {item.path for item in items if item.get_closest_marker("slow")}
    items.sort(key=lambda item: item.path not in heavy)  # stable: the order within is kept
