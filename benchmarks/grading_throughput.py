"""Grading throughput: N copies of a solution notebook through the sandboxed grader.

Usage::

    .venv/bin/python benchmarks/grading_throughput.py [--copies 20] [--jobs 2] [--hw hw01] [--variants]

Prints submissions per minute (wall clock, including kernel start-up and the sandbox) and
checks that every copy scored full marks.  With ``--variants`` the batch is graded as a course
with per-student variants grades it: a course secret (``--secret-file``), and each copy of the
solution done with its own student's variant code.  The README's figure comes from this script; it is not
part of the test suite (a timed assertion would fail on a busy machine).
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import nbformat

ROOT = Path(__file__).resolve().parents[1]


def _points(hidden: Path) -> dict:
    ns: dict = {}
    exec(compile(hidden.read_text(encoding="utf-8"), str(hidden), "exec"), ns)
    return ns["POINTS"]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--copies", type=int, default=20)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--hw", default="hw01")
    p.add_argument("--sandbox", default="bwrap", choices=["bwrap", "none"])
    p.add_argument("--variants", action="store_true", help="grade with a course secret")
    args = p.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    from course_lib.homework import variants

    secret = b"the benchmark's course secret, 32"
    solution = next((ROOT / "solutions").glob(f"{args.hw}_*.ipynb"))
    with tempfile.TemporaryDirectory() as tmp:
        subs, out = Path(tmp) / "subs", Path(tmp) / "out"
        subs.mkdir()
        for i in range(args.copies):
            name = f"student{i:03d}"
            if args.variants:
                nb = nbformat.read(solution, as_version=4)
                cell = next(c for c in nb.cells if c.cell_type == "code" and 'VARIANT = ""' in c.source)
                code = variants.code_for(secret, args.hw, name)
                cell.source = cell.source.replace('VARIANT = ""', f"VARIANT = {code!r}", 1)
                nbformat.write(nb, subs / f"{name}.ipynb")
            else:
                shutil.copyfile(solution, subs / f"{name}.ipynb")
        extra = []
        if args.variants:
            (Path(tmp) / "secret").write_bytes(secret)
            extra = ["--secret-file", str(Path(tmp) / "secret")]
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, str(ROOT / "tools" / "grade.py"),
             "--tests", str(ROOT / "solutions" / "hidden_tests" / f"{args.hw}.py"),
             "--submissions", str(subs), "--out", str(out), "--jobs", str(args.jobs),
             "--sandbox", args.sandbox, *extra],
            check=True, stdout=subprocess.DEVNULL,
        )  # fmt: skip
        seconds = time.perf_counter() - start
        with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
            rows = list(csv.DictReader(fh))
        maximum = sum(_points(ROOT / "solutions" / "hidden_tests" / f"{args.hw}.py").values())
        full = sum(1 for r in rows if float(r["raw_total"]) == maximum)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"{args.copies} copies of {solution.name}, --jobs {args.jobs}, --sandbox {args.sandbox}"
          f"{', variants on' if args.variants else ''}: "
          f"{seconds:.1f} s = {60 * args.copies / seconds:.1f} submissions/minute "
          f"({full}/{len(rows)} at full marks; load average {load:.1f})")
    return 0 if full == len(rows) == args.copies else 1


if __name__ == "__main__":
    sys.exit(main())
