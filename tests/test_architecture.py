"""The house rules of the package's layout (issue 26, "How we will know"), read from the source.

Every module of ``course_lib`` and ``tools`` is parsed with :mod:`ast` (nothing is imported)
and its imports -- at the top and inside functions -- are walked:

* no import cycle among the modules of ``course_lib`` (a call-time import counts: it is a
  cycle the reader has to keep in mind all the same);
* no private name (``_name``) imported from another module, and no private module imported
  from outside its own package (``course_lib.widgets._core`` is the widgets' business);
* no ``sys.path.insert``/``sys.path.append`` in ``course_lib``, ``tools`` or ``tests``;
* the math parts (``curves``, ``geometry``, ``constructions``, ``sources``, ``validation``)
  import neither matplotlib nor ipywidgets, not even inside a function;
* a module over :data:`MAX_LINES` lines says why in its docstring, in a sentence that starts
  with "Why this module is long:".

Each rule has a test below that builds a small counter-example, so the checks can fail.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
MAX_LINES = 450
WHY_LONG = "Why this module is long:"
MATH_PARTS = ("course_lib.curves", "course_lib.geometry", "course_lib.constructions",
              "course_lib.sources", "course_lib.validation")  # fmt: skip
PICTURE_LIBRARIES = ("matplotlib", "ipywidgets", "ipympl", "mpl_toolkits")


def module_name(path: Path, root: Path = ROOT) -> str:
    parts = list(path.relative_to(root).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def sources(top: str, root: Path = ROOT) -> dict[str, Path]:
    """Dotted module name -> file, for every ``.py`` file under ``root / top``."""
    return {module_name(p, root): p for p in sorted((root / top).rglob("*.py"))}


def imports_of(name: str, path: Path, known: set[str]) -> list[tuple[str, str | None, int]]:
    """``(module, imported name or None, line)`` for every import in the file, relative ones
    resolved; ``from package import submodule`` is an import of the submodule."""
    is_package = path.name == "__init__.py"
    package = name if is_package else name.rpartition(".")[0]
    out = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            out += [(a.name, None, node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - (node.level - 1)]
                module = ".".join([*base, *([node.module] if node.module else [])])
            else:
                module = node.module or ""
            for a in node.names:
                sub = f"{module}.{a.name}"
                out.append((sub, None, node.lineno) if sub in known else (module, a.name, node.lineno))
    return out


def import_graph(modules: dict[str, Path]) -> dict[str, set[str]]:
    known = set(modules)
    graph: dict[str, set[str]] = {m: set() for m in modules}
    for name, path in modules.items():
        for target, _, _ in imports_of(name, path, known):
            if target in known and target != name:
                graph[name].add(target)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in sorted(graph[v]):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def private_imports(modules: dict[str, Path], known: set[str]) -> list[str]:
    """Imports of a ``_name`` from another module, and of a private module from outside the
    package that holds it."""
    bad = []
    for name, path in modules.items():
        for target, imported, line in imports_of(name, path, known):
            where = f"{path.relative_to(ROOT) if path.is_relative_to(ROOT) else path}:{line}"
            if imported is not None and imported.startswith("_") and not imported.startswith("__"):
                if target != name:
                    bad.append(f"{where} imports {imported} from {target}")
            parts = target.split(".")
            for i, part in enumerate(parts):
                if part.startswith("_") and not part.startswith("__"):
                    owner = ".".join(parts[:i])  # the package the private module belongs to
                    if not (name == owner or name.startswith(owner + ".")):
                        bad.append(f"{where} imports the private module {target}")
                    break
    return bad


def path_surgery(files: list[Path], root: Path = ROOT) -> list[str]:
    pattern = re.compile(r"\bsys\.path\.(insert|append)\(")
    return [
        f"{p.relative_to(root)}:{i}"
        for p in files
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if pattern.search(line)
    ]


def picture_imports(
    modules: dict[str, Path], known: set[str], parts: tuple[str, ...] = MATH_PARTS
) -> list[str]:
    bad = []
    for name, path in modules.items():
        if not name.startswith(parts):
            continue
        for target, _, line in imports_of(name, path, known):
            if target.split(".")[0] in PICTURE_LIBRARIES:
                bad.append(f"{name}:{line} imports {target}")
    return bad


def long_without_reason(modules: dict[str, Path]) -> list[str]:
    bad = []
    for name, path in modules.items():
        text = path.read_text(encoding="utf-8")
        n = len(text.splitlines())
        if n > MAX_LINES and WHY_LONG not in (ast.get_docstring(ast.parse(text)) or ""):
            bad.append(f"{name}: {n} lines, no '{WHY_LONG} ...' in its docstring")
    return bad


# ------------------------------------------------------------------ the rules, on the repository
PACKAGE = sources("course_lib")
TOOLS = sources("tools")
EVERYTHING = {**PACKAGE, **TOOLS}


def test_no_import_cycle_in_the_package():
    assert cycles(import_graph(PACKAGE)) == []


def test_no_private_name_crosses_a_module():
    assert private_imports(EVERYTHING, set(EVERYTHING)) == []


def test_no_sys_path_surgery():
    files = [p for top in ("course_lib", "tools", "tests") for p in sorted((ROOT / top).rglob("*.py"))]
    files = [p for p in files if p != Path(__file__)]
    assert path_surgery(files) == []


def test_math_modules_import_no_picture_library():
    assert picture_imports(PACKAGE, set(PACKAGE)) == []


def test_a_long_module_says_why():
    assert long_without_reason(PACKAGE) == []


# ------------------------------------------------------------------ the checks can fail
def write(root: Path, files: dict[str, str]) -> dict[str, Path]:
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text, encoding="utf-8")
    return sources("pkg", root)


def test_a_call_time_cycle_is_found(tmp_path):
    modules = write(tmp_path, {
        "pkg/__init__.py": "",
        "pkg/a.py": "from pkg.b import f\n",
        "pkg/b.py": "def f():\n    from pkg import a\n",
        "pkg/c.py": "from . import a\n",
    })  # fmt: skip
    assert cycles(import_graph(modules)) == [["pkg.a", "pkg.b"]]


def test_private_names_and_modules_are_found(tmp_path):
    modules = write(tmp_path, {
        "pkg/__init__.py": "",
        "pkg/a.py": "def _helper():\n    pass\n",
        "pkg/b.py": "from pkg.a import _helper\n",
        "pkg/sub/__init__.py": "",
        "pkg/sub/_core.py": "X = 1\n",
        "pkg/sub/ok.py": "from pkg.sub._core import X\n",
        "pkg/c.py": "from pkg.sub._core import X\nfrom pkg.sub import _core\n",
    })  # fmt: skip
    bad = private_imports(modules, set(modules))
    assert len(bad) == 3, bad
    assert any("_helper" in b for b in bad) and sum("pkg.sub._core" in b for b in bad) == 2


def test_path_surgery_picture_imports_and_long_modules_are_found(tmp_path):
    modules = write(tmp_path, {
        "pkg/__init__.py": "",
        "pkg/long.py": '"""A module."""\n' + "x = 1\n" * (MAX_LINES + 1),
        "pkg/long_ok.py": f'"""A module.\n\n{WHY_LONG} one idea.\n"""\n' + "x = 1\n" * MAX_LINES,
        "pkg/geometry.py": "def f():\n    import matplotlib.pyplot as plt\n",
        "pkg/plotting.py": "import matplotlib.pyplot as plt\n",
        "tool.py": "import sys\nsys.path.insert(0, '.')\n",
    })  # fmt: skip
    expected = f"pkg.long: {MAX_LINES + 2} lines, no '{WHY_LONG} ...' in its docstring"
    assert long_without_reason(modules) == [expected]
    found = picture_imports(modules, set(modules), parts=("pkg.geometry",))
    assert found == ["pkg.geometry:2 imports matplotlib.pyplot"]
    assert path_surgery([tmp_path / "tool.py"], root=tmp_path) == ["tool.py:2"]
