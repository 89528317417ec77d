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
* limits set before exec: address space (``--memory``, default 4 GiB), CPU time, file size
  (the job folder's limit, ``--disk``), no core dumps, and the number of processes (a ``pids``
  cgroup when the grader runs as root and can create one, ``RLIMIT_NPROC`` otherwise);
* which limits a sandbox met is read from its own counters (``pids.events``,
  ``memory.failcnt`` / ``memory.events``, the free space of its ``/tmp`` and ``/dev/shm``, the
  peak address space of its processes), so a limit is named also when the student's code
  caught the error.

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
from course_lib.homework import answer_keys, own_work

LAUNCHER = Path(__file__).with_name("launch.py")
GIB = 1 << 30


@dataclass(frozen=True)
class Limits:
    """What one sandbox may use.

    ``file_bytes`` (the size of any one file, ``RLIMIT_FSIZE``) is by default the disk limit:
    a lower file-size limit would make ``--disk`` a lie (with the old fixed 64 MB, a job folder
    of ``--disk 128`` stopped at 64 MB for one big file, with "File too large").
    """

    memory_bytes: int = 4 * GIB
    cpu_seconds: int = 600
    file_bytes: int | None = None  # None: disk_bytes
    processes: int = 64
    output_bytes: int = 1 << 20  # per cell, enforced by the grader (kernel killed past it)
    disk_bytes: int = 512 << 20  # the job folder (a size-limited tmpfs when the grader is root)
    tmp_bytes: int = 64 << 20  # the sandbox's /tmp, and its /dev/shm (RAM: tmpfs)

    def __post_init__(self) -> None:
        if self.file_bytes is None:
            object.__setattr__(self, "file_bytes", int(self.disk_bytes))


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
    for lib in library_folders(_read(Path("/proc/self/maps"))):
        if lib == temp or lib in temp.parents or lib == root or root in lib.parents:
            continue  # never the temp folder whole (job roots) nor the checkout
        wanted.add(lib)
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


_SYSTEM_TOPS = frozenset(
    {"usr", "lib", "lib32", "lib64", "libx32", "bin", "sbin", "proc", "sys", "dev", "etc"}
)


def library_folders(maps: str) -> list[Path]:
    """The folders of the shared libraries mapped into a process (``/proc/<pid>/maps``'s text).

    The grader's Python may load libraries from outside its prefix: a ``RUNPATH`` fixed at
    build time (a relocated or hard-linked environment still loads ``libpython`` from where it
    was built), a conda or Nix store beside it.  The kernel in the sandbox needs them too.
    """
    found: set[Path] = set()
    for line in maps.splitlines():
        parts = line.split(None, 5)
        if len(parts) < 6:
            continue
        path = parts[5].strip()
        name = path.rsplit("/", 1)[-1]
        if not path.startswith("/") or path.endswith(" (deleted)"):
            continue
        if not (name.endswith(".so") or ".so." in name):
            continue
        folder = Path(os.path.normpath(path)).parent
        if folder.parts[1:2] and folder.parts[1] in _SYSTEM_TOPS:
            continue  # bound whole (bwrap_argv), or not libraries
        found.add(folder)
    return sorted(found)


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


def grader_keys_path(job: Path) -> Path:
    """The answer keys of the submission's own data, beside ``job``; the sandbox shows them
    read-only at ``answer_keys.GRADER_KEY_FILE``, so the notebook's checks work as at home."""
    return job.parent / f"{job.name}.keys.json"


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
    keys = grader_keys_path(job)
    if keys.is_file():
        argv += ["--ro-bind", str(keys), answer_keys.GRADER_KEY_FILE]
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


#: the controllers a sandbox uses
CONTROLLERS = ("pids", "cpu", "memory")
CGROUP_ROOT = Path("/sys/fs/cgroup")
#: every control group this grading process makes starts so (``course-grader-<run>-<job>``):
#: a check for groups left behind looks at its own run's only, whatever else runs on the host
RUN_PREFIX = f"course-grader-{os.getpid()}-{uuid.uuid4().hex[:8]}"


@dataclass(frozen=True)
class CgroupLayout:
    """What control groups the host offers the grader: a pure reading of what is mounted.

    ``version``: 1 (one hierarchy per controller, ``pids.max``, ``memory.limit_in_bytes``,
    ``cpu.shares``), 2 (the unified hierarchy: ``cgroup.controllers``, ``memory.max``,
    ``cpu.weight``) or 0 (none usable).  ``own``: controller -> the group in which a
    sandbox's group is made: the grader's own, or (v2) when that one enables no controller for
    children and is not the root, the nearest ancestor that does (v2 puts a process in one
    group only: every controller then has the same folder).  ``enable``: (v2) controllers the
    own group offers (``cgroup.controllers``) but has not yet enabled for its children
    (``cgroup.subtree_control``); enabling fails where the group holds processes.
    """

    version: int
    own: dict[str, Path]
    enable: tuple[str, ...] = ()


def cgroup_layout(base: Path, self_cgroup: str) -> CgroupLayout:
    """The layout of the control groups mounted at ``base``, for a process whose
    ``/proc/self/cgroup`` reads ``self_cgroup``.

    cgroup v2 when ``base`` itself is the unified hierarchy (it has ``cgroup.controllers``);
    else cgroup v1, each controller at ``base/<controller>`` or at a shared mount such as
    ``base/cpu,cpuacct`` (a v2 hierarchy beside them, ``base/unified``, holds no controller
    and is ignored).  Reads only files under ``base``.
    """
    base = Path(base)
    lines = [parts for parts in (ln.split(":", 2) for ln in self_cgroup.splitlines())
             if len(parts) == 3]  # fmt: skip
    if (base / "cgroup.controllers").is_file():
        rel = next((r for _, names, r in lines if names == ""), None)
        if rel is None:
            return CgroupLayout(0, {})
        own = base / rel.strip().lstrip("/")
        offered = _read(own / "cgroup.controllers").split()
        enabled = _read(own / "cgroup.subtree_control").split()
        usable = [c for c in CONTROLLERS if c in offered or c in enabled]
        if usable and own != base and not set(enabled) & set(CONTROLLERS):
            # A group holding processes (the grader's session scope) cannot enable controllers
            # for children ("no internal processes"); the nearest ancestor that has them on
            # for its children (a systemd slice) takes the sandboxes' groups instead.
            for parent in own.parents:
                on = [c for c in CONTROLLERS if c in _read(parent / "cgroup.subtree_control")]
                if on:
                    return CgroupLayout(2, dict.fromkeys(on, parent))
                if parent == base:
                    break
        return CgroupLayout(
            2 if usable else 0,
            dict.fromkeys(usable, own),
            tuple(c for c in usable if c not in enabled),
        )
    found: dict[str, Path] = {}
    for _, names, rel in lines:
        for ctrl in names.split(","):
            if ctrl not in CONTROLLERS or ctrl in found:
                continue
            for mount in (base / ctrl, base / names):
                path = mount / rel.strip().lstrip("/")
                if (path / "cgroup.procs").is_file():
                    found[ctrl] = path
                    break
    return CgroupLayout(1 if found else 0, found)


def host_cgroups() -> CgroupLayout:
    """This host's layout, for this process (:func:`cgroup_layout` of the real files)."""
    return cgroup_layout(CGROUP_ROOT, _read(Path("/proc/self/cgroup")))


def run_groups(layout: CgroupLayout | None = None) -> set[str]:
    """The control groups this grading process made and that still exist (none, once every
    sandbox has ended)."""
    layout = layout or host_cgroups()
    return {str(p) for own in set(layout.own.values()) for p in own.glob(f"{RUN_PREFIX}-*")}


def _settings(version: int, limits: Limits, memory: int) -> dict[str, list[tuple[str, str]]]:
    """controller -> the files (names as the kernel's documentation gives them) and values."""
    if version == 1:
        return {
            "pids": [("pids.max", str(limits.processes))],
            "cpu": [("cpu.shares", "1024"), ("cpu.cfs_period_us", "100000"),
                    ("cpu.cfs_quota_us", "100000")],
            "memory": [("memory.limit_in_bytes", str(memory))],
        }  # fmt: skip
    return {
        "pids": [("pids.max", str(limits.processes))],
        "cpu": [("cpu.weight", "100"), ("cpu.max", "100000 100000")],
        "memory": [("memory.max", str(memory)), ("memory.swap.max", "0")],
    }


#: written only where the kernel offers them (swap accounting may be off)
_OPTIONAL = frozenset({"memory.swap.max"})


def _events(path: Path) -> dict[str, int]:
    """A flat-keyed counter file (``pids.events``, ``memory.events``): key -> count."""
    out: dict[str, int] = {}
    for line in _read(path).splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[1].isdigit():
            out[parts[0]] = int(parts[1])
    return out


def _count(path: Path) -> int:
    text = _read(path).strip()
    return int(text) if text.isdigit() else 0


class SandboxGroups:
    """Control groups of one sandbox (root only), nested in the grader's own groups (cgroup
    v2: or in the nearest ancestor that enables the controllers, :class:`CgroupLayout`), named
    ``RUN_PREFIX-<job>``.

    ``pids``: at most ``limits.processes`` processes; ``cpu``: the share of any other sandbox
    (``cpu.shares``/``cpu.weight``) and at most one core, whatever number of processes it
    starts; ``memory``: ``limits.memory_bytes`` for all its processes *and* the files they
    write into ``tmpfs`` (``/tmp``, ``/dev/shm``, and the job folder when ``job_tmpfs``),
    which the address-space limit does not count.  ``paths`` is empty where none can be made
    (not root, no cgroups): then ``RLIMIT_NPROC``, ``nice`` and the size-limited tmpfs are
    what bound the sandbox.  ``layout`` and ``root_only`` are for tests (a fake cgroupfs).
    """

    def __init__(
        self,
        limits: Limits,
        *,
        job_tmpfs: bool = False,
        layout: CgroupLayout | None = None,
        root_only: bool = True,
    ) -> None:
        self.paths: dict[str, Path] = {}
        self.version = 0
        if root_only and os.geteuid() != 0:
            return
        layout = layout if layout is not None else host_cgroups()
        self.version = layout.version
        memory = limits.memory_bytes + 2 * limits.tmp_bytes
        if job_tmpfs:
            memory += limits.disk_bytes
        settings = _settings(layout.version, limits, memory)
        owns = dict(layout.own)
        for ctrl in layout.enable:  # v2: let the sandbox's group have the controller
            try:
                (owns[ctrl] / "cgroup.subtree_control").write_text(f"+{ctrl}")
            except OSError:
                del owns[ctrl]  # e.g. the grader's own group holds processes (not delegated)
        name = f"{RUN_PREFIX}-{uuid.uuid4().hex[:12]}"
        for ctrl, parent in owns.items():
            path = parent / name
            if path not in self.paths.values():
                try:
                    path.mkdir()
                except OSError:
                    continue
            self.paths[ctrl] = path
            if not _configure(path, settings[ctrl]):
                del self.paths[ctrl]
                if path not in self.paths.values():
                    _rmdir(path)

    @property
    def procs_files(self) -> list[str]:
        return sorted({str(p / "cgroup.procs") for p in self.paths.values()})

    def pids(self) -> list[int]:
        """The processes in the sandbox's groups now."""
        found: set[int] = set()
        for path in set(self.paths.values()):
            found |= {int(p) for p in _read(path / "cgroup.procs").split() if p.isdigit()}
        return sorted(found)

    def limits_reached(self) -> set[str]:
        """Which limits the sandbox met, by its groups' own counters: ``"processes"`` (a fork
        refused at ``pids.max``: ``pids.events`` ``max``), ``"memory"`` (v1
        ``memory.failcnt``; v2 ``memory.events`` ``max`` or ``oom_kill``) -- also when the
        student's code caught the error."""
        hit: set[str] = set()
        pids = self.paths.get("pids")
        if pids is not None and _events(pids / "pids.events").get("max", 0) > 0:
            hit.add("processes")
        mem = self.paths.get("memory")
        if mem is not None:
            if self.version == 1:
                met = _count(mem / "memory.failcnt") > 0
            else:
                events = _events(mem / "memory.events")
                met = events.get("max", 0) + events.get("oom_kill", 0) > 0
            if met:
                hit.add("memory")
        return hit

    def memory_exhausted(self) -> bool:
        """Did the memory limit stop the sandbox (an out-of-memory kill in its group)?"""
        path = self.paths.get("memory")
        if path is None:
            return False
        if self.version == 1:
            return _count(path / "memory.failcnt") > 0
        return _events(path / "memory.events").get("oom_kill", 0) > 0

    def kill_and_remove(self, wait: float = 3.0) -> None:
        """Kill whatever is left in the groups and remove them (once the kernel reaped it)."""
        deadline = time.monotonic() + wait
        while self.paths:
            for pid in self.pids():
                try:
                    os.kill(pid, 9)
                except OSError:
                    pass
            for ctrl, path in list(self.paths.items()):
                if _rmdir(path) or not path.exists():
                    del self.paths[ctrl]
            if not self.paths or time.monotonic() > deadline:
                return  # still busy: an empty group costs nothing; never block the batch
            time.sleep(0.05)


def process_limit_warning(limits: Limits, groups: type[SandboxGroups] | None = None) -> str:
    """One sentence when nothing would bound the number of a sandbox's processes, else "".

    ``RLIMIT_NPROC`` does not bind root, so a grader running as root needs the ``pids``
    cgroup; where none can be made (a container whose root group holds processes, a host
    without the controller) a fork bomb is bounded by nothing but the host.  ``groups`` is for
    tests (a fake cgroupfs).
    """
    if os.geteuid() != 0:
        return ""
    probe = (groups or SandboxGroups)(limits)
    try:
        if "pids" in probe.paths:
            return ""
    finally:
        probe.kill_and_remove()
    return (
        "warning: running as root without a usable pids cgroup, so nothing bounds the number "
        "of processes a submission starts (root ignores RLIMIT_NPROC); run the grader as an "
        "ordinary user, or on a host where the pids controller can be used"
    )


def _configure(path: Path, settings: list[tuple[str, str]]) -> bool:
    try:
        for key, value in settings:
            if key in _OPTIONAL and not (path / key).exists():
                continue
            (path / key).write_text(value)
    except OSError:
        return False
    return True


#: the sandbox's RAM-backed folders, checked for being full (a caught 'No space left')
TMPFS_MOUNTS = ("/tmp", "/dev/shm")


def full_tmpfs(pids: list[int], mounts: tuple[str, ...] = TMPFS_MOUNTS) -> set[str]:
    """Which of the sandbox's ``mounts`` are full (less than 1 % free), seen through
    ``/proc/<pid>/root`` of its processes; the grader's own folders of the same names (the
    processes outside the sandbox's mount namespace) are skipped."""
    own: dict[str, int] = {}
    for m in mounts:
        try:
            own[m] = os.stat(m).st_dev
        except OSError:
            own[m] = -1
    full: set[str] = set()
    for pid in pids:
        for m in mounts:
            if m in full:
                continue
            where = f"/proc/{pid}/root{m}"
            try:
                if os.stat(where).st_dev == own[m]:
                    continue
                sv = os.statvfs(where)
            except OSError:
                continue
            size = sv.f_blocks * sv.f_frsize
            if size and sv.f_bavail * sv.f_frsize * 100 <= size:
                full.add(m)
    return full


#: a process whose address space came this close to ``--memory`` had allocations refused
#: (``MemoryError``) or was about to: the kernel counts no refused allocation itself
NEAR_MEMORY_LIMIT = 0.9


def peak_address_space(pids: list[int]) -> int:
    """The largest ``VmPeak`` (bytes) of ``pids``: the most address space any of them held."""
    peak = 0
    for pid in pids:
        for line in _read(Path(f"/proc/{pid}/status")).splitlines():
            if line.startswith("VmPeak:"):
                parts = line.split()
                if len(parts) >= 2 and parts[1].isdigit():
                    peak = max(peak, int(parts[1]) * 1024)  # kB
                break
    return peak


def descendants(root: int) -> list[int]:
    """``root`` and every process below it (by ``/proc/<pid>/stat``'s parent field)."""
    children: dict[int, list[int]] = {}
    try:
        entries = [e for e in os.listdir("/proc") if e.isdigit()]
    except OSError:
        return [root]
    for entry in entries:
        try:
            stat_line = Path(f"/proc/{entry}/stat").read_text()
        except OSError:
            continue
        fields = stat_line.rsplit(")", 1)[-1].split()
        if len(fields) > 1 and fields[1].isdigit():
            children.setdefault(int(fields[1]), []).append(int(entry))
    out, todo = [], [root]
    while todo:
        pid = todo.pop()
        out.append(pid)
        todo += children.get(pid, [])
    return out


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
