"""Every figure has a text alternative (WCAG 2.1 1.1.1), kept with its cell.

A code cell of ``notebooks/`` or ``exercises/`` (and ``solutions/``) that draws a figure
carries ``{"mystnb": {"image": {"alt": "..."}}}`` in its metadata: the website uses it as
the image's ``alt`` and caption, JupyterLab shows it under the figure
(``course_lib/figure_alt.py``).  Homework gets it from ``### ALT`` lines of its source
(``tools/build_homework.py``).  A figure-drawing cell is recognised by its source (a demo
call, ``plt.show``/``subplots``, ``new_figure``, a ``plot_*`` call, ``fig.canvas``).
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from course_lib.figure_alt import CAPTION_PREFIX, caption_markdown, cell_alt, register

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(
    p for folder in ("notebooks", "exercises", "solutions") for p in (ROOT / folder).glob("*.ipynb")
)
FIGURE = re.compile(
    r"\bplt\.(show|subplots|subplot_mosaic|figure)\s*\(|\bnew_figure\s*\(|\b\w+_demo\s*\("
    r"|\bplot_\w+\s*\(|\bfig\w*\.canvas\s*$|\bdisplay\(\s*fig",
    re.M,
)
FILE_NAME = re.compile(r"^\S+\.(png|jpe?g|svg|gif|pdf)$|_images/|^\.\./", re.I)


def figure_cells(nb: dict) -> list[dict]:
    return [
        c for c in nb["cells"] if c["cell_type"] == "code" and FIGURE.search("".join(c["source"]))
    ]


def alt_problem(alt: str | None) -> str | None:
    """Why ``alt`` is not a text alternative (None if it is one)."""
    if alt is None:
        return "no alt text (cell metadata mystnb.image.alt)"
    if FILE_NAME.search(alt):
        return f"alt text is a file name: {alt!r}"
    if len(alt.split()) < 5:
        return f"alt text too short to say what the figure shows: {alt!r}"
    return None


@pytest.mark.parametrize("path", NOTEBOOKS, ids=[f"{p.parent.name}/{p.name}" for p in NOTEBOOKS])
def test_every_figure_cell_has_alt_text(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    bad = [
        f"{c.get('id')}: {why}"
        for c in figure_cells(nb)
        if (why := alt_problem(cell_alt(c.get("metadata", {})))) is not None
    ]
    assert not bad, f"{path.name}: figure cells without a text alternative: {bad}"


def test_the_check_can_fail():
    assert alt_problem(None)
    assert alt_problem("../_images/3f2a.png")
    assert alt_problem("figure.png")
    assert alt_problem("a curve")
    assert alt_problem("A blue curve with a corner at its only joint.") is None
    nb = {"cells": [{"cell_type": "code", "source": "fig, ax = plt.subplots()\n", "metadata": {}}]}
    assert len(figure_cells(nb)) == 1


def test_cell_alt_reads_mystnb_image_alt():
    assert cell_alt({"mystnb": {"image": {"alt": "  A  curve\n drawn "}}}) == "A curve drawn"
    for meta in ({}, {"mystnb": {}}, {"mystnb": {"image": {"alt": " "}}}, None):
        assert cell_alt(meta) is None


class _Events:
    def __init__(self):
        self.callbacks = {"post_run_cell": []}

    def register(self, name, fn):
        self.callbacks[name].append(fn)


class _Kernel:
    def __init__(self, metadata):
        self.metadata = metadata

    def get_parent(self, channel=None):
        return {"metadata": self.metadata}


def test_hook_shows_the_alt_text_under_the_figure(monkeypatch):
    """What JupyterLab does: the execute request carries the cell's metadata."""
    import IPython
    import IPython.display

    shown = []
    shell = type("Shell", (), {})()
    shell.events = _Events()
    shell.kernel = _Kernel({"mystnb": {"image": {"alt": "A blue curve with one corner."}}})
    monkeypatch.setattr(IPython, "get_ipython", lambda: shell)
    monkeypatch.setattr(
        IPython.display, "publish_display_data", lambda data, metadata=None: shown.append(data)
    )
    assert register(shell) and register(shell)  # once only
    (hook,) = shell.events.callbacks["post_run_cell"]
    ok = type("R", (), {"error_before_exec": None, "error_in_exec": None, "info": None})()
    hook(ok)
    assert shown == [
        {
            "text/markdown": caption_markdown("A blue curve with one corner."),
            "text/plain": f"{CAPTION_PREFIX} A blue curve with one corner.",
        }
    ]
    failed = type(
        "R", (), {"error_before_exec": None, "error_in_exec": ValueError(), "info": None}
    )()
    hook(failed)  # no caption under a cell that raised
    shell.kernel = _Kernel({})  # nbclient/nbval: no cell metadata, no caption
    hook(ok)
    assert len(shown) == 1


def test_homework_builder_turns_alt_lines_into_metadata(tmp_path):
    from tools import build_homework as bh
    src = tmp_path / "hw99_x.py"
    src.write_text(
        "# %%\n### ALT A grey polygon and a blue curve\n### ALT through its ends.\nx = 1\n",
        encoding="utf-8",
    )
    (cell,) = bh.build(src, "student").cells
    assert cell.source == "x = 1"
    assert (
        cell.metadata["mystnb"]["image"]["alt"]
        == "A grey polygon and a blue curve through its ends."
    )


def test_site_pages_show_the_alt_text_as_a_caption():
    from tools import build_site as bs
    png = {"output_type": "display_data", "data": {"image/png": "AA=="}, "metadata": {}}
    nb = {
        "cells": [
            {
                "cell_type": "code",
                "id": "c1",
                "source": "plt.show()",
                "outputs": [png],
                "metadata": {"mystnb": {"image": {"alt": "A blue curve with one corner."}}},
            },
        ],
        "metadata": {},
    }
    (cell,) = [c for c in bs.prepare(nb, "notebooks/x.ipynb")["cells"] if c["cell_type"] == "code"]
    assert cell["metadata"]["mystnb"]["image"]["alt"] == "A blue curve with one corner."
    assert (
        cell["metadata"]["mystnb"]["figure"]["caption"] == "Figure: A blue curve with one corner."
    )
