"""Tamper evidence: a submission's code that reaches into the grader's guards is flagged.

Code in a kernel can always rewrite other code in that kernel (``course_lib/own_work.py``,
README "The rule"), so what Python cannot prevent is made visible: before grading, the
submitted notebook's code cells are read as syntax trees (IPython syntax -- ``!cmd``,
``%magic`` -- translated first, as the kernel translates it) and searched for

* the guard machinery: any use of ``course_lib.homework.own_work`` or ``course_lib.homework.protocol`` (by import,
  alias, ``sys.modules``, ``importlib``, ``getattr``), its guard state (``_ACTIVE``, a frame's
  ``guarded``), a function's ``__code__``/``__globals__``/``__closure__``;
* frames, the garbage collector, ``ctypes``, tracers, ``sys.modules`` and ``__import__``
  rewritten: ``f_locals``, ``sys._getframe``, ``inspect.currentframe``, ``gc.get_referrers``;
* other processes: ``subprocess``, ``multiprocessing``, ``os.system``/``exec*``/``spawn*``/
  ``fork``, ``pty``, a ``ProcessPoolExecutor``, ``!`` and ``%%bash``;
* ``HOMEWORK`` or ``VARIANT`` bound again after their first assignment;
* a ``course_lib`` function or module attribute replaced (monkeypatching);
* code hidden from the scan: ``exec``/``eval``/``compile``/an import of a name computed at run
  time, or a string holding the names above.

A finding flags the submission for the instructor (:data:`FLAG` in the status column and
first in ``summary.md``, with the one-sentence reasons); the student's feedback says only that
the submission was flagged for review.  A *certain* finding -- code that writes into the guard
machinery (``own_work._ACTIVE.clear()``, ``own_work.require = ...``, a frame's ``guarded``, a
function's ``__code__``, ``__import__`` or ``sys.modules`` of ``course_lib``) -- also costs the
questions the guards protect in that homework: they score 0.

Nothing in the homework notebooks or the solutions matches (``tests/test_tamper.py``).
"""

from __future__ import annotations

import ast
from collections.abc import Iterable
from dataclasses import dataclass

from course_lib.homework import own_work

from . import identity

__all__ = ["FLAG", "REVIEW_NOTE", "Finding", "apply", "guarded_questions", "note_typed", "scan", "typed_answers"]

#: the status-column flag (identity.py's flag kinds)
FLAG = identity.TAMPERING

#: what the student's feedback says (nothing about how the scan works)
REVIEW_NOTE = (
    "this submission was flagged for the instructor's review: its code reaches into the "
    "course's grading machinery"
)
ZERO_NOTE = "0: flagged for the instructor's review (the notebook changes the grader's guards)"

_GUARD_MODULES = frozenset({"own_work", "protocol", "_probe"})
# bare names that stand for a guard module even when not reached from ``course_lib``
_GUARD_BARE = frozenset({"own_work", "_probe"})
_FRAME_ATTRS = frozenset(
    {"f_locals", "f_globals", "f_back", "f_builtins", "tb_frame", "gi_frame", "cr_frame",
     "ag_frame", "f_trace"}
)  # fmt: skip
_FRAME_NAMESPACES = frozenset({"f_locals", "f_globals", "f_builtins"})
_FUNCTION_INTERNALS = frozenset({"__code__", "__globals__", "__closure__", "__builtins__"})
_SPAWNING_MODULES = frozenset({"subprocess", "multiprocessing", "pty", "pexpect", "sh"})
_LOW_LEVEL_MODULES = frozenset({"ctypes", "_ctypes", "cffi", "_testcapi", "_xxsubinterpreters"})
_OS_SPAWN = ("system", "popen", "exec", "spawn", "fork", "posix_spawn", "forkpty")
#: names whose use is flagged -> what they reach
_REACHES = {
    **dict.fromkeys(
        ("sys._getframe", "sys._current_frames", "inspect.currentframe", "inspect.stack",
         "inspect.trace", "inspect.getouterframes", "inspect.getinnerframes"),
        "reads the interpreter's frames",
    ),
    **dict.fromkeys(("gc.get_referrers", "gc.get_referents", "gc.get_objects"),
                    "searches the garbage collector's objects"),
    **dict.fromkeys(("sys.settrace", "sys.setprofile", "threading.settrace",
                     "threading.setprofile"), "sets a tracer"),
    "importlib.reload": "reloads a module",
    "sys.executable": "starts Python in another process",
    "concurrent.futures.ProcessPoolExecutor": "starts other processes",
}  # fmt: skip
_FRAME_CALLS = frozenset(_REACHES)
_SHELL_MAGICS = frozenset(
    {"system", "sx", "bash", "sh", "script", "python", "python2", "python3", "pypy", "perl",
     "ruby", "run", "writefile", "file"}
)  # fmt: skip
_HIDDEN_WORDS = ("own_work", "_probe", "homework.protocol", "f_locals", "_getframe", "sys.modules", "__code__",
                 "_ACTIVE", "ctypes", "subprocess")  # fmt: skip
_PROTECTED_NAMES = ("HOMEWORK", "VARIANT")
_MUTATORS = frozenset(
    {"update", "pop", "popitem", "clear", "setdefault", "__setitem__", "__delitem__", "remove",
     "append", "extend", "insert", "discard", "add"}
)  # fmt: skip


@dataclass(frozen=True)
class Finding:
    """One match: the code cell (1-based), a one-sentence reason, and whether it is certain."""

    cell: int
    reason: str
    certain: bool = False

    def __str__(self) -> str:
        return f"code cell {self.cell}: {self.reason}"


def _python(source: str) -> ast.Module | None:
    """The cell as the kernel runs it (IPython syntax translated), or None if it cannot run."""
    try:
        from IPython.core.inputtransformer2 import TransformerManager

        source = TransformerManager().transform_cell(source)
    except Exception:  # no IPython, or a cell IPython cannot translate: parse it as it is
        pass
    try:
        return ast.parse(source)
    except (SyntaxError, ValueError, RecursionError):
        return None  # a cell that does not parse does not run either


def _const_str(node: ast.AST | None) -> str | None:
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    return None


def _const_name(node: ast.AST | None) -> str | None:
    """A constant dotted name (``"course_lib.homework.own_work"``); None for anything else, so no
    student text but identifiers reaches a reason."""
    text = _const_str(node)
    if text and len(text) <= 200 and all(part.isidentifier() for part in text.split(".")):
        return text
    return None


class _Scanner(ast.NodeVisitor):
    def __init__(self) -> None:
        self.aliases: dict[str, str] = {}  # a notebook name -> the dotted name it stands for
        self.findings: list[Finding] = []
        self.cell = 0
        self.first_binding: dict[str, object] = {}
        self.strings: list[str] = []
        self.depth = 0

    # ------------------------------------------------------------------ helpers
    def add(self, reason: str, certain: bool = False) -> None:
        finding = Finding(self.cell, reason, certain)
        if finding not in self.findings:
            self.findings.append(finding)

    def resolve(self, node: ast.AST) -> str | None:
        """The dotted name an expression stands for (``ks.own_work`` -> ``course_lib.
        knot_splines.own_work``), through imports, ``sys.modules[...]``, ``getattr``,
        ``importlib.import_module`` and ``__import__``; None if unknown."""
        if isinstance(node, ast.Name):
            return self.aliases.get(node.id, node.id)
        if isinstance(node, ast.Attribute):
            base = self.resolve(node.value)
            if base is None:
                return None
            return base if node.attr == "__dict__" else f"{base}.{node.attr}"
        if isinstance(node, ast.Subscript):
            base = self.resolve(node.value)
            key = _const_name(node.slice)
            if base in ("sys.modules", "sys.modules.get") and key:
                return key
            if base is not None and key and key.isidentifier():
                return f"{base}.{key}"
            return None
        if isinstance(node, ast.Call):
            func = self.resolve(node.func)
            first = _const_name(node.args[0]) if node.args else None
            if func in ("importlib.import_module", "sys.modules.get") and first:
                return first
            if func == "__import__" and first:
                fromlist = any(k.arg == "fromlist" for k in node.keywords) or len(node.args) > 3
                return first if fromlist else first.split(".")[0]
            if func in ("getattr", "vars") and node.args:
                base = self.resolve(node.args[0])
                name = _const_name(node.args[1]) if len(node.args) > 1 else None
                if base is None:
                    return None
                return f"{base}.{name}" if name else base
        return None

    @staticmethod
    def _guard_path(dotted: str | None) -> bool:
        if not dotted:
            return False
        parts = dotted.split(".")
        return bool(_GUARD_MODULES & set(parts)) and (
            parts[0] == "course_lib" or parts[0] in _GUARD_BARE
        )

    @staticmethod
    def _private_after_guard(dotted: str) -> bool:
        """A private name of the guard modules (``own_work._ACTIVE``): no notebook needs it."""
        parts = dotted.split(".")
        for i, part in enumerate(parts):
            if part in _GUARD_MODULES:
                return any(p.startswith("_") and not p.startswith("__") for p in parts[i + 1 :])
        return False

    def reference(self, dotted: str | None) -> bool:
        """Flag a read of ``dotted``; True if it was flagged."""
        if not dotted:
            return False
        if self._guard_path(dotted):
            self.add(
                f"uses {self._short(dotted)} (the grader's guard machinery)",
                certain=self._private_after_guard(dotted),
            )
        elif dotted in _FRAME_CALLS:
            self.add(f"uses {dotted} ({_REACHES[dotted]})")
        elif dotted.startswith("os.") and dotted[3:].startswith(_OS_SPAWN):
            self.add(f"uses {dotted} (starts other processes)")
        else:
            return False
        return True

    def written(self, target: ast.AST, how: str) -> None:
        """``target`` is assigned, deleted or mutated."""
        inner = target.value if isinstance(target, ast.Subscript) else target
        if isinstance(inner, ast.Attribute) and inner.attr in _FRAME_NAMESPACES:
            self.add(f"{how} a frame's namespace", certain=True)
            return
        dotted = self.resolve(inner)
        if isinstance(target, ast.Attribute):
            if target.attr in _FUNCTION_INTERNALS:
                self.add(f"{how} a function's {target.attr}", certain=True)
                return
            if target.attr == "__import__":
                self.add(f"{how} __import__", certain=True)
                return
            if target.attr in ("gettrace", "getprofile", "settrace", "setprofile", "_getframe"):
                self.add(f"{how} sys.{target.attr}", certain=True)
                return
        if dotted is None:
            return
        if self._guard_path(dotted):
            self.add(f"{how} {self._short(dotted)} (the grader's guard)", certain=True)
        elif dotted == "sys.modules" or dotted.startswith("sys.modules."):
            self.add(f"{how} sys.modules", certain=True)
        elif dotted in ("builtins", "__builtins__") or dotted.startswith(
            ("builtins.", "__builtins__.")
        ):
            self.add(f"{how} builtins ({self._short(dotted)})", certain="__import__" in dotted)
        elif dotted.startswith("course_lib.") and isinstance(
            target, (ast.Attribute, ast.Subscript)
        ):
            self.add(f"{how} {self._short(dotted)} (monkeypatches course_lib)")
        elif set(dotted.split(".")) & _FRAME_ATTRS:
            self.add(f"{how} a frame's namespace", certain=True)

    @staticmethod
    def _short(dotted: str) -> str:
        return dotted if len(dotted) <= 80 else dotted[:77] + "..."

    def binding(self, name: str, value: ast.AST | None, node: ast.AST) -> None:
        if name not in _PROTECTED_NAMES:
            return
        constant = value.value if isinstance(value, ast.Constant) else None
        if name not in self.first_binding and self.depth == 0 and isinstance(constant, str):
            self.first_binding[name] = constant
            return
        if self.first_binding.get(name, object()) == constant and self.depth == 0:
            return  # the same code pasted twice
        self.add(f"binds {name} again after its first assignment")

    # ------------------------------------------------------------------ imports
    def visit_Import(self, node: ast.Import) -> None:
        for a in node.names:
            self.aliases[a.asname or a.name.split(".")[0]] = (
                a.name if a.asname else a.name.split(".")[0]
            )
            self.imported(a.name)
            if a.asname:
                self.binding(a.asname, None, node)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        module = node.module or ""
        self.imported(module)
        for a in node.names:
            full = f"{module}.{a.name}" if module else a.name
            self.aliases[a.asname or a.name] = full
            self.imported(full)
            self.binding(a.asname or a.name, None, node)

    def imported(self, name: str) -> None:
        top = name.split(".")[0]
        if self._guard_path(name):
            self.add(f"imports {name} (the grader's guard machinery)")
        elif top in _SPAWNING_MODULES:
            self.add(f"imports {top} (starts other processes)")
        elif top in _LOW_LEVEL_MODULES:
            self.add(f"imports {top} (writes memory behind Python)")
        elif name == "concurrent.futures.ProcessPoolExecutor":
            self.add("imports ProcessPoolExecutor (starts other processes)")

    # ------------------------------------------------------------------ writes
    def visit_Assign(self, node: ast.Assign) -> None:
        for target in node.targets:
            self.target(target, node.value)
        # a notebook name standing for something (``ow = ks.own_work``)
        if len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
            dotted = self.resolve(node.value)
            if dotted and (dotted.startswith(("course_lib", "sys", "gc", "inspect", "builtins",
                                              "importlib", "os")) or self._guard_path(dotted)):  # fmt: skip
                self.aliases[node.targets[0].id] = dotted
        self.generic_visit(node)

    def visit_AugAssign(self, node: ast.AugAssign) -> None:
        self.target(node.target, None)
        self.generic_visit(node)

    def visit_AnnAssign(self, node: ast.AnnAssign) -> None:
        self.target(node.target, node.value)
        self.generic_visit(node)

    def visit_NamedExpr(self, node: ast.NamedExpr) -> None:
        self.target(node.target, node.value)
        self.generic_visit(node)

    def visit_Delete(self, node: ast.Delete) -> None:
        for target in node.targets:
            if isinstance(target, ast.Name):
                if target.id in _PROTECTED_NAMES:
                    self.add(f"deletes {target.id}")
            else:
                self.written(target, "deletes")
        self.generic_visit(node)

    def target(self, target: ast.AST, value: ast.AST | None) -> None:
        if isinstance(target, ast.Name):
            self.binding(target.id, value, target)
        elif isinstance(target, (ast.Tuple, ast.List)):
            for t in target.elts:
                self.target(t, None)
        elif isinstance(target, ast.Starred):
            self.target(target.value, None)
        elif isinstance(target, ast.Subscript):
            key = _const_str(target.slice)
            if key in _PROTECTED_NAMES:
                self.add(f"binds {key} again through a namespace")
            elif key == "guarded":
                self.add("writes a frame's 'guarded' (the grader's guard state)", certain=True)
            self.written(target, "changes")
        elif isinstance(target, ast.Attribute):
            self.written(target, "replaces")

    def visit_For(self, node: ast.For) -> None:
        self.target(node.target, None)
        self.generic_visit(node)

    visit_AsyncFor = visit_For

    def visit_withitem(self, node: ast.withitem) -> None:
        if node.optional_vars is not None:
            self.target(node.optional_vars, None)
        self.generic_visit(node)

    def visit_Global(self, node: ast.Global) -> None:
        for name in node.names:
            if name in _PROTECTED_NAMES:
                self.add(f"binds {name} again from a function (global)")

    def _scoped(self, node: ast.AST) -> None:
        if getattr(node, "name", None) in _PROTECTED_NAMES:
            self.add(f"binds {node.name} again (a def or class of that name)")
        self.depth += 1
        self.generic_visit(node)
        self.depth -= 1

    visit_FunctionDef = visit_AsyncFunctionDef = visit_ClassDef = visit_Lambda = _scoped

    # ------------------------------------------------------------------ reads and calls
    def visit_Attribute(self, node: ast.Attribute) -> None:
        if node.attr in _FRAME_ATTRS:
            self.add(f"reads a frame's {node.attr}")
        elif node.attr in _FUNCTION_INTERNALS:
            self.add(f"reads a function's {node.attr}")
        elif self.reference(self.resolve(node)):
            return  # one finding for the whole chain (own_work._ACTIVE.clear)
        self.generic_visit(node)

    def visit_Name(self, node: ast.Name) -> None:
        if isinstance(node.ctx, ast.Load) and node.id in self.aliases:
            self.reference(self.aliases[node.id])

    def visit_Call(self, node: ast.Call) -> None:
        func = self.resolve(node.func)
        args = node.args
        if func in ("setattr", "delattr") and args:
            self._attr_call(func, args)
        elif func == "getattr" and len(args) > 1 and _const_name(args[1]) is None:
            base = self.resolve(args[0])
            if base and (base.startswith("course_lib") or base in ("sys", "builtins", "os")):
                self.add(f"getattr on {base} with a name computed at run time")
        elif func in ("exec", "eval", "compile", "__import__", "importlib.import_module"):
            self._code_call(func, args)
        elif isinstance(node.func, ast.Attribute) and node.func.attr in _MUTATORS:
            self._mutator_call(node, args)
        if isinstance(node.func, ast.Attribute) and node.func.attr in (
            "system",
            "getoutput",
            "run_cell_magic",
            "run_line_magic",
        ):
            self._shell_call(node, args)
        self.generic_visit(node)

    def _attr_call(self, func: str, args: list[ast.expr]) -> None:
        """``setattr``/``delattr`` on a guard, a protected name or a function's internals."""
        base = self.resolve(args[0])
        name = _const_name(args[1]) if len(args) > 1 else None
        if name in _PROTECTED_NAMES:
            self.add(f"binds {name} again through {func}")
        elif name in _FUNCTION_INTERNALS:
            self.add(f"{func} on a function's {name}", certain=True)
        elif base is not None:
            fake = ast.Attribute(value=args[0], attr=name or "?", ctx=ast.Store())
            self.written(fake, "replaces" if func == "setattr" else "deletes")
        if name is None:
            self.add(f"{func} with a name computed at run time")

    def _code_call(self, func: str, args: list[ast.expr]) -> None:
        """``exec``/``eval``/``compile``/imports: read constant code, flag computed code."""
        code = _const_str(args[0]) if args else None
        if code is None:
            self.add(f"{func} of code or a name computed at run time")
        elif func in ("exec", "eval", "compile"):
            self.strings.append(code)
        elif _const_name(args[0]):
            self.imported(code)
        else:
            self.add(f"{func} of a name that is not a module's")

    def _mutator_call(self, node: ast.Call, args: list[ast.expr]) -> None:
        """``.update``/``.clear``/... on the guards, ``sys.modules`` or a frame's namespace."""
        owner = self.resolve(node.func.value)
        if (owner and (self._guard_path(owner) or owner.startswith("sys.modules"))) or (
            isinstance(node.func.value, ast.Attribute)
            and node.func.value.attr in _FRAME_NAMESPACES
        ):
            self.written(node.func.value, "changes")
        key = _const_str(args[0]) if args else None
        if key in _PROTECTED_NAMES or any(k.arg in _PROTECTED_NAMES for k in node.keywords):
            self.add(f"binds {key or 'HOMEWORK/VARIANT'} again through a namespace")
        if key == "guarded":
            self.add("writes a frame's 'guarded' (the grader's guard state)", certain=True)

    def _shell_call(self, node: ast.Call, args: list[ast.expr]) -> None:
        """``get_ipython().system(...)`` and the process-starting magics."""
        owner = node.func.value
        if isinstance(owner, ast.Call):  # get_ipython().system(...)
            owner = owner.func
        what = _const_name(args[0]) if args else None
        if (self.resolve(owner) or "").split(".")[-1] == "get_ipython":
            if node.func.attr in ("system", "getoutput"):
                self.add("runs a shell command (!), which starts other processes")
            elif what in _SHELL_MAGICS or what is None:
                self.add(f"runs the %{what} magic, which starts other processes or code")

    def visit_Constant(self, node: ast.Constant) -> None:
        if isinstance(node.value, str):
            if any(word in node.value for word in _HIDDEN_WORDS):
                self.add("holds code of the grader's machinery in a string")
            if node.value == "guarded":
                self.add("names the grader's guard state ('guarded')")


def scan(cells: Iterable[str]) -> list[Finding]:
    """The findings in a notebook's code cells (in order), each with a one-sentence reason."""
    scanner = _Scanner()
    for number, source in enumerate(cells, start=1):
        scanner.cell = number
        todo = [str(source)]
        while todo:  # the cell, then code in a string given to exec/eval/compile
            tree = _python(todo.pop())
            try:
                if tree is not None:
                    scanner.visit(tree)
            except RecursionError:
                scanner.add("is nested too deeply to be read")
            todo += scanner.strings
            scanner.strings = []
    findings = scanner.findings
    # a frame's locals written where the guard state is named: certain
    frames = any("frame's" in f.reason for f in findings)
    named = any("'guarded'" in f.reason for f in findings)
    if frames and named:
        findings = [
            Finding(f.cell, f.reason, True) if "'guarded'" in f.reason else f for f in findings
        ]
    return findings


def guarded_questions(homework: str) -> list[str]:
    """The questions of ``homework`` whose answers the library guards (own_work)."""
    return sorted(
        q
        for table in (own_work.EXERCISES, own_work.VALUE_EXERCISES)
        for q in table
        if q.split(".")[0] == homework
    )


def apply(result, cells: list[str], homework: str, points: dict[str, float]) -> list[Finding]:
    """Scan ``cells`` and record the findings on a runner ``Result``: the flag in its status,
    the reasons in ``review`` (for the instructor), one note for the student; a certain finding
    zeroes the homework's guarded questions.  Returns the findings."""
    findings = scan(cells)
    if not findings:
        return findings
    shown = sorted(findings, key=lambda f: not f.certain)[:5]  # certain ones first
    result.review = [str(f) for f in shown] + (
        [f"and {len(findings) - 5} more"] if len(findings) > 5 else []
    )
    result.status = f"{result.status}; {FLAG}"
    result.run_notes.append(REVIEW_NOTE)
    if any(f.certain for f in findings):
        for q in guarded_questions(homework):
            key = q.split(".", 1)[1]  # the hidden tests' POINTS name it "q7"
            if key in points:
                result.points[key] = 0.0
                result.fractions[key] = 0.0
                result.notes[key] = ZERO_NOTE
    return findings


# ------------------------------------------------------------------ answers typed in
#: significant digits from which a number written in a notebook was not typed from the question
TYPED_DIGITS = 9


def _literal_numbers(node: ast.AST) -> list[float] | None:
    """The numbers of an expression made only of number literals (``-0.41``, ``[1.5, 2]``,
    ``np.array([...])``, ``float(...)``), else None (the expression computes something)."""
    if isinstance(node, ast.Constant) and isinstance(node.value, int | float) and not isinstance(node.value, bool):
        return [float(node.value)]
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub | ast.UAdd):
        return _literal_numbers(node.operand)
    if isinstance(node, ast.List | ast.Tuple):
        parts = [_literal_numbers(e) for e in node.elts]
        return None if any(p is None for p in parts) else [x for p in parts for x in p]
    if isinstance(node, ast.Call) and not node.keywords and len(node.args) == 1:
        name = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
        if name in ("array", "asarray", "float", "float64"):
            return _literal_numbers(node.args[0])
    return None


def _digits(x: float) -> int:
    mantissa = repr(abs(x)).split("e")[0].replace(".", "").lstrip("0").rstrip("0")
    return len(mantissa)


def typed_answers(cells: Iterable[str], answer_names: Iterable[str]) -> list[str]:
    """``answer_q4 = 0.4104456668795813``-like assignments of the value answers
    ``answer_names``: a number of :data:`TYPED_DIGITS` or more significant digits written in the
    notebook, not computed there (where it came from is for the instructor to ask)."""
    wanted, found = set(answer_names), []
    for number, source in enumerate(cells, start=1):
        tree = _python(str(source))
        for node in ast.walk(tree) if tree is not None else ():
            if isinstance(node, ast.Assign):
                targets, value = node.targets, node.value
            elif isinstance(node, ast.AnnAssign) and node.value is not None:
                targets, value = [node.target], node.value
            else:
                continue
            names = [t.id for t in targets if isinstance(t, ast.Name) and t.id in wanted]
            numbers = _literal_numbers(value) if names else None
            if numbers and max(map(_digits, numbers)) >= TYPED_DIGITS:
                found += [f"{name} is a {max(map(_digits, numbers))}-digit number typed in code cell {number}"
                          for name in names]  # fmt: skip
    return found


def note_typed(result, cells: list[str], answer_names: Iterable[str]) -> list[str]:
    """Flag a runner ``Result`` whose value answers are typed in (:func:`typed_answers`): the
    status column and ``summary.md`` (instructor only); the points stand."""
    found = typed_answers(cells, answer_names)
    if found:
        result.status = f"{result.status}; {identity.TYPED_IN}"
        result.private_notes[identity.TYPED_IN] = "; ".join(found)
    return found
