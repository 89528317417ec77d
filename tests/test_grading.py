"""The grading command, end to end (tools/grade.py with nbclient kernels).

* the solution notebooks score full marks and the blank exercises score zero, for every
  homework set with a hidden-test file in solutions/hidden_tests/ (found, not listed);
* the faulty submissions of tests/fixtures/submissions/hw01/ (named by what they get wrong)
  each get exactly the expected points and notes -- an exception, an endless loop (in a cell
  and in a graded function), a kernel that dies, malformed JSON, deleted variables, answers of
  the wrong type -- and none of them stops the batch;
* nothing is modified: every submitted file is byte-identical afterwards (sha256);
* a hang never blocks the batch: the endless loop costs one short cell timeout.
"""

from __future__ import annotations

import csv
import hashlib
import json
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from tools import grade

ROOT = Path(__file__).resolve().parents[1]
FIXTURES = ROOT / "tests" / "fixtures" / "submissions" / "hw01"
HIDDEN = ROOT / "solutions" / "hidden_tests"


pytestmark = [pytest.mark.slow, pytest.mark.timeout(180)]
# the sandbox where it works (make test installs bubblewrap), else unsandboxed (macOS)
MODE = "bwrap" if grade.sandbox.bwrap_works()[0] else "none"


def _hashes(paths) -> dict[Path, str]:
    return {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in paths}


# name -> (total of 11 (q3 and q6 are multiple choice: feedback only), per-question note fragments, run-note fragments, status)
EXPECTED = {
    "correct": (11, {}, [], "ok"),
    "fails_q1_q4": (7, {"q1": "T(1) is wrong", "q4": "κ(1) is wrong"}, [], "ok"),
    "raises": (8, {"q2": "raised ValueError (the message is not shown"}, ["code cell 1 (the ", "raised ZeroDivisionError"], "ok"),
    "endless_loop": (
        8,
        {"q2": "did not finish within 2 s"},
        ["code cell 3 was skipped: it ran longer than 5 s"],
        "partly skipped",
    ),
    "kernel_dies": (11, {}, ["code cell 2 was skipped: the kernel died"], "partly skipped"),
    "malformed": (0, {"q1": "not a valid notebook"}, ["not a valid notebook"], "invalid notebook"),
    "deleted_variables": (
        6,
        {"q1": "`answer_q1` is not defined", "q2": "`chain_rule_derivatives` is not defined"},
        [],
        "ok",
    ),
    "wrong_types": (
        2,
        {"q1": "is None", "q2": "shape", "q3": "as a string", "q5": "is a string", "q7": "NaN"},
        [],
        "ok",
    ),
}


@pytest.fixture(scope="module")
def fixture_run(tmp_path_factory):
    files = sorted(FIXTURES.glob("*.ipynb"))
    before = _hashes(files)
    out = tmp_path_factory.mktemp("grades")
    start = time.monotonic()
    code = grade.main(
        [
            "--tests", str(HIDDEN / "hw01.py"),
            "--submissions", str(FIXTURES),
            "--out", str(out),
            "--cell-timeout", "5",
            "--question-timeout", "2",
            "--time-limit", "40",
            "--jobs", "4",
            "--sandbox", "auto",
        ]
    )  # fmt: skip
    return {"code": code, "out": out, "before": before, "after": _hashes(files),
            "seconds": time.monotonic() - start}  # fmt: skip


def test_fixture_set_is_complete():
    assert sorted(p.stem for p in FIXTURES.glob("*.ipynb")) == sorted(EXPECTED)


def test_batch_runs_and_leaves_submissions_untouched(fixture_run):
    assert fixture_run["code"] == 0
    assert fixture_run["before"] == fixture_run["after"]
    # how long the batch took is measured, not asserted (a loaded machine is slow, not wrong)
    print(f"grading the fixture batch took {fixture_run['seconds']:.1f} s")


def _rows(out: Path) -> dict[str, dict[str, str]]:
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        return {r["student"]: r for r in csv.DictReader(fh)}


#: the fixtures that type q7's arc length in as a number (answer_q7 = 1.4789428575445975): the
#: grader flags that for the instructor ("answer typed in", tools/grading/tamper.py); points stand
TYPED_Q7 = {"correct", "deleted_variables", "endless_loop", "fails_q1_q4", "kernel_dies", "raises"}


@pytest.mark.parametrize("name", sorted(EXPECTED))
def test_each_faulty_submission_gets_its_points_and_notes(fixture_run, name):
    total, notes, run_notes, status = EXPECTED[name]
    row = _rows(fixture_run["out"])[name]
    assert float(row["total"]) == total
    typed = "answer_q7 = 1.4789428575445975" in (FIXTURES / f"{name}.ipynb").read_text(encoding="utf-8")
    assert typed == (name in TYPED_Q7)
    assert row["status"] == status + ("; answer typed in" if typed else "")
    feedback = (fixture_run["out"] / "feedback" / f"{name}.md").read_text(encoding="utf-8")
    assert f"**Score: {total:g} / 11**" in feedback
    for q, fragment in notes.items():
        line = next(x for x in feedback.splitlines() if x.startswith(f"| {q} |"))
        assert fragment in line, f"{name} {q}: {line}"
        assert float(row[q]) == 0
    for fragment in run_notes:
        assert fragment in feedback, f"{name}: no run note {fragment!r}"
    if total == 11:
        assert all(
            float(row[q]) == grade.HiddenTests.load(HIDDEN / "hw01.py").points[q] for q in notes
        )


def test_score_table_layout(fixture_run):
    """One row per student and nothing else: the maximum lives in summary.md / results.json."""
    with open(fixture_run["out"] / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == ["student", "q1", "q2", "q3", "q4", "q5", "q6", "q7", "raw_total",
                       "late_penalty", "total", "status", "sandbox"]  # fmt: skip
    assert sorted(r[0] for r in rows[1:]) == sorted(EXPECTED)
    results = json.loads((fixture_run["out"] / "results.json").read_text(encoding="utf-8"))
    assert sum(results["points"].values()) == 11
    assert "maximum 11 points" in (fixture_run["out"] / "summary.md").read_text(encoding="utf-8")
    assert (fixture_run["out"] / "histogram.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def _homework_files() -> dict[str, str | dict[str, list[str]]]:
    """hwNN -> notebook name, for every hidden-test file ``solutions/hidden_tests/hwNN.py``.

    Derived from the files, so a new homework is graded here without registering it.
    """
    files = {}
    for hidden in sorted(HIDDEN.glob("hw*.py")):
        hw = hidden.stem
        names = {
            folder: sorted(p.name for p in (ROOT / folder).glob(f"{hw}_*.ipynb"))
            for folder in ("exercises", "solutions")
        }
        one = names["solutions"] == names["exercises"] and len(names["solutions"]) == 1
        files[hw] = names["solutions"][0] if one else names  # a dict: reported by the test
    return files


HOMEWORK_FILES = _homework_files()


def test_solutions_full_marks_blank_exercises_zero():
    assert len(HOMEWORK_FILES) >= 4, HOMEWORK_FILES
    bad = {hw: n for hw, n in HOMEWORK_FILES.items() if not isinstance(n, str)}
    assert not bad, f"each hidden test needs one exercises/ and one solutions/ notebook hwNN_*.ipynb: {bad}"
    jobs = []
    for hw, name in HOMEWORK_FILES.items():
        tests = grade.HiddenTests.load(HIDDEN / f"{hw}.py")
        jobs += [
            (ROOT / "solutions" / name, tests, "solution"),
            (ROOT / "exercises" / name, tests, "blank"),
        ]
    before = _hashes(p for p, _, _ in jobs)

    def run(job):
        path, tests, kind = job
        return (
            kind,
            tests,
            grade.grade_notebook(path, tests, kind, cell_timeout=60, time_limit=120, mode=MODE),
        )

    with ThreadPoolExecutor(max_workers=4) as pool:
        results = list(pool.map(run, jobs))
    for kind, tests, r in results:
        assert r.status == "ok", (tests.homework, kind, r.run_notes)
        if kind == "solution":
            assert r.total == tests.max_points, (tests.homework, r.notes)
        else:
            assert r.total == 0, (tests.homework, r.points)
            assert all(
                "not answered" in n for n in r.notes.values() if "NotImplemented" in n or "..." in n
            )
    assert _hashes(p for p, _, _ in jobs) == before


def test_overall_time_limit_stops_a_slow_submission(tmp_path):
    """A notebook whose cells each take a while is cut off at the wall limit, with a note."""
    import nbformat

    nb = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell("import time\ntime.sleep(1.5)") for _ in range(6)]
        + [nbformat.v4.new_code_cell("answer_q3 = 'd'")]
    )
    path = tmp_path / "slow.ipynb"
    nbformat.write(nb, path)
    tests = grade.HiddenTests.load(HIDDEN / "hw01.py")
    start = time.monotonic()
    r = grade.grade_notebook(
        path, tests, "slow", cell_timeout=10, time_limit=4, question_timeout=2, mode=MODE
    )
    assert time.monotonic() - start < 15
    assert r.status == "time limit" and r.total == 0
    assert any("overall time limit of 4 s" in n for n in r.run_notes), r.run_notes
