"""Every static figure of the course fits the notebook column of a laptop (issue 13, "Figures").

The check itself lives in the repository's ``conftest.py``: under nbval, a cell of a lecture or
homework (``notebooks/``, ``exercises/``, ``solutions/``) fails when it shows a PNG wider than ``MAX_FIGURE_WIDTH_PX``; it reads
only the PNG headers of the outputs nbval already keeps, so the lectures' nbval runs enforce
the limit at no extra cost.  These tests check that helper and, once, the whole chain.
"""

from __future__ import annotations

import base64
import io
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from _homework_support import load

ROOT = Path(__file__).resolve().parents[1]


def _root_conftest():
    return load("_root_conftest", ROOT / "conftest.py")


CONF = _root_conftest()


def _png_b64(width_in: float, dpi: int = 100) -> str:
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(width_in, 0.5), dpi=dpi)
    FigureCanvasAgg(fig)
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)  # no tight bbox: exactly width_in * dpi pixels
    return base64.b64encode(buf.getvalue()).decode()


def test_limit_is_the_laptop_notebook_column():
    assert CONF.MAX_FIGURE_WIDTH_PX == 900


def test_png_width_reads_the_header_or_the_display_metadata():
    assert CONF.png_width(_png_b64(9.5)) == 950
    assert CONF.png_width(_png_b64(3.0)) == 300
    # a retina figure: twice the pixels, shown at the width the kernel states
    assert CONF.png_width(_png_b64(9.5, dpi=200), {"width": 950}) == 950
    with pytest.raises(ValueError, match="PNG"):
        CONF.png_width(base64.b64encode(b"GIF89a" + bytes(40)).decode())


def test_too_wide_figures_looks_only_at_png_outputs():
    outputs = [
        {"output_type": "stream", "name": "stdout", "text": "x" * 2000},
        {"output_type": "display_data", "data": {"image/png": _png_b64(8.9)}, "metadata": {}},
        {"output_type": "display_data", "data": {"image/png": _png_b64(9.1)}, "metadata": {}},
        {"output_type": "execute_result", "data": {"text/plain": "1"}, "metadata": {}},
    ]
    assert CONF.too_wide_figures(outputs) == [910]
    assert CONF.too_wide_figures(outputs, limit=800) == [890, 910]
    assert CONF.too_wide_figures(None) == []


def _cell(i: int, source: str) -> dict:
    return {
        "cell_type": "code",
        "id": f"c{i}",
        "metadata": {},
        "execution_count": None,
        "outputs": [],
        "source": source,
    }


@pytest.mark.slow
def test_nbval_fails_a_lecture_cell_with_a_wide_figure(tmp_path):
    """End to end (one kernel, a few seconds): under nbval, a lecture fails on the cell
    that shows a too wide figure, and only there."""
    shutil.copy(ROOT / "conftest.py", tmp_path / "conftest.py")
    (tmp_path / "pytest.ini").write_text("[pytest]\n")
    plot = "import matplotlib.pyplot as plt\nplt.figure(figsize=({}, 1)); plt.plot([0, 1]);"
    nb = {
        "cells": [
            _cell(0, "%matplotlib inline"),
            _cell(1, plot.format(8.5)),
            _cell(2, plot.format(14)),
        ],
        "metadata": {
            "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
        },
        "nbformat": 4,
        "nbformat_minor": 5,
    }
    (tmp_path / "notebooks").mkdir()
    (tmp_path / "notebooks" / "lecture.ipynb").write_text(json.dumps(nb))
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            "-q",
            "-p",
            "no:cacheprovider",
            "--nbval-lax",
            "--nbval-current-env",
            "-rf",
            "notebooks/lecture.ipynb",
        ],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    out = run.stdout + run.stderr
    assert run.returncode == 1, out
    assert "2 passed" in out and "1 failed" in out, out
    assert re.search(r"figure 1[0-9]{3} px wide; a figure of the course may be at most 900 px", out), out
