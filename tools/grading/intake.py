"""Finding and opening submissions: regular files inside the submissions folder, never a link.

The grader reads submissions *outside* any sandbox, so what it opens must be what it claims:

* :func:`scan` walks the submissions folder without following a link: a notebook or a folder
  that is a symbolic link (to a classmate's notebook, to the course secret, anywhere) is
  reported -- "a link, not graded" -- and never opened; so is a notebook that is not a regular
  file (a FIFO, a device) or that has other names (a hard link);
* :func:`read_regular` opens a notebook again component by component with ``O_NOFOLLOW``
  relative to the submissions folder, checks that what it opened is a regular file with one
  name, and reads at most ``limit`` bytes -- so a link swapped in after the scan is refused too;
* names are shown with :func:`safe_names.display_name` (any bytes, printable, unambiguous).

Who the student is: a notebook directly in the folder is the student named by its file name
(``alice.ipynb`` -> ``alice``); a notebook in a sub-folder belongs to the student named by that
top-level folder (``alice/hw01.ipynb`` -> ``alice``).
"""

from __future__ import annotations

import errno
import os
import stat
from dataclasses import dataclass, field
from pathlib import Path

from .safe_names import display_name

__all__ = [
    "MAX_NOTEBOOK_BYTES",
    "Refused",
    "Scan",
    "read_regular",
    "refusal_note",
    "scan",
    "shown_path",
]

MAX_NOTEBOOK_BYTES = 50 << 20
LINK = "a link, not graded"
NOT_REGULAR = "not a regular file, not graded"
HARD_LINK = "a file with several names (a hard link), not graded"


class Refused(Exception):
    """A submission file the grader will not read; ``reason`` says why (no file content)."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


@dataclass
class Scan:
    """What :func:`scan` found.

    ``found``: ``(student, notebook to grade, other notebooks of that student)`` sorted by
    student; ``refused``: student -> ``[(shown path, reason), ...]`` for links and other files
    that were not opened.
    """

    found: list[tuple[str, Path, list[Path]]] = field(default_factory=list)
    refused: dict[str, list[tuple[str, str]]] = field(default_factory=dict)
    mtimes: dict[Path, float] = field(default_factory=dict)


def _hidden(name: str) -> bool:
    return name.startswith(".")


def _shown(rel: tuple[str, ...]) -> str:
    return "/".join(display_name(p) for p in rel)


def shown_path(path: Path, folder: Path) -> str:
    """``path`` relative to ``folder`` as printable text (:func:`safe_names.display_name`)."""
    return _shown(Path(path).relative_to(folder).parts)


def scan(folder: Path) -> Scan:
    """The submissions under ``folder``; links are listed as refused, never followed."""
    root = Path(folder)
    out = Scan()
    by_student: dict[str, list[Path]] = {}

    def refuse(student: str, rel: tuple[str, ...], reason: str) -> None:
        out.refused.setdefault(student, []).append((_shown(rel), reason))

    def consider(student: str, path: Path, rel: tuple[str, ...], st: os.stat_result) -> None:
        if stat.S_ISLNK(st.st_mode):
            refuse(student, rel, LINK)
        elif not stat.S_ISREG(st.st_mode):
            refuse(student, rel, NOT_REGULAR)
        elif st.st_nlink != 1:
            refuse(student, rel, HARD_LINK)
        else:
            by_student.setdefault(student, []).append(path)
            out.mtimes[path] = st.st_mtime

    with os.scandir(root) as it:
        top = sorted(it, key=lambda e: e.name)
    for entry in top:
        if _hidden(entry.name):
            continue
        path = root / entry.name
        st = entry.stat(follow_symlinks=False)
        if entry.name.endswith(".ipynb"):
            consider(display_name(entry.name[: -len(".ipynb")]), path, (entry.name,), st)
        elif stat.S_ISDIR(st.st_mode):
            _walk(path, (entry.name,), display_name(entry.name), consider, refuse)
        elif stat.S_ISLNK(st.st_mode) and os.path.isdir(path):  # stat only: never opened
            refuse(display_name(entry.name), (entry.name,), LINK)
    for student in sorted(by_student):
        files = sorted(by_student[student], key=lambda p: (-out.mtimes[p], str(p)))
        out.found.append((student, files[0], files[1:]))
    return out


def _walk(path: Path, rel: tuple[str, ...], student: str, consider, refuse) -> None:
    try:
        with os.scandir(path) as it:
            entries = sorted(it, key=lambda e: e.name)
    except OSError:
        refuse(student, rel, "a folder that could not be read, not graded")
        return
    for entry in entries:
        if _hidden(entry.name) or entry.name == ".ipynb_checkpoints":
            continue
        sub, sub_rel = path / entry.name, (*rel, entry.name)
        st = entry.stat(follow_symlinks=False)
        if entry.name.endswith(".ipynb"):
            consider(student, sub, sub_rel, st)
        elif stat.S_ISDIR(st.st_mode):
            _walk(sub, sub_rel, student, consider, refuse)
        elif stat.S_ISLNK(st.st_mode) and os.path.isdir(sub):
            refuse(student, sub_rel, LINK)


def read_regular(folder: Path, path: Path, limit: int = MAX_NOTEBOOK_BYTES) -> bytes:
    """The bytes of ``path`` (inside ``folder``), opened without following any link.

    Every component below ``folder`` is opened with ``O_NOFOLLOW`` relative to the previous
    one, so the file read is the one inside ``folder`` whatever was swapped in since the scan.

    Raises
    ------
    Refused
        ``path`` is not inside ``folder``, a component is a link, the file is not a regular
        file with a single name, or it is larger than ``limit`` bytes.
    """
    try:
        rel = Path(path).relative_to(folder).parts
    except ValueError:
        raise Refused("outside the submissions folder, not graded") from None
    if not rel or any(p in ("..", ".") for p in rel):
        raise Refused("outside the submissions folder, not graded")
    nofollow = getattr(os, "O_NOFOLLOW", 0)
    fds: list[int] = []
    try:
        try:
            fds.append(os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0)))
            for part in rel[:-1]:
                flags = os.O_RDONLY | getattr(os, "O_DIRECTORY", 0) | nofollow
                fds.append(os.open(part, flags, dir_fd=fds[-1]))
            flags = os.O_RDONLY | nofollow | getattr(os, "O_NONBLOCK", 0)
            fd = os.open(rel[-1], flags, dir_fd=fds[-1])
        except OSError as exc:
            # ELOOP / ENOTDIR: a link where a file or folder was expected
            link = exc.errno in (errno.ELOOP, errno.ENOTDIR)
            raise Refused(LINK if link else "could not be opened, not graded") from None
        fds.append(fd)
        st = os.fstat(fd)
        if not stat.S_ISREG(st.st_mode):
            raise Refused(NOT_REGULAR)
        if st.st_nlink != 1:
            raise Refused(HARD_LINK)
        if st.st_size > limit:
            raise Refused(f"larger than {limit >> 20} MB, not graded")
        chunks, left = [], limit + 1
        while left > 0:
            chunk = os.read(fd, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
        data = b"".join(chunks)
        if len(data) > limit:
            raise Refused(f"larger than {limit >> 20} MB, not graded")
        return data
    finally:
        for fd in reversed(fds):
            os.close(fd)


def refusal_note(entries: list[tuple[str, str]]) -> list[str]:
    """Notes for the feedback: which files were not opened, and why (never their content)."""
    return [f"{shown}: {reason}" for shown, reason in entries]


def load(folder: Path, found: Scan) -> dict[Path, bytes]:
    """Read every notebook to grade with :func:`read_regular`.

    A notebook refused now (swapped for a link since the scan) moves to ``found.refused``; a
    student left without a notebook is dropped from ``found.found``.
    """
    contents: dict[Path, bytes] = {}
    kept = []
    for student, path, others in found.found:
        for candidate in [path, *others]:
            try:
                contents[candidate] = read_regular(folder, candidate)
            except Refused as exc:
                rel = Path(candidate).relative_to(folder).parts
                found.refused.setdefault(student, []).append((_shown(rel), exc.reason))
                continue
            rest = [o for o in [path, *others] if o != candidate]
            kept.append((student, candidate, rest))
            break
    found.found = kept
    return contents
