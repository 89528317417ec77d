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
        "curves/bezier",
        "curves/curve",
        "geometry/differential_geometry",
        "geometry/reparametrization",
        "geometry/beta_constraints",
        "geometry/continuity",
        "constructions/stitching",
        "constructions/catmull_rom",
        "constructions/beta_splines/quadratic_cubic",
        "constructions/knot_splines",
        "constructions/beta_splines/degree_n",
        "constructions/surfaces",
        "constructions/outlines/__init__",
    ):
        assert "Lesson: ``notebooks/" in (ROOT / "course_lib" / f"{name}.py").read_text(), name
