"""From a student's submit() to a gradebook import (issue 15), end to end.

A student answers hw01 (the solution's code), calls ``submit()``; another hands in the blank
notebook; a third copies a submission by hand.  The grader reads the manifests, maps the
submissions through a roster, applies a deadline the first student missed by less than a day,
and writes Canvas's import layout.  ``--only`` regrades one student and leaves the other rows
alone; the same batch on a Dask ``LocalCluster`` of two worker processes gives the same scores.
"""

from __future__ import annotations

import csv
import json
import shutil
from datetime import datetime, timedelta
from pathlib import Path

import nbformat
import pytest

from course_lib.homework.submit import manifest_of, notebook_digest, submit
from tools import grade

ROOT = Path(__file__).resolve().parents[1]
HIDDEN = ROOT / "solutions" / "hidden_tests" / "hw01.py"
NAME = "hw01_reparametrization.ipynb"


pytestmark = [pytest.mark.slow, pytest.mark.timeout(300)]


@pytest.fixture(scope="module")
def course(tmp_path_factory):
    """A student's working folder and a folder of submissions as an LMS would give them."""
    work = tmp_path_factory.mktemp("student")
    (work / "exercises").mkdir()
    solved = work / "exercises" / NAME
    shutil.copyfile(ROOT / "solutions" / NAME, solved)
    blank = work / "exercises" / "blank.ipynb"
    shutil.copyfile(ROOT / "exercises" / NAME, blank)
    sub_a = submit(solved, student="s001")
    sub_b = submit(blank, student="s002", out_dir=work / "submissions")
    subs = tmp_path_factory.mktemp("lms")
    shutil.copyfile(sub_a.path, subs / "s001.ipynb")
    shutil.copyfile(sub_b.path, subs / "s002.ipynb")
    shutil.copyfile(ROOT / "exercises" / NAME, subs / "stranger.ipynb")  # not in the roster
    roster = subs.parent / "roster.csv"
    roster.write_text(
        "id,submission,name,email\n"
        "1001,s001,\"Lovelace, Ada\",ada@example.org\n"
        "1002,s002,\"Noether, Emmy\",emmy@example.org\n"
        "1003,s003,\"Germain, Sophie\",sophie@example.org\n",
        encoding="utf-8",
    )
    submitted = manifest_of(nbformat.read(sub_a.path, as_version=4))["time"]
    deadline = (submitted - timedelta(hours=2)).isoformat()  # one started day late
    return {"subs": subs, "roster": roster, "deadline": deadline, "sub_a": sub_a, "sub_b": sub_b}


def _grade(course, out: Path, *extra: str) -> int:
    return grade.main(
        ["--tests", str(HIDDEN), "--submissions", str(course["subs"]), "--out", str(out),
         "--roster", str(course["roster"]), "--deadline", course["deadline"],
         "--late-penalty", "10%", "--jobs", "2", *extra]
    )  # fmt: skip


def test_submit_writes_a_manifest_and_reports_failed_cells(course):
    a, b = course["sub_a"], course["sub_b"]
    assert a.path.name == "hw01-s001.ipynb" and a.failed_cells == []
    assert "Every cell ran" in a._repr_markdown_()
    assert b.failed_cells == []  # a blank homework runs cleanly: its checks say "not answered"
    nb = nbformat.read(a.path, as_version=4)
    m = manifest_of(nb)
    assert m["student"] == "s001" and m["homework"] == "hw01" and not m["tampered"]
    nb.cells[-1].source += "\n# edited after submit"
    assert manifest_of(nb)["tampered"]
    assert notebook_digest(nb) != nb.metadata["course_submission"]["sha256"]


def test_submit_lists_the_cells_that_fail_in_a_fresh_kernel(tmp_path, capsys):
    nb = nbformat.v4.new_notebook(cells=[
        nbformat.v4.new_code_cell('HOMEWORK = "hw01"'),
        nbformat.v4.new_code_cell("answer_q1 = undefined_name"),
        nbformat.v4.new_markdown_cell("## q2"),
        nbformat.v4.new_code_cell("\nassert 1 == 2"),
    ])  # fmt: skip
    nbformat.write(nb, tmp_path / "mine.ipynb")
    sub = submit(tmp_path / "mine.ipynb", student="s9", out_dir=tmp_path / "out")
    # as JupyterLab shows the cell: its place in the notebook and its first line; no empty ": "
    assert sub.failed_cells == [
        "code cell 2 (the 2nd cell of the notebook, starting `answer_q1 = undefined_name`): "
        "NameError: name 'undefined_name' is not defined",
        "code cell 3 (the 4th cell of the notebook, starting `assert 1 == 2`): AssertionError",
    ]
    assert "2 cell(s) raised an error" in str(sub)
    # from a notebook cell as from `make submit`: the summary is printed, never a bare repr,
    # and the hand-in kernel's TCP start-up warning is not shown
    shown = capsys.readouterr()
    assert "Submission written" in shown.out and "2 cell(s) raised an error" in shown.out
    assert "without encryption" not in shown.err
    assert not repr(sub).startswith("Submission(") and "Submission written" in repr(sub)


def test_submit_refuses_a_bad_student_id(course):
    with pytest.raises(ValueError, match="student must be your student id"):
        submit(course["sub_a"].path, student="../../etc")


@pytest.fixture(scope="module")
def canvas(course, tmp_path_factory):
    out = tmp_path_factory.mktemp("canvas")
    assert _grade(course, out, "--format", "canvas") == 0
    return out


def test_canvas_import_layout_with_late_penalty(canvas):
    rows = list(csv.reader(open(canvas / "scores.csv", encoding="utf-8")))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "hw01"]
    assert rows[1][0].strip() == "Points Possible" and rows[1][5] == "11"
    # a course roster's id is the SIS User ID Canvas matches on (ID is Canvas's own user id,
    # which only a Canvas export as roster knows); unmatched submissions never enter the file
    by_id = {r[2]: r for r in rows[2:]}
    assert sorted(by_id) == ["1001", "1002"] and all(r[1] == "" for r in rows[2:])
    # 11 points, one started day late at 10 % per day -> 9.9
    assert by_id["1001"][0] == "Lovelace, Ada" and float(by_id["1001"][5]) == pytest.approx(9.9)
    assert float(by_id["1002"][5]) == 0
    feedback = (canvas / "feedback" / "s001.md").read_text(encoding="utf-8")
    assert "10% of the points off per started day late" in feedback
    assert "Late by 1 started day(s): 10% off (11 → 9.9)" in feedback
    summary = (canvas / "summary.md").read_text(encoding="utf-8")
    assert "Submissions not in the roster (1): stranger" in summary
    assert summary.index("Act on these first") < summary.index("Statistics")
    late = next(x for x in summary.splitlines() if x.startswith("- **Late**"))
    assert "1001 (Lovelace, Ada)" in late
    assert "without a submission (1): 1003" in summary
    assert (canvas / "histogram.png").stat().st_size > 1000


def test_only_regrades_one_student_and_keeps_the_other_rows(course, canvas, tmp_path):
    out = tmp_path / "grades"
    shutil.copytree(canvas, out)
    before = list(csv.reader(open(out / "scores.csv", encoding="utf-8")))
    other_feedback = (out / "feedback" / "s002.md").read_bytes()
    shutil.copyfile(ROOT / "exercises" / NAME, course["subs"] / "stranger.ipynb")
    assert _grade(course, out, "--format", "canvas", "--only", "s001") == 0
    after = list(csv.reader(open(out / "scores.csv", encoding="utf-8")))
    assert after == before
    assert (out / "feedback" / "s002.md").read_bytes() == other_feedback
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert sorted(r["student"] for r in results["results"]) == ["s001", "s002", "stranger"]


def _layout(canvas, roster_path, fmt: str) -> list[dict]:
    """The same graded results in another layout (no regrading: the tables are pure)."""
    from tools.grading import reports

    tests = grade.HiddenTests.load(HIDDEN)
    results = grade.load_previous(canvas, tests)
    table = reports.scores_table(results, tests, fmt, reports.read_roster(roster_path), "hw01")
    return list(csv.DictReader(table.splitlines()))


def test_plain_layout_keeps_the_maximum_out_of_the_rows(course, canvas):
    rows = _layout(canvas, course["roster"], "plain")
    assert [r["student"] for r in rows] == ["s001", "s002", "stranger"]
    assert rows[0]["id"] == "1001" and float(rows[0]["raw_total"]) == 11
    assert float(rows[0]["late_penalty"]) == pytest.approx(0.1)
    assert float(rows[0]["total"]) == pytest.approx(9.9)


def test_moodle_layout(course, canvas):
    rows = _layout(canvas, course["roster"], "moodle")
    ada = next(r for r in rows if r["ID number"] == "1001")
    assert ada["Email address"] == "ada@example.org" and float(ada["hw01"]) == pytest.approx(9.9)
    # per-question notes in the feedback column; unmatched rows are not in an import file
    assert ada["Feedback"].startswith("9.9/11; q1 2/2 ✓") and "late: 10% off" in ada["Feedback"]
    assert {r["ID number"] for r in rows} == {"1001", "1002"}


def test_dask_executor_gives_the_same_scores(course, canvas, tmp_path):
    pytest.importorskip("distributed")
    assert _grade(course, tmp_path, "--format", "canvas", "--executor", "dask") == 0
    assert (tmp_path / "scores.csv").read_text() == (canvas / "scores.csv").read_text()


def test_deadline_and_penalty_are_validated():
    from tools.grading import reports

    with pytest.raises(SystemExit, match="ISO 8601"):
        reports.parse_deadline("next friday")
    with pytest.raises(SystemExit, match="between 0% and 100%"):
        reports.parse_penalty("150%")
    late = reports.LatePolicy(reports.parse_deadline("2026-12-01T12:00+00:00"), 0.25)
    assert late.apply(datetime.fromisoformat("2026-12-01T12:00+00:00")) == (0, 0.0)
    assert late.apply(datetime.fromisoformat("2026-12-01T12:00:01+00:00")) == (1, 0.25)
    assert late.apply(datetime.fromisoformat("2026-12-06T12:00+00:00")) == (5, 1.0)


def test_summary_flags_a_question_whose_variants_differ_in_difficulty():
    """Issue 19: success rates per kind of variant; a wide spread is flagged."""
    from tools.grading import reports

    tests = grade.HiddenTests.load(HIDDEN)
    results, labels = [], {}
    for i in range(20):
        easy = i % 2 == 0  # q3's right option is (a) for half the class, (b) for the others
        fractions = dict.fromkeys(tests.points, 1.0)
        if not easy and i % 10 != 1:
            fractions["q3"] = 0.0  # 2 of 10 (s01, s11) get the hard kind right, all the easy kind
        if i % 3 == 0:
            fractions["q1"] = 0.0  # q1 equally hard for every kind
        points = {q: f * tests.points[q] for q, f in fractions.items()}
        student = f"s{i:02d}"
        results.append(
            grade.Result(student, points, dict.fromkeys(points, ""), variant="X", fractions=fractions)
        )
        labels[student] = {"q1": "t > 0" if i < 10 else "t < 0",
                           "q3": "right option (a)" if easy else "right option (b)"}
    text, data = reports.summary(results, tests, None, labels)
    assert data["variants"]["q3"]["flagged"] and not data["variants"]["q1"]["flagged"]
    assert data["variants"]["q3"]["rates"]["right option (b)"] == [0.2, 10]
    assert "| q3 | right option (a): 100% (10); right option (b): 20% (10) | ⚠ |" in text


def test_hw01_variant_kinds_name_the_right_option():
    """The q3 label of a variant is the letter the hidden test grades as right."""
    from course_lib.homework import variants

    hidden = grade.HiddenTests.load(HIDDEN)
    module = {}
    exec(compile(hidden.source, str(HIDDEN), "exec"), module)
    for n in range(200):
        code = variants.code_for(b"a course secret of 32 bytes......", "hw01", f"s{n}")
        label = variants.strata("hw01", code)["q3"]
        right = module["answers_for"](variants.data("hw01", code))["answer_q3"]
        assert label == f"right option ({right})", (code, label, right)
    variants.data("hw01", variants.DEFAULT)
