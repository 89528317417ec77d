#!/usr/bin/env python3
"""Per-student homework variants, the instructor's side (issue 19; ``course_lib.homework.variants``).

Usage::

    python tools/variant.py secret [--out course_secret.txt]
        # once per course: a new random course secret, file mode 0600 (never overwrites one).
        # Keep it out of the repository and away from students; it makes and checks the codes.
    python tools/variant.py codes hw01 --secret-file course_secret.txt --roster roster.csv [--out codes.csv]
        # every student's variant code as CSV (id,name,email,code,tell_the_student) for the LMS:
        # mail merge, a gradebook column, ... Tell each student their code AND their id (the id
        # column): they hand in with STUDENT=<id>. Each student pastes their code into VARIANT.
    python tools/variant.py show hw01 STUDENT --secret-file course_secret.txt
        # office hours: the student's code, their data and the worked answers
        # (``answers_for(data)`` of the hidden tests, solutions/hidden_tests/hw01.py)

``STUDENT`` and the roster id are the ids the grader computes codes from
(``tools/grade.py --secret-file --roster``: the roster id of the submission's one identity).
The roster is the course's CSV (``id`` column) or an LMS export as downloaded (Canvas's
gradebook export: the SIS User ID; Moodle's grading worksheet or grades export: the ID number,
else the e-mail) -- give ``codes`` and ``tools/grade.py`` the same file.  A code is 10
characters without look-alikes, the last a check character (``course_lib.homework.variants``).
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
import importlib.util
import io
import json
import os
import secrets
import sys
from pathlib import Path

from course_lib.homework import variants
from tools.grading import reports
from tools.grading.safe_names import safe_csv_writer

ROOT = Path(__file__).resolve().parents[1]

DEFAULT_SECRET = Path("course_secret.txt")


def make_secret(out: Path) -> Path:
    """Write a new course secret to ``out`` (mode 0600); refuse to overwrite an existing file."""
    text = secrets.token_urlsafe(32) + "\n"
    try:
        out.parent.mkdir(mode=0o700, parents=True, exist_ok=True)  # ~/teaching/2026/, new
        fd = os.open(out, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    except FileExistsError:
        raise SystemExit(
            f"{out} exists: not overwritten (a new secret would change every student's code)"
        ) from None
    except OSError as exc:
        raise SystemExit(f"--out {out}: {exc.strerror}") from None
    with os.fdopen(fd, "w", encoding="ascii") as fh:
        fh.write(text)
    os.chmod(out, 0o600)
    return out


def read_secret(path: Path) -> bytes:
    try:
        secret = Path(path).read_bytes().strip()
    except OSError as exc:
        raise SystemExit(f"--secret-file {path}: {exc.strerror}") from None
    if len(secret) < 16:
        raise SystemExit(f"--secret-file {path}: too short (make one with tools/variant.py secret)")
    return secret


def _homework(hw: str) -> str:
    known = sorted(variants.generators())
    if hw not in known:
        raise SystemExit(f"{hw} has no variants (homeworks with variants: {', '.join(known) or 'none'})")
    return hw


def codes_csv(hw: str, secret: bytes, roster: dict) -> str:
    """``id,name,email,code,tell_the_student`` for every roster entry (codes by the roster id, as
    the grader makes them); the last column is the message for the student: the code and the id
    to hand in with (``make submit ... STUDENT=<id>``)."""
    buf = io.StringIO()
    w = safe_csv_writer(buf, lineterminator="\n")  # a roster name is never run as a formula
    w.writerow(["id", "name", "email", "code", "tell_the_student"])
    for entry in roster.values():
        code = variants.code_for(secret, hw, entry.id)
        w.writerow([entry.id, entry.name, entry.email, code,
                    f"{hw}: your variant code is {code}; hand in with STUDENT={entry.id} "
                    f'(submit(..., student="{entry.id}"))'])  # fmt: skip
    return buf.getvalue()


def load_hidden(hw: str, path: Path | None = None):
    path = Path(path) if path else ROOT / "solutions" / "hidden_tests" / f"{hw}.py"
    if not path.is_file():
        raise SystemExit(f"no hidden tests at {path} (give --tests)")
    spec = importlib.util.spec_from_file_location(f"hidden_{hw}_variant_tool", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _plain(value):
    if hasattr(value, "tolist"):
        return value.tolist()
    return value


def show(hw: str, student: str, secret: bytes, tests: Path | None = None) -> str:
    """The student's code, data (as printed in their notebook) and worked answers."""
    code = variants.code_for(secret, hw, student)
    data = variants.data(hw, code)
    lines = [f"{hw} for {student}: VARIANT = {code!r}", "", "Data:"]
    for q, d in data.items():
        text = d.get("text") if isinstance(d, dict) else None
        body = text if text else json.dumps(d, ensure_ascii=False)
        lines.append(f"  {q}: " + body.replace("\n", "\n      "))
    module = load_hidden(hw, tests)
    worked = getattr(module, "answers_for", None)
    if worked is None:
        lines += ["", f"(no answers_for(data) in the hidden tests of {hw})"]
    else:
        lines += ["", "Worked answers:"]
        lines += [f"  {name} = {_plain(v)!r}" for name, v in worked(data).items()]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("secret", help="create a course secret file (mode 0600)")
    s.add_argument("--out", type=Path, default=DEFAULT_SECRET)
    c = sub.add_parser("codes", help="every student's code, CSV id,name,email,code")
    c.add_argument("homework")
    c.add_argument("--secret-file", type=Path, required=True)
    c.add_argument("--roster", type=Path, required=True, help="CSV with an id column (as for tools/grade.py)")
    c.add_argument("--out", type=Path, help="write the CSV here (default: print it)")
    w = sub.add_parser("show", help="a student's code, data and worked answers")
    w.add_argument("homework")
    w.add_argument("student", help="the student's id (the roster's id)")
    w.add_argument("--secret-file", type=Path, required=True)
    w.add_argument("--tests", type=Path, help="hidden tests (default solutions/hidden_tests/HW.py)")
    args = p.parse_args(argv)

    if args.command == "secret":
        out = make_secret(args.out)
        print(f"wrote a new course secret to {out} (mode 0600): keep it out of git and from students")
        return 0
    hw = _homework(args.homework)
    secret = read_secret(args.secret_file)
    if args.command == "codes":
        try:
            roster = reports.read_roster(args.roster)
        except OSError as exc:
            raise SystemExit(f"--roster {args.roster}: {exc.strerror}") from None
        text = codes_csv(hw, secret, roster)
        if args.out:
            try:
                args.out.parent.mkdir(parents=True, exist_ok=True)
                args.out.write_text(text, encoding="utf-8")
            except OSError as exc:
                raise SystemExit(f"--out {args.out}: {exc.strerror}") from None
            print(f"wrote {text.count(chr(10)) - 1} codes to {args.out}")
            print("the student edition's answer keys hold the students of the roster it was built "
                  "with: after new students, build it again (make release SECRET=... ROSTER=...)")
        else:
            sys.stdout.write(text)
        return 0
    sys.stdout.write(show(hw, args.student, secret, args.tests))
    return 0


if __name__ == "__main__":
    sys.exit(main())
