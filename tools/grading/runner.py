"""Grade one submission: run it in a sandboxed kernel, run the hidden tests here.

The mechanics behind ``tools/grade.py`` (see its docstring for the trust boundary): a
:class:`_Session` runs the student's code cells in a fresh sandboxed kernel (restarting without a
cell that hangs, floods output or kills the kernel), and answers the hidden tests' requests
through ``course_lib.homework.protocol``; :func:`grade_notebook` runs every question of a
:class:`HiddenTests` file in this process with :func:`protocol.run_question`.
"""

from __future__ import annotations

import functools
import json
import os
import secrets
import signal
import stat
import subprocess
import tempfile
import time
import traceback
import types
import uuid
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

import nbformat

from course_lib.homework import own_work
from course_lib.homework.submit import describe_cell, error_text, manifest_of
from tools import answer_keys as keys_tool

from . import jobroot, protocol, sandbox, tamper

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
    source: str = ""
    variants: bool = False  # the module sets VARIANTS = True: tests are qN(student, data)
    key_values: Callable | None = None  # key_values(data): the values of the answer keys

    @classmethod
    def load(cls, path: Path) -> HiddenTests:
        return cls.from_source(Path(path).read_text(encoding="utf-8"), Path(path))

    @classmethod
    def from_source(cls, source: str, path: Path) -> HiddenTests:
        """Load hidden tests from their source (a Dask worker gets the text, not the file)."""
        module = types.ModuleType(f"hidden_tests_{Path(path).stem}")
        module.__file__ = str(path)
        exec(compile(source, str(path), "exec"), module.__dict__)
        ns = module.__dict__
        points = ns.get("POINTS")
        if not isinstance(points, dict) or not points:
            raise SystemExit(f"{path}: POINTS must be a non-empty dict question -> points")
        bad = {q: v for q, v in points.items() if not isinstance(v, int | float) or not v >= 0}
        if bad or not sum(points.values()) > 0:
            raise SystemExit(
                f"{path}: POINTS must be numbers >= 0 (0 = feedback only) with a positive sum; "
                f"got {bad or points}"
            )
        missing = [q for q in points if not callable(ns.get(q))]
        if missing:
            raise SystemExit(f"{path}: no test function for {missing}")
        functions = {q: ns[q] for q in points}
        homework = str(ns.get("HOMEWORK", Path(path).stem))
        variants = bool(ns.get("VARIANTS", False))
        key_values = ns.get("key_values") if callable(ns.get("key_values")) else None
        return cls(Path(path), homework, dict(points), functions, source, variants, key_values)

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
    file: str = ""
    manifest_student: str | None = None  # the student id written by submit(), if any
    submitted: str | None = None  # ISO time used for the late rule
    time_source: str = "none"  # "manifest", "file" or "none"
    file_time: str | None = None  # the file's own time (shown apart from the LMS's verdict)
    days_late: int = 0
    penalty: float = 0.0  # fraction of the points lost for lateness
    lms: dict | None = None  # the roster entry: id, name, email
    variant: str = ""  # the student's variant code ("" = the default data)
    #: the fraction of each question's credit earned (0..1); a feedback-only question (0 points)
    #: is right or wrong here although it adds nothing to the total
    fractions: dict[str, float] = field(default_factory=dict)
    #: why intake refused to open the student's file ("a link, not graded"), "" if it was opened
    refused: str = ""
    #: why the notebook's code was flagged for the instructor (tools/grading/tamper.py)
    review: list[str] = field(default_factory=list)
    #: for the instructor only (summary.md, results.json), never the feedback: per flag, the
    #: sentence that names another student (whose variant code, whose manifest)
    private_notes: dict[str, str] = field(default_factory=dict)

    def right(self, q: str, points: float) -> bool:
        """Did the answer to ``q`` earn full credit (also for a feedback-only question)?"""
        if q in self.fractions:
            return self.fractions[q] >= 1.0
        return points > 0 and self.points[q] >= points  # results written before fractions

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
    job_root: str | None = None  # None: a fresh private folder (grading.jobroot)


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
        output_used: int = 0  # bytes of this cell's output messages, measured on the wire
        comm_used: int = 0  # bytes of widget (comm) messages over the kernel's life
        flooded: str = ""  # which limit a message broke (the kernel is killed)

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
            # every message is measured before it is decoded (and the kernel killed past the
            # limit); a frame beyond the backstop is not even received (zmq drops it)
            self.km.session = _session_class()(parent=self.km, on_wire=self.on_wire)
            self.km.client_factory = _wire_client_class(max(WIRE_BACKSTOP, 4 * self.output_limit))
            return self.km

        def on_wire(self, msg_type: str, size: int) -> bool:
            """Count a message's bytes against the limits; False: drop it, undecoded."""
            if self.flooded:
                return False
            if msg_type in _OUTPUT_TYPES:
                self.output_used += size
                if self.output_used > self.output_limit:
                    self.flooded = f"it printed more than {self.output_limit} bytes of output"
            elif msg_type.startswith("comm"):
                self.comm_used += size
                if self.comm_used > self.output_limit:
                    self.flooded = (
                        f"its widgets sent more than {self.output_limit} bytes of messages "
                        "(the output limit)"
                    )
            elif size > self.output_limit + (64 << 10):
                self.flooded = f"it sent a message larger than {self.output_limit} bytes"
            if self.flooded:
                _kill_kernel(self)
                return False
            return True

        def output(self, outs, msg, display_id, cell_index):
            if self.flooded:
                return None
            return super().output(outs, msg, display_id, cell_index)

        def handle_comm_msg(self, outs, msg, cell_index):
            return None  # widget state is never kept (it is counted in on_wire)

    return _Client


#: a message frame larger than this is dropped by zmq, undecoded (the output limit, checked
#: on every message below it, stops the kernel long before)
WIRE_BACKSTOP = 64 << 20
_OUTPUT_TYPES = frozenset(
    {"stream", "display_data", "execute_result", "error", "update_display_data", "clear_output"}
)
_MAX_HEADER = 64 << 10


def _frame_size(frame) -> int:
    try:
        return len(frame)
    except TypeError:
        return len(frame.bytes)


@functools.lru_cache(maxsize=1)
def _session_class():
    from jupyter_client.session import Session
    from traitlets import Any

    class WireSession(Session):
        """A session that measures each message on the wire before decoding it."""

        on_wire = Any(None)  # a trait: Session.clone() (the client's copy) keeps it

        def deserialize(self, msg_list, content=True, copy=True):
            size = sum(_frame_size(f) for f in msg_list)
            head = msg_list[1] if len(msg_list) > 1 else b""
            msg_type = ""
            if _frame_size(head) <= _MAX_HEADER:
                try:
                    msg_type = str(json.loads(bytes(head)).get("msg_type", ""))
                except (ValueError, AttributeError, TypeError):
                    msg_type = ""
            if self.on_wire is None or self.on_wire(msg_type, size):
                return super().deserialize(msg_list, content=content, copy=copy)
            return _dropped(msg_list)

    return WireSession


def _dropped(msg_list) -> dict:
    """What stands for a message that was not decoded: a harmless 'busy' for its parent."""
    parent = {}
    if len(msg_list) > 2 and _frame_size(msg_list[2]) <= _MAX_HEADER:
        try:
            parent = json.loads(bytes(msg_list[2]))
        except (ValueError, TypeError):
            parent = {}
    header = {"msg_id": uuid.uuid4().hex, "msg_type": "status"}
    return {
        "header": header,
        "msg_id": header["msg_id"],
        "msg_type": "status",
        "parent_header": parent if isinstance(parent, dict) else {},
        "metadata": {},
        "content": {"execution_state": "busy", "status": "aborted"},
        "buffers": [],
    }


@functools.lru_cache(maxsize=8)
def _wire_client_class(max_bytes: int):
    """A kernel client whose sockets refuse (disconnect) any frame above ``max_bytes``."""
    import zmq
    import zmq.asyncio
    from jupyter_client.asynchronous import AsyncKernelClient
    from traitlets import default

    class WireLimitedClient(AsyncKernelClient):
        @default("context")
        def _limited_context(self):
            ctx = zmq.asyncio.Context()
            ctx.setsockopt(zmq.MAXMSGSIZE, max_bytes)
            return ctx

        def stop_channels(self) -> None:
            super().stop_channels()
            if not self.context.closed:
                self.context.destroy(linger=100)

    return WireLimitedClient


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

    def __init__(
        self,
        job: Path,
        opts: Options,
        deadline: float,
        hits: set[str] | None = None,
        job_tmpfs: bool = False,
    ) -> None:
        self.job = job
        self.opts = opts
        self.deadline = deadline
        self.client = None
        self.cgroup = None
        #: the limits this submission's sandboxes met (sandbox.SandboxGroups.limits_reached,
        #: sandbox.full_tmpfs), collected over its kernels; None: not counted (the preflight)
        self.hits = hits
        self.job_tmpfs = job_tmpfs

    def remaining(self) -> float:
        return self.deadline - time.monotonic()

    def start(self) -> None:
        from nbclient.exceptions import DeadKernelError

        self.cgroup = sandbox.SandboxGroups(self.opts.limits, job_tmpfs=self.job_tmpfs)
        client = _client_class()(
            nbformat.v4.new_notebook(),
            timeout=None,
            allow_errors=True,
            shutdown_kernel="immediate",
            record_timing=False,
            store_widget_state=False,
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
        client.output_used = 0
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
                raise _CellFailed(f"{client.flooded}; the kernel was stopped") from None
            if self.cgroup is not None and self.cgroup.memory_exhausted():
                raise _CellFailed(
                    f"it used more than the memory limit of {self.opts.limits.memory_bytes >> 20}"
                    " MB (files in /tmp and /dev/shm count: they are memory)"
                ) from None
            raise _CellFailed(f"the kernel died ({type(exc).__name__})") from None
        finally:
            client.nb.cells[index] = nbformat.v4.new_code_cell("")  # keep no outputs around
            self._count_limits()
        if client.flooded:
            raise _CellFailed(f"{client.flooded}; the kernel was stopped")
        return cell.get("outputs", [])

    def _sandbox_pids(self) -> list[int]:
        if self.cgroup is not None and self.cgroup.paths:
            return self.cgroup.pids()
        process = getattr(getattr(getattr(self.client, "km", None), "provisioner", None),
                          "process", None)  # fmt: skip
        return sandbox.descendants(process.pid) if process is not None else []

    def _count_limits(self) -> None:
        """After each cell (the files may be gone, the process dead, by the end): a full /tmp
        or /dev/shm, and an address space that came near ``--memory`` (a refused allocation,
        caught or not, is counted nowhere by the kernel)."""
        if self.hits is None:
            return
        pids = self._sandbox_pids()
        if self.opts.mode == "bwrap":
            self.hits |= sandbox.full_tmpfs(pids)
        if self.job_tmpfs and _job_full(self.job):
            self.hits.add("disk")
        limit = self.opts.limits.memory_bytes
        if sandbox.peak_address_space(pids) >= sandbox.NEAR_MEMORY_LIMIT * limit:
            self.hits.add("memory")

    def stop(self) -> None:
        if self.hits is not None and self.cgroup is not None:
            self.hits |= self.cgroup.limits_reached()  # before the groups are removed
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
        self.responses = job  # where the probe writes its answers (grade_notebook sets it)
        self.mounted = False  # is the job folder a size-limited tmpfs (else checked per cell)
        self.hits: set[str] = set()  # limits met by its sandboxes (counted by the sandbox)
        self.homework = ""  # written to the grader's state file (own_work) with each request

    def ensure(self) -> _Kernel | None:
        """A kernel that has run every (non-skipped) student cell, or None."""
        while self.kernel is None and not self.broken:
            if self.attempts >= MAX_ATTEMPTS:
                self.broken = f"gave up after {MAX_ATTEMPTS} attempts"
                self.result.run_notes.append(self.broken)
                break
            self.attempts += 1
            kernel = _Kernel(self.job, self.opts, self.deadline, self.hits, self.mounted)
            k = -1
            try:
                kernel.start()
                for k, source in enumerate(self.cells):
                    if k in self.skipped:
                        continue
                    outputs = kernel.run(source, self.opts.cell_timeout)
                    self._check_disk()
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
                if exc.why.startswith(_DISK):  # the cells are run again: their files too
                    _clear_job(self.job, keep={"submission.ipynb", self.responses.name})
                if k < 0 or k in self.skipped:
                    self.broken = f"the notebook could not be run: {exc.why}"
                    self.result.run_notes.append(self.broken)
                    self.result.status = "error"
                    break
                self.skipped[k] = exc.why
                self.result.run_notes.append(f"code cell {k + 1} was skipped: {exc.why}")
                self.result.status = "partly skipped"
        return self.kernel

    def _check_disk(self) -> None:
        """Without a size-limited tmpfs, the job folder's size is checked after every cell."""
        limit = self.opts.limits.disk_bytes
        if not self.mounted and limit and jobroot.used_bytes(self.job, stop_at=limit) > limit:
            raise _CellFailed(f"{_DISK} of {limit >> 20} MB in its job folder")

    def transport(self, question_timeout: float):
        """Requests of one question; its clock starts once a kernel is ready for it."""
        clock = {"deadline": None}

        def send(request: dict) -> bytes | None:
            kernel = self.ensure()
            if kernel is None:
                raise protocol.ChannelBroken(
                    "the overall time limit was reached"
                    if self.broken == "time limit"
                    else "the notebook could not be run this far"
                )
            if clock["deadline"] is None:
                clock["deadline"] = time.monotonic() + question_timeout
            question_deadline = clock["deadline"]
            # an unguessable name: code the student left running cannot plant a response
            response = self.responses / f".response-{secrets.token_hex(12)}.json"
            source = (
                "__import__('course_lib.homework.protocol', fromlist=['serve']).serve("
                f"{json.dumps(request)!r}, globals(), {str(response)!r})"
            )
            left = question_deadline - time.monotonic()
            if left <= 0:
                raise protocol.ChannelBroken(
                    f"the test did not finish within {self.opts.question_timeout:g} s "
                    "(an endless loop in your code?)"
                )
            guarded = own_work.questions_of(request.get("name")) if request.get("op") == "call" else ()
            state = sandbox.grader_state_path(self.job)
            try:
                if guarded:  # every process of the sandbox reads it (own_work.require)
                    state.write_text(own_work.grader_state_text(self.homework, guarded))
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
            finally:
                if guarded:
                    state.write_text(own_work.grader_state_text(self.homework))
            return _read_limited(response, protocol.MAX_RESPONSE_BYTES + 1)

        return send

    def close(self) -> None:
        if self.kernel is not None:
            self.kernel.stop()
            self.kernel = None


_DISK = "it wrote more than the disk limit"


def _clear_job(job: Path, keep: set[str]) -> None:
    for entry in os.scandir(job):
        if entry.name in keep:
            continue
        if entry.is_dir(follow_symlinks=False):
            jobroot.remove_job_folder(Path(entry.path), False)
        else:
            try:
                os.unlink(entry.path)
            except OSError:
                pass


def _read_limited(path: Path, limit: int) -> bytes | None:
    """At most ``limit`` bytes of a response file the student's code could have tampered with.

    Only a regular file is read: never a symlink (it would be followed outside the sandbox),
    a FIFO (it would block the grader) or a device.
    """
    flags = os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0)
    try:
        fd = os.open(path, flags)
    except OSError:
        return None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None
        chunks, left = [], limit
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
        return b"".join(chunks)
    except OSError:
        return None
    finally:
        os.close(fd)
        try:
            path.unlink()
        except OSError:
            pass


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
        data = json.loads(text)
    except json.JSONDecodeError as exc:  # where, never what: the bytes may be anyone's secret
        where = f"line {exc.lineno}, column {exc.colno}"
        return None, f"the file is not a valid notebook (not JSON: {where})"
    except RecursionError:
        return None, "the file is not a valid notebook (nested too deeply)"
    if not isinstance(data, dict) or not isinstance(data.get("cells"), list):
        return None, "the file is not a valid notebook (no cells)"
    try:
        nb = nbformat.reads(text, as_version=4)
    except Exception as exc:  # not a notebook: the type of error only, no text from the file
        return None, f"the file is not a valid notebook ({type(exc).__name__})"
    if not isinstance(nb.get("cells"), list):
        return None, "the file is not a valid notebook (no cells)"
    return nb, ""


def _error_text(outputs) -> str | None:
    for out in outputs:
        if out.get("output_type") == "error":
            return error_text(out.get("ename", "Error"), out.get("evalue", ""))
    return None


def _job_full(job: Path) -> bool:
    """Is a tmpfs job folder full (less than 1 MB left)?"""
    try:
        sv = os.statvfs(job)
    except OSError:
        return False
    return sv.f_bavail * sv.f_frsize < (1 << 20)


def _note_disk(job: Path, mounted: bool, limit: int, result: Result, hits: set[str]) -> None:
    """Say so when the submission filled its job folder (its own writes failed, nobody else's):
    full now, or full after one of its cells (``hits``: the files may have been removed)."""
    try:
        if mounted:
            full = "disk" in hits or _job_full(job)
        else:
            full = jobroot.used_bytes(job, stop_at=limit) > limit
    except OSError:
        return
    if full:
        result.run_notes.append(
            f"the job folder reached the disk limit of {limit >> 20} MB "
            "(writes past it failed with 'No space left on device')"
        )
        result.status = f"{result.status}; reached the disk limit ({limit >> 20} MB)"


def limit_flags(hits: set[str], limits: sandbox.Limits) -> list[tuple[str, str]]:
    """``(status flag, feedback sentence)`` for every limit a submission's sandbox met."""
    mb = 1 << 20
    said = {
        "processes": (
            f"reached the process limit ({limits.processes})",
            "starting more processes or threads failed in its code",
        ),
        "memory": (
            f"reached the memory limit ({limits.memory_bytes // mb} MB)",
            "allocations past it fail (MemoryError); files in /tmp and /dev/shm count as memory",
        ),
        "/tmp": (
            f"reached the /tmp limit ({limits.tmp_bytes // mb} MB)",
            "writes past it failed with 'No space left on device'",
        ),
        "/dev/shm": (
            f"reached the /dev/shm limit ({limits.tmp_bytes // mb} MB)",
            "writes past it failed with 'No space left on device'",
        ),
    }
    return [(said[h][0], f"the sandbox {said[h][0]}: {said[h][1]}")
            for h in ("processes", "memory", "/tmp", "/dev/shm") if h in hits]  # fmt: skip


def _note_limits(hits: set[str], limits: sandbox.Limits, result: Result) -> None:
    """One sentence and one status flag per limit the sandbox's own counters saw met, also
    when the student's code caught the error (a refused fork, a full /tmp)."""
    for flag, sentence in limit_flags(hits, limits):
        result.run_notes.append(sentence)
        result.status = f"{result.status}; {flag}"


def _note_variant_mismatch(session, timeout: float, variant: str, result: Result) -> None:
    """Tell a student whose notebook used another variant code (or none) why answers fail."""
    try:
        used = protocol.Student(session.transport(timeout))["VARIANT"]
    except Exception:  # no VARIANT, a broken notebook: the questions will say what is wrong
        return
    mine = variant.upper()
    theirs = (
        used.strip().upper().replace("-", "").replace(" ", "") if isinstance(used, str) else None
    )
    if theirs != mine:
        shown = f"code {used!r}" if theirs else "no code (the data printed in the notebook)"
        result.run_notes.append(
            f"your notebook used {shown}, but your variant code is {mine}: you were graded on "
            "your own data, so answers computed for other data are wrong"
        )


def _note_manifest(nb, homework: str, result: Result) -> None:
    """What the submit() manifest says (student, time), and whether it still holds."""
    manifest = manifest_of(nb)
    if manifest is None:
        return
    result.manifest_student = manifest["student"]
    result.submitted = manifest["time"].isoformat()
    result.time_source = "manifest"
    if manifest["tampered"]:
        result.run_notes.append("the notebook was changed after submit() (checksum mismatch)")
    if manifest["homework"] != homework:
        result.run_notes.append(f"submitted as {manifest['homework']!r}, graded as {homework!r}")


def _note_cell_errors(
    errors: dict, positions: list, cells: list, lim: sandbox.Limits, result: Result
) -> None:
    """The cells that raised (at most 12 notes in all), and what a full disk means."""
    for k in sorted(errors):
        if len(result.run_notes) < 12:
            where = describe_cell(k + 1, positions[k], cells[k])
            result.run_notes.append(f"{where} raised {errors[k]}")
    if any("[Errno 28]" in e for e in errors.values()):
        result.run_notes.append(
            f"'No space left on device' is a limit of the grader: /tmp and /dev/shm hold "
            f"{lim.tmp_bytes >> 20} MB each, the job folder {lim.disk_bytes >> 20} MB"
        )


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
    variant: str = "",
    job_root: str | None = None,
) -> Result:
    """Run one submission in a sandbox and grade it here; never raises for a bad submission."""
    opts = Options(
        cell_timeout, time_limit, question_timeout, mode, limits or sandbox.Limits(), job_root
    )
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
    positions = [n for n, c in enumerate(nb.cells, start=1) if c.get("cell_type") == "code"]
    _note_manifest(nb, tests.homework, result)
    variant_data = None
    if tests.variants:
        from course_lib.homework import variants

        variant_data = variants.data(tests.homework, variant)
        result.variant = variant
        if variant:
            result.run_notes.append(f"graded on the student's own data (variant {variant})")
    job, mounted = jobroot.job_folder(jobroot.job_root(job_root), opts.limits.disk_bytes)
    session = _Session(job, cells, opts, start + time_limit, result)
    session.homework = tests.homework
    # the sandbox shows it read-only: the homework's value guards hold in every process there
    sandbox.grader_state_path(job).write_text(own_work.grader_state_text(tests.homework))
    if variant_data is not None and tests.key_values is not None:  # the checks work as at home
        keys_tool.for_data(tests.homework, variant_data, tests.key_values).write(
            sandbox.grader_keys_path(job)
        )
    try:
        session.responses = jobroot.response_folder(job, 4 * protocol.MAX_RESPONSE_BYTES, mounted)
        session.mounted = mounted
        (job / "submission.ipynb").write_bytes(path.read_bytes())  # the kernel's working copy
        session.ensure()
        if variant_data is not None and variant:
            _note_variant_mismatch(session, question_timeout, variant, result)
        for q in questions:
            if session.broken == "time limit":
                result.notes[q] = "not graded: the overall time limit was reached"
                continue
            transport = session.transport(question_timeout)
            test = tests.functions[q]
            if tests.variants:  # graded on the student's own data (course_lib.homework.variants)
                test = functools.partial(test, data=variant_data)
            fraction, note = protocol.run_question(test, protocol.Student(transport))
            result.points[q] = round(fraction * tests.points[q], 2)
            result.fractions[q] = fraction
            result.notes[q] = note
        _note_cell_errors(session.errors, positions, cells, opts.limits, result)
    finally:
        session.close()
        _note_limits(session.hits, opts.limits, result)
        _note_disk(job, mounted, opts.limits.disk_bytes, result, session.hits)
        jobroot.remove_job_folder(job, mounted)
        sandbox.grader_state_path(job).unlink(missing_ok=True)
        sandbox.grader_keys_path(job).unlink(missing_ok=True)
    for q in questions:
        if result.fractions.get(q, 0.0) < 1.0 and not result.notes[q]:
            result.notes[q] = "wrong answer"
    tamper.apply(result, cells, tests.homework, tests.points)  # flagged; certain: guards' points 0
    values = [f"answer_{q}" for q, p in tests.points.items() if p > 0]  # the value answers' names
    tamper.note_typed(result, cells, values)  # flagged for review; the points stand
    if mode != "bwrap":
        result.run_notes.append(UNSANDBOXED_NOTE)
    result.seconds = round(time.monotonic() - start, 1)
    return result


def check_sandbox(opts: Options) -> str:
    """``""`` when a sandboxed kernel starts with the course's environment, else one message.

    Run once before a batch: the sandbox must see Python, the environment (a venv reached
    through a link, a conda environment) and ``course_lib``, and a kernel must start and import
    them.  The message names the path the sandbox could not see.
    """
    job, mounted = jobroot.job_folder(jobroot.job_root(opts.job_root), opts.limits.disk_bytes)
    kernel = None
    try:
        problem = sandbox.visibility_problem(job, opts.limits)
        if problem:
            return problem
        kernel = _Kernel(job, opts, time.monotonic() + 120)
        kernel.start()
        error = _error_text(kernel.run("import course_lib, numpy", 60))
        return f"a sandboxed kernel could not import the course: {error}" if error else ""
    except (_CellFailed, _WallLimit, Exception) as exc:  # any failure here stops the batch
        why = exc.why if isinstance(exc, _CellFailed) else type(exc).__name__
        return f"a sandboxed kernel could not be started ({why})"
    finally:
        if kernel is not None:
            kernel.stop()
        jobroot.remove_job_folder(job, mounted)


def grade_payload(payload: dict) -> dict:
    """Grade one submission from plain data (runs locally or on a Dask worker).

    ``payload``: ``tests_source``, ``tests_name``, ``student``, ``notebook`` (bytes) and
    ``options`` (keyword arguments of :func:`grade_notebook`).  Returns ``asdict(Result)``.
    """

    tests = HiddenTests.from_source(payload["tests_source"], Path(payload["tests_name"]))
    root = jobroot.job_root(payload["options"].get("job_root"))
    with tempfile.TemporaryDirectory(prefix="submission-", dir=root) as tmp:
        path = Path(tmp) / "submission.ipynb"
        path.write_bytes(payload["notebook"])
        try:
            r = grade_notebook(path, tests, payload["student"], **payload["options"])
        except BaseException as exc:  # an error barrier: one submission never ends the batch
            if isinstance(exc, KeyboardInterrupt):
                raise
            traceback.print_exc()
            r = Result(
                payload["student"],
                dict.fromkeys(tests.points, 0.0),
                dict.fromkeys(tests.points, "not graded (grader error)"),
                status="grader error",
                sandbox=payload["options"]["mode"],
            )
            r.run_notes.append(
                f"the grader failed on this submission ({type(exc).__name__}); please regrade it"
            )
    return asdict(r)
