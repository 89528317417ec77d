"""Grade a folder of submitted homework notebooks against hidden tests.

Usage (instructors)::

    python tools/grade.py --tests solutions/hidden_tests/hw01.py \\
        --submissions submissions/hw01 --out grades/hw01 [--jobs 2] [--sandbox auto]

writes ``grades/hw01/scores.csv`` (one row per student: points per question, total, status,
sandbox) and ``grades/hw01/feedback/<student>.md`` (points, the reason for each lost point,
notes on the run), each row and file as soon as its submission is graded.

Who the student is
------------------
A notebook directly in ``--submissions`` is the student named by its file name
(``alice.ipynb`` -> ``alice``); a notebook inside a sub-folder belongs to the student named by
that top-level folder (``alice/hw01.ipynb`` -> ``alice``).  When one student has several
notebooks, the most recently modified one is graded and the others are listed in the notes
and in the status.  Feedback file names are unique per student.

The trust boundary
------------------
Student code is hostile input.  It runs only in a sandboxed kernel (``tools/grading/sandbox.py``:
bubblewrap, no network, no view of the course checkout beyond ``course_lib``, resource limits,
nothing survives it).  Hidden tests and expected values never enter that kernel: they run here,
in the grader, and ask the kernel for *data* through ``course_lib._probe`` -- a name's value,
the result of the student's function on inputs chosen here, a symbolic answer evaluated at
points chosen here -- which arrives as size-limited JSON and is validated here
(``tools/grading/protocol.py``).  Comparisons, fractions and notes are computed here, clamped to
``[0, 1]``; a malformed or missing answer costs that question, never the batch.

How a submission is run
-----------------------
Each submission gets a private temporary job folder holding a copy of its notebook; its code
cells run one by one in a fresh sandboxed kernel (errors do not stop the run).  A cell that runs
longer than ``--cell-timeout``, prints more than ``--output-limit`` bytes or kills its kernel is
skipped: the kernel is killed and the notebook is run again without that cell, so the student
keeps the points earned elsewhere.  A request of a hidden test that does not finish within
``--question-timeout`` (an endless loop in a graded function) costs that question; the kernel is
replaced.  ``--time-limit`` bounds the whole submission.  The job folder is always removed.

Hidden tests
------------
A hidden test file is plain Python (not collected by pytest: do not name it ``test_*.py``)::

    HOMEWORK = "hw01"
    POINTS = {"q1": 2, "q2": 3}          # questions in report order, with their points

    def q1(student):                      # student: see tools/grading/protocol.py
        T = student["answer_q1"]          # plain data (a missing name is reported for you)
        assert ..., "message for the student"
        # return None for full points, or a fraction in [0, 1], or (fraction, "message")

Hidden tests compute their expected values from first principles (numpy, closed forms), not
with the code the solution notebook calls.

The exit code is 0 whenever the batch ran, whatever the submissions did; it is non-zero only
for the grader's own failures (bad arguments, a broken hidden-test file, no submissions).
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import io
import json
import os
import re
import runpy
import secrets
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback
import uuid
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

import nbformat

sys.path.insert(0, str(Path(__file__).resolve().parent))

from grading import protocol, sandbox

DEFAULT_CELL_TIMEOUT = 60.0
DEFAULT_TIME_LIMIT = 300.0
DEFAULT_QUESTION_TIMEOUT = 20.0
MAX_ATTEMPTS = 6
UNSANDBOXED_NOTE = (
    "graded WITHOUT a sandbox (--sandbox none): the submission's code ran with the grader's "
    "rights; scores are trustworthy only for trusted submissions"
)


class _WallLimit(Exception):
    """The overall time limit of a submission was reached."""


class _CellFailed(Exception):
    """A cell could not complete: ``why`` says how (time-out, output flood, dead kernel)."""

    def __init__(self, why: str) -> None:
        super().__init__(why)
        self.why = why


@dataclass
class HiddenTests:
    path: Path
    homework: str
    points: dict[str, float]
    functions: dict

    @classmethod
    def load(cls, path: Path) -> HiddenTests:
        ns = runpy.run_path(str(path))
        points = ns.get("POINTS")
        if not isinstance(points, dict) or not points:
            raise SystemExit(f"{path}: POINTS must be a non-empty dict question -> points")
        missing = [q for q in points if not callable(ns.get(q))]
        if missing:
            raise SystemExit(f"{path}: no test function for {missing}")
        functions = {q: ns[q] for q in points}
        return cls(path, str(ns.get("HOMEWORK", path.stem)), dict(points), functions)

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
    sandbox: str = "bwrap"

    @property
    def total(self) -> float:
        return round(sum(self.points.values()), 2)


@dataclass(frozen=True)
class Options:
    cell_timeout: float = DEFAULT_CELL_TIMEOUT
    time_limit: float = DEFAULT_TIME_LIMIT
    question_timeout: float = DEFAULT_QUESTION_TIMEOUT
    mode: str = "bwrap"  # "bwrap" or "none" (resolved from --sandbox auto by main)
    limits: sandbox.Limits = field(default_factory=sandbox.Limits)


# ------------------------------------------------------------------------------ kernels


def _client_class():
    """A NotebookClient whose kernel runs sandboxed, over Unix sockets in the job folder."""
    import ipykernel.kernelspec
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import AsyncKernelManager
    from nbclient import NotebookClient

    class _SandboxSpecs(KernelSpecManager):
        argv: tuple[str, ...] = ()

        def get_kernel_spec(self, kernel_name):
            spec = ipykernel.kernelspec.get_kernel_dict()
            spec["argv"] = list(self.argv)
            return self.kernel_spec_class(resource_dir=ipykernel.kernelspec.RESOURCES, **spec)

    class _Client(NotebookClient):
        job: Path
        kernel_cmd: list[str]
        output_limit: int
        output_used: int = 0
        flooded: bool = False

        def create_kernel_manager(self):
            specs = _SandboxSpecs()
            specs.argv = tuple(self.kernel_cmd)
            # Unix sockets in the job folder: the sandbox has no network, and kernels started
            # side by side cannot race for TCP ports.
            self.km = AsyncKernelManager(
                kernel_name="grader-sandbox",
                kernel_spec_manager=specs,
                config=self.config,
                transport="ipc",
                connection_file=str(self.job / f"k-{uuid.uuid4().hex[:12]}.json"),
            )
            return self.km

        def output(self, outs, msg, display_id, cell_index):
            size = len(json.dumps(msg.get("content", {}), default=str))
            self.output_used += size
            if self.output_used > self.output_limit:
                if not self.flooded:
                    self.flooded = True
                    _kill_kernel(self)
                return None
            return super().output(outs, msg, display_id, cell_index)

    return _Client


def _kill_kernel(client) -> None:
    km = getattr(client, "km", None)
    provisioner = getattr(km, "provisioner", None)
    process = getattr(provisioner, "process", None)
    if process is None:
        return
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except OSError:
        try:
            process.kill()
        except OSError:
            pass


class _Kernel:
    """One sandboxed kernel of one submission."""

    def __init__(self, job: Path, opts: Options, deadline: float) -> None:
        self.job = job
        self.opts = opts
        self.deadline = deadline
        self.client = None
        self.cgroup = None
        self.executed = 0

    def remaining(self) -> float:
        return self.deadline - time.monotonic()

    def start(self) -> None:
        from nbclient.exceptions import DeadKernelError

        self.cgroup = sandbox.ProcessGroupLimit(self.opts.limits.processes)
        client = _client_class()(
            nbformat.v4.new_notebook(),
            timeout=None,
            allow_errors=True,
            shutdown_kernel="immediate",
            shell_timeout_interval=1,  # notice a dead kernel within a second
            startup_timeout=60,
            resources={"metadata": {"path": str(self.job)}},
        )
        client.job = self.job
        client.kernel_cmd = sandbox.kernel_argv(
            self.job, self.opts.mode, self.opts.limits, self.cgroup
        )
        client.output_limit = self.opts.limits.output_bytes
        client.timeout_func = lambda cell: self._timeout
        self.client = client
        self._timeout = 60.0
        try:
            client.km = client.create_kernel_manager()
            # the kernel's own stdout/stderr (not its cells' output) go nowhere
            client.start_new_kernel(stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            client.start_new_kernel_client()
        except Exception as exc:
            self.stop()
            raise _CellFailed(f"the kernel could not start ({type(exc).__name__})") from None
        if not client.km.has_kernel:
            self.stop()
            raise DeadKernelError("no kernel")

    def run(self, source: str, timeout: float) -> list:
        """Run one cell; return its outputs or raise _CellFailed / _WallLimit."""
        from nbclient.exceptions import CellTimeoutError, DeadKernelError

        if self.remaining() <= 0:
            raise _WallLimit
        client = self.client
        client.output_used, client.flooded = 0, False
        self._timeout = max(0.5, min(timeout, self.remaining()))
        cell = nbformat.v4.new_code_cell(source)
        client.nb.cells.append(cell)
        index = len(client.nb.cells) - 1
        try:
            client.execute_cell(cell, index)
        except CellTimeoutError:
            if self.remaining() <= 0.5:
                raise _WallLimit from None
            raise _CellFailed(
                f"it ran longer than {self._timeout:g} s (an endless loop?)"
            ) from None
        except (DeadKernelError, RuntimeError, OSError) as exc:
            if client.flooded:
                raise _CellFailed(
                    f"it printed more than {self.opts.limits.output_bytes} bytes of output; "
                    "the kernel was stopped"
                ) from None
            raise _CellFailed(f"the kernel died ({type(exc).__name__})") from None
        finally:
            client.nb.cells[index] = nbformat.v4.new_code_cell("")  # keep no outputs around
        if client.flooded:
            raise _CellFailed(
                f"it printed more than {self.opts.limits.output_bytes} bytes of output; "
                "the kernel was stopped"
            )
        self.executed += 1
        return cell.get("outputs", [])

    def stop(self) -> None:
        client, self.client = self.client, None
        if client is not None:
            _kill_kernel(client)
            try:
                if getattr(client, "km", None) is not None:
                    client._cleanup_kernel()
            except Exception:
                pass
        if self.cgroup is not None:
            self.cgroup.kill_and_remove()
            self.cgroup = None


class _Session:
    """The student's notebook running in a kernel, restarted (without bad cells) when needed."""

    def __init__(
        self, job: Path, cells: list[str], opts: Options, deadline: float, result: Result
    ) -> None:
        self.job = job
        self.cells = cells
        self.opts = opts
        self.deadline = deadline
        self.result = result
        self.skipped: dict[int, str] = {}
        self.kernel: _Kernel | None = None
        self.errors: dict[int, str] = {}
        self.broken = ""  # why no kernel can be had any more
        self.attempts = 0
        self.requests = 0

    def ensure(self) -> _Kernel | None:
        """A kernel that has run every (non-skipped) student cell, or None."""
        while self.kernel is None and not self.broken:
            if self.attempts >= MAX_ATTEMPTS:
                self.broken = f"gave up after {MAX_ATTEMPTS} attempts"
                self.result.run_notes.append(self.broken)
                break
            self.attempts += 1
            kernel = _Kernel(self.job, self.opts, self.deadline)
            k = -1
            try:
                kernel.start()
                for k, source in enumerate(self.cells):
                    if k in self.skipped:
                        continue
                    outputs = kernel.run(source, self.opts.cell_timeout)
                    err = _error_text(outputs)
                    if err:
                        self.errors.setdefault(k, err)
                self.kernel = kernel
            except _WallLimit:
                kernel.stop()
                self.broken = "time limit"
                self.result.status = "time limit"
                where = f"before code cell {k + 1}" if k >= 0 else "before the notebook ran"
                self.result.run_notes.append(
                    f"the overall time limit of {self.opts.time_limit:g} s was reached {where}; "
                    "what came after was not run"
                )
            except _CellFailed as exc:
                kernel.stop()
                if k < 0 or k in self.skipped:
                    self.broken = f"the notebook could not be run: {exc.why}"
                    self.result.run_notes.append(self.broken)
                    self.result.status = "error"
                    break
                self.skipped[k] = exc.why
                self.result.run_notes.append(f"code cell {k + 1} was skipped: {exc.why}")
                self.result.status = "partly skipped"
        return self.kernel

    def transport(self, question_deadline: float):
        def send(request: dict) -> bytes | None:
            kernel = self.ensure()
            if kernel is None:
                raise protocol.ChannelBroken(
                    "the overall time limit was reached"
                    if self.broken == "time limit"
                    else "the notebook could not be run this far"
                )
            self.requests += 1
            # an unguessable name: code the student left running cannot plant a response
            response = self.job / f".response-{secrets.token_hex(12)}.json"
            source = (
                "__import__('course_lib._probe', fromlist=['serve']).serve("
                f"{json.dumps(request)!r}, globals(), {str(response)!r})"
            )
            left = question_deadline - time.monotonic()
            if left <= 0:
                raise protocol.ChannelBroken(
                    f"the test did not finish within {self.opts.question_timeout:g} s "
                    "(an endless loop in your code?)"
                )
            try:
                kernel.run(source, left)
            except _WallLimit:
                self.kernel = None
                kernel.stop()
                self.broken = "time limit"
                self.result.status = "time limit"
                raise protocol.ChannelBroken("the overall time limit was reached") from None
            except _CellFailed as exc:
                self.kernel = None
                kernel.stop()
                if "longer than" in exc.why:
                    why = (
                        f"the test did not finish within {self.opts.question_timeout:g} s "
                        "(an endless loop in your code?)"
                    )
                else:
                    why = f"the test was stopped: {exc.why}"
                raise protocol.ChannelBroken(why) from None
            return _read_limited(response, protocol.MAX_RESPONSE_BYTES + 1)

        return send

    def close(self) -> None:
        if self.kernel is not None:
            self.kernel.stop()
            self.kernel = None


def _read_limited(path: Path, limit: int) -> bytes | None:
    try:
        with open(path, "rb") as fh:
            data = fh.read(limit)
        path.unlink()
        return data
    except OSError:
        return None


def _read_notebook(path: Path) -> tuple[nbformat.NotebookNode | None, str]:
    try:
        if path.stat().st_size > 50 << 20:
            return None, "the file is larger than 50 MB"
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        return None, "the file is not UTF-8 text"
    except OSError as exc:
        return None, f"the file could not be read ({type(exc).__name__})"
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


def _jobs_base() -> Path:
    base = Path(tempfile.gettempdir()) / "course-grader"
    base.mkdir(mode=0o700, exist_ok=True)
    return base


def grade_notebook(
    path: Path,
    tests: HiddenTests,
    student: str,
    *,
    cell_timeout: float = DEFAULT_CELL_TIMEOUT,
    time_limit: float = DEFAULT_TIME_LIMIT,
    question_timeout: float = DEFAULT_QUESTION_TIMEOUT,
    mode: str = "bwrap",
    limits: sandbox.Limits | None = None,
) -> Result:
    """Run one submission in a sandbox and grade it here; never raises for a bad submission."""
    opts = Options(cell_timeout, time_limit, question_timeout, mode, limits or sandbox.Limits())
    start = time.monotonic()
    questions = list(tests.points)
    result = Result(
        student, dict.fromkeys(questions, 0.0), dict.fromkeys(questions, ""), sandbox=mode
    )
    nb, problem = _read_notebook(path)
    if nb is None:
        result.status = "invalid notebook"
        result.run_notes.append(problem + "; no points could be given")
        for q in questions:
            result.notes[q] = "not graded (the file is not a valid notebook)"
        return result
    cells = [str(c.get("source", "")) for c in nb.cells if c.get("cell_type") == "code"]

    job = Path(tempfile.mkdtemp(prefix="job-", dir=_jobs_base()))
    session = _Session(job, cells, opts, start + time_limit, result)
    try:
        (job / "submission.ipynb").write_bytes(path.read_bytes())  # the kernel's working copy
        session.ensure()
        for q in questions:
            if session.broken == "time limit":
                result.notes[q] = "not graded: the overall time limit was reached"
                continue
            transport = session.transport(time.monotonic() + question_timeout)
            fraction, note = protocol.run_question(tests.functions[q], protocol.Student(transport))
            result.points[q] = round(fraction * tests.points[q], 2)
            result.notes[q] = note
        for k in sorted(session.errors):
            if len(result.run_notes) < 12:
                result.run_notes.append(f"code cell {k + 1} raised {session.errors[k]}")
    finally:
        session.close()
        shutil.rmtree(job, ignore_errors=True)
    for q in questions:
        if result.points[q] < tests.points[q] and not result.notes[q]:
            result.notes[q] = "wrong answer"
    if mode != "bwrap":
        result.run_notes.append(UNSANDBOXED_NOTE)
    result.seconds = round(time.monotonic() - start, 1)
    return result


# ------------------------------------------------------------------------------ batches


def discover(folder: Path) -> list[tuple[str, Path, list[Path]]]:
    """``(student, notebook to grade, other notebooks of that student)``, sorted by student."""
    by_student: dict[str, list[Path]] = {}
    for f in sorted(folder.rglob("*.ipynb")):
        rel = f.relative_to(folder)
        if ".ipynb_checkpoints" in rel.parts or any(p.startswith(".") for p in rel.parts):
            continue
        if not f.is_file():
            continue
        student = rel.stem if len(rel.parts) == 1 else rel.parts[0]
        by_student.setdefault(student, []).append(f)
    out = []
    for student in sorted(by_student):
        files = sorted(by_student[student], key=lambda p: (-p.stat().st_mtime, str(p)))
        out.append((student, files[0], files[1:]))
    return out


_SAFE = re.compile(r"[A-Za-z0-9._-]")


def feedback_names(students: list[str]) -> dict[str, str]:
    """A distinct, filesystem-safe file stem per student (distinct even case-insensitively)."""

    def slug(s: str) -> str:
        text = "".join(ch if _SAFE.fullmatch(ch) else f"%{ord(ch):02X}" for ch in s)
        return text.lstrip(".") or "_"

    names = {s: slug(s) for s in students}
    counts: dict[str, int] = {}
    for n in names.values():
        counts[n.lower()] = counts.get(n.lower(), 0) + 1
    for s, n in names.items():
        if counts[n.lower()] > 1 or len(n) > 120:
            names[s] = f"{n[:100]}-{hashlib.sha256(s.encode()).hexdigest()[:10]}"
    return names


def _atomic_write(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex[:8]}.tmp")
    tmp.write_text(text, encoding="utf-8")
    os.replace(tmp, path)


def scores_csv(results: list[Result], tests: HiddenTests) -> str:
    questions = list(tests.points)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["student", *questions, "total", "status", "sandbox"])
    w.writerow(["(max)", *(tests.points[q] for q in questions), tests.max_points, "", ""])
    for r in sorted(results, key=lambda r: r.student):
        w.writerow(
            [
                r.student,
                *(r.points[q] for q in questions),
                r.total,
                r.status,
                "bwrap" if r.sandbox == "bwrap" else "none (unsandboxed)",
            ]
        )
    return buf.getvalue()


def feedback_markdown(r: Result, tests: HiddenTests) -> str:
    lines = [
        f"# {tests.homework} — {r.student}",
        "",
        f"**Score: {r.total:g} / {tests.max_points:g}**",
        "",
        "| question | points | max | note |",
        "|---|---|---|---|",
    ]
    for q in tests.points:
        note = r.notes[q].replace("|", "\\|").replace("\n", " ") or "✓"
        lines.append(f"| {q} | {r.points[q]:g} | {tests.points[q]:g} | {note} |")
    if r.run_notes:
        lines += ["", "## Notes on the run", "", *(f"- {n}" for n in r.run_notes)]
    return "\n".join(lines) + "\n"


class Reports:
    """scores.csv and feedback files, rewritten atomically after every graded submission."""

    def __init__(self, tests: HiddenTests, out: Path, names: dict[str, str]) -> None:
        self.tests, self.out, self.names = tests, out, names
        self.results: list[Result] = []
        self.lock = threading.Lock()
        (out / "feedback").mkdir(parents=True, exist_ok=True)

    def add(self, r: Result) -> None:
        with self.lock:
            self.results.append(r)
            _atomic_write(
                self.out / "feedback" / f"{self.names[r.student]}.md",
                feedback_markdown(r, self.tests),
            )
            _atomic_write(self.out / "scores.csv", scores_csv(self.results, self.tests))


def write_reports(results: list[Result], tests: HiddenTests, out: Path) -> None:
    reports = Reports(tests, out, feedback_names([r.student for r in results]))
    for r in results:
        reports.add(r)


def resolve_sandbox(choice: str) -> tuple[str, str]:
    """``(mode, message)`` for ``--sandbox auto|bwrap|none``."""
    if choice == "none":
        return "none", "WARNING: " + UNSANDBOXED_NOTE
    ok, why = sandbox.bwrap_works()
    if ok:
        return "bwrap", ""
    if choice == "bwrap":
        raise SystemExit(f"--sandbox bwrap: {why}")
    return "none", f"WARNING: {why}; " + UNSANDBOXED_NOTE


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description="Grade submitted notebooks against hidden tests.")
    p.add_argument("--tests", required=True, type=Path, help="hidden test file (.py)")
    p.add_argument("--submissions", required=True, type=Path, help="folder of submitted .ipynb")
    p.add_argument("--out", required=True, type=Path, help="folder for scores.csv and feedback/")
    p.add_argument("--cell-timeout", type=float, default=DEFAULT_CELL_TIMEOUT)
    p.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT, help="per submission")
    p.add_argument("--question-timeout", type=float, default=DEFAULT_QUESTION_TIMEOUT)
    p.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel")
    p.add_argument(
        "--sandbox",
        choices=["auto", "bwrap", "none"],
        default="auto",
        help="auto: bubblewrap where it works, else unsandboxed with a warning",
    )
    p.add_argument("--memory", type=float, default=4.0, help="address-space limit, GiB")
    p.add_argument("--output-limit", type=int, default=1 << 20, help="bytes of output per cell")
    args = p.parse_args(argv)

    tests = HiddenTests.load(args.tests)
    if not args.submissions.is_dir():
        print(f"--submissions {args.submissions} is not a folder", file=sys.stderr)
        return 2
    found = discover(args.submissions)
    if not found:
        print(f"no .ipynb files under {args.submissions}", file=sys.stderr)
        return 1
    mode, message = resolve_sandbox(args.sandbox)
    if message:
        print(message, file=sys.stderr, flush=True)
    limits = sandbox.Limits(
        memory_bytes=int(args.memory * sandbox.GIB),
        cpu_seconds=int(args.time_limit) + 30,
        output_bytes=args.output_limit,
    )
    args.out.mkdir(parents=True, exist_ok=True)
    reports = Reports(tests, args.out, feedback_names([s for s, _, _ in found]))

    def one(item: tuple[str, Path, list[Path]]) -> None:
        student, path, others = item
        try:
            r = grade_notebook(
                path, tests, student,
                cell_timeout=args.cell_timeout, time_limit=args.time_limit,
                question_timeout=args.question_timeout, mode=mode, limits=limits,
            )  # fmt: skip
        except BaseException as exc:  # an error barrier: one submission never ends the batch
            if isinstance(exc, KeyboardInterrupt):
                raise
            traceback.print_exc()
            r = Result(
                student,
                dict.fromkeys(tests.points, 0.0),
                dict.fromkeys(tests.points, "not graded (grader error)"),
                status="grader error",
                sandbox=mode,
            )
            r.run_notes.append(
                f"the grader failed on this submission ({type(exc).__name__}); please regrade it"
            )
        if others:
            r.status = f"{r.status}; several notebooks"
            r.run_notes.append(
                f"several notebooks were submitted; graded {path.relative_to(args.submissions)} "
                "(the newest), ignored "
                + ", ".join(str(o.relative_to(args.submissions)) for o in others)
            )
        reports.add(r)
        print(
            f"{student}: {r.total:g} / {tests.max_points:g} ({r.status}, {r.seconds:g} s)",
            flush=True,
        )

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        list(pool.map(one, found))
    print(
        f"wrote {args.out / 'scores.csv'} and {args.out / 'feedback'}{os.sep}"
        + (" -- UNSANDBOXED" if mode != "bwrap" else "")
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
