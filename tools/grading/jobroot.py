"""Where job folders live: a private directory nobody else can have prepared.

Each submission is run in a job folder (a copy of its notebook, its kernel's sockets, the
probe's response files).  Job folders are made with :func:`tempfile.mkdtemp` inside a *job
root*:

* by default a fresh private directory, ``mkdtemp`` in the system temp folder (mode 0700, a
  name nobody can predict), made once per grading process and removed when it ends;
* ``--job-root DIR``: a directory the instructor chose, created with mode 0700 or, if it
  exists, used only when it is a real directory (not a link), owned by the grader's user and
  closed to everyone else -- on a shared host (a JupyterHub server) another local user who
  created it first could otherwise swap job folders.

:func:`job_folder` makes one job folder, on a size-limited ``tmpfs`` when the grader runs as
root and may mount one (a hard bound on the disk a submission can fill), else a plain folder
(bounded by the file-size limit and checked afterwards).
"""

from __future__ import annotations

import atexit
import os
import shutil
import stat
import subprocess
import tempfile
import threading
from pathlib import Path

__all__ = [
    "check_root",
    "job_folder",
    "job_root",
    "remove_job_folder",
    "response_folder",
    "used_bytes",
]

_LOCK = threading.Lock()
_DEFAULT: dict[int, Path] = {}  # pid -> this process's private root


def check_root(path: Path) -> Path:
    """``path`` as a job root: created 0700, or verified to be private.

    Raises
    ------
    ValueError
        ``path`` is a link, not a directory, owned by another user, or open to others.
    """
    path = Path(path)
    try:
        os.mkdir(path, 0o700)
    except FileExistsError:
        pass
    st = os.lstat(path)
    if stat.S_ISLNK(st.st_mode):
        raise ValueError(f"job root {path}: is a symbolic link; use a real directory")
    if not stat.S_ISDIR(st.st_mode):
        raise ValueError(f"job root {path}: is not a directory")
    if st.st_uid != os.geteuid():
        raise ValueError(
            f"job root {path}: owned by uid {st.st_uid}, not by the grader (uid {os.geteuid()})"
        )
    if st.st_mode & 0o077:
        raise ValueError(
            f"job root {path}: mode {stat.S_IMODE(st.st_mode):o} lets others in; "
            "it must be 700 (chmod 700, or choose another folder)"
        )
    return path


def job_root(configured: str | os.PathLike | None = None) -> Path:
    """The job root: ``configured`` (checked by :func:`check_root`) or this process's own."""
    if configured:
        return check_root(Path(configured))
    with _LOCK:
        pid = os.getpid()
        if pid not in _DEFAULT:  # a forked worker makes its own
            root = Path(tempfile.mkdtemp(prefix="course-grader-"))
            _DEFAULT[pid] = root
            atexit.register(_remove_default, root, pid)
        return _DEFAULT[pid]


def _remove_default(root: Path, pid: int) -> None:
    if os.getpid() == pid:
        shutil.rmtree(root, ignore_errors=True)


def _can_mount() -> bool:
    return os.geteuid() == 0 and shutil.which("mount") is not None and os.name == "posix"


def _mount_tmpfs(path: Path, size: int) -> bool:
    options = f"size={int(size)},mode=0700,nosuid,nodev"
    proc = subprocess.run(
        ["mount", "-t", "tmpfs", "-o", options, "course-grader-job", str(path)],
        capture_output=True,
        timeout=20,
    )
    return proc.returncode == 0


def job_folder(root: Path, disk_bytes: int | None) -> tuple[Path, bool]:
    """A new private job folder in ``root``: ``(path, on a size-limited tmpfs?)``."""
    job = Path(tempfile.mkdtemp(prefix="job-", dir=root))
    if disk_bytes and _can_mount() and _mount_tmpfs(job, disk_bytes):
        return job, True
    return job, False


def response_folder(job: Path, size: int, mounted: bool) -> Path:
    """``job/.grader``, where the probe writes its answers: its own small tmpfs when ``job``
    is one, so a submission that fills its job folder still has its answers read."""
    folder = job / ".grader"
    folder.mkdir(mode=0o700)
    if mounted:
        _mount_tmpfs(folder, size)
    return folder


def remove_job_folder(job: Path, mounted: bool) -> None:
    """Remove a job folder made by :func:`job_folder` (unmounting its tmpfs first)."""
    if mounted:  # the job folder and the response folder inside it
        subprocess.run(
            ["umount", "--lazy", "--recursive", str(job)], capture_output=True, timeout=20
        )
    shutil.rmtree(job, ignore_errors=True)
    if job.exists():  # a folder the student made unwritable: open it up, try once more
        for dirpath, dirnames, _ in os.walk(job):
            for d in dirnames:
                try:
                    os.chmod(os.path.join(dirpath, d), 0o700)
                except OSError:
                    pass
        shutil.rmtree(job, ignore_errors=True)


def used_bytes(job: Path, stop_at: int | None = None) -> int:
    """Bytes of files under ``job`` (links not followed; stops counting past ``stop_at``).

    Every entry counts at least 4 KiB (a million empty files fill a disk's inodes too).
    """
    total = 0
    for dirpath, dirnames, filenames in os.walk(job):
        for name in filenames + dirnames:
            try:
                total += max(4096, os.lstat(os.path.join(dirpath, name)).st_blocks * 512)
            except OSError:
                pass
            if stop_at is not None and total > stop_at:
                return total
    return total
