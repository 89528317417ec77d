"""Build the course website: ``python tools/build_site.py`` (``make site``) -> ``build/site/``.

Sphinx + MyST-NB render every lecture (``notebooks/``) and every blank homework
(``exercises/``) with outputs, math, figures, navigation and search.  Nothing is edited in
the repository; the build works on copies in ``build/site-src/``:

1. **Execute** each notebook with nbclient in a kernel whose private ``IPYTHONDIR`` runs
   ``site/kernel_startup.py``: every live demo draws its static fallback (``static=True``)
   and ``%matplotlib widget`` becomes ``inline``.  Executed copies are cached in
   ``build/site-cache/`` under a hash of the notebook, ``course_lib/`` and this build, so an
   unchanged notebook is never executed twice.  Two notebooks run at a time (2 cores).
2. **Prepare** the copies: cells tagged ``evidence`` (or with ``jupyter.source_hidden``, as
   JupyterLab shows them) get MyST-NB's ``hide-input`` tag, i.e. collapsed like in
   JupyterLab; ``jupyter.outputs_hidden`` gives ``hide-output``; each cell id becomes an
   anchor ``cell-<id>``; after each demo a note says how to run it live.
3. **Pages**: the course map (``course.md``: the README's lecture and homework tables, their
   links pointing into the pages) and the guides, the Markdown pages of ``site/`` listed in
   ``GUIDES`` (teaching, grading, accessibility, ...).  In a guide, a link to a notebook on the
   site points at its page, a link to another file of the repository keeps its text only (the
   site has no such page), and the figure table's cell ids and the errors table's
   "notebook NN" link into the lectures.
4. **Sphinx** (``sphinx-build -b html``, no execution) with MathJax served from
   ``_static/mathjax`` (the ``jupyter-server-mathjax`` package): no CDN, no network.

Never read: ``solutions/``, ``tools/homework_src/``, ``solutions/hidden_tests/``.

Options: ``--only 01_parametric_continuity`` (repeatable; a partial site, for quick checks and
tests), ``--out DIR``, ``--no-cache``, ``--jobs N``.
"""

from __future__ import annotations

import argparse
import concurrent.futures as cf
import copy
import hashlib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from course_lib.figure_alt import CAPTION_PREFIX, cell_alt

ROOT = Path(__file__).resolve().parents[1]

SITE_CONF = ROOT / "site"
BUILD = ROOT / "build"
DEFAULT_OUT = BUILD / "site"
CACHE = BUILD / "site-cache"

#: The guides: Markdown pages of site/ (written for GitHub: their relative links resolve in the
#: repository), in the site's navigation under these captions, in this order.
GUIDES: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("For students", ("homework",)),
    ("For lecturers", ("teaching", "figures", "sources-errata")),
    ("For instructors", ("student-edition", "semester", "grading")),
    ("About the course", ("accessibility", "performance")),
    ("For contributors", ("developing", "api", "dependencies")),
)
#: (folder in the repository, folder on the site, glob).  Never solutions/.
SOURCES = (("notebooks", "lectures", "[0-9][0-9]_*.ipynb"), ("exercises", "homework", "hw*.ipynb"))
FORBIDDEN = ("solutions", "homework_src", "hidden_tests")
BUILD_VERSION = "1"  # bump to invalidate the execution cache
CELL_TIMEOUT = 180
DEMO_CALL = re.compile(r"\b\w+_demo\s*\(")
WIDGET_MAGIC = re.compile(r"^%matplotlib\s+(widget|ipympl)\b", re.M)
#: a cell that checks the live widgets (sliders, canvas) cannot pass with static demos: its
#: error is dropped and the page says that it runs live (any other error fails the build)
LIVE_ONLY = re.compile(r"\.controls\b|\.widget\b|\bcanvas\b|ipympl|ipywidgets")
LIVE_CHECK_NOTE = (
    "```{admonition} Checked live\n:class: note live-demo\n"
    "The cell above checks the live widgets (sliders, canvas); it runs in JupyterLab, "
    "not on this static page.\n```"
)
LIVE_NOTE = (
    "```{{admonition}} Live demo\n:class: tip live-demo\n"
    "This picture is static. Live, it is interactive (sliders, draggable points, rotation): "
    "run `make lab` and open `{path}` in JupyterLab, or show it as an app without code "
    "cells: `.venv/bin/voila {path}`.\n```"
)


# --------------------------------------------------------------------------- sources
def source_notebooks(only: list[str] | None = None) -> list[tuple[Path, str]]:
    """(notebook, site document name) for every lecture and blank homework."""
    out = []
    for folder, target, pattern in SOURCES:
        for path in sorted((ROOT / folder).glob(pattern)):
            if only and path.stem not in only:
                continue
            assert not any(part in FORBIDDEN for part in path.relative_to(ROOT).parts)
            out.append((path, f"{target}/{path.stem}"))
    return out


def _repo_path(path: Path) -> str:
    return str(path.relative_to(ROOT)) if path.is_relative_to(ROOT) else path.name


def _tree_hash() -> str:
    h = hashlib.sha256(BUILD_VERSION.encode())
    for path in sorted((ROOT / "course_lib").rglob("*.py")):
        h.update(str(path.relative_to(ROOT)).encode())
        h.update(path.read_bytes())
    h.update((SITE_CONF / "kernel_startup.py").read_bytes())
    return h.hexdigest()


def _notebook_key(nb: dict, tree: str) -> str:
    cells = [(c["cell_type"], "".join(c["source"])) for c in nb["cells"]]
    return hashlib.sha256(json.dumps([tree, cells]).encode()).hexdigest()[:20]


# ------------------------------------------------------------------------- execution
def _kernel_env() -> dict[str, str]:
    ipdir = Path(tempfile.mkdtemp(prefix="site-ipython-"))
    startup = ipdir / "profile_default" / "startup"
    startup.mkdir(parents=True)
    shutil.copy(SITE_CONF / "kernel_startup.py", startup / "00-course-static-build.py")
    env = dict(os.environ)
    env["IPYTHONDIR"] = str(ipdir)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(ROOT), env.get("PYTHONPATH")]))
    env["MPLBACKEND"] = "module://matplotlib_inline.backend_inline"
    env.pop("JPY_PARENT_PID", None)
    return env


def execute_notebook(src: str, dst: str, cwd: str, env: dict[str, str]) -> float:
    """Execute ``src`` into ``dst`` (a worker process); returns seconds."""
    import nbformat
    from nbclient import NotebookClient

    os.environ.clear()
    os.environ.update(env)
    t0 = time.perf_counter()
    nb = nbformat.read(src, as_version=4)
    client = NotebookClient(
        nb,
        timeout=CELL_TIMEOUT,
        kernel_name="python3",
        resources={"metadata": {"path": cwd}},
        allow_errors=True,  # judged below: only checks of the live widgets may fail
    )
    client.execute()
    for cell in nb.cells:
        errors = [o for o in cell.get("outputs", []) if o.get("output_type") == "error"]
        if not errors:
            continue
        if not LIVE_ONLY.search(cell.source):
            raise RuntimeError(
                f"{src}: cell {cell.get('id')} raised {errors[0].get('ename')}: "
                f"{errors[0].get('evalue')}\n{cell.source}"
            )
        cell.outputs = [o for o in cell.outputs if o.get("output_type") != "error"]
        cell.metadata["course_live_only"] = True
    Path(dst).parent.mkdir(parents=True, exist_ok=True)
    # a private temporary name, then an atomic rename: two builds sharing build/site-cache/
    # (the test run's two workers) may execute the same notebook at the same time
    tmp = Path(dst).with_suffix(f".{os.getpid()}.tmp")
    nbformat.write(nb, str(tmp))
    tmp.replace(dst)
    return time.perf_counter() - t0


def execute_all(items: list[tuple[Path, str]], jobs: int, use_cache: bool) -> dict[Path, Path]:
    tree = _tree_hash()
    CACHE.mkdir(parents=True, exist_ok=True)
    done: dict[Path, Path] = {}
    todo = []
    for path, _doc in items:
        nb = json.loads(path.read_text())
        cached = CACHE / f"{path.stem}-{_notebook_key(nb, tree)}.ipynb"
        done[path] = cached
        if use_cache and cached.exists():
            print(f"  cached   {_repo_path(path)}")
        else:
            todo.append((path, cached))
    if not todo:
        return done
    env = _kernel_env()
    with cf.ProcessPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = {
            pool.submit(execute_notebook, str(p), str(c), str(p.parent), env): p for p, c in todo
        }
        for fut in cf.as_completed(futures):
            p = futures[fut]
            print(f"  executed {_repo_path(p)} in {fut.result():.1f} s")
    shutil.rmtree(env["IPYTHONDIR"], ignore_errors=True)
    # drop stale cache entries of these notebooks
    keep = {c.name for c in done.values()}
    for path, _ in items:
        for old in CACHE.glob(f"{path.stem}-*.ipynb"):
            if old.name not in keep:
                old.unlink(missing_ok=True)  # another build may have dropped it already
    return done


# ------------------------------------------------------------------------ preparation
def _tags(cell: dict) -> list[str]:
    return list(cell.setdefault("metadata", {}).get("tags", []))


MD_LINK = re.compile(r"(?<!!)\[([^\]]*)\]\(([^)\s]+)\)")


def rewrite_links(text: str, repo_path: str, docs: dict[str, str]) -> str:
    """Links between notebooks point at their pages; a link to anything the site does not
    have (a repository file, a solution) keeps its text only."""
    here = Path(repo_path).parent
    page_dir = Path(docs.get(repo_path, repo_path)).parent

    def repl(m):
        label, target = m.group(1), m.group(2)
        if re.match(r"[a-z]+:|#", target):
            return m.group(0)
        path, _, frag = target.partition("#")
        rel = os.path.normpath(here / path).replace(os.sep, "/")
        if rel in docs:
            new = os.path.relpath(docs[rel] + ".ipynb", page_dir).replace(os.sep, "/")
            return f"[{label}]({new}{'#' + frag if frag else ''})"
        return label

    return MD_LINK.sub(repl, text)


def prepare(nb: dict, repo_path: str, docs: dict[str, str] | None = None) -> dict:
    """The page version of an executed notebook (see the module docstring, step 2);
    ``docs`` maps repository paths of the notebooks on the site to their documents."""
    nb = copy.deepcopy(nb)
    docs = docs or {}
    cells = []
    widget_figure_next = False  # the code cell after `%matplotlib widget` draws a live figure
    for cell in nb["cells"]:
        if cell["cell_type"] == "markdown":
            cell["source"] = rewrite_links("".join(cell["source"]), repo_path, docs)
        meta = cell.setdefault("metadata", {})
        tags = _tags(cell)
        jup = meta.get("jupyter", {})
        if cell["cell_type"] == "code":
            if "evidence" in tags or jup.get("source_hidden"):
                tags.append("hide-input")
            if jup.get("outputs_hidden"):
                tags.append("hide-output")
        if tags:
            meta["tags"] = sorted(set(tags))
        cid = cell.get("id")
        anchor = f"(cell-{cid})=\n" if cid and re.fullmatch(r"[\w-]+", cid) else ""
        if anchor and cell["cell_type"] == "markdown":
            cell["source"] = anchor + "\n" + "".join(cell["source"])
        elif anchor:
            cells.append(_markdown(anchor, len(cells)))
        cells.append(cell)
        if meta.pop("course_live_only", False):
            cells.append(_markdown(LIVE_CHECK_NOTE, len(cells)))
        if cell["cell_type"] != "code":
            continue
        src = "".join(cell["source"])
        has_picture = any("image/png" in o.get("data", {}) for o in cell.get("outputs", []))
        alt = cell_alt(meta)
        if has_picture and alt and "figure" not in meta.get("mystnb", {}):
            # MyST-NB: the alt text is the image's alt (mystnb.image.alt); shown also as a
            # visible caption, as JupyterLab shows it (course_lib/figure_alt.py)
            meta["mystnb"]["figure"] = {"caption": f"{CAPTION_PREFIX} {alt}"}
        live_demo = DEMO_CALL.search(src) and not re.search(r"static\s*=\s*True", src)
        if live_demo or (widget_figure_next and has_picture):
            cells.append(_markdown(LIVE_NOTE.format(path=repo_path), len(cells)))
            widget_figure_next = False
        elif WIDGET_MAGIC.search(src):
            widget_figure_next = True
    nb["cells"] = cells
    return nb


def _markdown(text: str, n: int) -> dict:
    return {"cell_type": "markdown", "id": f"site-{n}", "metadata": {}, "source": text}


# ------------------------------------------------------------------- pages from README
def _section(readme: str, heading: str) -> str:
    m = re.search(rf"^(#+) {re.escape(heading)}\n(.*?)(?=^#+ |\Z)", readme, re.M | re.S)
    if not m:
        return ""
    return m.group(2).strip()


def _doc_for(docs: dict[str, str], prefix: str) -> str | None:
    return next((d for stem, d in docs.items() if stem.startswith(prefix)), None)


def link_notebooks(text: str, docs: dict[str, str]) -> str:
    """README links ``[`stem`](notebooks/stem.ipynb)`` as links to the pages and links to a
    guide (``site/NAME.md``) as links to its page (from a page at the top of the site); any
    other relative link keeps its text only (the site has no such page)."""
    guides = "|".join(re.escape(g) for _, names in GUIDES for g in names)

    def repl(m):
        stem = Path(m.group(2)).stem
        d = docs.get(stem)
        return f"{{doc}}`{m.group(1)} </{d}>`" if d else m.group(1)

    text = re.sub(r"\[`([^`\]]+)`\]\(((?:notebooks|exercises)/[^)]+\.ipynb)\)", repl, text)
    text = re.sub(rf"\]\(site/((?:{guides})\.md(?:#[^)]*)?)\)", r"](\1)", text)
    return re.sub(rf"\[([^\]]+)\]\((?!https?:|#|(?:{guides})\.md)[^)]+\)", r"\1", text)


def link_figure_row(line: str, docs: dict[str, str], cell_ids: dict[str, set[str]]) -> str:
    """A row ``| figure | NN | section (`cell-id`) |``: the lecture number and the cell ids
    become links into the lecture's page."""
    cols = line.strip().strip("|").split("|")
    if len(cols) < 3 or not re.fullmatch(r"\s*\d\d\s*", cols[1]):
        return line
    nb = cols[1].strip()
    d = _doc_for(docs, nb)
    if d is None:
        return line
    stem = d.split("/")[-1]

    def cell(m):
        cid = m.group(1)
        if cid in cell_ids.get(stem, set()):
            return f"{{ref}}`{cid} <cell-{cid}>`"
        return m.group(0)

    cols[1] = f" {{doc}}`{nb} </{d}>` "
    cols[2] = re.sub(r"`([\w-]+)`", cell, cols[2])
    return "|" + "|".join(cols) + "|"


def link_errors(text: str, docs: dict[str, str]) -> str:
    """Each "notebook NN" and "hwNN" as a link to its page."""

    def nb(m):
        d = _doc_for(docs, m.group(1))
        return f"{{doc}}`notebook {m.group(1)} </{d}>`" if d else m.group(0)

    def hw(m):
        d = _doc_for(docs, m.group(1))
        return f"{{doc}}`{m.group(1)} </{d}>`" if d else m.group(0)

    text = re.sub(r"notebook (\d\d)\b", nb, text)
    return re.sub(r"\b(hw\d\d)\b", hw, text)


def course_page(docs: dict[str, str]) -> str:
    """``course.md``: the README's lecture and homework tables, linked into the site."""
    readme = (ROOT / "README.md").read_text()
    lectures = link_notebooks(_section(readme, "The lectures"), docs)
    homework = link_notebooks(_section(readme, "Homework"), docs)
    return (
        "# Course map\n\n"
        "The lectures in order and the homework that follows them. Every figure of the three\n"
        "sources is listed in {doc}`figures`, every error found in them in\n"
        "{doc}`sources-errata`.\n\n"
        f"## The lectures\n\n{lectures}\n\n"
        f"## Homework\n\n{homework}\n"
    )


def guide_page(name: str, text: str, docs: dict[str, str], cell_ids: dict[str, set[str]]) -> str:
    """The site version of the guide ``site/<name>.md`` (see the module docstring, step 3);
    ``docs`` maps notebook stems to their documents."""
    guides = {g for _, names in GUIDES for g in names}

    def repl(m):
        label, target = m.group(1), m.group(2)
        if re.match(r"[a-z]+:|#", target):
            return m.group(0)
        path, _, frag = target.partition("#")
        rel = os.path.normpath(Path("site") / path).replace(os.sep, "/")
        if rel.startswith("site/") and rel.endswith(".md") and rel[5:-3] in guides:
            return m.group(0)
        stem = Path(rel).stem
        if (
            rel.endswith(".ipynb")
            and rel.split("/")[0] in ("notebooks", "exercises")
            and stem in docs
        ):
            return f"[{label}]({docs[stem]}.ipynb{'#' + frag if frag else ''})"
        return label

    text = MD_LINK.sub(repl, text)
    if name == "figures":
        text = "\n".join(link_figure_row(x, docs, cell_ids) for x in text.splitlines()) + "\n"
    if name == "sources-errata":
        text = link_errors(text, docs)
    return text


def index_page(items: list[tuple[Path, str]]) -> str:
    readme = (ROOT / "README.md").read_text()
    intro = readme.split("\n## ", 1)[0].split("\n", 1)[1].strip()
    intro = link_notebooks(intro, {})
    intro = re.sub(r" \(in `[^`]*`\)", "", intro)
    lectures = "\n".join(d for _, d in items if d.startswith("lectures/"))
    homework = "\n".join(d for _, d in items if d.startswith("homework/"))
    parts = [
        "# Geometric continuity of parametric curves\n",
        intro,
        "\n**How to read this site.** Each lecture is shown executed, with its outputs and "
        "pictures; every live demo is replaced by its static picture, with a note saying how to "
        "run it live (`make lab`, then the notebook in JupyterLab). Cells that only check a claim "
        "(test evidence) are collapsed: click to open them. The {doc}`course map <course>` lists "
        "the lectures and the homework; the guides below are for students, lecturers, "
        "instructors and contributors.\n",
        "```{toctree}\n:maxdepth: 1\n:caption: Course map\n\ncourse\n```\n",
    ]
    if lectures:
        parts.append(f"```{{toctree}}\n:maxdepth: 1\n:caption: Lectures\n\n{lectures}\n```\n")
    if homework:
        parts.append(
            "```{toctree}\n:maxdepth: 1\n:caption: Homework (blank, as students get it)\n\n"
            f"{homework}\n```\n"
        )
    for caption, names in GUIDES:
        parts.append(
            f"```{{toctree}}\n:maxdepth: 1\n:caption: {caption}\n\n" + "\n".join(names) + "\n```\n"
        )
    return "\n".join(parts)


# ------------------------------------------------------------------------------ build
def mathjax_dir() -> Path:
    import jupyter_server_mathjax

    return Path(jupyter_server_mathjax.__file__).parent / "static"


def copy_mathjax(dest: Path) -> None:
    """MathJax 2.7 as jupyter-server-mathjax ships it (TeX input, HTML-CSS output, STIX-Web
    woff fonts; about 12 MB), without the translations of its menus."""
    src = mathjax_dir()

    def ignore(folder, names):
        if Path(folder) == src / "localization":
            return {n for n in names if n != "en"}
        return set()

    shutil.copytree(src, dest, ignore=ignore, dirs_exist_ok=True)


def build(
    only: list[str] | None,
    out: Path,
    jobs: int,
    use_cache: bool,
    items: list[tuple[Path, str]] | None = None,
) -> Path:
    """Build the site into ``out``; the Sphinx sources and doctrees go next to it
    (``<out>-src``, ``<out>-doctrees``).  ``items`` replaces the course's notebooks by other
    (notebook, document) pairs (tests)."""
    t0 = time.perf_counter()
    items = items if items is not None else source_notebooks(only)
    stage = out.parent / f"{out.name}-src"
    doctrees = out.parent / f"{out.name}-doctrees"
    if not items:
        raise SystemExit(f"no notebook matches {only}")
    print(f"executing {len(items)} notebooks (cache: {CACHE.relative_to(ROOT)})")
    executed = execute_all(items, jobs, use_cache)
    t_exec = time.perf_counter() - t0

    if stage.exists():
        shutil.rmtree(stage)
    shutil.copytree(SITE_CONF, stage, ignore=shutil.ignore_patterns("kernel_startup.py"))
    copy_mathjax(stage / "_static" / "mathjax")
    docs, cell_ids = {}, {}
    by_path = {_repo_path(p): d for p, d in items}
    for path, doc in items:
        nb = json.loads(executed[path].read_text())
        page = prepare(nb, _repo_path(path), by_path)
        target = stage / f"{doc}.ipynb"
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(json.dumps(page, ensure_ascii=False, indent=1))
        docs[path.stem] = doc
        cell_ids[path.stem] = {c.get("id") for c in nb["cells"]}
    (stage / "course.md").write_text(course_page(docs))
    for _, names in GUIDES:
        for name in names:
            text = (SITE_CONF / f"{name}.md").read_text()
            (stage / f"{name}.md").write_text(guide_page(name, text, docs, cell_ids))
    (stage / "index.md").write_text(index_page(items))

    if out.exists():
        shutil.rmtree(out)
    cmd = [sys.executable, "-m", "sphinx", "-b", "html", "-q", "-j", str(max(1, jobs))]
    cmd += ["-d", str(doctrees), str(stage), str(out)]
    print(" ".join(cmd))
    subprocess.run(cmd, check=True, cwd=ROOT)
    for junk in (out / "_static").glob("*macros.html"):  # the theme's Jinja macros, not pages
        junk.unlink()
    (out / ".nojekyll").touch()  # GitHub Pages: serve _static/ as is
    print(
        f"site: {out.relative_to(ROOT) if out.is_relative_to(ROOT) else out}/index.html "
        f"(execution {t_exec:.0f} s, total {time.perf_counter() - t0:.0f} s)"
    )
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--only", action="append", help="notebook stem (repeatable)")
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--no-cache", action="store_true")
    args = ap.parse_args(argv)
    build(args.only, args.out.resolve(), args.jobs, not args.no_cache)
    return 0


if __name__ == "__main__":
    sys.exit(main())
