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


def _hypothesis_profiles() -> None:
    """In CI (CI=true) property tests draw the same examples every run (derandomized), so a
    landing never depends on luck; locally they explore new examples each run."""
    import os

    try:
        from hypothesis import settings
    except ImportError:  # pragma: no cover - hypothesis is a test dependency
        return
    settings.register_profile("ci", derandomize=True, deadline=None, print_blob=True)
    if os.environ.get("CI"):
        settings.load_profile("ci")


_hypothesis_profiles()
