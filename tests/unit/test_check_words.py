"""Feedback says in words what the symbol says (WCAG 1.1.1: "✗" alone is read as nothing or
as "cross mark" by a screen reader)."""

from __future__ import annotations

from course_lib.homework.checks._core import FAIL, PASS, UNANSWERED, Verdict


def test_a_failed_check_says_so_in_words():
    v = Verdict("hw02.q3", False, "the tangent at t = 0 is (1, 0)", FAIL)
    assert str(v) == "✗ hw02.q3 (not right yet): the tangent at t = 0 is (1, 0)"
    assert "✗ hw02.q3 (not right yet)</b>" in v._repr_html_()


def test_passed_and_unanswered_keep_their_message():
    assert str(Verdict("hw01.q1", True, "correct.", PASS)) == "✓ hw01.q1: correct."
    msg = "not answered yet: replace the ... by your answer."
    assert str(Verdict("hw01.q1", False, msg, UNANSWERED)) == f"… hw01.q1: {msg}"
