"""Lecture mode: present a lecture notebook on a projector (``make present L=04``).

1. A *deck* is generated from the lecture (one source: nothing to maintain twice):
   the same cells minus the "check your understanding" answer cells (``quiz(...)``,
   ``check_value(...)``, ``check_choice(...)``, ``check_number(...)``, ``check_vector(...)``:
   they cannot be answered without code), in ``build/present/``.
2. Voilà serves it with the course's ``course-deck`` template
   (``.jupyter-course/voila/templates/``): code hidden, a new slide at every heading,
   28 px text in lines of at most ~80 characters, PageDown/PageUp between slides,
   nothing loaded from the network.  The demos' canvases are 1280 px wide
   (``COURSE_CANVAS_PX``), two thirds of a 1920 px projector.
3. The kernel is *pre-heated*: Voilà executes the deck as soon as it starts, before anyone
   opens the page, so the page is live the moment it opens.  The script prints the URL
   once the deck has been executed (``--wait``: default) and keeps serving until Ctrl-C.

Usage::

    python tools/present.py 07                 # or a path: notebooks/07_stitching_bezier_curves.ipynb
    python tools/present.py 04 --port 8866 --no-wait --build-only

Why Voilà and not RISE: jupyterlab-rise 0.43.1 (the newest release, checked with
``pip index versions jupyterlab-rise``) does not render ipywidgets or ipympl in its slide
view (jupyterlab-contrib/rise #119), and every demo of the course is a widget.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

from course_lib.figure_alt import caption_markdown, cell_alt

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOKS = ROOT / "notebooks"
BUILD = ROOT / "build" / "present"
TEMPLATES = ROOT / ".jupyter-course"  # holds voila/templates/course-deck
TEMPLATE = "course-deck"
CANVAS_PX = 1280  # >= 60 % of a 1920 px wide projector
READY = ".deck-executed"  # written next to the deck by its last cell
#: answer cells of "check your understanding": dropped from the deck
ANSWER_CELL = re.compile(
    r"\b(quiz|check_value|check_choice|check_number|check_vector|check|check_all)\s*\("
)


def find_lecture(which: str) -> Path:
    """``"07"``, ``"7"``, ``"07_stitching_bezier_curves"`` or a path -> the lecture notebook.

    Raises
    ------
    ValueError
        If no lecture (or more than one) matches.
    """
    p = Path(which)
    if p.suffix == ".ipynb" and p.exists():
        return p.resolve()
    key = which.strip()
    if key.isdigit():
        key = f"{int(key):02d}"
    hits = sorted(NOTEBOOKS.glob(f"{key}*.ipynb"))
    if len(hits) != 1:
        names = ", ".join(sorted(q.stem for q in NOTEBOOKS.glob("[0-9][0-9]_*.ipynb")))
        raise ValueError(f"L must name one lecture (e.g. L=04); {which!r} matches "
                         f"{len(hits)} of: {names}")
    return hits[0]


def build_deck(lecture: Path, out_dir: Path = BUILD) -> Path:
    """Write the deck of ``lecture`` into ``out_dir`` and return its path.

    The deck is the lecture without outputs and without its answer cells; everything else
    (prose, figures, demos, the code that makes them, hidden by the template) is kept.
    """
    nb = json.loads(lecture.read_text(encoding="utf-8"))
    cells = []
    for cell in nb["cells"]:
        src = "".join(cell.get("source", ""))
        if cell["cell_type"] == "code":
            if ANSWER_CELL.search(src) and "def " not in src:
                continue
            cell = {**cell, "outputs": [], "execution_count": None}
        cells.append(cell)
        alt = cell_alt(cell.get("metadata")) if cell["cell_type"] == "code" else None
        if alt:  # the figure's text alternative, visible, and its img's alt (deck template)
            cells.append({"cell_type": "markdown", "id": f"{cell.get('id', 'fig')}-alt",
                          "metadata": {}, "source": [caption_markdown(alt)]})
    # last, a cell without output that tells tools/present.py the deck has been executed
    cells.append({"cell_type": "code", "execution_count": None, "id": "deck-ready",
                  "metadata": {}, "outputs": [],
                  "source": [f"open({READY!r}, 'w').close()  # lecture mode: executed"]})
    deck = {**nb, "cells": cells}
    deck.setdefault("metadata", {})["kernelspec"] = {
        "name": "python3", "display_name": "Python 3 (ipykernel)", "language": "python"}
    out_dir.mkdir(parents=True, exist_ok=True)
    # the lecture's relative links and files keep working next to the deck
    for f in NOTEBOOKS.iterdir():
        if f.is_file() and f.suffix != ".ipynb":
            shutil.copy2(f, out_dir / f.name)
    out = out_dir / lecture.name
    out.write_text(json.dumps(deck, indent=1, ensure_ascii=False), encoding="utf-8")
    return out


def voila_command(deck: Path, port: int, *, python: str = sys.executable) -> list[str]:
    return [
        python, "-m", "voila", deck.name, "--no-browser",
        f"--port={port}", "--Voila.ip=127.0.0.1", "--Voila.port_retries=0",
        f"--template={TEMPLATE}", "--theme=light",
        "--preheat_kernel=True", "--pool_size=1",
        "--show_tracebacks=True",
        f"--Voila.root_dir={deck.parent}",
    ]


def voila_env(base: dict | None = None) -> dict:
    env = dict(os.environ if base is None else base)
    paths = [str(TEMPLATES)] + [p for p in env.get("JUPYTER_PATH", "").split(os.pathsep) if p]
    env["JUPYTER_PATH"] = os.pathsep.join(paths)
    env["COURSE_CANVAS_PX"] = str(CANVAS_PX)
    env["PYTHONPATH"] = os.pathsep.join(
        [str(ROOT)] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    return env


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_preheated(marker: Path, proc: subprocess.Popen, timeout: float) -> bool:
    """True once the pre-heated kernel has executed the whole deck (its last cell wrote
    ``marker``); False if Voilà exited or ``timeout`` passed."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if proc.poll() is not None:
            return False
        if marker.exists():
            return True
        time.sleep(0.3)
    return False


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("lecture", help="lecture number (04) or notebook path")
    ap.add_argument("--port", type=int, default=8866)
    ap.add_argument("--build-only", action="store_true", help="write the deck and stop")
    ap.add_argument("--no-wait", action="store_true",
                    help="print the URL at once instead of after pre-heating")
    args = ap.parse_args(argv)
    try:
        lecture = find_lecture(args.lecture)
    except ValueError as exc:
        print(exc, file=sys.stderr)
        return 2
    deck = build_deck(lecture)
    print(f"deck: {deck.relative_to(ROOT)}")
    if args.build_only:
        return 0
    log = deck.parent / "voila.log"
    marker = deck.parent / READY
    marker.unlink(missing_ok=True)
    signal.signal(signal.SIGTERM, lambda *_: (_ for _ in ()).throw(KeyboardInterrupt()))
    with log.open("wb") as fh:
        proc = subprocess.Popen(voila_command(deck, args.port), cwd=deck.parent,
                                env=voila_env(), stdout=fh, stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{args.port}/"
    try:
        if not args.no_wait:
            print("executing the lecture in a pre-heated kernel ...", flush=True)
            if not wait_preheated(marker, proc, timeout=300):
                print(f"Voilà did not execute the deck; see {log}", file=sys.stderr)
        print(f"lecture mode: open {url}  (PageDown/PageUp: next/previous slide; Ctrl-C stops)",
              flush=True)
        proc.wait()
    except KeyboardInterrupt:
        pass
    finally:
        if proc.poll() is None:
            proc.send_signal(signal.SIGTERM)
            try:
                proc.wait(15)
            except subprocess.TimeoutExpired:
                proc.kill()
    return 0


if __name__ == "__main__":
    sys.exit(main())
