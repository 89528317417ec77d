"""Build the student edition: what a class gets, and nothing an instructor keeps.

Usage::

    python tools/release.py --out dist/student-edition     # also writes dist/student-edition.zip
    python tools/release.py --out dist/student-edition --secret-file course_secret.txt --roster roster.csv
        # the same, with answer keys for every student's data (tools/answer_keys.py)

The edition holds the lecture notebooks (``notebooks/``), the blank homework (``exercises/``),
the installable ``course_lib`` package, ``pyproject.toml``, ``constraints.txt``,
``environment.yml`` (Binder-ready on its own), a student ``README.md`` and a small ``Makefile``
(``make lab`` installs and opens the course; ``make submit HW=hw01 STUDENT=id`` hands in).
It holds **no** solution notebook, hidden test, homework source, test or test fixture: it is built
from an allow-list, and ``tests/test_release.py`` greps the result for solution markers,
hidden-test names and the hidden tests' data.
"""

from __future__ import annotations

import argparse
import re
import shutil
import sys
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MARK = ".student-edition"

# what goes in, relative to the checkout (an allow-list: nothing else is copied)
INCLUDE_FILES = ["pyproject.toml", "constraints.txt", "environment.yml", "LICENSE",
                 ".jupyter-course/jupyter_server_config.py"]
INCLUDE_GLOBS = ["notebooks/*.ipynb", "exercises/*.ipynb", "course_lib/**/*.py",
                 "course_lib/**/*.json",
                 # JupyterLab as the course sets it up: no news popup, readable fonts, the
                 # table of contents open, widget views stripped on save (no dead widgets)
                 ".jupyter-course/lab/user-settings-defaults/**/*.jupyterlab-settings",
                 ".jupyter-course/lab/workspaces-defaults/*.jupyterlab-workspace"]

STUDENT_README = """# Geometric continuity of parametric curves — student edition

Lectures, homework and `course_lib`, the course's companion package. You need Python 3.10+
and `make` (or conda: see below). Nothing here needs the network once installed.

## Two commands

```sh
make lab                              # installs the course in .venv and opens JupyterLab
make submit HW=hw01 STUDENT=your-id   # hands in homework 1 (see "Submit")
```

With conda instead: `conda env create -f environment.yml && conda activate geometric-continuity`,
then `jupyter lab notebooks/00_welcome.ipynb`. The same `environment.yml` works on Binder.

## Lectures and homework

Work through `notebooks/` in order (`00_welcome` first). After each lecture comes its homework in
`exercises/`: replace every `...` (or write the body of the function), run the cell, then the
**check cell** under it. It answers ✓, or ✗ with what is wrong, or "not answered yet"; the last
cell checks everything at once. A "?" (value not checked here) means this copy has no answer key
for your data: check that `VARIANT` is your code, and if it is, tell your instructor. The checks
are feedback: your grade comes from the instructor's grader, which runs its own tests on other
data, so write code that works in general and keep the answer names.

## Your variant code

Every homework gives each student their own data. Your instructor hands you a short **variant
code** per homework (10 characters from A–Z and 2–9, without I, L, O, 0 or 1; the last one is a
check character, so a typo is caught at once). Paste it into the Preparations cell of the
homework, `VARIANT = "..."`, and run the notebook again: the cells marked "your data" now print
*your* data, and the checks give feedback on it. Your grade is computed on your own data from
your student id, so a friend's code (or none) makes the data questions wrong. With
`VARIANT = ""` you see the data printed in the notebook — fine to practise, not to hand in.

## Submit

`your-id` below is **the id your instructor gave you with your variant code** — your id on the
course roster (e.g. your student number / SIS id), not a name you choose: your variant code is
made from it, and the grader finds you (and your data) by it.

Save the notebook, then `make submit HW=hw01 STUDENT=your-id` (`HW=hw1` or `HW=1` work too; or,
in a new cell at the end of the notebook,
`from course_lib.homework.submit import submit; submit("hw01_reparametrization.ipynb", student="your-id")`).
It runs your notebook top to bottom in a fresh kernel — exactly what the grader does; the cell
that calls `submit` is not run again — lists the cells that raise an error, says how many checks
pass (and if `VARIANT` is still empty), and writes `submissions/hw01-your-id.ipynb` with a small
manifest (your id, the homework, the time, a checksum). Upload that file where your instructor
says, without opening and saving it again (the grader notices a file changed after `submit`).

## Accessibility

The course aims at WCAG 2.1 AA. Every figure has a text description (printed under it in
JupyterLab). Every demo with draggable points can be used with the keyboard alone: a point
selector, coordinate fields (arrow keys nudge the point) and nudge buttons; the continuity
report is read out by screen readers as it changes. A check that fails says so in words
("not right yet"), not only with a symbol. The demos' sliders are named for screen readers
when you run the demo's cell yourself (an output saved from an earlier session is not trusted:
run the cell again). If something stands in
your way — a figure you cannot follow, a control you cannot reach, a colour you cannot tell
apart — tell your instructor: they will help with the homework at once and pass the barrier on
to the course's authors, who fix it like any other bug.
"""

STUDENT_MAKEFILE = """# The student edition's commands (Python 3.10+):
#   make lab                             install the course in .venv and open JupyterLab
#   make submit HW=hw01 STUDENT=your-id  run homework 1 fresh and write submissions/hw01-your-id.ipynb
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
ALLOW_ROOT := $(if $(filter 0,$(shell id -u)),--allow-root,)

.PHONY: install lab submit

$(STAMP): pyproject.toml constraints.txt
\t@echo "installing the course into $(VENV) (a few minutes the first time)"
\t$(PYTHON) -m venv $(VENV)
\t$(BIN)/python -m pip install --progress-bar on -c constraints.txt -e .
\ttouch $@

install: $(STAMP)

lab: install
\t$(BIN)/jupyter lab --config=.jupyter-course/jupyter_server_config.py \\
\t    --ServerApp.root_dir=$(CURDIR) $(ALLOW_ROOT) notebooks/00_welcome.ipynb

submit: install
\t@test -n "$(STUDENT)" || (echo "usage: make submit HW=hw01 STUDENT=your-id"; exit 2)
\t$(BIN)/python -m course_lib.homework.submit "$(HW)" --student "$(STUDENT)"
"""


def edition_files() -> list[Path]:
    files: set[Path] = set()
    for name in INCLUDE_FILES:
        if (ROOT / name).is_file():
            files.add(ROOT / name)
    for pattern in INCLUDE_GLOBS:
        files.update(p for p in ROOT.glob(pattern) if p.is_file())
    return sorted(p for p in files if "__pycache__" not in p.parts
                  and ".ipynb_checkpoints" not in p.parts)


def _student_pyproject(text: str) -> str:
    """The course's pyproject without the instructors' test group; readme = the student's."""
    lines, skip = [], False
    for line in text.splitlines():
        if line.strip() == "[project.optional-dependencies]":
            skip = True
            continue
        if skip and line.startswith("["):
            skip = False
        if skip:
            continue
        if line.startswith("[tool.pytest") or line.startswith("[tool.ruff"):
            break  # instructors' tool settings
        if line.startswith("# tools/") or line.startswith("# in the course's environment"):
            continue  # the edition has no tools/: its package is course_lib alone
        lines.append(line.replace('include = ["course_lib*", "tools*"]', 'include = ["course_lib*"]'))
    return "\n".join(lines).rstrip() + "\n"


#: the welcome page as the edition has it: only the commands its Makefile has, no solutions link
WELCOME = "notebooks/00_welcome.ipynb"
WELCOME_EDITS = [
    (
        "| `make present L=06` | shows lecture 6 as slides for a projector: large text, live demos, "
        "no code (any lecture number works) |\n",
        "",
    ),
    (
        "| `make test` | the same installation, then the whole test suite: the package's unit tests, "
        "and every notebook of [`notebooks/`](./), [`exercises/`](../exercises/) and "
        "[`solutions/`](../solutions/) executed from top to bottom |",
        "| `make submit HW=hw01 STUDENT=your-id` | runs homework 1 top to bottom in a fresh kernel, "
        "as the grader will, and writes `submissions/hw01-your-id.ipynb` for you to upload |",
    ),
    (
        "The matching notebooks in [`solutions/`](../solutions/) hold worked solutions and are "
        "meant for instructors.\n\n",
        "",
    ),
]


def _student_welcome(text: str) -> str:
    """The welcome notebook without the instructors' commands and the solutions link."""
    import nbformat

    nb = nbformat.reads(text, as_version=4)
    for old, new in WELCOME_EDITS:
        cells = [c for c in nb.cells if old in c.source]
        if len(cells) != 1:
            raise SystemExit(f"{WELCOME}: the edition's edit no longer applies: {old[:60]!r}")
        cells[0].source = cells[0].source.replace(old, new)
    return nbformat.writes(nb) + "\n"


#: what must not be left in an edition: an author's TODO/FIXME, new_homework.py's @HW@ fields
UNFINISHED = re.compile(r"\bTODO\b|\bFIXME\b|\bXXX\b|@(?:HW|N|TITLE|STEM)@")


def unfinished(files: list[Path]) -> list[str]:
    """``file:line: text`` for every TODO or placeholder in the notebooks and the package."""
    hits = []
    for path in files:
        if path.suffix not in (".ipynb", ".py", ".md", ".yml"):
            continue
        for n, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if UNFINISHED.search(line):
                hits.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()[:100]}")
    return hits


def _student_environment(text: str) -> str:
    """environment.yml for students: the course's runtime only (no test suite, site, benchmark)."""
    keep, skip = [], False
    for line in text.splitlines():
        stripped = line.strip()
        if stripped.startswith("# Names and versions match"):
            line = "# Names and versions match the course's pyproject.toml and constraints.txt."
        if stripped in ("# the test suite", "# the website and the handouts (make site, make handouts)"):
            skip = True
            continue
        if stripped == "- pip:":
            skip = False
        if skip or "bezier" in stripped or stripped.startswith("# benchmark-only") or stripped.startswith("# its C library"):
            continue
        keep.append(line)
    return "\n".join(keep) + "\n"


def build(out: Path, keys=None) -> Path:
    """Write the edition to ``out`` (replacing it) and ``out``.zip; return the zip's path.

    ``keys`` (:class:`course_lib.homework.answer_keys.AnswerKeys`) replace the package's answer
    keys, which hold the default data's only.  Refuses (``SystemExit``) an edition with a TODO or
    a scaffold placeholder left in it."""
    left = unfinished(edition_files())
    if left:
        raise SystemExit(
            f"the student edition is not finished: {len(left)} TODO/placeholder(s) left, e.g.\n  "
            + "\n  ".join(left[:10])
        )
    if out.exists() and any(out.iterdir()):
        if not (out / MARK).is_file():  # never delete a folder this script did not write
            raise SystemExit(f"--out {out}: not empty and not an earlier student edition")
        shutil.rmtree(out)
    out.mkdir(parents=True, exist_ok=True)
    (out / MARK).write_text("built by tools/release.py\n", encoding="utf-8")
    for src in edition_files():
        rel = src.relative_to(ROOT)
        dst = out / rel
        dst.parent.mkdir(parents=True, exist_ok=True)
        if rel.as_posix() == "pyproject.toml":
            dst.write_text(_student_pyproject(src.read_text(encoding="utf-8")), encoding="utf-8")
        elif rel.as_posix() == "environment.yml":
            dst.write_text(_student_environment(src.read_text(encoding="utf-8")), encoding="utf-8")
        elif rel.as_posix() == WELCOME:
            dst.write_text(_student_welcome(src.read_text(encoding="utf-8")), encoding="utf-8")
        else:
            shutil.copyfile(src, dst)
    if keys is not None:
        keys.write(out / "course_lib" / "homework" / "answer_keys.json")
    (out / "README.md").write_text(STUDENT_README, encoding="utf-8")
    (out / "Makefile").write_text(STUDENT_MAKEFILE, encoding="utf-8")
    archive = out.with_suffix(".zip")
    with zipfile.ZipFile(archive, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(out.rglob("*")):
            if path.is_file():
                zf.write(path, Path(out.name) / path.relative_to(out))
    return archive


def _keyed() -> str:
    from tools.answer_keys import keyed_questions

    return "; ".join(f"{hw} {', '.join(quanta)}" for hw, quanta in keyed_questions().items())


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Build the student edition of the course.")
    p.add_argument("--out", type=Path, default=ROOT / "dist" / "student-edition")
    p.add_argument("--secret-file", type=Path,
                   help="the course secret: with --roster, the edition's checks get answer keys "
                        "for every student's data (tools/answer_keys.py)")
    p.add_argument("--roster", type=Path, help="the roster the students' codes are made from")
    args = p.parse_args(argv)
    if (args.secret_file is None) != (args.roster is None):
        raise SystemExit("give --secret-file and --roster together (SECRET= and ROSTER= of make release)")
    keys = None
    if args.roster is not None:  # before anything is written: a bad roster stops the build
        from tools import answer_keys as keys_tool

        keys, students = keys_tool.for_roster(args.secret_file, args.roster)
    if keys is not None:
        build(args.out, keys=keys)
        told = f"answer keys for the default data and {len(students)} students"
    else:
        build(args.out)
        told = (f"answer keys for the default data only: the checks of {_keyed()} say "
                "\"value not checked here\" to a student with a code; give SECRET= and ROSTER=")
    n = sum(1 for f in args.out.rglob("*") if f.is_file())
    print(f"wrote {args.out} ({n} files) and {args.out.with_suffix('.zip')}, with {told}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
