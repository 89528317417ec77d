"""Item 6: nbval time of each notebook and of the whole notebook suite.

One ``pytest --nbval-lax`` run over every ``.ipynb`` under ``notebooks/``,
``exercises/`` and ``solutions/`` (the project's pytest configuration, as in
``make test``), with a JUnit XML report.  A notebook's time is the sum of its
cells' times including setup and teardown (the kernel start and stop); the
suite's time is the wall time of the whole pytest run.  Run once: a notebook is
too slow to repeat within the benchmark's two-minute budget.  Reference, for
scale: a one-cell notebook executed with nbclient (the kernel start and stop).
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from collections import defaultdict
from pathlib import Path

from bench_common import REPO, Result, Sizes

FOLDERS = ("notebooks", "exercises", "solutions")


def find_notebooks() -> list[Path]:
    out: list[Path] = []
    for folder in FOLDERS:
        out += sorted(
            p for p in (REPO / folder).rglob("*.ipynb") if ".ipynb_checkpoints" not in p.parts
        )
    return out


def empty_notebook_time() -> float:
    """Wall time of executing a one-cell notebook with nbclient: the kernel start and
    stop that every notebook pays, for scale."""
    import nbformat
    from nbclient import NotebookClient

    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell("1 + 1")]
    t0 = time.perf_counter()
    NotebookClient(nb, kernel_name="python3", timeout=120).execute()
    return time.perf_counter() - t0


def run(sizes: Sizes, skip: bool = False) -> list[Result]:
    if skip:
        return [Result("6", "notebooks (nbval)", note="skipped (--skip-notebooks or --quick)")]
    notebooks = find_notebooks()
    if not notebooks:
        return [Result("6", "notebooks (nbval)", note="no .ipynb under notebooks/, exercises/, "
                       "solutions/ at run time")]
    with tempfile.TemporaryDirectory() as tmp:
        xml = Path(tmp) / "nbval.xml"
        t0 = time.perf_counter()
        proc = subprocess.run(
            [sys.executable, "-m", "pytest", "-q", "-p", "no:randomly", f"--junitxml={xml}",
             "-o", "junit_duration_report=total", "-o", "junit_family=xunit2",
             *(str(p.relative_to(REPO)) for p in notebooks)],
            capture_output=True, text=True, cwd=REPO, timeout=1800,
        )
        wall = time.perf_counter() - t0
        per_nb: dict[str, float] = defaultdict(float)
        failed: dict[str, int] = defaultdict(int)
        # JUnit's classname is the notebook's relative path with "/" turned into "."
        rel = [p.relative_to(REPO).as_posix() for p in notebooks]
        by_classname = {r.replace("/", "."): r for r in rel}
        if xml.exists():
            for case in ET.parse(xml).getroot().iter("testcase"):
                name = case.get("classname", "")
                nb = by_classname.get(name, name)
                per_nb[nb] += float(case.get("time", 0.0))
                if case.find("failure") is not None or case.find("error") is not None:
                    failed[nb] += 1
    try:
        kernel = empty_notebook_time()
    except Exception:  # no kernel: the nbval run above has said so already
        kernel = None
    results = []
    for nb, seconds in sorted(per_nb.items()):
        note = f"{failed[nb]} cell(s) FAILED" if failed[nb] else "all cells pass"
        results.append(
            Result(
                "6", f"nbval `{nb}`", seconds, "empty notebook" if kernel else "", kernel,
                note=note, met=not failed[nb],
            )
        )
    summary = proc.stdout.strip().splitlines()[-1] if proc.stdout.strip() else proc.stderr[-200:]
    results.append(
        Result(
            "6", f"nbval, whole suite ({len(notebooks)} notebooks)", wall, met=proc.returncode == 0,
            note=f"one pytest run, wall time: {summary}",
        )
    )
    return results
