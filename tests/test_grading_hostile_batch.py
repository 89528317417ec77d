"""Hostile files, names and resources graded in one batch beside two correct submissions
(issue 27, sections 1, 2, 3, 6, 7; the fixtures are ``tests/fixtures/redteam/hostile_files.py``).

One batch with small limits (``--output-limit``, ``--tmp-size``, ``--disk``, ``--memory``):

* every row is there and the grader exits 0; links score 0 with "a link, not graded" and are
  never read: the secret appears in no file the grader wrote;
* the victims keep full marks and their own, canonical feedback;
* every hostile submission that is graded is the solution plus an attack: it keeps full marks
  (its honest work) and its feedback names the limit its attack met -- also when its code
  caught the error (a refused fork, a full /tmp, a MemoryError): the sandbox's own counters
  name it, in the feedback and in the status column, for that submission only;
* names: one feedback file per student, distinct ignoring case; no CSV cell is a formula;
* nothing outside the sandbox is written: the submissions are byte-identical, the job root is
  empty afterwards, no job folder is still mounted, no control group of this run is left (the
  groups another grader on the host has made are not this run's: ``sandbox.RUN_PREFIX``).

Needs bubblewrap; skipped with the reason otherwise.  Run it under ``flock /tmp/heavy.lock``.
"""

from __future__ import annotations

import csv
import hashlib
import os
from pathlib import Path

import nbformat
import pytest
from _homework_support import load

from tools import grade

ROOT = Path(__file__).resolve().parents[1]
HIDDEN = ROOT / "solutions" / "hidden_tests" / "hw01.py"
SOLUTION = ROOT / "solutions" / "hw01_reparametrization.ipynb"

hostile_files = load("hostile_files", ROOT / "tests" / "fixtures" / "redteam" / "hostile_files.py")
safe_names = grade.safe_names

ok, why = grade.sandbox.bwrap_works()
pytestmark = [
    pytest.mark.slow,
    pytest.mark.timeout(600),
    pytest.mark.skipif(not ok and os.environ.get("CI") != "true", reason=f"no sandbox: {why}"),
]

OUTPUT_LIMIT = 256 << 10
LIMIT_NOTES = {
    "fills_tmp": ["No space left on device", "/tmp and /dev/shm hold 4 MB"],
    "fills_shm": ["No space left on device", "/tmp and /dev/shm hold 4 MB"],
    "fills_disk": ["disk limit of 16 MB"],
    "hogs_cpu": [],
    "huge_output": [f"printed more than {OUTPUT_LIMIT} bytes of output"],
    "comm_flood": [f"widgets sent more than {OUTPUT_LIMIT} bytes"],
    "caught_fork": [],
    "caught_tmp": [],
    "caught_memory": [],
}
#: the flag in the status column (and a sentence in the feedback) from the sandbox's counters
LIMIT_FLAGS = {
    "fills_tmp": "reached the /tmp limit (4 MB)",
    "fills_shm": "reached the /dev/shm limit (4 MB)",
    "fills_disk": "reached the disk limit (16 MB)",
    "hogs_cpu": "reached the process limit (64)",
    "caught_fork": "reached the process limit (64)",
    "caught_tmp": "reached the /tmp limit (4 MB)",
    "caught_memory": "reached the memory limit (2048 MB)",
}
ALL_ATTACKS = {**hostile_files.ATTACKS, **hostile_files.CAUGHT}


def _with_attack(source: str) -> bytes:
    nb = nbformat.read(SOLUTION, as_version=4)
    nb.cells.append(nbformat.v4.new_code_cell(source))
    return nbformat.writes(nb).encode()


def _tree(folder: Path) -> dict[str, str]:
    out = {}
    for dirpath, _dirs, files in os.walk(folder):
        for name in files:
            p = Path(dirpath) / name
            out[str(p)] = (
                "link:" + os.readlink(p)
                if p.is_symlink()
                else hashlib.sha256(p.read_bytes()).hexdigest()
            )
    return out


@pytest.fixture(scope="module")
def batch(tmp_path_factory):
    subs = tmp_path_factory.mktemp("submissions")
    outside = tmp_path_factory.mktemp("outside")
    solution = SOLUTION.read_bytes()
    (subs / "correct_1.ipynb").write_bytes(solution)
    (subs / "correct_2.ipynb").write_bytes(solution)
    kinds = hostile_files.lay_out(subs, outside, solution, _with_attack)
    kinds.update(correct_1="victim", correct_2="victim")
    before = {**_tree(subs), **_tree(outside)}
    jobs = tmp_path_factory.mktemp("jobroot") / "jobs"
    out = tmp_path_factory.mktemp("grades")
    code = grade.main(
        ["--tests", str(HIDDEN), "--submissions", str(subs), "--out", str(out),
         "--cell-timeout", "20", "--question-timeout", "10", "--time-limit", "120",
         "--jobs", "2", "--sandbox", "bwrap", "--memory", "2",
         "--output-limit", str(OUTPUT_LIMIT), "--tmp-size", "4", "--disk", "16",
         "--job-root", str(jobs)]
    )  # fmt: skip
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return {
        "code": code, "subs": subs, "outside": outside, "out": out, "kinds": kinds,
        "rows": rows, "before": before, "after": {**_tree(subs), **_tree(outside)},
        "jobs": jobs, "left_groups": grade.sandbox.run_groups(),
    }  # fmt: skip


def _shown(student: str) -> str:
    return safe_names.csv_cell(safe_names.display_name(student))


def _feedback(batch, student: str) -> str:
    stems = safe_names.file_stems([safe_names.display_name(s) for s in batch["kinds"]])
    path = batch["out"] / "feedback" / f"{stems[safe_names.display_name(student)]}.md"
    return path.read_text(encoding="utf-8")


def test_every_row_is_there(batch):
    assert batch["code"] == 0
    assert set(batch["rows"]) == {_shown(s) for s in batch["kinds"]}


def test_links_are_reported_and_never_read(batch):
    for student, kind in batch["kinds"].items():
        if kind == "link":
            row = batch["rows"][student]
            assert float(row["total"]) == 0 and row["status"] == "a link, not graded", row
            assert "a link, not graded" in _feedback(batch, student)
    written = b"".join(p.read_bytes() for p in batch["out"].rglob("*") if p.is_file())
    assert hostile_files.SECRET_TEXT.encode() not in written
    assert hostile_files.SECRET_TEXT[:12].encode() not in written


def test_victims_keep_full_marks_and_their_own_feedback(batch):
    tests = grade.HiddenTests.load(HIDDEN)
    for name in ("correct_1", "correct_2"):
        assert float(batch["rows"][name]["total"]) == tests.max_points
        full = grade.Result(name, dict(tests.points), dict.fromkeys(tests.points, ""),
                            fractions=dict.fromkeys(tests.points, 1.0))  # fmt: skip
        assert _feedback(batch, name) == grade.reports.feedback_markdown(full, tests)


@pytest.mark.parametrize("attack", sorted(ALL_ATTACKS))
def test_each_attack_costs_only_its_own_cell_and_names_the_limit(batch, attack):
    row = batch["rows"][attack]
    assert float(row["total"]) == 11, row  # the solution's honest work, all of it
    text = _feedback(batch, attack)
    for fragment in LIMIT_NOTES[attack]:
        assert fragment in text, (attack, text)
    flag = LIMIT_FLAGS.get(attack)
    if flag is not None:  # counted by the sandbox, also when the code caught the error
        assert flag in row["status"].split("; "), (attack, row["status"])
        assert f"the sandbox {flag}: " in text or "disk" in flag, (attack, text)


def test_limits_met_are_counted_against_their_submission_alone(batch):
    for student, kind in batch["kinds"].items():
        if kind in ("victim", "name"):
            row = batch["rows"][_shown(student)]
            assert "reached" not in row["status"], (student, row["status"])
            assert "the sandbox reached" not in _feedback(batch, student), student


def test_names_are_written_whatever_their_bytes_case_or_first_character(batch):
    names = [s for s, kind in batch["kinds"].items() if kind == "name"]
    for student in names:
        assert float(batch["rows"][_shown(student)]["total"]) == 11
        assert f"— {safe_names.display_name(student)}\n" in _feedback(batch, student)
    feedback = [p.name for p in (batch["out"] / "feedback").iterdir()]
    assert len(feedback) == len(batch["kinds"])
    assert len({n.lower() for n in feedback}) == len(feedback)
    with open(batch["out"] / "scores.csv", newline="", encoding="utf-8") as fh:
        for row in csv.reader(fh):
            for cell in row:
                if cell[:1] in ("=", "+", "-", "@", "\t", "\r"):
                    float(cell)  # only a number may start so


def test_nothing_outside_the_sandbox_was_written(batch):
    assert batch["before"] == batch["after"]
    assert list(batch["jobs"].iterdir()) == []
    assert str(batch["jobs"]) not in Path("/proc/mounts").read_text()
    assert grade.sandbox.RUN_PREFIX.startswith("course-grader-")
    assert batch["left_groups"] == set()
