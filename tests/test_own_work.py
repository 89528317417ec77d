"""Points only for one's own work (issue 24): the library does not do a function exercise.

For every function question of every homework, a submission that calls ``course_lib``'s
implementation of it -- directly, through an alias bound before the check, through
``importlib`` or ``getattr`` on the module, from another thread, after clearing the guard's
state -- gets 0 for that question from the grader (the hidden test through ``LocalStudent``:
the probe's own code, in-process) and a failing check, both with the one sentence
"<implementation> is the exercise of <question>: write it yourself".  The honest solution keeps
full marks.  One lazy notebook is also graded end to end in the sandboxed kernel.
"""

from __future__ import annotations

import ast
import functools
import importlib
import inspect
import json
import threading
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
from _homework_support import VariantHomework, load

from course_lib.homework import own_work, variants
from course_lib.homework.checks import HOMEWORKS, check, questions, registry
from tools.grading.protocol import LocalStudent, run_question

ROOT = Path(__file__).resolve().parents[1]
#: the tests' students' codes (the session's answer keys know their data: conftest.py)
HOME_CODES = {hw: VariantHomework(hw).codes for hw in ("hw01", "hw02")}
HIDDEN = {
    hw: load(f"hidden_{hw}_own_work", ROOT / "solutions" / "hidden_tests" / f"{hw}.py")
    for hw in HOMEWORKS
}



def _outline_of(P0, A, B, P2):
    from course_lib.constructions.outlines import Outline, truetype_contour

    pts = np.array([P0, A, B, P2], dtype=float)
    return Outline((truetype_contour(pts, np.array([True, False, False, True])),), "one joint")


#: question -> (module, implementation, how a lazy submission turns it into the answer)
LAZY = {
    "hw01.q2": (
        "course_lib.geometry.reparametrization",
        "faa_di_bruno",
        lambda impl, q1, q2, f1, f2: impl(np.array([q1, q2]), np.array([f1, f2])),
    ),
    "hw02.q3": (
        "course_lib.geometry.beta_constraints",
        "solve_shape_parameters",
        lambda impl, q, r, tol=1e-9: bool(
            impl(np.array([q], float), np.array([r], float)).betas[0] > 0
        ),
    ),
    "hw03.q2": ("course_lib.constructions.knot_splines", "bezier_points_from_g1", lambda impl, d, k: impl(d, k)),
    "hw03.q7": ("course_lib.constructions.knot_splines", "knot_ratio_beta1", lambda impl, t: impl(t)),
    "hw04.q2": (
        "course_lib.constructions.stitching",
        "g2_stitch_points",
        lambda impl, V, b1, b2: impl(V, b1, b2),
    ),
    "hw04.q4": (
        "course_lib.constructions.beta_splines.quadratic_cubic",
        "quadratic_beta_spline",
        lambda impl, V, b: np.array(impl(V, b).segments),
    ),
    "hw05.q2": (
        "course_lib.constructions.outlines.classification",
        "classify_joints",
        lambda impl, P0, A, B, P2: bool(impl(_outline_of(P0, A, B, P2)).kind[1] == "G2"),
    ),
}


def _lazy(qid: str, style: str):
    """A student's answer to ``qid`` that calls the library's implementation, in ``style``."""
    module_name, name, adapt = LAZY[qid]
    if style == "direct":
        impl = getattr(importlib.import_module(module_name), name)  # `from m import f` at the top
        return lambda *a: adapt(impl, *a)
    if style == "alias":
        alias = getattr(importlib.import_module(module_name), name)  # `f = knot_ratio_beta1`

        def answer(*a):
            return adapt(alias, *a)

        return answer
    if style == "importlib":
        return lambda *a: adapt(getattr(importlib.import_module(module_name), name), *a)
    if style == "getattr":
        module = importlib.import_module(module_name)
        return lambda *a: adapt(getattr(module, name), *a)
    if style == "wrapped":  # whatever a wrapper would hide: __wrapped__, a closure, __code__
        impl = getattr(importlib.import_module(module_name), name)
        inner = getattr(impl, "__wrapped__", impl)
        return lambda *a: adapt(inner, *a)
    if style == "thread":  # the call made on another thread

        def in_thread(*a):
            out = {}

            def run():
                try:
                    out["value"] = adapt(getattr(importlib.import_module(module_name), name), *a)
                except BaseException as exc:  # carried back to the caller
                    out["error"] = exc

            t = threading.Thread(target=run)
            t.start()
            t.join()
            if "error" in out:
                raise out["error"]
            return out["value"]

        return in_thread
    if style == "cleared":  # the guard's process-wide state emptied inside the function

        def cleared(*a):
            own_work._ACTIVE.clear()
            return adapt(getattr(importlib.import_module(module_name), name), *a)

        return cleared
    raise AssertionError(style)


STYLES = ("direct", "alias", "importlib", "getattr", "wrapped", "thread", "cleared")


def _function_questions() -> dict[str, str]:
    """question -> answer name, for every registered question answered by a function."""
    out = {}
    for hw in HOMEWORKS:
        for qid in questions(hw):
            name = registry()[qid].answer_name
            if not name.startswith("answer_"):
                out[qid] = name
    return out


def _grade(qid: str, namespace: dict) -> tuple[float, str]:
    hw, q = qid.split(".")
    test = functools.partial(getattr(HIDDEN[hw], q), data=variants.data(hw, variants.DEFAULT))
    return run_question(test, LocalStudent(namespace))


def test_every_function_question_has_a_row_and_its_answer_name():
    rows = {q: e.answer_name for q, e in own_work.EXERCISES.items()}
    assert rows == _function_questions()
    names = [e.answer_name for e in own_work.EXERCISES.values()]
    assert len(set(names)) == len(names), "the probe finds the question by its answer name"


def test_every_library_one_liner_of_the_table_is_guarded():
    assert {q for q, e in own_work.EXERCISES.items() if e.implementations} == set(LAZY)
    for qid, (module_name, name, _) in LAZY.items():
        assert f"{module_name}.{name}" in own_work.EXERCISES[qid].implementations


ALL_ROWS = [*own_work.EXERCISES.values(), *own_work.VALUE_EXERCISES.values()]


@pytest.mark.parametrize("dotted", sorted({n for e in ALL_ROWS for n in e.implementations}))
def test_every_implementation_starts_with_its_own_guard(dotted):
    module_name, name = dotted.rsplit(".", 1)
    func = getattr(importlib.import_module(module_name), name)
    assert not hasattr(func, "__wrapped__") and func.__closure__ is None  # no unguarded original
    tree = ast.parse(inspect.getsource(func).lstrip())
    body = tree.body[0].body
    first = (
        body[1]
        if isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant)
        else body[0]
    )
    assert ast.unparse(first) == f"own_work.require({dotted!r})"


@pytest.mark.parametrize("style", STYLES)
@pytest.mark.parametrize("qid", sorted(LAZY))
def test_library_call_gets_zero_from_the_grader_and_fails_the_check(qid, style):
    answer = _lazy(qid, style)
    implementation = ".".join(LAZY[qid][:2])
    sentence = own_work.exercise_message(implementation, qid)
    assert sentence == f"{implementation} is the exercise of {qid}: write it yourself"
    verdict = check(qid, answer)
    assert not verdict.passed and verdict.message == sentence + ".", verdict.message
    fraction, note = _grade(qid, {own_work.EXERCISES[qid].answer_name: answer})
    assert fraction == 0.0 and sentence in note, note
    assert not own_work._ACTIVE  # restored after the evaluation


@pytest.mark.parametrize("qid", sorted(LAZY))
def test_the_same_call_works_outside_an_evaluation(qid):
    """The guard is what stops the one-liner: outside the check and the probe it answers."""
    answer = _lazy(qid, "direct")
    args = {
        "hw01.q2": (np.array([1.0, 2.0]), np.array([0.0, 2.0]), 1.5, 1.0),
        "hw02.q3": (np.array([1.0, 2.0]), np.array([2.0, 4.0])),
        "hw03.q2": (np.arange(12.0).reshape(6, 2) ** 1.5, np.array([0.0, 1.0, 3.0])),
        "hw03.q7": (np.array([0.0, 1.0, 3.0]),),
        "hw04.q2": (np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]]), 1.5, 1.0),
        "hw04.q4": (
            np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]),
            np.array([1.0, 2.0, 0.5]),
        ),
        "hw05.q2": tuple(
            np.array(p) for p in ([913.5, 877.5], [830.0, 993.0], [538.0, 993.0], [454.5, 877.5])
        ),
    }[qid]
    assert answer(*args) is not None


def test_state_set_before_the_check_does_not_switch_the_guard_off(monkeypatch):
    """A notebook that empties the guard's state or the environment before its check."""
    monkeypatch.setenv(own_work.ENV_VAR, "")
    own_work._ACTIVE.clear()
    from course_lib.constructions.knot_splines import knot_ratio_beta1 as alias

    verdict = check("hw03.q7", alias)
    assert "is the exercise of hw03.q7" in verdict.message
    fraction, note = _grade("hw03.q7", {"knot_ratio_beta1": alias})
    assert fraction == 0 and "is the exercise of hw03.q7" in note


def test_a_child_process_inherits_the_exercise(tmp_path):
    import subprocess
    import sys

    code = (
        "import numpy as np\n"
        "from course_lib.constructions.knot_splines import knot_ratio_beta1\n"
        "print(knot_ratio_beta1(np.array([0.0, 1.0, 3.0])))\n"
    )

    def in_child(t):
        run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        if run.returncode:
            raise RuntimeError(run.stderr.strip().splitlines()[-1])
        return np.array([2.0] * (len(t) - 2))

    verdict = check("hw03.q7", in_child)
    assert "is the exercise of hw03.q7" in verdict.message


def test_other_questions_and_plain_use_are_not_guarded():
    """Outside an evaluation, and during another question's, the library works as always."""
    from course_lib.constructions.knot_splines import bezier_points_from_g1

    D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0]], dtype=float)
    ref = bezier_points_from_g1(D, [0.0, 1.0, 3.0])

    def knot_ratio_using_another_exercise(t):
        bezier_points_from_g1(D, [0.0, 1.0, 3.0])  # hw03.q2's implementation, inside q7: allowed
        h = np.diff(t)
        return h[1:] / h[:-1]

    assert check("hw03.q7", knot_ratio_using_another_exercise).passed
    assert np.allclose(bezier_points_from_g1(D, [0.0, 1.0, 3.0]), ref)


@pytest.fixture(scope="module")
def solution_namespaces():
    return {hw: VariantHomework(hw).solution_namespace(variants.DEFAULT) for hw in HOMEWORKS}


@pytest.mark.parametrize("qid", sorted(own_work.EXERCISES))
def test_the_honest_solution_keeps_full_marks(qid, solution_namespaces):
    ns = solution_namespaces[qid.split(".")[0]]
    name = own_work.EXERCISES[qid].answer_name
    assert check(qid, ns[name]).passed
    assert _grade(qid, ns)[0] == 1.0


# ------------------------------------------------------------------ in the sandboxed kernel
LAZY_CELLS = {
    "knot_ratio_beta1": (
        "from course_lib.constructions.knot_splines import knot_ratio_beta1 as _library_ratio\n"
        "knot_ratio_beta1 = _library_ratio  # an alias bound before the check\n"
    ),
    "g1_bezier_control_points": (
        "import importlib\n"
        "def g1_bezier_control_points(d, knots):\n"
        "    return importlib.import_module('course_lib.constructions.knot_splines').bezier_points_from_g1(d, knots)\n"
    ),
}


@pytest.mark.slow
@pytest.mark.timeout(300)
def test_a_lazy_notebook_graded_in_the_sandbox(tmp_path):
    import nbformat

    from tools import grade
    (solution,) = sorted((ROOT / "solutions").glob("hw03_*.ipynb"))
    nb = nbformat.read(solution, as_version=4)
    for cell in nb.cells:
        for name, source in LAZY_CELLS.items():
            if cell.cell_type == "code" and cell.source.lstrip().startswith(f"def {name}("):
                cell.source = source
    assert sum(c.source in LAZY_CELLS.values() for c in nb.cells) == 2
    (q1,) = [c for c in nb.cells if c.cell_type == "code" and c.source.startswith("t0, t1, t2 =")]
    q1.source = (  # a value question's one-liner: the cell raises in the kernel
        "from course_lib.constructions.knot_splines import bezier_points_from_g1\n"
        'answer_q1 = bezier_points_from_g1(D, DATA["q3"]["knots"]["a"])[3]\n'
    )
    subs = tmp_path / "subs"
    subs.mkdir()
    nbformat.write(nb, subs / "lazy.ipynb")
    out = tmp_path / "out"
    code = grade.main(
        [
            "--tests",
            str(ROOT / "solutions/hidden_tests/hw03.py"),
            "--submissions",
            str(subs),
            "--out",
            str(out),
            "--jobs",
            "1",
        ]
    )
    assert code == 0
    (row,) = json.loads((out / "results.json").read_text(encoding="utf-8"))["results"]
    points = row["points"]
    # q3 and q5 call the lazy g1_bezier_control_points in their cells: the value guard stops it
    lazy = ("q1", "q2", "q3", "q5", "q7")
    assert all(points[q] == 0 for q in lazy), row
    assert all(points[q] == p for q, p in HIDDEN["hw03"].POINTS.items() if q not in lazy), row
    assert "`answer_q1` is not defined" in row["notes"]["q1"]
    assert any(
        "bezier_points_from_g1 is the exercise of hw03.q1, hw03.q3 and hw03.q5" in n
        for n in row["run_notes"]
    ), row["run_notes"]
    assert (
        "bezier_points_from_g1 is the exercise of hw03.q2: write it yourself" in row["notes"]["q2"]
    )
    assert "knot_ratio_beta1 is the exercise of hw03.q7: write it yourself" in row["notes"]["q7"]


@pytest.mark.parametrize("hw", HOMEWORKS)
def test_the_homework_text_states_the_rule_and_what_each_function_may_use(hw):
    import nbformat

    (path,) = sorted((ROOT / "exercises").glob(f"{hw}_*.ipynb"))
    cells = [c.source for c in nbformat.read(path, as_version=4).cells if c.cell_type == "markdown"]
    flat = [" ".join(c.replace("#", " ").split()) for c in cells]
    assert "Your own work." in flat[0] and "write it yourself" in flat[0]
    for qid, exercise in own_work.EXERCISES.items():
        if qid.startswith(hw):
            (text,) = [c for c in flat if f"Question {qid.split('.q')[1]} —" in c]
            assert f"You may use:** {' '.join(exercise.may_use.split())}." in text
            for name in exercise.implementations:
                if not name.rsplit(".", 1)[1].startswith("_"):
                    assert f"`{name}`" in text


# ------------------------------------------------------------------ value questions
def _notebook_namespace(hw: str) -> dict:
    """The globals of a homework notebook after its Preparations cell."""
    ns: dict = {"__name__": f"{hw}_own_work"}
    exec(f"from course_lib.homework.checks import check, check_all\nHOMEWORK = {hw!r}\n", ns)
    return ns


@pytest.mark.parametrize(
    "qid, dotted",
    sorted((q, n) for q, e in own_work.VALUE_EXERCISES.items() for n in e.implementations),
)
def test_a_value_question_s_library_call_raises_in_its_homework(qid, dotted):
    """``answer_q1 = bezier_points_from_g1(D, knots)[3]`` in hw03 raises, in a cell, in a
    function of the notebook and through exec; the same call in another homework does not."""
    hw = qid.split(".")[0]
    module_name, name = dotted.rsplit(".", 1)
    ns = _notebook_namespace(hw)
    ns["impl"] = impl = getattr(importlib.import_module(module_name), name)
    required = [
        p
        for p in inspect.signature(impl).parameters.values()
        if p.default is p.empty and p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
    ]
    call = f"impl({', '.join(['None'] * len(required))})"
    for source in (
        call,
        f"def helper():\n    return {call}\nhelper()",
        f"exec({call!r}, {{'impl': impl}})",
    ):
        with pytest.raises(own_work.ExerciseError) as info:
            exec(source, ns)
        assert str(info.value).startswith(f"{dotted} is the exercise of ")
        assert qid in str(info.value) and str(info.value).endswith(": write it yourself")
    other = _notebook_namespace("hw00")
    other["impl"] = ns["impl"]
    with pytest.raises(Exception) as info:  # the library's own complaint about None, no guard
        exec(call, other)
    assert not isinstance(info.value, own_work.ExerciseError)


# ------------------------------------------------------------------ a tracer around the checks
RIGHT_TEXT = {"hw02.q4": "4*beta1*beta3 + 3*beta2**2", "hw03.q6": "3*(p4 - p2)/(t2 - t0)"}


def _value_questions():
    return [
        (hw, qid)
        for hw in HOMEWORKS
        for qid in questions(hw)
        if registry()[qid].answer_name.startswith("answer_")
    ]


def _numbers(obj, out: list, depth: int = 0) -> None:
    """Every float inside ``obj`` (numbers, arrays, containers, a few levels deep)."""
    if depth > 4:
        return
    if isinstance(obj, (bool, np.bool_)):
        return
    if isinstance(obj, (int, float, np.integer, np.floating)):
        out.append(float(obj))
    elif isinstance(obj, np.ndarray) and obj.dtype.kind in "if" and obj.size < 10_000:
        out.extend(float(x) for x in obj.ravel())
    elif isinstance(obj, (list, tuple)):
        for x in obj[:1000]:
            _numbers(x, out, depth + 1)
    elif isinstance(obj, dict):
        for x in list(obj.values())[:1000]:
            _numbers(x, out, depth + 1)


class Spy:
    """A generic tracer (sys.settrace and sys.setprofile): every local and return value seen."""

    def __init__(self) -> None:
        self.seen: list[float] = []

    def __call__(self, frame, event, arg):
        for value in list(frame.f_locals.values()):
            _numbers(value, self.seen)
        if event == "return":
            _numbers(arg, self.seen)
        return self


def _expected_numbers(hw: str, qid: str) -> list[float]:
    """The components of the right answer that are not already numbers of the question's data."""
    data = variants.data(hw, variants.DEFAULT)
    name = registry()[qid].answer_name
    right = HIDDEN[hw].answers_for(data)[name]
    if isinstance(right, str):
        return []  # a letter or a text: multiple choice (0 points) or symbolic (digests)
    got: list[float] = []
    _numbers(right, got)
    given: list[float] = []
    _numbers(data, given)
    return [
        x for x in got if x == x and not any(abs(x - g) <= 1e-9 * max(1, abs(x)) for g in given)
    ]


def _wrong_answer(hw: str, qid: str):
    data = variants.data(hw, variants.DEFAULT)
    right = HIDDEN[hw].answers_for(data)[registry()[qid].answer_name]
    if qid in RIGHT_TEXT:
        return "beta1 + t0"  # a symbolic answer of the wrong kind
    if isinstance(right, str):
        return "a"
    if isinstance(right, dict):
        return [np.full(np.shape(v), 0.123) for _, v in sorted(right.items())]
    return np.full(np.shape(right), 0.123) if np.ndim(right) else 0.123


def _under_spy(kind: str, run):
    """``run()`` with a :class:`Spy` installed by ``sys.settrace`` or ``sys.setprofile``:
    ``(its result, the spy)``; the spy is removed whatever happens."""
    import sys

    spy = Spy()
    install = sys.settrace if kind == "settrace" else sys.setprofile
    install(spy)
    try:
        return run(), spy
    finally:
        install(None)


@pytest.mark.parametrize("kind", ["settrace", "setprofile"])
@pytest.mark.parametrize("hw, qid", _value_questions())
def test_a_tracer_around_the_check_recovers_no_expected_value(hw, qid, kind):
    wrong = _wrong_answer(hw, qid)  # made before the tracer: it holds the right answer's shape
    verdict, spy = _under_spy(kind, lambda: check(qid, wrong))
    assert not verdict.passed and "do not run under a tracer" in verdict.message
    for x in _expected_numbers(hw, qid):
        assert not any(abs(x - s) <= 1e-9 * max(1.0, abs(x)) for s in spy.seen), (qid, x)


KEYED = [
    (hw, f"{hw}.{q}")
    for hw in HOMEWORKS
    for q in getattr(importlib.import_module(f"course_lib.homework.checks.{hw}"), "ANSWER_KEYS", {})
]


def test_the_keyed_questions_are_the_value_questions_a_check_could_only_compute():
    """hw01 q1, q4, q5, q7 and hw02 q5: the checks that used to compute their expected value."""
    assert [qid for _, qid in KEYED] == ["hw01.q1", "hw01.q4", "hw01.q5", "hw01.q7", "hw02.q5"]


@pytest.mark.parametrize("kind", ["settrace", "setprofile"])
@pytest.mark.parametrize("answer", ["wrong", "right"])
@pytest.mark.parametrize("hw, qid", KEYED)
def test_a_spy_finds_no_expected_value_even_where_the_check_lets_it_run(
    hw, qid, answer, kind, monkeypatch
):
    """With the refusal of tracers switched off (as a student can, in their own kernel), a spy
    on every frame of an answer-keyed check sees no expected value: the check holds digests."""
    monkeypatch.setattr("course_lib.homework.checks._core._gettrace", lambda: None)
    monkeypatch.setattr("course_lib.homework.checks._core._getprofile", lambda: None)
    data = variants.data(hw, HOME_CODES[hw][7])  # another student's data: keys of the test roster
    q = qid.split(".")[1]
    # held in an object the spy does not open (it sees this frame's locals too)
    kept = SimpleNamespace(right=dict(HIDDEN[hw].key_values(data)[q])["right"])
    value = np.full(np.shape(kept.right), 0.123) if answer == "wrong" else kept.right
    if qid == "hw01.q1" and answer == "wrong":
        value = np.array([0.6, 0.8])  # a unit vector: the check gets as far as the key
    try:
        verdict, spy = _under_spy(kind, lambda: check(qid, value))
    finally:
        variants.data(hw, variants.DEFAULT)
    assert verdict.passed == (answer == "right"), verdict
    if answer == "right":
        return  # the student's own value is the expected one: nothing to find
    expected = [float(x) for x in np.atleast_1d(kept.right)]
    given: list[float] = []
    _numbers(data, given)
    secret = [x for x in expected if not any(abs(x - g) <= 1e-9 * max(1, abs(x)) for g in given)]
    assert secret, "the right value is made of the question's own numbers: nothing to hide"
    for x in secret:
        assert not any(abs(x - s) <= 1e-6 * max(1.0, abs(x)) for s in spy.seen), (qid, x)


def test_the_spy_test_can_fail(monkeypatch):
    """The same spy finds the arc length in a check that computes it (hw01.q7 as it was)."""
    import math

    from course_lib.homework.checks import _core

    def computing_check(answer):  # the former check: quadrature of the speed, in place
        d = variants.current("hw01")["q7"]
        x, w = np.polynomial.legendre.leggauss(60)
        expected = float(np.sum(w * np.hypot(1.0, d["k"] * (x + 1) * d["b"])) * d["b"] / 2)
        return math.isclose(answer, expected, rel_tol=1e-6), ""

    monkeypatch.setattr(_core, "_gettrace", lambda: None)
    _, spy = _under_spy("settrace", lambda: _core.run_validate("hw01.q7", computing_check, 0.123))
    (x,) = _expected_numbers("hw01", "hw01.q7")
    assert any(abs(x - s) <= 1e-9 * abs(x) for s in spy.seen)


@pytest.mark.parametrize("qid", ["hw03.q7", "hw05.q5"])
def test_a_function_that_leaves_a_tracer_behind_is_refused(qid):
    import sys

    def answer(*args):
        sys.settrace(Spy())
        return np.zeros(3)

    try:
        verdict = check(qid, answer)
    finally:
        sys.settrace(None)
    assert not verdict.passed and "do not run under a tracer" in verdict.message


def test_no_check_module_has_a_helper_that_computes_an_answer():
    """The helpers the issue found (and their kind) are gone from the checks modules."""
    import course_lib.homework.checks.hw01 as h1
    import course_lib.homework.checks.hw02 as h2
    import course_lib.homework.checks.hw03 as h3
    import course_lib.homework.checks.hw05 as h5

    for module, name in [
        (h1, "_parabola_length"),
        (h1, "_parabola_derivatives"),
        (h1, "_c1_derivative"),
        (h2, "_chain_rule_coefficient"),
        (h2, "_values_of"),
        (h5, "_quad_end_curvatures"),
        (h5, "_bspline_polygons"),
        (h3, "bezier_points_from_g1"),
    ]:
        assert not hasattr(module, name), name


@pytest.mark.parametrize(
    "qid, text, digest_name",
    [
        ("hw02.q4", "4*beta1*beta3 + 3*beta2**2", "_Q4_RIGHT"),
        ("hw02.q4", "4*beta1*beta2 + 3*beta2**2", "_Q4_TRANSCRIBED"),
        ("hw03.q6", "3*(p4 - p2)/(t2 - t0)", "_Q6_RIGHT"),
        ("hw03.q6", "3*(t1 - t0)*(p4 - p2)/(t2 - t0)", "_Q6_LOCAL"),
    ],
)
def test_symbolic_digests_are_the_hand_derived_expressions_away_from_rounding(
    qid, text, digest_name
):
    from course_lib.homework import answers
    from course_lib.homework.checks import values_digest

    module = importlib.import_module(f"course_lib.homework.checks.{qid.split('.')[0]}")
    q = qid.split(".")[1].upper()
    symbols, points = getattr(module, f"_{q}_SYMBOLS"), getattr(module, f"_{q}_POINTS")
    _, values = answers.evaluate(text, symbols, points, "x")
    assert values_digest(qid, values) == getattr(module, digest_name)
    for v in values:  # at least 1e-3 of the 10th digit away from a rounding boundary
        mantissa = abs(complex(v).real) / 10 ** np.floor(np.log10(abs(complex(v).real)))
        frac = (mantissa * 1e9) % 1
        assert abs(frac - 0.5) > 1e-3


# ------------------------------------------------------------------ feedback and hidden cases
def _case_numbers(module) -> set[float]:
    """Every number of a hidden-test file's case lists (``Q2_CASES``, ...), except 0..10."""
    from fractions import Fraction

    out: list[float] = []

    def walk(obj):
        if isinstance(obj, (list, tuple)):
            for x in obj:
                walk(x)
        elif isinstance(obj, np.ndarray):
            out.extend(float(x) for x in obj.ravel())
        elif isinstance(obj, (int, float, Fraction)) and not isinstance(obj, bool):
            out.append(float(obj))

    for name in dir(module):
        if name.endswith("_CASES"):
            walk(getattr(module, name))
    return {x for x in out if not (x == int(x) and 0 <= x <= 10)}


@pytest.mark.parametrize("qid", sorted(own_work.EXERCISES))
def test_feedback_names_no_hidden_input(qid):
    """Wrong functions (the typical mistakes of test_answer_equivalence, and a constant) get notes
    that describe the kind of case, never its inputs or its expected value."""
    import re

    from test_answer_equivalence import TABLE

    hw = qid.split(".")[0]
    name = own_work.EXERCISES[qid].answer_name
    numbers = _case_numbers(HIDDEN[hw])

    def constant(*args):
        return np.zeros_like(np.asarray(args[0], dtype=float))

    notes = []
    for wrong in [*TABLE[qid][1], constant]:
        if callable(wrong):
            fraction, note = _grade(qid, {name: wrong})
            if fraction < 1:
                notes.append(note)
    assert notes
    for note in notes:
        note = re.sub(r"(shape|to) \([\d, ]*\)", "", note)  # an array's shape is a kind of case
        assert not re.search(r"[\(\[]\s*-?\d", note), note  # no point, vector or knot list
        assert not re.search(r"=\s*-?\d", note), note  # no "β1 = 0.7"
        for x in numbers:
            assert f"{x:g}" not in note and repr(x) not in note, (note, x)


@pytest.mark.parametrize("qid", sorted(own_work.EXERCISES))
def test_an_exception_cannot_carry_a_hidden_input_into_the_feedback(qid):
    """A function that raises with its inputs in the message (or in its class name) learns only
    the kind of exception: the red team read the hidden cases this way and resubmitted a table."""
    hw = qid.split(".")[0]
    name = own_work.EXERCISES[qid].answer_name
    numbers = _case_numbers(HIDDEN[hw])

    def leaky(*args):
        raise ValueError("IN " + repr([np.asarray(a).tolist() for a in args]))

    carrier = type("IN_" + "_".join(str(abs(int(x))) for x in sorted(numbers)[:3]), (Exception,), {})

    def leaky_class(*args):
        raise carrier("hidden")

    for func, kind in ((leaky, "ValueError"), (leaky_class, "an exception")):
        fraction, note = _grade(qid, {name: func})
        assert fraction < 1 and kind in note, note
        assert "IN " not in note and "IN_" not in note, note
        for x in numbers:
            assert repr(x) not in note, (note, x)


def test_the_red_team_one_liners_of_hw01_raise_in_hw01():
    """The three value one-liners a red team scored 6/11 with: arc-length derivatives for the
    unit tangent (q1) and the curvature (q4), the robust hodograph length for the arc (q7)."""
    ns = _notebook_namespace("hw01")
    ns.update(np=np)
    lines = {
        "hw01.q1": "from course_lib.geometry.differential_geometry import arc_length_derivatives as a\n"
        "from course_lib.curves.parametrization import ParametricCurve\nimport sympy as sp\n"
        "t = sp.Symbol('t')\n"
        "a(ParametricCurve.from_sympy([t, t**2], t, (-9, 9)), 0.5, 1)",
        "hw01.q7": "from course_lib.geometry.arc_length import robust_hodograph_length as r\n"
        "r(np.diff([[0.0, 0.0], [0.5, 0.0], [1.0, 1.0]], axis=0))",
    }
    for qid, source in lines.items():
        with pytest.raises(own_work.ExerciseError) as info:
            exec(source, ns)
        assert qid in str(info.value) or "hw01.q4" in str(info.value), str(info.value)


# ------------------------------------------------------- one-liners, and the grading page
#: Questions with points that no course_lib function computes (nothing to guard).
NO_LIBRARY_ROUTE = {
    "hw03.q6": "the closed form of the left derivative: no function of course_lib is symbolic here",
    "hw05.q5": "the phantom vertices: cubic_beta_spline is allowed, the ends are the exercise",
}


def _readme_open_to_one_liners() -> set[str]:
    import re

    text = (ROOT / "site" / "grading.md").read_text(encoding="utf-8")
    start = text.index("Open to a **one-liner**")
    part = " ".join(text[start : text.index("worth **0 points**", start)].split())
    listed, hw = set(), None
    for token in re.findall(r"hw\d\d|q\d", part):
        if token.startswith("hw"):
            hw = token
        else:
            listed.add(f"{hw}.{token}")
    return listed


def test_the_readme_lists_exactly_the_questions_open_to_one_liners():
    listed = _readme_open_to_one_liners()
    zero = {f"{hw}.{q}" for hw in HOMEWORKS for q, p in HIDDEN[hw].POINTS.items() if p == 0}
    assert listed == zero


@pytest.mark.parametrize("hw", HOMEWORKS)
def test_one_liners_score_only_the_open_points(hw):
    """A submission made only of library calls and the right answers of the open questions."""
    points, listed = HIDDEN[hw].POINTS, _readme_open_to_one_liners()
    right = HIDDEN[hw].answers_for(variants.data(hw, variants.DEFAULT))
    ns = _notebook_namespace(hw)
    for q in points:
        qid = f"{hw}.{q}"
        name = registry()[qid].answer_name
        if qid in listed:
            ns[name] = right[name]  # a one-liner finds it: it is worth nothing
        elif qid in LAZY:
            ns[name] = _lazy(qid, "direct")
        elif qid in own_work.VALUE_EXERCISES:
            for dotted in own_work.VALUE_EXERCISES[qid].implementations:
                module_name, attr = dotted.rsplit(".", 1)
                ns["impl"] = impl = getattr(importlib.import_module(module_name), attr)
                n = sum(
                    p.default is p.empty and p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)
                    for p in inspect.signature(impl).parameters.values()
                )
                with pytest.raises(own_work.ExerciseError):
                    exec(f"{name} = impl({', '.join(['None'] * n)})", ns)
        else:
            assert qid in NO_LIBRARY_ROUTE, f"{qid}: how would a one-liner answer it?"
    earned = sum(p * _grade(f"{hw}.{q}", ns)[0] for q, p in points.items())
    assert earned <= sum(p for q, p in points.items() if f"{hw}.{q}" in listed) == 0


# ------------------------------------------------------------------ a friend's notebook
@pytest.mark.parametrize("hw", HOMEWORKS)
def test_a_friends_notebook_scores_at_most_a_quarter(hw):
    """The solution done with Ada's code, graded as Sophie's (her data): at most 25 % of the
    points -- the data questions are Ada's numbers, and the questions that are the same for
    everyone earn nothing in a notebook not done on one's own data."""
    home = VariantHomework(hw)
    points = home.hidden.POINTS
    for ada, sophie in [(home.codes[0], home.codes[1]), (home.codes[2], home.codes[3])]:
        ns = home.solution_namespace(ada)
        data = variants.data(hw, sophie)
        notes = {}
        earned = 0.0
        for q, p in points.items():
            fraction, notes[q] = home.grade(q, ns, data)
            earned += fraction * p
        assert earned <= 0.25 * sum(points.values()), (hw, earned, notes)
        for qid in own_work.EXERCISES:
            if qid.startswith(hw):
                assert "not done on your own data" in notes[qid.split(".")[1]]
        # and on her own data the same notebook would have earned everything
        assert all(home.grade(q, ns, variants.data(hw, ada))[0] == 1.0 for q in points)
    variants.data(hw, variants.DEFAULT)


@pytest.mark.parametrize("how", ["require", "module", "code"])
def test_a_guard_switched_off_by_rebinding_costs_the_question(how, monkeypatch):
    """The obvious ways to switch the guard off before the check, each one assignment."""
    from course_lib.constructions import knot_splines

    if how == "require":
        monkeypatch.setattr(own_work, "require", lambda *a: None)
    elif how == "module":
        monkeypatch.setattr(knot_splines, "own_work", type("Fake", (), {"require": print}))
    else:

        def unguarded(knots):
            h = np.diff(np.asarray(knots, dtype=float))
            return h[1:] / h[:-1]

        monkeypatch.setattr(knot_splines.knot_ratio_beta1, "__code__", unguarded.__code__)
    answer = knot_splines.knot_ratio_beta1
    verdict = check("hw03.q7", answer)
    assert not verdict.passed and "guard of hw03.q7 was switched off" in verdict.message
    fraction, note = _grade("hw03.q7", {"knot_ratio_beta1": answer})
    assert fraction == 0 and "guard of hw03.q7 was switched off" in note


# ------------------------------------------------------------ one marker: ExerciseError's type


def test_the_exercise_travels_as_a_flag_not_as_a_sentence():
    """The check, the probe and the grader recognise ExerciseError by its type and fields: a
    student's exception that copies the sentence is an exception like any other."""
    from course_lib.constructions.knot_splines import knot_ratio_beta1
    from course_lib.homework import protocol as _probe
    from course_lib.homework.checks._core import AnswerProblem, call_answer

    sentence = own_work.exercise_message("course_lib.constructions.knot_splines.knot_ratio_beta1", "hw03.q7")

    def mimic(knots):
        raise RuntimeError(sentence)

    # the probe: kind "exercise" with the fields, for the library's guard only
    response = _probe.handle({"op": "call", "name": "knot_ratio_beta1", "args": [[0, 1, 3]]},
                             {"knot_ratio_beta1": knot_ratio_beta1})  # fmt: skip
    assert response["error"] == "exercise" and response["question"] == "hw03.q7"
    assert response["implementation"] == "course_lib.constructions.knot_splines.knot_ratio_beta1"
    response = _probe.handle({"op": "call", "name": "knot_ratio_beta1", "args": [[0, 1, 3]]},
                             {"knot_ratio_beta1": mimic})  # fmt: skip
    assert response["error"] == "raised"
    # the grader: the sentence for the library, the type only for the mimic
    assert sentence in _grade("hw03.q7", {"knot_ratio_beta1": knot_ratio_beta1})[1]
    fraction, note = _grade("hw03.q7", {"knot_ratio_beta1": mimic})
    assert fraction == 0 and sentence not in note and "RuntimeError" in note
    # the check: AnswerProblem.exercise
    with pytest.raises(AnswerProblem) as info:
        call_answer(knot_ratio_beta1, np.array([0.0, 1.0, 3.0]), name="knot_ratio_beta1")
    assert info.value.exercise and info.value.message == sentence + "."
    with pytest.raises(AnswerProblem) as info:
        call_answer(mimic, np.array([0.0, 1.0, 3.0]), name="knot_ratio_beta1")
    assert not info.value.exercise


def test_hw03_q2_passes_the_exercise_on_by_its_flag():
    """hw03.q2's check prefixes a failing case's knots -- but not to the own-work sentence."""
    from course_lib.constructions.knot_splines import bezier_points_from_g1

    sentence = own_work.exercise_message("course_lib.constructions.knot_splines.bezier_points_from_g1", "hw03.q2")
    assert check("hw03.q2", bezier_points_from_g1).message == sentence + "."

    def mimic(d, knots):
        raise RuntimeError(sentence)

    message = check("hw03.q2", mimic).message
    assert message.startswith("with knots") and "RuntimeError" in message


def test_a_forged_exercise_response_gets_no_sentence():
    """The sentence is written by the grader from registered fields, never from the response."""
    from tools.grading.protocol import StudentRaised, parse_response

    def forged(**fields):
        return json.dumps({"ok": False, "error": "exercise", "message": "anything", **fields})

    with pytest.raises(StudentRaised) as info:
        parse_response(forged(question="hw03.q7", implementation="course_lib.constructions.knot_splines.knot_ratio_beta1"))
    assert info.value.exercise and "is the exercise of hw03.q7" in str(info.value)
    value = "course_lib.constructions.knot_splines.bezier_points_from_g1 is the exercise of hw03.q1, hw03.q3"
    with pytest.raises(StudentRaised) as info:
        parse_response(forged(question="hw03.q1, hw03.q3 and hw03.q5",
                              implementation="course_lib.constructions.knot_splines.bezier_points_from_g1"))
    assert value in str(info.value)
    for fields in ({"question": "hw03.q7", "implementation": "course_lib.curves.bezier.anything"},
                   {"question": "hw03.q1 and hw01.q1",
                    "implementation": "course_lib.constructions.knot_splines.bezier_points_from_g1"},
                   {"question": "hw99.q1", "implementation": "x"}, {}):  # fmt: skip
        with pytest.raises(StudentRaised) as info:
            parse_response(forged(**fields))
        assert "exercise of" not in str(info.value) and "anything" not in str(info.value)


def test_an_exercise_error_crosses_processes_with_its_fields():
    import pickle

    err = own_work.ExerciseError("course_lib.constructions.knot_splines.knot_ratio_beta1", "hw03.q7", True)
    back = pickle.loads(pickle.dumps(err))
    assert (back.implementation, back.question, back.switched_off) == (
        err.implementation, err.question, True)  # fmt: skip
    assert str(back) == str(err) and "switched off" in str(back)


# ------------------------------------------------------------ the grader's state file


@pytest.fixture
def graded_state(tmp_path, monkeypatch):
    """This process as if in the grader's sandbox: the state file (normally bind-mounted
    read-only at own_work.GRADER_STATE_FILE) at a path of the test's own."""
    state = tmp_path / "grading"
    state.write_text(own_work.grader_state_text("hw03"))
    monkeypatch.setattr(own_work, "GRADER_STATE_FILE", str(state))
    monkeypatch.setattr(own_work, "_GRADED", True)
    monkeypatch.setenv(own_work.ENV_VAR, "")
    return state


def test_the_grader_s_state_guards_whatever_the_kernel_cleared(graded_state):
    """No frame of the probe, no list, no environment, no HOMEWORK: the file decides."""
    from course_lib.constructions.knot_splines import bezier_points_from_g1, knot_ratio_beta1

    D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0]], dtype=float)
    assert knot_ratio_beta1(np.array([0.0, 1.0, 3.0])) is not None  # between requests: free
    with pytest.raises(own_work.ExerciseError) as info:  # hw03.q1's value, HOMEWORK or not
        bezier_points_from_g1(D, [0.0, 1.0, 3.0])
    assert info.value.question.startswith("hw03.q1")  # hw03.q1, hw03.q3 and hw03.q5
    graded_state.write_text(own_work.grader_state_text("hw03", ("hw03.q7",)))  # a request
    own_work._ACTIVE.clear()
    with pytest.raises(own_work.ExerciseError) as info:
        knot_ratio_beta1(np.array([0.0, 1.0, 3.0]))
    assert (info.value.question, info.value.implementation) == (
        "hw03.q7", "course_lib.constructions.knot_splines.knot_ratio_beta1")  # fmt: skip
    graded_state.write_text(own_work.grader_state_text("hw04"))  # another homework: free
    assert bezier_points_from_g1(D, [0.0, 1.0, 3.0]) is not None
    graded_state.unlink()  # unreadable: every guarded implementation refuses
    with pytest.raises(own_work.ExerciseError):
        knot_ratio_beta1(np.array([0.0, 1.0, 3.0]))


def test_switching_the_state_file_off_in_the_kernel_costs_the_question(graded_state, monkeypatch):
    from course_lib.constructions.knot_splines import knot_ratio_beta1

    monkeypatch.setattr(own_work, "_GRADED", False)
    fraction, note = _grade("hw03.q7", {"knot_ratio_beta1": knot_ratio_beta1})
    assert fraction == 0 and "guard of hw03.q7 was switched off" in note


def test_the_state_text_is_one_line_per_name():
    assert own_work.grader_state_text("hw03", ("hw03.q7",)) == "hw03\nhw03.q7\n"
    with pytest.raises(ValueError, match="questions"):
        own_work.grader_state_text("hw03", ("hw03.q7\nhw03.q2",))


def test_the_sandbox_shows_the_state_file_read_only(tmp_path):
    from tools.grading import sandbox

    if sandbox.bwrap_path() is None:
        pytest.skip("bubblewrap is not installed")
    job = tmp_path / "job-x"
    job.mkdir()
    assert own_work.GRADER_STATE_FILE not in sandbox.bwrap_argv(job)
    sandbox.grader_state_path(job).write_text(own_work.grader_state_text("hw03"))
    argv = sandbox.bwrap_argv(job)
    i = argv.index(own_work.GRADER_STATE_FILE)
    assert argv[i - 2 : i] == ["--ro-bind", str(sandbox.grader_state_path(job))]
    assert job not in sandbox.grader_state_path(job).parents  # not in the writable job folder


def test_the_grading_page_lists_exactly_the_values_open_to_another_tool():
    """Every value question with points, and its total, is in the "types the number in" list."""
    import re

    text = " ".join((ROOT / "site" / "grading.md").read_text(encoding="utf-8").split())
    start = text.index("Open to a student who **computes a value somewhere else")
    part = text[start : text.index("points)", start)]
    listed, hw = set(), None
    for token in re.findall(r"hw\d\d|q\d", part):
        if token.startswith("hw"):
            hw = token
        else:
            listed.add(f"{hw}.{token}")
    values = {
        f"{hw}.{q}"
        for hw in HOMEWORKS
        for q, p in HIDDEN[hw].POINTS.items()
        if p > 0 and registry()[f"{hw}.{q}"].answer_name.startswith("answer_")
    }
    assert listed == values
    total = sum(HIDDEN[qid.split(".")[0]].POINTS[qid.split(".")[1]] for qid in values)
    course = sum(sum(HIDDEN[hw].POINTS.values()) for hw in HOMEWORKS)
    assert f"({total:g} of {course:g} points)" in text
