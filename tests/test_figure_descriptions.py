"""Complex figures carry a long description a reader can open (issue 28, WCAG 1.1.1).

A figure cell of a lecture has a short text alternative in its metadata
(``mystnb.image.alt``).  Curvature combs and constructions need more than a sentence or two:
such a cell is marked ``"figure_complex": true`` in its cell metadata and is followed by a
markdown cell that is one collapsible block::

    <details>
    <summary>Describe this figure</summary>

    What is drawn, what to notice, the numbers that matter.

    </details>

HTML ``<details>`` opens in JupyterLab and on the MyST-NB site alike.  Static checks only.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LECTURES = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
OPEN = "<details>\n<summary>Describe this figure</summary>\n"
MIN_WORDS = 60  # a description a reader learns from, not a second alt text
#: figure functions that draw combs or constructions: their cells must be marked complex
COMPLEX_FIGURES = ("combs_figure", "farin_boehm_figure", "g1_stitching_figure",
                   "knot_joint_figure", "cubic_beta_spline_figure", "outlines_figure")


def _cells(path: Path) -> list[dict]:
    return json.loads(path.read_text(encoding="utf-8"))["cells"]


def _src(cell: dict) -> str:
    return "".join(cell["source"])


def _is_complex(cell: dict) -> bool:
    return cell["cell_type"] == "code" and cell.get("metadata", {}).get("figure_complex") is True


def _is_description(cell: dict) -> bool:
    return cell["cell_type"] == "markdown" and _src(cell).startswith(OPEN)


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_every_complex_figure_is_followed_by_its_description(path):
    cells = _cells(path)
    problems = []
    for k, cell in enumerate(cells):
        if not _is_complex(cell):
            continue
        if not cell["metadata"].get("mystnb", {}).get("image", {}).get("alt"):
            problems.append(f"{cell['id']}: a complex figure needs its short alt text too")
        nxt = cells[k + 1] if k + 1 < len(cells) else None
        if nxt is None or not _is_description(nxt):
            problems.append(f"{cell['id']}: not followed by a 'Describe this figure' block")
            continue
        text = _src(nxt)
        body = text[len(OPEN):]
        if not text.rstrip().endswith("</details>"):
            problems.append(f"{nxt['id']}: the block does not end with </details>")
        words = len(re.findall(r"\S+", body.replace("</details>", "")))
        if words < MIN_WORDS:
            problems.append(f"{nxt['id']}: {words} words describe {cell['id']} (< {MIN_WORDS})")
    assert not problems, f"{path.name}: " + "; ".join(problems)


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_every_description_belongs_to_a_complex_figure(path):
    cells = _cells(path)
    orphans = [c["id"] for k, c in enumerate(cells)
               if _is_description(c) and not (k > 0 and _is_complex(cells[k - 1]))]
    assert not orphans, f"{path.name}: descriptions after no complex figure: {orphans}"


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_combs_and_constructions_are_marked_complex(path):
    unmarked = [c["id"] for c in _cells(path) if c["cell_type"] == "code"
                and any(f"{name}(" in _src(c) for name in COMPLEX_FIGURES)
                and not _is_complex(c)]
    assert not unmarked, f"{path.name}: comb or construction figures not marked complex: {unmarked}"


def test_the_course_has_complex_figures_to_check():
    marked = [c["id"] for p in LECTURES for c in _cells(p) if _is_complex(c)]
    assert len(marked) >= len(COMPLEX_FIGURES), marked
