"""Where a submission's code runs: a bubblewrap sandbox with resource limits.

One sandbox per submission (per kernel).  What the student's kernel sees:

* a read-only view of the system libraries (``/usr``), the Python installation and the
  virtual environment, and of the ``course_lib`` package -- and nothing else of the course
  checkout: no ``solutions/``, no ``tools/`` (homework sources, hidden tests), no ``.git``;
* its own private writable job folder (a copy of its notebook, its kernel's Unix sockets, the
  probe's response file), as ``HOME`` and working directory, and an empty ``/tmp``;
* no network (its own network namespace), its own PID and IPC namespaces (it cannot see or
  signal the grader, other kernels or their files), ``--die-with-parent`` so nothing it starts
  survives the kernel, ``--new-session`` and no capabilities;
* limits set before exec: address space (``--memory``, default 4 GiB), CPU time, file size,
  no core dumps, and the number of processes (a ``pids`` cgroup when the grader runs as root and
  can create one, ``RLIMIT_NPROC`` otherwise).

``mode`` is ``"bwrap"`` (sandboxed) or ``"none"`` (the kernel runs with the grader's rights:
only for machines without bubblewrap, e.g. macOS; the grader says so everywhere).  The limits
apply in both modes where the operating system supports them.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
import uuid
from dataclasses import asdict, dataclass
from pathlib import Path

import course_lib
from course_lib import own_work

LAUNCHER = Path(__file__).with_name("launch.py")
GIB = 1 << 30


@dataclass(frozen=True)
class Limits:
    memory_bytes: int = 4 * GIB
    cpu_seconds: int = 600
    file_bytes: int = 64 << 20
    processes: int = 64
    output_bytes: int = 1 << 20  # per cell, enforced by the grader (kernel killed past it)
    disk_bytes: int = 512 << 20  # the job folder (a size-limited tmpfs when the grader is root)
    tmp_bytes: int = 64 << 20  # the sandbox's /tmp, and its /dev/shm (RAM: tmpfs)


def bwrap_path() -> str | None:
    return shutil.which("bwrap")


def bwrap_works() -> tuple[bool, str]:
    """Can bubblewrap start a process here?  ``(ok, reason if not)``."""
    exe = bwrap_path()
    if exe is None:
        return False, "bubblewrap (bwrap) is not installed"
    try:
        proc = subprocess.run(
            [exe, "--unshare-all", "--die-with-parent", "--ro-bind", "/", "/", "true"],
            capture_output=True,
            timeout=20,
        )
    except (OSError, subprocess.TimeoutExpired) as exc:
        return False, f"bwrap could not start ({exc})"
    if proc.returncode != 0:
        return (
            False,
            f"bwrap could not start ({proc.stderr.decode(errors='replace').strip()[:200]})",
        )
    return True, ""


def _course_root() -> Path:
    return Path(course_lib.__file__).resolve().parent.parent


def _visible_paths() -> list[Path]:
    """Read-only paths the kernel needs: Python, the environment, course_lib -- nothing else."""
    root = _course_root()
    wanted = {
        Path(sys.base_prefix).resolve(),
        Path(sys.prefix).resolve(),
        Path(sys.executable).resolve().parent.parent,
    }
    temp = Path(tempfile.gettempdir()).resolve()
    for entry in sys.path:
        if not entry:
            continue  # the current folder: whatever the instructor ran the grader from
        p = Path(entry).resolve()
        if not p.is_dir() or p == temp or p in temp.parents:
            continue
        if p == root or root in p.parents:
            continue  # the checkout: only course_lib and the venv are shown (below)
        wanted.add(p)
    wanted.add(root / "course_lib")
    venv = Path(sys.prefix).resolve()
    wanted.add(venv)
    # drop paths inside other listed paths; never the course root itself
    out = sorted(wanted)
    kept: list[Path] = []
    for p in out:
        if p == root or p == Path("/") or any(k in p.parents for k in kept):
            continue
        if p in (Path("/usr"),) or Path("/usr") in p.parents:
            continue  # /usr is bound whole
        kept.append(p)
    return kept


_ETC = [
    "ld.so.cache",
    "ld.so.conf",
    "ld.so.conf.d",
    "localtime",
    "passwd",
    "group",
    "nsswitch.conf",
    "fonts",
    "alternatives",
    "mime.types",
    "ssl",
]


def _links_on_the_way(path: str | Path) -> list[tuple[str, str]]:
    """``(target, link)`` for every symbolic link met while resolving ``path``, in order.

    A venv or a checkout reached through a link (``/opt/course -> /srv/course-2026``) is seen
    in the sandbox only if the link is there too: the real folder is bound, the link remade.
    """
    links: list[tuple[str, str]] = []
    todo = Path(os.path.abspath(path))
    for _ in range(40):  # the kernel's own limit on nested links
        parts = todo.parts
        for i in range(2, len(parts) + 1):
            here = Path(*parts[:i])
            if here.is_symlink():
                target = os.readlink(here)
                links.append((target, str(here)))
                todo = Path(os.path.normpath(here.parent / target)).joinpath(*parts[i:])
                break
        else:
            return links
    return links


def _needed_links(bound: list[Path]) -> list[tuple[str, str]]:
    """Links to remake in the sandbox: on the way to Python, the environment, the checkout."""
    out: list[tuple[str, str]] = []
    for path in (sys.executable, sys.prefix, sys.exec_prefix, _course_root()):
        for target, link in _links_on_the_way(path):
            inside = [b for b in bound if Path(link) == b or b in Path(link).parents]
            if inside or link.startswith("/usr/") or (target, link) in out:
                continue  # visible already (bound whole), or remade once
            out.append((target, link))
    return out


def grader_state_path(job: Path) -> Path:
    """The grader's own file beside ``job`` that the sandbox shows read-only at
    ``own_work.GRADER_STATE_FILE`` (the runner writes it; the submission cannot)."""
    return job.parent / f"{job.name}.state"


def bwrap_argv(job: Path, limits: Limits | None = None) -> list[str]:
    """The bubblewrap command line (without the command) for a kernel in ``job``."""
    limits = limits or Limits()
    exe = bwrap_path()
    assert exe is not None
    argv = [
        exe,
        "--unshare-all",
        "--die-with-parent",
        "--new-session",
        "--cap-drop",
        "ALL",
        "--ro-bind",
        "/usr",
        "/usr",
    ]
    for top in ("/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"):
        p = Path(top)
        if p.is_symlink():
            argv += ["--symlink", os.readlink(p), top]
        elif p.is_dir():
            argv += ["--ro-bind", top, top]
    for name in _ETC:
        p = Path("/etc") / name
        if p.exists():
            argv += ["--ro-bind", str(p), str(p)]
    # /tmp and /dev/shm are RAM: bounded in size (and counted by the memory cgroup)
    size = str(max(1 << 20, int(limits.tmp_bytes)))
    argv += ["--proc", "/proc", "--dev", "/dev", "--size", size, "--tmpfs", "/dev/shm"]
    argv += ["--size", size, "--tmpfs", "/tmp"]
    visible = _visible_paths()
    for p in visible:
        argv += ["--ro-bind", str(p), str(p)]
    for target, link in _needed_links(visible):
        argv += ["--symlink", target, link]
    argv += ["--bind", str(job), str(job), "--chdir", str(job)]
    state = grader_state_path(job)  # which exercises are guarded now: the grader's, read-only
    if state.is_file():
        argv += ["--ro-bind", str(state), own_work.GRADER_STATE_FILE]
    # nothing else is writable: not the root bwrap builds, not /dev (both RAM, unbounded)
    argv += ["--remount-ro", "/dev", "--remount-ro", "/"]
    return argv


def kernel_environment(job: Path) -> dict[str, str]:
    """The kernel's whole environment (nothing of the grader's leaks in)."""
    env = {
        "HOME": str(job),
        "PATH": f"{Path(sys.executable).parent}:/usr/local/bin:/usr/bin:/bin",
        "LANG": "C.UTF-8",
        "MPLCONFIGDIR": str(job / ".config" / "matplotlib"),
        "IPYTHONDIR": str(job / ".ipython"),
        "JUPYTER_RUNTIME_DIR": str(job / ".runtime"),
        "JUPYTER_CONFIG_DIR": str(job / ".jupyter"),
        "XDG_CACHE_HOME": str(job / ".cache"),
        "TMPDIR": "/tmp",
        "PYDEVD_DISABLE_FILE_VALIDATION": "1",
        # the grader's own course_lib (the only part of the checkout the sandbox shows), even
        # when the environment's editable install points at another checkout
        "PYTHONPATH": str(_course_root()),
        "OPENBLAS_NUM_THREADS": "1",
        "OMP_NUM_THREADS": "1",
    }
    for key in ("OPENBLAS_CORETYPE", "OPENBLAS_L2_SIZE", "PYTHONHASHSEED"):
        if key in os.environ:
            env[key] = os.environ[key]
    return env


def _own_cgroups() -> dict[str, Path]:
    """controller -> the grader's own cgroup folder for it (v1 hierarchies, or v2's one)."""
    base = Path("/sys/fs/cgroup")
    found: dict[str, Path] = {}
    for line in _read(Path("/proc/self/cgroup")).splitlines():
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        _, controllers, rel = parts
        for ctrl in controllers.split(","):
            if ctrl in ("pids", "cpu", "memory"):
                for mount in (base / ctrl, base / controllers):
                    path = mount / rel.lstrip("/")
                    if (path / "cgroup.procs").exists():
                        found.setdefault(ctrl, path)
                        break
        if controllers == "" and (base / "cgroup.controllers").exists():  # pure cgroup v2
            path = base / rel.lstrip("/")
            for ctrl in _read(path / "cgroup.subtree_control").split():
                if ctrl in ("pids", "cpu", "memory"):
                    found.setdefault(ctrl, path)
    return found


class SandboxGroups:
    """Control groups of one sandbox (root only), nested in the grader's own groups.

    ``pids``: at most ``limits.processes`` processes; ``cpu``: the share of any other sandbox
    (``cpu.shares``/``cpu.weight``) and at most one core, whatever number of processes it
    starts; ``memory``: ``limits.memory_bytes`` for all its processes *and* the files they
    write into ``tmpfs`` (``/tmp``, ``/dev/shm``, a tmpfs job folder), which the address-space
    limit does not count.  ``paths`` is empty where none can be made (not root, no cgroups):
    then ``RLIMIT_NPROC``, ``nice`` and the size-limited tmpfs are what bound the sandbox.
    """

    def __init__(self, limits: Limits) -> None:
        self.paths: dict[str, Path] = {}
        if os.geteuid() != 0:
            return
        name = f"course-grader-{uuid.uuid4().hex[:12]}"
        for ctrl, parent in _own_cgroups().items():
            path = parent / name
            if path in self.paths.values():
                self.paths[ctrl] = path  # cgroup v2: one folder for every controller
                self._configure(ctrl, path, limits)
                continue
            try:
                path.mkdir()
            except OSError:
                continue
            self.paths[ctrl] = path
            if not self._configure(ctrl, path, limits):
                del self.paths[ctrl]
                if path not in self.paths.values():
                    _rmdir(path)

    @staticmethod
    def _configure(ctrl: str, path: Path, limits: Limits) -> bool:
        memory = limits.memory_bytes + 2 * limits.tmp_bytes
        settings = {
            "pids": [("pids.max", str(limits.processes))],
            "cpu": [("cpu.shares", "1024"), ("cpu.cfs_period_us", "100000"),
                    ("cpu.cfs_quota_us", "100000")]
            if (path / "cpu.shares").exists()
            else [("cpu.weight", "100"), ("cpu.max", "100000 100000")],
            "memory": [("memory.limit_in_bytes", str(memory))]
            if (path / "memory.limit_in_bytes").exists()
            else [("memory.max", str(memory)), ("memory.swap.max", "0")],
        }[ctrl]  # fmt: skip
        try:
            for key, value in settings:
                if key == "memory.swap.max" and not (path / key).exists():
                    continue
                (path / key).write_text(value)
        except OSError:
            return False
        return True

    @property
    def procs_files(self) -> list[str]:
        return sorted({str(p / "cgroup.procs") for p in self.paths.values()})

    def memory_exhausted(self) -> bool:
        """Did the memory limit stop the sandbox (an out-of-memory kill in its group)?"""
        path = self.paths.get("memory")
        if path is None:
            return False
        if (path / "memory.failcnt").exists():
            try:
                return int(_read(path / "memory.failcnt") or 0) > 0
            except ValueError:
                return False
        events = dict(
            line.split() for line in _read(path / "memory.events").splitlines() if " " in line
        )
        return int(events.get("oom_kill", 0) or 0) > 0

    def kill_and_remove(self, wait: float = 3.0) -> None:
        """Kill whatever is left in the groups and remove them (once the kernel reaped it)."""
        deadline = time.monotonic() + wait
        while self.paths:
            for path in set(self.paths.values()):
                for pid in _read(path / "cgroup.procs").split():
                    try:
                        os.kill(int(pid), 9)
                    except (OSError, ValueError):
                        pass
            for ctrl, path in list(self.paths.items()):
                if _rmdir(path) or not path.exists():
                    del self.paths[ctrl]
            if not self.paths or time.monotonic() > deadline:
                return  # still busy: an empty group costs nothing; never block the batch
            time.sleep(0.05)


def _rmdir(path: Path) -> bool:
    try:
        path.rmdir()
        return True
    except OSError:
        return False


def _read(path: Path) -> str:
    try:
        return path.read_text()
    except OSError:
        return ""


def launcher_argv(job: Path, mode: str, limits: Limits, groups: SandboxGroups | None) -> list[str]:
    """The launcher (cgroups, limits, environment), then bwrap (mode ``bwrap``)."""
    config = {
        **asdict(limits),
        "cgroups": groups.procs_files if groups is not None else [],
        "pids_group": bool(groups is not None and "pids" in groups.paths),
        "env": kernel_environment(job),
    }
    argv = [sys.executable, "-I", str(LAUNCHER), json.dumps(config), "--"]
    if mode == "bwrap":
        argv += bwrap_argv(job, limits)
    return argv


def kernel_argv(job: Path, mode: str, limits: Limits, groups: SandboxGroups | None) -> list[str]:
    """The kernel command: the launcher (limits), then bwrap (mode ``bwrap``), then ipykernel."""
    kernel = [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"]
    return [*launcher_argv(job, mode, limits, groups), *kernel]


_CHECK = """
import json, os, sys
for path in json.loads(sys.argv[1]):
    if not os.path.exists(path):
        print("MISSING", path)
        sys.exit(3)
import ipykernel, course_lib
print("OK")
"""


def visibility_problem(job: Path, limits: Limits, extra: tuple[str, ...] = ()) -> str:
    """``""`` when the sandbox sees Python, the environment and ``course_lib``; else why not.

    Runs the sandbox once (no kernel) with the kernel's environment: every path the kernel
    needs must exist inside it, and ``ipykernel`` and ``course_lib`` must import.  The message
    names the first path the sandbox could not see.
    """
    need = [sys.executable, sys.prefix, str(_course_root() / "course_lib"), *extra]
    argv = [*launcher_argv(job, "bwrap", limits, None), sys.executable, "-c", _CHECK]
    try:
        proc = subprocess.run(
            [*argv, json.dumps(need)], capture_output=True, timeout=120, cwd=str(job)
        )
    except (OSError, subprocess.TimeoutExpired) as exc:
        return f"the sandbox could not be started ({type(exc).__name__})"
    out = proc.stdout.decode(errors="replace")
    err = proc.stderr.decode(errors="replace").strip()
    if proc.returncode == 0 and "OK" in out:
        return ""
    for line in out.splitlines():
        if line.startswith("MISSING "):
            return f"the sandbox cannot see {line[len('MISSING ') :]}"
    if "execvp" in err:
        return f"the sandbox cannot see {sys.executable} (the Python that runs kernels)"
    last = err.splitlines()[-1] if err else f"exit code {proc.returncode}"
    return f"Python in the sandbox failed: {last[:300]}"
