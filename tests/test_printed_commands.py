"""Every command the user-facing documents print is run as printed (issue 23).

The documents: ``README.md``, every ``site/*.md`` page, and the student edition's ``README.md``
as ``make release`` (``tools/release.py``) writes it.  Their commands are *harvested*, never
listed here, by this convention (also in CONTRIBUTING.md, "Commands in the documents"):

* A fenced block whose info string is ``console`` (or ``shell-session``) holds a terminal
  session: every line that starts with ``$ `` is a command (the prompt is not part of it);
  lines without a prompt are the output shown, and are not run.
* A fenced block whose info string is ``sh``, ``bash``, ``shell`` or ``zsh`` holds commands
  only: every line that is not blank and does not start with ``#`` is a command.
* In both, a line ending with ``\\`` continues on the next line (a leading ``> `` there is the
  shell's continuation prompt and is dropped); a ``# comment`` after a command is part of
  the line the shell is given (it ignores it).
* Everything else -- ``text`` blocks, blocks without an info string, inline code -- is not
  run.  A synopsis with placeholders (``...``, ``[OPTIONS]``, ``tcp://HOST:8786``) or a command
  for another machine belongs there; in a harvested block it fails this test, naming the
  document and the line.

How they are run: each document's commands, in the order printed, by ``bash -c`` from the top
of a fresh scratch copy of the checkout (its working tree: tracked and untracked, not ignored,
files), or of the student edition unpacked from ``dist/student-edition.zip`` for the edition's
README.  The copy's ``.venv`` is this test run's environment, and the copy's install stamp is
up to date, so nothing is installed (``make -q install`` is checked first); ``PYTHONPATH``
is the copy, as its editable install would make it.  The user's own files are there, named as
the documents name them (:data:`USER_FILES`): a course roster ``roster.csv``, Canvas's
gradebook export ``gradebook.csv`` as downloaded, and in ``path/to/submitted/notebooks/`` the
file the student edition's own hand-in command wrote, named as Canvas's "Download Submissions"
names it.  A command passes when it exits 0 and prints no traceback.  The copies are
independent, so two documents run at a time; each command's seconds are reported
(``pytest -rP``), never asserted.

A few commands cannot be run as printed in a test; each is run in a form that shows it would do
what it says (one row per command in :data:`EQUIVALENT`; a harvested command matched by no row
runs as printed):

====================================  =========================================================
``make lab``                          started as printed; passes when the JupyterLab it starts
                                      answers its ``/lab`` URL and serves
                                      ``notebooks/00_welcome.ipynb``, then its process group is
                                      stopped (it serves until stopped, and opens a browser)
``make present L=NN``                 started as printed (``PORT=`` a free port only if 8866 is
                                      taken); the URL it prints once the deck is executed must
                                      serve the lecture's deck without an error; then stopped
``make present ...`` (other forms)    ``make -n``: the exact recipe
``make install``                      ``make -q install`` must report the install stamp up to
                                      date and ``make -n install`` must show nothing to run
                                      (never reinstalls)
``make test``                         ``make -n test``: the exact recipe (the whole suite, this
                                      test in it)
``make site``                         ``make -n site``: the exact recipe (minutes;
                                      ``tests/test_site.py`` builds the site)
``make handouts``                     ``make -n handouts`` (the site, then Chromium;
                                      ``tests/test_site.py``)
``make bench``                        ``make -n bench``, whose recipe must be
                                      ``.venv/bin/python benchmarks/run.py`` (the next row)
``.venv/bin/python benchmarks/run.py  with ``--quick --only evaluation`` added (the full run
[option]``                            takes minutes; ``--quick``, printed too, runs as printed
                                      and runs every item at small sizes): the option's code
                                      path on item 1; the plain command also with ``--output
                                      benchmarks/results.md``, which must write ``results.md``
                                      and ``results.json``
``...grading_throughput.py``          with ``--copies 1 --jobs 1``: the same grading of a
                                      solution copy, which must score full marks
``.venv/bin/python -m pytest          with ``--collect-only -q``: the four test modules the
tests/browser``                       pages name must be collected (running them takes minutes
                                      of Chromium; ``make test`` runs them)
``conda env create -f environment.yml  static (conda is not installed here, and creating the
&& conda activate NAME``              environment downloads every package): the file parses,
                                      creates the environment ``NAME`` and installs JupyterLab
                                      and the course (``pip: -e .``);
                                      ``tests/unit/test_environment.py`` checks its versions
``jupyter lab notebooks/``            started with ``.venv/bin`` first on PATH (the activated
                                      environment; ``--allow-root`` added when run as root, as
                                      the Makefile adds it); ``/lab`` must answer with
                                      ``notebooks/`` as its root (``00_welcome.ipynb``); stopped
``pip index versions NAME``           with ``--help`` added, ``.venv/bin`` first on PATH: pip
                                      has the command and reads the line (the query itself
                                      needs the network)
``.venv/bin/voila NOTEBOOK``          started as printed; its page must be the executed
                                      notebook, without an error; stopped
``.venv/bin/python -m http.server -d  started as printed on a stand-in ``build/site/index.html``
build/site 8000``                     (the real build takes minutes; ``tests/test_site.py``);
                                      the page's ``http://127.0.0.1:8000`` must serve it; stopped
====================================  =========================================================

The multi-machine Dask commands of ``site/grading.md`` are a ```text synopsis (``HOST``); they
are run on this machine by :func:`run_dask_synopsis` (``HOST`` is 127.0.0.1, the port a
free one) and checked by :func:`test_the_dask_synopsis_grades_on_one_machine`.

The grader's and the hand-in's output never carries the kernel's "running over TCP" start-up
warning (the grader's kernels use IPC and a silenced stderr; ``submit()`` filters the warning).
"""

from __future__ import annotations

import csv
import os
import re
import shutil
import signal
import socket
import subprocess
import sys
import time
import urllib.request
import zipfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
VENV = Path(sys.prefix)

pytestmark = [
    pytest.mark.slow,  # a minute and a half of commands
    pytest.mark.skipif(shutil.which("make") is None, reason="needs make"),
    pytest.mark.skipif(
        not (VENV / ".installed").is_file(),
        reason="needs the course's .venv with its install stamp (make install)",
    ),
]


def user_documents() -> list[Path]:
    """The documents a user reads for commands: the README and the website's pages."""
    return [ROOT / "README.md", *sorted((ROOT / "site").glob("*.md"))]


# ----------------------------------------------------------------------------- harvesting

PROMPT_BLOCKS = ("console", "shell-session")
SCRIPT_BLOCKS = ("sh", "bash", "shell", "zsh")
_FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>`{3,}|~{3,})\s*(?P<info>[^`\s]*)")


@dataclass(frozen=True)
class Command:
    doc: str  # the document, relative to its root
    line: int  # the line the command starts on
    text: str  # exactly as printed (without a "$ " prompt)

    def __str__(self) -> str:
        return f"{self.doc}:{self.line}: {self.text}"


def harvest(text: str, doc: str, prompt_blocks: tuple[str, ...] = PROMPT_BLOCKS,
            script_blocks: tuple[str, ...] = SCRIPT_BLOCKS) -> list[Command]:  # fmt: skip
    """The commands of a Markdown text, by the convention of the module docstring (other
    ``prompt_blocks`` read the ``$ `` lines of, e.g., ``text`` synopses)."""
    out: list[Command] = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        m = _FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, info = m["fence"], m["info"].lower()
        body, j = [], i + 1
        while j < len(lines) and not lines[j].strip().startswith(fence):
            body.append((j + 1, lines[j]))
            j += 1
        if info in prompt_blocks or info in script_blocks:
            out += _commands(body, doc, prompt=info in prompt_blocks)
        i = j + 1
    return out


def _commands(body: list[tuple[int, str]], doc: str, prompt: bool) -> list[Command]:
    out, k = [], 0
    while k < len(body):
        number, line = body[k]
        stripped = line.strip()
        if prompt:
            start = stripped.startswith("$ ")
            line = stripped[2:] if start else line
        else:
            start = bool(stripped) and not stripped.startswith("#")
            line = stripped
        k += 1
        if not start:
            continue
        parts = [line]
        while parts[-1].endswith("\\") and k < len(body):
            more = body[k][1]
            more = more.lstrip()[2:] if more.lstrip().startswith("> ") else more
            parts.append(more)
            k += 1
        out.append(Command(doc, number, "\n".join(parts)))
    return out


#: what a placeholder looks like: an ellipsis, an optional part in brackets, a HOST
PLACEHOLDER = re.compile(r"\.\.\.|…|(?:^|\s)\[[^\]]*\]|\bHOST\b|<[a-z-]+>")


def test_the_convention_is_what_the_harvester_reads():
    doc = "\n".join([
        "Intro `make inline` is not run.",
        "```console",
        "$ make lab   # a comment stays",
        "output line, not run",
        "$ tools/grade.py --tests t.py \\",
        ">     --out o",
        "```",
        "```sh",
        "# a comment line",
        "make test",
        "tools/variant.py codes hw01 \\",
        "    --roster roster.csv",
        "```",
        "```text",
        "make grade ... [ROSTER=roster.csv]",
        "```",
        "```",
        "$ no info string: not run",
        "```",
    ])  # fmt: skip
    got = [(c.line, c.text) for c in harvest(doc, "d.md")]
    assert got == [
        (3, "make lab   # a comment stays"),
        (5, "tools/grade.py --tests t.py \\\n    --out o"),
        (10, "make test"),
        (11, "tools/variant.py codes hw01 \\\n    --roster roster.csv"),
    ]
    assert PLACEHOLDER.search("make grade ... [ROSTER=x]") and PLACEHOLDER.search("tcp://HOST:8786")
    assert not PLACEHOLDER.search('make grade HW=hw01 ASSIGNMENT="Homework 1" OUT=grades/hw01')


# ----------------------------------------------------------------------------- the user's files

CANVAS_USER = "12345"
#: the user's own files, named as the documents name them (relative to the checkout)
USER_FILES = {
    # the course's roster (README: "id,name,email"): the student edition's hand-in names the
    # student "your-id", so that is a roster id here
    "roster.csv": "id,name,email\nyour-id,Ada Lovelace,ada@example.org\n1001,Emmy Noether,emmy@example.org\n",
    # Canvas's gradebook export as downloaded: its header, the "Points Possible" row, a column
    # per assignment named "<title> (<assignment id>)"
    "gradebook.csv": (
        "Student,ID,SIS User ID,SIS Login ID,Section,Homework 1 (4711),Current Score\n"
        "    Points Possible,,,,,11.00,(read only)\n"
        f'"Lovelace, Ada",{CANVAS_USER},your-id,alovelace,Section A,,\n'
        '"Noether, Emmy",12346,1001,enoether,Section A,,\n'
    ),
}
SUBMISSIONS = "path/to/submitted/notebooks"


# ----------------------------------------------------------------------------- running

KERNEL_TCP_WARNING = "Kernel is running over TCP"


@dataclass
class Ran:
    command: Command
    how: str
    output: str
    seconds: float = 0.0  # wall clock, reported (``pytest -rP``), never asserted


def _env(root: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("MAKE") and k != "MFLAGS"}
    env["PYTHONPATH"] = str(root)  # the copy's course_lib, as its editable install would give
    env.pop("VIRTUAL_ENV", None)
    return env


def scratch_checkout(dest: Path, files: list[Path], base: Path) -> Path:
    """``files`` (under ``base``) copied to ``dest``, with this run's .venv, installed."""
    for f in files:
        target = dest / f.relative_to(base)
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(f, target)
    (dest / ".venv").symlink_to(VENV, target_is_directory=True)
    stamp = (VENV / ".installed").stat().st_mtime
    for name in ("pyproject.toml", "constraints.txt"):  # installed: older than the stamp
        if (dest / name).exists():
            os.utime(dest / name, (stamp - 60, stamp - 60))
    check = subprocess.run(["make", "-q", "install"], cwd=dest, env=_env(dest), capture_output=True)
    if check.returncode != 0:  # never let a test reinstall into the environment it runs in
        pytest.fail(
            f"{dest}: `make -q install` says the install step would run; not running anything"
        )
    return dest


def checkout_files() -> list[Path]:
    """The checkout's working tree: tracked and untracked files, not the ignored ones."""
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("needs a git checkout (the scratch copy is its working tree)")
    out = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"],
        cwd=ROOT, capture_output=True, check=True,
    ).stdout.decode()  # fmt: skip
    return [ROOT / p for p in out.split("\0") if p and (ROOT / p).is_file()]


def _make_n(cmd: Command, root: Path, target: str) -> tuple[str, str]:
    shown = subprocess.run(["bash", "-c", cmd.text.replace("make ", "make -n ", 1)], cwd=root,
                           env=_env(root), capture_output=True, text=True, timeout=60)  # fmt: skip
    out = shown.stdout + shown.stderr
    assert shown.returncode == 0, f"{cmd}\n{out}"
    assert "pip install" not in out and "-m venv" not in out, f"{cmd}: would install\n{out}"
    return f"make -n {target}", out


def _make_bench(cmd: Command, root: Path) -> tuple[str, str]:
    """``make bench``: its recipe is the benchmark script as the page prints it next."""
    how, out = _make_n(cmd, root, "bench")
    assert re.search(r"^\.venv/bin/python benchmarks/run\.py\s*$", out, re.M), f"{cmd}\n{out}"
    return how + " (the recipe is `.venv/bin/python benchmarks/run.py`, run below)", out


def _run(cmd: Command, text: str, root: Path, env: dict[str, str] | None = None) -> str:
    done = subprocess.run(["bash", "-c", text], cwd=root, env=env or _env(root),
                          capture_output=True, text=True, timeout=600)  # fmt: skip
    output = done.stdout + done.stderr
    assert done.returncode == 0, f"{cmd}\nrun as: {text}\nexit {done.returncode}:\n{output[-4000:]}"
    return output


def _activated(root: Path) -> dict[str, str]:
    """The environment with the course's ``.venv/bin`` first on PATH, as an activated
    environment (``conda activate``, ``source .venv/bin/activate``) would have it."""
    env = _env(root)
    env["PATH"] = f"{root / '.venv' / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    return env


def _bench(cmd: Command, root: Path) -> tuple[str, str]:
    """``benchmarks/run.py [option]``: with ``--quick --only evaluation`` added.

    The full run takes one to two minutes; ``--quick`` (printed too, and run as printed) runs
    every item at small sizes.  Here the option's own code path runs on the first item, and
    the plain command writes its files (``--output``, the same code that writes
    ``benchmarks/results.md`` and ``results.json``)."""
    text = f"{cmd.text} --quick --only evaluation"
    plain = cmd.text.split() == [".venv/bin/python", "benchmarks/run.py"]
    written = [root / "benchmarks" / name for name in ("results.md", "results.json")]
    if plain:
        text += " --output benchmarks/results.md"
        for f in written:  # the copy holds the committed ones: they must be written anew
            f.unlink(missing_ok=True)
    output = _run(cmd, text, root)
    assert re.search(r"^\| 1 \|", output, re.M), f"{cmd}: no row of item 1\n{output[-3000:]}"
    if "--cpu" in cmd.text.split():
        assert "process CPU time for items 1-4" in output, f"{cmd}\n{output[-3000:]}"
    if plain:
        for f in written:
            assert f.is_file() and f.stat().st_size > 0, f"{cmd}: did not write {f.name}"
    return f"as `{text}` (the full run takes minutes)", output


def _throughput(cmd: Command, root: Path) -> tuple[str, str]:
    """``grading_throughput.py``: one copy, one job -- the same grading of a solution."""
    text = f"{cmd.text} --copies 1 --jobs 1"
    output = _run(cmd, text, root)
    assert "(1/1 at full marks" in output, f"{cmd}\n{output[-3000:]}"
    return f"as `{text}` (20 copies take a minute)", output


#: the browser test modules the pages name (site/developing.md, site/performance.md)
BROWSER_TESTS = ("test_jupyterlab.py", "test_lecture_deck.py", "test_demo_latency.py",
                 "test_accessibility.py")  # fmt: skip


def _browser_tests(cmd: Command, root: Path) -> tuple[str, str]:
    """The browser tests: collected, not run (minutes of Chromium; ``make test`` runs them)."""
    text = f"{cmd.text} --collect-only -q"
    output = _run(cmd, text, root)
    assert re.search(r"^\d+ tests? collected", output, re.M), f"{cmd}\n{output[-3000:]}"
    for name in BROWSER_TESTS:
        assert f"tests/browser/{name}::" in output, f"{cmd}: {name} not collected\n{output}"
    return f"as `{text}` (runs in `make test`; minutes of Chromium)", output


def _pip_index(cmd: Command, root: Path) -> tuple[str, str]:
    """``pip index versions NAME`` asks PyPI (the network): here pip's offline ``--help`` of
    the same command line shows that this pip has the command and reads its arguments."""
    text = f"{cmd.text} --help"
    output = _run(cmd, text, root, _activated(root))
    assert re.search(r"^\s*pip index versions <package>", output, re.M), output
    return f"as `{text}` with .venv/bin on PATH (the query needs the network)", output


def _conda_env(cmd: Command, root: Path) -> tuple[str, str]:
    """``conda env create -f FILE && conda activate NAME``: checked statically.

    conda is not part of the course's environment and creating the environment downloads
    every package; the file must exist, parse, name the environment ``NAME`` and install
    JupyterLab and the course (``pip: -e .``, so ``jupyter lab notebooks/`` finds
    ``course_lib``).  tests/unit/test_environment.py checks its versions against
    constraints.txt."""
    import yaml

    m = re.fullmatch(r"conda env create -f (\S+) && conda activate (\S+)", cmd.text)
    assert m, f"{cmd}: not the form this check reads"
    spec = yaml.safe_load((root / m[1]).read_text(encoding="utf-8"))
    assert spec["name"] == m[2], f"{cmd}: {m[1]} creates {spec['name']!r}, not {m[2]!r}"
    deps = spec["dependencies"]
    names = [d.split("=")[0] for d in deps if isinstance(d, str)]
    pips = [p for d in deps if isinstance(d, dict) for p in d.get("pip", [])]
    assert "jupyterlab" in names and "pip" in names and "-e ." in pips, spec
    return f"static: {m[1]} parses and creates the environment {m[2]!r} (no conda here)", ""


def _serve(cmd: Command, root: Path, url_re: str, env: dict[str, str] | None = None,
           text: str | None = None) -> tuple[subprocess.Popen, str, Path]:  # fmt: skip
    """Start ``text`` (default: the command as printed) until its log shows ``url_re``."""
    log = root / f".printed-commands-{cmd.line}.log"
    with open(log, "wb") as fh:
        proc = subprocess.Popen(["bash", "-c", text or cmd.text], cwd=root,
                                env=env or _env(root), stdout=fh, stderr=subprocess.STDOUT,
                                start_new_session=True)  # fmt: skip
    url, deadline = None, time.monotonic() + 90
    while url is None and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.3)
        m = re.search(url_re, log.read_text(errors="replace"))
        url = m[0] if m else None
    if url is None:
        _stop(proc)
        pytest.fail(f"{cmd}: did not start serving\n{log.read_text(errors='replace')[-3000:]}")
    return proc, url, log


def _stop(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=20)
    except ProcessLookupError:
        proc.wait()
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()


def _get(url: str) -> bytes:
    with urllib.request.urlopen(url, timeout=120) as page:
        assert page.status == 200, url
        return page.read()


LAB_URL = r"http://(?:127\.0\.0\.1|localhost):\d+/lab\?token=\w+"


def _serves_welcome(url: str, notebook: str) -> None:
    _get(url)
    base, token = url.split("/lab?token=")
    api = f"{base}/api/contents/{notebook}?content=0&token={token}"
    assert b'"type": "notebook"' in _get(api), api


def _serve_lab(cmd: Command, root: Path) -> tuple[str, str]:
    """``make lab`` as printed, until its server answers; then its process group is stopped."""
    proc, url, log = _serve(cmd, root, LAB_URL)
    try:
        _serves_welcome(url, "notebooks/00_welcome.ipynb")
        text = log.read_text(errors="replace")
        recipe = text.split("\n[")[0]  # what make echoed before the server's first log line
        assert "jupyter lab" in recipe and "notebooks/00_welcome.ipynb" in recipe, text[:500]
    finally:
        _stop(proc)
    return "started; /lab and notebooks/00_welcome.ipynb served; stopped", text


def _serve_conda_lab(cmd: Command, root: Path) -> tuple[str, str]:
    """``jupyter lab notebooks/`` in the activated environment: ``.venv/bin`` first on PATH
    (the conda environment is checked statically, above), ``--allow-root`` added when this
    test runs as root (JupyterLab refuses root without it; the Makefile adds it the same
    way).  It must serve ``/lab`` with ``notebooks/`` as its root folder; then it is stopped."""
    root_user = hasattr(os, "geteuid") and os.geteuid() == 0
    text = cmd.text + (" --allow-root" if root_user else "")
    proc, url, log = _serve(cmd, root, LAB_URL, env=_activated(root), text=text)
    try:
        _serves_welcome(url, "00_welcome.ipynb")
    finally:
        _stop(proc)
    how = f"`{text}` started with .venv/bin on PATH; /lab and 00_welcome.ipynb served; stopped"
    return how, log.read_text(errors="replace")


def _serve_voila(cmd: Command, root: Path) -> tuple[str, str]:
    """``.venv/bin/voila NOTEBOOK`` as printed: its page is the executed notebook, no error."""
    proc, url, log = _serve(cmd, root, r"http://localhost:\d+/")
    try:
        page = _get(url).decode("utf-8", errors="replace")
        name = Path(cmd.text.split()[-1]).stem
        assert f"<title>{name}</title>" in page, page[:1000]
        assert "Traceback" not in page and "error when executing" not in page, page[-3000:]
        text = log.read_text(errors="replace")
    finally:
        _stop(proc)
    assert "Traceback" not in text, text[-3000:]
    # the kernel's own start-up warning is Voilà's business, not the grader's
    return "started as printed; the executed notebook served; stopped", ""


def _serve_site(cmd: Command, root: Path) -> tuple[str, str]:
    """``python -m http.server -d build/site 8000``, as printed, on the folder ``make site``
    writes (here a stand-in index: the build takes minutes; ``tests/test_site.py`` builds it
    and opens it in Chromium).  The page's URL ``http://127.0.0.1:8000`` must serve it."""
    site = root / "build" / "site"
    site.mkdir(parents=True, exist_ok=True)
    marker = "<!-- the site make site writes: stand-in of tests/test_printed_commands.py -->"
    (site / "index.html").write_text(f"<html>{marker}</html>", encoding="utf-8")
    env = _env(root) | {"PYTHONUNBUFFERED": "1"}  # its "Serving HTTP" line, unbuffered
    proc, _url, _log = _serve(cmd, root, r"Serving HTTP on \S+ port 8000", env=env)
    try:
        assert marker in _get("http://127.0.0.1:8000/").decode(), "not the site folder"
    finally:
        _stop(proc)
    return "started as printed on a stand-in build/site; http://127.0.0.1:8000 served; stopped", ""


def _port_free(port: int) -> bool:
    with socket.socket() as s:
        try:
            s.bind(("127.0.0.1", port))
        except OSError:
            return False
        return True


def _serve_present(cmd: Command, root: Path) -> tuple[str, str]:
    """``make present L=NN`` as printed (``PORT=`` a free port only when its 8866 is taken):
    once it prints its URL (after the pre-heated kernel executed the deck) the URL must serve
    the lecture's deck without an error; then its process group is stopped."""
    text = cmd.text if _port_free(8866) else f"{cmd.text} PORT={_free_port()}"
    env = _env(root) | {"PYTHONUNBUFFERED": "1"}
    proc, url, log = _serve(cmd, root, r"(?<=lecture mode: open )http://\S+", env=env, text=text)
    try:
        page = _get(url).decode("utf-8", errors="replace")
        lecture = re.search(r"\bL=(\d+)", cmd.text)[1]
        assert re.search(rf"<title>{lecture}_\w+</title>", page), page[:1000]
        assert "Traceback" not in page and "error when executing" not in page, page[-3000:]
        output = log.read_text(errors="replace")
        assert "did not execute" not in output, output[-3000:]
    finally:
        _stop(proc)
    return f"`{text}` started; its URL served the executed deck; stopped", ""


#: commands not run as printed, and how they are run instead (the table of the docstring)
EQUIVALENT = [
    (re.compile(r"^make\s+lab\b"), lambda c, r: _serve_lab(c, r)),
    (re.compile(r"^make\s+present\s+L=\d+$"), _serve_present),
    (re.compile(r"^make\s+present\b"), lambda c, r: _make_n(c, r, "present")),
    (re.compile(r"^make\s+install\b"), lambda c, r: _make_n(c, r, "install")),
    (re.compile(r"^make\s+test\b"), lambda c, r: _make_n(c, r, "test")),
    (re.compile(r"^make\s+site\b"), lambda c, r: _make_n(c, r, "site")),
    (re.compile(r"^make\s+handouts\b"), lambda c, r: _make_n(c, r, "handouts")),
    (re.compile(r"^make\s+bench\b"), _make_bench),
    (re.compile(r"^\.venv/bin/python benchmarks/run\.py(?!.*--quick)"), _bench),
    (re.compile(r"^\.venv/bin/python benchmarks/grading_throughput\.py$"), _throughput),
    (re.compile(r"^\.venv/bin/python -m pytest tests/browser$"), _browser_tests),
    (re.compile(r"^conda env create\b"), _conda_env),
    (re.compile(r"^jupyter lab notebooks/$"), _serve_conda_lab),
    (re.compile(r"^pip index versions \S+$"), _pip_index),
    (re.compile(r"^\.venv/bin/voila notebooks/\S+\.ipynb$"), _serve_voila),
    (re.compile(r"^\.venv/bin/python -m http\.server -d build/site 8000$"), _serve_site),
]


def run_printed(commands: list[Command], root: Path) -> list[Ran]:
    """Run ``commands`` in order in ``root``; fail on the first that does not work as printed."""
    ran = []
    for cmd in commands:
        start = time.monotonic()
        assert not PLACEHOLDER.search(cmd.text), (
            f"{cmd}\nhas a placeholder: a synopsis belongs in a ```text block, a command in a "
            "```console/```sh block must run as printed (see tests/test_printed_commands.py)"
        )
        rule = next((run for pattern, run in EQUIVALENT if pattern.search(cmd.text)), None)
        if rule is not None:
            how, output = rule(cmd, root)
        else:
            done = subprocess.run(["bash", "-c", cmd.text], cwd=root, env=_env(root),
                                  capture_output=True, text=True, timeout=600)  # fmt: skip
            how, output = "as printed", done.stdout + done.stderr
            assert done.returncode == 0, f"{cmd}\nexit {done.returncode}:\n{output[-4000:]}"
        assert "Traceback (most recent call last)" not in output, f"{cmd}\n{output[-4000:]}"
        assert KERNEL_TCP_WARNING not in output, f"{cmd}\n{output[-4000:]}"
        ran.append(Ran(cmd, how, output, time.monotonic() - start))
        print(f"{ran[-1].seconds:6.1f} s  {cmd}  [{how}]")
    return ran


# ----------------------------------------------------------------------------- the tests


@pytest.fixture(scope="module")
def edition(tmp_path_factory):
    """The student edition as a student gets it (the zip ``make release`` writes), unpacked."""
    work = tmp_path_factory.mktemp("edition")
    repo = scratch_checkout(work / "course", checkout_files(), ROOT)
    done = subprocess.run(["make", "release"], cwd=repo, env=_env(repo), capture_output=True,
                          text=True, timeout=300)  # fmt: skip
    assert done.returncode == 0, done.stdout + done.stderr
    with zipfile.ZipFile(repo / "dist" / "student-edition.zip") as zf:
        zf.extractall(work / "student")
    unpacked = work / "student" / "student-edition"
    files = [p for p in unpacked.rglob("*") if p.is_file()]
    return scratch_checkout(work / "student-copy", files, unpacked)


@pytest.fixture(scope="module")
def edition_run(edition):
    commands = harvest(
        (edition / "README.md").read_text(encoding="utf-8"), "student edition README.md"
    )
    return commands, run_printed(commands, edition)


def test_the_student_editions_commands_work_as_printed(edition, edition_run):
    commands, ran = edition_run
    texts = [c.text for c in commands]
    # a student is told how to open the course and how to hand in
    assert any(t.startswith("make lab") for t in texts) and any(
        "make submit" in t for t in texts
    ), texts
    handed_in = sorted((edition / "submissions").glob("hw*.ipynb"))
    assert handed_in, "the edition's hand-in command wrote no submission"
    assert all(r.how for r in ran)


def _user_copy(tmp_path_factory, name: str, files: list[Path], handed_in: Path) -> Path:
    """A fresh scratch checkout with the user's files, as the documents name them."""
    root = scratch_checkout(tmp_path_factory.mktemp(name), files, ROOT)
    for user_file, text in USER_FILES.items():
        (root / user_file).write_text(text, encoding="utf-8")
    folder = root / SUBMISSIONS
    folder.mkdir(parents=True)
    # as Canvas's "Download Submissions" names the file: <name>_<user id>_<submission id>_<file>
    shutil.copy2(handed_in, folder / f"lovelaceada_{CANVAS_USER}_67890_{handed_in.name}")
    return root


@pytest.fixture(scope="module")
def all_runs(edition, edition_run, tmp_path_factory):
    """Each document's commands in a fresh scratch checkout with the user's files, and the Dask
    synopsis of site/grading.md (:func:`run_dask_synopsis`) in one more.

    The copies are independent, so two run at a time, most commands first; within a copy the
    commands run in the order printed."""
    handed_in = sorted((edition / "submissions").glob("hw*.ipynb"))[0]
    files = checkout_files()
    jobs = []
    for doc in user_documents():
        rel = doc.relative_to(ROOT).as_posix()
        commands = harvest(doc.read_text(encoding="utf-8"), rel)
        root = _user_copy(tmp_path_factory, doc.stem.lower(), files, handed_in)
        jobs.append((rel, root, len(commands), lambda c=commands, r=root: run_printed(c, r)))
    root = _user_copy(tmp_path_factory, "dask", files, handed_in)
    jobs.append(("dask", root, 3, lambda r=root: run_dask_synopsis(r)))
    jobs.sort(key=lambda job: -job[2])
    with ThreadPoolExecutor(max_workers=2) as pool:
        futures = {name: (root, pool.submit(run)) for name, root, _, run in jobs}
    return {name: (root, future.result()) for name, (root, future) in sorted(futures.items())}


@pytest.fixture(scope="module")
def repository_runs(all_runs):
    return {name: run for name, run in all_runs.items() if name != "dask"}


def test_the_repositorys_documents_commands_work_as_printed(repository_runs):
    ran = [r for _, rs in repository_runs.values() for r in rs]
    assert ran, "no harvested command in README.md or site/*.md"
    texts = [r.command.text for r in ran]
    for needed in ("make lab", "make test"):
        assert any(t.startswith(needed) for t in texts), f"no `{needed}` printed to run"


def test_grading_as_printed_writes_its_files_without_the_kernels_tcp_warning(repository_runs):
    graded = [(root, r) for root, rs in repository_runs.values() for r in rs
              if re.search(r"\bmake\s+grade\b|tools/grade\.py", r.command.text)]  # fmt: skip
    assert graded, "no grading command is printed to run (make grade or tools/grade.py)"
    for root, r in graded:
        assert "wrote " in r.output and "scores.csv" in r.output, f"{r.command}\n{r.output[-2000:]}"
        assert "your-id" in r.output, r.output[-2000:]  # the handed-in notebook was graded
        for f in (root / "grades").rglob("*"):
            if f.is_file() and f.suffix in (".md", ".csv", ".json"):
                assert KERNEL_TCP_WARNING not in f.read_text(encoding="utf-8"), f


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def run_dask_synopsis(root: Path) -> str:
    """site/grading.md's three Dask commands (a ```text synopsis: scheduler, worker and grader on
    different machines) run on this machine: ``HOST`` is 127.0.0.1 and the port a free one
    (the scheduler is given ``--port``); otherwise as printed, from the top of ``root``."""
    doc = (ROOT / "site" / "grading.md").read_text(encoding="utf-8")
    synopsis = [c for c in harvest(doc, "site/grading.md", ("text",), ()) if "dask" in c.text]
    kinds = ["dask scheduler", "dask worker", "--executor dask"]
    assert [next(k for k in kinds if k in c.text) for c in synopsis] == kinds, synopsis
    scheduler, worker, grader = synopsis
    port = _free_port()
    here = f"tcp://127.0.0.1:{port}"
    started = []
    try:
        for cmd, text in ((scheduler, f"{scheduler.text} --port {port}"),
                          (worker, worker.text.replace("tcp://HOST:8786", here))):  # fmt: skip
            started.append(_serve(cmd, root, r"Registered to:|Scheduler at:", text=text)[0])
        text = grader.text.replace("tcp://HOST:8786", here)
        assert "HOST" not in text and here in text, text
        return _run(grader, text, root)
    finally:
        for proc in reversed(started):
            _stop(proc)


def test_the_dask_synopsis_grades_on_one_machine(all_runs):
    """Every row graded on the scheduler and workers the synopsis starts (a scheduler that
    cannot import ``tools.grading`` fails every row as "grader error")."""
    root, output = all_runs["dask"]
    assert "wrote " in output and "your-id:" in output, output[-3000:]
    assert "grader error" not in output and "Traceback" not in output, output[-3000:]
    with open(root / "grades" / "hw01" / "scores.csv", newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    assert rows and all(r["status"] != "grader error" for r in rows), rows
