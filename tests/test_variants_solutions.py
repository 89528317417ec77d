"""Every homework with per-student variants, graded as the grader would (issue 19).

* The solution notebook, run in-process with a student's code, scores full marks on 50 variants.
* The same answers graded on another student's data lose the points of every data question
  whose answer differs, and those of the questions that are the same for everyone (a notebook
  not done on one's own data earns none of them: ``answers.require_own_data``)
  (questions worth 0 points, feedback-only multiple choice, are left out of that comparison).
"""

from __future__ import annotations

import matplotlib
import pytest

matplotlib.use("Agg")

from _homework_support import VariantHomework, differ

from course_lib.homework import variants

# homework -> (questions whose data differ per student, answers that must differ per pair)
HOMEWORKS = {
    "hw01": (("q1", "q3", "q4", "q5", "q6", "q7"), 4),  # q1, q4, q5, q7 rarely equal
    "hw02": (("q1", "q2", "q5", "q6", "q7"), 3),  # q1, q2, q5 rarely equal
    "hw03": (("q1", "q3", "q4", "q5"), 3),  # q1, q3, q5 rarely equal
    "hw04": (("q1", "q3", "q5", "q6"), 3),  # q1, q3, q5 rarely equal
    "hw05": (("q1", "q3", "q4", "q6"), 1),  # q3 rarely equal; q1, q6 equal for glyphs of one font
}
HW = {hw: VariantHomework(hw) for hw in HOMEWORKS}
SOLVED = 50


@pytest.fixture(autouse=True)
def _default_afterwards():
    yield
    for hw in HOMEWORKS:
        variants.data(hw, variants.DEFAULT)  # the checks of other tests see the default data


def test_every_homework_with_variants_is_covered_here():
    with_variants = set(variants.generators())
    assert with_variants == set(HOMEWORKS), f"list {sorted(with_variants ^ set(HOMEWORKS))} here"


@pytest.mark.parametrize("hw, index", [(hw, i) for hw in HOMEWORKS for i in range(SOLVED)])
def test_the_solution_scores_full_marks_on_its_variant(hw, index):
    home = HW[hw]
    code = home.codes[index]
    ns = home.solution_namespace(code)  # its last cell asserts that every check passes
    d = variants.data(hw, code)
    for q in home.hidden.POINTS:
        fraction, note = home.grade(q, ns, d)
        assert fraction == 1.0, f"{code} {q}: {fraction} ({note})"


@pytest.mark.parametrize("hw", HOMEWORKS)
def test_a_solution_done_with_another_code_loses_the_points_of_every_answer_that_differs(hw):
    home, (data_questions, per_pair) = HW[hw], HOMEWORKS[hw]
    pairs = list(zip(home.codes[:10], home.codes[10:20], strict=True))
    lost = 0
    for a, b in pairs:
        da, db = variants.data(hw, a), variants.data(hw, b)
        assert da != db
        wa, wb = home.hidden.answers_for(da), home.hidden.answers_for(db)
        ns = home.solution_namespace(a)
        total = 0.0
        for q, points in home.hidden.POINTS.items():
            fraction, _ = home.grade(q, ns, db)
            if q in data_questions and differ(wa[f"answer_{q}"], wb[f"answer_{q}"]):
                assert fraction < 1.0, (a, b, q)
                lost += 1
            elif q not in data_questions:  # the same for everyone: only on one's own data
                assert fraction == 0.0, (a, b, q)
            total += fraction * points
        # marked wrong also where no point is at stake (multiple choice); points lost elsewhere
        assert total < sum(home.hidden.POINTS.values()), (a, b)
    assert lost >= per_pair * len(pairs)
