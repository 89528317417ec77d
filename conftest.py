"""Repository-wide pytest configuration.

One `pytest` run covers the unit tests (tests/) and nbval over notebooks/, exercises/ and
solutions/ (options in pyproject.toml).  Notebooks under tests/fixtures/ are data for other tests
(submissions to grade, some broken on purpose), never executed by nbval.
"""

from __future__ import annotations

from pathlib import Path


def pytest_ignore_collect(collection_path: Path, config) -> bool | None:
    if collection_path.suffix == ".ipynb" and "fixtures" in collection_path.parts:
        return True
    return None
