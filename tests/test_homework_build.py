"""The homework notebooks are generated, never edited by hand, and never leak answers.

* exercises/ and solutions/ hold exactly what ``tools/build_homework.py`` renders from
  ``tools/homework_src/`` (so the two copies never drift apart);
* a student copy contains no solution text, and no hidden test content lives in exercises/ or
  in course_lib/ (hidden tests live in solutions/hidden_tests/ only);
* hidden tests do not use course_lib (their expected values must be independent of the code
  the solution notebooks call);
* every notebook has a title, a how-to, a Preparations cell, a check cell per question and a
  final check-all cell.
"""

from __future__ import annotations

import importlib.util
import json
import re
import sys
from pathlib import Path

import pytest

from course_lib.checks import HOMEWORKS, questions, registry

ROOT = Path(__file__).resolve().parents[1]


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


build = _load("build_homework", ROOT / "tools" / "build_homework.py")
SOURCES = build.sources()
HIDDEN = sorted((ROOT / "solutions" / "hidden_tests").glob("hw*.py"))


def test_one_source_per_homework():
    assert [s.stem[:4] for s in SOURCES] == list(HOMEWORKS)
    assert [h.stem for h in HIDDEN] == list(HOMEWORKS)


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
@pytest.mark.parametrize("version", ["student", "solution"])
def test_committed_notebook_is_generated(source, version):
    path = build.target(source, version)
    assert path.exists(), f"missing {path}; run python tools/build_homework.py"
    assert path.read_text(encoding="utf-8") == build.render(source, version), (
        f"{path.relative_to(ROOT)} differs from its source; run python tools/build_homework.py"
    )


def _solution_lines(source: Path) -> set[str]:
    """Non-trivial lines inside solution blocks / solution-only cells that occur nowhere else."""
    text = source.read_text(encoding="utf-8")
    inside, only, sol, common = False, False, set(), set()
    for line in text.splitlines():
        s = line.strip()
        m = re.match(r"^# %%(?: \[markdown\])?(?: (solution|student))?\s*$", line)
        if m:
            only = m.group(1) == "solution"
            continue
        if s in (build._BEGIN, build._END):
            inside = s == build._BEGIN
            continue
        if s.startswith("#"):
            s = s.lstrip("# ").strip()
        if len(s) < 12 or s.startswith(build._STUDENT.lstrip("# ")):
            continue
        (sol if inside or only else common).add(s)
    return sol - common


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
def test_student_copy_has_no_solution_text(source):
    student = "\n".join(
        "".join(c["source"])
        for c in json.loads(build.target(source, "student").read_text(encoding="utf-8"))["cells"]
    )
    lines = _solution_lines(source)
    assert lines, "the source has no solution blocks?"
    leaked = [s for s in lines if s in student]
    assert not leaked, f"solution text in the student copy: {leaked[:3]}"
    for marker in ("BEGIN SOLUTION", "END SOLUTION", "### STUDENT"):
        assert marker not in student
    # the placeholders are there instead
    assert "= ..." in student and "NotImplementedError" in student


def _hidden_fingerprints(path: Path) -> list[str]:
    """Lines of a hidden test file that are specific to it (assert messages, expected data)."""
    out = []
    for line in path.read_text(encoding="utf-8").splitlines():
        s = line.strip()
        if s.startswith(("assert ", "# ", "return ")) and len(s) > 25:
            out.append(s)
    return out


@pytest.mark.parametrize("hidden", HIDDEN, ids=lambda p: p.stem)
def test_hidden_tests_stay_hidden(hidden):
    fingerprints = _hidden_fingerprints(hidden)
    assert len(fingerprints) >= 5
    shipped = [p for p in (ROOT / "exercises").rglob("*") if p.is_file()]
    shipped += [p for p in (ROOT / "course_lib").rglob("*.py")]
    for path in shipped:
        text = path.read_text(encoding="utf-8", errors="replace")
        leaked = [f for f in fingerprints if f in text]
        assert not leaked, f"hidden test text of {hidden.name} found in {path}: {leaked[:2]}"
    assert not list((ROOT / "exercises").rglob("hidden*"))


@pytest.mark.parametrize("hidden", HIDDEN, ids=lambda p: p.stem)
def test_hidden_tests_are_independent_of_course_lib(hidden):
    text = hidden.read_text(encoding="utf-8")
    imports = re.findall(r"^\s*(?:from|import)\s+(\S+)", text, flags=re.MULTILINE)
    assert not [m for m in imports if m.startswith("course_lib")], imports
    module = _load(f"hidden_{hidden.stem}", hidden)
    qs = [q.split(".")[1] for q in questions(hidden.stem)]
    assert list(module.POINTS) == qs, "hidden tests and feedback checks must cover the same questions"
    assert all(callable(getattr(module, q)) for q in qs)


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
@pytest.mark.parametrize("version", ["student", "solution"])
def test_notebook_layout(source, version):
    nb = json.loads(build.target(source, version).read_text(encoding="utf-8"))
    cells = nb["cells"]
    text = ["".join(c["source"]) for c in cells]
    assert cells[0]["cell_type"] == "markdown" and "\n# Homework" in "\n" + text[0]
    assert "How to work" in text[0] and "check cell" in text[0]
    assert text[1].strip() == "## Preparations" and "from course_lib.checks import" in text[2]
    hw = source.stem[:4]
    for qid in questions(hw):
        name = registry()[qid].answer_name
        assert any(t.strip() == f'check("{qid}", {name})' for t in text), f"no check cell for {qid}"
    assert "check_all(globals(), HOMEWORK)" in text[-1]
    if version == "solution":
        assert "assert report.all_passed" in text[-1]
    for c in cells:
        if c["cell_type"] == "code":
            assert c["outputs"] == [] and c["execution_count"] is None
