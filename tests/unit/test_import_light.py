"""`import course_lib` and its math submodules must not load sympy, matplotlib or ipywidgets."""

from __future__ import annotations

import subprocess
import sys

MODULES = [
    "course_lib",
    "course_lib.curves.parametrization",
    "course_lib.geometry.differential_geometry",
    "course_lib.geometry.reparametrization",
    "course_lib.geometry.beta_constraints",
    "course_lib.geometry.continuity",
]
HEAVY = ["sympy", "matplotlib", "ipywidgets", "scipy"]
# The numeric paths must stay light at call time too (numeric Beta-constraints, reports).
USE = """
import numpy as np
from course_lib import PiecewiseBezier
from course_lib.geometry import beta_constraints as bc, continuity as co, differential_geometry as dg
c = PiecewiseBezier([np.array([[0, 0], [1, 1], [2, 0.]]), np.array([[2, 0], [3, -1], [4, 0.]])])
bc.solve_shape_parameters(bc.apply_beta_constraints(np.eye(2), [2.0, 1.0]), np.eye(2))
str(co.curve_continuity(c)[0])
dg.arc_length(c), dg.signed_curvature(c, 0.5), dg.parameter_at_arc_length(c, 1.0)
"""


def test_math_modules_import_light():
    code = (
        "import sys\n"
        + "".join(f"import {m}\n" for m in MODULES)
        + USE
        + f"print(','.join(m for m in {HEAVY!r} if m in sys.modules))\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "", f"heavy modules imported: {out.stdout.strip()}"


# Every math module (the parts curves/, geometry/, constructions/, sources/ of the module map in
# CONTRIBUTING.md, and validation), found on disk, each imported in turn in one fresh
# interpreter; the first one that pulls in a heavy package is named.
MATH_PARTS = ("curves", "geometry", "constructions", "sources")
LIGHT_ONLY = ["sympy", "matplotlib", "ipywidgets"]


def math_modules() -> list[str]:
    from pathlib import Path

    package = Path(__file__).resolve().parents[2] / "course_lib"
    found = ["course_lib.validation"]
    for part in MATH_PARTS:
        for path in sorted((package / part).rglob("*.py")):
            dotted = ".".join(path.relative_to(package.parent).with_suffix("").parts)
            found.append(dotted.removesuffix(".__init__"))
    return found


def test_every_existing_math_submodule_imports_light():
    present = math_modules()
    assert {"course_lib.curves.bezier", "course_lib.curves.curve"} <= set(present)
    code = (
        "import sys\n"
        f"heavy = {LIGHT_ONLY!r}\n"
        "import course_lib\n"
        "culprits = []\n"
        f"for name in {present!r}:\n"
        "    __import__(name)\n"
        "    culprits += [(name, h) for h in heavy if h in sys.modules and\n"
        "                 all(h != c[1] for c in culprits)]\n"
        "print(culprits)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]", f"(submodule, heavy package) pairs: {out.stdout.strip()}"
