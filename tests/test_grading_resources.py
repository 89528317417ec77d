"""The grader's own folders and the sandbox's limits (issue 27, sections 3 and 6).

* the job root is private: a fresh ``mkdtemp`` by default; a configured one is used only when
  it is a real directory of the grader's user with mode 700 (a link, another owner or an open
  mode is refused with a message naming the rule);
* a job folder is bounded on disk (a size-limited tmpfs when the grader runs as root): a write
  past the bound fails inside the folder, nothing is left afterwards.
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
