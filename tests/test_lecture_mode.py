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

pytestmark = pytest.mark.timeout(60)


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
        deadline = time.monotonic() + 30
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
        assert page is not None, "voila did not answer within 30 s:\n" + log_text(log)
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
