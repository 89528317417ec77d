"""Grades that cannot be forged: hostile submissions graded beside correct ones (issue 12).

One batch, graded as a course with per-student variants grades it (a course secret, so every
student is graded on their own data; issue 19): two copies of the hw01 solution, each done with
its student's own variant code, every cheat of ``tests/fixtures/redteam/cheats.py``
(one per class of attack: monkeypatching, lying objects, reading the tests, forged results,
reaching outside the kernel, resources) and submissions with colliding names.  Then:

* every cheat scores exactly what its honest wrong answers score (0);
* both correct submissions keep full marks and identical, canonical feedback;
* ``scores.csv`` has a row for everyone; the grader exits 0;
* no process started by a submission outlives the grader;
* nothing outside the sandbox's own folder changed: submitted files are byte-identical, and no
  file the cheats tried to plant exists anywhere they aimed at;
* feedback files are unique per student; several notebooks of one student are flagged.

Needs bubblewrap (``make test`` installs it as root); skipped with the reason otherwise.
"""

from __future__ import annotations

import csv
import hashlib
import os
import tempfile
from pathlib import Path

import nbformat
import pytest
from _homework_support import load

from tools import grade

ROOT = Path(__file__).resolve().parents[1]
HIDDEN = ROOT / "solutions" / "hidden_tests" / "hw01.py"
SOLUTION = ROOT / "solutions" / "hw01_reparametrization.ipynb"

cheats = load("cheats", ROOT / "tests" / "fixtures" / "redteam" / "cheats.py")

ok, why = grade.sandbox.bwrap_works()
pytestmark = [
    pytest.mark.slow,
    pytest.mark.timeout(420),
    pytest.mark.skipif(not ok and os.environ.get("CI") != "true", reason=f"no sandbox: {why}"),
]


SECRET = b"the red team's course secret, 32b"


def _solution_for(student: str) -> nbformat.NotebookNode:
    """The solution notebook as ``student`` hands it in: done with their own variant code."""
    from course_lib.homework import variants

    nb = nbformat.read(SOLUTION, as_version=4)
    code = variants.code_for(SECRET, "hw01", student)
    first = next(c for c in nb.cells if c.cell_type == "code" and 'VARIANT = ""' in c.source)
    first.source = first.source.replace('VARIANT = ""', f"VARIANT = {code!r}", 1)
    return nb


def _marker_processes() -> list[str]:
    found = []
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            cmd = Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()
        except OSError:
            continue
        if cheats.MARKER in cmd and "pytest" not in cmd:
            found.append(f"{pid}: {cmd[:120]}")
    return found


def _pwned_files(roots: list[Path]) -> list[Path]:
    """Every file named ``PWNED_NAME`` under ``roots``.  ``os.walk`` skips a folder that vanishes
    while it is read (the other test worker's temporary folders come and go meanwhile), where
    ``Path.rglob`` would raise."""
    hits = []
    for root in roots:
        for folder, _dirs, files in os.walk(root):
            hits += [Path(folder) / name for name in files if name == cheats.PWNED_NAME]
    return hits


@pytest.fixture(scope="module")
def batch(tmp_path_factory):
    subs = tmp_path_factory.mktemp("submissions")
    nbformat.write(_solution_for("correct_1"), subs / "correct_1.ipynb")
    nbformat.write(_solution_for("correct_2"), subs / "correct_2.ipynb")
    for name, (_, cells) in cheats.CHEATS.items():
        nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c.strip()) for c in cells])
        nbformat.write(nb, subs / f"cheat_{name}.ipynb")
    blank = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(cheats.HONEST_WRONG.strip())])
    # names: "a/b" (a folder) and "a__b" must not share a feedback file; "carol" sent two
    (subs / "a").mkdir()
    nbformat.write(blank, subs / "a" / "b.ipynb")
    nbformat.write(blank, subs / "a__b.ipynb")
    (subs / "carol").mkdir()
    nbformat.write(blank, subs / "carol" / "first.ipynb")
    nbformat.write(_solution_for("carol"), subs / "carol" / "second.ipynb")
    os.utime(subs / "carol" / "first.ipynb", (1_000_000_000, 1_000_000_000))

    groups_before = _cgroups()
    files = sorted(p for p in subs.rglob("*") if p.is_file())
    before = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in files}
    out = tmp_path_factory.mktemp("grades")
    secret = tmp_path_factory.mktemp("secret") / "course_secret.txt"
    secret.write_bytes(SECRET)
    code = grade.main(
        ["--tests", str(HIDDEN), "--submissions", str(subs), "--out", str(out),
         "--cell-timeout", "15", "--question-timeout", "8", "--time-limit", "90",
         "--jobs", "2", "--sandbox", "bwrap", "--secret-file", str(secret)]
    )  # fmt: skip
    import time

    time.sleep(4)  # the detached cheat would write 3 s after it started
    after = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in files}
    with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = {r["student"]: r for r in csv.DictReader(fh)}
    return {"code": code, "subs": subs, "out": out, "before": before, "after": after,
            "rows": rows, "survivors": _marker_processes(),
            "new_cgroups": _cgroups() - groups_before}  # fmt: skip


def test_batch_finishes_with_a_row_for_everyone(batch):
    assert batch["code"] == 0
    expected = {"correct_1", "correct_2", "a", "a__b", "carol",
                *(f"cheat_{n}" for n in cheats.CHEATS)}  # fmt: skip
    assert set(batch["rows"]) == expected


@pytest.mark.parametrize("name", sorted(cheats.CHEATS))
def test_each_cheat_scores_what_its_honest_wrong_answers_score(batch, name):
    row = batch["rows"][f"cheat_{name}"]
    assert float(row["total"]) == 0, (name, row)
    assert row["sandbox"] == "bwrap"


def test_correct_submissions_keep_full_marks_and_identical_feedback(batch):
    tests = grade.HiddenTests.load(HIDDEN)
    for name in ("correct_1", "correct_2"):
        assert float(batch["rows"][name]["total"]) == tests.max_points, batch["rows"][name]
        text = (batch["out"] / "feedback" / f"{name}.md").read_text(encoding="utf-8")
        full = grade.Result(name, dict(tests.points), dict.fromkeys(tests.points, ""),
                            fractions=dict.fromkeys(tests.points, 1.0))
        code = grade.variants.code_for(SECRET, "hw01", name)
        full.run_notes.append(f"graded on the student's own data (variant {code})")
        assert text == grade.reports.feedback_markdown(full, tests)


def test_nothing_outside_the_sandbox_changed(batch):
    assert batch["before"] == batch["after"]
    roots = [batch["subs"], batch["out"], ROOT, Path(tempfile.gettempdir())]
    assert _pwned_files(roots) == []


def test_no_process_outlives_the_grader(batch):
    assert batch["survivors"] == []
    assert batch["new_cgroups"] == set()  # each sandbox's pids group was removed


def _cgroups() -> set[str]:
    """This run's sandbox groups (another grader on the host has its own prefix)."""
    return grade.sandbox.run_groups()


def test_names_are_unique_and_duplicates_flagged(batch):
    feedback = sorted(p.name for p in (batch["out"] / "feedback").iterdir())
    assert len(feedback) == len(batch["rows"])  # one file per student, none shared
    assert "a.md" in feedback and "a__b.md" in feedback
    carol = batch["rows"]["carol"]
    assert "several notebooks" in carol["status"]
    text = (batch["out"] / "feedback" / "carol.md").read_text(encoding="utf-8")
    assert "carol/second.ipynb (the newest)" in text and "carol/first.ipynb" in text
    assert float(carol["total"]) == 11


def test_feedback_names_are_distinct_even_ignoring_case():
    names = grade.feedback_names(["Alice", "alice", "a/b", "a%2Fb", "..", "x" * 300])
    assert len({n.lower() for n in names.values()}) == 6
    assert all("/" not in n and not n.startswith(".") and len(n) < 130 for n in names.values())


def test_unsandboxed_grading_says_so_everywhere(tmp_path, capsys):
    subs = tmp_path / "subs"
    subs.mkdir()
    nbformat.write(
        nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(cheats.HONEST_WRONG.strip())]),
        subs / "dana.ipynb",
    )
    code = grade.main(["--tests", str(HIDDEN), "--submissions", str(subs), "--out",
                       str(tmp_path / "out"), "--sandbox", "none"])  # fmt: skip
    assert code == 0
    assert "WITHOUT a sandbox" in capsys.readouterr().err
    rows = list(csv.DictReader(open(tmp_path / "out" / "scores.csv", encoding="utf-8")))
    assert rows[-1]["sandbox"] == "none (unsandboxed)"
    assert "WITHOUT a sandbox" in (tmp_path / "out" / "feedback" / "dana.md").read_text()
