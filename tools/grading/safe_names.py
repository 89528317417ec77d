"""Names and cells the grader writes: printable, unique by construction, never a formula.

Everything a submission names -- its file and folder names (any bytes an archive produced), the
student id in its manifest, the text of its answers -- ends up in files an instructor opens:
feedback files, ``results.json``, ``scores.csv`` in a spreadsheet or an LMS.  Three rules:

* :func:`display_name`: a file or folder name as text that can always be written (UTF-8) and
  shown: bytes that are not UTF-8 become ``\\xNN``, control and format characters (newlines,
  right-to-left overrides) become ``\\xNN`` / ``\\uNNNN``, a backslash becomes ``\\\\`` -- so two
  different names never give the same text;
* :func:`file_stems`: a file stem per student that is filesystem-safe and distinct from every
  other student's *even ignoring case*, whatever the names and in whatever order they come;
* :func:`csv_cell`: a spreadsheet cell never starts with ``=``, ``+``, ``-``, ``@``, a tab or a
  carriage return unless it is a plain number (OWASP's advice against CSV injection: such a
  cell is prefixed with ``'``).
"""

from __future__ import annotations

import csv
import dataclasses
import hashlib
import os
import re
import unicodedata
from typing import Any

__all__ = ["csv_cell", "display_name", "file_stems", "printable", "safe_csv_writer", "scrub"]

_SAFE = re.compile(r"[A-Za-z0-9._-]")
_NUMBER = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")
_FORMULA_START = ("=", "+", "-", "@", "\t", "\r")
_MAX_STEM = 100


def display_name(raw: str | bytes) -> str:
    """A file or folder name as writable, unambiguous text (see the module docstring).

    ``raw`` is a name as the file system gave it: bytes, or ``str`` with the surrogate escapes
    of :func:`os.fsdecode`.  The mapping is injective: distinct names give distinct texts.
    """
    if isinstance(raw, bytes):
        raw = os.fsdecode(raw)
    if not isinstance(raw, str):
        raise TypeError(f"raw must be str or bytes, got {type(raw).__name__}")
    out = []
    for ch in raw:
        code = ord(ch)
        if ch == "\\":
            out.append("\\\\")
        elif 0xDC80 <= code <= 0xDCFF:  # a byte that was not UTF-8 (surrogateescape)
            out.append(f"\\x{code - 0xDC00:02x}")
        elif unicodedata.category(ch) in ("Cc", "Cf", "Cs", "Co", "Cn", "Zl", "Zp"):
            out.append(f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}")
        else:
            out.append(ch)
    return "".join(out)


def printable(text: str) -> str:
    """``text`` made encodable as UTF-8 (lone surrogates escaped); anything else kept."""
    try:
        text.encode("utf-8")
        return text
    except UnicodeEncodeError:
        return text.encode("utf-8", "backslashreplace").decode("utf-8")


def scrub(value: Any) -> Any:
    """``value`` (a result: dataclass, dict, list, str) with every string made :func:`printable`.

    A student's manifest or answer may carry lone surrogates (JSON allows ``"\\ud800"``); one
    such string must not make writing the feedback or ``results.json`` fail.
    """
    if isinstance(value, str):
        return printable(value)
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        for f in dataclasses.fields(value):
            setattr(value, f.name, scrub(getattr(value, f.name)))
        return value
    if isinstance(value, dict):
        return {scrub(k): scrub(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return type(value)(scrub(v) for v in value)
    return value


def _slug(name: str) -> str:
    """Injective: safe characters kept, every other one ``%XX``; never contains ``~``."""
    text = "".join(
        ch
        if _SAFE.fullmatch(ch)
        else "".join(f"%{b:02X}" for b in ch.encode("utf-8", "surrogatepass"))
        for ch in name
    )
    if text.startswith((".", "-")):  # no hidden file, no file name read as an option
        text = f"%{ord(text[0]):02X}" + text[1:]
    return text or "%"


def _digest(name: str) -> str:
    return hashlib.sha256(name.encode("utf-8", "surrogatepass")).hexdigest()[:10]


def file_stems(students, taken: dict[str, str] | None = None) -> dict[str, str]:
    """A distinct, filesystem-safe file stem per student, distinct even ignoring case.

    Parameters
    ----------
    students : iterable of str
        The students' names (any text).
    taken : dict, optional
        Stems already given out (student -> stem); they are kept as they are, so a file once
        written for a student is never renamed when others arrive.

    Returns
    -------
    dict
        student -> stem, for the students of ``taken`` and ``students``.

    Notes
    -----
    A stem is the name with every character but ``A-Za-z0-9._-`` written ``%XX`` (injective);
    a long one is cut and ends in ``~`` and a digest.  A stem whose lower case is already used
    (``Alice`` after ``alice``, or a name crafted to look like another's stem) gets ``~2``,
    ``~3``, ... -- ``~`` never occurs in an escaped name, so no student can claim such a stem.
    """
    stems = dict(taken or {})
    used = {s.lower() for s in stems.values()}
    for student in sorted(set(students)):
        if student in stems:
            continue
        stem = _slug(student)
        if len(stem) > _MAX_STEM:
            stem = f"{stem[:_MAX_STEM]}~{_digest(student)}"
        candidate, n = stem, 1
        while candidate.lower() in used:
            n += 1
            candidate = f"{stem}~{n}"
        stems[student] = candidate
        used.add(candidate.lower())
    return stems


def csv_cell(value: Any) -> Any:
    """A spreadsheet cell that is never a formula (OWASP: prefix such text with ``'``).

    Numbers (``int``/``float``, and text that is exactly a plain decimal number such as
    ``"-0.5"``) are kept; any other text starting with ``=``, ``+``, ``-``, ``@``, a tab or a
    carriage return gets a leading ``'`` -- and so does text starting with ``+`` even when it
    reads as a number: the grader never writes one so, and a student named ``+1001`` must not
    show as ``1001`` beside the real student 1001.  Text is also made :func:`printable`.
    """
    if isinstance(value, bool) or value is None:
        return value
    if isinstance(value, int | float):
        return value
    text = printable(str(value))
    if text == "-":  # Moodle's own "no date": a lone minus is no formula, and must read back as-is
        return text
    if text.startswith(_FORMULA_START) and (text.startswith("+") or not _NUMBER.fullmatch(text)):
        return "'" + text
    return text


class _SafeWriter:
    """A :func:`csv.writer` whose every cell goes through :func:`csv_cell`."""

    def __init__(self, writer) -> None:
        self._writer = writer

    def writerow(self, row):
        return self._writer.writerow([csv_cell(v) for v in row])

    def writerows(self, rows):
        for row in rows:
            self.writerow(row)


def safe_csv_writer(fh, **kwargs) -> _SafeWriter:
    """``csv.writer(fh, **kwargs)`` that never writes a formula (see :func:`csv_cell`)."""
    return _SafeWriter(csv.writer(fh, **kwargs))
