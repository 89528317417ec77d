"""Grade a folder of submitted homework notebooks against hidden tests.

Usage (instructors)::

    python tools/grade.py --tests solutions/hidden_tests/hw01.py \\
        --submissions submissions/hw01 --out grades/hw01 [--jobs 2]

writes ``grades/hw01/scores.csv`` (one row per student: points per question, total) and
``grades/hw01/feedback/<student>.md`` (points, the reason for each lost point, notes on the
run).  Every ``*.ipynb`` under ``--submissions`` is one submission; the student is its path
relative to that folder, without ``.ipynb`` (``alice.ipynb`` -> ``alice``).

How a submission is run
-----------------------
Each submission is copied to a fresh temporary folder and executed there, cell by cell, in a
fresh kernel of the current Python environment (nbclient; the submitted file is only read,
never modified).  Errors in a cell do not stop the run.  Then the hidden tests run in the same
kernel, one question per cell, each with its own time limit.  A cell that runs longer than
``--cell-timeout`` (an endless loop) or kills its kernel is skipped: the kernel is killed and
the notebook is run again in a new kernel without that cell, so the student keeps the points
earned elsewhere.  ``--time-limit`` bounds the whole submission.  A file that is not a valid
notebook scores zero with a note.  Nothing here needs Docker or the network.

Hidden tests
------------
A hidden test file is plain Python (not collected by pytest: do not name it ``test_*.py``)::

    HOMEWORK = "hw01"
    POINTS = {"q1": 2, "q2": 3}          # questions in report order, with their points

    def q1(ns):                           # ns: the notebook's global namespace
        T = ns["answer_q1"]               # a missing name is reported as "not defined"
        assert ..., "message for the student"
        # return None for full points, or a fraction in [0, 1] for partial credit,
        # or (fraction, "message")

Hidden tests must compute their expected values from first principles (numpy, closed
forms), not with the code the solution notebook calls.

Why nbclient and not otter-grader or nbgrader: both take over the course layout and need
their own notebook metadata formats; ``otter grade`` runs submissions in Docker and nbgrader
needs a database and its course directory structure.  Here one small script grades plain
notebooks offline, with the same kernel machinery the test suite already uses.
"""

from __future__ import annotations

import argparse
import csv
import json
import os
import runpy
import secrets
import shutil
import sys
import tempfile
import time
import uuid
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

DEFAULT_CELL_TIMEOUT = 60.0
DEFAULT_TIME_LIMIT = 300.0
DEFAULT_QUESTION_TIMEOUT = 20.0
MAX_ATTEMPTS = 6

# Code run inside the student's kernel after the notebook: it loads the hidden tests from an
# embedded string (they are never written next to the submission) and runs one question per
# call, printing a JSON line tagged with a per-run random marker.
_SETUP = r'''
def __cl_grader_setup(source, marker, limit):
    import json, signal, sys, types

    class _Timeout(BaseException):
        pass

    class MissingAnswer(Exception):
        pass

    class NotAnswered(Exception):
        pass

    class _Namespace(dict):
        def __missing__(self, key):
            raise MissingAnswer(key)

        def __getitem__(self, key):
            value = dict.__getitem__(self, key)
            if value is Ellipsis:
                raise NotAnswered(key)
            return value

    module = types.ModuleType("hidden_tests")
    exec(compile(source, "hidden_tests", "exec"), module.__dict__)

    def _alarm(signum, frame):
        raise _Timeout

    def run(qid, namespace):
        fraction, note = 0.0, ""
        old = signal.signal(signal.SIGALRM, _alarm)
        signal.setitimer(signal.ITIMER_REAL, limit)
        try:
            result = getattr(module, qid)(_Namespace(namespace))
            if result is None:
                fraction = 1.0
            elif isinstance(result, tuple):
                fraction, note = float(result[0]), str(result[1])
            else:
                fraction = float(result)
        except _Timeout:
            note = f"the test did not finish within {limit:g} s (an endless loop in your code?)"
        except MissingAnswer as exc:
            note = (f"`{exc.args[0]}` is not defined in the notebook "
                    "(deleted, renamed, or its cell was not run / failed)")
        except NotAnswered as exc:
            note = f"not answered (`{exc.args[0]}` is still ...)"
        except AssertionError as exc:
            note = str(exc) or "wrong answer"
        except NotImplementedError:
            note = "not answered (the function still raises NotImplementedError)"
        except RecursionError:
            note = "RecursionError: your code recursed without end"
        except Exception as exc:
            note = f"{type(exc).__name__}: {exc}"
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, old)
        fraction = min(max(fraction, 0.0), 1.0) if fraction == fraction else 0.0
        sys.stdout.write(marker + json.dumps({"q": qid, "fraction": fraction, "note": note[:500]}) + "\n")

    return run
'''


class _WallLimit(Exception):
    """The overall time limit of a submission was reached between two cells."""


@dataclass
class HiddenTests:
    path: Path
    homework: str
    points: dict[str, float]
    source: str

    @classmethod
    def load(cls, path: Path) -> HiddenTests:
        source = path.read_text(encoding="utf-8")
        ns = runpy.run_path(str(path))
        points = ns.get("POINTS")
        if not isinstance(points, dict) or not points:
            raise SystemExit(f"{path}: POINTS must be a non-empty dict question -> points")
        missing = [q for q in points if not callable(ns.get(q))]
        if missing:
            raise SystemExit(f"{path}: no test function for {missing}")
        return cls(path, str(ns.get("HOMEWORK", path.stem)), dict(points), source)

    @property
    def max_points(self) -> float:
        return float(sum(self.points.values()))


@dataclass
class Result:
    student: str
    points: dict[str, float]
    notes: dict[str, str]
    run_notes: list[str] = field(default_factory=list)
    status: str = "ok"
    seconds: float = 0.0

    @property
    def total(self) -> float:
        return round(sum(self.points.values()), 2)


def _client_class():
    """A NotebookClient whose kernels run in the Python environment running this script.

    The client creates (and therefore owns, kills and cleans up) its kernel manager.
    """
    import ipykernel.kernelspec
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import AsyncKernelManager
    from nbclient import NotebookClient

    class _CurrentEnv(KernelSpecManager):
        def get_kernel_spec(self, kernel_name):
            return self.kernel_spec_class(
                resource_dir=ipykernel.kernelspec.RESOURCES, **ipykernel.kernelspec.get_kernel_dict()
            )

    class _Client(NotebookClient):
        def create_kernel_manager(self):
            kw = {}
            if os.name == "posix":
                # Kernels talk over Unix sockets in the submission's own temporary folder:
                # with TCP, kernels started side by side (--jobs) or next to other servers can
                # race for the same free port and die at start-up ("Address already in use").
                folder = self.resources.get("metadata", {}).get("path") or tempfile.gettempdir()
                kw = {
                    "transport": "ipc",
                    "connection_file": os.path.join(folder, f"k-{uuid.uuid4().hex[:12]}.json"),
                }
            self.km = AsyncKernelManager(
                kernel_name="grader-current-env",
                kernel_spec_manager=_CurrentEnv(),
                config=self.config,
                **kw,
            )
            return self.km

    return _Client


def _read_notebook(path: Path) -> tuple[nbformat.NotebookNode | None, str]:
    try:
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        return None, "the file is not UTF-8 text"
    try:
        nb = nbformat.reads(text, as_version=4)
    except Exception as exc:  # malformed JSON or not a notebook at all
        first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
        return None, f"the file is not a valid notebook ({first[:200]})"
    if not isinstance(nb.get("cells"), list):
        return None, "the file is not a valid notebook (no cells)"
    return nb, ""


def _error_text(outputs) -> str | None:
    for out in outputs:
        if out.get("output_type") == "error":
            return f"{out.get('ename', 'Error')}: {str(out.get('evalue', ''))[:200]}"
    return None


def grade_notebook(
    path: Path,
    tests: HiddenTests,
    student: str,
    *,
    cell_timeout: float = DEFAULT_CELL_TIMEOUT,
    time_limit: float = DEFAULT_TIME_LIMIT,
    question_timeout: float = DEFAULT_QUESTION_TIMEOUT,
) -> Result:
    """Run one submission and its hidden tests; never raises for a bad submission."""
    from nbclient.exceptions import CellTimeoutError, DeadKernelError

    client_class = _client_class()

    start = time.monotonic()
    questions = list(tests.points)
    result = Result(student, dict.fromkeys(questions, 0.0), dict.fromkeys(questions, ""))
    nb, problem = _read_notebook(path)
    if nb is None:
        result.status = "invalid notebook"
        result.run_notes.append(problem + "; no points could be given")
        for q in questions:
            result.notes[q] = "not graded (the file is not a valid notebook)"
        return result

    student_cells = [
        nbformat.v4.new_code_cell(c.get("source", "")) if c.get("cell_type") == "code" else None
        for c in nb.cells
    ]
    student_cells = [c for c in student_cells if c is not None]
    marker = f"@@grade-{secrets.token_hex(8)}@@"
    setup = nbformat.v4.new_code_cell(
        _SETUP + f"\n__cl_grader_run = __cl_grader_setup({tests.source!r}, {marker!r}, "
        f"{question_timeout!r})\ndel __cl_grader_setup\n"
    )
    q_cells = [nbformat.v4.new_code_cell(f"__cl_grader_run({q!r}, globals())") for q in questions]
    n_student = len(student_cells)
    skipped: dict[int, str] = {}

    state = {"index": -1}

    def remaining() -> float:
        return time_limit - (time.monotonic() - start)

    def on_cell_start(cell, cell_index) -> None:
        state["index"] = cell_index
        if remaining() <= 0:
            raise _WallLimit

    with tempfile.TemporaryDirectory(prefix="grade-") as tmp:
        shutil.copyfile(path, Path(tmp) / "submission.ipynb")  # the kernel's working copy
        for _attempt in range(MAX_ATTEMPTS):
            cells = [
                nbformat.v4.new_code_cell("") if k in skipped else nbformat.v4.new_code_cell(c.source)
                for k, c in enumerate([*student_cells, setup, *q_cells])
            ]
            run_nb = nbformat.v4.new_notebook(cells=cells)
            state["index"] = -1
            client = client_class(
                run_nb,
                timeout=None,
                timeout_func=lambda cell: max(1.0, min(cell_timeout, remaining())),
                allow_errors=True,
                shutdown_kernel="immediate",
                shell_timeout_interval=1,  # notice a dead kernel within a second
                startup_timeout=60,
                resources={"metadata": {"path": tmp}},
                on_cell_start=on_cell_start,
            )
            try:
                client.execute()
                break
            except _WallLimit:
                result.status = "time limit"
                k = state["index"]
                where = f"before code cell {k + 1}" if k < n_student else "while running the tests"
                result.run_notes.append(
                    f"the overall time limit of {time_limit:g} s was reached {where}; "
                    "what came after was not run"
                )
                break
            except (CellTimeoutError, DeadKernelError, RuntimeError) as exc:
                k = state["index"]
                if isinstance(exc, CellTimeoutError):
                    why = (
                        "the overall time limit was reached"
                        if remaining() <= 1.0
                        else f"it ran longer than {cell_timeout:g} s (an endless loop?)"
                    )
                else:
                    why = f"the kernel died ({type(exc).__name__})"
                if k < 0 or k in skipped:
                    result.run_notes.append(f"the notebook could not be run: {why}")
                    result.status = "error"
                    break
                skipped[k] = why
                if k < n_student:
                    result.run_notes.append(f"code cell {k + 1} was skipped: {why}")
                elif k == n_student:
                    result.run_notes.append(f"the grading setup failed: {why}")
                else:
                    q = questions[k - n_student - 1]
                    result.notes[q] = f"the test was stopped: {why}"
                if remaining() <= 1.0:
                    result.status = "time limit"
                    result.run_notes.append(f"the overall time limit of {time_limit:g} s was reached")
                    break
                result.status = "partly skipped"
        else:
            result.run_notes.append(f"gave up after {MAX_ATTEMPTS} attempts")

        for k, cell in enumerate(run_nb.cells[:n_student]):
            err = _error_text(cell.get("outputs", []))
            if err and len(result.run_notes) < 12:
                result.run_notes.append(f"code cell {k + 1} raised {err}")
        for cell in run_nb.cells[n_student + 1 :]:
            for out in cell.get("outputs", []):
                for line in str(out.get("text", "")).splitlines():
                    if line.startswith(marker):
                        data = json.loads(line[len(marker) :])
                        q = data["q"]
                        if q in tests.points:
                            result.points[q] = round(float(data["fraction"]) * tests.points[q], 2)
                            result.notes[q] = data["note"]
    for q in questions:
        if result.points[q] < tests.points[q] and not result.notes[q]:
            result.notes[q] = "no result (the notebook could not be run this far)"
    result.seconds = round(time.monotonic() - start, 1)
    return result


def _slug(student: str) -> str:
    return student.replace("/", "__").replace("\\", "__")


def write_reports(results: list[Result], tests: HiddenTests, out: Path) -> None:
    out.mkdir(parents=True, exist_ok=True)
    questions = list(tests.points)
    with open(out / "scores.csv", "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(["student", *questions, "total", "status"])
        w.writerow(["(max)", *(tests.points[q] for q in questions), tests.max_points, ""])
        for r in results:
            w.writerow([r.student, *(r.points[q] for q in questions), r.total, r.status])
    fb = out / "feedback"
    fb.mkdir(exist_ok=True)
    for r in results:
        lines = [
            f"# {tests.homework} — {r.student}",
            "",
            f"**Score: {r.total:g} / {tests.max_points:g}**",
            "",
            "| question | points | max | note |",
            "|---|---|---|---|",
        ]
        for q in questions:
            note = r.notes[q].replace("|", "\\|").replace("\n", " ") or "✓"
            lines.append(f"| {q} | {r.points[q]:g} | {tests.points[q]:g} | {note} |")
        if r.run_notes:
            lines += ["", "## Notes on the run", "", *(f"- {n}" for n in r.run_notes)]
        (fb / f"{_slug(r.student)}.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Grade submitted notebooks against hidden tests.")
    p.add_argument("--tests", required=True, type=Path, help="hidden test file (.py)")
    p.add_argument("--submissions", required=True, type=Path, help="folder of submitted .ipynb")
    p.add_argument("--out", required=True, type=Path, help="folder for scores.csv and feedback/")
    p.add_argument("--cell-timeout", type=float, default=DEFAULT_CELL_TIMEOUT)
    p.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT, help="per submission")
    p.add_argument("--question-timeout", type=float, default=DEFAULT_QUESTION_TIMEOUT)
    p.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel")
    args = p.parse_args(argv)

    tests = HiddenTests.load(args.tests)
    files = sorted(f for f in args.submissions.rglob("*.ipynb") if ".ipynb_checkpoints" not in f.parts)
    if not files:
        print(f"no .ipynb files under {args.submissions}", file=sys.stderr)
        return 1
    students = [f.relative_to(args.submissions).with_suffix("").as_posix() for f in files]

    def one(item: tuple[Path, str]) -> Result:
        f, student = item
        r = grade_notebook(
            f,
            tests,
            student,
            cell_timeout=args.cell_timeout,
            time_limit=args.time_limit,
            question_timeout=args.question_timeout,
        )
        print(f"{student}: {r.total:g} / {tests.max_points:g} ({r.status}, {r.seconds:g} s)", flush=True)
        return r

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(one, zip(files, students, strict=True)))
    write_reports(results, tests, args.out)
    print(f"wrote {args.out / 'scores.csv'} and {args.out / 'feedback'}{os.sep}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
