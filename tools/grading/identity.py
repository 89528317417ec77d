"""Who handed a submission in, and what the instructor should know about it.

One identity per submission: it picks the roster row, the variant, the feedback file and the
gradebook row.  It is read, in this order of trust, from

1. the LMS's own download naming (the LMS recorded who uploaded the file):

   * Canvas, "Download Submissions": ``<name>_[LATE_]<canvas user id>_<submission id>_<file>``
     (``doejane_LATE_12345_67890_hw03-1001.ipynb``; ``LATE`` is Canvas's own late mark; a
     resubmission's file may carry ``-1``, ``-2`` before its extension);
   * Moodle, "Download all submissions": a folder ``<Full Name>_<participant id>_assignsubmission_file_``
     holding the file, or the flattened ``<Full Name>_<participant id>_assignsubmission_file_<file>``;

2. the file or folder name (``alice.ipynb``, ``alice/hw03.ipynb``; submit()'s
   ``hw03-1001.ipynb`` names student ``1001``);
3. the student id in the ``submit()`` manifest -- written on the student's machine, so it is
   used only when nothing else matches, and a manifest that names another roster student than
   the LMS/file match is flagged.

Flags are honest statements, never silent: they go into the status column, the feedback notes
and the class summary (:data:`FLAGS`).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from datetime import datetime, timedelta, timezone, tzinfo
from pathlib import Path, PurePosixPath

import nbformat

from course_lib.homework.submit import manifest_of

from . import intake

#: the flags an instructor acts on, as they appear in the status column (``ok; late; ...``)
EDITED = "edited after submit"
TIMES_DISAGREE = "manifest time disagrees"
ID_DIFFERS = "manifest id differs"
SEVERAL = "several notebooks"
LATE = "late"
NOT_IN_ROSTER = "not in the roster"
FILE_TIME_AFTER = "file time after deadline"  # Canvas says on time: Canvas decides
WRONG_CODE = "wrong variant code"
NO_CODE = "no variant code"
SHARED_CODE = "shared variant code"
TAMPERING = "reaches into the grader"  # the notebook's code (tools/grading/tamper.py)
TYPED_IN = "answer typed in"  # a value answer written as a long number (tools/grading/tamper.py)
FLAGS = (NOT_IN_ROSTER, EDITED, ID_DIFFERS, TIMES_DISAGREE, LATE, SEVERAL, WRONG_CODE,
         SHARED_CODE, NO_CODE, FILE_TIME_AFTER, TAMPERING, TYPED_IN)  # fmt: skip

#: a manifest time more than this after the file's own time cannot be true
CLOCK_SLACK_SECONDS = 600

# Canvas's "Download Submissions" names each file <sortable name, lower case, no punctuation>_
# [LATE_]<user id>_<submission id>_<the file's name>, e.g. smithbob_340934_208490284_BobsWork.zip
# (mikewesthad/canvas-unzipper README), name_LATE_canvasid_number_assignment.zip for a late one
# (HCI-Data-Analysis/HCI-data-analysis scripts/convert_zip_file/convert_zip_file_id.md); Moodle's
# "Download all submissions" <Full Name>_<participant id>_assignsubmission_file_<file's name>
# (gondree/canvas-offline-grading moodle_submissions.py: name, id, then the file after two
# fields), or the folder of that name with "Download submissions in folders" (Moodle's
# mod/assign/lang/en/assign.php, 'downloadasfolders_help').
_CANVAS = re.compile(
    r"^(?P<name>[a-z0-9-]+?)_(?:(?P<late>LATE)_)?(?P<uid>\d+)_(?P<sid>\d+)_(?P<file>.+)$"
)
_MOODLE_DIR = re.compile(r"^(?P<name>.+?)_(?P<pid>\d+)_assignsubmission_file_?$")
_MOODLE_FLAT = re.compile(r"^(?P<name>.+?)_(?P<pid>\d+)_assignsubmission_file_(?P<file>.+)$")
_SUBMIT_NAME = re.compile(r"^hw\d+-(?P<id>[A-Za-z0-9][A-Za-z0-9._@-]*?)(?:-\d+)?$")
_VARIANT = re.compile(r"^VARIANT\s*=\s*([\"'])(?P<code>[^\"'\n]*)\1", re.M)


@dataclass
class Found:
    """One notebook and what its name, the LMS and its manifest say about its author."""

    path: Path
    rel: str  # path relative to the submissions folder (posix)
    lms: str = "file"  # "canvas", "moodle" or "file": who named the file
    lms_id: str = ""  # Canvas user id / Moodle participant id
    lms_name: str = ""  # the LMS's name of the student (Canvas: "doejane"; Moodle: full name)
    lms_late: bool | None = None  # the LMS's own late mark (Canvas), None if it has none
    lms_time: datetime | None = None  # the LMS's record of the submission time (Moodle's worksheet)
    names: list[str] = field(default_factory=list)  # ids the file/folder name gives
    manifest: dict | None = None  # course_lib.homework.submit.manifest_of, or None
    mtime: datetime | None = None
    variant_used: str | None = None  # the VARIANT written in the notebook (None: none found)
    data: bytes | None = None  # the bytes read once, without following links (what is graded)

    @property
    def manifest_time(self) -> datetime | None:
        return self.manifest["time"] if self.manifest else None

    def order(self) -> tuple:
        """Newest submission last: a valid manifest's time, else the file's time."""
        valid = self.manifest is not None and not self.manifest["tampered"]
        when = self.manifest_time if valid else self.mtime
        return (when or datetime.min.replace(tzinfo=timezone.utc), self.rel)


def parse_name(rel: Path) -> Found:
    """What the file's path says: LMS naming (Canvas, Moodle) or a plain file/folder name."""
    f = Found(Path(), rel.as_posix())
    top = rel.parts[0]
    if len(rel.parts) == 1:
        m = _CANVAS.match(top)
        if m:
            f.lms, f.lms_id, f.lms_name = "canvas", m["uid"], m["name"]
            f.lms_late = bool(m["late"])
            f.names = _submit_names(Path(m["file"]).stem)
            return f
        m = _MOODLE_FLAT.match(top)
        if m:
            f.lms, f.lms_id, f.lms_name = "moodle", m["pid"], m["name"]
            f.names = _submit_names(Path(m["file"]).stem)
            return f
        f.names = [rel.stem, *_submit_names(rel.stem)]
        return f
    m = _MOODLE_DIR.match(top)
    if m:
        f.lms, f.lms_id, f.lms_name = "moodle", m["pid"], m["name"]
        f.names = _submit_names(Path(rel.parts[-1]).stem)
        return f
    f.names = [top]
    return f


def _submit_names(stem: str) -> list[str]:
    """submit() writes ``hw03-<id>.ipynb`` (an LMS may append ``-1`` to a resubmission)."""
    m = _SUBMIT_NAME.match(stem)
    return [m["id"]] if m else []


def read_notebook_facts(found: Found, data: bytes, mtime: float | None = None) -> Found:
    """The manifest, the file time and the ``VARIANT`` written in the notebook.

    A file that is not a notebook, or a hostile manifest, gives no facts (never an exception).
    ``data`` and ``mtime`` are the bytes and the time :mod:`intake` read (``read_regular``:
    no link followed); this function never opens ``found.path`` itself.
    """
    if not isinstance(data, bytes):
        raise TypeError(
            f"data must be the notebook's bytes as intake.read_regular returns them, not {type(data).__name__}"
        )
    try:
        found.data = data
        if mtime is not None:
            found.mtime = datetime.fromtimestamp(mtime, tz=timezone.utc)
        if len(data) > intake.MAX_NOTEBOOK_BYTES:
            return found
        nb = nbformat.reads(data.decode("utf-8"), as_version=4)  # the form submit() digested
    except Exception:  # unreadable or not a notebook: the grader reports it
        return found
    try:
        found.manifest = manifest_of(nb)
    except Exception:  # a hostile manifest is no manifest
        found.manifest = None
    for cell in nb.get("cells", []) if isinstance(nb.get("cells"), list) else []:
        if isinstance(cell, dict) and cell.get("cell_type") == "code":
            src = cell.get("source", "")
            src = "".join(src) if isinstance(src, list) else str(src)
            m = _VARIANT.search(src)
            if m:
                found.variant_used = m["code"]
                break
    return found


def discover(folder: Path, refused: dict[str, list[tuple[str, str]]] | None = None) -> list[Found]:
    """Every notebook under ``folder`` (hidden folders and checkpoints skipped), with its facts.

    Files are found and read by :mod:`intake`: never through a link, only regular files with
    one name inside ``folder``.  What it refuses is added to ``refused`` (shown student ->
    ``[(shown path, reason)]``) and never read.  Names are shown escaped
    (:func:`safe_names.display_name`), so any bytes a name has are safe to write.
    """
    folder = Path(folder)
    scan = intake.scan(folder)
    if refused is not None:
        for student, entries in scan.refused.items():
            refused.setdefault(student, []).extend(entries)
    out = []
    for student, path, others in scan.found:
        for f in [path, *others]:
            try:
                data = intake.read_regular(folder, f)
            except intake.Refused as exc:
                if refused is not None:
                    refused.setdefault(student, []).append(
                        (intake.shown_path(f, folder), exc.reason)
                    )
                continue
            found = parse_name(PurePosixPath(intake.shown_path(f, folder)))
            found.path = f
            out.append(read_notebook_facts(found, data, scan.mtimes.get(f)))
    return sorted(out, key=lambda x: x.rel)


class RosterIndex:
    """Every identifier of every roster entry -> the entry (ids, LMS ids, emails, names)."""

    def __init__(self, roster: dict) -> None:
        self.by_id: dict[str, object] = {}
        self.by_name: dict[str, list] = {}
        for entry in roster.values():
            for key in (entry.key, entry.id, *entry.aliases):
                if key:
                    self.by_id.setdefault(key.strip().lower(), entry)
            for name in (entry.name, *entry.names):
                if name:
                    self.by_name.setdefault(_name_key(name), []).append(entry)

    def get(self, key: str | None):
        return self.by_id.get(key.strip().lower()) if key else None

    def by_full_name(self, name: str):
        hits = self.by_name.get(_name_key(name), [])
        return hits[0] if len(hits) == 1 else None


def _name_key(name: str) -> str:
    return re.sub(r"[^a-z0-9]", "", name.lower())


@dataclass
class Identity:
    """Who a submission belongs to: the row key, the roster entry (if any), how it was found."""

    student: str
    entry: object | None
    how: str  # "lms", "name", "manifest"
    notes: list[str] = field(default_factory=list)  # for the student's feedback
    flags: list[str] = field(default_factory=list)
    #: for the instructor only (summary.md, results.json): per flag, the sentence that names
    #: another student (whose code, whose manifest)
    private: dict[str, str] = field(default_factory=dict)


def identify(found: Found, index: RosterIndex | None) -> Identity:
    """The one identity of a submission (see the module docstring for the order of trust)."""
    manifest_id = found.manifest["student"] if found.manifest else None
    if index is None:
        return _identify_without_roster(found, manifest_id)
    entry, how = _roster_entry(found, index, manifest_id)
    if entry is None:
        label = found.names[-1] if found.names else (found.lms_name or found.rel)
        if found.lms != "file":
            label = f"{found.lms_name}_{found.lms_id}"
        ident = Identity(label, None, "", flags=[NOT_IN_ROSTER])
        ident.notes.append(
            f"not in the roster ({found.rel}): map this submission to a student by hand"
        )
        return ident
    ident = Identity(entry.key, entry, how)
    if manifest_id and how != "manifest":
        _compare_manifest(ident, index, manifest_id)
    return ident


def _identify_without_roster(found: Found, manifest_id: str | None) -> Identity:
    """Without a roster: the LMS's naming, else the file or folder name, else the manifest."""
    if found.lms != "file":
        student = found.names[0] if found.names else f"{found.lms_name}_{found.lms_id}"
        how = "lms"
    elif found.names:
        student, how = found.names[-1] if len(found.names) > 1 else found.names[0], "name"
    else:
        student, how = manifest_id or found.rel, "manifest"
    ident = Identity(student, None, how)
    if manifest_id and manifest_id != student:
        ident.notes.append(f"the submission's manifest names student {manifest_id!r}")
    return ident


def _roster_entry(found: Found, index: RosterIndex, manifest_id: str | None):
    """``(roster entry or None, how it was found)``, in the order of trust."""
    if found.lms != "file":
        entry = index.get(found.lms_id)
        if entry is None and found.lms == "moodle":
            entry = index.by_full_name(found.lms_name)
        if entry is not None:
            return entry, "lms"
    for name in found.names:
        entry = index.get(name)
        if entry is not None:
            return entry, "name"
    if manifest_id:
        entry = index.get(manifest_id)
        if entry is not None:
            return entry, "manifest"
    return None, ""


def _compare_manifest(ident: Identity, index: RosterIndex, manifest_id: str) -> None:
    """The submit() manifest against the identity the LMS or the file name gave."""
    entry = ident.entry
    other = index.get(manifest_id)
    source = "LMS" if ident.how == "lms" else "file name"
    if other is not None and other is not entry:  # another roster student's submit()
        ident.flags.append(ID_DIFFERS)
        ident.notes.append(
            f"the submit() manifest names another roster student, but the {source} says "
            f"{entry.id}: graded as {entry.id}"
        )
        ident.private[ID_DIFFERS] = f"the manifest names roster student {other.id}"
    elif other is None:  # another form of id (an e-mail, a login): noted, not flagged
        ident.notes.append(
            f"the submit() manifest names student {manifest_id!r}; the {source} says {entry.id}"
        )


#: Moodle's grading worksheet ("Download grading worksheet", assignfeedback_offline: the grading
#: table downloaded) records each submission's time in this column, written by Moodle's
#: ``userdate()`` in the downloading user's time zone and language -- in English
#: "Tuesday, 8 December 2026, 11:59 PM" -- and "-" without a submission (mod/assign/lang/en/
#: assign.php: ``$string['lastmodifiedsubmission'] = 'Last modified (submission)'``;
#: gradingtable.php ``col_timesubmitted``: ``userdate($row->timesubmitted)``).  The file's own
#: time in a "Download all submissions" archive is not Moodle's record of the submission.
MOODLE_TIME_COLUMN = "Last modified (submission)"
_MOODLE_TIME_FORMATS = ("%A, %d %B %Y, %I:%M %p", "%A, %d %B %Y, %H:%M", "%d %B %Y, %I:%M %p")


def moodle_time(row: dict, tz: tzinfo) -> datetime | None:
    """Moodle's record of when the worksheet row's submission was made (``tz``: the worksheet's
    time zone, which Moodle does not write), or None (no submission, another language)."""
    text = " ".join(str(row.get(MOODLE_TIME_COLUMN) or "").split())
    for fmt in _MOODLE_TIME_FORMATS:
        try:
            return datetime.strptime(text, fmt).replace(tzinfo=tz)
        except ValueError:
            continue
    return None


def read_lms_time(found: Found, entry, deadline: datetime | None) -> list[str]:
    """Set ``found.lms_time`` from the LMS's record of the roster ``entry``, if it has one.

    Moodle: a notebook from its "Download all submissions" archive whose participant's row of
    the roster (Moodle's grading worksheet) records the submission time.  The worksheet writes
    local times without a zone: they are read in the deadline's zone (UTC without a deadline).
    Returns notes for the feedback (a time that could not be read).
    """
    if found.lms != "moodle" or entry is None or MOODLE_TIME_COLUMN not in getattr(entry, "row", {}):
        return []
    zone = deadline.tzinfo if deadline is not None and deadline.tzinfo else timezone.utc
    found.lms_time = moodle_time(entry.row, zone)
    text = entry.row[MOODLE_TIME_COLUMN]
    if found.lms_time is None and text not in ("", "-"):
        return [f"Moodle's submission time {text!r} could not be read (the worksheet is read in "
                "English): the file's time is used"]  # fmt: skip
    return []


def time_flags(found: Found, deadline: datetime | None) -> tuple[datetime | None, str, list[str], list[str]]:
    """``(submission time, its source, flags, notes)``: the LMS's record, else the file's time.

    The LMS's record: Canvas's late mark in its download's file names (``_LATE_``), Moodle's
    submission time from its grading worksheet (:func:`moodle_time`, set as ``lms_time``).

    The manifest's time is written on the student's machine: it is never used alone, only
    compared with the trusted time, and a disagreement is flagged.
    """
    flags, notes = [], []
    when, source = found.mtime, "file time"
    m_time = found.manifest_time
    if found.lms_time is not None:  # Moodle's record: used, the manifest's time only compared
        when, source = found.lms_time, "Moodle: submission time"
        ahead = m_time is not None and (m_time - found.lms_time).total_seconds() > CLOCK_SLACK_SECONDS
        sides = (m_time is not None and deadline is not None
                 and (m_time > deadline) != (found.lms_time > deadline))  # fmt: skip
        if ahead or sides:
            flags.append(TIMES_DISAGREE)
            notes.append(
                f"the submit() manifest says {m_time.isoformat(timespec='seconds')}, Moodle "
                f"recorded the submission at {found.lms_time.isoformat(timespec='seconds')}: "
                "Moodle's time is used"
            )
        return when, source, flags, notes
    if found.lms_late is not None and deadline is not None:
        source = "Canvas: late" if found.lms_late else "Canvas: on time"
        if found.lms_late:  # late by the file's time, and at least one started day
            later = deadline + timedelta(seconds=1)
            when = found.mtime if found.mtime and found.mtime > later else later
        else:
            when = min(found.mtime, deadline) if found.mtime else deadline
            if found.mtime is not None and found.mtime > deadline:
                notes.append(
                    f"the file's time {found.mtime.isoformat(timespec='seconds')} is after the "
                    "deadline, but Canvas marked the upload on time: Canvas's verdict is used "
                    "(no penalty; a file's time can also be when it was unpacked)"
                )
                if m_time is None:  # no submit() time backs Canvas's verdict up: have a look
                    flags.append(FILE_TIME_AFTER)
        if m_time is not None and (m_time > deadline) != found.lms_late:
            flags.append(TIMES_DISAGREE)
            notes.append(
                f"the submit() manifest says {m_time.isoformat(timespec='seconds')}, but "
                f"Canvas marked the upload {'late' if found.lms_late else 'on time'}"
            )
        return when, source, flags, notes
    if m_time is not None and found.mtime is not None:
        ahead = (m_time - found.mtime).total_seconds() > CLOCK_SLACK_SECONDS
        sides = deadline is not None and (m_time > deadline) != (found.mtime > deadline)
        if ahead or sides:
            flags.append(TIMES_DISAGREE)
            notes.append(
                f"the submit() manifest says {m_time.isoformat(timespec='seconds')}, the file's "
                f"time is {found.mtime.isoformat(timespec='seconds')}: the file's time is used"
            )
    return when, source, flags, notes
