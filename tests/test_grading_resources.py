"""The grader's own folders and the sandbox's limits (issue 27, sections 3 and 6).

* the job root is private: a fresh ``mkdtemp`` by default; a configured one is used only when
  it is a real directory of the grader's user with mode 700 (a link, another owner or an open
  mode is refused with a message naming the rule);
* a job folder is bounded on disk (a size-limited tmpfs when the grader runs as root): a write
  past the bound fails inside the folder, nothing is left afterwards;
* ``--disk`` means what it says: code in the sandbox writes one file up to close to it (no
  second, lower limit: the file-size limit was a fixed 64 MB, so ``--disk 128`` stopped at 64),
  and not beyond;
* the preflight passes with the course's environment wherever it is: a venv reached through a
  link, and a conda-like prefix (no venv, outside ``/usr`` and the course, under an ``/opt``-like
  folder reached from ``$HOME`` by a link) whose ``python`` loads ``libpython`` from outside it.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from tools import grade

ROOT = Path(__file__).resolve().parents[1]
jobroot = grade.jobroot


def test_default_job_root_is_private_and_fresh():
    root = jobroot.job_root()
    st = os.lstat(root)
    assert root.is_dir() and not root.is_symlink()
    assert st.st_mode & 0o777 == 0o700 and st.st_uid == os.geteuid()
    assert root.name.startswith("course-grader-") and root.name != "course-grader"
    assert jobroot.job_root() == root  # one per process


def test_configured_job_root_is_created_private(tmp_path):
    root = jobroot.check_root(tmp_path / "jobs")
    assert os.lstat(root).st_mode & 0o777 == 0o700


@pytest.mark.parametrize("kind", ["link", "open", "file", "owner"])
def test_configured_job_root_refused_unless_private(tmp_path, kind):
    target = tmp_path / "jobs"
    if kind == "link":
        (tmp_path / "real").mkdir(mode=0o700)
        os.symlink(tmp_path / "real", target)
        message = "symbolic link"
    elif kind == "open":
        target.mkdir()
        os.chmod(target, 0o777)
        message = "mode 777"
    elif kind == "file":
        target.write_text("")
        message = "not a directory"
    else:
        if os.geteuid() != 0:
            pytest.skip("making a folder owned by another user needs root")
        target.mkdir(mode=0o700)
        os.chown(target, 65534, 65534)
        message = "owned by uid 65534"
    with pytest.raises(ValueError, match=message):
        jobroot.check_root(target)


def test_job_folder_is_bounded_on_disk(tmp_path):
    root = jobroot.check_root(tmp_path / "jobs")
    job, mounted = jobroot.job_folder(root, 1 << 20)
    if not mounted:
        pytest.skip("no size-limited tmpfs here (needs root): the file-size limit bounds writes")
    with pytest.raises(OSError, match="No space left"):
        with open(job / "filler", "wb") as fh:
            for _ in range(4):
                fh.write(b"x" * (1 << 19))
                fh.flush()
    jobroot.remove_job_folder(job, mounted)
    assert not job.exists()
    assert str(job) not in Path("/proc/mounts").read_text()


def test_grade_refuses_an_unsafe_job_root(tmp_path):
    target = tmp_path / "jobs"
    target.mkdir()
    os.chmod(target, 0o755)
    subs = tmp_path / "subs"
    subs.mkdir()
    (subs / "a.ipynb").write_text("{")
    with pytest.raises(SystemExit, match=r"--job-root.*mode 755"):
        grade.main(["--tests", str(ROOT / "solutions" / "hidden_tests" / "hw01.py"),
                    "--submissions", str(subs), "--out", str(tmp_path / "out"),
                    "--sandbox", "none", "--job-root", str(target)])  # fmt: skip


SANDBOX_OK, SANDBOX_WHY = grade.sandbox.bwrap_works()
needs_sandbox = pytest.mark.skipif(not SANDBOX_OK, reason=f"no sandbox: {SANDBOX_WHY}")


def test_sandbox_bounds_tmp_and_shm_and_keeps_the_rest_read_only(tmp_path):
    if grade.sandbox.bwrap_path() is None:
        pytest.skip("bubblewrap is not installed")
    limits = grade.sandbox.Limits(tmp_bytes=3 << 20)
    argv = grade.sandbox.bwrap_argv(tmp_path, limits)
    joined = " ".join(argv)
    assert f"--size {3 << 20} --tmpfs /tmp" in joined
    assert f"--size {3 << 20} --tmpfs /dev/shm" in joined
    assert argv[-4:] == ["--remount-ro", "/dev", "--remount-ro", "/"]


@needs_sandbox
def test_preflight_names_the_path_the_sandbox_cannot_see(tmp_path):
    hidden = str(ROOT / "tools" / "grade.py")  # tools/ is never shown to a kernel
    problem = grade.sandbox.visibility_problem(tmp_path, grade.sandbox.Limits(), extra=(hidden,))
    assert problem == f"the sandbox cannot see {hidden}"


@needs_sandbox
@pytest.mark.timeout(180)
def test_preflight_passes_with_the_environment_reached_through_a_link(tmp_path):
    """The course's venv through a symbolic link: the link is remade in the sandbox."""
    import subprocess
    import sys

    link = tmp_path / "shared-env"
    os.symlink(Path(sys.prefix).resolve(), link)
    script = (
        "import sys\n"
        "from tools import grade\n"
        "assert sys.executable.startswith(sys.argv[1]), sys.executable\n"
        "print('PROBLEM:' + grade.check_sandbox(grade.Options(mode='bwrap')))\n"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    proc = subprocess.run(
        [str(link / "bin" / "python"), "-c", script, str(link)],
        capture_output=True, text=True, timeout=170, env=env, cwd=str(ROOT),
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "PROBLEM:\n" in proc.stdout, proc.stdout


@needs_sandbox
@pytest.mark.timeout(120)
def test_a_job_writes_close_to_the_disk_limit_and_not_beyond(tmp_path):
    """Through the launcher and bubblewrap, as a kernel is run: one file of --disk minus 2 MB
    is written whole; the next megabytes fail with 'No space left', not 'File too large'."""
    import subprocess
    import sys

    disk = 80 << 20  # above the old fixed 64 MB file-size limit
    limits = grade.sandbox.Limits(disk_bytes=disk, tmp_bytes=4 << 20)
    job, mounted = jobroot.job_folder(jobroot.check_root(tmp_path / "jobs"), disk)
    if not mounted:
        jobroot.remove_job_folder(job, mounted)
        pytest.skip("no size-limited tmpfs here (needs root): the disk limit is checked per cell")
    code = (
        "import sys\n"
        "n = 0\n"
        "with open('big', 'wb') as fh:\n"
        f"    for _ in range({(disk >> 20) - 2}):\n"
        "        fh.write(b'x' * (1 << 20)); fh.flush(); n += 1\n"
        "print('whole', n)\n"
        "try:\n"
        "    with open('more', 'wb') as fh:\n"
        "        for _ in range(64):\n"
        "            fh.write(b'x' * (1 << 20)); fh.flush(); n += 1\n"
        "except OSError as exc:\n"
        "    print('stopped', n, exc.errno)\n"
    )
    groups = grade.sandbox.SandboxGroups(limits, job_tmpfs=True)
    try:
        argv = [*grade.sandbox.launcher_argv(job, "bwrap", limits, groups), sys.executable, "-c"]
        proc = subprocess.run([*argv, code], capture_output=True, text=True, timeout=100,
                              cwd=str(job))  # fmt: skip
        used = jobroot.used_bytes(job)
    finally:
        groups.kill_and_remove()
        jobroot.remove_job_folder(job, mounted)
    assert proc.returncode == 0, proc.stderr[-2000:]
    lines = proc.stdout.split("\n")
    assert lines[0] == f"whole {(disk >> 20) - 2}", proc.stdout
    stopped = lines[1].split()
    assert stopped[0] == "stopped" and stopped[2] == "28", proc.stdout  # ENOSPC, not EFBIG (27)
    assert disk - (2 << 20) <= used <= disk, used
    print(f"--disk {disk >> 20} MB: {used / (1 << 20):.1f} MB written before 'No space left'")


@needs_sandbox
@pytest.mark.timeout(300)
def test_preflight_passes_with_a_conda_like_prefix_outside_usr_and_the_course(tmp_path):
    """A conda-like environment -- one prefix holding Python and the packages, no venv on top
    (``sys.prefix == sys.base_prefix``), under ``/opt``-like and reached from ``$HOME``
    through a link -- made here of hard links to this Python and this environment's packages.
    Its ``python`` still loads ``libpython`` through the ``RUNPATH`` it was built with (outside
    the prefix): the sandbox must show that folder too."""
    import subprocess
    import sys

    base = Path(sys.base_prefix).resolve()
    site = Path(next(p for p in sys.path if p.endswith("site-packages"))).resolve()
    if base == Path("/usr") or Path("/usr") in base.parents:
        pytest.skip(f"this Python is the system's ({base}): no prefix outside /usr to copy")
    if (
        os.stat(base).st_dev != os.stat(tmp_path).st_dev
        or os.stat(site).st_dev != os.stat(tmp_path).st_dev
    ):
        pytest.skip("the environment is on another file system than the temp folder (no links)")
    real = tmp_path / "opt" / "conda"
    prefix = real / "envs" / "course"
    prefix.parent.mkdir(parents=True)
    subprocess.run(["cp", "-al", str(base), str(prefix)], check=True, timeout=120)
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    packages = prefix / "lib" / version / "site-packages"
    subprocess.run(["rm", "-rf", str(packages)], check=True, timeout=60)
    subprocess.run(["cp", "-al", str(site), str(packages)], check=True, timeout=120)
    home = tmp_path / "home"
    home.mkdir()
    os.symlink(real, home / "miniconda3")
    seen = home / "miniconda3" / "envs" / "course"
    script = (
        "import sys\n"
        "from _homework_support import load\n"
        f"grade = load('g', {str(ROOT / 'tools' / 'grade.py')!r})\n"
        "assert sys.prefix == sys.base_prefix == sys.argv[1], (sys.prefix, sys.base_prefix)\n"
        "print('PROBLEM:' + grade.check_sandbox(grade.Options(mode='bwrap')))\n"
    )
    env = {**os.environ, "PYTHONPATH": f"{ROOT}{os.pathsep}{ROOT / 'tests'}"}
    env.pop("VIRTUAL_ENV", None)
    proc = subprocess.run(
        [str(seen / "bin" / version), "-c", script, str(seen)],
        capture_output=True, text=True, timeout=170, env=env, cwd=str(ROOT),
    )  # fmt: skip
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert "PROBLEM:\n" in proc.stdout, proc.stdout
