"""``tools/new_homework.py`` scaffolds a homework that works end to end, with nothing registered by hand.

In a temporary copy of the repository (never in this checkout) the scaffolder writes the next
homework (hw06 today); then, in that copy:

* ``tools/build_homework.py --check`` passes (the notebooks were built from the source);
* the solution notebook runs in a Jupyter kernel (nbclient) and every check says ✓; the blank
  notebook runs too and its checks say "not answered yet";
* the hidden-test stub gives full marks to the solution's namespace and 0 ("not answered") to
  the blank's, through ``tools/grading/protocol.py``'s ``LocalStudent`` and ``run_question``;
* the policy tests of ``tests/test_homework_build.py`` accept the new files, and the two tables
  of question data (``tests/test_answer_equivalence.py``, ``tests/unit/test_checks.py``) fail
  with a message that tells the author which rows to add;
* running it again refuses to overwrite anything; bad arguments are refused with the rule.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TITLE = "Are letters smooth?"

pytestmark = [pytest.mark.slow, pytest.mark.timeout(180)]

# Runs inside the copy (cwd and PYTHONPATH = the copy): build check, kernels, hidden-test stub.
DRIVER = r"""
import json, sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import matplotlib
matplotlib.use("Agg")
import nbformat
from nbclient import NotebookClient

root, hw = Path.cwd(), sys.argv[1]
from tools import build_homework as build
from tools.grading.protocol import LocalStudent, run_question
import course_lib.homework.checks

out = {"course_lib": course_lib.homework.checks.__file__, "homeworks": list(course_lib.homework.checks.HOMEWORKS),
       "build_check": build.main(["--check"])}
(source,) = [s for s in build.sources() if s.stem.startswith(hw + "_")]


def run_kernel(version):
    nb = nbformat.read(build.target(source, version), as_version=4)
    NotebookClient(nb, timeout=60, kernel_name="python3",
                   resources={"metadata": {"path": str(root / "exercises")}}).execute()
    checks = []
    for cell in nb.cells:
        if cell.cell_type == "code" and ("check(" in cell.source or "check_all(" in cell.source):
            checks.append("".join(o.get("data", {}).get("text/plain", "") for o in cell.outputs))
    return checks


def namespace(version):
    ns = {"__name__": f"{hw}_{version}"}
    for cell in build.build(source, version).cells:
        if cell.cell_type == "code":
            exec(compile(cell.source, f"{hw}-{version}", "exec"), ns)
    return ns


with ThreadPoolExecutor(max_workers=2) as pool:
    kernels = dict(zip(("solution", "student"), pool.map(run_kernel, ("solution", "student"))))
out["kernel_checks"] = kernels

import importlib.util
spec = importlib.util.spec_from_file_location("hidden_new", root / "solutions" / "hidden_tests" / f"{hw}.py")
hidden = importlib.util.module_from_spec(spec)
spec.loader.exec_module(hidden)
out["points"] = hidden.POINTS
out["grades"] = {
    version: {q: run_question(getattr(hidden, q), LocalStudent(namespace(version))) for q in hidden.POINTS}
    for version in ("solution", "student")
}
print("RESULT" + json.dumps(out))
"""

POLICY_TESTS = [
    "tests/test_homework_build.py",
    "tests/test_answer_equivalence.py::test_every_question_has_a_table",
    "tests/unit/test_checks.py::test_every_homework_question_is_covered_here",
]


def _next_homework() -> str:
    numbers = [int(p.stem[2:]) for p in (ROOT / "course_lib" / "homework" / "checks").glob("hw[0-9][0-9].py")]
    return f"hw{max(numbers) + 1:02d}"


def _env(root: Path) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env.update(PYTHONPATH=str(root), MPLBACKEND="Agg")
    return env


def _scaffold(root: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, str(root / "tools" / "new_homework.py"), *args],
        cwd=root, env=_env(root), capture_output=True, text=True, timeout=60,
    )  # fmt: skip


@pytest.fixture(scope="module")
def scaffolded(tmp_path_factory):
    hw = _next_homework()
    root = tmp_path_factory.mktemp("course")
    skip = shutil.ignore_patterns("__pycache__", ".ipynb_checkpoints", "fixtures", "browser")
    for folder in ("tools", "course_lib", "exercises", "solutions", "tests"):
        shutil.copytree(ROOT / folder, root / folder, ignore=skip)
    for name in ("conftest.py", "pyproject.toml", "nbval-sanitize.cfg"):
        shutil.copy2(ROOT / name, root / name)
    before = sorted(p.relative_to(root) for p in root.rglob("*") if p.is_file())
    made = _scaffold(root, hw, TITLE)
    assert made.returncode == 0, made.stdout + made.stderr
    # the kernels, the hidden-test stub and the policy tests, two processes at once
    (root / "driver.py").write_text(DRIVER, encoding="utf-8")
    procs = {
        "driver": [sys.executable, "driver.py", hw],
        # no plugin autoload, no addopts (nbval, timeouts): only the policy tests, quickly
        "pytest": [sys.executable, "-m", "pytest", "-q", "-o", "addopts=", "-p", "no:cacheprovider",
                   "--junitxml", str(root / "policy.xml"), *POLICY_TESTS],
    }  # fmt: skip
    env = {"driver": _env(root), "pytest": {**_env(root), "PYTEST_DISABLE_PLUGIN_AUTOLOAD": "1"}}
    running = {
        k: subprocess.Popen(cmd, cwd=root, env=env[k], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
        for k, cmd in procs.items()
    }  # fmt: skip
    done = {k: p.communicate(timeout=150) for k, p in running.items()}
    return {"hw": hw, "root": root, "made": made, "before": before, "done": done,
            "codes": {k: p.returncode for k, p in running.items()}}  # fmt: skip


def test_scaffolder_writes_the_files_and_says_what_to_do(scaffolded):
    hw, root, made = scaffolded["hw"], scaffolded["root"], scaffolded["made"]
    stem = f"{hw}_are_letters_smooth"
    new = sorted(
        str(p.relative_to(root))
        for p in root.rglob("*")
        if p.is_file() and p.relative_to(root) not in scaffolded["before"]
        and p.suffix in (".py", ".ipynb")
    )  # fmt: skip
    assert new == sorted([
        f"course_lib/homework/checks/{hw}.py",
        f"exercises/{stem}.ipynb", f"solutions/hidden_tests/{hw}.py",
        f"solutions/{stem}.ipynb", f"tools/homework_src/{stem}.py", "driver.py",
    ])  # fmt: skip
    assert "Next:" in made.stdout and "tests/test_answer_equivalence.py" in made.stdout
    assert "CONTRIBUTING.md" in made.stdout
    source = (root / "tools" / "homework_src" / f"{stem}.py").read_text(encoding="utf-8")
    assert f'HOMEWORK = "{hw}"' in source and f"# # Homework {int(hw[2:])} — {TITLE}" in source
    # a variant generator is scaffolded beside the checks and wired: notebook, check and hidden
    # test read its data
    checks = (root / "course_lib" / "homework" / "checks" / f"{hw}.py").read_text(encoding="utf-8")
    assert "def generate(rng) -> dict:" in checks
    assert 'VARIANT = ""' in source and "DATA = variants.data(HOMEWORK, VARIANT)" in source
    hidden = (root / "solutions" / "hidden_tests" / f"{hw}.py").read_text(encoding="utf-8")
    assert "VARIANTS = True" in hidden and "def q1(student, data=None):" in hidden
    # nothing was written into this checkout
    assert not list((ROOT / "course_lib" / "homework" / "checks").glob(f"{hw}.py"))
    assert not list((ROOT / "tools" / "homework_src").glob(f"{hw}_*.py"))


def _driver(scaffolded) -> dict:
    out, err = scaffolded["done"]["driver"]
    assert scaffolded["codes"]["driver"] == 0, out[-3000:] + err[-3000:]
    (line,) = [x for x in out.splitlines() if x.startswith("RESULT")]
    return json.loads(line[len("RESULT") :])


def test_new_homework_is_found_and_its_notebooks_are_built(scaffolded):
    result = _driver(scaffolded)
    assert result["course_lib"].startswith(str(scaffolded["root"]))  # the copy's, not ours
    assert result["homeworks"][-1] == scaffolded["hw"]  # derived from the files, no registration
    assert result["build_check"] == 0


def test_solution_notebook_passes_its_checks_and_blank_is_not_answered(scaffolded):
    kernels = _driver(scaffolded)["kernel_checks"]
    hw = scaffolded["hw"]
    *solution, report = kernels["solution"]
    assert len(solution) == 2 and all(s.startswith(f"✓ {hw}.q") for s in solution), solution
    assert f"{hw}: 2 of 2 checks passed" in report
    *blank, report = kernels["student"]
    assert len(blank) == 2 and all("not answered yet" in s for s in blank), blank
    assert f"{hw}: 0 of 2 checks passed" in report


def test_hidden_test_stub_full_marks_for_the_solution_zero_for_the_blank(scaffolded):
    result = _driver(scaffolded)
    grades = result["grades"]
    assert list(grades["solution"]) == list(result["points"]) == ["q1", "q2"]
    for q, (fraction, note) in grades["solution"].items():
        assert fraction == 1.0, (q, note)
    for q, (fraction, note) in grades["student"].items():
        assert fraction == 0.0 and note.startswith("not answered"), (q, note)


def _junit(scaffolded) -> dict[str, str]:
    """test id -> "passed" or the failure message."""
    path = scaffolded["root"] / "policy.xml"
    assert path.exists(), "".join(scaffolded["done"]["pytest"])[-3000:]
    tree = ET.parse(path)
    out = {}
    for case in tree.iter("testcase"):
        failure = case.find("failure") if case.find("failure") is not None else case.find("error")
        out[f"{case.get('classname')}::{case.get('name')}"] = (
            "passed" if failure is None else failure.get("message", "")
        )
    return out


def test_policy_tests_accept_the_new_files(scaffolded):
    results = _junit(scaffolded)
    hw = scaffolded["hw"]
    build = {k: v for k, v in results.items() if "test_homework_build" in k}
    assert [k for k in build if f"{hw}_are_letters_smooth" in k or f"[{hw}]" in k], sorted(build)
    assert all(v == "passed" for v in build.values()), {
        k: v for k, v in build.items() if v != "passed"
    }


def test_question_tables_tell_the_author_which_rows_to_add(scaffolded):
    results = _junit(scaffolded)
    hw = scaffolded["hw"]
    (table,) = [v for k, v in results.items() if k.endswith("test_every_question_has_a_table")]
    assert "no row in TABLE" in table and f"{hw}.q1" in table and f"{hw}.q2" in table, table
    (right,) = [
        v for k, v in results.items() if k.endswith("test_every_homework_question_is_covered_here")
    ]
    assert "no right answer in RIGHT" in right and f"{hw}.q1" in right, right


def test_it_never_overwrites_and_refuses_bad_arguments(scaffolded):
    root, hw = scaffolded["root"], scaffolded["hw"]
    files = sorted(root.rglob(f"{hw}*"))
    digest = {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in files if p.is_file()}
    again = _scaffold(root, hw, "Another title")
    assert (
        again.returncode == 1
        and "exists already" in again.stderr
        and "nothing written" in again.stderr
    )
    assert sorted(root.rglob(f"{hw}*")) == files
    assert {p: hashlib.sha256(p.read_bytes()).hexdigest() for p in digest} == digest
    for args, rule in [
        (("hw5", TITLE), "hw and two digits"),
        (("hw00", TITLE), "start at 1"),
        (("hw99", "   "), "must not be empty"),
        (("hw99", "?!"), "letters or digits"),
        (("hw99", 'A "quoted" title'), "plain text"),
        (("hw99", "x" * 81), "at most 80"),
    ]:
        bad = _scaffold(root, *args)
        assert bad.returncode == 2 and rule in bad.stderr, (args, bad.stderr)
    assert not list(root.rglob("hw99*"))


@pytest.mark.parametrize(
    ("title", "expected"),
    [("Are letters smooth?", "are_letters_smooth"), ("Courbes G¹ à la main", "courbes_g1_a_la_main"),
     ("G2 & C2: Beta-splines", "g2_c2_beta_splines")],
)  # fmt: skip
def test_file_names_come_from_the_title(title, expected):
    from tools import new_homework as module

    assert module.slug(title) == expected
    assert re.fullmatch(r"[a-z0-9_]{1,40}", module.slug("word " * 30))
