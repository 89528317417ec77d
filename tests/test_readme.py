"""The README is a door and the course's pages keep their promises.

The README (a few screens) links the guides, Markdown pages in ``site/`` that are also pages
of the website (``tools/build_site.py``, ``GUIDES``).  Here: every relative link of the README
and the guides resolves in the repository, anchors included (as GitHub renders them); every
guide is on the site; the figure table cites cells that exist and lists every figure of the
sources; every dependency is justified; the README's two commands are what CI and ``make lab``
run.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
import tomllib
from _homework_support import load

ROOT = Path(__file__).resolve().parents[1]
README = (ROOT / "README.md").read_text(encoding="utf-8")
GUIDE_FILES = sorted((ROOT / "site").glob("*.md"))
FIGURES = (ROOT / "site" / "figures.md").read_text(encoding="utf-8")
LINK = re.compile(r"(?<!!)\[((?:[^\[\]]|\[[^\]]*\])*)\]\(([^)\s]+)\)")

build_site = load("build_site_links", ROOT / "tools" / "build_site.py")


def _prose(text: str) -> str:
    """Markdown without fenced blocks and code spans (a link inside them is not a link)."""
    text = re.sub(r"^```.*?^```", "", text, flags=re.M | re.S)
    return re.sub(r"`[^`\n]*`", "code", text)


def _slug(heading: str) -> str:
    """The anchor GitHub (and MyST's ``myst_heading_anchors``) gives a heading."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link: its text
    text = re.sub(r"[`*_]{1,2}(?=\S)|(?<=\S)[`*_]{1,2}", "", text).strip().lower()
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def anchors(path: Path) -> set[str]:
    out, seen = set(), {}
    for line in _fence_free_lines(path.read_text(encoding="utf-8")):
        m = re.match(r"#{1,6} (.+?)\s*#*$", line)
        if m:
            slug = _slug(m.group(1))
            n = seen.get(slug, 0)
            out.add(slug if n == 0 else f"{slug}-{n}")
            seen[slug] = n + 1
    return out


def _fence_free_lines(text: str) -> list[str]:
    return re.sub(r"^```.*?^```", "", text, flags=re.M | re.S).splitlines()


def broken_links(path: Path) -> list[str]:
    """Relative links of a Markdown file that do not resolve to a file or a heading."""
    broken = []
    for _label, target in LINK.findall(_prose(path.read_text(encoding="utf-8"))):
        if re.match(r"[a-z]+:", target):
            continue
        file, _, frag = target.partition("#")
        dest = (path.parent / file).resolve() if file else path
        if not dest.exists():
            broken.append(f"{target} (no such file)")
        elif frag and dest.suffix == ".md" and frag not in anchors(dest):
            broken.append(f"{target} (no such heading in {dest.name})")
    return broken


# ------------------------------------------------------------------------------ the door
def test_the_readme_fits_on_a_few_screens():
    assert len(README.splitlines()) <= 250


@pytest.mark.parametrize(
    "path",
    [ROOT / "README.md", ROOT / "CONTRIBUTING.md", *GUIDE_FILES],
    ids=lambda p: str(p.relative_to(ROOT)),
)
def test_every_relative_link_resolves(path):
    assert broken_links(path) == []


def test_the_link_checker_can_fail(tmp_path):
    (tmp_path / "a.md").write_text("# Title\n\n## A section: with `code`\n", encoding="utf-8")
    page = tmp_path / "b.md"
    page.write_text(
        "[ok](a.md#a-section-with-code) [ok](a.md) [gone](c.md) [no heading](a.md#nowhere) "
        "`[in code](c.md)` [web](https://example.org)\n",
        encoding="utf-8",
    )
    assert broken_links(page) == ["c.md (no such file)", "a.md#nowhere (no such heading in a.md)"]


def test_every_guide_is_on_the_site_and_linked_from_the_readme():
    listed = [name for _, names in build_site.GUIDES for name in names]
    assert sorted(listed) == sorted(p.stem for p in GUIDE_FILES)
    linked = {Path(t.partition("#")[0]).as_posix() for _, t in LINK.findall(_prose(README))}
    assert {f"site/{name}.md" for name in listed} <= linked


def test_guides_link_notebooks_to_their_pages_and_other_files_by_name():
    docs = {"01_a": "lectures/01_a", "hw01_a": "homework/hw01_a"}
    text = (
        "[lecture](../notebooks/01_a.ipynb#sec) [hw](../exercises/hw01_a.ipynb) "
        "[grading](grading.md#limits) [code](../CONTRIBUTING.md#tests) [web](https://x.org)\n"
        "| 000 Fig. 1 — a joint | 01 | §2 (`c1`, `zz`) |\n"
    )
    page = build_site.guide_page("figures", text, docs, {"01_a": {"c1"}})
    assert "[lecture](lectures/01_a.ipynb#sec)" in page
    assert "[hw](homework/hw01_a.ipynb)" in page
    assert "[grading](grading.md#limits)" in page and "[web](https://x.org)" in page
    assert " code " in page and "CONTRIBUTING" not in page
    assert "{doc}`01 </lectures/01_a>`" in page and "{ref}`c1 <cell-c1>`" in page
    assert "`zz`" in page, "a cell id the notebook does not have stays text"


def test_readme_links_on_the_site_point_at_pages_or_keep_their_text():
    docs = {"01_a": "lectures/01_a"}
    text = build_site.link_notebooks(
        "[`01_a`](notebooks/01_a.ipynb) [grading](site/grading.md#limits) "
        "[contributing](CONTRIBUTING.md) [folder](site/) [web](https://x.org)",
        docs,
    )
    assert text == (
        "{doc}`01_a </lectures/01_a>` [grading](grading.md#limits) contributing folder "
        "[web](https://x.org)"
    )


# ------------------------------------------------------------------- the figure table
def _cell_ids(nb: str) -> set[str]:
    path = next((ROOT / "notebooks").glob(f"{nb}_*.ipynb"))
    return {c.get("id") for c in json.loads(path.read_text())["cells"]}


def test_figure_table_points_at_existing_cells():
    rows = [line for line in FIGURES.splitlines() if re.match(r"\| (000|001|004) Fig", line)]
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
    for src, figs in re.findall(r"^\| (000|001|004) Figs?\. ([\d, ()ab]+)", FIGURES, re.M):
        listed |= {(src, int(n)) for n in re.findall(r"\d+", figs)}
    assert expected <= listed, sorted(expected - listed)


# ------------------------------------------------------------------------ dependencies
def test_every_dependency_is_justified():
    pyproject = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    names = [*pyproject["dependencies"], *pyproject["optional-dependencies"]["test"]]
    names = {re.split(r"[<>=!~\[; ]", n, maxsplit=1)[0].lower() for n in names}
    page = (ROOT / "site" / "dependencies.md").read_text(encoding="utf-8")
    justified = set()
    for row in re.findall(r"^\| ([^|]+) \| (.+) \|$", page, re.M):
        if row[1].strip("- ") and row[0] != "package":
            justified |= {n.strip().lower() for n in re.sub(r"\(.*?\)", "", row[0]).split(",")}
    assert names <= justified, sorted(names - justified)


# --------------------------------------------------------------------------- commands
def test_ci_runs_exactly_the_readme_test_command():
    assert "$ make test\n" in README
    assert "make test" in (ROOT / ".ci" / "run").read_text()


def test_make_lab_opens_the_welcome_notebook_with_the_whole_course_served():
    import shutil
    import subprocess

    assert "$ make lab\n" in README
    if shutil.which("make") is None:
        pytest.skip("make is not installed")
    out = subprocess.run(
        ["make", "-n", "-o", ".venv/.installed", "lab"], cwd=ROOT, capture_output=True, text=True
    ).stdout
    line = next(x for x in out.splitlines() if "jupyter lab" in x)
    assert f"--ServerApp.root_dir={ROOT}" in line  # exercises/ reachable from the file browser
    assert line.split()[-1] == "notebooks/00_welcome.ipynb"
    assert (ROOT / "notebooks" / "00_welcome.ipynb").is_file()
