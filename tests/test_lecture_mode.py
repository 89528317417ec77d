"""Lecture mode: Voilà serves a demo notebook as a page with live widgets.

Starts ``voila`` on loopback with a free port (``port_retries=0``: a busy port fails
instead of silently moving), requests the page (the notebook is executed for the
request), checks that the executed page carries the demo's widget view and the text
of its continuity report, then stops the server with SIGTERM and checks that neither
the server nor its kernel is left running.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "tests" / "fixtures" / "lecture_demo.ipynb"
VOILA = Path(sys.executable).with_name("voila")

# waits are generous (a loaded machine is slow, not wrong); the timeout only guards a hang
WAIT_S = 300
pytestmark = pytest.mark.timeout(900)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def children(pid: int) -> set[int]:
    """All descendants of ``pid`` (Linux /proc)."""
    kids: dict[int, list[int]] = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                ppid = int((d / "stat").read_text().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            kids.setdefault(ppid, []).append(int(d.name))
    out, todo = set(), [pid]
    while todo:
        for k in kids.get(todo.pop(), []):
            if k not in out:
                out.add(k)
                todo.append(k)
    return out


def alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    stat = Path(f"/proc/{pid}/stat")
    return not (stat.exists() and stat.read_text().rsplit(")", 1)[1].split()[0] == "Z")


@pytest.mark.skipif(
    not VOILA.exists() and shutil.which("voila") is None,
    reason="voila is not installed (pip install voila) - lecture mode untested",
)
@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc to find leftover processes")
def test_voila_serves_the_demo_with_its_widgets(tmp_path):
    exe = str(VOILA) if VOILA.exists() else shutil.which("voila")
    shutil.copy(NOTEBOOK, tmp_path / NOTEBOOK.name)
    port = free_port()
    env = dict(os.environ, JUPYTER_RUNTIME_DIR=str(tmp_path / "runtime"))
    log = open(tmp_path / "voila.log", "w+")  # closed in the finally block
    proc = subprocess.Popen(
        [
            exe,
            NOTEBOOK.name,
            "--no-browser",
            f"--port={port}",
            "--Voila.ip=127.0.0.1",
            "--Voila.port_retries=0",
            "--show_tracebacks=True",
        ],
        cwd=tmp_path,
        env=env,
        stdout=log,
        stderr=subprocess.STDOUT,
    )
    descendants: set[int] = set()
    try:
        url = f"http://127.0.0.1:{port}/"
        deadline = time.monotonic() + WAIT_S
        page = None
        while time.monotonic() < deadline:
            assert proc.poll() is None, "voila exited early:\n" + log_text(log)
            try:
                with urllib.request.urlopen(url, timeout=40) as r:
                    assert r.status == 200
                    page = r.read().decode("utf-8", "replace")
                break
            except (ConnectionError, urllib.error.URLError):
                time.sleep(0.3)
        assert page is not None, f"voila did not answer within {WAIT_S} s:\n" + log_text(log)
        descendants = children(proc.pid)
        assert "application/vnd.jupyter.widget-view+json" in page, page[-2000:]
        assert "Joint 0 at" in page and "G2" in page  # the printed continuity report
        assert "Traceback" not in page
        assert descendants, "the notebook's kernel should be a child of the server"
    finally:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()
            pytest.fail("voila did not stop on SIGTERM:\n" + log_text(log))
        log.close()
    time.sleep(0.5)
    left = [p for p in descendants if alive(p)]
    for p in left:
        os.kill(p, signal.SIGKILL)
    assert not left, f"processes left behind after SIGTERM: {left}"


def log_text(f) -> str:
    f.flush()
    f.seek(0)
    return f.read()[-3000:]


# ----------------------------------------------- make present: the deck of a lecture
def _present():

    from tools import present

    return present


def test_deck_is_the_lecture_without_answer_cells(tmp_path):
    import json

    present = _present()
    lecture = present.find_lecture("04")
    assert lecture.name.startswith("04_")
    deck = present.build_deck(lecture, tmp_path)
    src = json.loads(lecture.read_text())["cells"]
    out = json.loads(deck.read_text())["cells"]
    answers = [c for c in src if c["cell_type"] == "code"
               and present.ANSWER_CELL.search("".join(c["source"]))]
    assert answers, "lecture 04 has check-your-understanding cells"
    kept = [c for c in src if c not in answers]
    # the same cells in the same order (no second copy to maintain), minus the answers, plus
    # after each figure its text alternative as a visible caption (the deck's img alt comes
    # from it), plus the last cell that tells present.py the deck was executed
    captions = [c for c in out if c["id"].endswith("-alt")]
    assert [c["id"] for c in out[:-1] if c not in captions] == [c["id"] for c in kept]
    with_alt = [c for c in kept if c["cell_type"] == "code"
                and c.get("metadata", {}).get("mystnb", {}).get("image", {}).get("alt")]
    assert [c["id"] for c in captions] == [f"{c['id']}-alt" for c in with_alt] and captions
    for c in with_alt:
        i = [x["id"] for x in out].index(c["id"])
        alt = " ".join(c["metadata"]["mystnb"]["image"]["alt"].split())
        assert "".join(out[i + 1]["source"]) == f"*Figure:* {alt}"
    assert all(not c.get("outputs") for c in out if c["cell_type"] == "code")
    assert present.READY in "".join(out[-1]["source"])
    assert any("_demo(" in "".join(c["source"]) for c in out)


def test_find_lecture_names_the_lectures_on_a_bad_choice():
    present = _present()
    assert present.find_lecture("4") == present.find_lecture("04")
    with pytest.raises(ValueError, match=r"L must name one lecture.*00_welcome"):
        present.find_lecture("99")


def test_voila_runs_the_deck_template_preheated_and_offline():
    present = _present()
    cmd = " ".join(present.voila_command(Path("/x/07_stitching_bezier_curves.ipynb"), 8866))
    assert "--template=course-deck" in cmd and "--preheat_kernel=True" in cmd
    assert "--Voila.ip=127.0.0.1" in cmd
    env = present.voila_env({})
    assert int(env["COURSE_CANVAS_PX"]) >= 0.6 * 1920
    tpl = ROOT / ".jupyter-course" / "voila" / "templates" / "course-deck" / "index.html.j2"
    assert env["JUPYTER_PATH"].split(os.pathsep)[0] == str(tpl.parents[3])
    import re

    loads = re.findall(r"""(?:href|src)=["']https?://[^"']+""", tpl.read_text())
    assert not loads, loads  # nothing from a CDN


def test_make_present_and_make_lab_commands():
    if shutil.which("make") is None:
        pytest.skip("make is not installed")
    out = subprocess.run(["make", "-n", "-o", ".venv/.installed", "present", "L=04"],
                         cwd=ROOT, capture_output=True, text=True).stdout
    assert "tools/present.py 04" in out
    out = subprocess.run(["make", "-n", "-o", ".venv/.installed", "lab"],
                         cwd=ROOT, capture_output=True, text=True).stdout
    assert "--config=" + str(ROOT / ".jupyter-course" / "jupyter_server_config.py") in out
