"""Which control groups the grader uses, v1 or v2, and what it writes there (issue 27, section 3);
what the sandbox binds for a Python outside ``/usr`` and outside the course (a conda prefix).

The v1/v2 choice is :func:`sandbox.cgroup_layout`, a pure function of the files mounted under a
folder and of ``/proc/self/cgroup``'s text: both branches are read here from fake cgroupfs trees
in a tmp folder, with the file names of the kernel's documentation (``cgroup.controllers``,
``cgroup.subtree_control``, ``pids.max``, ``memory.max``, ``memory.events``, ``cpu.weight`` for
v2; ``pids.max``, ``memory.limit_in_bytes``, ``memory.failcnt``, ``cpu.shares`` for v1).  The
host's own layout is checked against ``stat -f`` of ``/sys/fs/cgroup``.  Fast: no sandbox runs.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from tools.grading import runner, sandbox

ROOT = Path(__file__).resolve().parents[1]

LIMITS = sandbox.Limits(memory_bytes=1 << 30, tmp_bytes=8 << 20, disk_bytes=32 << 20)

V1_SELF = """\
9:name=systemd:/
8:pids:/
4:memory:/process_api/abc
2:cpu,cpuacct:/
0::/
"""
V2_SELF = "0::/user.slice/grader.scope\n"


def _files(folder: Path, **files: str) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (folder / name).write_text(text)
    return folder


def _v1_tree(base: Path) -> dict[str, Path]:
    """A hybrid host like this one: v1 controllers, cpu and cpuacct mounted together (with the
    usual ``cpu`` link), and an empty v2 hierarchy at ``unified``."""
    pids = _files(base / "pids", **{"cgroup.procs": "1\n"})
    memory = _files(base / "memory" / "process_api" / "abc", **{"cgroup.procs": "1\n"})
    _files(base / "memory", **{"cgroup.procs": ""})
    cpu = _files(base / "cpu,cpuacct", **{"cgroup.procs": "1\n", "cpu.shares": "1024"})
    os.symlink("cpu,cpuacct", base / "cpu")
    _files(base / "unified", **{"cgroup.controllers": "", "cgroup.procs": "1\n"})
    return {"pids": pids, "memory": memory, "cpu": base / "cpu,cpuacct", "_cpu": cpu}


def _v2_tree(base: Path, enabled: str = "", above: str = "") -> Path:
    """The grader in ``user.slice/grader.scope``; ``enabled``: its own ``subtree_control``,
    ``above``: that of the slice and of the root."""
    _files(base, **{"cgroup.controllers": "cpuset cpu io memory hugetlb pids rdma misc",
                    "cgroup.subtree_control": above, "cgroup.procs": ""})  # fmt: skip
    _files(base / "user.slice", **{"cgroup.controllers": "cpu memory pids",
                                   "cgroup.subtree_control": above})  # fmt: skip
    return _files(
        base / "user.slice" / "grader.scope",
        **{"cgroup.controllers": "cpu memory pids", "cgroup.subtree_control": enabled,
           "cgroup.procs": "4242\n"},
    )  # fmt: skip


def test_v1_is_chosen_when_controllers_have_their_own_hierarchies(tmp_path):
    tree = _v1_tree(tmp_path)
    layout = sandbox.cgroup_layout(tmp_path, V1_SELF)
    assert layout.version == 1
    assert layout.own == {"pids": tree["pids"], "memory": tree["memory"], "cpu": tmp_path / "cpu"}
    assert layout.enable == ()


@pytest.mark.parametrize("enabled", ["memory", "cpu memory pids"])
def test_v2_is_chosen_when_the_root_is_the_unified_hierarchy(tmp_path, enabled):
    own = _v2_tree(tmp_path, enabled)
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    assert layout.version == 2
    assert layout.own == {"pids": own, "cpu": own, "memory": own}
    assert layout.enable == tuple(c for c in ("pids", "cpu", "memory") if c not in enabled)


def test_v2_a_scope_with_processes_uses_the_nearest_slice_that_enables_controllers(tmp_path):
    """systemd: the grader's session scope holds processes and enables nothing for children;
    its slice has ``pids`` and ``memory`` on for its children: the sandboxes go there."""
    _v2_tree(tmp_path, enabled="", above="cpu memory pids")
    (tmp_path / "user.slice" / "cgroup.subtree_control").write_text("memory pids\n")
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    slice_ = tmp_path / "user.slice"
    assert layout == sandbox.CgroupLayout(2, {"pids": slice_, "memory": slice_})
    (slice_ / "cgroup.subtree_control").write_text("")  # nothing on anywhere below the root
    (tmp_path / "cgroup.subtree_control").write_text("")
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    own = slice_ / "grader.scope"
    assert layout.own == {"pids": own, "cpu": own, "memory": own}  # to enable (may fail)
    assert layout.enable == ("pids", "cpu", "memory")


def test_v2_the_root_group_enables_its_controllers_itself(tmp_path):
    _v2_tree(tmp_path)
    (tmp_path / "cgroup.subtree_control").write_text("")
    layout = sandbox.cgroup_layout(tmp_path, "0::/\n")
    assert layout.own == dict.fromkeys(("pids", "cpu", "memory"), tmp_path)
    assert layout.enable == ("pids", "cpu", "memory")


def test_v2_uses_only_the_controllers_its_own_group_offers(tmp_path):
    own = _v2_tree(tmp_path, enabled="memory")
    (own / "cgroup.controllers").write_text("memory\n")
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    assert layout.own == {"memory": own} and layout.enable == ()


@pytest.mark.parametrize("case", ["nothing mounted", "v2 without own line", "v2 no controllers"])
def test_no_usable_groups(tmp_path, case):
    self_cgroup = V2_SELF
    if case == "v2 without own line":
        _v2_tree(tmp_path)
        self_cgroup = "4:memory:/x\n"
    elif case == "v2 no controllers":
        (_v2_tree(tmp_path) / "cgroup.controllers").write_text("io\n")
    layout = sandbox.cgroup_layout(tmp_path, self_cgroup)
    assert layout.version == 0 and layout.own == {}


def test_the_hosts_layout_matches_what_is_mounted():
    kind = subprocess.run(["stat", "-fc", "%T", "/sys/fs/cgroup"], capture_output=True,
                          text=True).stdout.strip()  # fmt: skip
    layout = sandbox.host_cgroups()
    if kind == "cgroup2fs":
        assert layout.version in (0, 2), layout
    elif kind == "tmpfs":  # v1 hierarchies (and perhaps an empty v2 one beside them)
        assert layout.version in (0, 1), layout
    else:
        assert layout.version == 0, (kind, layout)
    print(f"/sys/fs/cgroup is {kind}: cgroup v{layout.version}, {sorted(layout.own)}")


def _written(folder: Path) -> dict[str, str]:
    return {p.name: p.read_text() for p in folder.iterdir() if p.is_file()}


def test_v2_groups_get_the_v2_files(tmp_path):
    own = _v2_tree(tmp_path)
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    groups = sandbox.SandboxGroups(LIMITS, job_tmpfs=True, layout=layout, root_only=False)
    (path,) = set(groups.paths.values())
    assert sorted(groups.paths) == ["cpu", "memory", "pids"]
    assert path.parent == own and path.name.startswith(sandbox.RUN_PREFIX + "-")
    memory = LIMITS.memory_bytes + 2 * LIMITS.tmp_bytes + LIMITS.disk_bytes  # job folder: RAM
    assert _written(path) == {"pids.max": "64", "cpu.weight": "100",
                              "cpu.max": "100000 100000", "memory.max": str(memory)}  # fmt: skip
    assert (own / "cgroup.subtree_control").read_text().startswith("+")  # enabled for children
    assert sandbox.run_groups(layout) == {str(path)}
    (own / "course-grader-1-0badf00d-123456789abc").mkdir()  # another grader's, same host
    assert sandbox.run_groups(layout) == {str(path)}
    assert groups.procs_files == [str(path / "cgroup.procs")]


def test_v1_groups_get_the_v1_files(tmp_path):
    tree = _v1_tree(tmp_path)
    layout = sandbox.cgroup_layout(tmp_path, V1_SELF)
    groups = sandbox.SandboxGroups(LIMITS, layout=layout, root_only=False)
    assert sorted(groups.paths) == ["cpu", "memory", "pids"]
    assert _written(groups.paths["pids"]) == {"pids.max": "64"}
    assert _written(groups.paths["memory"]) == {
        "memory.limit_in_bytes": str(LIMITS.memory_bytes + 2 * LIMITS.tmp_bytes)
    }
    assert _written(groups.paths["cpu"]) == {"cpu.shares": "1024", "cpu.cfs_period_us": "100000",
                                             "cpu.cfs_quota_us": "100000"}  # fmt: skip
    assert groups.paths["memory"].parent == tree["memory"]
    assert len(sandbox.run_groups(layout)) == 3


def test_v2_controllers_that_cannot_be_enabled_are_left_out(tmp_path):
    """A v2 group that holds processes refuses ``+pids`` in its ``cgroup.subtree_control``
    (not delegated): the sandbox then has no such group (made to fail here: a folder)."""
    own = _v2_tree(tmp_path)
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    (own / "cgroup.subtree_control").unlink()
    (own / "cgroup.subtree_control").mkdir()
    groups = sandbox.SandboxGroups(LIMITS, layout=layout, root_only=False)
    assert groups.paths == {} and sandbox.run_groups(layout) == set()


@pytest.mark.parametrize("version", [1, 2])
def test_counters_name_the_limits_met_even_when_the_error_was_caught(tmp_path, version):
    if version == 1:
        _v1_tree(tmp_path)
        layout = sandbox.cgroup_layout(tmp_path, V1_SELF)
    else:
        _v2_tree(tmp_path)
        layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    groups = sandbox.SandboxGroups(LIMITS, layout=layout, root_only=False)
    pids, memory = groups.paths["pids"], groups.paths["memory"]
    (pids / "pids.events").write_text("max 0\n")
    if version == 1:
        (memory / "memory.failcnt").write_text("0\n")
    else:
        (memory / "memory.events").write_text("low 0\nhigh 0\nmax 0\noom 0\noom_kill 0\n")
    assert groups.limits_reached() == set()
    (pids / "pids.events").write_text("max 3\n")  # three forks refused (and caught)
    assert groups.limits_reached() == {"processes"}
    if version == 1:
        (memory / "memory.failcnt").write_text("12\n")
    else:
        (memory / "memory.events").write_text("low 0\nhigh 0\nmax 5\noom 0\noom_kill 0\n")
    assert groups.limits_reached() == {"processes", "memory"}
    assert groups.memory_exhausted() is (version == 1)  # v2: 'max' without an oom_kill


def test_limit_notes_name_the_limit_and_its_value():
    limits = sandbox.Limits(processes=64, memory_bytes=2 << 30, tmp_bytes=4 << 20)
    flags = runner.limit_flags({"/dev/shm", "processes", "memory", "/tmp"}, limits)
    assert [f for f, _ in flags] == [
        "reached the process limit (64)",
        "reached the memory limit (2048 MB)",
        "reached the /tmp limit (4 MB)",
        "reached the /dev/shm limit (4 MB)",
    ]
    assert all(sentence.startswith(f"the sandbox {f}: ") for f, sentence in flags)


def test_the_file_size_limit_is_the_disk_limit_unless_set():
    """--disk 128 once stopped at 64 MB: RLIMIT_FSIZE was a fixed 64 MB (issue 27)."""
    assert sandbox.Limits(disk_bytes=128 << 20).file_bytes == 128 << 20
    assert sandbox.Limits(disk_bytes=128 << 20, file_bytes=1 << 20).file_bytes == 1 << 20


def test_a_python_outside_usr_and_the_course_is_bound_with_the_links_to_it(tmp_path, monkeypatch):
    """A conda environment under $HOME reached through a link to /opt (fake prefix): the
    environment is bound whole, read-only, and the link on the way remade; nothing else."""
    if sandbox.bwrap_path() is None:
        pytest.skip("bubblewrap is not installed")
    real = tmp_path / "opt" / "miniconda3"
    prefix = real / "envs" / "course"
    site = prefix / "lib" / "python3.11" / "site-packages"
    site.mkdir(parents=True)
    (prefix / "bin").mkdir()
    (prefix / "bin" / "python3.11").write_text("")
    home = tmp_path / "home" / "teacher"
    home.mkdir(parents=True)
    os.symlink(real, home / "miniconda3")
    seen = home / "miniconda3" / "envs" / "course"
    monkeypatch.setattr(sys, "prefix", str(seen))
    monkeypatch.setattr(sys, "exec_prefix", str(seen))
    monkeypatch.setattr(sys, "base_prefix", str(seen))  # conda: no venv on top
    monkeypatch.setattr(sys, "executable", str(seen / "bin" / "python3.11"))
    monkeypatch.setattr(sys, "path", ["", str(seen / "lib" / "python3.11" / "site-packages")])
    job = tmp_path / "job"
    job.mkdir()
    argv = sandbox.bwrap_argv(job, LIMITS)
    binds = [argv[i + 1] for i, a in enumerate(argv) if a == "--ro-bind"]
    links = [(argv[i + 1], argv[i + 2]) for i, a in enumerate(argv) if a == "--symlink"]
    assert str(prefix) in binds
    assert (str(real), str(home / "miniconda3")) in links
    assert str(ROOT / "course_lib") in binds and str(ROOT) not in binds
    assert not any(b.startswith(str(tmp_path)) and b != str(prefix) for b in binds), binds


def test_library_folders_are_read_from_the_maps_of_a_process():
    maps = (
        "7f1d7bc00000-7f1d7bc9a000 r--p 00000000 fe:00 123 /opt/py/lib/libpython3.11.so.1.0\n"
        "7f1d7ba1e000-7f1d7ba46000 r--p 00000000 fe:00 124 /usr/lib/x86_64-linux-gnu/libc.so.6\n"
        "7f1d7ba00000-7f1d7ba10000 r-xp 00000000 fe:00 125 /lib/x86_64-linux-gnu/libm.so.6\n"
        "7f1d7b000000-7f1d7b100000 r--p 00000000 fe:00 126 /nix/store/abc-zlib/lib/libz.so\n"
        "7f1d7a000000-7f1d7a100000 rw-s 00000000 00:01 127 /dev/shm/x.so (deleted)\n"
        "7f1d79000000-7f1d79100000 r--p 00000000 fe:00 128 /opt/py/lib/python3.11/os.py\n"
        "7ffd3c5f4000-7ffd3c615000 rw-p 00000000 00:00 0 [stack]\n"
        "7f1d78000000-7f1d78100000 rw-p 00000000 00:00 0\n"
    )
    assert sandbox.library_folders(maps) == [Path("/nix/store/abc-zlib/lib"), Path("/opt/py/lib")]


def test_root_without_a_pids_group_is_warned(tmp_path, monkeypatch):
    """As root, RLIMIT_NPROC binds nothing: without a ``pids`` group the grader says so."""
    own = _v2_tree(tmp_path)
    layout = sandbox.cgroup_layout(tmp_path, V2_SELF)
    monkeypatch.setattr(sandbox.os, "geteuid", lambda: 0)

    def groups(limits):
        return sandbox.SandboxGroups(limits, layout=layout, root_only=False)

    assert sandbox.process_limit_warning(LIMITS, groups) == ""
    (own / "cgroup.subtree_control").unlink()
    (own / "cgroup.subtree_control").mkdir()  # not delegated: no controller for children
    warning = sandbox.process_limit_warning(LIMITS, groups)
    assert "without a usable pids cgroup" in warning and "RLIMIT_NPROC" in warning
