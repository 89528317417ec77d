"""What tests of homework share: loading hidden tests by path, and per-student variants.

A :class:`VariantHomework` holds one homework's hidden tests, 1,000 student codes made with a
test secret, its grading through :class:`LocalStudent` on a variant's data, and the solution
notebook's code cells run in-process with ``VARIANT`` set to a code.
"""

from __future__ import annotations

import functools
import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from course_lib.homework import variants
from tools import build_homework as build
from tools.grading.protocol import LocalStudent, run_question

ROOT = Path(__file__).resolve().parents[1]

SECRET = b"a test secret of the course, 32b"


def load(name: str, path: Path):
    """Load a file that is data, not part of a package: a hidden-test file (the grader reads it
    by path too), a fixture module, a configuration file.  The course's code imports as usual
    (``from tools import grade``)."""
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module



#: the students of :class:`VariantHomework` (their codes under :data:`SECRET`)
STUDENTS = [f"student-{i:04d}" for i in range(1000)]
#: scrypt's cost in the tests' answer keys: the digests of an edition (2**13) cost ~30 ms each
TEST_KEY_COST = 16


@functools.cache
def keys_of_the_test_students():
    """The answer keys a release with :data:`SECRET` and a roster of :data:`STUDENTS` writes
    (``tools/answer_keys.py``), cheaper to hash: what in-process checks of other variants use."""
    from tools import answer_keys as keys_tool

    return keys_tool.build(secret=SECRET, students=STUDENTS, cost=TEST_KEY_COST)


class VariantHomework:
    def __init__(self, hw: str) -> None:
        self.hw = hw
        self.hidden = load(
            f"hidden_{hw}_variants", ROOT / "solutions" / "hidden_tests" / f"{hw}.py"
        )
        self.codes = [variants.code_for(SECRET, hw, student) for student in STUDENTS]

    def grade(self, q: str, namespace: dict, data: dict) -> tuple[float, str]:
        """One hidden test on ``data``, the answers read from ``namespace`` as the grader would."""
        test = functools.partial(getattr(self.hidden, q), data=data)
        return run_question(test, LocalStudent(namespace))

    @functools.cached_property
    def _solution_cells(self) -> list[str]:
        (source,) = [s for s in build.sources() if s.stem.startswith(self.hw)]
        cells = [c.source for c in build.build(source, "solution").cells if c.cell_type == "code"]
        assert 'VARIANT = ""' in cells[0]
        return cells

    @functools.cache  # noqa: B019 - one instance per homework, kept for the session
    def solution_namespace(self, code: str) -> dict:
        """The globals of the solution notebook's code cells run with ``VARIANT = code``."""
        import matplotlib.pyplot as plt

        cells = list(self._solution_cells)
        cells[0] = cells[0].replace('VARIANT = ""', f"VARIANT = {code!r}", 1)
        ns: dict = {"__name__": f"{self.hw}_solution_variant"}
        try:
            for k, cell in enumerate(cells):
                exec(compile(cell, f"{self.hw}-solution-cell{k}", "exec"), ns)
        finally:
            plt.close("all")
        return ns


def differ(a, b) -> bool:
    """Are two worked answers different (letters, numbers, arrays, dicts of them)?"""
    if isinstance(a, str):
        return a != b
    if isinstance(a, dict):
        return any(differ(a[k], b[k]) for k in a)
    return not np.allclose(a, b)


def default_data_afterwards(hw: str):
    """An autouse fixture: after each test the checks of ``hw`` see the default data again."""

    @pytest.fixture(autouse=True)
    def _fixture():
        yield
        variants.data(hw, variants.DEFAULT)

    return _fixture


def far(a, b, rel: float = 1e-3) -> bool:
    """Are two answers at least ``rel`` of the second's size apart (other shapes always are)?"""
    a, b = np.atleast_1d(np.asarray(a, float)), np.atleast_1d(np.asarray(b, float))
    if a.shape != b.shape:
        return True
    return float(np.linalg.norm(a - b)) > rel * max(1.0, float(np.linalg.norm(b)))
