"""``tools/`` is a package: its commands run as the README prints them, nothing edits ``sys.path``.

The course is installed editable with ``tools`` beside ``course_lib`` (``pyproject.toml``), so
``from tools.grading import ...`` works from any folder of the course's environment, and each
``tools/<name>.py`` stays the command the README prints (``tools/grade.py ...``,
``.venv/bin/python tools/build_homework.py``).
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PATH_SURGERY = re.compile(r"sys\.path\.(insert|append|extend)|spec_from_file_location\([^)]*tools")


def _python_files(folder: str) -> list[Path]:
    return [p for p in (ROOT / folder).rglob("*.py") if "fixtures" not in p.relative_to(ROOT).parts]


@pytest.mark.parametrize("folder", ["tools", "tests"])
def test_no_sys_path_surgery(folder):
    found = [
        f"{p.relative_to(ROOT)}:{n}"
        for p in _python_files(folder)
        for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if PATH_SURGERY.search(line) and p.name not in ("test_tools_package.py", "test_architecture.py")
    ]
    assert not found, "import the package (from tools import grade) instead: " + ", ".join(found)


def test_tools_is_installed_with_the_course():
    text = (ROOT / "pyproject.toml").read_text(encoding="utf-8")
    section = text.split("[tool.setuptools.packages.find]", 1)[1].split("\n[", 1)[0]
    (include,) = re.findall(r"(?m)^include = (.*)$", section)
    assert '"tools*"' in include and '"course_lib*"' in include
    assert (ROOT / "tools" / "__init__.py").is_file()
    assert (ROOT / "tools" / "grading" / "__init__.py").is_file()


@pytest.mark.parametrize(
    ("script", "expected"),
    [("grade.py", "--submissions"), ("variant.py", "secret"), ("build_homework.py", "--check"),
     ("new_homework.py", "homework"), ("strip_notebooks.py", "usage")],
)  # fmt: skip
def test_a_printed_command_runs_from_another_folder(tmp_path, script, expected):
    """``python tools/X.py --help`` from outside the checkout: the script finds its siblings
    through the installed package, not through the folder it was started from."""
    proc = subprocess.run(
        [sys.executable, str(ROOT / "tools" / script), "--help"],
        cwd=tmp_path, capture_output=True, text=True, timeout=60,
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert expected in proc.stdout
