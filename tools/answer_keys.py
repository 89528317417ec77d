#!/usr/bin/env python3
"""Answer keys for the edition's checks: the instructor's side (``course_lib.homework.answer_keys``).

Usage::

    python tools/answer_keys.py
        # the keys of the default data: rewrites course_lib/homework/answer_keys.json
    python tools/answer_keys.py --secret-file course_secret.txt --roster roster.csv --out keys.json
        # the keys of the default data and of every roster student's data

``make release SECRET=course_secret.txt ROSTER=roster.csv`` writes the second kind into the
student edition, so each student's checks of hw01 q1, q4, q5, q7 and hw02 q5 know their value
without holding it.  The values come from the hidden tests (``key_values(data)`` in
``solutions/hidden_tests/hwNN.py``), the grid step of each question from its checks module
(``ANSWER_KEYS``).  A student who is not on the roster (a late enrolment) gets "value not
checked here" from those checks until the edition, or just this file, is made again.
"""

from __future__ import annotations

if __name__ == "__main__":  # run as printed: with the course's .venv if any
    import os as _os
    import sys as _sys
    from pathlib import Path as _Path

    _venv = _Path(__file__).resolve().parents[1] / ".venv"
    if (_venv / "bin" / "python").is_file() and _Path(_sys.prefix).resolve() != _venv.resolve():
        _os.execv(str(_venv / "bin" / "python"), [str(_venv / "bin" / "python"), *_sys.argv])

import argparse
import importlib
import sys
from collections.abc import Iterable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from course_lib.homework import answer_keys, variants
from tools.grading import reports
from tools.variant import load_hidden, read_secret

ROOT = Path(__file__).resolve().parents[1]
PACKAGE_KEYS = ROOT / "course_lib" / "homework" / answer_keys.KEY_FILE


def keyed_questions() -> dict[str, dict[str, float]]:
    """``{homework: {question: grid step}}`` of every checks module with an ``ANSWER_KEYS``."""
    out = {}
    for hw in sorted(variants.generators()):
        quanta = getattr(
            importlib.import_module(f"course_lib.homework.checks.{hw}"), "ANSWER_KEYS", None
        )
        if quanta:
            out[hw] = dict(quanta)
    return out


def for_data(homework: str, data: dict, key_values, cost: int = 16) -> answer_keys.AnswerKeys:
    """The keys of one student's ``data`` of ``homework`` (``key_values`` of its hidden tests):
    what the grader shows the submission's kernel.  Cheap digests: the file never leaves the
    grader's sandbox, whose grade does not depend on it."""
    quanta = keyed_questions().get(homework, {})
    values = key_values(data) if quanta else {}
    keys = dict(
        answer_keys.entry(f"{homework}.{q}", quantum, data[q], values[q], cost=cost)
        for q, quantum in quanta.items()
    )
    return answer_keys.AnswerKeys({"format": answer_keys.FORMAT, "cost": cost, "keys": keys})


def build(
    codes: Iterable[str] = (),
    *,
    secret: bytes | None = None,
    students: Iterable[str] = (),
    cost: int = answer_keys.DEFAULT_COST,
    hidden_tests: Path | None = None,
) -> answer_keys.AnswerKeys:
    """The keys of the default data, of the variant ``codes`` and of the ``students``' codes
    under ``secret`` (each homework's own code, as ``tools/variant.py codes`` makes them)."""
    students = list(students)
    if students and secret is None:
        raise ValueError("students need the course secret to have codes")
    jobs = []
    for hw, quanta in keyed_questions().items():
        hidden = load_hidden(hw, hidden_tests / f"{hw}.py" if hidden_tests else None)
        wanted = [variants.DEFAULT, *codes, *(variants.code_for(secret, hw, s) for s in students)]
        for code in dict.fromkeys(wanted):
            data = variants.generator(hw)(variants.rng_for(hw, code))
            values = hidden.key_values(data)
            for q, quantum in quanta.items():
                jobs.append((f"{hw}.{q}", quantum, data[q], values[q]))

    def key(job):
        return answer_keys.entry(*job, cost=cost)

    if cost >= 1024:  # scrypt releases the GIL: threads use every core
        with ThreadPoolExecutor() as pool:
            keys = dict(pool.map(key, jobs))
    else:  # cheap digests (tests): threads would cost more than they save
        keys = dict(map(key, jobs))
    return answer_keys.AnswerKeys({"format": answer_keys.FORMAT, "cost": cost, "keys": keys})


def for_roster(secret_file: Path, roster: Path) -> tuple[answer_keys.AnswerKeys, list[str]]:
    """The keys of the default data and of every student of ``roster`` (an LMS export as
    downloaded, as for ``tools/variant.py codes``), and the students' ids; ``SystemExit`` with
    one sentence for an unreadable file."""
    secret = read_secret(secret_file)
    try:
        students = [entry.id for entry in reports.read_roster(roster).values()]
    except OSError as exc:
        raise SystemExit(f"--roster {roster}: {exc.strerror}") from None
    return build(secret=secret, students=students), students


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--secret-file", type=Path, help="the course secret (tools/variant.py secret)")
    p.add_argument("--roster", type=Path, help="the roster the codes were made from")
    p.add_argument("--out", type=Path, default=PACKAGE_KEYS, help="default: the package's key file")
    args = p.parse_args(argv)
    if (args.secret_file is None) != (args.roster is None):
        raise SystemExit("give --secret-file and --roster together (the students' codes need both)")
    if args.roster is not None:
        keys, students = for_roster(args.secret_file, args.roster)
    else:
        keys, students = build(), []
    try:
        keys.write(args.out)
    except OSError as exc:
        raise SystemExit(f"--out {args.out}: {exc.strerror}") from None
    print(f"wrote the answer keys of the default data and {len(students)} students to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
