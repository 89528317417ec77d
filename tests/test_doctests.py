"""The Examples of the public API run as doctests in the suite (``pytest`` with its defaults).

``pyproject.toml`` passes ``--doctest-modules`` and lists ``course_lib`` in ``testpaths``; the
root ``conftest.py`` keeps the doctests to ``course_lib``'s modules that have an example, so no
test file, hidden test or tool is imported as a doctest module.  Every public module of the
module map in CONTRIBUTING.md carries at least one example.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _conftest():
    from _homework_support import load

    return load("_root_conftest_doctests", ROOT / "conftest.py")


def _module_map() -> list[str]:
    """The ``name.py`` rows of CONTRIBUTING.md's module map, private modules left out."""
    text = (ROOT / "CONTRIBUTING.md").read_text(encoding="utf-8")
    section = text.split("## Module map", 1)[1].split("\n## ", 1)[0]
    names = re.findall(r"(?m)^\| `(?:[a-z_]+/)*([a-z][a-z0-9_]*)\.py` \|", section)
    assert len(names) >= 10, names
    # The homework boundary's other modules run inside a student's kernel or the grader; they
    # are tested end to end there (test_own_work, test_grading, test_submit_handin).
    boundary = {"answers", "protocol", "own_work", "submit"}
    return [n for n in names if n not in boundary]


@pytest.mark.parametrize("name", _module_map())
def test_every_public_module_has_an_example_that_runs(name):
    pictures = {"plotting", "widgets"}  # their modules of the same name are not the map's
    (path,) = [p for p in (ROOT / "course_lib").rglob(f"{name}.py") if not pictures & set(p.parts)]
    assert _conftest().wants_doctests(path), f"{path.relative_to(ROOT)} has no >>> example"


def test_doctests_are_collected_from_course_lib_only():
    wants = _conftest().wants_doctests
    assert any(wants(p) for p in (ROOT / "course_lib").rglob("bezier.py"))
    for other in ("tests/test_doctests.py", "solutions/hidden_tests/hw01.py", "tools/grade.py",
                  "conftest.py", "tests/fixtures/redteam/cheats.py"):  # fmt: skip
        assert not wants(ROOT / other), other
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    assert '"--doctest-modules"' in text
    assert re.search(r'(?m)^testpaths = \[.*"course_lib".*\]$', text)


def test_a_wrong_example_fails(tmp_path):
    """The doctests are checked, not only collected: a wrong expected value fails."""
    pkg = tmp_path / "course_lib"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("")
    (pkg / "wrong.py").write_text(
        'def two():\n    """\n    >>> two()\n    3\n    """\n    return 2\n'
    )
    (tmp_path / "conftest.py").write_text((ROOT / "conftest.py").read_text(encoding="utf-8"))
    (tmp_path / "pytest.ini").write_text(
        "[pytest]\naddopts = --doctest-modules -p no:cacheprovider\n"
    )
    proc = subprocess.run(
        [sys.executable, "-m", "pytest", "-q", "-p", "no:nbval", "course_lib"],
        cwd=tmp_path, capture_output=True, text=True, timeout=120,
        env={"PATH": "/usr/bin:/bin", "PYTHONPATH": str(tmp_path)},
    )  # fmt: skip
    assert proc.returncode == 1 and "1 failed" in proc.stdout, proc.stdout[-2000:]
