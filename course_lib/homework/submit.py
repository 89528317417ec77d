"""Hand in a homework notebook: run it fresh, report what failed, write one submission file.

From the last cell of a homework notebook::

    from course_lib.homework.submit import submit
    submit("hw01_reparametrization.ipynb", student="s1234567")

or from a shell: ``make submit HW=hw01 STUDENT=s1234567``.  The notebook is executed top to
bottom in a fresh kernel (what the grader will do) -- except cells that call ``submit(...)``
themselves, which are not run then and are commented out in the submission file (and
``submit()`` does nothing while a submission is being made: ``COURSE_SUBMITTING`` is set), so
handing in from a cell can recurse neither here nor in the grader.  The cells that
raised are listed, the checks are run once more ("5 of 7 checks pass; q3 not answered yet";
an empty ``VARIANT`` in a homework with per-student variants is named), and
``submissions/<homework>-<student>.ipynb`` is written: the executed notebook with a small
manifest in its metadata (``course_submission``: student id, homework, time, sha256 of the
notebook without the manifest).  Upload that file.  The grader reads the manifest when present;
the checks in the notebook stay feedback, the grade comes from the grader.
"""

from __future__ import annotations

import copy
import hashlib
import json
import os
import re
import sys
import tempfile
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

__all__ = ["Submission", "manifest_of", "notebook_digest", "submit"]

MANIFEST_KEY = "course_submission"
#: set while submit() runs a notebook: a submit() inside it does nothing
SUBMITTING_ENV = "COURSE_SUBMITTING"
_CALLS_SUBMIT = re.compile(r"^[^#\n]*\bsubmit\s*\(", re.M)
_MARK = "<<course-submit-checks>>"
SUBMIT_CELL_NOTE = "# (handed in from this cell; commented out in the submission)\n"
_CHECKS_CELL = """\
import json as _submit_json
_submit_out = {}
try:
    from course_lib.homework.checks import check_all as _submit_check_all
    _submit_out["verdicts"] = [[v.question, v.status] for v in _submit_check_all(globals(), %r).verdicts]
except Exception as _submit_exc:
    _submit_out["error"] = type(_submit_exc).__name__
_submit_out["variant"] = globals().get("VARIANT")
try:
    from course_lib.homework import variants as _submit_variants
    _submit_out["has_variants"] = %r in _submit_variants.generators()
except Exception:
    _submit_out["has_variants"] = False
print(%r + _submit_json.dumps(_submit_out))
"""
_ID = re.compile(r"^[A-Za-z0-9][A-Za-z0-9._@-]{0,63}$")


def notebook_digest(nb: dict) -> str:
    """sha256 of a notebook's JSON without its submission manifest (canonical key order)."""
    data = copy.deepcopy(dict(nb))
    data.setdefault("metadata", {})
    data["metadata"] = {k: v for k, v in dict(data["metadata"]).items() if k != MANIFEST_KEY}
    text = json.dumps(data, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    return hashlib.sha256(text.encode("utf-8")).hexdigest()


def manifest_of(nb: dict) -> dict | None:
    """The manifest of a submitted notebook, validated, or None (``tampered`` if it changed)."""
    raw = dict(nb.get("metadata", {})).get(MANIFEST_KEY)
    if not isinstance(raw, dict):
        return None
    student, homework, when, digest = (
        raw.get(k) for k in ("student", "homework", "time", "sha256")
    )
    if not (
        isinstance(student, str)
        and _ID.match(student)
        and isinstance(homework, str)
        and isinstance(when, str)
        and isinstance(digest, str)
    ):
        return None
    try:
        parsed = datetime.fromisoformat(when)
    except ValueError:
        return None
    if parsed.tzinfo is None:
        parsed = parsed.replace(tzinfo=timezone.utc)
    return {
        "student": student,
        "homework": homework[:40],
        "time": parsed,
        "tampered": digest != notebook_digest(nb),
    }


def ordinal(n: int) -> str:
    """``1st``, ``2nd``, ``3rd``, ``11th``, ``21st`` ..."""
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def describe_cell(code_number: int, position: int, source: str) -> str:
    """A code cell as a student finds it in JupyterLab: ``code cell 14 (the 21st cell of the
    notebook, starting `assert ...`)``; ``code_number`` and ``position`` count from 1."""
    first = next((line.strip() for line in source.splitlines() if line.strip()), "")
    if len(first) > 60:
        first = first[:57] + "..."
    start = f", starting `{first}`" if first else ""
    return f"code cell {code_number} (the {ordinal(position)} cell of the notebook{start})"


def error_text(ename: object, evalue: object, limit: int = 200) -> str:
    """``AssertionError: message``, or just ``AssertionError`` when there is no message."""
    value = str(evalue or "").strip()[:limit]
    return f"{ename or 'Error'}: {value}" if value else str(ename or "Error")


#: a log line of the kernel's own start-up that is no business of a student's (ipykernel >= 7)
_KERNEL_NOISE = ("Kernel is running over TCP without encryption",)


def _echo_kernel_log(data: bytes) -> None:
    """The hand-in kernel's stderr, without the start-up warning about TCP transport."""
    text = data.decode("utf-8", "replace")
    kept = [line for line in text.splitlines() if line.strip() and not any(n in line for n in _KERNEL_NOISE)]
    if kept:
        print("\n".join(kept), file=sys.stderr)


@dataclass(repr=False)
class Submission:
    path: Path | None
    student: str
    homework: str
    failed_cells: list[str] = field(default_factory=list)
    #: what the checks said in the fresh run: "5 of 7 checks pass; q3 not answered yet; ..."
    checked: str = ""
    skipped: bool = False  # submit() was called while a submission was being made
    #: submit() printed the summary already (a notebook cell does not show it twice)
    printed: bool = field(default=False, compare=False)

    def __repr__(self) -> str:
        return str(self)

    def _ipython_display_(self) -> None:
        if self.printed:  # submit() printed it in this cell already
            return
        from IPython.display import Markdown, display

        display(Markdown(self._repr_markdown_()))

    def _repr_markdown_(self) -> str:
        if self.skipped:
            return "submit() is not run while the notebook is being submitted (no recursion)."
        head = f"**Submission written:** `{self.path}` ({self.homework}, student {self.student})."
        if self.checked:
            head += f"\n\n**Checked:** {self.checked}."
        if not self.failed_cells:
            return head + "\n\nEvery cell ran without an error in a fresh kernel. Upload that file."
        items = "\n".join(f"- {c}" for c in self.failed_cells)
        return (
            head + f"\n\n**{len(self.failed_cells)} cell(s) raised an error** in a fresh "
            f"kernel — the grader will see the same:\n{items}\n\nFix them and submit again, "
            "or upload as is."
        )

    def __str__(self) -> str:
        return self._repr_markdown_().replace("**", "").replace("`", "")


def _homework_of(nb: dict, path: Path) -> str:
    for cell in nb.get("cells", []):
        src = "".join(cell.get("source", "")) if cell.get("cell_type") == "code" else ""
        m = re.search(r"^HOMEWORK\s*=\s*[\"'](hw\d+)[\"']", src, re.M)
        if m:
            return m.group(1)
    m = re.match(r"(hw\d+)", path.name)
    if m:
        return m.group(1)
    raise ValueError(f"notebook {path}: cannot tell which homework it is (no HOMEWORK = 'hwNN')")


def submit(
    notebook: str | os.PathLike,
    student: str | None = None,
    *,
    out_dir: str | os.PathLike | None = None,
    timeout: float = 120,
) -> Submission:
    """Run ``notebook`` in a fresh kernel and write its submission file.

    Parameters
    ----------
    notebook : path of the homework notebook (save it first: unsaved edits are not seen).
    student : your student id (letters, digits, ``. _ @ -``); defaults to the environment
        variable ``COURSE_STUDENT_ID``.
    out_dir : where to write; default ``submissions/`` next to the notebook's folder.
    timeout : seconds per cell.
    """
    import nbformat
    from nbclient import NotebookClient

    path = Path(notebook).absolute()  # "submissions/" next to its folder, from any cwd
    if not path.is_file():
        raise ValueError(f"notebook must be an existing .ipynb file; {path} is not")
    student = student if student is not None else os.environ.get("COURSE_STUDENT_ID", "")
    if not isinstance(student, str) or not _ID.match(student):
        raise ValueError(
            "student must be your student id (1-64 letters, digits, '.', '_', '@', "
            f"'-'; e.g. submit(..., student='s1234567')); got {student!r}"
        )
    if os.environ.get(SUBMITTING_ENV):
        return Submission(None, student, "", skipped=True)
    nb = nbformat.read(path, as_version=4)
    homework = _homework_of(nb, path)
    nb.metadata.pop(MANIFEST_KEY, None)
    originals = {}
    for k, cell in enumerate(nb.cells):  # a cell that hands in is not run while handing in
        if cell.cell_type == "code" and _CALLS_SUBMIT.search(cell.source):
            originals[k] = cell.source
            cell.source = "# (this cell calls submit(): not run while submitting)"
    nb.cells.append(nbformat.v4.new_code_cell(_CHECKS_CELL % (homework, homework, _MARK)))
    client = NotebookClient(
        nb,
        timeout=timeout,
        allow_errors=True,
        kernel_name="python3",
        resources={"metadata": {"path": str(path.parent)}},
    )
    before = os.environ.get(SUBMITTING_ENV)
    os.environ[SUBMITTING_ENV] = "1"  # the kernel inherits it: a nested submit() does nothing
    try:
        with tempfile.TemporaryFile() as log:  # the kernel's own start-up log
            try:
                client.execute(stderr=log)
            finally:
                log.seek(0)
                _echo_kernel_log(log.read())
    finally:
        if before is None:
            os.environ.pop(SUBMITTING_ENV, None)
        else:
            os.environ[SUBMITTING_ENV] = before
    checked = _checked(nb.cells.pop(), homework)
    for k, source in originals.items():  # kept, commented out: the grader must not run it
        nb.cells[k].source = SUBMIT_CELL_NOTE + "\n".join(f"# {line}" for line in source.splitlines())
        nb.cells[k].outputs = []
        nb.cells[k].execution_count = None
    failed = []
    number = 0
    for position, cell in enumerate(nb.cells, start=1):
        if cell.cell_type != "code":
            continue
        number += 1
        for out in cell.get("outputs", []):
            if out.get("output_type") == "error":
                where = describe_cell(number, position, cell.source)
                failed.append(f"{where}: {error_text(out.get('ename'), out.get('evalue'), 120)}")
                break
    nb.metadata[MANIFEST_KEY] = {
        "student": student,
        "homework": homework,
        "time": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "sha256": "",
    }
    nb.metadata[MANIFEST_KEY]["sha256"] = notebook_digest(nb)
    target_dir = Path(out_dir) if out_dir is not None else path.parent.parent / "submissions"
    target_dir.mkdir(parents=True, exist_ok=True)
    target = target_dir / f"{homework}-{student}.ipynb"
    nbformat.write(nb, target)
    result = Submission(target, student, homework, failed, checked)
    print(result)  # the same summary from a notebook cell as from `make submit`
    result.printed = True
    return result


def _checked(cell, homework: str) -> str:
    """One line from the checks cell's output: how many pass, what is not answered, VARIANT."""
    data = None
    for out in cell.get("outputs", []):
        for line in str(out.get("text", "")).splitlines():
            if line.startswith(_MARK):
                try:
                    data = json.loads(line[len(_MARK):])
                except ValueError:
                    data = None
    if not isinstance(data, dict) or "verdicts" not in data:
        return "the checks could not be run in the fresh kernel"
    verdicts = [(str(q).removeprefix(f"{homework}."), status) for q, status in data["verdicts"]]
    passed = sum(1 for _, status in verdicts if status == "passed")
    parts = [f"{passed} of {len(verdicts)} checks pass"]
    todo = [q for q, status in verdicts if status == "not answered"]
    wrong = [q for q, status in verdicts if status == "failed"]
    unchecked = [q for q, status in verdicts if status == "not checked here"]
    if todo:
        parts.append(", ".join(todo) + " not answered yet")
    if wrong:
        parts.append(", ".join(wrong) + " ✗")
    if unchecked:
        parts.append(", ".join(unchecked) + " ? (no answer key for your data here: the grader checks them)")
    variant = data.get("variant")
    if data.get("has_variants") and isinstance(variant, str) and not variant.strip():
        parts.append(
            f"VARIANT is empty but {homework} has per-student variants: if your course hands out "
            "variant codes, paste yours (you are graded on your own data)"
        )
    return "; ".join(parts)


def find_homework(name: str, folder: str | os.PathLike = "exercises") -> Path:
    """The notebook ``name`` names: a path, or a homework (``hw3``, ``hw03``, ``3``) in ``folder``."""
    if name.endswith(".ipynb") or os.sep in name:
        return Path(name)
    m = re.fullmatch(r"(?:hw)?0*(\d{1,2})", name.strip().lower())
    if m is None:
        raise ValueError(f"HW must name a homework, e.g. HW=hw01 (or hw1, 1); got {name!r}")
    hw = f"hw{int(m.group(1)):02d}"
    hits = sorted(Path(folder).glob(f"{hw}_*.ipynb"))
    if not hits:
        known = ", ".join(sorted(p.name.split("_")[0] for p in Path(folder).glob("hw*_*.ipynb")))
        raise ValueError(f"HW={name}: no {hw} notebook in {folder}/ (there: {known or 'none'})")
    return hits[0]


def main(argv: list[str] | None = None) -> int:
    """``python -m course_lib.homework.submit NOTEBOOK|HW --student ID`` (what ``make submit`` runs)."""
    import argparse

    p = argparse.ArgumentParser(description="Run a homework notebook fresh and write its submission.")
    p.add_argument("notebook", help="the notebook, or the homework: hw01, hw1, 1")
    p.add_argument("--student", default=None, help="your student id (or COURSE_STUDENT_ID)")
    p.add_argument("--out-dir", default=None)
    args = p.parse_args(argv)
    try:
        result = submit(find_homework(args.notebook), args.student, out_dir=args.out_dir)
    except ValueError as exc:
        print(f"submit: {exc}")
        return 2
    return 0 if result.path is not None else 1


if __name__ == "__main__":
    raise SystemExit(main())
