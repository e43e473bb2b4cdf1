"""Release basics: the wheel builds and installs, with its package data and licence;
LICENSE and CITATION.cff agree with pyproject; ``tasks.py`` help lists every task.

The wheel is built offline from a copy of the sources (``--no-build-isolation``: the build
backend, setuptools >= 77 for the SPDX ``license`` field, comes from the test environment), and
installed with ``--no-deps`` into a temporary target that is imported in a fresh interpreter.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tomllib
import zipfile
from importlib.metadata import version
from pathlib import Path

import pytest
import yaml

from impactlab.references import PAPER, REFERENCES

ROOT = Path(__file__).resolve().parents[2]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
#: the oldest setuptools that reads ``license = "MIT"`` (PEP 639, SPDX expression)
SETUPTOOLS_MIN = (77, 0)
#: files under src/impactlab that are not package data (modules, caches)
_NOT_DATA = {".py", ".pyc", ".nbi", ".nbc"}


def _run(*cmd: str | Path, cwd: Path, env: dict[str, str] | None = None) -> str:
    res = subprocess.run(
        [str(c) for c in cmd], cwd=cwd, env=env, capture_output=True, text=True, check=False
    )
    assert res.returncode == 0, f"{cmd} failed:\n{res.stdout}\n{res.stderr}"
    return res.stdout


def _source_copy(dest: Path) -> Path:
    """What an sdist holds: the package (no caches), pyproject, README and LICENSE."""
    ignore = shutil.ignore_patterns("__pycache__", "*.pyc", "*.nbi", "*.nbc", "*.egg-info")
    shutil.copytree(ROOT / "src" / "impactlab", dest / "src" / "impactlab", ignore=ignore)
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy2(ROOT / name, dest / name)
    return dest


@pytest.fixture(scope="module")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    have = tuple(int(p) for p in version("setuptools").split(".")[:2])
    assert have >= SETUPTOOLS_MIN, (
        f"setuptools {version('setuptools')} cannot build impactlab (needs >= 77 for the SPDX "
        "license field): run `python3 tasks.py test`, which installs requirements.lock"
    )
    src = _source_copy(tmp_path_factory.mktemp("src"))
    dist = tmp_path_factory.mktemp("dist")
    pip = (sys.executable, "-m", "pip", "--disable-pip-version-check")
    _run(*pip, "wheel", ".", "--no-deps", "--no-build-isolation", "-q", "-w", dist, cwd=src)
    (whl,) = dist.glob("impactlab-*.whl")
    return whl


def test_wheel_holds_every_module_and_data_file(wheel: Path) -> None:
    names = set(zipfile.ZipFile(wheel).namelist())
    pkg = ROOT / "src" / "impactlab"
    modules = {
        "impactlab/" + p.relative_to(pkg).as_posix()
        for p in pkg.rglob("*.py")
        if "__pycache__" not in p.parts
    }
    assert modules <= names, sorted(modules - names)
    # every data file of the package (not only those package-data names) is in the wheel
    data = {
        "impactlab/" + p.relative_to(pkg).as_posix()
        for p in pkg.rglob("*")
        if p.is_file() and "__pycache__" not in p.parts and p.suffix not in _NOT_DATA
    }
    missing = sorted(data - names)
    assert "impactlab/py.typed" in data and not missing, (
        f"{missing}: add them to [tool.setuptools.package-data] in pyproject.toml"
    )
    dist_info = f"impactlab-{PYPROJECT['project']['version']}.dist-info"
    assert f"{dist_info}/licenses/LICENSE" in names
    meta = zipfile.ZipFile(wheel).read(f"{dist_info}/METADATA").decode()
    assert "License-Expression: MIT" in meta
    entry = zipfile.ZipFile(wheel).read(f"{dist_info}/entry_points.txt").decode()
    assert "impactlab = impactlab.cli:main" in entry


def test_wheel_installs_and_imports(wheel: Path, tmp_path: Path) -> None:
    target = tmp_path / "site"
    pip = (sys.executable, "-m", "pip", "--disable-pip-version-check")
    _run(*pip, "install", "--no-deps", "--no-index", "-q", "--target", target, wheel, cwd=tmp_path)
    code = (
        "import importlib.resources as r, impactlab; "
        "print(impactlab.__file__); print(impactlab.__version__); "
        "print(r.files('impactlab').joinpath('py.typed').is_file())"
    )
    env = {**os.environ, "PYTHONPATH": str(target)}
    out = _run(sys.executable, "-c", code, cwd=tmp_path, env=env).split()
    assert Path(out[0]).is_relative_to(target), out[0]  # not the source tree
    assert out[1] == PYPROJECT["project"]["version"] and out[2] == "True"


def test_license_is_mit() -> None:
    text = (ROOT / "LICENSE").read_text()
    assert PYPROJECT["project"]["license"] == "MIT"
    assert text.startswith("MIT License") and "impactlab developers" in text


def test_citation_cff() -> None:
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text())
    assert cff["cff-version"] == "1.2.0"
    for key in ("message", "title", "authors"):  # required by CFF 1.2.0
        assert cff[key]
    assert cff["version"] == PYPROJECT["project"]["version"]
    assert cff["license"] == PYPROJECT["project"]["license"]
    (paper,) = cff["references"]
    assert paper["doi"] == REFERENCES[PAPER].doi and paper["type"] == "article"
    assert all(set(a) <= {"family-names", "given-names", "name"} for a in paper["authors"])


def _tasks(*args: str) -> subprocess.CompletedProcess[str]:
    cmd = [sys.executable, str(ROOT / "tasks.py"), *args]
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, check=False)


@pytest.mark.parametrize("args", [(), ("help",), ("-h",), ("--help",)])
def test_tasks_help_lists_every_task(args: tuple[str, ...]) -> None:
    res = _tasks(*args)
    assert res.returncode == 0
    handled = set(re.findall(r'task == "(\w+)"', (ROOT / "tasks.py").read_text()))
    listed = dict(re.findall(r"^  (\w+) +(\S.*)$", res.stdout, flags=re.MULTILINE))
    assert handled <= set(listed) and {"test", "reproduce", "docs", "help"} <= set(listed)
    assert all(len(text) <= 100 for text in listed.values())


def test_tasks_unknown_task_lists_the_tasks() -> None:
    res = _tasks("nope")
    assert res.returncode == 2 and "unknown task 'nope'" in res.stderr
    assert re.search(r"^  test +\S", res.stderr, flags=re.MULTILINE)
