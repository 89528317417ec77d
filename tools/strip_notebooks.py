"""Strip outputs, execution counts and volatile metadata from the course's notebooks.

Notebooks are committed without outputs so that diffs show only what an author wrote;
nbval re-executes them in the test suite.  Usage::

    .venv/bin/python tools/strip_notebooks.py            # strip notebooks/ exercises/ solutions/
    .venv/bin/python tools/strip_notebooks.py --check    # exit 1 if any notebook has outputs
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]
FOLDERS = ("notebooks", "exercises", "solutions")
KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}


def course_notebooks() -> list[Path]:
    return sorted(
        p
        for f in FOLDERS
        for p in (ROOT / f).rglob("*.ipynb")
        if ".ipynb_checkpoints" not in p.parts
    )


def stripped(nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
    for cell in nb.cells:
        if cell.cell_type == "code":
            cell.outputs = []
            cell.execution_count = None
        cell.metadata.pop("execution", None)
        cell.metadata.pop("collapsed", None)
        cell.metadata.pop("scrolled", None)
    nb.metadata = {
        "kernelspec": KERNELSPEC,
        "language_info": {"name": "python"},
    }
    return nb


def is_stripped(path: Path) -> bool:
    nb = nbformat.read(path, as_version=4)
    return nbformat.writes(stripped(nbformat.read(path, as_version=4))) == nbformat.writes(nb)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--check", action="store_true", help="only report notebooks that need stripping"
    )
    args = parser.parse_args(argv)
    dirty = []
    for path in course_notebooks():
        if args.check:
            if not is_stripped(path):
                dirty.append(path)
        else:
            nb = stripped(nbformat.read(path, as_version=4))
            nbformat.write(nb, path)
    for path in dirty:
        print(f"needs stripping: {path.relative_to(ROOT)}")
    return 1 if dirty else 0


if __name__ == "__main__":
    sys.exit(main())
