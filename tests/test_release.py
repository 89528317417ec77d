"""The student edition (``tools/release.py``): everything a student needs, nothing they must not see.

* built from an allow-list: lectures, blank homework, ``course_lib``, the install files;
* no solution marker, no hidden-test file name, no solution notebook, and none of the hidden
  tests' data (every list of three or more numbers written in a hidden test) anywhere in it;
* it installs into a fresh virtual environment on its own (not editable: the package is really
  packaged) and its welcome lecture and blank homework run there under nbval.
"""

from __future__ import annotations

import ast
import hashlib
import json
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

from tools import release

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def edition(tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("dist") / "student-edition"
    archive = release.build(out)
    assert archive.is_file()
    return out


def _text_files(folder: Path):
    for p in folder.rglob("*"):
        if p.is_file():
            yield p, p.read_text(encoding="utf-8", errors="replace")


def _flat_numbers(node: ast.AST) -> tuple[float, ...] | None:
    """The numbers of a (nested) list/tuple literal of numbers, flattened; None otherwise."""
    try:
        value = ast.literal_eval(node)
    except (ValueError, SyntaxError, TypeError):
        return None
    out: list[float] = []

    def walk(v) -> bool:
        if isinstance(v, (list, tuple)):
            return all(walk(x) for x in v)
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            out.append(float(v))
            return True
        return False

    return tuple(out) if walk(value) else None


def _number_runs(tree: ast.AST) -> set[tuple[float, ...]]:
    """Every list/tuple literal of >= 4 numbers (nested lists flattened) in a syntax tree.

    Shorter runs (a 3-vector, three knots) coincide by chance with the lectures' examples.
    """
    runs = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.List, ast.Tuple)):
            flat = _flat_numbers(node)
            if flat is not None and len(flat) >= 4:
                runs.add(flat)
    return runs


def _secret_runs(path: Path) -> set[tuple[float, ...]]:
    """The hidden tests' own data: every number run outside ``DATA`` (the question as stated)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    runs: set[tuple[float, ...]] = set()
    for node in tree.body:
        targets = [t.id for t in getattr(node, "targets", []) if isinstance(t, ast.Name)]
        if "DATA" not in targets:
            runs |= _number_runs(node)
    return runs


def test_edition_holds_what_a_student_needs(edition):
    names = {p.relative_to(edition).as_posix() for p in edition.rglob("*") if p.is_file()}
    assert {"README.md", "Makefile", "pyproject.toml", "environment.yml", "constraints.txt",
            "course_lib/__init__.py", "course_lib/homework/submit.py", "notebooks/00_welcome.ipynb"} <= names
    # make lab's JupyterLab set-up (no news popup, table of contents open, no dead widgets)
    assert {".jupyter-course/jupyter_server_config.py",
            ".jupyter-course/lab/workspaces-defaults/default-37a8.jupyterlab-workspace",
            ".jupyter-course/lab/user-settings-defaults/@jupyterlab/apputils-extension/"
            "notification.jupyterlab-settings"} <= names
    assert "--config=.jupyter-course/jupyter_server_config.py" in (edition / "Makefile").read_text()
    # the edition installs course_lib alone (tools/ stays with the instructors)
    pyproject = (edition / "pyproject.toml").read_text(encoding="utf-8")
    assert 'include = ["course_lib*"]' in pyproject and '"tools*"' not in pyproject
    # its welcome page names only the edition's commands and links nothing it does not hold
    welcome = (edition / "notebooks" / "00_welcome.ipynb").read_text(encoding="utf-8")
    assert "make submit HW=hw01" in welcome and "make lab" in welcome
    for absent in ("solutions/", "make test", "make present"):
        assert absent not in welcome, absent
    makefile = (edition / "Makefile").read_text()
    assert all(f"\n{t}:" in makefile for t in ("lab", "submit"))
    assert {f"exercises/{p.name}" for p in (ROOT / "exercises").glob("*.ipynb")} <= names
    lectures = {f"notebooks/{p.name}" for p in (ROOT / "notebooks").glob("*.ipynb")}
    assert lectures <= names
    assert not [n for n in names if n.split("/")[0] in {"solutions", "tools", "tests", ".git"}]
    with zipfile.ZipFile(edition.with_suffix(".zip")) as zf:
        assert {n.split("/", 1)[1] for n in zf.namelist()} == names


def test_edition_holds_no_solution_and_no_hidden_test(edition):
    solutions = {hashlib.sha256(p.read_bytes()).hexdigest()
                 for p in (ROOT / "solutions").glob("*.ipynb")}
    hidden = sorted((ROOT / "solutions" / "hidden_tests").glob("hw*.py"))
    forbidden = ["### BEGIN SOLUTION", "### END SOLUTION", "### STUDENT",
                 *(f"hidden_tests/{p.name}" for p in hidden)]
    for path, text in _text_files(edition):
        assert hashlib.sha256(path.read_bytes()).hexdigest() not in solutions, path
        for word in forbidden:
            assert word not in text, f"{path}: {word!r}"
    # the hidden tests' data: no list of 3+ numbers of a hidden test appears in the edition
    secret = set().union(*(_secret_runs(p) for p in hidden))
    assert len(secret) > 10  # the search has something to find
    public = set()
    for path, text in _text_files(edition):
        sources = [text] if path.suffix == ".py" else []
        if path.suffix == ".ipynb":
            sources = ["".join(c["source"]) for c in json.loads(text)["cells"]
                       if c["cell_type"] == "code"]
        for src in sources:
            try:
                public |= _number_runs(ast.parse(src))
            except SyntaxError:
                continue  # a cell with IPython magics: its numbers are read below
            public |= {tuple(float(x) for x in m.split(","))
                       for m in re.findall(r"-?\d[\d.]*(?:\s*,\s*-?\d[\d.]*){3,}", src)
                       if all(re.fullmatch(r"-?\d+(\.\d*)?", x.strip()) for x in m.split(","))}
    trivial = {(0.0, 1.0, 2.0, 3.0), (0.0, 1.0, 2.0, 3.0, 4.0)}  # plain ranges
    leaked = (secret & public) - trivial
    assert not leaked, f"hidden-test data in the student edition: {sorted(leaked)[:5]}"


@pytest.mark.slow
@pytest.mark.timeout(600)
def test_edition_installs_and_runs_in_a_fresh_venv(edition, tmp_path):
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True)
    py = venv / "bin" / "python"
    pins = [line for line in (ROOT / "constraints.txt").read_text().splitlines()
            if line.startswith(("pytest==", "nbval=="))]
    # what a student types, plus --no-compile: pip skips byte-compiling the ~110 packages
    # (a third of the install's time); Python compiles what the notebooks import on import
    subprocess.run(
        [str(py), "-m", "pip", "install", "--quiet", "--no-compile",
         "-c", str(edition / "constraints.txt"), str(edition), *pins],
        check=True, timeout=480,
    )  # fmt: skip
    env = {k: v for k, v in os.environ.items() if k not in {"PYTHONPATH", "VIRTUAL_ENV"}}
    env["MPLBACKEND"] = "Agg"
    run = subprocess.run(
        [str(py), "-m", "pytest", "-q", "-p", "no:cacheprovider", "--nbval-lax",
         "--nbval-current-env", "--nbval-cell-timeout=120", "-c", os.devnull,
         "--rootdir", str(edition), "notebooks/00_welcome.ipynb", "exercises"],
        cwd=edition, env=env, capture_output=True, text=True, timeout=480,
    )  # fmt: skip
    assert run.returncode == 0, run.stdout[-3000:] + run.stderr[-2000:]
    # the package came from the edition's own (non-editable) install, not from this checkout
    where = subprocess.run([str(py), "-c", "import course_lib; print(course_lib.__file__)"],
                           cwd=tmp_path, env=env, capture_output=True, text=True, check=True)
    assert str(venv) in where.stdout
