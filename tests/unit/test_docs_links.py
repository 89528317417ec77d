"""Every "Lesson:" link in a course_lib docstring names a notebook that exists."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
MODULES = sorted((ROOT / "course_lib").rglob("*.py"))


@pytest.mark.parametrize("path", MODULES, ids=[str(p.relative_to(ROOT)) for p in MODULES])
def test_notebook_links_point_to_existing_notebooks(path):
    for link in re.findall(
        r"``((?:notebooks|exercises|solutions)/[\w/.-]+\.ipynb)``", path.read_text()
    ):
        assert (ROOT / link).is_file(), f"{path.name} links to missing {link}"


def test_every_construction_module_links_its_lesson():
    for name in (
        "bezier",
        "curve",
        "differential_geometry",
        "reparametrization",
        "beta_constraints",
        "continuity",
        "stitching",
        "catmull_rom",
        "beta_splines",
        "knot_splines",
        "higher_order",
        "surfaces",
    ):
        assert "Lesson: ``notebooks/" in (ROOT / "course_lib" / f"{name}.py").read_text(), name
