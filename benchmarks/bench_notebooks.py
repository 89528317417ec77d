"""Item 6: nbval time of each notebook and of the whole notebook suite.

``pytest --nbval-lax`` over every ``.ipynb`` under ``notebooks/``, ``exercises/``
and ``solutions/`` (the project's pytest configuration, as in ``make test``), with
JUnit XML reports; the notebooks are shared out to two pytest processes running
side by side (one per core) to keep the benchmark short.  A notebook's time is
the sum of its cells' times including setup and teardown (the kernel start and
stop); the suite's time is reported both as the sum over the notebooks (what the
sequential ``make test`` spends on them) and as this run's wall time.  Run once: a notebook is
too slow to repeat within the benchmark's two-minute budget.  Reference, for
scale: a one-cell notebook executed with nbclient (the kernel start and stop).
"""

from __future__ import annotations

import os
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


def _split(notebooks: list[Path], workers: int) -> list[list[Path]]:
    """Balanced groups, largest files first (file size as a proxy for run time)."""
    groups: list[list[Path]] = [[] for _ in range(workers)]
    load = [0] * workers
    for nb in sorted(notebooks, key=lambda p: -p.stat().st_size):
        i = load.index(min(load))
        groups[i].append(nb)
        load[i] += nb.stat().st_size
    return [g for g in groups if g]


def run(sizes: Sizes, skip: bool = False, workers: int | None = None) -> list[Result]:
    if skip:
        return [Result("6", "notebooks (nbval)", note="skipped (--skip-notebooks or --quick)")]
    notebooks = find_notebooks()
    if not notebooks:
        return [Result("6", "notebooks (nbval)", note="no .ipynb under notebooks/, exercises/, "
                       "solutions/ at run time")]
    workers = workers or max(1, min(2, os.cpu_count() or 1))
    groups = _split(notebooks, workers)
    rel = [p.relative_to(REPO).as_posix() for p in notebooks]
    by_classname = {r.replace("/", "."): r for r in rel}  # JUnit classname: "/" -> "."
    per_nb: dict[str, float] = defaultdict(float)
    failed: dict[str, int] = defaultdict(int)
    summaries, codes = [], []
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        procs = []
        for g, group in enumerate(groups):
            xml = Path(tmp) / f"nbval-{g}.xml"
            cmd = [
                sys.executable, "-m", "pytest", "-q", "-p", "no:randomly", f"--junitxml={xml}",
                "-o", "junit_duration_report=total", "-o", "junit_family=xunit2",
                *(p.relative_to(REPO).as_posix() for p in group),
            ]
            procs.append((xml, subprocess.Popen(
                cmd, cwd=REPO, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
            )))
        for xml, proc in procs:
            out, err = proc.communicate(timeout=1800)
            codes.append(proc.returncode)
            summaries.append(out.strip().splitlines()[-1] if out.strip() else err[-200:])
            if not xml.exists():
                continue
            for case in ET.parse(xml).getroot().iter("testcase"):
                name = case.get("classname", "")
                nb = by_classname.get(name, name)
                per_nb[nb] += float(case.get("time", 0.0))
                if case.find("failure") is not None or case.find("error") is not None:
                    failed[nb] += 1
        wall = time.perf_counter() - t0
    try:
        kernel = empty_notebook_time()
    except Exception:  # no kernel: the nbval run above has said so already
        kernel = None
    results = []
    for nb, seconds in sorted(per_nb.items()):
        note = f"{failed[nb]} cell(s) FAILED" if failed[nb] else "all cells pass"
        if len(groups) > 1:
            note += f"; ran beside another notebook ({len(groups)} pytest processes)"
        results.append(
            Result(
                "6", f"nbval `{nb}`", seconds, "empty notebook" if kernel else "", kernel,
                note=note, met=not failed[nb],
            )
        )
    ok = all(c == 0 for c in codes)
    results.append(
        Result(
            "6", f"nbval, all {len(notebooks)} notebooks, one after another", sum(per_nb.values()),
            met=ok, note="sum of the notebooks' times: what the sequential `pytest` run spends",
        )
    )
    results.append(
        Result(
            "6", f"nbval, all {len(notebooks)} notebooks, {len(groups)} pytest processes",
            wall, met=ok, note="wall time of this run; " + " / ".join(summaries),
        )
    )
    return results
