"""The commands of a semester work as printed (issue 23): make grade/submit, the student edition.

Fast: ``make -n`` shows what a target would run; the edition is built (not installed).
"""

from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from course_lib.homework.submit import find_homework
from tools import release

ROOT = Path(__file__).resolve().parents[1]

needs_make = pytest.mark.skipif(shutil.which("make") is None, reason="needs make")


def _make_n(*args: str) -> str:
    out = subprocess.run(["make", "-n", "-C", str(ROOT), *args], capture_output=True, text=True, check=False)
    return out.stdout + out.stderr


@needs_make
def test_make_grade_passes_every_option_through():
    text = _make_n("grade", "HW=hw03", "SUBMISSIONS=in dir", "OUT=out", "ROSTER=roster.csv",
                   "SECRET=course_secret.txt", "FORMAT=canvas", "DEADLINE=2026-12-08T23:59+01:00",
                   "PENALTY=10%", "EXECUTOR=dask", "ONLY=1001")  # fmt: skip
    text = text.replace("\\\n", " ")
    line = next(x for x in text.splitlines() if "tools/grade.py" in x)
    for part in ("--tests solutions/hidden_tests/hw03.py", '--submissions "in dir"', '--roster "roster.csv"',
                 '--secret-file "course_secret.txt"', "--format canvas", '--deadline "2026-12-08T23:59+01:00"',
                 '--late-penalty "10%"', "--executor dask", '--only "1001"'):  # fmt: skip
        assert part in line, (part, line)


@needs_make
def test_make_submit_takes_hw3_and_install_says_what_it_does():
    # -W pyproject.toml: as on a fresh checkout, where the install step has not run yet
    text = _make_n("-W", "pyproject.toml", "submit", "HW=hw3", "STUDENT=s1")
    assert 'course_lib.homework.submit "hw3" --student "s1"' in text
    assert "--quiet" not in text and "installing the course" in text


@needs_make
@pytest.mark.parametrize("hw", ["hw3", "3", "HW3", "hw03", "03", "hw03_bernstein"])
def test_make_grade_reads_hw_as_make_submit_does(hw):
    """HW=hw3 names hw03 for `make grade` (its hidden tests, its output folder) as for submit."""
    text = _make_n("grade", f"HW={hw}", "SUBMISSIONS=subs")
    line = next(x for x in text.replace("\\\n", " ").splitlines() if "tools/grade.py" in x)
    assert "--tests solutions/hidden_tests/hw03.py " in line and '--out "grading-output/hw03"' in line
    if "_" not in hw:  # submit takes a homework id or a notebook, not a notebook's stem
        assert find_homework(hw, ROOT / "exercises").name.startswith("hw03_")


def test_the_scripts_run_as_the_readme_prints_them():
    for name in ("grade.py", "variant.py"):
        path = ROOT / "tools" / name
        assert os.access(path, os.X_OK), f"tools/{name} is not executable"
        assert path.read_text(encoding="utf-8").startswith("#!/usr/bin/env python3\n")


def test_the_student_edition_is_a_students_and_explains_the_variant_code(tmp_path):
    out = tmp_path / "student-edition"
    release.build(out)
    readme = (out / "README.md").read_text(encoding="utf-8")
    assert "## Your variant code" in readme and 'VARIANT = "..."' in readme
    env = (out / "environment.yml").read_text(encoding="utf-8")
    for dev in ("pytest", "playwright", "voila", "sphinx", "distributed", "bezier", "tests/"):
        assert dev not in env, dev
    assert "numpy=" in env and "-e ." in env
    assert 'course_lib.homework.submit "$(HW)"' in (out / "Makefile").read_text(encoding="utf-8")


def test_release_refuses_an_edition_with_a_todo_left(tmp_path, monkeypatch):
    unfinished = tmp_path / "hw09_draft.ipynb"
    unfinished.write_text('{"cells": [{"source": "TODO: one paragraph"}]}', encoding="utf-8")
    monkeypatch.setattr(release, "ROOT", tmp_path)
    monkeypatch.setattr(release, "edition_files", lambda: [unfinished])
    with pytest.raises(SystemExit, match="not finished: 1 TODO"):
        release.build(tmp_path / "out")
    assert not (tmp_path / "out").exists()
