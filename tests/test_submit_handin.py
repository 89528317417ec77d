"""Handing in from the notebook itself cannot recurse, and says what was checked (issue 23)."""

from __future__ import annotations

import shutil
from pathlib import Path

import nbformat
import pytest

from course_lib.homework.submit import SUBMIT_CELL_NOTE, SUBMITTING_ENV, manifest_of, submit

ROOT = Path(__file__).resolve().parents[1]
NAME = "hw01_reparametrization.ipynb"

pytestmark = [pytest.mark.slow, pytest.mark.timeout(300)]


def test_a_submit_cell_in_the_notebook_is_not_run_again(tmp_path):
    work = tmp_path / "exercises"
    work.mkdir()
    nb = nbformat.read(ROOT / "exercises" / NAME, as_version=4)
    hand_in = f'from course_lib.homework.submit import submit\nsubmit("{NAME}", student="s1")'
    nb.cells.append(nbformat.v4.new_code_cell(hand_in))
    nbformat.write(nb, work / NAME)
    sub = submit(work / NAME, student="s1", timeout=60)
    assert sub.path == tmp_path / "submissions" / "hw01-s1.ipynb" and sub.failed_cells == []
    written = nbformat.read(sub.path, as_version=4)
    assert written.cells[-1].source == SUBMIT_CELL_NOTE + "\n".join(f"# {x}" for x in hand_in.splitlines())
    assert written.cells[-1].outputs == []
    assert len(written.cells) == len(nb.cells)  # the checks cell is not left in the file
    assert not manifest_of(written)["tampered"]
    assert sub.checked.startswith("0 of 7 checks pass; q1, q2")
    assert "not answered yet" in sub.checked
    assert "VARIANT is empty but hw01 has per-student variants" in sub.checked
    assert "Checked: 0 of 7 checks pass" in str(sub)


def test_a_solved_notebook_reports_every_check_passing(tmp_path):
    work = tmp_path / "exercises"
    work.mkdir()
    shutil.copyfile(ROOT / "solutions" / NAME, work / NAME)
    sub = submit(work / NAME, student="s2", timeout=60)
    assert sub.checked.startswith("7 of 7 checks pass")


def test_submit_inside_a_submission_does_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv(SUBMITTING_ENV, "1")
    sub = submit(ROOT / "exercises" / NAME, student="s1", out_dir=tmp_path)
    assert sub.skipped and sub.path is None and list(tmp_path.iterdir()) == []
    assert "not run while the notebook is being submitted" in str(sub)
