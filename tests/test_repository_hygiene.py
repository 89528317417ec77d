"""The repository holds source, not build products: no binary packages, and the declared licence."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BINARY_PACKAGES = (".whl", ".tar.gz", ".tgz", ".zip", ".egg", ".conda", ".so", ".dylib", ".dll")


def tracked_files() -> list[str]:
    out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True)
    return [name for name in out.stdout.decode().split("\0") if name]


def test_no_binary_package_is_tracked():
    files = tracked_files()
    assert "pyproject.toml" in files  # the listing itself worked
    offenders = [f for f in files if f.endswith(BINARY_PACKAGES)]
    assert offenders == [], f"binary packages in git: {offenders}"


def test_wheels_are_ignored():
    ignored = subprocess.run(["git", "check-ignore", "-q", "numpy-9.9-py3-none-any.whl"], cwd=ROOT)
    assert ignored.returncode == 0


def test_license_file_matches_the_declared_licence():
    declared = re.search(r'^license = \{ text = "([^"]+)" \}$',
                         (ROOT / "pyproject.toml").read_text(), re.M)
    assert declared is not None and declared.group(1) == "BSD-3-Clause"
    text = (ROOT / "LICENSE").read_text()
    assert "BSD 3-Clause License" in text
    assert "Neither the name of the copyright holder" in text  # the third clause, not BSD-2
    assert "LICENSE" in tracked_files()
