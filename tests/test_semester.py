"""A semester, end to end, as the course's pages tell its people to live it (issue 23).

The instructor downloads the Canvas gradebook as the roster, makes a course secret and the
students' codes with ``tools/variant.py`` (run as printed); the students each get the student
edition (``tools/release.py``), do hw01 in it with their own code (the answers are the solution's
code cells, typed into the edition's notebook), and hand in with ``submit()`` -- one of them from
a cell of the notebook itself.  The files arrive as Canvas's "Download Submissions" zip:

* Jane (1001) on time;  Rick (1002) late (Canvas's ``LATE`` mark);
* Ann (1003) twice: a blank attempt, then the answered one -- the blank file is touched last;
* Tom (1004) opened and saved his submission after ``submit()`` (a markdown cell changed);
* Sam (1005) used Jane's code;  a stranger not on the roster;  Mia (1006) handed in nothing.

``tools/grade.py`` grades them as ``site/semester.md`` prints it; the import file is read back as Canvas
reads it; Ann is regraded with ``--only``.  Every honest student has full marks; every flag is
in the summary's first section and in the status column.
"""

from __future__ import annotations

import csv
import json
import os
import subprocess
import sys
import zipfile
from datetime import datetime, timedelta, timezone
from pathlib import Path

import nbformat
import pytest

from course_lib.homework.submit import manifest_of, submit

ROOT = Path(__file__).resolve().parents[1]
HW, NAME, FULL = "hw01", "hw01_reparametrization.ipynb", 11

pytestmark = [pytest.mark.slow, pytest.mark.timeout(600)]

GRADEBOOK = (  # Canvas: Grades > Export, as downloaded (its "Points Possible" row, its Test Student)
    "Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (12345),Homework 2 (12346),"
    "Current Score,Final Score\n"
    "    Points Possible,,,,,100.00,100.00,(read only),(read only)\n"
    '"Doe, Jane",20001,1001,jdoe,Geometry A,,,,\n'
    '"Roe, Rick",20002,1002,rroe,Geometry A,,,,\n'
    '"Poe, Ann",20003,1003,apoe,Geometry A,,,,\n'
    '"Lee, Tom",20004,1004,tlee,Geometry B,,,,\n'
    '"Fox, Sam",20005,1005,sfox,Geometry B,,,,\n'
    '"Kim, Mia",20006,1006,mkim,Geometry B,,,,\n'
    '"Student, Test",20099,,,Geometry A,,,,\n'
)
CANVAS_MAX = 100  # the export's Points Possible for "Homework 1 (12345)"


def run(*cmd: str, cwd: Path = ROOT) -> str:
    """A command as a user types it: the venv's bin first on PATH (an activated venv)."""
    env = dict(os.environ, PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    env["PYTHONPATH"] = str(ROOT)
    done = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=500)
    assert done.returncode == 0, (cmd, done.stdout[-3000:], done.stderr[-3000:])
    return done.stdout


def do_homework(edition: Path, home: Path, code: str, *, answered: bool = True) -> Path:
    """A student's copy of the edition's hw01 with their code (and the solution's answers)."""
    (home / "exercises").mkdir(parents=True)
    nb = nbformat.read(edition / "exercises" / NAME, as_version=4)
    if answered:
        solution = nbformat.read(ROOT / "solutions" / NAME, as_version=4)
        mine = [c for c in nb.cells if c.cell_type == "code"]
        theirs = [c for c in solution.cells if c.cell_type == "code"]
        assert len(mine) == len(theirs)
        for cell, answer in zip(mine, theirs, strict=True):
            if "..." in cell.source or "NotImplementedError" in cell.source:  # an answer cell
                cell.source = answer.source  # (the check cells stay the edition's)
    (cell,) = [c for c in nb.cells if c.cell_type == "code" and 'VARIANT = ""' in c.source]
    cell.source = cell.source.replace('VARIANT = ""', f'VARIANT = "{code}"', 1)
    nbformat.write(nb, home / "exercises" / NAME)
    return home / "exercises" / NAME


def hand_in_from_the_notebook(path: Path, student: str) -> Path:
    """As the homework says: submit(...) "in a new cell here", the notebook run top to bottom."""
    from nbclient import NotebookClient

    nb = nbformat.read(path, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(
        f'from course_lib.homework.submit import submit\nsubmit("{NAME}", student="{student}")'))  # fmt: skip
    nbformat.write(nb, path)
    NotebookClient(nb, timeout=120, kernel_name="python3",
                   resources={"metadata": {"path": str(path.parent)}}).execute()  # fmt: skip
    outputs = nb.cells[-1].outputs
    shown = "".join(str(o.get("text", "")) for o in outputs if o.get("name") == "stdout")
    shown += "".join(str(o.get("data", {}).get("text/markdown", "")) for o in outputs)
    assert "Submission written" in shown and "7 of 7 checks pass" in shown, shown
    assert shown.count("Submission written") == 1, shown  # printed once, not shown again
    everything = json.dumps(outputs)
    assert "Submission(" not in everything and "without encryption" not in everything, everything
    return path.parent.parent / "submissions" / f"{HW}-{student}.ipynb"


@pytest.fixture(scope="module")
def semester(tmp_path_factory):
    base = tmp_path_factory.mktemp("semester")
    course = base / "instructor"
    course.mkdir()
    (course / "gradebook.csv").write_text(GRADEBOOK, encoding="utf-8")
    # the instructor: a secret, the codes (site/semester.md: tools/variant.py ...)
    run("tools/variant.py", "secret", "--out", str(course / "course_secret.txt"))
    run("tools/variant.py", "codes", HW, "--secret-file", str(course / "course_secret.txt"),
        "--roster", str(course / "gradebook.csv"), "--out", str(course / "codes.csv"))  # fmt: skip
    with open(course / "codes.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    codes = {row["id"]: row["code"] for row in rows}
    assert sorted(codes) == ["1001", "1002", "1003", "1004", "1005", "1006"]  # no Test Student
    # what the instructor tells each student: the code and the id to hand in with
    assert rows[0]["tell_the_student"].startswith(f"{HW}: your variant code is {codes['1001']}")
    assert "STUDENT=1001" in rows[0]["tell_the_student"]
    # the student edition, as make release SECRET=... ROSTER=... builds it (site/semester.md)
    run(sys.executable, "tools/release.py", "--out", str(base / "dist" / "student-edition"),
        "--secret-file", str(course / "course_secret.txt"), "--roster", str(course / "gradebook.csv"))  # fmt: skip
    edition = base / "dist" / "student-edition"
    told = "the id your instructor gave you with your variant code"
    assert told in " ".join((edition / "README.md").read_text(encoding="utf-8").split())
    hand_in = nbformat.read(edition / "exercises" / NAME, as_version=4).cells[-1].source
    assert told.replace("the id your", "id your") in " ".join(hand_in.split())

    students = base / "students"
    handed = {}
    # the students' kernels import the edition's course_lib (its answer keys), as its own
    # editable install would give them
    old_path = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = str(edition)
    try:
        handed["1001"] = hand_in_from_the_notebook(do_homework(edition, students / "jane", codes["1001"]), "1001")
        handed["1004"] = submit(do_homework(edition, students / "tom", codes["1004"]), student="1004").path
        blank = submit(do_homework(edition, students / "ann-1", codes["1003"], answered=False), student="1003")
        handed["1003"] = submit(do_homework(edition, students / "ann-2", codes["1003"]), student="1003").path
        handed["1005"] = submit(do_homework(edition, students / "sam", codes["1001"]), student="1005").path
        handed["7777"] = submit(do_homework(edition, students / "x", codes["1001"]), student="7777").path
        # the deadline passes; Rick hands in after it (Canvas marks his upload LATE)
        deadline = datetime.now(timezone.utc).replace(microsecond=0) + timedelta(seconds=1)
        handed["1002"] = submit(do_homework(edition, students / "rick", codes["1002"]), student="1002").path
    finally:
        if old_path is None:
            os.environ.pop("PYTHONPATH", None)
        else:
            os.environ["PYTHONPATH"] = old_path
    # Tom opens his submission and saves it again with a changed cell
    tom = nbformat.read(handed["1004"], as_version=4)
    tom.cells[0].source += "\n\n(opened again after submit)"
    nbformat.write(tom, handed["1004"])

    # Canvas's "Download Submissions" zip: <name>_[LATE_]<user id>_<submission id>_<file>
    now = datetime.now(timezone.utc)
    zipped = course / "submissions.zip"
    with zipfile.ZipFile(zipped, "w") as zf:
        zf.write(handed["1001"], "doejane_20001_70001_hw01-1001.ipynb")
        zf.write(handed["1002"], "roerick_LATE_20002_70002_hw01-1002.ipynb")
        zf.write(blank.path, "poeann_20003_70003_hw01-1003.ipynb")
        zf.write(handed["1003"], "poeann_20003_70013_hw01-1003-1.ipynb")
        zf.write(handed["1004"], "leetom_20004_70004_hw01-1004.ipynb")
        zf.write(handed["1005"], "foxsam_20005_70005_hw01-1005.ipynb")
        zf.write(handed["7777"], "strangerx_29999_70006_hw01-7777.ipynb")
    subs = course / "hw01-submissions"
    with zipfile.ZipFile(zipped) as zf:
        zf.extractall(subs)
    later = (now + timedelta(minutes=5)).timestamp()
    os.utime(subs / "poeann_20003_70003_hw01-1003.ipynb", (later, later))  # the blank is newest by file time
    # Tom's file is dated after the deadline, but Canvas did not mark it LATE: Canvas decides
    os.utime(subs / "leetom_20004_70004_hw01-1004.ipynb", (later, later))

    deadline = deadline.isoformat(timespec="seconds")
    out = course / "grades" / HW
    grade = ("tools/grade.py", "--tests", f"solutions/hidden_tests/{HW}.py", "--submissions", str(subs),
             "--out", str(out), "--jobs", "2", "--roster", str(course / "gradebook.csv"),
             "--secret-file", str(course / "course_secret.txt"), "--format", "canvas",
             "--deadline", deadline, "--late-penalty", "10%", "--assignment", "Homework 1")  # fmt: skip
    console = run(*grade)
    tom_file_time = datetime.fromtimestamp(later, timezone.utc).isoformat(timespec="seconds")
    return {"out": out, "subs": subs, "codes": codes, "grade": grade, "console": console,
            "handed": handed, "blank": blank.path, "course": course, "deadline": deadline,
            "tom_file_time": tom_file_time}  # fmt: skip


def _canvas_rows(out: Path) -> tuple[list[str], list[list[str]]]:
    """scores.csv as Canvas's gradebook import reads it: a header, "Points Possible", students."""
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    assert rows[1][0].strip() == "Points Possible" and rows[1][5] == f"{CANVAS_MAX}"
    return rows[0], rows[2:]


def _results(out: Path) -> dict[str, dict]:
    data = json.loads((out / "results.json").read_text(encoding="utf-8"))
    return {r["student"]: r for r in data["results"]}


def test_the_import_file_reimports_into_canvas(semester):
    header, rows = _canvas_rows(semester["out"])
    # the export's own column, "(id)" and all: Canvas's import matches on the header
    assert header == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Homework 1 (12345)"]
    by_canvas_id = {r[1]: r for r in rows}
    # only roster students, with Canvas's own ids and the export's SIS columns
    assert sorted(by_canvas_id) == ["20001", "20002", "20003", "20004", "20005"]
    assert by_canvas_id["20001"][:5] == ["Doe, Jane", "20001", "1001", "jdoe", "Geometry A"]
    scores = {r[2]: float(r[5]) for r in rows}
    # 11/11 in the homework is 100/100 in Canvas (the export's Points Possible)
    assert scores["1001"] == CANVAS_MAX and scores["1003"] == CANVAS_MAX and scores["1004"] == CANVAS_MAX
    assert scores["1002"] == pytest.approx(CANVAS_MAX * 0.9)  # Canvas said LATE: one started day
    # Sam handed in Jane's notebook: her data are not his (the secret is new each run, so a
    # data question may agree by chance; the copy limit itself is proved with a fixed secret
    # in test_grading_variants)
    assert scores["1005"] < CANVAS_MAX / 2


def test_every_honest_student_has_full_marks_on_their_own_data(semester):
    results = _results(semester["out"])
    for sid in ("1001", "1002", "1003", "1004"):
        r = results[sid]
        assert sum(r["points"].values()) == FULL, (sid, r["notes"], r["run_notes"])
        assert r["variant"] == semester["codes"][sid]
    assert results["1003"]["file"] == "poeann_20003_70013_hw01-1003-1.ipynb"  # the newest manifest
    assert results["1005"]["variant"] == semester["codes"]["1005"]  # his own data, not Jane's


def test_every_flag_is_where_the_instructor_looks_first(semester):
    out = semester["out"]
    summary = (out / "summary.md").read_text(encoding="utf-8")
    first = summary[: summary.index("## Statistics")]
    flags = {line.split("**")[1]: line for line in first.splitlines() if line.startswith("- **")}
    assert "strangerx_29999" in flags["Not in the roster (not in the import file; resolve by hand, then `--only`)"]
    assert "1004 (Lee, Tom)" in flags["Edited after submit() (checksum mismatch)"]
    assert "1002 (Roe, Rick)" in flags["Late"]
    assert "1003 (Poe, Ann)" in flags["Several notebooks (the newest graded)"]
    wrong = flags["Wrong variant code (whose code follows each name)"]
    assert "1005 (Fox, Sam) (its VARIANT is the code of roster student 1001)" in wrong
    assert "Roster students without a submission (1): 1006 (Kim, Mia)" in first  # not the Test Student
    assert "Test" not in first
    assert f"{FULL}/{FULL} → {CANVAS_MAX}/{CANVAS_MAX} in Canvas" in summary
    honest = [line for line in flags.values() if "1001 (Doe, Jane)" in line]
    assert all("same variant code" in line for line in honest)  # Jane: only as the code's owner
    assert not [line for line in flags.values() if "1002" in line and "Late" not in line]
    results = _results(out)
    assert results["1004"]["status"] == "ok; edited after submit"  # his submit() time agrees
    assert results["1004"]["penalty"] == 0  # Canvas said on time: no penalty
    assert results["1002"]["status"] == "ok; late"
    assert "wrong variant code" in results["1005"]["status"]
    assert results["strangerx_29999"]["status"].startswith("not graded")
    sam = next(p for p in (out / "feedback").iterdir() if p.name.startswith("1005"))
    sam_text = sam.read_text(encoding="utf-8")
    assert "not the code you were given" in sam_text
    # privacy: a student's feedback never names another student (whose code, whose manifest)
    for path in (out / "feedback").iterdir():
        text = path.read_text(encoding="utf-8")
        own = path.name.split(".")[0].split("_")[0]
        others = {"1001", "1002", "1003", "1004", "1005", "1006"} - {own}
        assert not [o for o in others if f"student {o}" in text or f"of {o}" in text], path.name
    jane = (out / "feedback" / "1001.md").read_text(encoding="utf-8")
    assert "raised" not in jane  # her hand-in cell is not run by the grader
    assert f"{FULL}/{FULL} → {CANVAS_MAX}/{CANVAS_MAX} in Canvas" in jane
    # Tom: the file's real time and Canvas's verdict, apart; never the deadline as his time
    tom = (out / "feedback" / "1004.md").read_text(encoding="utf-8")
    assert f"Canvas says on time; the file's time is {semester['tom_file_time']}" in tom
    assert f"Submitted: {semester['deadline']}" not in tom
    assert "Canvas's verdict is used" in tom and "On time." in tom
    assert "strangerx_29999: listed, not graded" in semester["console"]
    assert "Per-student variants" not in summary or "| q" in summary.split("Per-student variants")[1]


def test_a_regrade_with_only_touches_one_student(semester, tmp_path):
    out = semester["out"]
    before_rows = _canvas_rows(out)
    jane = (out / "feedback" / "1001.md").read_bytes()
    (semester["subs"] / "poeann_20003_70003_hw01-1003.ipynb").unlink()  # the blank attempt withdrawn
    run(*semester["grade"], "--only", "1003")
    assert _canvas_rows(out) == before_rows
    assert (out / "feedback" / "1001.md").read_bytes() == jane
    ann = _results(out)["1003"]
    assert ann["status"] == "ok" and sum(ann["points"].values()) == FULL
    assert sorted(_results(out)) == ["1001", "1002", "1003", "1004", "1005", "strangerx_29999"]


# ---------------------------------------------------------------------------------- Moodle
WORKSHEET = (  # Moodle: Assignment > "Download grading worksheet" (ID number shown as identity)
    "Identifier,Full name,ID number,Email address,Status,Grade,Maximum Grade,Grade can be changed,"
    "Last modified (submission),Last modified (grade),Feedback comments\n"
    "Participant 801,Jane Doe,1001,jane@uni.example,Submitted for grading,,100.00,Yes,,-,\n"
    "Participant 802,Rick Roe,1002,rick@uni.example,Submitted for grading,,100.00,Yes,,-,\n"
    "Participant 803,Ann Poe,1003,ann@uni.example,Submitted for grading,,100.00,Yes,,-,\n"
    "Participant 804,Tom Lee,1004,tom@uni.example,Submitted for grading,,100.00,Yes,,-,\n"
    "Participant 805,Sam Fox,1005,sam@uni.example,Submitted for grading,,100.00,Yes,,-,\n"
    "Participant 806,Mia Kim,1006,mia@uni.example,No submission,,100.00,Yes,,-,\n"
)


@pytest.fixture(scope="module")
def moodle(semester):
    """The same semester in Moodle: "Download all submissions" (in folders), the worksheet."""
    course = semester["course"]
    (course / "worksheet.csv").write_text(WORKSHEET, encoding="utf-8")
    h = semester["handed"]
    files = {  # <Full Name>_<participant id>_assignsubmission_file_/<file>, and one flattened
        "Jane Doe_801_assignsubmission_file_/hw01-1001.ipynb": h["1001"],
        "Rick Roe_802_assignsubmission_file_/hw01-1002.ipynb": h["1002"],
        "Ann Poe_803_assignsubmission_file_/first/hw01-1003.ipynb": semester["blank"],
        "Ann Poe_803_assignsubmission_file_/hw01-1003.ipynb": h["1003"],
        "Tom Lee_804_assignsubmission_file_hw01-1004.ipynb": h["1004"],
        "Sam Fox_805_assignsubmission_file_/hw01-1005.ipynb": h["1005"],
        "Max Mustermann_899_assignsubmission_file_/hw01-7777.ipynb": h["7777"],
    }
    subs = course / "moodle-submissions"
    for name, src in files.items():
        dst = subs / name
        dst.parent.mkdir(parents=True, exist_ok=True)
        dst.write_bytes(src.read_bytes())
        # Moodle has no late mark in its names: the upload time is the file's time
        when = manifest_of(nbformat.read(src, as_version=4))["time"].timestamp()
        os.utime(dst, (when, when))
    out = course / "grades" / "hw01-moodle"
    run("tools/grade.py", "--tests", f"solutions/hidden_tests/{HW}.py", "--submissions", str(subs),
        "--out", str(out), "--jobs", "2", "--roster", str(course / "worksheet.csv"),
        "--secret-file", str(course / "course_secret.txt"), "--format", "moodle",
        "--deadline", semester["deadline"], "--late-penalty", "10%")  # fmt: skip
    return out


def test_the_moodle_worksheet_comes_back_filled_in(moodle):
    with open(moodle / "scores.csv", newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        assert reader.fieldnames == WORKSHEET.splitlines()[0].split(",")
        rows = {r["Identifier"]: r for r in reader}
    # matched to Moodle's own identifiers; the stranger and Mia (no submission) are not in it
    assert sorted(rows) == [f"Participant {n}" for n in (801, 802, 803, 804, 805)]
    grades = {k: float(r["Grade"]) for k, r in rows.items()}  # scaled to the Maximum Grade
    assert grades["Participant 801"] == 100 and grades["Participant 803"] == 100
    assert grades["Participant 804"] == 100 and grades["Participant 805"] < 100
    assert grades["Participant 802"] == pytest.approx(100 * 0.9)
    assert rows["Participant 801"]["Feedback comments"].startswith("11/11; q1 2/2 ✓; q2 3/3 ✓")
    sam = rows["Participant 805"]["Feedback comments"]
    assert "q1 0/2" in sam and "not done on your own data" in sam  # per question, with the reason
    assert rows["Participant 802"]["Email address"] == "rick@uni.example"


def test_moodle_flags_are_in_the_summary(moodle):
    summary = (moodle / "summary.md").read_text(encoding="utf-8")
    first = summary[: summary.index("## Statistics")]
    assert "Max Mustermann_899" in first and "1004 (Tom Lee)" in first
    late = next(x for x in first.splitlines() if x.startswith("- **Late**"))
    assert late.endswith("1002 (Rick Roe)")
    several = next(x for x in first.splitlines() if x.startswith("- **Several notebooks"))
    assert several.endswith("1003 (Ann Poe)")
    assert "Roster students without a submission (1): 1006 (Mia Kim)" in first
    assert f"{FULL}/{FULL} → 100/100 in Moodle" in summary
    assert "manifest" not in first  # no honest student's manifest disagrees with Moodle


def test_an_assignment_the_canvas_export_lacks_stops_before_grading(tmp_path):
    """site/semester.md: ASSIGNMENT= names the export's column; a wrong name stops with the columns."""
    (tmp_path / "gradebook.csv").write_text(GRADEBOOK, encoding="utf-8")
    (tmp_path / "subs").mkdir()
    (tmp_path / "subs" / "doejane_20001_70001_hw01-1001.ipynb").write_text("{}", encoding="utf-8")
    for extra in ([], ["--assignment", "Homework 9"]):  # hw01 is no column of this export either
        done = subprocess.run(
            [sys.executable, "tools/grade.py", "--tests", f"solutions/hidden_tests/{HW}.py",
             "--submissions", str(tmp_path / "subs"), "--out", str(tmp_path / "out"),
             "--roster", str(tmp_path / "gradebook.csv"), "--format", "canvas", *extra],
            cwd=ROOT, capture_output=True, text=True, timeout=120,
            env=dict(os.environ, PYTHONPATH=str(ROOT)),
        )  # fmt: skip
        assert done.returncode != 0
        message = done.stderr.strip()
        assert len(message.splitlines()) == 1, message
        assert '"Homework 1 (12345)"; "Homework 2 (12346)"' in message, message
        assert "Current Score" not in message and "nothing was graded" in message
        assert not (tmp_path / "out").exists()


def test_the_student_data_the_readme_names_is_git_ignored():
    """site/semester.md, "Where student data lives": rosters, codes and grades are never committed."""
    paths = ["codes.csv", "codes-hw01.csv", "roster.csv", "gradebook.csv", "worksheet.csv",
             "course_secret.txt", "grades/hw01/scores.csv", "grading-output/hw01/scores.csv",
             "submissions/hw01-1001.ipynb"]  # fmt: skip
    done = subprocess.run(["git", "check-ignore", "--no-index", *paths], cwd=ROOT,
                          capture_output=True, text=True)  # fmt: skip
    assert sorted(done.stdout.split()) == sorted(paths), done.stdout
    page = (ROOT / "site" / "semester.md").read_text(encoding="utf-8")
    assert all(f"`{p}`" in page for p in ("codes*.csv", "roster*.csv", "grades/"))
