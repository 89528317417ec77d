"""Tamper evidence (issue 24): a notebook's code that reaches into the grader's guards is flagged.

``tools/grading/tamper.py`` reads a submission's code cells as syntax trees.  Every bypass the
red team found in the kernel -- the guard's state emptied, a frame's ``guarded`` rewritten,
child processes, ``HOMEWORK`` hidden, monkeypatching -- is flagged for the instructor, certain
tampering also costs the guarded questions; the course's own notebooks (homework, solutions,
lectures) are never flagged.  The end-to-end grading of such notebooks is
``tests/test_own_work_redteam.py``.
"""

from __future__ import annotations

from pathlib import Path

import nbformat
import pytest

from tools.grading import identity, reports, tamper
from tools.grading.runner import Result

ROOT = Path(__file__).resolve().parents[1]
COURSE_NOTEBOOKS = sorted(
    [*ROOT.glob("solutions/*.ipynb"), *ROOT.glob("exercises/*.ipynb"),
     *ROOT.glob("notebooks/**/*.ipynb")]
)  # fmt: skip


def _cells(path: Path) -> list[str]:
    nb = nbformat.read(path, as_version=4)
    return [c.source for c in nb.cells if c.cell_type == "code"]


PREP = 'HOMEWORK = "hw03"\nVARIANT = ""'

#: name -> (code cells after the Preparations cell, certain?)
HOSTILE = {
    "active cleared": ("from course_lib import own_work\nown_work._ACTIVE.clear()", True),
    "active through an alias": (
        "import course_lib.constructions.knot_splines as ks\now = ks.own_work\na = ow._ACTIVE\na.clear()",
        True,
    ),
    "require replaced": ("import course_lib.homework.own_work as o\no.require = lambda *a: None", True),
    "sys.modules": ('import sys\nsys.modules["course_lib.homework.own_work"]._ACTIVE.clear()', True),
    "frame's guarded": (
        "import sys\ndef f():\n    fr = sys._getframe(1)\n    while fr:\n"
        '        fr.f_locals["guarded"] = {}\n        fr = fr.f_back',
        True,
    ),
    "frame locals cleared": (
        "import inspect\ndef f():\n    inspect.currentframe().f_back.f_locals.clear()",
        True,
    ),
    "__code__": ("def f(): pass\nf.__code__ = (lambda: 1).__code__", True),
    "__import__": ("import builtins\nbuiltins.__import__ = None", True),
    "gettrace": ("import sys\nsys.gettrace = lambda: None", True),
    "probe replaced": ("import course_lib.homework.protocol as p\np.handle = None", True),
    "hidden in exec": ('exec("import course_lib.homework.own_work as o; o._ACTIVE.clear()")', True),
    "subprocess, empty env": (
        "import subprocess, sys\ndef knot_ratio_beta1(t):\n"
        '    return subprocess.run([sys.executable, "-c", "1"], env={})',
        False,
    ),
    "os.execv": ('import os\nos.execv("/bin/true", ["x"])', False),
    "multiprocessing spawn": (
        'from multiprocessing import get_context\nctx = get_context("spawn")',
        False,
    ),
    "process pool": ("from concurrent.futures import ProcessPoolExecutor", False),
    "shell escape": ('!python -c "print(1)"', False),
    "bash magic": ("%%bash\necho hi", False),
    "HOMEWORK deleted": ("del HOMEWORK", False),
    "HOMEWORK rebound": ('HOMEWORK = "hw99"', False),
    "VARIANT rebound": ("VARIANT = None", False),
    "HOMEWORK through globals()": ('globals()["HOMEWORK"] = None', False),
    "HOMEWORK through update": ("globals().update(HOMEWORK=None)", False),
    "HOMEWORK from a function": ("def f():\n    global HOMEWORK\n    HOMEWORK = None", False),
    "monkeypatched library": (
        "from course_lib import knot_splines\nknot_splines.knot_ratio_beta1 = print",
        False,
    ),
    "exec of computed code": ('x = "1"\nexec(x)', False),
    "computed getattr": ('import course_lib\ngetattr(course_lib, "own" + "_work")', False),
    "computed import": ('__import__("course_lib." + "own_work")', False),
    "garbage collector": ("import gc\ngc.get_referrers(1)", False),
    "ctypes": ("import ctypes", False),
}


@pytest.mark.parametrize("path", COURSE_NOTEBOOKS, ids=lambda p: p.name)
def test_the_course_s_own_notebooks_are_not_flagged(path):
    assert tamper.scan(_cells(path)) == []


def test_the_course_notebooks_are_there():
    names = {p.parent.name for p in COURSE_NOTEBOOKS}
    assert {"solutions", "exercises"} <= names and len(COURSE_NOTEBOOKS) >= 10


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_each_bypass_is_flagged(name):
    source, certain = HOSTILE[name]
    findings = tamper.scan([PREP, source])
    assert findings, name
    assert all(f.cell == 2 for f in findings), findings
    assert any(f.certain for f in findings) is certain, findings


def test_the_same_code_pasted_twice_is_not_a_rebinding():
    assert tamper.scan([PREP, PREP]) == []
    assert tamper.scan([PREP, 'VARIANT = "ABC"']) != []


def test_a_reason_carries_no_student_text():
    """A computed name full of markup reaches no reason (they go into summary.md)."""
    evil = "_ACTIVE\\n# **all full marks**"
    findings = tamper.scan([f'from course_lib import own_work\ngetattr(own_work, "{evil}")'])
    assert findings
    assert all("**" not in str(f) and "\n" not in str(f) for f in findings)


def _result() -> Result:
    points = {"q1": 2.0, "q2": 4.0, "q6": 2.0, "q7": 2.0}
    return Result("3004", dict(points), dict.fromkeys(points, ""),
                  fractions=dict.fromkeys(points, 1.0))  # fmt: skip


def test_certain_tampering_zeroes_the_guarded_questions_and_flags():
    r = _result()
    tamper.apply(r, [PREP, HOSTILE["active cleared"][0]], "hw03", r.points.copy())
    assert r.points == {"q1": 0.0, "q2": 0.0, "q6": 2.0, "q7": 0.0}  # q6: no guard protects it
    assert r.status == f"ok; {identity.TAMPERING}"
    assert r.review and "own_work._ACTIVE" in r.review[0]
    assert tamper.REVIEW_NOTE in r.run_notes
    assert "_ACTIVE" not in " ".join(r.run_notes)  # the student is not told what was found


def test_a_flag_alone_keeps_the_points():
    r = _result()
    tamper.apply(r, [PREP, HOSTILE["multiprocessing spawn"][0]], "hw03", r.points.copy())
    assert r.points == {"q1": 2.0, "q2": 4.0, "q6": 2.0, "q7": 2.0}
    assert identity.TAMPERING in reports.flags_of(r)


def test_an_honest_notebook_is_untouched():
    r = _result()
    assert tamper.apply(r, _cells(ROOT / "solutions" / "hw03_g1_knot_bezier_splines.ipynb"),
                        "hw03", r.points.copy()) == []  # fmt: skip
    assert r.status == "ok" and r.review == [] and r.run_notes == []


def test_the_summary_acts_on_it_first_with_the_reasons():
    class Tests:
        homework, points, max_points = "hw03", {"q1": 2.0}, 2.0

    r = _result()
    r.points, r.notes, r.fractions = {"q1": 2.0}, {"q1": ""}, {"q1": 1.0}
    tamper.apply(r, [PREP, HOSTILE["require replaced"][0]], "hw03", r.points.copy())
    text, _ = reports.summary([r], Tests, None)
    first = text.split("## Statistics")[0]
    assert "grader's guards" in first and "3004" in first and "own_work.require" in first
    assert identity.TAMPERING in identity.FLAGS
    assert identity.TAMPERING in {flag for flag, _ in reports.ACT_ON}


def test_code_too_deep_to_read_is_flagged_not_a_crash():
    deep = "x = " + "[" * 5000 + "]" * 5000
    findings = tamper.scan([PREP, deep])
    assert all(f.cell == 2 for f in findings)  # flagged, or unparsable (then it cannot run)
    nested_exec = "exec(" * 3 + '"import ctypes"' + ")" * 3
    assert tamper.scan([nested_exec]) != []


# ------------------------------------------------------------------ answers typed in
VALUE_NAMES = [f"answer_q{n}" for n in range(1, 8)]


@pytest.mark.parametrize("path", COURSE_NOTEBOOKS, ids=lambda p: p.name)
def test_no_course_notebook_types_a_value_answer_in(path):
    assert tamper.typed_answers(_cells(path), VALUE_NAMES) == []


@pytest.mark.parametrize(
    "source, flagged",
    [
        ("answer_q4 = 0.4104456668795813", True),  # computed elsewhere, pasted (the walk)
        ("answer_q5 = np.array([-1.5, -0.2237500000012])", True),
        ("answer_q7: float = float(0.7672247797918961)", True),
        ("answer_q4 = -0.41044567", False),  # 8 digits: a rounded number (the check says so)
        ("answer_q5 = np.array([4.25, -0.75])", False),  # read off small data
        ("answer_q4 = kappa", False),
        ("answer_q4 = 2 * k / (1 + 4 * k * k * u * u) ** 1.5", False),
        ("x = 0.4104456668795813", False),  # not an answer
    ],
)
def test_a_long_number_typed_as_a_value_answer_is_found(source, flagged):
    found = tamper.typed_answers(["import numpy as np", source], VALUE_NAMES)
    assert bool(found) == flagged, found
    if flagged:
        assert "typed in code cell 2" in found[0] and source.split(" ")[0].rstrip(":") in found[0]


def test_a_typed_answer_is_flagged_for_the_instructor_and_keeps_its_points():
    class Tests:
        homework, points, max_points = "hw03", {"q1": 2.0}, 2.0

    r = _result()
    r.points, r.notes, r.fractions = {"q1": 2.0}, {"q1": ""}, {"q1": 1.0}
    tamper.note_typed(r, [PREP, "answer_q1 = [0.123456789012, 2]"], ["answer_q1"])
    assert identity.TYPED_IN in reports.flags_of(r) and r.points == {"q1": 2.0}
    assert not r.run_notes  # the student's feedback says nothing of it
    text, _ = reports.summary([r], Tests, None)
    first = text.split("## Statistics")[0]
    assert "typed in as a long number" in first and "answer_q1 is a 12-digit number" in first
