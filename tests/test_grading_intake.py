"""What the grader opens and what it writes (issue 27, sections 1, 2 and 7).

* links are reported, never read: a notebook or a folder that is a symbolic link (to a
  classmate's notebook, to the course secret), a FIFO, a hard link -- in the scan, and again
  when the file is opened (a link swapped in after the scan);
* a file that is not a notebook says so without a byte of its content;
* every name is written, whatever its bytes (not UTF-8, control characters) or case: one
  feedback file per student, stable, distinct ignoring case, unclaimable by a crafted name;
* no cell of ``scores.csv`` starts with a formula character unless it is a number.

Everything here grades only links and invalid notebooks (no kernel starts), so it is fast.
"""

from __future__ import annotations

import csv
import json
import os
from pathlib import Path

import nbformat
import pytest

from tools import grade
from tools.grading import runner

ROOT = Path(__file__).resolve().parents[1]
HIDDEN = ROOT / "solutions" / "hidden_tests" / "hw01.py"

intake, safe_names = grade.intake, grade.safe_names

SECRET_TEXT = "course-secret-Zq7Vw2Lp9Xk4Rt8Yb3Nm6"


def _notebook(path: Path, code: str = "x = 1") -> Path:
    nbformat.write(nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(code)]), path)
    return path


@pytest.fixture
def subs(tmp_path):
    folder = tmp_path / "subs"
    folder.mkdir()
    secret = tmp_path / "course_secret.txt"
    secret.write_text(SECRET_TEXT)
    _notebook(folder / "victim.ipynb", "answer = 'the victim work'")
    os.symlink(folder / "victim.ipynb", folder / "copycat.ipynb")
    os.symlink(secret, folder / "thief.ipynb")
    os.symlink(tmp_path, folder / "dirlink")  # a folder link: "dirlink" is refused
    (folder / "mixed").mkdir()
    _notebook(folder / "mixed" / "mine.ipynb")
    os.symlink(secret, folder / "mixed" / "newer.ipynb")
    os.mkfifo(folder / "fifo.ipynb")
    _notebook(tmp_path / "elsewhere.ipynb")
    os.link(tmp_path / "elsewhere.ipynb", folder / "hard.ipynb")
    return folder


def test_scan_refuses_links_fifos_and_hard_links(subs):
    found = intake.scan(subs)
    assert [f[0] for f in found.found] == ["mixed", "victim"]
    assert found.found[0][1].name == "mine.ipynb" and found.found[0][2] == []
    reasons = {k: [r for _, r in v] for k, v in found.refused.items()}
    assert reasons == {
        "copycat": [intake.LINK],
        "thief": [intake.LINK],
        "dirlink": [intake.LINK],
        "mixed": [intake.LINK],
        "fifo": [intake.NOT_REGULAR],
        "hard": [intake.HARD_LINK],
    }


def test_read_regular_refuses_a_link_swapped_in_after_the_scan(subs, tmp_path):
    found = intake.scan(subs)
    victim = found.found[1][1]
    assert b"the victim work" in intake.read_regular(subs, victim)
    victim.unlink()
    os.symlink(tmp_path / "course_secret.txt", victim)
    with pytest.raises(intake.Refused, match="a link"):
        intake.read_regular(subs, victim)
    # a folder on the way swapped for a link
    inner = found.found[0][1]
    os.rename(subs / "mixed", tmp_path / "moved")
    os.symlink(tmp_path / "moved", subs / "mixed")
    with pytest.raises(intake.Refused, match="a link"):
        intake.read_regular(subs, inner)
    with pytest.raises(intake.Refused, match="outside"):
        intake.read_regular(subs, tmp_path / "course_secret.txt")


def test_load_moves_a_swapped_file_to_refused(subs, tmp_path):
    found = intake.scan(subs)
    (subs / "victim.ipynb").unlink()
    os.symlink(tmp_path / "course_secret.txt", subs / "victim.ipynb")
    contents = intake.load(subs, found)
    assert [f[0] for f in found.found] == ["mixed"]
    assert found.refused["victim"] == [("victim.ipynb", intake.LINK)]
    assert all(SECRET_TEXT.encode() not in b for b in contents.values())


@pytest.mark.parametrize(
    "content",
    [SECRET_TEXT, f'{{"cells": "{SECRET_TEXT}"}}', f'{{"cells": [], "{SECRET_TEXT}": 1,}}',
     f'{{"cells": [{{"cell_type": "{SECRET_TEXT}"}}], "nbformat": 4}}'],
)  # fmt: skip
def test_a_file_that_is_no_notebook_is_not_echoed(tmp_path, content):
    path = tmp_path / "x.ipynb"
    path.write_text(content)
    nb, problem = runner._read_notebook(path)
    assert nb is None and "not a valid notebook" in problem
    assert not any(SECRET_TEXT[i : i + 4] in problem for i in range(len(SECRET_TEXT) - 3))


def test_display_names_are_printable_and_injective():
    raw = [b"caf\xe9", b"caf\\xe9", b"caf\xc3\xa9", b"a\nb", b"a\\nb", b"x\xe2\x80\xaey", b"\xff"]
    shown = [safe_names.display_name(os.fsdecode(b)) for b in raw]
    assert len(set(shown)) == len(raw)
    for text in shown:
        text.encode("utf-8")  # never raises
        assert "\n" not in text and "\u202e" not in text
    assert shown[0] == "caf\\xe9" and shown[1] == "caf\\\\xe9" and shown[2] == "café"


def test_file_stems_distinct_ignoring_case_and_unclaimable():
    names = ["Alice", "alice", "ALICE", "a/b", "a%2Fb", "..", ".x", "-x", "x" * 300, "", "Alice~2"]
    stems = safe_names.file_stems(names)
    lowered = [s.lower() for s in stems.values()]
    assert len(set(lowered)) == len(names)
    for s in stems.values():
        assert "/" not in s and not s.startswith((".", "-")) and 0 < len(s) < 130
    # a name crafted to equal another's disambiguated stem gets its own escaped stem
    assert stems["Alice~2"] == "Alice%7E2"
    # stable: a stem once given is kept when later names arrive
    again = safe_names.file_stems(["alicE", "aLice"], stems)
    assert {k: again[k] for k in stems} == stems
    assert len({s.lower() for s in again.values()}) == len(names) + 2


@pytest.mark.parametrize(
    ("value", "cell"),
    [("=HYPERLINK(\"http://x\")", "'=HYPERLINK(\"http://x\")"), ("+1+1", "'+1+1"),
     ("-2+3", "'-2+3"), ("@SUM(A1)", "'@SUM(A1)"), ("\tx", "'\tx"), ("\rx", "'\rx"),
     ("-0.5", "-0.5"), ("+3e2", "'+3e2"), ("+1001", "'+1001"), (-1.5, -1.5), (7, 7),
     ("alice", "alice"), ("-", "-"), ("--", "'--"),
     ("\ud800", "\\ud800")],
)  # fmt: skip
def test_csv_cells_are_never_formulas(value, cell):
    assert safe_names.csv_cell(value) == cell


HOSTILE = {
    b"caf\xe9": "bad UTF-8 file name",
    b"Bob": "case 1",
    b"bob": "case 2",
    b'=HYPERLINK("evil.example","x")': "formula",
    b"@cmd": "formula",
    b"-2+3": "formula",
    b"new\nline": "control character",
}


def test_hostile_names_and_links_get_a_row_each_and_their_own_feedback(subs, tmp_path):
    # invalid notebooks: no kernel starts, so this batch is fast
    for raw in HOSTILE:
        (subs / os.fsdecode(raw + b".ipynb")).write_bytes(b"not json: " + raw)
    (subs / os.fsdecode(b"dir\xff")).mkdir()
    (subs / os.fsdecode(b"dir\xff") / os.fsdecode(b"n\xfe.ipynb")).write_bytes(b"{}")
    os.unlink(subs / "victim.ipynb")  # keep the batch free of real kernels
    os.unlink(subs / "mixed" / "mine.ipynb")
    (subs / "victim.ipynb").write_text("{")
    out = tmp_path / "out"
    code = grade.main(["--tests", str(HIDDEN), "--submissions", str(subs), "--out", str(out),
                       "--sandbox", "none"])  # fmt: skip
    assert code == 0
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    shown = {safe_names.display_name(os.fsdecode(raw)) for raw in HOSTILE}
    links = {"copycat", "thief", "dirlink", "mixed", "fifo", "hard"}
    expected = shown | links | {"victim", "dir\\xff"}
    assert {k.removeprefix("'") for k in rows} == expected
    for name in links:
        assert rows[name]["total"] == "0.0" and "not graded" in rows[name]["status"]
    for key in rows:  # no formula in any cell
        for cell in rows[key].values():
            assert not cell.startswith(("=", "+", "@", "\t", "\r")) or cell[0] == "'", cell
            assert not cell.startswith("-") or cell.lstrip("-").replace(".", "").isdigit(), cell
    feedback = sorted((out / "feedback").iterdir())
    assert len(feedback) == len(expected)
    assert len({p.name.lower() for p in feedback}) == len(feedback)
    everything = b"".join(p.read_bytes() for p in out.rglob("*") if p.is_file())
    assert SECRET_TEXT.encode() not in everything
    thief = next(p for p in feedback if p.name == "thief.md").read_text(encoding="utf-8")
    assert "a link, not graded" in thief
    results = json.loads((out / "results.json").read_text(encoding="utf-8"))
    assert len(results["results"]) == len(expected)
    # the rows intake refused say so in their own field; the summary lists them from it
    refused = {r["student"]: r["refused"] for r in results["results"] if r["refused"]}
    assert set(refused) == links and refused["thief"] == "a link, not graded"
    act = (out / "summary.md").read_text(encoding="utf-8").split("## Statistics")[0]
    assert "Files not opened" in act and all(name in act for name in links)
    mixed = next(p for p in feedback if p.name == "mixed.md").read_text(encoding="utf-8")
    assert "mixed/newer.ipynb: a link, not graded" in mixed


def test_a_manifest_with_lone_surrogates_is_still_written(tmp_path):
    tests = grade.HiddenTests.load(HIDDEN)
    out = grade.Reports(tests, tmp_path)
    r = grade.Result("eve", dict.fromkeys(tests.points, 0.0), dict.fromkeys(tests.points, "\ud800"))
    r.manifest_student = "\udcff=cmd"
    out.add(r)
    out.finish()
    assert "\\ud800" in (tmp_path / "feedback" / "eve.md").read_text(encoding="utf-8")


def test_a_link_of_a_roster_student_is_listed_as_a_file_not_opened(tmp_path):
    """The summary names links for what they are: not 'not in the roster', not 'missing'."""
    reports = grade.reports
    roster_csv = tmp_path / "roster.csv"
    roster_csv.write_text("id,name,email\n1001,Ann,a@x\n1010,Lin,l@x\n1020,Max,m@x\n")
    roster = reports.read_roster(roster_csv)
    tests = grade.HiddenTests.load(HIDDEN)
    ann = grade.Result("1001", dict(tests.points), dict.fromkeys(tests.points, "✓"))
    ann.lms = {"id": "1001", "name": "Ann", "email": "a@x"}
    link = grade.Result("1010", dict.fromkeys(tests.points, 0.0), dict.fromkeys(tests.points, ""),
                        status="a link, not graded", refused="a link, not graded")  # fmt: skip
    text, data = reports.summary([ann, link], tests, roster)
    act = text.split("## Statistics")[0]
    assert "Files not opened" in act and "1010 (a link)" in act
    assert data["not_in_roster"] == [] and data["no_submission"] == ["1020 (Max)"]
