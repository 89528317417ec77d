"""``tools/variant.py``: the course secret, the codes for the LMS, a student's data and answers."""

from __future__ import annotations

import ast
import csv
import io
import stat
from pathlib import Path

import numpy as np
import pytest

from course_lib.homework import variants
from tools import variant as tool

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(autouse=True)
def _default_afterwards():
    yield
    variants.data("hw01", variants.DEFAULT)
    variants.data("hw02", variants.DEFAULT)
    variants.data("hw04", variants.DEFAULT)


@pytest.fixture
def secret(tmp_path):
    path = tmp_path / "course_secret.txt"
    assert tool.main(["secret", "--out", str(path)]) == 0
    return path


def test_secret_is_private_random_and_never_overwritten(secret, tmp_path, capsys):
    assert stat.S_IMODE(secret.stat().st_mode) == 0o600
    text = secret.read_bytes()
    assert len(text.strip()) >= 40
    with pytest.raises(SystemExit, match="not overwritten"):
        tool.main(["secret", "--out", str(secret)])
    assert secret.read_bytes() == text
    other = tmp_path / "other.txt"
    tool.main(["secret", "--out", str(other)])
    assert other.read_bytes() != text


def test_codes_for_the_lms_are_the_codes_the_grader_computes(secret, tmp_path, capsys):
    roster = tmp_path / "roster.csv"
    roster.write_text(
        'id,submission,name,email\n1001,s001,"Lovelace, Ada",ada@example.org\n1002,s002,Emmy,e@example.org\n',
        encoding="utf-8",
    )
    capsys.readouterr()
    assert tool.main(["codes", "hw01", "--secret-file", str(secret), "--roster", str(roster)]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    key = secret.read_bytes().strip()
    assert [r["id"] for r in rows] == ["1001", "1002"] and rows[0]["name"] == "Lovelace, Ada"
    assert rows[0]["code"] == variants.code_for(key, "hw01", "1001")  # by the LMS id
    assert rows[0]["code"] != rows[1]["code"]
    out = tmp_path / "codes.csv"
    tool.main(["codes", "hw01", "--secret-file", str(secret), "--roster", str(roster), "--out", str(out)])
    assert list(csv.DictReader(out.open(encoding="utf-8"))) == rows
    with pytest.raises(SystemExit, match="hw99 has no variants"):
        tool.main(["codes", "hw99", "--secret-file", str(secret), "--roster", str(roster)])
    short = tmp_path / "short.txt"
    short.write_text("abc")
    with pytest.raises(SystemExit, match="too short"):
        tool.main(["codes", "hw01", "--secret-file", str(short), "--roster", str(roster)])


def _show(secret, capsys, hw: str) -> tuple[str, dict, dict[str, str]]:
    """``variant.py show hw 1001``: its text, the student's data and the worked answers' text."""
    capsys.readouterr()
    assert tool.main(["show", hw, "1001", "--secret-file", str(secret)]) == 0
    text = capsys.readouterr().out
    code = variants.code_for(secret.read_bytes().strip(), hw, "1001")
    data = variants.data(hw, code)
    variants.data(hw, variants.DEFAULT)
    assert f"VARIANT = {code!r}" in text  # the line the student pastes
    worked = {}
    for line in text.splitlines():
        name, sep, value = line.strip().partition(" = ")
        if sep and name.startswith("answer_"):
            worked[name] = value.strip()
    return text, data, worked


def test_show_prints_the_students_data_and_worked_answers(secret, capsys):
    text, data, worked = _show(secret, capsys, "hw01")
    assert data["q1"]["text"] in text and data["q5"]["text"] in text
    assert "Worked answers:" in text and "answer_q7 = " in text
    # the worked unit tangent is the one of the student's curve: c'(t0) normalized, by hand
    d = data["q1"]
    t = d["t"]
    c1 = np.array([d["x"][1] + 2 * d["x"][2] * t, d["y"][1] + 3 * d["y"][3] * t * t])
    got = np.array(ast.literal_eval(worked["answer_q1"]))
    assert np.allclose(got, c1 / np.linalg.norm(c1))


def test_show_works_for_hw02_too(secret, capsys):
    text, data, worked = _show(secret, capsys, "hw02")
    assert data["q2"]["text"] in text
    # the worked β1 is the student's: r'(0) = β1 q'(1), read off the first coordinate by hand
    d = data["q1"]
    assert float(worked["answer_q1"]) == pytest.approx(d["r1"][0] / d["q1"][0])
    letter = worked["answer_q6"].strip("'")
    assert "C²" in data["q6"]["options"][letter]


def test_show_works_for_hw04_too(secret, capsys):
    text, data, worked = _show(secret, capsys, "hw04")
    assert data["q3"]["text"] in text and data["q6"]["text"].splitlines()[0] in text
    # the worked W1 is the student's: V_d + β1 (V_d − V_{d−1}), by hand
    d = data["q1"]
    got = np.array(ast.literal_eval(worked["answer_q1"]))
    assert np.allclose(got, np.add(d["V_d"], d["beta1"] * np.subtract(d["V_d"], d["V_dm1"])))
    letter = worked["answer_q6"].strip("'")
    assert "B-spline" in data["q6"]["options"][letter]


def test_show_works_for_hw05_too(secret, capsys):
    text, data, worked = _show(secret, capsys, "hw05")
    assert data["glyph"]["text"] in text and data["q3"]["text"] in text and data["q6"]["text"] in text
    # the worked letter names the option that gives the right reason in the student's order
    letter = worked["answer_q4"].strip("'")
    assert data["q4"]["options"][letter].startswith("at each of them the chord P0P2")
    # the worked curvatures are the student's: (B - A) x q''(1) / |B - A|³ in em, by hand
    P0, A, B, _ = np.array(data["q3"]["points"]) / data["q3"]["em"]
    v, M = B - A, (A + B) / 2
    a = 2 * (P0 - 2 * A + M)
    got = ast.literal_eval(worked["answer_q3"])
    assert got[0] == pytest.approx((v[0] * a[1] - v[1] * a[0]) / np.linalg.norm(v) ** 3)


def test_variants_find_each_generator_in_its_checks_module_by_name():
    """No registration by import: ``generate`` lives beside the checks of its homework and
    ``variants`` looks it up there by the homework's name."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "from course_lib.homework import variants\n"
        "before = 'course_lib.homework.checks.hw01' in sys.modules\n"
        "from course_lib.homework.checks import hw01\n"
        "print(before, variants.generator('hw01') is hw01.generate, variants.generator('hw99'),"
        " variants.generator('lectures'), sorted(variants.generators())[:2])\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "True", "None", "None", "['hw01',", "'hw02']"]


def test_a_new_instructors_folders_and_typos_get_one_sentence(tmp_path):
    """The semester page suggests ``~/teaching/2026/course_secret.txt``: a folder that does not
    exist yet is made (private); a roster that is not there is one sentence, not a traceback."""
    secret = tmp_path / "teaching" / "2026" / "course_secret.txt"
    assert tool.main(["secret", "--out", str(secret)]) == 0
    assert stat.S_IMODE(secret.parent.stat().st_mode) == 0o700
    assert stat.S_IMODE(secret.stat().st_mode) == 0o600
    with pytest.raises(SystemExit) as stop:
        tool.main(["codes", "hw01", "--secret-file", str(secret), "--roster", str(tmp_path / "nope.csv")])
    assert str(stop.value) == f"--roster {tmp_path / 'nope.csv'}: No such file or directory"
