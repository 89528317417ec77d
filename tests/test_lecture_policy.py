"""The measurable rules of a lecture notebook (CONTRIBUTING.md, "Lecture notebooks").

Applies to every ``notebooks/NN_*.ipynb`` except ``00_welcome``.  Static checks only
(json + ast + symtable + tokenize): the whole file runs in well under a second.

The rules are what a student meets, not floors to sit on: code cells a student reads are
short (median at most two lines; the plumbing lives in ``course_lib``), one short import
cell, no markdown cell longer than a page of reading, evidence cells that only check,
prose that speaks to students (authors and years, not "seed 000"; no test paths or
benchmarks outside a closing "For instructors" note), and no answers in the notebook.
Whether a lecture fits a 50-minute class is not measured here: a cell count was, and it
was met by merging cells, which made them longer to read (issue 25).
"""

from __future__ import annotations

import ast
import io
import json
import re
import statistics
import symtable
import tokenize
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = sorted(
    p for p in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb") if not p.name.startswith("00_")
)
IDS = [p.stem for p in NOTEBOOKS]

MIN_PROSE_RATIO = 2.5  # characters of markdown per character of code
MAX_LINE = 88  # characters per code line
MAX_MEDIAN_CODE_LINES = 2  # median lines of the code cells a student reads (not evidence)
MAX_IMPORT_LINES = 4  # the one import cell of a lecture
MAX_MARKDOWN_WORDS = 250  # one markdown cell: about a page of reading
MAX_HELPER_LINES = 5  # body lines of a function defined in a lecture
EVIDENCE_TAG = "evidence"
CHECK_CALLS = ("quiz", "check_choice", "check_value", "check_number", "check_vector", "check")


def _cells(path: Path) -> list[dict]:
    return json.loads(path.read_text())["cells"]


def _src(cell: dict) -> str:
    return "".join(cell["source"])


def _code_cells(path: Path) -> list[dict]:
    return [c for c in _cells(path) if c["cell_type"] == "code"]


def _python(cell: dict) -> str:
    """The cell's source with IPython magics (``%...``, ``!...``) blanked out."""
    return "\n".join(
        "" if line.lstrip().startswith(("%", "!")) else line for line in _src(cell).splitlines()
    )


def _tags(cell: dict) -> list[str]:
    return cell.get("metadata", {}).get("tags", [])


def _lecture_number(path: Path) -> int:
    return int(path.name[:2])


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_prose_outweighs_code(path):
    cells = _cells(path)
    prose = sum(len(_src(c)) for c in cells if c["cell_type"] == "markdown")
    code = sum(len(_src(c)) for c in cells if c["cell_type"] == "code")
    assert prose >= MIN_PROSE_RATIO * code, (
        f"{path.name}: prose:code = {prose / code:.2f} < {MIN_PROSE_RATIO} (characters); "
        "explain more or move code into course_lib"
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_code_lines_are_short(path):
    long = [
        (c["id"], len(line))
        for c in _code_cells(path)
        for line in _src(c).splitlines()
        if len(line) > MAX_LINE
    ]
    assert not long, f"{path.name}: code lines longer than {MAX_LINE} characters: {long}"


def _lines(cell: dict) -> int:
    return len([line for line in _src(cell).strip().splitlines() if line.strip()])


def _is_evidence(cell: dict) -> bool:
    return EVIDENCE_TAG in _tags(cell)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_code_cells_a_student_reads_are_short(path):
    read = [_lines(c) for c in _code_cells(path) if not _is_evidence(c)]
    median = statistics.median(read)
    long = [(c["id"], _lines(c)) for c in _code_cells(path) if not _is_evidence(c)
            and _lines(c) > 3 * MAX_MEDIAN_CODE_LINES]
    assert median <= MAX_MEDIAN_CODE_LINES, (
        f"{path.name}: the median code cell has {median} lines > {MAX_MEDIAN_CODE_LINES}; "
        f"move plumbing into course_lib or split the cell (the longest: {long})"
    )


def _imports(cell: dict) -> bool:
    return any(isinstance(n, (ast.Import, ast.ImportFrom)) for n in ast.walk(ast.parse(_python(cell))))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_one_short_import_cell(path):
    code = _code_cells(path)
    importing = [c["id"] for c in code if _imports(c)]
    assert importing == [code[0]["id"]], (
        f"{path.name}: imports belong in the first code cell only; found in {importing}"
    )
    assert _lines(code[0]) <= MAX_IMPORT_LINES, (
        f"{path.name}: the import cell has {_lines(code[0])} lines > {MAX_IMPORT_LINES}; "
        "import from a course_lib module that gathers the lecture's tools"
    )


def _words(text: str) -> int:
    return len(re.findall(r"\S+", text))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_no_markdown_cell_is_a_wall_of_text(path):
    long = [
        (c["id"], _words(_src(c)))
        for c in _cells(path)
        if c["cell_type"] == "markdown" and _words(_src(c)) > MAX_MARKDOWN_WORDS
    ]
    assert not long, f"{path.name}: markdown cells over {MAX_MARKDOWN_WORDS} words: {long}"


FOR_AUTHORS = re.compile(
    r"\bseeds?\s*0\d\d\b|\bseed\b|tests?/|\bbenchmarks?\b|collapsed cell|hidden cell|evidence cell",
    re.IGNORECASE,
)


def _student_prose(cell: dict) -> str:
    """A markdown cell without its closing "*For instructors:*" paragraphs."""
    paragraphs = re.split(r"\n\s*\n", _src(cell))
    return "\n\n".join(p for p in paragraphs if not p.lstrip().startswith("*For instructors"))


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_prose_is_written_for_students(path):
    found = [
        (c["id"], m.group(0))
        for c in _cells(path)
        if c["cell_type"] == "markdown"
        for m in FOR_AUTHORS.finditer(_student_prose(c))
    ]
    assert not found, (
        f"{path.name}: words for the course's authors in a lecture's prose: {found}; cite "
        "sources by author and year (Barsky & DeRose 1988), keep test paths and benchmarks "
        "in a closing '*For instructors:*' note"
    )


def _bound(src: str) -> set[str]:
    table = symtable.symtable(src, "<cell>", "exec")
    return {s.get_name() for s in table.get_symbols() if s.is_assigned() or s.is_imported()}


def _free(src: str) -> set[str]:
    """Names a cell reads from the notebook's namespace (at any depth)."""
    top = symtable.symtable(src, "<cell>", "exec")
    out = set()

    def walk(table):
        for s in table.get_symbols():
            if s.is_referenced() and s.is_global():
                out.add(s.get_name())
        for child in table.get_children():
            walk(child)

    for child in top.get_children():  # functions, lambdas, comprehensions
        walk(child)
    return out | {s.get_name() for s in top.get_symbols() if s.is_referenced()} - _bound(src)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_evidence_cells_define_nothing_later_cells_use(path):
    """An evidence cell only checks: hide it (or drop it) and the lecture still runs."""
    code = _code_cells(path)
    bad = []
    for k, cell in enumerate(code):
        if not _is_evidence(cell):
            continue
        alive = _bound(_python(cell))
        for later in code[k + 1 :]:
            src = _python(later)
            bad += [(cell["id"], name, later["id"]) for name in sorted(alive & _free(src))]
            alive -= _bound(src)
    assert not bad, f"{path.name}: (evidence cell, name, later cell that uses it): {bad}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_no_semicolon_chains(path):
    """``a; b`` is two statements on one line; only a final ``;`` (hide the output) is allowed."""
    bad = []
    for c in _code_cells(path):
        src = _python(c).rstrip()
        toks = list(tokenize.generate_tokens(io.StringIO(src + "\n").readline))
        semis = [t for t in toks if t.type == tokenize.OP and t.string == ";"]
        final = len(semis) == 1 and semis[0].end == (
            len(src.splitlines()),
            len(src.splitlines()[-1]),
        )
        if semis and not final:
            bad.append(c["id"])
    assert not bad, f"{path.name}: ';' between statements in cells {bad}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_no_side_effect_comprehensions_or_long_helpers(path):
    problems = []
    for c in _code_cells(path):
        tree = ast.parse(_python(c))
        comps = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
        for k, stmt in enumerate(tree.body):
            shown = k == len(tree.body) - 1 and not _src(c).rstrip().endswith(";")
            if isinstance(stmt, ast.Expr) and isinstance(stmt.value, comps) and not shown:
                problems.append(f"{c['id']}: comprehension used as a statement")
        for node in ast.walk(tree):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                body = node.end_lineno - node.lineno
                if body > MAX_HELPER_LINES:
                    problems.append(
                        f"{c['id']}: {node.name} has {body} lines; move it to course_lib"
                    )
    assert not problems, f"{path.name}: " + "; ".join(problems)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_assert_only_cells_are_tagged_evidence_and_collapsed(path):
    bad = []
    for c in _code_cells(path):
        body = ast.parse(_python(c)).body
        assert_only = bool(body) and all(isinstance(s, ast.Assert) for s in body)
        tagged = EVIDENCE_TAG in _tags(c)
        hidden = c.get("metadata", {}).get("jupyter", {}).get("source_hidden") is True
        if (assert_only and not tagged) or (tagged and not hidden):
            bad.append(c["id"])
    assert not bad, (
        f"{path.name}: cells {bad} must carry the tag {EVIDENCE_TAG!r} and "
        "metadata jupyter.source_hidden = true (assert-only cells, CONTRIBUTING.md)"
    )


def _literal_only(node: ast.AST) -> bool:
    return all(
        isinstance(n, (ast.Constant, ast.BinOp, ast.UnaryOp, ast.operator, ast.unaryop))
        for n in ast.walk(node)
    )


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_no_answers_in_the_lecture(path):
    """Checks compare with a hash or a value computed in course_lib.homework.checks, never a literal."""
    problems = []
    cells = _cells(path)
    for k, c in enumerate(cells):
        if c["cell_type"] != "code":
            continue
        tree = ast.parse(_python(c))
        calls = [
            n
            for n in ast.walk(tree)
            if isinstance(n, ast.Call) and getattr(n.func, "id", None) in CHECK_CALLS
        ]
        for call in calls:
            if call.func.id == "check_value":
                problems.append(f"{c['id']}: check_value takes the answer from the notebook")
            for kw in call.keywords:
                if kw.arg == "expected" and _literal_only(kw.value):
                    problems.append(f"{c['id']}: literal expected value")
        nxt = cells[k + 1] if k + 1 < len(cells) else None
        if calls and nxt and nxt["cell_type"] == "markdown":
            first = _src(nxt).lstrip()
            if not (first.startswith("#") or first.startswith("**Q")):
                problems.append(f"{nxt['id']}: prose right after a check (an answer?)")
    assert not problems, f"{path.name}: " + "; ".join(problems)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_summary_references_and_links(path):
    cells = _cells(path)
    headings = [
        line.strip()
        for c in cells
        if c["cell_type"] == "markdown"
        for line in _src(c).splitlines()
        if line.startswith("## ")
    ]
    assert "## Summary" in headings and "## References" in headings, (
        f"{path.name}: needs '## Summary' and '## References' sections"
    )
    assert headings.index("## Summary") < headings.index("## References")
    first, last = _src(cells[0]), _src(cells[-1])
    n = _lecture_number(path)
    names = {_lecture_number(p): p.name for p in NOTEBOOKS}
    assert "00_welcome.ipynb" in first
    if n - 1 in names:
        assert f"({names[n - 1]})" in first, (
            f"{path.name}: first cell must link the previous lecture"
        )
    if n + 1 in names:
        assert f"({names[n + 1]})" in last, f"{path.name}: last cell must link the next lecture"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=IDS)
def test_one_notation_and_static_figures(path):
    cells = _cells(path)
    prose = "\n".join(_src(c) for c in cells if c["cell_type"] == "markdown")
    code = "\n".join(_src(c) for c in cells if c["cell_type"] == "code")
    assert not re.search(r"\s--\s", prose), f"{path.name}: write a dash as '—', not '--'"
    assert "\\mathbf" not in prose, (
        f"{path.name}: points and vectors are plain letters (q, r, Q, T), not \\mathbf"
    )
    assert "%matplotlib widget" not in code, (
        f"{path.name}: static figures only; demos make their own interactive canvases"
    )
    positive = [
        c["id"]
        for c in _code_cells(path)
        for n in ast.walk(ast.parse(_python(c)))
        if isinstance(n, ast.Call)
        and getattr(n.func, "attr", None) in ("symbols", "Symbol")
        and any(k.arg == "positive" for k in n.keywords)
        and n.args
        and re.search(r"beta[2-9]|β[2-9]", str(getattr(n.args[0], "value", "")))
    ]
    assert not positive, f"{path.name}: only β1 is positive; β2, β3, ... are real ({positive})"


def test_every_lecture_is_measured_and_numbered_without_gaps():
    """The rules above run on every lecture, and the previous/next link check has a neighbour
    to look for: lectures are numbered 01, 02, ... without a gap (a split renumbers them)."""
    numbers = [_lecture_number(p) for p in NOTEBOOKS]
    assert numbers == list(range(1, len(numbers) + 1)), numbers
    assert len(IDS) == len(set(p.name[:2] for p in NOTEBOOKS))
