"""Issue 24's in-kernel bypasses, graded as a course grades them: the real grader command.

The red team scored a function question with the library's own implementation by tampering in
the kernel.  Each bypass is now a hw03 notebook -- the solution done with the student's own
variant code, one answer replaced by the bypass -- handed in beside the honest solution and
graded with ``tools/grade.py`` as the README prints it (a course secret made with
``tools/variant.py secret``, a roster, ``--secret-file``, ``--roster``, the bubblewrap sandbox):

* a child process started with an empty environment (``subprocess.run(..., env={})``) that
  imports ``course_lib`` and calls the exercise: the grader's state file, read-only in the
  sandbox, guards it there -- 0 for the question, and flagged (it starts a process);
* a ``multiprocessing`` spawn pool doing the same: 0, with the own-work sentence, flagged;
* the probe's guard state emptied from a frame (``f_locals["guarded"]``, ``own_work._ACTIVE``):
  0 for every guarded question (certain tampering) and flagged;
* ``HOMEWORK`` hidden while a value is computed with the library: that value's question 0,
  flagged;
* the honest solution: full marks, no flag, and the same feedback as before.

The child-process bypass graded *without* a sandbox (no state file) scores its question: the
state file is what stops it (so this test can fail).
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import nbformat
import pytest
from _homework_support import load

ROOT = Path(__file__).resolve().parents[1]
HW, NAME = "hw03", "hw03_g1_knot_bezier_splines.ipynb"
FLAG = "reaches into the grader"

pytestmark = [pytest.mark.slow, pytest.mark.timeout(900)]

ROSTER = (
    "id,name,email\n"
    "3001,Honest Hana,h@example.edu\n"
    "3002,Child Carl,c@example.edu\n"
    "3003,Spawn Sue,s@example.edu\n"
    "3004,Frame Fred,f@example.edu\n"
    "3005,Hidden Hal,x@example.edu\n"
)

# the bypasses, each replacing the cell that starts with ``anchor`` in the solution
CHILD = """
import json, os, subprocess, sys
import course_lib

_ROOT = os.path.dirname(os.path.dirname(course_lib.__file__))


def knot_ratio_beta1(knots):
    code = (
        "import json, sys; sys.path[:0] = [%r]; "
        "from course_lib.constructions.knot_splines import knot_ratio_beta1; "
        "print(json.dumps([float(x) for x in knot_ratio_beta1(json.loads(sys.argv[1]))]))"
    ) % _ROOT
    done = subprocess.run(
        [sys.executable, "-c", code, json.dumps([float(k) for k in knots])],
        env={}, capture_output=True, text=True, timeout=60,
    )
    return np.array(json.loads(done.stdout))
"""

SPAWN = """
import multiprocessing
from course_lib.constructions import knot_splines


def knot_ratio_beta1(knots):
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        return pool.apply(knot_splines.knot_ratio_beta1, (np.asarray(knots, dtype=float),))
"""

FRAMES = """
import sys
from course_lib.constructions import knot_splines


def knot_ratio_beta1(knots):
    frame = sys._getframe(1)
    while frame is not None:
        if "guarded" in frame.f_locals:
            frame.f_locals["guarded"] = {}
        frame = frame.f_back
    knot_splines.own_work._ACTIVE.clear()
    return knot_splines.knot_ratio_beta1(knots)
"""

HIDDEN = """
from course_lib.constructions.knot_splines import bezier_points_from_g1

_kept = HOMEWORK
del HOMEWORK
answer_q1 = bezier_points_from_g1(D[:6], DATA["q1"]["knots"])[3]
HOMEWORK = _kept
"""

Q7, Q1 = "def knot_ratio_beta1(knots):", 't0, t1, t2 = DATA["q1"]["knots"]'
CHEATS = {"3002": (Q7, CHILD), "3003": (Q7, SPAWN), "3004": (Q7, FRAMES), "3005": (Q1, HIDDEN)}


def run(*cmd: str) -> str:
    """A command as a user types it: the venv's bin first on PATH (an activated venv)."""
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    env["PYTHONPATH"] = str(ROOT)
    done = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True, timeout=800)
    assert done.returncode == 0, (cmd, done.stdout[-3000:], done.stderr[-3000:])
    return done.stdout


def notebook(code: str, cheat: tuple[str, str] | None) -> nbformat.NotebookNode:
    """The hw03 solution done with ``code``; with ``cheat``, one answer cell replaced."""
    nb = nbformat.read(ROOT / "solutions" / NAME, as_version=4)
    (first,) = [c for c in nb.cells if c.cell_type == "code" and 'VARIANT = ""' in c.source]
    first.source = first.source.replace('VARIANT = ""', f'VARIANT = "{code}"', 1)
    if cheat is not None:
        anchor, source = cheat
        (cell,) = [c for c in nb.cells if c.cell_type == "code" and c.source.startswith(anchor)]
        cell.source = source.strip()
    return nb


def _rows(out: Path) -> dict[str, dict]:
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        return {r["student"]: r for r in csv.DictReader(fh)}


def _results(out: Path) -> dict[str, dict]:
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return {r["student"]: r for r in data["results"]}


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    base = tmp_path_factory.mktemp("redteam24")
    (base / "roster.csv").write_text(ROSTER, encoding="utf-8")
    secret = base / "course_secret.txt"
    run(sys.executable, "tools/variant.py", "secret", "--out", str(secret))
    run(sys.executable, "tools/variant.py", "codes", HW, "--secret-file", str(secret),
        "--roster", str(base / "roster.csv"), "--out", str(base / "codes.csv"))  # fmt: skip
    with open(base / "codes.csv", newline="", encoding="utf-8") as fh:
        codes = {row["id"]: row["code"] for row in csv.DictReader(fh)}
    subs = base / "submissions"
    subs.mkdir()
    for sid in codes:
        nbformat.write(notebook(codes[sid], CHEATS.get(sid)), subs / f"{HW}-{sid}.ipynb")
    out = base / "grades"
    run(sys.executable, "tools/grade.py", "--tests", f"solutions/hidden_tests/{HW}.py",
        "--submissions", str(subs), "--out", str(out), "--jobs", "2", "--sandbox", "bwrap",
        "--roster", str(base / "roster.csv"), "--secret-file", str(secret))  # fmt: skip
    # the child-process bypass without a sandbox (no state file), graded on the same data
    alone = base / "unsandboxed"
    alone.mkdir()
    nbformat.write(notebook(codes["3002"], CHEATS["3002"]), alone / f"{HW}-3002.ipynb")
    run(sys.executable, "tools/grade.py", "--tests", f"solutions/hidden_tests/{HW}.py",
        "--submissions", str(alone), "--out", str(base / "grades-none"), "--sandbox", "none",
        "--roster", str(base / "roster.csv"), "--secret-file", str(secret))  # fmt: skip
    return {"out": out, "none": base / "grades-none"}


_ok, _why = load("grade_redteam24", ROOT / "tools" / "grade.py").sandbox.bwrap_works()
needs_sandbox = pytest.mark.skipif(
    not _ok and os.environ.get("CI") != "true", reason=f"no sandbox: {_why}"
)


@needs_sandbox
def test_the_honest_solution_keeps_full_marks_unflagged(graded):
    row = _rows(graded["out"])["3001"]
    assert float(row["total"]) == 15, row
    assert FLAG not in row["status"]
    text = (graded["out"] / "feedback" / "3001.md").read_text(encoding="utf-8")
    assert "flagged" not in text


@needs_sandbox
@pytest.mark.parametrize("sid", ["3002", "3003", "3004"])
def test_a_function_bypass_scores_zero_and_is_flagged(graded, sid):
    row, result = _rows(graded["out"])[sid], _results(graded["out"])[sid]
    assert float(row["q7"]) == 0, (sid, result["notes"]["q7"])
    assert FLAG in row["status"], row
    assert result["review"], result
    text = (graded["out"] / "feedback" / f"{sid}.md").read_text(encoding="utf-8")
    assert "flagged for the instructor's review" in text
    for word in ("subprocess", "f_locals", "multiprocessing", "_ACTIVE", "scan"):
        assert word not in text  # the student is not taught how the scan works
    summary = (graded["out"] / "summary.md").read_text(encoding="utf-8")
    first = summary.split("## Statistics")[0]
    assert "reaches into the grader" in first.lower() or "grader's guards" in first
    assert sid in first


@needs_sandbox
def test_the_spawned_child_names_the_exercise(graded):
    note = _results(graded["out"])["3003"]["notes"]["q7"]
    assert "knot_ratio_beta1 is the exercise of hw03.q7: write it yourself" in note


@needs_sandbox
def test_emptying_the_guard_state_is_certain_tampering(graded):
    row = _rows(graded["out"])["3004"]
    # every question the library's guards protect in hw03 scores 0, not only q7
    for q in ("q1", "q2", "q3", "q5", "q7"):
        assert float(row[q]) == 0, (q, row)
    assert float(row["q6"]) == 2  # a question no guard protects keeps its points


@needs_sandbox
def test_hiding_homework_does_not_unguard_a_value(graded):
    row, result = _rows(graded["out"])["3005"], _results(graded["out"])["3005"]
    assert float(row["q1"]) == 0, result["notes"]["q1"]
    assert float(row["q7"]) == 2 and float(row["q2"]) == 4  # the rest is the honest solution
    assert FLAG in row["status"]


def test_the_child_bypass_scores_without_the_state_file(graded):
    """Unsandboxed (no state file), the same notebook earns q7: the file is what stops it."""
    row = _rows(graded["none"])["3002"]
    assert float(row["q7"]) == 2, row
    assert FLAG in row["status"]  # the scan flags it all the same
