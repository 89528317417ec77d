"""The homework notebooks are generated, never edited by hand, and never leak answers.

* exercises/ and solutions/ hold exactly what ``tools/build_homework.py`` renders from
  ``tools/homework_src/`` (so the two copies never drift apart);
* a student copy contains no solution text, and no hidden test content lives in exercises/ or
  in course_lib/ (hidden tests live in solutions/hidden_tests/ only);
* hidden tests use nothing of course_lib but ``course_lib.homework.answers`` (the answer normalizers they
  share with the feedback checks, which hold no mathematics): their expected values must be
  independent of the code the solution notebooks call; they take the ``qN(student)`` form and
  never parse student text (no sympify / parse_expr / eval);
* every notebook has a title, a how-to, a Preparations cell setting ``HOMEWORK``, a check cell
  per question, a check-all cell as its last code cell, and ends with the "Hand in" section;
* one source, one checks module and one hidden-test file per homework (the list of homework is
  derived from the files: ``course_lib.homework.checks.HOMEWORKS``).
"""

from __future__ import annotations

import inspect
import json
import re
from pathlib import Path

import pytest
from _homework_support import load

from course_lib.homework.checks import HOMEWORKS, questions, registry
from tools import build_homework as build

ROOT = Path(__file__).resolve().parents[1]




SOURCES = build.sources()
HIDDEN = sorted((ROOT / "solutions" / "hidden_tests").glob("hw*.py"))


def test_one_source_per_homework():
    """Each homework hwNN has exactly one source, one checks module and one hidden-test file.

    ``HOMEWORKS`` is derived from the modules ``course_lib/homework/checks/hwNN.py``; the other two lists
    from the files, so nothing is registered by hand (``tools/new_homework.py`` writes all three).
    """
    sources = [s.stem[:4] for s in SOURCES]
    assert sources == list(HOMEWORKS), (
        f"tools/homework_src/ has sources for {sources}, course_lib/homework/checks/ has modules for "
        f"{list(HOMEWORKS)}: one source hwNN_<name>.py and one checks module hwNN.py per homework"
    )
    hidden = [h.stem for h in HIDDEN]
    assert hidden == list(HOMEWORKS), (
        f"solutions/hidden_tests/ has {hidden}, course_lib/homework/checks/ has {list(HOMEWORKS)}: "
        "one hidden-test file hwNN.py per homework"
    )


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
    imports = re.findall(r"^\s*(from\s+\S+\s+import\s+[^\n]+|import\s+\S+)", text, flags=re.MULTILINE)
    from_course_lib = [m for m in imports if "course_lib" in m]
    assert from_course_lib == ["from course_lib.homework import answers"], from_course_lib
    for forbidden in ("sympify", "parse_expr", "eval(", "exec(", "import sympy", "lambdify"):
        assert forbidden not in text, f"{hidden.name} must not use {forbidden}: student text is data"
    module = load(f"hidden_{hidden.stem}", hidden)
    qs = [q.split(".")[1] for q in questions(hidden.stem)]
    assert list(module.POINTS) == qs, "hidden tests and feedback checks must cover the same questions"
    for q in qs:
        fn = getattr(module, q)
        params = ["student", "data"] if getattr(module, "VARIANTS", False) else ["student"]
        assert callable(fn) and list(inspect.signature(fn).parameters) == params, q


def _choice_questions(module) -> set[str]:
    """The questions whose hidden test reads a multiple-choice answer."""
    return {q for q in module.POINTS if "answers.choice(" in inspect.getsource(getattr(module, q))}


@pytest.mark.parametrize("hidden", HIDDEN, ids=lambda p: p.stem)
def test_multiple_choice_is_feedback_only(hidden):
    """No point for what trying each letter in the check finds (the README's one-liner rule)."""
    module = load(f"hidden_{hidden.stem}_points", hidden)
    choice = _choice_questions(module)
    if hidden.stem == "hw01":  # the detection is not stale: hw01's two multiple-choice questions
        assert choice == {"q3", "q6"}, choice
    paid = {q: module.POINTS[q] for q in choice if module.POINTS[q] != 0}
    assert not paid, f"{hidden.name}: multiple choice must be worth 0 points (feedback only): {paid}"
    assert sum(module.POINTS.values()) > 0


def test_answers_module_knows_no_mathematics_of_the_course():
    text = (ROOT / "course_lib" / "homework" / "answers.py").read_text(encoding="utf-8")
    imports = re.findall(r"^\s*(?:from|import)\s+(\S+)", text, flags=re.MULTILINE)
    # the wire format (and, for the default data, the variants), nothing of the mathematics
    allowed = {"course_lib.homework", "course_lib.homework.protocol"}
    assert {m for m in imports if "course_lib" in m or m.startswith(".")} <= allowed
    assert "from course_lib.homework import protocol" in text  # the wire format it reads


@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.stem)
@pytest.mark.parametrize("version", ["student", "solution"])
def test_notebook_layout(source, version):
    nb = json.loads(build.target(source, version).read_text(encoding="utf-8"))
    cells = nb["cells"]
    text = ["".join(c["source"]) for c in cells]
    assert cells[0]["cell_type"] == "markdown" and "\n# Homework" in "\n" + text[0]
    assert "How to work" in text[0] and "check cell" in text[0]
    assert text[1].strip() == "## Preparations" and "from course_lib.homework.checks import" in text[2]
    hw = source.stem[:4]
    for qid in questions(hw):
        name = registry()[qid].answer_name
        assert any(t.strip() == f'check("{qid}", {name})' for t in text), f"no check cell for {qid}"
    assert f'HOMEWORK = "{hw}"' in text[2], "the Preparations cell must set HOMEWORK"
    code = [t for c, t in zip(cells, text, strict=True) if c["cell_type"] == "code"]
    assert "check_all(globals(), HOMEWORK)" in code[-1], "the last code cell must check everything"
    if version == "solution":
        assert "assert report.all_passed" in code[-1]
    # the notebook ends with how to hand it in (course_lib.homework.submit)
    assert cells[-1]["cell_type"] == "markdown" and text[-1].startswith("## Hand in"), text[-1][:60]
    assert f"make submit HW={hw}" in text[-1] and f'submit("{source.stem}.ipynb"' in text[-1]
    for c in cells:
        if c["cell_type"] == "code":
            assert c["outputs"] == [] and c["execution_count"] is None


def test_the_example_variant_code_in_each_homework_is_a_valid_code():
    """A student who copies the example to see the format gets the format right (check character)."""
    from course_lib.homework import variants

    for src in sorted((ROOT / "tools" / "homework_src").glob("hw*.py")):
        examples = re.findall(r'e\.g\. VARIANT = "([^"]+)"', src.read_text())
        assert examples, f"{src.name}: no example code"
        for code in examples:
            assert variants.normalize(code) == code, src.name
