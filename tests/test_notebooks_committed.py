"""How notebooks are committed: stripped of outputs, with a title, runnable in a fresh kernel.

The policy (README, "Notebooks in git"): notebooks/, exercises/ and solutions/ are committed
without outputs; nbval re-executes every one of them in the same pytest run, and the claims the
prose makes are `assert` cells, so executing a notebook checks it.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tools.strip_notebooks import course_notebooks, is_stripped

ROOT = Path(__file__).resolve().parents[1]

NOTEBOOKS = course_notebooks()
IDS = [str(p.relative_to(ROOT)) for p in NOTEBOOKS]


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_committed_without_outputs(path):
    assert is_stripped(path), (
        f"run `.venv/bin/python tools/strip_notebooks.py` to strip {path.name}"
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_starts_with_a_title(path):
    cells = json.loads(path.read_text())["cells"]
    first = "".join(cells[0]["source"])
    assert cells[0]["cell_type"] == "markdown" and "# " in first, (
        "first cell must be a markdown title"
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_no_network_or_relative_file_reads(path):
    code = "\n".join(
        "".join(c["source"])
        for c in json.loads(path.read_text())["cells"]
        if c["cell_type"] == "code"
    )
    for forbidden in ("http://", "https://", "urlopen", "requests.get", "open("):
        assert forbidden not in code, f"{path.name} code uses {forbidden!r}"


def test_lecture_notebooks_exist_in_course_order():
    names = sorted(p.name for p in (ROOT / "notebooks").glob("*.ipynb"))
    expected = [
        "00_welcome.ipynb",
        "01_parametric_continuity.ipynb",
        "02_reparametrization.ipynb",
        "03_beta_constraints.ipynb",
        "04_arc_length_and_theorem_1.ipynb",
        "05_curvature_of_plane_curves.ipynb",
        "06_g1_knot_bezier_splines.ipynb",
        "07_stitching_bezier_curves.ipynb",
        "08_beta_splines.ipynb",
        "09_higher_order.ipynb",
        "10_surfaces.ipynb",
        "11_are_letters_smooth.ipynb",
    ]
    assert [n for n in names if n in expected] == expected
