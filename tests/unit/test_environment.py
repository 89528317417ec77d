"""The three dependency lists (pyproject.toml, environment.yml, constraints.txt) agree."""

from __future__ import annotations

import re
from pathlib import Path

import tomllib

ROOT = Path(__file__).resolve().parents[2]


def _name(req: str) -> str:
    return re.split(r"[<>=!~\[; ]", req.strip(), maxsplit=1)[0].lower().replace("_", "-")


def pyproject_requirements() -> dict[str, str]:
    data = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    reqs = list(data["dependencies"]) + list(data["optional-dependencies"]["test"])
    return {_name(r): r for r in reqs}


def conda_requirements() -> tuple[dict[str, str | None], list[str]]:
    deps: dict[str, str | None] = {}
    pip: list[str] = []
    in_pip = False
    text = (ROOT / "environment.yml").read_text()
    for raw in text.split("\ndependencies:", 1)[1].splitlines():
        line = raw.split("#", 1)[0].rstrip()
        if not line.strip().startswith("- "):
            continue
        item = line.strip()[2:].strip()
        indent = len(line) - len(line.lstrip())
        if item == "pip:" or item.startswith("pip:"):
            in_pip = True
            continue
        if in_pip and indent > 2:
            pip.append(item)
            continue
        in_pip = False
        name, _, version = item.partition("=")
        deps[name.lower()] = version or None
    return deps, pip


def constraints() -> dict[str, str]:
    out = {}
    for line in (ROOT / "constraints.txt").read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if line:
            name, _, version = line.partition("==")
            out[name.lower()] = version
    return out


def _pip_pins(pip: list[str]) -> dict[str, str]:
    """Packages environment.yml takes from PyPI (``name==version``), besides ``-e .``."""
    pins = {}
    for item in pip:
        if "==" in item:
            name, version = item.split("==", 1)
            pins[_name(name)] = version.strip()
    return pins


def test_environment_yml_names_the_same_dependencies_as_pyproject():
    conda, pip = conda_requirements()
    conda_names = (set(conda) - {"python", "pip"}) | set(_pip_pins(pip))
    assert conda_names == set(pyproject_requirements()), (
        f"only in environment.yml: {sorted(conda_names - set(pyproject_requirements()))}; "
        f"only in pyproject.toml: {sorted(set(pyproject_requirements()) - conda_names)}"
    )
    assert "-e ." in pip, "environment.yml must install course_lib from the repository (Binder)"


def test_pinned_versions_agree_with_constraints():
    conda, pip = conda_requirements()
    conda = {**conda, **_pip_pins(pip)}
    pins = constraints()
    assert set(pins) <= set(pyproject_requirements()), "constraints.txt pins a package nobody needs"
    for name, version in conda.items():
        if name in pins:
            assert version == pins[name], (
                f"{name}: environment.yml {version} vs constraints {pins[name]}"
            )
