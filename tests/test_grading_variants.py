"""Per-student variants through the real sandboxed grader (issue 19), end to end.

Three students hand in the hw01 (hw02, hw03, hw04, hw05) solution notebook: two with their own variant
code in ``VARIANT``, one with a friend's code.  ``tools/grade.py --secret-file --roster`` recomputes each
code from the roster's id and grades on that student's own data: the two honest submissions get
full marks, the borrowed code does not.
"""

from __future__ import annotations

import csv
from pathlib import Path

import nbformat
import pytest
from _homework_support import differ, load

from course_lib.homework import variants
from tools import grade

ROOT = Path(__file__).resolve().parents[1]
HOMEWORKS = ("hw01", "hw02", "hw03", "hw04", "hw05")
HIDDEN = {hw: ROOT / "solutions" / "hidden_tests" / f"{hw}.py" for hw in HOMEWORKS}
SOLUTION = {
    "hw01": ROOT / "solutions" / "hw01_reparametrization.ipynb",
    "hw02": ROOT / "solutions" / "hw02_beta_constraints.ipynb",
    "hw03": ROOT / "solutions" / "hw03_g1_knot_bezier_splines.ipynb",
    "hw04": ROOT / "solutions" / "hw04_beta_splines.ipynb",
    "hw05": ROOT / "solutions" / "hw05_are_letters_smooth.ipynb",
}
#: the questions that are the same for everyone (functions; symbolic answers without data)
SAME_FOR_ALL = {
    "hw01": {"q2": 3},
    "hw02": {"q3": 3, "q4": 2},
    "hw03": {"q2": 4, "q6": 2, "q7": 2},
    "hw04": {"q2": 4, "q4": 3},
    "hw05": {"q2": 3, "q5": 4},
}
#: full marks (multiple choice is feedback only: 0 points)
FULL = {"hw01": 11, "hw02": 10, "hw03": 15, "hw04": 11, "hw05": 7}
#: how many questions worth points at least differ between Ada's and Sophie's data (3 unless
#: named here; hw05's data questions are practice, worth 0 points; hw02 has three data questions
#: worth points and q1's answer comes from a small set: with the check-character codes of
#: issue 23 Ada and Sophie share it by chance)
DIFFER = {"hw05": 0, "hw02": 2}



pytestmark = [pytest.mark.slow, pytest.mark.timeout(300)]

SECRET = "a course secret for the variant test"


def _with_variant(hw: str, code: str, path: Path) -> None:
    nb = nbformat.read(SOLUTION[hw], as_version=4)
    (cell,) = [c for c in nb.cells if c.cell_type == "code" and 'VARIANT = ""' in c.source]
    cell.source = cell.source.replace('VARIANT = ""', f'VARIANT = "{code}"', 1)
    nbformat.write(nb, path)


@pytest.fixture(scope="module", params=HOMEWORKS)
def graded(request, tmp_path_factory):
    hw = request.param
    root = tmp_path_factory.mktemp(f"course-{hw}")
    secret = root / "course_secret.txt"
    secret.write_text(SECRET + "\n", encoding="utf-8")
    roster = root / "roster.csv"
    roster.write_text(
        "id,submission,name,email\n"
        "1001,s001,Ada,ada@example.org\n1002,s002,Emmy,emmy@example.org\n1003,s003,Sophie,s@example.org\n",
        encoding="utf-8",
    )
    codes = {i: variants.code_for(SECRET, hw, i) for i in ("1001", "1002", "1003")}
    subs = root / "submissions"
    subs.mkdir()
    _with_variant(hw, codes["1001"], subs / "s001.ipynb")
    _with_variant(hw, codes["1002"], subs / "s002.ipynb")
    _with_variant(hw, codes["1001"], subs / "s003.ipynb")  # Sophie used Ada's code
    out = root / "grades"
    code = grade.main(
        ["--tests", str(HIDDEN[hw]), "--submissions", str(subs), "--out", str(out), "--roster", str(roster),
         "--secret-file", str(secret), "--jobs", "2", "--sandbox", "auto"]
    )  # fmt: skip
    variants.data(hw, variants.DEFAULT)
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return {"hw": hw, "code": code, "rows": rows, "out": out, "codes": codes}


def test_each_student_is_graded_on_their_own_variant(graded):
    assert graded["code"] == 0
    rows = graded["rows"]
    full = FULL[graded["hw"]]
    assert float(rows["s001"]["total"]) == full and float(rows["s002"]["total"]) == full
    feedback = (graded["out"] / "feedback" / "s001.md").read_text(encoding="utf-8")
    assert f"variant {graded['codes']['1001']}" in feedback


def test_a_friends_code_does_not_earn_full_marks(graded):
    hw, row = graded["hw"], graded["rows"]["s003"]
    # issue 24: a copied notebook is worth at most a quarter of the points
    assert float(row["total"]) <= 0.25 * FULL[hw]
    # the data questions are answered for Ada's data, not Sophie's; the functions (and the
    # symbolic answers), the same for everyone, earn points only in a notebook on one's own data
    assert all(float(row[q]) == 0 for q in SAME_FOR_ALL[hw])
    hidden = load(f"hidden_{hw}_grading_variants", HIDDEN[hw])
    ada, sophie = (hidden.answers_for(variants.data(hw, graded["codes"][i])) for i in ("1001", "1003"))
    variants.data(hw, variants.DEFAULT)
    # (a question worth 0 points, multiple choice that is feedback only, has nothing to lose)
    differing = [
        q for q, points in hidden.POINTS.items()
        if points > 0 and q not in SAME_FOR_ALL[hw] and differ(ada[f"answer_{q}"], sophie[f"answer_{q}"])
    ]
    assert len(differing) >= DIFFER.get(hw, 3), differing
    assert all(float(row[q]) < hidden.POINTS[q] for q in differing), differing
    if hw == "hw01":
        assert all(float(row[q]) == 0 for q in ("q1", "q4", "q5", "q7"))
    # and the feedback says why
    text = (graded["out"] / "feedback" / "s003.md").read_text(encoding="utf-8")
    assert f"but your variant code is {graded['codes']['1003']}" in text
    ada = (graded["out"] / "feedback" / "s001.md").read_text(encoding="utf-8")
    assert "but your variant code is" not in ada


def test_the_batch_ran_in_the_sandbox_where_it_works(graded):
    mode, _ = grade.resolve_sandbox("auto")
    assert {r["sandbox"] for r in graded["rows"].values()} == {mode}
