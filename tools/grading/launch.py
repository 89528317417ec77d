"""Start a student's kernel under limits: ``python -I launch.py CONFIG_JSON -- COMMAND...``.

Run by the grader (see ``sandbox.py``): joins the sandbox's cgroups (``pids``, ``cpu``,
``memory``, when they could be made), sets the resource limits and a lower priority (``nice``),
replaces the environment, then execs COMMAND (bwrap, or the kernel itself when grading
unsandboxed).  Standard library only; nothing here trusts the
student: it runs before any student code.
"""

from __future__ import annotations

import json
import os
import resource
import sys


def _set(limit: int, value: int) -> None:
    try:
        _soft, hard = resource.getrlimit(limit)
        if hard != resource.RLIM_INFINITY:
            value = min(value, hard)
        resource.setrlimit(limit, (value, value))
    except (ValueError, OSError):
        pass  # not supported here (e.g. RLIMIT_AS on macOS): the grader's note says which apply


def _user_processes() -> int:
    uid = os.getuid()
    count = 0
    try:
        for entry in os.listdir("/proc"):
            if entry.isdigit():
                try:
                    if os.stat(f"/proc/{entry}").st_uid == uid:
                        count += len(os.listdir(f"/proc/{entry}/task"))
                except OSError:
                    pass
    except OSError:
        return 0
    return count


def main() -> None:
    sep = sys.argv.index("--")
    config = json.loads(sys.argv[1])
    command = sys.argv[sep + 1 :]
    for procs in config.get("cgroups", []):  # pids, cpu, memory groups of this sandbox
        with open(procs, "w") as fh:
            fh.write(str(os.getpid()))
    if not config.get("pids_group") and os.getuid() != 0 and hasattr(resource, "RLIMIT_NPROC"):
        # RLIMIT_NPROC counts all of this user's processes: allow what runs now plus the limit
        _set(resource.RLIMIT_NPROC, _user_processes() + int(config["processes"]))
    _set(resource.RLIMIT_AS, int(config["memory_bytes"]))
    _set(resource.RLIMIT_CPU, int(config["cpu_seconds"]))
    _set(resource.RLIMIT_FSIZE, int(config["file_bytes"]))
    _set(resource.RLIMIT_CORE, 0)
    try:
        os.nice(int(config.get("nice", 5)))  # below the grader, whatever the host's scheduler
    except OSError:
        pass
    os.execve(command[0], command, config["env"])


if __name__ == "__main__":
    main()
