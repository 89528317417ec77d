"""course_lib.lessons: each lecture's one import line brings in exactly what it lists."""

from __future__ import annotations

import ast
import importlib
import json
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
LECTURES = sorted((ROOT / "notebooks").glob("0[1-9]_*.ipynb"))


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_the_lecture_imports_its_own_lessons_module(path):
    cells = [c for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "code"]
    first = ast.parse("".join(cells[0]["source"]))
    star = [n.module for n in first.body if isinstance(n, ast.ImportFrom)
            and any(a.name == "*" for a in n.names)]
    assert star == [f"course_lib.lessons.l{path.name[:2]}"]


@pytest.mark.parametrize("number", [p.name[:2] for p in LECTURES])
def test_every_listed_name_exists_and_nothing_else_is_exported(number):
    module = importlib.import_module(f"course_lib.lessons.l{number}")
    assert module.__all__ == sorted(set(module.__all__), key=module.__all__.index)
    missing = [name for name in module.__all__ if not hasattr(module, name)]
    assert not missing
    namespace: dict = {}
    exec(f"from course_lib.lessons.l{number} import *", namespace)  # what a lecture gets
    assert set(namespace) - {"__builtins__"} == set(module.__all__)


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_every_name_a_lecture_reads_is_defined_somewhere(path):
    """A name read by a cell is imported, or assigned by an earlier cell, or a builtin."""
    import builtins

    cells = [c for c in json.loads(path.read_text())["cells"] if c["cell_type"] == "code"]
    module = importlib.import_module(f"course_lib.lessons.l{path.name[:2]}")
    known = set(module.__all__) | set(dir(builtins)) | {"np", "sp"}
    for cell in cells:
        tree = ast.parse("".join(cell["source"]))
        for node in ast.walk(tree):
            if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
                known.add(node.id)
            elif isinstance(node, ast.FunctionDef):
                known.add(node.name)
            elif isinstance(node, ast.arg):
                known.add(node.arg)
            elif isinstance(node, ast.ExceptHandler) and node.name:
                known.add(node.name)
            elif isinstance(node, (ast.Import, ast.ImportFrom)):
                known |= {(a.asname or a.name).split(".")[0] for a in node.names}
    read = {
        n.id
        for c in cells
        for n in ast.walk(ast.parse("".join(c["source"])))
        if isinstance(n, ast.Name) and isinstance(n.ctx, ast.Load)
    }
    assert read <= known, f"{path.name}: names read but defined nowhere: {read - known}"
