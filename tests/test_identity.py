"""One identity per submission (issue 23): LMS naming, rosters from LMS exports, flags.

Fast: no notebook is run.  The notebooks are two-cell stand-ins with a ``VARIANT`` and, where it
matters, a real ``submit()``-style manifest (digest made by ``course_lib.homework.submit``).
"""

from __future__ import annotations

import csv
import os
from dataclasses import asdict
from datetime import datetime, timedelta, timezone
from pathlib import Path

import nbformat
import pytest

from course_lib.homework import variants
from course_lib.homework.submit import MANIFEST_KEY, notebook_digest
from tools import grade
from tools.grading import identity, intake, reports

ROOT = Path(__file__).resolve().parents[1]

SECRET = b"a course secret for identity tests"
DEADLINE = datetime(2026, 12, 8, 22, 59, tzinfo=timezone.utc)

CANVAS_EXPORT = (
    "Student,ID,SIS User ID,SIS Login ID,Section,hw01 (4711),Final Score\n"
    "    Points Possible,,,,,11.00,(read only)\n"
    '"Doe, Jane",12345,1001,jdoe,Section A,,\n'
    '"Roe, Rick",12346,1002,rroe,Section A,,\n'
    '"Poe, Ann",12347,1003,apoe,Section B,,\n'
)
MOODLE_WORKSHEET = (
    "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Grade can be changed,"
    "Last modified (submission),Last modified (grade),Feedback comments\n"
    "Participant 4711,Jane Doe,jane@example.org,Submitted for grading,,11.00,Yes,,-,\n"
    "Participant 4712,Rick Roe,rick@example.org,Submitted for grading,,11.00,Yes,,-,\n"
)


def notebook(path: Path, code: str = "", student: str | None = None, when=None, edit=False):
    nb = nbformat.v4.new_notebook(cells=[
        nbformat.v4.new_code_cell(f'HOMEWORK = "hw01"\nVARIANT = "{code}"'),
        nbformat.v4.new_code_cell("answer_q1 = 1.0"),
    ])  # fmt: skip
    if student is not None:
        nb.metadata[MANIFEST_KEY] = {"student": student, "homework": "hw01",
                                     "time": (when or DEADLINE).isoformat(), "sha256": ""}  # fmt: skip
        nb.metadata[MANIFEST_KEY]["sha256"] = notebook_digest(nb)
    if edit:
        nb.cells[1].source = "answer_q1 = 2.0"
    path.parent.mkdir(parents=True, exist_ok=True)
    nbformat.write(nb, path)
    return path


def touch(path: Path, when: datetime) -> None:
    os.utime(path, (when.timestamp(), when.timestamp()))


def test_canvas_and_moodle_download_names_are_parsed():
    f = identity.parse_name(Path("doejane_LATE_12345_67890_hw01-1001.ipynb"))
    assert (f.lms, f.lms_id, f.lms_name, f.lms_late, f.names) == ("canvas", "12345", "doejane", True, ["1001"])
    f = identity.parse_name(Path("doejane_12345_67890_hw01-1001-1.ipynb"))  # a resubmission
    assert (f.lms, f.lms_late, f.names) == ("canvas", False, ["1001"])
    f = identity.parse_name(Path("Jane Doe_4711_assignsubmission_file_/hw01-1001.ipynb"))
    assert (f.lms, f.lms_id, f.lms_name) == ("moodle", "4711", "Jane Doe")
    f = identity.parse_name(Path("Jane Doe_4711_assignsubmission_file_hw01.ipynb"))  # flattened
    assert (f.lms, f.lms_id) == ("moodle", "4711")
    assert identity.parse_name(Path("hw03-1001.ipynb")).names == ["hw03-1001", "1001"]
    assert identity.parse_name(Path("alice/hw01.ipynb")).names == ["alice"]


def test_a_canvas_export_is_a_roster_and_its_points_possible_row_is_skipped(tmp_path):
    (tmp_path / "g.csv").write_text(CANVAS_EXPORT, encoding="utf-8")
    roster = reports.read_roster(tmp_path / "g.csv")
    assert roster.kind == "canvas" and list(roster) == ["1001", "1002", "1003"]
    jane = roster["1001"]
    assert jane.id == "1001" and "12345" in jane.aliases and "jdoe" in jane.aliases
    (tmp_path / "m.csv").write_text(MOODLE_WORKSHEET, encoding="utf-8")
    moodle = reports.read_roster(tmp_path / "m.csv")
    assert moodle.kind == "moodle-worksheet" and moodle["jane@example.org"].aliases[0] == "4711"


def test_the_variant_comes_from_the_roster_id_never_from_the_file_name(tmp_path):
    (tmp_path / "roster.csv").write_text("id,name\n1001,Jane\n", encoding="utf-8")
    roster = reports.read_roster(tmp_path / "roster.csv")
    code = variants.code_for(SECRET, "hw01", "1001")
    notebook(tmp_path / "subs" / "hw01-1001.ipynb", code, student="1001")
    (item,) = grade.plan(tmp_path / "subs", roster, homework="hw01", secret=SECRET, variants_on=True)
    assert item.student == "1001" and item.who.entry.id == "1001"
    assert item.variant == code and item.who.flags == []
    # and without a roster: the id submit() put in the name, not "hw01-1001"
    (item,) = grade.plan(tmp_path / "subs", None, homework="hw01", secret=SECRET, variants_on=True)
    assert item.student == "1001" and item.variant == code


def test_a_canvas_semester_is_identified_and_flagged(tmp_path):
    (tmp_path / "g.csv").write_text(CANVAS_EXPORT, encoding="utf-8")
    roster = reports.read_roster(tmp_path / "g.csv")
    code = {i: variants.code_for(SECRET, "hw01", i) for i in ("1001", "1002", "1003")}
    subs = tmp_path / "subs"
    notebook(subs / "doejane_12345_1_hw01-1001.ipynb", code["1001"], "1001")
    # Rick: two attempts; the older file is touched later, the newer manifest wins
    old = notebook(subs / "roerick_12346_2_hw01-1002.ipynb", "", "1002", DEADLINE - timedelta(days=2))
    notebook(subs / "roerick_12346_3_hw01-1002-1.ipynb", code["1002"], "1002", DEADLINE - timedelta(days=1))
    touch(old, DEADLINE - timedelta(hours=1))
    # Ann: Jane's code, a manifest naming Jane, edited after submit
    notebook(subs / "poeann_LATE_12347_4_hw01-1003.ipynb", code["1001"], "1001", edit=True)
    notebook(subs / "strangerx_99999_5_hw01-7777.ipynb", code["1001"], "7777")
    items = {i.student: i for i in grade.plan(subs, roster, homework="hw01", secret=SECRET, variants_on=True)}
    assert set(items) == {"1001", "1002", "1003", "strangerx_99999"}
    assert not items["strangerx_99999"].graded and items["strangerx_99999"].who.flags == [identity.NOT_IN_ROSTER]
    rick = items["1002"]
    assert rick.found.rel == "roerick_12346_3_hw01-1002-1.ipynb" and identity.SEVERAL in rick.who.flags
    assert rick.variant == code["1002"] and identity.WRONG_CODE not in rick.who.flags
    ann = items["1003"]
    assert ann.variant == code["1003"]  # her own data, whatever her notebook says
    assert {identity.WRONG_CODE, identity.SHARED_CODE, identity.ID_DIFFERS} <= set(ann.who.flags)
    assert "code of roster student 1001" in ann.who.private[identity.WRONG_CODE]  # the instructor's
    assert not any("1001" in n for n in ann.who.notes)  # her feedback names no other student
    assert ann.found.manifest["tampered"] and ann.found.lms_late


def facts(found: identity.Found, path: Path) -> identity.Found:
    """What the grader knows of ``path``: read as intake reads it (no link followed)."""
    found.path = path
    data = intake.read_regular(path.parent, path)
    return identity.read_notebook_facts(found, data, os.lstat(path).st_mtime)


def test_reading_facts_takes_intakes_bytes_never_the_path(tmp_path):
    target = notebook(tmp_path / "friend.ipynb", "", "1002")
    (tmp_path / "mine.ipynb").symlink_to(target)
    with pytest.raises(intake.Refused):
        intake.read_regular(tmp_path, tmp_path / "mine.ipynb")
    found = identity.Found(tmp_path / "mine.ipynb", "mine.ipynb")
    with pytest.raises(TypeError, match="data must be the notebook's bytes"):
        identity.read_notebook_facts(found, None)
    assert found.manifest is None and found.data is None


def test_lateness_comes_from_the_lms_and_a_manifest_time_is_only_compared(tmp_path):
    on_time = DEADLINE - timedelta(hours=3)
    # Canvas said LATE; the student edited the manifest time to before the deadline
    f = identity.parse_name(Path("poeann_LATE_12347_4_hw01-1003.ipynb"))
    f = facts(f, notebook(tmp_path / "a.ipynb", "", "1003", on_time))
    when, source, flags, _ = identity.time_flags(f, DEADLINE)
    assert when > DEADLINE and source == "Canvas: late" and flags == [identity.TIMES_DISAGREE]
    # no LMS record: the file's time, and a manifest claiming another side of the deadline is flagged
    path = notebook(tmp_path / "b.ipynb", "", "1003", on_time)
    touch(path, DEADLINE + timedelta(hours=5))
    g = facts(identity.Found(Path(), "b.ipynb"), path)
    when, source, flags, notes = identity.time_flags(g, DEADLINE)
    assert when > DEADLINE and source == "file time" and flags == [identity.TIMES_DISAGREE]
    assert "the file's time is used" in notes[0]


def test_import_files_hold_only_matched_students_with_the_lms_ids(tmp_path):
    (tmp_path / "g.csv").write_text(CANVAS_EXPORT, encoding="utf-8")
    roster = reports.read_roster(tmp_path / "g.csv")
    tests = grade.HiddenTests.load(ROOT / "solutions" / "hidden_tests" / "hw01.py")
    full = grade.Result("1001", dict(tests.points), dict.fromkeys(tests.points, ""),
                        fractions=dict.fromkeys(tests.points, 1.0))  # fmt: skip
    full.lms = asdict(roster["1001"])
    stray = grade.Result("x_1", dict.fromkeys(tests.points, 0.0), dict.fromkeys(tests.points, ""))
    column = reports.canvas_column(roster, "hw01")  # the export's header, "(id)" and all
    top = reports.lms_maximum(roster, "canvas", column)
    rows = list(csv.reader(reports.scores_table([full, stray], tests, "canvas", roster, column, top).splitlines()))
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "hw01 (4711)"]
    assert rows[2] == ["Doe, Jane", "12345", "1001", "jdoe", "Section A", "11"] and len(rows) == 3
    # out of 100 in Canvas: the homework's 11 points are scaled to it
    scaled = list(csv.reader(reports.scores_table([full], tests, "canvas", roster, column, 100.0).splitlines()))
    assert scaled[1][5] == "100" and scaled[2][5] == "100"
    assert "11/11 → 100/100 in Canvas" in reports.feedback_markdown(full, tests, None, ("Canvas", 100.0))


def test_the_canvas_column_is_found_by_name_with_or_without_its_id_and_the_test_student_skipped(tmp_path):
    (tmp_path / "g.csv").write_text(
        "Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (12345),Homework 2 (12346),"
        "Current Score,Final Score\n"
        "    Points Possible,,,,,100.00,50.00,(read only),(read only)\n"
        '"Doe, Jane",20001,1001,jdoe,A,,,,\n'
        '"Student, Test",20099,,,A,,,,\n',
        encoding="utf-8",
    )
    roster = reports.read_roster(tmp_path / "g.csv")
    assert list(roster) == ["1001"]  # Canvas's Test Student is no student
    assert reports.canvas_assignments(roster) == ["Homework 1 (12345)", "Homework 2 (12346)"]
    for name in ("Homework 1", "homework 1", "Homework 1 (12345)"):
        assert reports.canvas_column(roster, name) == "Homework 1 (12345)"
    assert reports.canvas_column(roster, "hw01") is None
    assert reports.canvas_column(roster, "Current Score") is None
    assert reports.lms_maximum(roster, "canvas", "Homework 2 (12346)") == 50


@pytest.mark.parametrize("bad", ["id,name\n,Jane\n", "name\nJane\n"])
def test_a_bad_roster_is_refused_in_one_sentence(tmp_path, bad):
    (tmp_path / "r.csv").write_text(bad, encoding="utf-8")
    with pytest.raises(SystemExit, match="--roster"):
        reports.read_roster(tmp_path / "r.csv")


def test_variant_codes_can_be_typed_and_a_typo_is_caught_in_one_sentence():
    code = variants.code_for(SECRET, "hw01", "1001")
    assert len(code) == 10 and set(code) <= set(variants.ALPHABET)
    assert not set("01ILO") & set(variants.ALPHABET)
    assert variants.normalize(f" {code[:5].lower()}-{code[5:]} ") == code
    for i in range(10):  # every single wrong character and every swap of neighbours is caught
        for ch in variants.ALPHABET:
            typo = code[:i] + ch + code[i + 1 :]
            if typo != code:
                with pytest.raises(variants.VariantCodeError, match="check character"):
                    variants.normalize(typo)
        if i < 9 and code[i] != code[i + 1]:
            with pytest.raises(ValueError, match="does not match"):
                variants.normalize(code[:i] + code[i + 1] + code[i] + code[i + 2 :])
    with pytest.raises(ValueError, match=r"contains 'O', but a code is 10 characters") as exc:
        variants.normalize("O" + code[1:])
    assert "\n" not in str(exc.value)
    assert exc.value._render_traceback_() == [f"VariantCodeError: {exc.value}"]  # no traceback


def test_a_moodle_grades_export_is_a_roster_and_gets_an_import_file_with_feedback(tmp_path):
    (tmp_path / "g.csv").write_text(
        "First name,Last name,ID number,Institution,Department,Email address,"
        "Assignment: hw01 (Real),Last downloaded from this course\n"
        "Jane,Doe,1001,Uni,Maths,jane@uni.example,-,1764000000\n"
        "Rick,Roe,,Uni,Maths,rick@uni.example,-,1764000000\n",
        encoding="utf-8",
    )
    roster = reports.read_roster(tmp_path / "g.csv")
    assert roster.kind == "moodle-grades" and list(roster) == ["1001", "rick@uni.example"]
    # Moodle's download folder names the student by full name and participant id
    found = identity.parse_name(Path("Jane Doe_4711_assignsubmission_file_/hw01.ipynb"))
    who = identity.identify(found, identity.RosterIndex(roster))
    assert who.entry is roster["1001"] and who.how == "lms"
    tests = grade.HiddenTests.load(ROOT / "solutions" / "hidden_tests" / "hw01.py")
    r = grade.Result("1001", dict(tests.points), dict.fromkeys(tests.points, ""),
                     fractions=dict.fromkeys(tests.points, 1.0))  # fmt: skip
    r.points["q4"], r.fractions["q4"], r.notes["q4"] = 0.0, 0.0, "κ(1) is wrong"
    r.lms = asdict(roster["1001"])
    rows = list(csv.DictReader(reports.scores_table([r], tests, "moodle", roster, "hw01").splitlines()))
    assert rows == [{"ID number": "1001", "Email address": "jane@uni.example", "Full name": "Jane Doe",
                     "hw01": "9", "Feedback": "9/11; q1 2/2 ✓; q2 3/3 ✓; q4 0/2 κ(1) is wrong; "
                     "q5 2/2 ✓; q7 2/2 ✓"}]  # fmt: skip


def test_a_roster_with_a_submission_column_still_matches_submit_manifests(tmp_path):
    """Issue 23: with ``submission`` keys, submit()'s files named by student id were "missing"."""
    (tmp_path / "roster.csv").write_text(
        "id,submission,name\n1001,ada,Ada\n1002,emmy,Emmy\n", encoding="utf-8"
    )
    roster = reports.read_roster(tmp_path / "roster.csv")
    notebook(tmp_path / "subs" / "hw01-1001.ipynb", variants.code_for(SECRET, "hw01", "1001"), "1001")
    notebook(tmp_path / "subs" / "emmy.ipynb", variants.code_for(SECRET, "hw01", "1002"), "1002")
    items = grade.plan(tmp_path / "subs", roster, homework="hw01", secret=SECRET, variants_on=True)
    assert [(i.student, i.who.entry.id, i.who.flags) for i in items] == [("ada", "1001", []), ("emmy", "1002", [])]


def test_a_file_dated_after_the_deadline_canvas_calls_on_time_is_noted_not_penalised(tmp_path):
    """Canvas (no LATE mark) decides; the file's real time is kept and said, never the deadline."""
    after = DEADLINE + timedelta(hours=5)
    for student, flagged in ((None, True), ("1001", False)):  # a submit() time backs Canvas up
        path = notebook(tmp_path / f"{student}.ipynb", "", student, DEADLINE - timedelta(hours=1))
        touch(path, after)
        f = facts(identity.parse_name(Path("doejane_12345_4_hw01-1001.ipynb")), path)
        when, source, flags, notes = identity.time_flags(f, DEADLINE)
        assert when <= DEADLINE and source == "Canvas: on time"
        assert flags == ([identity.FILE_TIME_AFTER] if flagged else [])
        assert after.isoformat(timespec="seconds") in notes[0] and "Canvas's verdict is used" in notes[0]


# Moodle's grading worksheet as "Download grading worksheet" writes it: the submission time in
# "Last modified (submission)" by userdate() (English: "Tuesday, 8 December 2026, 6:00 PM",
# quoted as it holds commas; "-" without a submission), no time zone
MOODLE_WORKSHEET_TIMES = (
    "Identifier,Full name,Email address,Status,Grade,Maximum Grade,Grade can be changed,"
    "Last modified (submission),Last modified (grade),Feedback comments\n"
    'Participant 4711,Jane Doe,jane@example.org,Submitted for grading,,11.00,Yes,'
    '"Tuesday, 8 December 2026, 6:00 PM",-,\n'
    "Participant 4712,Rick Roe,rick@example.org,Submitted for grading - 10 hours 16 mins late,"
    ',11.00,Yes,"Wednesday, 9 December 2026, 10:15 AM",-,\n'
    "Participant 4713,Ann Poe,ann@example.org,No submission,,11.00,Yes,-,-,\n"
)


def test_moodles_recorded_submission_time_decides_lateness(tmp_path):
    """Moodle's worksheet records when each submission was made: that time is used, not the
    file's (an unpacked archive's file time is the unpacking), and a manifest is only compared."""
    (tmp_path / "worksheet.csv").write_text(MOODLE_WORKSHEET_TIMES, encoding="utf-8")
    roster = reports.read_roster(tmp_path / "worksheet.csv")
    deadline = datetime(2026, 12, 8, 23, 59, tzinfo=timezone(timedelta(hours=1)))
    subs = tmp_path / "subs"
    # "Download all submissions": a folder per participant, or flattened file names
    jane = notebook(subs / "Jane Doe_4711_assignsubmission_file_" / "hw01.ipynb", "", "jane",
                    deadline - timedelta(hours=6))  # fmt: skip
    rick = notebook(subs / "Rick Roe_4712_assignsubmission_file_hw01-rick.ipynb", "", "rick",
                    deadline - timedelta(hours=1))  # his manifest claims on time  # fmt: skip
    touch(jane, deadline + timedelta(days=3))  # unpacked days later
    touch(rick, deadline - timedelta(hours=1))  # a file time that looks on time
    items = {i.who.entry.id: i for i in grade.plan(subs, roster)}
    assert set(items) == {"jane@example.org", "rick@example.org"}
    late = reports.LatePolicy(deadline, 0.1)
    outcome = {}
    for rid, item in items.items():
        assert identity.read_lms_time(item.found, item.who.entry, deadline) == []
        when, source, flags, _ = identity.time_flags(item.found, deadline)
        outcome[rid] = (when, source, flags, late.apply(when))
    when, source, flags, (days, _) = outcome["jane@example.org"]
    assert when == datetime(2026, 12, 8, 18, 0, tzinfo=deadline.tzinfo) and source.startswith("Moodle")
    assert days == 0 and flags == []
    when, source, flags, (days, penalty) = outcome["rick@example.org"]
    assert when == datetime(2026, 12, 9, 10, 15, tzinfo=deadline.tzinfo) and days == 1
    assert penalty == pytest.approx(0.1) and flags == [identity.TIMES_DISAGREE]


def test_a_moodle_time_that_cannot_be_read_falls_back_to_the_files_time_and_says_so(tmp_path):
    (tmp_path / "worksheet.csv").write_text(
        MOODLE_WORKSHEET_TIMES.replace("Tuesday, 8 December 2026, 6:00 PM", "martes, 8 de diciembre"),
        encoding="utf-8",
    )
    roster = reports.read_roster(tmp_path / "worksheet.csv")
    path = notebook(tmp_path / "subs" / "Jane Doe_4711_assignsubmission_file_hw01.ipynb")
    touch(path, DEADLINE - timedelta(hours=2))
    (item,) = grade.plan(tmp_path / "subs", roster)
    notes = identity.read_lms_time(item.found, item.who.entry, DEADLINE)
    assert item.found.lms_time is None and "could not be read" in notes[0]
    when, source, _, _ = identity.time_flags(item.found, DEADLINE)
    assert source == "file time" and when == DEADLINE - timedelta(hours=2)
    # a plain file (not from Moodle's archive) never takes a worksheet's time
    f = identity.Found(path, "jane.ipynb")
    assert identity.read_lms_time(f, item.who.entry, DEADLINE) == [] and f.lms_time is None
