"""The README's promises are kept: links, figure table cell ids, commands."""

from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text()


def _cell_ids(nb: str) -> set[str]:
    path = next((ROOT / "notebooks").glob(f"{nb}_*.ipynb"))
    return {c.get("id") for c in json.loads(path.read_text())["cells"]}


def test_figure_table_points_at_existing_cells():
    rows = [line for line in README.splitlines() if re.match(r"\| (000|001|004) Fig", line)]
    assert len(rows) >= 20
    for row in rows:
        cols = [c.strip() for c in row.strip("|").split("|")]
        ids = re.findall(r"`([\w-]+)`", cols[2])
        assert ids, row
        assert set(ids) <= _cell_ids(cols[1]), f"missing cell ids in notebook {cols[1]}: {row}"


def test_every_seed_figure_is_listed():
    expected = {("000", n) for n in range(1, 12)} | {("001", n) for n in range(1, 9)}
    expected |= {("004", n) for n in range(1, 9)}
    listed = set()
    for src, figs in re.findall(r"^\| (000|001|004) Figs?\. ([\d, ()ab]+)", README, re.M):
        listed |= {(src, int(n)) for n in re.findall(r"\d+", figs)}
    assert expected <= listed, sorted(expected - listed)


def test_relative_links_exist():
    for link in re.findall(r"\]\(((?!https?:)[^)#]+)\)", README):
        assert (ROOT / link).exists(), link


def test_ci_runs_exactly_the_readme_test_command():
    assert "make test" in README
    assert "make test" in (ROOT / ".ci" / "run").read_text()


def test_make_lab_opens_the_welcome_notebook_with_the_whole_course_served():
    import shutil
    import subprocess

    if shutil.which("make") is None:
        import pytest

        pytest.skip("make is not installed")
    out = subprocess.run(
        ["make", "-n", "-o", ".venv/.installed", "lab"], cwd=ROOT, capture_output=True, text=True
    ).stdout
    line = next(x for x in out.splitlines() if "jupyter lab" in x)
    assert f"--ServerApp.root_dir={ROOT}" in line  # exercises/ reachable from the file browser
    assert line.split()[-1] == "notebooks/00_welcome.ipynb"
    assert (ROOT / "notebooks" / "00_welcome.ipynb").is_file()
