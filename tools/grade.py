#!/usr/bin/env python3
"""Grade a folder of submitted homework notebooks against hidden tests.

Usage (instructors)::

    python tools/grade.py --tests solutions/hidden_tests/hw01.py \\
        --submissions submissions/hw01 --out grades/hw01 [--jobs 2] [--sandbox auto]

writes ``grades/hw01/scores.csv`` (one row per student: points per question, total, status,
sandbox) and ``grades/hw01/feedback/<student>.md`` (points, the reason for each lost point,
notes on the run), each row and file as soon as its submission is graded.

Who the student is
------------------
One identity per submission picks the roster row, the variant, the feedback file and the
gradebook row (``tools/grading/identity.py``): the LMS's own download naming (Canvas's
``doejane_LATE_12345_67890_hw03-1001.ipynb``, Moodle's ``Jane Doe_4711_assignsubmission_file_/``
folders), else the file or folder name (``alice.ipynb``, ``alice/hw01.ipynb``, submit()'s
``hw03-1001.ipynb`` is student ``1001``), else the id in the ``submit()`` manifest.  With a
roster and a course secret, a submission that matches no roster entry is not graded (it would
be graded on the wrong data): it is listed in ``summary.md`` for the instructor to resolve.
When one student has several notebooks, the one with the newest valid manifest time (else file
time) is graded and the status says ``several notebooks``.  The submission time is the LMS's
record where it has one -- Canvas's ``LATE`` mark in its file names; with Moodle's grading
worksheet as the roster, its "Last modified (submission)" for a notebook from Moodle's
download -- else the file's time; the manifest's time is only compared with it.  Flags (edited after submit, manifest
time or id disagreeing, late, wrong or shared variant code) go into the status column, the
feedback and the summary.
Only regular files inside ``--submissions`` are opened, never through a link: a notebook or
folder that is a symbolic link (or a FIFO, a hard link) is reported as "a link, not graded"
(``tools/grading/intake.py``).  Names are written escaped and unique even ignoring case, and no
CSV cell is a formula (``tools/grading/safe_names.py``); job folders live in a private folder
(``tools/grading/jobroot.py``).

The trust boundary
------------------
Student code is hostile input.  It runs only in a sandboxed kernel (``tools/grading/sandbox.py``:
bubblewrap, no network, no view of the course checkout beyond ``course_lib``, resource limits,
nothing survives it).  Hidden tests and expected values never enter that kernel: they run here,
in the grader, and ask the kernel for *data* through ``course_lib.homework.protocol`` -- a name's value,
the result of the student's function on inputs chosen here, a symbolic answer evaluated at
points chosen here -- which arrives as size-limited JSON and is validated here
(``tools/grading/protocol.py``).  Comparisons, fractions and notes are computed here, clamped to
``[0, 1]``; a malformed or missing answer costs that question, never the batch.

How a submission is run
-----------------------
Each submission gets a private temporary job folder holding a copy of its notebook; its code
cells run one by one in a fresh sandboxed kernel (errors do not stop the run).  A cell that runs
longer than ``--cell-timeout``, prints more than ``--output-limit`` bytes or kills its kernel is
skipped: the kernel is killed and the notebook is run again without that cell, so the student
keeps the points earned elsewhere.  A request of a hidden test that does not finish within
``--question-timeout`` (an endless loop in a graded function) costs that question; the kernel is
replaced.  ``--time-limit`` bounds the whole submission.  The job folder is always removed.

Hidden tests
------------
A hidden test file is plain Python (not collected by pytest: do not name it ``test_*.py``) with
``HOMEWORK``, ``POINTS`` (questions in report order, with their points) and one function
``qN(student)`` per question; ``student`` gives plain data only (``tools/grading/protocol.py``).
The format, the answer readers of ``course_lib.homework.answers`` and the rules are in
``solutions/hidden_tests/README.md``.  Expected values come from first principles, never from
the code the solution notebook calls.

Gradebooks
----------
``--roster`` maps submissions to LMS ids; ``--format plain|canvas|moodle`` chooses the layout of
``scores.csv``; ``--assignment NAME`` picks a Canvas export's column (its exact header, "(id)"
included; points scaled to its "Points Possible"); ``--deadline`` and ``--late-penalty`` apply a late rule (stated in every feedback
file); ``--only STUDENT`` regrades one student and merges the row; ``--executor dask`` grades on a
Dask cluster (``--scheduler``).  See ``tools/grading/reports.py`` and the README.

The exit code is 0 whenever the batch ran, whatever the submissions did; it is non-zero only
for the grader's own failures (bad arguments, a broken hidden-test file, no submissions).
"""

from __future__ import annotations

if __name__ == "__main__":  # run as printed (tools/grade.py ...): with the course's .venv if any
    import os as _os
    import sys as _sys
    from pathlib import Path as _Path

    _venv = _Path(__file__).resolve().parents[1] / ".venv"
    if (_venv / "bin" / "python").is_file() and _Path(_sys.prefix).resolve() != _venv.resolve():
        _os.execv(str(_venv / "bin" / "python"), [str(_venv / "bin" / "python"), *_sys.argv])

import argparse
import json
import os
import sys
import threading
from concurrent.futures import ThreadPoolExecutor, as_completed
from dataclasses import asdict, dataclass
from pathlib import Path

from course_lib.homework import variants
from tools.grading import identity, intake, jobroot, reports, safe_names, sandbox
from tools.grading.runner import (
    DEFAULT_CELL_TIMEOUT,
    DEFAULT_QUESTION_TIMEOUT,
    DEFAULT_TIME_LIMIT,
    UNSANDBOXED_NOTE,
    HiddenTests,
    Options,
    Result,
    check_sandbox,
    grade_notebook,
    grade_payload,
)

__all__ = [
    "HiddenTests",
    "Result",
    "discover",
    "feedback_names",
    "grade_notebook",
    "main",
    "sandbox",
]


# ------------------------------------------------------------------------------ batches


@dataclass
class Item:
    """One student's submission as planned: the notebook to grade and what is known about it."""

    student: str
    found: identity.Found
    others: list[identity.Found]
    who: identity.Identity
    variant: str = ""  # the code the student is graded on ("" = the default data)
    graded: bool = True  # False: listed for the instructor, not graded

    @property
    def path(self) -> Path:
        return self.found.path


def _code(text: str | None) -> str:
    return (text or "").strip().upper().replace("-", "").replace(" ", "")


def plan(
    folder: Path, roster=None, *, homework: str = "", secret: bytes | None = None,
    variants_on: bool = False, refused: dict | None = None,
) -> list[Item]:  # fmt: skip
    """Every student's submission, identified once, sorted by student (see the docstring)."""
    index = identity.RosterIndex(roster) if roster is not None else None
    groups: dict[str, list[tuple[identity.Found, identity.Identity]]] = {}
    for found in identity.discover(folder, refused):
        who = identity.identify(found, index)
        groups.setdefault(who.student, []).append((found, who))
    items = []
    for student in sorted(groups):
        pairs = sorted(groups[student], key=lambda p: p[0].order(), reverse=True)
        (found, who), rest = pairs[0], [p[0] for p in pairs[1:]]
        item = Item(student, found, rest, who)
        if rest:
            who.flags.append(identity.SEVERAL)
            who.notes.append(
                f"several notebooks were submitted; graded {found.rel} (the newest), ignored "
                + ", ".join(o.rel for o in rest)
            )
        if variants_on and secret is not None:
            if who.entry is not None:
                item.variant = variants.code_for(secret, homework, who.entry.id)
            elif roster is not None:
                item.graded = False  # its own data is unknown: never grade it on another's
                who.notes.append("not graded: with a course secret it would be graded on the wrong data")
            else:
                item.variant = variants.code_for(secret, homework, student)
        items.append(item)
    if variants_on and secret is not None:
        _variant_flags(items, roster, homework, secret)
    return items


def _variant_flags(items: list[Item], roster, homework: str, secret: bytes) -> None:
    """Whose code did each notebook use (the grader can tell: codes are made from roster ids)."""
    owner = {}
    for entry in (roster or {}).values():
        owner[variants.code_for(secret, homework, entry.id)] = entry.id
    for item in items:
        owner.setdefault(item.variant, item.who.entry.id if item.who.entry else item.student)
    users: dict[str, list[str]] = {}
    for item in items:
        if item.graded and _code(item.found.variant_used):
            users.setdefault(_code(item.found.variant_used), []).append(item.student)
    for item in items:
        if not item.graded or not item.variant:
            continue
        used = _code(item.found.variant_used)
        if not used:
            item.who.flags.append(identity.NO_CODE)
            continue
        if used != item.variant:
            whose = owner.get(used)
            item.who.flags.append(identity.WRONG_CODE)
            item.who.notes.append(
                "the notebook's VARIANT is not the code you were given: the data questions "
                "were graded on your own data"
            )
            item.who.private[identity.WRONG_CODE] = (
                f"its VARIANT is the code of roster student {whose}"
                if whose else "its VARIANT is no roster student's code"
            )
        if len(users.get(used, [])) > 1:
            item.who.flags.append(identity.SHARED_CODE)
            item.who.notes.append("the same VARIANT is in another student's notebook")
            item.who.private[identity.SHARED_CODE] = (
                "the same VARIANT is in the notebooks of " + ", ".join(sorted(users[used]))
            )


def discover(folder: Path) -> list[tuple[str, Path, list[Path]]]:
    """``(student, notebook to grade, other notebooks of that student)``, without a roster.

    Links and files that are not regular are left out (``intake.scan`` reports them)."""
    return [(i.student, i.path, [o.path for o in i.others]) for i in plan(folder)]


def feedback_names(students: list[str]) -> dict[str, str]:
    """A distinct, filesystem-safe file stem per student (distinct even case-insensitively)."""
    return safe_names.file_stems(students)


class Reports:
    """Every output file, rewritten atomically after every graded submission."""

    def __init__(
        self,
        tests: HiddenTests,
        out: Path,
        *,
        fmt: str = "plain",
        roster=None,
        late=None,
        keep: list[Result] | None = None,
        assignment: str | None = None,
    ) -> None:
        self.tests, self.out, self.fmt, self.roster, self.late = tests, out, fmt, roster, late
        #: the import file's column (the export's exact header) and the LMS's maximum
        self.assignment = assignment or tests.homework
        self.lms_max = reports.lms_maximum(roster, fmt, self.assignment) if roster is not None else None
        self.lms = {"canvas": "Canvas", "moodle": "Moodle"}.get(fmt)
        self.results: dict[str, Result] = {r.student: r for r in keep or []}
        self.labels: dict[str, dict[str, str]] = {}
        self.stems: dict[str, str] = safe_names.file_stems(self.results)
        self.lock = threading.Lock()
        (out / "feedback").mkdir(parents=True, exist_ok=True)

    def lookup(self, r: Result, entry=None) -> None:
        if self.roster is not None:
            r.lms = asdict(entry) if entry is not None else None

    def reserve(self, students) -> None:
        """Give every student of the batch a feedback file name now (stable whatever order)."""
        with self.lock:
            self.stems = safe_names.file_stems(students, self.stems)

    def add(self, r: Result) -> None:
        safe_names.scrub(r)  # text from the submission that UTF-8 cannot encode is escaped
        with self.lock:
            self.results[r.student] = r
            self.write(only=r)

    def write(self, only: Result | None = None) -> None:
        results = list(self.results.values())
        self.stems = safe_names.file_stems(self.results, self.stems)
        for r in [only] if only is not None else results:
            reports.atomic_write(
                self.out / "feedback" / f"{self.stems[r.student]}.md",
                reports.feedback_markdown(
                    r, self.tests, self.late, (self.lms, self.lms_max) if self.lms else None
                ),
            )
        table = reports.scores_table(
            results, self.tests, self.fmt, self.roster, self.assignment, self.lms_max
        )
        reports.atomic_write(self.out / "scores.csv", table)
        reports.atomic_write(
            self.out / "results.json", reports.results_json(results, self.tests, self.late)
        )
        text, _ = reports.summary(
            results, self.tests, self.roster, self.variant_labels(results),
            lms=(self.lms, self.lms_max, self.assignment) if self.lms else None,
        )  # fmt: skip
        reports.atomic_write(self.out / "summary.md", text)

    def variant_labels(self, results: list[Result]) -> dict[str, dict[str, str]]:
        """The kind of variant of every question of every student graded on their own data."""
        if not self.tests.variants:
            return {}
        for r in results:  # each student's variant is generated once
            if r.variant and r.student not in self.labels:
                self.labels[r.student] = variants.strata(self.tests.homework, r.variant)
        return {r.student: self.labels[r.student] for r in results if r.variant}

    def graded_students(self) -> list[Result]:
        """The results of the class: roster students only when there is a roster."""
        results = [r for r in self.results.values() if not r.status.startswith(NOT_GRADED)]
        return [r for r in results if r.lms] if self.roster is not None else results

    def finish(self) -> None:
        with self.lock:
            self.write()
            reports.atomic_write(
                self.out / "histogram.png",
                reports.histogram_png(self.graded_students(), self.tests),
            )


def import_column(roster, fmt: str, name: str) -> str:
    """The import file's assignment column: with a Canvas export as the roster, the export's
    own header for ``name`` (Canvas matches on it, "(id)" included); stops when there is none."""
    if fmt != "canvas" or getattr(roster, "kind", "") != "canvas":
        return name
    column = reports.canvas_column(roster, name)
    if column is None:
        have = "; ".join(f'"{c}"' for c in reports.canvas_assignments(roster)) or "none"
        raise SystemExit(
            f"--assignment {name!r}: the Canvas export has no such assignment column (its "
            f"assignment columns: {have}); nothing was graded -- pass --assignment \"NAME\" "
            "(make grade ... ASSIGNMENT=\"NAME\")."
        )
    return column


def load_previous(out: Path, tests: HiddenTests) -> list[Result]:
    """The results of an earlier run in ``out`` (for ``--only``)."""
    path = out / "results.json"
    if not path.exists():
        raise SystemExit(f"--only: no earlier results in {out} (results.json is missing)")
    data = json.loads(path.read_text(encoding="utf-8"))
    if data.get("homework") != tests.homework:
        raise SystemExit(f"--only: {out} holds grades of {data.get('homework')!r}")
    return [Result(**r) for r in data["results"]]


def read_secret(path: Path) -> bytes:
    try:
        secret = path.read_bytes().strip()
    except OSError as exc:
        raise SystemExit(f"--secret-file {path}: {exc.strerror}") from None
    if len(secret) < 16:
        raise SystemExit(f"--secret-file {path}: too short (make one with tools/variant.py secret)")
    return secret


def resolve_sandbox(choice: str) -> tuple[str, str]:
    """``(mode, message)`` for ``--sandbox auto|bwrap|none``."""
    if choice == "none":
        return "none", "WARNING: " + UNSANDBOXED_NOTE
    ok, why = sandbox.bwrap_works()
    if ok:
        return "bwrap", ""
    if choice == "bwrap":
        raise SystemExit(f"--sandbox bwrap: {why}")
    return "none", f"WARNING: {why}; " + UNSANDBOXED_NOTE


def _refused_result(student: str, entries, tests: HiddenTests, mode: str) -> Result:
    """The row of a student none of whose files was opened (links, FIFOs, ...): 0, and why."""
    reason = entries[0][1]
    r = Result(
        student,
        dict.fromkeys(tests.points, 0.0),
        dict.fromkeys(tests.points, f"not graded: the submission is {reason.split(',')[0]}"),
        status=reason,
        sandbox=mode,
    )
    r.file, r.refused = entries[0][0], reason
    r.run_notes += intake.refusal_note(entries)
    r.run_notes.append("the grader opens only regular files inside the submissions folder")
    return r


NOT_GRADED = "not graded"


def _finish_result(r: Result, item: Item, args, late) -> Result:
    """The identity, the trusted time and every flag of a graded (or listed) submission."""
    found, who = item.found, item.who
    r.student, r.file = item.student, found.rel
    flags = list(who.flags)
    notes = list(who.notes)
    if found.manifest is not None and found.manifest["tampered"]:
        flags.insert(0, identity.EDITED)
    deadline = late.deadline if late is not None else None
    notes += identity.read_lms_time(found, who.entry, deadline)
    when, source, tflags, tnotes = identity.time_flags(found, deadline)
    if args.time_source == "file":
        when, source = found.mtime, "file time"
    flags += tflags
    notes += tnotes
    if found.mtime is not None:
        r.file_time = found.mtime.isoformat(timespec="seconds")
    if when is not None:
        r.submitted, r.time_source = when.isoformat(timespec="seconds"), source
    else:  # never the manifest's time alone: it is written on the student's machine
        r.submitted, r.time_source = None, "none"
    if late is not None:
        r.days_late, r.penalty = late.apply(when)
        if r.days_late:
            flags.append(identity.LATE)
    r.run_notes = [n for n in r.run_notes if not n.startswith("the submission's manifest names")]
    r.run_notes[:0] = notes
    r.private_notes = dict(who.private)
    seen = []
    for f in flags:
        if f not in seen:
            seen.append(f)
    if seen:
        r.status = "; ".join([r.status, *seen])
    return r


def _not_graded(item: Item, tests: HiddenTests, mode: str) -> Result:
    reason = "not in the roster" if item.who.entry is None else "not graded"
    r = Result(
        item.student,
        dict.fromkeys(tests.points, 0.0),
        dict.fromkeys(tests.points, f"not graded ({reason})"),
        status=NOT_GRADED,
        sandbox=mode,
    )
    return r


def _parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(description="Grade submitted notebooks against hidden tests.")
    p.add_argument("--tests", required=True, type=Path, help="hidden test file (.py)")
    p.add_argument("--submissions", required=True, type=Path, help="folder of submitted .ipynb")
    p.add_argument("--out", required=True, type=Path, help="folder for scores.csv and feedback/")
    p.add_argument("--cell-timeout", type=float, default=DEFAULT_CELL_TIMEOUT)
    p.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT, help="per submission")
    p.add_argument("--question-timeout", type=float, default=DEFAULT_QUESTION_TIMEOUT)
    p.add_argument("--jobs", type=int, default=1, help="submissions graded in parallel")
    p.add_argument(
        "--sandbox",
        choices=["auto", "bwrap", "none"],
        default="auto",
        help="auto: bubblewrap where it works, else unsandboxed with a warning",
    )
    p.add_argument("--memory", type=float, default=4.0, help="address-space limit, GiB")
    p.add_argument("--output-limit", type=int, default=1 << 20, help="bytes of output per cell")
    p.add_argument(
        "--disk", type=float, default=512, help="MB a submission may write in its job folder"
    )
    p.add_argument(
        "--tmp-size", type=float, default=64, help="MB of the sandbox's /tmp and of its /dev/shm"
    )
    p.add_argument(
        "--job-root",
        type=Path,
        help="folder for job folders (created 0700, or must be yours and 0700; "
        "default: a fresh private temp folder)",
    )
    p.add_argument("--roster", type=Path, help="CSV: id[, submission, name, email]")
    p.add_argument(
        "--format",
        choices=reports.FORMATS,
        default="plain",
        help="layout of scores.csv: plain, canvas or moodle gradebook import",
    )
    p.add_argument(
        "--assignment",
        metavar="NAME",
        help="the gradebook column to fill: with a Canvas export as --roster, the export's "
        "assignment column by its name, with or without Canvas's '(id)' (default: the homework, "
        "e.g. hw01)",
    )
    p.add_argument("--deadline", help="ISO time, e.g. 2026-12-01T23:59+01:00")
    p.add_argument("--late-penalty", default="10%", help="per started day late (default 10%%)")
    p.add_argument(
        "--time-source",
        choices=["lms", "file"],
        default="lms",
        help="submission time: the LMS's record where it has one (Canvas's LATE mark; Moodle's "
        "worksheet time, with a Moodle grading worksheet as --roster), else the file time; or "
        "always the file time.  The manifest's time is only compared",
    )
    p.add_argument("--only", metavar="STUDENT", help="regrade one student, merge into --out")
    p.add_argument(
        "--secret-file",
        type=Path,
        help="the course secret (tools/variant.py secret): grade each student on their own "
        "variant of a homework with VARIANTS; without it, on the default data",
    )
    p.add_argument("--executor", choices=["local", "dask"], default="local")
    p.add_argument(
        "--scheduler",
        help="Dask scheduler address, e.g. tcp://host:8786 "
        "(default with --executor dask: a local cluster)",
    )
    return p


def _only(student: str, found: list[Item], refused: dict) -> tuple[list[Item], dict]:
    """``--only``: the submissions and refused files of one student (file name or roster id)."""
    found = [i for i in found if student == i.student
             or (i.who.entry is not None and student in (i.who.entry.id, *i.who.entry.aliases))]  # fmt: skip
    return found, {k: v for k, v in refused.items() if k == student}


def _kept_rows(out: Path, tests: HiddenTests, found: list[Item]) -> list[Result]:
    """``--only``: the earlier rows that stay (the regraded submissions replace theirs)."""
    files = {i.found.rel for i in found} | {o.rel for i in found for o in i.others}
    students = {i.student for i in found}
    return [r for r in load_previous(out, tests)
            if r.student not in students and r.file not in files]  # fmt: skip


def _list_refused(out: Reports, refused: dict, found: list[Item], tests: HiddenTests, mode: str):
    """A row for each student none of whose files was opened (links, FIFOs, ...)."""
    for student, entries in refused.items():
        if not any(i.student == student for i in found):  # nothing of theirs was opened
            r = _refused_result(student, entries, tests, mode)
            out.lookup(r)
            out.add(r)
            print(f"{r.student}: not graded ({r.status})", flush=True)


def _run_options(args, mode: str) -> dict:
    """The runner's options from the command line: time limits, sandbox, resource limits."""
    limits = sandbox.Limits(
        memory_bytes=int(args.memory * sandbox.GIB),
        cpu_seconds=int(args.time_limit) + 30,
        output_bytes=args.output_limit,
        disk_bytes=int(args.disk * (1 << 20)),
        tmp_bytes=int(args.tmp_size * (1 << 20)),
    )
    if args.job_root is not None:
        try:
            jobroot.check_root(args.job_root)
        except (ValueError, OSError) as exc:
            raise SystemExit(f"--job-root: {exc}") from None
    return {
        "cell_timeout": args.cell_timeout,
        "time_limit": args.time_limit,
        "question_timeout": args.question_timeout,
        "mode": mode,
        "limits": limits,
        "job_root": str(args.job_root) if args.job_root is not None else None,
    }


def _grade_on_dask(args, found: list[Item], payload, done, tests: HiddenTests, mode: str) -> None:
    """``--executor dask``: one task per submission on ``--scheduler`` (or a local cluster)."""
    from distributed import Client, LocalCluster
    from distributed import as_completed as dask_completed

    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = LocalCluster(
            n_workers=max(1, args.jobs),
            threads_per_worker=1,
            processes=True,
            dashboard_address=None,
        )
        client = Client(cluster)
    try:
        futures = {client.submit(grade_payload, payload(item), pure=False): item for item in found}
        # a generous bound, so that a cluster that cannot run the task never hangs the batch
        bound = (args.time_limit + 120) * (1 + len(found) // max(1, args.jobs))
        for future in dask_completed(futures, timeout=bound):
            item = futures[future]
            try:
                data = future.result()
            except Exception as exc:  # a lost worker: the row says so, the batch goes on
                data = asdict(
                    Result(
                        item.student,
                        dict.fromkeys(tests.points, 0.0),
                        dict.fromkeys(tests.points, "not graded"),
                        [f"the Dask worker failed ({type(exc).__name__})"],
                        status="grader error",
                        sandbox=mode,
                    )
                )
            done(item, data)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _grade_locally(args, found: list[Item], payload, done) -> None:
    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = {pool.submit(grade_payload, payload(item)): item for item in found}
        for future in as_completed(futures):  # each row is written as soon as it is graded
            done(futures[future], future.result())


def _preflight(options: dict) -> bool:
    """Prove the sandbox starts the course's kernels (else one sentence, False); warn when
    nothing would bound a submission's processes."""
    problem = check_sandbox(Options(**options))
    if problem:
        print(
            f"the sandbox cannot run the course's kernels: {problem}. Nothing was graded "
            "(a link to the environment is followed for you; bind or copy what is missing, "
            "or use --sandbox none for trusted submissions only).",
            file=sys.stderr,
        )
        return False
    warning = sandbox.process_limit_warning(options["limits"])
    if warning:
        print(warning, file=sys.stderr, flush=True)
    return True


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    tests = HiddenTests.load(args.tests)
    if not args.submissions.is_dir():
        print(f"--submissions {args.submissions} is not a folder", file=sys.stderr)
        return 2
    roster = reports.read_roster(args.roster) if args.roster else None
    assignment = import_column(roster, args.format, args.assignment or tests.homework)
    secret = read_secret(args.secret_file) if args.secret_file else None
    if tests.variants and secret is None:
        print(
            f"note: {tests.homework} has per-student variants; without --secret-file every "
            "submission is graded on the default data",
            file=sys.stderr,
        )
    refused: dict[str, list[tuple[str, str]]] = {}  # links, FIFOs: never read
    found = plan(args.submissions, roster, homework=tests.homework, secret=secret,
                 variants_on=tests.variants, refused=refused)  # fmt: skip
    if args.only is not None:
        found, refused = _only(args.only, found, refused)
        if not found and not refused:
            print(f"--only {args.only}: no submission of that student", file=sys.stderr)
            return 2
    if not found and not refused:
        print(f"no .ipynb files under {args.submissions}", file=sys.stderr)
        return 1
    late = (reports.LatePolicy(reports.parse_deadline(args.deadline),
                               reports.parse_penalty(args.late_penalty))
            if args.deadline else None)  # fmt: skip
    mode, message = resolve_sandbox(args.sandbox)
    if message:
        print(message, file=sys.stderr, flush=True)
    options = _run_options(args, mode)
    if mode == "bwrap" and not _preflight(options):  # proved once, before anyone is graded
        return 2
    args.out.mkdir(parents=True, exist_ok=True)
    keep = None if args.only is None else _kept_rows(args.out, tests, found)
    out = Reports(tests, args.out, fmt=args.format, roster=roster, late=late, keep=keep,
                  assignment=assignment)  # fmt: skip
    out.reserve([i.student for i in found] + list(refused))
    _list_refused(out, refused, found, tests, mode)

    def payload(item: Item) -> dict:
        opts = dict(options)
        if tests.variants and secret is not None:
            # the code is made from the roster id the instructor handed codes out for
            opts["variant"] = item.variant
        return {
            "tests_source": tests.source,
            "tests_name": str(args.tests),
            "student": item.student,
            "notebook": item.found.data,  # the bytes read once, no link followed (intake)
            "options": opts,
        }

    grader_errors: list[str] = []

    def done(item: Item, data: dict) -> None:
        r = _finish_result(Result(**data), item, args, late)
        if r.status.startswith("grader error"):
            grader_errors.append(r.student)
        r.run_notes += intake.refusal_note(refused.get(r.student, []))
        out.lookup(r, item.who.entry)
        out.add(r)
        print(
            f"{r.student}: {reports.final_total(r):g} / {tests.max_points:g} "
            f"({r.status}, {r.seconds:g} s)",
            flush=True,
        )

    for item in [i for i in found if not i.graded]:
        r = _finish_result(_not_graded(item, tests, mode), item, args, late)
        out.lookup(r, None)
        out.add(r)
        print(f"{r.student}: listed, not graded ({r.status})", flush=True)
    found = [i for i in found if i.graded]

    if args.executor == "dask":
        _grade_on_dask(args, found, payload, done, tests, mode)
    else:
        _grade_locally(args, found, payload, done)
    out.finish()
    print(
        f"wrote {args.out / 'scores.csv'}, {args.out / 'summary.md'} and "
        f"{args.out / 'feedback'}{os.sep}" + (" -- UNSANDBOXED" if mode != "bwrap" else "")
    )
    return _grader_error_exit(grader_errors, len(found))


def _grader_error_exit(students: list[str], graded: int) -> int:
    """3 and one sentence on stderr when rows failed on the grader's side (not the student's)."""
    if not students:
        return 0
    print(
        f"{len(students)} of {graded} submissions were not graded because the grader failed "
        f"(status 'grader error'; the first: {students[0]}). Fix the cause and regrade them "
        f"with --only; the scores of these rows are not grades.",
        file=sys.stderr,
    )
    return 3


if __name__ == "__main__":
    sys.exit(main())
