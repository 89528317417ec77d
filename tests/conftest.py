"""Fixtures of the tests under tests/ (the repository-wide configuration is ../conftest.py)."""

from __future__ import annotations

import pytest
from _homework_support import keys_of_the_test_students

from course_lib.homework import answer_keys


@pytest.fixture(scope="session", autouse=True)
def answer_keys_of_the_test_students():
    """The checks in this process know the answers of the tests' 1,000 students per homework
    (as an edition made with their roster does: ``make release SECRET=... ROSTER=...``), hashed
    cheaply; the package's own key file is tested in ``tests/test_answer_keys.py``."""
    answer_keys.use(keys_of_the_test_students())
    yield
    answer_keys.use(None)
