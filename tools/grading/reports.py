"""What the grader writes: score tables for a gradebook, feedback files, a class summary.

* ``scores.csv`` in one of three layouts (``--format``):

  - ``plain``: one row per student (``student``, roster columns when a roster is given, points
    per question, ``raw_total``, ``late_penalty``, ``total``, ``status``, ``sandbox``); the
    maximum is *not* a row (it is in ``summary.md`` and ``results.json``), so a spreadsheet or an
    LMS never mistakes it for a student;
  - ``canvas``: Canvas's gradebook import layout (``Student, ID, SIS User ID, SIS Login ID,
    Section, <assignment>``, then the ``Points Possible`` row);
  - ``moodle``: Moodle's grade import layout (an identifier column to map on, then the grade and
    a feedback column);
* ``feedback/<student>.md``: points, the reason for every lost point, the late rule applied;
* ``results.json``: everything above, machine-readable; ``--only STUDENT`` merges into it;
* ``summary.md`` and ``histogram.png``: mean, median, per-question success rate, the score
  distribution, submissions without a roster entry and roster students without a submission.

Every file is replaced atomically, after every graded submission.
"""

from __future__ import annotations

import csv
import io
import json
import math
import os
import re
import statistics
import uuid
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path

from .safe_names import safe_csv_writer

FORMATS = ("plain", "canvas", "moodle")


def atomic_write(path: Path, data: str | bytes) -> None:
    tmp = path.with_name(f".{path.name}.{uuid.uuid4().hex[:8]}.tmp")
    if isinstance(data, bytes):
        tmp.write_bytes(data)
    else:
        tmp.write_text(data, encoding="utf-8")
    os.replace(tmp, path)


# ---------------------------------------------------------------------------- roster


@dataclass(frozen=True)
class RosterEntry:
    key: str  # what a submission is matched on first (the ``submission`` column, else ``id``)
    id: str  # the roster id: variant codes are made from it (tools/variant.py codes)
    name: str
    email: str
    aliases: tuple[str, ...] = ()  # other ids that identify the student (LMS ids, SIS, e-mail)
    names: tuple[str, ...] = ()  # other spellings of the name (Moodle's download folders)
    row: dict = field(default_factory=dict)  # the LMS export's row, to write grades back


class Roster(dict):
    """``key -> RosterEntry``; ``kind`` is ``plain``, ``canvas``, ``moodle-worksheet`` or
    ``moodle-grades`` (the export it was read from), ``fields`` that export's columns."""

    kind = "plain"
    fields: tuple[str, ...] = ()
    #: Canvas's "Points Possible" row (column -> text), when the export has one
    points_possible: dict[str, str] | None = None
    #: roster entries skipped on purpose (Canvas's "Test Student")
    skipped: tuple[str, ...] = ()


#: a Canvas gradebook export: these columns, then one per assignment; its second row is
#: "Points Possible" (and newer exports add posting-policy rows): rows without an ID are skipped
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")


def _kind(fields: list[str]) -> str:
    names = {f.strip().lower() for f in fields}
    if {"student", "id", "sis user id"} <= names:
        return "canvas"
    if "identifier" in names and "full name" in names:
        return "moodle-worksheet"  # Moodle's assignment "grading worksheet"
    if "email address" in names and ("first name" in names or "id number" in names):
        return "moodle-grades"  # Moodle's gradebook export / participants list
    return "plain"


def read_roster(path: Path) -> Roster:
    """A roster: the course's CSV, or an LMS export as downloaded.

    * plain: ``id`` (the roster id) and optionally ``submission`` (the file/folder name or
      manifest id the submissions carry), ``name``, ``email``;
    * Canvas gradebook export (``Student, ID, SIS User ID, SIS Login ID, Section, ...``): the
      roster id is the SIS User ID (else the SIS Login ID, else Canvas's ID); Canvas's user id
      matches its "Download Submissions" files;
    * Moodle grading worksheet (``Identifier, Full name, Email address, ...``): the roster id is
      the ``ID number`` column when present, else the e-mail; ``Participant N`` matches Moodle's
      download folders;
    * Moodle grades export (``First name, Last name, ID number, ..., Email address``): the
      roster id is the ID number, else the e-mail.
    """
    with open(path, newline="", encoding="utf-8-sig") as fh:
        reader = csv.DictReader(fh)
        fields = [f for f in reader.fieldnames or []]
        kind = _kind(fields)
        if kind == "plain" and "id" not in {f.strip().lower() for f in fields}:
            raise SystemExit(
                f"--roster {path}: needs an 'id' column, or a Canvas/Moodle export "
                f"(found {sorted(fields)})"
            )
        roster = Roster()
        roster.kind, roster.fields = kind, tuple(fields)
        roster.points_possible, skipped = {}, []
        for n, raw in enumerate(reader, start=2):
            raw = {k.strip(): (v or "").strip() for k, v in raw.items() if k}
            if kind == "canvas" and raw.get("Student", "").startswith("Points Possible"):
                roster.points_possible = raw
                continue
            if kind == "canvas" and _canvas_test_student(raw):
                skipped.append(raw.get("Student", ""))
                continue
            entry = _entry(kind, raw)
            if entry is None:
                continue
            if not entry.id:
                raise SystemExit(f"--roster {path}, line {n}: empty id")
            if entry.key in roster:
                raise SystemExit(f"--roster {path}, line {n}: {entry.key!r} appears twice")
            roster[entry.key] = entry
    roster.skipped = tuple(skipped)
    return roster


def _canvas_test_student(raw: dict) -> bool:
    """Canvas's "Test Student" (Student View): no SIS id, named "Student, Test"."""
    name = " ".join(raw.get("Student", "").replace(",", " ").split()).lower()
    no_sis = not raw.get("SIS User ID") and not raw.get("SIS Login ID")
    return no_sis and name in ("student test", "test student")


def _entry(kind: str, raw: dict) -> RosterEntry | None:
    low = {k.lower(): v for k, v in raw.items()}
    if kind == "canvas":
        if not low.get("id") or low.get("student", "").startswith("Points Possible"):
            return None  # "Points Possible", posting-policy rows: not students
        rid = low.get("sis user id") or low.get("sis login id") or low["id"]
        aliases = tuple(a for a in (low["id"], low.get("sis user id"), low.get("sis login id")) if a)
        name = low.get("student", "")
        return RosterEntry(rid, rid, name, "", aliases, _name_forms(name), raw)
    if kind == "moodle-worksheet":
        ident = low.get("identifier", "")
        participant = re.sub(r"\D", "", ident)
        email = low.get("email address", "")
        rid = low.get("id number") or email or participant
        aliases = tuple(a for a in (participant, email, low.get("id number")) if a)
        name = low.get("full name", "")
        return RosterEntry(rid, rid, name, email, aliases, (), raw)
    if kind == "moodle-grades":
        email = low.get("email address", "")
        rid = low.get("id number") or email
        name = f"{low.get('first name', '')} {low.get('last name', '')}".strip()
        aliases = tuple(a for a in (email, low.get("id number")) if a)
        return RosterEntry(rid, rid, name, email, aliases, (), raw)
    if not low.get("id"):
        return RosterEntry("", "", "", "")
    key = low.get("submission") or low["id"]
    return RosterEntry(key, low["id"], low.get("name", ""), low.get("email", ""), (), (), raw)


def _name_forms(name: str) -> tuple[str, ...]:
    """Canvas names download files ``lastfirst`` from its "Last, First" sortable name."""
    if "," in name:
        last, first = (p.strip() for p in name.split(",", 1))
        return (f"{first} {last}", f"{last}{first}")
    parts = name.split()
    return (f"{parts[-1]}{''.join(parts[:-1])}",) if len(parts) > 1 else ()


# ---------------------------------------------------------------------------- late rule


@dataclass(frozen=True)
class LatePolicy:
    deadline: datetime
    per_day: float  # fraction of the points lost per started day late

    def describe(self) -> str:
        return (
            f"deadline {self.deadline:%Y-%m-%d %H:%M %Z}; "
            f"{self.per_day:.0%} of the points off per started day late"
        )

    def apply(self, submitted: datetime | None) -> tuple[int, float]:
        """``(started days late, fraction of the points lost)``."""
        if submitted is None or submitted <= self.deadline:
            return 0, 0.0
        days = math.ceil((submitted - self.deadline).total_seconds() / 86400)
        return days, min(1.0, days * self.per_day)


def parse_deadline(text: str) -> datetime:
    try:
        when = datetime.fromisoformat(text)
    except ValueError:
        raise SystemExit(
            f"--deadline {text!r}: use ISO 8601, e.g. 2026-12-01T23:59+01:00"
        ) from None
    return when if when.tzinfo else when.replace(tzinfo=timezone.utc)


def parse_penalty(text: str) -> float:
    value = text.strip().removesuffix("/day").strip()
    try:
        fraction = float(value.removesuffix("%")) / 100 if value.endswith("%") else float(value)
    except ValueError:
        raise SystemExit(f"--late-penalty {text!r}: e.g. '10%' (per started day)") from None
    if not 0 <= fraction <= 1:
        raise SystemExit(f"--late-penalty {text!r}: must be between 0% and 100% per day")
    return fraction


# ---------------------------------------------------------------------------- tables


def final_total(r) -> float:
    return round(r.total * (1 - r.penalty), 2)


def notes_text(r, tests) -> str:
    """Per-question feedback in one line (Moodle's feedback column): points and the reason."""
    parts = [f"{final_total(r):g}/{tests.max_points:g}"]
    for q in tests.points:
        if tests.points[q] == 0:
            continue
        note = r.notes.get(q, "").replace("\n", " ").strip()
        mark = "✓" if r.right(q, tests.points[q]) else (note or "wrong answer")
        parts.append(f"{q} {r.points[q]:g}/{tests.points[q]:g} {mark}")
    if r.penalty:
        parts.append(f"late: {r.penalty:.0%} off")
    return "; ".join(parts)


#: columns of a Canvas export that are not assignments (totals, group scores, grades)
_CANVAS_TOTALS = re.compile(r"(current|final|unposted).*(score|grade|points)$|points$", re.I)


def canvas_assignments(roster) -> list[str]:
    """The assignment columns of a Canvas gradebook export, as headed there."""
    possible = getattr(roster, "points_possible", {}) or {}
    out = []
    for f in getattr(roster, "fields", ())[len(CANVAS_COLUMNS):]:
        name = f.strip()
        if not name or "read only" in possible.get(name, "").lower():
            continue
        if not possible and _CANVAS_TOTALS.search(name):
            continue
        out.append(name)
    return out


def canvas_column(roster, assignment: str) -> str | None:
    """The export's column for ``assignment``: its exact header (with Canvas's ``(id)``),
    matched with or without that suffix, case-insensitively; ``None`` if there is none."""
    want = " ".join(assignment.split()).lower()
    for f in canvas_assignments(roster):
        low = " ".join(f.split()).lower()
        if low == want or re.sub(r"\s*\(\d+\)$", "", low) == want:
            return f
    return None


def lms_maximum(roster, fmt: str, column: str | None) -> float | None:
    """The assignment's maximum as the LMS export states it (Canvas's Points Possible row,
    Moodle's worksheet "Maximum Grade"), else ``None``."""
    text = ""
    if fmt == "canvas" and column:
        text = (getattr(roster, "points_possible", {}) or {}).get(column, "")
    elif fmt == "moodle" and getattr(roster, "kind", "") == "moodle-worksheet":
        found = {e.row.get("Maximum Grade", "") for e in roster.values()} - {""}
        text = found.pop() if len(found) == 1 else ""
    try:
        value = float(text.replace(",", "."))
    except ValueError:
        return None
    return value if value > 0 else None


def lms_score(r, tests, lms_max: float | None) -> float:
    """The score written into the import file: scaled to the LMS's maximum when it has one."""
    if not lms_max or not tests.max_points:
        return final_total(r)
    return round(final_total(r) * lms_max / tests.max_points, 2)


def scale_note(r, tests, lms_max: float | None, lms: str) -> str:
    """``11/11 → 100/100 in Canvas`` (or why the score is written unscaled)."""
    if lms_max is None:
        return f"{final_total(r):g}/{tests.max_points:g} (written as is: the {lms} export gives no maximum)"
    return f"{final_total(r):g}/{tests.max_points:g} → {lms_score(r, tests, lms_max):g}/{lms_max:g} in {lms}"


def scores_table(
    results,
    tests,
    fmt: str,
    roster: dict[str, RosterEntry] | None,
    assignment: str,
    lms_max: float | None = None,
) -> str:
    """``scores.csv`` in ``fmt``.  The Canvas and Moodle layouts are import files: a row whose
    submission matched no roster entry is never in them (the summary lists it).  ``assignment``
    is the import column's exact header; ``lms_max`` the LMS's maximum the scores are scaled to."""
    questions = list(tests.points)
    buf = io.StringIO()
    w = safe_csv_writer(buf, lineterminator="\n")  # no cell is ever a formula
    rows = sorted(results, key=lambda r: r.student)
    matched = [r for r in rows if r.lms]
    kind = getattr(roster, "kind", "plain")
    if fmt in ("canvas", "moodle") and roster is None:
        matched = rows  # no roster: the submission's own name is all there is
    if fmt == "canvas":
        w.writerow([*CANVAS_COLUMNS, assignment])
        w.writerow(["    Points Possible", "", "", "", "", f"{lms_max or tests.max_points:g}"])
        for r in matched:
            e = r.lms or {}
            row = e.get("row") or {}
            if kind == "canvas":  # Canvas's own ids, exactly as exported
                ids = [row.get("Student", ""), row.get("ID", ""), row.get("SIS User ID", ""),
                       row.get("SIS Login ID", ""), row.get("Section", "")]  # fmt: skip
            else:  # a course roster: its id is the SIS User ID Canvas matches on
                ids = [e.get("name") or r.student, "", e.get("id", r.student), "", ""]
            w.writerow([*ids, f"{lms_score(r, tests, lms_max):g}"])
    elif fmt == "moodle":
        if kind == "moodle-worksheet":  # Moodle's grading worksheet, filled in: upload it back
            fields = list(roster.fields)
            for extra in ("Grade", "Feedback comments"):
                if extra not in fields:
                    fields.append(extra)
            w.writerow(fields)
            for r in matched:
                row = dict(r.lms.get("row") or {})
                row["Grade"] = f"{lms_score(r, tests, lms_max):g}"
                row["Feedback comments"] = notes_text(r, tests)
                w.writerow([row.get(f, "") for f in fields])
        else:  # Moodle's grade import: map "ID number" (or "Email address") to the user
            w.writerow(["ID number", "Email address", "Full name", assignment, "Feedback"])
            for r in matched:
                e = r.lms or {}
                row = e.get("row") or {}
                w.writerow(
                    [
                        row.get("ID number", e.get("id", r.student)),
                        e.get("email", ""),
                        e.get("name", ""),
                        f"{final_total(r):g}",
                        notes_text(r, tests),
                    ]
                )
    else:
        lms = ["id", "name", "email"] if roster is not None else []
        w.writerow(
            ["student", *lms, *questions, "raw_total", "late_penalty", "total", "status", "sandbox"]
        )
        for r in rows:
            e = r.lms or {}
            w.writerow(
                [
                    r.student,
                    *(e.get(k, "") for k in lms),
                    *(r.points[q] for q in questions),
                    r.total,
                    f"{r.penalty:g}",
                    final_total(r),
                    r.status,
                    "bwrap" if r.sandbox == "bwrap" else "none (unsandboxed)",
                ]
            )
    return buf.getvalue()


def feedback_markdown(r, tests, late: LatePolicy | None = None, lms=None) -> str:
    """One student's feedback; ``lms`` is ``(LMS name, its maximum or None)`` when the scores
    go to an LMS import file (the scaling is stated)."""
    lines = [
        f"# {tests.homework} — {r.student}",
        "",
        f"**Score: {final_total(r):g} / {tests.max_points:g}**",
        "",
    ]
    if lms is not None and r.lms is not None:
        lines += [f"In the gradebook: {scale_note(r, tests, lms[1], lms[0])}.", ""]
    lines += [
        "| question | points | max | note |",
        "|---|---|---|---|",
    ]
    for q in tests.points:
        text = r.notes[q].replace("|", "\\|").replace("\n", " ")
        note = text or "✓"
        if tests.points[q] == 0:  # multiple choice: a check can be tried letter by letter
            note = "feedback only: " + ("✓ right" if r.right(q, 0) else f"✗ {text or 'wrong answer'}")
        lines.append(f"| {q} | {r.points[q]:g} | {tests.points[q]:g} | {note} |")
    if late is not None:
        if r.time_source.startswith("Canvas"):  # the LMS's verdict; the file's own time apart
            verdict = r.time_source.removeprefix("Canvas: ")
            when = f"Canvas says {verdict}; the file's time is {r.file_time or 'unknown'}"
        else:
            when = f"{r.submitted or 'unknown'} ({r.time_source})"
        lines += [
            "",
            "## Deadline",
            "",
            f"Rule: {late.describe()}. Submitted: {when}.",
            f"Late by {r.days_late} started day(s): {r.penalty:.0%} off "
            f"({r.total:g} → {final_total(r):g})."
            if r.days_late
            else "On time.",
        ]
    if r.run_notes:
        lines += ["", "## Notes on the run", "", *(f"- {n}" for n in r.run_notes)]
    return "\n".join(lines) + "\n"


MIN_PER_STRATUM = 5  # students per kind of variant before success rates are compared
SPREAD_FLAG = 0.30  # flag a question whose kinds of variant differ by more than this


def variant_spread(results, tests, labels: dict[str, dict[str, str]]) -> dict[str, dict]:
    """Per question: full-marks rate per kind of variant, and whether they differ widely."""
    out = {}
    for q in tests.points:
        groups: dict[str, list[bool]] = {}
        for r in results:
            label = labels.get(r.student, {}).get(q)
            if label is not None:
                groups.setdefault(label, []).append(r.right(q, tests.points[q]))
        rates = {k: (sum(v) / len(v), len(v)) for k, v in sorted(groups.items())}
        big = [rate for rate, n in rates.values() if n >= MIN_PER_STRATUM]
        flagged = len(big) >= 2 and max(big) - min(big) > SPREAD_FLAG
        if rates:
            out[q] = {
                "rates": {k: [round(r, 3), n] for k, (r, n) in rates.items()},
                "flagged": flagged,
            }
    return out


#: the flags of the status column, in the order an instructor acts on them (identity.py)
ACT_ON = (
    ("not in the roster", "Not in the roster (not in the import file; resolve by hand, then `--only`)"),
    ("reaches into the grader", "Code that reaches into the grader's guards (review the notebook; why follows each name)"),
    ("answer typed in", "A value answer typed in as a long number, not computed in the notebook (review: where did it come from?)"),
    ("edited after submit", "Edited after submit() (checksum mismatch)"),
    ("manifest id differs", "The submit() manifest names another roster student"),
    ("manifest time disagrees", "The submit() manifest's time disagrees with the LMS/file time"),
    ("wrong variant code", "Wrong variant code (whose code follows each name)"),
    ("shared variant code", "The same variant code in several notebooks"),
    ("no variant code", "No variant code in the notebook (graded on their own data)"),
    ("late", "Late"),
    ("file time after deadline", "File time after the deadline, but Canvas says on time (Canvas decides; no penalty)"),
    ("several notebooks", "Several notebooks (the newest graded)"),
)


def flags_of(r) -> list[str]:
    return [p.strip() for p in r.status.split(";")[1:]]


def _why(r, flag: str) -> str:
    """The details after a flagged name: the scan's reasons (tools/grading/tamper.py), or whose
    code or manifest it is (the instructor's notes; the student's feedback does not name them)."""
    if flag == "reaches into the grader":
        details = getattr(r, "review", None) or []
    else:
        private = (getattr(r, "private_notes", None) or {}).get(flag)
        details = [private] if private else []
    return f" ({'; '.join(details)})" if details else ""


def _named(e: RosterEntry) -> str:
    return f"{e.id} ({e.name})" if e.name and e.name != e.id else e.id


def _who(r) -> str:
    e = r.lms or {}
    name = e.get("name") or ""
    ident = e.get("id") or r.student
    return f"{ident} ({name})" if name and name != ident else ident


def summary(
    results,
    tests,
    roster: dict[str, RosterEntry] | None,
    labels: dict[str, dict[str, str]] | None = None,
    lms: tuple[str, float | None, str] | None = None,
) -> tuple[str, dict]:
    """The class summary: what to act on first (flags, missing students), then statistics
    over the class (roster students only when there is a roster; not-graded rows never).
    ``lms`` is ``(LMS name, its maximum or None, the import column)`` for an import file."""
    listed = list(results)
    results = [r for r in listed if not r.status.startswith("not graded") and not r.refused]
    if roster is not None:
        results = [r for r in results if r.lms]
    totals = [final_total(r) for r in results]
    rates = {
        q: (
            sum(1 for r in results if r.right(q, tests.points[q])) / len(results)
            if results
            else 0.0
        )
        for q in tests.points
    }
    data = {
        "homework": tests.homework,
        "max_points": tests.max_points,
        "points": tests.points,
        "submissions": len(results),
        "mean": round(statistics.fmean(totals), 2) if totals else None,
        "median": round(statistics.median(totals), 2) if totals else None,
        "success_rate": {q: round(v, 3) for q, v in rates.items()},
        "unsandboxed": sum(1 for r in listed if r.sandbox != "bwrap"),
    }
    lines = [f"# {tests.homework}: class summary", "", "## Act on these first", ""]
    flagged: dict[str, list[str]] = {}
    for flag, title in ACT_ON:
        who = sorted(_who(r) + _why(r, flag) for r in listed if flag in flags_of(r))
        flagged[flag] = who
        if who:
            lines.append(f"- **{title}** ({len(who)}): " + ", ".join(who))
    refused = sorted((r.student, r.refused) for r in listed if r.refused)
    if refused:  # links, FIFOs, hard links: never opened (intake.py), never graded
        data["not_opened"] = [s for s, _ in refused]
        lines.append(
            f"- **Files not opened: links or not regular files** ({len(refused)}; 0 points, "
            "not in the import file; ask the student for the file itself): "
            + ", ".join(f"{s} ({why.removesuffix(', not graded')})" for s, why in refused)
        )
    if roster is not None:
        seen = {r.lms["id"] for r in listed if r.lms}
        refused_names = {s.lower() for s, _ in refused}
        unknown = sorted(
            r.student for r in listed if not r.lms and r.student.lower() not in refused_names
        )
        missing = sorted(
            _named(e)
            for e in roster.values()
            if e.id not in seen and not refused_names & {k.lower() for k in (e.id, e.key, *e.aliases) if k}
        )
        data["not_in_roster"], data["no_submission"] = unknown, missing
        lines += [
            f"- Submissions not in the roster ({len(unknown)}): " + (", ".join(unknown) or "none"),
            f"- Roster students without a submission ({len(missing)}): "
            + (", ".join(missing) or "none"),
        ]
    elif not any(flagged.values()):
        lines.append("- nothing flagged")
    data["flags"] = {k: v for k, v in flagged.items() if v}
    lines += [
        "",
        "## Statistics",
        "",
        f"{len(results)} submission{'' if len(results) == 1 else 's'} graded"
        + (" (roster students)" if roster is not None else "")
        + f"; maximum {tests.max_points:g} points.",
    ]
    if totals:
        lines.append(f"Mean {data['mean']:g}, median {data['median']:g}.")
    if lms is not None:
        name, top, column = lms
        data["import"] = {"lms": name, "column": column, "maximum": top}
        if top is None:
            lines.append(
                f"Import file (scores.csv, column \"{column}\"): scores written as they are "
                f"(out of {tests.max_points:g}); the {name} export gives no maximum."
            )
        else:
            lines.append(
                f"Import file (scores.csv, column \"{column}\"): scores scaled to {name}'s "
                f"maximum, {tests.max_points:g}/{tests.max_points:g} → {top:g}/{top:g} in {name}."
            )
    lines += ["", "| question | points | right |", "|---|---|---|"]
    lines += [
        f"| {q} | {tests.points[q]:g}{' (feedback only)' if tests.points[q] == 0 else ''} "
        f"| {rates[q]:.0%} |"
        for q in tests.points
    ]
    if labels:
        spread = variant_spread(results, tests, labels)
        data["variants"] = spread
    if labels and any(len(info["rates"]) > 1 for info in spread.values()):
        lines += [
            "",
            "## Per-student variants",
            "",
            f"Full-marks rate per kind of variant (compared when a kind has at least "
            f"{MIN_PER_STRATUM} students; ⚠ = kinds differ by more than "
            f"{SPREAD_FLAG:.0%}: check that generator's variants are equally hard).",
            "",
            "| question | kinds of variant (rate, students) | |",
            "|---|---|---|",
        ]
        for q, info in spread.items():
            if len(info["rates"]) < 2:
                continue
            kinds = "; ".join(f"{k}: {r:.0%} ({n})" for k, (r, n) in info["rates"].items())
            lines.append(f"| {q} | {kinds} | {'⚠' if info['flagged'] else ''} |")
    if data["unsandboxed"]:
        lines += ["", f"**{data['unsandboxed']} submissions were graded WITHOUT a sandbox.**"]
    lines += ["", "![score distribution](histogram.png)"]
    return "\n".join(lines) + "\n", data


def histogram_png(results, tests) -> bytes:
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6, 3.2), dpi=100)
    ax = fig.add_subplot()
    totals = [final_total(r) for r in results]
    bins = max(1, min(20, math.ceil(tests.max_points)))
    ax.hist(totals, bins=bins, range=(0, tests.max_points), color="#0072B2", edgecolor="white")
    ax.set_xlabel(f"score (of {tests.max_points:g})")
    ax.set_ylabel("students")
    ax.set_title(f"{tests.homework}: {len(totals)} submissions")
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    return buf.getvalue()


def results_json(results, tests, late: LatePolicy | None) -> str:
    from dataclasses import asdict

    return json.dumps(
        {
            "homework": tests.homework,
            "points": tests.points,
            "late_rule": late.describe() if late else None,
            "results": [asdict(r) for r in sorted(results, key=lambda r: r.student)],
        },
        indent=1,
        ensure_ascii=False,
    )
