"""Harness of the browser tests: a private JupyterLab (or Voilà) server, headless Chromium.

The pytest fixtures built on it are in conftest.py.

Everything a test starts is stopped by its fixture, also when the test fails:

* a server on ``127.0.0.1`` at a free port (``port_retries=0``, so it never silently moves),
  with a random token, its own root folder holding *copies* of the notebooks (JupyterLab
  autosaves into it), its own settings, workspaces, runtime, config and IPython folders,
  all under one temporary directory;
* headless Debian Chromium driven by Playwright's sync API (``executable_path``; never
  ``playwright install``), with every request to a host other than ``127.0.0.1`` aborted.

Stopping sends SIGTERM to the server (it shuts its kernels down) and then checks that no
process whose command line or working directory lies in that temporary directory is left
(JupyterLab's kernels have their connection file in its runtime folder; every kernel runs in
the root folder, where its notebook is).

Without Playwright or Chromium the tests are skipped with the reason (``make test`` installs
Chromium first with ``tools/ensure-browser``).  Recipe: /work/shared/recipes/
browser-and-notebook-testing.md.
"""

from __future__ import annotations

import http.client
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from urllib.parse import urlsplit

ROOT = Path(__file__).resolve().parents[2]
ARTIFACTS = ROOT / "test-artifacts"
#: How long a browser test waits for something that must happen (a server, a kernel, a frame,
#: a report) before it counts as a hang.  Generous on purpose: on a loaded machine things are
#: slow, not wrong; how long they take is measured (test_demo_latency.py), never asserted.
WAIT_S = float(os.environ.get("COURSE_BROWSER_WAIT_S", "300"))
WAIT_MS = int(WAIT_S * 1000)
# one rule for finding the browser, shared with the handouts (tools/chromium.py)
from tools.chromium import CHROMIUM_ENV as CHROMIUM_ENV  # noqa: E402
from tools.chromium import find_chromium as find_chromium  # noqa: E402

# ----------------------------------------------------------------------------- the kernel behind a page
EXECUTE_JS = """async (code) => {
  const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
  const future = kernel.requestExecute({code, silent: false, store_history: false});
  let out = '';
  future.onIOPub = (msg) => {
    const t = msg.header.msg_type;
    if (t === 'stream') out += msg.content.text;
    else if (t === 'execute_result') out += msg.content.data['text/plain'];
    else if (t === 'error') out += 'KERNEL ERROR ' + msg.content.ename + ': ' + msg.content.evalue;
  };
  await future.done;
  return out;
}"""

# 'error: ...' as soon as a cell has an error output; true when every code cell has run and
# the kernel is idle.
RUN_STATE_JS = """() => {
  const w = window.jupyterapp && window.jupyterapp.shell.currentWidget;
  if (!w || !w.content || !w.content.model || !w.sessionContext.session) return false;
  const cells = w.content.model.toJSON().cells.filter(c => c.cell_type === 'code');
  for (const [i, c] of cells.entries()) {
    for (const o of (c.outputs || [])) {
      if (o.output_type === 'error') return `error in code cell ${i}: ${o.ename}: ${o.evalue}`;
    }
  }
  const kernel = w.sessionContext.session.kernel;
  return cells.every(c => c.execution_count !== null) && kernel && kernel.status === 'idle';
}"""


def kernel(page, code: str) -> str:
    out = page.evaluate(EXECUTE_JS, code)
    assert "KERNEL ERROR" not in out, out
    return out


# ----------------------------------------------------------------------------- browser
class PageLog:
    """Console errors, uncaught page errors, HTTP errors and aborted outside requests of a page."""

    def __init__(self) -> None:
        self.console_errors: list[str] = []
        self.page_errors: list[str] = []
        self.blocked: list[str] = []
        self.http_errors: list[str] = []

    def problems(self, ignore: tuple[str, ...] = ()) -> list[str]:
        msgs = [f"console: {m}" for m in self.console_errors] + [
            f"pageerror: {m}" for m in self.page_errors
        ] + [f"http: {m}" for m in self.http_errors]
        return [m for m in msgs if not any(s in m for s in ignore)]


def new_page(browser, *, width: int = 1400, height: int = 1000):
    """A page in a fresh context that may only talk to 127.0.0.1; returns ``(context, page, log)``."""
    context = browser.new_context(viewport={"width": width, "height": height},
                                  device_scale_factor=1)
    page = context.new_page()
    log = PageLog()

    def local_only(route):
        host = urlsplit(route.request.url).hostname
        if host in ("127.0.0.1", "localhost") or route.request.url.startswith(("data:", "blob:")):
            route.continue_()
        else:
            log.blocked.append(route.request.url)
            route.abort()

    page.route("**/*", local_only)
    page.on("console", lambda m: m.type == "error" and log.console_errors.append(m.text))
    page.on("pageerror", lambda e: log.page_errors.append(str(e)))
    page.on("response", lambda r: r.status >= 400 and log.http_errors.append(f"{r.status} {r.url}"))
    return context, page, log


# ----------------------------------------------------------------------------- servers
def free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def processes_under(path: Path) -> list[str]:
    """``pid cmdline`` of every process whose command line or cwd mentions ``path``
    (Linux /proc; elsewhere nothing can be checked and the list is empty)."""
    key = str(path).rstrip("/") + "/"
    found = []
    if not Path("/proc").is_dir():
        return found
    for d in Path("/proc").iterdir():
        if not d.name.isdigit() or int(d.name) == os.getpid():
            continue
        try:
            cmd = (d / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        try:
            cwd = os.readlink(d / "cwd")
        except OSError:
            cwd = ""
        if key in cmd or (cwd + "/").startswith(key):
            found.append(f"{d.name} {cmd.strip()}")
    return found


class Server:
    """A notebook server subprocess living in its own temporary directory ``base``.

    ``base/root`` holds copies of the notebooks; ``base/settings``, ``base/ws``,
    ``base/rt`` (runtime: kernel connection files), ``base/config``, ``base/ipython``
    isolate it from the user's Jupyter set-up.
    """

    def __init__(self, kind: str, base: Path, notebooks: list[Path], *, token: str) -> None:
        self.kind, self.base, self.token = kind, base, token
        self.root = base / "root"
        self.root.mkdir(parents=True)
        for nb in notebooks:
            shutil.copy2(nb, self.root / nb.name)
        self.port = free_port()
        self.url = f"http://127.0.0.1:{self.port}"
        self.log_path = base / f"{kind}.log"
        self.proc: subprocess.Popen | None = None
        self.returncode: int | None = None
        self.leftovers: list[str] = []

    # -- configuration
    def env(self) -> dict:
        env = dict(os.environ)
        for name, sub in (("JUPYTER_RUNTIME_DIR", "rt"), ("JUPYTER_CONFIG_DIR", "config"),
                          ("IPYTHONDIR", "ipython"), ("MPLCONFIGDIR", "mpl")):
            (self.base / sub).mkdir(exist_ok=True)
            env[name] = str(self.base / sub)
        env.pop("JUPYTER_TOKEN", None)
        return env

    def lab_command(self) -> list[str]:
        # The course's own configuration, as `make lab` loads it: its settings defaults
        # (no news popup, font sizes, kernel started without asking) and the pre-save hook
        # that strips widget views.  The user-settings folder stays private, seeded with the
        # course's defaults as `make lab` seeds .jupyter-course/lab/user-settings/.
        settings = self.base / "settings"
        if not settings.exists():
            shutil.copytree(ROOT / ".jupyter-course" / "lab" / "user-settings-defaults", settings)
        workspaces = self.base / "ws"
        if not workspaces.exists():  # the course's layout: the table of contents open
            shutil.copytree(ROOT / ".jupyter-course" / "lab" / "workspaces-defaults", workspaces)
        cmd = [
            sys.executable, "-m", "jupyterlab", "--no-browser",
            "--ServerApp.ip=127.0.0.1", f"--ServerApp.port={self.port}",
            f"--config={ROOT / '.jupyter-course' / 'jupyter_server_config.py'}",
            "--ServerApp.port_retries=0", f"--IdentityProvider.token={self.token}",
            f"--ServerApp.root_dir={self.root}",
            f"--LabApp.user_settings_dir={settings}",
            f"--LabApp.workspaces_dir={workspaces}",
            "--LabApp.news_url=None",
            "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
            "--LabApp.expose_app_in_browser=True",  # window.jupyterapp: kernel probe, model
            "--LabApp.extension_manager=readonly",  # never asks PyPI
            # server extensions the test does not use: less to import on a busy machine
            # (not jupyter_lsp: without it the page's GET /lsp/status is a 404 error)
            *(f"--ServerApp.jpserver_extensions={ext}=False" for ext in (
                "jupyter_server_terminals", "voila.server_extension", "notebook_shim")),
        ]
        if os.geteuid() == 0:
            cmd.append("--allow-root")
        return cmd

    def voila_command(self, notebook: str) -> list[str]:
        return [
            sys.executable, "-m", "voila", str(self.root / notebook), "--no-browser",
            "--Voila.ip=127.0.0.1", f"--port={self.port}", "--Voila.port_retries=0",
            f"--Voila.token={self.token}", f"--Voila.root_dir={self.root}",
            "--show_tracebacks=True",
        ]

    # -- life cycle
    def launch(self, cmd: list[str]) -> None:
        """Start the server process (does not wait; see ``wait_ready``)."""
        self._log = self.log_path.open("wb")
        self.proc = subprocess.Popen(
            cmd, cwd=self.root, env=self.env(), stdout=self._log, stderr=subprocess.STDOUT,
            stdin=subprocess.DEVNULL, start_new_session=True,
        )

    def wait_ready(self, timeout: float = WAIT_S) -> None:
        """Wait until the server answers; raise with the log's tail if it exits or hangs."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise RuntimeError(f"{self.kind} server exited with {self.proc.returncode}:\n"
                                   f"{self.log_tail()}")
            if self._ready():
                return
            time.sleep(0.2)
        raise RuntimeError(f"{self.kind} server not ready after {timeout} s:\n{self.log_tail()}")

    def _ready(self) -> bool:
        """JupyterLab: ``GET /api/status`` answers 200 (with the token).  Voilà: the port
        accepts connections (any page request would start executing the notebook)."""
        if self.kind != "lab":
            try:
                with socket.create_connection(("127.0.0.1", self.port), timeout=1):
                    return True
            except OSError:
                return False
        req = urllib.request.Request(self.url + "/api/status",
                                     headers={"Authorization": f"token {self.token}"})
        try:
            with urllib.request.urlopen(req, timeout=2) as r:
                return r.status == 200
        except (urllib.error.URLError, ConnectionError, TimeoutError):
            return False

    def start_kernel_for(self, notebook: str) -> None:
        """Create the notebook's session (and kernel) through the REST API, so the kernel
        starts while the browser loads JupyterLab, which then attaches to it."""
        body = json.dumps({"path": notebook, "name": notebook, "type": "notebook",
                           "kernel": {"name": "python3"}}).encode()
        req = urllib.request.Request(
            self.url + "/api/sessions", data=body, method="POST",
            headers={"Authorization": f"token {self.token}",
                     "Content-Type": "application/json"})
        with urllib.request.urlopen(req, timeout=60) as r:
            assert r.status == 201, r.status

    def status_without_token(self, path: str) -> int:
        """HTTP status of ``GET path`` without the token, redirects not followed
        (JupyterLab's API answers 403, Voilà redirects to /login: 302)."""
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=10)
        try:
            conn.request("GET", path)
            return conn.getresponse().status
        finally:
            conn.close()

    def stop(self, timeout: float = 15.0) -> None:
        """SIGTERM (the server shuts its kernels down), then wait for everything under ``base``.

        Idempotent.  Anything still alive after ``timeout`` is killed and listed in
        ``leftovers`` (the tests assert that list is empty).
        """
        if self.proc is None or self.returncode is not None:
            return
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(5)
        self.returncode = self.proc.returncode
        self._log.close()
        deadline = time.monotonic() + timeout
        left = processes_under(self.base)
        while left and time.monotonic() < deadline:
            time.sleep(0.2)
            left = processes_under(self.base)
        self.leftovers = left
        for line in left:  # never leave them running, but report them
            try:
                os.kill(int(line.split()[0]), signal.SIGKILL)
            except OSError:
                pass

    def log_tail(self, n: int = 40) -> str:
        try:
            return "\n".join(self.log_path.read_text(errors="replace").splitlines()[-n:])
        except OSError:
            return "(no log)"

    def save_log(self, name: str) -> None:
        ARTIFACTS.mkdir(exist_ok=True)
        if self.log_path.exists():
            shutil.copy2(self.log_path, ARTIFACTS / name)

    @contextmanager
    def serving(self, log_name: str, what: str) -> Iterator[Server]:
        """The server for the block; then stopped and its log kept as ``log_name`` whatever
        happens, and, when the block ended normally, a test failure if ``what`` left processes
        behind."""
        import pytest

        try:
            yield self
        finally:
            self.stop()
            self.save_log(log_name)
        if self.leftovers:
            pytest.fail(f"processes left by {what}: {self.leftovers}")


def make_server(kind: str, tmp_path_factory, notebooks: list[Path]) -> Server:
    base = tmp_path_factory.mktemp(f"browser-{kind}-")
    return Server(kind, base, notebooks, token=secrets.token_hex(24))
