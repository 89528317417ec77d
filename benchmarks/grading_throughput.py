"""Grading throughput: N copies of a solution notebook through the sandboxed grader.

Usage::

    .venv/bin/python benchmarks/grading_throughput.py [--copies 20] [--jobs 2] [--hw hw01]

Prints submissions per minute (wall clock, including kernel start-up and the sandbox) and
checks that every copy scored full marks.  The README's figure comes from this script; it is not
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

ROOT = Path(__file__).resolve().parents[1]


def main(argv: list[str] | None = None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--copies", type=int, default=20)
    p.add_argument("--jobs", type=int, default=2)
    p.add_argument("--hw", default="hw01")
    p.add_argument("--sandbox", default="bwrap", choices=["bwrap", "none"])
    args = p.parse_args(argv)
    solution = next((ROOT / "solutions").glob(f"{args.hw}_*.ipynb"))
    with tempfile.TemporaryDirectory() as tmp:
        subs, out = Path(tmp) / "subs", Path(tmp) / "out"
        subs.mkdir()
        for i in range(args.copies):
            shutil.copyfile(solution, subs / f"student{i:03d}.ipynb")
        start = time.perf_counter()
        subprocess.run(
            [sys.executable, str(ROOT / "tools" / "grade.py"),
             "--tests", str(ROOT / "solutions" / "hidden_tests" / f"{args.hw}.py"),
             "--submissions", str(subs), "--out", str(out), "--jobs", str(args.jobs),
             "--sandbox", args.sandbox],
            check=True, stdout=subprocess.DEVNULL,
        )  # fmt: skip
        seconds = time.perf_counter() - start
        with open(out / "scores.csv", newline="", encoding="utf-8") as fh:
            rows = list(csv.DictReader(fh))
        full = sum(1 for r in rows if float(r["raw_total"]) == max(float(x["raw_total"]) for x in rows))
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    print(f"{args.copies} copies of {solution.name}, --jobs {args.jobs}, --sandbox {args.sandbox}: "
          f"{seconds:.1f} s = {60 * args.copies / seconds:.1f} submissions/minute "
          f"({full}/{len(rows)} at full marks; load average {load:.1f})")
    return 0 if full == len(rows) == args.copies else 1


if __name__ == "__main__":
    sys.exit(main())
