"""Answer keys (issue 24): checks that recognise a value without holding it.

hw01 q1, q4, q5, q7 and hw02 q5 are values whose only test is the formula the question asks
for.  Their checks compare scrypt digests from a key file (``course_lib/homework/answer_keys.py``)
that the instructor writes from the hidden tests (``tools/answer_keys.py``; ``make release
SECRET=... ROSTER=...`` for every student's data).  Here: the package's key file is the tool's
output, a ✓ is a full grade, every known mistake gets its message, a student without a key is
told so, the key file holds no answer, and an edition made with a roster checks a roster
student's answers in the student's own Python.
"""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from _homework_support import SECRET, STUDENTS, VariantHomework
from hypothesis import Phase, given, settings
from hypothesis import strategies as st

from course_lib.homework import answer_keys, variants
from course_lib.homework.checks import check
from tools.grading.protocol import LocalStudent, run_question

ROOT = Path(__file__).resolve().parents[1]
HOMES = {hw: VariantHomework(hw) for hw in ("hw01", "hw02")}
KEYED = {
    "hw01": {"q1": "answer_q1", "q4": "answer_q4", "q5": "answer_q5", "q7": "answer_q7"},
    "hw02": {"q5": "answer_q5"},
}
#: what each check says for each known mistake (a phrase of its message)
MISTAKE_MESSAGES = {
    "backwards": "points backwards",
    "swapped": "swapped",
    "sign-left": "turns left",
    "sign-right": "turns right",
    "radius": "radius of curvature",
    "power": "power of ‖q'‖",
    "missing-term": "missing",
    "at-s": "not at u = s",
    "f1-not-squared": "f' enters squared",
    "original": "q'' of the original curve",
    "chord": "length of the chord",
    "beta1-not-squared": "β1 enters the second derivative squared",
    "mixed-up": "mixed them up",
}


@pytest.fixture
def package_keys():
    """The checks as a student's copy has them: the package's own key file."""
    before = answer_keys.keys()
    answer_keys.use(None)
    yield answer_keys.keys()
    answer_keys.use(before)


def _grade(hw: str, q: str, value, data) -> float:
    test = getattr(HOMES[hw].hidden, q)
    return run_question(lambda student: test(student, data), LocalStudent({KEYED[hw][q]: value}))[0]


# ------------------------------------------------------------------ the package's key file
def test_the_package_key_file_is_what_the_tool_writes(tmp_path):
    out = tmp_path / "keys.json"
    done = subprocess.run([sys.executable, "tools/answer_keys.py", "--out", str(out)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)  # fmt: skip
    assert done.returncode == 0, done.stderr
    committed = ROOT / "course_lib" / "homework" / "answer_keys.json"
    assert out.read_bytes() == committed.read_bytes(), (
        "course_lib/homework/answer_keys.json is stale: run python tools/answer_keys.py"
    )
    assert json.loads(committed.read_text())["cost"] == answer_keys.DEFAULT_COST


@pytest.mark.parametrize("hw", ["hw01", "hw02"])
def test_with_the_package_keys_the_default_data_is_checked_by_digest(hw, package_keys):
    data = variants.data(hw, variants.DEFAULT)
    for q, pairs in HOMES[hw].hidden.key_values(data).items():
        qid = f"{hw}.{q}"
        for tag, value in pairs:
            verdict = check(qid, value)
            if tag == "right":
                assert verdict.passed and verdict.status == "passed", (qid, verdict)
            else:
                assert not verdict.passed, (qid, tag, verdict)
                assert MISTAKE_MESSAGES[tag] in verdict.message, (qid, tag, verdict.message)
        right = dict(pairs)["right"]
        other = np.asarray(right, dtype=float) * 1.37 + 0.011
        if qid == "hw01.q1":
            other = other / np.linalg.norm(other)  # a unit vector, another direction
        verdict = check(qid, other)
        assert verdict.status == "failed", (qid, verdict)


def test_the_key_file_holds_digests_and_tags_only():
    document = json.loads((ROOT / "course_lib" / "homework" / "answer_keys.json").read_text())
    assert set(document) == {"about", "format", "cost", "keys"}
    hexes = re.compile(r"[0-9a-f]{32}")
    for index, entry in document["keys"].items():
        assert hexes.fullmatch(index)
        for dig, tag in entry.items():
            assert hexes.fullmatch(dig) and (tag == "right" or tag in MISTAKE_MESSAGES), (dig, tag)
    text = json.dumps(document)
    for hw in ("hw01", "hw02"):
        for pairs in HOMES[hw].hidden.key_values(variants.data(hw, variants.DEFAULT)).values():
            for x in np.atleast_1d(dict(pairs)["right"]):
                for digits in range(2, 13):
                    shown = f"{abs(float(x)):.{digits}f}".rstrip("0")
                    if len(shown) > 4:  # "0.1" could be anywhere in a hex digest's neighbourhood
                        assert shown not in text, (hw, x, shown)
    variants.data("hw01", variants.DEFAULT)


# ------------------------------------------------------------------ a ✓ is a full grade
@settings(
    max_examples=60,
    deadline=None,
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink],
)
@given(
    student=st.integers(0, len(STUDENTS) - 1),
    which=st.sampled_from(
        [("hw01", "q1"), ("hw01", "q4"), ("hw01", "q5"), ("hw01", "q7"), ("hw02", "q5")]
    ),
    steps=st.floats(-3.0, 3.0),
)
def test_a_check_s_tick_is_a_full_grade_and_far_misses_are_refused(student, which, steps):
    """A value off by up to three grid steps: if the check says ✓, the grader gives full points;
    more than two steps off, the check never says ✓; within one step, it always does."""
    hw, q = which
    module = __import__(f"course_lib.homework.checks.{hw}", fromlist=["ANSWER_KEYS"])
    quantum = module.ANSWER_KEYS[q]
    data = variants.data(hw, HOMES[hw].codes[student])
    right = np.atleast_1d(
        np.asarray(dict(HOMES[hw].hidden.key_values(data)[q])["right"], dtype=float)
    )
    value = right + steps * quantum
    if q == "q1" and hw == "hw01":  # a unit tangent stays a unit vector: turn it instead
        angle = steps * quantum
        c, s = math.cos(angle), math.sin(angle)
        value = np.array([c * right[0] - s * right[1], s * right[0] + c * right[1]])
    verdict = check(f"{hw}.{q}", value if value.size > 1 else float(value[0]))
    variants.data(hw, variants.DEFAULT)
    off = float(np.max(np.abs(value - right))) / quantum
    if verdict.passed:
        assert _grade(hw, q, value if value.size > 1 else float(value[0]), data) == 1.0
    if off >= 2.0:
        assert not verdict.passed, (hw, q, off)
    if off <= 1.0:
        assert verdict.passed, (hw, q, off, verdict)


@given(x=st.floats(-1e3, 1e3), quantum=st.sampled_from([5e-10, 2.5e-7, 1e-3]))
def test_a_value_lands_on_the_right_grid_point_or_a_neighbour(x, quantum):
    """Property of the grid: every value within one step of x has x's point among its candidates."""
    points = set(answer_keys.grid_candidates([x], quantum))
    for nearby in (x - 0.999 * quantum, x + 0.999 * quantum, x):
        (own,) = list(answer_keys.grid_candidates([nearby], quantum))[:1]
        assert own in points


# ------------------------------------------------------------------ no key, bad keys
def test_a_student_without_a_key_is_told_so_not_marked_wrong():
    """A code made after the release (a late enrolment): hw02 q5's data (~500,000 kinds) is
    almost surely no roster student's, so there is no key for it."""
    code = variants.code_for(SECRET, "hw02", "someone-not-on-the-roster")
    variants.data("hw02", code)
    try:
        verdict = check("hw02.q5", [0.25, 1.5])
        malformed = check("hw02.q5", "a string")
    finally:
        variants.data("hw02", variants.DEFAULT)
    assert verdict.status == "not checked here" and not verdict.passed
    assert str(verdict).startswith("? hw02.q5 (value not checked here):")
    assert "instructor" in verdict.message and "VARIANT" in verdict.message
    assert malformed.status == "failed"  # the form is still checked first


@pytest.mark.parametrize(
    "document, rule",
    [
        ({"format": 2, "cost": 16, "keys": {}}, "format 1"),
        ({"format": 1, "cost": 1000, "keys": {}}, "power of 2"),
        ([], "format 1"),
        ({"format": 1, "cost": 16, "keys": {"ab": ["not", "a", "map"]}}, "digest: tag"),
    ],
)
def test_a_broken_key_file_is_refused_with_its_rule(document, rule):
    with pytest.raises(ValueError, match=rule):
        answer_keys.AnswerKeys(document)


def test_an_entry_needs_one_right_value_and_finite_values():
    with pytest.raises(ValueError, match="exactly one pair tagged 'right'"):
        answer_keys.entry("hw01.q4", 5e-10, {"k": 1.0}, [("sign", 0.5)], cost=16)
    with pytest.raises(ValueError, match="finite"):
        answer_keys.entry("hw01.q4", 5e-10, {"k": 1.0}, [("right", float("nan"))], cost=16)
    with pytest.raises(ValueError, match="quantum"):
        list(answer_keys.grid_candidates([1.0], 0.0))


def test_a_mistake_next_to_the_right_value_is_left_out():
    _index, entry = answer_keys.entry(
        "hw01.q4", 1e-3, {"k": 1.0}, [("right", 0.5), ("sign", 0.5005), ("radius", 2.0)], cost=16
    )
    assert sorted(entry.values()) == ["radius", "right"]


# ------------------------------------------------------------------ the user's path
def test_an_edition_released_with_the_roster_checks_a_roster_student_in_their_python(tmp_path):
    """As the semester page says: the secret, the roster, ``tools/release.py`` with both (what
    ``make release SECRET=... ROSTER=...`` runs); then the student's Python in the unpacked
    edition, with their code, checks their right answer ✓ and a mistake ✗, and a code of
    someone not on the roster gets "value not checked here"."""
    secret_file = tmp_path / "course_secret.txt"
    secret_file.write_bytes(SECRET + b"\n")
    roster = tmp_path / "roster.csv"
    roster.write_text("id,name,email\n1001,Ada Lovelace,ada@example.org\n1002,Emmy Noether,\n")
    out = tmp_path / "dist" / "student-edition"
    done = subprocess.run(
        [sys.executable, "tools/release.py", "--out", str(out), "--secret-file", str(secret_file),
         "--roster", str(roster)],
        cwd=ROOT, capture_output=True, text=True, timeout=600,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    assert "answer keys for the default data and 2 students" in done.stdout
    import zipfile

    with zipfile.ZipFile(out.with_suffix(".zip")) as zf:
        zf.extractall(tmp_path / "unpacked")
    edition = tmp_path / "unpacked" / "student-edition"
    code = variants.code_for(SECRET, "hw01", "1002")
    stranger = variants.code_for(SECRET, "hw01", "1003")
    data = variants.data("hw01", code)
    values = dict(HOMES["hw01"].hidden.key_values(data)["q5"])
    variants.data("hw01", variants.DEFAULT)
    script = (
        "import sys\n"
        "from course_lib.homework import variants\n"
        "from course_lib.homework.checks import check\n"
        "import course_lib\n"
        "print(course_lib.__file__)\n"
        f"variants.data('hw01', {code!r})\n"
        f"print(check('hw01.q5', {values['right'].tolist()!r}).status)\n"
        f"print(check('hw01.q5', {values['missing-term'].tolist()!r}))\n"
        f"variants.data('hw01', {stranger!r})\n"
        f"print(check('hw01.q5', {values['right'].tolist()!r}).status)\n"
    )
    ran = subprocess.run([sys.executable, "-c", script], cwd=edition, capture_output=True, text=True,
                         env={"PATH": "/usr/bin:/bin", "PYTHONPATH": str(edition)}, timeout=300)  # fmt: skip
    assert ran.returncode == 0, ran.stderr
    where, right, mistake, unknown = ran.stdout.splitlines()
    assert where.startswith(str(edition)), where  # the edition's own course_lib
    assert right == "passed"
    assert mistake.startswith("✗ hw01.q5") and "one term is missing" in mistake
    assert unknown == "not checked here"


@pytest.mark.parametrize(
    "args, said",
    [
        (["--secret-file", "course_secret.txt"], "give --secret-file and --roster together"),
        (["--roster", "roster.csv"], "give --secret-file and --roster together"),
        (["--secret-file", "course_secret.txt", "--roster", "missing.csv"], "--roster missing.csv"),
    ],
)
def test_a_release_with_half_of_what_keys_need_stops_in_one_sentence(tmp_path, args, said):
    (tmp_path / "course_secret.txt").write_bytes(SECRET)
    out = tmp_path / "edition"
    done = subprocess.run([sys.executable, str(ROOT / "tools" / "release.py"), "--out", str(out), *args],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)  # fmt: skip
    assert done.returncode != 0 and said in done.stderr and "Traceback" not in done.stderr
    assert not out.exists()  # nothing written


def test_a_rounded_number_is_told_to_keep_its_digits_not_that_the_formula_is_wrong():
    """The walk: κ typed with 8 decimals was told "not the signed curvature" alone."""
    data = variants.data("hw01", variants.DEFAULT)
    kappa = dict(HOMES["hw01"].hidden.key_values(data)["q4"])["right"]
    typed = check("hw01.q4", float(f"{kappa:.8f}"))
    computed_wrong = check("hw01.q4", kappa * math.pi)
    assert not typed.passed and "If you typed a rounded number" in typed.message
    assert "9 decimals" in typed.message
    assert not computed_wrong.passed and "rounded" not in computed_wrong.message
    assert check("hw01.q4", kappa).passed  # full precision


def test_without_a_key_the_checks_that_need_none_still_speak():
    """A late enrolment's q7: an arc shorter than its chord is still "too short"; the report
    counts the questions not checked here apart from the failed ones."""
    code = variants.code_for(SECRET, "hw01", "a-late-enrolment")
    data = variants.data("hw01", code)
    try:
        keys = answer_keys.keys()
        answer_keys.use(answer_keys.AnswerKeys({"format": 1, "cost": 16, "keys": {}}))
        short = check("hw01.q7", 0.0001)
        unchecked = check("hw01.q7", 1e3)
        from course_lib.homework.checks import check_all

        worked = HOMES["hw01"].hidden.answers_for(data)
        report = str(check_all({**worked, "HOMEWORK": "hw01", "VARIANT": code}, "hw01"))
    finally:
        answer_keys.use(keys)
        variants.data("hw01", variants.DEFAULT)
    assert short.status == "failed" and "too short" in short.message
    assert unchecked.status == "not checked here"
    assert "4 not checked here (no answer key for your data)" in report.splitlines()[0], report


@pytest.mark.parametrize(
    "hw, q, tag, words",
    [
        ("hw01", "q4", "sign-left", "the sign of κ is wrong"),
        ("hw01", "q4", "radius", "radius of curvature"),
        ("hw01", "q5", "missing-term", "a term of the chain rule is missing"),
        ("hw01", "q7", "chord", "length of the chord"),
        ("hw02", "q5", "missing-term", "the β2 term is missing"),
    ],
)
def test_the_grader_s_feedback_names_the_mistake_the_check_named(hw, q, tag, words):
    """The walk: a sign error was "✗ the sign is not right" in the check but only "κ(-2) is
    wrong" in the grade's feedback."""
    data = variants.data(hw, variants.DEFAULT)
    pairs = HOMES[hw].hidden.key_values(data)[q]
    value = next(v for t, v in pairs if t == tag or (tag == "sign-left" and t.startswith("sign")))
    test = getattr(HOMES[hw].hidden, q)
    fraction, note = run_question(lambda student: test(student, data), LocalStudent({KEYED[hw][q]: value}))
    assert fraction == 0.0 and words in note, note
