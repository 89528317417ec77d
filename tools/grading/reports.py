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
import statistics
import uuid
from dataclasses import dataclass
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
    key: str
    id: str
    name: str
    email: str


def read_roster(path: Path) -> dict[str, RosterEntry]:
    """A roster CSV: ``id`` (the LMS id) and optionally ``submission`` (the file/folder name or
    the manifest's student id the submissions carry; defaults to ``id``), ``name``, ``email``."""
    with open(path, newline="", encoding="utf-8-sig") as fh:
        reader = csv.DictReader(fh)
        fields = {f.strip().lower() for f in reader.fieldnames or []}
        if "id" not in fields:
            raise SystemExit(f"--roster {path}: needs an 'id' column (found {sorted(fields)})")
        roster: dict[str, RosterEntry] = {}
        for n, row in enumerate(reader, start=2):
            row = {k.strip().lower(): (v or "").strip() for k, v in row.items() if k}
            if not row.get("id"):
                raise SystemExit(f"--roster {path}, line {n}: empty id")
            key = row.get("submission") or row["id"]
            if key in roster:
                raise SystemExit(f"--roster {path}, line {n}: {key!r} appears twice")
            roster[key] = RosterEntry(key, row["id"], row.get("name", ""), row.get("email", ""))
    return roster


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


def scores_table(
    results, tests, fmt: str, roster: dict[str, RosterEntry] | None, assignment: str
) -> str:
    questions = list(tests.points)
    buf = io.StringIO()
    w = safe_csv_writer(buf, lineterminator="\n")  # no cell is ever a formula
    rows = sorted(results, key=lambda r: r.student)
    if fmt == "canvas":
        w.writerow(["Student", "ID", "SIS User ID", "SIS Login ID", "Section", assignment])
        w.writerow(["    Points Possible", "", "", "", "", f"{tests.max_points:g}"])
        for r in rows:
            e = r.lms
            w.writerow(
                [
                    e["name"] if e else r.student,
                    e["id"] if e else "",
                    "",
                    "",
                    "",
                    f"{final_total(r):g}",
                ]
            )
    elif fmt == "moodle":
        w.writerow(["ID number", "Email address", "Full name", assignment, "Feedback"])
        for r in rows:
            e = r.lms
            w.writerow(
                [
                    e["id"] if e else r.student,
                    e["email"] if e else "",
                    e["name"] if e else "",
                    f"{final_total(r):g}",
                    f"{final_total(r):g}/{tests.max_points:g}; {r.status}",
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


def feedback_markdown(r, tests, late: LatePolicy | None = None) -> str:
    lines = [
        f"# {tests.homework} — {r.student}",
        "",
        f"**Score: {final_total(r):g} / {tests.max_points:g}**",
        "",
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
        when = r.submitted or "unknown"
        lines += [
            "",
            "## Deadline",
            "",
            f"Rule: {late.describe()}. Submitted: {when} ({r.time_source}).",
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


def summary(
    results,
    tests,
    roster: dict[str, RosterEntry] | None,
    labels: dict[str, dict[str, str]] | None = None,
) -> tuple[str, dict]:
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
        "unsandboxed": sum(1 for r in results if r.sandbox != "bwrap"),
    }
    lines = [
        f"# {tests.homework}: class summary",
        "",
        f"{len(results)} submissions; maximum {tests.max_points:g} points.",
    ]
    if totals:
        lines.append(f"Mean {data['mean']:g}, median {data['median']:g}.")
    lines += ["", "| question | points | right |", "|---|---|---|"]
    lines += [
        f"| {q} | {tests.points[q]:g}{' (feedback only)' if tests.points[q] == 0 else ''} "
        f"| {rates[q]:.0%} |"
        for q in tests.points
    ]
    if roster is not None:
        seen = {r.lms["id"] for r in results if r.lms}
        unknown = sorted(r.student for r in results if not r.lms)
        missing = sorted(e.id for e in roster.values() if e.id not in seen)
        data["not_in_roster"], data["no_submission"] = unknown, missing
        lines += [
            "",
            f"Submissions not in the roster ({len(unknown)}): " + (", ".join(unknown) or "none"),
            f"Roster students without a submission ({len(missing)}): "
            + (", ".join(missing) or "none"),
        ]
    if labels:
        spread = variant_spread(results, tests, labels)
        data["variants"] = spread
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
