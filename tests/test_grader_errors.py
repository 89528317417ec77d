"""A batch where the grader itself failed must not look like a batch of grades.

When the grader cannot grade (a broken cluster, a bug), every such row is written with the
status "grader error" and 0 points -- and the command says so on stderr and exits 3, so a
script or an instructor does not upload those zeros as grades.
"""

from __future__ import annotations

import csv
import shutil
from pathlib import Path

from tools import grade
from tools.grading import runner

ROOT = Path(__file__).resolve().parents[1]
SOLUTION = ROOT / "solutions" / "hw01_reparametrization.ipynb"


def test_a_batch_the_grader_failed_exits_3_and_says_so(tmp_path, monkeypatch, capsys):
    subs = tmp_path / "subs"
    subs.mkdir()
    shutil.copy(SOLUTION, subs / "alice.ipynb")

    def broken(*args, **kwargs):
        raise RuntimeError("the grader's own failure")

    monkeypatch.setattr(runner, "grade_notebook", broken)
    code = grade.main([
        "--tests", str(ROOT / "solutions" / "hidden_tests" / "hw01.py"),
        "--submissions", str(subs), "--out", str(tmp_path / "out"), "--sandbox", "none",
    ])  # fmt: skip
    assert code == 3
    err = capsys.readouterr().err
    assert "1 of 1 submissions were not graded because the grader failed" in err
    with open(tmp_path / "out" / "scores.csv", newline="", encoding="utf-8") as fh:
        (row,) = list(csv.DictReader(fh))
    assert row["status"].startswith("grader error")


def test_a_batch_without_grader_errors_exits_0():
    assert grade._grader_error_exit([], 5) == 0
