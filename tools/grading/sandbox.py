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
import time
import uuid
from dataclasses import asdict, dataclass
from pathlib import Path

import course_lib

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
    for entry in sys.path:
        p = Path(entry or ".").resolve()
        if not p.is_dir():
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


def bwrap_argv(job: Path) -> list[str]:
    """The bubblewrap command line (without the command) for a kernel in ``job``."""
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
    argv += ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"]
    for p in _visible_paths():
        argv += ["--ro-bind", str(p), str(p)]
    argv += ["--bind", str(job), str(job), "--chdir", str(job)]
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


class ProcessGroupLimit:
    """A ``pids`` cgroup for one sandbox (root only); ``path`` is None where none can be made."""

    def __init__(self, limit: int) -> None:
        self.path: Path | None = None
        if os.geteuid() != 0:
            return
        for base in (Path("/sys/fs/cgroup/pids"), Path("/sys/fs/cgroup")):
            if not (base / "cgroup.procs").exists():
                continue
            if base == Path("/sys/fs/cgroup") and "pids" not in _read(base / "cgroup.controllers"):
                continue
            path = base / f"course-grader-{uuid.uuid4().hex[:12]}"
            try:
                path.mkdir()
                (path / "pids.max").write_text(str(limit))
            except OSError:
                try:
                    path.rmdir()
                except OSError:
                    pass
                continue
            self.path = path
            return

    def kill_and_remove(self, wait: float = 3.0) -> None:
        """Kill whatever is left in the group and remove it (once the kernel has reaped it)."""
        if self.path is None:
            return
        deadline = time.monotonic() + wait
        while True:
            pids = _read(self.path / "cgroup.procs").split()
            for pid in pids:
                try:
                    os.kill(int(pid), 9)
                except (OSError, ValueError):
                    pass
            try:
                self.path.rmdir()
                self.path = None
                return
            except OSError:
                if time.monotonic() > deadline:
                    return  # still busy: an empty group costs nothing; never block the batch
                time.sleep(0.05)


def _read(path: Path) -> str:
    try:
        return path.read_text()
    except OSError:
        return ""


def kernel_argv(job: Path, mode: str, limits: Limits, cgroup: ProcessGroupLimit) -> list[str]:
    """The kernel command: the launcher (limits), then bwrap (mode ``bwrap``), then ipykernel."""
    config = {
        **asdict(limits),
        "cgroup": str(cgroup.path) if cgroup.path else None,
        "env": kernel_environment(job),
    }
    argv = [sys.executable, "-I", str(LAUNCHER), json.dumps(config), "--"]
    if mode == "bwrap":
        argv += bwrap_argv(job)
    argv += [sys.executable, "-m", "ipykernel_launcher", "-f", "{connection_file}"]
    return argv
