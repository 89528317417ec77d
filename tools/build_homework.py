"""Build the homework notebooks from one source each: a student copy and a solution copy.

Usage::

    python tools/build_homework.py            # (re)write exercises/*.ipynb and solutions/*.ipynb
    python tools/build_homework.py --check    # exit 1 if a committed notebook differs from its source

Sources live in ``tools/homework_src/hwNN_<name>.py`` in "percent" format:

``# %%``                       a code cell (both copies)
``# %% [markdown]``            a markdown cell; each line starts with ``#`` (both copies)
``# %% solution``              a code cell only in the solution copy
``# %% [markdown] solution``   a markdown cell only in the solution copy

Inside a code cell::

    ### BEGIN SOLUTION
    answer_q1 = c1 / np.linalg.norm(c1)      # kept in the solution copy only
    ### END SOLUTION
    ### STUDENT answer_q1 = ...               # becomes `answer_q1 = ...` in the student copy
    ### ALT The curve and, under it, its tangent angle and curvature ...

An ``### ALT`` line (several are joined with spaces) is removed from the code and becomes the
cell's text alternative for its figure, ``{"mystnb": {"image": {"alt": ...}}}``: MyST-NB uses it
as the ``alt`` of the figure on the website, and JupyterLab shows it under the figure (see
``course_lib.figure_alt``).  Every figure-producing cell needs one (``tests/test_figure_alt.py``).

so the blank notebook still runs (its checks answer "not answered yet").  The notebooks are
written without outputs, with ``execution_count`` null and stable cell ids, so they diff well
and ``tests/test_homework_build.py`` can assert they are exactly what this script produces.
"""

from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
SRC = ROOT / "tools" / "homework_src"
OUT = {"student": ROOT / "exercises", "solution": ROOT / "solutions"}

_CELL = re.compile(r"^# %%(?: \[(markdown)\])?(?: (solution|student))?\s*$")
_BEGIN, _END, _STUDENT = "### BEGIN SOLUTION", "### END SOLUTION", "### STUDENT"
_ALT = "### ALT "


def sources() -> list[Path]:
    """The homework sources, in order."""
    return sorted(SRC.glob("hw[0-9][0-9]_*.py"))


def _split_cells(text: str) -> list[tuple[str, str | None, list[str]]]:
    cells: list[tuple[str, str | None, list[str]]] = []
    for line in text.splitlines():
        m = _CELL.match(line)
        if m:
            cells.append(("markdown" if m.group(1) else "code", m.group(2), []))
        elif cells:
            cells[-1][2].append(line)
        elif line.strip() and not line.startswith("#"):
            raise ValueError(f"text before the first cell marker: {line!r}")
    return cells


def _strip_blank(lines: list[str]) -> list[str]:
    while lines and not lines[0].strip():
        lines = lines[1:]
    while lines and not lines[-1].strip():
        lines = lines[:-1]
    return lines


def _code_for(lines: list[str], version: str, where: str) -> str:
    out: list[str] = []
    inside = False
    for n, line in enumerate(lines):
        s = line.strip()
        if s == _BEGIN:
            if inside:
                raise ValueError(f"{where}: nested {_BEGIN} (line {n})")
            inside = True
        elif s == _END:
            if not inside:
                raise ValueError(f"{where}: {_END} without {_BEGIN} (line {n})")
            inside = False
        elif s.startswith(_STUDENT):
            if version == "student":
                indent = line[: len(line) - len(line.lstrip())]
                out.append(indent + s[len(_STUDENT) :].strip())
        elif inside:
            if version == "solution":
                out.append(line)
        else:
            out.append(line)
    if inside:
        raise ValueError(f"{where}: {_BEGIN} without {_END}")
    return "\n".join(_strip_blank(out))


def _markdown(lines: list[str], where: str) -> str:
    out = []
    for line in lines:
        if line.startswith("# "):
            out.append(line[2:])
        elif line.rstrip() == "#":
            out.append("")
        elif not line.strip():
            continue
        else:
            raise ValueError(f"{where}: markdown lines must start with '#': {line!r}")
    return "\n".join(_strip_blank(out))


def build(source: Path, version: str) -> nbformat.NotebookNode:
    """The notebook of ``version`` ("student" or "solution") built from ``source``."""
    if version not in OUT:
        raise ValueError(f"version must be 'student' or 'solution', got {version!r}")
    stem = source.stem
    cells = []
    for k, (kind, only, lines) in enumerate(_split_cells(source.read_text(encoding="utf-8"))):
        if only and only != version:
            continue
        where = f"{source.name}, cell {k}"
        if kind == "markdown":
            cell = nbformat.v4.new_markdown_cell(_markdown(lines, where))
        else:
            alts = [ln.strip()[len(_ALT) :].strip() for ln in lines if ln.strip().startswith(_ALT)]
            alt = " ".join(alts)
            lines = [ln for ln in lines if not ln.strip().startswith(_ALT)]
            cell = nbformat.v4.new_code_cell(_code_for(lines, version, where))
            if alt:
                cell.metadata["mystnb"] = {"image": {"alt": alt}}
        cell["id"] = f"{stem[:4]}-{k:02d}"
        cells.append(cell)
    nb = nbformat.v4.new_notebook(cells=cells)
    nb.metadata = {
        "kernelspec": {
            "display_name": "Python 3 (ipykernel)",
            "language": "python",
            "name": "python3",
        },
        "language_info": {"name": "python"},
    }
    nbformat.validate(nb)
    return nb


def render(source: Path, version: str) -> str:
    """The exact text written for ``source`` in ``version`` (stable, diffable JSON)."""
    return nbformat.writes(build(source, version)) + "\n"


def target(source: Path, version: str) -> Path:
    return OUT[version] / f"{source.stem}.ipynb"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--check", action="store_true", help="only report notebooks that differ")
    args = parser.parse_args(argv)
    stale = []
    for src in sources():
        for version in OUT:
            path, text = target(src, version), render(src, version)
            old = path.read_text(encoding="utf-8") if path.exists() else None
            if old == text:
                continue
            if args.check:
                stale.append(path)
            else:
                path.parent.mkdir(parents=True, exist_ok=True)
                path.write_text(text, encoding="utf-8")
                print(f"wrote {path.relative_to(ROOT)}")
    for path in stale:
        print(f"out of date: {path.relative_to(ROOT)} (run python tools/build_homework.py)")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
